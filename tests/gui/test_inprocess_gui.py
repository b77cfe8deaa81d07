"""The in-process stock in the real GUI: the dock's slider over the whole program, what earlier moves
changed at the chosen CL point, and the command "Show in-process stock" following the slider.

The program: two adjacent three-axis passes of a D12 tool over the model test 1 stock (stepover
8 mm, so the second pass meets what the first removed), tests/cad/test_inprocess_feature's.
"""

import os

from tests.cad.test_inprocess_feature import XS, write_two_passes
from tests.conftest import ROOT

STOCK = os.path.join(ROOT, "resources", "models", "model_test_1", "stock.json")


BODY = """
import numpy as np
from PySide import QtCore, QtGui

def key(widget, code, text="", modifiers=QtCore.Qt.NoModifier):
    for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
        QtGui.QApplication.sendEvent(widget, QtGui.QKeyEvent(kind, code, modifiers, text))

def wait(ms):
    until = QtCore.QTime.currentTime().addMSecs(ms)
    while QtCore.QTime.currentTime() < until:
        QtGui.QApplication.processEvents(QtCore.QEventLoop.AllEvents, 50)
from abm_workbench.features import create_engagement, create_stock, create_toolpath
from abm_workbench.gui import commands, dock, view_providers

FreeCADGui.activateWorkbench("ABMWorkbench")
doc = FreeCAD.newDocument("InProcess")
stock = create_stock(doc, {stock!r})
toolpath = create_toolpath(doc, {program!r})
engagement = create_engagement(doc, stock, toolpath, flutes=2, feed_per_tooth=0.1, phi_step=10.0)
for obj in (stock, toolpath, engagement):
    view_providers.attach(obj)
doc.recompute()
QtGui.QApplication.processEvents()
result, in_process = engagement.Proxy.result(engagement), engagement.Proxy.in_process(engagement)
verdict["cl_points"] = [result.shape[0], toolpath.CLPoints, engagement.ChangedCLPoints, engagement.StockModelUsed]
verdict["changed"] = np.flatnonzero(in_process.changed).tolist()

shown = commands.InspectEngagement.show(engagement, 0)
QtGui.QApplication.processEvents()
shown.slider.setFocus()
key(shown.slider, QtCore.Qt.Key_End)  # the slider's end: the program's last CL point
verdict["end"] = [shown.slider.maximum(), shown.spin.value()]
chosen = int(np.argmax(in_process.initial.max(axis=1) - result.length.max(axis=1)))
key(shown.spin, QtCore.Qt.Key_A, "", QtCore.Qt.ControlModifier)  # the CL point typed into the spin box
for char in str(chosen):
    key(shown.spin, ord(char), char)
key(shown.spin, QtCore.Qt.Key_Return)
QtGui.QApplication.processEvents()
verdict["chosen"] = [chosen, shown.spin.value(), shown.about.text(), float(result.length[chosen].max()),
                     float(in_process.initial[chosen].max())]
verdict["first"] = [bool(in_process.changed[0]), shown.title.text()]

# the command from the ABM menu, as a user picks it
menu = [m for m in FreeCADGui.getMainWindow().menuBar().findChildren(QtGui.QMenu) if m.title() == "ABM"][0]
action = [a for a in menu.actions() if a.text() == "Show in-process stock"][0]
action.trigger()
QtGui.QApplication.processEvents()
made = [o for o in doc.Objects if o.Name.startswith("InProcessStock")]
verdict["made"] = [len(made), made[0].CLPoint, made[0].Label, made[0].Shape.isValid(), made[0].Shape.Volume,
                   stock.Shape.Volume, made[0].RemovedVolume, stock.ViewObject.Visibility,
                   made[0].ViewObject.Visibility]
# the slider moves on: the stock follows once it rests
key(shown.slider, QtCore.Qt.Key_Left)
deadline = QtCore.QTime.currentTime().addSecs(60)
while made[0].CLPoint != chosen - 1 and QtCore.QTime.currentTime() < deadline:
    wait(100)
verdict["followed"] = [made[0].CLPoint, made[0].Label]
made[0].FollowDock = False  # now only the command moves it
key(shown.slider, QtCore.Qt.Key_Left)
wait(2000)
verdict["stayed"] = [made[0].CLPoint, shown.spin.value(), "Touched" in made[0].State]
view = FreeCADGui.ActiveDocument.ActiveView
view.viewIsometric()
view.fitAll()
wait(300)
view.saveImage({png!r}, 1000, 750, "White")
"""


def test_dock_and_in_process_stock(tmp_path, run_gui):
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"  # the workbench installed: its menu
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    program = tmp_path / "two_passes.apt"
    write_two_passes(program)
    png = tmp_path / "inprocess.png"
    verdict = run_gui(BODY.format(stock=STOCK, program=str(program), png=str(png)))
    m, points, changed_count, used = verdict["cl_points"]
    assert m == points == 2 * len(XS) and used == "in-process"
    # the second pass meets what the first removed; the first pass only its own earlier moves
    changed = verdict["changed"]
    assert changed_count == len(changed) and set(range(len(XS), m)) <= set(changed)
    assert verdict["end"] == [m - 1, m - 1]
    chosen, value, about, in_process, initial = verdict["chosen"]
    assert value == chosen and chosen in changed and initial > in_process
    assert (f"changed by earlier moves: longest length of cut in-process {in_process:.2f} mm / initial "
            f"{initial:.2f} mm") in about
    assert not verdict["first"][0]  # nothing is earlier than the program's first CL point
    title = verdict["first"][1]
    assert f"in-process stock: {changed_count} CL points changed by earlier moves" in title
    count, cl, label, valid, volume, stock_volume, removed, stock_visible, visible = verdict["made"]
    assert count == 1 and cl == chosen and label == f"In-process stock at CL {chosen}" and valid
    assert removed > 0.0 and abs(stock_volume - volume - removed) < 1e-6 * stock_volume
    assert not stock_visible and visible
    assert verdict["followed"] == [chosen - 1, f"In-process stock at CL {chosen - 1}"]
    assert verdict["stayed"] == [chosen - 1, chosen - 2, False]
    assert png.stat().st_size > 10000
