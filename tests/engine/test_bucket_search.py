"""BucketSearch answers exactly what np.searchsorted answers (the independent reference)."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from abm_workbench.engine.bucket_search import MOST_PER_BUCKET, BucketSearch

_finite = st.floats(-1e3, 1e3, allow_nan=False, allow_infinity=False)


def _queries(keys, extra):
    """The keys themselves, their neighbouring floats, values outside, NaN, ±inf and `extra`."""
    return np.concatenate([keys, np.nextafter(keys, -np.inf), np.nextafter(keys, np.inf),
                           [np.nan, np.inf, -np.inf, -1e300, 1e300], np.asarray(extra, dtype=float)])


def _check(keys, extra):
    keys = np.sort(np.asarray(keys, dtype=float))
    search, values = BucketSearch(keys), _queries(keys, extra)
    for side in ("left", "right"):
        assert np.array_equal(search.search(values, side), np.searchsorted(keys, values, side=side)), side
        # any shape, as np.searchsorted
        grid = values[: values.size // 2 * 2].reshape(2, -1)
        assert np.array_equal(search.search(grid, side), np.searchsorted(keys, grid, side=side))


@given(st.lists(_finite, max_size=60), st.lists(_finite, max_size=40))
def test_spread_keys(keys, extra):
    _check(keys, extra)


@given(st.lists(st.sampled_from([0.0, 0.5, 1e-9, 2.0, 2.0 + 1e-12]), max_size=40), st.lists(_finite, max_size=20))
def test_repeated_and_bunched_keys(keys, extra):
    _check(keys, extra)  # many equal keys: more than MOST_PER_BUCKET in a bucket bisects


def test_knot_keys_of_many_walls():
    # Like SplineTable.keys: runs of knots, each wall's shifted past the others'.
    rng = np.random.default_rng(7)
    keys = np.concatenate([np.cumsum(rng.uniform(0.1, 2.0, 60)) + 200.0 * k for k in range(12)])
    _check(keys, rng.uniform(-10.0, 2500.0, 5000))
    assert not BucketSearch(keys).bisect  # spread keys take the bucket path


def test_bunched_keys_fall_back_to_bisection():
    keys = np.concatenate([np.zeros(MOST_PER_BUCKET + 1), [1.0]])
    assert BucketSearch(keys).bisect
    _check(keys, [0.0, 0.5, 1.0])


def test_no_keys_and_one_key():
    for keys in ([], [3.0]):
        _check(keys, [-1.0, 3.0, 4.0])


@pytest.mark.parametrize("keys", [[1.0, 0.0], [0.0, np.nan], [0.0, np.inf], [-np.inf, 1e308, np.inf]])
def test_keys_not_finite_and_sorted_are_bisected(keys):
    # What np.searchsorted answers for them, whatever that means (the engine's stacked knot
    # keys of walls near 1e308 can overflow to inf: nothing changes for them).
    search, values = BucketSearch(keys), np.array([-1.0, 0.0, 0.5, 1.0, 2.0, np.nan, np.inf])
    assert search.bisect
    for side in ("left", "right"):
        assert np.array_equal(search.search(values, side), np.searchsorted(np.asarray(keys), values, side=side))


def test_side_is_checked():
    with pytest.raises(ValueError, match="side"):
        BucketSearch([0.0, 1.0]).search([0.5], "middle")
