"""ABM_EngageCamJob in the real FreeCAD GUI: a CAM Job built by FreeCAD's own CAM, selected in the tree,
its toolbar button clicked; the engagement of the operation the engine computes, with the tool
controller's tool; the results following the Job as it recomputes; an operation it cannot compute
refused in words."""

from tests.cad.cam_builds import build_job
from tests.conftest import ROOT
from tests.gui.events import EVENTS

HEAD = """
from PySide2 import QtCore, QtGui, QtWidgets
import shiboken2
window = FreeCADGui.getMainWindow()
"""
BODY = """
report = window.findChild(QtWidgets.QDockWidget, "Report view").widget()
FreeCADGui.activateWorkbench("ABMWorkbench")
toolbar = window.findChild(QtWidgets.QToolBar, "ABM")
engage = toolbar.widgetForAction(next(a for a in toolbar.actions() if a.objectName() == "ABM_EngageCamJob"))
doc = FreeCAD.openDocument({job!r})
FreeCADGui.Selection.clearSelection()
FreeCADGui.Selection.addSelection(doc.getObject("Job"))  # what a click on the Job in the tree selects
settle()
press(engage)
settle()
made = [o for o in doc.Objects if o.Label.endswith(" engagement")]
verdict["made"] = [(o.Label, o.State, o.Diameter.Value, o.Flutes, o.FluteLength.Value, round(o.FeedPerTooth.Value, 9),
                    o.SpindleSpeed, o.EngagedCLPoints > 0, o.Instants, o.CornerRadius.Value) for o in made]
verdict["toolpaths"] = [(o.Label, o.CamJob.Name, o.CamOperation.Name, o.CLPoints) for o in doc.Objects
                        if o.Label.endswith(" toolpath")]
profile = doc.getObject("Profile")
profile.setExpression("StepDown", None)
profile.StepDown = 2.0
doc.recompute()
settle()
verdict["after"] = [(o.State, o.Instants) for o in made]
start = len(report.toPlainText())
FreeCADGui.Selection.clearSelection()
FreeCADGui.Selection.addSelection(doc.getObject("Drilling"))
press(engage)
settle()
verdict["refused"] = report.toPlainText()[start:]
"""


def test_a_selected_cam_job_engaged_by_its_toolbar_button(tmp_path, run_gui):
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    build_job(tmp_path)

    # The Adaptive's ball-end mill against the in-process stock (1287 CL points after 145 rapids) takes about
    # 17 s of CPU time (docs/BENCHMARKS.md, "Corner tools in the in-process stock: memory and time on a real
    # program"), and the Job's recompute computes it again: the whole test took 100 s on the shared 2-core VM
    # (load average about 7), so twice the usual time limit (900 s when that run took two minutes of CPU).
    verdict = run_gui(HEAD + EVENTS + BODY.format(job=str(tmp_path / "job.FCStd")), timeout=360)

    # The operations the engine computes (the profile's flat-end, the pocket's bull-nose and the adaptive's
    # ball-end mill), each with its tool controller's tool and cut: the profile's 600 mm/min at 8000 rpm
    # with 2 flutes is 0.0375 mm per tooth.
    made = {row[0]: row for row in verdict["made"]}
    assert sorted(made) == ["Adaptive engagement", "Pocket engagement", "Profile engagement"]
    assert made["Profile engagement"] == ["Profile engagement", ["Up-to-date"], 5.0, 2, 30.0, 0.0375, 8000.0, True,
                                          made["Profile engagement"][8], 0.0]
    assert [made[name][2:5] + made[name][9:] for name in ("Pocket engagement", "Adaptive engagement")] == [
        [6.0, 4, 40.0, 1.5], [6.0, 2, 40.0, 3.0]]
    assert all(row[1] == ["Up-to-date"] and row[7] for row in made.values())
    toolpaths = {row[0]: row for row in verdict["toolpaths"]}
    assert toolpaths["Profile toolpath"] == ["Profile toolpath", "Job", "Profile", toolpaths["Profile toolpath"][3]]
    (state, instants), = [after for row, after in zip(verdict["made"], verdict["after"]) if row[0] ==
                          "Profile engagement"]
    assert state == ["Up-to-date"] and instants > made["Profile engagement"][8]  # more passes, more CL points
    assert "ABM: operation 4: drill D5 mm: not a milling tool" in verdict["refused"]
