"""Stock solids nobody here had seen, built with FreeCAD's Part module (mm): walls on offset surfaces
(as STEP exporters write offset walls), parabola and hyperbola walls, and solids that are not 2.5D
at all (a sphere, cone apexes, a spherical dimple) whose degenerated edges have no curve."""

import math

import numpy as np

from abm_workbench.cad.freecad_env import FreeCAD, Part

from .recognition_shapes import line, plan_face, two_sections

V = FreeCAD.Vector
#: The block that pockets are cut from: x 0..60, y −20..20, z 0..10.
BLOCK = ((0.0, 60.0), (-20.0, 20.0), (0.0, 10.0))


def block():
    """The 60 × 40 × 10 block of BLOCK."""
    (x0, x1), (y0, y1), (z0, z1) = BLOCK
    return Part.makeBox(x1 - x0, y1 - y0, z1 - z0, V(x0, y0, z0))


def _sewn(faces):
    """One valid solid from faces whose shared edges coincide (sewn, then fixed by OpenCASCADE)."""
    shell = Part.Shell(faces)
    shell.sewShape()
    solid = Part.Solid(Part.Shell(shell.Faces))
    if solid.Volume < 0:
        solid.reverse()
    solid.fix(1e-7, 1e-7, 1e-7)
    return solid


def _on_surface(surface, a, b):
    """The face of `surface` over the parameter rectangle whose opposite corners are the points a and b."""
    (u0, v0), (u1, v1) = surface.parameter(V(*a)), surface.parameter(V(*b))
    return surface.toShape(min(u0, u1), max(u0, u1), min(v0, v1), max(v0, v1))


def offset_wall(basis):
    """Two sections (x 0..60, y ±15, base 0; left top z = 10, right z = 5) whose wall x = 30 is a face on
    an OffsetSurface, 2 mm off its basis at x = 28: "plane" (a plane) or "line" (an extrusion along z of
    a line along y)."""
    base = two_sections([line((30, -15, 0), (30, 15, 0))])
    if basis == "plane":
        surface = Part.Plane(V(28, 0, 0), V(1, 0, 0))
    else:
        surface = Part.SurfaceOfExtrusion(Part.Line(V(28, 0, 0), V(28, 1, 0)), V(0, 0, 1))
    wall = _on_surface(Part.OffsetSurface(surface, 2.0), (30, -15, 5), (30, 15, 10))
    faces = [f for f in base.Faces if not (f.BoundBox.XLength < 1e-9 and abs(f.BoundBox.XMin - 30) < 1e-9)]
    return _sewn(faces + [wall])


def offset_top():
    """The block whose top (z = 10) is a face on an OffsetSurface 2 mm above the plane z = 8."""
    (x0, x1), (y0, y1), (_, z1) = BLOCK
    top = _on_surface(Part.OffsetSurface(Part.Plane(V(0, 0, 8), V(0, 0, 1)), 2.0), (x0, y0, z1), (x1, y1, z1))
    return _sewn([f for f in block().Faces if f.BoundBox.ZMin < z1 - 1e-9] + [top])


def _prism(side):
    """The solid bounded by the closed vertical face `side` and the two planar faces closing its ends (each
    bounded by one of its edges that is not the seam, a line)."""
    return _sewn([side] + [Part.Face(Part.Wire(edge)) for edge in side.Edges if not isinstance(edge.Curve, Part.Line)])


def _pocket(side, depth=5.0):
    """The block with a pocket `depth` deep whose wall is the closed vertical face `side` (z 0..20)."""
    return block().cut(_prism(side).translate(V(0, 0, BLOCK[2][1] - depth))).Solids[0]


def offset_round_pocket(basis):
    """The block with a round pocket of radius 7 about (30, 0), 5 mm deep, whose wall is an
    OffsetSurface 2 mm outside a radius-5 "cylinder" or "circle" (an extrusion of a circle)."""
    circle = Part.Circle(V(30, 0, 0), V(0, 0, 1), 5.0)
    if basis == "cylinder":
        surface = Part.Cylinder()
        surface.Center, surface.Radius = V(30, 0, 0), 5.0
    else:
        surface = Part.SurfaceOfExtrusion(circle, V(0, 0, 1))
    return _pocket(Part.OffsetSurface(surface, 2.0).toShape(0, 2 * math.pi, 0, 20))


def _closed_spline():
    """A closed periodic B-spline about (30, 0) in the plane z = 0, about 10 × 7 mm."""
    curve = Part.BSplineCurve()
    curve.interpolate([V(30 + 10 * math.cos(a) + 0.5 * math.cos(3 * a), 7 * math.sin(a), 0)
                       for a in np.linspace(0, 2 * math.pi, 10, endpoint=False)], PeriodicFlag=True)
    return curve


def offset_spline_pocket():
    """The block with a pocket whose wall is an OffsetSurface (1 mm) of an extrusion along z of a closed
    B-spline: vertical, but its plan curve, an offset of a B-spline, has no exact B-spline form."""
    curve = _closed_spline()
    surface = Part.OffsetSurface(Part.SurfaceOfExtrusion(curve, V(0, 0, 1)), 1.0)
    return _pocket(surface.toShape(curve.FirstParameter, curve.LastParameter, 0, 20))


def offset_curve_prism():
    """A prism 5 mm high whose wall is an extrusion along z of an OffsetCurve (1 mm) of a closed B-spline;
    the edges where it meets its ends lie on offset curves."""
    curve = _closed_spline()
    surface = Part.SurfaceOfExtrusion(Part.OffsetCurve(curve, 1.0, V(0, 0, 1)), V(0, 0, 1))
    return _prism(surface.toShape(curve.FirstParameter, curve.LastParameter, 0, 5))


def parabola():
    """The parabola x = 25 + y²/40 (focal length 10, apex (25, 0)) in the plane z = 0."""
    curve = Part.Parabola()
    curve.Focal, curve.Center = 10.0, V(25, 0, 0)
    return curve


def hyperbola():
    """The right branch x²/20² − y²/12² = 1 of a hyperbola centred at (10, 0), z = 0."""
    curve = Part.Hyperbola()
    curve.MajorRadius, curve.MinorRadius, curve.Center = 20.0, 12.0, V(10, 0, 0)
    return curve


def conic_wall(kind):
    """Two sections on y ±15 whose wall is a vertical extrusion of a "parabola" or "hyperbola" arc,
    one x per y."""
    curve, half = (parabola(), 15.0) if kind == "parabola" else (hyperbola(), math.asinh(15.0 / 12.0))
    return two_sections([Part.Edge(curve, -half, half)])


def conic_pocket(kind):
    """The block with a pocket 5 mm deep bounded by a "parabola" or "hyperbola" arc over |y| ≤ 15 (from its
    apex at x = 25 or 30 to x = 30.6 or 42) and the chord closing it."""
    curve, half = (parabola(), 15.0) if kind == "parabola" else (hyperbola(), math.asinh(15.0 / 12.0))
    arc = Part.Edge(curve, -half, half)
    a, b = (vertex.Point for vertex in arc.Vertexes)
    pocket = plan_face([arc, line(tuple(b), tuple(a))]).extrude(V(0, 0, 20)).translate(V(0, 0, 5))
    return block().cut(pocket).Solids[0]


#: Solids that are not 2.5D, {name: (builder, surface type of the face refused)}: a sphere (its poles
#: degenerated edges), cones with their apex up and down (a degenerated edge), and the block with a
#: spherical dimple whose lowest point is the sphere's pole.
NOT_2_5D = {
    "sphere": (lambda: Part.makeSphere(10), "Sphere"),
    "cone apex up": (lambda: Part.makeCone(10, 0, 10), "Cone"),
    "cone apex down": (lambda: Part.makeCone(0, 10, 10), "Cone"),
    "spherical dimple": (lambda: block().cut(Part.makeSphere(5, V(30, 0, 12))).Solids[0], "Sphere"),
}
