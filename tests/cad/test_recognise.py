"""Recognition: solids back into staircases, exact to 1e-9 mm; refusals name the face."""

import os

import numpy as np
import pytest

from abm_workbench.cad.freecad_env import FreeCAD, Part
from abm_workbench.cad.recognise import load_solid, recognise, recognise_staircase
from abm_workbench.cad.solids import export_brep, export_step, staircase_solid
from abm_workbench.errors import InputError
from abm_workbench.formats.staircase_json import load_staircase

from . import shapes
from .conftest import CHEBYSHEV, STOCKS, Y_MAX, Y_MIN

TOL = 1e-9  # mm
MODELS = os.path.join(os.path.dirname(__file__), "..", "..", "resources", "models")


def assert_same_staircase(found, expected):
    """Limits, heights, wall points and the walls themselves (at 101 y) agree to TOL; straightness too."""
    for name in ("x_min", "x_max", "y_min", "y_max", "base_z"):
        assert getattr(found, name) == pytest.approx(getattr(expected, name), abs=TOL), name
    assert found.z_top == pytest.approx(expected.z_top, abs=TOL)
    assert found.wall_points.shape == expected.wall_points.shape
    y = np.linspace(found.y_min, found.y_max, 101)
    for points, got, want in zip(found.wall_points, found.walls, expected.walls):
        assert np.abs(points[:, 0] - want.x_at(points[:, 1])).max() < TOL
        assert np.abs(got.x_at(y) - want.x_at(y)).max() < TOL
        assert got.is_straight == want.is_straight


@pytest.mark.parametrize("name", sorted(STOCKS))
def test_recognises_generated_stocks(solids, name):
    result = recognise(solids[name])
    assert_same_staircase(result.staircase, STOCKS[name])
    assert result.staircase.wall_points[..., 1] == pytest.approx(np.broadcast_to(CHEBYSHEV, (len(result.walls), 6)))
    assert len(result.tops) == STOCKS[name].n_sections


@pytest.mark.parametrize("export, name", [(export_step, "ridge.step"), (export_step, "RIDGE.STP"),
                                          (export_brep, "ridge.brep"), (export_brep, "ridge.brp")])
def test_round_trip_through_a_file_keeps_the_walls_exact(solids, tmp_path, export, name):
    path = tmp_path / name
    export(solids["ridge"], path)
    found = recognise_staircase(load_solid(path), source=str(path))
    assert_same_staircase(found, STOCKS["ridge"])


def test_even_points_over_a_window(solids):
    result = recognise(solids["descending"], wall_points="even", y_window=(-5.0, 7.0))
    stock = result.staircase
    assert (stock.y_min, stock.y_max) == (-5.0, 7.0) and result.y_window == (-5.0, 7.0)
    assert stock.wall_points[0, :, 1] == pytest.approx(np.linspace(-5.0, 7.0, 6))
    y = np.linspace(-5.0, 7.0, 41)
    for points, got, want in zip(stock.wall_points, stock.walls, STOCKS["descending"].walls):
        assert np.abs(points[:, 0] - want.x_at(points[:, 1])).max() < TOL
        assert np.abs(got.x_at(y) - want.x_at(y)).max() < TOL


def test_each_wall_keeps_its_faces_and_edges(solids):
    result = recognise(solids["ascending"])
    assert [w.is_straight for w in result.walls] == [False, True, False]
    curved, straight = result.walls[0], result.walls[1]
    assert isinstance(curved.edges[0].Curve, Part.BSplineCurve)
    assert isinstance(straight.edges[0].Curve, Part.Line)
    assert np.ptp(straight.points[:, 0]) == 0.0
    assert curved.y_range == pytest.approx((Y_MIN, Y_MAX), abs=TOL)
    assert curved.z_range == pytest.approx((2.0, 5.0), abs=TOL)
    assert all(name.startswith("Face") for w in result.walls for name in w.faces)


def test_a_wall_in_two_faces_is_one_wall():
    result = recognise(shapes.split_wall())
    assert len(result.walls) == 1 and len(result.walls[0].faces) == 2 and len(result.walls[0].edges) == 2
    assert_same_staircase(result.staircase, shapes.SPLIT_STOCK)


@pytest.mark.parametrize("model", ["model_test_1", "model_test_2"])
def test_bundled_model_stock_round_trips_as_a_solid(tmp_path, model):
    stock = load_staircase(os.path.join(MODELS, model, "stock.json"))
    path = tmp_path / "stock.step"
    export_step(staircase_solid(stock), path)
    found = recognise_staircase(load_solid(path), source=str(path))
    assert_same_staircase(found, stock)
    # the bundled walls' points sit at the Chebyshev nodes of the stock's y range
    assert found.wall_points == pytest.approx(stock.wall_points, abs=TOL)


def faulty(shape, match):
    """Recognising `shape` raises InputError whose message matches `match`."""
    with pytest.raises(InputError, match=match):
        recognise(shape, source="part.step")


def test_refuses_a_slanted_top():
    shape = shapes.slanted_top()
    name = shapes.face_named(shape, lambda f: 0.1 < shapes.normal_z(f) < 0.99)
    faulty(shape, rf"^part\.step: {name}: slanted top")


def test_refuses_an_overhang():
    shape = shapes.overhang()
    name = shapes.face_named(shape, lambda f: shapes.normal_z(f) < -0.5 and f.BoundBox.ZMin > 1)
    faulty(shape, rf"{name}: overhang")


def test_refuses_a_curved_top():
    shape = shapes.curved_top()
    name = shapes.face_named(shape, lambda f: isinstance(f.Surface, Part.Cylinder))
    faulty(shape, rf"{name}: curved top")


def test_refuses_a_leaning_wall():
    shape = shapes.leaning_wall()
    name = shapes.face_named(shape, lambda f: 0.05 < shapes.normal_z(f) < 0.5)
    faulty(shape, rf"{name}: wall not vertical")


def test_refuses_a_wall_with_several_x_for_one_y():
    shape = shapes.s_wall()
    name = shapes.face_named(shape, lambda f: isinstance(f.Surface, Part.SurfaceOfExtrusion))
    faulty(shape, rf"{name}: wall has more than one x for y = ")


def test_refuses_an_open_shell():
    faulty(shapes.open_shell(), r"not a closed solid: an open shell, Face1, Face2, Face3, Face4 have edges bordering no")


def test_refuses_two_solids():
    faulty(shapes.two_solids(), "holds 2 solids")


def test_refuses_two_top_faces_in_one_section():
    shape = shapes.split_tops()
    tops = [f"Face{k}" for k, f in enumerate(shape.Faces, start=1) if shapes.normal_z(f) > 0.5 and f.BoundBox.ZMax < 5]
    faulty(shape, rf"section 0 .* has more than one top face: {tops[0]}, {tops[1]}")


def test_refuses_a_window_outside_the_stock(solids):
    with pytest.raises(InputError, match=r"y_window \(-20.0, 0.0\) must be increasing and inside"):
        recognise(solids["ridge"], y_window=(-20, 0))
    with pytest.raises(ValueError, match="wall_points must be"):
        recognise(solids["ridge"], wall_points="random")


def save_document(path, shapes_by_name):
    """Save a FreeCAD document holding one Part::Feature per (name, shape), and close it."""
    doc = FreeCAD.newDocument("abm_saved")
    try:
        for name, shape in shapes_by_name.items():
            doc.addObject("Part::Feature", name).Shape = shape
        doc.saveAs(str(path))
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_loads_the_single_solid_of_a_document(solids, tmp_path):
    path = tmp_path / "stock.FCStd"
    save_document(path, {"Stock": solids["ridge"]})
    assert_same_staircase(recognise_staircase(load_solid(path)), STOCKS["ridge"])
    assert FreeCAD.listDocuments() == {}


def test_loads_a_named_solid_and_refuses_to_guess(solids, tmp_path):
    path = tmp_path / "two.FCStd"
    save_document(path, {"Up": solids["ascending"], "Down": solids["descending"]})
    assert load_solid(path, name="Down").Volume == pytest.approx(solids["descending"].Volume)
    with pytest.raises(InputError, match=r"two\.FCStd: several solids \(Up, Down\); choose one with --solid NAME"):
        load_solid(path)
    with pytest.raises(InputError, match=r"two\.FCStd: no object with a solid named 'Side'"):
        load_solid(path, name="Side")
    assert FreeCAD.listDocuments() == {}


def test_a_document_already_open_is_used_and_left_open(solids, tmp_path):
    path = tmp_path / "open.FCStd"
    save_document(path, {"Stock": solids["ridge"]})
    doc = FreeCAD.openDocument(str(path))
    try:
        assert load_solid(path).Volume == pytest.approx(solids["ridge"].Volume)
        assert doc.Name in FreeCAD.listDocuments()
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_refuses_a_document_without_solids(tmp_path):
    path = tmp_path / "empty.FCStd"
    save_document(path, {})
    with pytest.raises(InputError, match=r"empty\.FCStd: no object holds a solid"):
        load_solid(path)


@pytest.mark.parametrize("name, content, match", [
    ("missing.step", None, r"missing\.step: no such file"),
    ("stock.iges", "", r"stock\.iges: unknown file type"),
    ("bad.step", "garbage", r"bad\.step: damaged or unreadable STEP \(cannot read as STEP"),
    ("bad.brep", "garbage", r"bad\.brep: the BREP file holds no shape"),
])
def test_load_errors_name_the_file(tmp_path, name, content, match):
    path = tmp_path / name
    if content is not None:
        path.write_text(content)
    with pytest.raises(InputError, match=match):
        load_solid(path)
