"""The exact solid of the volume a cylinder (a flat-end mill's cutting part) sweeps along a straight move with
its axis fixed: the convex hull of its two end cylinders, which is the union of the two cylinders and the
extrusions, along the move d = c1 − c0, of the cylinder's bottom disc, its top disc and its axial rectangle
across the move (the rectangle through the axis, ⊥ to d's part across the axis). Every line parallel to d
that meets the first cylinder meets one of those three faces inside it, so the extrusions fill the gap
between the two cylinders. Lengths in mm.
"""

import numpy as np

from .freecad_env import FreeCAD, Part

#: A move component below this (mm) is zero: its extrusion would be flat.
FLAT_EPS = 1e-9


def _vector(values):
    return FreeCAD.Vector(*(float(v) for v in values))


def hull_parts(c0, c1, axis, radius, height):
    """Part.Shape solids whose union is the volume a cylinder (radius, height, unit axis, bottom
    centre c0) sweeps moving straight to c1 with its axis fixed: the two end cylinders and the
    extrusions of the module docstring (mm). A list of 1 to 5 solids."""
    c0, c1, w = (np.asarray(v, dtype=float) for v in (c0, c1, axis))
    d = c1 - c0
    da = float(d @ w)
    dp = d - da * w
    parts = [Part.makeCylinder(radius, height, _vector(c0), _vector(w))]
    if np.linalg.norm(d) <= FLAT_EPS:
        return parts
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
    return parts


def hull_solid(c0, c1, axis, radius, height):
    """Part.Shape of the volume a cylinder (radius, height, unit axis, bottom centre c0) sweeps
    moving straight to c1 with its axis fixed: the convex hull of the two end cylinders (mm),
    the hull_parts fused."""
    parts = hull_parts(c0, c1, axis, radius, height)
    return parts[0] if len(parts) == 1 else parts[0].multiFuse(parts[1:]).removeSplitter()
