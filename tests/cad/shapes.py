"""Solids that are not staircases, and one whose wall is split in two faces (mm)."""

import numpy as np

from abm_workbench.cad.freecad_env import FreeCAD, Part
from abm_workbench.cad.solids import wall_edge
from abm_workbench.engine import Staircase

from .conftest import Y_MAX, Y_MIN, wall

V = FreeCAD.Vector


def prism(profile_xz):
    """The polygon profile [(x, z), ...] in the plane y = Y_MIN, extruded to y = Y_MAX."""
    points = [V(x, Y_MIN, z) for x, z in profile_xz]
    face = Part.Face(Part.makePolygon(points + points[:1]))
    return face.extrude(V(0, Y_MAX - Y_MIN, 0))


def slanted_top():
    """A wedge: its top rises from z = 10 to z = 20."""
    return prism([(0, 0), (40, 0), (40, 20), (0, 10)])


def overhang():
    """A ledge at x 20..30 over empty space below z = 5."""
    return prism([(0, 0), (20, 0), (20, 5), (30, 5), (30, 10), (0, 10)])


def leaning_wall():
    """A step whose wall leans back (about 79° from horizontal)."""
    return prism([(0, 0), (50, 0), (50, 10), (32, 10), (30, 20), (0, 20)])


def curved_top():
    """A box with the top arc of a cylinder (axis along y) standing out of its top."""
    box = Part.makeBox(40, Y_MAX - Y_MIN, 15, V(0, Y_MIN, -10))
    cylinder = Part.makeCylinder(8, Y_MAX - Y_MIN, V(20, Y_MIN, 0), V(0, 1, 0))
    return box.fuse(cylinder).removeSplitter().Solids[0]


def s_wall():
    """Two sections whose wall, seen from above, zig-zags: it has three x for some y."""
    curve = Part.BSplineCurve()
    curve.interpolate([V(20, Y_MIN, 0), V(25, 6, 0), V(35, -6, 0), V(40, Y_MAX, 0)])
    middle = curve.toShape()
    left = Part.Face(Part.Wire([
        Part.LineSegment(V(0, Y_MIN, 0), V(20, Y_MIN, 0)).toShape(), middle,
        Part.LineSegment(V(40, Y_MAX, 0), V(0, Y_MAX, 0)).toShape(),
        Part.LineSegment(V(0, Y_MAX, 0), V(0, Y_MIN, 0)).toShape(),
    ]))
    right = Part.Face(Part.Wire([
        Part.LineSegment(V(20, Y_MIN, 0), V(60, Y_MIN, 0)).toShape(),
        Part.LineSegment(V(60, Y_MIN, 0), V(60, Y_MAX, 0)).toShape(),
        Part.LineSegment(V(60, Y_MAX, 0), V(40, Y_MAX, 0)).toShape(), middle,
    ]))
    return left.extrude(V(0, 0, 10)).fuse(right.extrude(V(0, 0, 5))).removeSplitter().Solids[0]


def open_shell():
    """A box without its top: five faces, no solid; the four sides border the hole."""
    return Part.Shell(Part.makeBox(10, 10, 10).Faces[:5])


def two_solids():
    """Two separate boxes in one compound."""
    return Part.Compound([Part.makeBox(10, 10, 10), Part.makeBox(10, 10, 10, V(20, 0, 0))])


def split_tops():
    """Sections 0 and 1 of equal height left as two top faces (fused without removeSplitter)."""
    blocks = [prism([(0, 0), (20, 0), (20, 4), (0, 4)]), prism([(20, 0), (40, 0), (40, 4), (20, 4)]),
              prism([(40, 0), (60, 0), (60, 7), (40, 7)])]
    return blocks[0].multiFuse(blocks[1:]).Solids[0]


#: Two sections with one curved wall, built by split_wall() with that wall in two faces.
SPLIT_STOCK = Staircase(0.0, 60.0, Y_MIN, Y_MAX, -5.0, [3.0, 8.0], [wall(lambda y: 30.0 + 2.0 * np.sin(0.3 * y))])


def split_wall():
    """SPLIT_STOCK as a solid whose wall is two faces, over y < 0 and y > 0."""
    z = SPLIT_STOCK.base_z
    whole = wall_edge(SPLIT_STOCK.walls[0], Y_MIN, Y_MAX, z)
    halves = []
    for lo, hi in ((Y_MIN, 0.0), (0.0, Y_MAX)):
        curve = whole.Curve.copy()
        curve.segment(lo, hi)
        halves.append(curve.toShape())
    a, b = whole.valueAt(Y_MIN), whole.valueAt(Y_MAX)
    blocks = []
    for x_end, height in zip((SPLIT_STOCK.x_min, SPLIT_STOCK.x_max), SPLIT_STOCK.z_top):
        p, q = V(x_end, Y_MIN, z), V(x_end, Y_MAX, z)
        edges = [Part.LineSegment(p, a).toShape(), *halves, Part.LineSegment(b, q).toShape(),
                 Part.LineSegment(q, p).toShape()]
        blocks.append(Part.Face(Part.Wire(edges)).extrude(V(0, 0, height - z)))
    return blocks[0].fuse(blocks[1]).removeSplitter().Solids[0]


def face_named(shape, predicate):
    """'FaceK' of the one face of `shape` for which predicate(face) holds."""
    names = [f"Face{k}" for k, face in enumerate(shape.Faces, start=1) if predicate(face)]
    assert len(names) == 1, names
    return names[0]


def normal_z(face):
    """n_z at the middle of the face's parameter range."""
    u0, u1, v0, v1 = face.ParameterRange
    return face.normalAt(0.5 * (u0 + u1), 0.5 * (v0 + v1)).z

