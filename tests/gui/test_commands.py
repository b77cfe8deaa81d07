"""The ABM commands in the real FreeCAD GUI: workbench, objects, colours, undo, errors, screenshots.

One GUI session (~30 s): the checkout is linked into the test HOME's Mod folder so FreeCAD finds
the workbench, as `make install` does. Screenshots go to tmp and to build/screenshots/.
"""

import os

import pytest

from abm_workbench.errors import InputError
from abm_workbench.jobs import load_path
from tests.conftest import ROOT

MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")
SCREENSHOTS = os.path.join(ROOT, "build", "screenshots")
NAMES = ["ABM_OpenModelTest", "ABM_ImportStock", "ABM_ImportToolpath", "ABM_ComputeEngagement"]

BODY = """
from PySide2 import QtWidgets
import numpy as np
from pivy import coin

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
                         engagement.Inclination.Value, engagement.FeedPerTooth.Value]
verdict["icon_files"] = [os.path.basename(o.ViewObject.Proxy.getIcon()) for o in doc.Objects]
result = engagement.Proxy.result(engagement)
from abm_workbench.features.engagement import engaged_surface_parts
from abm_workbench.report.colours import SURFACE_COLOURS
shapes, keys = engaged_surface_parts(result)
expected = []
for shape, key in zip(shapes, keys):
    expected += [SURFACE_COLOURS[key[2]]] * len(shape.Faces)
colours = [tuple(c[:3]) for c in engagement.ViewObject.DiffuseColor]
verdict["faces"] = [len(engagement.Shape.Faces), len(colours)]
verdict["colours_match"] = len(colours) == len(expected) and bool(np.allclose(colours, expected, atol=1e-6))
verdict["surfaces"] = sorted({{key[2] for key in keys}})
verdict["undo_names"] = list(doc.UndoNames)

# screenshots: the whole pass, then zoomed on the CL point with the most kinds of UEP surface
view = FreeCADGui.ActiveDocument.ActiveView
view.viewIsometric(); view.fitAll(); FreeCADGui.updateGui()
shots = []
for folder in {folders!r}:
    os.makedirs(folder, exist_ok=True)
    view.saveImage(os.path.join(folder, "model_test_1.png"), 1024, 768, "White")
    shots.append(os.path.join(folder, "model_test_1.png"))
cl = max(range(result.shape[0]), key=lambda i: (len({{s["surface"] for s in result.segments(i)}}),
                                                len(result.segments(i))))
points = np.concatenate([result.lep_xyz[cl], result.uep_xyz[cl]])
centre = points[~np.isnan(points).any(axis=1)].mean(axis=0)
camera = view.getCameraNode()
direction = camera.orientation.getValue().multVec(coin.SbVec3f(0, 0, -1))
camera.position.setValue(coin.SbVec3f(*centre) - direction * camera.focalDistance.getValue())
camera.height.setValue(30)
FreeCADGui.updateGui()
for folder in {folders!r}:
    view.saveImage(os.path.join(folder, "model_test_1_cl%03d.png" % cl), 1024, 768, "White")
    shots.append(os.path.join(folder, "model_test_1_cl%03d.png" % cl))
verdict["zoom_cl"] = [cl, sorted({{s["surface"] for s in result.segments(cl)}})]
from PySide2 import QtGui
image = QtGui.QImage(shots[-1]).convertToFormat(QtGui.QImage.Format_RGB888)
pixels = np.frombuffer(bytes(image.constBits()), np.uint8)[:image.height() * image.bytesPerLine()]
pixels = pixels.reshape(image.height(), image.bytesPerLine())[:, :3 * image.width()].reshape(-1, 3).astype(int)
r, g, b = pixels.T
verdict["pixels"] = {{"blue": int(np.count_nonzero((b > r + 40) & (b > g))),  # tops
                     "red": int(np.count_nonzero((r > g + 60) & (r > b + 40) & (g < 90))),  # curved walls
                     "orange": int(np.count_nonzero((r > b + 60) & (g > 90) & (g < r - 30)))}}  # straight walls
verdict["shots"] = shots
verdict["report_open"] = report_since(start)

# ---- ABM_ComputeEngagement from the selection, then undo -------------------------------------
start = len(report.toPlainText())
FreeCADGui.Selection.clearSelection()
FreeCADGui.Selection.addSelection(stock); FreeCADGui.Selection.addSelection(path)
FreeCADGui.runCommand("ABM_ComputeEngagement")
FreeCADGui.updateGui()
second = doc.getObject("Engagement001")
verdict["second"] = None if second is None else [second.State, second.DepthOfCutMax.Value,
                                                 second.Stock.Name, second.Toolpath.Name,
                                                 len(second.ViewObject.DiffuseColor)]
verdict["undo_names_2"] = list(doc.UndoNames)
doc.undo()
verdict["after_undo"] = [o.Name for o in doc.Objects]
verdict["report_compute"] = report_since(start)

# ---- errors: the command line's message in the report view, the document unchanged ---------
from abm_workbench.gui import commands
start = len(report.toPlainText())
before = [o.Name for o in doc.Objects]
made = commands.ImportToolpath().execute({bad!r})
doc.recompute()
verdict["bad_import"] = [made is None, [o.Name for o in doc.Objects] == before,
                         all(o.isValid() for o in doc.Objects)]
commands.ImportStock().execute(os.path.join({model!r}, "stock.json"))
made = commands.ComputeEngagement().execute([])
verdict["ambiguous"] = made is None
verdict["report_errors"] = report_since(start)

# ---- ImportStock, ImportToolpath and ComputeEngagement in a new document -------------------
FreeCAD.newDocument("Imported")
stock2 = commands.ImportStock().execute(os.path.join({model!r}, "stock.json"))
path2 = commands.ImportToolpath().execute(os.path.join({model!r}, "toolpath.csv"))
FreeCADGui.Selection.clearSelection()
start = len(report.toPlainText())
third = commands.ComputeEngagement().execute()
FreeCADGui.updateGui()
verdict["imported"] = [stock2.State, path2.State, third.State, third.DepthOfCutMin.Value,
                       third.DepthOfCutMax.Value, type(third.ViewObject.Proxy).__name__]
verdict["report_imported"] = report_since(start)
"""


def test_commands_build_model_test_1_colour_it_undo_and_report_errors(tmp_path, run_gui):
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    bad = tmp_path / "bad.csv"
    bad.write_text("x,y,z\n1,2,3\n")
    with pytest.raises(InputError) as cli_error:
        load_path(str(bad))
    folders = [str(tmp_path / "shots"), SCREENSHOTS]

    verdict = run_gui(BODY.format(names=NAMES, folders=folders, bad=str(bad), model=MODEL))

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
    low, high, engaged, diameter, flutes, inclination, feed = verdict["engagement"]
    assert 1.7 < low < 1.9 and 7.3 < high < 7.5 and engaged > 40
    assert (diameter, flutes, inclination, feed) == (12, 2, 10, pytest.approx(0.1))
    # every face coloured by the UEP surface of its segment; tops, straight and curved walls
    assert verdict["faces"][0] > 1000 and verdict["faces"][0] == verdict["faces"][1]
    assert verdict["colours_match"]
    assert {"top", "straight_wall", "curved_wall"} <= set(verdict["surfaces"])
    assert verdict["undo_names"] == ["Open model test 1"]
    assert len(verdict["zoom_cl"][1]) >= 3
    assert all(count > 500 for count in verdict["pixels"].values()), verdict["pixels"]  # segments seen
    for shot in verdict["shots"]:
        assert os.path.getsize(shot) > 20_000, shot  # a picture, not a blank view
    assert "error" not in verdict["report_open"].lower(), verdict["report_open"]
    # ComputeEngagement from the selection: the same results; one undo removes it
    state, depth_max, stock, path, colours = verdict["second"]
    assert state == ["Up-to-date"] and depth_max == pytest.approx(high) and (stock, path) == ("Stock", "Toolpath")
    assert colours == verdict["faces"][0]
    assert verdict["undo_names_2"][0] == "Compute engagement"
    assert verdict["after_undo"] == ["Stock", "Toolpath", "Engagement"]
    assert "error" not in verdict["report_compute"].lower(), verdict["report_compute"]
    # errors: the command line's message, nothing added, the document still recomputes
    assert verdict["bad_import"] == [True, True, True]
    assert f"abm: error: {cli_error.value}" in verdict["report_errors"]
    assert verdict["ambiguous"]
    assert "abm: error: 2 stocks in the document: select the one to use" in verdict["report_errors"]
    # the import commands and ComputeEngagement (job.json beside the toolpath) in a new document
    assert verdict["imported"][:3] == [["Up-to-date"]] * 3
    assert verdict["imported"][3] == pytest.approx(low, abs=0.1) and verdict["imported"][4] == pytest.approx(high, abs=0.1)
    assert verdict["imported"][5] == "EngagementViewProvider"
    assert "error" not in verdict["report_imported"].lower(), verdict["report_imported"]


RESTORE_BODY = """
FreeCADGui.activateWorkbench("ABMWorkbench")
FreeCADGui.updateGui()
def look(doc):
    FreeCADGui.updateGui()
    engagement = doc.getObject("Engagement")
    return {{"providers": [type(o.ViewObject.Proxy).__name__ for o in doc.Objects],
             "faces": len(engagement.Shape.Faces),
             "colours": sorted({{tuple(round(v, 2) for v in c[:3]) for c in engagement.ViewObject.DiffuseColor}}),
             "count": len(engagement.ViewObject.DiffuseColor)}}
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

    # saved colours are 8 bits per channel: compare to 0.01
    palette = {tuple(round(v, 2) for v in colour) for colour in SURFACE_COLOURS.values()}
    for state in ("headless", "reopened"):
        look = verdict[state]
        assert look["providers"] == ["StockViewProvider", "ToolpathViewProvider", "EngagementViewProvider"], state
        assert look["faces"] > 100 and look["count"] == look["faces"], state
        assert len(look["colours"]) >= 2 and {tuple(c) for c in look["colours"]} <= palette, state
