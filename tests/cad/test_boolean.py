"""The boolean reference against the engine: the solid holds the engine's own quintics, so
length of cut, LEP and UEP must agree to 1e-6 mm."""

import os

import numpy as np
import pytest

from abm_workbench.cad.boolean import cutter_intersection, edge_lengths_by_boolean
from abm_workbench.cad.recognise import load_solid, recognise_staircase
from abm_workbench.cad.solids import export_step, staircase_solid
from abm_workbench.engine import SURFACES, CutSettings, Tool, Toolpath, engage
from abm_workbench.formats.staircase_json import load_staircase
from abm_workbench.formats.toolpath_csv import load_toolpath

from .conftest import STOCKS

TOL = 1e-6  # mm
TOOL = Tool(diameter=12.0, flutes=2, flute_length=25.0)
# Eight angles 4.3°, 29°, … 177.2°: irregular values, so no edge grazes a vertex by design.
SETTINGS = CutSettings(feed_per_tooth=0.1, phi_start=4.3, phi_end=177.2, phi_step=24.7)
# CL points beside each wall, the tool tilted both ways about x and y (deg); the last two
# lean steeply into a lower section, so the UEP falls on a curved wall.
PATH = Toolpath(
    cl=[[21.3, 0.7, 0.9], [31.7, -2.1, 3.2], [44.9, 1.3, 2.1], [56.1, -0.9, 4.4], [69.2, 2.3, 1.7],
        [79.4, -1.6, 6.3], [23.0, 0.5, 4.3], [73.0, -0.4, 4.3]],
    theta_a=[12.0, -9.0, 0.0, 17.0, -14.0, 6.0, 5.0, -6.0],
    theta_b=[18.0, -22.0, 25.0, -11.0, 9.0, -27.0, 30.0, -30.0],
)
MODELS = os.path.join(os.path.dirname(__file__), "..", "..", "resources", "models")


def largest_difference(engine, boolean):
    """max |engine − boolean| (mm) over length, LEP and UEP; pieces and engagement must match."""
    assert np.array_equal(engine.pieces, boolean["pieces"])
    worst = 0.0
    for name in ("length", "lep_l", "uep_l"):
        a, b = getattr(engine, name), boolean[name]
        assert np.array_equal(np.isnan(a), np.isnan(b)), name
        worst = max(worst, float(np.nanmax(np.abs(a - b), initial=0.0)))
    return worst


@pytest.fixture(scope="module")
def compared(solids):
    """{stock name: (engine Engagement, boolean dict)} over PATH × SETTINGS.phi."""
    return {
        name: (engage(stock, TOOL, PATH, SETTINGS), edge_lengths_by_boolean(solids[name], TOOL, PATH, SETTINGS.phi))
        for name, stock in STOCKS.items()
    }


@pytest.mark.parametrize("name", sorted(STOCKS))
def test_boolean_agrees_with_the_engine(compared, name):
    engine, boolean = compared[name]
    assert largest_difference(engine, boolean) < TOL
    assert (boolean["length"] > 0).mean() > 0.5  # the cases do engage


def test_the_cases_put_the_uep_on_every_kind_of_surface(compared):
    surfaces = {SURFACES[s] for engine, _ in compared.values() for s in engine.uep_surface.ravel()}
    assert {"top", "straight_wall", "curved_wall"} <= surfaces
    assert max(engine.pieces.max() for engine, _ in compared.values()) >= 2


def test_bundled_model_against_its_recognised_staircase(tmp_path):
    """Model test 1 as a STEP solid: boolean on the solid, engine on the staircase recognised from it."""
    stock = load_staircase(os.path.join(MODELS, "model_test_1", "stock.json"))
    path = load_toolpath(os.path.join(MODELS, "model_test_1", "toolpath.csv"))
    step = tmp_path / "stock.step"
    export_step(staircase_solid(stock), step)
    solid = load_solid(step)
    picked = Toolpath(path.cl[[12, 30]], path.theta_a[[12, 30]], path.theta_b[[12, 30]])
    tool = Tool(12.0, 2, 30.0)
    engine = engage(recognise_staircase(solid), tool, picked, SETTINGS)
    boolean = edge_lengths_by_boolean(solid, tool, picked, SETTINGS.phi)
    assert largest_difference(engine, boolean) < TOL
    assert (boolean["length"] > 0).any()


def test_progress_is_reported_per_cl_point_and_an_interrupt_propagates(solids):
    calls = []
    edge_lengths_by_boolean(solids["ridge"], TOOL, PATH, [90.0], progress=lambda *args: calls.append(args))
    assert calls == [(i, len(PATH)) for i in range(1, len(PATH) + 1)]

    def interrupt(done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        edge_lengths_by_boolean(solids["ridge"], TOOL, PATH, [90.0], progress=interrupt)


def test_no_engagement_gives_zero_length_and_nan_ends(solids):
    above = Toolpath([[50.0, 0.0, 40.0]], [5.0], [-5.0])
    result = edge_lengths_by_boolean(solids["ridge"], TOOL, above, [10.0, 90.0])
    assert np.all(result["length"] == 0) and np.all(result["pieces"] == 0)
    assert np.isnan(result["lep_l"]).all() and np.isnan(result["uep_l"]).all()


def test_cutter_intersection_is_the_material_inside_the_cutter(solids):
    solid = solids["ascending"]
    cut = cutter_intersection(solid, TOOL, PATH, 1)
    assert cut.isValid() and cut.Volume > 1.0
    assert cut.Volume < np.pi * TOOL.radius ** 2 * TOOL.flute_length
    assert solid.common(cut).Volume == pytest.approx(cut.Volume, rel=1e-9)
    axis = np.array([np.sin(np.radians(-22.0)), -np.sin(np.radians(-9.0)) * np.cos(np.radians(-22.0)),
                     np.cos(np.radians(-9.0)) * np.cos(np.radians(-22.0))])
    for vertex in cut.Vertexes:
        offset = np.array(tuple(vertex.Point)) - PATH.cl[1]
        along = offset @ axis
        assert -1e-7 <= along <= TOOL.flute_length + 1e-7
        assert np.linalg.norm(offset - along * axis) <= TOOL.radius + 1e-7


def test_angles_equal_modulo_360_give_equal_results(solids):
    result = edge_lengths_by_boolean(solids["ridge"], TOOL, PATH, [29.3, 389.3, -330.7, 90.0, 360.0, 0.0])
    for name in ("length", "lep_l", "uep_l", "pieces"):
        assert np.array_equal(result[name][:, 0], result[name][:, 1], equal_nan=True)
        assert np.array_equal(result[name][:, 0], result[name][:, 2], equal_nan=True)
        assert np.array_equal(result[name][:, 4], result[name][:, 5], equal_nan=True)
    assert (result["length"][:, 0] > 0).any()


def test_no_angles_and_bad_angles(solids):
    empty = edge_lengths_by_boolean(solids["ridge"], TOOL, PATH, [])
    assert empty["length"].shape == (len(PATH), 0)
    with pytest.raises(ValueError, match=r"phi_deg must be finite angles of shape \(p,\)"):
        edge_lengths_by_boolean(solids["ridge"], TOOL, PATH, [[10.0, 20.0]])
    with pytest.raises(ValueError, match="phi_deg must be finite"):
        edge_lengths_by_boolean(solids["ridge"], TOOL, PATH, [np.nan])
