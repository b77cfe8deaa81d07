"""Terraced recognition: any 2.5D solid into slabs of loops of exact plan curves.

The references are OpenCASCADE's, built apart from the recogniser:

- every curve lies on the face it names: points along it, at the slab's mid height, are within
  1e-9 mm of that face (OCC's distance), and where it meets a curve of another face, its end
  lies on the solid's edges;
- the solid rebuilt from the recognised loops (Part edges from the curves' own data, faces by
  FreeCAD's bullseye face maker, which nests holes and islands itself) encloses the same material
  as the original (both one-sided differences empty);
- each slab's area: the recogniser's closed-form/Gauss area equals an adaptive quadrature of
  ½∮(x dy − y dx) over the rebuilt Part edges to 1e-10 relative, and both equal OpenCASCADE's
  cross-section of the solid (its common with the slab, by volume over height) to 1e-9 relative
  when every wall is a plane or a cylinder. With spline walls OCC's own area and volume
  integration was measured up to 2e-2 relative off, so there the exact test is the curves lying
  on their faces, and the rebuilt solid.
"""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from abm_workbench.cad.freecad_env import FreeCAD, Part
from abm_workbench.cad.solids import export_brep, export_step
from abm_workbench.cad.recognise import load_solid
from abm_workbench.cad.terraced_recognise import recognise_any, recognise_terraced, region_area
from abm_workbench.engine.terraced_model import PlanArc, PlanLine, PlanSpline
from abm_workbench.errors import InputError

from . import recognition_shapes as shapes
from . import shapes as staircase_shapes

V = FreeCAD.Vector
#: Slab areas against OCC, relative, when every edge is a line or an arc.
OCC_AREA_REL = 1e-9


def curve_edge(curve, z):
    """A Part edge at height z (mm) from a plan curve's own data."""
    if isinstance(curve, PlanLine):
        return Part.LineSegment(V(*curve.start, z), V(*curve.end, z)).toShape()
    if isinstance(curve, PlanArc):
        circle = Part.Circle(V(*curve.center, z), V(0, 0, 1), curve.radius)
        if abs(abs(curve.sweep) - 2 * math.pi) < 1e-12:
            return circle.toShape()
        a, b = sorted((curve.start_angle, curve.start_angle + curve.sweep))
        return Part.ArcOfCircle(circle, a, b).toShape()
    values, mults = np.unique(curve.knots, return_counts=True)
    spline = Part.BSplineCurve()
    weights = None if curve.weights is None else [float(w) for w in curve.weights]
    spline.buildFromPolesMultsKnots([V(x, y, z) for x, y in curve.control], mults.tolist(), values.tolist(),
                                    False, curve.degree, weights)
    return spline.toShape()


def slab_face(slab):
    """The slab's region as an OCC face at its bottom, from its loops (bullseye nesting)."""
    wires = [Part.Wire(Part.__sortEdges__([curve_edge(c, slab.z_bottom) for c in loop.curves]))
             for loop in slab.loops]
    return Part.makeFace(wires, "Part::FaceMakerBullseye")


def section_area(solid, z0, z1):
    """Area (mm²) of the solid's cross-section between z0 and z1: its common with the slab, over height."""
    box = solid.BoundBox
    cutter = Part.makeBox(box.XLength + 20, box.YLength + 20, z1 - z0, V(box.XMin - 10, box.YMin - 10, z0))
    return solid.common(cutter).Volume / (z1 - z0)


def green_area(edge):
    """½∫(x dy − y dx) along a Part edge (mm²), adaptive quadrature on OCC's own evaluation."""
    def integrand(u):
        p, d = edge.valueAt(u), edge.derivative1At(u)
        return 0.5 * (p.x * d.y - p.y * d.x)
    breaks = np.linspace(edge.FirstParameter, edge.LastParameter, 9)
    return sum(quad(integrand, a, b, epsabs=1e-12, epsrel=1e-12, limit=200)[0] for a, b in zip(breaks[:-1], breaks[1:]))


def curve_area(curve):
    """½∮(x dy − y dx) along a plan curve in its own direction, from the rebuilt Part edge."""
    edge = curve_edge(curve, 0.0)
    sign = 1.0
    if isinstance(curve, PlanArc) and curve.sweep < 0:
        sign = -1.0  # the Part arc runs counter-clockwise
    return sign * green_area(edge)


def assert_recognised(solid, stock, occ_rel=OCC_AREA_REL):
    """Curves on their faces, ends on the solid's edges; areas agree (against OCC unless occ_rel is None:
    spline walls); the rebuilt solid is the original."""
    edges = Part.Compound(solid.Edges)
    faces = {f"Face{k}": face for k, face in enumerate(solid.Faces, start=1)}
    pieces = []
    for slab in stock.slabs:
        face = slab_face(slab)
        mine = region_area(slab)
        assert mine == pytest.approx(sum(curve_area(c) for loop in slab.loops for c in loop.curves), rel=1e-10)
        if occ_rel is not None:
            expected = section_area(solid, slab.z_bottom, slab.z_top)
            assert face.Area == pytest.approx(expected, rel=occ_rel)
            assert mine == pytest.approx(expected, rel=occ_rel)
        pieces.append(face.extrude(V(0, 0, slab.z_top - slab.z_bottom)))
        z = 0.5 * (slab.z_bottom + slab.z_top)
        for loop in slab.loops:
            for curve, following in zip(loop.curves, loop.curves[1:] + loop.curves[:1]):
                if curve.face != following.face:  # where two faces meet, the solid has an edge
                    point = curve.end_points[1]
                    assert edges.distToShape(Part.Vertex(V(*point, z)))[0] < 1e-9
                edge = curve_edge(curve, z)
                for u in np.linspace(edge.FirstParameter, edge.LastParameter, 7)[1:-1]:
                    assert faces[curve.face].distToShape(Part.Vertex(edge.valueAt(u)))[0] < 1e-9
    rebuilt = pieces[0].fuse(pieces[1:]) if len(pieces) > 1 else pieces[0]
    assert solid.cut(rebuilt).Volume < 1e-6 and rebuilt.cut(solid).Volume < 1e-6


def curves_of(slab, kind):
    """The slab's curves of one type."""
    return [c for loop in slab.loops for c in loop.curves if isinstance(c, kind)]


def test_pocket_island_boss_ring_and_ridge():
    solid = shapes.terraced_part()
    stock = recognise_terraced(solid, source="part.step")
    assert stock.levels == pytest.approx([0, 8, 14, 20, 23, 24, 26], abs=1e-12)
    assert_recognised(solid, stock)
    bottom, island, pocket, ring, ridge, boss = stock.slabs
    assert len(bottom.loops) == 1 and len(curves_of(bottom, PlanLine)) == 4
    (arc,) = curves_of(island, PlanArc)
    assert (arc.radius, *arc.center) == pytest.approx((5, 22, 20), abs=1e-12) and abs(arc.sweep) == 2 * math.pi
    assert len(island.loops) == 3 and len(pocket.loops) == 2
    assert sorted(a.radius for a in curves_of(ring, PlanArc)) == pytest.approx([4, 6, 9], abs=1e-12)
    assert len(ring.loops) == 4 and len(curves_of(ring, PlanLine)) == 4
    assert len(ridge.loops) == 2 and [a.radius for a in curves_of(boss, PlanArc)] == pytest.approx([4])
    names = [f"Face{k}" for k in range(1, len(solid.Faces) + 1)]
    assert all(c.face in names for slab in stock.slabs for loop in slab.loops for c in loop.curves)
    cylinder = next(k for k, f in enumerate(solid.Faces, 1) if isinstance(f.Surface, Part.Cylinder)
                    and abs(f.Surface.Radius - 5) < 1e-12)
    assert arc.face == f"Face{cylinder}"


@pytest.mark.parametrize("angle, shift", [(90.0, (0, 0)), (33.3, (120.0, -45.5)), (-151.0, (-3.0, 7.0))])
def test_any_orientation_about_z(angle, shift):
    solid = shapes.terraced_part()
    moved = solid.copy()
    moved.rotate(V(0, 0, 0), V(0, 0, 1), angle)
    moved.translate(V(*shift, 0))
    stock = recognise_terraced(moved)
    assert_recognised(moved, stock)
    reference = recognise_terraced(solid)
    for turned, slab in zip(stock.slabs, reference.slabs):
        assert region_area(turned) == pytest.approx(region_area(slab), rel=1e-12)


def test_spline_and_bezier_plan_curves():
    solid = shapes.spline_terraces()
    stock = recognise_terraced(solid)
    assert_recognised(solid, stock, None)
    assert any(curves_of(slab, PlanSpline) for slab in stock.slabs)


def test_a_bezier_wall_from_brep_is_its_step_twin(tmp_path):
    solid = shapes.bezier_wall()
    stocks = []
    for export, name in ((export_brep, "b.brep"), (export_step, "b.step")):
        export(solid, tmp_path / name)
        loaded = load_solid(tmp_path / name)
        stocks.append(recognise_terraced(loaded, source=name))
        assert_recognised(loaded, stocks[-1], None)
    for a, b in zip(*(s.slabs for s in stocks)):
        assert region_area(a) == pytest.approx(region_area(b), rel=1e-12)


def test_recognise_any_says_which():
    staircase = shapes.bezier_wall()
    found = recognise_any(staircase)
    assert found.kind == "staircase" and found.staircase is not None and found.reason == ""
    turned = staircase.copy()
    turned.rotate(V(0, 0, 0), V(0, 0, 1), 90)
    found = recognise_any(turned, source="turned.step")
    assert found.kind == "terraced" and found.staircase is None
    assert found.reason.startswith("turned.step: Face")
    assert_recognised(turned, found.terraced, None)


@pytest.mark.parametrize("build, match", [
    (staircase_shapes.slanted_top, r"^part\.step: Face\d+: slanted top: a plane tilted 14\.0° from horizontal"),
    (shapes.dented_top, r"^part\.step: Face\d+: curved top: not a horizontal plane"),
    (lambda: shapes.wall_surface_stock(0.5), r"^part\.step: Face\d+: wall not vertical: leans up to 5\.7°"),
    (staircase_shapes.two_solids, r"^part\.step: holds 2 solids"),
])
def test_refusals_name_the_face(build, match):
    with pytest.raises(InputError, match=match):
        recognise_terraced(build(), source="part.step")


def test_an_overhang_is_a_terraced_stock():
    """Slabs describe material above empty space exactly, so an overhang is recognised."""
    solid = staircase_shapes.overhang()
    assert_recognised(solid, recognise_terraced(solid))


def random_terraces(seed):
    """A stack of 1–6 random star-shaped prisms (polygons and closed splines), each on the one below,
    with a random hole through some, turned by a random angle about z."""
    rng = np.random.default_rng(seed)
    solid = None
    z = 0.0
    for level in range(rng.integers(1, 7)):
        height = rng.uniform(0.5, 6.0)
        count = rng.integers(5, 10)
        angles = np.sort(rng.uniform(0, 2 * np.pi, count))
        radii = rng.uniform(20, 30, count) - 2.5 * level
        points = [V(r * np.cos(a), r * np.sin(a), 0) for r, a in zip(radii, angles)]
        if rng.random() < 0.5:
            face = Part.Face(Part.makePolygon(points + points[:1]))
        else:
            curve = Part.BSplineCurve()
            curve.interpolate(points, PeriodicFlag=True)
            face = Part.Face(Part.Wire(curve.toShape()))
        if rng.random() < 0.4:
            face = face.cut(Part.Face(Part.Wire(Part.makeCircle(rng.uniform(1, 4), V(*rng.uniform(-3, 3, 2), 0)))))
        prism = face.extrude(V(0, 0, height)).translate(V(0, 0, z))
        solid = prism if solid is None else solid.fuse(prism)
        z += height
    solid = solid.removeSplitter().Solids[0]
    solid.rotate(V(0, 0, 0), V(0, 0, 1), rng.uniform(0, 360))
    return solid


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_random_terraces(seed):
    solid = random_terraces(seed)
    assert_recognised(solid, recognise_terraced(solid), None)


def test_partial_arcs_of_rounded_corners_and_slots():
    solid = shapes.rounded_terraces()
    stock = recognise_terraced(solid)
    assert_recognised(solid, stock)
    arcs = [c for slab in stock.slabs for c in curves_of(slab, PlanArc)]
    assert {round(a.radius, 12) for a in arcs} == {3.0, 5.0, 6.0}
    assert all(abs(a.sweep) < 2 * math.pi - 1e-9 for a in arcs)


def test_an_elliptic_pocket_becomes_a_rational_spline():
    solid = shapes.elliptic_pocket()
    stock = recognise_terraced(solid)
    assert_recognised(solid, stock, None)
    splines = curves_of(stock.slabs[1], PlanSpline)
    assert splines and all(s.weights is not None for s in splines)
