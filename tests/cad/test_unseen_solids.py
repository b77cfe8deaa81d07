"""Stock solids nobody here had seen (issue "No silent wrong answers, no frozen FreeCAD, no tracebacks",
Stocks): walls on offset surfaces and on parabolas and hyperbolas are computed exactly, checked against
OpenCASCADE's booleans; solids that are not 2.5D (a sphere, cone apexes, a spherical dimple, offsets
with no exact form) are refused in words naming the face, on the command line too: one line, exit
status 2, no output file. The solids are built here (unseen_shapes) and read back from STEP, as users
give them."""

import os
import subprocess
import sys

import numpy as np
import pytest
from scipy.interpolate import BSpline

from abm_workbench import cli
from abm_workbench.cad.boolean import edge_lengths_by_boolean
from abm_workbench.cad.freecad_env import Part
from abm_workbench.cad.solids import export_brep, export_step
from abm_workbench.cad.terraced_recognise import recognise_terraced
from abm_workbench.engine import CutSettings, Tool, Toolpath, angles_to_axis
from abm_workbench.engine.stocks import engage_stock
from abm_workbench.engine.terraced_model import PlanArc, PlanSpline
from abm_workbench.errors import InputError
from abm_workbench.jobs import load_stock
from tests.conftest import ROOT

from . import unseen_shapes as shapes

AGREE = 1e-6  # mm, engine against the boolean
MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")
TOOL = Tool(8.0, 2, 20.0)
CUT = CutSettings(0.1, 10.0, 0.0, 355.0, 5.0)

#: name: (builder, model kind, surface type every such face keeps through STEP)
COMPUTED = {
    "wall offset from a plane": (lambda: shapes.offset_wall("plane"), "staircase", "OffsetSurface"),
    "wall offset from an extruded line": (lambda: shapes.offset_wall("line"), "staircase", "OffsetSurface"),
    "round pocket offset from a cylinder": (lambda: shapes.offset_round_pocket("cylinder"), "terraced",
                                            "OffsetSurface"),
    "round pocket offset from an extruded circle": (lambda: shapes.offset_round_pocket("circle"), "terraced",
                                                    "OffsetSurface"),
    "top offset from a horizontal plane": (shapes.offset_top, "staircase", "OffsetSurface"),
    "parabola wall": (lambda: shapes.conic_wall("parabola"), "staircase", "SurfaceOfExtrusion"),
    "hyperbola wall": (lambda: shapes.conic_wall("hyperbola"), "staircase", "SurfaceOfExtrusion"),
    "parabola pocket": (lambda: shapes.conic_pocket("parabola"), "terraced", "SurfaceOfExtrusion"),
    "hyperbola pocket": (lambda: shapes.conic_pocket("hyperbola"), "terraced", "SurfaceOfExtrusion"),
}


def stock_file(solid, folder, name="stock.step"):
    """`solid` written to folder/name, STEP or BREP by its suffix (mm)."""
    path = os.path.join(folder, name)
    (export_brep if name.endswith(".brep") else export_step)(solid, path)
    return path


def crossing_pass(y):
    """Eight CL points along x from 18 to 46 mm at `y`, z = 3 (below every top, above the pockets'
    floors at z = 5 by the tool's lean), the axis leaning up to 12° each way."""
    x = np.linspace(18.0, 46.0, 8)
    cl = np.column_stack([x, np.full_like(x, y), np.full_like(x, 3.0)])
    return Toolpath.from_axes(cl, angles_to_axis(np.linspace(-8.0, 12.0, 8), np.linspace(10.0, -6.0, 8)))


@pytest.mark.parametrize("name", COMPUTED)
def test_new_walls_are_computed_exactly(name, tmp_path):
    """Recognised (the staircase or the terraced stock; a staircase as a terraced stock too), and the engine
    on the recognised model equals OpenCASCADE's boolean on the solid read back, within 1e-6 mm: length,
    LEP, UEP, pieces."""
    build, kind, surface = COMPUTED[name]
    path = stock_file(build(), tmp_path)
    solid = Part.read(path)
    assert any(type(face.Surface).__name__ == surface for face in solid.Faces)  # kept through STEP
    stock = load_stock(path)
    assert stock.kind == kind, stock.reason
    models = [stock.model] + ([recognise_terraced(solid)] if kind == "staircase" else [])
    for y in (0.7, -4.3):
        toolpath = crossing_pass(y)
        reference = edge_lengths_by_boolean(solid, TOOL, toolpath, CUT.phi)
        for model in models:
            mine = engage_stock(model, TOOL, toolpath, CUT)
            assert mine.engaged.sum() > 100
            assert np.abs(mine.length - reference["length"]).max() < AGREE
            assert np.array_equal(mine.pieces, reference["pieces"])
            both = mine.engaged
            assert np.abs(mine.lep_l[both] - reference["lep_l"][both]).max() < AGREE
            assert np.abs(mine.uep_l[both] - reference["uep_l"][both]).max() < AGREE


def test_offset_walls_are_where_their_offsets_put_them(tmp_path):
    """The offset plane wall is the straight wall x = 30; the offset cylinder the circle of radius 7."""
    wall = load_stock(stock_file(shapes.offset_wall("plane"), tmp_path)).staircase.walls[0]
    assert wall.is_straight and abs(wall.x_at(np.array([0.0]))[0] - 30.0) < 1e-9
    pocket = load_stock(stock_file(shapes.offset_round_pocket("cylinder"), tmp_path)).terraced.slabs[-1]
    (arc,) = [curve for loop in pocket.loops for curve in loop.curves if isinstance(curve, PlanArc)]
    assert abs(arc.radius - 7.0) < 1e-9 and np.allclose(arc.center, [30.0, 0.0], atol=1e-9)


def spline_points(curve, count=201):
    """(count, 2) points of a PlanSpline over its whole range (mm)."""
    weights = np.ones(len(curve.control)) if curve.weights is None else curve.weights
    homogeneous = BSpline(curve.knots, np.column_stack([curve.control * weights[:, None], weights]), curve.degree)
    t = np.linspace(curve.knots[curve.degree], curve.knots[len(curve.control)], count)
    x, y, w = homogeneous(t).T
    return np.column_stack([x / w, y / w])


@pytest.mark.parametrize("kind", ["parabola", "hyperbola"])
def test_conic_walls_lie_on_their_conics(kind, tmp_path):
    """The walls recognised are the conics themselves (rational degree 2, not approximations): on the
    staircase wall and on the pocket's spline, x = 25 + y²/40 or x = 10 + 20·√(1 + y²/144) to 1e-9 mm."""
    def conic(y):
        return 25.0 + y * y / 40.0 if kind == "parabola" else 10.0 + 20.0 * np.sqrt(1.0 + y * y / 144.0)

    wall = load_stock(stock_file(shapes.conic_wall(kind), tmp_path)).staircase.walls[0]
    y = np.linspace(-15.0, 15.0, 301)
    assert wall.degree == 2 and np.abs(wall.x_at(y) - conic(y)).max() < 1e-9
    pocket = load_stock(stock_file(shapes.conic_pocket(kind), tmp_path)).terraced.slabs[-1]
    (spline,) = [curve for loop in pocket.loops for curve in loop.curves if isinstance(curve, PlanSpline)]
    points = spline_points(spline)
    assert spline.degree == 2 and np.abs(points[:, 0] - conic(points[:, 1])).max() < 1e-9


#: name: (builder, what the refusal says after the face's name)
REFUSED = {
    **{name: (build, f"(wall not vertical|curved top: not a horizontal plane|overhang: faces down): a {surface} "
                     "surface near ") for name, (build, surface) in shapes.NOT_2_5D.items()},
    "offset of an extruded B-spline": (shapes.offset_spline_pocket, r"an OffsetSurface \(1 mm\) of a "
                                       r"SurfaceOfExtrusion of a BSplineCurve: its offset has no exact form"),
    "extruded offset curve": (shapes.offset_curve_prism, r"the edge at \(.*\) lies on an OffsetCurve, which has "
                                                         r"no exact B-spline form"),
}


#: FreeCAD's STEP writer leaves an extrusion of an offset curve out (an empty file): it goes as BREP.
FILE_NAME = {"extruded offset curve": "stock.brep"}


@pytest.mark.parametrize("name", REFUSED)
def test_solids_that_are_not_2_5d_are_refused_in_words(name, tmp_path):
    build, words = REFUSED[name]
    path = stock_file(build(), tmp_path, FILE_NAME.get(name, "stock.step"))
    with pytest.raises(InputError, match=rf"^{path}: Face\d+: {words}"):
        load_stock(path)


@pytest.mark.parametrize("name", REFUSED)
def test_the_command_line_refuses_them_in_one_line(name, tmp_path, capsys):
    build, _ = REFUSED[name]
    path = stock_file(build(), tmp_path, FILE_NAME.get(name, "stock.step"))
    out = tmp_path / "R.csv"
    status = cli.main(["engage", "--stock", path, "--toolpath", os.path.join(MODEL, "toolpath.csv"), "--job",
                       os.path.join(MODEL, "job.json"), "--out", str(out)])
    lines = capsys.readouterr().err.splitlines()
    assert status == 2 and len(lines) == 1
    assert lines[0].startswith(f"abm: error: {path}: Face")
    assert os.listdir(tmp_path) == [os.path.basename(path)]


def test_a_sphere_on_the_real_command_line(tmp_path):
    """`python -m abm_workbench engage` itself: one line on stderr, exit status 2, no traceback, no file."""
    path = stock_file(shapes.NOT_2_5D["sphere"][0](), tmp_path)
    done = subprocess.run([sys.executable, "-m", "abm_workbench", "engage", "--stock", path, "--toolpath",
                           os.path.join(MODEL, "toolpath.csv"), "--job", os.path.join(MODEL, "job.json"), "--out",
                           str(tmp_path / "R.csv")], cwd=ROOT, capture_output=True, text=True, timeout=300)
    (line,) = done.stderr.splitlines()
    assert done.returncode == 2 and line.startswith(f"abm: error: {path}: Face1: wall not vertical: a Sphere surface")
    assert sorted(os.listdir(tmp_path)) == ["stock.step"]
