"""The in-process stock by OpenCASCADE: the stock solid cut by the volumes earlier moves swept.

It mirrors engine.inprocess with booleans. Each constant-axis piece of a cutting move (the same
pieces engine.inprocess.swept_pieces makes: a move whose axis turns is cut into sub-steps) is
built as an exact solid: the convex hull of its two end cylinders is the union of the two
cylinders and the extrusions, along the move d = c1 − c0, of the cylinder's bottom disc, its
top disc and its axial rectangle across the move (the rectangle through the axis, ⊥ to d's part
across the axis). Every line parallel to d that meets the first cylinder meets one of those
three faces inside it, so the extrusions fill the gap between the two cylinders. Lengths in mm.
"""

import numpy as np

from ..engine.inprocess import SweptPieces, swept_pieces
from .boolean import _inside_intervals
from .freecad_env import FreeCAD, Part

#: A move component below this (mm) is zero: its extrusion would be flat.
FLAT_EPS = 1e-9


def _vector(values):
    return FreeCAD.Vector(*(float(v) for v in values))


def hull_solid(c0, c1, axis, radius, height):
    """Part.Shape of the volume a cylinder (radius, height, unit axis, bottom centre c0) sweeps
    moving straight to c1 with its axis fixed: the convex hull of the two end cylinders (mm)."""
    c0, c1, w = (np.asarray(v, dtype=float) for v in (c0, c1, axis))
    d = c1 - c0
    da = float(d @ w)
    dp = d - da * w
    parts = [Part.makeCylinder(radius, height, _vector(c0), _vector(w))]
    if np.linalg.norm(d) <= FLAT_EPS:
        return parts[0]
    parts.append(Part.makeCylinder(radius, height, _vector(c1), _vector(w)))
    if abs(da) > FLAT_EPS:
        for base in (c0, c0 + height * w):
            disc = Part.Face(Part.Wire(Part.makeCircle(radius, _vector(base), _vector(w))))
            parts.append(disc.extrude(_vector(d)))
    if np.linalg.norm(dp) > FLAT_EPS:
        across = np.cross(w, dp / np.linalg.norm(dp))
        corners = [c0 - radius * across, c0 + radius * across, c0 + radius * across + height * w,
                   c0 - radius * across + height * w]
        rectangle = Part.Face(Part.makePolygon([_vector(c) for c in corners + corners[:1]]))
        parts.append(rectangle.extrude(_vector(d)))
    return parts[0].multiFuse(parts[1:]).removeSplitter()


def _pieces_near(pieces: SweptPieces, moves, upto, near):
    """Indices of the pieces of moves ending at or before row upto − 1 whose bounding sphere
    comes within `near` mm of the tool at row upto (None: the tool's own bounding sphere)."""
    radius, height = moves.radius[upto], moves.flute_length[upto]
    centre = moves.cl[upto] + 0.5 * height * moves.axis[upto]
    reach = np.hypot(radius, 0.5 * height) if near is None else float(near)
    piece_centre = 0.5 * (pieces.c0 + pieces.c1) + 0.5 * pieces.height[:, None] * pieces.axis
    piece_bound = 0.5 * np.linalg.norm(pieces.c1 - pieces.c0, axis=1) + np.hypot(pieces.radius, 0.5 * pieces.height)
    gap = np.linalg.norm(piece_centre - centre, axis=1) - piece_bound
    return np.flatnonzero((pieces.move <= upto - 1) & (gap <= reach))


def inprocess_solid(stock_solid, moves, upto, near=None, tolerance=0.05):
    """The stock solid cut by the volumes of the cutting moves that end at or before program
    row upto − 1 (ProgramMoves `moves`, or its SweptPieces with `moves` then given as
    (moves, pieces)), restricted to those near the tool at row `upto` (bounding spheres within
    `near` mm of the tool's; default: touching the tool's own bounding sphere). Part.Shape."""
    moves, pieces = moves if isinstance(moves, tuple) else (moves, swept_pieces(moves, tolerance))
    chosen = _pieces_near(pieces, moves, int(upto), near)
    if chosen.size == 0:
        return stock_solid
    tools = [hull_solid(pieces.c0[i], pieces.c1[i], pieces.axis[i], pieces.radius[i], pieces.height[i])
             for i in chosen]
    removal = tools[0].multiFuse(tools[1:]) if len(tools) > 1 else tools[0]
    return stock_solid.cut(removal)


def inprocess_lengths(stock_solid, moves, upto, origins, direction, length, near=None, tolerance=0.05):
    """Edge lines of the tool at program row `upto` against inprocess_solid, by one boolean.

    origins: (p, 3) points at l = 0; direction: (3,) unit, shared; length: flute length (mm).
    Returns a dict of (p,) arrays: length (inside length, mm), lep_l, uep_l (first start, last
    end; NaN without engagement), pieces (int), and "solid": the in-process solid used.
    """
    solid = inprocess_solid(stock_solid, moves, upto, near, tolerance)
    origins = np.asarray(origins, dtype=float).reshape(-1, 3)
    found = _inside_intervals(solid, origins, np.asarray(direction, dtype=float), float(length))
    p = len(found)
    out = {"length": np.zeros(p), "lep_l": np.full(p, np.nan), "uep_l": np.full(p, np.nan),
           "pieces": np.zeros(p, dtype=int), "solid": solid}
    for k, pieces in enumerate(found):
        if pieces:
            out["length"][k] = sum(b - a for a, b in pieces)
            out["lep_l"][k], out["uep_l"][k] = pieces[0][0], pieces[-1][1]
            out["pieces"][k] = len(pieces)
    return out
