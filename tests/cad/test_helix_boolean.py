"""Helical cutting edges against OpenCASCADE: flute_engagement on the exact walls read from the
model tests' STEP solids must agree with booleans of the helices with the same solids.

The helix of the reference is a straight line on OCC's cylinder, whose 3D curve OCC
approximates to its confusion tolerance, 1e-7 mm (the edge's Tolerance); a crossing found on
that curve moves along the axis by about the curve's deviation over the sine of the angle at
which the helix meets the surface. Measured on these cases: at most 7.6e-7 mm (a curved wall
met at 4.3°), so 1e-6 mm holds. See docs/HELIX.md, "Checked against OpenCASCADE".
"""

import json
import os

import numpy as np
import pytest

from abm_workbench import cli
from abm_workbench.cad import helix_boolean
from abm_workbench.cad.boolean import edge_lengths_by_boolean
from abm_workbench.cad.freecad_env import FreeCAD
from abm_workbench.cad.helix_boolean import flute_lengths_by_boolean, helix_edge
from abm_workbench.cad.recognise import load_solid, recognise
from abm_workbench.engine import SURFACES, CutSettings, Tool, Toolpath, flute_engagement, rotation_matrix
from abm_workbench.formats.toolpath_csv import load_toolpath
from abm_workbench.report.tables import FLUTE_COLUMNS
from abm_workbench.validation import NoEngagementError, validate_helix

MODELS = os.path.join(os.path.dirname(__file__), "..", "..", "resources", "models")
TOL = 1e-6  # mm
# CL points (from 0): curved walls and tops (model 1: 11, 44; model 2: 14, 15), straight walls
# (model 1: 29, the wall at x = 76; model 2: 3, on the extruded flank).
PICKED = {"model_test_1": [11, 29, 44], "model_test_2": [3, 14, 15]}
PHI = (0.0, 345.0, 15.0)  # every 15° over a whole turn
HELICES = (30.0, -20.0)


def formula_points(tool, cl, frame, psi0_deg, l):
    """T + R·(R_t sin ψ, R_t cos ψ, l), ψ = ψ0 − deg(l tan β / R_t): (k, 3) mm at heights l (k,)."""
    psi = np.radians(psi0_deg) - l * np.tan(np.radians(tool.helix)) / tool.radius
    local = np.column_stack([tool.radius * np.sin(psi), tool.radius * np.cos(psi), l])
    return cl + local @ frame.T


@pytest.mark.parametrize("helix", [30.0, -20.0, 0.0])
def test_the_occ_edge_is_the_flute_helix(helix):
    """Every point of the OCC edge lies on the helix of its own height, to OCC's 1e-7 mm, and the edge
    spans l = 0..L: placement, start angle and handedness are right."""
    tool = Tool(12.0, 2, 30.0, helix=helix)
    cl, frame = np.array([12.3, -1.1, 4.2]), rotation_matrix(13.0, -21.0)
    for psi0 in (0.0, 77.0, 200.0):
        edge = helix_edge(tool, cl, frame, psi0)
        points = np.array([tuple(edge.valueAt(u)) for u in np.linspace(*edge.ParameterRange, 301)])
        l = (points - cl) @ frame[:, 2]
        assert np.abs(points - formula_points(tool, cl, frame, psi0, l)).max() < 1e-7
        assert abs(l.min()) < 1e-12 and abs(l.max() - 30.0) < 1e-12
        assert edge.Tolerance <= 1e-7


@pytest.fixture(scope="module", params=sorted(PICKED))
def model(request):
    """(solid, exact-wall staircase, job dict, picked Toolpath) of one model test."""
    folder = os.path.join(MODELS, request.param)
    job = json.load(open(os.path.join(folder, "job.json")))
    full = load_toolpath(os.path.join(folder, "toolpath.csv"))
    rows = PICKED[request.param]
    solid = load_solid(os.path.join(folder, "stock.step"))
    return solid, recognise(solid).staircase, job, Toolpath(full.cl[rows], full.theta_a[rows], full.theta_b[rows])


def settings_of(job):
    """The job's cut settings with PHI."""
    return CutSettings(job["feed_per_tooth"], job["inclination"], *PHI)


@pytest.mark.parametrize("helix", HELICES)
def test_flute_engagement_agrees_with_the_helix_boolean(model, helix):
    solid, stock, job, path = model
    tool = Tool(job["diameter"], 2, job["flute_length"], helix=helix)
    engine = flute_engagement(stock, tool, path, settings_of(job))
    boolean = flute_lengths_by_boolean(solid, tool, path, engine.phi)
    assert np.array_equal(engine.pieces, boolean["pieces"])
    for name in ("axial_length", "edge_length", "lep_l", "uep_l"):
        a, b = getattr(engine, name), boolean[name]
        assert np.array_equal(np.isnan(a), np.isnan(b)), name
        assert np.nanmax(np.abs(a - b)) < TOL, name
    assert (boolean["axial_length"] > 0).mean() > 0.5
    kinds = {SURFACES[s] for s in engine.uep_surface[engine.pieces > 0]}
    assert {"top", "straight_wall", "curved_wall"} <= kinds


def test_a_straight_tool_gives_the_straight_boolean(model):
    """β = 0: every flute's result is the straight boolean's at its own angle φ + 360k/Z."""
    solid, _, job, path = model
    tool = Tool(job["diameter"], 2, job["flute_length"])
    phi = settings_of(job).phi
    helix = flute_lengths_by_boolean(solid, tool, path, phi)
    for flute in range(2):
        straight = edge_lengths_by_boolean(solid, tool, path, phi + 180.0 * flute)
        np.testing.assert_array_equal(helix["pieces"][..., flute], straight["pieces"])
        for name, other in (("axial_length", "length"), ("edge_length", "length"), ("lep_l", "lep_l"),
                            ("uep_l", "uep_l")):
            np.testing.assert_allclose(helix[name][..., flute], straight[other], rtol=0, atol=1e-12)


def test_a_nearly_straight_helix_tends_to_the_straight_boolean(model):
    """β = 1e-6°: the helix strays 5e-7 mm from the straight edge over L, so the OCC helix (a line on
    the cylinder, not the straight segment) must give the straight boolean's results to 1e-6 mm
    wherever no surface is met at a grazing angle."""
    solid, _, job, path = model
    phi = settings_of(job).phi
    helix = flute_lengths_by_boolean(solid, Tool(job["diameter"], 2, job["flute_length"], helix=1e-6), path, phi,
                                     flutes=[0])
    straight = edge_lengths_by_boolean(solid, Tool(job["diameter"], 2, job["flute_length"]), path, phi)
    np.testing.assert_array_equal(helix["pieces"][..., 0], straight["pieces"])
    for name, other in (("axial_length", "length"), ("lep_l", "lep_l"), ("uep_l", "uep_l")):
        np.testing.assert_allclose(helix[name][..., 0], straight[other], rtol=0, atol=TOL)
    assert (helix["axial_length"][..., 1] == 0).all()  # flute 1 not asked for


def test_validate_helix_per_flute(model):
    solid, stock, job, path = model
    tool = Tool(job["diameter"], 2, job["flute_length"], helix=30.0)
    checked = validate_helix(solid, stock, tool, path, settings_of(job), flutes=[1])
    assert checked.flutes == (1,)
    (row,) = checked.flute_summary()
    assert row["flute"] == 1 and row["mismatched"] == 0 and row["engaged_abm"] > 0
    assert max(row[f"max_{k}_difference"] for k in ("axial", "lep", "uep")) < TOL
    validation = checked.flute(1)
    assert validation.engagement.shape == (3, 24)
    np.testing.assert_array_equal(validation.comparison.l_abm, checked.engagement.axial_length[..., 1])
    np.testing.assert_allclose(validation.comparison.depth_ref, validation.comparison.depth_abm, atol=TOL)
    with pytest.raises(ValueError, match="flute 0 was not checked"):
        checked.flute(0)


def test_errors(model):
    solid, stock, job, path = model
    tool = Tool(job["diameter"], 2, job["flute_length"], helix=30.0)
    with pytest.raises(ValueError, match=r"flutes must be indices in 0\.\.1"):
        flute_lengths_by_boolean(solid, tool, path, [0.0], flutes=[2])
    with pytest.raises(ValueError, match="phi_deg must be finite"):
        flute_lengths_by_boolean(solid, tool, path, [np.nan])
    with pytest.raises(ValueError, match=r"flutes must be indices in 0\.\.1"):
        validate_helix(solid, stock, tool, path, settings_of(job), flutes=[-1])
    away = Toolpath(path.cl + [0.0, 0.0, 100.0], path.theta_a, path.theta_b)
    with pytest.raises(NoEngagementError):
        validate_helix(solid, stock, tool, away, settings_of(job))


def test_a_result_edge_off_every_helix_is_an_error(model, monkeypatch):
    """Edges 1e-3 mm beside their helices: the result cannot be mapped back, and says so."""
    solid, _, job, path = model
    tool = Tool(job["diameter"], 2, job["flute_length"], helix=30.0)

    def shifted(*args):
        edge = helix_edge(*args)
        edge.translate(FreeCAD.Vector(0.0, 0.0, 1e-3))
        return edge
    monkeypatch.setattr(helix_boolean, "helix_edge", shifted)
    with pytest.raises(RuntimeError, match="lies on no flute helix"):
        flute_lengths_by_boolean(solid, tool, path, settings_of(job).phi)


@pytest.fixture
def pass_files(tmp_path):
    """Model test 2's STEP, job and a toolpath CSV of its picked CL points, in tmp_path."""
    folder = os.path.join(MODELS, "model_test_2")
    lines = open(os.path.join(folder, "toolpath.csv")).read().splitlines()
    (tmp_path / "path.csv").write_text("\n".join([lines[0]] + [lines[i + 1] for i in PICKED["model_test_2"]]) + "\n")
    return [os.path.join(folder, "stock.step"), str(tmp_path / "path.csv"), os.path.join(folder, "job.json")]


def test_cli_validate_helix(pass_files, tmp_path, capsys):
    stock, path, job = pass_files
    report = tmp_path / "report"
    status = cli.main(["validate", "--stock", stock, "--toolpath", path, "--job", job, "--phi-step", "30",
                       "--helix", "-20", "--report", str(report)])
    out, err = capsys.readouterr()
    assert status == 0, err
    assert "Helical edges against the helix boolean: flute 1: max |Δ axial length|" in out and "flute 2:" in out
    page = (report / "index.html").read_text()
    assert "<h1>Helical edges (β = -20°), flute 1 of 2, ABM against booleans: stock.step / path.csv</h1>" in page
    assert "flute length 30 mm, helix -20°" in page and ", helix -20° [--helix]" in out
    lines = (report / "flutes.csv").read_text().splitlines()
    assert lines[0] == ",".join(FLUTE_COLUMNS) and len(lines) == 1 + 3 * 7 * 2
    rows = np.genfromtxt(lines[1:], delimiter=",")
    differences = rows[:, [FLUTE_COLUMNS.index(c) for c in ("axial_difference", "lep_difference", "uep_difference")]]
    assert np.nanmax(np.abs(differences)) < TOL
    status = cli.main(["validate", "--stock", stock, "--toolpath", path, "--job", job, "--phi-step", "30",
                       "--helix", "30", "--flute", "2", "--report", str(report), "--cl", "1",
                       "--fcstd", str(tmp_path / "helix.FCStd")])
    out, err = capsys.readouterr()
    assert status == 0, err
    assert "flute 2:" in out and "flute 1:" not in out
    assert (tmp_path / "helix.FCStd").stat().st_size > 0
    assert "flute 2 of 2" in (report / "index.html").read_text()
    assert len((report / "flutes.csv").read_text().splitlines()) == 1 + 3 * 7


@pytest.mark.parametrize("options, message", [
    (["--flute", "3"], "--flute: must be 1..2 (the tool has 2 flutes), got 3"),
    (["--helix", "95"], "--helix: must be within [-60, 60]°, got 95°"),
])
def test_cli_validate_helix_errors(pass_files, tmp_path, capsys, options, message):
    stock, path, job = pass_files
    status = cli.main(["validate", "--stock", stock, "--toolpath", path, "--job", job, "--report",
                       str(tmp_path / "report")] + options)
    _, err = capsys.readouterr()
    assert status == 2
    assert message in err
    assert not (tmp_path / "report").exists()
