"""Helical cutting edges (engine/helix.py) against independent references.

- β = 0: every flute equals the straight engine (engage) at φ + 360k/Z, to 1e-9 mm, on both
  model tests and on random staircases.
- β ≠ 0: the brute-force sampler of the exact helix (reference.reference_helix_sweep) on
  random staircases, tilts, helix angles, flute counts, with and without an immersion range.
- Hand cases with closed-form answers: a vertical tool in flat stock, a helix crossing a top
  plane at a chosen height, two roots 10^-4 mm apart, the area integral against quadrature,
  B-spline walls against their quintic twins.
"""

import os

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from scipy.integrate import quad
from scipy.optimize import brentq

from abm_workbench.engine import CASES, SURFACES, CutSettings, Staircase, Tool, Toolpath, engage, flute_engagement
from abm_workbench.jobs import load_job, load_path, load_stock

from .reference import StairData, helix_points, reference_helix_sweep
from .strategies import Job, engine_stock, jobs, staircases
from .test_spline_walls import bezier_twin, quintic_stock, random_path

STRAIGHT_TOL = 1e-9  # mm, β = 0 against the straight engine
TOL = 1e-6           # mm, against the brute-force sampler (its crossings are bisected to 1e-13)
MODELS = os.path.join(os.path.dirname(__file__), "..", "..", "resources", "models")


def _model(number):
    folder = os.path.join(MODELS, f"model_test_{number}")
    stock = load_stock(os.path.join(folder, "stock.json")).staircase
    path, _ = load_path(os.path.join(folder, "toolpath.csv"))
    job = load_job(os.path.join(folder, "job.json"))
    settings_ = CutSettings(job["feed_per_tooth"], job["inclination"], job["phi_start"], job["phi_end"], job["phi_step"])
    return stock, path, job, settings_


def assert_equals_straight(stock, path, diameter, flute_length, flutes, cut):
    """flute_engagement with β = 0 against engage at φ + 360k/Z for every flute k."""
    helical = flute_engagement(stock, Tool(diameter, flutes, flute_length, helix=0.0), path, cut)
    for k in range(flutes):
        shifted = CutSettings(cut.feed_per_tooth, cut.inclination, cut.phi_start + 360.0 * k / flutes,
                              cut.phi_end + 360.0 * k / flutes, cut.phi_step)
        straight = engage(stock, Tool(diameter, flutes, flute_length), path, shifted)
        for got, want in ((helical.lep_l[..., k], straight.lep_l), (helical.uep_l[..., k], straight.uep_l),
                          (helical.axial_length[..., k], straight.length),
                          (helical.lep_xyz[..., k, :], straight.lep_xyz), (helical.uep_xyz[..., k, :], straight.uep_xyz)):
            np.testing.assert_allclose(got, want, atol=STRAIGHT_TOL, rtol=0)
        np.testing.assert_array_equal(helical.pieces[..., k], straight.pieces)
    return helical


@pytest.mark.parametrize("number, flutes", [(1, 2), (1, 3), (2, 2), (2, 4)])
def test_straight_helix_equals_engine_on_model_tests(number, flutes):
    stock, path, job, cut = _model(number)
    helical = assert_equals_straight(stock, path, job["diameter"], job["flute_length"], flutes, cut)
    assert (helical.axial_length > 0).sum() > 1000
    as_straight = helical.as_engagement(0)
    straight = engage(stock, Tool(job["diameter"], flutes, job["flute_length"]), path, cut)
    np.testing.assert_array_equal(as_straight.uep_surface, straight.uep_surface)
    np.testing.assert_array_equal(as_straight.case, straight.case)
    np.testing.assert_array_equal(as_straight.segment, straight.segment)
    np.testing.assert_allclose(as_straight.area, straight.area, atol=1e-12, rtol=1e-9)
    np.testing.assert_allclose(as_straight.depth_of_cut, straight.depth_of_cut, atol=STRAIGHT_TOL, rtol=0)


@settings(max_examples=60, deadline=None)
@given(jobs(), st.integers(1, 4))
def test_straight_helix_equals_engine_on_random_staircases(job, flutes):
    cut = CutSettings(0.1, phi_start=job.phi_start, phi_end=job.phi_end, phi_step=job.phi_step)
    assert_equals_straight(engine_stock(job.stock), Toolpath(job.cl, job.theta_a, job.theta_b), job.diameter,
                           job.flute_length, flutes, cut)


def _immersions():
    """None or (start, end) deg; the offset keeps the ends off the round φ values drawn for the
    flutes (an edge starting exactly on an immersion end is a tie that rounding decides)."""
    width = st.floats(10.0, 350.0)
    offset = np.sqrt(2.0) / 10.0
    return st.one_of(st.none(), st.tuples(st.floats(-180.0, 180.0), width).map(
        lambda t: (t[0] + offset, t[0] + offset + t[1])))


def _helix_angles():
    """β in (−60°, 60°): exactly 0, or at least 0.5° either way (tinier angles only turn the
    edge by rounding errors, which makes ties at the immersion ends)."""
    size = st.floats(0.5, 59.9)
    return st.one_of(st.just(0.0), size, size.map(lambda b: -b))


def _close(a, b):
    return (np.isnan(a) and np.isnan(b)) or abs(a - b) <= TOL


def assert_agrees_with_reference(job, helix, flutes, immersion):
    """Every interval, LEP, UEP, length and point of every flute against the sampled helix."""
    stock = engine_stock(job.stock)
    tool = Tool(job.diameter, flutes, job.flute_length, helix=helix)
    cut = CutSettings(0.1, phi_start=job.phi_start, phi_end=job.phi_end, phi_step=job.phi_step)
    result = flute_engagement(stock, tool, Toolpath(job.cl, job.theta_a, job.theta_b), cut, immersion=immersion)
    problems = []
    for i in range(len(job.cl)):
        psi0 = (result.phi[:, None] + 360.0 * np.arange(flutes) / flutes).reshape(-1)
        refs = reference_helix_sweep(job.stock, job.diameter / 2, job.flute_length, job.cl[i], job.theta_a[i],
                                     job.theta_b[i], psi0, helix, immersion)
        for index, ref in enumerate(refs):
            k, f = divmod(index, flutes)
            got = [(a, b) for a, b in zip(result.start[i, k, f], result.end[i, k, f]) if not np.isnan(a)]
            where = f"CL {i} φ {result.phi[k]!r} flute {f} β {helix!r} immersion {immersion}"
            if len(got) != len(ref.pieces) or not all(_close(a, c) and _close(b, d)
                                                      for (a, b), (c, d) in zip(got, ref.pieces)):
                problems.append(f"{where}: intervals {got}, reference {ref.pieces}")
            for name, value, want in (("lep_l", result.lep_l[i, k, f], ref.lep), ("uep_l", result.uep_l[i, k, f], ref.uep),
                                      ("axial_length", result.axial_length[i, k, f], ref.length)):
                if not _close(value, want):
                    problems.append(f"{where}: {name} {value!r}, reference {want!r}")
            for name, value, want in (("lep_xyz", result.lep_xyz[i, k, f], ref.lep_xyz),
                                      ("uep_xyz", result.uep_xyz[i, k, f], ref.uep_xyz)):
                if not all(_close(a, b) for a, b in zip(value, want)):
                    problems.append(f"{where}: {name} {value}, reference {want}")
    assert not problems, "\n".join(problems[:10])
    return result


#: A case once found: the immersion range splits a flute's interval so that the later window
#: comes first in ψ order; the intervals must still come out sorted along l.
_SPLIT_BY_IMMERSION = Job(StairData(0.0, 8.0, 0.0, 10.0, 0.0, (2.0, 2.0), (tuple((3.0 + 0.2 * y, y) for y in (0, 2, 4, 6, 8, 10)),)),
                          4.0, 5.026457513110646, np.array([[4.01414214, 0.01732051, 0.02236068]]), np.zeros(1),
                          np.zeros(1), 0.0, 180.0, 30.0)


@settings(max_examples=40, deadline=None)
@given(jobs(max_points=2), _helix_angles(), st.integers(1, 4), _immersions())
@example(_SPLIT_BY_IMMERSION, 53.0, 1, (np.sqrt(2.0) / 10.0, 315.0 + np.sqrt(2.0) / 10.0))
def test_random_helices_agree_with_the_sampled_helix(job, helix, flutes, immersion):
    assert_agrees_with_reference(job, helix, flutes, immersion)


@settings(max_examples=25, deadline=None)
@given(jobs(stocks=staircases(min_sections=2, curved=True), max_points=2), _helix_angles(), st.integers(2, 4),
       _immersions())
def test_random_helices_on_curved_walls_agree_with_the_sampled_helix(job, helix, flutes, immersion):
    assert_agrees_with_reference(job, helix, flutes, immersion)


def _flat_stock(top=20.0):
    return StairData(-50.0, 50.0, -50.0, 50.0, -10.0, (top,), ())


@pytest.mark.parametrize("helix", [-55.0, -30.0, 0.0, 15.0, 45.0])
def test_vertical_tool_in_flat_stock_cuts_up_to_the_top(helix):
    """A vertical tool with its tip 7.5 mm below a flat top: every flute is in from 0 to 7.5 mm."""
    stock = engine_stock(_flat_stock())
    path = Toolpath([[0.0, 0.0, 12.5]], [0.0], [0.0])
    result = flute_engagement(stock, Tool(10, 4, 30, helix=helix), path, CutSettings(0.1, 0, 0, 350, 10))
    np.testing.assert_allclose(result.axial_length, 7.5, atol=1e-12)
    np.testing.assert_allclose(result.edge_length, 7.5 / np.cos(np.radians(helix)), atol=1e-12)
    np.testing.assert_allclose(result.lep_l, 0.0, atol=0)
    assert set(np.asarray(SURFACES)[result.uep_surface].ravel()) == {"top"}
    np.testing.assert_allclose(result.uep_xyz[..., 2], 20.0, atol=1e-12)


def test_immersion_keeps_the_half_turn_in_range():
    """β chosen so the edge turns 180° over the 10 mm in cut: starting at ψ = 90°, the part with
    ψ in [0°, 180°] is l in [0, 5]; starting at 270°, [5, 10]; 0° and 180° keep all of it
    (ψ runs over [−180°, 0°] touching 0 and over [0°, 180°])."""
    radius, height = 5.0, 10.0
    helix = np.degrees(np.arctan(np.pi * radius / height))
    stock = engine_stock(_flat_stock())
    path = Toolpath([[0.0, 0.0, 20.0 - height]], [0.0], [0.0])
    result = flute_engagement(stock, Tool(2 * radius, 2, 30, helix=helix), path, CutSettings(0.1, 0, 0, 90, 90),
                              immersion=(0.0, 180.0))
    # flutes at 0°, 180° (φ = 0) and 90°, 270° (φ = 90)
    np.testing.assert_allclose(result.start[0, 1, :, 0], [0.0, height / 2], atol=1e-12)
    np.testing.assert_allclose(result.end[0, 1, :, 0], [height / 2, height], atol=1e-12)
    np.testing.assert_allclose(result.axial_length[0, 0], [0.0, height], atol=1e-12)
    assert SURFACES[result.uep_surface[0, 1, 0]] == "immersion_end"
    assert SURFACES[result.uep_surface[0, 1, 1]] == "top"


def test_helix_crossing_a_top_plane_at_a_chosen_height():
    """A tilted helical edge rising through z = z(l*) leaves the stock exactly at l*."""
    cl, ta, tb, radius, helix, psi0, chosen = [3.0, -2.0, 1.0], 12.0, -20.0, 6.0, 35.0, 40.0, 7.3
    z = helix_points(radius, cl, ta, tb, [psi0], helix, [[chosen]])[0, 0, 2]
    stock = engine_stock(StairData(-60.0, 60.0, -60.0, 60.0, -30.0, (float(z),), ()))
    result = flute_engagement(stock, Tool(2 * radius, 1, 25, helix=helix), Toolpath([cl], [ta], [tb]),
                              CutSettings(0.1, 0, psi0, psi0, 1))
    assert result.pieces[0, 0, 0] == 1
    assert abs(result.uep_l[0, 0, 0] - chosen) <= 1e-10
    assert result.lep_l[0, 0, 0] == 0.0
    np.testing.assert_allclose(result.uep_xyz[0, 0, 0], helix_points(radius, cl, ta, tb, [psi0], helix, [[chosen]])[0, 0],
                               atol=1e-10)


def test_two_roots_closer_than_any_sampling_step_are_both_found():
    """A steep helix on a tilted tool: z(l) has a local maximum; a top 10^-9 mm below it cuts
    the edge twice, about 10^-4 mm apart. Both crossings and the gap between them are found."""
    cl, ta, tb, radius, helix, psi0 = [0.0, 0.0, 0.0], 40.0, 0.0, 5.0, 60.0, 0.0

    def z(l):
        return helix_points(radius, cl, ta, tb, [psi0], helix, [[l]])[0, 0, 2]

    grid = np.linspace(0.0, 20.0, 20001)
    values = helix_points(radius, cl, ta, tb, [psi0], helix, [grid])[0, :, 2]
    peaks = np.flatnonzero((values[1:-1] > values[:-2]) & (values[1:-1] > values[2:])) + 1
    assert peaks.size, "the chosen helix must have a local maximum of z"
    from scipy.optimize import minimize_scalar
    peak = minimize_scalar(lambda l: -z(l), bracket=(grid[peaks[0] - 1], grid[peaks[0]], grid[peaks[0] + 1]),
                           tol=1e-14).x
    top = z(peak) - 1e-9
    first, second = brentq(lambda l: z(l) - top, 0.0, peak, xtol=1e-14), brentq(lambda l: z(l) - top, peak, grid[peaks[0] + 1000], xtol=1e-14)
    assert 0 < second - first < 1e-3
    stock = engine_stock(StairData(-60.0, 60.0, -60.0, 60.0, -30.0, (float(top),), ()))
    result = flute_engagement(stock, Tool(2 * radius, 1, 20, helix=helix), Toolpath([cl], [ta], [tb]),
                              CutSettings(0.1, 0, psi0, psi0, 1))
    pieces = [(a, b) for a, b in zip(result.start[0, 0, 0], result.end[0, 0, 0]) if not np.isnan(a)]
    ends = [b for _, b in pieces]
    starts = [a for a, _ in pieces]
    assert any(abs(e - first) <= 1e-9 for e in ends) and any(abs(s - second) <= 1e-9 for s in starts), pieces


@pytest.mark.parametrize("helix, immersion", [(0.0, None), (30.0, None), (-50.0, (20.0, 200.0)), (1e-7, None)])
def test_area_is_the_integral_of_the_thickness(helix, immersion):
    """area() against adaptive quadrature of thickness_at over each interval."""
    stock = quintic_stock()
    rng = np.random.default_rng(3)
    path = random_path(rng, 4)
    result = flute_engagement(stock, Tool(12, 3, 25, helix=helix), path, CutSettings(0.12, 8, 0, 350, 25),
                              immersion=immersion)
    area = result.area()
    assert (area > 0).sum() > 10
    for index in np.ndindex(*result.shape):
        i, k, f = index
        want = 0.0
        for a, b in zip(result.start[index], result.end[index]):
            if not np.isnan(a):
                want += quad(lambda l: result.thickness_at(l, f)[i, k], a, b, epsabs=1e-14, epsrel=1e-13, limit=200)[0]
        assert abs(area[index] - want) <= 1e-10, (index, area[index], want)


def test_bezier_twin_walls_give_the_same_helical_engagement():
    """B-spline walls (the quintics written as Bézier curves) against the quintic walls, β = 40°."""
    stock = quintic_stock()
    twin = Staircase(stock.x_min, stock.x_max, stock.y_min, stock.y_max, stock.base_z, stock.z_top,
                     stock.wall_points, tuple(bezier_twin(w, -15, 15) for w in stock.walls))
    rng = np.random.default_rng(11)
    path, tool, cut = random_path(rng, 20), Tool(12, 3, 25, helix=40.0), CutSettings(0.1, 10, 0, 180, 6)
    a, b = flute_engagement(stock, tool, path, cut), flute_engagement(twin, tool, path, cut)
    assert (a.axial_length > 0).sum() > 300
    for name in ("lep_l", "uep_l", "axial_length"):
        np.testing.assert_allclose(getattr(b, name), getattr(a, name), atol=1e-9, rtol=0)
    np.testing.assert_allclose(b.start, a.start, atol=1e-9, rtol=0)


def test_helical_as_engagement_is_a_flute_view():
    stock = quintic_stock()
    path = random_path(np.random.default_rng(5), 6)
    result = flute_engagement(stock, Tool(12, 2, 25, helix=30.0), path, CutSettings(0.1, 10, 0, 180, 10))
    view = result.as_engagement(1)
    np.testing.assert_array_equal(view.length, result.axial_length[:, :, 1])
    np.testing.assert_array_equal(view.uep_surface, result.uep_surface[:, :, 1])
    assert set(np.asarray(CASES)[view.case].ravel()) == {"none"}
    np.testing.assert_allclose(view.h, result.thickness_at(0.0, 1))
    np.testing.assert_allclose(view.area, result.area()[:, :, 1])
    assert (view.segment >= 0).sum() == view.engaged.sum()


def test_progress_is_reported_per_chunk():
    stock = quintic_stock()
    path = random_path(np.random.default_rng(2), 10)
    calls = []
    flute_engagement(stock, Tool(12, 2, 25, helix=20.0), path, CutSettings(0.1, 0, 0, 180, 10),
                     chunk_instants=100, progress=lambda done, total: calls.append((done, total)))
    assert calls[-1] == (10, 10) and len(calls) > 1


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match="helix must be within"):
        Tool(10, 2, 20, helix=90.0)
    with pytest.raises(ValueError, match="helix must be a finite number"):
        Tool(10, 2, 20, helix=float("nan"))
    stock, path = quintic_stock(), random_path(np.random.default_rng(1), 2)
    with pytest.raises(ValueError, match="use flute_engagement"):
        engage(stock, Tool(12, 2, 25, helix=10.0), path, CutSettings(0.1))
    with pytest.raises(ValueError, match="immersion"):
        flute_engagement(stock, Tool(12, 2, 25, helix=10.0), path, CutSettings(0.1), immersion=(90.0, 10.0))
    with pytest.raises(ValueError, match="immersion"):
        flute_engagement(stock, Tool(12, 2, 25, helix=10.0), path, CutSettings(0.1), immersion="0:180")
    result = flute_engagement(stock, Tool(12, 2, 25, helix=10.0), path, CutSettings(0.1))
    with pytest.raises(ValueError, match="flute must be in 0..1"):
        result.as_engagement(2)
    assert Tool(10, 2, 20).helix == 0.0


@pytest.mark.parametrize("bend", [0.0, 0.004])
def test_a_wall_grazed_by_the_helix_leaves_a_gap_of_the_right_length(bend):
    """A vertical tool whose helix (β = 45°) grazes wall x = x_w + bend·y², 10^-8 mm beyond it at
    the closest approach: past the wall lies a section too low to cut, so the flute's cut
    has a gap between the two crossings (about 10^-3 mm apart). The crossings come from
    scipy's brentq on either side of the grazing point found by minimize_scalar."""
    from scipy.optimize import minimize_scalar
    radius, helix, psi0, cl = 5.0, 45.0, 150.0, np.array([0.0, 0.0, 0.0])
    kappa = np.tan(np.radians(helix)) / radius

    def point(l):
        psi = np.radians(psi0) - kappa * l
        return cl + np.array([radius * np.sin(psi), radius * np.cos(psi), l])

    def beyond(l, x_w):  # x − W(y) along the helix
        x, y, _ = point(l)
        return x - (x_w + bend * y * y)

    apex = minimize_scalar(lambda l: -beyond(l, 0.0), bounds=(0.0, 2.0 * np.pi / kappa), method="bounded",
                           options={"xatol": 1e-12}).x
    x_w = beyond(apex, 0.0) - 1e-8
    first = brentq(lambda l: beyond(l, x_w), apex - 0.05, apex, xtol=1e-15)
    second = brentq(lambda l: beyond(l, x_w), apex, apex + 0.05, xtol=1e-15)
    assert 1e-4 < second - first < 1e-2
    ys = np.linspace(-20.0, 20.0, 6)
    stock = Staircase(-30.0, 30.0, -20.0, 20.0, -5.0, [25.0, -4.0], [[[x_w + bend * y * y, y] for y in ys]])
    result = flute_engagement(stock, Tool(2 * radius, 1, 20, helix=helix), Toolpath([cl], [0.0], [0.0]),
                              CutSettings(0.1, 0, psi0, psi0, 1))
    pieces = [(a, b) for a, b in zip(result.start[0, 0, 0], result.end[0, 0, 0]) if not np.isnan(a)]
    gaps = [(b0, a1) for (_, b0), (a1, _) in zip(pieces, pieces[1:])]
    assert any(abs(g0 - first) <= 1e-9 and abs(g1 - second) <= 1e-9 for g0, g1 in gaps), (pieces, first, second)
    assert abs(result.axial_length[0, 0, 0] - (20.0 - (second - first))) <= 1e-9
