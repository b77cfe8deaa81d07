"""The in-process stock in the real GUI: the dock's slider over the whole program, what earlier moves
changed at the chosen CL point, and the command "Show in-process stock" following the slider.

The program: two adjacent three-axis passes of a D12 tool over the model test 1 stock (stepover
8 mm, so the second pass meets what the first removed), tests/cad/test_inprocess_feature's.
"""

import os

from tests.cad.test_inprocess_feature import XS, write_two_passes
from tests.conftest import ROOT
from tests.gui.events import EVENTS

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


RESPONSIVE = """
import time
import numpy as np
import shiboken2
from PySide2 import QtCore, QtGui, QtWidgets
from abm_workbench.cad.inprocess_boolean import cut_by_hulls, hulls_near
from abm_workbench.features import create_engagement, create_stock, create_toolpath
from abm_workbench.gui import commands, inprocess_view, view_providers
window = FreeCADGui.getMainWindow()
{events}
FreeCADGui.activateWorkbench("ABMWorkbench")
doc = FreeCAD.newDocument("Responsive")
stock = create_stock(doc, {stock!r})
toolpath = create_toolpath(doc, {program!r})
engagement = create_engagement(doc, stock, toolpath, flutes=2, feed_per_tooth=0.1, phi_step=10.0)
for obj in (stock, toolpath, engagement):
    view_providers.attach(obj)
doc.recompute()
settle()
shown = commands.InspectEngagement.show(engagement, 0)
settle()
chosen = {chosen}
shown.spin.setFocus()
key(shown.spin, QtCore.Qt.Key_A, "", QtCore.Qt.ControlModifier)  # the CL point typed into the spin box
for char in str(chosen):
    key(shown.spin, ord(char), char)
key(shown.spin, QtCore.Qt.Key_Return)
settle()
menu = [m for m in window.menuBar().findChildren(QtWidgets.QMenu) if m.title() == "ABM"][0]
action = [a for a in menu.actions() if a.text() == "Show in-process stock"][0]
report = window.findChild(QtWidgets.QDockWidget, "Report view").widget()
start = len(report.toPlainText())

ticks = []
heart = QtCore.QTimer()
heart.timeout.connect(lambda: ticks.append(time.perf_counter()))
heart.start(10)

def during(act, cancel):
    # act() with the GUI thread's ticks counted; with cancel, Cancel of the progress dialog clicked once it
    # shows a step of the booleans: (longest gap between ticks, seconds, Cancel to return, steps seen)
    seen = {{"steps": [], "clicked": None}}
    def watch():
        dialogs = [d for d in window.findChildren(QtWidgets.QProgressDialog)
                   if d.objectName() == "ABM_Engine" and shiboken2.isValid(d) and d.isVisible()]
        if dialogs and seen["clicked"] is None:
            seen["steps"].append([dialogs[0].value(), dialogs[0].maximum()])
            if cancel and dialogs[0].value() > 0:
                seen["clicked"] = time.perf_counter()
                press(dialogs[0].findChild(QtWidgets.QPushButton))
                return
        if not seen.get("over"):
            QtCore.QTimer.singleShot(20, watch)
    QtCore.QTimer.singleShot(20, watch)
    del ticks[:]
    started = time.perf_counter()
    act()
    ended = time.perf_counter()
    seen["over"] = True
    inside = [started] + [t for t in ticks if started <= t <= ended] + [ended]
    gaps = max(b - a for a, b in zip(inside, inside[1:]))
    return [gaps, ended - started, None if seen["clicked"] is None else ended - seen["clicked"], seen["steps"]]

def made():
    return [o for o in doc.Objects if o.Name.startswith("InProcessStock")]

# Cancel while a new in-process stock is computed: nothing is left
verdict["cancel_new"] = during(action.trigger, True) + [len(made())]
settle()
# the whole computation, the GUI ticking meanwhile
verdict["computed"] = during(action.trigger, False)
settle()
obj = made()[0]
moves, pieces, rows = obj.Proxy.sweep(obj)
reference = cut_by_hulls(stock.Shape, hulls_near((moves, pieces), int(rows[chosen]), None))  # here, on this thread
verdict["shape"] = [obj.CLPoint, obj.ProgramRow, int(rows[chosen]), obj.Shape.isValid(), obj.Shape.Volume,
                    reference.Volume, obj.RemovedVolume, stock.Shape.Volume - reference.Volume,
                    len(obj.Shape.Faces), len(reference.Faces), obj.State]
# the slider moves on, the stock follows: Cancel leaves it at its CL point, with its shape, not recomputed
volume, seconds = obj.Shape.Volume, obj.ComputeTime
def follow():
    # the key, then the event loop run until the Follower's timer has fired and its show_at returned
    shown.slider.setFocus()
    key(shown.slider, QtCore.Qt.Key_Left)
    pressed = time.perf_counter()
    while time.perf_counter() < pressed + 60 and (time.perf_counter() < pressed + 2 * inprocess_view.SETTLE_MS / 1000
                                                  or shown.in_process_follower.timer.isActive()):
        QtWidgets.QApplication.processEvents(QtCore.QEventLoop.AllEvents, 20)
verdict["cancel_follow"] = during(follow, True) + [obj.CLPoint, obj.Shape.Volume == volume, obj.State,
                                                   obj.Label, obj.ComputeTime == seconds]
doc.recompute()
settle()
verdict["after"] = [obj.CLPoint, obj.Shape.Volume == volume, obj.State, obj.ComputeTime == seconds]
heart.stop()
import multiprocessing
verdict["children"] = len(multiprocessing.active_children())
FreeCADGui.updateGui()
verdict["report"] = report.toPlainText()[start:]
"""


def test_in_process_stock_keeps_the_gui_responsive_and_cancels(tmp_path, run_gui):
    """The in-process stock's booleans run in a worker process: the GUI thread's 10 ms timer keeps ticking
    (no gap over 1 s; the booleans and the process's start take seconds), the progress dialog shows the
    hull solids built, Cancel clicked on it returns within 0.5 s and leaves nothing (a new object removed,
    an earlier one at its CL point with its shape, not recomputed again); the shape computed equals the
    same booleans run on the GUI thread."""
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    program = tmp_path / "two_passes.apt"
    write_two_passes(program)
    chosen = len(XS) + 3  # the second pass, beside what the first removed
    verdict = run_gui(RESPONSIVE.format(stock=STOCK, program=str(program), chosen=chosen, events=EVENTS))
    gap, seconds, answered, steps, left = verdict["cancel_new"]
    assert answered is not None and answered < 0.5 and left == 0, verdict["cancel_new"]
    assert gap < 1.0, verdict["cancel_new"]
    gap, seconds, answered, steps = verdict["computed"]
    assert answered is None and gap < 1.0 and seconds > 2 * gap, verdict["computed"]
    assert steps and steps[-1][1] > 2 and any(value > 0 for value, _ in steps), steps  # hulls, fuse, cut
    cl, row, reference_row, valid, volume, reference, removed, reference_removed, faces, reference_faces, state = \
        verdict["shape"]
    assert cl == chosen and row == reference_row and valid and "Invalid" not in state
    assert volume == reference and removed == reference_removed and faces == reference_faces, verdict["shape"]
    assert removed > 0.0
    gap, seconds, answered, steps, cl, same, state, label, kept = verdict["cancel_follow"]
    assert answered is not None and answered < 0.5 and gap < 1.0, verdict["cancel_follow"]
    assert cl == chosen and same and label == f"In-process stock at CL {chosen}", verdict["cancel_follow"]
    assert state == ["Up-to-date"] and kept, verdict["cancel_follow"]  # its shape, no booleans run again
    assert verdict["after"] == [chosen, True, ["Up-to-date"], True], verdict["after"]
    assert verdict["children"] == 0
    assert "Traceback" not in verdict["report"], verdict["report"]
