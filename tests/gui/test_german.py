"""The translations end to end: FreeCAD's language set to German, the workbench's labels in German
(translations/ABM_de.qm, built by `make translations` from ABM_de.ts and loaded from the folder InitGui
adds), the task panel opened by a double-click-free setEdit, the dock by the toolbar button; typed
numbers refused, a job model's check, a reader's error, a feature's printed warning and a system file error
in German (gui.messages, gui.reporting)."""

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
from abm_workbench.gui.i18n import language
verdict["language"] = language()  # the validation report's lang
press(toolbar_button("ABM_OpenModelTest"))
settle()
shown = dock.find()
verdict["dock"] = [shown.windowTitle(), shown.tabs.tabText(0), shown.about.text()[:40]]
shown.plot_chosen()  # the plots of the CL point shown, as the dock draws them once the events queued are handled
axes = shown.figure.axes
verdict["plots"] = [[ax.get_title() for ax in axes], axes[0].get_ylabel(), axes[2].get_xlabel(),
                    axes[0].get_legend().get_title().get_text(), [t.get_text() for t in axes[3].get_legend().get_texts()],
                    shown.about.text()]
FreeCADGui.ActiveDocument.setEdit(FreeCAD.ActiveDocument.getObject("Engagement"), 0)
settle()
panel = task_panel.shown()
verdict["panel"] = sorted(label.text() for label in panel.form.findChildren(QtWidgets.QLabel))
verdict["sections"] = [section.header.text() for section in panel.sections.values()]
# typed numbers and the job model's checks, in German
retype("PhiStep", "1x2")
verdict["letters"] = panel.message.text()
retype("PhiStep", "-3")
verdict["negative"] = panel.message.text()
click("Abbrechen")
settle()
# a reader's error in the report view, in German, its file and line kept
report = window.findChild(QtWidgets.QDockWidget, "Report view").widget()
start = len(report.toPlainText())
commands.ImportToolpath().execute({bad!r})
settle()
verdict["report"] = report.toPlainText()[start:]
# a feature's warning (features.base.tell, its localizer installed by InitGui.py) and a system file error
from abm_workbench.features.base import tell
from abm_workbench.gui.reporting import report_error
start = len(report.toPlainText())
tell(FreeCAD.ActiveDocument.getObject("Engagement"), "results in the document not read (r.abm: no such file)")
report_error(FileNotFoundError(2, "No such file or directory", {bad!r}))
settle()
verdict["printed"] = report.toPlainText()[start:]
"""


def test_german_labels(tmp_path, run_gui):
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    bad = tmp_path / "kaputt.apt"
    bad.write_text("CUTTER/6\nGOTO/1,2\n")
    verdict = run_gui(BODY.format(events=EVENTS, dialogs=DIALOGS, bad=str(bad)))
    assert verdict["language"] == "de"
    title, tab, about = verdict["dock"]
    assert title == "ABM-Eingriff" and tab == "Eingriff" and about.startswith("CL ") and "Schnitttiefe" in about
    assert "Durchmesser" in verdict["panel"] and "Wandmodell" in verdict["panel"]
    assert "Diameter" not in verdict["panel"]
    titles, ylabel, xlabel, legend_title, legend, about = verdict["plots"]
    assert titles[0].startswith("CL ") and titles[0].endswith(" über dem Drehwinkel φ des Werkzeugs")
    assert titles[3] == "Verlauf über die Bahn" and ylabel == "Schnitt-\nlänge (mm)" and xlabel == "φ (Grad)"
    assert legend_title == "Segment: UEP-Fläche" and legend == ["Schnitttiefe", "größte Schnittlänge"]
    assert "gekrümmte Wand" in about or "Deckfläche" in about  # the segments' UEP surfaces in German
    assert verdict["sections"] == ["Werkzeug", "Schnitt", "Drehwinkel φ des Werkzeugs", "Rohteilmodell",
                                   "Schnittkräfte"]
    assert verdict["letters"] == ("Schrittweite von φ: „1x2“ ist kein Winkel: geben Sie eine Zahl ein, nach "
                                  "Wunsch mit Einheit (10°, 0.2 rad)."), verdict["letters"]
    assert verdict["negative"] == "Schrittweite von φ muss positiv sein, erhalten: -3°.", verdict["negative"]

    assert f"{tmp_path / 'kaputt.apt'}:2: GOTO: " in verdict["report"] and "erhalten: 2" in verdict["report"], \
        verdict["report"]
    assert "got 2" not in verdict["report"]
    assert "Ergebnisse im Dokument nicht gelesen (r.abm: " in verdict["printed"], verdict["printed"]
    assert f"[Errno 2] Datei oder Verzeichnis nicht gefunden: '{bad}'" in verdict["printed"], verdict["printed"]
