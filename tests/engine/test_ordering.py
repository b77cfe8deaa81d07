"""group_order gives np.lexsort's order, index for index, for every input it meets and its edges."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from abm_workbench.engine.ordering import EXACT, group_order

SPECIAL = [0.0, -0.0, 1.0, -1.0, np.inf, -np.inf, np.nan, 5e-324, -5e-324, 1e308, -1e308, 0.5]


def _check(value, group):
    expected = np.lexsort((value, group))
    got = group_order(value, group)
    assert got.dtype == expected.dtype
    np.testing.assert_array_equal(got, expected)


@pytest.mark.parametrize("seed", range(20))
@pytest.mark.parametrize("sorted_groups", [True, False])
def test_random_groups_and_values(seed, sorted_groups):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(0, 5000))
    group = np.repeat(np.arange(n), rng.integers(1, 6, size=n))[:n] - int(rng.integers(0, 3)) * 1000
    if not sorted_groups:
        group = rng.permutation(group)
    value = np.round(rng.normal(size=n), int(rng.integers(0, 3)))  # many ties
    special = rng.random(n) < 0.2
    value[special] = rng.choice(SPECIAL, size=int(special.sum()))
    _check(value, group)
    _check(np.where(np.isnan(value), 0.0, value), group)


def test_ties_keep_their_order_and_signed_zeros_are_equal():
    group = np.array([3, 1, 3, 1, 3, 1, 2])
    value = np.array([0.0, -0.0, -0.0, 0.0, 0.0, 1.0, -0.0])
    _check(value, group)
    np.testing.assert_array_equal(group_order(value, group), [1, 3, 5, 6, 0, 2, 4])


def test_nan_values_last_in_their_group_only():
    group = np.array([0, 0, 1, 1])
    value = np.array([np.nan, 2.0, 1.0, 0.0])
    np.testing.assert_array_equal(group_order(value, group), [1, 0, 3, 2])


@pytest.mark.parametrize("big", [EXACT, -EXACT, EXACT + 1, np.iinfo(np.int64).max, np.iinfo(np.int64).min])
def test_groups_beyond_float_precision(big):
    group = np.array([big, big - 1 if big > 0 else big + 1, big, 0], dtype=np.int64)
    _check(np.array([1.0, 0.0, 0.0, 2.0]), group)


def test_empty_and_other_dtypes():
    _check(np.zeros(0), np.zeros(0, dtype=np.intp))
    _check(np.array([2, 1, 1], dtype=np.int64), np.array([0, 0, 0]))
    _check(np.array([2.0, 1.0, 1.0], dtype=np.float32), np.array([1, 0, 0]))
    _check(np.array([2.0, 1.0, 3.0]), np.array([1.0, 0.0, 0.0]))
    _check(np.array([2.0, 1.0, 3.0]), np.array([1, 0, 0], dtype=np.uint32))


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(st.integers(-5, 5), st.one_of(st.sampled_from(SPECIAL),
                                                        st.floats(allow_nan=True, allow_infinity=True))),
                max_size=60))
def test_any_pairs(pairs):
    group = np.array([g for g, _ in pairs], dtype=np.int64)
    value = np.array([v for _, v in pairs], dtype=float)
    _check(value, group)
