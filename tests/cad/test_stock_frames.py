"""A stock's 2.5D direction is its own, whatever the program's frame: a stock upright in the part under a
CL program whose frame (NX MSYS) is turned is computed in that frame turned to the stock, and gives the
results of the program written in the part, whichever way its tool axes point (issue "No silent wrong
answers …", Stocks)."""

import os

import numpy as np
import pytest

from abm_workbench import cli
from abm_workbench.cad.freecad_env import Part
from abm_workbench.cad.solids import export_step, moved
from abm_workbench.cad.stock_frame import stock_frame
from abm_workbench.engine import angles_to_axis
from abm_workbench.errors import InputError
from abm_workbench.formats.results_csv import read_results
from abm_workbench.jobs import load_stock

from .test_validate import CL, THETA_A, THETA_B

#: Where the MCS's origin sits in the part (mm).
ORIGIN = np.array([5.0, -3.0, 20.0])
COMPARED = ("length", "lep_l", "uep_l", "pieces", "h", "area", "lep_x", "lep_y", "lep_z", "uep_x", "uep_y", "uep_z")


def turn(axis, degrees):
    """(3, 3) the right-handed rotation by `degrees` about coordinate axis 0, 1 or 2."""
    c, s = np.cos(np.radians(degrees)), np.sin(np.radians(degrees))
    j, k = (axis + 1) % 3, (axis + 2) % 3
    rotation = np.eye(3)
    rotation[j, j], rotation[j, k], rotation[k, j], rotation[k, k] = c, -s, s, c
    return rotation


def clsf(mcs, axes=None):
    """An NX CLSF of test_validate's pass over the "ascending" stock (part coordinates), written in the MCS
    whose axes are the columns of `mcs` (3, 3) with origin ORIGIN (MSYS), or in the part when mcs is None.
    axes: (3, 3) tool axes in the file frame instead of the pass's own."""
    points, part_axes = np.array(CL), angles_to_axis(THETA_A, THETA_B)
    msys = ""
    if mcs is not None:
        points, part_axes = (points - ORIGIN) @ mcs, part_axes @ mcs
        msys = "MSYS/" + ",".join(f"{v:.15g}" for v in (*ORIGIN, *mcs[:, 0], *mcs[:, 1])) + "\n"
    axes = part_axes if axes is None else axes
    moves = "".join("GOTO/" + ",".join(f"{v:.15f}" for v in (*p, *a)) + "\n" for p, a in zip(points, axes))
    return (f"TOOL PATH/PASS,TOOL,EM12\nTLDATA/MILL,12.0000,0.0000,75.0000,0.0000,0.0000\n{msys}PAINT/PATH\n"
            f"{moves}END-OF-PATH\n")


@pytest.fixture(scope="module")
def stock_step(solids, tmp_path_factory):
    """The "ascending" stock, upright in the part, as STEP."""
    path = tmp_path_factory.mktemp("upright") / "stock.step"
    export_step(solids["ascending"], path)
    return str(path)


def engaged(stock, text, folder, name):
    """Results of `abm engage` on the stock and a CLSF of text `text` (written to folder/name.clsf)."""
    path = folder / f"{name}.clsf"
    path.write_text(text)
    status = cli.main(["engage", "--stock", stock, "--toolpath", str(path), "--flutes", "2", "--feed-per-tooth",
                       "0.1", "--flute-length", "25", "--phi-step", "5", "--out", str(folder / f"{name}.csv")])
    assert status == 0
    return read_results(folder / f"{name}.csv")


@pytest.mark.parametrize("mcs, reference", [
    (turn(0, 10.0), None),                                  # tilted 10° about x: the part's own results
    (turn(2, 30.0) @ turn(0, 10.0), turn(2, 30.0)),         # also turned 30° about z: the MCS turned about z
])
def test_a_turned_program_over_an_upright_stock_is_computed_in_the_stock_frame(stock_step, tmp_path, capsys, mcs,
                                                                                reference):
    """Before, the stock was moved into the MCS and refused as leaning 10°. Now the MCS is turned back the
    least to the stock's own upright: the results are those of the same pass written in the part (or in
    the MCS turned only about z), LEP and UEP in part coordinates."""
    turned = engaged(stock_step, clsf(mcs), tmp_path, "turned")
    upright = engaged(stock_step, clsf(reference), tmp_path, "upright")
    capsys.readouterr()
    assert (upright["length"] > 0).sum() > 50
    for column in COMPARED:
        np.testing.assert_allclose(turned[column], upright[column], atol=1e-9, equal_nan=True, err_msg=column)


def test_tool_axes_on_both_sides_of_the_stock_are_computed(stock_step, tmp_path, capsys):
    """An MCS on its side (its Z along the part's −y) whose tool axes lean ±10° about its X: up in the MCS,
    sideways in the part, half of them a little down along the stock's upright. The engine takes every
    direction: the results are those of the same pass written in the part."""
    mcs = np.column_stack([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])
    lean = np.radians(10.0)
    axes = np.array([[0.0, np.sin(lean), np.cos(lean)], [0.0, -np.sin(lean), np.cos(lean)], [0.0, 0.0, 1.0]])
    assert ((axes @ mcs.T)[:, 2] < 0.0).any()  # pointing down in the part
    turned = engaged(stock_step, clsf(mcs, axes), tmp_path, "side")
    upright = engaged(stock_step, clsf(None, axes @ mcs.T), tmp_path, "part")
    capsys.readouterr()
    assert (upright["length"] > 0).sum() > 10
    for column in COMPARED:
        np.testing.assert_allclose(turned[column], upright[column], atol=1e-9, equal_nan=True, err_msg=column)


def test_a_stock_loaded_in_a_frame_not_its_own_is_refused_in_words(stock_step):
    """load_stock with a turned frame (as a front end that does not turn the toolpath asks): words, not
    a wall "leaning 10°"."""
    frame = (turn(0, 10.0).T, np.zeros(3))
    with pytest.raises(InputError, match=r"stock\.step: the stock is 2\.5D along \(0, 0, 1\) in the part, 10° from "
                                         r"the z of the operation's frame"):
        load_stock(stock_step, frame=frame)


def test_stock_frame_keeps_the_operation_frame_when_it_fits(solids):
    solid = solids["ascending"]
    about_z = (turn(2, 30.0), np.array([1.0, 2.0, 3.0]))
    assert stock_frame(solid, None) is None and stock_frame(solid, about_z) is about_z
    box = Part.makeBox(10, 20, 30)  # 2.5D along x, y and z: the operation's frame is kept
    on_side = (turn(0, 90.0), np.zeros(3))
    assert stock_frame(box, on_side) is on_side


def test_stock_frame_turns_the_least(solids):
    """The MCS tilted 10° about x and turned 30° about z: turned back about the axis square to both z
    (its x stays in the plane of x before), origin kept; a stock tilted in the part likewise."""
    mcs = turn(2, 30.0) @ turn(0, 10.0)
    frame = (mcs.T, -mcs.T @ ORIGIN)
    rotation, translation = stock_frame(solids["ascending"], frame)
    np.testing.assert_allclose(rotation @ [0.0, 0.0, 1.0], [0.0, 0.0, 1.0], atol=1e-15)
    np.testing.assert_allclose(rotation, turn(2, -30.0), atol=1e-15)
    np.testing.assert_allclose(translation, rotation @ -ORIGIN, atol=1e-12)
    tilted = moved(solids["ascending"], turn(1, 7.0), np.zeros(3))
    rotation, _ = stock_frame(tilted, None)
    np.testing.assert_allclose(rotation @ turn(1, 7.0), np.eye(3), atol=1e-15)
