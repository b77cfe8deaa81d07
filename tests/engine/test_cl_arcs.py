"""CIRCLE arcs and NX NURBS curves: points on the true curve, chord error within the tolerance,
end point exact; checked against geometry the tests build themselves (random circles in a
basis of their own, B-splines evaluated by the Cox-de Boor recursion written here)."""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from abm_workbench.formats.cl.arcs import arc_points
from abm_workbench.formats.cl.nurbs import bspline_points

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
       rise=st.floats(-20, 20), full=st.booleans(), tolerance=st.sampled_from([1e-4, 1e-3, 1e-2, 0.1]))
def test_arc_points_on_the_circle_turning_right_handed(centre, axis, radius, start, sweep, rise, full, tolerance):
    centre = np.array(centre)
    u, v, w = basis(axis, start)
    if full:
        sweep = 2 * math.pi
    else:  # an end point within the tolerance of the start (in the plane) means a full turn
        assume(2 * radius * math.sin(sweep / 2) > 1e-5 and sweep < 2 * math.pi)
    begin = centre + radius * u
    end = centre + radius * (math.cos(sweep) * u + math.sin(sweep) * v) + rise * w
    points = arc_points(begin, end, centre, axis, tolerance)
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


def test_a_tiny_arc_stays_tiny_and_the_same_point_is_a_full_turn():
    tiny = arc_points([10, 0, 0], [10 * math.cos(1e-5), 10 * math.sin(1e-5), 0], [0, 0, 0], [0, 0, 1], 1e-3)
    assert len(tiny) == 1
    full = arc_points([10, 0, 0], [10, 0, 0], [0, 0, 0], [0, 0, 1], 1e-3)
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
    points = bspline_points(knots, control, tolerance)
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


def test_bspline_counts_that_give_no_curve_are_refused():
    with pytest.raises(ValueError, match="no B-spline of degree 1 or more"):
        bspline_points([0, 0, 1, 1], [[0, 0, 0], [1, 0, 0], [2, 0, 0]], 1e-3)
    with pytest.raises(ValueError, match="knot 0.5 is repeated more often than the degree 1"):
        bspline_points([0, 0, 0.5, 0.5, 1, 1], [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]], 1e-3)
    with pytest.raises(ValueError, match="the knots decrease"):
        bspline_points([0, 0, 1, 0.5, 1, 1], [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]], 1e-3)
