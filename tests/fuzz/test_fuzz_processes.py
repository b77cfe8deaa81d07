"""Fuzz tier, the run's surroundings (issue #29): special files, worker processes, signals, report folders.

Each case runs ``python -m abm_workbench`` as a child and checks the promises of harness.py:
special files (FIFO, /dev/zero, folders, sockets) as inputs and outputs are refused at once; local
workers are at most one per core, die with their parent however it dies, and a limit on processes
is one error line, not a hang; a second signal during the clean-up, or a signal while the command
line is still starting, leaves nothing behind and prints no traceback; a report folder holding a
user's files is never emptied.
"""

import os
import random
import signal
import socket
import subprocess
import sys
import time

import pytest

from tests.fuzz.harness import (MODEL_1, abm, alive, check_promises, children, copy_inputs, environment,
                                snapshot)

INPUTS = {name: os.path.join(MODEL_1, name) for name in ("stock.json", "toolpath.csv", "job.json")}


@pytest.fixture
def case(tmp_path):
    """tmp_path holding model test 1's inputs."""
    copy_inputs(str(tmp_path), INPUTS)
    return tmp_path


def engage(*more, out="out/R.csv"):
    return ["engage", "--stock", "stock.json", "--toolpath", "toolpath.csv", "--job", "job.json", "--phi-step", "30",
            "--stock-model", "initial", "--out", out, *more]


# Special files.

def _special(folder, kind):
    """Make a special file of `kind` in `folder`; its path (and what keeps it alive)."""
    path = os.path.join(folder, f"special.{kind}")
    if kind == "fifo":
        os.mkfifo(path)
        return path, None
    if kind == "socket":
        server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        server.bind(path)
        return path, server
    if kind == "folder":
        os.mkdir(path)
        return path, None
    if kind == "zero":
        return "/dev/zero", None
    raise ValueError(kind)


@pytest.mark.parametrize("kind", ["fifo", "zero", "folder", "socket"])
@pytest.mark.parametrize("option", ["--stock", "--toolpath", "--job", "--tool-table", "--machine", "--offsets"])
def test_a_special_file_as_an_input_is_refused_at_once(case, option, kind):
    path, keep = _special(str(case), kind)
    try:
        argv = engage()
        if option in ("--stock", "--toolpath", "--job"):
            argv[argv.index(option) + 1] = path
        else:
            argv += [option, path]
        before = snapshot(case)
        done = abm(argv, case, timeout=60)
        check_promises(done, before, snapshot(case), names=[path])
        assert done.status == 2 and done.seconds < 30
        assert "not a file" in done.errors[0] or "cannot read" in done.errors[0], done.err
    finally:
        if keep is not None:
            keep.close()


@pytest.mark.parametrize("kind", ["fifo", "zero", "folder"])
def test_a_special_file_given_to_the_toolpath_command_is_refused(case, kind):
    path, _ = _special(str(case), kind)
    done = abm(["toolpath", path], case, timeout=60)
    assert done.status == 2 and "Traceback" not in done.err and len(done.errors) == 1, done.err


@pytest.mark.parametrize("kind", ["fifo", "socket", "link", "dangling"])
@pytest.mark.parametrize("option", ["--out", "--plot"])
def test_a_special_file_or_link_as_an_output_is_left_alone(case, option, kind):
    if kind in ("fifo", "socket"):
        path, keep = _special(str(case), kind)
    else:
        path, keep = os.path.join(case, f"link.{kind}"), None
        os.symlink("toolpath.csv" if kind == "link" else "nowhere.csv", path)
    try:
        argv = engage(out="R.csv") if option == "--plot" else engage(out=path)
        if option == "--plot":
            argv += ["--plot", path]
        before = snapshot(case)
        done = abm(argv, case, timeout=60)
        check_promises(done, before, snapshot(case), names=[path])
        assert done.status == 2
        if kind in ("link", "dangling"):
            assert os.path.islink(path)
    finally:
        if keep is not None:
            keep.close()


def test_an_empty_output_name_of_the_toolpath_command_is_refused(case):
    done = abm(["toolpath", "toolpath.csv", "--out", ""], case, timeout=60)
    assert done.status == 2 and done.errors == ["abm: error: --out: is empty; give a file name"], done.err


# Worker processes.

def _big_engage(out, *more):
    """An engage run of ~1 M instants (about 10 s on one core), so that it is caught running."""
    return ["engage", "--stock", "stock.json", "--toolpath", "toolpath.csv", "--job", "job.json", "--phi-step", "0.01",
            "--stock-model", "initial", "--out", out, *more]


def _start(argv, cwd):
    return subprocess.Popen([sys.executable, "-m", "abm_workbench", *argv], cwd=cwd, env=environment(),
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def _wait_for(condition, seconds, what):
    deadline = time.monotonic() + seconds
    while not condition():
        assert time.monotonic() < deadline, f"no {what} within {seconds} s"
        time.sleep(0.05)


def test_workers_beyond_the_cores_start_one_per_core(case):
    """--workers 100000 started over 5,000 processes; now one per core, with a warning, and the run's bytes."""
    cores = len(os.sched_getaffinity(0))
    child = _start(_big_engage("R.csv", "--workers", "100000"), case)
    try:
        _wait_for(lambda: children(child.pid) or child.poll() is not None, 60, "worker")
        time.sleep(0.5)
        assert len(children(child.pid)) <= max(cores, 2)
        _, err = child.communicate(timeout=300)
    finally:
        if child.poll() is None:
            child.kill()
            child.communicate()
    assert child.returncode == 0, err
    assert f"--workers 100000: this process may run on {cores} cores" in err


def test_workers_die_with_their_parent(case):
    """engage --workers 2 killed (SIGKILL, no clean-up): its workers are gone at once, not left computing."""
    child = _start(_big_engage("R.csv", "--workers", "2"), case)
    try:
        _wait_for(lambda: len(children(child.pid)) >= 2, 60, "two workers")
        workers = children(child.pid)
        time.sleep(0.3)
    finally:
        child.kill()
        child.communicate()
    deadline = time.monotonic() + 10.0
    while any(alive(pid) for pid in workers) and time.monotonic() < deadline:
        time.sleep(0.05)
    left = [pid for pid in workers if alive(pid)]
    for pid in left:
        os.kill(pid, signal.SIGKILL)
    assert not left, "workers outlived their parent"


#: A child that cannot start more than FORKS processes (as under a limit on processes: os.fork raises EAGAIN).
FORK_LIMIT = """
import os, sys
allowed = int(sys.argv[1])
real = os.fork
def fork():
    global allowed
    if allowed <= 0:
        raise BlockingIOError(11, "Resource temporarily unavailable")
    allowed -= 1
    return real()
os.fork = fork
sys.argv = ["abm"] + sys.argv[2:]
from abm_workbench.cli import main
sys.exit(main())
"""


@pytest.mark.parametrize("forks", [0, 1])
def test_a_limit_on_processes_is_one_error_not_a_hang(case, forks):
    before = snapshot(case)
    try:
        done = subprocess.run([sys.executable, "-c", FORK_LIMIT, str(forks), *engage("--workers", "2")], cwd=case,
                              env=environment(), capture_output=True, text=True, timeout=60)
    except subprocess.TimeoutExpired:
        pytest.fail("engage --workers 2 hung when it could not start its workers")
    assert done.returncode == 2 and "Traceback" not in done.stderr, done.stderr
    assert done.stderr.splitlines()[-1].startswith("abm: error: --workers: could not start 2 worker processes")
    assert snapshot(case) == before


#: A child that sends itself `signal` right after each fork of a worker, in fork's own callbacks (as a
#: SIGTERM to the process group does when it comes while the workers start).
SIGNAL_AT_FORK = """
import os, signal, sys
stop = int(sys.argv[1])
os.register_at_fork(after_in_parent=lambda: os.kill(os.getpid(), stop))
sys.argv = ["abm"] + sys.argv[2:]
from abm_workbench.cli import main
sys.exit(main())
"""


@pytest.mark.parametrize("stop", [signal.SIGINT, signal.SIGTERM])
def test_a_signal_while_the_workers_are_forked_stops_the_run(tmp_path, stop):
    """Its handler ran inside fork's callbacks, where the exception it raised was printed ('Exception ignored
    in: <function _releaseLock>') and lost: the run went on, with every stop signal ignored, to status 0."""
    copy_inputs(str(tmp_path), INPUTS)
    argv = [sys.executable, "-c", SIGNAL_AT_FORK, str(int(stop)), *_big_engage("made/R.csv", "--workers", "2")]
    done = subprocess.run(argv, cwd=tmp_path, env=environment(), capture_output=True, text=True, timeout=300)
    words = "interrupted" if stop == signal.SIGINT else f"stopped by {stop.name}"
    assert done.returncode == 128 + stop and "Traceback" not in done.stderr, done.stderr
    assert done.stderr.splitlines()[-1] == f"abm: {words}", done.stderr
    assert sorted(os.listdir(tmp_path)) == sorted(INPUTS)


# Signals.

@pytest.mark.parametrize("seed", range(3))
def test_a_second_signal_during_the_clean_up_leaves_nothing(tmp_path, seed):
    """A first stop signal once the results are being written, a second 5-60 ms later (any of SIGINT,
    SIGTERM, SIGHUP each, with and without workers): the status and message of the first, nothing left."""
    rng = random.Random(seed)
    copy_inputs(str(tmp_path), INPUTS)
    stops = [signal.SIGINT, signal.SIGTERM, signal.SIGHUP]
    first, second = rng.choice(stops), rng.choice(stops)
    out = tmp_path / "made" / "deeper" / "R.csv"
    child = _start(_big_engage(str(out), *(["--workers", "2"] if seed % 2 else [])), tmp_path)
    try:
        _wait_for(lambda: out.parent.is_dir() and any(n.endswith(".tmp") for n in os.listdir(out.parent))
                  or child.poll() is not None, 120, "temporary file")
        assert child.poll() is None, "the run ended before its temporary file was seen"
        child.send_signal(first)
        time.sleep(rng.uniform(0.005, 0.06))
        if child.poll() is None:
            child.send_signal(second)
        _, err = child.communicate(timeout=120)
    finally:
        if child.poll() is None:
            child.kill()
            child.communicate()
    words = "interrupted" if first == signal.SIGINT else f"stopped by {first.name}"
    assert child.returncode == 128 + first, err
    assert err.splitlines()[-1] == f"abm: {words}" and "Traceback" not in err
    assert sorted(os.listdir(tmp_path)) == sorted(INPUTS)


@pytest.mark.parametrize("stop", [signal.SIGINT, signal.SIGTERM])
def test_a_signal_to_the_whole_process_group_with_workers(tmp_path, stop):
    """Ctrl-C on a terminal reaches every process of the group, the workers too: they print nothing and end;
    the run ends as by a signal to it alone."""
    copy_inputs(str(tmp_path), INPUTS)
    out = tmp_path / "made" / "R.csv"
    child = subprocess.Popen([sys.executable, "-m", "abm_workbench", *_big_engage(str(out), "--workers", "2")],
                             cwd=tmp_path, env=environment(), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, start_new_session=True)
    try:
        _wait_for(lambda: out.parent.is_dir() and any(n.endswith(".tmp") for n in os.listdir(out.parent))
                  or child.poll() is not None, 120, "temporary file")
        workers = children(child.pid)
        os.killpg(child.pid, stop)
        _, err = child.communicate(timeout=120)
    finally:
        if child.poll() is None:
            os.killpg(child.pid, signal.SIGKILL)
            child.communicate()
    assert child.returncode == 128 + stop and "Traceback" not in err, err
    assert err.splitlines()[-1] in ("abm: interrupted", f"abm: stopped by {stop.name}"), err
    assert sorted(os.listdir(tmp_path)) == sorted(INPUTS)
    time.sleep(0.5)
    assert not [pid for pid in workers if alive(pid)]


#: Seconds the interpreter takes to start before any of the package's code runs (no handler can be
#: set earlier): a SIGINT then is Python's own KeyboardInterrupt.
def _interpreter_start():
    started = time.monotonic()
    subprocess.run([sys.executable, "-c", "pass"], check=True)
    return time.monotonic() - started


@pytest.mark.parametrize("stop", [signal.SIGINT, signal.SIGTERM, signal.SIGHUP])
def test_a_signal_while_starting_up_is_clean(tmp_path, stop):
    """A stop signal at random moments of the first second (while numpy and the engine are imported, the
    arguments parsed, the inputs read): no traceback, the command line's status and message, nothing left."""
    rng = random.Random(int(stop))
    copy_inputs(str(tmp_path), INPUTS)
    start = 2.0 * _interpreter_start() if stop == signal.SIGINT else 0.0
    for _ in range(6):
        delay = rng.uniform(start, max(start, 1.0))
        child = _start(engage(), tmp_path)
        time.sleep(delay)
        child.send_signal(stop)
        _, err = child.communicate(timeout=120)
        assert "Traceback" not in err, f"after {delay:.3f} s: {err}"
        assert child.returncode in (0, 128 + stop, -stop), f"after {delay:.3f} s: {child.returncode} {err}"
        if child.returncode == 128 + stop:
            assert err.splitlines()[-1] in ("abm: interrupted", f"abm: stopped by {stop.name}"), err
            assert sorted(os.listdir(tmp_path)) == sorted(INPUTS)
        for name in os.listdir(tmp_path):
            if name not in INPUTS:
                assert name == "out" and sorted(os.listdir(tmp_path / "out")) == ["R.csv", "R.summary.csv"]
                for each in os.listdir(tmp_path / "out"):
                    os.remove(tmp_path / "out" / each)
                os.rmdir(tmp_path / "out")


# Report folders.

@pytest.mark.parametrize("command", ["validate", "schedule"])
def test_a_report_folder_holding_other_files_is_never_emptied(case, command):
    """validate --report DIR used to delete a user's files in DIR when it held an older report: refused,
    DIR as it was; a folder of an older report alone is still replaced."""
    report = case / "rep"
    report.mkdir()
    (report / "index.html").write_text("<p>an older report</p>")
    (report / "notes.txt").write_text("mine")
    argv = ["--stock", "stock.json", "--toolpath", "toolpath.csv", "--job", "job.json", "--phi-step", "60",
            "--stock-model", "initial", "--report", "rep"]
    argv = ["validate", *argv, "--check", "0"] if command == "validate" else \
        ["schedule", *argv, "--material", "al7075-t6", "--max-force", "400", "--out", "P.csv"]
    before = snapshot(case)
    done = abm(argv, case, timeout=300)
    check_promises(done, before, snapshot(case), names=["rep"])
    assert done.status == 2 and "'notes.txt', which no report writes" in done.errors[0]
    assert (report / "notes.txt").read_text() == "mine"
