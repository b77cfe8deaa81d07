"""The corner arcs of bull-nose and ball-end mills on a staircase (engine.corner_staircase), against the
brute-force reference of profile_reference on the arc alone, against the terraced route (corner.py on the
staircase's terraced form), and on the points its labels name.

Stocks: the quintic staircase of test_tool_profiles; a staircase with exact walls (a cubic B-spline with
uneven knots, a rational quadratic circle arc and a straight degree-1 B-spline), whose reference evaluates
the curves with scipy; model test 1 with its quintic walls (stock.json) and with its true contour walls
(walls.json as cubic B-splines, as resources/models/make_model_solids.py builds the STEP solid's walls:
their knots fall on the bands' bin edges). Tools of r/R in {0.1, 0.3, 0.5, 1}, tilted and turning axes,
axes sideways and down, a flute shorter than the corner. A planted error must fail the comparisons.
"""

import json
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.interpolate import BSpline, make_interp_spline

from abm_workbench.engine import CutSettings, Staircase, Tool, Toolpath
from abm_workbench.engine import corner_staircase, profile
from abm_workbench.engine.corner import CORNER_TOP, corner_intervals
from abm_workbench.engine.corner_staircase import staircase_corner_intervals
from abm_workbench.engine.engagement import SURFACES
from abm_workbench.engine.profile import as_terraced, corner_top, radial_directions
from abm_workbench.engine.stocks import engage_stock
from abm_workbench.engine.walls import SplineWall
from abm_workbench.formats.staircase_json import load_staircase
from abm_workbench.formats.toolpath_csv import load_toolpath

from . import profile_reference as ref
from .reference import _Stock
from .test_tool_profiles import PHI, STAIR, STAIRCASE, fixed_pass, mismatches, passes

TOL = 1e-6  # mm, against the brute-force reference
SAME = 1e-9  # mm, against the terraced route on exact walls
QUINTIC_SAME = 1e-7  # mm, against the terraced route on quintic walls (its own error reaches 4e-8 there)
ON = 1e-9  # mm, a labelled end from the surface it names
RATIOS = (0.1, 0.3, 0.5, 1.0)
MODEL_1 = Path(__file__).resolve().parents[2] / "resources" / "models" / "model_test_1"


class SplineReference:
    """Membership of a staircase with B-spline walls, the curves evaluated by scipy (homogeneous for a
    rational one); x of a wall at y from a dense table of the curve parameter, bracketed, then Newton on
    y(s) = y kept in the bracket."""

    def __init__(self, stock):
        self.stock = stock
        self.curves = []
        for wall in stock.walls:
            weights = np.ones(len(wall.poles)) if wall.weights is None else np.array(wall.weights)
            homogeneous = np.column_stack([np.array(wall.poles) * weights[:, None], weights])
            curve = BSpline(np.array(wall.knots), homogeneous, wall.degree)
            s = np.linspace(wall.knots[wall.degree], wall.knots[-wall.degree - 1], 4001)
            point = curve(s)
            y = point[:, 1] / point[:, 2]
            order = np.argsort(y)
            self.curves.append((curve, curve.derivative(), s[order], y[order]))

    def wall_x(self, j, y):
        curve, slope, s_table, y_table = self.curves[j]
        y = np.clip(np.asarray(y, dtype=float), y_table[0], y_table[-1])
        k = np.clip(np.searchsorted(y_table, y) - 1, 0, s_table.size - 2)
        a, b = np.minimum(s_table[k], s_table[k + 1]), np.maximum(s_table[k], s_table[k + 1])
        s = np.interp(y, y_table, s_table)
        for _ in range(6):
            p, dp = curve(s), slope(s)
            value = p[:, 1] / p[:, 2] - y
            step = value / ((dp[:, 1] * p[:, 2] - p[:, 1] * dp[:, 2]) / p[:, 2] ** 2)
            s = np.clip(s - step, a, b)
        point = curve(s)
        return point[:, 0] / point[:, 2]

    def inside(self, p):
        st_ = self.stock
        x, y, z = p[:, 0], p[:, 1], p[:, 2]
        box = (st_.x_min <= x) & (x <= st_.x_max) & (st_.y_min <= y) & (y <= st_.y_max) & (st_.base_z <= z)
        yc = np.clip(y, st_.y_min, st_.y_max)
        section = sum((x >= self.wall_x(j, yc)).astype(int) for j in range(len(self.curves)))
        return box & (z <= st_.z_top[section])


def wavy_wall(x_centre, amplitude):
    """A cubic B-spline wall through a wavy contour, with uneven knots (none on a band's bin edge)."""
    s = np.linspace(0.0, 1.0, 12) ** 1.3
    y = -16.0 + 32.0 * s
    spline = make_interp_spline(s, np.column_stack([x_centre + amplitude * np.sin(0.3 * y) + 0.01 * y * y, y]), k=3)
    return SplineWall(3, spline.t, spline.c, None)


def circle_wall(x_centre, radius):
    """A rational quadratic B-spline: the circle arc of `radius` about (x_centre − radius, 0) from −30° to 30°,
    bulging towards +x (y from −radius/2 to radius/2)."""
    half = np.radians(30.0)
    poles = [[x_centre - radius + radius * np.cos(half), -radius * np.sin(half)],
             [x_centre - radius + radius / np.cos(half), 0.0],
             [x_centre - radius + radius * np.cos(half), radius * np.sin(half)]]
    return SplineWall(2, [0, 0, 0, 1, 1, 1], poles, [1.0, np.cos(half), 1.0])


def spline_stock():
    """A four-section staircase over the window of test_tool_profiles' STAIR, with exact walls."""
    walls = (wavy_wall(-8.0, 1.5), circle_wall(1.0, 40.0), SplineWall(1, [-16, -16, 16, 16], [[9.0, -16], [9.0, 16]],
                                                                       None))
    points = [[[w.x_at(np.array([y]))[0], y] for y in np.linspace(-15, 15, 6)] for w in walls]
    return Staircase(-20, 20, -15, 15, 0.0, [6.0, 10.0, 4.0, 8.0], points, walls)


SPLINE = spline_stock()
SPLINE_REFERENCE = SplineReference(SPLINE)
STOCKS = {
    "quintic": (STAIRCASE, _Stock(STAIR).inside, [0.0, 4.0, 6.0, 10.0]),
    "spline": (SPLINE, SPLINE_REFERENCE.inside, [0.0, 4.0, 6.0, 8.0, 10.0]),
}


def contour_stock(folder):
    """Model test 1 with its true contour walls (walls.json) as cubic B-splines, as
    resources/models/make_model_solids.contour_wall builds them for the STEP solid."""
    stock = load_staircase(folder / "stock.json")
    walls = []
    for wall in json.loads((folder / "walls.json").read_text())["walls"]:
        points = np.array(wall["points"], dtype=float)
        x, y = points[:, 0], points[:, 1]
        if wall["straight"]:
            walls.append(SplineWall(1, [y[0], y[0], y[-1], y[-1]], [[x[0], y[0]], [x[0], y[-1]]], None))
            continue
        spline = make_interp_spline(y, x, k=3)
        greville = np.array([spline.t[i + 1:i + 4].mean() for i in range(spline.c.size)])
        walls.append(SplineWall(3, spline.t, np.column_stack([spline.c, greville]), None))
    return Staircase(stock.x_min, stock.x_max, stock.y_min, stock.y_max, stock.base_z, stock.z_top,
                     stock.wall_points, tuple(walls))


def sections(stock, x, y):
    """The section holding each point (x, y) (n,): the number of walls with x ≥ W_j(y), B-spline walls by
    SplineReference (Staircase.section_at asks the engine's own curves and bands)."""
    if isinstance(stock.walls[0], SplineWall):
        reference = SplineReference(stock)
        return sum((x >= reference.wall_x(j, y)).astype(int) for j in range(len(stock.walls)))
    return sum((x >= wall.x_at(y)).astype(int) for wall in stock.walls)


def arcs(toolpath, phi, tool):
    """(centre, d, w) (N, 3) of the corner arcs of every CL point × angle (row i·p + k)."""
    r, big = tool.corner_radius, tool.radius
    d = radial_directions(toolpath, phi)
    w = np.broadcast_to(toolpath.axes[:, None, :], d.shape).reshape(-1, 3)
    tip = np.broadcast_to(toolpath.cl[:, None, :], d.shape).reshape(-1, 3)
    d = d.reshape(-1, 3)
    return tip + (big - r) * d + r * w, d, w


def arc_point(centre, d, w, r, s):
    """Points (n, 3) of one arc at arc lengths s (n,) mm."""
    psi = np.asarray(s, dtype=float)[:, None] / r
    return centre - r * np.cos(psi) * w + r * np.sin(psi) * d


def reference_runs(inside, levels, centre, d, w, r, top):
    """The brute-force inside runs [(s0, s1), …] of one arc."""
    span = r * top
    point = lambda s: arc_point(centre, d, w, r, s)  # noqa: E731
    extra = ref.level_hits(levels, centre[2], lambda s: point(s)[:, 2], span)
    return ref.curve_runs(inside, point, span, extra)


def summary(found, row):
    """(length, first start, last end) in s (mm) of one row of EdgeIntervals (NaN, NaN without a run)."""
    k = np.flatnonzero(found.rows == row)
    if k.size == 0:
        return 0.0, np.nan, np.nan
    return float((found.end[k] - found.start[k]).sum()), float(found.start[k[0]]), float(found.end[k[-1]])


def arc_mismatches(stock_name, tool, toolpath, phis=PHI.phi):
    """[(row, engine, reference)] where the corner arcs' length, first start or last end differ by more than TOL."""
    stock, inside, levels = STOCKS[stock_name]
    centre, d, w = arcs(toolpath, phis, tool)
    r, top = tool.corner_radius, corner_top(tool)
    found = staircase_corner_intervals(stock, centre, d, w, r, top)
    bad = []
    for row in range(centre.shape[0]):
        runs = reference_runs(inside, levels, centre[row], d[row], w[row], r, top)
        want = (sum(b - a for a, b in runs), runs[0][0], runs[-1][1]) if runs else (0.0, np.nan, np.nan)
        got = summary(found, row)
        if not np.allclose(got, want, rtol=0.0, atol=TOL, equal_nan=True):
            bad.append((row, got, want))
    return bad


def terraced_mismatches(stock, centre, d, w, r, top, tol):
    """[(row, engine, terraced route)] where length, first start or last end differ by more than tol."""
    terraced, pieces = as_terraced(stock)
    old = corner_intervals(terraced, centre, d, w, r, top, pieces)
    new = staircase_corner_intervals(stock, centre, d, w, r, top)
    bad = []
    for row in np.union1d(old.rows, new.rows):
        a, b = summary(new, row), summary(old, row)
        if not np.allclose(a, b, rtol=0.0, atol=tol, equal_nan=True):
            bad.append((int(row), a, b))
    return bad


@pytest.mark.parametrize("stock_name", sorted(STOCKS))
@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(job=passes(), ratio=st.sampled_from(RATIOS))
def test_tilted_and_turning_axes_agree_with_the_reference(stock_name, job, ratio):
    tool, toolpath = job
    tool = Tool(tool.diameter, 2, tool.flute_length, corner_radius=tool.radius * ratio)
    assert arc_mismatches(stock_name, tool, toolpath) == []


@pytest.mark.parametrize("stock_name", sorted(STOCKS))
@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(job=passes(turned=True), ratio=st.sampled_from(RATIOS))
def test_axes_sideways_and_down_agree_with_the_reference(stock_name, job, ratio):
    tool, toolpath = job
    tool = Tool(tool.diameter, 2, tool.flute_length, corner_radius=tool.radius * ratio)
    assert arc_mismatches(stock_name, tool, toolpath) == []


@pytest.mark.parametrize("stock_name", sorted(STOCKS))
@pytest.mark.parametrize("ratio", RATIOS)
def test_each_ratio_on_a_fixed_pass(stock_name, ratio):
    tool = Tool(10.0, 2, 12.0, corner_radius=5.0 * ratio)
    assert arc_mismatches(stock_name, tool, fixed_pass()) == []


@pytest.mark.parametrize("stock_name", sorted(STOCKS))
def test_a_flute_shorter_than_the_corner_and_an_upright_axis(stock_name):
    cl = np.array([[-8.0, 2.0, 4.5], [0.5, -6.0, 7.0], [9.2, 3.0, 2.0]])
    upright = Toolpath(cl, np.zeros(3), np.zeros(3))
    for tool in (Tool(10.0, 2, 1.5, corner_radius=4.0), Tool(8.0, 2, 20.0, corner_radius=4.0)):
        assert arc_mismatches(stock_name, tool, upright) == []
        assert arc_mismatches(stock_name, tool, fixed_pass()) == []


def test_the_whole_edge_of_a_bull_nose_on_the_exact_stock():
    """The corner joined to the side and the end edge (engage_stock) against the whole-edge reference."""
    tool = Tool(10.0, 2, 12.0, corner_radius=2.0)
    toolpath = fixed_pass()
    engagement = engage_stock(SPLINE, tool, toolpath, PHI)
    assert engagement.engaged.sum() > 20
    bad = []
    for i in range(len(toolpath)):
        for k, phi in enumerate(PHI.phi):
            want = ref.reference_instant(SPLINE_REFERENCE.inside, STOCKS["spline"][2], toolpath.cl[i],
                                         toolpath.theta_a[i], toolpath.theta_b[i], toolpath.alpha[i], phi,
                                         tool.radius, tool.corner_radius, tool.flute_length)
            for name in ("length", "lep_l", "uep_l", "end_length"):
                got = getattr(engagement, name)[i, k]
                if not ((np.isnan(got) and np.isnan(want[name])) or abs(got - want[name]) <= TOL):
                    bad.append((i, phi, name, got, want[name]))
    assert bad == []


def model_pass(count=40):
    """Model test 1's pass, `count` of its CL points spread along it with their axes as read, and the same
    points with axes leaning 30° (half of them pointing down) and frames turned to any feed."""
    toolpath = load_toolpath(MODEL_1 / "toolpath.csv")
    pick = np.linspace(0, len(toolpath) - 1, count).astype(int)
    cl = toolpath.cl[pick]
    turn = np.random.default_rng(3).uniform(-180.0, 180.0, count)
    lean, down = np.radians(30.0), np.where(np.arange(count) % 2 == 0, 1.0, -1.0)
    axes = np.column_stack([np.sin(lean) * np.cos(np.radians(turn)), np.sin(lean) * np.sin(np.radians(turn)),
                            np.cos(lean) * down])
    return toolpath.rows(pick), Toolpath.from_axes(cl, axes, alpha=turn)


@pytest.mark.parametrize("walls", ["quintic", "exact"])
@pytest.mark.parametrize("ratio", RATIOS)
def test_model_test_1_agrees_with_the_terraced_route(walls, ratio):
    stock = load_staircase(MODEL_1 / "stock.json") if walls == "quintic" else contour_stock(MODEL_1)
    tool = Tool(12.0, 2, 30.0, corner_radius=6.0 * ratio)
    for toolpath in model_pass():
        centre, d, w = arcs(toolpath, np.arange(0.0, 360.0, 5.0), tool)
        bad = terraced_mismatches(stock, centre, d, w, tool.corner_radius, corner_top(tool),
                                  QUINTIC_SAME if walls == "quintic" else SAME)
        assert bad == []


@pytest.mark.parametrize("stock_name", sorted(STOCKS))
def test_the_small_stocks_agree_with_the_terraced_route(stock_name):
    stock = STOCKS[stock_name][0]
    for ratio in RATIOS:
        tool = Tool(10.0, 2, 12.0, corner_radius=5.0 * ratio)
        for toolpath in (fixed_pass(), Toolpath(fixed_pass().cl, [150.0, -100.0, 95.0], [80.0, -60.0, 10.0],
                                                alpha=[10.0, 200.0, -45.0])):
            centre, d, w = arcs(toolpath, np.arange(0.0, 360.0, 7.5), tool)
            tol = QUINTIC_SAME if stock_name == "quintic" else SAME
            assert terraced_mismatches(stock, centre, d, w, tool.corner_radius, corner_top(tool), tol) == []


@pytest.mark.parametrize("walls", ["quintic", "exact", "small"])
def test_every_end_lies_on_the_surface_its_label_names(walls):
    """Wall crossings on the wall (x = W_j(y) to ON, quintic or B-spline), tops and the base at their heights,
    the limits on their planes, the arc's ends at s = 0 and r·ψ_max; sections those of the material next
    to each end."""
    stock = {"quintic": lambda: load_staircase(MODEL_1 / "stock.json"), "exact": lambda: contour_stock(MODEL_1),
             "small": lambda: SPLINE}[walls]()
    tool = Tool(12.0, 2, 30.0, corner_radius=3.0)
    r, top = tool.corner_radius, corner_top(tool)
    seen = set()
    for toolpath in (model_pass(25) if walls != "small" else (fixed_pass(),)):
        centre, d, w = arcs(toolpath, np.arange(0.0, 360.0, 4.0), tool)
        found = staircase_corner_intervals(stock, centre, d, w, r, top)
        for end, inward in (("start", 1e-7), ("end", -1e-7)):
            s = getattr(found, end)
            code, wall, section = (getattr(found, f"{end}_{name}") for name in ("surface", "wall", "section"))
            point = np.array([arc_point(centre[i], d[i], w[i], r, [v])[0] for i, v in zip(found.rows, s)])
            near = np.array([arc_point(centre[i], d[i], w[i], r, [v + inward])[0] for i, v in zip(found.rows, s)])
            np.testing.assert_array_equal(section, sections(stock, near[:, 0], near[:, 1]))
            for k in range(found.rows.size):
                name = "CORNER_TOP" if code[k] == CORNER_TOP else SURFACES[code[k]]
                seen.add(name)
                x, y, z = point[k]
                if name in ("straight_wall", "curved_wall") and 0 < wall[k] < stock.n_sections:
                    assert abs(x - stock.walls[wall[k] - 1].x_at(np.array([y]))[0]) <= ON
                elif name == "straight_wall":
                    assert abs(x - (stock.x_min if wall[k] == 0 else stock.x_max)) <= ON
                elif name == "stock_side":
                    assert min(abs(y - stock.y_min), abs(y - stock.y_max)) <= ON and wall[k] == -1
                elif name == "top":
                    assert np.abs(z - stock.z_top).min() <= ON and wall[k] == -1
                elif name == "bottom":
                    assert abs(z - stock.base_z) <= ON and wall[k] == -1
                elif name == "flute_start":
                    assert s[k] == 0.0 and end == "start"
                else:
                    assert name == "CORNER_TOP" and end == "end" and s[k] == pytest.approx(r * top, abs=1e-12)
    assert {"top", "curved_wall", "flute_start", "CORNER_TOP"} <= seen


def test_a_b_spline_wall_is_read_at_its_knots():
    """On model test 1's contour walls the bands' bin edges are knots; a piece's side of a wall at a knot's
    y (here: every arc of an upright tool at y = 0 lies there) is that of the curve's point."""
    stock = contour_stock(MODEL_1)
    knots = np.concatenate([w.span_y for w in stock.walls])
    walls = np.repeat(np.arange(len(stock.walls)), [w.span_y.size for w in stock.walls])
    x = corner_staircase._spline_x(stock.splines, walls, knots)
    want = np.concatenate([SplineReference(stock).wall_x(j, w.span_y) for j, w in enumerate(stock.walls)])
    np.testing.assert_allclose(x, want, rtol=0.0, atol=1e-9)
    tool = Tool(12.0, 2, 30.0, corner_radius=3.0)
    toolpath = Toolpath(np.column_stack([np.linspace(5.0, 120.0, 30), np.zeros(30), np.linspace(0, 20, 30)]),
                        np.zeros(30), np.zeros(30))
    centre, d, w = arcs(toolpath, [90.0, 270.0], tool)
    assert terraced_mismatches(stock, centre, d, w, 3.0, corner_top(tool), SAME) == []


@pytest.mark.parametrize("plant", ["centre", "sweep"])
def test_a_planted_error_in_the_corner_is_caught(monkeypatch, plant):
    """The whole-edge comparison of test_tool_profiles fails on the staircase when the corner's centre moves
    by 0.01 mm or its arc turns the wrong way (profile_intervals calls staircase_corner_intervals there)."""
    tool = Tool(10.0, 2, 12.0, corner_radius=2.0)
    toolpath = fixed_pass()
    original = profile.staircase_corner_intervals

    def planted(stock, centre, d, w, radius, psi_max):
        if plant == "centre":
            return original(stock, centre + 0.01 * w, d, w, radius, psi_max)
        return original(stock, centre, -d, w, radius, psi_max)

    assert mismatches(engage_stock(STAIRCASE, tool, toolpath, PHI), "staircase", tool, toolpath) == []
    monkeypatch.setattr(profile, "staircase_corner_intervals", planted)
    assert mismatches(engage_stock(STAIRCASE, tool, toolpath, PHI), "staircase", tool, toolpath) != []


@pytest.mark.parametrize("plant", ["quintic root", "spline root", "section"])
def test_a_planted_error_in_the_solver_is_caught(monkeypatch, plant):
    """A wall crossing moved by 1e-5 rad, or a section miscounted, fails the reference and the terraced route."""
    stock_name = "spline" if plant == "spline root" else "quintic"
    tool = Tool(10.0, 2, 12.0, corner_radius=3.0)
    toolpath = fixed_pass()
    stock = STOCKS[stock_name][0]
    centre, d, w = arcs(toolpath, PHI.phi, tool)
    assert arc_mismatches(stock_name, tool, toolpath) == []
    if plant == "quintic root":
        original = corner_staircase._quintic_roots
        monkeypatch.setattr(corner_staircase, "_quintic_roots", lambda *a: original(*a) + 1e-5)
    elif plant == "spline root":
        original = corner_staircase._polished
        monkeypatch.setattr(corner_staircase, "_polished", lambda *a: original(*a) + 1e-5)
    else:
        original = corner_staircase._candidate_walls
        monkeypatch.setattr(corner_staircase, "_candidate_walls",
                            lambda *a: (lambda rows, walls, left: (rows, walls, left + (left > 0)))(*original(*a)))
    assert arc_mismatches(stock_name, tool, toolpath) != []
    assert terraced_mismatches(stock, centre, d, w, 3.0, corner_top(tool), TOL) != []


def test_arcs_outside_the_stock_and_empty_input():
    tool = Tool(10.0, 2, 12.0, corner_radius=3.0)
    far = Toolpath(np.array([[100.0, 0.0, 5.0], [0.0, 0.0, 50.0]]), np.zeros(2), np.zeros(2))
    centre, d, w = arcs(far, PHI.phi, tool)
    found = staircase_corner_intervals(STAIRCASE, centre, d, w, 3.0, corner_top(tool))
    assert found.n_rows == centre.shape[0] and found.rows.size == 0
    empty = staircase_corner_intervals(STAIRCASE, np.zeros((0, 3)), np.zeros((0, 3)), np.zeros((0, 3)), 3.0, 1.0)
    assert empty.n_rows == 0 and empty.rows.size == 0
    with pytest.raises(ValueError, match=r"\(N, 3\)"):
        staircase_corner_intervals(STAIRCASE, np.zeros((2, 3)), np.zeros((3, 3)), np.zeros((2, 3)), 3.0, 1.0)


def test_profile_intervals_takes_the_staircase_solver(monkeypatch):
    """profile_intervals solves a Staircase's corner here and a TerracedStock's in corner.py."""
    called = []
    original = profile.staircase_corner_intervals
    monkeypatch.setattr(profile, "staircase_corner_intervals", lambda *a: called.append(1) or original(*a))
    monkeypatch.setattr(profile, "corner_intervals", lambda *a: pytest.fail("the terraced route was taken"))
    engage_stock(STAIRCASE, Tool(10.0, 2, 12.0, corner_radius=3.0), fixed_pass(), CutSettings(0.1, phi_step=30.0))
    assert called


def test_spline_wall_x_at_at_a_knot():
    """A knot whose span's start y rounds below it: x_at keeps the span the point is on (bracketed_root
    may return the bracket's end there)."""
    stock = contour_stock(MODEL_1)
    y = np.array([-3.75, -3.28125])
    np.testing.assert_allclose(stock.walls[0].x_at(y), SplineReference(stock).wall_x(0, y), rtol=0.0, atol=1e-9)
