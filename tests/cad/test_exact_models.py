"""The bundled model tests as STEP solids with their true contour walls (resources/models/*/stock.step).

The boolean (OpenCASCADE) on the solid is the reference. The engine on the exact walls read
from the solid must agree with it; the paper's quintic walls (six Chebyshev points per wall)
are measured against it per UEP surface kind, as in the paper's check against Siemens NX:
error = (l_ABM − l_ref) / l_ref, or l_ABM − l_ref (mm) where l_ref < 1e-3 mm. A few CL points
per model test, chosen to hold the largest quintic errors of the whole pass, at every φ = 0..180°.
"""

import json
import os

import numpy as np
import pytest

from abm_workbench.cad.boolean import edge_lengths_by_boolean
from abm_workbench.cad.recognise import load_solid, recognise
from abm_workbench.engine import SURFACES, CutSettings, Tool, Toolpath, engage
from abm_workbench.formats.toolpath_csv import load_toolpath

MODELS = os.path.join(os.path.dirname(__file__), "..", "..", "resources", "models")
TOL = 1e-6  # mm, exact walls against the boolean
NEGLIGIBLE = 1e-6  # relative error with the UEP on a top or a straight wall
CURVED_LIMIT = 0.01  # relative error with the UEP on a curved wall
WINDOW_MARGIN = 2.0  # mm beyond the tool radius on each side of the pass: the y the edge sweeps
# CL points (from 0): the worst curved-wall instants, top UEPs after a curved-wall LEP, straight walls.
PICKED = {"model_test_1": [11, 18, 29, 44], "model_test_2": [3, 14, 15, 23]}


def relative_error(length, reference):
    """(l − l_ref)/l_ref, or l − l_ref (mm) where l_ref < 1e-3 mm; arrays of one shape."""
    small = reference < 1e-3
    return np.where(small, length - reference, (length - reference) / np.where(small, 1.0, reference))


@pytest.fixture(scope="module", params=sorted(PICKED))
def model(request):
    """One model test at its picked CL points: the boolean on the STEP solid, and the engine on the
    staircases recognised from it: exact walls, quintics over the whole strip, quintics over the
    y the pass sweeps."""
    folder = os.path.join(MODELS, request.param)
    job = json.load(open(os.path.join(folder, "job.json")))
    tool = Tool(job["diameter"], job["flutes"], job["flute_length"])
    settings = CutSettings(job["feed_per_tooth"], job["inclination"], *job["phi_range"], job["phi_step"])
    full = load_toolpath(os.path.join(folder, "toolpath.csv"))
    rows = PICKED[request.param]
    path = Toolpath(full.cl[rows], full.theta_a[rows], full.theta_b[rows])
    solid = load_solid(os.path.join(folder, "stock.step"))
    reach = tool.radius + WINDOW_MARGIN
    window = (full.cl[:, 1].min() - reach, full.cl[:, 1].max() + reach)
    return {
        "boolean": edge_lengths_by_boolean(solid, tool, path, settings.phi),
        "exact": engage(recognise(solid).staircase, tool, path, settings),
        "quintic": engage(recognise(solid, walls="quintic").staircase, tool, path, settings),
        "pass_quintic": engage(recognise(solid, walls="quintic", y_window=window).staircase, tool, path, settings),
    }


def test_exact_walls_agree_with_the_boolean(model):
    engine, boolean = model["exact"], model["boolean"]
    assert np.array_equal(engine.pieces, boolean["pieces"])
    for name in ("length", "lep_l", "uep_l"):
        a, b = getattr(engine, name), boolean[name]
        assert np.array_equal(np.isnan(a), np.isnan(b)), name
        assert np.nanmax(np.abs(a - b)) < TOL, name
    kinds = set(engine.surface_names()[engine.engaged])
    assert {"top", "straight_wall", "curved_wall"} <= kinds


def plain_top_or_straight(model, quintic):
    """(m, p) bool: the UEP is on a top or a straight wall in the reference and in `quintic`, and
    the edge is inside in one piece from its bottom (l = 0) in both: no wall below the UEP."""
    reference = model["exact"]
    same = reference.uep_surface == quintic.uep_surface
    kind = np.isin(reference.uep_surface, [SURFACES.index("top"), SURFACES.index("straight_wall")])
    whole = [(e.pieces == 1) & (e.lep_l == 0.0) for e in (reference, quintic)]
    return same & kind & whole[0] & whole[1]


@pytest.mark.parametrize("variant", ["quintic", "pass_quintic"])
def test_quintic_walls_are_exact_where_the_uep_is_on_a_top_or_straight_wall(model, variant):
    """Where no curved wall bounds the engaged part, the quintic's fit error cannot show."""
    quintic = model[variant]
    mask = plain_top_or_straight(model, quintic)
    assert mask.sum() > 100
    error = relative_error(quintic.length, model["boolean"]["length"])
    assert np.abs(error[mask]).max() < NEGLIGIBLE
    # the UEP itself, wherever both models put it on the same top or straight wall
    reference = model["exact"]
    kind = np.isin(reference.uep_surface, [SURFACES.index("top"), SURFACES.index("straight_wall")])
    same = kind & (reference.uep_surface == quintic.uep_surface) & (reference.uep_section == quintic.uep_section)
    assert np.nanmax(np.abs(quintic.uep_l - model["boolean"]["uep_l"])[same]) < NEGLIGIBLE


def test_quintic_over_the_swept_window_is_within_one_percent_on_curved_walls(model):
    """Six Chebyshev points over the y the edge sweeps, y_T ± (R_t + 2 mm), fit the contours well
    enough; measured over the whole passes: 0.05 % (model 1) and 0.26 % (model 2) at most."""
    kinds = model["exact"].uep_surface
    error = relative_error(model["pass_quintic"].length, model["boolean"]["length"])
    curved = kinds == SURFACES.index("curved_wall")
    assert curved.sum() > 30
    assert np.abs(error[curved]).max() < CURVED_LIMIT
    assert np.abs(error).max() < CURVED_LIMIT  # every kind


@pytest.mark.xfail(strict=True, reason="measured: six Chebyshev points over the whole 30 mm strip give up to "
                                       "3.2 % (model 1) and 3.0 % (model 2) on curved walls")
def test_quintic_over_the_whole_strip_is_within_one_percent_on_curved_walls(model):
    kinds = model["exact"].uep_surface
    error = relative_error(model["quintic"].length, model["boolean"]["length"])
    assert np.abs(error[kinds == SURFACES.index("curved_wall")]).max() < CURVED_LIMIT

