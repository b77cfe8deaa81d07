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

from . import inprocess_pass
from .engagement import edge_lines, empty_results, engage, finished_engagement, inside_intervals
from .inprocess import inprocess_intervals, removal_intervals, subtract
from .inprocess_arc_search import arc_removal_intervals
from .interval_engagement import engagement_from_intervals
from .arguments import check_arguments
from .model import Staircase
from .profile import (_chunk_results, as_terraced, corner_top, end_lengths, profile_engagement, profile_intervals,
                      radial_directions)
from .terraced import engage_terraced, terraced_intervals
from .terraced_model import TerracedStock


def engage_stock(stock, tool, toolpath, settings, *, progress=None):
    """The Engagement of a pass over `stock`, a Staircase or a TerracedStock; TypeError for anything else.

    A tool with a corner radius goes to profile.profile_engagement. Every Engagement carries the end
    edge's engaged length (profile.end_lengths)."""
    _check(stock, tool, toolpath, settings)
    if tool.corner_radius > 0.0:
        return profile_engagement(stock, tool, toolpath, settings, progress=progress)
    if isinstance(stock, Staircase):
        found = _engage_staircase(stock, tool, toolpath, settings, progress)
    else:
        found = engage_terraced(stock, tool, toolpath, settings, progress=progress)
    return dataclasses.replace(found, end_length=end_lengths(stock, tool, toolpath, settings.phi))


def _check(stock, tool, toolpath, settings):
    """TypeError for a stock that is neither a Staircase nor a TerracedStock; the arguments' own checks."""
    if not isinstance(stock, (Staircase, TerracedStock)):
        raise TypeError(f"stock must be a Staircase or a TerracedStock, got {type(stock).__name__}")
    check_arguments(tool=tool, toolpath=toolpath, settings=settings)


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

    A tool with a corner radius (bull-nose, ball-end) goes to _corner_in_process: its corner arcs, straight
    sides and end edges against the in-process stock; its changed CL points keep case "corner", and their
    end_length is the end edge's in the in-process stock too.
    """
    if tool.corner_radius > 0.0:
        return _corner_in_process(stock, tool, toolpath, settings, pieces, program_index)
    if inprocess_pass.shared(stock, tool, toolpath):
        return _engage_shared(stock, tool, toolpath, settings, pieces, program_index)
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


def _engage_shared(stock, tool, toolpath, settings, pieces, program_index):
    """engage_in_process where the stock's edge lines are solved once (inprocess_pass): the same
    Engagement, initial length and changed, bit for bit."""
    m, p = len(toolpath), settings.phi.size
    program_index = np.asarray(program_index, dtype=np.intp).reshape(-1)
    if program_index.shape != (m,):
        raise ValueError(f"program_index must have shape ({m},), got {program_index.shape}")
    solve = inprocess_pass.shared_solve(stock, tool, toolpath, settings)
    out, _, _, inside, base, direction = solve
    length = out["length"].copy()  # the Engagement's own is overwritten below where changed
    line = np.flatnonzero(length.reshape(-1) > 0.0)
    rows, enter, leave = removal_intervals(pieces, program_index, line, out["lep_l"].reshape(-1)[line],
                                           out["uep_l"].reshape(-1)[line], base.reshape(-1, 3),
                                           np.repeat(direction, p, axis=0), p)
    changed = np.zeros(m, dtype=bool)
    if rows.size:
        remaining = subtract(inside, rows, enter, leave)
        changed = (remaining.length != inside.length).reshape(-1, p).any(axis=1)
    lost = np.flatnonzero(changed)
    initial = inprocess_pass.stock_engagement(solve, stock, tool, toolpath, settings, np.flatnonzero(~changed))
    if lost.size == 0:
        return initial, length, changed
    lines = (base[lost].reshape(-1, 3), np.repeat(direction[lost], p, axis=0))
    in_process = engagement_from_intervals(inprocess_pass.cl_rows(remaining, lost, p), toolpath.rows(lost), tool,
                                           settings, *lines)
    per_cl = {field.name: getattr(initial, field.name) for field in dataclasses.fields(initial)
              if field.name not in ("phi", "h")}
    for name, values in per_cl.items():
        values[lost] = getattr(in_process, name)
    return dataclasses.replace(initial, **per_cl), length, changed


def in_process_lengths(stock, tool, toolpath, phi_deg, pieces, program_index):
    """(m, p) length of cut (mm) against the in-process stock at angles phi_deg (p,) (any, e.g.
    another flute's φ + 360·k/Z) of the m CL points of `toolpath`; pieces and program_index as
    for engage_in_process. Every edge line's intervals in the stock, less the removals (for a tool
    with a corner, its peripheral edges': in_process_runs)."""
    phi = np.atleast_1d(np.asarray(phi_deg, dtype=float))
    if tool.corner_radius > 0.0:
        return in_process_runs(stock, tool, toolpath, phi, pieces, program_index).length.reshape(len(toolpath), -1)
    base, direction = edge_lines(toolpath, tool, phi)
    origins, directions = base.reshape(-1, 3), np.repeat(direction, phi.size, axis=0)
    inside = stock_intervals(stock, origins, directions, tool.flute_length)
    remaining, _ = inprocess_intervals(inside, pieces, program_index, origins, directions, phi.size)
    return remaining.length.reshape(len(toolpath), -1)


def in_process_runs(stock, tool, toolpath, phi_deg, pieces, program_index):
    """EdgeIntervals of the m·p peripheral edges (row i·p + k, arc length s in mm, as profile.profile_intervals
    gives them) of a tool with a corner against the in-process stock at angles phi_deg (p,); pieces and
    program_index as for engage_in_process: each edge's runs in the stock less what the earlier moves removed
    from its corner arc and its straight side (the runs forces.pass_forces takes as runs_at)."""
    if tool.corner_radius <= 0.0:
        raise ValueError("in_process_runs is for tools with a corner radius; a flat-end tool's edges are lines "
                         "(in_process_lengths)")
    phi = np.atleast_1d(np.asarray(phi_deg, dtype=float))
    program_index = np.asarray(program_index, dtype=np.intp).reshape(-1)
    edges = _CornerEdges(tool, toolpath, phi)
    inside = profile_intervals(stock, tool, toolpath, phi, _terraced(stock, tool))
    first = np.flatnonzero(np.r_[True, inside.rows[1:] != inside.rows[:-1]]) if inside.rows.size else inside.rows
    last = np.r_[first[1:], inside.rows.size] - 1
    rows, enter, leave = edges.removals(pieces, program_index, inside.rows[first], inside.start[first],
                                        inside.end[last])
    return subtract(inside, rows, enter, leave)


def _terraced(stock, tool):
    """The terraced form profile_intervals takes for a tool with a corner (as profile.profile_engagement makes it:
    its curved pieces split at the corner radius), None for a Staircase: every in-process result of such a tool
    starts from the same intervals as the stock's Engagement."""
    return None if isinstance(stock, Staircase) else as_terraced(stock, tool.corner_radius)


#: Ends of an edge's engaged range are widened by this (mm) where they come back from heights (the range
#: the search for removals is given must hold all the edge's material).
_RANGE_SLACK = 1e-9


class _CornerEdges:
    """The cutting edges of a tool with a corner at m CL points × p angles (row i·p + k): the corner arcs
    (centre, d, w; arc length s = r·ψ), the straight sides (origin, direction w; l = s − r·ψ_max) and the
    end edges (origin the tip, direction d), as the engine's profile module defines them."""

    def __init__(self, tool, toolpath, phi):
        self.tool = tool
        self.p = phi.size
        self.r, self.big, self.length = tool.corner_radius, tool.radius, tool.flute_length
        self.corner_length = self.r * corner_top(tool)
        d = radial_directions(toolpath, phi)
        self.d = d.reshape(-1, 3)
        self.w = np.repeat(toolpath.axes, self.p, axis=0)
        self.tip = np.repeat(toolpath.cl, self.p, axis=0)
        self.centre = self.tip + (self.big - self.r) * self.d + self.r * self.w
        self.side = self.tip + self.big * self.d + self.r * self.w

    def removals(self, pieces, program_index, line, lo, hi):
        """(rows, enter, leave) in arc length s of the peripheral edges `line` (ascending) whose material lies
        within lo … hi (s, mm): the corner arcs' (inprocess_arc) and the straight sides' (inprocess), joined."""
        corner = self.corner_length
        parts = [(np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0))]
        on_arc = lo < corner
        if on_arc.any():
            parts.append(arc_removal_intervals(pieces, program_index, line[on_arc], lo[on_arc],
                                               np.minimum(hi[on_arc], corner), self.centre, self.d, self.w, self.r,
                                               corner_top(self.tool), self.p, self.tip, self.big))
        on_side = (hi > corner) & (self.length > self.r)
        if on_side.any():
            rows, enter, leave = removal_intervals(pieces, program_index, line[on_side],
                                                   np.maximum(lo[on_side] - corner, 0.0), hi[on_side] - corner,
                                                   self.side, self.w, self.p)
            parts.append((rows, enter + corner, leave + corner))
        rows, enter, leave = (np.concatenate(part) for part in zip(*parts))
        order = np.argsort(rows, kind="stable")
        return rows[order], enter[order], leave[order]

    def end_lines(self):
        """(origins, directions, length) of the end edges, or None for a ball (no end edge)."""
        reach = self.big - self.r
        return (self.tip, self.d, reach) if reach > 0.0 else None

    def s_of_height(self, height):
        """Arc length s (mm) of the peripheral edge's points at `height` above the tip (the inverse of
        profile.height_at)."""
        r = self.r
        with np.errstate(invalid="ignore"):
            on_corner = r * np.arccos(np.clip(1.0 - height / r, -1.0, 1.0))
        return np.where(height < r, on_corner, self.corner_length + (height - r))


def _corner_in_process(stock, tool, toolpath, settings, pieces, program_index):
    """engage_in_process for a tool with a corner: (Engagement, initial length (m, p), changed (m,)).

    The peripheral and end edges' intervals in the stock are found once (as profile.profile_engagement finds them)
    and give the stock's Engagement; each instant's engaged range of the peripheral edge (from its LEP and UEP
    heights) bounds the search for removals on the corner arc and on the straight side, the end edge's intervals
    in the stock bound it on the end edge. The CL points with a removal get their edges' intervals less the
    removals; those that lost length on any edge (changed) take that result in every per-instant and per-CL field,
    case "corner", with the end edge's in-process length; the others keep the stock's Engagement."""
    _check(stock, tool, toolpath, settings)
    m, p = len(toolpath), settings.phi.size
    program_index = np.asarray(program_index, dtype=np.intp).reshape(-1)
    if program_index.shape != (m,):
        raise ValueError(f"program_index must have shape ({m},), got {program_index.shape}")
    phi = settings.phi
    edges = _CornerEdges(tool, toolpath, phi)
    inside = profile_intervals(stock, tool, toolpath, phi, _terraced(stock, tool))
    end = edges.end_lines()
    end_inside = stock_intervals(stock, *end) if end is not None else None
    initial = _profile_engagement(inside, toolpath, tool, settings,
                                  None if end is None else end_inside.length.reshape(m, p))
    line = np.flatnonzero(initial.engaged.reshape(-1))
    total = edges.corner_length + max(tool.flute_length - tool.corner_radius, 0.0)
    lo = np.maximum(edges.s_of_height(initial.lep_l.reshape(-1)[line]) - _RANGE_SLACK, 0.0)
    hi = np.minimum(edges.s_of_height(initial.uep_l.reshape(-1)[line]) + _RANGE_SLACK, total)
    rows, enter, leave = edges.removals(pieces, program_index, line, lo, hi)
    found = [rows]
    if end is not None:
        first = np.flatnonzero(np.r_[True, end_inside.rows[1:] != end_inside.rows[:-1]]) if end_inside.rows.size \
            else end_inside.rows
        last = np.r_[first[1:], end_inside.rows.size] - 1
        end_rows, end_enter, end_leave = removal_intervals(pieces, program_index, end_inside.rows[first],
                                                           end_inside.start[first], end_inside.end[last], end[0],
                                                           end[1], p)
        found.append(end_rows)
    changed = np.zeros(m, dtype=bool)
    touched = np.unique(np.concatenate(found) // p)
    if touched.size == 0:
        return initial, initial.length, changed
    local = np.searchsorted(touched, rows // p) * p + rows % p
    part_inside = inprocess_pass.cl_rows(inside, touched, p)
    remaining = subtract(part_inside, local, enter, leave)
    lost = remaining.length != part_inside.length
    end_length = None
    if end is not None:
        end_part = inprocess_pass.cl_rows(end_inside, touched, p)
        end_local = np.searchsorted(touched, end_rows // p) * p + end_rows % p
        end_remaining = subtract(end_part, end_local, end_enter, end_leave)
        lost |= end_remaining.length != end_part.length
        end_length = end_remaining.length.reshape(-1, p)
    lost = lost.reshape(-1, p).any(axis=1)
    if not lost.any():
        return initial, initial.length, changed
    changed[touched[lost]] = True
    part = toolpath.rows(touched)
    in_process = _profile_engagement(remaining, part, tool, settings, end_length)
    per_cl = {field.name: getattr(initial, field.name).copy() for field in dataclasses.fields(initial)
              if field.name not in ("phi", "h")}
    for name, values in per_cl.items():
        values[touched[lost]] = getattr(in_process, name)[lost]
    return dataclasses.replace(initial, **per_cl), initial.length, changed


def _profile_engagement(intervals, toolpath, tool, settings, end_length):
    """The Engagement of a tool with a corner from its peripheral edges' intervals (in arc length s, rows
    i·p + k), as profile.profile_engagement builds it; end_length (m, p) mm or None (zeros: a ball)."""
    phi = settings.phi
    m, p = len(toolpath), phi.size
    chunk = _chunk_results(intervals, toolpath, tool, phi)
    out, _, _ = empty_results(m, p)
    out = {name: chunk[name] for name in out}
    engagement = finished_engagement(phi, settings, out, chunk["lep_xyz"], chunk["uep_xyz"],
                                     toolpath.inclinations(settings), axial=chunk["axial"],
                                     end_length=np.zeros((m, p)) if end_length is None else end_length)
    return dataclasses.replace(engagement, **{name: chunk[name] for name in ("lep_surface", "lep_section",
                                                                            "lep_wall")})
