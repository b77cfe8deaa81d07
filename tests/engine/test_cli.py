"""The command line, end to end: in-process through main() and once as `python -m abm_workbench`."""

import io
import json
import os
import signal
import subprocess
import sys

import numpy as np
import pytest

from abm_workbench import cli
from abm_workbench.jobs import run as runs
from abm_workbench.formats.results_csv import (INPROCESS_COLUMNS, INPROCESS_SUMMARY_COLUMNS, RESULT_COLUMNS, SUMMARY_COLUMNS,
                                                TOOLPATH_COLUMNS, read_results)

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PYTHON = "/usr/bin/python3"
M, P = 12, 37  # CL points of the test pass; angles 0:180 by 5 degrees
JOB = {"diameter": 12, "flutes": 2, "flute_length": 30, "feed_per_tooth": 0.1, "inclination": 10,
       "spindle_rpm": 4000, "phi_range": [0, 180], "phi_step": 5, "description": "test pass"}
INPUTS = ["job.json", "stock.json", "toolpath.csv"]


@pytest.fixture
def case(tmp_path, monkeypatch):
    """tmp_path holding stock.json, toolpath.csv (M points across a step and a curved wall), job.json.

    The working directory is tmp_path, so the files go by their bare names.
    """
    y = [-15.0, -9.0, -3.0, 3.0, 9.0, 15.0]
    stock = {
        "format": "abm-staircase/1", "units": "mm", "base_z": -20, "x_min": 0, "x_max": 130,
        "y_min": -15, "y_max": 15,
        "sections": [{"z_top": 4.0}, {"z_top": 6.5, "wall": [[40, v] for v in y]},
                     {"z_top": 3.0, "wall": [[80 + 3 * np.sin(v / 5), v] for v in y]}],
    }
    (tmp_path / "stock.json").write_text(json.dumps(stock))
    rows = [f"{x:.6f},0,{x / 60 - 1:.6f},0,10" for x in np.linspace(10, 120, M)]
    (tmp_path / "toolpath.csv").write_text("x,y,z,theta_a,theta_b\n" + "\n".join(rows) + "\n")
    (tmp_path / "job.json").write_text(json.dumps(JOB))
    monkeypatch.chdir(tmp_path)
    return tmp_path


BASE = ["engage", "--stock", "stock.json", "--toolpath", "toolpath.csv", "--job", "job.json", "--out", "R.csv"]
FULL = ["engage", "--stock", "stock.json", "--toolpath", "toolpath.csv", "--diameter", "12", "--flutes", "2",
        "--flute-length", "30", "--feed-per-tooth", "0.1", "--inclination", "10", "--phi-step", "5",
        "--phi-range", "0:180", "--spindle-rpm", "4000", "--out", "R.csv", "--plot", "R.png"]


def run(argv, capsys):
    """main(argv) -> (status, stdout, stderr)."""
    status = cli.main(argv)
    out, err = capsys.readouterr()
    return status, out, err


def test_engage_with_every_option(case, capsys):
    status, out, err = run(FULL, capsys)
    assert (status, err) == (0, "")
    assert sorted(os.listdir(case)) == sorted(INPUTS + ["R.csv", "R.png", "R.summary.csv"])
    summary, sources = out.splitlines()
    assert summary.startswith(f"abm: {M} CL points x {P} angles = {M * P} instants in ")
    assert "depth of cut " in summary and summary.endswith("wrote R.csv, R.summary.csv, R.png")
    assert sources == ("abm: parameters: diameter 12 mm [--diameter], 2 flutes [--flutes], flute length 30 mm "
                       "[--flute-length], corner radius 0 mm [default], feed 0.1 mm/tooth [--feed-per-tooth], inclination 10° [--inclination], "
                       "spindle 4000 rpm [--spindle-rpm], φ 0..180° [--phi-range], step 5° [--phi-step]; in-process stock "
                       "(0 of 12 CL points changed by earlier moves)")
    results = read_results(case / "R.csv")
    assert list(results) == [*RESULT_COLUMNS, *INPROCESS_COLUMNS] and len(results["cl"]) == M * P
    np.testing.assert_array_equal(results["phi_deg"][:P], np.arange(0, 181, 5))
    summary = read_results(case / "R.summary.csv")
    assert list(summary) == [*SUMMARY_COLUMNS, *TOOLPATH_COLUMNS, *INPROCESS_SUMMARY_COLUMNS]
    assert sorted(set(summary["cl"])) == list(range(M))
    assert (case / "R.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_job_gives_defaults_and_options_override(case, capsys):
    status, out, _ = run(BASE + ["--phi-step", "10", "--phi-range", "0:90"], capsys)
    assert status == 0 and f"x 10 angles = {M * 10} instants" in out
    assert sorted(os.listdir(case)) == sorted(INPUTS + ["R.csv", "R.summary.csv"])
    status, out, _ = run(BASE, capsys)
    assert status == 0 and f"x {P} angles" in out


def test_engage_as_a_module_from_the_repository_root(case):
    argv = [PYTHON, "-m", "abm_workbench", "engage", "--stock", str(case / "stock.json"),
            "--toolpath", str(case / "toolpath.csv"), "--job", str(case / "job.json"), "--out", str(case / "R.csv")]
    done = subprocess.run(argv, cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith(f"abm: {M} CL points") and done.stderr == ""
    assert len(read_results(case / "R.csv")["cl"]) == M * P
    bad = subprocess.run(argv[:-1] + [str(case / "R.csv"), "--phi-range", "a:b"], cwd=ROOT, capture_output=True,
                         text=True, timeout=120)
    assert bad.returncode == 2
    assert bad.stderr == "abm: error: --phi-range: expected START:END in degrees such as 0:180, got 'a:b'\n"


def test_apt_toolpath_gives_tool_and_spindle(case, capsys):
    axes = ",".join(f"{v:.9f}" for v in (np.sin(np.radians(10)), 0, np.cos(np.radians(10))))
    moves = "".join(f"GOTO/{x:.6f},0,{x / 60 - 1:.6f},{axes}\n" for x in np.linspace(10, 120, M))
    (case / "path.apt").write_text(f"MULTAX\nCUTTER/10,0,5,0,0,0,60\nCSI_SET_FLUTE_LENGTH/25\nSPINDL/3000\n"
                                  f"OPSKIP/ON\n{moves}OPSKIP/OFF\n")
    status, out, err = run(BASE[:4] + ["path.apt", "--job", "job.json", "--spindle-rpm", "5000", "--out", "R.csv"],
                           capsys)
    assert status == 0
    assert err.splitlines() == [
        "abm: warning: path.apt:5: OPSKIP: record not understood, ignored (2 times)",
        "abm: warning: path.apt gives diameter 10, job.json 12: using 10, the value the toolpath was made for",
        "abm: warning: path.apt gives flute_length 25, job.json 30: using 25, the value the toolpath was made for",
        "abm: warning: path.apt gives spindle_rpm 3000, --spindle-rpm 5000: using 3000, the value the toolpath "
        "was made for",
        "abm: warning: path.apt gives spindle_rpm 3000, job.json 4000: using 3000, the value the toolpath was made for",
    ]
    sources = out.splitlines()[1]
    assert "diameter 10 mm [path.apt CUTTER]" in sources and "flute length 25 mm [path.apt CSI_SET_FLUTE_LENGTH]" in sources
    assert "spindle 3000 rpm [path.apt SPINDL]" in sources and "2 flutes [job.json]" in sources
    assert len(read_results(case / "R.csv")["cl"]) == M * P


@pytest.mark.parametrize("option", [["--walls", "exact"], ["--wall-points", "even"], ["--y-window", "swept"]])
def test_solid_options_refused_for_a_json_stock(case, capsys, option):
    status, _, err = run(BASE + option, capsys)
    assert status == 2 and err == (f"abm: error: {option[0]}: applies to a solid stock (.step, .stp, .brep, .brp, "
                                   ".FCStd), not to stock.json\n")


def _write(name, text):
    def prepare(folder):
        (folder / name).write_text(text)
    return prepare


def _job(**changes):
    return _write("job.json", json.dumps({**JOB, **changes}))


def _nothing(folder):
    """No change to the inputs."""


@pytest.mark.parametrize(
    "prepare, extra, message",
    [
        (_write("stock.json", '{"format": "abm-staircase/1",\n "units": }'), [],
         "stock.json:2:11: invalid JSON: Expecting value"),
        (_write("stock.json", '{"format": "abm-staircase/9"}'), [], "stock.json: format must be 'abm-staircase/1'"),
        (_write("toolpath.csv", "x,y,z,theta_a,theta_b\n10,0,0,0,10\n20,0,zero,0,10\n"), [],
         "toolpath.csv:3: column 'z': 'zero' is not a number"),
        (_write("toolpath.csv", "x,y,z,i,j,k\n10,0,0,0,0,1\n20,0,0,0,0,-1\n"), [],
         "toolpath.csv: the in-process stock cannot sweep the program: row 1 (line 3): the tool axis turns by 180° "
         "in one cutting move"),
        (_nothing, ["--stock", "missing.json"], "missing.json: cannot read: No such file or directory"),
        (_nothing, ["--phi-range", "a:b"], "--phi-range: expected START:END in degrees such as 0:180, got 'a:b'"),
        (_nothing, ["--phi-range", "0:90:180"], "--phi-range: expected START:END"),
        (_nothing, ["--phi-range", "180:0"], "--phi-range: must not be below the first rotation angle 180°, got 0°"),
        (_nothing, ["--phi-step", "0"], "--phi-step: must be positive, got 0°"),
        (_nothing, ["--diameter", "-12"], "--diameter: must be positive, got -12 mm"),
        (_nothing, ["--flute-length", "nan"], "--flute-length: must be a finite number, got nan"),
        (_job(diameter=None), [], "job.json: diameter: must be a number, got null"),
        (_job(flutes="two"), [], "job.json: flutes: must be a number, got \"two\""),
        (_job(flutes=2.5), [], "job.json: flutes: must be a whole number, got 2.5"),
        (_job(phi_range=[0]), [], "job.json: phi_range: must be [start, end] in degrees"),
        (_job(description=3), [], "job.json: description: must be a string"),
        (_job(tool="ball"), [], "job.json: unknown key 'tool'"),
        (_write("job.json", json.dumps({k: v for k, v in JOB.items() if k != "feed_per_tooth"})), [],
         "missing --feed-per-tooth (or 'feed_per_tooth' in a --job file)"),
        (_write("toolpath.csv", "x,y,z,theta_a,theta_b\n10,0,40,0,0\n20,0,40,0,0\n"), [],
         "toolpath.csv: the tool never touches the stock"),
        (_nothing, ["--out", "toolpath.csv/R.csv"], "toolpath.csv/R.csv: cannot write: "),
        (_nothing, ["--out", "new/R.csv", "--diameter", "0"], "--diameter: must be positive"),
        (_nothing, ["--plot", "R.csv"], "R.csv: written twice"),
        (_nothing, ["--toolpath", "toolpath.nc"], "toolpath.nc: cannot read: No such file or directory"),
        (_write("toolpath.csv", "\x00\x01\x02 binary"), [], "toolpath.csv: "),
        (_nothing, ["--stock", "stock.txt"], "stock.txt: unknown stock file type"),
        (_nothing, ["--out", "toolpath.csv"], "toolpath.csv: is an input and would be overwritten"),
    ],
)
def test_bad_input_exits_2_and_writes_nothing(case, capsys, prepare, extra, message):
    prepare(case)
    status, out, err = run(BASE + ["--plot", "R.png"] + extra, capsys)
    assert status == 2 and out == ""
    assert err.startswith(f"abm: error: {message}") and err.count("\n") == 1
    assert sorted(os.listdir(case)) == INPUTS


def test_output_folders_are_made(case, capsys):
    status, out, _ = run(BASE[:-1] + ["out/pass 1/R.csv", "--plot", "plots/R.png"], capsys)
    assert status == 0 and out.splitlines()[0].endswith("wrote out/pass 1/R.csv, out/pass 1/R.summary.csv, plots/R.png")
    assert sorted(os.listdir(case / "out" / "pass 1")) == ["R.csv", "R.summary.csv"]
    assert os.listdir(case / "plots") == ["R.png"]


def test_missing_job_and_options(case, capsys):
    status, _, err = run(BASE[:5] + ["--out", "R.csv"], capsys)
    assert status == 2 and err == "abm: error: missing --diameter (or 'diameter' in a --job file)\n"


def test_failure_leaves_older_results_untouched(case, capsys):
    for name in ("R.csv", "R.summary.csv", "R.png"):
        (case / name).write_text(f"old {name}")
    status, _, _ = run(BASE + ["--plot", "R.png", "--diameter", "0"], capsys)
    assert status == 2
    for name in ("R.csv", "R.summary.csv", "R.png"):
        assert (case / name).read_text() == f"old {name}"
    assert sorted(os.listdir(case)) == sorted(INPUTS + ["R.csv", "R.png", "R.summary.csv"])


def test_interrupt_while_writing_leaves_nothing(case, capsys, monkeypatch):
    written = []

    def interrupt_after_first_chunk(parts, path, summary):
        with open(path, "w") as results, open(summary, "w") as segments:
            for results_text, summary_text in parts:
                results.write(results_text)
                segments.write(summary_text)
                written.append(path)
                raise KeyboardInterrupt

    monkeypatch.setattr(runs, "write_chunks", interrupt_after_first_chunk)
    status, _, err = run(BASE, capsys)
    assert (status, err) == (130, "abm: interrupted\n")
    assert len(written) == 1 and sorted(os.listdir(case)) == INPUTS


@pytest.mark.parametrize("stop", [signal.SIGINT, signal.SIGHUP])
def test_a_stop_signal_once_the_outputs_move_is_ignored(case, capsys, monkeypatch, stop):
    """A signal between the moves of R.csv and R.summary.csv into place used to stop the run with R.csv new and
    the summary missing: the run is finishing by then, and ends whole (status 0)."""
    real = os.replace

    def signalled(*args, **kwargs):
        real(*args, **kwargs)
        os.kill(os.getpid(), stop)

    monkeypatch.setattr(os, "replace", signalled)
    status, _, err = run(BASE, capsys)
    assert (status, err) == (0, "")
    assert sorted(os.listdir(case)) == sorted(INPUTS + ["R.csv", "R.summary.csv"])


def test_interrupt_in_the_engine(case, capsys, monkeypatch):
    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(runs, "engage_stock", interrupted)
    monkeypatch.setattr(runs, "engage_in_process", interrupted)
    status, _, _ = run(BASE, capsys)
    assert status == 130 and sorted(os.listdir(case)) == INPUTS


@pytest.mark.parametrize(
    "argv, message",
    [
        ([], "abm: error: the following arguments are required: COMMAND"),
        (["mill"], "abm: error: argument COMMAND: invalid choice: 'mill'"),
        (BASE + ["--diameter", "twelve"], "abm: error: argument --diameter: invalid float value: 'twelve'"),
        (BASE[:3], "abm: error: the following arguments are required: --toolpath, --out"),
    ],
)
def test_usage_errors(case, capsys, argv, message):
    status, _, err = run(argv, capsys)
    assert status == 2 and err.startswith("usage: abm") and message in err


def test_help(capsys):
    status, out, _ = run(["engage", "--help"], capsys)
    assert status == 0 and "--feed-per-tooth" in out and "--phi-range" in out


def test_progress_only_on_a_terminal(case, capsys, monkeypatch):
    status, _, err = run(BASE, capsys)
    assert status == 0 and err == ""
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    status, _, err = run(BASE, capsys)
    assert status == 0 and err.startswith("\rabm: engage [")
    assert err.endswith("\n") and f"] {M}/{M} CL points, " in err and "s elapsed, ETA 0 s" in err.splitlines()[-1]


class _Stream(io.StringIO):
    """A text stream that says whether it is a terminal."""

    def __init__(self, terminal):
        super().__init__()
        self.terminal = terminal

    def isatty(self):
        return self.terminal


def test_progress_lines_and_bar(monkeypatch):
    clock = iter([0.0, 2.0, 8.0])
    monkeypatch.setattr(cli.time, "perf_counter", lambda: next(clock))
    stream = _Stream(False)
    progress = cli._Progress("boolean reference", stream)
    progress(1, 4)
    progress(4, 4)
    assert stream.getvalue() == ("abm: boolean reference: CL point 1/4, 2.0 s elapsed, ETA 6 s\n"
                                 "abm: boolean reference: CL point 4/4, 8.0 s elapsed, ETA 0 s\n")
    clock = iter([0.0, 2.0, 8.0])
    stream = _Stream(True)
    progress = cli._Progress("boolean", stream)
    progress(1, 4)
    progress(4, 4)
    assert stream.getvalue() == (f"\rabm: boolean [{'#' * 8}{'.' * 22}] 1/4 CL points, 2.0 s elapsed, ETA 6 s"
                                 f"\rabm: boolean [{'#' * 30}] 4/4 CL points, 8.0 s elapsed, ETA 0 s\n")


@pytest.mark.parametrize("corner", [3.0, 6.0])
def test_bull_nose_and_ball_against_the_in_process_stock(case, capsys, corner):
    """A bull-nose (R3) and a ball-end (R6) mill run against the in-process stock, with no fallback: the results are
    engine.stocks.engage_in_process's against the program swept with the tool's corner radius (not a flat-end
    cylinder's, which removes more), and some CL points of the second pass lost material to the first."""
    from abm_workbench.engine import CutSettings, Tool
    from abm_workbench.engine.inprocess import ProgramMoves, swept_pieces
    from abm_workbench.engine.stocks import engage_in_process
    from abm_workbench.formats.staircase_json import load_staircase
    from abm_workbench.formats.toolpath_csv import load_toolpath

    x = np.linspace(10, 120, M)
    cl = np.concatenate([np.stack([x, np.full(M, -4.0), x / 60 - 1.5], 1),
                         np.stack([x[::-1], np.full(M, 4.0), x[::-1] / 60 - 1.0], 1)])
    (case / "toolpath.csv").write_text("x,y,z,theta_a,theta_b\n" + "".join(f"{a:.6f},{b:.6f},{c:.6f},0,0\n"
                                                                        for a, b, c in cl))
    status, out, err = run(BASE + ["--corner-radius", f"{corner:g}"], capsys)
    assert (status, err) == (0, "")
    changed = int(out.splitlines()[1].split("in-process stock (")[1].split(" of ")[0])
    assert 0 < changed <= M and out.splitlines()[1].endswith(f"of {2 * M} CL points changed by earlier moves)")
    results = read_results(case / "R.csv")
    n = len(cl)
    tool = Tool(12.0, 2, 30.0, corner_radius=corner)
    toolpath = load_toolpath(case / "toolpath.csv")  # its frames turned to the feed, as the job takes them
    settings = CutSettings(0.1, inclination=10.0, phi_start=0.0, phi_end=180.0, phi_step=5.0)
    stock = load_staircase(case / "stock.json")

    def engine(corner_swept):
        moves = ProgramMoves(toolpath.cl, np.tile([0.0, 0.0, 1.0], (n, 1)), np.arange(n) > 0, np.full(n, 6.0),
                             np.full(n, 30.0),
                             np.arange(n) + 2, np.full(n, corner_swept))
        return engage_in_process(stock, tool, toolpath, settings, swept_pieces(moves), np.arange(n))[0].length

    want = engine(corner)
    np.testing.assert_allclose(results["length"].reshape(n, P), want, rtol=0, atol=1e-9)
    assert np.abs(engine(0.0) - want).max() > 1e-3


def test_validate_keeps_the_in_process_stock_for_every_tool(monkeypatch):
    """validate keeps the in-process stock for flat-end, ball-end and bull-nose mills, a bull-nose ramp
    included (the reference decides the volumes OpenCASCADE has no reliable solids for with its exact inside
    test: tests/cad/test_corner_inprocess_occ.py); single flutes (--flute) refuse it when it is asked for."""
    from types import SimpleNamespace

    from abm_workbench.engine import Tool
    from abm_workbench.engine.inprocess import ProgramMoves, swept_pieces
    from abm_workbench.errors import ParameterError

    ramp = [(0, 0, 9), (0, 0, 2), (20, 0, 0), (20, 10, 0)]
    bull, ball = Tool(8.0, 2, 12.0, corner_radius=1.0), Tool(8.0, 2, 12.0, corner_radius=4.0)
    for tool in (bull, ball, Tool(8.0, 2, 12.0)):
        moves = ProgramMoves(np.array(ramp, dtype=float), np.tile([0.0, 0.0, 1.0], (4, 1)), np.arange(4) > 0,
                             np.full(4, 4.0), np.full(4, 12.0), np.arange(4) + 1, np.full(4, tool.corner_radius))
        sweep = swept_pieces(moves), np.arange(4)
        monkeypatch.setattr(runs, "in_process_sweep", lambda prepared, warn=None: (sweep, ""))
        for model in (None, "in-process"):
            prepared = SimpleNamespace(tool=tool, job=SimpleNamespace(stock_model=model))
            assert runs._validated_sweep(prepared.job, prepared, None, None) == (sweep, "")
    prepared = SimpleNamespace(tool=ball, job=SimpleNamespace(stock_model="in-process"))
    with pytest.raises(ParameterError, match="in-process is not available for validate with --flute"):
        runs._validated_sweep(prepared.job, prepared, [0], None)
