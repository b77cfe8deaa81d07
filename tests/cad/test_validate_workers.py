"""Validation on several processes: the same reference, bit for bit, as one process; progress per
CL point; an interrupt stops every worker; and SIGTERM during ``validate`` leaves no staging folder.
"""

import json
import multiprocessing
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

from abm_workbench.cad.recognise import load_solid, recognise
from abm_workbench.engine import CutSettings, Tool, Toolpath
from abm_workbench.formats.toolpath_csv import load_toolpath
from abm_workbench.validation import reference_by_workers, validate, validate_helix

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")
ROWS = [3, 11, 20, 29, 37, 44]  # CL points over curved walls, the straight wall at x = 76 and tops


@pytest.fixture(scope="module")
def model():
    """(solid, exact-wall staircase, tool, toolpath of ROWS, settings every 20°) of model test 1."""
    job = json.load(open(os.path.join(MODEL, "job.json")))
    full = load_toolpath(os.path.join(MODEL, "toolpath.csv"))
    solid = load_solid(os.path.join(MODEL, "stock.step"))
    path = Toolpath(full.cl[ROWS], full.theta_a[ROWS], full.theta_b[ROWS])
    tool = Tool(job["diameter"], job["flutes"], job["flute_length"])
    settings = CutSettings(job["feed_per_tooth"], job["inclination"], 0, 180, 20)
    return solid, recognise(solid).staircase, tool, path, settings


def same(a, b):
    """Two dicts of arrays equal bit for bit (NaN where the other is NaN, same dtype and shape)."""
    assert a.keys() == b.keys()
    for name in a:
        assert a[name].dtype == b[name].dtype and a[name].shape == b[name].shape, name
        assert np.array_equal(a[name], b[name], equal_nan=a[name].dtype.kind == "f"), name


def test_two_workers_give_the_reference_of_one_process(model):
    solid, stock, tool, path, settings = model
    calls = []
    one = validate(solid, stock, tool, path, settings)
    two = validate(solid, stock, tool, path, settings, workers=2,
                   progress=lambda done, total: calls.append((done, total)))
    same(one.reference, two.reference)
    assert (one.reference["length"] > 0).any()
    assert calls == [(k, len(ROWS)) for k in range(1, len(ROWS) + 1)]
    assert multiprocessing.active_children() == []


def slow_first(solid, tool, toolpath, phi, progress):
    """A stand-in reference (in the workers): the CL points' x, the first CL point of the model
    pass the slowest by far, so that the CL points finish out of order."""
    time.sleep(1.5 if toolpath.cl[0, 0] < 15.0 else 0.05)
    return {"x": toolpath.cl[:, 0] + 0.0 * solid.Volume, "phi": np.tile(phi, (len(toolpath), 1))}


def test_results_go_back_to_their_cl_points(model):
    solid, _, tool, path, settings = model
    assert path.cl[0, 0] < 15.0 <= path.cl[1:, 0].min()
    out = reference_by_workers(slow_first, solid, tool, path, settings.phi, workers=2)
    assert np.array_equal(out["x"], path.cl[:, 0]) and out["phi"].shape == (len(ROWS), settings.phi.size)


def test_two_workers_give_the_helix_reference_of_one_process(model):
    solid, stock, tool, path, settings = model
    helical = Tool(tool.diameter, tool.flutes, tool.flute_length, helix=30.0)
    short = Toolpath(path.cl[:3], path.theta_a[:3], path.theta_b[:3])
    one = validate_helix(solid, stock, helical, short, settings, flutes=[1])
    two = validate_helix(solid, stock, helical, short, settings, flutes=[1], workers=2)
    same(one.reference, two.reference)


def test_an_interrupt_stops_every_worker(model):
    """Ctrl-C after the first CL point: the workers are killed at once, not left to finish their
    booleans, and none is left behind."""
    solid, stock, tool, path, settings = model
    workers, before = [], set(multiprocessing.active_children())  # children of earlier tests are not ours

    def interrupt(done, total):
        workers.extend(set(multiprocessing.active_children()) - before)
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        validate(solid, stock, tool, path, settings, workers=2, progress=interrupt)
    assert len(workers) == 2 and -signal.SIGKILL in [worker.exitcode for worker in workers]
    assert not any(worker.is_alive() for worker in workers)
    assert set(multiprocessing.active_children()) - before == set()


def test_sigterm_during_validate_leaves_no_staging_folder(tmp_path):
    report = tmp_path / "report"
    command = [sys.executable, "-m", "abm_workbench", "validate", "--stock", os.path.join(MODEL, "stock.step"),
               "--toolpath", os.path.join(MODEL, "toolpath.csv"), "--job", os.path.join(MODEL, "job.json"),
               "--phi-step", "5", "--cl", "0,1", "--check", "0,1", "--report", str(report)]
    child = subprocess.Popen(command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120.0
    while not any(name.startswith(".report.") for name in os.listdir(tmp_path)):
        assert child.poll() is None, "validate ended before its staging folder was seen"
        assert time.monotonic() < deadline
        time.sleep(0.05)
    child.send_signal(signal.SIGTERM)
    _, err = child.communicate(timeout=120)
    assert child.returncode == 128 + signal.SIGTERM and err.splitlines()[-1] == "abm: stopped by SIGTERM"
    assert os.listdir(tmp_path) == []


def test_apart_computes_one_workers_reference_in_a_spawned_process(model):
    """apart (the GUI's way: FreeCAD's bindings hold Python's lock through a boolean): 1 worker is a
    spawned process, with the reference of this one bit for bit and a step per CL point."""
    solid, stock, tool, path, settings = model
    seen, calls = [], []

    def progress(done, total):
        seen.append(len(multiprocessing.active_children()))
        calls.append((done, total))

    here = validate(solid, stock, tool, path, settings)
    apart = validate(solid, stock, tool, path, settings, workers=1, apart=True, progress=progress)
    same(here.reference, apart.reference)
    assert seen == [1] * len(ROWS) and calls == [(k, len(ROWS)) for k in range(1, len(ROWS) + 1)]
    assert multiprocessing.active_children() == []


def test_whole_sends_the_pass_as_one_task(model):
    solid, _, tool, path, settings = model
    calls = []
    out = reference_by_workers(slow_first, solid, tool, path, settings.phi, workers=1, apart=True, whole=True,
                               progress=lambda done, total: calls.append((done, total)))
    assert np.array_equal(out["x"], path.cl[:, 0]) and calls == [(1, 1)]
