"""An operation computed in its own frame: a CL program whose MCS (NX MSYS) turns Z down in the part,
against the stock solid in part coordinates, equals the same pass computed in the MCS directly."""

import os

import numpy as np
import pytest

from abm_workbench import cli
from abm_workbench.cad.freecad_env import Part
from abm_workbench.cad.solids import export_step, moved
from abm_workbench.formats.results_csv import read_results
from abm_workbench.formats.toolpath_csv import load_toolpath
from tests.conftest import ROOT

MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")
#: The MCS in part coordinates: origin, X and Y axes (Z = X × Y points down).
ORIGIN = np.array([250.0, -40.0, 120.0])
X_AXIS, Y_AXIS = np.array([0.0, 1.0, 0.0]), np.array([1.0, 0.0, 0.0])


def _frame():
    """(R, t) from MCS to part coordinates: columns X, Y, Z."""
    return np.column_stack([X_AXIS, Y_AXIS, np.cross(X_AXIS, Y_AXIS)]), ORIGIN


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """(results in the MCS, results of the NX program against the part-frame stock)."""
    folder = tmp_path_factory.mktemp("frames")
    rotation, origin = _frame()
    assert rotation[2, 2] == -1.0  # the MCS's Z points down in the part
    export_step(moved(Part.read(os.path.join(MODEL, "stock.step")), rotation, origin), str(folder / "part.step"))
    path = load_toolpath(os.path.join(MODEL, "toolpath.csv"))
    axes = path.axes
    moves = "".join("GOTO/" + ",".join(f"{v:.12f}" for v in (*p, *a)) + "\n" for p, a in zip(path.cl, axes))
    msys = ",".join(f"{v:.12g}" for v in (*origin, *X_AXIS, *Y_AXIS))
    for name, frame in (("mcs.clsf", ""), ("job.clsf", f"MSYS/{msys}\n")):  # the same program, in the MCS or the part
        (folder / name).write_text(
            "TOOL PATH/VC_PASS,TOOL,EM12\nTLDATA/MILL,12.0000,0.0000,75.0000,0.0000,0.0000\n"
            f"{frame}PAINT/PATH\nSPINDL/RPM,4000,CLW\nFEDRAT/MMPM,800.0000\n{moves}END-OF-PATH\n")
    common = ["--job", os.path.join(MODEL, "job.json"), "--phi-step", "5"]
    assert cli.main(["engage", "--stock", os.path.join(MODEL, "stock.step"), "--toolpath",
                     str(folder / "mcs.clsf"), "--out", str(folder / "mcs.csv"), *common]) == 0
    assert cli.main(["engage", "--stock", str(folder / "part.step"), "--toolpath", str(folder / "job.clsf"),
                     "--out", str(folder / "part.csv"), *common]) == 0
    return read_results(folder / "mcs.csv"), read_results(folder / "part.csv")


def test_the_operation_frame_gives_the_mcs_results(runs):
    mcs, part = runs
    assert np.count_nonzero(mcs["length"] > 0) > 1000
    for column in ("length", "lep_l", "uep_l", "pieces"):
        np.testing.assert_allclose(part[column], mcs[column], atol=1e-9, equal_nan=True, err_msg=column)
    np.testing.assert_array_equal(part["uep_surface"], mcs["uep_surface"])


def test_engagement_points_are_written_in_part_coordinates(runs):
    mcs, part = runs
    rotation, origin = _frame()
    for end in ("lep", "uep"):
        local = np.stack([mcs[f"{end}_{axis}"] for axis in "xyz"], axis=1)
        written = np.stack([part[f"{end}_{axis}"] for axis in "xyz"], axis=1)
        np.testing.assert_allclose(written, local @ rotation.T + origin, atol=1e-9, equal_nan=True)


def test_a_json_staircase_under_a_turned_mcs_is_computed_in_the_part(tmp_path):
    """A JSON staircase stands in the part and can only be moved: a program whose MSYS turns 90° about z
    (its points in the MCS) is computed in the part, and gives what the same points written in the part
    give."""
    turn = np.column_stack([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])  # MCS -> part
    origin = np.array([5.0, -3.0, 0.0])
    path = load_toolpath(os.path.join(MODEL, "toolpath.csv"))
    programs = {"part.clsf": (path.cl, path.axes, ""),
                "turned.clsf": ((path.cl - origin) @ turn, path.axes @ turn,
                                "MSYS/" + ",".join(f"{v:.12g}" for v in (*origin, *turn[:, 0], *turn[:, 1])) + "\n")}
    for name, (points, axes, msys) in programs.items():
        moves = "".join("GOTO/" + ",".join(f"{v:.12f}" for v in (*p, *a)) + "\n" for p, a in zip(points, axes))
        (tmp_path / name).write_text(f"TOOL PATH/P,TOOL,EM12\nTLDATA/MILL,12,0,75,0,0\n{msys}{moves}END-OF-PATH\n")
        assert cli.main(["engage", "--stock", os.path.join(MODEL, "stock.json"), "--toolpath", str(tmp_path / name),
                         "--job", os.path.join(MODEL, "job.json"), "--phi-step", "5",
                         "--out", str(tmp_path / (name + ".csv"))]) == 0
    part, turned = (read_results(tmp_path / (name + ".csv")) for name in programs)
    assert np.count_nonzero(part["length"] > 0) > 500
    for column in ("length", "lep_l", "uep_l", "pieces", "lep_x", "lep_y", "lep_z", "uep_x", "uep_y", "uep_z"):
        np.testing.assert_allclose(turned[column], part[column], atol=1e-9, equal_nan=True, err_msg=column)
