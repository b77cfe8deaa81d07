"""engage --out R.npz: the same columns as the CSV, the engine's doubles bit for bit, all or nothing, and
a reader that refuses what it did not write."""

import os
import zipfile

import numpy as np
import pytest

from abm_workbench import cli
from abm_workbench.engine import CASES, SURFACES, engage, segment_letter
from abm_workbench.engine.stocks import engage_stock
from abm_workbench.errors import InputError
from abm_workbench.features.stored import read_engagement, read_forces
from abm_workbench.formats import replacing, results_csv, results_npz
from abm_workbench.formats.results_columns import chunk_columns
from abm_workbench.parallel import toolpath_part

from .test_parallel import MODELS, ROOT, assert_identical, model_job

MODEL = os.path.join(MODELS, "model_test_1")
# Uneven chunks of model test 1's 53 CL points, one of a single CL point.
BOUNDS = [0, 7, 8, 30, 53]
MATERIAL = "al7075-t6"


def run(tmp_path, out, *extra):
    """Exit status of engage on model test 1's JSON job writing `out` in tmp_path."""
    return cli.main(["engage", "--stock", os.path.join(MODEL, "stock.json"), "--toolpath",
                     os.path.join(MODEL, "toolpath.csv"), "--job", os.path.join(MODEL, "job.json"),
                     "--out", str(tmp_path / out), *extra])


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """Folder with model test 1 engaged to R.npz and R.csv, against the in-process stock (default) and
    with forces against the stock as given (F.npz, F.csv)."""
    folder = tmp_path_factory.mktemp("written")
    for out in ("R.npz", "R.csv"):
        assert run(folder, out) == 0
    for out in ("F.npz", "F.csv"):
        assert run(folder, out, "--forces", "--material", MATERIAL, "--stock-model", "initial") == 0
    return folder


@pytest.mark.parametrize("stem", ["R", "F"])
@pytest.mark.parametrize("summary", [False, True])
def test_npz_holds_the_csv_columns(written, stem, summary):
    """Same names in the same order, same rows; text and integers equal, every float the CSV's once
    rounded to its 10 decimals (the CSV rounds, the archive keeps the doubles), NaN where the CSV is empty."""
    csv = results_csv.read_results(written / f"{stem}{'.summary' if summary else ''}.csv")
    npz = results_npz.read_results(written / f"{stem}.npz", summary=summary)
    assert list(npz) == list(csv)
    extra = {("R", False): "length_initial", ("R", True): "changed", ("F", False): "fx", ("F", True): "peak_force"}
    assert extra[stem, summary] in npz
    for name, values in csv.items():
        got = npz[name]
        assert got.dtype.kind == values.dtype.kind and got.shape == values.shape, name
        if values.dtype.kind == "f":
            got = np.round(got, 10) + 0.0
        assert np.array_equal(got, values, equal_nan=values.dtype.kind == "f"), name


def test_npz_holds_the_engines_doubles(written):
    """Against the stock as given the archive's columns are the engine's arrays bit for bit, and the
    Engagement read back (features.stored) is the engine's."""
    stock, tool, toolpath, settings = model_job(1)
    engagement = engage_stock(stock, tool, toolpath, settings)
    columns = results_npz.read_results(written / "F.npz")
    m, p = engagement.shape
    assert np.array_equal(columns["cl"], np.repeat(np.arange(m), p))
    for name in ("lep_l", "uep_l", "length", "area"):
        assert np.array_equal(columns[name], getattr(engagement, name).ravel(), equal_nan=True), name
    assert np.array_equal(columns["uep_z"], engagement.uep_xyz[..., 2].ravel(), equal_nan=True)
    assert columns["uep_surface"].tolist() == [SURFACES[code] for code in engagement.uep_surface.ravel()]
    assert columns["case"].tolist() == [CASES[code] for code in engagement.case.ravel()]
    assert columns["segment"].tolist() == ["" if s < 0 else segment_letter(s) for s in engagement.segment.ravel()]
    assert_identical(read_engagement(written / "F.npz"), engagement)


def test_forces_read_back_from_the_archive_are_the_csvs_unrounded(written):
    from_npz, from_csv = read_forces(written / "F.npz", 0.1), read_forces(written / "F.csv", 0.1)
    assert from_npz.shape == from_csv.shape == (53, 181)
    for name in ("xyz", "torque", "power"):
        assert np.array_equal(np.round(getattr(from_npz, name), 10) + 0.0, getattr(from_csv, name)), name
    assert read_forces(written / "R.npz", 0.1) is None


def test_chunks_write_the_same_archive_as_the_whole_pass(tmp_path):
    stock, tool, toolpath, settings = model_job(1)
    whole = engage(stock, tool, toolpath, settings)
    rows = len(toolpath) * settings.phi.size
    assert results_npz.write_chunks([chunk_columns(whole, 0, toolpath=toolpath)], tmp_path / "whole.npz", rows) == 1
    parts = []
    for start, stop in zip(BOUNDS[:-1], BOUNDS[1:]):
        part = toolpath_part(toolpath, start, stop)
        parts.append(chunk_columns(engage(stock, tool, part, settings), start, toolpath=part))
    assert results_npz.write_chunks(iter(parts), tmp_path / "R.npz", rows) == 4
    for summary in (False, True):
        a = results_npz.read_results(tmp_path / "whole.npz", summary)
        b = results_npz.read_results(tmp_path / "R.npz", summary)
        assert list(a) == list(b)
        for name in a:
            assert np.array_equal(a[name], b[name], equal_nan=a[name].dtype.kind == "f"), name
    assert sorted(os.listdir(tmp_path)) == ["R.npz", "whole.npz"]  # no scratch folder left


def test_an_error_in_a_late_chunk_leaves_no_file(tmp_path):
    stock, tool, toolpath, settings = model_job(1)
    (tmp_path / "R.npz").write_bytes(b"old")

    def failing():
        for start, stop in zip(BOUNDS[:2], BOUNDS[1:3]):
            yield chunk_columns(engage(stock, tool, toolpath_part(toolpath, start, stop), settings), start)
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        with replacing(tmp_path / "R.npz") as temporaries:
            results_npz.write_chunks(failing(), temporaries[0], len(toolpath) * settings.phi.size)
    assert os.listdir(tmp_path) == ["R.npz"] and (tmp_path / "R.npz").read_bytes() == b"old"


def test_a_failed_run_leaves_no_npz(tmp_path, capsys):
    """A pass whose tool never touches the stock fails after its columns were streamed: nothing is left."""
    lifted = tmp_path / "lifted.csv"
    lines = open(os.path.join(MODEL, "toolpath.csv")).read().splitlines()
    rows = [line.split(",") for line in lines[1:]]
    lifted.write_text("\n".join(["x,y,z,i,j,k"] + [",".join(row[:2] + [str(float(row[2]) + 100.0)] + row[3:6])
                                              for row in rows]) + "\n")
    status = cli.main(["engage", "--stock", os.path.join(MODEL, "stock.json"), "--toolpath", str(lifted),
                       "--job", os.path.join(MODEL, "job.json"), "--out", str(tmp_path / "out" / "R.npz")])
    assert status == 2 and "never touches the stock" in capsys.readouterr().err
    assert os.listdir(tmp_path) == ["lifted.csv"]


@pytest.fixture(scope="module")
def members(written):
    """Every member of a good archive, key -> array."""
    with np.load(written / "R.npz", allow_pickle=False) as archive:
        return {key: archive[key] for key in archive.files}


def _saved(path, arrays):
    np.savez(path, **arrays)
    return path


def _single(path, array):
    with open(path, "wb") as handle:
        np.save(handle, array)


def _without(members, key):
    return {name: value for name, value in members.items() if name != key}


BAD = {
    "text": (lambda path, members: path.write_text("cl,phi_deg\n0,1.0\n"), "an .npz file is a zip file"),
    "one array": (lambda path, members: _single(path, members["length"]), "an .npz file is a zip file"),
    "pickled": (lambda path, members: _saved(path, {**members, "length": np.array([{"a": 1}] * 3, dtype=object)}),
                "pickled objects"),
    "truncated": (None, "damaged"),
    "no format": (lambda path, members: _saved(path, _without(members, "format")), "no 'format' member"),
    "missing column": (lambda path, members: _saved(path, _without(members, "uep_l")), "no array 'uep_l'"),
    "missing summary": (lambda path, members: _saved(path, _without(members, "summary/depth_of_cut")),
                        "no array 'summary/depth_of_cut'"),
    "unknown column": (lambda path, members: _saved(path, {**members, "extra": members["length"]}),
                       "unknown array 'extra'"),
    "float32": (lambda path, members: _saved(path, {**members, "area": members["area"].astype(np.float32)}),
                "array 'area': float32"),
    "short": (lambda path, members: _saved(path, {**members, "h": members["h"][:-1]}), "array 'h': float64 of shape"),
    "2-D": (lambda path, members: _saved(path, {**members, "summary/phi_end": members["summary/phi_end"][:, None]}),
            "array 'summary/phi_end'"),
    "code": (lambda path, members: _saved(path, {**members, "case": np.full_like(members["case"], len(CASES))}),
             f"code {len(CASES)} has no label"),
    "no labels": (lambda path, members: _saved(path, _without(members, "labels/segment")), "no labels"),
    "huge": (lambda path, members: _saved(path, {**members, "lep_x": np.full_like(members["lep_x"], np.inf)}),
             "array 'lep_x': row 0: inf is too large"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_a_file_that_is_not_a_results_archive_is_refused(written, members, tmp_path, case):
    make, message = BAD[case]
    path = tmp_path / "bad.npz"
    if make is None:
        whole = (written / "R.npz").read_bytes()
        path.write_bytes(whole[: len(whole) // 2])
    else:
        make(path, members)
    with pytest.raises(InputError, match=message) as error:
        results_npz.read_results(path)
    assert str(error.value).startswith(f"{path}: ")
    with pytest.raises(InputError, match=message):
        read_engagement(path)


def test_a_byte_changed_in_a_column_is_refused_as_damaged(written, tmp_path):
    """Each member's CRC-32 is checked as it is read: one byte changed in the middle of the data is found."""
    data = bytearray((written / "R.npz").read_bytes())
    with zipfile.ZipFile(written / "R.npz") as archive:
        info = archive.getinfo("length.npy")
    data[info.header_offset + 30 + len(info.filename) + info.file_size // 2] ^= 0x40
    path = tmp_path / "bad.npz"
    path.write_bytes(bytes(data))
    with pytest.raises(InputError, match=f"^{path}: not a results archive: damaged .*CRC"):
        results_npz.read_results(path)


def test_the_archive_is_stored_uncompressed_with_every_column(written):
    with zipfile.ZipFile(written / "R.npz") as archive:
        infos = archive.infolist()
    assert {info.compress_type for info in infos} == {zipfile.ZIP_STORED}
    names = {info.filename for info in infos}
    assert {f"{name}.npy" for name in results_csv.RESULT_COLUMNS} <= names
    assert {f"summary/{name}.npy" for name in results_csv.SUMMARY_COLUMNS} <= names
    assert {"format.npy", "labels/case.npy", "labels/segment.npy"} <= names


def test_the_longest_output_name_allowed_is_written(tmp_path):
    """The scratch folder's name does not grow with the output's: a name at the length limit works."""
    from abm_workbench.formats import STAGING_EXTRA

    stem = "r" * (os.pathconf(tmp_path, "PC_NAME_MAX") - STAGING_EXTRA - len(".npz"))
    assert run(tmp_path, stem + ".npz", "--stock-model", "initial") == 0
    assert os.listdir(tmp_path) == [stem + ".npz"]


def test_a_run_stopped_while_columns_stream_leaves_nothing(tmp_path):
    """SIGTERM once the staged archive holds columns (mid-stream, ~10⁶ instants): no archive, no staged
    or temporary file, no folder made, exit status 128 + 15."""
    import signal
    import subprocess
    import sys
    import time

    out = tmp_path / "made" / "R.npz"
    command = [sys.executable, "-m", "abm_workbench", "engage", "--stock", os.path.join(MODEL, "stock.json"),
               "--toolpath", os.path.join(MODEL, "toolpath.csv"), "--job", os.path.join(MODEL, "job.json"),
               "--stock-model", "initial", "--phi-step", "0.01", "--out", str(out)]
    child = subprocess.Popen(command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True)

    def streaming():  # the staged archive holds the first chunk's columns
        return any(entry.name.startswith(".R.npz.") and entry.stat().st_size for entry in os.scandir(out.parent))

    deadline = time.monotonic() + 300.0
    while not (out.parent.is_dir() and streaming()):
        assert child.poll() is None, "the run ended before its columns were seen"
        assert time.monotonic() < deadline
        time.sleep(0.02)
    child.send_signal(signal.SIGTERM)
    _, err = child.communicate(timeout=300)
    assert child.returncode == 128 + signal.SIGTERM and "Traceback" not in err
    assert os.listdir(tmp_path) == []
