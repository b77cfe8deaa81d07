"""GUI tier: the real FreeCAD GUI under Xvfb, driven by a macro that writes a JSON verdict.

FREECAD_NOTES: run as `xvfb-run -a freecad macro.py` with HOME isolated and the Qt WebEngine
sandbox off; a macro that raises would leave the GUI open, so the macro always ends with
os._exit and the run has a timeout, after which the whole process group (xvfb-run, Xvfb,
FreeCAD) is killed. A run that ends without a verdict fails with what it left: FreeCAD's exit
status, whether the macro had started, the Python stacks of every thread at a crash
(faulthandler), the ends of FreeCAD's output and of Xvfb's.
"""

import json
import os
import shutil
import signal
import subprocess
import textwrap

import pytest

from tests.conftest import ROOT

#: Seconds the GUI may take to start, run the macro and quit.
GUI_TIMEOUT = 180

#: Characters of each log told when FreeCAD ends without a verdict.
LOG_TAIL = 6000

MACRO = """
import faulthandler, json, os, sys, traceback
from PySide2 import QtCore
sys.path.insert(0, {root!r})
faults = open({faults!r}, "w")
faulthandler.enable(faults, all_threads=True)  # a crash writes every Python thread's stack there

def run():
    open({started!r}, "w").close()
    verdict = {{"ok": False}}
    try:
        import FreeCAD, FreeCADGui
{body}
        verdict["ok"] = True
    except Exception:
        verdict["error"] = traceback.format_exc()
    finally:
        with open({out!r}, "w") as handle:
            json.dump(verdict, handle)
        os._exit(0)

QtCore.QTimer.singleShot(1500, run)
"""


def run_macro(body, folder, screen="1280x1024", timeout=GUI_TIMEOUT):
    """The verdict (dict) of `body` (Python, sets keys of `verdict`) run inside the FreeCAD GUI, with HOME
    `folder`/home and the macro and its verdict in `folder`, on an X screen of `screen` pixels ("WxH"),
    failing after `timeout` seconds."""
    if shutil.which("xvfb-run") is None or shutil.which("freecad") is None:
        pytest.fail("the GUI tier needs xvfb-run and freecad (make deps installs them)")
    out, macro = folder / "verdict.json", folder / "macro.py"
    logs = {name: folder / f"{name}.txt" for name in ("started", "faults", "freecad", "xvfb")}
    macro.write_text(MACRO.format(root=ROOT, out=str(out), faults=str(logs["faults"]), started=str(logs["started"]),
                                  body=textwrap.indent(textwrap.dedent(body), " " * 8)))
    home = folder / "home"
    home.mkdir(exist_ok=True)
    env = dict(os.environ, HOME=str(home), QTWEBENGINE_DISABLE_SANDBOX="1")
    with open(logs["freecad"], "wb") as output:
        process = subprocess.Popen(["xvfb-run", "-a", "-e", str(logs["xvfb"]), "-s", f"-screen 0 {screen}x24",
                                    "freecad", str(macro)], env=env, cwd=folder, stdout=output,
                                   stderr=subprocess.STDOUT, start_new_session=True)
    try:
        process.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)  # xvfb-run, Xvfb and FreeCAD: nothing left running
        pytest.fail(f"the FreeCAD GUI did not finish in {timeout} s\n{told(logs)}")
    if not out.exists():
        when = "after the macro started, before its verdict" if logs["started"].exists() else "before the macro ran"
        pytest.fail(f"the FreeCAD GUI ended {when}: exit status {status(process.returncode)}\n{told(logs)}")
    verdict = json.loads(out.read_text())
    assert verdict["ok"], f"{verdict.get('error')}\nverdict so far: {str(verdict)[:4000]}"
    return verdict


def status(code):
    """xvfb-run's exit status `code` in words: FreeCAD's own, or the signal that ended FreeCAD (the shell's
    128 + N) or xvfb-run (-N)."""
    number = -code if code < 0 else code - 128 if code > 128 else None
    try:
        name = signal.Signals(number).name
    except ValueError:
        return str(code)
    return f"{code} ({'xvfb-run' if code < 0 else 'FreeCAD'} ended by {name})"


def told(logs):
    """The ends of the run's logs that exist and are not empty (faulthandler's stacks, FreeCAD's output,
    Xvfb's), LOG_TAIL characters each."""
    parts = []
    for name in ("faults", "freecad", "xvfb"):
        text = logs[name].read_text(errors="replace") if logs[name].exists() else ""
        if text.strip():
            parts.append(f"--- {name} (last {LOG_TAIL} characters) ---\n{text[-LOG_TAIL:]}")
    return "\n".join(parts) or "(no output, no crash stacks)"


@pytest.fixture
def run_gui(tmp_path):
    """run_gui(body, timeout=GUI_TIMEOUT) -> dict: run `body` (Python, sets keys of `verdict`) inside the
    FreeCAD GUI."""
    return lambda body, timeout=GUI_TIMEOUT: run_macro(body, tmp_path, timeout=timeout)
