"""The vectorised CSV text (formats.decimal_text, results_csv) against a plain per-value writer.

The reference writes each float as ``repr(float(np.round(v, 10) + 0.0))`` ('' for NaN), each
integer as ``str(int(v))``, and joins a row's fields with ',' in Python: the text the results
CSV has always had. Whole files of both model tests are compared byte for byte.
"""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy.interpolate import make_interp_spline

from abm_workbench.engine import CASES, SURFACES, CutSettings, Staircase, Toolpath, engage, segment_letter
from abm_workbench.engine.walls import SplineWall
from abm_workbench.formats.decimal_text import WORD, integer_field, number_field, text_field
from abm_workbench.formats.results_csv import (FORCE_COLUMNS, FORCE_SUMMARY_COLUMNS, RESULT_COLUMNS,
                                               SUMMARY_COLUMNS, TOOLPATH_COLUMNS, chunk_texts, results_text,
                                               summary_text)
from abm_workbench.forces import Coefficients, material, pass_forces
from abm_workbench.parallel import toolpath_part

from .test_parallel import model_job


def texts(field):
    """Each value's text of a field (w, n): the non-NUL bytes of its words, decoded."""
    rows = np.ascontiguousarray(field.T).view(np.uint8).reshape(field.shape[1], 8 * field.shape[0])
    return [bytes(row[row != 0]).decode("utf-8") for row in rows]


def number_text(value):
    """The reference text of a float: repr of the value rounded to 10 places, '' for NaN.

    Above 1e290, where value·10^10 would overflow in np.round, Python's round (exact decimal
    rounding; such doubles are whole numbers): a finite value is never written as inf."""
    if math.isnan(value):
        return ""
    return repr((round(value, 10) if abs(value) > 1e290 else float(np.round(value, 10))) + 0.0)


# Floats of every kind, and the ones near each edge of the fast path.
ANY_FLOAT = st.floats(allow_nan=True, allow_infinity=True, allow_subnormal=True, width=64)
TINY = st.floats(1e-11, 1e-4) | st.floats(-1e-4, -1e-11)
NEAR_1E5 = st.floats(99_999.0, 100_001.0) | st.floats(-100_001.0, -99_999.0)
HUGE = st.floats(1e15, 1e17) | st.floats(-1e17, -1e15)
ON_THE_GRID = st.integers(-10**15 - 10, 10**15 + 10).map(lambda k: k / 1e10)
HALVES = st.integers(-10**7, 10**7).map(lambda k: (k + 0.5) * 1e-10)
SHORT_DECIMALS = st.builds(lambda k, places: k / 10**places, st.integers(-10**6, 10**6), st.integers(0, 12))
FLOATS = ANY_FLOAT | TINY | NEAR_1E5 | HUGE | ON_THE_GRID | HALVES | SHORT_DECIMALS | st.sampled_from(
    [0.0, -0.0, 5e-11, -5e-11, 1e-4, -1e-4, 9.99999e-5, 1e5, 99_999.99999999995, 1e15, 1e16, math.inf, -math.inf,
     math.nan, 5e-324, 1e300, -1e300, -1.2345678901234567e200, 0.1, 1 / 3])


@given(st.lists(FLOATS, min_size=1, max_size=60))
def test_number_text_is_the_rounded_repr(values):
    field = number_field(np.array(values))
    assert field.dtype == WORD and field.shape[1] == len(values)
    assert texts(field) == [number_text(value) for value in values]
    assert not (field[-1] >> np.uint64(56)).any()  # the last byte is free for a separator


def test_number_text_over_every_magnitude():
    rng = np.random.default_rng(11)
    values = rng.standard_normal(30000) * 10.0 ** rng.integers(-16, 20, 30000)
    values[::89] = np.nan
    values[7] = -1.2345678901234567e200  # a repr of 24 characters: a fourth word
    field = number_field(values)
    assert field.shape == (4, values.size)
    assert texts(field) == [number_text(value) for value in values.tolist()]


@given(st.lists(st.integers(-2**63, 2**63 - 1), min_size=1, max_size=60))
def test_integer_text_is_str(values):
    field = integer_field(np.array(values, dtype=np.int64))
    assert texts(field) == [str(value) for value in values]
    assert not (field[-1] >> np.uint64(56)).any()


@pytest.mark.parametrize("dtype", [np.int8, np.int16, np.int32, np.uint8, np.uint32, np.int64, np.uint64])
def test_integer_text_of_every_integer_dtype(dtype):
    info = np.iinfo(dtype)
    candidates = [info.min, info.min + 1, -1, 0, 1, 9, 10, 99_999, 100_000, 10**15, info.max // 3, info.max - 1,
                  info.max]
    values = np.array([value for value in candidates if info.min <= value <= min(info.max, 2**63 - 1)], dtype=dtype)
    assert texts(integer_field(values)) == [str(value) for value in values.tolist()]


@given(st.lists(st.text(st.characters(blacklist_categories=("Cs",), blacklist_characters="\0")), max_size=20))
def test_text_field_keeps_the_strings(strings):
    field = text_field(strings)
    assert field.shape[1] == len(strings) and texts(field) == strings
    assert not (field[-1] >> np.uint64(56)).any()


def test_empty_columns():
    for field in (number_field(np.empty(0)), integer_field(np.empty(0, dtype=int)), text_field([])):
        assert field.shape[1] == 0 and texts(field) == []


@pytest.mark.parametrize("call, message", [
    (lambda: number_field(np.zeros((2, 3))), r"values must be a 1-D array \(n,\), got shape \(2, 3\)"),
    (lambda: integer_field(np.zeros((4, 1), dtype=int)), r"got shape \(4, 1\)"),
    (lambda: integer_field(np.array([1.5])), "values must be integers within int64, got dtype float64"),
    (lambda: integer_field(np.array([2**63], dtype=np.uint64)), "within int64"),
    (lambda: text_field(["a", "b\0c"]), r"strings\[1\] = 'b\\x00c' holds a NUL character"),
])
def test_bad_input_is_named(call, message):
    with pytest.raises(ValueError, match=message):
        call()


# Whole files: both model tests, quintic and exact (B-spline) walls, with and without forces.

def exact_walls(stock):
    """The stock with each quintic wall replaced by a cubic B-spline through 9 of its points."""
    y = np.linspace(stock.y_min, stock.y_max, 9)
    curves = []
    for wall in stock.walls:
        spline = make_interp_spline(np.linspace(0.0, 1.0, 9), np.column_stack([wall.x_at(y), y]), k=3)
        curves.append(SplineWall(3, spline.t, spline.c, None))
    return Staircase(stock.x_min, stock.x_max, stock.y_min, stock.y_max, stock.base_z, stock.z_top,
                     stock.wall_points, tuple(curves))


def reference_results(engagement, first_cl=0, forces=None):
    """The results CSV written value by value in Python."""
    m, p = engagement.shape
    names = list(RESULT_COLUMNS)
    if forces is not None:
        names += FORCE_COLUMNS[:4] if forces.power is None else FORCE_COLUMNS
        xyz, torque, power = forces.xyz.tolist(), forces.torque.tolist(), forces.power
        power = None if power is None else power.tolist()
    e = {name: getattr(engagement, name).tolist() for name in (
        "phi", "h", "lep_l", "uep_l", "length", "pieces", "uep_surface", "uep_section", "uep_wall", "case", "segment",
        "area", "lep_xyz", "uep_xyz", "lep_surface", "lep_section", "lep_wall", "end_length")}
    lines = [",".join(names)]
    for i in range(m):
        for j in range(p):
            segment = e["segment"][i][j]
            row = [str(first_cl + i), number_text(e["phi"][j]), number_text(e["lep_l"][i][j]),
                   number_text(e["uep_l"][i][j]), number_text(e["length"][i][j]), str(e["pieces"][i][j]),
                   SURFACES[e["uep_surface"][i][j]], str(e["uep_section"][i][j]), str(e["uep_wall"][i][j]),
                   CASES[e["case"][i][j]], segment_letter(segment) if segment >= 0 else "", number_text(e["h"][i][j]),
                   number_text(e["area"][i][j]), *map(number_text, e["lep_xyz"][i][j]),
                   *map(number_text, e["uep_xyz"][i][j]), SURFACES[e["lep_surface"][i][j]],
                   str(e["lep_section"][i][j]), str(e["lep_wall"][i][j]), number_text(e["end_length"][i][j])]
            if forces is not None:
                row += [*map(number_text, xyz[i][j]), number_text(torque[i][j])]
                row += [] if power is None else [number_text(power[i][j])]
            lines.append(",".join(row))
    return "\n".join(lines) + "\n"


def reference_summary(engagement, toolpath=None, first_cl=0, forces=None):
    """The summary CSV written value by value in Python."""
    names = list(SUMMARY_COLUMNS) + (list(TOOLPATH_COLUMNS) if toolpath is not None else []) + (
        list(FORCE_SUMMARY_COLUMNS) if forces is not None else [])
    if forces is not None:
        peak, mean, torque = forces.peak.tolist(), forces.mean.tolist(), forces.torque.max(axis=1).tolist()
    lines = [",".join(names)]
    for i in range(engagement.shape[0]):
        segments = engagement.segments(i) or [dict(letter="", phi_start=math.nan, phi_end=math.nan, surface="none",
                                                   section=-1, wall=-1, max_length=0.0, mean_length=0.0)]
        for s in segments:
            row = [str(first_cl + i), number_text(engagement.depth_of_cut[i]), s["letter"], number_text(s["phi_start"]),
                   number_text(s["phi_end"]), s["surface"], str(s["section"]), str(s["wall"]),
                   number_text(s["max_length"]), number_text(s["mean_length"])]
            if toolpath is not None:
                row += [*map(number_text, toolpath.cl[i]), number_text(toolpath.theta_a[i]),
                        number_text(toolpath.theta_b[i])]
            if forces is not None:
                row += [number_text(peak[i]), number_text(mean[i]), number_text(torque[i])]
            lines.append(",".join(row))
    return "\n".join(lines) + "\n"


CASES_OF_FILES = [(number, walls, with_forces) for number in (1, 2) for walls in ("quintic", "exact")
                  for with_forces in (False, True)]


@pytest.fixture(scope="module", params=CASES_OF_FILES,
                ids=lambda case: f"model{case[0]}-{case[1]}-{'forces' if case[2] else 'plain'}")
def model_pass(request):
    number, walls, with_forces = request.param
    stock, tool, toolpath, settings = model_job(number)
    if walls == "exact":
        stock = exact_walls(stock)
    if with_forces:  # with a spindle speed on model test 1 (a power column), without on model test 2
        settings = CutSettings(settings.feed_per_tooth, settings.inclination, settings.phi_start, settings.phi_end,
                               settings.phi_step, 4000.0 if number == 1 else None)
    return stock, tool, toolpath, settings, with_forces


def forces_of(stock, tool, toolpath, settings, with_forces):
    return pass_forces(stock, tool, toolpath, settings, Coefficients(**vars(material("al7075-t6")))) if with_forces \
        else None


def test_whole_files_are_the_reference_bytes(model_pass):
    stock, tool, toolpath, settings, with_forces = model_pass
    engagement = engage(stock, tool, toolpath, settings)
    forces = forces_of(stock, tool, toolpath, settings, with_forces)
    assert engagement.engaged.any() and (~engagement.engaged).any()
    assert results_text(engagement, forces=forces) == reference_results(engagement, forces=forces)
    assert summary_text(engagement, toolpath=toolpath, forces=forces) == reference_summary(
        engagement, toolpath, forces=forces)


def test_chunks_are_the_reference_bytes(model_pass):
    """Chunks engaged on their own (first_cl > 0) and BLOCK_ROWS crossed inside a chunk."""
    stock, tool, toolpath, settings, with_forces = model_pass
    for start, stop in [(0, 5), (5, 6), (6, len(toolpath))]:
        part = toolpath_part(toolpath, start, stop)
        engagement = engage(stock, tool, part, settings)
        forces = forces_of(stock, tool, part, settings, with_forces)
        results, summary = chunk_texts(engagement, start, toolpath=part, forces=forces)
        want = (reference_results(engagement, start, forces), reference_summary(engagement, part, start, forces))
        if start > 0:
            want = tuple(text.split("\n", 1)[1] for text in want)
        assert (results, summary) == want


def test_blocks_join_seamlessly(monkeypatch):
    """Rows formatted a few at a time (blocks of 7, so fields differ in width from block to block)."""
    from abm_workbench.formats import results_csv

    stock, tool, toolpath, settings = model_job(1)
    engagement = engage(stock, tool, toolpath_part(toolpath, 20, 26), settings)
    monkeypatch.setattr(results_csv, "BLOCK_ROWS", 7)
    assert results_text(engagement, first_cl=99_998) == reference_results(engagement, 99_998)


def test_summary_of_cl_points_without_engagement():
    """CL points lifted clear of the stock, first, in the middle and last: one empty row each, in CL order."""
    stock, tool, toolpath, settings = model_job(1)
    part = toolpath_part(toolpath, 10, 20)
    lift = np.zeros((len(part), 3))
    lift[[0, 4, 5, 9], 2] = 500.0
    lifted = Toolpath(part.cl + lift, part.theta_a, part.theta_b)
    engagement = engage(stock, tool, lifted, settings)
    assert not engagement.engaged[[0, 4, 5, 9]].any() and engagement.engaged[[1, 2, 3, 6, 7, 8]].any(axis=1).all()
    assert summary_text(engagement, toolpath=lifted, first_cl=10) == reference_summary(engagement, lifted, 10)
