"""The in-process stock by OpenCASCADE: the stock solid cut by the volumes earlier moves swept.

It mirrors engine.inprocess with booleans. Each constant-axis piece of a cutting move (the same
pieces engine.inprocess.swept_pieces makes: a move whose axis turns is cut into sub-steps) is
built as an exact solid: a flat-end mill's the convex hull of its two end cylinders (hull_solids), a
corner tool's its corner_sweep solids.

validate's reference against the in-process stock (edge_lengths_in_process) sections each edge
segment with the stock and with each of those solids of the pieces near the tool, and keeps what
lies in the stock and in none of them (inprocess_sections); inprocess_solid, the stock actually cut
by the fused hulls, costs OpenCASCADE seconds per piece and serves small checks. Lengths in mm.
"""

from dataclasses import dataclass

import numpy as np

from ..engine import Tool, Toolpath, edge_lines
from ..engine.inprocess import SweptPieces, swept_pieces
from .boolean import _distinct_angles, _inside_intervals, _merged
from .corner_sweep import swept_solid
from .freecad_env import Part
from .hull_solids import hull_parts, hull_solid
from .sweep_membership import curve_intervals

#: The local stock around a CL point is the stock inside the tool's bounding box grown by this (mm).
BOX_MARGIN = 1.0
#: Stock left between two swept solids that meet (OpenCASCADE puts their common face within its
#: 1e-7 mm confusion of each other) is shorter than this (mm) and dropped.
SLIVER = 1e-6
#: Boxes that come within this (mm) of each other are taken to meet (room for rounding).
BOX_SLACK = 1e-6


def pieces_near(pieces: SweptPieces, upto, centre, reach):
    """(k,) indices of the pieces of moves ending at or before program row upto − 1 whose bounding
    sphere comes within `reach` mm of `centre` (3,) mm: every piece that can touch a body inside
    that ball."""
    piece_centre = 0.5 * (pieces.c0 + pieces.c1) + 0.5 * pieces.height[:, None] * pieces.axis
    piece_bound = 0.5 * np.linalg.norm(pieces.c1 - pieces.c0, axis=1) + np.hypot(pieces.radius, 0.5 * pieces.height)
    gap = np.linalg.norm(piece_centre - np.asarray(centre, dtype=float), axis=1) - piece_bound
    return np.flatnonzero((pieces.move <= upto - 1) & (gap <= reach))


#: The arrays of :func:`hulls_of`, each (k,) or (k, 3): the pieces' swept volumes as cut_by_hulls builds them
#: (and "corner", the corner radius, when a piece has one).
HULL_FIELDS = ("c0", "c1", "axis", "radius", "height")


def hulls_of(pieces: SweptPieces, chosen):
    """{c0, c1, axis, radius, height[, corner]}: the arrays of pieces `chosen` (k,), all cut_by_hulls needs
    (plain numpy, so a worker process gets them without the program's pieces); corner when a piece has a
    corner radius."""
    chosen = np.asarray(chosen, dtype=int)
    hulls = {name: np.array(getattr(pieces, name)[chosen]) for name in HULL_FIELDS}
    if (pieces.corner[chosen] > 0.0).any():
        hulls["corner"] = np.array(pieces.corner[chosen])
    return hulls


def cut_by_hulls(stock_solid, hulls, progress=None):
    """`stock_solid` (Part.Shape) minus the hull solids of the pieces `hulls` (hulls_of), fused first (a corner
    tool's piece too: the flat-end hull holds its volume; fusing hundreds of exact corner solids took
    OpenCASCADE more than ten minutes on model test 5); the solid itself when there is none.
    progress(done, total): after each hull solid, the fuse and the cut."""
    return _cut_counted(stock_solid, hulls, progress)[0]


def _cut_counted(stock_solid, hulls, progress=None):
    """(cut_by_hulls's shape, outlined): outlined, the pieces of a tool with a corner (cut as the flat-end hull
    that holds their volume)."""
    count = len(hulls["radius"])
    if count == 0:
        return stock_solid, 0
    total = count + 2
    corner = hulls.get("corner", np.zeros(count))
    tools, outlined = [], int((corner > 0.0).sum())
    for i in range(count):
        tools.append(hull_solid(*(hulls[name][i] for name in HULL_FIELDS)))
        if progress is not None:
            progress(i + 1, total)
    removal = tools[0].multiFuse(tools[1:]) if len(tools) > 1 else tools[0]
    if progress is not None:
        progress(count + 1, total)
    cut = stock_solid.cut(removal)
    if progress is not None:
        progress(total, total)
    return cut, int(outlined)


def cut_and_removed(stock_solid, hulls, progress=None):
    """(cut_by_hulls(stock_solid, hulls), the volume it removed (mm³), the pieces of a tool with a corner cut as
    the flat-end hull that holds them): all computed where the booleans run (OpenCASCADE's volume of a cut
    B-spline solid takes a fraction of a second)."""
    cut, outlined = _cut_counted(stock_solid, hulls, progress)
    return cut, stock_solid.Volume - cut.Volume, outlined


def cut_by_pieces(stock_solid, pieces: SweptPieces, chosen):
    """`stock_solid` (Part.Shape) minus the hull solids of pieces `chosen` (k,), fused first; the
    solid itself when none is chosen."""
    return cut_by_hulls(stock_solid, hulls_of(pieces, chosen))


def hulls_near(moves, upto, near=None, tolerance=0.05):
    """hulls_of the pieces inprocess_solid cuts the stock by (same arguments, without the stock)."""
    moves, pieces = moves if isinstance(moves, tuple) else (moves, swept_pieces(moves, tolerance))
    upto = int(upto)
    radius, height = moves.radius[upto], moves.flute_length[upto]
    centre = moves.cl[upto] + 0.5 * height * moves.axis[upto]
    reach = np.hypot(radius, 0.5 * height) if near is None else float(near)
    return hulls_of(pieces, pieces_near(pieces, upto, centre, reach))


def inprocess_solid(stock_solid, moves, upto, near=None, tolerance=0.05):
    """The stock solid cut by the volumes of the cutting moves that end at or before program
    row upto − 1 (ProgramMoves `moves`, or its SweptPieces with `moves` then given as
    (moves, pieces)), restricted to those near the tool at row `upto` (bounding spheres within
    `near` mm of the tool's; default: touching the tool's own bounding sphere). Part.Shape."""
    return cut_by_hulls(stock_solid, hulls_near(moves, upto, near, tolerance))


def inprocess_lengths(stock_solid, moves, upto, origins, direction, length, near=None, tolerance=0.05):
    """Edge lines of the tool at program row `upto` against inprocess_solid, by one boolean.

    origins: (p, 3) points at l = 0; direction: (3,) unit, shared; length: flute length (mm).
    Returns a dict of (p,) arrays: length (inside length, mm), lep_l, uep_l (first start, last
    end; NaN without engagement), pieces (int), and "solid": the in-process solid used.
    """
    solid = inprocess_solid(stock_solid, moves, upto, near, tolerance)
    origins = np.asarray(origins, dtype=float).reshape(-1, 3)
    found = _inside_intervals(solid, origins, np.asarray(direction, dtype=float), float(length))
    return {**_filled(found, range(len(found))), "solid": solid}


@dataclass(frozen=True)
class ProgramSweep:
    """What the in-process reference of a pass needs besides the stock: pieces, the SweptPieces of
    the whole program (in the pass's frame); rows (m,) int, the program row of each CL point of the
    pass; toolpath, the whole pass (m CL points), in which a part of it is found again by its values
    (a worker is handed CL points without their index)."""

    pieces: SweptPieces
    rows: np.ndarray
    toolpath: Toolpath

    def rows_of(self, part: Toolpath):
        """(n,) program rows of the n consecutive CL points `part` of the pass. ValueError when the
        part is not found in the pass, or found at several places (an exact repeat of CL points)."""
        whole, n = self.toolpath, len(part)
        columns = [(whole.cl, part.cl)] + [(getattr(whole, name)[:, None], getattr(part, name)[:, None])
                                           for name in ("theta_a", "theta_b", "alpha")]
        starts = np.arange(len(whole) - n + 1)
        for offset in range(n):
            keep = np.ones(starts.size, dtype=bool)
            for mine, theirs in columns:
                keep &= (mine[starts + offset] == theirs[offset]).all(axis=1)
            starts = starts[keep]
        if starts.size != 1:
            raise ValueError(f"the {n} CL points are found {starts.size} times in the pass of {len(whole)}; "
                             "the in-process reference needs them once")
        return np.asarray(self.rows)[starts[0]:starts[0] + n]


def inprocess_sections(stock_solid, pieces: SweptPieces, chosen, base, direction, length):
    """Per line (q lists), the merged (l_start, l_end) intervals of the lines base + l·direction,
    0 ≤ l ≤ length (base (q, 3), direction (3,) unit, mm), inside `stock_solid` and inside none of
    the swept volumes of pieces `chosen`: the stock's sections (one boolean) minus each line's
    sections with every hull_parts solid, one boolean per solid with the lines whose bounding boxes
    meet its own (the union of the parts is the hull, so no solid is fused or cut: OpenCASCADE takes
    seconds per fuse or cut of these nearly coincident solids, milliseconds per section)."""
    base = np.asarray(base, dtype=float).reshape(-1, 3)
    direction = np.asarray(direction, dtype=float)
    kept = _inside_intervals(stock_solid, base, direction, length)
    inside = [k for k, found in enumerate(kept) if found]
    if not inside or len(chosen) == 0:
        return kept
    extent = np.array([(found[0][0], found[-1][1]) for found in (kept[k] for k in inside)])
    ends = np.stack([base[inside] + extent[:, :1] * direction, base[inside] + extent[:, 1:] * direction])
    low, high = ends.min(axis=0) - BOX_SLACK, ends.max(axis=0) + BOX_SLACK
    removed = [[] for _ in inside]
    piece_low, piece_high = _piece_boxes(pieces, chosen)
    reaching = ((piece_low[:, None, :] <= high[None]) & (piece_high[:, None, :] >= low[None])).all(axis=2).any(axis=1)
    for i in np.asarray(chosen)[reaching]:
        for part in hull_parts(pieces.c0[i], pieces.c1[i], pieces.axis[i], pieces.radius[i], pieces.height[i]):
            box = part.BoundBox
            meets = np.flatnonzero(((low <= [box.XMax, box.YMax, box.ZMax]) &
                                    (high >= [box.XMin, box.YMin, box.ZMin])).all(axis=1))
            if meets.size:
                lines = [inside[k] for k in meets]
                for k, more in zip(meets, _inside_intervals(part, base[lines], direction, length)):
                    removed[k].extend(more)
    for k, found in zip(inside, removed):
        kept[k] = _minus(kept[k], _merged(found))
    return kept


def _piece_boxes(pieces: SweptPieces, chosen):
    """(low, high) (k, 3) mm: the axis-aligned boxes of the swept volumes of pieces `chosen` (k,), each
    the box of its two end cylinders (the volume is their convex hull): a cylinder of unit axis w and
    radius r reaches r·sqrt(1 − w_i²) beyond its axis segment along coordinate i."""
    chosen = np.asarray(chosen, dtype=int)
    w, r, h = pieces.axis[chosen], pieces.radius[chosen, None], pieces.height[chosen, None]
    ends = np.stack([pieces.c0[chosen], pieces.c0[chosen] + h * w, pieces.c1[chosen], pieces.c1[chosen] + h * w])
    rim = r * np.sqrt(np.clip(1.0 - w * w, 0.0, 1.0))
    return ends.min(axis=0) - rim, ends.max(axis=0) + rim


def _minus(kept, removed):
    """The intervals `kept` less the intervals `removed` (both merged, increasing); pieces shorter
    than SLIVER dropped."""
    out = []
    for start, end in kept:
        for cut_start, cut_end in removed:
            if cut_end <= start or cut_start >= end:
                continue
            if cut_start - start >= SLIVER:
                out.append((start, cut_start))
            start = max(start, cut_end)
        if end - start >= SLIVER:
            out.append((start, end))
    return out


def _filled(found, source):
    """{length, lep_l, uep_l, pieces} (p,) arrays of the intervals `found` of the distinct lines, line
    source[k] for angle k (mm; NaN LEP and UEP without engagement)."""
    p = len(source)
    out = {"length": np.zeros(p), "lep_l": np.full(p, np.nan), "uep_l": np.full(p, np.nan),
           "pieces": np.zeros(p, dtype=int)}
    for k, j in enumerate(source):
        if found[j]:
            out["length"][k] = sum(b - a for a, b in found[j])
            out["lep_l"][k], out["uep_l"][k] = found[j][0][0], found[j][-1][1]
            out["pieces"][k] = len(found[j])
    return out


def _segment_gaps(p, u, q, v):
    """(k,) shortest distances (mm) between the segment p + s·u, 0 ≤ s ≤ 1 ((3,) each) and the
    segments q + t·v ((k, 3) each): the closest points by clamping (Ericson, Real-Time Collision
    Detection, 5.1.9)."""
    r = p - q
    a, b, c = u @ u, v @ u, r @ u
    e, f = np.einsum("ij,ij->i", v, v), np.einsum("ij,ij->i", v, r)
    denom = a * e - b * b
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(denom > 1e-12 * a * e, np.clip((b * f - c * e) / denom, 0.0, 1.0), 0.0)
        t = (b * s + f) / e
    s = np.where(t < 0.0, np.clip(-c / a, 0.0, 1.0), np.where(t > 1.0, np.clip((b - c) / a, 0.0, 1.0), s))
    t = np.clip(t, 0.0, 1.0)
    return np.linalg.norm(r + s[:, None] * u - t[:, None] * v, axis=1)


def _near_tool(pieces: SweptPieces, row, tool: Tool, toolpath: Toolpath, i):
    """(k,) the pieces of moves ending before program row `row` that can reach the tool at CL point i
    of `toolpath`, and the tool's axis (3,). A piece's volume lies within its radius + |c1 − c0|/2
    of its axis segment at the middle of the move, the tool within its radius of its own axis
    segment: the pieces whose axis segments come closer than the sum (and whose bounding spheres
    reach the tool's, pieces_near)."""
    _, direction = edge_lines(toolpath, tool, [0.0])
    w = direction[i]
    centre = toolpath.cl[i] + 0.5 * tool.flute_length * w
    near = pieces_near(pieces, int(row), centre, np.hypot(tool.radius, 0.5 * tool.flute_length))
    move = pieces.c1[near] - pieces.c0[near]
    middle = 0.5 * (pieces.c0[near] + pieces.c1[near])
    gap = _segment_gaps(toolpath.cl[i], tool.flute_length * w, middle, pieces.height[near, None] * pieces.axis[near])
    reach = tool.radius + pieces.radius[near] + 0.5 * np.linalg.norm(move, axis=1)
    return near[gap <= reach], w


def edge_lengths_in_process(shape, tool: Tool, toolpath: Toolpath, phi_deg, sweep: ProgramSweep, progress=None):
    """The boolean reference against the in-process stock: at each CL point of `toolpath` (a part of
    sweep.toolpath) the cutting-edge lines at phi_deg (p,) (deg) inside the stock `shape`
    (Part.Shape) and in none of the volumes the earlier cutting moves near it swept
    (inprocess_sections). Returns a dict of (m, p) arrays as cad.boolean.edge_lengths_by_boolean
    (length, lep_l, uep_l mm, pieces) and "swept" (m,) int: the swept pieces met at each CL point.
    progress(done, total) after each CL point."""
    phi = np.atleast_1d(np.asarray(phi_deg, dtype=float))
    distinct, source = _distinct_angles(phi)
    base, direction = edge_lines(toolpath, tool, distinct)
    rows = sweep.rows_of(toolpath)
    parts = []
    for i, row in enumerate(rows):
        chosen, _ = _near_tool(sweep.pieces, row, tool, toolpath, i)
        found = inprocess_sections(shape, sweep.pieces, chosen, base[i], direction[i], tool.flute_length)
        parts.append({**_filled(found, source), "swept": len(chosen)})
        if progress is not None:
            progress(i + 1, len(rows))
    return {name: np.array([part[name] for part in parts]) for name in parts[0]}


def swept_near_tool(pieces: SweptPieces, row, tool: Tool, toolpath: Toolpath, i):
    """(Part.Compound or None, outlined): the solids (not fused) of the volumes that the earlier moves'
    pieces near the tool at CL point i of `toolpath` (program row `row`) swept, those the in-process
    reference sections there (None when no earlier piece comes near): hull_parts of a flat-end mill's
    piece; of a piece of a tool with a corner, its exact solid (corner_sweep.swept_solid) or, where it has
    none, the hull of the flat-end cylinder of its radius, which holds its volume; outlined counts those."""
    chosen, _ = _near_tool(pieces, row, tool, toolpath, i)
    if len(chosen) == 0:
        return None, 0
    solids, outlined = [], 0
    for k in chosen:
        exact = None
        if pieces.corner[k] > 0.0:
            exact = swept_solid(pieces.c0[k], pieces.c1[k], pieces.axis[k], pieces.radius[k], pieces.corner[k],
                                pieces.height[k])
            outlined += exact is None
        solids += [exact] if exact is not None else hull_parts(pieces.c0[k], pieces.c1[k], pieces.axis[k],
                                                                pieces.radius[k], pieces.height[k])
    return Part.Compound(solids), int(outlined)


def stock_heights(stock_solid, pieces: SweptPieces, row, tool: Tool, toolpath: Toolpath, i, cells=24):
    """The in-process stock around CL point i of `toolpath` (program row `row`) seen from above:
    (x (c,), y (c,), z (c, c)) mm, z[a, b] the top of the stock minus the earlier moves' swept
    volumes (inprocess_sections of vertical lines; the volumes of pieces of tools with a corner by the
    exact inside test, sweep_membership) over (x[b], y[a]), NaN where none is left; the grid of
    c = `cells` points covers the tool's bounding box grown by BOX_MARGIN."""
    chosen, w = _near_tool(pieces, row, tool, toolpath, i)
    centre = toolpath.cl[i] + 0.5 * tool.flute_length * w
    half = 0.5 * tool.flute_length * np.abs(w) + tool.radius * np.sqrt(np.clip(1.0 - w * w, 0.0, 1.0)) + BOX_MARGIN
    box = stock_solid.BoundBox
    x = np.linspace(centre[0] - half[0], centre[0] + half[0], cells)
    y = np.linspace(centre[1] - half[1], centre[1] + half[1], cells)
    gx, gy = np.meshgrid(x, y)
    base = np.column_stack([gx.ravel(), gy.ravel(), np.full(gx.size, box.ZMin - 1.0)])
    up = np.array([0.0, 0.0, 1.0])
    chosen = np.asarray(chosen, dtype=int)
    corner = pieces.corner[chosen] > 0.0
    found = inprocess_sections(stock_solid, pieces, chosen[~corner], base, up, box.ZLength + 2.0)
    for k in chosen[corner]:
        piece = (pieces.c0[k], pieces.c1[k], pieces.axis[k], pieces.radius[k], pieces.corner[k], pieces.height[k])
        inside, _ = curve_intervals(lambda owner, t: base[owner] + t[:, None] * up, found, piece)
        found = [_minus(kept, away) for kept, away in zip(found, inside)]
    top = np.array([pieces_[-1][1] if pieces_ else np.nan for pieces_ in found]) + box.ZMin - 1.0
    return x, y, top.reshape(cells, cells)
