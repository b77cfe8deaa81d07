"""The Bernstein proof of monotonicity that lets the engine take a single root without isolation."""

import numpy as np
from hypothesis import given, strategies as st

from abm_workbench.engine.polynomials import proved_monotone_unit

coefficients = st.lists(st.floats(-10.0, 10.0, allow_nan=False), min_size=6, max_size=6)


@given(st.lists(coefficients, min_size=1, max_size=20))
def test_a_proof_holds_on_a_dense_sample(rows):
    """Where a quintic is proved monotone, its derivative has one sign on a dense sample of [0, 1]."""
    c = np.array(rows)
    proved = proved_monotone_unit(c)
    u = np.linspace(0.0, 1.0, 4001)
    slope = np.polynomial.polynomial.polyval(u, (c[:, 1:] * np.arange(1, 6)).T)  # (m, 4001)
    one_sign = (slope > 0).all(axis=1) | (slope < 0).all(axis=1)
    assert not (proved & ~one_sign).any()


def test_known_cases():
    """u + u³ rises, (u − ½)² turns at ½, 3 − 2u falls, a constant is not strictly monotone,
    and (u − 0.3)(u − 0.35) + 1, whose slope changes sign at 0.325, is not proved."""
    rows = np.array([
        [0.0, 1.0, 0.0, 1.0, 0.0, 0.0],
        [0.25, -1.0, 1.0, 0.0, 0.0, 0.0],
        [3.0, -2.0, 0.0, 0.0, 0.0, 0.0],
        [4.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [1.105, -0.65, 1.0, 0.0, 0.0, 0.0],
    ])
    assert proved_monotone_unit(rows).tolist() == [True, False, True, False, False]

