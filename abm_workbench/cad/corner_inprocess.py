"""The boolean reference of a bull-nose or ball-end mill against the in-process stock.

At each CL point every cutting edge of the tool (profile_edges: corner arcs as true arcs, straight sides,
end edges) is sectioned with the stock as given (profile_boolean.edge_intervals), then with the volume
each earlier piece near the tool swept (corner_sweep.sweep_parts: exact solids, each sectioned alone, one
boolean per solid with the edges whose boxes meet its own); what lies in a piece's volume (inside one of
its `union` solids and, for a ball's ramp, inside one of its `column` solids) is taken away. The pieces are
those of cad.inprocess_boolean's reference (its _near_tool): the same constant-axis sub-steps as the
engine's swept_pieces. Lengths in mm, angles in degrees.

A piece whose volume has no such solids (corner_sweep.move_kind "gauge": a bull-nose mill's nearly flat
ramp, an oblique move of a tool shorter than its corner radius, or solids OpenCASCADE failed to build) is
decided by the exact inside test instead (sweep_membership.exact_intervals); "gauged" counts such pieces.
That test first asks of every piece whether it meets what is left of the edges at all: a piece it finds apart
from them is not built nor sectioned ("apart" counts them), and OpenCASCADE sections only the edges it meets.
Both are exact, so this changes no result; it spares the booleans of the many pieces near the tool that take
nothing more (most of them, once the nearest pieces have taken what they swept).
"""

import numpy as np

from ..engine import Tool, Toolpath
from .boolean import _distinct_angles, _merged
from .corner_sweep import NotExactError, move_kind, sweep_parts
from .inprocess_boolean import BOX_SLACK, ProgramSweep, _minus, _near_tool, _piece_boxes
from .profile_boolean import _angles, _instant_arrays, _sectioned, edge_intervals
from .profile_edges import EdgeGeometry, edge_shapes, tool_frames
from .sweep_membership import exact_intervals


def _intersected(first, second):
    """The intersection of two merged interval lists (merged)."""
    out = []
    for a, b in first:
        for c, d in second:
            start, end = max(a, c), min(b, d)
            if end > start:
                out.append((start, end))
    return _merged(out)


def _inside_parts(solids, geometry: EdgeGeometry, shapes, boxes):
    """{(kind, k): merged intervals} of the edges `shapes` (edge_shapes items) inside the union of `solids`:
    each solid sectioned alone (one boolean with the edges whose boxes (low, high (n, 3)) meet its own)."""
    found = {}
    low, high = boxes
    for solid in solids:
        box = solid.BoundBox
        meets = np.flatnonzero(((low <= [box.XMax, box.YMax, box.ZMax]) &
                                (high >= [box.XMin, box.YMin, box.ZMin])).all(axis=1))
        if meets.size == 0:
            continue
        chosen = [shapes[j] for j in meets]
        for kind, lists in _sectioned(solid, geometry, chosen).items():
            for k, pieces in enumerate(lists):
                if pieces:
                    found.setdefault((kind, k), []).extend(pieces)
    return {key: _merged(pieces) for key, pieces in found.items()}


def _edge_boxes(shapes):
    """(low, high) (n, 3): the edges' bounding boxes grown by BOX_SLACK (mm)."""
    boxes = [shape.BoundBox for _, _, shape in shapes]
    low = np.array([[b.XMin, b.YMin, b.ZMin] for b in boxes]) - BOX_SLACK
    high = np.array([[b.XMax, b.YMax, b.ZMax] for b in boxes]) + BOX_SLACK
    return low, high


def swept_away(found, geometry: EdgeGeometry, pieces, chosen, parts=sweep_parts, gauged=None, apart=None):
    """`found` ({kind: q lists of merged intervals}, the edges inside the stock) less what lies in the
    volumes pieces `chosen` (k,) swept, nearest piece to the tip first; edges left empty drop out. parts:
    the function building a piece's SweptParts (a test plants an error in it); gauged: a list that gets
    (piece, undecided) for each piece decided by the exact inside test; apart: a list that gets each piece
    the exact test finds apart from what is left of the edges, which OpenCASCADE then does not section
    (module docstring)."""
    chosen = np.asarray(chosen, dtype=int)
    if chosen.size == 0:
        return found
    middle = 0.5 * (pieces.c0[chosen] + pieces.c1[chosen]) + 0.5 * pieces.height[chosen, None] * pieces.axis[chosen]
    chosen = chosen[np.argsort(np.linalg.norm(middle - geometry.tip, axis=1), kind="stable")]
    piece_low, piece_high = _piece_boxes(pieces, chosen)
    every = edge_shapes(geometry)
    for i, p_low, p_high in zip(chosen, piece_low, piece_high):
        shapes = [item for item in every if found[item[0]][item[1]]]
        if not shapes:
            break
        low, high = _edge_boxes(shapes)
        near = ((low <= p_high) & (high >= p_low)).all(axis=1)
        if not near.any():
            continue
        shapes = [item for item, keep in zip(shapes, near) if keep]
        boxes = (low[near], high[near])
        piece = (pieces.c0[i], pieces.c1[i], pieces.axis[i], pieces.radius[i], pieces.corner[i], pieces.height[i])
        inside, undecided = exact_intervals(geometry, {(kind, k): found[kind][k] for kind, k, _ in shapes}, piece)
        touched = np.array([bool(inside[(kind, k)]) for kind, k, _ in shapes])
        if not touched.any():
            if apart is not None:
                apart.append(int(i))
            continue
        try:
            swept = None if move_kind(*piece) == "gauge" else parts(*piece)
        except NotExactError:
            swept = None
        if swept is None:
            if gauged is not None:
                gauged.append((int(i), undecided))
        else:
            shapes = [item for item, keep in zip(shapes, touched) if keep]
            boxes = (boxes[0][touched], boxes[1][touched])
            inside = _inside_parts(swept.union, geometry, shapes, boxes)
            if swept.column is not None and inside:
                column = _inside_parts(swept.column, geometry, shapes, boxes)
                inside = {key: _intersected(value, column.get(key, [])) for key, value in inside.items()}
        for (kind, k), removed in inside.items():
            if removed:
                found[kind][k] = _minus(found[kind][k], removed)
    return found


def corner_lengths_in_process(shape, tool: Tool, toolpath: Toolpath, phi_deg, sweep: ProgramSweep, progress=None,
                              parts=sweep_parts):
    """profile_boolean.profile_lengths_by_boolean's dict (m, p) against the in-process stock: at each CL
    point of `toolpath` (a part of sweep.toolpath) the edges inside the stock `shape` (Part.Shape) and in
    none of the volumes the earlier pieces near the tool swept (swept_away); plus "swept" (m,) int, the
    pieces met at each CL point, "gauged" (m,) int, those of them decided by the exact inside test,
    "undecided" (m,) int, the pieces of edges that test left undecided (sweep_membership.BUDGET), and
    "apart" (m,) int, the pieces that test found apart from what was left of the edges. For tools
    with a corner radius. progress(done, total) after each CL point; parts: as swept_away."""
    if tool.corner_radius <= 0.0:
        raise ValueError("corner_lengths_in_process is for tools with a corner radius; flat-end mills have "
                         "profile_boolean.flat_lengths_in_process")
    phi = _angles(phi_deg)
    distinct, source = _distinct_angles(phi)
    frames = tool_frames(toolpath)
    rows = sweep.rows_of(toolpath)
    out = []
    for i, row in enumerate(rows):
        chosen, _ = _near_tool(sweep.pieces, row, tool, toolpath, i)
        geometry = EdgeGeometry.of(tool, toolpath.cl[i], frames[i], distinct)
        disputes, gauged, apart = [], [], []
        found = swept_away(edge_intervals(shape, geometry, disputes=disputes), geometry, sweep.pieces, chosen, parts,
                           gauged, apart)
        out.append({**_instant_arrays(geometry, found, source), "disputed": len(disputes), "swept": len(chosen),
                    "gauged": len(gauged), "undecided": sum(count for _, count in gauged), "apart": len(apart)})
        if progress is not None:
            progress(i + 1, len(rows))
    return {name: np.array([part[name] for part in out]) for name in out[0]}
