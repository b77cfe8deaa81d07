"""The results CSV written chunk by chunk: the same bytes as the whole-pass writer, all or nothing."""

import os

import numpy as np
import pytest

from abm_workbench.engine import engage
from abm_workbench.formats import replacing
from abm_workbench.formats.results_csv import chunk_texts, summary_path, write_chunks, write_results
from abm_workbench.parallel import toolpath_part

from .test_parallel import model_job

# Uneven chunks of model test 1's 53 CL points, one of a single CL point.
BOUNDS = [0, 7, 8, 30, 53]


@pytest.fixture(scope="module")
def model_1():
    stock, tool, toolpath, settings = model_job(1)
    return stock, tool, toolpath, settings, engage(stock, tool, toolpath, settings)


def chunk_parts(model, with_toolpath=True):
    """(results, summary) texts of model test 1 engaged chunk by chunk (each chunk on its own)."""
    stock, tool, toolpath, settings, _ = model
    for start, stop in zip(BOUNDS[:-1], BOUNDS[1:]):
        part = toolpath_part(toolpath, start, stop)
        yield chunk_texts(engage(stock, tool, part, settings), start, toolpath=part if with_toolpath else None)


@pytest.mark.parametrize("with_toolpath", [True, False])
def test_chunks_write_the_same_bytes_as_the_whole_pass(model_1, tmp_path, with_toolpath):
    *_, toolpath, _, engagement = model_1
    write_results(engagement, tmp_path / "whole.csv", toolpath=toolpath if with_toolpath else None)
    assert write_chunks(chunk_parts(model_1, with_toolpath), tmp_path / "R.csv", tmp_path / "R.summary.csv") == 4
    for name in ("R.csv", "R.summary.csv"):
        whole = (tmp_path / name.replace("R", "whole")).read_bytes()
        assert (tmp_path / name).read_bytes() == whole
    rows = whole.decode().splitlines()
    assert rows[0].startswith("cl,") and sum(row.startswith("cl,") for row in rows) == 1


def test_later_chunks_carry_no_header_and_their_own_cl_numbers(model_1):
    results, summary = list(chunk_parts(model_1))[2]  # CL points 8..29
    cl = [int(line.split(",", 1)[0]) for line in results.splitlines()]
    assert cl[0] == 8 and cl[-1] == 29 and len(cl) == 22 * 181
    assert np.unique([int(line.split(",", 1)[0]) for line in summary.splitlines()]).tolist() == list(range(8, 30))


def test_an_error_in_a_late_chunk_leaves_no_file(model_1, tmp_path):
    (tmp_path / "R.csv").write_text("old")

    def failing():
        yield from list(chunk_parts(model_1))[:2]
        raise RuntimeError("chunk 3 failed")

    target = tmp_path / "R.csv"
    with pytest.raises(RuntimeError, match="chunk 3 failed"):
        with replacing(target, summary_path(target)) as temporaries:
            write_chunks(failing(), *temporaries)
    assert os.listdir(tmp_path) == ["R.csv"] and target.read_text() == "old"


def test_numbers_read_as_numpy_writes_them():
    """The CSV's number text is numpy's str of the float64 rounded to DECIMALS places (the shortest
    text that reads back as it), '' for NaN, '0.0' for −0.0, over every magnitude."""
    from abm_workbench.formats.decimal_text import DECIMALS, number_field

    from .test_decimal_text import texts

    rng = np.random.default_rng(5)
    values = np.concatenate([rng.standard_normal(20000) * 10.0 ** rng.integers(-15, 20, 20000),
                             [0.0, -0.0, 1e16, 1e-4, 9.99999e-5, 1e15, 0.1, 1 / 3, -1e-11, 5e-11, np.inf, -np.inf]])
    values[::97] = np.nan
    want = np.where(np.isnan(values), "", (np.round(values, DECIMALS) + 0.0).astype(str))
    assert texts(number_field(values)) == want.tolist()
    with pytest.raises(ValueError, match=r"got shape \(5003, 4\)"):
        number_field(values.reshape(-1, 4))
