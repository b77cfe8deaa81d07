"""The GUI's validation keeps FreeCAD drawing: with the preference "Validation workers" at its default (1),
the boolean reference runs in one spawned process, not in a thread of FreeCAD's own process, where
FreeCAD's Python bindings hold the interpreter's lock through each OpenCASCADE boolean and the GUI's
thread stalls as long. A 10 ms timer on the GUI thread is watched through the Validate command (the
longest gap between its ticks). The same validation in FreeCAD's own process (apart=False) stalled the
GUI 1.44 s against 0.19 s apart (2026-11-26, load about 10), and fails this test."""

from tests.conftest import ROOT
from tests.gui.events import EVENTS

MODEL = f"{ROOT}/resources/models/model_test_1"

BODY = """
import multiprocessing, os, time
from PySide import QtCore, QtGui
QtWidgets = QtGui
window = FreeCADGui.getMainWindow()
{events}
FreeCADGui.activateWorkbench("ABMWorkbench")
from abm_workbench.gui import commands
from abm_workbench.gui import validate as validate_module
from abm_workbench.gui.preferences import validation_workers

verdict["workers"] = validation_workers()
doc = FreeCAD.newDocument("Apart")
stock = commands.ImportStock().execute(os.path.join({model!r}, "stock.step"))
path = commands.ImportToolpath().execute(os.path.join({model!r}, "toolpath.csv"))
engagement = commands.ComputeEngagement().execute(
    dict(diameter=12, flutes=2, flute_length=30, feed_per_tooth=0.1, inclination=10, phi_step=1), [stock, path])
settle()

def watched(name, apart):
    ticks = {{"last": time.perf_counter(), "gap": 0.0, "children": 0}}
    def tick():
        now = time.perf_counter()
        ticks["gap"] = max(ticks["gap"], now - ticks["last"])
        ticks["last"] = now
        ticks["children"] = max(ticks["children"], len(multiprocessing.active_children()))
    timer = QtCore.QTimer()
    timer.timeout.connect(tick)
    prepared = validate_module.prepare
    validate_module.prepare = lambda *args: prepared(*args, apart=apart)
    timer.start(10)
    started = time.perf_counter()
    try:
        commands.ValidateEngagement().activated(doc, engagement, "3,20", os.path.join({out!r}, name),
                                                open_report=False)
    finally:
        timer.stop()
        validate_module.prepare = prepared
    return [round(ticks["gap"], 3), round(time.perf_counter() - started, 2), ticks["children"]]

verdict["apart"] = watched("apart", None)
verdict["left"] = len(multiprocessing.active_children())
"""


def test_validation_runs_its_booleans_beside_the_gui(run_gui, tmp_path):
    out = tmp_path / "reports"
    out.mkdir()
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    verdict = run_gui(BODY.format(events=EVENTS, model=MODEL, out=str(out)))
    gap, seconds, children = verdict["apart"]
    assert verdict["workers"] == 1 and children == 1, str(verdict)
    assert gap < 0.5, str(verdict)
    assert verdict["left"] == 0 and sorted(p.name for p in out.iterdir()) == ["apart"], str(verdict)
