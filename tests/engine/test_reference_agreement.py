"""The engine agrees with the brute-force reference (tests/engine/reference.py).

Random jobs (hypothesis) and hand-made cases, one per row of Table 1 plus edge cases.
Lengths and points must agree to TOL; the UEP surface must be one the reference finds at
the UEP, and the Table 1 case must follow the rules (reference.table1_case). For the
hand-made cases the case and surface names are also checked against values derived by hand.
"""

from typing import NamedTuple, Tuple

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from abm_workbench.engine import CutSettings, Tool, Toolpath, engage

from .reference import StairData, reference_engagement, reference_sweep, rotation, table1_case
from .strategies import engine_inputs, engine_stock, jobs, staircases

TOL = 1e-6  # mm, engine vs reference, for every length and point


def _close(a, b):
    """Whether two floats (mm) agree to TOL, NaN matching NaN."""
    return (np.isnan(a) and np.isnan(b)) or abs(a - b) <= TOL


def _surface_key(engagement, i, k):
    """(surface name, wall index or −1) of the engine's UEP at CL i, angle k."""
    name = engagement.surface_names()[i, k]
    wall = int(engagement.uep_wall[i, k]) if name in ("straight_wall", "curved_wall") else -1
    return name, wall


def _mismatches(engagement, i, k, ref, z_top, theta_b):
    """Descriptions of every way the engine's instant (i, k) differs from RefEngagement ref."""
    e = engagement
    out = []
    for name, got, want in (("length", e.length[i, k], ref.length), ("lep_l", e.lep_l[i, k], ref.lep),
                            ("uep_l", e.uep_l[i, k], ref.uep)):
        if not _close(got, want):
            out.append(f"{name}: engine {got!r}, reference {want!r}")
    for name, got, want in (("lep_xyz", e.lep_xyz[i, k], ref.lep_xyz), ("uep_xyz", e.uep_xyz[i, k], ref.uep_xyz)):
        if not all(_close(g, w) for g, w in zip(got, want)):
            out.append(f"{name}: engine {got}, reference {want}")
    if e.pieces[i, k] != len(ref.pieces):
        out.append(f"pieces: engine {e.pieces[i, k]}, reference {ref.pieces}")
    if _surface_key(e, i, k) not in ref.uep_candidates:
        out.append(f"uep surface: engine {_surface_key(e, i, k)}, reference {set(ref.uep_candidates)}")
    if e.uep_section[i, k] != ref.uep_section:
        out.append(f"uep_section: engine {e.uep_section[i, k]}, reference {ref.uep_section}")
    case = table1_case(ref, z_top, theta_b)
    if e.case_names()[i, k] != case:
        out.append(f"case: engine {e.case_names()[i, k]}, rules {case} (sections {set(ref.sections)}, "
                   f"Sec A {ref.bottom_section})")
    return out


def assert_agrees(job):
    """Run the engine on a strategies.Job and compare every instant with the reference."""
    e = engage(*engine_inputs(job))
    problems = []
    for i in range(len(job.cl)):
        refs = reference_sweep(job.stock, job.diameter / 2, job.flute_length, job.cl[i],
                               job.theta_a[i], job.theta_b[i], e.phi)
        for k, ref in enumerate(refs):
            for text in _mismatches(e, i, k, ref, job.stock.z_top, job.theta_b[i]):
                problems.append(f"CL {i} {job.cl[i].tolist()} θA {job.theta_a[i]!r} θB {job.theta_b[i]!r} "
                                f"φ {e.phi[k]!r}: {text}")
    assert not problems, "\n".join(problems[:10])


@settings(max_examples=150)
@given(jobs())
def test_random_jobs(job):
    """Random stocks, tools, orientations and CL points."""
    assert_agrees(job)


@settings(max_examples=60)
@given(jobs(stocks=staircases(min_sections=2, curved=True), theta_b=st.just(0.0)))
def test_random_curved_walls_tilt_about_x(job):
    """Curved walls and θ_B = 0: the edge keeps a constant x and may cross a wall twice."""
    assert_agrees(job)


@settings(max_examples=60)
@given(jobs(stocks=staircases(min_sections=4, curved=True)))
def test_random_many_curved_sections(job):
    """Four to six sections, all walls curved."""
    assert_agrees(job)


@settings(max_examples=60)
@given(jobs(stocks=staircases(min_sections=5, curved=True),
            theta_b=st.floats(35.0, 60.0) | st.floats(-60.0, -35.0)))
def test_random_steep_tilt_across_several_walls(job):
    """Five or six sections and a steep θ_B: edges that cross two or more walls, each once,
    which the engine solves in closed form (engagement._single_crossings)."""
    assert_agrees(job)


# ---------------------------------------------------------------- hand-made cases

def _wall(x_of_y, y_min=-30.0, y_max=30.0):
    """Six (x, y) points of the wall x = x_of_y(y), evenly spaced on [y_min, y_max]."""
    return tuple((float(x_of_y(y)), float(y)) for y in np.linspace(y_min, y_max, 6))


STRAIGHT = _wall(lambda y: 0.0)
CURVED = _wall(lambda y: (y / 30.0) ** 2 - 0.5)


def two_steps(z_left, z_right, wall=STRAIGHT):
    """Two sections, x in [−40, 40], y in [−30, 30], base 0; one wall near x = 0."""
    return StairData(-40.0, 40.0, -30.0, 30.0, 0.0, (z_left, z_right), (wall,))


FOUR_STEPS_DOWN = StairData(-40.0, 40.0, -30.0, 30.0, 0.0, (30.0, 25.0, 20.0, 15.0),
                            (_wall(lambda y: 0.0), _wall(lambda y: 3.0), _wall(lambda y: 6.0)))
PARABOLA = _wall(lambda y: 0.02 * y * y - 1.0, -10.0, 10.0)


def parabola_stock(z_left, z_right):
    """Two sections split by the wall x = 0.02 y² − 1, x in [−20, 20], y in [−10, 10], base 0."""
    return StairData(-20.0, 20.0, -10.0, 10.0, 0.0, (z_left, z_right), (PARABOLA,))


class HandCase(NamedTuple):
    """A hand-made instant: the edge's bottom point (3,) mm is given, the CL point derived.

    Expected values come from the hand derivation in the comment of each case.
    """

    stock: StairData
    bottom: Tuple[float, float, float]
    theta_a: float
    theta_b: float
    phi: float
    case: str
    surface: str
    pieces: int
    wall: int = -1
    radius: float = 5.0
    flute_length: float = 30.0


# Unless noted: θ_A = 10°, θ_B = ±20°, the edge direction is (±0.342, −0.163, 0.925), the
# straight wall is x = 0 and sections are 0 (x < 0) and 1 (x ≥ 0); bottom point P0.
HAND_CASES = {
    # P0 in section 0 (z 20), leaning +x; x = 0 at l 8.77, z 8.6 < 10: into section 1,
    # out through its top z = 10 at l 10.3. E = {A, B}, z_A > z_B, +x.
    "A.2": HandCase(two_steps(20.0, 10.0), (-3.0, 0.0, 0.5), 10.0, 20.0, 90.0, "A.2", "top", 1),
    # Mirror of A.2: P0 in section 1 (z 20), leaning −x into section 0 (z 10).
    "A.1": HandCase(two_steps(10.0, 20.0), (3.0, 0.0, 0.5), 10.0, -20.0, 90.0, "A.1", "top", 1),
    # Crosses x = 0 at z 13.1, between z_B = 10 and z_A = 20: leaves A through the wall.
    "A.4": HandCase(two_steps(20.0, 10.0), (-3.0, 0.0, 5.0), 10.0, 20.0, 90.0, "A.4", "straight_wall", 1, 1),
    # Mirror of A.4 on the curved wall x = (y/30)² − 0.5 (crossed near y = −1.4, x = −0.5).
    "A.3": HandCase(two_steps(10.0, 20.0, CURVED), (3.0, 0.0, 5.0), 10.0, -20.0, 90.0, "A.3", "curved_wall",
                    1, 1),
    # Section 0 (z 10), leaning +x; x = 0 at z 8.6 < 10: into section 1 (z 20), out at its top.
    "B.1": HandCase(two_steps(10.0, 20.0), (-3.0, 0.0, 0.5), 10.0, 20.0, 90.0, "B.1", "top", 1),
    "B.2": HandCase(two_steps(20.0, 10.0), (3.0, 0.0, 0.5), 10.0, -20.0, 90.0, "B.2", "top", 1),
    # Out of A's top z = 10 at l 5.4 (x −3.2), back in through the wall at l 14.6 (z 18.5),
    # out of B's top z = 20 at l 16.2: two pieces.
    "B.3": HandCase(two_steps(10.0, 20.0), (-5.0, 0.0, 5.0), 10.0, 20.0, 90.0, "B.3", "top", 2),
    "B.4": HandCase(two_steps(20.0, 10.0), (5.0, 0.0, 5.0), 10.0, -20.0, 90.0, "B.4", "top", 2),
    # Starts above A (12 > 10) and passes over the wall at z 20.1 > 20: nothing cut.
    "B.5": HandCase(two_steps(10.0, 20.0), (-3.0, 0.0, 12.0), 10.0, 20.0, 90.0, "B.5", "none", 0),
    # Starts above A, enters B through the wall at z 19.1 < 20, leaves at B's top.
    "B.6": HandCase(two_steps(10.0, 20.0), (-3.0, 0.0, 11.0), 10.0, 20.0, 90.0, "B.6", "top", 1),
    # Far above a descending stock: no engagement and (z_A > z_B) not B.5.
    "no_engagement": HandCase(two_steps(20.0, 10.0), (-3.0, 0.0, 25.0), 10.0, 20.0, 90.0, "none", "none", 0),
    # θ_B = 0: the edge stays at x = −3 (parallel to the wall), leaves A's top; no Sec B.
    "theta_b_zero": HandCase(two_steps(10.0, 20.0), (-3.0, 0.0, 2.0), 10.0, 0.0, 90.0, "none", "top", 1),
    # θ_A = 0, edge (0.342, 0, 0.940): crosses the curved wall (x −0.5 at y 0) at z 13.8, A.4.
    "theta_a_zero": HandCase(two_steps(20.0, 10.0, CURVED), (-3.0, 0.0, 7.0), 0.0, 20.0, 90.0, "A.4",
                             "curved_wall", 1, 1),
    # L = 5: the edge ends at z 5.6, x −8.3, still inside A: UEP at the flute end.
    "flute_end": HandCase(two_steps(20.0, 10.0), (-10.0, 0.0, 1.0), 10.0, 20.0, 90.0, "none", "flute_end", 1,
                          flute_length=5.0),
    # θ_B = 40°, θ_A = 0, edge (0.643, 0, 0.766) from (−2, 0, 0.5) through walls x = 0, 3, 6
    # at z 2.9, 6.5, 10.0 (all below the tops 25, 20, 15), out at z = 15 in section 3.
    "multi": HandCase(FOUR_STEPS_DOWN, (-2.0, 0.0, 0.5), 0.0, 40.0, 90.0, "multi", "top", 1),
    # θ_A = 40°, θ_B = 0, φ = 0: edge (0, −0.643, 0.766) at x = 0 from y 9, z 5. Section 0
    # (x < 0.02 y² − 1, |y| > 7.07) is low (z 1), section 1 high: in through the parabola at
    # y 7.07 (l 3.0), out through it at y −7.07 (l 25.0, z 24.2). Sec A = 0, E = {1}: multi.
    "curved_wall_twice_in_out": HandCase(parabola_stock(1.0, 40.0), (0.0, 9.0, 5.0), 40.0, 0.0, 0.0, "multi",
                                         "curved_wall", 1, 1),
    # Same edge, section 0 high and section 1 low: out through the parabola at y 7.07, back
    # in at y −7.07, out through the side y = −10 at l 29.6 (z 27.6): two pieces, E = {A}.
    "curved_wall_twice_out_in": HandCase(parabola_stock(40.0, 1.0), (0.0, 9.0, 5.0), 40.0, 0.0, 0.0, "none",
                                         "stock_side", 2),
    # Bottom 3 mm below the base: in through the base at l 3.2, out of A's top z 20 at l 24.9
    # (x −1.5, still section 0). E = {A}, UEP on a top: no Table 1 row.
    "bottom_below_base": HandCase(two_steps(20.0, 10.0), (-10.0, 0.0, -3.0), 10.0, 20.0, 90.0, "none", "top", 1),
    # Bottom 3 mm beyond x_min = −40: in through the x_min face at l 8.8 (z 10.1), out of
    # A's top z 20 at l 19.5 (x −36.4).
    "bottom_beside_stock": HandCase(two_steps(20.0, 10.0), (-43.0, 0.0, 2.0), 10.0, 20.0, 90.0, "none", "top", 1),
}


def cl_for_bottom(bottom, radius, theta_a, theta_b, phi):
    """The CL point (3,) mm that puts the edge's bottom point (l = 0) at bottom (3,) at angle phi (deg)."""
    p = np.radians(phi)
    return np.asarray(bottom) - rotation(theta_a, theta_b) @ np.array([radius * np.sin(p), radius * np.cos(p), 0.0])


def run_hand_case(c: HandCase):
    """Engine Engagement (one CL point, one φ) and the RefEngagement of a HandCase."""
    cl = cl_for_bottom(c.bottom, c.radius, c.theta_a, c.theta_b, c.phi)
    e = engage(engine_stock(c.stock), Tool(2 * c.radius, 2, c.flute_length),
               Toolpath(cl[None, :], np.array([c.theta_a]), np.array([c.theta_b])),
               CutSettings(0.1, phi_start=c.phi, phi_end=c.phi))
    ref = reference_engagement(c.stock, c.radius, c.flute_length, cl, c.theta_a, c.theta_b, c.phi)
    return e, ref


@pytest.mark.parametrize("name", sorted(HAND_CASES))
def test_hand_case_matches_reference(name):
    """Lengths and points agree with the reference; the reference confirms the hand design."""
    c = HAND_CASES[name]
    e, ref = run_hand_case(c)
    assert len(ref.pieces) == c.pieces and (c.surface, c.wall) in ref.uep_candidates
    assert table1_case(ref, c.stock.z_top, c.theta_b) == c.case
    assert not _mismatches(e, 0, 0, ref, c.stock.z_top, c.theta_b)


@pytest.mark.parametrize("name", sorted(HAND_CASES))
def test_hand_case_names(name):
    """The engine reports the Table 1 case, UEP surface and wall derived by hand."""
    c = HAND_CASES[name]
    e, _ = run_hand_case(c)
    assert (e.case_names()[0, 0], e.surface_names()[0, 0], e.pieces[0, 0]) == (c.case, c.surface, c.pieces)
    if c.wall >= 0:
        assert e.uep_wall[0, 0] == c.wall


def test_no_engagement_reports_nothing():
    """Without engagement: NaN LEP/UEP and points, zero length and area, no segment, section −1."""
    e, _ = run_hand_case(HAND_CASES["no_engagement"])
    assert np.isnan([e.lep_l[0, 0], e.uep_l[0, 0], *e.lep_xyz[0, 0], *e.uep_xyz[0, 0]]).all()
    assert (e.length[0, 0], e.area[0, 0], e.pieces[0, 0], e.segment[0, 0], e.uep_section[0, 0]) == (0, 0, 0, -1, -1)
