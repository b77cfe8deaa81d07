"""Instant edits in the real FreeCAD GUI, driven by key events and mouse clicks: the engaged surface
is one Coin mesh (drawn, hidden, kept coloured when selected), a recompute that fails on bad input
says so in plain words without a Python traceback in the report view, and a long recompute runs
its engine in a worker thread whose progress dialog's Cancel stops it, the GUI drawn meanwhile.
"""

import os
import re

import pytest

from tests.conftest import ROOT
from tests.gui.events import EVENTS

MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")

BODY = """
import hashlib, sys, time
import numpy as np
import shiboken2
from pivy import coin
from PySide import QtCore, QtGui
QtWidgets = QtGui
window = FreeCADGui.getMainWindow()
report = window.findChild(QtWidgets.QDockWidget, "Report view").widget()
def report_since(start):
    FreeCADGui.updateGui()
    return report.toPlainText()[start:]
{events}
def open_panel():
    FreeCADGui.ActiveDocument.setEdit(engagement, 0)
    settle()
    return task_panel.shown()

FreeCADGui.activateWorkbench("ABMWorkbench")
from abm_workbench.gui import commands, dock, task_panel
doc = FreeCAD.newDocument("Instant")
stock = commands.ImportStock().execute(os.path.join({model!r}, "stock.json"))
path = commands.ImportToolpath().execute(os.path.join({model!r}, "toolpath.csv"))
engagement = commands.ComputeEngagement().execute(
    dict(diameter=12, flutes=2, flute_length=30, feed_per_tooth=0.1, inclination=10, phi_step=10), [stock, path])
settle()
provider = engagement.ViewObject.Proxy
def fingerprint():
    result = engagement.Proxy.result(engagement)
    return [engagement.PhiStep.Value, engagement.State, engagement.Instants,
            None if result is None else hashlib.sha256(np.round(result.length, 9).tobytes()).hexdigest(),
            None if provider.mesh is None else len(provider.mesh.triangles), list(doc.UndoNames)]

# ---- the mesh: one Coin node in the view provider, drawn while visible -------------------------------
drawn = lambda: provider.surface.whichChild.getValue() == coin.SO_SWITCH_ALL
verdict["mesh"] = [len(provider.mesh.triangles), len(provider.mesh.points), len(provider.colours), drawn(),
                   len(engagement.Shape.Faces), len(engagement.Shape.Edges) > 0]
engagement.ViewObject.Visibility = False
settle()
hidden = drawn()
engagement.ViewObject.Visibility = True
settle()
verdict["visibility"] = [hidden, drawn()]
view = FreeCADGui.ActiveDocument.ActiveView
view.viewIsometric()
view.fitAll()
for folder in {folders!r}:
    os.makedirs(folder, exist_ok=True)
    FreeCADGui.Selection.clearSelection()
    settle()
    view.saveImage(os.path.join(folder, "mesh_plain.png"), 800, 600, "White")
    FreeCADGui.Selection.addSelection(engagement)
    settle()
    view.saveImage(os.path.join(folder, "mesh_selected.png"), 800, 600, "White")
    FreeCADGui.Selection.clearSelection()

# ---- bad input: plain words in the report view, no traceback, the object marked Invalid ---------------
start = len(report.toPlainText())
panel = open_panel()
retype("Diameter", "500")
click("OK")
verdict["bad_ok"] = [task_panel.shown() is panel, panel.message.text(), engagement.State,
                     engagement.getStatusString(), hasattr(sys, "tracebacklimit")]
click("Cancel")
engagement.Flutes = 0  # outside the panel: a plain recompute
doc.recompute()
settle()
verdict["bad_recompute"] = [engagement.State, engagement.getStatusString(), hasattr(sys, "tracebacklimit")]
engagement.Flutes = 2
doc.recompute()
settle()
verdict["report_bad"] = report_since(start)
verdict["restored"] = engagement.State

# ---- a long recompute: the engine in a worker thread, progress shown, Cancel stops it ----------------
before = fingerprint()
start = len(report.toPlainText())
seen = {{"ticks": 0, "progress": [], "cancelled_at": None, "label": ""}}
def watch():
    # runs from the GUI thread's event loop while the recompute waits for the worker
    seen["ticks"] += 1
    dialogs = [d for d in window.findChildren(QtWidgets.QProgressDialog)
               if d.objectName() == "ABM_Engine" and shiboken2.isValid(d) and d.isVisible()]
    if dialogs and seen["cancelled_at"] is None:
        seen["progress"].append([dialogs[0].value(), dialogs[0].maximum()])
        seen["label"] = dialogs[0].labelText()
        if len(seen["progress"]) >= 3 and dialogs[0].value() > 0:
            seen["cancelled_at"] = time.perf_counter()
            press(dialogs[0].findChild(QtWidgets.QPushButton))
            return
    if seen["ticks"] < 4000:
        QtCore.QTimer.singleShot(25, watch)
panel = open_panel()
retype("PhiStep", "0.005")
QtCore.QTimer.singleShot(25, watch)
started = time.perf_counter()
click("OK")
ended = time.perf_counter()
verdict["worker"] = [seen["cancelled_at"] is not None, seen["progress"][:1], seen["progress"][-1:],
                     None if seen["cancelled_at"] is None else ended - seen["cancelled_at"], ended - started,
                     task_panel.shown() is panel, panel.message.text(), engagement.State]
click("Cancel")
settle()
verdict["label"] = seen["label"]
verdict["after_cancel"] = [before, fingerprint(), task_panel.shown() is None]
verdict["report_worker"] = report_since(start)
"""


@pytest.fixture
def verdict(tmp_path, run_gui):
    """The verdict of BODY run once in the real GUI (the workbench linked into the test HOME)."""
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    folders = [str(tmp_path / "shots"), os.path.join(ROOT, "build", "screenshots")]
    return run_gui(BODY.format(model=MODEL, folders=folders, events=EVENTS))


def test_mesh_plain_errors_and_a_cancellable_worker(verdict):
    # one mesh: thousands of triangles, every vertex coloured; the Shape is the outline (no faces)
    triangles, points, colours, drawn, faces, edges = verdict["mesh"]
    assert triangles > 1000 and points == colours > 1000 and drawn and faces == 0 and edges
    assert verdict["visibility"] == [False, True]
    # bad input: the panel and the report view say it in plain words; no traceback; Invalid
    stays, message, state, status, limit = verdict["bad_ok"]
    assert stays and "never touches the stock" in message and "Invalid" in state
    assert "never touches the stock" in status and not limit
    state, status, limit = verdict["bad_recompute"]
    assert "Invalid" in state and "Number of flutes" in status and not limit, verdict["bad_recompute"]
    report = verdict["report_bad"]
    assert "Traceback" not in report and 'File "' not in report, report
    assert "never touches the stock" in report and "Number of flutes" in report, report
    assert verdict["restored"] == ["Up-to-date"]
    # the worker: the GUI thread ran its event loop during the recompute (the watcher saw the dialog and
    # its progress), Cancel ended the recompute within a second, the panel says so and stays open
    cancelled, first, last, after_cancel, total, stays, message, state = verdict["worker"]
    assert cancelled, verdict["worker"]
    assert last[0][1] == 53 and 0 < last[0][0] < 53, verdict["worker"]
    assert after_cancel < 1.0, verdict["worker"]
    assert stays and "cancelled" in message and "Invalid" in state, verdict["worker"]
    # the dialog says how many CL points are done and estimates the time left
    estimate = re.fullmatch(r"Computing the engagement…\n(\d+) of 53 CL points, about (\d+ min )?\d+ s left",
                            verdict["label"])
    assert estimate and int(estimate.group(1)) == last[0][0], verdict["label"]
    # the panel's Cancel then gives back the object as it was, with no undo step
    before, after, closed = verdict["after_cancel"]
    assert after == before and closed
    assert "Traceback" not in verdict["report_worker"], verdict["report_worker"]
