"""engine.terraced against OpenCASCADE: hypothesis-drawn terraced stocks built with
terraced_solid, random lines as OCC edges, one solid.common over all of them, mapped back.

Examples per test: ABM_TERRACED_OCC_EXAMPLES (default 6; more for a longer run)."""

import os

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from abm_workbench.cad.boolean import edge_lengths_by_boolean
from abm_workbench.cad.freecad_env import FreeCAD, Part
from abm_workbench.cad.terraced_solids import terraced_solid
from abm_workbench.engine import CutSettings, Tool, Toolpath, engage, rotation_matrix
from abm_workbench.engine.terraced import engage_terraced, terraced_intervals
from abm_workbench.engine.terraced_model import Loop, PlanArc, PlanLine, PlanSpline, Slab, TerracedStock
from abm_workbench.engine.terraced_staircase import staircase_as_terraced
from abm_workbench.formats.terraced_json import dump_terraced, load_terraced
from abm_workbench.formats.toolpath_csv import load_toolpath
from abm_workbench.jobs import load_stock

EXAMPLES = int(os.environ.get("ABM_TERRACED_OCC_EXAMPLES", "6"))
AGREE = 1e-6       # mm
ON_LINE = 1e-7     # mm: a result edge's ends lie on its line within this
#: Radius bands (mm) of nested loops: outer contour, pocket, island, hole in the island. A loop
#: stays within its band: its vertices (control points) are drawn at radius ≥ lo / cos(Δ/2),
#: Δ the largest angle between neighbours, so its edges (its curve, inside the control
#: polygon) stay outside lo.
BANDS = ((7.5, 11.0), (4.6, 6.2), (2.0, 3.3), (0.4, 1.1))
JITTER = 0.2  # rad, largest shift of a vertex's angle from even spacing


def floats(lo, hi):
    return st.floats(lo, hi, allow_nan=False, allow_infinity=False)


@st.composite
def nested_loop(draw, band, centre, angle):
    """A closed loop within radius band (lo, hi) about `centre`, turned by `angle`: a star
    polygon, a circle, a closed cubic B-spline (maybe rational) or a polygon with an arc."""
    lo, hi = band
    kind = draw(st.sampled_from(["polygon", "circle", "spline", "arc_polygon"]))
    if kind == "circle":
        return Loop((PlanArc(centre, draw(floats(lo, hi)), draw(floats(-np.pi, np.pi)), 2 * np.pi),))
    k = draw(st.integers(8, 12)) if kind == "spline" else draw(st.integers(6, 9))
    jitter = np.array(draw(st.lists(floats(-JITTER, JITTER), min_size=k, max_size=k)))
    theta = angle + np.arange(k) * 2 * np.pi / k + jitter
    low = lo / np.cos(0.5 * (2 * np.pi / k + 2 * JITTER))
    radii = np.array(draw(st.lists(floats(low, hi), min_size=k, max_size=k)))
    points = centre + radii[:, None] * np.stack([np.cos(theta), np.sin(theta)], axis=1)
    if kind == "spline":
        control = np.vstack([points, points[:1]])
        knots = np.concatenate([[0, 0, 0], np.linspace(0, 1, len(control) - 2), [1, 1, 1]])
        weights = None
        if draw(st.booleans()):
            weights = np.array(draw(st.lists(floats(0.5, 2.0), min_size=len(control), max_size=len(control))))
            weights[-1] = weights[0]
        return Loop((PlanSpline(3, knots, control, weights),))
    curves = [PlanLine(points[i], points[(i + 1) % k]) for i in range(k)]
    if kind == "arc_polygon":  # the first edge replaced by an arc about the centre, radius of its start
        r0 = radii[0]
        end = centre + r0 * np.array([np.cos(theta[1]), np.sin(theta[1])])
        curves[0] = PlanArc(centre, r0, theta[0], theta[1] - theta[0])
        curves[1] = PlanLine(end, points[2 % k])
    return Loop(tuple(curves))


@st.composite
def terraced_stocks(draw):
    """1-25 slabs about one centre, each an outer contour with maybe a pocket, an island in it
    and a hole in the island (nested by radius bands), all turned by one random angle."""
    n = draw(st.integers(1, 25))
    angle = draw(floats(0, 2 * np.pi))
    centre = np.array([draw(floats(-3, 3)), draw(floats(-3, 3))])
    heights = np.cumsum([0.0] + draw(st.lists(floats(0.2, 2.5), min_size=n, max_size=n))) - 5.0
    slabs = []
    for k in range(n):
        depth = draw(st.integers(1, 4))
        loops = tuple(draw(nested_loop(BANDS[i], centre, angle)) for i in range(depth))
        slabs.append(Slab(float(heights[k]), float(heights[k + 1]), loops))
    return TerracedStock(tuple(slabs))


def occ_intervals(shape, origins, directions, length):
    """Per line, the merged inside intervals [(l0, l1), …] from one shape.common over all lines."""
    edges = [Part.LineSegment(FreeCAD.Vector(*o), FreeCAD.Vector(*(o + length * d))).toShape()
             for o, d in zip(origins, directions)]
    found = [[] for _ in edges]
    for edge in shape.common(edges).Edges:
        ends = np.array([tuple(edge.valueAt(u)) for u in edge.ParameterRange])
        along = np.einsum("nij,nj->ni", ends[None] - origins[:, None], directions)
        off = np.linalg.norm(ends[None] - origins[:, None] - along[..., None] * directions[:, None], axis=2).max(axis=1)
        k = int(np.argmin(off))
        assert off[k] < ON_LINE
        found[k].append(tuple(sorted(along[k])))
    merged = []
    for pieces in found:
        runs = []
        for a, b in sorted(pieces):
            if runs and a - runs[-1][1] < 1e-9:
                runs[-1] = (runs[-1][0], max(runs[-1][1], b))
            elif b - a > 1e-9:
                runs.append((a, b))
        merged.append(runs)
    return merged


def random_lines(rng, stock, n):
    """n lines through the stock's box (origins (n, 3), unit directions (n, 3)): mostly rising
    like cutting edges, some vertical, some horizontal."""
    z0, z1 = stock.base_z, stock.levels[-1]
    origins = np.column_stack([rng.uniform(-13, 13, n), rng.uniform(-13, 13, n), rng.uniform(z0 - 1, z1, n)])
    directions = rng.normal(size=(n, 3))
    directions[:, 2] = np.abs(directions[:, 2])
    directions[: n // 8, :2] = 0.0
    directions[n // 8: n // 4, 2] = 0.0
    return origins, directions / np.linalg.norm(directions, axis=1, keepdims=True)


def compare(stock, origins, directions, length):
    """Lengths, LEP and UEP of the engine against OCC within AGREE."""
    shape = terraced_solid(stock)
    assert shape.isValid()
    expected = occ_intervals(shape, origins, directions, length)
    found = terraced_intervals(stock, origins, directions, length)
    for row, runs in enumerate(expected):
        mine = np.flatnonzero(found.rows == row)
        total = sum(b - a for a, b in runs)
        assert abs(found.length[row] - total) < AGREE, (row, list(zip(found.start[mine], found.end[mine])), runs)
        if runs:
            assert abs(found.start[mine[0]] - runs[0][0]) < AGREE and abs(found.end[mine[-1]] - runs[-1][1]) < AGREE


@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(terraced_stocks(), st.integers(0, 2**32 - 1))
def test_hypothesis_stocks_agree_with_occ(stock, seed):
    origins, directions = random_lines(np.random.default_rng(seed), stock, 40)
    compare(stock, origins, directions, 40.0)


def test_pocket_boss_ring_and_ridge_agree_with_occ(tmp_path):
    """A closed pocket, a round boss, a ring terrace and a ridge across y, through the JSON format."""
    def rect(x0, y0, x1, y1):
        p = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        return Loop(tuple(PlanLine(p[i], p[(i + 1) % 4]) for i in range(4)))

    def circle(cx, cy, r):
        return Loop((PlanArc((cx, cy), r, 0.0, 2 * np.pi),))

    stock = TerracedStock((
        Slab(-10.0, -6.0, (rect(-30, -20, 30, 20), rect(-25, -15, -5, 15))),                # pocket
        Slab(-6.0, -3.0, (rect(-30, -20, 30, 20), rect(-25, -15, -5, 15), circle(-15, 0, 4))),  # boss in it
        Slab(-3.0, 0.0, (circle(15, 0, 12), circle(15, 0, 7), rect(-2, -20, 2, 20))),         # ring, ridge
        Slab(0.0, 2.0, (rect(-1, -20, 1, 20),)),
    ))
    path = tmp_path / "stock.json"
    dump_terraced(stock, path)
    again = load_terraced(path)
    rng = np.random.default_rng(5)
    origins = np.column_stack([rng.uniform(-32, 32, 200), rng.uniform(-22, 22, 200), rng.uniform(-11, 2, 200)])
    directions = rng.normal(size=(200, 3))
    directions[:, 2] = np.abs(directions[:, 2])
    directions /= np.linalg.norm(directions, axis=1, keepdims=True)
    compare(again, origins, directions, 30.0)


@pytest.mark.parametrize("angle", [0.0, 0.7, np.pi / 2])
def test_turned_spline_terraces_agree_with_occ(angle):
    rng = np.random.default_rng(11)
    theta = angle + np.linspace(0, 2 * np.pi, 10, endpoint=False)
    radii = np.array([9.0, 8.5, 9.5, 8.8, 9.2, 9.9, 8.7, 9.4, 9.1, 8.9])
    control = radii[:, None] * np.stack([np.cos(theta), np.sin(theta)], axis=1)
    control = np.vstack([control, control[:1]])
    knots = np.concatenate([[0, 0, 0], np.linspace(0, 1, len(control) - 2), [1, 1, 1]])
    outer = Loop((PlanSpline(3, knots, control),))
    weights = 1.0 + 0.5 * np.sin(np.arange(len(control)))
    weights[-1] = weights[0]
    inner = Loop((PlanSpline(3, knots, 0.5 * control, weights),))
    stock = TerracedStock((Slab(0.0, 3.0, (outer,)), Slab(3.0, 5.0, (outer, inner))))
    origins, directions = random_lines(rng, stock, 80)
    compare(stock, origins, directions, 30.0)


def test_model_test_4_agrees_with_the_boolean_on_its_step():
    """Model test 4 (resources/models/model_test_4): its JSON stock through engage_terraced
    against the project's boolean reference on its STEP solid (every 4th CL point, φ every 5°)."""
    folder = "resources/models/model_test_4/"
    stock = load_terraced(folder + "stock.json")
    toolpath = load_toolpath(folder + "toolpath.csv")
    toolpath = Toolpath.from_axes(toolpath.cl[::4], axis_of(toolpath)[::4])
    tool, cut = Tool(10.0, 2, 25.0), CutSettings(0.1, 10.0, 0.0, 180.0, 5.0)
    mine = engage_terraced(stock, tool, toolpath, cut)
    reference = edge_lengths_by_boolean(Part.read(folder + "stock.step"), tool, toolpath, cut.phi)
    assert mine.engaged.sum() > 100
    assert np.abs(mine.length - reference["length"]).max() < AGREE
    assert np.array_equal(mine.pieces, reference["pieces"])
    both = mine.engaged
    assert np.abs(mine.lep_l[both] - reference["lep_l"][both]).max() < AGREE
    assert np.abs(mine.uep_l[both] - reference["uep_l"][both]).max() < AGREE


def axis_of(toolpath):
    """(m, 3) unit tool axes of a Toolpath."""
    return rotation_matrix(toolpath.theta_a, toolpath.theta_b)[:, :, 2]


@pytest.mark.parametrize("test", [1, 2])
def test_recognised_staircase_as_terraced_matches_engage(test):
    """The model tests' STEP solids recognised with their exact B-spline walls: the staircase
    engine and engage_terraced on staircase_as_terraced of the same staircase agree."""
    folder = f"resources/models/model_test_{test}/"
    staircase = load_stock(folder + "stock.step", walls="exact").staircase
    assert any(not w.is_straight for w in staircase.walls)
    toolpath = load_toolpath(folder + "toolpath.csv")
    tool, cut = Tool(12.0, 2, 30.0), CutSettings(0.1, 10.0, 0.0, 180.0, 3.0)
    a = engage(staircase, tool, toolpath, cut)
    b = engage_terraced(staircase_as_terraced(staircase), tool, toolpath, cut)
    assert np.abs(a.length - b.length).max() < 1e-9
    assert np.nanmax(np.abs(a.lep_l - b.lep_l)) < 1e-9 and np.nanmax(np.abs(a.uep_l - b.uep_l)) < 1e-9
    assert np.array_equal(a.pieces, b.pieces)
