"""Exact recognition of staircases (issue 16): the issue's silent wrong answers are refused, legal
walls and faces of every curve and surface type are accepted, solids are chosen by name, and a
swept y range beyond the window is caught. References are independent of the recogniser: the
curves' own points, dense samples of the test's own curves, and OpenCASCADE booleans."""

import numpy as np
import pytest

from abm_workbench.cad.freecad_env import FreeCAD, Part
from abm_workbench.cad.recognise import check_window, load_solid, recognise
from abm_workbench.cad.solids import export_brep, export_step, staircase_solid
from abm_workbench.errors import InputError

from . import recognition_shapes as shapes

V = FreeCAD.Vector
TOL = 1e-9  # mm


def assert_same_solid(a, b, volume_tol=1e-6):
    """The solids a and b enclose the same material: both one-sided differences have no volume (mm³)."""
    assert a.cut(b).Volume < volume_tol and b.cut(a).Volume < volume_tol


def test_a_spline_wall_folding_back_a_tenth_of_a_millimetre_is_refused():
    solid, curve = shapes.spline_fold()
    # the reference: the curve's own y, densely, turns back by about 0.1 mm
    y = np.array([curve.value(t).y for t in np.linspace(0.0, 1.0, 20001)])
    assert 0.099 < (np.maximum.accumulate(y) - y).max() < 0.101
    face = shapes.face_name(solid, lambda f: isinstance(f.Surface, Part.SurfaceOfExtrusion))
    with pytest.raises(InputError, match=rf"^part\.step: (Face\d+, )*{face}(, Face\d+)*: wall has more than one x "
                                         r"for y = -0\.05\d* \(its top edge turns back by 0\.1 mm"):
        recognise(solid, source="part.step")


def test_a_polyline_wall_folding_back_is_refused():
    with pytest.raises(InputError, match=r"wall has more than one x for y = 4\.92 \(two of its top edges overlap "
                                         r"in y from 4\.87 to 4\.97\)"):
        recognise(shapes.polyline_fold())


def test_a_wall_leaning_only_between_old_sample_normals_is_refused():
    solid = shapes.wall_surface_stock(0.5)
    face = shapes.face_name(solid, lambda f: isinstance(f.Surface, Part.BSplineSurface))
    with pytest.raises(InputError, match=rf"^{face}: wall not vertical: leans up to 5\.7° near x = 30\.1667, "
                                         r"y = -?15 .*a 2\.5D stock has horizontal tops and vertical walls$"):
        recognise(solid)


def test_a_dented_spline_top_is_refused():
    solid = shapes.dented_top()
    face = shapes.face_name(solid, lambda f: isinstance(f.Surface, Part.BSplineSurface))
    with pytest.raises(InputError, match=rf"^{face}: curved top: not a horizontal plane: a BSplineSurface whose "
                                         r"control points span z 9\.5 to 10, near x = 8, y = -9;"):
        recognise(solid)


def test_a_vertical_wall_stored_as_a_spline_surface_is_accepted():
    solid = shapes.wall_surface_stock(0.0)
    stock = recognise(solid).staircase
    assert stock.z_top == pytest.approx([10.0, 5.0], abs=TOL)
    assert np.abs(stock.wall_points[0][:, 0] - 30.0).max() < TOL
    assert_same_solid(staircase_solid(stock), solid)


def test_a_flat_top_stored_as_a_spline_surface_is_accepted():
    solid = shapes.flat_spline_top()
    stock = recognise(solid).staircase
    assert stock.n_sections == 1 and stock.z_top == pytest.approx([10.0], abs=TOL)
    assert_same_solid(staircase_solid(stock), solid)


def test_a_stock_whose_every_face_is_a_spline_surface_is_accepted():
    """As some CAD exports write them: sides, tops, base and wall all B-spline surfaces."""
    solid = shapes.bezier_wall()
    nurbs = solid.toNurbs()
    nurbs = Part.Solid(Part.Shell(nurbs.Faces))
    assert all(isinstance(f.Surface, Part.BSplineSurface) for f in nurbs.Faces)
    stock = recognise(nurbs).staircase
    bezier = next(e.Curve for e in solid.Edges if isinstance(e.Curve, Part.BezierCurve))
    _wall_matches_bezier(stock, bezier)
    assert stock.z_top == pytest.approx([10.0, 5.0], abs=TOL)


def _wall_matches_bezier(stock, bezier):
    """The recognised wall passes through the Bézier curve's own points (to TOL)."""
    points = np.array([tuple(bezier.value(t)) for t in np.linspace(0.0, 1.0, 201)])
    assert np.abs(stock.walls[0].x_at(points[:, 1]) - points[:, 0]).max() < TOL


def test_a_bezier_wall_from_brep_is_its_step_twin(tmp_path):
    solid = shapes.bezier_wall()
    bezier = next(e.Curve for e in solid.Edges if isinstance(e.Curve, Part.BezierCurve))
    found = {}
    for export, name in ((export_brep, "bezier.brep"), (export_step, "bezier.step")):
        path = tmp_path / name
        export(solid, path)
        found[name] = recognise(load_solid(path), source=str(path)).staircase
        _wall_matches_bezier(found[name], bezier)
    y = np.linspace(-15.0, 15.0, 101)
    brep, step = found["bezier.brep"], found["bezier.step"]
    assert np.abs(brep.walls[0].x_at(y) - step.walls[0].x_at(y)).max() < TOL
    assert brep.z_top == pytest.approx(step.z_top, abs=TOL)
    assert_same_solid(staircase_solid(brep), solid)


def test_a_spline_wall_drawn_longer_than_the_stock_is_accepted():
    solid = shapes.long_spline_wall()
    result = recognise(solid)
    stock = result.staircase
    assert (stock.x_min, stock.x_max, stock.y_min, stock.y_max) == pytest.approx((0, 60, -15, 15), abs=TOL)
    assert_same_solid(staircase_solid(stock), solid)


def test_a_wall_of_two_stacked_faces_is_one_wall():
    solid = shapes.stacked_wall()
    result = recognise(solid)
    (wall,) = result.walls
    assert len(wall.faces) == 2 and wall.z_range == pytest.approx((5.0, 10.0), abs=TOL)
    assert np.abs(wall.points[:, 0] - 30.0).max() < TOL
    assert_same_solid(staircase_solid(result.staircase), solid)


@pytest.mark.parametrize("suffix, export", [(".step", export_step), (".brep", export_brep)])
def test_a_file_with_several_solids_lets_the_caller_choose(tmp_path, suffix, export):
    first = Part.makeBox(10, 10, 10)
    second = Part.makeBox(20, 10, 5, V(30, 0, 0))
    path = tmp_path / f"two{suffix}"
    export(Part.Compound([first, second]), path)
    with pytest.raises(InputError, match=rf"two\{suffix}: several solids \(Solid1, Solid2\); choose one with "
                                         r"--solid NAME"):
        load_solid(path)
    assert load_solid(path, "Solid2").Volume == pytest.approx(second.Volume)
    assert load_solid(path, "Solid1").Volume == pytest.approx(first.Volume)
    with pytest.raises(InputError, match=r"no solid named 'Solid3' .*\(its solids: Solid1, Solid2\)"):
        load_solid(path, "Solid3")


def test_check_window_refuses_a_sweep_beyond_the_window():
    check_window((-5.0, 7.0), (-5.0, 7.0))
    with pytest.raises(InputError, match=r"^path\.apt: the cutting edges sweep y -6 to 7 mm, beyond the y window "
                                         r"-5 to 7 mm"):
        check_window((-5.0, 7.0), (-6.0, 7.0), source="path.apt")
    with pytest.raises(InputError, match=r"sweep y -5 to 7\.5 mm, beyond the y window -5 to 7 mm"):
        check_window((-5.0, 7.0), (-5.0, 7.5))


def _with_unit(step_text, unit):
    """STEP text with its millimetre length unit replaced by `unit` ("METRE" or "INCH": 25.4 mm)."""
    milli = "( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) )"
    assert milli in step_text
    if unit == "METRE":
        return step_text.replace(milli, "( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT($,.METRE.) )")
    inch = "( CONVERSION_BASED_UNIT('INCH',#9001) LENGTH_UNIT() NAMED_UNIT(#9003) )"
    extra = ("#9001 = LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),#9002);\n"
             "#9002 = ( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) );\n"
             "#9003 = DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.);\nENDSEC;\nEND-ISO")
    return step_text.replace(milli, inch).replace("ENDSEC;\nEND-ISO", extra, 1)


@pytest.mark.parametrize("unit, scale", [("METRE", 1000.0), ("INCH", 25.4)])
def test_metre_and_inch_step_files_are_read_in_millimetres(tmp_path, unit, scale):
    solid = shapes.bezier_wall()
    small = solid.copy()
    small.scale(1.0 / scale)
    mm_path = tmp_path / "small.step"
    export_step(small, mm_path)
    path = tmp_path / f"{unit.lower()}.step"
    path.write_text(_with_unit(mm_path.read_text(), unit))
    stock = recognise(load_solid(path)).staircase
    reference = recognise(solid).staircase
    assert stock.z_top == pytest.approx(reference.z_top, abs=1e-6)
    y = np.linspace(-15.0, 15.0, 51)
    assert np.abs(stock.walls[0].x_at(y) - reference.walls[0].x_at(y)).max() < 1e-6
