"""engage on a STEP stock and an APT toolpath, and validate end to end (report, FCStd, interrupts, errors)."""

import json
import os

import numpy as np
import pytest

from abm_workbench import cli
from abm_workbench.cad.freecad_env import FreeCAD
from abm_workbench.cad.solids import export_step
from abm_workbench.engine import Tool, angles_to_axis
from abm_workbench.formats.results_csv import read_results
from abm_workbench.formats.staircase_json import dump_staircase
from abm_workbench.cad.recognise import load_solid
from abm_workbench.jobs import load_path, swept_y_window

from .conftest import STOCKS

# Three CL points beside the walls of the "ascending" stock, tilted both ways (mm, deg).
CL = [[21.3, 0.7, 0.9], [44.9, 1.3, 2.1], [73.0, -0.4, 4.3]]
THETA_A, THETA_B = [12.0, 0.0, -6.0], [18.0, 25.0, -30.0]
JOB = {"flutes": 2, "feed_per_tooth": 0.1, "inclination": 10, "phi_step": 10, "description": "a test pass"}
INPUTS = ["job.json", "path.apt", "stock.json", "stock.step"]


def apt_text():
    """The pass as an APT file: CUTTER D 12, flute length 25 (CSI_SET_FLUTE_LENGTH: CUTTER's seventh number is the
    tool's height), SPINDL 4000, and one record it does not know."""
    axes = angles_to_axis(THETA_A, THETA_B)
    gotos = "".join(f"GOTO/{x:.6f},{y:.6f},{z:.6f},{i:.9f},{j:.9f},{k:.9f}\nAUXFUN/7\n"
                    for (x, y, z), (i, j, k) in zip(CL, axes))
    return f"MULTAX/ON\nCUTTER/12,0,6,0,0,0,60\nCSI_SET_FLUTE_LENGTH/25\nSPINDL/RPM,4000,CLW\n{gotos}OPSKIP/OFF\n"


@pytest.fixture
def case(tmp_path, monkeypatch, solids):
    """tmp_path (the working directory) holding stock.step, the same stock.json, path.apt and job.json."""
    export_step(solids["ascending"], tmp_path / "stock.step")
    dump_staircase(STOCKS["ascending"], tmp_path / "stock.json")
    (tmp_path / "path.apt").write_text(apt_text())
    (tmp_path / "job.json").write_text(json.dumps(JOB))
    monkeypatch.chdir(tmp_path)
    return tmp_path


def run(argv, capsys):
    """main(argv) -> (status, stdout, stderr)."""
    status = cli.main(argv)
    out, err = capsys.readouterr()
    return status, out, err


ENGAGE = ["engage", "--toolpath", "path.apt", "--job", "job.json"]
VALIDATE = ["validate", "--stock", "stock.step", "--toolpath", "path.apt", "--job", "job.json", "--report", "report"]


def test_engage_on_step_and_apt_matches_the_json_stock(case, capsys):
    status, out, err = run(ENGAGE + ["--stock", "stock.step", "--out", "step.csv"], capsys)
    assert status == 0, err
    assert err == ("abm: warning: path.apt:11: OPSKIP: record not understood, ignored\n"
                   "abm: warning: path.apt: records that carry nothing the engine needs, ignored: AUXFUN (3)\n")
    summary, sources = out.splitlines()
    assert summary.startswith("abm: 3 CL points x 19 angles = 57 instants in ")
    assert sources.startswith("abm: parameters: diameter 12 mm [path.apt CUTTER], 2 flutes [job.json], "
                              "flute length 25 mm [path.apt CSI_SET_FLUTE_LENGTH], "
                              "corner radius 0 mm [path.apt CUTTER], feed 0.1 mm/tooth [job.json]")
    assert "spindle 4000 rpm [path.apt SPINDL]" in sources and "step 10° [job.json]" in sources
    assert sources.endswith("; stock: exact walls, y window -12..12 mm; in-process stock (0 of 3 CL points changed "
                            "by earlier moves)")
    status, _, _ = run(ENGAGE + ["--stock", "stock.json", "--out", "json.csv"], capsys)
    assert status == 0
    step, json_ = read_results(case / "step.csv"), read_results(case / "json.csv")
    assert (json_["length"] > 0).sum() > 30
    np.testing.assert_allclose(step["length"], json_["length"], atol=1e-8)
    assert (step["uep_surface"] == json_["uep_surface"]).all()


@pytest.mark.parametrize("options", [
    ["--walls", "quintic", "--wall-points", "even"],
    ["--walls", "quintic", "--y-window", "swept"],
    ["--y-window=-10:10", "--inclination", "5"],
])
def test_engage_solid_options(case, capsys, options):
    status, out, err = run(ENGAGE + ["--stock", "stock.step", "--out", "R.csv"] + options, capsys)
    assert status == 0, err
    if "--y-window=-10:10" in options:
        assert "inclination 5° [--inclination]" in out and "y window -10..10 mm" in out
    if "swept" in options or options[:2] == ["--walls", "quintic"] and "--y-window" not in options:
        # swept is the quintic's default; inside the stock's y range -12..12 mm here
        z_max = load_solid("stock.step").BoundBox.ZMax
        low, high = swept_y_window(load_path("path.apt")[0], Tool(12, 2, 25), z_max)
        assert -12 < low < high < 12 and f"quintic walls, y window {low:.6g}..{high:.6g} mm" in out


def test_validate_writes_report_and_fcstd(case, capsys):
    status, out, err = run(VALIDATE + ["--fcstd", "out/pass.FCStd", "--cl", "0,2"], capsys)
    assert status == 0, err
    unknown, ignored, *progress = err.splitlines()
    assert unknown.startswith("abm: warning: path.apt:11: OPSKIP: ") and ignored.endswith("ignored: AUXFUN (3)")
    assert [line.split(",")[0] for line in progress] == [f"abm: boolean reference: CL point {k}/3" for k in (1, 2, 3)]
    assert all(" s elapsed, ETA " in line for line in progress)
    assert out.startswith("abm: 3 CL points x 19 angles: length of cut max |relative error| ")
    assert out.splitlines()[0].endswith("wrote report/index.html, out/pass.FCStd")
    assert sorted(os.listdir(case)) == sorted(INPUTS + ["out", "report"])
    assert sorted(os.listdir(case / "report")) == ["comparison.csv", "depth.csv", "index.html", "segments.csv",
                                                   "surfaces.csv"]
    assert os.listdir(case / "out") == ["pass.FCStd"]
    comparison = (case / "report" / "comparison.csv").read_text().splitlines()
    assert len(comparison) == 1 + 3 * 19
    difference = [float(row.split(",")[4]) for row in comparison[1:]]
    assert max(map(abs, difference)) < 1e-8  # exact walls: ABM and the boolean agree
    document = FreeCAD.openDocument(str(case / "out" / "pass.FCStd"))
    try:
        names = {obj.Name for obj in document.Objects}
        assert {"Stock", "Toolpath", "CL000", "CL002", "CL000_Intersection", "CL002_Intersection"} <= names
        assert "CL001" not in names
        assert all(obj.isValid() for obj in document.Objects)
        assert all(obj.Shape.isValid() for obj in document.Objects if obj.TypeId == "Part::Feature")
    finally:
        FreeCAD.closeDocument(document.Name)


def test_validate_a_json_stock_replaces_an_older_report(case, capsys):
    """An older report (only files a report writes) is replaced; a folder holding anything else is refused
    before any work, and the user's file is kept."""
    (case / "report").mkdir()
    (case / "report" / "index.html").write_text("old")
    (case / "report" / "surfaces.csv").write_text("old")
    status, out, err = run(VALIDATE[:2] + ["stock.json"] + VALIDATE[3:] + ["--phi-step", "30"], capsys)
    assert status == 0, err
    assert "x 7 angles" in out and "step 30° [--phi-step]" in out
    assert (case / "report" / "surfaces.csv").read_text() != "old"
    assert "quintic walls (JSON)" in (case / "report" / "index.html").read_text()
    (case / "report" / "notes.txt").write_text("mine")
    status, out, err = run(VALIDATE[:2] + ["stock.json"] + VALIDATE[3:] + ["--phi-step", "30"], capsys)
    assert status == 2 and "folder holds 'notes.txt', which no report writes" in err
    assert (case / "report" / "notes.txt").read_text() == "mine"


def test_interrupted_validate_leaves_nothing(case, capsys, monkeypatch):
    (case / "old.FCStd").write_text("old")

    def interrupt(self, done, total):
        if done == 2:
            raise KeyboardInterrupt

    monkeypatch.setattr(cli._Progress, "__call__", interrupt)
    status, out, err = run(VALIDATE + ["--fcstd", "old.FCStd"], capsys)
    assert (status, out) == (130, "") and err.endswith("\nabm: interrupted\n")
    assert sorted(os.listdir(case)) == sorted(INPUTS + ["old.FCStd"])
    assert (case / "old.FCStd").read_text() == "old"
    assert not [name for name in FreeCAD.listDocuments() if name.startswith("ABM_")]


def _write(name, text):
    def prepare(folder):
        (folder / name).write_text(text)
    return prepare


def _nothing(folder):
    """No change to the inputs."""


@pytest.mark.parametrize("prepare, extra, message", [
    (_write("stock.step", "ISO-10303-21;\nnot a step file\n"), [], "stock.step: "),
    (_nothing, ["--stock", "stock.json", "--walls", "quintic"],
     "--walls: applies to a solid stock (.step, .stp, .brep, .brp, .FCStd), not to stock.json"),
    (_nothing, ["--y-window", "a:b"], "--y-window: expected whole, swept or Y0:Y1 in mm"),
    (_nothing, ["--y-window=30:40"], "stock.step: y window 30..40 mm misses the stock's y range -12..12 mm"),
    (_nothing, ["--cl", "0,7"], "--cl: CL point 7 is not in the pass (0..2)"),
    (_nothing, ["--cl", "x"], "--cl: expected CL indices such as 0,22,40, got 'x'"),
    (_nothing, ["--fcstd", "pass.step"], "--fcstd: must end in .FCStd, got pass.step"),
    (_nothing, ["--fcstd", "report/pass.FCStd"], "report/pass.FCStd: lies inside the report folder report"),
    (_write("report", "a file"), [], "--report: must be a folder, and report is a file"),
    (_write("path.apt", "GOTO/1,2\n"), [], "path.apt:1: GOTO: takes x,y,z or x,y,z,i,j,k, got 2 number(s)"),
    (_write("path.apt", "MULTAX\nGOTO/10,0,40,0,0,1\n"), ["--diameter", "12", "--flute-length", "25"],
     "path.apt: the tool never touches the stock"),
    (_write("path.apt", "GOTO/20,0,1\n"), [], "missing --diameter (or 'diameter' in a --job file)"),
])
def test_bad_input_exits_2_and_writes_nothing(case, capsys, prepare, extra, message):
    prepare(case)
    before = sorted(os.listdir(case))
    status, out, err = run(VALIDATE + ["--fcstd", "pass.FCStd"] + extra, capsys)
    assert status == 2 and out == ""
    assert err.splitlines()[-1].startswith(f"abm: error: {message}"), err
    assert sorted(os.listdir(case)) == before


def test_a_folder_of_other_files_is_not_replaced(case, capsys):
    (case / "report").mkdir()
    (case / "report" / "notes.txt").write_text("mine")
    status, _, err = run(VALIDATE, capsys)
    assert status == 2 and "report: folder holds files but no report (index.html)" in err
    assert os.listdir(case / "report") == ["notes.txt"]
