"""The benchmark's independent peer (benchmarks/peer_raycast.py) against OpenCASCADE.

The peer needs trimesh, embreex and manifold3d, which only ``make compare-peers`` installs (in
build/peers-venv): without them its tests are skipped. Run them with that environment's python:
``build/peers-venv/bin/python -m pytest -q tests/cad/test_peer_raycast.py``.
"""

import os
import subprocess
import sys

import numpy as np
import pytest

from abm_workbench.cad.boolean import edge_lengths_by_boolean
from abm_workbench.cad.freecad_env import FreeCAD, Part
from abm_workbench.engine import Tool, Toolpath, edge_lines
from abm_workbench.formats.toolpath_csv import load_toolpath
from abm_workbench.jobs import load_job

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BENCHMARKS = os.path.join(ROOT, "benchmarks")
MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")
#: CL points of model test 1 checked: the start, the main ridge and the valley.
CL_POINTS = [0, 22, 40]
DEVIATIONS = (0.01, 0.001)
#: trimesh steps 10^-6 of the mesh's size past each hit (~1.4e-4 mm here): a crossing point may lie that far on.
STEP_PAST_HIT = 2e-4


def test_compare_methods_help_runs():
    done = subprocess.run([sys.executable, os.path.join(BENCHMARKS, "compare_methods.py"), "--help"],
                          capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "--peers" in done.stdout


@pytest.fixture(scope="module")
def model():
    """(tool, toolpath of CL_POINTS, phi (deg), boolean reference dict, {deviation: peer dict}, solid)."""
    for name in ("trimesh", "embreex", "manifold3d"):
        pytest.importorskip(name)
    sys.path.insert(0, BENCHMARKS)
    try:
        import peer_raycast
    finally:
        sys.path.remove(BENCHMARKS)
    job = load_job(os.path.join(MODEL, "job.json"))
    tool = Tool(job["diameter"], int(job["flutes"]), job["flute_length"])
    full = load_toolpath(os.path.join(MODEL, "toolpath.csv"))
    toolpath = Toolpath(full.cl[CL_POINTS], full.theta_a[CL_POINTS], full.theta_b[CL_POINTS])
    phi = np.arange(0.0, 181.0, 1.0)
    step = os.path.join(MODEL, "stock.step")
    peers = {}
    for deviation in DEVIATIONS:
        mesh = peer_raycast.mesh_stock(step, deviation)
        peers[deviation] = peer_raycast.edge_lengths_by_ray_casting(mesh, tool, toolpath, phi)
    solid = Part.Shape()
    solid.read(step)
    reference = edge_lengths_by_boolean(solid, tool, toolpath, phi)
    return tool, toolpath, phi, reference, peers, solid


@pytest.mark.parametrize("deviation", DEVIATIONS)
def test_peer_engages_where_the_boolean_does(model, deviation):
    """Same instants engaged, same number of inside pieces, no crossing lost in the mesh; the
    bottom rim point inside the solid (reference LEP at l = 0) gives LEP 0 exactly."""
    _, _, _, reference, peers, _ = model
    peer = peers[deviation]
    assert peer["unbalanced"] == 0
    np.testing.assert_array_equal(np.isnan(peer["uep_l"]), np.isnan(reference["uep_l"]))
    np.testing.assert_array_equal(peer["pieces"], reference["pieces"])
    at_rim = reference["lep_l"] == 0.0
    assert at_rim.any()
    np.testing.assert_array_equal(peer["lep_l"][at_rim], 0.0)


@pytest.mark.parametrize("deviation", DEVIATIONS)
def test_peer_crossings_lie_within_the_chord_deviation_of_the_solid(model, deviation):
    """Every UEP the peer finds below the top of the flute is a point of its mesh, so it lies within
    the tessellation's chordal deviation of the solid's boundary (OpenCASCADE distance), up to
    trimesh's step past each hit. Every 6th angle, to keep the distance queries few."""
    tool, toolpath, phi, _, peers, solid = model
    peer = peers[deviation]
    base, direction = edge_lines(toolpath, tool, phi)
    inner = np.isfinite(peer["uep_l"]) & (peer["uep_l"] < tool.flute_length)
    inner[:, np.arange(phi.size) % 6 != 0] = False
    assert inner.sum() > 50
    points = (base + peer["uep_l"][..., None] * direction[:, None, :])[inner]
    boundary = solid.Shells[0]
    distances = np.array([boundary.distToShape(Part.Vertex(FreeCAD.Vector(*p)))[0] for p in points])
    assert distances.max() <= deviation + STEP_PAST_HIT, distances.max()


def test_peer_length_error_shrinks_with_the_deviation(model):
    """Against the boolean, the finer mesh's length error is smaller (max and mean), and each
    mesh's error stays within 10 deviations: a chord `deviation` off the surface moves a crossing
    by deviation / sin θ along an edge meeting the surface at θ, so 10 allows θ down to about 6°."""
    _, _, _, reference, peers, _ = model
    errors = {d: np.abs(peers[d]["length"] - reference["length"]) for d in DEVIATIONS}
    coarse, fine = DEVIATIONS
    assert errors[fine].max() < errors[coarse].max()
    assert errors[fine].mean() < errors[coarse].mean()
    for deviation, error in errors.items():
        assert error.max() <= 10 * deviation, (deviation, error.max())
