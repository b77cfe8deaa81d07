"""The GUI's validation on worker processes: the preference "Validation workers" typed into the
preferences page and saved, the Validate command then computing the boolean reference on 2 spawned
processes (seen as FreeCAD's children while it runs) with the same comparison, byte for byte, as in
FreeCAD's own process; and Cancel clicked in the progress dialog ending both workers at once,
writing nothing."""

import pytest
from tests.conftest import ROOT
from tests.gui.events import EVENTS

MODEL = f"{ROOT}/resources/models/model_test_1"

BODY = """
import multiprocessing, os
import shiboken2
from PySide import QtCore, QtGui
QtWidgets = QtGui
window = FreeCADGui.getMainWindow()
{events}
FreeCADGui.activateWorkbench("ABMWorkbench")
from abm_workbench.gui import commands
from abm_workbench.gui.preferences import GROUP, PreferencesPage
from abm_workbench.gui.progress import ProgressDialog
from abm_workbench.gui.validate import Cancelled, validate_engagement

page = PreferencesPage()
page.loadSettings()
page.form.show()
verdict["offered"] = [page.workers.value(), page.workers.minimum(), page.workers.specialValueText()]
page.workers.setFocus()
key(page.workers, QtCore.Qt.Key_A, "", QtCore.Qt.ControlModifier)
key(page.workers, QtCore.Qt.Key_2, "2")
settle()
page.saveSettings()
verdict["stored"] = FreeCAD.ParamGet(GROUP).GetInt("ValidationWorkers")

doc = FreeCAD.newDocument("Workers")
stock = commands.ImportStock().execute(os.path.join({model!r}, "stock.step"))
path = commands.ImportToolpath().execute(os.path.join({model!r}, "toolpath.csv"))
engagement = commands.ComputeEngagement().execute(
    dict(diameter=12, flutes=2, flute_length=30, feed_per_tooth=0.1, inclination=10, phi_step=10), [stock, path])
settle()
out = {out!r}
validate_engagement(engagement, [3, 11, 20, 29], os.path.join(out, "one"), workers=1)

seen = []
class Watched(ProgressDialog):
    cancel = False
    def __call__(self, done, total):
        seen.append(sorted(p.pid for p in multiprocessing.active_children()))
        if self.cancel:
            press(self.dialog.findChild(QtGui.QPushButton))
        super().__call__(done, total)
commands.ProgressDialog = Watched
commands.ValidateEngagement().activated(doc, engagement, "3,11,20,29", os.path.join(out, "two"), open_report=False)
verdict["workers_seen"] = [len(pids) for pids in seen]
verdict["same"] = all(open(os.path.join(out, "one", name)).read() == open(os.path.join(out, "two", name)).read()
                      for name in ("comparison.csv", "segments.csv", "depth.csv"))
children = multiprocessing.active_children
verdict["left_after_run"] = len(children())

seen.clear()
Watched.cancel = True
try:
    commands.ValidateEngagement().activated(doc, engagement, "3,11,20,29", os.path.join(out, "three"),
                                            open_report=False)
    verdict["cancelled"] = False
except Cancelled:
    verdict["cancelled"] = True
verdict["cancel_calls"] = len(seen)
verdict["cancel_workers"] = len(seen[0]) if seen else 0
verdict["left_after_cancel"] = len(children())
verdict["written_after_cancel"] = sorted(os.listdir(out))
"""


@pytest.mark.xfail(strict=False, reason="open fault (issue #29): passes alone (26 s), but in the whole suite on "
                   "2026-11-26 it once saw 0 workers at the last progress step and once FreeCAD ended without "
                   "running the macro; not diagnosed")
def test_the_gui_validates_on_the_preferred_workers_and_cancel_ends_them(run_gui, tmp_path):
    out = tmp_path / "reports"
    out.mkdir()
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"  # FreeCAD finds the workbench there
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    verdict = run_gui(BODY.format(events=EVENTS, model=MODEL, out=str(out)))
    assert verdict["offered"] == [1, 0, "one per core"] and verdict["stored"] == 2
    assert verdict["workers_seen"] == [2, 2, 2, 2] and verdict["same"] and verdict["left_after_run"] == 0
    assert verdict["cancelled"] and verdict["cancel_calls"] == 1 and verdict["cancel_workers"] == 2
    assert verdict["left_after_cancel"] == 0 and verdict["written_after_cancel"] == ["one", "two"]
