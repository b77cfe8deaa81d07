"""validate --check / --check-every: the boolean reference at chosen CL points only.

Against the in-process program of test_validate_inprocess (its brute-force sampler the independent
reference): the checked CL points agree with the brute force, the others carry no reference and
no statistics; the report's tables and the annotated document say which were checked and, against
the in-process stock, show what earlier moves removed near the shown CL points.
"""

import zipfile

import numpy as np
import pytest

from abm_workbench import cli
from abm_workbench.cad.boolean import _inside_intervals
from abm_workbench.cad.freecad_env import FreeCAD
from abm_workbench.cad.solids import staircase_solid
from abm_workbench.engine import Tool, Toolpath
from abm_workbench.engine.inprocess import swept_pieces
from abm_workbench.formats.staircase_json import dump_staircase
from abm_workbench.validation import overall, segment_summary, validate
from tests.engine.test_inprocess import staircase

from .test_report import read_csv
from .profile_cases import TWO_PASSES_APT
from .test_validate_inprocess import AGREE, SETTINGS, TOLERANCE, check, program


def test_only_the_chosen_cl_points_are_checked_and_they_agree_with_brute_force():
    prog, _, other = program()
    _, length, lep, uep = check(other)  # the brute force at every CL point of operation 2
    d = prog.as_dict()
    path = Toolpath.from_axes(d["cl"][other], d["axis"][other])
    stock = staircase()
    tool = Tool(7.0, 2, 16.0)
    chosen = [3, 1]
    result = validate(staircase_solid(stock), stock, tool, path, SETTINGS, cls=chosen,
                      sweep=(swept_pieces(prog.moves(), TOLERANCE), other))
    np.testing.assert_array_equal(result.checked, [False, True, False, True, False])
    for key, want in (("length", length), ("lep_l", lep), ("uep_l", uep)):
        np.testing.assert_allclose(result.reference[key][chosen], want[chosen], rtol=0, atol=AGREE, err_msg=key)
        assert np.isnan(result.reference[key][[0, 2, 4]]).all(), key
    assert np.isnan(result.in_process.swept[[0, 2, 4]]).all() and (result.in_process.swept[chosen] > 0).all()
    # the engine ran everywhere; the statistics count the checked instants only
    assert result.engagement.shape == length.shape
    total = overall(result.comparison)
    assert total["instants"] == 2 * SETTINGS.phi.size and total["mismatched"] == 0
    assert total["max_abs_difference"] <= AGREE
    assert {row["cl"] for row in segment_summary(result.engagement, result.comparison)} <= set(chosen)


@pytest.mark.parametrize("cls", [[], [5], [-1], [1, 1]])
def test_validate_rejects_bad_cl_lists(cls):
    prog, _, other = program()
    d = prog.as_dict()
    path = Toolpath.from_axes(d["cl"][other], d["axis"][other])
    with pytest.raises(ValueError, match="cls must be distinct CL indices in 0..4"):
        validate(staircase_solid(staircase()), staircase(), Tool(7.0, 2, 16.0), path, SETTINGS, cls=cls)


@pytest.fixture
def case(tmp_path, monkeypatch):
    """The test program's files in tmp_path (the working folder); the validate arguments without outputs."""
    dump_staircase(staircase(), tmp_path / "stock.json")
    (tmp_path / "path.apt").write_text(TWO_PASSES_APT.format(corner=0))
    monkeypatch.chdir(tmp_path)
    return ["validate", "--stock", "stock.json", "--toolpath", "path.apt", "--flutes", "2", "--feed-per-tooth",
            "0.1", "--phi-step", "30", "--stock-model", "in-process"]


def test_cli_check_writes_the_checked_cl_points(case, tmp_path, capsys):
    status = cli.main(case + ["--report", "report", "--check", "1,3-4", "--cl", "6", "--fcstd", "shown.FCStd"])
    _, err = capsys.readouterr()
    assert status == 0, err
    depth = read_csv(tmp_path / "report" / "depth.csv")
    m = len(depth["cl"])
    checked = [cl for cl in range(m) if depth["checked"][cl] == "1"]
    assert checked == [1, 3, 4, 6] and set(depth["checked"]) == {"0", "1"}
    assert all(depth["depth_ref"][cl] == "" for cl in range(m) if cl not in checked)
    comparison = read_csv(tmp_path / "report" / "comparison.csv")
    assert sorted({int(cl) for cl in comparison["cl"]}) == checked and "" not in comparison["l_ref"]
    assert {int(cl) for cl in read_csv(tmp_path / "report" / "segments.csv")["cl"]} <= set(checked)
    page = (tmp_path / "report" / "index.html").read_text(encoding="utf-8")
    assert f"CL points checked</td><td>4 of {m}: 1, 3–4, 6 " in page
    with zipfile.ZipFile(tmp_path / "shown.FCStd") as archive:
        document = archive.read("Document.xml").decode("utf-8")
    for name in ("CL006_Intersection", "CL006_Removed", "CL006_InProcessTop"):
        assert f'name="{name}"' in document, name
    assert "not the in-process stock" in document
    reopened = FreeCAD.openDocument(str(tmp_path / "shown.FCStd"))
    try:
        removed, top = reopened.getObject("CL006_Removed"), reopened.getObject("CL006_InProcessTop")
        assert removed.Shape.isValid() and len(removed.Shape.Solids) >= int(depth["swept"][6]) > 0
        # the in-process top never rises above the stock as given, and lies lower where earlier moves cut
        points = np.unique([[v.X, v.Y, v.Z] for v in top.Shape.Vertexes], axis=0)
        stock = reopened.getObject("Stock").Shape
        low = stock.BoundBox.ZMin - 1.0
        lines = _inside_intervals(stock, np.column_stack([points[:, :2], np.full(len(points), low)]),
                                  np.array([0.0, 0.0, 1.0]), stock.BoundBox.ZLength + 2.0)
        given = np.array([found[-1][1] + low for found in lines])
        assert (points[:, 2] <= given + AGREE).all() and (points[:, 2] < given - AGREE).any()
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_cli_check_every(case, tmp_path, capsys):
    status = cli.main(case + ["--report", "report", "--check-every", "4", "--cl", "1"])
    _, err = capsys.readouterr()
    assert status == 0, err
    depth = read_csv(tmp_path / "report" / "depth.csv")
    m = len(depth["cl"])
    assert [cl for cl in range(m) if depth["checked"][cl] == "1"] == sorted({1, *range(0, m, 4)})


@pytest.mark.parametrize("extra, words", [
    (["--check", ""], "--check: is empty"),
    (["--check", " , "], "--check: is empty"),
    (["--check", "1,x"], "--check: item 2 'x' is not a CL index or a range"),
    (["--check", "1,5-2"], "--check: item 2 '5-2' runs backwards"),
    (["--check", "0,99"], "--check: item 2: CL point 99 is not in the pass (0.."),
    (["--check", "-3"], "--check: item 1 '-3' is not a CL index or a range"),
    (["--check-every", "0"], "--check-every: must be a positive whole number of CL points, got 0"),
])
def test_cli_check_rejects_bad_lists(case, tmp_path, capsys, extra, words):
    status = cli.main(case + ["--report", "report"] + extra)
    _, err = capsys.readouterr()
    assert status == 2 and words in err and "Traceback" not in err
    assert not (tmp_path / "report").exists()
