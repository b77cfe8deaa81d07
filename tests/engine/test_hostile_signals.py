"""SIGTERM and SIGHUP in the middle of a run clean up as Ctrl-C does (issue #15, item 5).

The run is a real ``python -m abm_workbench engage`` writing a ~150 MB results CSV into folders
it has to make; the signal is sent once its hidden temporary file exists, i.e. mid-write.
"""

import os
import signal
import subprocess
import sys
import time

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")


@pytest.mark.parametrize("stop", [signal.SIGTERM, signal.SIGHUP])
def test_a_stopped_run_leaves_nothing(tmp_path, stop):
    out = tmp_path / "made" / "deeper" / "R.csv"
    command = [sys.executable, "-m", "abm_workbench", "engage", "--stock", os.path.join(MODEL, "stock.json"),
               "--toolpath", os.path.join(MODEL, "toolpath.csv"), "--job", os.path.join(MODEL, "job.json"),
               "--phi-step", "0.01", "--out", str(out)]
    child = subprocess.Popen(command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120.0
    while not (out.parent.is_dir() and any(name.endswith(".tmp") for name in os.listdir(out.parent))):
        assert child.poll() is None, "the run ended before its temporary file was seen"
        assert time.monotonic() < deadline
        time.sleep(0.02)
    child.send_signal(stop)
    _, err = child.communicate(timeout=120)
    assert child.returncode == 128 + stop
    assert err.splitlines()[-1] == f"abm: stopped by {signal.Signals(stop).name}"
    assert "Traceback" not in err
    assert os.listdir(tmp_path) == []
