"""The translations end to end: FreeCAD's language set to German, the workbench's labels in German
(translations/ABM_de.qm, built by `make translations` from ABM_de.ts and loaded from the folder InitGui
adds), the task panel opened by a double-click-free setEdit, the dock by the toolbar button."""

from tests.conftest import ROOT
from tests.gui.dialogs import DIALOGS
from tests.gui.events import EVENTS

BODY = """
import shiboken2
from PySide import QtCore, QtGui
QtWidgets = QtGui
window = FreeCADGui.getMainWindow()
{events}
{dialogs}
FreeCADGui.setLocale("German")
settle()
FreeCADGui.activateWorkbench("ABMWorkbench")
from abm_workbench.gui import commands, dock, task_panel
press(toolbar_button("ABM_OpenModelTest"))
settle()
shown = dock.find()
verdict["dock"] = [shown.windowTitle(), shown.tabs.tabText(0), shown.about.text()[:40]]
FreeCADGui.ActiveDocument.setEdit(FreeCAD.ActiveDocument.getObject("Engagement"), 0)
settle()
panel = task_panel.shown()
verdict["panel"] = sorted(label.text() for label in panel.form.findChildren(QtWidgets.QLabel))
verdict["sections"] = [section.header.text() for section in panel.sections.values()]
click("Abbrechen")
"""


def test_german_labels(tmp_path, run_gui):
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    verdict = run_gui(BODY.format(events=EVENTS, dialogs=DIALOGS))
    title, tab, about = verdict["dock"]
    assert title == "ABM-Eingriff" and tab == "Eingriff" and about.startswith("CL ") and "Schnitttiefe" in about
    assert "Durchmesser" in verdict["panel"] and "Wandmodell" in verdict["panel"]
    assert "Diameter" not in verdict["panel"]
    assert verdict["sections"] == ["Werkzeug", "Schnitt", "Drehwinkel φ des Werkzeugs", "Rohteilmodell",
                                   "Schnittkräfte"]
