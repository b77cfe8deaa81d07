"""Passes in chunks of CL points, on local processes and on a loopback Dask cluster: the same results
as one engine call on the whole pass, bit for bit (NaNs in the same places), and the same CSV bytes."""

import dataclasses
import json
import os
import socket

import numpy as np
import pytest
from hypothesis import given, settings

from abm_workbench import cli, parallel
from abm_workbench.jobs import run as runs
from abm_workbench.engine import CutSettings, Engagement, Tool, engage
from abm_workbench.formats.staircase_json import load_staircase
from abm_workbench.formats.toolpath_csv import load_toolpath

from .strategies import engine_inputs, jobs

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODELS = os.path.join(ROOT, "resources", "models")


def model_job(number):
    """(stock, tool, toolpath, settings) of bundled model test `number`."""
    folder = os.path.join(MODELS, f"model_test_{number}")
    with open(os.path.join(folder, "job.json")) as handle:
        job = json.load(handle)
    return (load_staircase(os.path.join(folder, "stock.json")), Tool(job["diameter"], job["flutes"], job["flute_length"]),
            load_toolpath(os.path.join(folder, "toolpath.csv")),
            CutSettings(job["feed_per_tooth"], job["inclination"], *job["phi_range"], job["phi_step"]))


def assert_identical(got, want):
    """Every field of two Engagements equal bit for bit, dtype and shape included, NaN equal to NaN."""
    for field in dataclasses.fields(Engagement):
        a, b = getattr(got, field.name), getattr(want, field.name)
        assert a.dtype == b.dtype and a.shape == b.shape, field.name
        assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), field.name


@pytest.fixture(scope="module")
def model_1():
    return model_job(1)


@pytest.mark.parametrize("workers", [1, 2])
def test_model_test_1_in_chunks_is_the_single_call(model_1, workers):
    progress = []
    got = parallel.engage_parallel(*model_1, workers=workers, chunk_instants=2000,
                                   progress=lambda done, total: progress.append((done, total)))
    assert_identical(got, engage(*model_1))
    done = [done for done, _ in progress]  # chunks of 11, 11, 11, 11, 9 CL points, in the order they finish
    assert len(done) == 5 and done[-1] == 53 and np.all(np.diff(done) > 0) and {t for _, t in progress} == {53}
    assert set(np.diff([0] + done)) <= {9, 11}


@settings(max_examples=6)
@given(jobs(max_points=30))
def test_random_staircase_on_two_processes(job):
    stock, tool, toolpath, cut = engine_inputs(job)
    p = cut.phi.size
    got = parallel.engage_parallel(stock, tool, toolpath, cut, workers=2, chunk_instants=4 * p)
    assert_identical(got, engage(stock, tool, toolpath, cut))


def test_many_jobs_share_the_workers(model_1):
    second = model_job(2)
    got = parallel.engage_jobs([model_1, second, model_1], workers=2, chunk_instants=5000)
    for engagement, job in zip(got, [model_1, second, model_1]):
        assert_identical(engagement, engage(*job))


def test_chunks_are_whole_engine_chunks_and_cover_the_pass():
    ranges = parallel.cl_ranges(53, 181, chunk_instants=2000)
    assert ranges == [(0, 11), (11, 22), (22, 33), (33, 44), (44, 53)]
    assert parallel.cl_ranges(3, 181, chunk_instants=10) == [(0, 1), (1, 2), (2, 3)]
    assert parallel.cl_ranges(10, 181) == [(0, 10)]


@pytest.mark.parametrize("workers", [-1, 1.5, True, "2"])
def test_bad_worker_counts(workers):
    with pytest.raises(ValueError, match="workers must be a whole number >= 0"):
        parallel.worker_count(workers)


def test_zero_workers_means_every_core():
    assert parallel.worker_count(0) == len(os.sched_getaffinity(0))


def failing_on_cl_12(job, start, stop):
    """A task that fails on the chunk holding CL point 12."""
    if start <= 12 < stop:
        raise ZeroDivisionError("boom")
    return stop - start


@pytest.mark.parametrize("workers", [1, 2])
def test_a_worker_error_names_its_cl_range(model_1, workers):
    with pytest.raises(parallel.ChunkError, match=r"^CL points 11\.\.21: ZeroDivisionError: boom$") as error:
        list(parallel.map_chunks(failing_on_cl_12, [model_1], workers=workers, chunk_instants=2000))
    assert (error.value.job, error.value.start, error.value.stop) == (0, 11, 22)
    assert isinstance(error.value.__cause__, ZeroDivisionError)
    with pytest.raises(parallel.ChunkError, match=r"^job [01], CL points 11\.\.21: ") as error:  # the first to fail
        list(parallel.map_chunks(failing_on_cl_12, [model_1, model_1], workers=workers, chunk_instants=2000))
    assert str(error.value).startswith(f"job {error.value.job}, ")


def closed_port():
    """A loopback TCP port nothing listens on (bound, then released)."""
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


def test_an_unreachable_scheduler_is_named(model_1):
    address = f"tcp://127.0.0.1:{closed_port()}"
    with pytest.raises(parallel.SchedulerError, match=f"Dask scheduler {address}: no answer within 3 s"):
        parallel.engage_parallel(*model_1, scheduler=address)


@pytest.fixture(scope="module")
def cluster():
    """A Dask cluster on loopback: two worker processes, one thread each, no dashboard."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as local:
        yield local.scheduler_address


def test_dask_cluster_gives_the_single_call(model_1, cluster):
    got = parallel.engage_jobs([model_1, model_job(2)], scheduler=cluster, chunk_instants=3000)
    assert_identical(got[0], engage(*model_1))
    assert_identical(got[1], engage(*model_job(2)))


def engage_argv(out, *extra):
    """The engage command on model test 1 writing `out` (and its summary)."""
    folder = os.path.join(MODELS, "model_test_1")
    return ["engage", "--job", os.path.join(folder, "job.json"), "--stock", os.path.join(folder, "stock.json"),
            "--toolpath", os.path.join(folder, "toolpath.csv"), "--out", str(out), *extra]


def read_outputs(out):
    """Bytes of a results CSV and its summary."""
    return [open(path, "rb").read() for path in (out, str(out)[:-4] + ".summary.csv")]


@pytest.fixture(scope="module")
def single_process_csv(tmp_path_factory):
    """Bytes of model test 1's results and summary CSV from one process (the default)."""
    out = tmp_path_factory.mktemp("single") / "R.csv"
    assert cli.main(engage_argv(out)) == 0
    return read_outputs(out)


def test_cli_on_two_processes_writes_the_same_bytes(tmp_path, capsys, single_process_csv, monkeypatch):
    monkeypatch.setattr(parallel, "CHUNK_INSTANTS", 2000)
    out = tmp_path / "R.csv"
    assert cli.main(engage_argv(out, "--workers", "2", "--plot", str(tmp_path / "R.png"))) == 0
    assert "on 2 processes" in capsys.readouterr().out
    assert read_outputs(out) == single_process_csv and os.path.getsize(tmp_path / "R.png") > 0


def test_cli_on_the_dask_cluster_writes_the_same_bytes(tmp_path, capsys, single_process_csv, cluster):
    out = tmp_path / "R.csv"
    assert cli.main(engage_argv(out, "--scheduler", cluster)) == 0
    assert f"on the Dask cluster at {cluster}" in capsys.readouterr().out
    assert read_outputs(out) == single_process_csv


@pytest.mark.parametrize(
    "extra, message",
    [
        (["--workers", "-2"], "--workers: must be 0 (all cores) or a positive number of processes, got -2"),
        (["--scheduler", "localhost:8786"], "--scheduler: expected a Dask scheduler address such as tcp://"),
        (["--method", "zmap", "--workers", "2"], "--workers: applies to the abm method"),
        (["--method", "zmap", "--scheduler", "tcp://127.0.0.1:8786"], "--scheduler: applies to the abm method"),
    ],
)
def test_cli_bad_parallel_options(tmp_path, capsys, extra, message):
    out = tmp_path / "new" / "R.csv"
    assert cli.main(engage_argv(out, *extra)) == 2
    _, err = capsys.readouterr()
    assert err.startswith(f"abm: error: {message}") and err.count("\n") == 1
    assert os.listdir(tmp_path) == []


def test_cli_unreachable_scheduler_leaves_nothing(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(parallel, "SCHEDULER_TIMEOUT", 1.0)
    address = f"tcp://127.0.0.1:{closed_port()}"
    out = tmp_path / "new" / "R.csv"
    (tmp_path / "old.csv").write_text("old")
    assert cli.main(engage_argv(tmp_path / "old.csv", "--scheduler", address)) == 2
    assert cli.main(engage_argv(out, "--scheduler", address)) == 2
    _, err = capsys.readouterr()
    assert err.count(f"abm: error: Dask scheduler {address}: no answer within 1 s") == 2
    assert os.listdir(tmp_path) == ["old.csv"] and (tmp_path / "old.csv").read_text() == "old"


def test_cli_no_engagement_found_while_streaming_removes_new_folders(tmp_path, capsys):
    path = tmp_path / "above.csv"
    path.write_text("x,y,z,theta_a,theta_b\n10,0,60,0,0\n20,0,60,0,0\n")
    argv = engage_argv(tmp_path / "new" / "deeper" / "R.csv")
    argv[argv.index("--toolpath") + 1] = str(path)
    assert cli.main(argv) == 2
    assert "the tool never touches the stock" in capsys.readouterr().err
    assert os.listdir(tmp_path) == ["above.csv"]


def test_cli_engine_failure_names_the_cl_range_and_leaves_nothing(tmp_path, capsys, monkeypatch):
    def broken(*args, **kwargs):
        raise FloatingPointError("overflow")

    monkeypatch.setattr(runs, "engage_stock", broken)
    monkeypatch.setattr(runs, "engage_in_process", broken)
    assert cli.main(engage_argv(tmp_path / "new" / "R.csv")) == 1
    assert capsys.readouterr().err == "abm: error: CL points 0..52: FloatingPointError: overflow\n"
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("helix", ["0", "30"])
def test_cli_forces_in_chunks_are_the_whole_pass_forces(tmp_path, capsys, model_1, monkeypatch, helix):
    """Forces computed chunk by chunk on 2 processes (straight and helical flutes) are the forces
    of one pass_forces call over the whole pass, and the force plot is written."""
    from abm_workbench.forces import FULL_SLOT, material, pass_forces
    from abm_workbench.formats.results_csv import read_results

    monkeypatch.setattr(parallel, "CHUNK_INSTANTS", 2000)
    out = tmp_path / "R.csv"
    argv = engage_argv(out, "--workers", "2", "--forces", "--material", "al7075-t6", "--helix", helix,
                       "--plot", str(tmp_path / "R.png"))
    assert cli.main(argv) == 0
    assert "peak force" in capsys.readouterr().out
    assert os.path.getsize(tmp_path / "R.forces.png") > 0
    stock, tool, toolpath, settings = model_1
    whole = pass_forces(stock, dataclasses.replace(tool, helix=float(helix)), toolpath, settings,
                        material("al7075-t6"), immersion=FULL_SLOT)
    rows = read_results(out)
    xyz = whole.xyz.reshape(-1, 3)
    for axis, name in enumerate(("fx", "fy", "fz")):
        np.testing.assert_allclose(rows[name], xyz[:, axis], rtol=0, atol=1e-9)
    np.testing.assert_allclose(rows["torque"], whole.torque.reshape(-1), rtol=0, atol=1e-9)
