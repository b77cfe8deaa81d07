"""Row reductions of the engine against numpy's own, on random arrays with NaNs and empty rows."""

import numpy as np
from hypothesis import given, strategies as st
from hypothesis.extra.numpy import arrays

from abm_workbench.engine.rows import row_any, row_count, row_max, row_min, row_sum

shapes = st.tuples(st.integers(0, 30), st.integers(1, 12))
floats = st.floats(-1e6, 1e6) | st.just(float("nan"))


@given(shapes.flatmap(lambda shape: arrays(float, shape, elements=floats)))
def test_float_rows(a):
    np.testing.assert_allclose(row_sum(a), a.sum(axis=1), rtol=1e-12, atol=1e-6)
    assert np.array_equal(row_min(a), a.min(axis=1), equal_nan=True)
    assert np.array_equal(row_max(a), a.max(axis=1), equal_nan=True)


@given(st.tuples(st.integers(0, 30), st.integers(0, 300)).flatmap(lambda shape: arrays(bool, shape)))
def test_bool_rows(mask):
    """Counts stay exact past 255 columns (no uint8 overflow)."""
    assert np.array_equal(row_count(mask), mask.sum(axis=1))
    assert np.array_equal(row_any(mask), mask.any(axis=1))
