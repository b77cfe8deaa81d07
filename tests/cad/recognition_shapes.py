"""Solids for the recognition tests: the issue's silent wrong answers, legal walls of every curve
type, and terraced stocks with pockets, islands, bosses, rings and ridges (mm)."""

import numpy as np

from abm_workbench.cad.freecad_env import FreeCAD, Part

V = FreeCAD.Vector


def line(a, b):
    """The edge from a to b ((3,) each)."""
    return Part.LineSegment(V(*a), V(*b)).toShape()


def plan_face(edges):
    """The face at z = 0 bounded by a closed chain of plan edges."""
    return Part.Face(Part.Wire(Part.__sortEdges__(edges)))


def two_sections(wall_edges, z_left=10.0, z_right=5.0, x_max=60.0, y=(-15.0, 15.0)):
    """A staircase of two sections on x 0..x_max, the given y range, base z = 0: the wall is the chain
    `wall_edges` at z = 0 running from y[0] to y[1]; left section up to z_left, right to z_right."""
    first = wall_edges[0].Vertexes[0].Point
    last = wall_edges[-1].Vertexes[-1].Point
    left = plan_face([line((0, y[0], 0), (first.x, y[0], 0)), *wall_edges,
                      line((last.x, y[1], 0), (0, y[1], 0)), line((0, y[1], 0), (0, y[0], 0))])
    right = plan_face([line((first.x, y[0], 0), (x_max, y[0], 0)), line((x_max, y[0], 0), (x_max, y[1], 0)),
                       line((x_max, y[1], 0), (last.x, y[1], 0)), *wall_edges])
    return left.extrude(V(0, 0, z_left)).fuse(right.extrude(V(0, 0, z_right))).removeSplitter().Solids[0]


def polyline_fold():
    """A wall x(y) on a 30 mm stock that runs back 0.1 mm in y (from y = 4.97 to 4.87), between the
    y levels an old sampler checked (−15 + (i + ½)·30/256)."""
    corners = [(30, -15, 0), (31, 4.97, 0), (31.5, 4.87, 0), (32, 15, 0)]
    return two_sections([line(a, b) for a, b in zip(corners[:-1], corners[1:])])


def spline_fold():
    """A stock on y ±16 whose wall runs x = 30 up to y = −15, then one cubic B-spline span whose y rises
    from −15 to 0.05, falls back 0.1 mm to −0.05 and rises to 15, then x = 33: an S-fold between two
    of the y levels an old sampler checked (−0.0625, 0.0625), with every span end in order.
    Returns (solid, curve)."""
    curve = Part.BSplineCurve()
    poles = [V(30, -15, 0), V(31, 15.8553, 0), V(32, -15.8553, 0), V(33, 15, 0)]
    curve.buildFromPolesMultsKnots(poles, [4, 4], [0.0, 1.0], False, 3)
    edges = [line((30, -16, 0), (30, -15, 0)), curve.toShape(), line((33, 15, 0), (33, 16, 0))]
    return two_sections(edges, y=(-16.0, 16.0)), curve


def bezier_wall():
    """A legal wall whose edge is a cubic Bézier curve, one x per y."""
    curve = Part.BezierCurve()
    curve.setPoles([V(20, -15, 0), V(32, -5, 0), V(18, 5, 0), V(26, 15, 0)])
    return two_sections([curve.toShape()])


def long_spline_wall():
    """A wall on a B-spline drawn from y = −40 to 40, cut by the stock's y range −15..15."""
    curve = Part.BSplineCurve()
    curve.interpolate([V(30 + 3 * np.sin(0.05 * y), y, 0) for y in np.linspace(-40, 40, 9)])
    box = Part.makeBox(60, 30, 10, V(0, -15, 0))
    north, south = (30 + 3 * np.sin(2.0), 40, 0), (30 + 3 * np.sin(-2.0), -40, 0)
    cutter = Part.Face(Part.Wire([curve.toShape(), line(north, (70, 40, 0)), line((70, 40, 0), (70, -40, 0)),
                                  line((70, -40, 0), south)]))
    return box.cut(cutter.extrude(V(0, 0, 20)).translate(V(0, 0, 5))).removeSplitter().Solids[0]


def _sewn_solid(faces):
    """One solid from faces whose shared edges coincide."""
    shell = Part.Shell(faces)
    shell.sewShape()
    solid = Part.Solid(Part.Shell(shell.Faces))
    if solid.Volume < 0:
        solid.reverse()
    return solid


def _surface(poles, u, v, degree_u=1, degree_v=1):
    """A Part.BSplineSurface from poles[i][j] ((3,) tuples), knot lists u, v (uniform, clamped)."""
    surface = Part.BSplineSurface()
    mults_u = [degree_u + 1] + [1] * (len(u) - 2) + [degree_u + 1]
    mults_v = [degree_v + 1] + [1] * (len(v) - 2) + [degree_v + 1]
    surface.buildFromPolesMultsKnots([[V(*p) for p in row] for row in poles], mults_u, mults_v, u, v,
                                     False, False, degree_u, degree_v)
    return surface


def dented_top():
    """A box 40 × 30 × 10 whose top is a bilinear B-spline surface with 20 × 20 spans, flat at z = 10
    except one pole at (u, v) = (0.2, 0.2) lowered 0.5 mm: a dent between the normals an old
    sampler looked at (u, v = 0.1, 0.3, …, 0.9)."""
    knots = list(np.linspace(0.0, 1.0, 21))
    poles = [[(2.0 * i, -15.0 + 1.5 * j, 9.5 if (i, j) == (4, 4) else 10.0) for j in range(21)] for i in range(21)]
    top = Part.Face(_surface(poles, knots, knots))
    return _sewn_top_box(top, (0.0, 40.0), (-15.0, 15.0), (0.0, 10.0))


def flat_spline_top():
    """The same box with a flat top stored as a B-spline surface: a legal horizontal plane."""
    knots = list(np.linspace(0.0, 1.0, 5))
    poles = [[(10.0 * i, -15.0 + 7.5 * j, 10.0) for j in range(5)] for i in range(5)]
    return _sewn_top_box(Part.Face(_surface(poles, knots, knots)), (0.0, 40.0), (-15.0, 15.0), (0.0, 10.0))


def _sewn_top_box(top, x, y, z):
    """A box whose top face is `top` (its boundary the box's top rectangle)."""
    box = Part.makeBox(x[1] - x[0], y[1] - y[0], z[1] - z[0], V(x[0], y[0], z[0]))
    others = [f for f in box.Faces if f.BoundBox.ZMin < z[1] - 1e-9]
    return _sewn_solid(others + [top])


def wall_surface_stock(lean):
    """Two sections (x 0..60, y ±15, base 0; left top z = 10, right z = 5) whose wall is a B-spline
    surface, degree 1 in z with knots 0, 0.95, 1 in v: the plan x = 30 from z = 5 to 9.75, then
    moving `lean` mm in x up to z = 10 (lean 0: a vertical wall stored as a B-spline surface). An
    old sampler's normals (v = 0.1, …, 0.9) all lie below the lean."""
    y0, y1 = -15.0, 15.0
    rows = [[(30.0, y, 5.0), (30.0, y, 9.75), (30.0 + lean, y, 10.0)] for y in (y0, y1)]
    surface = Part.BSplineSurface()
    surface.buildFromPolesMultsKnots([[V(*p) for p in row] for row in rows], [2, 2], [2, 1, 2], [0.0, 1.0],
                                     [0.0, 0.95, 1.0], False, False, 1, 1)
    wall = Part.Face(surface)
    south, north = [e for e in wall.Edges if e.BoundBox.YLength < 1e-9 and e.BoundBox.ZLength > 1]
    if south.BoundBox.YMin > north.BoundBox.YMin:
        south, north = north, south
    top_x = 30.0 + lean

    def side(y, iso):
        return Part.Face(Part.Wire(Part.__sortEdges__([
            line((0, y, 0), (60, y, 0)), line((60, y, 0), (60, y, 5)), line((60, y, 5), (30, y, 5)), iso,
            line((top_x, y, 10), (0, y, 10)), line((0, y, 10), (0, y, 0))])))

    faces = [
        wall, side(y0, south), side(y1, north),
        Part.Face(Part.makePolygon([V(0, y0, 10), V(top_x, y0, 10), V(top_x, y1, 10), V(0, y1, 10), V(0, y0, 10)])),
        Part.Face(Part.makePolygon([V(30, y0, 5), V(60, y0, 5), V(60, y1, 5), V(30, y1, 5), V(30, y0, 5)])),
        Part.Face(Part.makePolygon([V(0, y0, 0), V(60, y0, 0), V(60, y1, 0), V(0, y1, 0), V(0, y0, 0)])),
        Part.Face(Part.makePolygon([V(0, y0, 0), V(0, y1, 0), V(0, y1, 10), V(0, y0, 10), V(0, y0, 0)])),
        Part.Face(Part.makePolygon([V(60, y0, 0), V(60, y1, 0), V(60, y1, 5), V(60, y0, 5), V(60, y0, 0)])),
    ]
    return _sewn_solid(faces)


def stacked_wall():
    """Two sections whose wall (x = 30, z 5..10) is two faces stacked at z = 7.5 (fused unrefined)."""
    low = Part.makeBox(60, 30, 5, V(0, -15, 0))
    blocks = [Part.makeBox(30, 30, 2.5, V(0, -15, 5)), Part.makeBox(30, 30, 2.5, V(0, -15, 7.5))]
    return low.multiFuse(blocks).Solids[0]


def terraced_part():
    """A terraced stock: a 80 × 60 block (base 0, top 20) with a closed rectangular pocket down to
    z = 8 holding a round island up to z = 14, a round boss on top up to z = 26 ringed by a ring
    terrace to z = 23, and a ridge across y (x 60..66) up to z = 24."""
    block = Part.makeBox(80, 60, 20)
    pocket = Part.makeBox(30, 24, 12, V(8, 8, 8))
    island = Part.makeCylinder(5, 6, V(22, 20, 8))
    boss = Part.makeCylinder(4, 6, V(40, 45, 20))
    ring = Part.makeCylinder(9, 3, V(40, 45, 20)).cut(Part.makeCylinder(6, 3, V(40, 45, 20)))
    ridge = Part.makeBox(6, 60, 4, V(60, 0, 20))
    solid = block.cut(pocket).fuse([island, boss, ring, ridge]).removeSplitter()
    return solid.Solids[0]


def spline_terraces():
    """Terraces bounded by B-spline and Bézier plan curves: a block whose upper part is a closed
    periodic B-spline contour, with a Bézier-bounded notch, on a rectangular base."""
    base = Part.makeBox(70, 50, 5, V(-35, -25, 0))
    closed = Part.BSplineCurve()
    closed.interpolate([V(25 * np.cos(a), 18 * np.sin(a) + 2 * np.sin(3 * a), 0)
                        for a in np.linspace(0, 2 * np.pi, 12, endpoint=False)], PeriodicFlag=True)
    upper = Part.Face(Part.Wire(closed.toShape())).extrude(V(0, 0, 7)).translate(V(0, 0, 5))
    bezier = Part.BezierCurve()
    bezier.setPoles([V(-5, -30, 0), V(-12, -5, 0), V(12, 5, 0), V(5, -30, 0)])
    notch = Part.Face(Part.Wire([bezier.toShape(), line((5, -30, 0), (-5, -30, 0))])).extrude(V(0, 0, 20))
    return base.fuse(upper).cut(notch.translate(V(0, 0, 8))).removeSplitter().Solids[0]


def face_name(shape, predicate):
    """The name ("Face7") of the one face of `shape` for which predicate(face) holds."""
    (name,) = [f"Face{k}" for k, face in enumerate(shape.Faces, start=1) if predicate(face)]
    return name


def rounded_terraces():
    """Partial arcs: a 60 × 40 × 10 block with its vertical edges rounded (radius 6), a stadium-shaped
    boss (a slot of width 10 with round ends) up to z = 16, and a pocket with rounded corners."""
    block = Part.makeBox(60, 40, 10)
    block = block.makeFillet(6, [e for e in block.Edges if e.BoundBox.ZLength > 1])
    slot = Part.makeBox(20, 10, 6, V(10, 25, 10)).fuse(
        [Part.makeCylinder(5, 6, V(10, 30, 10)), Part.makeCylinder(5, 6, V(30, 30, 10))])
    pocket = Part.makeBox(16, 12, 4, V(35, 8, 6))
    pocket = pocket.makeFillet(3, [e for e in pocket.Edges if e.BoundBox.ZLength > 1])
    return block.fuse(slot).cut(pocket).removeSplitter().Solids[0]


def elliptic_pocket():
    """A 60 × 40 × 10 block with an elliptic pocket (semi-axes 8 and 4, turned 30°) 5 mm deep."""
    ellipse = Part.Ellipse(V(30, 0, 0), 8, 4)
    ellipse.rotate(FreeCAD.Placement(V(30, 0, 0), FreeCAD.Rotation(V(0, 0, 1), 30), V(0, 0, 0)))
    pocket = Part.Face(Part.Wire(ellipse.toShape())).extrude(V(0, 0, 5)).translate(V(0, 0, 5))
    return Part.makeBox(60, 40, 10, V(0, -20, 0)).cut(pocket).removeSplitter().Solids[0]
