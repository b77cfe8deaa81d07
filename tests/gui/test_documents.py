"""Portable documents in the real GUI: an FCStd copied alone reopens with its results and colours
without a recompute; input files that moved are re-pointed in one dialog (the folder's name entered
in it and accepted: Qt's own file dialog did not take typed keys or a click on Choose from the
events the other GUI tests send)."""

import os
import shutil

from tests.conftest import ROOT

MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")

BODY = """
import hashlib, shutil
import numpy as np
from PySide import QtCore, QtGui
from abm_workbench.features import engagement as engagement_module
def settle():
    for _ in range(5):
        FreeCADGui.updateGui()
def key(widget, code, text=""):
    for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
        QtGui.QApplication.sendEvent(widget, QtGui.QKeyEvent(kind, code, QtCore.Qt.NoModifier, text))
def digest(obj):
    result = obj.Proxy.result(obj)
    return None if result is None else hashlib.sha256(np.round(result.length, 12).tobytes()).hexdigest()

asked = []
FreeCADGui.activateWorkbench("ABMWorkbench")
from abm_workbench.gui import commands
doc = FreeCAD.newDocument("Portable")
stock = commands.ImportStock().execute(os.path.join({inputs!r}, "stock.json"))
path = commands.ImportToolpath().execute(os.path.join({inputs!r}, "toolpath.csv"))
engagement = commands.ComputeEngagement().execute(
    dict(diameter=12, flutes=2, flute_length=30, feed_per_tooth=0.1, inclination=10, phi_step=10), [stock, path])
settle()
before = [digest(engagement), len(engagement.ViewObject.Proxy.colours)]
doc.saveAs({saved!r})
FreeCAD.closeDocument(doc.Name)
settle()
# only the FCStd is copied; the input files move elsewhere
os.makedirs(os.path.dirname({alone!r}))
shutil.copyfile({saved!r}, {alone!r})
shutil.move({inputs!r}, {moved!r})

calls = []
def counting(engine):
    def counted(*args, **kwargs):
        calls.append(1)
        return engine(*args, **kwargs)
    return counted
engagement_module.flute_1 = counting(engagement_module.flute_1)  # against the stock as given
engagement_module.engage_in_process = counting(engagement_module.engage_in_process)  # against the in-process one
def answer(tries=[0]):
    dialogs = [w for w in QtGui.QApplication.topLevelWidgets() if w.objectName() == "ABM_Repoint" and w.isVisible()]
    tries[0] += 1
    if not dialogs:
        if tries[0] < 300:
            QtCore.QTimer.singleShot(100, answer)
        return
    dialog = dialogs[0]
    asked.append(dialog.windowTitle())
    opened = [d for d in FreeCAD.listDocuments().values() if d.FileName == {alone!r}][0].getObject("Engagement")
    verdict["at_dialog"] = [len(calls), digest(opened) == before[0], opened.State]
    try:
        dialog.findChild(QtGui.QLineEdit, "fileNameEdit").setText({moved!r})  # the folder's name entered
        dialog.accept()
    except Exception as error:
        asked.append(repr(error))
        dialog.reject()
QtCore.QTimer.singleShot(100, answer)
reopened = FreeCAD.openDocument({alone!r})
engagement = reopened.getObject("Engagement")
verdict["reopened"] = [digest(engagement) == before[0], engagement.State, len(calls)]
import time
waited = time.perf_counter()
while time.perf_counter() - waited < 60:  # the dialog comes once the document is restored
    settle()
    if asked and reopened.getObject("Stock").SourceFile.startswith({moved!r}):
        break
    time.sleep(0.05)
settle()
verdict["asked"] = asked
verdict["recomputed"] = len(calls)
verdict["repointed"] = [reopened.getObject("Stock").SourceFile, reopened.getObject("Toolpath").File,
                        [o.State for o in reopened.Objects], digest(engagement) == before[0],
                        len(engagement.ViewObject.Proxy.colours) == before[1]
                        == len(engagement.ViewObject.Proxy.mesh.points)]
"""


def test_an_fcstd_copied_alone_reopens_with_results_and_moved_inputs_are_repointed(tmp_path, run_gui):
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    inputs = tmp_path / "project" / "inputs"
    inputs.mkdir(parents=True)
    for name in ("stock.json", "toolpath.csv"):
        shutil.copyfile(os.path.join(MODEL, name), inputs / name)
    moved = tmp_path / "somewhere" / "else"
    moved.parent.mkdir()

    verdict = run_gui(BODY.format(inputs=str(inputs), saved=str(tmp_path / "project" / "job.FCStd"),
                                  alone=str(tmp_path / "copy" / "job.FCStd"), moved=str(moved)))

    # the copy alone, as the dialog opens: the results of the saved document, the engine not run
    assert verdict["at_dialog"] == [0, True, ["Up-to-date"]]
    # as openDocument returns: the same results; the recompute the re-pointing asks for may already be done
    # (FreeCAD handles events while it loads, so when it runs depends on timing), never more than once
    assert verdict["reopened"][:2] == [True, ["Up-to-date"]] and verdict["reopened"][2] <= 1
    # one dialog for the two missing files, the folder typed into it: both re-pointed, all valid again
    assert len(verdict["asked"]) == 1 and "(2)" in verdict["asked"][0]
    stock_file, toolpath_file, states, same, coloured = verdict["repointed"]
    assert (stock_file, toolpath_file) == (str(moved / "stock.json"), str(moved / "toolpath.csv"))
    assert states == [["Up-to-date"]] * 3 and same and coloured
    assert verdict["recomputed"] == 1  # the files re-pointed: recomputed once from them, the same results
