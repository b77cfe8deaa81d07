"""validate(..., scheduler=…): the boolean reference on a Dask cluster (a loopback LocalCluster of 2
worker processes, each its own FreeCAD) is the reference of one process, bit for bit; progress once
per CL point; a malformed or silent scheduler is an InputError naming it; the command line's
``validate --scheduler`` writes the tables of one process byte for byte."""

import os
import subprocess
import sys

import numpy as np
import pytest

from abm_workbench.cad.freecad_env import FreeCAD
from abm_workbench.engine import Toolpath
from abm_workbench.errors import InputError
from abm_workbench.validation import validate

from .test_validate_interrupt import short_pass  # noqa: F401  (model test 1's first CL points as a CSV file)
from .test_validate_workers import MODEL, ROOT, model, same  # noqa: F401  (the model fixture of model test 1)

distributed = pytest.importorskip("distributed", reason="dask.distributed is not installed")


@pytest.fixture(scope="module")
def cluster():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as local:
        yield local


def test_a_dask_cluster_gives_the_reference_of_one_process(model, cluster):  # noqa: F811
    solid, stock, tool, path, settings = model
    calls = []
    one = validate(solid, stock, tool, path, settings)
    dask = validate(solid, stock, tool, path, settings, scheduler=cluster.scheduler_address,
                    progress=lambda done, total: calls.append((done, total)))
    same(one.reference, dask.reference)
    assert (one.reference["length"] > 0).any()
    assert calls == [(k, len(path)) for k in range(1, len(path) + 1)]


def test_a_dask_worker_reads_each_new_solid(model, cluster):  # noqa: F811
    """Two validations of different solids on the same cluster: each gets its own stock (the cached
    BREP is replaced, not reused for another solid)."""
    solid, stock, tool, path, settings = model
    short = Toolpath(path.cl[:2], path.theta_a[:2], path.theta_b[:2])
    moved = solid.copy()
    moved.translate(FreeCAD.Vector(0.0, 0.0, -1.0))
    first = validate(moved, stock, tool, short, settings, scheduler=cluster.scheduler_address).reference
    alone = validate(moved, stock, tool, short, settings).reference
    same(first, alone)
    again = validate(solid, stock, tool, short, settings, scheduler=cluster.scheduler_address).reference
    same(again, validate(solid, stock, tool, short, settings).reference)
    assert not np.array_equal(first["length"], again["length"])


def test_a_scheduler_that_does_not_answer_is_named(model):  # noqa: F811
    solid, stock, tool, path, settings = model
    short = Toolpath(path.cl[:1], path.theta_a[:1], path.theta_b[:1])
    with pytest.raises(InputError, match="tcp://127.0.0.1:9"):
        validate(solid, stock, tool, short, settings, scheduler="tcp://127.0.0.1:9")


def run_validate(toolpath, report, *options):
    """validate of model test 1's short pass (φ every 10°) into `report`; the finished process."""
    command = [sys.executable, "-m", "abm_workbench", "validate", "--stock", os.path.join(MODEL, "stock.step"),
               "--toolpath", str(toolpath), "--job", os.path.join(MODEL, "job.json"), "--phi-step", "10",
               "--report", str(report), *options]
    return subprocess.run(command, cwd=ROOT, capture_output=True, text=True, timeout=300)


def test_the_command_line_on_a_dask_cluster_writes_the_same_tables(tmp_path, short_pass, cluster):  # noqa: F811
    out = tmp_path / "out"
    alone = run_validate(short_pass, out / "one")
    dask = run_validate(short_pass, out / "dask", "--scheduler", cluster.scheduler_address)
    assert alone.returncode == dask.returncode == 0, dask.stderr
    for name in ("comparison.csv", "segments.csv", "depth.csv"):
        assert (out / "one" / name).read_bytes() == (out / "dask" / name).read_bytes(), name
    bad = run_validate(short_pass, out / "bad", "--scheduler", "localhost:8786")
    assert bad.returncode == 2 and bad.stderr.splitlines() == [
        "abm: error: --scheduler: expected a Dask scheduler address such as tcp://127.0.0.1:8786, got 'localhost:8786'"]
    assert sorted(os.listdir(out)) == ["dask", "one"]
