"""Reductions along the short last axis of (N, k) arrays, row by row.

numpy's own reductions over a short last axis (k of 2 to ~20, N of 10^4) cost several times
what k whole-column operations do, so the engine reduces column by column. Each row's result
depends on that row alone, summed left to right, so chunking a pass never changes a bit.
"""

from functools import reduce

import numpy as np


def row_sum(a):
    """(N,) sums of the rows of a float (N, k) array (k ≥ 1), left to right."""
    return reduce(np.add, (a[:, j] for j in range(1, a.shape[1])), a[:, 0].copy())


def row_min(a):
    """(N,) minima of the rows of a (N, k) array (k ≥ 1); NaN propagates as in np.min."""
    return reduce(np.minimum, (a[:, j] for j in range(1, a.shape[1])), a[:, 0].copy())


def row_max(a):
    """(N,) maxima of the rows of a (N, k) array (k ≥ 1); NaN propagates as in np.max."""
    return reduce(np.maximum, (a[:, j] for j in range(1, a.shape[1])), a[:, 0].copy())


def row_count(mask):
    """(N,) int: how many entries of each row of a bool (N, k) array are True."""
    mask = np.ascontiguousarray(mask, dtype=bool)
    if mask.shape[1] < 256:  # uint8 sums cannot overflow
        return (mask.view(np.uint8) @ np.ones(mask.shape[1], dtype=np.uint8)).astype(np.intp)
    return mask.sum(axis=1)


def row_any(mask):
    """(N,) bool: some entry of each row of a bool (N, k) array is True."""
    return row_count(mask) > 0
