"""A terraced stock as an exact solid (mm).

Each loop of a slab becomes a wire at the slab's bottom, of Part.LineSegment, Part.ArcOfCircle
(a full circle: Part.Circle) and Part.BSplineCurve edges carrying the model's own geometry,
and then a face; the slab's region is their even-odd combination (symmetric differences of
the faces), extruded up to the slab's top. The slabs' prisms are fused. The fused
solid keeps the faces split where slabs meet (a wall running through two slabs is two faces):
OpenCASCADE's removeSplitter, which would merge them, was seen to fail ("FuseEdges: Projection
failed for closed curve") and to crash the process on such stocks.
"""

import numpy as np

from ..engine.terraced_model import PlanArc, PlanLine
from .freecad_env import FreeCAD, Part
from .solids import bspline_curve


def _edge(curve, z):
    """The Part edge of one plan curve in the plane z (mm)."""
    if isinstance(curve, PlanLine):
        return Part.LineSegment(FreeCAD.Vector(*curve.start, z), FreeCAD.Vector(*curve.end, z)).toShape()
    if isinstance(curve, PlanArc):
        circle = Part.Circle(FreeCAD.Vector(*curve.center, z), FreeCAD.Vector(0, 0, 1), curve.radius)
        if abs(curve.sweep) >= 2.0 * np.pi - 1e-12:
            return circle.toShape()
        a0, a1 = sorted((curve.start_angle, curve.start_angle + curve.sweep))
        return Part.ArcOfCircle(circle, a0, a1).toShape()
    return bspline_curve(curve.degree, curve.knots, curve.control, curve.weights, z).toShape()


def _region(slab):
    """The slab's region as a Part face (or shell of faces) at z = z_bottom, by the even-odd rule."""
    faces = [Part.Face(Part.Wire(Part.__sortEdges__([_edge(c, slab.z_bottom) for c in loop.curves])))
             for loop in slab.loops]
    region = faces[0]
    for face in faces[1:]:
        region = region.cut(face).fuse(face.cut(region)).removeSplitter()
    return region


def terraced_solid(stock):
    """The TerracedStock as one valid Part shape (a Solid, or a Compound when the material
    falls apart into several solids); RuntimeError if OpenCASCADE gives an invalid shape."""
    prisms = [_region(slab).extrude(FreeCAD.Vector(0, 0, slab.z_top - slab.z_bottom)) for slab in stock.slabs]
    fused = prisms[0].multiFuse(prisms[1:]) if len(prisms) > 1 else prisms[0]
    solids = fused.Solids
    if not solids:
        raise RuntimeError("the terraced stock gave no solid")
    shape = solids[0] if len(solids) == 1 else Part.Compound(solids)
    if not shape.isValid():
        raise RuntimeError("the terraced solid is not valid")
    return shape
