"""validate with tools of every kind: the engine against the whole-edge OpenCASCADE reference (corner arc,
side, end edge), the end edge in the comparison, the summaries and the report; the annotated document draws
the engaged corner as arcs; a flat-end mill keeps its side-line reference bit for bit and gains the end
edge, against the stock as given and the in-process stock; a bull-nose mill's ramp against the in-process
stock is refused in words."""

import zipfile

import numpy as np
import pytest

from abm_workbench.cad.annotate import write_annotated
from abm_workbench.cad.boolean import edge_lengths_by_boolean
from abm_workbench.cad.freecad_env import FreeCAD, Part
from abm_workbench.cad.inprocess_boolean import inprocess_solid
from abm_workbench.cad.profile_boolean import end_sections
from abm_workbench.cad.profile_edges import EdgeGeometry, tool_frames
from abm_workbench.cad.solids import staircase_solid
from abm_workbench.engine import CutSettings, Tool, Toolpath
from abm_workbench.engine.inprocess import ProgramMoves, swept_pieces
from abm_workbench.report.html import ReportJob, report_cls, write_report
from abm_workbench.report.tables import COMPARISON_COLUMNS, STATISTICS_COLUMNS
from abm_workbench.validation import overall, segment_summary, surface_summary, validate
from tests.engine.test_inprocess import Program, staircase, straight

from .profile_cases import TOL, seeded_pass, stocks

SETTINGS = CutSettings(0.1, phi_start=2.5, phi_end=180.0, phi_step=7.5)


@pytest.fixture(scope="module")
def solids():
    return stocks()


def read_csv(path):
    lines = path.read_text().splitlines()
    names = lines[0].split(",")
    return {name: [line.split(",")[k] for line in lines[1:]] for k, name in enumerate(names)}


@pytest.mark.parametrize("stock_name", ["staircase", "terraced"])
@pytest.mark.parametrize("corner", [1.5, 5.0])
def test_validate_a_corner_tool(solids, stock_name, corner, tmp_path):
    stock, solid = solids[stock_name]
    tool = Tool(10.0, 3, 14.0, corner_radius=corner)
    path = seeded_pass(stock_name, "tilted", 42, n=5)
    result = validate(solid, stock, tool, path, SETTINGS)
    total = overall(result.comparison)
    assert total["max_abs_difference"] < TOL and total["mismatched"] == 0
    assert total["max_lep_difference"] < TOL and total["max_uep_difference"] < TOL
    assert total["end_instants"] == path.cl.shape[0] * SETTINGS.phi.size
    if corner < tool.radius:
        assert total["max_end_difference"] < TOL and total["end_mismatched"] == 0
        assert (result.comparison.end_ref > 0.0).any()
    else:
        assert (result.comparison.end_ref == 0.0).all() and total["max_end_difference"] == 0.0
    np.testing.assert_allclose(result.comparison.depth_ref, result.comparison.depth_abm, rtol=0, atol=TOL)
    for row in segment_summary(result.engagement, result.comparison) + surface_summary(result.engagement,
                                                                                      result.comparison):
        assert set(STATISTICS_COLUMNS) <= set(row)
    job = ReportJob("corner", "a test", "stock", "path", path, tool, SETTINGS, "", "exact", None, 0.0)
    write_report(str(tmp_path), result, job, report_cls(result))
    page = (tmp_path / "index.html").read_text()
    assert ("bull-nose mill D 10 mm, corner radius 1.5 mm" if corner < 5.0 else "ball-end mill D 10 mm") in page
    assert "true circular arc" in page and "max |Δ end| (mm)" in page
    table = read_csv(tmp_path / "comparison.csv")
    assert tuple(table) == COMPARISON_COLUMNS
    difference = np.array([float(v) for v in table["end_difference"]])
    assert np.abs(difference).max() < TOL


def test_workers_give_the_same_corner_reference(solids):
    stock, solid = solids["terraced"]
    tool = Tool(10.0, 2, 12.0, corner_radius=3.0)
    path = seeded_pass("terraced", "sideways", 8, n=3)
    one = validate(solid, stock, tool, path, SETTINGS)
    two = validate(solid, stock, tool, path, SETTINGS, workers=2)
    assert one.reference.keys() == two.reference.keys()
    for name in one.reference:
        np.testing.assert_array_equal(one.reference[name], two.reference[name])


def test_a_nearly_flat_bull_nose_ramp_against_the_in_process_stock(solids):
    """A bull-nose mill's earlier moves rising 0.03 mm per mm (no reliable OpenCASCADE solids: the reference's
    exact inside test decides them) then a pass beside them: validate agrees at every instant."""
    stock, solid = solids["staircase"]
    tool = Tool(10.0, 2, 12.0, corner_radius=2.0)
    cl = np.array([[20.0, 0.0, 5.0], [30.0, 0.0, 5.3], [40.0, 0.0, 5.6]] + [[x, 4.0, 5.0] for x in (40, 35, 30, 25)])
    n = len(cl)
    path = Toolpath.from_axes(cl, np.tile([0.0, 0.0, 1.0], (n, 1)))
    moves = ProgramMoves(cl, path.axes, np.arange(n) > 0, np.full(n, 5.0), np.full(n, 12.0), np.arange(n) + 1,
                         np.full(n, 2.0))
    result = validate(solid, stock, tool, path, SETTINGS, sweep=(swept_pieces(moves), np.arange(n)))
    assert result.reference["gauged"][3:].min() >= 1 and result.reference["undecided"].sum() == 0
    assert (result.in_process.initial[3:] - result.comparison.l_ref[3:]).max(axis=1).min() > 0.5
    assert np.nanmax(np.abs(result.comparison.difference)) <= TOL


def test_a_flat_end_mill_keeps_its_reference_and_gains_the_end_edge(solids):
    stock, solid = solids["staircase"]
    tool = Tool(12.0, 2, 25.0)
    path = seeded_pass("staircase", "tilted", 17, n=4)
    result = validate(solid, stock, tool, path, SETTINGS)
    lines = edge_lengths_by_boolean(solid, tool, path, result.engagement.phi)
    for name in lines:
        np.testing.assert_array_equal(result.reference[name], lines[name])
    total = overall(result.comparison)
    assert total["end_instants"] == 4 * SETTINGS.phi.size and total["max_end_difference"] < TOL
    assert (result.comparison.end_ref > 0.0).any() and total["end_mismatched"] == 0


def test_a_checked_subset_spreads_the_end_lengths(solids):
    stock, solid = solids["terraced"]
    tool = Tool(10.0, 2, 12.0, corner_radius=2.0)
    path = seeded_pass("terraced", "down", 5, n=4)
    result = validate(solid, stock, tool, path, SETTINGS, cls=[1, 3])
    assert np.isnan(result.comparison.end_ref[[0, 2]]).all() and np.isfinite(result.comparison.end_ref[[1, 3]]).all()
    assert overall(result.comparison)["end_instants"] == 2 * SETTINGS.phi.size


def test_the_annotated_document_draws_the_corner_as_arcs(solids, tmp_path):
    stock, solid = solids["terraced"]
    tool = Tool(10.0, 2, 12.0, corner_radius=3.0)
    path = seeded_pass("terraced", "tilted", 31, n=3)
    result = validate(solid, stock, tool, path, SETTINGS)
    file = tmp_path / "corner.FCStd"
    write_annotated(file, "ABM_corner", solid, result.engagement, path, tool, cls=[0, 1], intersections=[1])
    with zipfile.ZipFile(file) as archive:
        assert "GuiDocument.xml" in archive.namelist()
    document = FreeCAD.openDocument(str(file))
    try:
        curves = set()
        for obj in document.Objects:
            if obj.TypeId == "Part::Feature":
                assert obj.Shape.isValid(), obj.Name
            if "_Seg_" in obj.Name:
                curves |= {type(edge.Curve).__name__ for edge in obj.Shape.Edges}
                for edge in obj.Shape.Edges:
                    if isinstance(edge.Curve, Part.Circle):
                        assert edge.Curve.Radius == pytest.approx(3.0)
        assert "Circle" in curves and curves <= {"Circle", "Line"}
        intersection = document.getObject("CL001_Intersection").Shape
        # the corner: the arc turned about the axis (exact, a surface of revolution of a circle)
        assert any(isinstance(face.Surface, Part.SurfaceOfRevolution) and isinstance(face.Surface.BasisCurve,
                                                                                      (Part.Circle, Part.ArcOfCircle))
                   for face in intersection.Faces)
        cutter = solid.common(Part.makeCylinder(tool.radius, tool.flute_length, FreeCAD.Vector(*path.cl[1]),
                                                FreeCAD.Vector(*path.axes[1])))
        assert 0.0 < intersection.Volume < cutter.Volume  # the rounded corner holds less than the cylinder
    finally:
        FreeCAD.closeDocument(document.Name)


def inprocess_program():
    """(Program, rows of its second pass): two overlapping passes of a D10 flat-end mill, the second higher,
    so that its end edges lie partly where the first pass removed the stock."""
    prog = Program()
    prog.add_pass(straight(8, 52, -3.0, 3.0, 5), 5.0, 12.0)
    back = straight(52, 8, 4.0, 0.0, 5)
    back[:, 2] = np.linspace(4.5, 3.5, 5)
    second = prog.add_pass(back, 5.0, 12.0, np.tile([0.05, -0.1, 1.0], (5, 1)))
    return prog, second


def test_the_end_edges_against_the_in_process_stock():
    """The end edges' reference against the in-process stock (sections with each swept solid) equals the
    end edges sectioned with the stock actually cut by the fused swept solids (inprocess_solid)."""
    prog, rows = inprocess_program()
    d = prog.as_dict()
    tool = Tool(10.0, 2, 12.0)
    path = Toolpath.from_axes(d["cl"][rows], d["axis"][rows])
    stock = staircase()
    solid = staircase_solid(stock)
    moves = prog.moves()
    pieces = swept_pieces(moves, 0.01)
    result = validate(solid, stock, tool, path, SETTINGS, sweep=(pieces, rows))
    assert result.in_process.changed.any()
    frames = tool_frames(path)
    cut_somewhere = False
    for i, row in enumerate(rows[1:4], start=1):
        cut = inprocess_solid(solid, (moves, pieces), row, near=30.0)
        geometry = EdgeGeometry.of(tool, path.cl[i], frames[i], SETTINGS.phi)
        want = np.array([sum(b - a for a, b in found) for found in end_sections(cut, geometry)])
        np.testing.assert_allclose(result.reference["end_length"][i], want, rtol=0, atol=TOL)
        as_given = np.array([sum(b - a for a, b in found) for found in end_sections(solid, geometry)])
        cut_somewhere |= bool((as_given - want > 0.1).any())
    assert cut_somewhere  # earlier moves removed material from some end edge
    comparison = result.comparison
    assert np.isnan(comparison.end_abm[result.in_process.changed]).all()  # the engine leaves those out
    assert not comparison.end_checked[result.in_process.changed].any()


def test_the_removal_estimate_against_the_exact_in_process_reference():
    """profile_inprocess.removed_lengths on a flat-end mill, whose in-process stock the boolean computes
    exactly: the estimated in-process length within two sample cells of the exact one per run, for the side
    and the end edges; for a bull-nose it removes some of what the stock as given holds, never more."""
    from abm_workbench.cad.profile_boolean import flat_lengths_in_process
    from abm_workbench.cad.profile_inprocess import EDGE_STEP, removed_lengths
    from abm_workbench.cad.inprocess_boolean import ProgramSweep

    prog, rows = inprocess_program()
    d = prog.as_dict()
    tool = Tool(10.0, 2, 12.0)
    path = Toolpath.from_axes(d["cl"][rows], d["axis"][rows])
    solid = staircase_solid(staircase())
    moves = prog.moves()
    phi = SETTINGS.phi
    exact = flat_lengths_in_process(solid, tool, path, phi, ProgramSweep(swept_pieces(moves, 0.001), rows, path))
    cls = [1, 2, 3]
    estimate = removed_lengths(solid, tool, path, phi, moves, rows, cls)
    assert (estimate.removed > 1.0).any()
    runs = np.maximum(exact["pieces"][cls], 1)
    np.testing.assert_array_less(np.abs(estimate.in_process - exact["length"][cls]), 2.0 * EDGE_STEP * runs + 1e-9)
    np.testing.assert_array_less(np.abs(estimate.end_given - estimate.end_removed - exact["end_length"][cls]),
                                 2.0 * EDGE_STEP * np.maximum(exact["end_pieces"][cls], 1) + 1e-9)
    corner = removed_lengths(solid, Tool(10.0, 2, 12.0, corner_radius=3.0), path, phi, moves, rows, cls)
    assert (corner.removed <= corner.given + 1e-12).all() and corner.positions.min() > 0
