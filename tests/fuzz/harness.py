"""What the fuzz tier shares: the command line run in a child process under limits, and its promises.

Every run of the command line, whatever its input, must

- end with status 0, or 2 with exactly one ``abm: error:`` line (the last line of stderr) naming an
  input file or an option (a status of 128 + n after signal n, with ``abm: interrupted`` or
  ``abm: stopped by SIGTERM``);
- print no traceback;
- leave no output on failure (nor a folder made for it) and no hidden temporary file ever;
- leave every input as it was;
- end within its time limit and under its memory limit (``resource.setrlimit`` in the child).

Very slow cases are marked :data:`slow` and run only with ``ABM_FUZZ_SLOW=1``; the default run of
tests/fuzz stays within a few minutes (``make test`` runs it with every tier).
"""

import contextlib
import os
import resource
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODELS = os.path.join(ROOT, "resources", "models")
MODEL_1 = os.path.join(MODELS, "model_test_1")
FIXTURES = os.path.join(ROOT, "tests", "fixtures", "cl")
FUZZ = os.path.dirname(os.path.abspath(__file__))
#: Memory a child may map (bytes): numpy, scipy and the engine fit well within it, the runs the issue
#: found (allocations of 487 GiB to 45 TiB) do not.
MEMORY = 3 << 30
#: Cases that take minutes: only with ABM_FUZZ_SLOW=1.
slow = pytest.mark.skipif(not os.environ.get("ABM_FUZZ_SLOW"), reason="slow fuzz case: set ABM_FUZZ_SLOW=1")


@dataclass
class Done:
    """A finished child: exit status, stdout, stderr, wall seconds."""

    status: int
    out: str
    err: str
    seconds: float

    @property
    def errors(self):
        return [line for line in self.err.splitlines() if line.startswith("abm: error: ")]


def environment(**extra):
    """The child's environment: this one, the checkout importable, one BLAS thread (its buffers count
    against the address-space limit), `extra` added."""
    env = dict(os.environ, PYTHONPATH=ROOT, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1", MKL_NUM_THREADS="1")
    env.update(extra)
    return env


def limited(memory):
    """preexec_fn of a child: its address space limited to `memory` bytes (None: as it is)."""
    def apply():
        if memory is not None:
            resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
    return apply


def abm(argv, cwd, *, memory=MEMORY, timeout=120.0, env=None):
    """Run ``python -m abm_workbench argv`` in `cwd` under `memory` bytes of address space; a Done.
    A run still going after `timeout` seconds is killed and fails the test."""
    started = time.monotonic()
    try:
        done = subprocess.run([sys.executable, "-m", "abm_workbench", *argv], cwd=cwd, capture_output=True, text=True,
                              timeout=timeout, env=env or environment(), preexec_fn=limited(memory))
    except subprocess.TimeoutExpired as expired:
        pytest.fail(f"abm {' '.join(argv)} still ran after {timeout:g} s (a hang); stderr: {expired.stderr!r}")
    return Done(done.returncode, done.stdout, done.stderr, time.monotonic() - started)


def snapshot(folder):
    """{relative path: bytes} of every file under `folder` (links not followed), folders as None."""
    found = {}
    for top, dirs, names in os.walk(folder):
        for name in dirs:
            found[os.path.relpath(os.path.join(top, name), folder)] = None
        for name in names:
            path = os.path.join(top, name)
            if os.path.islink(path) or not os.path.isfile(path):
                found[os.path.relpath(path, folder)] = "special"
            else:
                with open(path, "rb") as file:
                    found[os.path.relpath(path, folder)] = file.read()
    return found


def check_promises(done, before, after, *, names=(), allowed=(0, 2), outputs=()):
    """The module docstring's promises for one finished run: `before` and `after` snapshots of its folder
    (an error leaves it as it was; success changes only `outputs`, relative paths, and adds no hidden
    file); `names`: the inputs, one of which (or an option) an error line must name."""
    assert "Traceback" not in done.err, done.err
    assert done.status in allowed, f"status {done.status}: {done.err}"
    hidden = [path for path in after if os.path.basename(path).startswith(".") and path not in before]
    assert not hidden, f"hidden files left: {hidden}"
    if done.status == 0:
        assert done.errors == [], done.err
        changed = {path for path in set(before) | set(after) if before.get(path) != after.get(path)}
        stray = [path for path in changed if not any(path == out or out.startswith(path + os.sep)
                                                     or path.startswith(out + os.sep) for out in outputs)]
        assert not stray, f"changed besides the outputs: {stray}"
        return
    lines = done.err.splitlines()
    assert len(done.errors) == 1 and done.errors[0] == lines[-1], done.err
    named = [name for name in names if name in done.errors[0]]
    assert named or " --" in done.errors[0] or done.errors[0].startswith("abm: error: --") or \
        "argument " in done.errors[0], f"the error names no input file or option: {done.err}"
    assert after == before, "a failed run changed its folder"


def copy_inputs(folder, sources):
    """Copy {name: source path} into `folder`; {name: new path}."""
    paths = {}
    for name, source in sources.items():
        paths[name] = os.path.join(folder, name)
        shutil.copyfile(source, paths[name])
    return paths


def children(pid):
    """Pids of the live child processes of `pid`."""
    found = []
    with contextlib.suppress(FileNotFoundError):
        for entry in os.listdir("/proc"):
            if entry.isdigit():
                with contextlib.suppress(OSError, IndexError):
                    with open(f"/proc/{entry}/stat") as file:
                        fields = file.read().rsplit(")", 1)[1].split()
                    if int(fields[1]) == pid and fields[0] != "Z":
                        found.append(int(entry))
    return found


def alive(pid):
    """Whether process `pid` exists and is not a zombie."""
    try:
        with open(f"/proc/{pid}/stat") as file:
            return file.read().rsplit(")", 1)[1].split()[0] != "Z"
    except (OSError, IndexError):
        return False
