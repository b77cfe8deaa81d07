"""Exact (B-spline) walls: solids built from SplineWalls, recognised back as the same curves,
and the engine on them against the boolean (mm)."""

import numpy as np
import pytest
from scipy.interpolate import make_interp_spline

from abm_workbench.cad.boolean import edge_lengths_by_boolean
from abm_workbench.cad.freecad_env import FreeCAD, Part
from abm_workbench.cad.recognise import load_solid, recognise
from abm_workbench.cad.solids import export_step, staircase_solid, wall_edge
from abm_workbench.engine import CutSettings, Staircase, Tool, Toolpath, engage
from abm_workbench.engine.walls import SplineWall
from abm_workbench.errors import InputError

from .conftest import Y_MAX, Y_MIN, wall

TOL = 1e-9  # mm
V = FreeCAD.Vector
RNG_SEED = 20


def cubic_wall():
    """A wavy cubic B-spline wall near x = 22, non-uniform parameter, running towards −y."""
    s = np.linspace(0.0, 1.0, 11) ** 1.4
    y = Y_MAX - (Y_MAX - Y_MIN) * s
    x = 22.0 + 2.5 * np.sin(0.3 * y) + 0.02 * y * y
    spline = make_interp_spline(s, np.column_stack([x, y]), k=3)
    return SplineWall(3, spline.t, spline.c, None)


def arc_wall():
    """The circle arc x = 90 − √(30² − y²), |y| ≤ 12, as one rational quadratic span."""
    half = np.arcsin(Y_MAX / 30.0)
    end, middle = 90.0 - 30.0 * np.cos(half), 90.0 - 30.0 / np.cos(half)
    poles = [[end, Y_MIN], [middle, 0.0], [end, Y_MAX]]
    return SplineWall(2, [0, 0, 0, 1, 1, 1], poles, [1.0, np.cos(half), 1.0])


def long_wall():
    """A quadratic wall near x = 80 running beyond the window (y −14..15): the solid trims it."""
    return SplineWall(2, [0, 0, 0, 0.4, 1, 1, 1], [[79.0, -14.0], [82.0, -5.0], [77.0, 6.0], [80.0, 15.0]], None)


def arc_x(y):
    """x of arc_wall at y (mm)."""
    return 90.0 - np.sqrt(900.0 - np.asarray(y) ** 2)


CURVES = (cubic_wall(), SplineWall(1, [0, 0, 1, 1], [[40.0, Y_MIN], [40.0, Y_MAX]], None), arc_wall(), long_wall())
STOCK = Staircase(0.0, 110.0, Y_MIN, Y_MAX, -10.0, [3.0, 8.0, 5.0, 11.0, 6.0],
                  [wall(c.x_at) for c in CURVES], CURVES)


@pytest.fixture(scope="module")
def solid():
    """STOCK as a solid."""
    return staircase_solid(STOCK)


def wall_area(curve, y_lo, y_hi):
    """∫ x(y) dy over [y_lo, y_hi] (mm²): 24-point Gauss-Legendre between the curve's span ends."""
    breaks = np.unique(np.clip(np.concatenate([curve.span_y, [y_lo, y_hi]]), y_lo, y_hi))
    nodes, weights = np.polynomial.legendre.leggauss(24)
    total = 0.0
    for a, b in zip(breaks[:-1], breaks[1:]):
        total += 0.5 * (b - a) * weights @ curve.x_at(a + 0.5 * (b - a) * (nodes + 1.0))
    return total


def test_solid_of_spline_walls_is_valid_with_the_height_field_volume(solid):
    height = STOCK.y_max - STOCK.y_min
    areas = [STOCK.x_min * height] + [wall_area(c, Y_MIN, Y_MAX) for c in CURVES] + [STOCK.x_max * height]
    volume = sum((z - STOCK.base_z) * (b - a) for z, a, b in zip(STOCK.z_top, areas[:-1], areas[1:]))
    # OpenCASCADE's volume (BRepGProp without a precision) integrates a B-spline boundary across
    # interior knots inexactly: a line x = 79 drawn as a two-span quadratic bounds a face of
    # 2292.78 mm² instead of 2291. On this stock it is 1.1e-5 off; the walls are checked exactly below.
    assert solid.isValid() and solid.Volume == pytest.approx(volume, rel=1e-4)
    kinds = sorted(type(f.Surface).__name__ for f in solid.Faces)
    assert kinds.count("SurfaceOfExtrusion") == 3 and kinds.count("Plane") == 5 + 1 + 5


@pytest.mark.parametrize("j", range(len(CURVES)))
def test_wall_edge_is_the_spline_wall_over_the_window(j):
    edge = wall_edge(CURVES[j], Y_MIN, Y_MAX, 2.5)
    start, end = edge.valueAt(edge.FirstParameter), edge.valueAt(edge.LastParameter)
    assert (start.y, end.y) == (Y_MIN, Y_MAX)  # runs towards +y, exactly over the window
    points = np.array([tuple(edge.valueAt(u)) for u in np.linspace(edge.FirstParameter, edge.LastParameter, 301)])
    assert np.abs(points[:, 0] - CURVES[j].x_at(points[:, 1])).max() < TOL
    assert np.abs(points[:, 2] - 2.5).max() < 1e-12


def test_rational_wall_is_the_circle():
    y = np.linspace(Y_MIN, Y_MAX, 201)
    assert np.abs(arc_wall().x_at(y) - arc_x(y)).max() < TOL


def random_ys(count, lo=Y_MIN, hi=Y_MAX):
    """(count,) y uniformly in [lo, hi], seeded."""
    return np.random.default_rng(RNG_SEED).uniform(lo, hi, count)


def assert_same_curves(found, expected, lo=Y_MIN, hi=Y_MAX):
    """Walls agree to TOL at 400 random y in [lo, hi]."""
    y = random_ys(400, lo, hi)
    for got, want in zip(found, expected):
        assert np.abs(got.x_at(y) - want.x_at(y)).max() < TOL


def test_exact_recognition_through_step_gives_back_the_curves(solid, tmp_path):
    path = tmp_path / "spline.step"
    export_step(solid, path)
    result = recognise(load_solid(path), source=str(path))
    stock = result.staircase
    assert stock.wall_curves is not None and all(isinstance(w, SplineWall) for w in stock.walls)
    assert_same_curves(stock.walls, CURVES)
    cubic, straight, arc, trimmed = stock.walls
    assert (cubic.degree, straight.degree, arc.degree) == (3, 1, 2)
    assert straight.is_straight and np.all(straight.poles[:, 0] == 40.0)
    assert np.ptp(arc.weights) > 0 and np.ptp(cubic.weights) == 0  # rational only where it was
    assert trimmed.span_y[[0, -1]] == pytest.approx([Y_MIN, Y_MAX], abs=1e-12)
    assert stock.z_top == pytest.approx(STOCK.z_top, abs=TOL)


def test_a_window_cuts_the_curves_to_it(solid):
    stock = recognise(solid, y_window=(-5.0, 7.0)).staircase
    for curve in stock.walls:
        assert curve.span_y[[0, -1]] == pytest.approx([-5.0, 7.0], abs=1e-12)
    assert_same_curves(stock.walls, CURVES, -5.0, 7.0)


def test_quintic_recognition_keeps_the_papers_model(solid):
    stock = recognise(solid, walls="quintic").staircase
    assert stock.wall_curves is None
    # the quintic interpolates the six points on each true wall, and nothing more
    for got, want, points in zip(stock.walls, CURVES, stock.wall_points):
        assert np.abs(got.x_at(points[:, 1]) - want.x_at(points[:, 1])).max() < TOL
    with pytest.raises(ValueError, match="walls must be 'exact' or 'quintic', got 'nurbs'"):
        recognise(solid, walls="nurbs")


def chain_solid(edges, x_min, x_max, z_tops, base_z):
    """Two sections split by one wall made of `edges` (joined end to end, at z = base_z)."""
    points = sorted((vertex.Point for edge in edges for vertex in edge.Vertexes), key=lambda p: p.y)
    lo, hi = points[0], points[-1]
    blocks = []
    for x_end, height in zip((x_min, x_max), z_tops):
        p, q = V(x_end, lo.y, base_z), V(x_end, hi.y, base_z)
        wire = Part.Wire(Part.__sortEdges__([Part.LineSegment(p, lo).toShape(), *edges,
                                             Part.LineSegment(hi, q).toShape(), Part.LineSegment(q, p).toShape()]))
        blocks.append(Part.Face(wire).extrude(V(0, 0, height - base_z)))
    return blocks[0].fuse(blocks[1]).removeSplitter().Solids[0]


def line_and_arc_solid():
    """A wall of a line x = 30 (y −12..0) and the arc x = 50 − √(20² − y²) (y 0..12, drawn towards −y)."""
    z = -5.0
    line = Part.LineSegment(V(30, Y_MIN, z), V(30, 0, z)).toShape()
    circle = Part.Circle(V(50, 0, z), V(0, 0, 1), 20.0)
    arc = Part.ArcOfCircle(circle, np.pi - np.arcsin(0.6), np.pi).toShape()
    return chain_solid([line, arc], 0.0, 60.0, (3.0, 8.0), z)


def line_and_arc_x(y):
    """x (mm) of line_and_arc_solid's wall at y."""
    y = np.asarray(y, dtype=float)
    return np.where(y < 0, 30.0, 50.0 - np.sqrt(400.0 - np.maximum(y, 0.0) ** 2))


def test_a_wall_of_a_line_and_an_arc_is_joined_into_one_rational_curve():
    result = recognise(line_and_arc_solid())
    (found,) = result.walls
    assert len(found.edges) == 2
    curve = found.curve
    assert curve.degree == 2 and np.ptp(curve.weights) > 0
    y = random_ys(400)
    assert np.abs(curve.x_at(y) - line_and_arc_x(y)).max() < TOL
    assert curve.span_y[[0, -1]] == pytest.approx([Y_MIN, Y_MAX], abs=1e-12)


def test_a_placed_solid_gives_the_moved_curve():
    shape = line_and_arc_solid()
    shape.Placement = FreeCAD.Placement(V(4.0, -3.0, 2.0), FreeCAD.Rotation())
    (curve,) = recognise(shape).staircase.walls
    y = random_ys(200, Y_MIN - 3.0, Y_MAX - 3.0)
    assert np.abs(curve.x_at(y) - (4.0 + line_and_arc_x(y + 3.0))).max() < TOL


def test_a_wall_that_folds_back_in_y_between_the_levels_is_refused():
    """A jog along x at y = 0 (between two check levels) is not one x per y: the curve says so."""
    z = 0.0
    corners = [V(30, Y_MIN, z), V(30, 0, z), V(33, 0, z), V(33, Y_MAX, z)]
    edges = [Part.LineSegment(a, b).toShape() for a, b in zip(corners[:-1], corners[1:])]
    with pytest.raises(InputError, match=r"^jog\.step: Face\d+(, Face\d+)*: wall has more than one x for y = 0 "
                                         r"\(its top edge runs along x there"):
        recognise(chain_solid(edges, 0.0, 60.0, (3.0, 8.0), z), source="jog.step")


# The engine on exact walls against the boolean: CL points beside each wall, tilted both ways.
TOOL = Tool(diameter=12.0, flutes=2, flute_length=25.0)
SETTINGS = CutSettings(feed_per_tooth=0.1, phi_start=0.0, phi_end=180.0, phi_step=3.0)
PATH = Toolpath(
    cl=[[19.3, 0.7, 1.2], [26.8, -1.4, 4.0], [37.5, 0.6, 1.0], [58.2, -0.6, 5.9], [64.7, 0.9, 2.7],
        [76.4, 2.2, 8.6], [85.1, -2.0, 6.1], [24.6, 0.4, 7.0]],
    theta_a=[10.0, -8.0, 4.0, 15.0, -12.0, 7.0, -5.0, 6.0],
    theta_b=[20.0, -25.0, 25.0, 26.0, -24.0, 22.0, -28.0, -30.0],
)


def test_engine_on_exact_walls_agrees_with_the_boolean(solid):
    stock = recognise(solid).staircase
    engine = engage(stock, TOOL, PATH, SETTINGS)
    boolean = edge_lengths_by_boolean(solid, TOOL, PATH, SETTINGS.phi)
    assert np.array_equal(engine.pieces, boolean["pieces"])
    for name in ("length", "lep_l", "uep_l"):
        a, b = getattr(engine, name), boolean[name]
        assert np.array_equal(np.isnan(a), np.isnan(b)), name
        assert np.nanmax(np.abs(a - b)) < TOL, name
    surfaces = set(engine.surface_names()[engine.engaged])
    assert {"top", "straight_wall", "curved_wall"} <= surfaces
