"""The engagement's task panel driven as a user drives it: key events typed into the fields and mouse
clicks on OK and Cancel (QKeyEvent / QMouseEvent sent to the widgets, as QTest does), undo and redo
by FreeCAD's own commands, selection in the 3D view.

Each check is one fault found that way: Cancel after a failed OK, the deleted button box after a
typed-then-OK edit, stale results after undo / redo, letters in a quantity field, a panel wider
than the combo view, selection painting over the colour map; and a panel refused now and then
after an OK (its fields made where the closed dialog's widgets were, whose Python wrappers were
still registered there), provoked every time by the second test.
"""

import os

import pytest

from tests.conftest import ROOT
from tests.gui.events import EVENTS

MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")

#: Shared by the macros: the report view, the input events, model test 1's engagement, open_panel().
SETUP = """
import hashlib
import numpy as np
import shiboken2
from PySide import QtCore, QtGui
QtWidgets = QtGui
window = FreeCADGui.getMainWindow()
report = window.findChild(QtWidgets.QDockWidget, "Report view").widget()
def report_since(start):
    FreeCADGui.updateGui()
    return report.toPlainText()[start:]
{events}
FreeCADGui.activateWorkbench("ABMWorkbench")
from abm_workbench.gui import commands, dock, task_panel
from abm_workbench.gui.screenshots import grab_screen
doc = FreeCAD.newDocument("Faults")
stock = commands.ImportStock().execute(os.path.join({model!r}, "stock.json"))
path = commands.ImportToolpath().execute(os.path.join({model!r}, "toolpath.csv"))
engagement = commands.ComputeEngagement().execute(
    dict(diameter=12, flutes=2, flute_length=30, feed_per_tooth=0.1, inclination=10, phi_step=10), [stock, path])
shown_dock = dock.find()
settle()

def open_panel():
    FreeCADGui.ActiveDocument.setEdit(engagement, 0)
    settle()
    if task_panel.shown() is None:
        raise AssertionError("setEdit opened no task panel; the report view says:\\n" + report_since(start)[-3000:])
    return task_panel.shown()
"""

BODY = SETUP + """
def snapshot():
    result = engagement.Proxy.result(engagement)
    vobj = engagement.ViewObject
    return {{"diameter": engagement.Diameter.Value, "phi_end": engagement.PhiEnd.Value,
            "phi_step": engagement.PhiStep.Value, "state": engagement.State, "instants": engagement.Instants,
            "result": None if result is None else [result.phi.tolist(), round(float(np.nansum(result.length)), 9),
                                                    hashlib.sha256(np.round(result.length, 9).tobytes()).hexdigest()],
            "faces": 0 if vobj.Proxy.mesh is None else len(vobj.Proxy.mesh.points),
            "colours": hashlib.sha256(np.round(np.reshape(vobj.Proxy.colours, (-1, 3)), 6).tobytes()).hexdigest(),
            "coloured": 0 if vobj.Proxy.colours is None else len(vobj.Proxy.colours),
            "undo": list(doc.UndoNames), "redo": list(doc.RedoNames),
            "dock": [shown_dock.obj is engagement, shown_dock.spin.maximum(), shown_dock.about.text(),
                     [float(v) for v in shown_dock.figure.axes[0].get_xlim()]]}}

# ---- (a) Cancel after a failed OK restores the object, its results and the view ------------------
start = len(report.toPlainText())
dock.show(engagement)
settle()
before = snapshot()
panel = open_panel()
retype("Diameter", "500")
verdict["typed_500"] = [panel.number("Diameter"), button("OK").isEnabled()]
click("OK")
verdict["failed_ok"] = [task_panel.shown() is panel, bool(panel.message.text()), "Invalid" in engagement.State]
click("Cancel")
verdict["cancelled"] = [task_panel.shown() is None, FreeCADGui.ActiveDocument.getInEdit() is None]
verdict["before_cancel"], verdict["after_cancel"] = before, snapshot()
verdict["report_cancel"] = report_since(start)

# ---- (b) typed-then-OK edits: no deleted button box --------------------------------------------
start = len(report.toPlainText())
edits = (("Inclination", "5"), ("PhiStep", "20"), ("FeedPerTooth", "0.2"), ("Diameter", "10"),
         ("FluteLength", "25"), ("PhiEnd", "160"))
applied = []
for name, text in edits:
    open_panel()
    retype(name, text)
    click("OK")
    applied.append([task_panel.shown() is None, float(getattr(engagement, name).Value), engagement.State])
verdict["applied"] = applied
verdict["report_edits"] = report_since(start)

# ---- (c) undo and redo by FreeCAD's commands: results, colours and the dock follow -------------------
start = len(report.toPlainText())
edited = snapshot()
FreeCADGui.runCommand("Std_Undo")
settle()
undone = snapshot()
engagement.touch()
doc.recompute()
settle()
verdict["undone"], verdict["undone_recomputed"] = undone, snapshot()
FreeCADGui.runCommand("Std_Redo")
settle()
redone = snapshot()
engagement.touch()
doc.recompute()
settle()
verdict["edited"], verdict["redone"], verdict["redone_recomputed"] = edited, redone, snapshot()
verdict["report_undo"] = report_since(start)

# ---- (d) letters in a quantity field: refused in plain words, OK disabled -----------------------------
start = len(report.toPlainText())
panel = open_panel()
retype("Diameter", "1x2")
verdict["letters_panel"] = [task_panel.shown() is panel, task_panel.shown() is None]
verdict["letters"] = [panel.field("Diameter").text(), panel.message.text(), button("OK").isEnabled(),
                      bool(panel.field("Diameter").styleSheet())]
key(task_panel.shown().field("Diameter"), QtCore.Qt.Key_Return, "\\r")
settle()
verdict["letters_enter"] = [task_panel.shown() is panel, engagement.Diameter.Value]
retype("Diameter", "12")
verdict["letters_fixed"] = [panel.message.text(), button("OK").isEnabled(), bool(panel.field("Diameter").styleSheet())]

# ---- (e) the panel fits the combo view: no horizontal scrolling, nothing clipped ---------------------
retype("Diameter", "-3")
scroll = panel.form.parentWidget()
while scroll is not None and not isinstance(scroll, QtWidgets.QScrollArea):
    scroll = scroll.parentWidget()
viewport = scroll.viewport()
def right_edge(widget):
    return widget.mapTo(viewport, QtCore.QPoint(widget.width(), 0)).x()
visible = [w for w in panel.form.findChildren(QtWidgets.QWidget) if w.isVisible() and w.width() > 0]
verdict["fits"] = [viewport.width(), scroll.horizontalScrollBar().isVisible(),
                   max(right_edge(w) for w in visible), right_edge(panel.message),
                   panel.message.text(), panel.message.height() > panel.message.fontMetrics().height()]
for folder in {folders!r}:
    os.makedirs(folder, exist_ok=True)
    grab_screen(os.path.join(folder, "task_panel_fits.png"))
click("Cancel")
verdict["report_letters"] = report_since(start)

# ---- (f) selecting the engagement keeps its colour map --------------------------------------------------
view = FreeCADGui.ActiveDocument.ActiveView
view.viewIsometric()
view.fitAll()
FreeCADGui.Selection.clearSelection()
settle()
def view_pixels(name):
    settle()
    view.redraw()
    settle()
    widget = view.graphicsView()
    corner = widget.mapToGlobal(QtCore.QPoint(0, 0))
    image = QtWidgets.QApplication.primaryScreen().grabWindow(0, corner.x(), corner.y(), widget.width(),
                                                              widget.height()).toImage()
    image = image.convertToFormat(QtGui.QImage.Format_RGB888)
    for folder in {folders!r}:
        image.save(os.path.join(folder, name + ".png"))
    data = bytes(image.constBits())[:image.bytesPerLine() * image.height()]
    rows = np.frombuffer(data, dtype=np.uint8).reshape(image.height(), image.bytesPerLine())
    return rows[:, :3 * image.width()].reshape(image.height(), image.width(), 3).astype(int)
plain = view_pixels("engagement_plain")
FreeCADGui.Selection.addSelection(engagement)
selected = view_pixels("engagement_selected")
FreeCADGui.Selection.clearSelection()
def green(pixels):
    r, g, b = pixels[..., 0], pixels[..., 1], pixels[..., 2]
    return int(np.count_nonzero((g > r + 60) & (g > b + 60)))
engagement.ViewObject.Visibility = False
hidden = view_pixels("engagement_hidden")
engagement.ViewObject.Visibility = True
surface = np.any(plain != hidden, axis=2)  # where the engagement is drawn
changed = np.any(plain != selected, axis=2)
verdict["selection"] = [int(np.count_nonzero(surface)), green(plain[surface]), green(selected[surface]),
                        int(np.count_nonzero(changed & surface)), engagement.ViewObject.SelectionStyle]
"""


def run_body(tmp_path, run_gui, body):
    """The verdict of the macro `body` run once in the real GUI (the workbench linked into the test HOME)."""
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    folders = [str(tmp_path / "shots"), os.path.join(ROOT, "build", "screenshots")]
    return run_gui(body.format(model=MODEL, folders=folders, events=EVENTS))


@pytest.fixture
def verdict(tmp_path, run_gui):
    """The verdict of BODY run once in the real GUI."""
    return run_body(tmp_path, run_gui, BODY)


def clean(text):
    """True when the report view text has no error, traceback or deleted Qt object in it."""
    return not any(word in text for word in ("Traceback", "RuntimeError", "already deleted", "rror"))


def test_typed_keys_cancel_undo_letters_width_and_selection(verdict):
    # (a) a diameter of 500 mm passes the panel's check, but the tool then never touches the stock:
    # OK fails and says why; Cancel then gives back the object, its results, its colours and the
    # dock exactly as before, and leaves no undo step
    assert verdict["typed_500"] == [500.0, True]
    assert verdict["failed_ok"] == [True, True, True]
    assert verdict["cancelled"] == [True, True]
    before, after = verdict["before_cancel"], verdict["after_cancel"]
    assert before["state"] == ["Up-to-date"] and before["result"] is not None
    assert after == before
    # (b) six edits typed, then OK clicked: each applied, nothing red in the report view
    assert [row[0] for row in verdict["applied"]] == [True] * 6
    assert [row[1] for row in verdict["applied"]] == [5.0, 20.0, 0.2, 10.0, 25.0, 160.0]
    assert all(row[2] == ["Up-to-date"] for row in verdict["applied"])
    assert clean(verdict["report_edits"]), verdict["report_edits"]
    # (c) undo / redo: the results, colours and dock are those a recompute of the restored
    # properties gives (the reference), at once
    undone, edited = verdict["undone"], verdict["edited"]
    assert undone["phi_end"] == 180.0 and edited["phi_end"] == 160.0
    assert undone["result"][0][-1] == 180.0 and edited["result"][0][-1] == 160.0
    for state in ("undone", "redone"):
        restored, reference = dict(verdict[state]), dict(verdict[state + "_recomputed"])
        assert restored["faces"] == restored["coloured"] > 0, state
        for key in ("undo", "redo", "state"):  # a recompute of its own: not compared
            restored.pop(key), reference.pop(key)
        assert restored == reference, state
    redone = dict(verdict["redone"])
    assert redone["result"] == edited["result"] and redone["dock"] == edited["dock"]
    assert clean(verdict["report_undo"]), verdict["report_undo"]
    # (d) letters: the value is refused in plain words, the field marked, OK and Enter do nothing
    shown, message, ok, marked = verdict["letters"]
    assert shown == "1x2"  # kept as typed
    assert message == ("Tool diameter: “1x2” is not a length: type a number, with a unit if you like "
                       "(12 mm, 0.5 in).")
    assert not ok and marked
    assert verdict["letters_enter"] == [True, 10.0]
    assert verdict["letters_fixed"] == ["", True, False]
    # (e) the panel within the combo view: no horizontal scroll bar, no field or message past its edge,
    # the message wrapped onto several lines
    width, scrolling, widest, message_edge, message, wrapped = verdict["fits"]
    assert not scrolling and widest <= width and message_edge <= width, verdict["fits"]
    assert message == "Tool diameter must be positive, got -3 mm." and wrapped
    assert clean(verdict["report_letters"]), verdict["report_letters"]
    # (f) selected, the surface keeps its colours: no selection green over it, its pixels unchanged
    # (found as those that change when it is hidden); the bounding box drawn around it is not on it
    surface, green_plain, green_selected, changed, style = verdict["selection"]
    assert surface > 2000 and green_selected <= green_plain + 0.05 * surface, verdict["selection"]
    assert changed <= 0.05 * surface, verdict["selection"]


STALE_BODY = SETUP + """
start = len(report.toPlainText())

# Each quantity field, and the line edit in it, made where a deleted button box was whose wrapper is
# still held: a wrapper of that class registered at its address, as the allocator's reuse leaves it.
stale = []
def stale_at(wrapper):
    address = shiboken2.getCppPointer(wrapper)[0]
    shiboken2.invalidate(wrapper)  # unregistered (the object lives on)
    stale.append(shiboken2.wrapInstance(address, QtWidgets.QDialogButtonBox))
    return address
made = task_panel._spin_box
def spin_box_where_a_box_was(unit, *args, **keywords):
    widget = made(unit, *args, **keywords)
    if unit is None:
        return widget
    stale_at(widget.findChild(QtWidgets.QLineEdit))
    return shiboken2.wrapInstance(stale_at(widget), QtWidgets.QAbstractSpinBox)  # as FreeCAD hands it over
task_panel._spin_box = spin_box_where_a_box_was
try:
    panel = open_panel()
finally:
    task_panel._spin_box = made
verdict["stale"] = len(stale)
verdict["field"] = [type(panel.field("Diameter")).__name__,
                    type(panel.field("Diameter").findChild(QtWidgets.QLineEdit)).__name__]
retype("Diameter", "1x2")
verdict["letters"] = [panel.message.text(), button("OK").isEnabled()]
retype("Diameter", "11")
click("OK")
verdict["applied"] = [task_panel.shown() is None, engagement.Diameter.Value, engagement.State]
verdict["report"] = report_since(start)
"""


def test_panel_opens_where_deleted_widgets_left_their_wrappers(tmp_path, run_gui):
    # A field made at the address of a deleted widget whose Python wrapper is still registered there
    # (the CI failure: after an OK, the next setEdit opened no panel): the panel lets the stale wrappers
    # go, opens, checks typed text and applies it
    verdict = run_body(tmp_path, run_gui, STALE_BODY)
    # 13 fields of lengths and angles (diameter, flute length, corner radius, helix angle, feed per tooth,
    # inclination, φ start, end and step, y window from and to, immersion from and to) and their line edits
    assert verdict["stale"] == 2 * 13
    assert verdict["field"] == ["NumberField", "QLineEdit"]  # the panel's own field found, not a button box
    assert verdict["letters"] == ["Tool diameter: “1x2” is not a length: type a number, with a unit if you like "
                                  "(12 mm, 0.5 in).", False]
    assert verdict["applied"] == [True, 11.0, ["Up-to-date"]]
    assert clean(verdict["report"]), verdict["report"]
