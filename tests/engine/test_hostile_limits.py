"""Hostile input, the command-line part of issue #29: each fault of the list, with the input that showed it.

Fast, in this process; the faults that need a child process (memory limits, signals, worker processes,
special files on the command line) are in tests/fuzz. The references are independent of the code
under test: counts taken from the engine's own swept pieces, sizes from the files' bytes, numpy's
own writer for archives.
"""

import os
import socket
import threading
import time
import zipfile

import numpy as np
import pytest

from abm_workbench import cli
from abm_workbench.engine import CutSettings, Tool, Toolpath, engage, flute_engagement
from abm_workbench.engine.arguments import WrongArgument
from abm_workbench.engine.model import NotANumber
from abm_workbench.errors import InputError
from abm_workbench.formats import check_output_path, read_bytes, read_text
from abm_workbench.formats.cl import read_program
from abm_workbench.formats.cl.arcs import arc_points, step_angle
from abm_workbench.formats.results_csv import read_results as read_csv_results
from abm_workbench.formats.results_npz import read_results as read_npz_results
from abm_workbench.formats.staircase_json import load_staircase
from abm_workbench.formats.toolpath_csv import load_toolpath
from abm_workbench.limits import TooLarge, allowing_large
from abm_workbench.parallel import engage_parallel, worker_count

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")
MODEL_3 = os.path.join(ROOT, "resources", "models", "model_test_3")


@pytest.fixture
def model(tmp_path, monkeypatch):
    """tmp_path holding model test 1's stock.json, toolpath.csv and job.json (working directory)."""
    for name in ("stock.json", "toolpath.csv", "job.json"):
        (tmp_path / name).write_bytes(open(os.path.join(MODEL, name), "rb").read())
    monkeypatch.chdir(tmp_path)
    return tmp_path


def run(argv, capsys):
    """cli.main(argv) -> (status, stderr lines)."""
    status = cli.main(argv)
    return status, capsys.readouterr().err.splitlines()


def engage_argv(*more, out="out/R.csv"):
    return ["engage", "--stock", "stock.json", "--toolpath", "toolpath.csv", "--job", "job.json", "--phi-step", "30",
            "--out", out, *more]


# One grammar for numbers on the command line, as in the files.

@pytest.mark.parametrize("option, text", [("--diameter", "1_2"), ("--diameter", "١٢"), ("--flutes", "٢"),
                                          ("--flutes", "1_0"), ("--workers", "1_0"), ("--operation", "１"),
                                          ("--sweep-tolerance", "0x10"), ("--tolerance", "1e")])
def test_numbers_outside_the_grammar_are_refused(model, capsys, option, text):
    status, err = run(engage_argv(option, text), capsys)
    assert status == 2 and err[-1].startswith(f"abm: error: argument {option}: invalid ")
    assert not os.path.exists("out")


@pytest.mark.parametrize("option, text", [("--phi-range", "0:1_80"), ("--phi-range", "٠:180"),
                                          ("--phi-range", "nan:180"), ("--y-window", "-inf:10"),
                                          ("--immersion", "0:٩٠")])
def test_pairs_outside_the_grammar_are_refused(model, capsys, option, text):
    extra = ["--forces", "--material", "al7075-t6"] if option == "--immersion" else []
    status, err = run(engage_argv(f"{option}={text}", *extra), capsys)
    assert status == 2 and len(err) == 1 and err[0].startswith(f"abm: error: {option}: expected ")
    assert err[0].endswith(f"got {text!r}")


@pytest.mark.parametrize("option, text, words", [
    ("--cl", "1_2", "expected CL indices such as 0,22,40, got '1_2'"),
    ("--cl", "١", "expected CL indices such as 0,22,40, got '١'"),
    ("--check", "0-1_0", "item 1 '0-1_0' is not a CL index or a range A-B (such as 0,27,80-100)"),
    ("--check", "2,٣", "item 2 '٣' is not a CL index or a range A-B (such as 0,27,80-100)"),
])
def test_cl_lists_outside_the_grammar_are_refused(model, capsys, option, text, words):
    """int() reads '1_2' as 12 and '٣' as 3."""
    status, err = run(["validate", "--stock", "stock.json", "--toolpath", "toolpath.csv", "--job", "job.json",
                       "--report", "rep", option, text], capsys)
    assert status == 2 and err == [f"abm: error: {option}: {words}"]
    assert not os.path.exists("rep")


@pytest.mark.parametrize("option", ["--tolerance", "--step", "--sweep-tolerance", "--grid"])
@pytest.mark.parametrize("text", ["nan", "inf", "1e300"])
def test_number_options_are_finite_and_bounded(model, capsys, option, text):
    status, err = run(engage_argv(option, text), capsys)
    assert status == 2 and len(err) == 1 and err[0].startswith(f"abm: error: {option}: must be ")


@pytest.mark.parametrize("text", ["1e-16", "1e-15", "0"])
def test_a_chordal_tolerance_below_a_nanometre_is_refused(tmp_path, capsys, text):
    program = tmp_path / "p.apt"
    program.write_text("UNITS/MM\nCUTTER/12\nGOTO/100,0,0\nCIRCLE/0,0,0,0,0,1,100\nGOTO/100,0,0\nFINI\n")
    status, err = run(["toolpath", str(program), "--tolerance", text], capsys)
    assert status == 2 and err == [f"abm: error: --tolerance: must be at least 1e-06 mm, got {float(text):g}"]
    with pytest.raises(InputError, match="chordal tolerance must be at least 1e-06 mm"):
        read_program(program, tolerance=float(text))


def test_the_step_angle_never_divides_by_zero():
    """1 − t/r rounded to 1 for t/r below 1e-16: the angle was 0 and the count a division by zero."""
    for radius, tolerance in [(1.0, 1e-16), (1e12, 1e-6), (1e9, 1e-3), (100.0, 1e-3)]:
        angle = step_angle(radius, tolerance)
        sagitta = 2.0 * radius * np.sin(0.25 * angle) ** 2  # r (1 − cos θ/2), without its cancellation
        assert angle > 0.0 and sagitta == pytest.approx(tolerance, rel=1e-6)


def test_an_empty_output_of_the_toolpath_command_is_refused(model, capsys):
    status, err = run(["toolpath", "toolpath.csv", "--out", ""], capsys)
    assert status == 2 and err == ["abm: error: --out: is empty; give a file name"]


# Nonsense the readers accepted.

def test_a_fractional_operation_number_is_refused(tmp_path):
    path = tmp_path / "P.csv"
    path.write_text("operation,x,y,z,i,j,k\n1,0,0,0,0,0,1\n1.5,1,0,0,0,0,1\n")
    with pytest.raises(InputError, match=rf"^{path}:3: column 'operation': 1.5 is not a whole number of at least 1"):
        load_toolpath(path, operation=1)


@pytest.mark.parametrize("text, message", [
    ("UNITS/MM\nCUTTER/12\nMULTAX/ON\nROTABL/1e12,CAXIS\nGOTO/0,0,0,0,0,1\nFINI\n",
     r":4: ROTABL: the table's angle 1e\+12° is beyond ±1e\+06°"),
    ("UNITS/MM\nCUTTER/12\nMULTAX/ON\nROTABL/600000,CAXIS,INCR\nROTABL/600000,CAXIS,INCR\nGOTO/0,0,0,0,0,1\nFINI\n",
     r":5: ROTABL: the table's angle 1.2e\+06° is beyond"),
])
def test_a_table_turned_by_1e12_degrees_is_refused(tmp_path, text, message):
    path = tmp_path / "p.apt"
    path.write_text(text)
    with pytest.raises(InputError, match=message):
        read_program(path)


def test_a_rotary_word_of_1e12_degrees_is_refused(tmp_path):
    from abm_workbench.formats.gcode.options import ReadOptions

    (tmp_path / "m.json").write_text('{"kinematics": "xyzac-trt"}')
    (tmp_path / "t.tbl").write_text("T1 P1 D12 Z30 ;flat\n")
    path = tmp_path / "p.ngc"
    path.write_text("G21 G90\nT1 M6\nG0 X0 Y0 Z5 A0 C0\nG1 X10 C1000000000000 F100\nM30\n")
    with pytest.raises(InputError, match=r"p.ngc:4: C1000000000000: the C axis at 1e\+12° is beyond ±1e\+06°"):
        read_program(path, options=ReadOptions(None, str(tmp_path / "t.tbl"), str(tmp_path / "m.json"), None))


# Arcs and curves within the 1e12 bound, interpolated without limit.

def test_a_circle_of_radius_1e9_is_refused_before_it_is_interpolated(tmp_path):
    """It took 159 s and 638 MB (62,831,853,072 CL points at the default step)."""
    path = tmp_path / "big.apt"
    path.write_text("UNITS/MM\nCUTTER/12\nGOTO/1e9,0,0\nCIRCLE/0,0,0,0,0,1,1e9\nGOTO/1e9,0,0\nFINI\n")
    started = time.perf_counter()
    with pytest.raises(InputError, match=r"big.apt:5: GOTO: the arc of the CIRCLE on line 4: interpolating it: "
                                         r"62,831,853,072 CL points"):
        read_program(path)
    assert time.perf_counter() - started < 5.0


def test_the_arcs_of_a_program_share_one_budget(tmp_path):
    """Each of 400 circles at step 0.01 mm is 62,832 CL points, within the budget alone; together they are not."""
    path = tmp_path / "many.apt"
    path.write_text("UNITS/MM\nCUTTER/12\nGOTO/100,0,0\n" + "CIRCLE/0,0,0,0,0,1,100\nGOTO/100,0,0\n" * 400 + "FINI\n")
    with pytest.raises(InputError, match="the program's arcs and curves so far"):
        read_program(path, step=0.01)
    one = tmp_path / "one.apt"
    one.write_text("UNITS/MM\nCUTTER/12\nGOTO/100,0,0\nCIRCLE/0,0,0,0,0,1,100\nGOTO/100,0,0\nFINI\n")
    assert len(read_program(one, step=0.01).operations[0].lines) == 1 + 62832  # the GOTO, the arc's points


def test_allowing_large_interpolates_beyond_the_budget():
    start, centre, axis = np.array([100.0, 0, 0]), np.zeros(3), np.array([0, 0, 1.0])
    with pytest.raises(TooLarge):
        arc_points(start, start, centre, axis, 1e-3, step=1e-4)
    with allowing_large():
        points, _ = arc_points(start, start, centre, axis, 1e-3, step=1e-4)
    assert len(points) == 6_283_186


def test_a_nurbs_of_1e11_mm_is_refused(tmp_path):
    path = tmp_path / "p.cls"
    path.write_text("MULTAX\nGOTO/0,0,0,0,0,1\nNURBS/3\nKNOT/0,0,0,1,1,1\nCNTRL/0,0,0\nCNTRL/1e11,1e11,0\n"
                    "CNTRL/2e11,0,0\nGOTO/2e11,0,0,0,0,1\n")
    with pytest.raises(InputError, match=r"p.cls:3: NURBS: interpolating it"):
        read_program(path)


# The in-process stock's sweep, counted before it is made.

def test_the_sweep_is_counted_as_the_engine_makes_it():
    """sweep_size counts the pieces and spans engine.inprocess.swept_pieces makes, exactly, and bounds
    its balls; on model test 3's program (five-axis moves, arcs, several tools)."""
    from abm_workbench.engine.inprocess import swept_pieces
    from abm_workbench.jobs import Job
    from abm_workbench.jobs.job import prepare
    from abm_workbench.jobs.inputs import program_moves
    from abm_workbench.jobs.run import sweep_size

    job = Job(os.path.join(MODEL_3, "stock.json"), os.path.join(MODEL_3, "program.apt"),
              os.path.join(MODEL_3, "job.json"), {}, operation=2)
    prepared = prepare(job)
    moves, _, _ = program_moves(prepared.hints.program, prepared.hints.operation, prepared.tool)
    for tolerance in (0.05, 0.5, 0.005):
        pieces, spans, balls = sweep_size(moves, tolerance)
        swept = swept_pieces(moves, tolerance)
        assert (pieces, spans) == (len(swept.c0), len(swept.span_first))
        assert len(swept.ball_chain) <= balls <= 2 * len(swept.ball_chain) + 10


@pytest.mark.parametrize("extra", [["--diameter", "1e12"], ["--diameter", "1e-300"], ["--flute-length", "1e12"],
                                   ["--sweep-tolerance", "1e-6"]])
def test_an_endless_sweep_is_refused_before_it_starts(model, capsys, extra):
    """These asked for 22.5 TiB, 44.9 TiB, an int64 overflow ('repeats may not contain negative values')."""
    started = time.perf_counter()
    status, err = run(engage_argv(*extra), capsys)
    assert status == 2 and len(err) == 1 and err[0].startswith("abm: error: toolpath.csv: the in-process stock "), err
    assert time.perf_counter() - started < 20.0 and not os.path.exists("out")


def test_a_run_of_too_many_instants_must_be_confirmed(model, capsys, monkeypatch):
    from abm_workbench import limits

    monkeypatch.setattr(limits, "LARGE_INSTANTS", 1000)
    assert run(engage_argv("--stock-model", "initial"), capsys)[0] == 0  # 53 x 7 = 371 instants
    status, err = run(engage_argv("--stock-model", "initial", "--phi-step", "1", out="big/R.csv"), capsys)
    assert status == 2 and err == ["abm: error: toolpath.csv: 53 CL points x 181 angles = 9,593 instants (more than "
                                   "the 1,000 a run takes without confirmation): give a larger --phi-step or a "
                                   "shorter --phi-range, or give --allow-large to run it anyway"]
    assert not os.path.exists("big")
    assert run(engage_argv("--stock-model", "initial", "--phi-step", "1", "--allow-large", out="big/R.csv"),
               capsys)[0] == 0


def test_a_zmap_run_of_too_many_edge_samples_must_be_confirmed(model, capsys, monkeypatch):
    """53 CL points x 7 angles x 151 points along the 30 mm flute at the 0.2 mm default edge step; the
    edge step is the grid's there, so the error names --grid; with --edge-step given, --edge-step."""
    from abm_workbench import limits

    monkeypatch.setattr(limits, "LARGE_ZMAP_SAMPLES", 50_000)
    zmap = ["--method", "zmap", "--stock-model", "initial"]
    status, err = run(engage_argv(*zmap), capsys)
    assert status == 2 and err == ["abm: error: --grid: the Z-map would sample 56,021 edge points (53 CL points x 7 "
                                   "angles x 151 along the edge) (the edge step is the grid's unless --edge-step is "
                                   "given) (more than the 50,000 a run takes without confirmation): give a larger "
                                   "--grid or --phi-step, or give --allow-large to run it anyway"]
    status, err = run(engage_argv(*zmap, "--edge-step", "0.25"), capsys)
    assert status == 0, err  # 121 along the edge: 44,891
    status, err = run(engage_argv(*zmap, "--edge-step", "0.15"), capsys)
    assert status == 2 and err[0].startswith("abm: error: --edge-step: the Z-map would sample 74,571 edge points")
    assert run(engage_argv(*zmap, "--allow-large"), capsys)[0] == 0


@pytest.mark.parametrize("extra, message", [
    (["--grid", "1e-3"], "--grid: 0.001 mm gives the stock 3,900,000,000 Z-map cells, more than the Z-map holds"),
    (["--edge-step", "1e-5"], "--edge-step: an edge step of 1e-05 mm samples the 30 mm flute at 3,000,001 points, "
                              "7 angles x 3,000,001 = 21,000,007 per CL point, more than the Z-map takes"),
])
def test_a_zmap_beyond_what_the_engine_takes_is_refused_before_any_output(model, capsys, extra, message):
    status, err = run(engage_argv("--method", "zmap", "--stock-model", "initial", *extra, "--allow-large"), capsys)
    assert status == 2 and len(err) == 1 and err[0].startswith(f"abm: error: {message}"), err
    assert not os.path.exists("out")


def test_a_run_beyond_the_memory_is_refused_even_when_allowed(model, capsys, monkeypatch):
    from abm_workbench import limits

    monkeypatch.setattr(limits, "available_memory", lambda: 100 << 20)
    for extra in ([], ["--allow-large"]):
        status, err = run(engage_argv("--stock-model", "initial", *extra), capsys)
        assert status == 2 and "of memory, and this process may use 100 MiB" in err[0]


# Outputs and inputs that are no files.

def test_outputs_that_are_fifos_sockets_or_links_are_refused(tmp_path):
    fifo = tmp_path / "fifo.csv"
    os.mkfifo(fifo)
    with pytest.raises(InputError, match="is a FIFO .* it would be replaced by the output"):
        check_output_path(fifo)
    link = tmp_path / "link.csv"
    os.symlink("elsewhere.csv", link)
    with pytest.raises(InputError, match=r"is a symbolic link \(to elsewhere.csv\)"):
        check_output_path(link)
    with socket.socket(socket.AF_UNIX) as server:
        server.bind(str(tmp_path / "s.csv"))
        with pytest.raises(InputError, match="is a socket"):
            check_output_path(tmp_path / "s.csv")


def test_reading_a_fifo_or_dev_zero_is_refused_without_waiting(tmp_path):
    """A FIFO hung the reader (nobody writes it); /dev/zero was read until memory ran out."""
    fifo = tmp_path / "p.csv"
    os.mkfifo(fifo)
    found = []
    reader = threading.Thread(target=lambda: found.append(pytest.raises(InputError, read_text, fifo)), daemon=True)
    reader.start()
    reader.join(10.0)
    if reader.is_alive():  # unblock it: open the FIFO for writing
        with open(fifo, "w"):
            pass
        pytest.fail("reading a FIFO blocked")
    assert "is a FIFO (named pipe), not a file" in str(found[0].value)
    with pytest.raises(InputError, match="/dev/zero: is a character device, not a file"):
        read_bytes("/dev/zero")
    with pytest.raises(InputError, match="is a folder, not a file"):
        read_bytes(tmp_path)


def test_a_file_too_large_for_the_memory_is_refused_unread(tmp_path, monkeypatch):
    from abm_workbench import limits

    path = tmp_path / "big.csv"
    with open(path, "wb") as file:
        file.truncate(200 << 20)  # 200 MiB of holes: nothing written, nothing read
    monkeypatch.setattr(limits, "available_memory", lambda: 1 << 30)
    with pytest.raises(InputError, match=r"big.csv: reading its 209,715,200 bytes would need about 3.12 GiB"):
        read_bytes(path)


# Worker counts.

def test_worker_counts_are_bounded_by_the_cores():
    cores = len(os.sched_getaffinity(0))
    assert worker_count(100000) == cores and worker_count(0) == cores and worker_count(1) == 1
    with pytest.raises(ValueError):
        worker_count(-1)


# The report folder.

def test_a_report_folder_with_a_users_files_is_refused_and_kept(model, capsys):
    os.mkdir("rep")
    for name, text in (("index.html", "<p>older</p>"), ("comparison.csv", "cl\n"), ("thesis.tex", "mine")):
        (model / "rep" / name).write_text(text)
    status, err = run(["validate", "--stock", "stock.json", "--toolpath", "toolpath.csv", "--job", "job.json",
                       "--phi-step", "60", "--check", "0", "--report", "rep"], capsys)
    assert status == 2 and err == ["abm: error: rep: folder holds 'thesis.tex', which no report writes; an older "
                                   "report there is replaced as a whole, which would delete it: choose a new or empty "
                                   "folder, or move it away"]
    assert sorted(os.listdir("rep")) == ["comparison.csv", "index.html", "thesis.tex"]


# The results readers.

def _results(tmp_path):
    """A real run's results: (R.csv, R.npz)."""
    base = ["engage", "--stock", os.path.join(MODEL, "stock.json"), "--toolpath", os.path.join(MODEL, "toolpath.csv"),
            "--job", os.path.join(MODEL, "job.json"), "--phi-step", "30", "--stock-model", "initial"]
    assert cli.main(base + ["--out", str(tmp_path / "R.csv")]) == 0
    assert cli.main(base + ["--out", str(tmp_path / "R.npz")]) == 0
    return tmp_path / "R.csv", tmp_path / "R.npz"


@pytest.mark.parametrize("change, message", [
    (lambda lines: lines[:1] + ["0,0," + "1" * 5_000] + lines[2:], r":2: a field of 5,000 characters; at most 100"),
    (lambda lines: lines[:1] + ["9" * 40 + lines[1][1:]] + lines[2:], r":2: column 'cl': '9{40}.*' is not a valid int"),
    (lambda lines: lines[:1] + ["x" * 20_000] + lines[2:], r":2: a line of 20,000 characters; at most 10,000"),
])
def test_the_results_csv_reader_refuses_fields_too_long(tmp_path, capsys, change, message):
    """A 4 MB file with one long field made a table of 4.2 GB; a 40-digit integer an OverflowError."""
    csv_path, _ = _results(tmp_path)
    capsys.readouterr()
    lines = csv_path.read_text().splitlines()
    csv_path.write_text("\n".join(change(lines)) + "\n")
    with pytest.raises(InputError, match=message):
        read_csv_results(csv_path)


def _npz_members(path):
    with zipfile.ZipFile(path) as archive:
        return {info.filename: archive.read(info) for info in archive.infolist()}


def _write_members(path, members, compression=zipfile.ZIP_STORED):
    with zipfile.ZipFile(path, "w", compression) as archive:
        for name, data in members.items():
            archive.writestr(name, data)


def _npy(header_text, body=b""):
    """An .npy member of version 1.0 with the header dict `header_text` (padded as numpy pads)."""
    header = header_text.encode("latin1")
    padding = 64 - (10 + len(header) + 1) % 64
    header += b" " * padding + b"\n"
    return b"\x93NUMPY\x01\x00" + len(header).to_bytes(2, "little") + header + body


@pytest.mark.parametrize("label", ["huge shape", "overflowing shape", "bad header", "object dtype", "compressed",
                                   "short body", "2-D shape"])
def test_the_results_archive_reader_refuses_what_it_cannot_have_written(tmp_path, capsys, label):
    """A header claiming 10^15 rows made numpy allocate (MemoryError), a malformed one raised TokenError,
    dimensions past int64 OverflowError; a compressed member could expand without bound."""
    _, npz_path = _results(tmp_path)
    capsys.readouterr()
    members = _npz_members(npz_path)
    compression = zipfile.ZIP_STORED
    if label == "huge shape":
        members["length.npy"] = _npy("{'descr': '<f8', 'fortran_order': False, 'shape': (10**15,), }")
    elif label == "overflowing shape":
        members["length.npy"] = _npy("{'descr': '<f8', 'fortran_order': False, 'shape': (99999999999999999999999,), }")
    elif label == "bad header":
        members["length.npy"] = _npy("{'descr': '<f8', 'fortran_order': False, 'shape': (3,)\"\"\"")
    elif label == "object dtype":
        members["length.npy"] = _npy("{'descr': '|O', 'fortran_order': False, 'shape': (3,), }", b"\0" * 24)
    elif label == "compressed":
        compression = zipfile.ZIP_DEFLATED
    elif label == "short body":
        members["length.npy"] = members["length.npy"][:-8]
    else:
        members["length.npy"] = _npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 371), }", b"\0" * 2968)
    _write_members(npz_path, members, compression)
    with pytest.raises(InputError, match=rf"^{npz_path}: not a results archive"):
        read_npz_results(npz_path)


def test_the_results_archive_reader_still_reads_what_numpy_writes(tmp_path):
    """The archive rewritten by numpy's own savez (stored): read as before."""
    _, npz_path = _results(tmp_path)
    want = read_npz_results(npz_path)
    with np.load(npz_path) as archive:
        arrays = {key: archive[key] for key in archive.files}
    again = tmp_path / "again.npz"
    np.savez(again, **arrays)
    got = read_npz_results(again)
    assert sorted(got) == sorted(want)
    for key in want:
        np.testing.assert_array_equal(got[key], want[key])


# The Python API.

@pytest.fixture(scope="module")
def api():
    stock = load_staircase(os.path.join(MODEL, "stock.json"))
    path = load_toolpath(os.path.join(MODEL, "toolpath.csv"))
    return stock, Tool(12, 2, 30), path, CutSettings(0.1, 10, 0, 180, 30)


@pytest.mark.parametrize("function", [engage, flute_engagement, engage_parallel])
@pytest.mark.parametrize("position, name", [(0, "stock"), (1, "tool"), (2, "toolpath"), (3, "settings")])
def test_wrong_argument_types_raise_type_error_naming_the_argument(api, function, position, name):
    """They raised AttributeError ('str' object has no attribute 'x_min')."""
    arguments = list(api)
    arguments[position] = "stock.json" if position == 0 else None
    with pytest.raises(TypeError, match=rf"^{name} must be a "):
        function(*arguments)


@pytest.mark.parametrize("value", ["12", None, [12], {"d": 12}, 12j])
def test_a_tool_size_that_is_no_number_is_a_type_error(value):
    with pytest.raises(TypeError, match=r"^diameter must be a number, got "):
        Tool(value, 2, 30)
    with pytest.raises(NotANumber):  # also a ValueError, as every bad value of the engine
        CutSettings(value)


def test_a_1e300_mm_tool_is_refused_not_computed_as_zeros():
    with pytest.raises(ValueError, match=r"diameter must be at most 1e\+12 in size, got 1e\+300"):
        Tool(1e300, 2, 30)
    with pytest.raises(ValueError, match=r"flute_length must be at most 1e\+12"):
        Tool(12, 2, 1e300)
    assert Tool(np.float32(12), np.int64(2), 30.0).flutes == 2


def test_toolpath_arrays_of_no_numbers_are_type_errors():
    with pytest.raises(TypeError, match="cl must be an array of numbers"):
        Toolpath("abc", [0], [0])
    with pytest.raises(WrongArgument, match="coefficients must be Coefficients"):
        from abm_workbench.forces import pass_forces

        stock = load_staircase(os.path.join(MODEL, "stock.json"))
        pass_forces(stock, Tool(12, 2, 30), load_toolpath(os.path.join(MODEL, "toolpath.csv")),
                    CutSettings(0.1), "al7075-t6")
