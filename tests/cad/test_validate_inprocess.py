"""validate against the in-process stock: the OpenCASCADE reference (the stock cut by exact solids
of the earlier moves' swept volumes) and the engine, both against the brute-force sampler of
tests/engine/test_inprocess.py (dense points along each edge line, inside the stock and in no
earlier tool position, changes refined by bisection).

The program: operation 1 (D 10, flute length 12) in two overlapping passes, the second turning
its axis (five-axis moves, in sub-steps of TOLERANCE); operation 2 (D 7, flute length 16),
tilted, crossing both. Both operations' passes are validated.
"""

import numpy as np
import pytest

from abm_workbench.cad import inprocess_boolean
from abm_workbench.cad.inprocess_boolean import ProgramSweep
from abm_workbench.cad.solids import staircase_solid
from abm_workbench.engine import CutSettings, Tool, Toolpath, edge_lines
from abm_workbench.engine.inprocess import swept_pieces
from abm_workbench.validation import validate
from tests.cad.profile_cases import validate_two_passes
from tests.engine.test_inprocess import Program, reference, staircase, straight

AGREE = 0.01  # mm: the bound, for lengths, LEP and UEP
TOLERANCE = 0.01  # mm: five-axis sub-steps, fine enough that their error stays well inside AGREE
SETTINGS = CutSettings(0.1, 0.0, 0.0, 330.0, 30.0)  # the whole circle of the tool


def program():
    """(Program, rows of pass 2, rows of operation 2), see the module docstring."""
    prog = Program()
    prog.add_pass(straight(8, 52, -3.0, 3.0, 5), 5.0, 12.0)
    back = straight(52, 8, 4.0, 0.0, 5)
    back[:, 2] = np.linspace(4.5, 2.0, 5)
    turning = np.column_stack([np.linspace(0.04, -0.02, 5), np.linspace(0.0, 0.02, 5), np.ones(5)])
    second = prog.add_pass(back, 5.0, 12.0, turning)
    cross = np.stack([np.full(5, 30.0), np.linspace(-16, 14, 5), np.full(5, 1.5)], axis=1)
    lean = np.tile([0.1, -0.1, 1.0], (5, 1))
    other = prog.add_pass(cross, 3.5, 16.0, lean)
    return prog, second, other


def check(rows, workers=1):
    """Validate the pass at program `rows`; return (Validation, brute-force lengths, LEP, UEP (m, p))."""
    prog, *_ = program()
    d = prog.as_dict()
    radius, flute = d["radius"][rows[0]], d["flute"][rows[0]]
    tool = Tool(2.0 * radius, 2, flute)
    path = Toolpath.from_axes(d["cl"][rows], d["axis"][rows])
    stock = staircase()
    result = validate(staircase_solid(stock), stock, tool, path, SETTINGS, workers=workers,
                      sweep=(swept_pieces(prog.moves(), TOLERANCE), rows))
    base, direction = edge_lines(path, tool, SETTINGS.phi)
    found = [[reference(base[i, k], direction[i], flute, d, row) for k in range(SETTINGS.phi.size)]
             for i, row in enumerate(rows)]
    length = np.array([[sum(b - a for a, b in line) for line in cl] for cl in found])
    lep = np.array([[line[0][0] if line else np.nan for line in cl] for cl in found])
    uep = np.array([[line[-1][1] if line else np.nan for line in cl] for cl in found])
    return result, length, lep, uep


def assert_agree(result, length, lep, uep):
    """Engine and boolean reference both within AGREE of the brute force, NaN where it has none."""
    for name, got in (("boolean", result.reference), ("engine", {"length": result.comparison.l_abm,
                                                                 "lep_l": result.comparison.lep_abm,
                                                                 "uep_l": result.comparison.uep_abm})):
        for key, want in (("length", length), ("lep_l", lep), ("uep_l", uep)):
            np.testing.assert_allclose(got[key], want, rtol=0, atol=AGREE, err_msg=f"{name} {key}")


@pytest.mark.parametrize("which", ["second pass", "second operation"])
def test_validate_in_process_agrees_with_brute_force(which):
    _, second, other = program()
    rows = second if which == "second pass" else other
    result, length, lep, uep = check(rows)
    assert_agree(result, length, lep, uep)
    check_ = result.in_process
    assert check_.changed.any() and check_.swept.max() > 0
    # what earlier moves removed shows: the stock as given has more material at the changed CL points
    assert (check_.initial[check_.changed] > length[check_.changed] + AGREE).any(axis=1).all()
    assert np.abs(result.comparison.difference).max() <= AGREE


def test_workers_give_the_same_reference():
    _, _, other = program()
    one, *_ = check(other[:3])
    two, *_ = check(other[:3], workers=2)
    for key in ("length", "lep_l", "uep_l", "swept"):
        np.testing.assert_array_equal(one.reference[key], two.reference[key])


def test_rows_of_finds_a_part_once():
    cl = np.array([[0.0, 0, 0], [1, 0, 0], [2, 0, 0], [1, 0, 0]])
    whole = Toolpath(cl, np.zeros(4), np.zeros(4))
    sweep = ProgramSweep(None, np.array([10, 11, 12, 13]), whole)
    part = Toolpath(cl[1:3], np.zeros(2), np.zeros(2))
    np.testing.assert_array_equal(sweep.rows_of(part), [11, 12])
    np.testing.assert_array_equal(sweep.rows_of(whole), [10, 11, 12, 13])
    with pytest.raises(ValueError, match="found 2 times"):
        sweep.rows_of(Toolpath(cl[1:2], np.zeros(1), np.zeros(1)))
    with pytest.raises(ValueError, match="found 0 times"):
        sweep.rows_of(Toolpath(cl[1:2], np.ones(1), np.zeros(1)))


def test_stock_heights_show_what_earlier_moves_removed():
    """Top of the in-process stock around the second operation's CL points, against the test stock's
    sections and the brute-force removal of tests/engine/test_inprocess.py along vertical lines."""
    prog, _, other = program()
    d = prog.as_dict()
    tool = Tool(7.0, 2, 16.0)
    path = Toolpath.from_axes(d["cl"][other], d["axis"][other])
    stock = staircase_solid(staircase())
    pieces = swept_pieces(prog.moves())
    lowered = 0
    for i in (1, 3):
        x, y, z = inprocess_boolean.stock_heights(stock, pieces, other[i], tool, path, i, cells=9)
        for a, b in ((2, 3), (4, 4), (6, 1), (7, 7)):
            base = np.array([x[b], y[a], -1.0])
            want = reference(base, np.array([0.0, 0, 1]), 12.0, d, other[i])
            top = want[-1][1] - 1.0 if want else np.nan
            np.testing.assert_allclose(z[a, b], top, rtol=0, atol=AGREE)
            before = reference(base, np.array([0.0, 0, 1]), 12.0, d, 0)  # no earlier move
            lowered += not want or top < before[-1][1] - 1.0 - AGREE
    assert lowered  # some of the points show what earlier moves removed


def test_cli_validate_in_process_names_the_stock_model(tmp_path, monkeypatch, capsys):
    page = validate_two_passes(tmp_path, monkeypatch, capsys, 0)
    assert "stock model" in page and "in-process: the stock minus the volumes swept" in page
    assert "<h2>In-process stock</h2>" in page
    header = (tmp_path / "report" / "comparison.csv").read_text().splitlines()[0].split(",")
    assert header[-1] == "l_initial"
    depth = (tmp_path / "report" / "depth.csv").read_text().splitlines()
    changed = [int(line.split(",")[-2]) for line in depth[1:]]
    assert depth[0].endswith("changed,swept") and any(changed)
    page = validate_two_passes(tmp_path, monkeypatch, capsys, 0, "initial", "initial")
    assert "initial: the stock as given" in page and "<h2>In-process stock</h2>" not in page
