"""SIGTERM and SIGHUP in the middle of a run clean up as Ctrl-C does (issue #15, item 5), and Ctrl-C
(SIGINT) itself (issue #27).

The run is a real ``python -m abm_workbench engage`` against the in-process stock (the default)
writing a ~150 MB results CSV into folders it has to make; the results are streamed chunk by
chunk as they are computed, so the signal, sent once its hidden temporary file exists, comes
mid-computation and mid-write.
"""

import os
import signal
import subprocess
import sys
import time

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")


@pytest.mark.parametrize("stop", [signal.SIGTERM, signal.SIGHUP, signal.SIGINT])
def test_a_stopped_run_leaves_nothing(tmp_path, stop):
    out = tmp_path / "made" / "deeper" / "R.csv"
    command = [sys.executable, "-m", "abm_workbench", "engage", "--stock", os.path.join(MODEL, "stock.json"),
               "--toolpath", os.path.join(MODEL, "toolpath.csv"), "--job", os.path.join(MODEL, "job.json"),
               "--phi-step", "0.01", "--out", str(out)]
    # SIGINT as a terminal's Ctrl-C delivers it (a shell without job control starts children with it ignored).
    child = subprocess.Popen(command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    deadline = time.monotonic() + 120.0
    while not (out.parent.is_dir() and any(name.endswith(".tmp") for name in os.listdir(out.parent))):
        assert child.poll() is None, "the run ended before its temporary file was seen"
        assert time.monotonic() < deadline
        time.sleep(0.02)
    child.send_signal(stop)
    _, err = child.communicate(timeout=120)
    assert child.returncode == 128 + stop
    words = "interrupted" if stop == signal.SIGINT else f"stopped by {signal.Signals(stop).name}"
    assert err.splitlines() == [f"abm: {words}"]  # one line (no progress bar: stderr is not a terminal)
    assert "Traceback" not in err
    assert os.listdir(tmp_path) == []
