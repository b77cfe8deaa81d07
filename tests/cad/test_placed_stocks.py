"""A stock chosen in a FreeCAD document is taken where the document shows it: inside App::Part
containers (their placements applied, nested too) and through App::Link objects (the link's placement,
at the top or inside a container). The document is written to an FCStd file and read back."""

import os

import numpy as np
import pytest

from abm_workbench import cli
from abm_workbench.cad.freecad_env import FreeCAD
from abm_workbench.cad.recognise import load_solid
from abm_workbench.cad.solids import export_step, moved
from abm_workbench.engine import angles_to_axis
from abm_workbench.formats.results_csv import read_results

from .test_validate import CL, THETA_A, THETA_B

V = FreeCAD.Vector


def placed_apt(rotation, translation):
    """test_validate's pass over the "ascending" stock, moved by (R, t) (mm), as an APT file's text."""
    axes = angles_to_axis(THETA_A, THETA_B) @ rotation.T
    points = np.array(CL) @ rotation.T + translation
    gotos = "".join("GOTO/" + ",".join(f"{v:.12f}" for v in (*p, *a)) + "\n" for p, a in zip(points, axes))
    return f"MULTAX/ON\nCUTTER/12,0,6,0,0,0,60\nCSI_SET_FLUTE_LENGTH/25\n{gotos}"


def placement_matrix(placement):
    """(R (3, 3), t (3,)) of a FreeCAD Placement."""
    matrix = placement.toMatrix()
    rows = np.array(matrix.A).reshape(4, 4)
    return rows[:3, :3], rows[:3, 3]


#: Placements (mm, degrees) of the containers and links in the document.
OUTER = FreeCAD.Placement(V(10, -4, 10), FreeCAD.Rotation(V(0, 0, 1), 30))
INNER = FreeCAD.Placement(V(0, 0, 2), FreeCAD.Rotation(V(0, 0, 1), -30))
LINK = FreeCAD.Placement(V(0, 200, 0), FreeCAD.Rotation())
HOLDER = FreeCAD.Placement(V(0, -200, 5), FreeCAD.Rotation(V(0, 0, 1), 90))


@pytest.fixture(scope="module")
def document(solids, tmp_path_factory):
    """(path of an FCStd, the stock solid): Outer (App::Part) ⊃ Inner (App::Part) ⊃ Stock (Part::Feature);
    StockLink (App::Link to Stock) at the top; Holder (App::Part) ⊃ HeldLink (App::Link to Stock)."""
    path = str(tmp_path_factory.mktemp("placed") / "placed.FCStd")
    doc = FreeCAD.newDocument("placed")
    outer, inner, holder = (doc.addObject("App::Part", name) for name in ("Outer", "Inner", "Holder"))
    outer.Placement, inner.Placement, holder.Placement = OUTER, INNER, HOLDER
    outer.addObject(inner)
    stock = doc.addObject("Part::Feature", "Stock")
    stock.Shape = solids["ascending"]
    inner.addObject(stock)
    link = doc.addObject("App::Link", "StockLink")
    link.LinkedObject, link.Placement = stock, LINK
    held = doc.addObject("App::Link", "HeldLink")
    held.LinkedObject = stock
    holder.addObject(held)
    doc.recompute()
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    return path, solids["ascending"]


def assert_placed(shape, solid, *placements):
    """`shape` is `solid` moved by the placements, outermost first (vertices within 1e-9 mm)."""
    expected = solid
    for placement in reversed(placements):
        expected = moved(expected, *placement_matrix(placement))
    found = np.array(sorted(tuple(np.round(v.Point, 6)) for v in shape.Vertexes))
    want = np.array(sorted(tuple(np.round(v.Point, 6)) for v in expected.Vertexes))
    assert found.shape == want.shape and np.abs(found - want).max() < 1e-9
    assert abs(shape.Volume - solid.Volume) < 1e-6 * solid.Volume


@pytest.mark.parametrize("name, placements", [
    ("Stock", (OUTER, INNER)),          # in nested containers: both placements
    ("StockLink", (LINK,)),             # a link at the top: its own placement
    ("HeldLink", (HOLDER,)),            # a link in a container: the container's placement too
])
def test_a_chosen_object_is_where_the_document_shows_it(document, name, placements):
    path, solid = document
    assert_placed(load_solid(path, name), solid, *placements)


def test_engage_on_a_stock_in_a_container_equals_the_placed_step(document, tmp_path, capsys):
    """`--solid Stock` from the FCStd gives the results of the same solid, placed, from STEP."""
    path, solid = document
    placed = solid
    for placement in (INNER, OUTER):
        placed = moved(placed, *placement_matrix(placement))
    export_step(placed, tmp_path / "placed.step")
    (tmp_path / "path.apt").write_text(placed_apt(*placement_matrix(OUTER.multiply(INNER))))
    common = ["--toolpath", str(tmp_path / "path.apt"), "--flutes", "2", "--feed-per-tooth", "0.1", "--phi-step",
              "10"]
    assert cli.main(["engage", "--stock", path, "--solid", "Stock", "--out", str(tmp_path / "fcstd.csv"),
                     *common]) == 0
    assert cli.main(["engage", "--stock", str(tmp_path / "placed.step"), "--out", str(tmp_path / "step.csv"),
                     *common]) == 0
    capsys.readouterr()
    fcstd, step = read_results(tmp_path / "fcstd.csv"), read_results(tmp_path / "step.csv")
    assert (step["length"] > 0).sum() > 30
    for column in ("length", "lep_l", "uep_l", "lep_x", "uep_y"):
        np.testing.assert_allclose(fcstd[column], step[column], atol=1e-9, equal_nan=True, err_msg=column)
