"""Flat-end, bull-nose and ball-end mills, any tool axis, against the brute-force reference of
profile_reference: length along the peripheral edge, the heights of its LEP and UEP, and the end
edge's engaged length, on a staircase and on a terraced stock, within 1e-6 mm.

A planted error (the corner's centre moved, its arc swept the wrong way) must make the comparison fail.
"""

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from abm_workbench.engine import CutSettings, Tool, Toolpath
from abm_workbench.engine import profile
from abm_workbench.engine.engagement import CASES
from abm_workbench.engine.frames import angles_to_axis, axis_to_angles
from abm_workbench.engine.stocks import engage_stock

from . import profile_reference as ref
from . import terraced_reference
from .reference import StairData, _Stock
from .strategies import engine_stock
from .test_terraced import to_stock

TOL = 1e-6  # mm
RATIOS = (0.0, 0.1, 0.3, 0.5, 1.0)  # r / R

SLABS = [(0.0, 5.0, [("polygon", np.array([[-20, -15], [25, -12], [22, 18], [-18, 20]]))]),
         (5.0, 9.0, [("circle", np.array([1.0, 2.0]), 9.0), ("circle", np.array([3.0, 1.0]), 3.0)]),
         (9.0, 14.0, [("stadium", np.array([-4.0, 0.0]), np.array([6.0, 3.0]), 4.0)])]
TERRACED = to_stock(SLABS)
TERRACED_LEVELS = sorted({z for z0, z1, _ in SLABS for z in (z0, z1)})
STAIR = StairData(-20, 20, -15, 15, 0.0, (6.0, 10.0, 4.0),
                  (tuple((-5 + 0.3 * np.sin(y / 5), y) for y in np.linspace(-15, 15, 6)),
                   tuple((8.0 - 0.05 * y, y) for y in np.linspace(-15, 15, 6))))
STAIRCASE = engine_stock(STAIR)
STOCKS = {
    "terraced": (TERRACED, lambda points: terraced_reference.inside(points, SLABS), TERRACED_LEVELS),
    "staircase": (STAIRCASE, _Stock(STAIR).inside, [0.0, 4.0, 6.0, 10.0]),
}
PHI = CutSettings(0.1, phi_start=0.0, phi_end=345.0, phi_step=15.0)


def mismatches(engagement, stock_name, tool, toolpath, phis=PHI.phi):
    """[(CL, φ, field, engine, reference)] where the engine and the reference differ by more than TOL."""
    _, inside, levels = STOCKS[stock_name]
    bad = []
    for i in range(len(toolpath)):
        for k, phi in enumerate(phis):
            want = ref.reference_instant(inside, levels, toolpath.cl[i], toolpath.theta_a[i], toolpath.theta_b[i],
                                         toolpath.alpha[i], phi, tool.radius, tool.corner_radius, tool.flute_length)
            for name in ("length", "lep_l", "uep_l", "end_length"):
                got = getattr(engagement, name)[i, k]
                if not ((np.isnan(got) and np.isnan(want[name])) or abs(got - want[name]) <= TOL):
                    bad.append((i, phi, name, got, want[name]))
            for name in ("lep_xyz", "uep_xyz"):
                got = getattr(engagement, name)[i, k]
                if not np.allclose(got, want[name], rtol=0.0, atol=TOL, equal_nan=True):
                    bad.append((i, phi, name, got, want[name]))
    return bad


@st.composite
def passes(draw, turned=False):
    """(Tool, Toolpath): a tool of a ratio r/R in RATIOS and three CL points near the stocks, with tilted
    axes (turned: any direction, also sideways and down) and frames turned to any feed."""
    radius = draw(st.floats(2.0, 8.0))
    corner = radius * draw(st.sampled_from(RATIOS))
    length = draw(st.floats(max(0.5 * corner, 1.0), 25.0))
    # Off the stocks' levels and loops by an odd offset: an end edge lying in a floor to within rounding may
    # be in or out, and shrinking would find exactly that.
    cl = np.array([[draw(st.floats(-15, 15)), draw(st.floats(-12, 12)), draw(st.floats(-3, 13))] for _ in range(3)])
    cl = cl + np.array([0.01234567, 0.0213579, 0.0372941])
    a_range, b_range = (180.0, 89.0) if turned else (60.0, 60.0)
    theta_a = np.array([draw(st.floats(-a_range, a_range)) for _ in range(3)])
    theta_b = np.array([draw(st.floats(-b_range, b_range)) for _ in range(3)])
    alpha = np.array([draw(st.floats(-180.0, 180.0)) for _ in range(3)])
    return Tool(2 * radius, 2, length, corner_radius=corner), Toolpath(cl, theta_a, theta_b, alpha=alpha)


@pytest.mark.parametrize("stock_name", sorted(STOCKS))
@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(job=passes())
def test_tilted_tools_of_every_corner_agree_with_the_reference(stock_name, job):
    tool, toolpath = job
    engagement = engage_stock(STOCKS[stock_name][0], tool, toolpath, PHI)
    assert mismatches(engagement, stock_name, tool, toolpath) == []


@pytest.mark.parametrize("stock_name", sorted(STOCKS))
@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(job=passes(turned=True))
def test_any_axis_direction_agrees_with_the_reference(stock_name, job):
    tool, toolpath = job
    engagement = engage_stock(STOCKS[stock_name][0], tool, toolpath, PHI)
    assert mismatches(engagement, stock_name, tool, toolpath) == []


def fixed_pass():
    """Three CL points whose corners meet walls, floors and tops of both stocks."""
    cl = np.array([[-6.0, 1.0, 3.0], [8.5, -3.0, 5.5], [2.0, 6.0, 8.0]])
    return Toolpath(cl, np.array([20.0, -35.0, 10.0]), np.array([15.0, 25.0, -40.0]), alpha=np.array([0.0, 60.0, -120.0]))


@pytest.mark.parametrize("stock_name", sorted(STOCKS))
@pytest.mark.parametrize("ratio", RATIOS)
def test_each_ratio_on_a_fixed_pass(stock_name, ratio):
    tool = Tool(10.0, 2, 12.0, corner_radius=5.0 * ratio)
    toolpath = fixed_pass()
    engagement = engage_stock(STOCKS[stock_name][0], tool, toolpath, PHI)
    assert engagement.engaged.sum() > 20  # the pass cuts
    assert mismatches(engagement, stock_name, tool, toolpath) == []
    assert (engagement.end_length[engagement.engaged] >= 0.0).all()
    corner = engagement.case_names()[engagement.engaged]
    assert set(corner) <= ({"corner"} if ratio else set(CASES) - {"corner"})


def test_a_flute_shorter_than_the_corner():
    tool = Tool(10.0, 2, 1.5, corner_radius=4.0)
    toolpath = fixed_pass()
    engagement = engage_stock(TERRACED, tool, toolpath, PHI)
    assert mismatches(engagement, "terraced", tool, toolpath) == []
    assert np.nanmax(engagement.uep_l) <= 1.5 + 1e-12


@pytest.mark.parametrize("plant", ["centre", "sweep"])
def test_a_planted_error_in_the_corner_is_caught(monkeypatch, plant):
    """The comparison fails when the corner's centre moves by 0.01 mm or its arc turns the wrong way."""
    tool = Tool(10.0, 2, 12.0, corner_radius=2.0)
    toolpath = fixed_pass()
    original = profile.corner_intervals

    def planted(stock, centre, d, w, radius, psi_max, pieces=None):
        if plant == "centre":
            return original(stock, centre + 0.01 * w, d, w, radius, psi_max, pieces)
        return original(stock, centre, -d, w, radius, psi_max, pieces)

    assert mismatches(engage_stock(TERRACED, tool, toolpath, PHI), "terraced", tool, toolpath) == []
    monkeypatch.setattr(profile, "corner_intervals", planted)
    assert mismatches(engage_stock(TERRACED, tool, toolpath, PHI), "terraced", tool, toolpath) != []


def test_area_integrates_the_chip_along_the_corner():
    """area = f·sin φ·cos(inclination)·∫ sin κ ds over the engaged edge, κ = ψ on the corner and 90° on the
    side: Σ over the reference's runs of the height at its end less the height at its start."""
    tool = Tool(10.0, 2, 12.0, corner_radius=3.0)
    toolpath = fixed_pass()
    engagement = engage_stock(TERRACED, tool, toolpath, PHI)
    _, inside, levels = STOCKS["terraced"]
    for i in range(len(toolpath)):
        for k, phi in enumerate(PHI.phi):
            want = ref.reference_instant(inside, levels, toolpath.cl[i], toolpath.theta_a[i], toolpath.theta_b[i],
                                         toolpath.alpha[i], phi, 5.0, 3.0, 12.0)
            axial = sum(ref.height(b, 5.0, 3.0, 12.0) - ref.height(a, 5.0, 3.0, 12.0) for a, b in want["runs"])
            chip = max(0.1 * np.sin(np.radians(phi)), 0.0)
            assert engagement.area[i, k] == pytest.approx(chip * axial, abs=1e-9)


@pytest.mark.parametrize("axis", [(0.0, 0.0, -1.0), (1.0, 0.0, 0.0), (0.3, -0.8, -0.5), (0.0, 1.0, 1e-300)])
def test_every_axis_direction_has_angles(axis):
    axes = np.array([axis])
    theta_a, theta_b = axis_to_angles(axes)
    assert -180.0 <= theta_a[0] <= 180.0 and -90.0 <= theta_b[0] <= 90.0
    np.testing.assert_allclose(angles_to_axis(theta_a, theta_b)[0], axes[0] / np.linalg.norm(axes[0]), atol=1e-15)


def test_the_readers_take_a_tool_pointing_down(tmp_path):
    from abm_workbench.formats.cl import read_program
    from abm_workbench.formats.toolpath_csv import load_toolpath

    csv = tmp_path / "down.csv"
    csv.write_text("x,y,z,i,j,k\n0,0,10,0,0,-1\n5,0,10,1,0,0\n")
    toolpath = load_toolpath(csv)
    np.testing.assert_allclose(toolpath.axes, [[0, 0, -1], [1, 0, 0]], atol=1e-15)
    apt = tmp_path / "down.apt"
    apt.write_text("CUTTER/10\nTLAXIS/0,0,-1\nGOTO/0,0,10\nGOTO/5,0,10\nGOTO/10,0,10\n")
    program = read_program(str(apt))
    np.testing.assert_allclose(program.operations[0].axes_part, [[0, 0, -1]] * 3, atol=1e-15)
