"""GUI tier: the real FreeCAD GUI under Xvfb, driven by a macro that writes a JSON verdict.

FREECAD_NOTES: run as `xvfb-run -a freecad macro.py` with HOME isolated and the Qt WebEngine
sandbox off; a macro that raises would leave the GUI open, so the macro always ends with
os._exit and the run has a timeout, after which the whole process group (xvfb-run, Xvfb,
FreeCAD) is killed.
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

MACRO = """
import json, os, sys, traceback
from PySide2 import QtCore
sys.path.insert(0, {root!r})

def run():
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
    macro.write_text(MACRO.format(root=ROOT, out=str(out), body=textwrap.indent(textwrap.dedent(body), " " * 8)))
    home = folder / "home"
    home.mkdir(exist_ok=True)
    env = dict(os.environ, HOME=str(home), QTWEBENGINE_DISABLE_SANDBOX="1")
    process = subprocess.Popen(["xvfb-run", "-a", "-s", f"-screen 0 {screen}x24", "freecad", str(macro)],
                               env=env, cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                               start_new_session=True)
    try:
        process.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)  # xvfb-run, Xvfb and FreeCAD: nothing left running
        pytest.fail(f"the FreeCAD GUI did not finish in {timeout} s")
    assert out.exists(), "the FreeCAD GUI ended without running the macro"
    verdict = json.loads(out.read_text())
    assert verdict["ok"], f"{verdict.get('error')}\nverdict so far: {str(verdict)[:4000]}"
    return verdict


@pytest.fixture
def run_gui(tmp_path):
    """run_gui(body, timeout=GUI_TIMEOUT) -> dict: run `body` (Python, sets keys of `verdict`) inside the
    FreeCAD GUI."""
    return lambda body, timeout=GUI_TIMEOUT: run_macro(body, tmp_path, timeout=timeout)
