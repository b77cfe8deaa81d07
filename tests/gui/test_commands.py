"""The ABM commands in the real FreeCAD GUI, on model test 1: workbench, objects, colours, the task
panel, the dock (CL slider, colour by, legend, plots), validation, undo, errors, screenshots.

The checkout is linked into the test HOME's Mod folder so FreeCAD finds the workbench, as
`make install` does. Screenshots go to tmp and to build/screenshots/.
"""

import os

import numpy as np
import pytest

from abm_workbench.errors import InputError, ParameterError
from abm_workbench.jobs import BY_NAME, label_words, load_path
from tests.conftest import ROOT

MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")
SCREENSHOTS = os.path.join(ROOT, "build", "screenshots")
NAMES = ["ABM_OpenModelTest", "ABM_ImportStock", "ABM_ImportToolpath", "ABM_ComputeEngagement",
         "ABM_EngageCamJob", "ABM_InspectEngagement", "ABM_ValidateEngagement", "ABM_ShowInProcessStock"]
APT = "MULTAX/ON\nCUTTER/12,0,6,0,0,0,60\nCSI_SET_FLUTE_LENGTH/30\nSPINDL/RPM,4000,CLW\nFEDRAT/MMPM,800\n{moves}END-OF-PATH\n"

BODY = """
from PySide2 import QtCore, QtWidgets
import numpy as np
from scipy.spatial import cKDTree
from matplotlib import colormaps

window = FreeCADGui.getMainWindow()
report = window.findChild(QtWidgets.QDockWidget, "Report view").widget()
def report_since(start):
    FreeCADGui.updateGui()
    return report.toPlainText()[start:]

FreeCADGui.activateWorkbench("ABMWorkbench")
verdict["workbench"] = FreeCADGui.activeWorkbench().name()
verdict["commands"] = sorted(c for c in FreeCADGui.listCommands() if c.startswith("ABM_"))
verdict["toolbar"] = [a.objectName() or a.text() for a in window.findChild(QtWidgets.QToolBar, "ABM").actions()]
verdict["icons"] = [os.path.isfile(FreeCADGui.Command.get(n).getInfo()["pixmap"]) for n in {names!r}]
start = len(report.toPlainText())

# ---- ABM_OpenModelTest: one click --------------------------------------------------------
FreeCADGui.runCommand("ABM_OpenModelTest")
FreeCADGui.updateGui()
doc = FreeCAD.ActiveDocument
verdict["objects"] = [(o.Name, o.State, type(o.ViewObject.Proxy).__name__) for o in doc.Objects]
stock, path, engagement = doc.getObject("Stock"), doc.getObject("Toolpath"), doc.getObject("Engagement")
verdict["stock"] = [stock.Sections, stock.StraightWalls, stock.CurvedWalls, stock.WallModel,
                    os.path.basename(stock.SourceFile), stock.ViewObject.Transparency]
verdict["toolpath"] = [path.CLPoints, path.ViewObject.LineWidth]
verdict["engagement"] = [engagement.DepthOfCutMin.Value, engagement.DepthOfCutMax.Value,
                         engagement.EngagedCLPoints, engagement.Diameter.Value, engagement.Flutes,
                         engagement.Inclination.Value, engagement.FeedPerTooth.Value, engagement.YWindow,
                         engagement.YWindowMin.Value, engagement.YWindowMax.Value]
verdict["icon_files"] = [os.path.basename(o.ViewObject.Proxy.getIcon()) for o in doc.Objects]
result = engagement.Proxy.result(engagement)
from abm_workbench.report.colours import SURFACE_COLOURS
# every vertex of the mesh is an engaged instant's LEP or UEP (found by geometry, not by the mesh's own
# bookkeeping); its colour is the UEP surface of the segment whose φ range holds that instant
mesh_points = np.array(engagement.ViewObject.Proxy.mesh.points)
instants = np.argwhere(result.segment >= 0)
ends = np.concatenate([result.lep_xyz[instants[:, 0], instants[:, 1]], result.uep_xyz[instants[:, 0], instants[:, 1]]])
at = np.concatenate([instants, instants])
distance, nearest = cKDTree(ends).query(mesh_points)
def surface_at(cl, row):
    phi = result.phi[row]
    return [s["surface"] for s in result.segments(cl) if s["phi_start"] <= phi <= s["phi_end"]][0]
expected = [SURFACE_COLOURS[surface_at(*at[i])] for i in nearest]
colours = np.array(engagement.ViewObject.Proxy.colours)
verdict["faces"] = [len(mesh_points), len(colours), len(engagement.ViewObject.Proxy.mesh.triangles)]
verdict["colours_match"] = float(distance.max()) < 1e-9 and bool(np.allclose(colours, expected, atol=1e-6))
verdict["surfaces"] = sorted({{surface_at(*i) for i in instants}})
verdict["undo_names"] = list(doc.UndoNames)
verdict["report_open"] = report_since(start)

# ---- the dock: opened on the engagement; slider, highlight, colour by length, legend ----------
from abm_workbench.gui import commands, dock, task_panel
from abm_workbench.gui.screenshots import grab_screen, richest_cl, zoom_on
start = len(report.toPlainText())
panel_dock = dock.find()
verdict["dock"] = [panel_dock is not None and panel_dock.isVisible(), panel_dock.obj.Name, panel_dock.spin.maximum()]
cl = richest_cl(result)
panel_dock.slider.setValue(cl)
FreeCADGui.updateGui()
provider = engagement.ViewObject.Proxy
verdict["slider"] = [panel_dock.spin.value(), provider.cl, panel_dock.about.text().split(":")[0],
                     provider.overlay.getNumChildren(), len(panel_dock.figure.axes),
                     [list(map(float, line.get_xdata())) for line in panel_dock.figure.axes[3].lines
                      if len(line.get_xdata()) == 2 and line.get_xdata()[0] == line.get_xdata()[1]][:1]]
verdict["legend_segment"] = [provider.legend.kind, [name for name, _ in provider.legend.entries]]
panel_dock.colour_by.setCurrentIndex(1)
FreeCADGui.updateGui()
legend = provider.legend
verdict["legend_length"] = [engagement.ViewObject.ColourBy, legend.kind, legend.unit, legend.low, legend.high,
                            not panel_dock.legend.pixmap().isNull()]
# each vertex's colour against the length of cut of the instant it lies on (found by geometry)
lengths = np.concatenate([result.length[instants[:, 0], instants[:, 1]]] * 2)
mesh_points = np.array(provider.mesh.points)
distance, nearest = cKDTree(ends).query(mesh_points)
vertex_values = lengths[nearest]
low, high = result.length[result.segment >= 0].min(), result.length[result.segment >= 0].max()
expected = colormaps["viridis"]((vertex_values - low) / (high - low))[:, :3]
colours = np.array(provider.colours)
verdict["length_colours"] = [float(distance.max()), float(np.abs(colours - expected).max()),
                             float(vertex_values.min()), float(vertex_values.max()), float(low), float(high)]
view = FreeCADGui.ActiveDocument.ActiveView
view.viewIsometric(); view.fitAll()
zoom_on(view, result, cl)
FreeCADGui.updateGui()
shots = []
for folder in {folders!r}:
    os.makedirs(folder, exist_ok=True)
    view.saveImage(os.path.join(folder, "model_test_1_cl_length.png"), 1024, 768, "White")
    shots.append(os.path.join(folder, "model_test_1_cl_length.png"))
panel_dock.colour_by.setCurrentIndex(0)
view.fitAll()
verdict["report_dock"] = report_since(start)

# ---- the task panel by setEdit (double-click): a bad value, then a changed one, accepted ------
start = len(report.toPlainText())
instants = [engagement.Instants]
engagement.ViewObject.Proxy.doubleClicked(engagement.ViewObject)  # as a double-click in the tree
FreeCADGui.updateGui()
panel = task_panel.shown()
ok = lambda: panel.buttons.button(QtWidgets.QDialogButtonBox.Ok).isEnabled()
verdict["panel_open"] = [panel is not None, ok(), panel.message.text(), panel.number("Diameter"),
                         panel.number("Inclination")]
panel.set_number("Diameter", -3.0)
FreeCADGui.updateGui()
verdict["panel_bad"] = [ok(), panel.message.text(), bool(panel.field("Diameter").styleSheet()),
                        bool(panel.field("Flutes").styleSheet()), panel.accept()]
for folder in {folders!r}:
    grab_screen(os.path.join(folder, "task_panel_invalid.png"))
    shots.append(os.path.join(folder, "task_panel_invalid.png"))
panel.set_number("Diameter", 12.0)
panel.set_number("Inclination", 5.0)
panel.set_number("PhiStep", 2.0)
FreeCADGui.updateGui()
verdict["panel_good"] = [ok(), panel.message.text()]
verdict["accepted"] = panel.accept()
FreeCADGui.updateGui()
verdict["edited"] = [engagement.State, engagement.Inclination.Value, "inclination 5°" in engagement.Parameters,
                     engagement.Instants, task_panel.shown() is None,
                     FreeCADGui.ActiveDocument.getInEdit() is None, list(doc.UndoNames)[:2]]
doc.undo()
doc.recompute()
FreeCADGui.updateGui()
verdict["edit_undone"] = [engagement.Inclination.Value, engagement.Instants, engagement.State, instants[0]]
# Cancel: nothing changes, no undo step
undo_before = list(doc.UndoNames)
FreeCADGui.ActiveDocument.setEdit(engagement, 0)
FreeCADGui.updateGui()
task_panel.shown().set_number("Inclination", 3.0)
task_panel.shown().reject()
FreeCADGui.updateGui()
verdict["edit_cancelled"] = [engagement.Inclination.Value, engagement.State, list(doc.UndoNames) == undo_before,
                             task_panel.shown() is None, FreeCADGui.ActiveDocument.getInEdit() is None]
verdict["report_panel"] = report_since(start)

# ---- ABM_ValidateEngagement on two CL points; then a cancelled one --------------------------
start = len(report.toPlainText())
page = commands.ValidateEngagement().execute(engagement, "22,%d" % cl, {report_folder!r}, False)
verdict["validated"] = [page, engagement.ValidationReport, list(doc.UndoNames)[:1]]
def cancel_soon():
    progress = window.findChild(QtWidgets.QProgressDialog, "ABM_Progress")
    if progress is not None:
        progress.cancel()
    else:
        QtCore.QTimer.singleShot(20, cancel_soon)
QtCore.QTimer.singleShot(0, cancel_soon)
cancelled = commands.ValidateEngagement().execute(engagement, "0,1,2,3", {cancel_folder!r}, False)
verdict["cancelled"] = [cancelled, os.path.exists({cancel_folder!r}), engagement.ValidationReport == page]
verdict["report_validate"] = report_since(start)

# ---- ABM_ComputeEngagement non-interactive (scripts): the job's values; undo --------------------
start = len(report.toPlainText())
FreeCADGui.Selection.clearSelection()
FreeCADGui.Selection.addSelection(stock); FreeCADGui.Selection.addSelection(path)
second = commands.ComputeEngagement().execute(commands.load_settings(os.path.join({model!r}, "job.json")))
FreeCADGui.updateGui()
verdict["second"] = None if second is None else [second.State, second.DepthOfCutMax.Value,
                                                 second.Stock.Name, second.Toolpath.Name,
                                                 len(second.ViewObject.Proxy.colours)]
verdict["undo_names_2"] = list(doc.UndoNames)
doc.undo()
verdict["after_undo"] = [o.Name for o in doc.Objects]
verdict["report_compute"] = report_since(start)

# ---- errors: the command line's message in the report view, the document unchanged ---------
start = len(report.toPlainText())
before = [o.Name for o in doc.Objects]
made = commands.ImportToolpath().execute({bad!r})
doc.recompute()
verdict["bad_import"] = [made is None, [o.Name for o in doc.Objects] == before,
                         all(o.isValid() for o in doc.Objects)]
commands.ImportStock().execute(os.path.join({model!r}, "stock.json"))
FreeCADGui.Selection.clearSelection()
FreeCADGui.runCommand("ABM_ComputeEngagement")
verdict["ambiguous"] = task_panel.shown() is None
verdict["report_errors"] = report_since(start)

# ---- a new document: import, then ABM_ComputeEngagement's task panel typed in and accepted -----
doc2 = FreeCAD.newDocument("Imported")
stock2 = commands.ImportStock().execute(os.path.join({model!r}, "stock.json"))
path2 = commands.ImportToolpath().execute(os.path.join({model!r}, "toolpath.csv"))
FreeCADGui.Selection.clearSelection()
start = len(report.toPlainText())
FreeCADGui.runCommand("ABM_ComputeEngagement")
FreeCADGui.updateGui()
panel = task_panel.shown()
verdict["new_panel"] = [ok(), panel.message.text(), [o.Name for o in doc2.Objects]]
for name, value in (("Diameter", 12.0), ("Flutes", 2), ("FluteLength", 30.0), ("FeedPerTooth", 0.1),
                    ("Inclination", 10.0), ("PhiStep", 5.0)):
    panel.set_number(name, value)
FreeCADGui.updateGui()
verdict["new_ok"] = [ok(), panel.message.text(), panel.accept()]
third = doc2.getObject("Engagement")
verdict["imported"] = [stock2.State, path2.State, third.State, third.DepthOfCutMin.Value,
                       third.DepthOfCutMax.Value, third.Instants, type(third.ViewObject.Proxy).__name__,
                       list(doc2.UndoNames)[:1]]
# Cancel takes a new engagement back
FreeCADGui.Selection.clearSelection()
FreeCADGui.Selection.addSelection(stock2); FreeCADGui.Selection.addSelection(path2)
FreeCADGui.runCommand("ABM_ComputeEngagement")
FreeCADGui.updateGui()
task_panel.shown().reject()
verdict["rejected"] = [o.Name for o in doc2.Objects]
verdict["report_imported"] = report_since(start)

# ---- an APT toolpath: the fields it fixes are read-only and explained ----------------------------
path3 = commands.ImportToolpath().execute({apt!r})
FreeCADGui.Selection.clearSelection()
FreeCADGui.Selection.addSelection(stock2); FreeCADGui.Selection.addSelection(path3)
FreeCADGui.runCommand("ABM_ComputeEngagement")
FreeCADGui.updateGui()
panel = task_panel.shown()
panel.set_number("Flutes", 2)
FreeCADGui.updateGui()
verdict["apt_panel"] = [[panel.field(n).isEnabled() for n in ("Diameter", "FluteLength", "SpindleSpeed",
                                                               "FeedPerTooth", "Flutes")],
                        panel.number("Diameter"), panel.number("FeedPerTooth"),
                        panel.fixed.text()]
panel.reject()
for folder in {folders!r}:
    grab_screen(os.path.join(folder, "window.png"))
    shots.append(os.path.join(folder, "window.png"))
verdict["shots"] = shots

# ---- ABM_ImportStock with a solid of the document selected: no dialog, the solid linked ---------
start = len(report.toPlainText())
import Part
solid = doc2.addObject("Part::Feature", "Solid")
solid.Shape = Part.read(os.path.join({model!r}, "stock.step"))
doc2.recompute()
FreeCADGui.Selection.clearSelection()
FreeCADGui.Selection.addSelection(solid)
FreeCADGui.runCommand("ABM_ImportStock")
linked = [o for o in doc2.Objects if o.Name.startswith("Stock") and o.SourceObject is not None]
verdict["from_solid"] = [len(linked), linked[0].SourceObject.Name if linked else None,
                         linked[0].Sections if linked else None, list(doc2.UndoNames)[:1]]
# ---- closing the document the dock shows empties it -----------------------------------------------
shown_in = panel_dock.obj.Document.Name
FreeCAD.closeDocument(doc2.Name)
FreeCADGui.updateGui()
verdict["dock_closed"] = [shown_in, panel_dock.obj is None, panel_dock.about.text()]
verdict["report_last"] = report_since(start)
"""


def test_commands_on_model_test_1_task_panel_dock_validate_undo_and_errors(tmp_path, run_gui):
    from abm_workbench.formats.toolpath_csv import load_toolpath

    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    bad = tmp_path / "bad.csv"
    bad.write_text("x,y,z\n1,2,3\n")
    with pytest.raises(InputError) as cli_error:
        load_path(str(bad))
    with pytest.raises(ParameterError) as negative:
        BY_NAME["diameter"].check(-3.0)
    toolpath = load_toolpath(os.path.join(MODEL, "toolpath.csv"))
    axes = np.stack([np.sin(np.radians(toolpath.theta_b)),
                     -np.sin(np.radians(toolpath.theta_a)) * np.cos(np.radians(toolpath.theta_b)),
                     np.cos(np.radians(toolpath.theta_a)) * np.cos(np.radians(toolpath.theta_b))], axis=1)
    apt = tmp_path / "path.apt"
    apt.write_text(APT.format(moves="".join("GOTO/" + ",".join(f"{v:.12f}" for v in (*p, *w)) + "\n"
                                            for p, w in zip(toolpath.cl, axes))))
    folders = [str(tmp_path / "shots"), SCREENSHOTS]
    report_folder, cancel_folder = str(tmp_path / "validation"), str(tmp_path / "cancelled")

    verdict = run_gui(BODY.format(names=NAMES, folders=folders, bad=str(bad), model=MODEL, apt=str(apt),
                                  report_folder=report_folder, cancel_folder=cancel_folder))

    assert verdict["workbench"] == "ABMWorkbench"
    assert verdict["commands"] == sorted(NAMES)
    assert len(verdict["toolbar"]) == len(NAMES) and all(verdict["icons"])
    # model test 1: STEP stock with exact walls, 53 CL points, job.json's tool and cut
    assert [o[0] for o in verdict["objects"]] == ["Stock", "Toolpath", "Engagement"]
    assert all(o[1] == ["Up-to-date"] for o in verdict["objects"])
    assert [o[2] for o in verdict["objects"]] == ["StockViewProvider", "ToolpathViewProvider",
                                                  "EngagementViewProvider"]
    assert verdict["icon_files"] == ["ABM_ImportStock.svg", "ABM_ImportToolpath.svg", "ABM_ComputeEngagement.svg"]
    assert verdict["stock"] == [17, 1, 15, "exact", "stock.step", 75]
    assert verdict["toolpath"] == [53, 4.0]
    low, high, engaged, diameter, flutes, inclination, feed, window, y0, y1 = verdict["engagement"]
    assert 1.7 < low < 1.9 and 7.3 < high < 7.5 and engaged > 40
    assert (diameter, flutes, inclination, feed) == (12, 2, 10, pytest.approx(0.1))
    assert (window, y0, y1) == ("auto", -15.0, 15.0)  # exact walls: the whole y range, as the command line
    # one mesh: every vertex (an engaged instant's LEP or UEP) coloured by the UEP surface of its
    # segment; tops, straight and curved walls
    assert verdict["faces"][0] > 1000 and verdict["faces"][0] == verdict["faces"][1] and verdict["faces"][2] > 1000
    assert verdict["colours_match"]
    assert {"top", "straight_wall", "curved_wall"} <= set(verdict["surfaces"])
    assert verdict["undo_names"] == ["Open model test 1"]
    assert "error" not in verdict["report_open"].lower(), verdict["report_open"]
    # the dock: the CL slider moves the highlight, the text and the pass progression's marker
    assert verdict["dock"] == [True, "Engagement", 52]
    cl = verdict["slider"][0]
    assert verdict["slider"][1:5] == [cl, f"CL {cl}", verdict["slider"][3], 4] and verdict["slider"][3] > 5
    assert verdict["slider"][5] == [[cl, cl]]
    assert verdict["legend_segment"][0] == "segment"
    assert {"top", "straight_wall", "curved_wall"} <= set(verdict["legend_segment"][1])
    # colour by length: the legend's range (the engaged instants') and units; every vertex's colour is
    # the length of cut of the instant it lies on (found by geometry), on the colour map
    colour_by, kind, unit, low_length, high_length, bar = verdict["legend_length"]
    assert (colour_by, kind, unit, bar) == ("length", "length", "mm", True)
    max_distance, colour_error, vertex_low, vertex_high, shortest, longest = verdict["length_colours"]
    assert max_distance < 1e-9 and colour_error < 1e-6, verdict["length_colours"]
    assert (low_length, high_length) == (pytest.approx(shortest), pytest.approx(longest))
    assert (vertex_low, vertex_high) == (pytest.approx(shortest), pytest.approx(longest))
    assert "error" not in verdict["report_dock"].lower(), verdict["report_dock"]
    # the task panel: the job model's check in plain words, the field marked, OK disabled
    assert verdict["panel_open"] == [True, True, "", 12.0, 10.0]
    assert verdict["panel_bad"] == [False, label_words(negative.value), True, False, False]
    assert label_words(negative.value) == "Tool diameter must be positive, got -3 mm."
    assert verdict["panel_good"] == [True, ""] and verdict["accepted"] is True
    state, inclination, said, instants, closed, not_editing, undo_names = verdict["edited"]
    assert state == ["Up-to-date"] and inclination == 5.0 and said and closed and not_editing
    assert instants == 53 * 91 and undo_names == ["Edit engagement", "Open model test 1"]  # φ step 2°
    assert verdict["edit_undone"] == [10.0, 53 * 181, ["Up-to-date"], 53 * 181]
    assert verdict["edit_cancelled"] == [10.0, ["Up-to-date"], True, True, True]
    assert "error" not in verdict["report_panel"].lower(), verdict["report_panel"]
    # validation: the report written and recorded, one undo step; a cancelled one writes nothing
    page, recorded, undo_names = verdict["validated"]
    assert page == os.path.join(report_folder, "index.html") == recorded and undo_names == ["Validate engagement…"]
    text = open(page, encoding="utf-8").read()
    assert "CL points 22, " in text and "pass CL 22" in text
    assert {"comparison.csv", "segments.csv", "surfaces.csv", "depth.csv"} <= set(os.listdir(report_folder))
    assert verdict["cancelled"] == [None, False, True]
    assert "ABM: validation cancelled: nothing written" in verdict["report_validate"]
    assert "error" not in verdict["report_validate"].lower(), verdict["report_validate"]
    # ComputeEngagement for scripts: the job's values, the same results; one undo removes it
    state, depth_max, stock, path, colours = verdict["second"]
    assert state == ["Up-to-date"] and depth_max == pytest.approx(high) and (stock, path) == ("Stock", "Toolpath")
    assert colours == verdict["faces"][0]
    assert verdict["undo_names_2"][0] == "Compute engagement"
    assert verdict["after_undo"] == ["Stock", "Toolpath", "Engagement"]
    assert "error" not in verdict["report_compute"].lower(), verdict["report_compute"]
    # errors: in plain words, nothing added, the document still recomputes
    assert verdict["bad_import"] == [True, True, True]
    assert f"ABM: {cli_error.value}" in verdict["report_errors"]
    assert verdict["ambiguous"]
    assert "ABM: 2 stocks in the document: select the one to use" in verdict["report_errors"]
    # the task panel of a new engagement: OK only once the required values are typed
    assert verdict["new_panel"] == [False, "Tool diameter is required: the field is empty.",
                                    ["Stock", "Toolpath", "Engagement"]]
    assert verdict["new_ok"] == [True, "", True]
    assert verdict["imported"][:3] == [["Up-to-date"]] * 3
    assert verdict["imported"][3] == pytest.approx(low, abs=0.1) and verdict["imported"][4] == pytest.approx(high, abs=0.1)
    assert verdict["imported"][5:] == [53 * 37, "EngagementViewProvider", ["Compute engagement"]]
    assert verdict["rejected"] == ["Stock", "Toolpath", "Engagement"]
    assert "error" not in verdict["report_imported"].lower(), verdict["report_imported"]
    # an APT toolpath fixes diameter, flute length, spindle and (with the flutes typed) the feed per tooth
    enabled, apt_diameter, apt_feed, fixed = verdict["apt_panel"]
    assert enabled == [False, False, False, False, True]
    assert apt_diameter == 12.0 and apt_feed == pytest.approx(800 / 4000 / 2)
    assert "path.apt CUTTER" in fixed and "path.apt FEDRAT" in fixed
    for shot in verdict["shots"]:
        assert os.path.getsize(shot) > 20_000, shot  # a picture, not a blank view
    # a stock from the selected solid; the dock emptied when its document closes
    assert verdict["from_solid"] == [1, "Solid", 17, ["Import stock…"]]
    assert verdict["dock_closed"] == ["Imported", True, ""]
    assert "error" not in verdict["report_last"].lower(), verdict["report_last"]


def test_make_screenshots_writes_the_readme_pictures_with_visible_segments(tmp_path):
    from PIL import Image

    from abm_workbench.gui.screenshots import main

    assert main(str(tmp_path)) == 0
    names = ["gui_window.png", "gui_cl_segments.png", "gui_cl_length.png", "gui_task_panel.png", "gui_dock_forces.png",
             "gui_program.png"]
    assert sorted(os.listdir(tmp_path)) == sorted(names)
    pixels = np.asarray(Image.open(tmp_path / "gui_cl_segments.png").convert("RGB")).reshape(-1, 3).astype(int)
    r, g, b = pixels.T
    counts = {"blue": np.count_nonzero((b > r + 40) & (b > g)),  # tops
              "red": np.count_nonzero((r > g + 60) & (r > b + 40) & (g < 90)),  # curved walls
              "orange": np.count_nonzero((r > b + 60) & (g > 90) & (g < r - 30)),  # straight walls
              "yellow": np.count_nonzero((r > 200) & (g > 180) & (b < 60))}  # the chosen CL point
    assert all(count > 500 for count in counts.values()), counts
    for name in names:
        assert os.path.getsize(tmp_path / name) > 20_000, name


RESTORE_BODY = """
FreeCADGui.activateWorkbench("ABMWorkbench")
FreeCADGui.updateGui()
def look(doc):
    FreeCADGui.updateGui()
    engagement = doc.getObject("Engagement")
    return {{"providers": [type(o.ViewObject.Proxy).__name__ for o in doc.Objects],
             "faces": len(engagement.ViewObject.Proxy.mesh.points),
             "colours": sorted({{tuple(round(float(v), 2) for v in c) for c in engagement.ViewObject.Proxy.colours}}),
             "count": len(engagement.ViewObject.Proxy.colours)}}
doc = FreeCAD.openDocument({headless!r})
verdict["headless"] = look(doc)
doc.saveAs({saved!r})
FreeCAD.closeDocument(doc.Name)
verdict["reopened"] = look(FreeCAD.openDocument({saved!r}))
"""


def test_view_providers_attach_to_a_document_made_headless_and_survive_saving(tmp_path, run_gui):
    from abm_workbench.cad.freecad_env import FreeCAD
    from abm_workbench.features import create_engagement, create_stock, create_toolpath
    from abm_workbench.report.colours import SURFACE_COLOURS

    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    doc = FreeCAD.newDocument("Headless")
    try:
        stock = create_stock(doc, os.path.join(MODEL, "stock.json"))
        path = create_toolpath(doc, os.path.join(MODEL, "toolpath.csv"))
        create_engagement(doc, stock, path, diameter=12, flutes=2, flute_length=30, feed_per_tooth=0.1,
                          inclination=10, phi_step=10)
        doc.recompute()
        assert all(obj.isValid() for obj in doc.Objects)
        doc.saveAs(str(tmp_path / "headless.FCStd"))
    finally:
        FreeCAD.closeDocument(doc.Name)

    verdict = run_gui(RESTORE_BODY.format(headless=str(tmp_path / "headless.FCStd"), saved=str(tmp_path / "saved.FCStd")))

    # the UEP surfaces' colours, to 0.01
    palette = {tuple(round(v, 2) for v in colour) for colour in SURFACE_COLOURS.values()}
    for state in ("headless", "reopened"):
        look = verdict[state]
        assert look["providers"] == ["StockViewProvider", "ToolpathViewProvider", "EngagementViewProvider"], state
        assert look["faces"] > 100 and look["count"] == look["faces"], state
        assert len(look["colours"]) >= 2 and {tuple(c) for c in look["colours"]} <= palette, state
