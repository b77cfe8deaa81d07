"""User actions that showed a Python traceback, or left the GUI showing what was gone, each driven as a
user does it: toolbar buttons clicked, file names typed into the file dialogs, choices made with keys.

- Import toolpath on G-code that loads tools by number (M6 T1): a tool table asked for; Escape imports
  nothing and says why in words (it was a traceback naming the command line's ``--tool-table``).
- Import toolpath on model test 3's program.apt (two operations): the operation asked for in a dialog
  (it was a traceback: "holds several operations").
- Import stock with a sphere selected: refused in words (a traceback from the recognition).
- A document reopened without its input files: Inspect, double-click and Escape (Escape was a traceback
  from the highlight reading the missing toolpath file; Inspect failed for the same reason).
- Undo of "Open model test 1" (the toolbar's Undo): the dock no longer shows the removed engagement.
"""

import os

from tests.conftest import ROOT
from tests.gui.dialogs import DIALOGS
from tests.gui.events import EVENTS

MODEL_1 = os.path.join(ROOT, "resources", "models", "model_test_1")
PROGRAM_3 = os.path.join(ROOT, "resources", "models", "model_test_3", "program.apt")

GCODE = """G21 G90 G17
T1 M6
S4000 M3
G0 X-10 Y0 Z5
G1 Z-2 F400
G1 X50 Y0
G1 X50 Y10
G0 Z5
M30
"""
#: A LinuxCNC tool table naming tool 1: a D10 flat-end mill.
TOOL_TABLE = "T1 P1 D10.0 Z0 ;flat end mill\n"

SETUP = """
import json, shutil, time
import shiboken2
from PySide import QtCore, QtGui
QtWidgets = QtGui
window = FreeCADGui.getMainWindow()
report = window.findChild(QtWidgets.QDockWidget, "Report view").widget()
def report_since(start):
    FreeCADGui.updateGui()
    return report.toPlainText()[start:]
{events}
{dialogs}
FreeCADGui.activateWorkbench("ABMWorkbench")
from abm_workbench.gui import commands, dock, task_panel
settle()
def stuck():  # a dialog left open: say which, and end
    verdict["stuck"] = [(type(w).__name__, w.objectName(), w.windowTitle())
                        for w in QtWidgets.QApplication.topLevelWidgets() if w.isVisible()]
    verdict["report"] = report.toPlainText()[-3000:]
    with open({out!r}, "w") as handle:
        json.dump(verdict, handle)
    os._exit(0)
QtCore.QTimer.singleShot(60000, stuck)
"""

IMPORTS = SETUP + """
doc = FreeCAD.newDocument("Imports")
settle()
def tool_table_dialog():
    dialog = top(QtWidgets.QFileDialog)
    return dialog if dialog is not None and dialog.windowTitle().startswith("Tool table of") else None

# ---- G-code loading tool 1: the tool table asked for; Escape: nothing made, said in words -----------------
start = len(report.toPlainText())
when_shown(lambda: top(QtWidgets.QFileDialog), choose_file({ngc!r}))
when_shown(lambda: tool_table_dialog(), escape)
press(toolbar_button("ABM_ImportToolpath"))
settle()
verdict["gcode_escaped"] = [[o.Name for o in doc.Objects], report_since(start)]
# again, the tool table chosen: the toolpath made, with the table's tool
start = len(report.toPlainText())
when_shown(lambda: top(QtWidgets.QFileDialog), choose_file({ngc!r}))
when_shown(lambda: tool_table_dialog(), choose_file({table!r}))
press(toolbar_button("ABM_ImportToolpath"))
settle()
made = [o for o in doc.Objects if o.Name.startswith("Toolpath")]
verdict["gcode"] = [len(made), made[0].ToolTable if made else None, made[0].ToolDiameter.Value if made else None,
                    made[0].State if made else None, report_since(start)]

# ---- program.apt of two operations: the operation chosen in a dialog (the second, by the Down key) --------
start = len(report.toPlainText())
seen = {{}}
def choose_second(dialog):
    combo = dialog.findChild(QtWidgets.QComboBox)
    seen["items"] = [combo.itemText(i) for i in range(combo.count())]
    seen["label"] = dialog.findChild(QtWidgets.QLabel).text()
    key(combo, QtCore.Qt.Key_Down)
    press([b for b in dialog.findChildren(QtWidgets.QPushButton) if b.text().replace("&", "") == "OK"][0])
when_shown(lambda: top(QtWidgets.QFileDialog), choose_file({program!r}))
when_shown(lambda: top(QtWidgets.QInputDialog, "ABM_ChooseOperation"), choose_second)
press(toolbar_button("ABM_ImportToolpath"))
settle()
made = [o for o in doc.Objects if o.Name.startswith("Toolpath") and o.File == {program!r}]
verdict["program"] = [seen, len(made), made[0].Operation if made else None, made[0].CLPoints if made else None,
                      made[0].State if made else None, report_since(start)]
# the dialog cancelled: nothing made
start = len(report.toPlainText())
before = len(doc.Objects)
when_shown(lambda: top(QtWidgets.QFileDialog), choose_file({program!r}))
when_shown(lambda: top(QtWidgets.QInputDialog, "ABM_ChooseOperation"), escape)
press(toolbar_button("ABM_ImportToolpath"))
settle()
verdict["program_cancelled"] = [len(doc.Objects) - before, report_since(start)]

# ---- Import stock with a sphere selected: refused in words, nothing made ---------------------------------
start = len(report.toPlainText())
sphere = doc.addObject("Part::Sphere", "Sphere")
doc.recompute()
FreeCADGui.Selection.clearSelection()
FreeCADGui.Selection.addSelection(sphere)
before = [o.Name for o in doc.Objects]
press(toolbar_button("ABM_ImportStock"))
settle()
verdict["sphere"] = [[o.Name for o in doc.Objects] == before, report_since(start)]
"""

REOPENED = SETUP + """
work = {work!r}
os.makedirs(work, exist_ok=True)
for name in ("stock.json", "toolpath.csv"):
    shutil.copy(os.path.join({model!r}, name), work)
doc = FreeCAD.newDocument("Moved")
stock = commands.ImportStock().execute(os.path.join(work, "stock.json"))
path = commands.ImportToolpath().execute(os.path.join(work, "toolpath.csv"))
engagement = commands.ComputeEngagement().execute(
    dict(diameter=12, flutes=2, flute_length=30, feed_per_tooth=0.1, phi_step=10), [stock, path])
doc.saveAs({saved!r})
FreeCAD.closeDocument(doc.Name)
shutil.rmtree(work)  # the input files are gone; the results CSV stays beside the document
settle()
start = len(report.toPlainText())
when_shown(lambda: top(QtWidgets.QFileDialog, "ABM_Repoint"), escape)  # the folder not given
FreeCAD.openDocument({saved!r})
for _ in range(40):
    settle()
    time.sleep(0.05)
doc = FreeCAD.ActiveDocument
engagement = doc.getObject("Engagement")
verdict["reopened"] = report_since(start)

# Inspect (toolbar) with the engagement selected
start = len(report.toPlainText())
FreeCADGui.Selection.clearSelection()
FreeCADGui.Selection.addSelection(engagement)
press(toolbar_button("ABM_InspectEngagement"))
settle()
shown = dock.find()
verdict["inspect"] = [shown is not None and shown.obj is engagement, shown.about.text() if shown else "",
                      report_since(start)]

# double-click in the tree: the task panel; Escape: closed
start = len(report.toPlainText())
tree = [t for t in window.findChildren(QtWidgets.QTreeWidget) if t.isVisible()][0]
item = tree.findItems("Engagement", QtCore.Qt.MatchExactly | QtCore.Qt.MatchRecursive)[0]
tree.scrollToItem(item)
centre = QtCore.QPointF(tree.visualItemRect(item).center())
for kind in (QtCore.QEvent.MouseButtonPress, QtCore.QEvent.MouseButtonRelease, QtCore.QEvent.MouseButtonDblClick,
             QtCore.QEvent.MouseButtonRelease):
    QtWidgets.QApplication.sendEvent(tree.viewport(), QtGui.QMouseEvent(kind, centre, QtCore.Qt.LeftButton,
                                                                         QtCore.Qt.LeftButton, QtCore.Qt.NoModifier))
settle()
panel = task_panel.shown()
verdict["double_click"] = [panel is not None, report_since(start)]
start = len(report.toPlainText())
if panel is not None:
    field = panel.field("Diameter")
    field.setFocus()
    QtWidgets.QApplication.sendEvent(field, QtGui.QKeyEvent(QtCore.QEvent.KeyPress, QtCore.Qt.Key_Escape,
                                                            QtCore.Qt.NoModifier))
    settle()
verdict["escape"] = [task_panel.shown() is None, report_since(start)]

# ---- Undo of "Open model test 1" (toolbar buttons): the dock lets the removed engagement go -------------------
start = len(report.toPlainText())
press(toolbar_button("ABM_OpenModelTest"))
settle()
opened = FreeCAD.ActiveDocument
shown = dock.find()
verdict["opened"] = [opened.Name, shown.obj.Name if shown.obj is not None else None]
undo = [b for b in window.findChildren(QtWidgets.QToolButton) if b.isVisible() and b.defaultAction() is not None
        and b.defaultAction().text().replace("&", "") == "Undo"][0]
press(undo)
settle()
verdict["undone"] = [[o.Name for o in opened.Objects], shown.obj is None, shown.title.text(), shown.about.text(),
                     shown.spin.maximum(), report_since(start)]
"""


def no_traceback(text):
    return "Traceback" not in text and "Error" not in text.replace("ABM:", "")


def test_imports_ask_what_the_file_needs_and_refuse_in_words(tmp_path, run_gui):
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"  # the workbench installed: its toolbar
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    ngc, table = tmp_path / "square.ngc", tmp_path / "tools.tbl"
    ngc.write_text(GCODE)
    table.write_text(TOOL_TABLE)
    verdict = run_gui(IMPORTS.format(events=EVENTS, dialogs=DIALOGS, ngc=str(ngc), table=str(table),
                                     program=PROGRAM_3, out=str(tmp_path / "verdict.json")))
    assert "stuck" not in verdict, verdict
    names, said = verdict["gcode_escaped"]
    assert names == [] and "Traceback" not in said and "--" not in said
    assert "square.ngc: not imported: its program loads tools by number, and no tool table was chosen" in said
    count, tools, diameter, state, said = verdict["gcode"]
    assert count == 1 and tools == str(table) and diameter == 10.0 and "Invalid" not in state and "Traceback" not in said
    seen, count, operation, points, state, said = verdict["program"]
    assert seen["items"][0].startswith("1: OP1_SEMI_FINISH") and seen["items"][1].startswith("2: OP2_REST")
    assert "holds several operations" in seen["label"]
    assert count == 1 and operation == 2 and points == 110 and "Invalid" not in state and "Traceback" not in said
    assert verdict["program_cancelled"] == [0, ""]
    unchanged, said = verdict["sphere"]
    assert unchanged and "Traceback" not in said
    assert "ABM: Sphere: Face1: wall not vertical: a Sphere surface" in said


def test_a_reopened_document_without_its_files_and_undo_of_open_model_test(tmp_path, run_gui):
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    verdict = run_gui(REOPENED.format(events=EVENTS, dialogs=DIALOGS, model=MODEL_1, work=str(tmp_path / "inputs"),
                                      saved=str(tmp_path / "saved" / "moved.FCStd"),
                                      out=str(tmp_path / "verdict.json")))
    assert "stuck" not in verdict, verdict
    assert "input files missing, not re-pointed" in verdict["reopened"] and "Traceback" not in verdict["reopened"]
    shown, about, said = verdict["inspect"]
    assert shown and about.startswith("CL ") and said == ""
    opened, said = verdict["double_click"]
    assert opened and "Traceback" not in said
    closed, said = verdict["escape"]
    assert closed and "Traceback" not in said
    assert verdict["opened"] == ["ModelTest1", "Engagement"]
    objects, gone, title, about, maximum, said = verdict["undone"]
    assert objects == [] and gone and title.startswith("No engagement") and about == "" and "Traceback" not in said
