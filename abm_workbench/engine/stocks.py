"""The engine for either stock model: the paper's staircase (its fast special case) or the general 2.5D terraced stock.

:func:`engage_stock` is ``engagement.engage`` for a :class:`~.model.Staircase` and
``terraced.engage_terraced`` for a :class:`~.terraced_model.TerracedStock`; both give an
:class:`~.engagement.Engagement` of m CL points × p angles (mm, degrees).
:func:`stock_intervals` gives either model's inside intervals of edge lines, and
:func:`engage_in_process` a pass against the in-process stock (the stock minus what earlier
moves of the program removed, :mod:`.inprocess`), :func:`in_process_lengths` just its lengths
of cut at any angles (the other flutes' for the forces).
"""

import dataclasses

import numpy as np

from .engagement import edge_lines, engage, inside_intervals
from .inprocess import inprocess_intervals, removal_intervals, subtract
from .interval_engagement import engagement_from_intervals
from .arguments import check_arguments
from .model import Staircase
from .profile import end_lengths, profile_engagement
from .terraced import engage_terraced, terraced_intervals
from .terraced_model import TerracedStock


def engage_stock(stock, tool, toolpath, settings, *, progress=None):
    """The Engagement of a pass over `stock`, a Staircase or a TerracedStock; TypeError for anything else.

    A tool with a corner radius goes to profile.profile_engagement. Every Engagement carries the end
    edge's engaged length (profile.end_lengths)."""
    if not isinstance(stock, (Staircase, TerracedStock)):
        raise TypeError(f"stock must be a Staircase or a TerracedStock, got {type(stock).__name__}")
    check_arguments(tool=tool, toolpath=toolpath, settings=settings)
    if tool.corner_radius > 0.0:
        return profile_engagement(stock, tool, toolpath, settings, progress=progress)
    if isinstance(stock, Staircase):
        found = _engage_staircase(stock, tool, toolpath, settings, progress)
    else:
        found = engage_terraced(stock, tool, toolpath, settings, progress=progress)
    return dataclasses.replace(found, end_length=end_lengths(stock, tool, toolpath, settings.phi))


def _engage_staircase(stock, tool, toolpath, settings, progress):
    """engagement.engage, whose Table 1 is for edges that rise; the CL points whose tool axis points down
    (w_z < 0) from their edge lines' intervals (engagement.inside_intervals reads a falling line
    backwards), case "2.5D"."""
    falling = toolpath.axes[:, 2] < 0.0
    if not falling.any():
        return engage(stock, tool, toolpath, settings, progress=progress)
    rising, down = np.flatnonzero(~falling), np.flatnonzero(falling)
    parts = [engage(stock, tool, toolpath.rows(rising), settings)] if rising.size else []
    part = toolpath.rows(down)
    base, direction = edge_lines(part, tool, settings.phi)
    origins, directions = base.reshape(-1, 3), np.repeat(direction, settings.phi.size, axis=0)
    found = inside_intervals(stock, origins, directions, tool.flute_length)
    parts.append(engagement_from_intervals(found, part, tool, settings, origins, directions))
    if progress is not None:
        progress(len(toolpath), len(toolpath))
    return stacked(parts, np.concatenate([rising, down]))


def stacked(parts, rows):
    """One Engagement of the CL points `rows` (concatenated over the parts, each an Engagement of the
    same angles), put back in CL point order."""
    back = np.argsort(rows, kind="stable")
    fields = {field.name: np.concatenate([getattr(part, field.name) for part in parts])[back]
              for field in dataclasses.fields(parts[0]) if field.name != "phi"}
    return dataclasses.replace(parts[0], **fields)


def stock_intervals(stock, origins, directions, length):
    """EdgeIntervals of N edge lines (origins, directions (N, 3), 0 ≤ l ≤ length mm) inside `stock`,
    a Staircase (engagement.inside_intervals) or a TerracedStock (terraced.terraced_intervals)."""
    if isinstance(stock, Staircase):
        return inside_intervals(stock, origins, directions, length)
    if isinstance(stock, TerracedStock):
        return terraced_intervals(stock, origins, directions, length)
    raise TypeError(f"stock must be a Staircase or a TerracedStock, got {type(stock).__name__}")


def engage_in_process(stock, tool, toolpath, settings, pieces, program_index):
    """(Engagement against the in-process stock, initial length (m, p) mm, changed (m,) bool) of a pass.

    pieces: the SweptPieces of the whole program (inprocess.swept_pieces), in the stock's frame;
    program_index: (m,) the program row of each CL point of `toolpath`. The Engagement's lengths,
    LEP and UEP are those of the stock minus what every cutting move ending before a CL point
    removed (docs/ENGINE.md); `initial` is the length of cut in the stock itself; `changed[i]`
    says whether earlier moves removed material from any edge line of CL point i.

    The stock's own Engagement (engage_stock) comes first; its LEP … UEP per instant bound
    each edge line's material for the search of removals (inprocess.removal_intervals). Only
    the CL points with a removal get their lines' intervals in the stock, less the removals
    (the same intervals as in_process_lengths finds). A CL point whose lines lost material
    (changed) takes that result in every per-instant and per-CL field (case "2.5D"); every
    other CL point keeps the stock's Engagement as it is (the staircase's Table 1 cases).
    """
    initial = engage_stock(stock, tool, toolpath, settings)
    m, p = initial.shape
    program_index = np.asarray(program_index, dtype=np.intp).reshape(-1)
    if program_index.shape != (m,):
        raise ValueError(f"program_index must have shape ({m},), got {program_index.shape}")
    base, direction = edge_lines(toolpath, tool, settings.phi)
    line = np.flatnonzero(initial.engaged.reshape(-1))
    rows, enter, leave = removal_intervals(pieces, program_index, line, initial.lep_l.reshape(-1)[line],
                                           initial.uep_l.reshape(-1)[line], base.reshape(-1, 3),
                                           np.repeat(direction, p, axis=0), p)
    changed = np.zeros(m, dtype=bool)
    touched = np.unique(rows // p)
    if touched.size == 0:
        return initial, initial.length, changed
    # Rows of the touched CL points' lines, numbered within them.
    local = np.searchsorted(touched, rows // p) * p + rows % p
    lines = (base[touched].reshape(-1, 3), np.repeat(direction[touched], p, axis=0))
    inside = stock_intervals(stock, *lines, tool.flute_length)
    remaining = subtract(inside, local, enter, leave)
    lost = (remaining.length != inside.length).reshape(-1, p).any(axis=1)
    if not lost.any():
        return initial, initial.length, changed
    changed[touched[lost]] = True
    in_process = engagement_from_intervals(remaining, toolpath.rows(touched), tool, settings, *lines)
    per_cl = {field.name: getattr(initial, field.name).copy() for field in dataclasses.fields(initial)
              if field.name not in ("phi", "h")}
    for name, values in per_cl.items():
        values[touched[lost]] = getattr(in_process, name)[lost]
    return dataclasses.replace(initial, **per_cl), initial.length, changed


def in_process_lengths(stock, tool, toolpath, phi_deg, pieces, program_index):
    """(m, p) length of cut (mm) against the in-process stock at angles phi_deg (p,) (any, e.g.
    another flute's φ + 360·k/Z) of the m CL points of `toolpath`; pieces and program_index as
    for engage_in_process. Every edge line's intervals in the stock, less the removals."""
    phi = np.atleast_1d(np.asarray(phi_deg, dtype=float))
    base, direction = edge_lines(toolpath, tool, phi)
    origins, directions = base.reshape(-1, 3), np.repeat(direction, phi.size, axis=0)
    inside = stock_intervals(stock, origins, directions, tool.flute_length)
    remaining, _ = inprocess_intervals(inside, pieces, program_index, origins, directions, phi.size)
    return remaining.length.reshape(len(toolpath), -1)
