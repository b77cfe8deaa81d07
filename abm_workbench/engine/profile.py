"""The whole cutting edge of a milling tool: corner arc and straight side (the peripheral edge), and the end edge.

A tool of diameter D = 2R, corner radius r (0 ≤ r ≤ R) and flute length L has, at each CL point T
(the tip's centre) and rotation angle φ, in its frame u, v, w (Toolpath.frames) with
d = sin φ·u + cos φ·v (docs/ENGINE.md, "Tools with a corner"):

- the peripheral edge: the corner's quarter arc from (R − r)·d (height 0) to R·d + r·w
  (corner.py), then the straight side at radius R from height r up to L (a line, the flat-end
  engines' edge); its one coordinate is the arc length s along it, s = r·ψ on the corner and
  s = r·π/2 + (height − r) on the side. For r = 0 it is the flat-end mill's side edge;
- the end edge: the segment in the tip plane from T to T + (R − r)·d (none for a ball).

Per instant an Engagement gives: length, the engaged length along the peripheral edge (mm of s);
lep_l, uep_l, the heights along w above the tip of its lowest and highest engaged points; their
points and surfaces; pieces, its inside runs; end_length, the engaged length of the end edge; h,
the chip on the straight side, f·sin φ·cos(inclination); area = ∫ h·sin κ ds over the engaged edge,
κ the angle between the axis and the tool surface's normal (90° on the side, ψ on the corner),
which is h times the engaged edge's extent along the axis. Shapes: m CL points × p angles φ.
"""

import dataclasses

import numpy as np

from .corner import CORNER_TOP, corner_intervals
from .corner_staircase import staircase_corner_intervals
from .engagement import CASES, SURFACES, edge_lines, empty_results, finished_engagement, inside_intervals
from .intervals import EdgeIntervals
from .model import Staircase
from .terraced import merged_intervals, terraced_intervals
from .terraced_model import TerracedStock
from .terraced_pieces import slab_pieces, split_pieces
from .terraced_staircase import staircase_as_terraced

_CORNER_CASE = CASES.index("corner")


def radial_directions(toolpath, phi_deg):
    """(m, p, 3) unit radial directions d = sin φ·u + cos φ·v of the flutes at angles phi_deg (p,)."""
    frames = toolpath.frames()
    phi = np.radians(np.asarray(phi_deg, dtype=float))
    return np.sin(phi)[None, :, None] * frames[:, None, :, 0] + np.cos(phi)[None, :, None] * frames[:, None, :, 1]


def end_lengths(stock, tool, toolpath, phi_deg):
    """(m, p) engaged length (mm) of the end edge, T to T + (R − r)·d, at every CL point and angle."""
    length = tool.radius - tool.corner_radius
    d = radial_directions(toolpath, phi_deg)
    m, p = d.shape[:2]
    if length <= 0.0:
        return np.zeros((m, p))
    origins = np.broadcast_to(toolpath.cl[:, None, :], d.shape).reshape(-1, 3)
    return stock_intervals(stock, origins, d.reshape(-1, 3), length).length.reshape(m, p)


def as_terraced(stock, longest=None):
    """(TerracedStock, its slab_pieces) of a Staircase (its exact terraced form) or a TerracedStock; with
    `longest` (mm), curved pieces wider than that halved (terraced_pieces.split_pieces: the corner meets
    fewer of them)."""
    terraced = staircase_as_terraced(stock) if isinstance(stock, Staircase) else stock
    groups, straight = slab_pieces(terraced)
    if longest is not None:
        groups = split_pieces(groups, longest)
    return terraced, (groups, straight)


def height_at(s, radius, psi_max):
    """Height (mm) along the axis above the tip of the peripheral edge's point at arc length s (mm)."""
    s = np.asarray(s, dtype=float)
    on_corner = s <= radius * psi_max
    with np.errstate(divide="ignore", invalid="ignore"):
        corner = radius * (1.0 - np.cos(np.where(on_corner, s / np.where(radius > 0.0, radius, 1.0), 0.0)))
    return np.where(on_corner, corner, radius + (s - radius * psi_max))


def arc_length_at(height, radius, psi_max):
    """Arc length s (mm) along the peripheral edge of its point at `height` (mm) above the tip (height_at's
    inverse; the corner's ψ = acos(1 − height/r))."""
    height = np.asarray(height, dtype=float)
    top = radius * (1.0 - np.cos(psi_max))
    with np.errstate(divide="ignore", invalid="ignore"):
        corner = radius * np.arccos(np.clip(1.0 - height / (radius if radius > 0.0 else 1.0), -1.0, 1.0))
    return np.where(height <= top, corner, radius * psi_max + (height - radius))


def edge_between(result, toolpath, tool, frame, cl, row, t):
    """Points (n, k, 3) of the peripheral edge of n instants (CL point cl (n,) of `toolpath`, angle
    result.phi[row] (n,)) at the heights a fraction t (k,) of the way from each instant's LEP to its UEP
    (result.lep_l, uep_l), in the part frame: the toolpath is in the engine frame `frame` ((R, t),
    part -> engine, or None), as the Engagement `result` was computed there."""
    r, psi_max = tool.corner_radius, corner_top(tool)
    lep, uep = result.lep_l[cl, row], result.uep_l[cl, row]
    heights = lep[:, None] + np.asarray(t, dtype=float)[None, :] * (uep - lep)[:, None]
    frames = toolpath.rows(np.asarray(cl)).frames()
    phi = np.radians(result.phi[row])
    d = np.sin(phi)[:, None] * frames[:, :, 0] + np.cos(phi)[:, None] * frames[:, :, 1]
    points = point_at(arc_length_at(heights, r, psi_max), toolpath.cl[cl][:, None], d[:, None], frames[:, None, :, 2],
                      tool.radius, r, psi_max)
    if frame is not None:
        points = (points - frame[1]) @ frame[0]
    return points


def point_at(s, tip, d, w, radius, corner_radius, psi_max):
    """Points (..., 3) of the peripheral edge at arc length s (...) mm; tip, d, w broadcast (..., 3)."""
    s = np.asarray(s, dtype=float)[..., None]
    r = corner_radius
    on_corner = s <= r * psi_max
    psi = np.where(on_corner, s / (r if r > 0.0 else 1.0), 0.0)
    corner = tip + (radius - r) * d + r * w + r * np.sin(psi) * d - r * np.cos(psi) * w
    side = tip + radius * d + (r + (s - r * psi_max)) * w
    return np.where(on_corner, corner, side)


def profile_intervals(stock, tool, toolpath, phi_deg, terraced=None):
    """EdgeIntervals of the m·p peripheral edges (row i·p + k for CL point i, angle k) in arc length s (mm):
    the corner's (on a Staircase by corner_staircase, on a TerracedStock by corner.py against `terraced`,
    (TerracedStock, pieces), made when None; a Staircase ignores it) and the straight side's (the stock's own
    engine), joined where a run goes on from the corner's top to the side."""
    r, big, length = tool.corner_radius, tool.radius, tool.flute_length
    psi_max = corner_top(tool)
    d = radial_directions(toolpath, phi_deg)
    m, p = d.shape[:2]
    w = np.broadcast_to(toolpath.axes[:, None, :], d.shape).reshape(-1, 3)
    tip = np.broadcast_to(toolpath.cl[:, None, :], d.shape).reshape(-1, 3)
    d = d.reshape(-1, 3)
    parts = []
    if r > 0.0:
        centre = tip + (big - r) * d + r * w
        if isinstance(stock, Staircase):
            parts.append(staircase_corner_intervals(stock, centre, d, w, r, psi_max))
        else:
            terraced, pieces = as_terraced(stock) if terraced is None else terraced
            parts.append(corner_intervals(terraced, centre, d, w, r, psi_max, pieces))
    if length > r:
        side = stock_intervals(stock, tip + big * d + r * w, w, length - r)
        parts.append(_shifted(side, r * psi_max))
    return _joined(m * p, parts)


def corner_top(tool):
    """ψ_max (rad): where the corner arc ends, 90° unless the flute ends within the corner."""
    r, length = tool.corner_radius, tool.flute_length
    if r <= 0.0:
        return 0.0
    return 0.5 * np.pi if length >= r else float(np.arccos(1.0 - length / r))


def stock_intervals(stock, origins, directions, length):
    """EdgeIntervals of N lines in a Staircase or a TerracedStock (engine.stocks' rule, here to stay below it)."""
    if isinstance(stock, Staircase):
        return inside_intervals(stock, origins, directions, length)
    return terraced_intervals(stock, origins, directions, length)


def _shifted(intervals, by):
    """The same intervals moved along the edge by `by` mm."""
    return EdgeIntervals(intervals.n_rows, intervals.rows, intervals.start + by, intervals.end + by,
                         intervals.start_surface, intervals.start_section, intervals.start_wall,
                         intervals.end_surface, intervals.end_section, intervals.end_wall)


def _joined(n, parts):
    """EdgeIntervals of n rows from the corner's and the side's, sorted, touching runs merged (the corner's
    top and the side's start are one place)."""
    found = [(part.rows, part.start, part.end, part.start_surface, part.start_wall, part.end_surface, part.end_wall,
              part.start_section) for part in parts]
    merged = merged_intervals(n, found)
    corner_end = merged.end_surface == CORNER_TOP  # a corner run the side does not continue: the flute ends there
    end_surface = np.where(corner_end, SURFACES.index("flute_end"), merged.end_surface)
    return EdgeIntervals(n, merged.rows, merged.start, merged.end, merged.start_surface, merged.start_section,
                         merged.start_wall, end_surface.astype(np.int8), merged.end_section, merged.end_wall)


def profile_engagement(stock, tool, toolpath, settings, *, chunk_instants=1 << 15, progress=None):
    """The Engagement of a tool with a corner (tool.corner_radius > 0) over a Staircase or a TerracedStock:
    every CL point × angle of settings.phi, in chunks of about `chunk_instants` instants; progress(done, m)
    after each (see the module docstring for what each field holds). The case is "corner" where engaged:
    the paper's Table 1 is for flat-end mills."""
    phi = settings.phi
    m, p = len(toolpath), phi.size
    terraced = None if isinstance(stock, Staircase) else as_terraced(stock, tool.corner_radius)
    out, lep_xyz, uep_xyz = empty_results(m, p)
    labels = {name: np.full((m, p), fill, dtype=dtype) for name, fill, dtype in (
        ("lep_surface", 0, np.int8), ("lep_section", -1, np.int32), ("lep_wall", -1, np.int32))}
    axial = np.zeros((m, p))
    step = max(1, int(chunk_instants) // max(p, 1))
    for start in range(0, m, step):
        stop = min(m, start + step)
        part = toolpath.rows(slice(start, stop))
        chunk = _chunk_results(profile_intervals(stock, tool, part, phi, terraced), part, tool, phi)
        for name, target in (*out.items(), *labels.items(), ("axial", axial), ("lep_xyz", lep_xyz),
                             ("uep_xyz", uep_xyz)):
            target[start:stop] = chunk[name]
        if progress is not None:
            progress(stop, m)
    engagement = finished_engagement(phi, settings, out, lep_xyz, uep_xyz, toolpath.inclinations(settings),
                                     axial=axial, end_length=end_lengths(stock, tool, toolpath, phi))
    return dataclasses.replace(engagement, **labels)


def _chunk_results(found, part, tool, phi):
    """{field: (n, p) array} of the CL points of `part` from their peripheral edges' intervals `found`
    (in s): the Engagement's per-instant fields, the LEP's labels, the LEP and UEP points (n, p, 3) and
    "axial", each instant's engaged extent along the axis (mm; Σ over the runs of the height at the
    end less the height at the start)."""
    n, p = len(part), phi.size
    r, psi_max = tool.corner_radius, corner_top(tool)
    results, lep_xyz, uep_xyz = empty_results(n, p)
    flat = {name: values.reshape(-1) for name, values in results.items()}
    count = found.count
    engaged = np.flatnonzero(count > 0)
    first = np.searchsorted(found.rows, engaged, side="left")
    last = np.searchsorted(found.rows, engaged, side="right") - 1
    flat["length"][:] = found.length
    flat["pieces"][:] = count
    flat["lep_l"][engaged] = height_at(found.start[first], r, psi_max)
    flat["uep_l"][engaged] = height_at(found.end[last], r, psi_max)
    flat["uep_surface"][engaged] = found.end_surface[last]
    flat["uep_section"][engaged] = found.end_section[last]
    flat["uep_wall"][engaged] = found.end_wall[last]
    flat["case"][engaged] = _CORNER_CASE
    labels = {name: np.full(n * p, fill, dtype=dtype) for name, fill, dtype in (
        ("lep_surface", 0, np.int8), ("lep_section", -1, np.int32), ("lep_wall", -1, np.int32))}
    for name, source in (("lep_surface", found.start_surface), ("lep_section", found.start_section),
                         ("lep_wall", found.start_wall)):
        labels[name][engaged] = source[first]
    axial = np.bincount(found.rows, weights=height_at(found.end, r, psi_max) - height_at(found.start, r, psi_max),
                        minlength=n * p)
    d = radial_directions(part, phi).reshape(-1, 3)[engaged]
    w = np.repeat(part.axes, p, axis=0)[engaged]
    tip = np.repeat(part.cl, p, axis=0)[engaged]
    points = {}
    for name, s, target in (("lep_xyz", found.start[first], lep_xyz), ("uep_xyz", found.end[last], uep_xyz)):
        flat_points = target.reshape(-1, 3)
        flat_points[engaged] = point_at(s, tip, d, w, tool.radius, r, psi_max)
        points[name] = target
    return {**results, **{name: values.reshape(n, p) for name, values in labels.items()},
            "axial": axial.reshape(n, p), **points}
