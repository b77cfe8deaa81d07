"""Cutting forces of bull-nose and ball-end mills along their whole peripheral edge (forces.profile_forces).

- Closed forms derived by hand for upright tools in a flat block (a ball, a bull-nose, a run that starts
  above the tip and one that goes on up the side): every component and the torque within 1e-9 relative.
- An independent quadrature: Gauss–Legendre over the arc length along the engaged runs that the brute-force
  reference (profile_reference) finds, each element's force built from the geometry here (normal, chip,
  width dz / sin κ, the axial direction as e × n, the torque as w·(P − T) × dF): tilted tools turned to any
  feed on a staircase and a terraced stock, r/R in {0.1, 0.3, 0.5, 1}, two and three flutes, full and
  partial immersion, per-CL inclinations.
- A planted error (κ taken as 90° on the corner) fails both.
- r → 0: the forces tend to the flat-end mill's linearly in r; at r = 0 the profile form is the flat-end form.
- The API: pass_forces on both stocks and through the job runner's call, runs_at, its errors, chunks; the
  cut area is the engine's; a schedule of a ball-end mill keeps its limit.
"""

import os

import numpy as np
import pytest

from abm_workbench import forces as forces_module
from abm_workbench.engine import CutSettings, Staircase, Tool, Toolpath
from abm_workbench.engine.profile import profile_intervals
from abm_workbench.engine.stocks import engage_stock
from abm_workbench.formats.staircase_json import load_staircase
from abm_workbench.formats.toolpath_csv import load_toolpath
from abm_workbench.forces import (Coefficients, edge_forces, flute_lengths, flute_runs, material, pass_forces,
                                  profile_forces)
from abm_workbench.jobs.run import pass_forces_of
from abm_workbench.scheduling import schedule
from tests.conftest import ROOT

from . import profile_reference as ref
from .test_tool_profiles import STOCKS, fixed_pass

K = Coefficients(ktc=700.0, krc=210.0, kac=120.0, kte=25.0, kre=30.0, kae=4.0)
CLOSED_RTOL = 1e-9
#: Gauss–Legendre nodes per sub-interval and sub-intervals per piece (corner or side) of a run.
GAUSS_NODES, GAUSS_PIECES = 24, 8
RATIOS = (0.1, 0.3, 0.5, 1.0)
#: Flute 1's angles: off the immersion limits 0, 30, 150, 180 for every flute of 2 or 3.
PHI = CutSettings(0.1, phi_start=7.5, phi_end=352.5, phi_step=15.0)


def _block(top, base=-5.0):
    """A flat staircase one section high, base to top (mm)."""
    return Staircase(-60.0, 60.0, -60.0, 60.0, base, [top], [])


# --- (a) closed forms by hand --------------------------------------------------------------------------------

def _hand_upright(big, r, psi0, psi1, side, phi_deg, feed):
    """(force on the tool (3,) N, torque N·mm) of one flute at phi_deg of an upright tool (u = x, v = y,
    w = z) whose corner is engaged for ψ in [psi0, psi1] (rad) and whose side is engaged over `side` mm
    (κ = 90°), chip h = f sin φ sin κ, width db = dz / sin κ = r dψ, radius of an element R − r + r sin ψ.

    Antiderivatives: ∫ sin = −cos, ∫ cos = sin, ∫ sin² = ψ/2 − sin 2ψ / 4, ∫ sin cos = sin² / 2.
    Force on the tool: −dF_t·e − dF_r·n + dF_a·a, e = (cos φ, −sin φ, 0), n = sin ψ·d − cos ψ·w,
    a = cos ψ·d + sin ψ·w, d = (sin φ, cos φ, 0).
    """
    ph = np.radians(phi_deg)
    c = feed * np.sin(ph)
    one = psi1 - psi0
    sin_ = np.cos(psi0) - np.cos(psi1)
    cos_ = np.sin(psi1) - np.sin(psi0)
    sin2 = (psi1 / 2 - np.sin(2 * psi1) / 4) - (psi0 / 2 - np.sin(2 * psi0) / 4)
    sincos = (np.sin(psi1) ** 2 - np.sin(psi0) ** 2) / 2
    # Corner, each integral times r (ds = r dψ); the side: κ = 90°, n = d, a = w.
    tangential = r * (K.ktc * c * sin_ + K.kte * one) + (K.ktc * c + K.kte) * side
    radial_d = r * (-(K.krc * c * sin2 + K.kre * sin_)) - (K.krc * c + K.kre) * side   # −F_r n, d part
    radial_w = r * (K.krc * c * sincos + K.kre * cos_)                                  # −F_r n, w part
    axial_d = r * (K.kac * c * sincos + K.kae * cos_)
    axial_w = r * (K.kac * c * sin2 + K.kae * sin_) + (K.kac * c + K.kae) * side
    e = np.array([np.cos(ph), -np.sin(ph), 0.0])
    d = np.array([np.sin(ph), np.cos(ph), 0.0])
    w = np.array([0.0, 0.0, 1.0])
    force = -tangential * e + (radial_d + axial_d) * d + (radial_w + axial_w) * w
    # ∫ ρ dF_t, ρ = R − r + r sin ψ on the corner, R on the side.
    torque = (r * ((big - r) * (K.ktc * c * sin_ + K.kte * one) + r * (K.ktc * c * sin2 + K.kte * sin_))
              + big * (K.ktc * c + K.kte) * side)
    return force, torque


@pytest.mark.parametrize("big, r, tip_z, top, length", [
    (5.0, 5.0, 0.0, 2.0, 20.0),     # ball, corner engaged from the tip up to ψ = acos(1 − 2/5)
    (5.0, 5.0, -6.0, 2.0, 20.0),    # ball one mm below the block: ψ from acos(1 − 1/5) to 90°, then 3 mm of side
    (6.0, 2.0, 0.0, 1.2, 20.0),     # bull-nose, corner only
    (6.0, 2.0, -5.5, 3.0, 20.0),    # bull-nose: ψ from acos(1 − 0.5/2) to 90°, then 6.5 mm of side
    (5.0, 5.0, 0.0, 9.0, 3.0),      # a ball whose flute ends on its corner: ψ up to acos(1 − 3/5)
])
@pytest.mark.parametrize("flutes", [1, 3])
def test_upright_tools_in_a_block_match_the_hand_closed_form(big, r, tip_z, top, length, flutes):
    feed, base = 0.12, -5.0
    tool = Tool(2 * big, flutes, length, corner_radius=r)
    path = Toolpath([[0.0, 0.0, tip_z]], [0.0], [0.0])
    settings = CutSettings(feed, 0.0, 10.0, 350.0, 20.0, spindle_rpm=5000.0)
    got = pass_forces(_block(top, base), tool, path, settings, K)
    low, high = max(base - tip_z, 0.0), min(top - tip_z, length)     # engaged heights above the tip
    psi0 = np.arccos(1.0 - min(low, r) / r)
    psi1 = np.arccos(1.0 - min(high, r) / r)
    side = max(high - max(low, r), 0.0)
    for j, phi in enumerate(settings.phi):
        want, torque = np.zeros(3), 0.0
        for k in range(flutes):
            angle = phi + 360.0 * k / flutes
            if np.mod(angle, 360.0) < 180.0:                         # the default immersion 0:180
                force, moment = _hand_upright(big, r, psi0, psi1, side, angle, feed)
                want, torque = want + force, torque + moment
        scale = max(np.abs(want).max(), 1.0)
        assert np.abs(got.xyz[0, j] - want).max() <= CLOSED_RTOL * scale, (phi, got.xyz[0, j], want)
        assert got.torque[0, j] == pytest.approx(torque, rel=CLOSED_RTOL, abs=CLOSED_RTOL)
    np.testing.assert_allclose(got.power, got.torque * 1e-3 * 2 * np.pi * 5000.0 / 60.0, rtol=1e-14)


# --- (b) an independent quadrature along the reference's runs -----------------------------------------------

def _reference_runs(stock_name, toolpath, i, phi, big, r, length):
    """The brute-force reference's engaged runs [(s0, s1)] of the edge at angle phi of CL point i."""
    _, inside, levels = STOCKS[stock_name]
    rot = ref.frame(toolpath.theta_a[i], toolpath.theta_b[i], toolpath.alpha[i])
    ph = np.radians(phi)
    d = np.sin(ph) * rot[:, 0] + np.cos(ph) * rot[:, 1]
    tip, span = toolpath.cl[i], ref.edge_span(big, r, length)

    def point_at(s):
        return ref.profile_points(s, tip, d, rot[:, 2], big, r, length)

    return ref.curve_runs(inside, point_at, span, ref.level_hits(levels, tip[2], lambda s: point_at(s)[:, 2], span))


def _gauss(a, b):
    """(nodes, weights) of GAUSS_PIECES × GAUSS_NODES-point Gauss–Legendre on [a, b]."""
    x, wt = np.polynomial.legendre.leggauss(GAUSS_NODES)
    edges = np.linspace(a, b, GAUSS_PIECES + 1)
    half = 0.5 * np.diff(edges)
    nodes = (0.5 * (edges[:-1] + edges[1:]))[:, None] + half[:, None] * x[None, :]
    return nodes.reshape(-1), (half[:, None] * wt[None, :]).reshape(-1)


def _element_sum(runs, tip, rot, phi, big, r, length, feed, inclination):
    """(force on the tool (3,) N, torque about the axis N·mm) of one flute at phi over `runs`, by quadrature.

    Each element at arc length s: point P and unit tangent t along the edge, outward normal n (t turned
    by −90° in the plane of d and w), sin κ = n·d, cos κ = −n·w; chip h = f sin φ sin κ cos(inclination);
    width db = dz / sin κ with dz = t·w ds; edge length ds. Force on the tool −dF_t·e − dF_r·n + dF_a·a,
    e = ∂d/∂φ, a = e × n; torque w·((P − T) × dF).
    """
    u, v, w = rot[:, 0], rot[:, 1], rot[:, 2]
    ph = np.radians(phi)
    d, e = np.sin(ph) * u + np.cos(ph) * v, np.cos(ph) * u - np.sin(ph) * v
    top = ref.corner_end(big, r, length)
    force, torque = np.zeros(3), 0.0
    for a, b in runs:
        pieces = [(a, min(b, r * top)), (max(a, r * top), b)]      # the corner and the side: smooth on each
        for lo, hi in pieces:
            if hi <= lo:
                continue
            s, weight = _gauss(lo, hi)
            psi = np.where(s <= r * top, s / max(r, 1e-300), 0.5 * np.pi)
            tangent = np.cos(psi)[:, None] * d + np.sin(psi)[:, None] * w
            normal = np.sin(psi)[:, None] * d - np.cos(psi)[:, None] * w
            sin_k, cos_k = normal @ d, -(normal @ w)
            h = feed * np.sin(ph) * sin_k * np.cos(np.radians(inclination))
            db = (tangent @ w) / sin_k                                # per unit ds
            dft = K.ktc * h * db + K.kte
            dfr = K.krc * h * db + K.kre
            dfa = K.kac * h * db + K.kae
            axial = np.cross(e, normal)
            df = -dft[:, None] * e - dfr[:, None] * normal + dfa[:, None] * axial
            force = force + weight @ df
            arm = ref.profile_points(s, np.zeros(3), d, w, big, r, length)
            torque = torque + weight @ (np.cross(arm, df) @ w)
    return force, torque


def _quadrature(stock_name, toolpath, big, r, length, flutes, phis, feed, inclination, immersion):
    """(m, p, 3) forces and (m, p) torques of the pass by _element_sum, summed over the flutes in the
    immersion (start ≤ φ_k mod 360 < end)."""
    m = len(toolpath)
    force, torque = np.zeros((m, len(phis), 3)), np.zeros((m, len(phis)))
    for i in range(m):
        rot = ref.frame(toolpath.theta_a[i], toolpath.theta_b[i], toolpath.alpha[i])
        for j, phi in enumerate(phis):
            for k in range(flutes):
                angle = phi + 360.0 * k / flutes
                if not immersion[0] <= np.mod(angle, 360.0) < immersion[1]:
                    continue
                runs = _reference_runs(stock_name, toolpath, i, angle, big, r, length)
                f, t = _element_sum(runs, toolpath.cl[i], rot, angle, big, r, length, feed, inclination[i])
                force[i, j] += f
                torque[i, j] += t
    return force, torque


def _tilted_pass():
    """fixed_pass with an inclination of its own at each CL point."""
    path = fixed_pass()
    return Toolpath(path.cl, path.theta_a, path.theta_b, alpha=path.alpha, inclination=np.array([0.0, 12.0, 25.0]))


#: Tolerance against the quadrature (N; ten times it for the torque in N·mm), on peaks of 1000–1200 N and
#: 4000–4900 N·mm: the reference's runs end within its bisection (1e-13 mm), the engine's within its
#: solvers' rounding; at most 3.6e-11 N and 1.7e-10 N·mm measured.
QUAD_ATOL = 1e-9


def _compare(stock_name, ratio, flutes, immersion):
    big, length, feed = 5.0, 12.0, 0.1
    tool = Tool(2 * big, flutes, length, corner_radius=big * ratio)
    toolpath = _tilted_pass()
    got = pass_forces(STOCKS[stock_name][0], tool, toolpath, PHI, K, immersion=immersion)
    want, torque = _quadrature(stock_name, toolpath, big, tool.corner_radius, length, flutes, PHI.phi, feed,
                               toolpath.inclination, immersion)
    return got, want, torque


@pytest.mark.parametrize("stock_name", sorted(STOCKS))
@pytest.mark.parametrize("ratio", RATIOS)
@pytest.mark.parametrize("flutes, immersion", [(2, (0.0, 180.0)), (3, (30.0, 150.0))])
def test_tilted_corner_tools_match_a_quadrature_along_the_reference_runs(stock_name, ratio, flutes, immersion):
    got, want, torque = _compare(stock_name, ratio, flutes, immersion)
    assert (np.linalg.norm(want, axis=-1) > 1.0).sum() > 10          # the pass cuts
    np.testing.assert_allclose(got.xyz, want, rtol=0.0, atol=QUAD_ATOL)
    np.testing.assert_allclose(got.torque, torque, rtol=0.0, atol=10.0 * QUAD_ATOL)


# --- (c) a planted error -------------------------------------------------------------------------------------

def _kappa_90(start, end, corner_radius):
    """The corner's integrals as if κ were 90° all along it."""
    width = np.where(np.isnan(start) | np.isnan(end), 0.0, end - start)
    return width, width, np.zeros_like(width), width, np.zeros_like(width)


def test_kappa_taken_as_90_degrees_on_the_corner_fails_both_checks(monkeypatch):
    monkeypatch.setattr(forces_module, "corner_integrals", _kappa_90)
    got, want, _ = _compare("terraced", 0.5, 2, (0.0, 180.0))
    assert np.abs(got.xyz - want).max() > 1e3 * QUAD_ATOL
    tool = Tool(10.0, 1, 20.0, corner_radius=5.0)
    upright = Toolpath([[0.0, 0.0, 0.0]], [0.0], [0.0])
    planted = pass_forces(_block(2.0), tool, upright, CutSettings(0.12, 0, 90, 90, 1), K)
    hand, _ = _hand_upright(5.0, 5.0, 0.0, np.arccos(1.0 - 2.0 / 5.0), 0.0, 90.0, 0.12)
    assert np.abs(planted.xyz[0, 0] - hand).max() > 1.0


# --- (d) r → 0 -----------------------------------------------------------------------------------------------

@pytest.mark.parametrize("stock_name", sorted(STOCKS))
def test_a_vanishing_corner_tends_to_the_flat_end_mill(stock_name):
    """The gap to the flat-end mill's forces is linear in r (its slope the same to 1e-6 from r = 10⁻² to
    10⁻⁶ mm; about 40 N per mm of r here), and at r = 10⁻⁶ mm below 10⁻⁷ of the force."""
    stock = STOCKS[stock_name][0]
    toolpath = _tilted_pass()
    flat = pass_forces(stock, Tool(10.0, 2, 12.0), toolpath, PHI, K)
    scale = np.abs(flat.xyz).max()
    assert scale > 100.0
    radii = np.array([1e-2, 1e-3, 1e-4, 1e-6])
    gaps, torques = [], []
    for r in radii:
        corner = pass_forces(stock, Tool(10.0, 2, 12.0, corner_radius=r), toolpath, PHI, K)
        gaps.append(np.abs(corner.xyz - flat.xyz).max())
        torques.append(np.abs(corner.torque - flat.torque).max())
    slopes = np.array(gaps) / radii
    assert 1.0 < slopes[0] < 1e3
    np.testing.assert_allclose(slopes, slopes[0], rtol=1e-6)
    assert (np.array(torques) <= 100.0 * radii * scale / 5.0).all()
    assert gaps[-1] < 1e-7 * scale


@pytest.mark.parametrize("stock_name", sorted(STOCKS))
def test_at_r_0_the_profile_form_is_the_flat_end_form(stock_name):
    stock, tool, toolpath = STOCKS[stock_name][0], Tool(10.0, 3, 12.0), _tilted_pass()
    runs = flute_runs(stock, tool, toolpath, PHI.phi)
    lengths = np.stack([found.length.reshape(len(toolpath), -1) for found in runs])
    args = (PHI.phi, toolpath.frames())
    profile = profile_forces(runs, *args, tool, toolpath.inclination, 0.1, K, immersion=(20.0, 170.0))
    flat = edge_forces(lengths, *args, tool.radius, toolpath.inclination, 0.1, K, immersion=(20.0, 170.0))
    scale = np.abs(flat.xyz).max()
    np.testing.assert_allclose(profile.xyz, flat.xyz, rtol=0.0, atol=1e-12 * scale)
    np.testing.assert_allclose(profile.torque, flat.torque, rtol=0.0, atol=1e-12 * scale * tool.radius)
    np.testing.assert_allclose(profile.area, flat.area, rtol=0.0, atol=1e-14)
    # … and the flat-end's own engine gives those lengths.
    np.testing.assert_allclose(lengths, flute_lengths(stock, tool, toolpath, PHI), rtol=0.0, atol=1e-9)


# --- the API ------------------------------------------------------------------------------------------------

def test_the_cut_area_is_the_engagement_area():
    """One flute: the forces' area is the engine's Engagement.area (h times the engaged extent along the
    axis) wherever the flute cuts."""
    stock, tool, toolpath = STOCKS["terraced"][0], Tool(10.0, 1, 12.0, corner_radius=3.0), _tilted_pass()
    got = pass_forces(stock, tool, toolpath, PHI, K)
    engagement = engage_stock(stock, tool, toolpath, PHI)
    cuts = np.mod(PHI.phi, 360.0) < 180.0
    np.testing.assert_allclose(got.area[:, cuts], engagement.area[:, cuts], rtol=0.0, atol=1e-12)
    assert (got.area[:, ~cuts] == 0.0).all()


def test_runs_at_supplies_the_runs():
    stock, tool, toolpath = STOCKS["staircase"][0], Tool(10.0, 2, 12.0, corner_radius=1.5), _tilted_pass()
    calls = []

    def runs_at(phi):
        calls.append(np.array(phi))
        return profile_intervals(stock, tool, toolpath, phi)

    given = pass_forces(stock, tool, toolpath, PHI, K, runs_at=runs_at)
    solved = pass_forces(stock, tool, toolpath, PHI, K, first=np.zeros((3, PHI.phi.size)))  # first: lengths, unused
    np.testing.assert_array_equal(given.xyz, solved.xyz)
    np.testing.assert_array_equal(calls[1], PHI.phi + 180.0)
    # A flat-end tool takes the runs' lengths: the same as its engine's lengths.
    flat = Tool(10.0, 2, 12.0)
    by_runs = pass_forces(stock, flat, toolpath, PHI, K,
                          runs_at=lambda phi: profile_intervals(stock, flat, toolpath, phi))
    np.testing.assert_allclose(by_runs.xyz, pass_forces(stock, flat, toolpath, PHI, K).xyz, rtol=0.0, atol=1e-9)


@pytest.mark.parametrize("stock_name", sorted(STOCKS))
def test_the_job_runner_s_call_takes_a_corner_tool(stock_name):
    """jobs.run.pass_forces_of passes flute 1's Engagement lengths as `first`: a tool with a corner solves its
    runs instead and gets pass_forces' forces."""
    stock, tool, toolpath = STOCKS[stock_name][0], Tool(10.0, 2, 12.0, corner_radius=2.5), _tilted_pass()
    engagement = engage_stock(stock, tool, toolpath, PHI)
    got = pass_forces_of(stock, tool, toolpath, PHI, (K, (0.0, 120.0)), engagement)
    np.testing.assert_array_equal(got.xyz, pass_forces(stock, tool, toolpath, PHI, K, immersion=(0.0, 120.0)).xyz)
    assert np.abs(got.xyz).max() > 100.0


def test_flute_runs_in_chunks_are_the_whole():
    stock, tool, toolpath = STOCKS["terraced"][0], Tool(10.0, 2, 12.0, corner_radius=2.0), _tilted_pass()
    whole = flute_runs(stock, tool, toolpath, PHI.phi)
    chunked = flute_runs(stock, tool, toolpath, PHI.phi, chunk_instants=PHI.phi.size)   # one CL point a chunk
    for a, b in zip(whole, chunked):
        np.testing.assert_array_equal(a.rows, b.rows)
        np.testing.assert_array_equal(a.start, b.start)
        np.testing.assert_array_equal(a.end, b.end)


def test_flute_lengths_accept_a_corner_tool():
    stock, tool, toolpath = STOCKS["terraced"][0], Tool(10.0, 2, 12.0, corner_radius=2.0), _tilted_pass()
    lengths = flute_lengths(stock, tool, toolpath, PHI)
    runs = flute_runs(stock, tool, toolpath, PHI.phi)
    np.testing.assert_allclose(lengths, np.stack([found.length.reshape(3, -1) for found in runs]), atol=1e-12)


def test_errors_name_what_is_wrong():
    stock, tool, toolpath = STOCKS["staircase"][0], Tool(10.0, 2, 12.0, corner_radius=1.5), _tilted_pass()
    with pytest.raises(ValueError, match="bull-nose mill need each flute's engaged runs along its corner"):
        pass_forces(stock, tool, toolpath, PHI, K, lengths_at=lambda shifted: np.zeros((3, PHI.phi.size)))
    with pytest.raises(ValueError, match=r"runs_at for flute 1 must have 72 rows \(CL points × angles\), got 3"):
        pass_forces(stock, tool, toolpath, PHI, K, runs_at=lambda phi: profile_intervals(stock, tool, toolpath, [0.0]))
    with pytest.raises(ValueError, match="runs_at for flute 1 must be EdgeIntervals"):
        pass_forces(stock, tool, toolpath, PHI, K, runs_at=lambda phi: np.zeros(3))
    with pytest.raises(ValueError, match="give lengths_at or runs_at, not both"):
        pass_forces(stock, Tool(10.0, 2, 12.0), toolpath, PHI, K, lengths_at=len, runs_at=len)
    with pytest.raises(ValueError, match="lengths_at and runs_at are for straight flutes only"):
        pass_forces(stock, Tool(10.0, 2, 12.0, 30.0), toolpath, PHI, K, runs_at=len)
    runs = flute_runs(stock, tool, toolpath, PHI.phi)
    with pytest.raises(ValueError, match=r"runs must hold one EdgeIntervals per flute \(2\), got 1"):
        profile_forces(runs[:1], PHI.phi, toolpath.frames(), tool, 0.0, 0.1, K)
    with pytest.raises(ValueError, match=r"rotation must have shape \(m, 3, 3\)"):
        profile_forces(runs, PHI.phi, np.eye(3), tool, 0.0, 0.1, K)


def test_a_schedule_of_a_ball_end_mill_keeps_the_limit():
    """Model test 1 with a ball-end mill (R 6): the forces stay affine in the feed, so a schedule at 70 % of
    the peak, recomputed from scratch at the new feeds, keeps every CL point at or under the limit."""
    model = os.path.join(ROOT, "resources", "models", "model_test_1")
    stock, path = load_staircase(os.path.join(model, "stock.json")), load_toolpath(os.path.join(model, "toolpath.csv"))
    tool, settings = Tool(12.0, 2, 30.0, corner_radius=6.0), CutSettings(0.1, 10.0, 0.0, 180.0, 2.0, spindle_rpm=4000.0)
    forces = pass_forces(stock, tool, path, settings, material("al7075-t6"))
    limit = 0.7 * forces.peak.max()
    plan = schedule(forces, limit)
    again = pass_forces(stock, tool, path, settings, material("al7075-t6"), feed=plan.feed)
    assert (again.peak <= limit + 1e-9).all()
    assert np.isclose(again.peak, limit, rtol=1e-9, atol=0.0).any()
