"""The engine's row helpers (engine.swept: rows, kept, row_cross) give numpy's own numbers, bit for bit: the
in-process searches call them instead of fancy and boolean indexing and np.cross for speed alone."""

import numpy as np
import pytest

from abm_workbench.engine.swept import kept, row_cross, rows


@pytest.mark.parametrize("columns", [None, 2, 3])
def test_rows_and_kept_are_numpy_indexing(columns):
    rng = np.random.default_rng(7)
    shape = (500,) if columns is None else (500, columns)
    table = rng.normal(size=shape)
    index = rng.integers(0, 500, 900)
    assert np.array_equal(rows(table, index), table[index])
    assert rows(table, index[:0]).shape == table[index[:0]].shape
    mask = rng.random(500) < 0.3
    ints = np.arange(500)
    got_table, got_ints = kept(mask, table, ints)
    assert np.array_equal(got_table, table[mask]) and np.array_equal(got_ints, ints[mask])
    assert got_ints.dtype == ints.dtype
    nothing = kept(np.zeros(500, dtype=bool), table)[0]
    assert nothing.shape == table[:0].shape


def test_row_cross_is_np_cross_to_the_bit():
    rng = np.random.default_rng(11)
    for scale_a, scale_b in ((1.0, 1.0), (1e-9, 1e6), (1e8, 1e-7), (1e-150, 1e150)):
        a, b = rng.normal(size=(2000, 3)) * scale_a, rng.normal(size=(2000, 3)) * scale_b
        assert np.array_equal(row_cross(a, b), np.cross(a, b))
    unit = np.eye(3)
    assert np.array_equal(row_cross(unit[[0]], unit[[1]]), unit[[2]])
