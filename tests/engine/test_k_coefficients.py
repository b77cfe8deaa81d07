"""The curve-boundary quintic (notes §4) and the tool frame (notes §2)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.polynomial import Polynomial

from abm_workbench.engine import angles_to_axis, axis_to_angles, k_coefficients, rotation_matrix

RTOL = 1e-12   # relative to the size of the terms summed into each coefficient
TINY = np.finfo(float).tiny  # below the normal range relative accuracy means nothing
ATOL = 1e-14   # for unit-length quantities (rotation entries, axes)


def _floats(lo, hi):
    """Finite floats in [lo, hi], no subnormals."""
    return st.floats(lo, hi, allow_nan=False, allow_infinity=False, allow_subnormal=False)


def composed(h, a, b, s, sin_b):
    """Coefficients (6,), ascending, of P(b − s·l) − (a + sin_b·l) by numpy polynomial arithmetic."""
    coef = (Polynomial(h)(Polynomial([b, -s])) - Polynomial([a, sin_b])).coef
    return np.pad(coef, (0, 6 - len(coef)))


def term_size(h, a, b, s, sin_b):
    """Coefficients (6,) of the same composition with every input made non-negative: the
    size of the terms each coefficient sums, the scale for its rounding error."""
    return composed(np.abs(h), -abs(a), abs(b), -abs(s), -abs(sin_b))


coefficients = st.lists(_floats(-100.0, 100.0), min_size=6, max_size=6).map(np.array)
angle = _floats(-89.0, 89.0)


@settings(max_examples=200)
@given(coefficients, _floats(-200.0, 200.0), _floats(-200.0, 200.0), _floats(-1.0, 1.0), _floats(-1.0, 1.0))
def test_k_coefficients_equal_polynomial_composition(h, a, b, s, sin_b):
    """K_0..K_5 equal the composition P(b − s·l) − (a + sin_b·l) coefficient by coefficient."""
    got = k_coefficients(h, a, b, s, sin_b)
    assert got.shape == (6,)
    assert np.all(np.abs(got - composed(h, a, b, s, sin_b)) <= RTOL * term_size(h, a, b, s, sin_b) + TINY)


@settings(max_examples=50)
@given(coefficients, st.lists(st.tuples(*[_floats(-1.0, 1.0)] * 4), min_size=1, max_size=5))
def test_k_coefficients_broadcast_rows(h, rows):
    """Arrays of a, b, s, sin_b (k,) give (k, 6), row i the composition for the i-th values."""
    a, b, s, sin_b = (np.array(col) * scale for col, scale in zip(zip(*rows), (200, 200, 1, 1)))
    got = k_coefficients(h, a, b, s, sin_b)
    assert got.shape == (len(rows), 6)
    for i in range(len(rows)):
        want = composed(h, a[i], b[i], s[i], sin_b[i])
        assert np.all(np.abs(got[i] - want) <= RTOL * term_size(h, a[i], b[i], s[i], sin_b[i]) + TINY)


def test_k_coefficients_broadcast_a_alone():
    """An array a (2,) with scalar b, s, sin_b broadcasts to (2, 6), as the docstring promises
    (an earlier engine took the result's shape from h, b, s only and raised ValueError)."""
    h = np.arange(6.0)
    got = k_coefficients(h, np.array([1.0, 2.0]), 2.0, 0.3, 0.4)
    np.testing.assert_allclose(got, [composed(h, 1.0, 2.0, 0.3, 0.4), composed(h, 2.0, 2.0, 0.3, 0.4)],
                               rtol=RTOL)


def rx_ry(theta_a, theta_b):
    """Rx(θ_A)·Ry(θ_B) (3, 3) written out from the notes §2, angles in degrees."""
    a, b = np.radians(theta_a), np.radians(theta_b)
    return np.array([[np.cos(b), 0.0, np.sin(b)],
                     [np.sin(a) * np.sin(b), np.cos(a), -np.sin(a) * np.cos(b)],
                     [-np.cos(a) * np.sin(b), np.sin(a), np.cos(a) * np.cos(b)]])


@settings(max_examples=100)
@given(angle, angle)
def test_rotation_matrix_is_proper_rotation(theta_a, theta_b):
    """Orthonormal, det 1, equal to Rx·Ry; third column (sin θB, −sin θA cos θB, cos θA cos θB)."""
    r = rotation_matrix(theta_a, theta_b)
    np.testing.assert_allclose(r @ r.T, np.eye(3), atol=ATOL)
    assert abs(np.linalg.det(r) - 1.0) <= ATOL
    np.testing.assert_allclose(r, rx_ry(theta_a, theta_b), atol=ATOL)
    a, b = np.radians(theta_a), np.radians(theta_b)
    np.testing.assert_allclose(r[..., :, 2], [np.sin(b), -np.sin(a) * np.cos(b), np.cos(a) * np.cos(b)], atol=ATOL)


def test_rotation_matrix_batch_shape():
    """Angles (2, 3) give matrices (2, 3, 3, 3), each the scalar result."""
    ta, tb = np.linspace(-80, 80, 6).reshape(2, 3), np.linspace(30, -30, 6).reshape(2, 3)
    r = rotation_matrix(ta, tb)
    assert r.shape == (2, 3, 3, 3)
    np.testing.assert_allclose(r[1, 2], rx_ry(ta[1, 2], tb[1, 2]), atol=ATOL)


@settings(max_examples=100)
@given(st.lists(st.tuples(angle, angle), min_size=1, max_size=5))
def test_angles_round_trip(pairs):
    """angles_to_axis then axis_to_angles gives the angles back; the axis is R's third column."""
    ta, tb = np.array(pairs).T
    axes = angles_to_axis(ta, tb)
    np.testing.assert_allclose(axes, rotation_matrix(ta, tb)[..., :, 2], atol=ATOL)
    back_a, back_b = axis_to_angles(axes)
    np.testing.assert_allclose(back_a, ta, atol=1e-9)
    np.testing.assert_allclose(back_b, tb, atol=1e-9)


@settings(max_examples=100)
@given(st.lists(st.tuples(_floats(-3.0, 3.0), _floats(-3.0, 3.0), _floats(0.05, 3.0)), min_size=1, max_size=5))
def test_axis_round_trip(rows):
    """axis_to_angles then angles_to_axis gives the normalised axis back, for any axis with k > 0."""
    axes = np.array(rows)
    ta, tb = axis_to_angles(axes)
    assert np.all(np.abs(ta) < 90) and np.all(np.abs(tb) < 90)
    np.testing.assert_allclose(angles_to_axis(ta, tb), axes / np.linalg.norm(axes, axis=1, keepdims=True),
                               atol=1e-12)


@pytest.mark.parametrize("bad", [[0.0, 0.0, 0.0], [np.nan, 0.0, 1.0], [np.inf, 0.0, 0.0]],
                         ids=["zero", "nan", "inf"])
def test_axis_to_angles_rejects_bad_row(bad):
    """ValueError for a zero or not finite axis, naming the offending row (here row 3); k ≤ 0 is
    accepted (test_tool_profiles)."""
    axes = np.array([[0.0, 0.0, 1.0], [0.1, 0.2, 1.0], [-0.1, 0.0, 1.0], bad])
    with pytest.raises(ValueError, match=r"\b3\b"):
        axis_to_angles(axes)
