"""CIRCLE arcs and NX NURBS curves: points on the true curve, chord error within the tolerance,
points at most a step apart, tangents along the motion, end point exact; NX's knot layouts; checked
against geometry the tests build themselves (random circles in a basis of their own, B-splines
evaluated by the Cox-de Boor recursion written here)."""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from abm_workbench.formats.cl.arcs import arc_points
from abm_workbench.formats.cl.nurbs import bspline_points, resolve

finite = st.floats(-200, 200, allow_nan=False)


def basis(axis, seed):
    """A right-handed orthonormal (u, v, w) with w along `axis`, u turned by `seed` radians."""
    w = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    helper = np.array([0.0, 0.0, 1.0]) if abs(w[2]) < 0.8 else np.array([1.0, 0.0, 0.0])
    u0 = np.cross(helper, w)
    u0 /= np.linalg.norm(u0)
    v0 = np.cross(w, u0)
    u = math.cos(seed) * u0 + math.sin(seed) * v0
    return u, np.cross(w, u), w


@settings(max_examples=200, deadline=None)
@given(centre=st.tuples(finite, finite, finite),
       axis=st.tuples(finite, finite, finite).filter(lambda a: np.linalg.norm(a) > 1e-3),
       radius=st.floats(0.05, 500), start=st.floats(-math.pi, math.pi), sweep=st.floats(0.01, 2 * math.pi),
       rise=st.floats(-20, 20), full=st.booleans(), tolerance=st.sampled_from([1e-4, 1e-3, 1e-2, 0.1]),
       spacing=st.sampled_from([math.inf, 0.1, 1.0, 7.0]))
def test_arc_points_on_the_circle_turning_right_handed(centre, axis, radius, start, sweep, rise, full, tolerance,
                                                       spacing):
    centre = np.array(centre)
    u, v, w = basis(axis, start)
    if full:
        sweep = 2 * math.pi
    else:  # an end point within the tolerance of the start (in the plane) means a full turn
        assume(2 * radius * math.sin(sweep / 2) > 1e-5 and sweep < 2 * math.pi)
    begin = centre + radius * u
    end = centre + radius * (math.cos(sweep) * u + math.sin(sweep) * v) + rise * w
    points, tangents = arc_points(begin, end, centre, axis, tolerance, spacing)
    assert np.array_equal(points[-1], end)
    offset = points - centre
    height = offset @ w
    radial = offset - height[:, None] * w
    scale = 1e-9 * (1 + radius + np.abs(centre).max() + abs(rise))
    np.testing.assert_allclose(np.linalg.norm(radial, axis=1), radius, rtol=0, atol=scale)
    turned = np.unwrap(np.concatenate([[0.0], np.arctan2(radial @ v, radial @ u)]))
    step = np.diff(turned)
    assert (step > 0).all()  # counter-clockwise about the axis (right-hand rule)
    assert turned[-1] == pytest.approx(sweep, abs=1e-7)
    np.testing.assert_allclose(height, rise * turned[1:] / sweep, rtol=0, atol=scale)
    assert (radius * (1 - np.cos(step / 2))).max() <= tolerance * (1 + 1e-9) + 1e-12
    # At most `step` apart along the arc (a helix: the turn and the rise together).
    along = np.hypot(radius * step, rise * step / sweep)
    assert along.max() <= spacing * (1 + 1e-9)
    # The tangent: d/dθ of the point (turning right-handed, rising evenly), unit.
    theta = turned[1:]
    expected = radius * (-np.sin(theta)[:, None] * u + np.cos(theta)[:, None] * v) + rise / sweep * w
    np.testing.assert_allclose(tangents, expected / np.linalg.norm(expected, axis=1)[:, None], rtol=0, atol=1e-9)


def test_a_tiny_arc_stays_tiny_and_the_same_point_is_a_full_turn():
    tiny, _ = arc_points([10, 0, 0], [10 * math.cos(1e-5), 10 * math.sin(1e-5), 0], [0, 0, 0], [0, 0, 1], 1e-3, 0.1)
    assert len(tiny) == 1
    full, _ = arc_points([10, 0, 0], [10, 0, 0], [0, 0, 0], [0, 0, 1], 1e-3)
    turned = np.unwrap(np.concatenate([[0.0], np.arctan2(full[:, 1], full[:, 0])]))
    assert turned[-1] == pytest.approx(2 * math.pi, abs=1e-12)


def test_arc_with_a_zero_axis_or_a_point_on_it_is_refused():
    with pytest.raises(ValueError, match="axis is zero"):
        arc_points([1, 0, 0], [0, 1, 0], [0, 0, 0], [0, 0, 0], 1e-3)
    with pytest.raises(ValueError, match="lies on the circle's axis"):
        arc_points([0, 0, 1], [0, 1, 0], [0, 0, 0], [0, 0, 1], 1e-3)


def de_boor(knots, control, degree, u):
    """C(u) for parameters u (s,) by the Cox-de Boor recursion of the basis functions."""
    knots = np.asarray(knots, dtype=float)
    n = len(control)
    top = knots[n]
    values = np.zeros((len(u), len(knots) - 1))
    for i in range(len(knots) - 1):
        inside = (knots[i] <= u) & (u < knots[i + 1])
        if knots[i + 1] == top and knots[i] < top:
            inside |= u == top
        values[:, i] = inside
    for p in range(1, degree + 1):
        new = np.zeros((len(u), len(knots) - 1 - p))
        for i in range(len(knots) - 1 - p):
            left = knots[i + p] - knots[i]
            right = knots[i + p + 1] - knots[i + 1]
            if left > 0:
                new[:, i] += (u - knots[i]) / left * values[:, i]
            if right > 0:
                new[:, i] += (knots[i + p + 1] - u) / right * values[:, i + 1]
        values = new
    return values[:, :n] @ np.asarray(control, dtype=float)


def parameter_of(knots, control, degree, point, guess, width=5e-4):
    """The parameter u within `width` of `guess` whose curve point is nearest `point` (golden-section search)."""
    low, high = max(0.0, guess - width), min(float(knots[-1]), guess + width)
    ratio = (math.sqrt(5) - 1) / 2
    for _ in range(50):
        a, b = high - ratio * (high - low), low + ratio * (high - low)
        da, db = (np.linalg.norm(de_boor(knots, control, degree, np.array([x]))[0] - point) for x in (a, b))
        low, high = (low, b) if da <= db else (a, high)
    return 0.5 * (low + high)


def distance_to_polyline(samples, polyline):
    """(s,) distance of each sample to the polyline."""
    a, b = polyline[:-1], polyline[1:]
    ab = b - a
    length = np.einsum("ij,ij->i", ab, ab)
    best = np.full(len(samples), np.inf)
    for chunk in range(0, len(samples), 256):
        part = samples[chunk:chunk + 256]
        along = np.einsum("sij,ij->si", part[:, None, :] - a, ab) / np.where(length > 0, length, 1)
        along = np.clip(along, 0, 1)
        nearest = a + along[..., None] * ab
        best[chunk:chunk + 256] = np.linalg.norm(nearest - part[:, None, :], axis=2).min(axis=1)
    return best


@settings(max_examples=25, deadline=None)
@given(degree=st.integers(1, 5), extra=st.integers(0, 6), seed=st.integers(0, 10 ** 6),
       tolerance=st.sampled_from([1e-3, 1e-2, 0.1]), repeat=st.booleans())
def test_bspline_points_are_on_the_curve_within_the_chord_tolerance(degree, extra, seed, tolerance, repeat):
    rng = np.random.default_rng(seed)
    n = degree + 1 + extra
    control = rng.uniform(-30, 30, (n, 3))
    inner = np.sort(rng.uniform(0.0, 5.0, n - degree - 1))
    if repeat and len(inner) > 1 and degree > 1:
        inner[1] = inner[0]
    knots = np.concatenate([np.zeros(degree + 1), inner, np.full(degree + 1, 5.0)])
    layout, gap = resolve(knots, control, control[0], tolerance)
    assert (layout.words, layout.degree, gap) == ("full", degree, 0.0)
    points, tangents = bspline_points(layout, tolerance)
    np.testing.assert_allclose(points[-1], control[-1], atol=1e-9)  # clamped: the curve ends on the last point
    dense = de_boor(knots, control, degree, np.linspace(0.0, 5.0, 4001))
    polyline = np.vstack([control[0], points])
    # The chords stay within the tolerance of the curve ...
    assert distance_to_polyline(dense, polyline).max() <= tolerance * (1 + 1e-6)
    # ... and every point is on it: within half a sample spacing of a fine sampling.
    fine = de_boor(knots, control, degree, np.linspace(0.0, 5.0, 20001))
    spacing = np.linalg.norm(np.diff(fine, axis=0), axis=1).max()
    nearest = np.array([np.linalg.norm(fine - point, axis=1).min() for point in points])
    assert nearest.max() <= spacing / 2 + 1e-9
    # The tangents point along the motion arriving at each point: the chord from a point just before it,
    # at the point's own parameter (the nearest fine sample's, refined by golden-section search).
    u = np.linspace(0.0, 5.0, 20001)
    some = np.unique(np.linspace(0, len(points) - 1, 12).astype(int))
    at = [parameter_of(knots, control, degree, point, u[np.argmin(np.linalg.norm(fine - point, axis=1))])
          for point in points[some]]
    before = (de_boor(knots, control, degree, np.array(at))
              - de_boor(knots, control, degree, np.maximum(np.array(at) - 1e-7, 0.0)))
    moving = np.linalg.norm(before, axis=1) > 1e-12
    cosine = (tangents[some][moving] * before[moving]).sum(axis=1) / np.linalg.norm(before[moving], axis=1)
    assert (cosine > 0.999).all()


@pytest.mark.parametrize("step", [0.5, 2.0])
def test_bspline_points_are_at_most_a_step_apart(step):
    knots = [0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1]
    control = [[0, 0, 0], [10, 5, 0], [20, -5, 1], [30, 5, 2], [40, -5, 1], [50, 0, 0]]
    layout, _ = resolve(knots, control, None, 1e-3)
    points, _ = bspline_points(layout, 1.0, step)
    chords = np.linalg.norm(np.diff(np.vstack([control[0], points]), axis=0), axis=1)
    assert chords.max() <= step * (1 + 1e-9) and len(points) >= 50 / step


def nx_block(degree, count, seed):
    """(start, written control points, written knots, full knots): a clamped B-spline of `count` control
    points whose first is the tool's position, written as NX writes it (the start and the end knots'
    multiplicity left out)."""
    rng = np.random.default_rng(seed)
    control = np.cumsum(rng.uniform(-5, 5, (count, 3)) + [8, 0, 0], axis=0)
    inner = np.sort(rng.uniform(0.0, 1.0, count - degree - 1))
    full = np.concatenate([np.zeros(degree + 1), inner, np.ones(degree + 1)])
    return control[0], control[1:], np.concatenate([[0.0], inner, [1.0]]), full, control


@pytest.mark.parametrize("degree, count", [(4, 9), (4, 12), (3, 8)])
def test_nx_blocks_start_at_the_tool_and_take_their_implied_knots(degree, count):
    start, written, knots, full, control = nx_block(degree, count, count)
    layout, gap = resolve(knots, written, start, 1e-6)
    assert (layout.words, layout.degree, gap) == ("clamped ends, start implied", degree, 0.0)
    points, _ = bspline_points(layout, 1e-4)
    dense = de_boor(full, control, degree, np.linspace(0.0, 1.0, 4001))
    assert distance_to_polyline(dense, np.vstack([start, points])).max() <= 1e-4 * (1 + 1e-6)
    np.testing.assert_allclose(points[-1], control[-1], atol=1e-9)


def test_a_written_start_is_taken_when_it_is_the_tools_position():
    """NX's count with the start written (knots = control points - 2, cubic) when the first point is the tool's."""
    start, written, knots, full, control = nx_block(3, 8, 5)
    layout, gap = resolve(knots, control, start, 1e-6)  # every control point written, one knot more than NX's
    assert (layout.words, layout.degree, gap) == ("clamped ends", 4, 0.0) or layout.words == "clamped ends"
    assert gap == 0.0


def test_a_curve_away_from_the_tool_is_reached_straight():
    knots = [0, 0, 1, 1]
    layout, gap = resolve(knots, [[5, 0, 0], [6, 0, 0]], np.array([0.0, 0.0, 0.0]), 1e-3)
    assert layout.words == "full" and gap == pytest.approx(5.0)


def test_bspline_counts_that_give_no_curve_are_refused():
    with pytest.raises(ValueError, match="fit no B-spline of degree 1 to 9"):
        resolve(list(range(30)), [[0, 0, 0], [1, 0, 0], [2, 0, 0]], None, 1e-3)
    with pytest.raises(ValueError, match="knot 0.5 is repeated more often than the degree 1"):
        resolve([0, 0, 0.5, 0.5, 1, 1], [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]], None, 1e-3)
    with pytest.raises(ValueError, match="the knots decrease"):
        resolve([0, 0, 1, 0.5, 1, 1], [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]], None, 1e-3)
