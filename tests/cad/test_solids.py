"""Staircase solids: valid, the volume of the height field, walls equal to the engine's quintic
(B-spline walls: test_exact_walls.py)."""

import os

import numpy as np
import pytest

from abm_workbench.cad.freecad_env import Part
from abm_workbench.cad.solids import bezier_poles, export_brep, export_step, staircase_solid, wall_edge
from abm_workbench.engine import Staircase
from abm_workbench.engine.walls import SplineWall

from .conftest import STOCKS, Y_MAX, Y_MIN, wall


def height_field_volume(stock):
    """∫∫ (z_top − base_z) dx dy (mm³) by Gauss-Legendre in y (exact for quintic walls)."""
    nodes, weights = np.polynomial.legendre.leggauss(8)
    half = 0.5 * (stock.y_max - stock.y_min)
    y = stock.y_min + half * (nodes + 1.0)
    x = [np.full_like(y, stock.x_min)] + [w.x_at(y) for w in stock.walls] + [np.full_like(y, stock.x_max)]
    widths = np.array([half * weights @ (x[j + 1] - x[j]) for j in range(stock.n_sections)])
    return float(widths @ (stock.z_top - stock.base_z))


@pytest.mark.parametrize("name", sorted(STOCKS))
def test_solid_is_valid_and_has_the_height_field_volume(solids, name):
    solid = solids[name]
    assert solid.ShapeType == "Solid" and solid.isValid()
    assert solid.Volume == pytest.approx(height_field_volume(STOCKS[name]), rel=1e-12)


def test_walls_are_extrusions_of_the_quintic_and_straight_walls_planes(solids):
    kinds = sorted(type(f.Surface).__name__ for f in solids["ascending"].Faces)
    assert kinds.count("SurfaceOfExtrusion") == 2  # the two curved walls
    assert kinds.count("Plane") == 4 + 1 + 5  # tops, the straight wall, base and four sides


@pytest.mark.parametrize("j", [0, 2])
def test_wall_edge_is_the_quintic(j):
    quintic = STOCKS["ascending"].walls[j]
    edge = wall_edge(quintic, Y_MIN, Y_MAX, 3.0)
    y = np.linspace(Y_MIN, Y_MAX, 97)
    points = np.array([tuple(edge.valueAt(u)) for u in y])  # the parameter is y
    assert np.abs(points[:, 1] - y).max() < 1e-12
    assert np.abs(points[:, 0] - quintic.x_at(y)).max() < 1e-12
    assert np.all(points[:, 2] == 3.0)


def test_bezier_poles_reproduce_the_polynomial_at_its_ends():
    quintic = STOCKS["ascending"].walls[0]
    poles = bezier_poles(quintic, -20.0, 30.0)
    assert poles.shape == (6, 2)
    assert poles[[0, -1], 0] == pytest.approx(quintic.x_at(np.array([-20.0, 30.0])), abs=1e-12)
    assert np.diff(poles[:, 1]) == pytest.approx(np.full(5, 10.0))


def test_equal_neighbouring_heights_merge_into_one_top():
    stock = Staircase(0, 60, Y_MIN, Y_MAX, 0, [4.0, 4.0, 7.0], [wall(lambda y: 20 + 0.1 * y), wall(lambda y: 40.0)])
    solid = staircase_solid(stock)
    tops = [f for f in solid.Faces if f.normalAt(0, 0).z > 0.5]
    assert solid.isValid() and len(tops) == 2


def test_refuses_a_spline_wall_that_does_not_span_the_window():
    short = SplineWall(1, [0, 0, 1, 1], [[20.0, Y_MIN + 0.5], [22.0, Y_MAX]], None)
    stock = Staircase(0, 60, Y_MIN, Y_MAX, 0, [4.0, 7.0], [wall(lambda y: 21.0 + y / 12)], (short,))
    with pytest.raises(ValueError, match=r"sections\[1\]\.wall: the B-spline wall spans y -11\.5 to 12, not all of"):
        staircase_solid(stock)


def test_a_single_section_is_a_box():
    solid = staircase_solid(Staircase(1, 5, -2, 3, -1, [2.0], []))
    assert solid.isValid() and solid.Volume == pytest.approx(4 * 5 * 3)


@pytest.mark.parametrize("export, suffix", [(export_step, ".step"), (export_brep, ".brep")])
def test_exports_replace_the_target_and_leave_no_temporary(solids, tmp_path, export, suffix):
    target = tmp_path / f"stock{suffix}"
    target.write_text("old")
    export(solids["ridge"], target)
    assert os.listdir(tmp_path) == [target.name]
    again = Part.read(str(target))
    assert again.Volume == pytest.approx(solids["ridge"].Volume, rel=1e-12)


def test_failed_export_keeps_the_old_file(tmp_path):
    target = tmp_path / "stock.step"
    target.write_text("old")

    class Broken:
        def exportStep(self, path):
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        export_step(Broken(), target)
    assert target.read_text() == "old" and os.listdir(tmp_path) == ["stock.step"]
