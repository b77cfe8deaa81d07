"""``validate --workers 2`` stopped at any moment: no worker left running, no staging folder, no traceback.

The command line is interrupted by SIGINT sent to its whole process group (as Ctrl-C on a terminal
does: the workers get it too), by SIGTERM and by SIGHUP sent to it alone, each at four moments: as
soon as the first worker process exists (it is still starting its interpreter), half a second later
(the workers import FreeCAD and read the solid), after the first CL point's progress line (mid-run)
and after the last one (the workers being ended, the report written). The workers are found
independently of the code under test, as the command's child processes in /proc, watched until
the signal is sent; after the command has ended each of them must be gone. And when the command
is killed outright (SIGKILL, no clean-up possible), its workers must end by themselves.
"""

import os
import signal
import subprocess
import sys
import threading
import time

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")
#: CL points of the short pass (a header line and these rows of model test 1's toolpath).
ROWS = 6
#: Seconds any one step may take on a loaded machine.
PATIENCE = 120.0
MOMENTS = ("first worker", "first worker + 0.5 s", "first CL point", "last CL point")


def stat(pid):
    """(parent pid, state, start time) of process `pid` from /proc, None if it is gone."""
    try:
        with open(f"/proc/{pid}/stat") as handle:
            fields = handle.read().rsplit(")", 1)[1].split()
    except (FileNotFoundError, ProcessLookupError, IndexError):
        return None
    return int(fields[1]), fields[0], fields[19]


def workers_of(parent):
    """{pid: start time} of the worker processes (spawned interpreters) whose parent is `parent`."""
    found = {}
    for name in os.listdir("/proc"):
        if name.isdigit() and (info := stat(int(name))) and info[0] == parent:
            try:
                with open(f"/proc/{name}/cmdline", "rb") as handle:
                    command = handle.read()
            except (FileNotFoundError, ProcessLookupError):
                continue
            if b"spawn_main" in command:
                found[int(name)] = info[2]
    return found


def running(pid, started):
    """Whether the process `pid` that started at `started` still runs (not gone, not a zombie)."""
    info = stat(pid)
    return info is not None and info[2] == started and info[1] != "Z"


def wait_all_gone(workers, seconds):
    """Wait up to `seconds` for every worker {pid: start time} to be gone; the ones still running."""
    deadline = time.monotonic() + seconds
    while (alive := [pid for pid, started in workers.items() if running(pid, started)]) and time.monotonic() < deadline:
        time.sleep(0.05)
    return alive


@pytest.fixture
def short_pass(tmp_path):
    """Model test 1's toolpath cut to its first ROWS CL points, in tmp_path/inputs."""
    inputs = tmp_path / "inputs"
    inputs.mkdir()
    with open(os.path.join(MODEL, "toolpath.csv")) as handle:
        lines = handle.readlines()[:ROWS + 1]
    (inputs / "toolpath.csv").write_text("".join(lines))
    return inputs / "toolpath.csv"


def start_validate(toolpath, report):
    """The validate command with 2 workers, in a process group of its own, stderr read line by line into
    the returned list by a thread."""
    command = [sys.executable, "-m", "abm_workbench", "validate", "--stock", os.path.join(MODEL, "stock.step"),
               "--toolpath", str(toolpath), "--job", os.path.join(MODEL, "job.json"), "--phi-step", "10",
               "--workers", "2", "--report", str(report)]
    child = subprocess.Popen(command, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                             start_new_session=True)
    lines = []
    reader = threading.Thread(target=lambda: lines.extend(child.stderr), daemon=True)
    reader.start()
    return child, lines, reader


def watch_until(child, lines, moment, seen):
    """Record the child's workers into `seen` until `moment` (one of MOMENTS) has come."""
    deadline = time.monotonic() + PATIENCE
    first_worker = None
    while True:
        seen.update(workers_of(child.pid))
        if first_worker is None and seen:
            first_worker = time.monotonic()
        if moment == "first worker" and seen:
            return
        if moment == "first worker + 0.5 s" and first_worker is not None and time.monotonic() >= first_worker + 0.5:
            return
        if moment == "first CL point" and any("CL point 1/" in line for line in lines):
            return
        if moment == "last CL point" and any(f"CL point {ROWS}/{ROWS}" in line for line in lines):
            return
        assert child.poll() is None, f"validate ended before the moment {moment!r}: {''.join(lines)}"
        assert time.monotonic() < deadline, f"the moment {moment!r} did not come"
        time.sleep(0.005)


@pytest.mark.parametrize("moment", MOMENTS)
@pytest.mark.parametrize("number", [signal.SIGINT, signal.SIGTERM, signal.SIGHUP], ids=["INT", "TERM", "HUP"])
def test_a_stopped_validate_leaves_no_worker_and_no_staging_folder(tmp_path, short_pass, moment, number):
    out = tmp_path / "out"
    out.mkdir()
    child, lines, reader = start_validate(short_pass, out / "report")
    seen = {}
    try:
        watch_until(child, lines, moment, seen)
        seen.update(workers_of(child.pid))
        if number == signal.SIGINT:
            os.killpg(child.pid, number)  # Ctrl-C on a terminal: the whole foreground group
        else:
            child.send_signal(number)
        child.wait(timeout=PATIENCE)
    finally:
        if child.poll() is None:
            os.killpg(child.pid, signal.SIGKILL)
            child.wait()
    reader.join(timeout=PATIENCE)
    text = "".join(lines)
    assert seen, "no worker process was seen"
    assert wait_all_gone(seen, 10.0) == [], f"workers still running after validate ended ({moment})"
    assert "Traceback" not in text, text
    if child.returncode == 0:  # finished before the signal came (the last moment, on a fast machine)
        assert os.listdir(out) == ["report"]
    else:
        words = "interrupted" if number == signal.SIGINT else f"stopped by {signal.Signals(number).name}"
        assert child.returncode == 128 + number and lines[-1].strip() == f"abm: {words}", text
        assert os.listdir(out) == []


def test_workers_end_by_themselves_when_validate_is_killed(tmp_path, short_pass):
    """SIGKILL leaves the command no clean-up: its workers must notice and end after their task."""
    child, lines, reader = start_validate(short_pass, tmp_path / "report")
    seen = {}
    try:
        watch_until(child, lines, "first CL point", seen)
        seen.update(workers_of(child.pid))
    finally:
        child.kill()
        child.wait()
    reader.join(timeout=PATIENCE)
    assert seen and wait_all_gone(seen, 60.0) == []
