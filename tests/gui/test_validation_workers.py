"""The GUI's validation on worker processes: the preference "Validation workers" typed into the
preferences page and saved, the Validate command then computing the boolean reference on 2 spawned
processes (FreeCAD's children as each CL point's step is reported), every step drawn in the progress
dialog, with the same comparison, byte for byte, as in FreeCAD's own process; and Cancel clicked in the
progress dialog ending both workers at once (while they are busy with the next CL points), writing
nothing."""

from tests.conftest import ROOT
from tests.gui.events import EVENTS

MODEL = f"{ROOT}/resources/models/model_test_1"

BODY = """
import multiprocessing, os, threading, time
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
validate_engagement(engagement, [3, 11, 20, 29], os.path.join(out, "one"), workers=1, apart=False)

from abm_workbench.gui import validate as validate_module, worker
children = multiprocessing.active_children

# The workers alive as the worker thread reports each CL point's step: the pool is open then (it ends its
# workers after the last step is reported, and the GUI thread draws that step up to POLL_MS later, or
# later still under load: looked at there, the last step could find them already ended).
# When cancelling, the worker thread waits after reporting the first step until the GUI thread has drawn it and
# pressed Cancel: the pool is then surely open, its workers busy with the next CL points.
reported, pressed = [], threading.Event()
prepared = validate_module.prepare
def prepare(*args, **keywords):
    run = prepared(*args, **keywords)
    def reporting_run(progress=None):
        def reporting(done, total):
            reported.append(len(children()))
            progress(done, total)
            if Watched.cancel:
                pressed.wait(60)
        return run(progress=reporting)
    return reporting_run
validate_module.prepare = prepare

drawn, at_cancel = [], []
class Watched(ProgressDialog):
    cancel = False
    def __call__(self, done, total):
        drawn.append([done, total])
        if self.cancel:
            at_cancel.append(len(children()))
            verdict["pressed_at"] = time.monotonic()
            press(self.dialog.findChild(QtGui.QPushButton))
            pressed.set()
        super().__call__(done, total)
commands.ProgressDialog = Watched
commands.ValidateEngagement().activated(doc, engagement, "3,11,20,29", os.path.join(out, "two"), open_report=False)
verdict["workers_reported"], verdict["steps_drawn"] = list(reported), list(drawn)
verdict["same"] = all(open(os.path.join(out, "one", name)).read() == open(os.path.join(out, "two", name)).read()
                      for name in ("comparison.csv", "segments.csv", "depth.csv"))
verdict["left_after_run"] = len(children())

drawn.clear()
reported.clear()
Watched.cancel = True
started = time.monotonic()
try:
    commands.ValidateEngagement().activated(doc, engagement, "3,11,20,29", os.path.join(out, "three"),
                                            open_report=False)
    verdict["cancelled"] = False
except Cancelled:
    verdict["cancelled"] = True
returned = time.monotonic()  # told, not checked: the whole cancelled run, and from the click to the command's return
verdict["cancel_seconds"] = [round(returned - started, 2), round(returned - verdict.pop("pressed_at", returned), 3)]
verdict["cancel_calls"], verdict["workers_at_cancel"] = len(drawn), list(at_cancel)
verdict["reported_in_cancelled_run"] = list(reported)  # told, not checked: 1 step, or 2 if two CL points ended together
verdict["left_after_cancel"] = len(children())
verdict["abandoned"] = len(worker._ABANDONED)  # the validation's thread given up after GRACE_MS
verdict["written_after_cancel"] = sorted(os.listdir(out))
"""


def test_the_gui_validates_on_the_preferred_workers_and_cancel_ends_them(run_gui, tmp_path):
    out = tmp_path / "reports"
    out.mkdir()
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"  # FreeCAD finds the workbench there
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    verdict = run_gui(BODY.format(events=EVENTS, model=MODEL, out=str(out)))
    assert verdict["offered"] == [1, 0, "one per core"] and verdict["stored"] == 2, str(verdict)
    assert verdict["workers_reported"] == [2, 2, 2, 2], str(verdict)
    assert verdict["steps_drawn"] == [[1, 4], [2, 4], [3, 4], [4, 4]], str(verdict)
    assert verdict["same"] and verdict["left_after_run"] == 0, str(verdict)
    # Cancel at the first step, both workers busy with the next CL points: killed then (worker_processes.stop_when),
    # not after those CL points end, so the thread is not given up and nothing is left running.
    assert verdict["cancelled"] and verdict["cancel_calls"] == 1 and verdict["workers_at_cancel"] == [2], str(verdict)
    assert verdict["left_after_cancel"] == 0 and verdict["abandoned"] == 0, str(verdict)
    assert verdict["written_after_cancel"] == ["one", "two"], str(verdict)
