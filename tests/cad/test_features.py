"""The parametric document objects (abm_workbench.features), headless: create, recompute, save,
reopen without recomputing, change a property, bad input."""

import functools
import json
import os
import re
import subprocess
import sys

import numpy as np
import pytest

from abm_workbench.cad.freecad_env import FreeCAD, Part
from abm_workbench.engine import CutSettings, Tool, engage
from abm_workbench.engine import flute_engagement
from abm_workbench.errors import InputError
from abm_workbench.forces import material, pass_forces
from abm_workbench.features import VERSION, create_engagement, create_stock, create_toolpath
from abm_workbench.features import engagement as engagement_module
from abm_workbench.features.engagement import EngagementFeature
from abm_workbench.formats.toolpath_csv import load_toolpath
from abm_workbench.jobs import load_path, load_stock, swept_y_window
from tests.conftest import ROOT

MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")
STOCK_JSON, STOCK_STEP = os.path.join(MODEL, "stock.json"), os.path.join(MODEL, "stock.step")
TOOLPATH = os.path.join(MODEL, "toolpath.csv")
with open(os.path.join(MODEL, "job.json"), encoding="utf-8") as _file:
    JOB = json.load(_file)
SETTINGS = {key: JOB[key] for key in ("diameter", "flutes", "flute_length", "feed_per_tooth", "inclination",
                                      "spindle_rpm", "phi_range", "phi_step")}
ARRAYS = ("phi", "h", "lep_l", "uep_l", "length", "pieces", "uep_surface", "uep_section", "uep_wall", "case",
          "segment", "area", "lep_xyz", "uep_xyz", "depth_of_cut")
APT = """\
MULTAX/ON
CUTTER/12,0,6,0,0,0,60
CSI_SET_FLUTE_LENGTH/30
SPINDL/RPM,4000,CLW
FEDRAT/MMPM,800
AUXFUN/3
{moves}END-OF-PATH
"""


@pytest.fixture
def doc():
    """A new document, closed after the test (whatever its name is by then)."""
    document = FreeCAD.newDocument("ABMFeatures")
    name = document.Name
    yield document
    if name in FreeCAD.listDocuments():
        FreeCAD.closeDocument(name)


def reference(stock=STOCK_JSON, inclination=JOB["inclination"]):
    """The engine's Engagement of model test 1 with the job's values."""
    tool = Tool(JOB["diameter"], JOB["flutes"], JOB["flute_length"])
    settings = CutSettings(JOB["feed_per_tooth"], inclination, *JOB["phi_range"], JOB["phi_step"], JOB["spindle_rpm"])
    return engage(load_stock(stock).staircase, tool, load_toolpath(TOOLPATH), settings)


def assert_same(result, expected, atol=0.0):
    """Every array of two Engagements equal (NaN equal to NaN), floats within atol."""
    for name in ARRAYS:
        a, b = getattr(result, name), getattr(expected, name)
        assert a.shape == b.shape, name
        if np.issubdtype(b.dtype, np.floating):
            np.testing.assert_allclose(a, b, rtol=0.0, atol=atol, err_msg=name)
        else:
            np.testing.assert_array_equal(a, b, err_msg=name)


def model_test(doc, stock=STOCK_JSON, **options):
    """Stock, toolpath and engagement of model test 1 in `doc` (not recomputed), against the initial stock
    unless `options` say otherwise (tests/cad/test_inprocess_feature.py tests the in-process one)."""
    stock_obj = create_stock(doc, stock)
    toolpath = create_toolpath(doc, TOOLPATH)
    return stock_obj, toolpath, create_engagement(doc, stock_obj, toolpath, **SETTINGS,
                                                  **{"stock_model": "initial", **options})


def test_factories_raise_without_a_document(monkeypatch):
    monkeypatch.setattr(FreeCAD, "ActiveDocument", None)
    for factory, args in ((create_stock, (STOCK_JSON,)), (create_toolpath, (TOOLPATH,)),
                          (create_engagement, (None, None))):
        with pytest.raises(RuntimeError, match="no document"):
            factory(None, *args)


def test_engagement_equals_the_engine_and_is_restored_without_recompute(doc, tmp_path, monkeypatch):
    stock, toolpath, engagement = model_test(doc)
    assert doc.recompute() == 3
    assert all(obj.isValid() for obj in doc.Objects)
    expected = reference()
    result = engagement.Proxy.result(engagement)
    assert_same(result, expected)

    assert (stock.Sections, stock.StraightWalls, stock.CurvedWalls) == (17, 1, 15)
    assert (stock.YMin.Value, stock.YMax.Value) == (-15.0, 15.0)
    assert stock.Shape.isValid() and stock.Shape.Solids
    assert toolpath.CLPoints == 53 and len(toolpath.Shape.Vertexes) == 53 and toolpath.ToolDiameter.Value == 0.0
    assert engagement.Instants == 53 * 181 and engagement.EngagedCLPoints == 53
    assert engagement.EngagedInstants == int(expected.engaged.sum())
    assert engagement.DepthOfCutMin.Value == pytest.approx(np.nanmin(expected.depth_of_cut), abs=1e-12)
    assert engagement.DepthOfCutMax.Value == pytest.approx(np.nanmax(expected.depth_of_cut), abs=1e-12)
    assert engagement.MaxLengthOfCut.Value == pytest.approx(expected.length.max(), abs=1e-12)
    assert engagement.EngineTime > 0.0
    assert "diameter 12 mm [Diameter]" in engagement.Parameters
    # The Shape: the outline, one closed polyline edge (or a line) per CL point and engagement segment,
    # through that segment's LEP and UEP points and them only (the GUI draws the surface as a mesh).
    segments = [(cl, segment) for cl in range(53) for segment in expected.segments(cl)]
    assert engagement.Shape.isValid() and len(engagement.Shape.childShapes()) == len(segments)
    assert not engagement.Shape.Faces
    shapes, keys = engagement_module.engaged_outline_parts(result)
    assert len(shapes) == len(keys) == len(segments) and keys[0][:2] == (0, "A")
    assert keys == [(cl, segment["letter"], segment["surface"]) for cl, segment in segments]
    for shape, (cl, segment) in zip(engagement.Shape.childShapes(), segments):
        rows = (expected.phi >= segment["phi_start"]) & (expected.phi <= segment["phi_end"])
        ends = np.concatenate([expected.lep_xyz[cl, rows], expected.uep_xyz[cl, rows]])
        corners = np.array([list(point) for point in shape.Curve.getPoles()])
        assert np.abs(corners[:, None] - ends[None]).max(axis=2).min(axis=1).max() < 1e-9
        assert np.abs(ends[:, None] - corners[None]).max(axis=2).min(axis=1).max() < 1e-9
        assert len(shape.Edges) == 1 and shape.Curve.Degree == 1
        assert shape.isClosed() == (rows.sum() > 1)
    for name in ("DepthOfCutMax", "Instants", "ResultsFile"):
        assert engagement.getEditorMode(name) == ["ReadOnly"]
    assert engagement.getGroupOfProperty("Diameter") == "Tool" and engagement.getDocumentationOfProperty("Diameter")
    assert engagement.Version == VERSION

    # Unsaved: the results sit in a temporary folder; saved: beside the document.
    assert os.path.isabs(engagement.ResultsFile) and os.path.isfile(engagement.ResultsFile)
    path = tmp_path / "job.FCStd"
    doc.saveAs(str(path))
    assert engagement.ResultsFile == os.path.join("job_abm", "Engagement.csv")
    assert (tmp_path / "job_abm" / "Engagement.csv").is_file()
    assert (tmp_path / "job_abm" / "Engagement.summary.csv").is_file()
    FreeCAD.closeDocument(doc.Name)
    forbid_the_engine(monkeypatch)
    reopened = FreeCAD.openDocument(str(path))
    try:
        engagement = reopened.getObject("Engagement")
        assert isinstance(engagement.Proxy, EngagementFeature)
        assert "Touched" not in engagement.State and engagement.isValid()
        assert_same(engagement.Proxy.result(engagement), expected, atol=1e-9)
        assert engagement.Instants == 53 * 181 and engagement.Shape.isValid()
        assert reopened.getObject("Stock").Sections == 17
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_a_property_change_touches_and_recompute_updates(doc):
    _, _, engagement = model_test(doc)
    engagement.ShowSurfaces = False
    doc.recompute()
    assert engagement.Shape.isNull()
    before = engagement.Proxy.result(engagement)
    engagement.Inclination = 5.0
    assert "Touched" in engagement.State
    doc.recompute()
    assert "Touched" not in engagement.State
    after = engagement.Proxy.result(engagement)
    assert_same(after, reference(inclination=5.0))
    assert not np.array_equal(after.h, before.h)
    assert "inclination 5° [Inclination]" in engagement.Parameters


def test_missing_file_is_an_error_state_and_the_document_stays_usable(doc, tmp_path):
    missing = str(tmp_path / "nowhere.json")
    stock, toolpath, engagement = model_test(doc, missing)
    engagement.ShowSurfaces = False
    assert doc.recompute() != 3
    with pytest.raises(InputError) as error:
        load_stock(missing)
    assert not stock.isValid() and stock.getStatusString() == str(error.value)
    # FreeCAD does not run the objects that depend on an invalid one: they stay touched.
    assert "Touched" in engagement.State and engagement.Proxy.result(engagement) is None
    assert toolpath.isValid()
    stock.SourceFile = STOCK_JSON
    doc.recompute()
    assert all(obj.isValid() for obj in doc.Objects)
    assert engagement.Proxy.result(engagement) is not None


def test_errors_are_in_plain_words_with_the_property_named(doc, tmp_path):
    far = tmp_path / "far.csv"
    path = load_toolpath(TOOLPATH)
    rows = "".join(f"{x},{y + 500},{z},{a},{b}\n" for (x, y, z), a, b in zip(path.cl, path.theta_a, path.theta_b))
    far.write_text("x,y,z,theta_a,theta_b\n" + rows)
    stock = create_stock(doc, STOCK_JSON)
    toolpath = create_toolpath(doc, far)
    engagement = create_engagement(doc, stock, toolpath, **{**SETTINGS, "flutes": None})
    engagement.ShowSurfaces = False
    doc.recompute()
    assert engagement.getStatusString() == ("Engagement: Number of flutes is required: the toolpath file does not "
                                            "give it (property Flutes).")
    engagement.Flutes = 2
    doc.recompute()
    assert engagement.getStatusString() == (
        f"{far}: the tool never touches the stock: no CL point of the pass engages it (are the toolpath and "
        f"{STOCK_JSON} in the same frame?)")
    engagement.WallModel = "exact"
    doc.recompute()
    assert engagement.getStatusString().startswith("WallModel exact applies to a solid stock")
    toolpath.File = TOOLPATH
    engagement.WallModel = "stock"
    doc.recompute()
    assert engagement.isValid()


def test_y_window_of_a_solid_stock_as_the_command_line_chooses_it(doc):
    tool = Tool(JOB["diameter"], JOB["flutes"], JOB["flute_length"])
    path = load_toolpath(TOOLPATH)
    swept = functools.partial(swept_y_window, path, tool)
    _, _, engagement = model_test(doc, STOCK_STEP, walls="quintic", y_window="auto")
    engagement.PhiStep = 10
    engagement.ShowSurfaces = False
    stock_obj = engagement.Stock
    doc.recompute()
    # auto with quintic walls: swept, as `abm engage --walls quintic` without --y-window
    expected = load_stock(STOCK_STEP, walls="quintic", y_window=swept).staircase
    assert (engagement.YWindowMin.Value, engagement.YWindowMax.Value) == pytest.approx(
        (expected.y_min, expected.y_max), abs=1e-12)
    assert expected.y_max - expected.y_min < stock_obj.YMax.Value - stock_obj.YMin.Value
    settings = CutSettings(JOB["feed_per_tooth"], JOB["inclination"], 0, 180, 10, JOB["spindle_rpm"])
    assert_same(engagement.Proxy.result(engagement), engage(expected, tool, path, settings), atol=1e-12)
    # custom: the window given, the results of `--y-window=-6:6`
    engagement.YWindow, engagement.YWindowMin, engagement.YWindowMax = "custom", -6.0, 6.0
    doc.recompute()
    expected = load_stock(STOCK_STEP, walls="quintic", y_window=(-6.0, 6.0)).staircase
    assert (expected.y_min, expected.y_max) == (-6.0, 6.0)
    assert_same(engagement.Proxy.result(engagement), engage(expected, tool, path, settings), atol=1e-12)
    # whole: the stock's y range
    engagement.YWindow = "whole"
    doc.recompute()
    assert (engagement.YWindowMin.Value, engagement.YWindowMax.Value) == (stock_obj.YMin.Value, stock_obj.YMax.Value)
    # errors: an empty custom window, a window off the stock, a window on a JSON stock
    engagement.YWindow, engagement.YWindowMin, engagement.YWindowMax = "custom", 3.0, 3.0
    doc.recompute()
    assert engagement.getStatusString() == "Engagement: YWindowMin (3 mm) must be below YWindowMax (3 mm)"
    engagement.YWindowMin, engagement.YWindowMax = 40.0, 50.0
    doc.recompute()
    assert engagement.getStatusString() == (f"{STOCK_STEP}: y window 40..50 mm misses the stock's y range "
                                            f"{stock_obj.YMin.Value:g}..{stock_obj.YMax.Value:g} mm")
    engagement.WallModel = "stock"
    stock_obj.SourceFile = STOCK_JSON
    doc.recompute()
    assert engagement.getStatusString() == (f"YWindow custom applies to a solid stock (.step, .stp, .brep, .brp, "
                                            f".FCStd), not to {STOCK_JSON}")
    with pytest.raises(ValueError, match="y_window must be auto, whole, swept or"):
        create_engagement(doc, stock_obj, engagement.Toolpath, y_window="narrow")


def test_apt_toolpath_gives_the_tool_spindle_and_feed(doc, tmp_path):
    path = load_toolpath(TOOLPATH)
    axes = np.stack([np.sin(np.radians(path.theta_b)),
                     -np.sin(np.radians(path.theta_a)) * np.cos(np.radians(path.theta_b)),
                     np.cos(np.radians(path.theta_a)) * np.cos(np.radians(path.theta_b))], axis=1)
    moves = "".join("GOTO/" + ",".join(f"{v:.12f}" for v in (*p, *w)) + "\n" for p, w in zip(path.cl, axes))
    apt = tmp_path / "path.apt"
    apt.write_text(APT.format(moves=moves))
    stock = create_stock(doc, STOCK_JSON)
    toolpath = create_toolpath(doc, apt)
    toolpath.recompute()
    assert toolpath.CLPoints == 53 and toolpath.ToolDiameter.Value == 12.0 and toolpath.FluteLength.Value == 30.0
    assert toolpath.SpindleSpeed == 4000.0 and (toolpath.Feed, toolpath.FeedUnit) == (800.0, "MMPM")
    assert toolpath.Warnings == [f"{apt}: records that carry nothing the engine needs, ignored: AUXFUN (1), "
                                 "END-OF-PATH (1)"]
    engagement = create_engagement(doc, stock, toolpath, flutes=2, inclination=10.0)
    engagement.ShowSurfaces = False
    assert (engagement.Diameter.Value, engagement.FluteLength.Value, engagement.SpindleSpeed) == (12.0, 30.0, 4000.0)
    doc.recompute()
    assert engagement.isValid(), engagement.getStatusString()
    assert "feed 0.1 mm/tooth [path.apt FEDRAT]" in engagement.Parameters
    assert "diameter 12 mm [path.apt CUTTER]" in engagement.Parameters
    # The CL file's own frames (turned to its tool tip's feed) and each move's inclination, as the engine reads it.
    tool = Tool(JOB["diameter"], JOB["flutes"], JOB["flute_length"])
    settings = CutSettings(JOB["feed_per_tooth"], 10.0, *JOB["phi_range"], JOB["phi_step"], JOB["spindle_rpm"])
    program_path, _ = load_path(apt)
    assert program_path.alpha.any() and program_path.inclination is not None
    expected = engage(load_stock(STOCK_JSON).staircase, tool, program_path, settings)
    np.testing.assert_allclose(engagement.Proxy.result(engagement).length, expected.length, atol=1e-6)


def test_stock_from_a_linked_solid_with_exact_walls(doc):
    solid = doc.addObject("Part::Feature", "Solid")
    solid.Shape = Part.read(STOCK_STEP)
    stock = create_stock(doc, solid)
    toolpath = create_toolpath(doc, TOOLPATH)
    engagement = create_engagement(doc, stock, toolpath, **SETTINGS, stock_model="initial")
    engagement.ShowSurfaces = False
    doc.recompute()
    assert all(obj.isValid() for obj in doc.Objects)
    assert (stock.Sections, stock.StraightWalls, stock.CurvedWalls) == (17, 1, 15)
    assert abs(stock.Shape.Volume - solid.Shape.Volume) < 1e-9
    assert_same(engagement.Proxy.result(engagement), reference(STOCK_STEP))


def forbid_the_engine(monkeypatch):
    """Make the engagement object's engine calls fail: what follows must not compute."""
    def no_engine(*args, **kwargs):
        raise AssertionError("the engine ran on restore")

    monkeypatch.setattr(engagement_module, "flute_1", no_engine)
    monkeypatch.setattr(engagement_module, "engage_in_process", no_engine)
    monkeypatch.setattr(engagement_module, "pass_forces_of", no_engine)


def test_restore_without_results_file_marks_touched_and_migrates(doc, tmp_path):
    _, _, engagement = model_test(doc)
    engagement.ShowSurfaces = False
    doc.recompute()
    for name in ("YWindow", "YWindowMin", "YWindowMax", "ValidationReport", "HelixAngle", "Forces", "Material",
                 "Ktc", "Krc", "Kac", "Kte", "Kre", "Kae", "ImmersionStart", "ImmersionEnd", "PeakForce",
                 "ForceFeedPerTooth", "ResultsData", "StockModel", "SweepTolerance", "ChangedCLPoints",
                 "StockModelUsed"):  # as saved by version 1
        engagement.removeProperty(name)
    engagement.Version = 1
    toolpath = doc.getObject("Toolpath")
    for name in ("Operation", "Operations"):  # as saved by version 3
        toolpath.removeProperty(name)
    toolpath.Version = 3
    path = tmp_path / "old.FCStd"
    doc.saveAs(str(path))
    FreeCAD.closeDocument(doc.Name)
    for name in os.listdir(tmp_path / "old_abm"):
        os.remove(tmp_path / "old_abm" / name)
    reopened = FreeCAD.openDocument(str(path))
    try:
        engagement = reopened.getObject("Engagement")
        assert engagement.Version == VERSION == 6
        assert engagement.CornerRadius.Value == 0.0  # version 6: a flat-end mill, as every older one
        toolpath = reopened.getObject("Toolpath")
        assert toolpath.Version == VERSION and toolpath.Operation == 0 and toolpath.Operations == []
        assert engagement.YWindow == "whole" and engagement.ValidationReport == ""  # what version 1 computed
        assert engagement.StockModel == "initial" and engagement.StockModelUsed == "initial"
        assert engagement.HelixAngle.Value == 0.0 and not engagement.Forces and engagement.PeakForce == 0.0
        assert "Touched" in engagement.State and engagement.Proxy.result(engagement) is None
        reopened.recompute()
        assert_same(engagement.Proxy.result(engagement), reference())
        reopened.save()
        engagement.Inclination = 5.0  # recomputed (the CSV rewritten) but not saved
        reopened.recompute()
    finally:
        FreeCAD.closeDocument(reopened.Name)
    # the document holds the results it was saved with (ResultsData): those of inclination 10°
    reopened = FreeCAD.openDocument(str(path))
    try:
        engagement = reopened.getObject("Engagement")
        assert engagement.Inclination.Value == 10.0
        assert "Touched" not in engagement.State
        assert_same(engagement.Proxy.result(engagement), reference())
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_the_documented_example_runs(tmp_path):
    with open(os.path.join(ROOT, "docs", "FEATURES.md"), encoding="utf-8") as file:
        text = file.read()
    script = re.search(r"```python\n(.*?)```", text, re.S).group(1)
    (tmp_path / "example.py").write_text(script)
    done = subprocess.run([sys.executable, str(tmp_path / "example.py"), str(tmp_path / "out")], cwd=ROOT,
                          capture_output=True, text=True, timeout=120, env={**os.environ, "PYTHONPATH": ROOT})
    assert done.returncode == 0, done.stderr
    assert "depth of cut 1.813-7.430 mm" in done.stdout
    assert (tmp_path / "out" / "model_test_1_abm" / "Engagement.csv").is_file()


def test_the_headless_example_of_the_usage_guide_runs(tmp_path):
    with open(os.path.join(ROOT, "docs", "USAGE.md"), encoding="utf-8") as file:
        text = file.read()
    section = text[text.index("## Scripts: the document objects without the GUI"):]
    script = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    (tmp_path / "script.py").write_text(script)
    done = subprocess.run([sys.executable, str(tmp_path / "script.py"), str(tmp_path / "out")], cwd=ROOT,
                          capture_output=True, text=True, timeout=180, env={**os.environ, "PYTHONPATH": ROOT})
    assert done.returncode == 0, done.stderr
    assert "4823 instants, depth of cut 1.81-7.43 mm; diameter 12 mm [Diameter]" in done.stdout  # 53 × 91
    assert "reopened: 53 CL points x 91 angles, max length of cut" in done.stdout
    assert (tmp_path / "out" / "pass_abm" / "Engagement.csv").is_file()


def test_links_must_be_abm_objects(doc):
    stock = create_stock(doc, STOCK_JSON)
    toolpath = create_toolpath(doc, TOOLPATH)
    engagement = create_engagement(doc, toolpath, stock, **SETTINGS)  # swapped
    doc.recompute()
    assert engagement.getStatusString() == "Engagement: Toolpath must link an ABM Toolpath object"
    with pytest.raises(TypeError, match="unknown setting 'feed'"):
        create_engagement(doc, stock, toolpath, feed=0.1)


def model_test_forces(immersion=(0.0, 120.0), helix=0.0):
    """pass_forces of model test 1 (JSON stock) with Al7075-T6 coefficients, as the object should give them."""
    tool = Tool(JOB["diameter"], JOB["flutes"], JOB["flute_length"], helix=helix)
    settings = CutSettings(JOB["feed_per_tooth"], JOB["inclination"], *JOB["phi_range"], JOB["phi_step"],
                           JOB["spindle_rpm"])
    return pass_forces(load_stock(STOCK_JSON).staircase, tool, load_toolpath(TOOLPATH), settings,
                       material("al7075-t6"), immersion=immersion)


def assert_same_forces(forces, expected, atol):
    for name in ("xyz", "torque", "power", "peak", "mean"):
        np.testing.assert_allclose(getattr(forces, name), getattr(expected, name), rtol=0.0, atol=atol, err_msg=name)


def test_forces_equal_pass_forces_and_are_restored_without_recompute(doc, tmp_path, monkeypatch):
    _, _, engagement = model_test(doc, forces=True, material="al7075-t6", immersion=(0.0, 120.0))
    engagement.ShowSurfaces = False
    assert [engagement.getEditorMode(name) for name in ("Ktc", "PeakForce")] == [["ReadOnly"]] * 2
    assert engagement.getGroupOfProperty("Ktc") == "Forces" and "N/mm²" in engagement.getDocumentationOfProperty("Ktc")
    doc.recompute()
    assert engagement.isValid()
    expected = model_test_forces()
    forces = engagement.Proxy.forces(engagement)
    assert forces.power is not None  # the job has a spindle speed
    assert_same_forces(forces, expected, 1e-9)
    assert engagement.PeakForce == pytest.approx(expected.peak.max(), abs=1e-9) and engagement.PeakForce > 100.0
    assert engagement.Ktc == material("al7075-t6").ktc
    path = tmp_path / "forces.FCStd"
    doc.saveAs(str(path))
    FreeCAD.closeDocument(doc.Name)

    forbid_the_engine(monkeypatch)
    reopened = FreeCAD.openDocument(str(path))
    try:
        engagement = reopened.getObject("Engagement")
        assert "Touched" not in engagement.State
        assert_same_forces(engagement.Proxy.forces(engagement), expected, 1e-9)
        np.testing.assert_array_equal(engagement.Proxy.forces(engagement).feed, JOB["feed_per_tooth"])
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_forces_off_write_no_force_columns_and_custom_coefficients_are_used(doc):
    _, _, engagement = model_test(doc)
    engagement.ShowSurfaces = False
    doc.recompute()
    assert engagement.Proxy.forces(engagement) is None and engagement.PeakForce == 0.0
    assert "fx" not in open(engagement.ResultsFile, encoding="utf-8").readline().split(",")
    engagement.Forces, engagement.Material = True, "custom"
    assert engagement.getEditorMode("Ktc") == []
    engagement.Ktc = 2.0 * material("al7075-t6").ktc  # the others stay at the table's values
    doc.recompute()
    doubled = engagement.Proxy.forces(engagement)
    table = model_test_forces(immersion=(0.0, 180.0))
    assert "fx" in open(engagement.ResultsFile, encoding="utf-8").readline().split(",")
    assert not np.allclose(doubled.xyz, table.xyz)
    engagement.Material = "al7075-t6"
    assert engagement.Ktc == material("al7075-t6").ktc and engagement.getEditorMode("Ktc") == ["ReadOnly"]
    doc.recompute()
    assert_same_forces(engagement.Proxy.forces(engagement), table, 1e-9)


def test_bad_force_settings_fail_the_recompute_in_plain_words(doc):
    _, _, engagement = model_test(doc, forces=True, material="custom", ktc=-1.0, krc=1.0, kac=1.0)
    engagement.ShowSurfaces = False
    doc.recompute()
    assert engagement.getStatusString() == ("Engagement: Ktc (tangential cutting coefficient) must be positive, "
                                            "got -1 N/mm² (property Ktc).")
    engagement.Ktc = 700.0
    engagement.ImmersionStart, engagement.ImmersionEnd = 90.0, 30.0
    doc.recompute()
    assert engagement.getStatusString() == (
        "Engagement: End of immersion must be above the start of immersion 90°, got 30° (property ImmersionEnd).")
    engagement.ImmersionStart = 0.0
    engagement.HelixAngle = 95.0
    doc.recompute()
    assert engagement.getStatusString() == "Engagement: Helix angle must be within [-60, 60]°, got 95° (property HelixAngle)."
    engagement.HelixAngle = 0.0
    doc.recompute()
    assert engagement.isValid() and engagement.PeakForce > 0.0


def test_helix_30_changes_the_length_of_cut_as_flute_engagement_does(doc):
    _, _, engagement = model_test(doc, helix=30.0, forces=True, material="al7075-t6", immersion=(0.0, 120.0))
    engagement.ShowSurfaces = False
    doc.recompute()
    assert engagement.isValid()
    tool = Tool(JOB["diameter"], JOB["flutes"], JOB["flute_length"], helix=30.0)
    settings = CutSettings(JOB["feed_per_tooth"], JOB["inclination"], *JOB["phi_range"], JOB["phi_step"],
                           JOB["spindle_rpm"])
    expected = flute_engagement(load_stock(STOCK_JSON).staircase, tool, load_toolpath(TOOLPATH),
                                settings).as_engagement(0)
    result = engagement.Proxy.result(engagement)
    assert_same(result, expected)
    straight = reference()
    assert not np.allclose(result.length, straight.length)
    assert engagement.MaxLengthOfCut.Value == pytest.approx(expected.length.max(), abs=1e-12)
    assert_same_forces(engagement.Proxy.forces(engagement), model_test_forces(helix=30.0), 1e-9)


def test_a_copied_fcstd_alone_reopens_with_its_results_and_forces_without_recompute(doc, tmp_path, monkeypatch):
    import shutil

    _, _, engagement = model_test(doc, forces=True, material="al7075-t6", immersion=(0.0, 120.0))
    engagement.ShowSurfaces = False
    doc.recompute()
    assert engagement.isValid() and engagement.getEditorMode("ResultsData") == ["ReadOnly"]
    saved = tmp_path / "project" / "job.FCStd"
    saved.parent.mkdir()
    doc.saveAs(str(saved))
    FreeCAD.closeDocument(doc.Name)
    # only the .FCStd travels: the folder it was saved in, results CSV and all, is gone
    copy = tmp_path / "elsewhere" / "copy.FCStd"
    copy.parent.mkdir()
    shutil.copyfile(saved, copy)
    shutil.rmtree(saved.parent)

    forbid_the_engine(monkeypatch)
    reopened = FreeCAD.openDocument(str(copy))
    try:
        engagement = reopened.getObject("Engagement")
        assert "Touched" not in engagement.State and engagement.isValid()
        assert_same(engagement.Proxy.result(engagement), reference())  # bit for bit: the arrays themselves
        assert_same_forces(engagement.Proxy.forces(engagement), model_test_forces(), 1e-9)  # as computed
        assert os.listdir(copy.parent) == ["copy.FCStd"]
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_a_moved_project_reopens_with_its_input_files_and_missing_ones_are_repointed(doc, tmp_path):
    import shutil

    from abm_workbench.features.base import missing_files, repoint

    project = tmp_path / "project"
    (project / "inputs").mkdir(parents=True)
    for name in ("stock.json", "toolpath.csv"):
        shutil.copyfile(os.path.join(MODEL, name), project / "inputs" / name)
    stock = create_stock(doc, str(project / "inputs" / "stock.json"))
    toolpath = create_toolpath(doc, str(project / "inputs" / "toolpath.csv"))
    create_engagement(doc, stock, toolpath, **SETTINGS, stock_model="initial")
    doc.recompute()
    doc.saveAs(str(project / "job.FCStd"))
    assert (stock.SourceFileRelative, toolpath.FileRelative) == (os.path.join("inputs", "stock.json"),
                                                                 os.path.join("inputs", "toolpath.csv"))
    FreeCAD.closeDocument(doc.Name)
    # the project folder moved whole: the input files found beside the document, and the results
    # recomputed from them equal the engine's
    moved = tmp_path / "moved"
    shutil.move(str(project), str(moved))
    reopened = FreeCAD.openDocument(str(moved / "job.FCStd"))
    try:
        stock, toolpath = reopened.getObject("Stock"), reopened.getObject("Toolpath")
        assert (stock.SourceFile, toolpath.File) == (str(moved / "inputs" / "stock.json"),
                                                    str(moved / "inputs" / "toolpath.csv"))
        assert missing_files(reopened) == []
        engagement = reopened.getObject("Engagement")
        for obj in reopened.Objects:
            obj.touch()
        reopened.recompute()
        assert all(obj.isValid() for obj in reopened.Objects)
        assert_same(engagement.Proxy.result(engagement), reference())
    finally:
        FreeCAD.closeDocument(reopened.Name)
    # the FCStd alone: both files missing, re-pointed to a folder that holds them by name
    alone = tmp_path / "alone"
    alone.mkdir()
    shutil.copyfile(moved / "job.FCStd", alone / "job.FCStd")
    shutil.rmtree(moved)
    reopened = FreeCAD.openDocument(str(alone / "job.FCStd"))
    try:
        missing = missing_files(reopened)
        assert sorted((obj.Name, prop) for obj, prop, _ in missing) == [("Stock", "SourceFile"), ("Toolpath", "File")]
        assert [obj.Name for obj in repoint(reopened, MODEL)] == ["Stock", "Toolpath"]
        assert missing_files(reopened) == []
        assert reopened.getObject("Toolpath").File == os.path.join(MODEL, "toolpath.csv")
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_a_property_overruled_by_the_toolpath_file_is_named_as_a_property(doc, tmp_path):
    """The engagement's warning names the property that differs from the file, in the GUI's words (no
    command-line option)."""
    path = load_toolpath(TOOLPATH)
    moves = "".join("GOTO/" + ",".join(f"{v:.12f}" for v in (*p, 0.0, 0.0, 1.0)) + "\n" for p in path.cl)
    apt = tmp_path / "path.apt"
    apt.write_text(APT.format(moves=moves))
    engagement = create_engagement(doc, create_stock(doc, STOCK_JSON), create_toolpath(doc, apt), flutes=2)
    engagement.ShowSurfaces = False
    engagement.SpindleSpeed = 5000.0
    doc.recompute()
    assert engagement.isValid(), engagement.getStatusString()
    conflict = [text for text in engagement.Warnings if "spindle_rpm" in text]
    assert conflict == [f"{apt} gives spindle_rpm 4000, the property SpindleSpeed 5000: using 4000, the value the "
                        "toolpath was made for"], engagement.Warnings
