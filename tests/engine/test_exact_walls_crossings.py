"""Where edge lines cross exact (B-spline) walls: SplineTable.crossings against a reference written here.

The reference knows nothing of spans or power bases: it evaluates the curve with
scipy.interpolate.BSpline (a NURBS as two B-splines, numerator and weight), samples the cross
product of the line's direction with the curve point densely along the curve parameter, bisects
every sign change, and finds touching points at the sampled extrema by golden-section search.
Sides (x ≥ W(y)) come from bisection of y(s) = y on the curve. Cases: random lines of every
direction (those proved to cross once and the others), lines through the knots, tangent and
nearly tangent lines, segments ending at a crossing, and a circle arc as a rational span.
"""

import numpy as np
import pytest
from scipy.interpolate import BSpline, make_interp_spline

from abm_workbench.engine.walls import SplineTable, SplineWall

TOL = 1e-9  # mm, crossings and their l against the reference
SAMPLES = 40001  # samples of the curve parameter in the reference


class Curve:
    """A (rational) B-spline curve s -> (x, y) evaluated by scipy, the reference's only geometry."""

    def __init__(self, knots, poles, degree, weights=None):
        self.weights = np.ones(len(poles)) if weights is None else np.asarray(weights, dtype=float)
        self.numerator = BSpline(knots, np.asarray(poles) * self.weights[:, None], degree)
        self.denominator = BSpline(knots, self.weights, degree)
        self.s0, self.s1 = knots[degree], knots[-degree - 1]
        self.knots = np.unique(knots[degree:-degree])

    def __call__(self, s):
        """(K, 2) points at parameters s (K,)."""
        return self.numerator(s) / self.denominator(s)[:, None]

    def wall_x(self, y):
        """x of the curve at heights y (K,) (y monotone along the curve), by bisection on s."""
        a, b = np.full(np.shape(y), self.s0), np.full(np.shape(y), self.s1)
        rising = self([self.s1])[0, 1] > self([self.s0])[0, 1]
        for _ in range(80):
            m = 0.5 * (a + b)
            below = (self(m)[:, 1] < y) == rising
            a, b = np.where(below, m, a), np.where(below, b, m)
        return self(0.5 * (a + b))[:, 0]


def reference(curve, x0, y0, dx, dy, lo, hi):
    """Sorted l in [lo, hi] where the line (x0, y0) + l·(dx, dy) meets the curve, and the sides at lo, hi."""
    cross = lambda s: (curve(s)[:, 0] - x0) * dy - (curve(s)[:, 1] - y0) * dx  # noqa: E731
    s = np.linspace(curve.s0, curve.s1, SAMPLES)
    f = cross(s)
    found = list(s[f == 0.0])
    k = np.flatnonzero(f[:-1] * f[1:] < 0.0)
    a, b = s[k], s[k + 1]
    for _ in range(70):
        m = 0.5 * (a + b)
        same = np.sign(cross(m)) == np.sign(f[k])
        a, b = np.where(same, m, a), np.where(same, b, m)
    found += list(0.5 * (a + b))
    # Touching points: extrema of the sampled cross product with no sign change around them.
    for i in np.flatnonzero((f[1:-1] - f[:-2]) * (f[2:] - f[1:-1]) < 0.0) + 1:
        if f[i - 1] * f[i + 1] <= 0.0 or f[i - 1] * f[i] <= 0.0 or abs(f[i]) > 1e-3:
            continue  # a sign change (bisected above), or too far from zero to touch within two samples
        lo_s, hi_s, sign = s[i - 1], s[i + 1], np.sign(f[i])
        for _ in range(80):  # golden section towards the extremum
            c = hi_s - 0.618 * (hi_s - lo_s)
            d = lo_s + 0.618 * (hi_s - lo_s)
            if sign * cross(np.array([c]))[0] < sign * cross(np.array([d]))[0]:
                hi_s = d
            else:
                lo_s = c
        if abs(cross(np.array([0.5 * (lo_s + hi_s)]))[0]) < 1e-9:
            found.append(0.5 * (lo_s + hi_s))
    points = curve(np.array(found)) if found else np.empty((0, 2))
    l = ((points[:, 0] - x0) * dx + (points[:, 1] - y0) * dy) / (dx * dx + dy * dy)
    l = np.sort(l[(l >= lo) & (l <= hi)])
    ends = np.array([lo, hi])
    sides = x0 + dx * ends >= curve.wall_x(y0 + dy * ends)
    return l, sides


def distinct(values, tol=TOL):
    """Sorted values with those within tol of the previous one dropped."""
    values = np.sort(values[~np.isnan(values)])
    return values[np.concatenate([[True], np.diff(values) > tol])] if values.size else values


def wavy_curve(rational=False):
    """A cubic B-spline wall across y = −15..15 with non-uniform knots, wavy enough that lines
    at shallow angles cross it several times; with `rational`, uneven weights."""
    s = np.linspace(0.0, 1.0, 16) ** 1.3
    y = -15.0 + 30.0 * s
    x = 40.0 + 2.5 * np.sin(0.45 * y) + 0.02 * y * y
    spline = make_interp_spline(s, np.column_stack([x, y]), k=3)
    weights = 1.0 + 0.3 * np.cos(np.arange(len(spline.c))) if rational else None
    return spline.t, spline.c, weights


def table_and_curve(rational=False):
    knots, poles, weights = wavy_curve(rational)
    return SplineTable((SplineWall(3, knots, poles, weights),)), Curve(knots, poles, 3, weights)


def check(table, curve, x0, y0, dx, dy, lo, hi):
    """Every line against the reference: the distinct crossings and the sides at both ends."""
    k = np.size(x0)
    roots, at_lo, at_hi = table.crossings(np.zeros(k, dtype=np.intp), x0, y0, dx, dy, lo, hi, sides=True)
    plain = table.crossings(np.zeros(k, dtype=np.intp), x0, y0, dx, dy, lo, hi)
    np.testing.assert_array_equal(plain, roots)
    counts = []
    for i in range(k):
        expected, sides = reference(curve, x0[i], y0[i], dx[i], dy[i], lo[i], hi[i])
        got = distinct(roots[i])
        assert got.size == expected.size, (i, got, expected)
        np.testing.assert_allclose(got, expected, atol=TOL, rtol=0)
        assert [at_lo[i], at_hi[i]] == list(sides), (i, got, expected)
        counts.append(got.size)
    return np.array(counts)


@pytest.mark.parametrize("rational", [False, True])
def test_random_lines_against_the_reference(rational):
    table, curve = table_and_curve(rational)
    rng = np.random.default_rng(11 + rational)
    k = 120
    # A third nearly along x (proved to cross once), a third nearly along the wall (crossing it
    # up to several times), a third at any angle.
    angle = np.concatenate([rng.uniform(-0.2, 0.2, k // 3), rng.uniform(np.pi / 2 - 0.5, np.pi / 2 + 0.5, k // 3),
                            rng.uniform(0.0, np.pi, k - 2 * (k // 3))])
    dx, dy = np.cos(angle), np.sin(angle)
    x0, y0 = rng.uniform(30.0, 50.0, k), rng.uniform(-13.0, 13.0, k)
    lo, hi = rng.uniform(-12.0, 0.0, k), rng.uniform(0.0, 12.0, k)
    counts = check(table, curve, x0, y0, dx, dy, lo, hi)
    assert (counts == 1).sum() > 30 and (counts >= 2).sum() >= 3 and (counts == 0).sum() > 10


def test_lines_through_the_knots():
    table, curve = table_and_curve()
    knots = curve.knots[1:-1]
    points = curve(knots)
    rng = np.random.default_rng(5)
    angle = rng.uniform(-0.6, 0.6, knots.size)  # across the wall
    dx, dy = np.cos(angle), np.sin(angle)
    lo, hi = np.full(knots.size, -4.0), np.full(knots.size, 4.0)
    x0, y0 = points[:, 0] - 1.5 * dx, points[:, 1] - 1.5 * dy  # the knot at l = 1.5
    counts = check(table, curve, x0, y0, dx, dy, lo, hi)
    assert (counts >= 1).all()


def test_segments_ending_at_a_crossing_and_at_the_curve_ends():
    table, curve = table_and_curve()
    s = np.array([0.13, 0.5, 0.77])
    points = curve(s)
    dx, dy = np.full(3, 0.96), np.full(3, 0.28)
    dx, dy = dx / np.hypot(dx, dy), dy / np.hypot(dx, dy)
    x0, y0 = points[:, 0] - 2.0 * dx, points[:, 1] - 2.0 * dy  # crossing at l = 2
    for hi in (2.0 + 1e-7, 2.0 - 1e-7):  # just past the crossing, just short of it
        check(table, curve, x0, y0, dx, dy, np.zeros(3), np.full(3, hi))
    check(table, curve, x0, y0, dx, dy, np.full(3, 2.0 - 1e-7), np.full(3, 6.0))
    # Lines along x near the curve's first and last points: inside its y range, a hair inside (the
    # last span's far end), and past them.
    ends = curve(np.array([curve.s0, curve.s1]))
    y0 = np.concatenate([ends[0, 1] + np.array([1e-3, 1e-9, -1e-3]), ends[1, 1] + np.array([-1e-3, -1e-9, 1e-3])])
    x0 = np.repeat(ends[:, 0], 3) - 1.0
    check(table, curve, x0, y0, np.ones(6), np.zeros(6), np.zeros(6), np.full(6, 3.0))


def test_tangent_and_nearly_tangent_lines():
    table, curve = table_and_curve()
    s = np.array([0.2, 0.35, 0.6, 0.85])
    points = curve(s)
    eps = 1e-6
    tangent = (curve(s + eps) - curve(s - eps)) / (2 * eps)
    tangent /= np.hypot(*tangent.T)[:, None]
    normal = np.column_stack([tangent[:, 1], -tangent[:, 0]])
    # The side towards which the curve bends: moving the tangent line there gives two crossings.
    chord_middle = (curve(s + 0.01) + curve(s - 0.01)) / 2
    bend = np.sign(np.einsum("ij,ij->i", chord_middle - points, normal))
    lo, hi = np.full(4, -3.0), np.full(4, 3.0)
    counts = check(table, curve, *(points + 1e-4 * bend[:, None] * normal).T, *tangent.T, lo, hi)
    assert (counts == 2).all()
    counts = check(table, curve, *(points - 1e-4 * bend[:, None] * normal).T, *tangent.T, lo, hi)
    assert (counts == 0).all()
    # The exact tangent: the touching point, once, or nothing (a touch does not change the side).
    k = 4
    roots, at_lo, at_hi = table.crossings(np.zeros(k, dtype=np.intp), *points.T, *tangent.T, lo, hi, sides=True)
    np.testing.assert_array_equal(at_lo, at_hi)
    for i in range(k):
        got = distinct(roots[i], 1e-6)
        assert got.size <= 1 and (got.size == 0 or abs(got[0]) < 1e-6)


def test_a_point_line_never_crosses():
    table, curve = table_and_curve()
    roots, at_lo, at_hi = table.crossings(np.zeros(2, dtype=np.intp), np.array([30.0, 50.0]), np.zeros(2),
                                          np.zeros(2), np.zeros(2), np.zeros(2), np.ones(2), sides=True)
    assert np.isnan(roots).all()
    assert list(at_lo) == [False, True] and list(at_hi) == [False, True]


def test_circle_arc_as_one_rational_span():
    # x = 90 − √(30² − y²) for |y| ≤ 12 as a rational quadratic Bézier (weights 1, cos(θ/2), 1).
    half = np.arcsin(12.0 / 30.0)
    a, b = (90 - 30 * np.cos(half), -12.0), (90 - 30 * np.cos(half), 12.0)
    apex = (90 - 30 / np.cos(half), 0.0)
    poles = np.array([a, apex, b])
    knots, weights = np.array([0, 0, 0, 1, 1, 1.0]), np.array([1.0, np.cos(half), 1.0])
    table = SplineTable((SplineWall(2, knots, poles, weights),))
    curve = Curve(knots, poles, 2, weights)
    rng = np.random.default_rng(3)
    k = 40
    angle = rng.uniform(-1.2, 1.2, k)
    x0, y0 = rng.uniform(55.0, 70.0, k), rng.uniform(-11.0, 11.0, k)
    counts = check(table, curve, x0, y0, np.cos(angle), np.sin(angle), np.full(k, -10.0), np.full(k, 10.0))
    assert (counts >= 1).sum() > 10
    # The circle itself: a crossing on it lies at distance 30 from the centre (90, 0).
    roots = table.crossings(np.zeros(k, dtype=np.intp), x0, y0, np.cos(angle), np.sin(angle), np.full(k, -10.0),
                            np.full(k, 10.0))
    line, col = np.nonzero(~np.isnan(roots))
    l = roots[line, col]
    radius = np.hypot(x0[line] + l * np.cos(angle[line]) - 90.0, y0[line] + l * np.sin(angle[line]))
    np.testing.assert_allclose(radius, 30.0, atol=1e-9, rtol=0)


def test_long_lines_across_many_spans():
    # Lines at 11°..43° to x over 20 mm: steeper than the wall everywhere, so proved to cross it
    # once, across up to eight spans, where one regula falsi step on the knots often misses.
    table, curve = table_and_curve()
    rng = np.random.default_rng(1)
    k = 60
    angle = rng.uniform(0.2, 0.75, k)
    x0, y0 = rng.uniform(35.0, 45.0, k), rng.uniform(-5.0, 5.0, k)
    counts = check(table, curve, x0, y0, np.cos(angle), np.sin(angle), np.full(k, -10.0), np.full(k, 10.0))
    assert (counts == 1).sum() > 20


@pytest.mark.parametrize("rational", [False, True])
def test_span_slope_bounds_hold_the_curve(rational):
    knots, poles, weights = wavy_curve(rational)
    wall = SplineWall(3, knots, poles, weights)
    curve = Curve(knots, poles, 3, weights)
    d_numerator, d_denominator = curve.numerator.derivative(), curve.denominator.derivative()
    edges = curve.knots
    for j, (low, high) in enumerate(wall.span_slopes):
        s = np.linspace(edges[j], edges[j + 1], 2001)
        w, dw = curve.denominator(s), d_denominator(s)
        velocity = (d_numerator(s) * w[:, None] - curve.numerator(s) * dw[:, None]) / (w * w)[:, None]
        slope = velocity[:, 0] / velocity[:, 1]
        assert low <= slope.min() and slope.max() <= high
        assert high - low <= 2 * np.ptp(slope) + 1e-6  # a bound, not a blanket


@pytest.mark.parametrize("rational", [False, True])
def test_bands_of_a_spline_wall_are_its_x_range_per_bin(rational):
    # The bands decide which walls an edge line can reach: too narrow would lose crossings.
    knots, poles, weights = wavy_curve(rational)
    wall = SplineWall(3, knots, poles, weights)
    curve = Curve(knots, poles, 3, weights)
    edges = np.linspace(-14.0, 14.0, 23)
    low, high, slope = wall.bins(edges)
    for b in range(edges.size - 1):
        y = np.linspace(edges[b], edges[b + 1], 4001)
        x = curve.wall_x(y)
        assert low[b] <= x.min() + 1e-9 and x.max() - 1e-9 <= high[b]
        assert x.min() - low[b] < 1e-6 and high[b] - x.max() < 1e-6  # exact, not a bound
        assert slope[b] >= np.abs(np.diff(x) / np.diff(y)).max() - 1e-6
