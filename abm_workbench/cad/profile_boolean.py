"""The boolean reference for the whole cutting edge of any milling tool: corner arc, straight side, end edge.

At each CL point the edges of every rotation angle φ (:mod:`.profile_edges`: the corner arc as a true
circular arc, the straight side and the end edge as segments, built from the tool's definition alone, not by
the engine's code) go into ONE ``shape.common([edges])`` with the stock cut to the box of those edges grown
by a margin (:func:`local_stock`: the box's faces keep clear of every edge, so only the time changes), done
twice with two margins that must agree (:func:`edge_intervals` says how a disagreement is settled). Each
edge of the result is mapped back to the edge it lies on (its middle within ON_EDGE_TOL of it), and its two
ends give its range on that edge: the angle ψ
about the corner's centre (arc length s = r·ψ), the height along the side, the distance from the tip along
the end edge. Per instant the peripheral edge's pieces (corner and side, in s, joined where a run goes on
from the corner's top up the side) give the length of cut (mm of s), LEP and UEP (heights along the axis
above the tip of the lowest start and the highest end) and their points; the end edge's pieces its
engaged length. Lengths in mm, φ in degrees.

For a flat-end mill the peripheral edge is the side line alone, which cad.boolean already sections:
:func:`flat_lengths_by_boolean` keeps that reference's arrays bit for bit and adds the end edge's;
:func:`flat_lengths_in_process` does the same for cad.inprocess_boolean's reference against the in-process
stock. A tool with a corner is checked against the in-process stock by cad.corner_inprocess.
"""

import numpy as np

from ..engine import Tool, Toolpath, edge_lines
from .boolean import PIECE_EPS, _distinct_angles, _inside_intervals, _merged
from .freecad_env import FreeCAD, Part
from .inprocess_boolean import (BOX_SLACK, ProgramSweep, _filled, _minus, _near_tool, _piece_boxes, hull_parts,
                                inprocess_sections)
from .profile_edges import EdgeGeometry, edge_shapes, segment_shape, tool_frames

#: A result edge's middle must lie within this distance (mm) of the edge it is mapped to.
ON_EDGE_TOL = 1e-6
#: The stock is first cut to the box of a CL point's edges grown by this (mm), whose faces then stay this far
#: from every edge: OpenCASCADE sections an arc with a trimmed B-spline wall many times faster than with the
#: whole wall (measured 11.8 s against 1.9 s for 91 arcs at a CL point of model test 5).
LOCAL_MARGIN = 1.0
def _angles(phi_deg):
    phi = np.atleast_1d(np.asarray(phi_deg, dtype=float))
    if phi.ndim != 1 or not np.isfinite(phi).all():
        raise ValueError(f"phi_deg must be finite angles of shape (p,), got shape {phi.shape}")
    return phi


def profile_lengths_by_boolean(shape, tool: Tool, toolpath: Toolpath, phi_deg, progress=None):
    """Engagement of every CL point × φ of any tool (flat-end, bull-nose, ball) by booleans with `shape`.

    phi_deg: (p,) rotation angles (deg). Returns a dict of (m, p) arrays: length (engaged arc length along the
    peripheral edge, mm), lep_l and uep_l (heights along the axis above the tip of the lowest and highest
    engaged points of the peripheral edge, mm; NaN without engagement), pieces (its inside runs, int),
    corner_length (the part of `length` on the corner arc, mm), end_length (engaged length of the end edge,
    mm; 0 for a ball), end_pieces (int); (m, p, 3) lep_xyz, uep_xyz (the LEP and UEP points, mm; NaN
    without engagement); and (m,) disputed, the edges of each CL point on which the two local booleans
    disagreed and the whole stock decided (edge_intervals). progress(done, total) after each CL point.
    """
    phi = _angles(phi_deg)
    distinct, source = _distinct_angles(phi)
    frames = tool_frames(toolpath)
    parts = []
    for i in range(len(toolpath)):
        geometry = EdgeGeometry.of(tool, toolpath.cl[i], frames[i], distinct)
        disputes = []
        parts.append({**_instant_arrays(geometry, edge_intervals(shape, geometry, disputes=disputes), source),
                      "disputed": len(disputes)})
        if progress is not None:
            progress(i + 1, len(toolpath))
    return {name: np.array([part[name] for part in parts]) for name in parts[0]}


def edge_intervals(shape, geometry: EdgeGeometry, shapes=None, local=True, disputes=None):
    """{kind: q lists of merged (start, end) intervals} of the edges of `geometry` inside `shape`: "arc" in
    arc length s = r·ψ from the corner's start, "side" in height above the side's start (height − r), "end" in
    distance from the tip; only the kinds the tool has. shapes: the edge_shapes to section (default:
    edge_shapes(geometry)), for a test to plant an error in.

    local False: one boolean with the whole `shape`. local True (faster on B-spline walls): two booleans, with
    the stock cut to the edges' box grown by LOCAL_MARGINS[0] and by LOCAL_MARGINS[1] (local_stock), which
    must agree (within SAME_RESULT mm). OpenCASCADE was seen to keep a piece of an edge that lies outside the
    solid for one such box and not for others (1 edge of 94 794 in model test 5): an edge on which the two
    disagree is sectioned with the whole stock, and the result two of the three give is taken; where all
    three differ, the states of the pieces between all their breakpoints are decided by the point classifier
    (Part.Shape.isInside at each piece's middle) on the whole stock. disputes: a list to which one entry
    (kind, k) is appended per edge so settled."""
    shapes = edge_shapes(geometry) if shapes is None else shapes
    if not local:
        return _sectioned(shape, geometry, shapes)
    edges = [edge for _, _, edge in shapes]
    results = [_sectioned(local_stock(shape, edges, margin), geometry, shapes) for margin in LOCAL_MARGINS]
    disputed = [(kind, k) for kind in results[0] for k in range(len(geometry.d))
                if not _same(results[0][kind][k], results[1][kind][k])]
    if not disputed:
        return results[0]
    chosen = [item for item in shapes if (item[0], item[1]) in disputed]
    whole = _sectioned(shape, geometry, chosen)
    found = results[0]
    for kind, k in disputed:
        if disputes is not None:
            disputes.append((kind, k))
        if _same(whole[kind][k], results[0][kind][k]) or _same(whole[kind][k], results[1][kind][k]):
            found[kind][k] = whole[kind][k]
        else:
            found[kind][k] = _classified(shape, geometry, kind, k, [results[0][kind][k], results[1][kind][k],
                                                                    whole[kind][k]])
    return found


#: Margins (mm) of the two local stocks whose booleans must agree (edge_intervals).
LOCAL_MARGINS = (LOCAL_MARGIN, 1.618 * LOCAL_MARGIN)
#: Two results of one edge are the same when their pieces' ends agree within this (mm).
SAME_RESULT = 1e-9
#: Points this close (mm) to the stock's boundary count as inside for the point classifier.
CLASSIFY_TOL = 1e-9


def _same(first, second):
    """Whether two merged interval lists are the same within SAME_RESULT."""
    return len(first) == len(second) and all(abs(a - c) <= SAME_RESULT and abs(b - e) <= SAME_RESULT
                                             for (a, b), (c, e) in zip(first, second))


def _edge_length(geometry: EdgeGeometry, kind):
    return {"arc": geometry.corner_length, "side": geometry.side_length, "end": geometry.end_length}[kind]


def _edge_point(geometry: EdgeGeometry, kind, k, t):
    """(3,) the point at position t (mm, in the edge's own coordinate) on edge (kind, k)."""
    if kind == "arc":
        return geometry.points(k, [t])[0]
    if kind == "side":
        return geometry.points(k, [geometry.corner_length + t])[0]
    return geometry.tip + t * geometry.d[k]


def _classified(shape, geometry: EdgeGeometry, kind, k, candidates):
    """Merged intervals of edge (kind, k) inside `shape` by the point classifier: the edge cut at every
    breakpoint of the candidate results, each piece (longer than PIECE_EPS) inside when its middle is."""
    cuts = sorted({0.0, _edge_length(geometry, kind)} | {t for found in candidates for piece in found for t in piece})
    inside = []
    for a, b in zip(cuts[:-1], cuts[1:]):
        if b - a >= PIECE_EPS and shape.isInside(FreeCAD.Vector(*_edge_point(geometry, kind, k, 0.5 * (a + b))),
                                                  CLASSIFY_TOL, True):
            inside.append((a, b))
    return _merged(inside)


def _sectioned(shape, geometry: EdgeGeometry, shapes):
    """{kind: q lists of merged intervals} of the edges `shapes` (edge_shapes items) inside `shape` (None:
    nothing), by one boolean; each result edge mapped back to the edge its middle lies on."""
    q = len(geometry.d)
    found = {kind: [[] for _ in range(q)] for kind in geometry.kinds}
    if not shapes or shape is None:
        return found
    for edge in shape.common([edge for _, _, edge in shapes]).Edges:
        first, last = edge.ParameterRange
        ends = np.array([tuple(edge.valueAt(first)), tuple(edge.valueAt(last))])
        if np.linalg.norm(ends[1] - ends[0]) < PIECE_EPS:
            continue
        middle = np.array(tuple(edge.valueAt(0.5 * (first + last))))
        kind, k, distance = _nearest_edge(geometry, middle)
        if distance > ON_EDGE_TOL:
            raise RuntimeError(f"a boolean result edge lies on no cutting edge (nearest {distance:.3g} mm away)")
        start, end = np.sort(_coordinates(geometry, kind, k, ends))
        found[kind][k].append((float(start), float(end)))
    return {kind: [_merged(pieces) for pieces in lists] for kind, lists in found.items()}


def local_stock(shape, edges, margin=LOCAL_MARGIN):
    """The part of `shape` inside the box of `edges` (Part.Edges) grown by `margin` mm (one boolean), or None
    when nothing of it is there; `shape` itself when OpenCASCADE gives an invalid part. The box's faces stay
    `margin` from every edge, so the edges' sections with it are those with `shape`."""
    box = Part.Compound(edges).BoundBox
    box.enlarge(margin)
    if not box.intersect(shape.BoundBox):
        return None
    cube = Part.makeBox(box.XLength, box.YLength, box.ZLength, FreeCAD.Vector(box.XMin, box.YMin, box.ZMin))
    local = shape.common(cube)
    if local.isNull() or not local.isValid():
        return shape
    return local if local.Solids else None


def _nearest_edge(geometry: EdgeGeometry, point):
    """(kind, k, distance mm): the edge of `geometry` nearest to `point` (3,)."""
    best = ("", -1, np.inf)
    for kind in geometry.kinds:
        if kind == "arc":
            offset = point - geometry.centres
            psi = np.clip(np.arctan2(np.einsum("ij,ij->i", offset, geometry.d), -(offset @ geometry.w)),
                          0.0, geometry.psi_max)
            nearest = geometry.centres + geometry.corner * (np.sin(psi)[:, None] * geometry.d
                                                            - np.cos(psi)[:, None] * geometry.w)
        elif kind == "side":
            along = np.clip((point - geometry.side_start) @ geometry.w, 0.0, geometry.side_length)
            nearest = geometry.side_start + along[:, None] * geometry.w
        else:
            along = np.clip(geometry.d @ (point - geometry.tip), 0.0, geometry.end_length)
            nearest = geometry.tip + along[:, None] * geometry.d
        distance = np.linalg.norm(nearest - point, axis=1)
        k = int(np.argmin(distance))
        if distance[k] < best[2]:
            best = (kind, k, float(distance[k]))
    return best


def _coordinates(geometry: EdgeGeometry, kind, k, points):
    """(n,) positions of points (n, 3) on edge (kind, k): s = r·ψ on the arc, height above the side's start,
    distance from the tip along the end edge; clipped to the edge."""
    if kind == "arc":
        offset = points - geometry.centres[k]
        psi = np.arctan2(offset @ geometry.d[k], -(offset @ geometry.w))
        return geometry.corner * np.clip(psi, 0.0, geometry.psi_max)
    if kind == "side":
        return np.clip((points - geometry.side_start[k]) @ geometry.w, 0.0, geometry.side_length)
    return np.clip((points - geometry.tip) @ geometry.d[k], 0.0, geometry.end_length)


def peripheral_runs(geometry: EdgeGeometry, found, k):
    """The merged runs (s_start, s_end) of the peripheral edge of angle k (mm of arc length): the corner's
    intervals and the side's shifted by the corner's length, joined where they touch."""
    pieces = list(found.get("arc", [[]] * (k + 1))[k])
    pieces += [(a + geometry.corner_length, b + geometry.corner_length) for a, b in found.get("side", [[]] * (k + 1))[k]]
    return _merged(pieces)


def _instant_arrays(geometry: EdgeGeometry, found, source):
    """{name: (p,) or (p, 3) array} of one CL point from the intervals `found` at its q distinct angles;
    angle j of the pass takes distinct angle source[j]."""
    q = len(geometry.d)
    out = {"length": np.zeros(q), "lep_l": np.full(q, np.nan), "uep_l": np.full(q, np.nan),
           "pieces": np.zeros(q, dtype=int), "corner_length": np.zeros(q), "end_length": np.zeros(q),
           "end_pieces": np.zeros(q, dtype=int), "lep_xyz": np.full((q, 3), np.nan),
           "uep_xyz": np.full((q, 3), np.nan)}
    for k in range(q):
        runs = peripheral_runs(geometry, found, k)
        if runs:
            out["length"][k] = sum(b - a for a, b in runs)
            out["pieces"][k] = len(runs)
            s = np.array([runs[0][0], runs[-1][1]])
            out["lep_l"][k], out["uep_l"][k] = geometry.height(s)
            out["lep_xyz"][k], out["uep_xyz"][k] = geometry.points(k, s)
            out["corner_length"][k] = sum(b - a for a, b in found.get("arc", [[]] * q)[k])
        end = found.get("end", [[]] * q)[k]
        out["end_length"][k] = sum(b - a for a, b in end)
        out["end_pieces"][k] = len(end)
    return {name: values[source] for name, values in out.items()}


# ---- flat-end mills: cad.boolean's reference, and the end edge ----------------------------------

def _end_geometry(tool: Tool, toolpath: Toolpath, frames, i, distinct):
    return EdgeGeometry.of(tool, toolpath.cl[i], frames[i], distinct)


def end_sections(shape, geometry: EdgeGeometry):
    """q lists of merged (start, end) intervals (mm from the tip) of the end edges of `geometry` inside
    `shape`, by one boolean with the whole `shape` as cad.boolean sections the side lines (empty lists for a
    ball)."""
    if "end" not in geometry.kinds:
        return [[] for _ in geometry.d]
    shapes = [item for item in edge_shapes(geometry) if item[0] == "end"]
    return edge_intervals(shape, geometry, shapes, local=False)["end"]


def _end_arrays(pieces, source):
    """{end_length, end_pieces}: (p,) arrays of the end edges' intervals at the distinct angles."""
    length = np.array([sum(b - a for a, b in found) for found in pieces])
    count = np.array([len(found) for found in pieces], dtype=int)
    return {"end_length": length[source], "end_pieces": count[source]}


def flat_lengths_by_boolean(shape, tool: Tool, toolpath: Toolpath, phi_deg, progress=None):
    """cad.boolean.edge_lengths_by_boolean's dict (length, lep_l, uep_l along the side line, pieces: the
    same calls, so the same values bit for bit), plus end_length and end_pieces (m, p) of the end edges, by
    a second boolean per CL point. For a flat-end mill (corner radius 0). progress(done, total) after each
    CL point."""
    if tool.corner_radius > 0.0:
        raise ValueError("flat_lengths_by_boolean is for flat-end mills; use profile_lengths_by_boolean")
    phi = _angles(phi_deg)
    distinct, source = _distinct_angles(phi)
    base, direction = edge_lines(toolpath, tool, distinct)
    frames = tool_frames(toolpath)
    parts = []
    for i in range(len(toolpath)):
        part = _filled(_inside_intervals(shape, base[i], direction[i], tool.flute_length), source)
        part.update(_end_arrays(end_sections(shape, _end_geometry(tool, toolpath, frames, i, distinct)), source))
        parts.append(part)
        if progress is not None:
            progress(i + 1, len(toolpath))
    return {name: np.array([part[name] for part in parts]) for name in parts[0]}


def flat_lengths_in_process(shape, tool: Tool, toolpath: Toolpath, phi_deg, sweep: ProgramSweep, progress=None):
    """cad.inprocess_boolean.edge_lengths_in_process's dict (length, lep_l, uep_l, pieces, swept: the same
    calls, bit for bit), plus end_length and end_pieces (m, p): the end edges inside the stock `shape` and in
    none of the volumes the earlier moves near the tool swept (end_sections_in_process). Flat-end mills."""
    if tool.corner_radius > 0.0:
        raise ValueError("flat_lengths_in_process is for flat-end mills; use corner_inprocess.corner_lengths_in_process")
    phi = _angles(phi_deg)
    distinct, source = _distinct_angles(phi)
    base, direction = edge_lines(toolpath, tool, distinct)
    frames = tool_frames(toolpath)
    rows = sweep.rows_of(toolpath)
    parts = []
    for i, row in enumerate(rows):
        chosen, _ = _near_tool(sweep.pieces, row, tool, toolpath, i)
        found = inprocess_sections(shape, sweep.pieces, chosen, base[i], direction[i], tool.flute_length)
        part = {**_filled(found, source), "swept": len(chosen)}
        geometry = _end_geometry(tool, toolpath, frames, i, distinct)
        part.update(_end_arrays(end_sections_in_process(shape, sweep.pieces, chosen, geometry), source))
        parts.append(part)
        if progress is not None:
            progress(i + 1, len(rows))
    return {name: np.array([part[name] for part in parts]) for name in parts[0]}


def end_sections_in_process(stock_solid, pieces, chosen, geometry: EdgeGeometry):
    """q lists of merged intervals (mm from the tip) of the end edges of `geometry` inside `stock_solid`
    and inside none of the swept volumes of pieces `chosen` (cad.inprocess_boolean.hull_parts of each), as
    inprocess_sections does for side lines: the stock's sections (one boolean), then, piece by piece from the
    nearest to the tip, each hull part sectioned (one boolean) with the stretches of the edges still left
    whose boxes meet its own, and what lies inside it taken away. Edges left empty drop out, so the pieces
    that remove the most go first and the later ones meet fewer edges."""
    kept = end_sections(stock_solid, geometry)
    if not any(kept) or len(chosen) == 0:
        return kept
    chosen = np.asarray(chosen)
    middle = 0.5 * (pieces.c0[chosen] + pieces.c1[chosen]) + 0.5 * pieces.height[chosen, None] * pieces.axis[chosen]
    chosen = chosen[np.argsort(np.linalg.norm(middle - geometry.tip, axis=1), kind="stable")]
    piece_low, piece_high = _piece_boxes(pieces, chosen)
    for i, p_low, p_high in zip(chosen, piece_low, piece_high):
        active = [k for k, found in enumerate(kept) if found]
        if not active:
            break
        stretch = np.array([(kept[k][0][0], kept[k][-1][1]) for k in active])
        starts = geometry.tip + stretch[:, :1] * geometry.d[active]
        stops = geometry.tip + stretch[:, 1:] * geometry.d[active]
        low, high = np.minimum(starts, stops) - BOX_SLACK, np.maximum(starts, stops) + BOX_SLACK
        if not ((low <= p_high) & (high >= p_low)).all(axis=1).any():
            continue
        for part in hull_parts(pieces.c0[i], pieces.c1[i], pieces.axis[i], pieces.radius[i], pieces.height[i]):
            box = part.BoundBox
            meets = np.flatnonzero(((low <= [box.XMax, box.YMax, box.ZMax]) &
                                    (high >= [box.XMin, box.YMin, box.ZMin])).all(axis=1))
            if meets.size == 0:
                continue
            edges = [active[j] for j in meets]
            removed = _segment_sections(part, geometry.tip, geometry.d[edges], stretch[meets])
            for k, found in zip(edges, removed):
                if found:
                    kept[k] = _minus(kept[k], _merged(found))
    return kept


def _segment_sections(shape, tip, directions, stretches):
    """Per segment tip + t·directions[j], stretches[j, 0] ≤ t ≤ stretches[j, 1] (all from one point `tip`,
    mm), the (t_start, t_end) pieces of it inside `shape`, by one boolean; each result edge is mapped to the
    segment its middle lies on (within ON_EDGE_TOL)."""
    segments = [segment_shape(tip + a * u, tip + b * u) for u, (a, b) in zip(directions, stretches)]
    found = [[] for _ in segments]
    for edge in shape.common(segments).Edges:
        first, last = edge.ParameterRange
        ends = np.array([tuple(edge.valueAt(first)), tuple(edge.valueAt(last))])
        if np.linalg.norm(ends[1] - ends[0]) < PIECE_EPS:
            continue
        middle = 0.5 * (ends[0] + ends[1]) - tip
        along = directions @ middle
        distance = np.linalg.norm(middle - along[:, None] * directions, axis=1)
        distance = np.where((along >= stretches[:, 0] - ON_EDGE_TOL) & (along <= stretches[:, 1] + ON_EDGE_TOL),
                            distance, np.inf)
        j = int(np.argmin(distance))
        if distance[j] > ON_EDGE_TOL:
            raise RuntimeError(f"a boolean result edge lies on no end edge (nearest {distance[j]:.3g} mm away)")
        positions = np.sort((ends - tip) @ directions[j])
        found[j].append((float(positions[0]), float(positions[1])))
    return found

