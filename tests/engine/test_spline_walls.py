"""Exact (B-spline) walls: the engine's SplineWall against a quintic twin and a brute-force check."""

from math import comb

import numpy as np
import pytest
from scipy.interpolate import BSpline, make_interp_spline

from abm_workbench.engine import CutSettings, Staircase, Tool, Toolpath, edge_lines, engage
from abm_workbench.engine.walls import SplineWall, Wall

TOL = 1e-6  # mm, engine against the brute-force reference
TWIN_TOL = 1e-9  # mm, the same curve in two representations


def bezier_twin(wall, y_lo, y_hi):
    """The quintic wall x = P(y) over [y_lo, y_hi] as a degree-5 Bézier SplineWall (exactly)."""
    v = np.linspace(0.0, 1.0, 6)
    y = y_lo + (y_hi - y_lo) * v
    # power coefficients in v from six exact samples, then Bernstein control points
    power = np.linalg.solve(np.vander(v, 6, increasing=True), wall.x_at(y))
    poles_x = [sum(comb(i, k) / comb(5, k) * power[k] for k in range(i + 1)) for i in range(6)]
    poles = np.column_stack([poles_x, y_lo + (y_hi - y_lo) * np.arange(6) / 5])
    return SplineWall(5, np.r_[[y_lo] * 6, [y_hi] * 6], poles, None)


def quintic_stock():
    ys = np.linspace(-15, 15, 6)
    walls = [[[30 + 3 * np.sin(0.15 * y) + 0.01 * y * y, y] for y in ys], [[55.0, y] for y in ys],
             [[80 - 4 * np.cos(0.1 * y), y] for y in ys]]
    return Staircase(0, 110, -15, 15, -20, [3.0, 7.0, 4.0, 9.0], walls)


def random_path(rng, m):
    cl = np.column_stack([rng.uniform(15, 95, m), rng.uniform(-6, 6, m), rng.uniform(-1, 6, m)])
    return Toolpath(cl, rng.uniform(-25, 25, m), rng.uniform(-30, 30, m))


def test_bezier_twin_of_a_quintic_gives_the_same_engagement():
    stock = quintic_stock()
    twin = Staircase(stock.x_min, stock.x_max, stock.y_min, stock.y_max, stock.base_z, stock.z_top,
                     stock.wall_points, tuple(bezier_twin(w, -15, 15) for w in stock.walls))
    assert twin.walls[1].is_straight and not twin.walls[0].is_straight
    rng = np.random.default_rng(7)
    path, tool, settings = random_path(rng, 40), Tool(12, 2, 25), CutSettings(0.1, 10, 0, 180, 3)
    a, b = engage(stock, tool, path, settings), engage(twin, tool, path, settings)
    assert a.engaged.sum() > 500
    np.testing.assert_allclose(b.length, a.length, atol=TWIN_TOL, rtol=0)
    np.testing.assert_allclose(b.lep_l, a.lep_l, atol=TWIN_TOL, rtol=0)
    np.testing.assert_allclose(b.uep_l, a.uep_l, atol=TWIN_TOL, rtol=0)
    np.testing.assert_array_equal(b.uep_surface, a.uep_surface)


def wavy_spline_wall(x_centre, amplitude, y_lo=-15.0, y_hi=15.0):
    """A cubic B-spline wall interpolating a wavy contour, with non-uniform parameter."""
    s = np.linspace(0.0, 1.0, 14) ** 1.3
    y = y_lo + (y_hi - y_lo) * s
    x = x_centre + amplitude * np.sin(0.35 * y) + 0.02 * y * y
    spline = make_interp_spline(s, np.column_stack([x, y]), k=3)
    return spline.t, spline.c


class BruteForce:
    """Height field of a staircase whose walls are scipy B-splines (x(s), y(s)), sampled densely."""

    def __init__(self, stock, splines):
        self.stock = stock
        self.curves = [BSpline(t, c, 3) for t, c in splines]
        self.tables = []
        for curve, (t, _) in zip(self.curves, splines):
            s = np.linspace(t[0], t[-1], 4001)
            self.tables.append((s, curve(s)[:, 1]))

    def wall_x(self, j, y):
        """x of wall j at heights y (K,): bracket in a dense table, then bisection on s."""
        s_table, y_table = self.tables[j]
        k = np.clip(np.searchsorted(y_table, y) - 1, 0, s_table.size - 2)
        a, b = s_table[k], s_table[k + 1]
        for _ in range(42):  # the table bracket is 1/4000 of s: 2^-42 of it is far below 1e-9 mm
            m = 0.5 * (a + b)
            below = self.curves[j](m)[:, 1] < y
            a, b = np.where(below, m, a), np.where(below, b, m)
        return self.curves[j](0.5 * (a + b))[:, 0]

    def inside(self, p):
        """Inside test of points p (K, 3)."""
        st = self.stock
        x, y, z = p.T
        box = (st.x_min <= x) & (x <= st.x_max) & (st.y_min <= y) & (y <= st.y_max) & (st.base_z <= z)
        section = sum((x >= self.wall_x(j, y)).astype(int) for j in range(len(self.curves)))
        return box & (z <= st.z_top[section])

    def pieces(self, bases, directions, length, samples=2001):
        """Inside pieces [(l0, l1), ...] of each edge bases[k] + l·directions[k], 0 ≤ l ≤ length.

        bases, directions: (K, 3); all lines are sampled and refined together.
        """
        l = np.linspace(0, length, samples)
        points = bases[:, None, :] + l[None, :, None] * directions[:, None, :]
        state = self.inside(points.reshape(-1, 3)).reshape(len(bases), samples)
        line, k = np.nonzero(state[:, 1:] != state[:, :-1])
        a, b = l[k], l[k + 1]
        for _ in range(60):
            m = 0.5 * (a + b)
            same = self.inside(bases[line] + m[:, None] * directions[line]) == state[line, k]
            a, b = np.where(same, m, a), np.where(same, b, m)
        edges = 0.5 * (a + b)
        result = []
        for i in range(len(bases)):
            bounds = ([0.0] if state[i, 0] else []) + list(edges[line == i]) + ([length] if state[i, -1] else [])
            result.append(list(zip(bounds[::2], bounds[1::2])))
        return result


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_cubic_spline_walls_against_brute_force(seed):
    splines = [wavy_spline_wall(35, 2.5), wavy_spline_wall(60, -3.0)]
    walls = tuple(SplineWall(3, t, c, None) for t, c in splines)
    points = [[[w.x_at(y), y] for y in np.linspace(-15, 15, 6)] for w in walls]
    stock = Staircase(0, 100, -15, 15, -10, [2.0, 6.0, 3.5], points, walls)
    rng = np.random.default_rng(seed)
    path, tool = random_path(rng, 6), Tool(10, 2, 20)
    settings = CutSettings(0.1, 0, 0, 180, 20)
    result = engage(stock, tool, path, settings)
    reference = BruteForce(stock, splines)

    base, direction = edge_lines(path, tool, settings.phi)
    p = settings.phi.size
    all_pieces = reference.pieces(base.reshape(-1, 3), np.repeat(direction, p, axis=0), tool.flute_length)
    checked = 0
    for i in range(len(path)):
        for k in range(p):
            pieces = all_pieces[i * p + k]
            length = sum(b - a for a, b in pieces)
            assert result.length[i, k] == pytest.approx(length, abs=TOL)
            if pieces:
                checked += 1
                assert result.lep_l[i, k] == pytest.approx(pieces[0][0], abs=TOL)
                assert result.uep_l[i, k] == pytest.approx(pieces[-1][1], abs=TOL)
    assert checked > 10


def test_spline_wall_x_at_matches_the_curve_and_clamps_beyond_its_ends():
    t, c = wavy_spline_wall(40, 2.0)
    wall = SplineWall(3, t, c, None)
    curve = BSpline(t, c, 3)
    s = np.linspace(0.05, 0.95, 17)
    xy = curve(s)
    np.testing.assert_allclose(wall.x_at(xy[:, 1]), xy[:, 0], atol=1e-10)
    assert wall.x_at(-100.0) == pytest.approx(curve(t[0])[0])
    low, high = wall.x_range(-15, 15)
    assert low <= xy[:, 0].min() and high >= xy[:, 0].max()


def test_spline_wall_refuses_bad_data():
    t, c = wavy_spline_wall(40, 2.0)
    with pytest.raises(ValueError, match="knots"):
        SplineWall(3, t[:-1], c, None)
    with pytest.raises(ValueError, match="weights"):
        SplineWall(3, t, c, -np.ones(len(c)))
    folded = c.copy()
    folded[:, 1] = np.sin(np.linspace(0, 6, len(c)))
    with pytest.raises(ValueError, match="monotone"):
        SplineWall(3, t, folded, None)
    assert isinstance(Wall.from_points([[1, y] for y in range(6)]), Wall)
