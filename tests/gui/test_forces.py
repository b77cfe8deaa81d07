"""Cutting forces in the real FreeCAD GUI on model test 1: turned on in the task panel (a bad
immersion marked first), recomputed, shown in the dock's Forces tab (the plotted lines are the
object's forces), and in the validation report."""

import os

from tests.conftest import ROOT

BODY = """
from PySide2 import QtWidgets
import numpy as np

window = FreeCADGui.getMainWindow()
report = window.findChild(QtWidgets.QDockWidget, "Report view").widget()
FreeCADGui.activateWorkbench("ABMWorkbench")
from abm_workbench.gui import commands, dock, task_panel
_, _, engagement = commands.OpenModelTest().run()
doc = engagement.Document
FreeCADGui.updateGui()
start = len(report.toPlainText())
panel_dock = dock.find()
verdict["before"] = [panel_dock.tabs.isTabEnabled(dock.FORCES_TAB), engagement.Proxy.forces(engagement) is None,
                     panel_dock.colour_by.model().item(3).isEnabled()]

engagement.ViewObject.Proxy.doubleClicked(engagement.ViewObject)
FreeCADGui.updateGui()
panel = task_panel.shown()
ok = lambda: panel.buttons.button(QtWidgets.QDialogButtonBox.Ok).isEnabled()
verdict["off"] = [panel.field("Material").isEnabled(), panel.field("Ktc").isEnabled(),
                  panel.field("ImmersionEnd").isEnabled()]
panel.field("Forces").setChecked(True)
panel.field("Material").setCurrentText("al7075-t6")
panel.set_number("ImmersionEnd", 200.0)
FreeCADGui.updateGui()
verdict["bad"] = [ok(), panel.message.text(), bool(panel.field("ImmersionEnd").styleSheet()),
                  panel.number("Ktc"), panel.field("Ktc").isEnabled()]
panel.set_number("ImmersionEnd", 120.0)
panel.set_number("HelixAngle", 95.0)
FreeCADGui.updateGui()
verdict["bad_helix"] = [ok(), panel.message.text(), bool(panel.field("HelixAngle").styleSheet())]
panel.set_number("HelixAngle", 0.0)
panel.field("Material").setCurrentText("custom")
panel.set_number("Ktc", -5.0)
FreeCADGui.updateGui()
verdict["bad_ktc"] = [ok(), panel.message.text(), bool(panel.field("Ktc").styleSheet())]
panel.field("Material").setCurrentText("al7075-t6")
FreeCADGui.updateGui()
verdict["good"] = [ok(), panel.message.text()]
verdict["accepted"] = panel.accept()
FreeCADGui.updateGui()
forces = engagement.Proxy.forces(engagement)
verdict["object"] = [engagement.State, engagement.Forces, engagement.Material, engagement.ImmersionEnd.Value,
                     engagement.PeakForce, float(forces.peak.max())]

panel_dock = dock.find()
panel_dock.tabs.setCurrentIndex(dock.FORCES_TAB)
cl = int(np.argmax(forces.peak))
panel_dock.slider.setValue(cl)
FreeCADGui.updateGui()
over_phi, along = panel_dock.force_figure.axes
lines = {{line.get_label(): line for line in over_phi.lines if not line.get_label().startswith("_")}}
verdict["dock"] = [panel_dock.tabs.isTabEnabled(dock.FORCES_TAB), panel_dock.spin.value(), sorted(lines)]
expected = {{"$F_x$": forces.xyz[cl, :, 0], "$F_y$": forces.xyz[cl, :, 1], "$F_z$": forces.xyz[cl, :, 2],
            "$|F|$": forces.resultant[cl]}}
verdict["lines_match"] = [bool(np.array_equal(lines[name].get_xdata(), forces.phi)
                               and np.allclose(lines[name].get_ydata(), values, rtol=0, atol=1e-9))
                          for name, values in expected.items()]
along_lines = {{line.get_label(): line for line in along.lines}}
verdict["along_match"] = [bool(np.allclose(along_lines["peak |F| over φ"].get_ydata(), forces.peak, atol=1e-9)),
                          bool(np.allclose(along_lines["mean |F| over φ"].get_ydata(), forces.mean, atol=1e-9)),
                          [float(x) for x in along.lines[-1].get_xdata()]]
from scipy.spatial import cKDTree
from abm_workbench.gui.colouring import COLOUR_BY, quantity_colours
panel_dock.colour_by.setCurrentIndex(COLOUR_BY.index("force"))
FreeCADGui.updateGui()
provider = engagement.ViewObject.Proxy
legend = provider.legend
# each vertex of the mesh is the LEP or UEP of an engaged instant (found by geometry): its |F| there
result = engagement.Proxy.result(engagement)
instants = np.argwhere(result.segment >= 0)
ends = np.concatenate([result.lep_xyz[instants[:, 0], instants[:, 1]], result.uep_xyz[instants[:, 0], instants[:, 1]]])
resultant = np.linalg.norm(forces.xyz, axis=-1)[instants[:, 0], instants[:, 1]]
distance, nearest = cKDTree(ends).query(np.array(provider.mesh.points))
values = np.concatenate([resultant, resultant])[nearest]
colours = np.array(provider.colours)
verdict["colour_force"] = [panel_dock.colour_by.model().item(3).isEnabled(), engagement.ViewObject.ColourBy,
                           legend.kind, legend.unit, abs(legend.high - float(values.max())),
                           float(np.abs(colours - quantity_colours(values, values.min(), values.max())).max()),
                           float(distance.max())]
page = commands.ValidateEngagement().execute(engagement, "%d,40" % cl, {report_folder!r}, False)
verdict["validated"] = [page is not None, sorted(os.listdir({report_folder!r}))]
verdict["report_view"] = report.toPlainText()[start:]
"""


def test_forces_in_the_task_panel_the_dock_and_the_validation_report(tmp_path, run_gui):
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    folder = tmp_path / "validation"
    verdict = run_gui(BODY.format(report_folder=str(folder)))

    assert verdict["before"] == [False, True, False]
    assert verdict["off"] == [False, False, False]
    # plain words and the field of the bad value marked (the end of immersion, not its start)
    assert verdict["bad"] == [False, "End of immersion must be within (0, 180]°, got 200°.", True, 767.01, False]
    assert verdict["bad_helix"][:2] == [False, "Helix angle must be within [-60, 60]°, got 95°."]
    assert verdict["bad_helix"][2]
    assert verdict["bad_ktc"] == [False, "Ktc (tangential cutting coefficient) must be positive, got -5 N/mm².", True]
    assert verdict["good"] == [True, ""] and verdict["accepted"] is True
    state, on, material, end, peak, computed = verdict["object"]
    assert (state, on, material, end) == (["Up-to-date"], True, "al7075-t6", 120.0)
    assert peak == computed and peak > 100.0
    assert verdict["dock"][0] is True and verdict["dock"][2] == ["$F_x$", "$F_y$", "$F_z$", "$|F|$"]
    assert verdict["lines_match"] == [True] * 4
    cl = verdict["dock"][1]
    assert verdict["along_match"] == [True, True, [cl, cl]]
    enabled, colour_by, kind, unit, high_error, colour_error, distance = verdict["colour_force"]
    assert (enabled, colour_by, kind, unit) == (True, "force", "force", "N")
    assert high_error < 1e-9 and colour_error < 1e-6 and distance < 1e-9  # as test_commands checks colour by length
    assert verdict["validated"][0] and "forces.png" in verdict["validated"][1]
    assert "<h2>Cutting forces</h2>" in (folder / "index.html").read_text(encoding="utf-8")
    assert "Error" not in verdict["report_view"] and "Traceback" not in verdict["report_view"], verdict["report_view"]
    assert os.path.getsize(folder / "forces.png") > 20_000
