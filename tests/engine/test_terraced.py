"""engine.terraced against the brute-force reference of terraced_reference, the staircase engine
and fixed degenerate cases."""

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.interpolate import BSpline

from abm_workbench.engine import CASES, SURFACES, CutSettings, Tool, Toolpath, engage
from abm_workbench.engine.interval_engagement import engagement_from_intervals
from abm_workbench.engine.terraced import engage_terraced, terraced_intervals
from abm_workbench.engine.terraced_model import Loop, PlanArc, PlanLine, PlanSpline, Slab, TerracedStock
from abm_workbench.engine.terraced_pieces import curve_list, spline_pieces
from abm_workbench.engine.terraced_staircase import staircase_as_terraced
from abm_workbench.formats.staircase_json import load_staircase

from . import terraced_reference as ref

TOL = 1e-9  # mm: exact loops (polygons, circles, stadiums) against bisection to 1e-13
CODE = {name: i for i, name in enumerate(SURFACES)}


def rotate(points, angle):
    """Plan points (..., 2) turned by `angle` (radians) about the origin."""
    c, s = np.cos(angle), np.sin(angle)
    points = np.asarray(points, dtype=float)
    return np.stack([c * points[..., 0] - s * points[..., 1], s * points[..., 0] + c * points[..., 1]], axis=-1)


def to_loop(data, face=""):
    """The engine's Loop of a reference loop (polygon, circle or stadium)."""
    kind = data[0]
    if kind == "polygon":
        v = np.asarray(data[1], dtype=float)
        return Loop(tuple(PlanLine(v[i], v[(i + 1) % len(v)], face) for i in range(len(v))))
    if kind == "circle":
        return Loop((PlanArc(data[1], data[2], data[3] if len(data) > 3 else 0.3, 2 * np.pi, face),))
    a, b, r = np.asarray(data[1], float), np.asarray(data[2], float), data[3]
    e = (b - a) / np.hypot(*(b - a))
    n = np.array([-e[1], e[0]])
    ang = np.arctan2(n[1], n[0])
    return Loop((PlanLine(a - r * n, b - r * n, face), PlanArc(b, r, ang - np.pi, np.pi, face),
                 PlanLine(b + r * n, a + r * n, face), PlanArc(a, r, ang, np.pi, face)))


def to_stock(slabs):
    """TerracedStock of reference slabs."""
    return TerracedStock(tuple(Slab(z0, z1, tuple(to_loop(loop) for loop in loops)) for z0, z1, loops in slabs))


def floats(lo, hi):
    return st.floats(lo, hi, allow_nan=False, allow_infinity=False)


@st.composite
def loops(draw, angle):
    """A random reference loop, turned by `angle`: star polygon, circle or stadium."""
    kind = draw(st.sampled_from(["polygon", "circle", "stadium"]))
    centre = np.array([draw(floats(-8, 8)), draw(floats(-8, 8))])
    if kind == "polygon":
        k = draw(st.integers(3, 9))
        gaps = np.array(draw(st.lists(floats(0.2, 1.0), min_size=k, max_size=k)))
        theta = np.cumsum(gaps) / gaps.sum() * 2 * np.pi
        radii = np.array(draw(st.lists(floats(1.0, 9.0), min_size=k, max_size=k)))
        vertices = centre + radii[:, None] * np.stack([np.cos(theta), np.sin(theta)], axis=1)
        return ("polygon", rotate(vertices, angle))
    if kind == "circle":
        return ("circle", rotate(centre, angle), draw(floats(0.5, 8.0)), draw(floats(-3, 3)))
    other = centre + np.array([draw(floats(-8, 8)), draw(floats(-8, 8))])
    if np.hypot(*(other - centre)) < 0.5:
        other = centre + np.array([1.0, 0.7])
    return ("stadium", rotate(centre, angle), rotate(other, angle), draw(floats(0.3, 5.0)))


@st.composite
def stocks(draw):
    """Reference slabs: 1-25 levels, 1-3 loops each (overlapping loops: even-odd)."""
    n = draw(st.integers(1, 25))
    angle = draw(floats(0, 2 * np.pi))
    heights = np.cumsum([0.0] + draw(st.lists(floats(0.1, 3.0), min_size=n, max_size=n))) - 4.0
    return [(float(heights[k]), float(heights[k + 1]), draw(st.lists(loops(angle), min_size=1, max_size=3)))
            for k in range(n)]


def random_lines(rng, slabs, n):
    """n lines (origins (n, 3), unit directions (n, 3)) through the stock's box; some vertical,
    some horizontal, some falling."""
    z_lo, z_hi = slabs[0][0], slabs[-1][1]
    origins = np.column_stack([rng.uniform(-14, 14, n), rng.uniform(-14, 14, n), rng.uniform(z_lo - 2, z_hi, n)])
    directions = rng.normal(size=(n, 3))
    directions[: n // 6, :2] = 0.0
    directions[n // 6: n // 3, 2] = 0.0
    directions[n // 3:, 2] = np.abs(directions[n // 3:, 2])
    directions[-2:, 2] *= -1
    return origins, directions / np.linalg.norm(directions, axis=1, keepdims=True)


def check_against_reference(slabs, origins, directions, length, tol=TOL, labels=True):
    """engine.terraced_intervals against ref.line_runs, line by line: runs, and the surfaces at
    each run's ends."""
    stock = to_stock(slabs)
    found = terraced_intervals(stock, origins, directions, length)
    curves = curve_list(stock)
    for row in range(origins.shape[0]):
        expected = ref.line_runs(slabs, origins[row], directions[row], length)
        mine = np.flatnonzero(found.rows == row)
        got = list(zip(found.start[mine], found.end[mine]))
        assert len(got) == len(expected), (row, got, expected)
        for (a, b), (c, d) in zip(got, expected):
            assert abs(a - c) < tol and abs(b - d) < tol, (row, got, expected)
        if not labels:
            continue
        for i, (a, b) in zip(mine, expected):
            for l, surface, wall, section, end in ((a, found.start_surface[i], found.start_wall[i],
                                                    found.start_section[i], "start"),
                                                   (b, found.end_surface[i], found.end_wall[i],
                                                    found.end_section[i], "end")):
                point = origins[row] + l * directions[row]
                if l in (0.0, length):
                    assert surface == CODE["flute_start" if end == "start" else "flute_end"]
                    continue
                what = ref.surface_at(slabs, point)
                if what[0] == "level":
                    # rising: a run starts on a face looking down and ends on one looking up
                    up = (end == "end") == (directions[row, 2] > 0)
                    assert surface == CODE["top" if up else "bottom"], (row, what, surface)
                    assert slabs[section][1 if up else 0] == what[1]
                else:
                    assert surface in (CODE["straight_wall"], CODE["curved_wall"]), (row, what, surface)
                    assert curves[wall][:2] == what[1:], (row, what, curves[wall][:3])


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(stocks(), st.integers(0, 2**32 - 1), floats(5.0, 60.0))
def test_random_stocks_match_reference(slabs, seed, length):
    origins, directions = random_lines(np.random.default_rng(seed), slabs, 16)
    check_against_reference(slabs, origins, directions, length)


@settings(max_examples=25, deadline=None)
@given(stocks(), st.integers(0, 2**32 - 1), floats(0.0, 2 * np.pi))
def test_rotation_about_z_keeps_lengths(slabs, seed, angle):
    origins, directions = random_lines(np.random.default_rng(seed), slabs, 24)
    turned = []
    for z0, z1, loops in slabs:
        new = []
        for loop in loops:
            if loop[0] == "polygon":
                new.append(("polygon", rotate(loop[1], angle)))
            elif loop[0] == "circle":
                new.append(("circle", rotate(loop[1], angle), loop[2], loop[3] + angle))
            else:
                new.append(("stadium", rotate(loop[1], angle), rotate(loop[2], angle), loop[3]))
        turned.append((z0, z1, new))
    o2 = np.column_stack([rotate(origins[:, :2], angle), origins[:, 2]])
    d2 = np.column_stack([rotate(directions[:, :2], angle), directions[:, 2]])
    a = terraced_intervals(to_stock(slabs), origins, directions, 30.0)
    b = terraced_intervals(to_stock(turned), o2, d2, 30.0)
    assert np.allclose(a.length, b.length, rtol=0, atol=1e-8)


def star_spline(rational):
    """A closed cubic B-spline loop (clamped, first control point = last) around (1, 2), and a
    fine polyline of it from scipy (independent of the engine's Bézier spans)."""
    k = 9
    theta = np.linspace(0, 2 * np.pi, k, endpoint=False)
    radii = np.array([6.0, 3.0, 7.0, 4.0, 6.5, 2.5, 5.5, 4.5, 6.0])
    control = np.array([1.0, 2.0]) + radii[:, None] * np.stack([np.cos(theta), np.sin(theta)], axis=1)
    control = np.vstack([control, control[:1]])
    knots = np.concatenate([[0, 0, 0], np.linspace(0, 1, len(control) - 2), [1, 1, 1]])
    weights = np.linspace(0.5, 2.0, len(control)) if rational else None
    if rational:
        weights[-1] = weights[0]
    spline = PlanSpline(3, knots, control, weights)
    t = np.linspace(0, 1, 100001)
    w = np.ones(len(control)) if weights is None else weights
    num = BSpline(knots, control * w[:, None], 3)(t)
    den = BSpline(knots, w, 3)(t)
    return spline, num / den[:, None]


@pytest.mark.parametrize("rational", [False, True])
def test_spline_loop_matches_polyline_reference(rational):
    spline, polyline = star_spline(rational)
    rng = np.random.default_rng(7)
    origins, directions = random_lines(rng, [(0.0, 5.0, None)], 24)
    stock = TerracedStock((Slab(0.0, 5.0, (Loop((spline,)), to_loop(("circle", (1.0, 2.0), 1.0)))),))
    slabs = [(0.0, 5.0, [("polyline", polyline), ("circle", (1.0, 2.0), 1.0)])]
    found = terraced_intervals(stock, origins, directions, 40.0)
    expected = [sum(b - a for a, b in ref.line_runs(slabs, origins[r], directions[r], 40.0)) for r in range(24)]
    # polyline chords of ~5e-4 mm: their sagitta is below 1e-7 mm
    assert np.allclose(found.length, expected, rtol=0, atol=1e-6)


def test_spline_pieces_reproduce_the_spline():
    spline, _ = star_spline(True)
    control, weights = spline_pieces(spline)
    u = np.linspace(0, 1, 7)
    b = np.stack([(1 - u) ** 3, 3 * u * (1 - u) ** 2, 3 * u ** 2 * (1 - u), u ** 3], axis=1)
    spans = control.shape[0]
    points = np.einsum("uk,skc->suc", b, control * weights[..., None]) / np.einsum("uk,sk->su", b, weights)[..., None]
    distinct = np.unique(spline.knots)
    t = (distinct[:-1, None] + u * np.diff(distinct)[:, None]).reshape(-1)
    w = spline.weights
    knots = np.array(spline.knots)
    expected = BSpline(knots, spline.control * w[:, None], 3)(t) / BSpline(knots, np.array(w), 3)(t)[:, None]
    assert spans == distinct.size - 1
    assert np.allclose(points.reshape(-1, 2), expected, rtol=0, atol=1e-12)


def square(a, b, c, d):
    return ("polygon", np.array([[a, b], [c, b], [c, d], [a, d]], dtype=float))


def test_degenerate_lines():
    slabs = [(0.0, 2.0, [square(0, 0, 10, 10)]), (2.0, 4.0, [("circle", (5.0, 5.0), 3.0, 0.0)])]
    stock = to_stock(slabs)
    s2 = np.sqrt(0.5)
    origins = np.array([
        [-1.0, 10.0, 1.0],   # along the top edge y = 10, material on the right: inside
        [-1.0, 0.0, 1.0],    # along the bottom edge, material on the left: outside
        [-1.0, -1.0, 1.0],   # through two corners along the diagonal
        [5.0, 2.0, 3.0],     # tangent to the circle at (5, 2)
        [5.0, 5.0, -1.0],    # vertical through both slabs
        [0.0, 5.0, -1.0],    # vertical on the square's side (x = 0): ray to +x crosses once
        [3.0, 3.0, 2.0],     # horizontal on the level between slabs: belongs to the upper slab
    ])
    directions = np.array([[1, 0, 0], [1, 0, 0], [s2, s2, 0], [1, 0, 0], [0, 0, 1], [0, 0, 1], [1, 0, 0]], float)
    found = terraced_intervals(stock, origins, directions, 20.0)
    assert np.allclose(found.length[:6], [10.0, 0.0, 10 * np.sqrt(2), 0.0, 4.0, 2.0], rtol=0, atol=1e-12)
    # the horizontal line at z = 2 lies in the upper slab: from x = 3 to the circle at y = 3
    assert abs(found.length[6] - (2.0 + np.sqrt(5.0))) < 1e-12
    vertical = np.flatnonzero(found.rows == 4)
    assert found.count[4] == 1 and found.start[vertical[0]] == 1.0 and found.end[vertical[0]] == 5.0
    assert found.start_surface[vertical[0]] == CODE["bottom"] and found.end_surface[vertical[0]] == CODE["top"]
    assert found.end_section[vertical[0]] == 1


def test_staircase_special_case_matches_engage():
    for test in (1, 2):
        folder = f"resources/models/model_test_{test}/"
        staircase = load_staircase(folder + "stock.json")
        toolpath = Toolpath.from_axes(*_toolpath(folder + "toolpath.csv"))
        tool, cut = Tool(12.0, 2, 30.0), CutSettings(0.1, 10.0, 0.0, 180.0, 2.0)
        a = engage(staircase, tool, toolpath, cut)
        b = engage_terraced(staircase_as_terraced(staircase), tool, toolpath, cut)
        assert np.abs(a.length - b.length).max() < 1e-9
        assert np.array_equal(np.isnan(a.lep_l), np.isnan(b.lep_l))
        assert np.nanmax(np.abs(a.lep_l - b.lep_l)) < 1e-9 and np.nanmax(np.abs(a.uep_l - b.uep_l)) < 1e-9
        assert np.array_equal(a.pieces, b.pieces)
        side = a.uep_surface == CODE["stock_side"]
        assert np.array_equal(a.uep_surface[~side], b.uep_surface[~side])
        assert (b.case[b.engaged] == CASES.index("2.5D")).all() and (b.lep_surface[~b.engaged] == 0).all()


def _toolpath(path):
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    return data[:, :3], data[:, 3:6]


def test_engagement_fields_and_labels():
    slabs = [(0.0, 3.0, [square(0, 0, 20, 10)]), (3.0, 6.0, [square(10, 0, 20, 10)])]
    stock = to_stock(slabs)
    cl = np.array([[5.0, 5.0, 1.0], [8.5, 5.0, 1.0]])
    toolpath = Toolpath.from_axes(cl, np.tile([0.0, 0.0, 1.0], (2, 1)))
    tool, cut = Tool(4.0, 2, 10.0), CutSettings(0.1, 0.0, 0.0, 180.0, 90.0)
    e = engage_terraced(stock, tool, toolpath, cut)
    # CL 0: every edge in the lower slab only, from its start (z 1) to the top z 3; CL 1 at
    # φ = 90°: the edge at x = 10.5 rises through both slabs to z 6.
    assert e.length[0].tolist() == [2.0, 2.0, 2.0]
    assert e.uep_surface[0].tolist() == [CODE["top"]] * 3 and (e.lep_surface[0] == CODE["flute_start"]).all()
    assert e.length[1, 1] == 5.0 and e.uep_section[1, 1] == 1
    assert np.allclose(e.uep_xyz[1, 1], [10.5, 5.0, 6.0])
    assert e.depth_of_cut[1] == 5.0


def test_bad_line_arrays():
    stock = to_stock([(0.0, 1.0, [square(0, 0, 1, 1)])])
    with pytest.raises(ValueError, match="origins and directions"):
        terraced_intervals(stock, np.zeros((3, 3)), np.ones((2, 3)), 1.0)


def test_chunks_change_nothing_and_bad_interval_counts_are_refused():
    slabs = [(0.0, 3.0, [square(0, 0, 20, 10), ("circle", (8.0, 5.0), 2.0, 0.0)]), (3.0, 6.0, [square(10, 0, 20, 10)])]
    stock = to_stock(slabs)
    cl = np.column_stack([np.linspace(2, 18, 7), np.full(7, 5.0), np.full(7, 1.0)])
    axes = np.column_stack([np.full(7, 0.2), np.full(7, -0.1), np.ones(7)])
    toolpath = Toolpath.from_axes(cl, axes)
    tool, cut = Tool(4.0, 2, 10.0), CutSettings(0.1, 5.0, 0.0, 180.0, 10.0)
    whole = engage_terraced(stock, tool, toolpath, cut)
    pieces = engage_terraced(stock, tool, toolpath, cut, chunk_instants=20)
    for name in ("length", "lep_l", "uep_l", "uep_surface", "lep_surface", "lep_wall", "segment", "depth_of_cut"):
        assert np.array_equal(getattr(whole, name), getattr(pieces, name), equal_nan=name != "segment")
    found = terraced_intervals(stock, np.zeros((3, 3)), np.tile([0.0, 0.0, 1.0], (3, 1)), 5.0)
    with pytest.raises(ValueError, match="need 133 lines"):
        engagement_from_intervals(found, toolpath, tool, cut, np.zeros((3, 3)), np.zeros((3, 3)))
