"""Mechanistic cutting forces (abm_workbench.forces) against independent references.

- Full-immersion slotting with a vertical straight-fluted tool: the mean forces and torque
  over a revolution against the closed-form averages derived from the model (docs/FORCES.md).
- A brute-force sum over finely sampled edge elements, each tested against the stock with
  the reference's own point-in-stock test (tests/engine/reference.py), projected with the
  reference's own rotation: tilted tools, curved walls, partial immersion.
- Sign convention at φ = 90°, immersion bounds, input validation.
"""

import subprocess
import sys
import textwrap

import numpy as np
import pytest
from scipy.integrate import quad

from abm_workbench.engine import CutSettings, Staircase, Tool, Toolpath
from abm_workbench.formats.results_csv import (FORCE_COLUMNS, FORCE_SUMMARY_COLUMNS, INPROCESS_COLUMNS,
                                               INPROCESS_SUMMARY_COLUMNS, RESULT_COLUMNS, read_results)
from abm_workbench.formats.staircase_json import load_staircase
from abm_workbench.formats.toolpath_csv import load_toolpath
from abm_workbench.forces import (MATERIALS, Coefficients, check_immersion, edge_forces, in_immersion,
                                  interval_integrals, material, pass_forces)
from tests.conftest import ROOT

from .reference import StairData, _Stock, edge_lines, rotation
from .test_cli import BASE, M, case, run  # noqa: F401  (case is a fixture)

K = Coefficients(ktc=700.0, krc=210.0, kac=120.0, kte=25.0, kre=30.0, kae=4.0)


def _flat(depth, base=-5.0):
    """A flat stock one section high: top at z = depth (mm), wide enough for any slot."""
    return Staircase(-60.0, 60.0, -60.0, 60.0, base, [depth], [])


def _slot_means(flutes, depth, feed, radius):
    """Closed-form mean (F_x, F_y, F_z) (N) and torque (N·mm) of full slotting (docs/FORCES.md)."""
    za = flutes * depth
    return (np.array([-za * K.krc * feed / 4 - za * K.kre / np.pi,
                      za * K.ktc * feed / 4 + za * K.kte / np.pi,
                      za * K.kac * feed / np.pi + za * K.kae / 2]),
            radius * za * (K.ktc * feed / np.pi + K.kte / 2))


@pytest.mark.parametrize("flutes", [1, 2, 3, 4])
@pytest.mark.parametrize("phi_start, phi_end, rtol", [
    # φ = 0:360 at 0.1°: samples on the immersion limits, where the edge forces jump, make
    # the sample mean a rectangle rule with an O(step) error (4.4e-4 measured).
    (0.0, 360.0, 1e-3),
    # Samples between the limits (midpoint rule): O(step²).
    (0.05, 359.95, 1e-6),
])
def test_full_slot_means_match_the_closed_form(flutes, phi_start, phi_end, rtol):
    depth, feed, diameter = 4.0, 0.12, 10.0
    tool = Tool(diameter, flutes, 30.0)
    path = Toolpath([[0.0, 0.0, 0.0], [20.0, 3.0, 1.5]], [0.0, 0.0], [0.0, 0.0])
    settings = CutSettings(feed, 0.0, phi_start, phi_end, 0.1)
    forces = pass_forces(_flat(depth), tool, path, settings, K)
    means, torque = _slot_means(flutes, depth, feed, tool.radius)
    np.testing.assert_allclose(forces.mean_xyz[0], means, rtol=rtol)
    np.testing.assert_allclose(forces.torque[0, forces.phi < phi_start + 360.0 - 1e-9].mean(), torque, rtol=rtol)
    # The second CL point is 1.5 mm higher: 2.5 mm of the edge in the stock.
    means, _ = _slot_means(flutes, depth - 1.5, feed, tool.radius)
    np.testing.assert_allclose(forces.mean_xyz[1], means, rtol=rtol)


def test_power_is_torque_times_spindle_speed():
    tool = Tool(10.0, 2, 30.0)
    path = Toolpath([[0.0, 0.0, 0.0]], [0.0], [0.0])
    settings = CutSettings(0.1, 0.0, 0.0, 180.0, 10.0, spindle_rpm=6000.0)
    forces = pass_forces(_flat(3.0), tool, path, settings, K)
    np.testing.assert_allclose(forces.power, forces.torque * 1e-3 * 2 * np.pi * 100.0)
    assert pass_forces(_flat(3.0), tool, path, CutSettings(0.1), K).power is None


def test_sign_convention_one_flute_at_90_degrees():
    # Feed along +x, the flute straight ahead: the radial force pushes the tool back (−x),
    # the tangential force on the tool points to +y (the edge moves towards −y).
    depth, feed = 3.0, 0.1
    tool = Tool(10.0, 1, 30.0)
    settings = CutSettings(feed, 0.0, 90.0, 90.0, 1.0)
    upright = pass_forces(_flat(depth), tool, Toolpath([[0.0, 0.0, 0.0]], [0.0], [0.0]), settings, K)
    ft, fr, fa = ((K.ktc * feed + K.kte) * depth, (K.krc * feed + K.kre) * depth, (K.kac * feed + K.kae) * depth)
    np.testing.assert_allclose(upright.xyz[0, 0], [-fr, ft, fa], rtol=1e-12)
    np.testing.assert_allclose(upright.torque[0, 0], 5.0 * ft, rtol=1e-12)
    # Tilted about y by 20°: u = (cos 20°, 0, −sin 20°), v = y, w = (sin 20°, 0, cos 20°).
    # The edge is at 90°: along u from the CL point at height 0, so it still starts at z ≤ 0;
    # its length in the stock is the flat top's height above the edge's foot over cos 20°.
    b = np.radians(20.0)
    tilted = pass_forces(_flat(depth), tool, Toolpath([[0.0, 0.0, 0.0]], [0.0], [20.0]), settings, K)
    length = (depth + 5.0 * np.sin(b)) / np.cos(b)
    ft, fr, fa = ((K.ktc * feed + K.kte) * length, (K.krc * feed + K.kre) * length, (K.kac * feed + K.kae) * length)
    u, w = np.array([np.cos(b), 0.0, -np.sin(b)]), np.array([np.sin(b), 0.0, np.cos(b)])
    np.testing.assert_allclose(tilted.xyz[0, 0], -fr * u + ft * np.array([0.0, 1.0, 0.0]) + fa * w, rtol=1e-12)


def test_immersion_switches_whole_flutes_half_open():
    phi = np.array([0.0, 30.0, 89.999, 90.0, 179.0, 180.0, 359.9999999999, 360.0, 390.0, -330.0])
    np.testing.assert_array_equal(in_immersion(phi, (0.0, 180.0)),
                                  [True, True, True, True, True, False, True, True, True, True])
    np.testing.assert_array_equal(in_immersion(phi, (30.0, 90.0)),
                                  [False, True, True, False, False, False, False, False, True, True])
    # Down-milling half: only the second flute of a two-flute tool at φ = 20° (it is at 200°) …
    lengths = np.ones((2, 1, 2))
    forces = edge_forces(lengths, [20.0, 110.0], np.eye(3)[None], 5.0, 0.0, 0.1, K, immersion=(90.0, 180.0))
    assert np.all(forces.resultant[0, 0] == 0.0)       # flute 1 at 20°, flute 2 at 200°: neither cuts
    assert forces.resultant[0, 1] > 0.0                # flute 1 at 110° cuts


def _brute_force(stock, radius, flute_length, flutes, cl, theta_a, theta_b, phi, feed, inclination, immersion,
                 elements=40000):
    """(p, 3) global force (N) at one CL point: a sum over `elements` edge elements per flute, each
    inside or not by the reference's point-in-stock test. Also the element length (mm)."""
    model = _Stock(stock)
    dl = flute_length / elements
    l = (np.arange(elements) + 0.5) * dl
    rot = rotation(theta_a, theta_b)
    out = np.zeros((len(phi), 3))
    for k in range(flutes):
        angle = np.asarray(phi, dtype=float) + 360.0 * k / flutes
        base, w = edge_lines(radius, cl, theta_a, theta_b, angle)
        inside = model.inside(base[:, None, :] + l[None, :, None] * w)             # (p, E)
        b = inside.sum(axis=1) * dl
        rel = np.mod(angle - immersion[0], 360.0)
        cuts = rel < immersion[1] - immersion[0]
        h = feed * np.sin(np.radians(angle)) * np.cos(np.radians(inclination))
        ft, fr, fa = ((K.ktc * h + K.kte) * b, (K.krc * h + K.kre) * b, (K.kac * h + K.kae) * b)
        s, c = np.sin(np.radians(angle)), np.cos(np.radians(angle))
        local = np.stack([-ft * c - fr * s, ft * s - fr * c, fa], axis=1) * cuts[:, None]
        out += local @ rot.T
    return out, dl


STAIRS = StairData(
    x_min=-30.0, x_max=60.0, y_min=-25.0, y_max=25.0, base_z=-12.0, z_top=(3.0, 7.5, 1.0),
    walls=(tuple((8.0 + 2.0 * np.sin(y / 9.0), y) for y in np.linspace(-25.0, 25.0, 6)),
           tuple((30.0, y) for y in np.linspace(-25.0, 25.0, 6))),
)


@pytest.mark.parametrize("cl, theta_a, theta_b, immersion, flutes", [
    ((5.3, 1.1, -1.0), 0.0, 0.0, (0.0, 180.0), 2),
    ((7.1, -2.3, 0.4), 12.0, -8.0, (30.0, 150.0), 3),
    ((27.7, 0.9, -2.2), -6.0, 15.0, (0.0, 90.0), 4),
    ((33.2, 0.0, 0.5), 4.0, 25.0, (60.0, 180.0), 1),
])
def test_summed_forces_match_a_brute_force_edge_element_sum(cl, theta_a, theta_b, immersion, flutes):
    diameter, flute_length, feed, inclination = 12.0, 14.0, 0.11, 7.0
    stock = Staircase(STAIRS.x_min, STAIRS.x_max, STAIRS.y_min, STAIRS.y_max, STAIRS.base_z,
                      STAIRS.z_top, STAIRS.walls)
    tool = Tool(diameter, flutes, flute_length)
    settings = CutSettings(feed, inclination, 0.5, 359.5, 9.0)
    path = Toolpath([cl], [theta_a], [theta_b])
    forces = pass_forces(stock, tool, path, settings, K, immersion=immersion)
    want, dl = _brute_force(STAIRS, 0.5 * diameter, flute_length, flutes, cl, theta_a, theta_b, settings.phi,
                            feed, inclination, immersion)
    assert np.abs(want).max() > 100.0  # the case does cut
    # Each flute's length is off by at most one element per boundary crossing (a few per edge).
    per_mm = np.linalg.norm(K.cutting) * feed + np.linalg.norm(K.edge)
    np.testing.assert_allclose(forces.xyz[0], want, rtol=0.0, atol=flutes * 4 * dl * per_mm)


def test_mean_counts_one_revolution():
    lengths = np.ones((1, 1, 5))
    forces = edge_forces(lengths, [0.0, 90.0, 180.0, 270.0, 360.0], np.eye(3)[None], 5.0, 0.0, 0.1, K)
    np.testing.assert_allclose(forces.mean[0], forces.resultant[0, :4].mean())
    np.testing.assert_allclose(forces.peak[0], forces.resultant[0].max())


def test_with_feed_is_affine():
    lengths = np.random.default_rng(3).uniform(0.0, 5.0, (3, 4, 7))
    rot = np.stack([rotation(5.0 * i, -3.0 * i) for i in range(4)])
    phi = np.linspace(0.0, 180.0, 7)
    low = edge_forces(lengths, phi, rot, 4.0, 5.0, 0.05, K)
    high = edge_forces(lengths, phi, rot, 4.0, 5.0, [0.1, 0.2, 0.3, 0.4], K)
    np.testing.assert_allclose(low.with_feed([0.1, 0.2, 0.3, 0.4]).xyz, high.xyz, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(high.area, high.feed[:, None] * low.area_per_feed)


@pytest.mark.parametrize("kwargs, message", [
    ({"ktc": 0.0, "krc": 1.0, "kac": 1.0}, "ktc must be positive"),
    ({"ktc": 1.0, "krc": float("nan"), "kac": 1.0}, "krc must be a finite number"),
    ({"ktc": 1.0, "krc": 1.0, "kac": "x"}, "kac must be a number"),
    ({"ktc": 1.0, "krc": 1.0, "kac": 1.0, "kae": True}, "kae must be a finite number"),
])
def test_coefficients_are_validated(kwargs, message):
    with pytest.raises(ValueError, match=message):
        Coefficients(**kwargs)


@pytest.mark.parametrize("immersion", [(90.0, 90.0), (-10.0, 90.0), (0.0, 200.0), (120.0, 60.0), ("a", 1), (1,)])
def test_immersion_is_validated(immersion):
    with pytest.raises(ValueError, match="immersion"):
        check_immersion(immersion)


def test_materials_table():
    assert material("AL7075-T6") is MATERIALS["al7075-t6"][0]
    with pytest.raises(ValueError, match="unknown material 'steel'.*al6082-t6"):
        material("steel")


def test_shapes_are_checked():
    with pytest.raises(ValueError, match=r"lengths must have shape \(Z, m, 3\)"):
        edge_forces(np.ones((2, 1, 4)), [0.0, 1.0, 2.0], np.eye(3)[None], 5.0, 0.0, 0.1, K)
    with pytest.raises(ValueError, match=r"rotation must have shape \(1, 3, 3\)"):
        edge_forces(np.ones((2, 1, 3)), [0.0, 1.0, 2.0], np.eye(3), 5.0, 0.0, 0.1, K)
    with pytest.raises(ValueError, match="feed per tooth"):
        edge_forces(np.ones((2, 1, 3)), [0.0, 1.0, 2.0], np.eye(3)[None], 5.0, 0.0, -0.1, K)
    with pytest.raises(ValueError, match=r"feed per tooth must be a number or have shape \(1,\), got \(2,\)"):
        edge_forces(np.ones((2, 1, 3)), [0.0, 1.0, 2.0], np.eye(3)[None], 5.0, 0.0, [0.1, 0.2], K)



def test_engage_forces_columns(case, capsys):
    status, out, err = run(BASE + ["--forces", "--material", "AL7075-T6", "--kae", "1.5", "--immersion", "30:150",
                                   "--phi-range", "0:360"], capsys)
    assert (status, err) == (0, "")
    assert "; peak force " in out
    results = read_results(case / "R.csv")
    # Forces are computed against the in-process stock by default (its initial-stock length column).
    assert list(results) == [*RESULT_COLUMNS, *INPROCESS_COLUMNS, *FORCE_COLUMNS]
    summary = read_results(case / "R.summary.csv")
    assert list(summary)[-4:] == [*FORCE_SUMMARY_COLUMNS, *INPROCESS_SUMMARY_COLUMNS]
    # The same numbers as the Python API (the CSV keeps 10 decimals).
    coefficients = Coefficients(**{**vars(material("al7075-t6")), "kae": 1.5})
    forces = pass_forces(load_staircase("stock.json"), Tool(12, 2, 30), load_toolpath("toolpath.csv"),
                         CutSettings(0.1, 10, 0, 360, 5, 4000), coefficients, immersion=(30, 150))
    np.testing.assert_allclose(results["fx"], forces.xyz[..., 0].reshape(-1), atol=1e-9)
    np.testing.assert_allclose(results["torque"], forces.torque.reshape(-1), atol=1e-9)
    np.testing.assert_allclose(results["power"], forces.power.reshape(-1), atol=1e-9)
    first = np.searchsorted(summary["cl"], np.arange(M))
    np.testing.assert_allclose(summary["peak_force"][first], forces.peak, atol=1e-9)
    np.testing.assert_allclose(summary["mean_force"][first], forces.mean, atol=1e-9)


@pytest.mark.parametrize("options, message", [
    (["--ktc", "700"], "--ktc applies with --forces"),
    (["--immersion", "0:90"], "--immersion applies with --forces"),
    (["--forces", "--ktc", "700", "--krc", "200"], "--kac: is required for the forces: give a material or the coefficients ktc, krc and kac"),
    (["--forces", "--material", "steel"], "--material: unknown material 'steel'"),
    (["--forces", "--material", "al7075-t6", "--ktc", "-5"], "--ktc: must be positive, got -5 N/mm²"),
    (["--forces", "--material", "al7075-t6", "--immersion", "0:200"], "--immersion: must be within (0, 180]°, got 200°"),
    (["--forces", "--material", "al7075-t6", "--immersion", "30"], "--immersion: expected START:END"),
    (["--forces", "--material", "al7075-t6", "--method", "zmap"], "--forces: needs the abm method"),
])
def test_engage_force_option_errors(case, capsys, options, message):
    status, _, err = run(BASE + options, capsys)
    assert status == 2 and err.startswith(f"abm: error: {message}"), err
    assert not (case / "R.csv").exists()



@pytest.mark.parametrize("kappa", [0.0, 1e-9, 0.05, -0.3, 2.0])
def test_interval_integrals_match_quadrature(kappa):
    rng = np.random.default_rng(11)
    start = rng.uniform(0.0, 10.0, 12)
    end = start + rng.uniform(0.0, 8.0, 12)
    psi0 = rng.uniform(-4.0, 8.0, 12)
    got = interval_integrals(start, end, psi0, kappa)
    for g, func in zip(got, (lambda p: 1.0, np.sin, np.cos, lambda p: np.sin(p) ** 2,
                             lambda p: np.sin(p) * np.cos(p))):
        want = [quad(lambda l: func(p0 - kappa * l), a, b, epsabs=1e-13, epsrel=1e-13, limit=200)[0]
                for a, b, p0 in zip(start, end, psi0)]
        np.testing.assert_allclose(g, want, rtol=1e-10, atol=1e-12)
    nothing = interval_integrals([np.nan], [np.nan], 1.0, kappa)
    assert all(v[0] == 0.0 for v in nothing)


@pytest.mark.parametrize("flutes, helix, multiple", [(2, 30.0, 1), (3, 45.0, 2), (4, 20.0, 1)])
def test_helical_full_slot_force_is_constant_at_a_multiple_of_pitch_over_z(flutes, helix, multiple):
    radius = 5.0
    pitch = 2.0 * np.pi * radius / np.tan(np.radians(helix))
    depth = multiple * pitch / flutes
    feed = 0.1
    tool = Tool(2 * radius, flutes, depth + 10.0, helix)
    path = Toolpath([[0.0, 0.0, 0.0]], [0.0], [0.0])
    forces = pass_forces(_flat(depth, base=-3.0), tool, path, CutSettings(feed, 0.0, 0.0, 359.0, 1.0), K)
    xyz = forces.xyz[0]
    spread = np.ptp(xyz, axis=0) / np.linalg.norm(xyz.mean(axis=0))
    assert spread.max() < 1e-6, spread
    np.testing.assert_allclose(np.ptp(forces.torque[0]) / forces.torque[0].mean(), 0.0, atol=1e-6)
    # … and equal to the straight-flute mean of the same slot (the closed form).
    means, torque = _slot_means(flutes, depth, feed, radius)
    np.testing.assert_allclose(xyz.mean(axis=0), means, rtol=1e-9)
    np.testing.assert_allclose(forces.torque[0].mean(), torque, rtol=1e-9)


def test_helical_force_varies_when_the_depth_is_not_a_multiple():
    radius, helix, flutes = 5.0, 30.0, 2
    depth = 0.5 * 2.0 * np.pi * radius / np.tan(np.radians(helix)) / flutes
    tool = Tool(2 * radius, flutes, 40.0, helix)
    forces = pass_forces(_flat(depth), tool, Toolpath([[0.0, 0.0, 0.0]], [0.0], [0.0]),
                         CutSettings(0.1, 0.0, 0.0, 359.0, 1.0), K)
    assert np.ptp(forces.resultant[0]) / forces.resultant[0].mean() > 0.05


def _brute_force_helix(stock, radius, flute_length, flutes, helix, cl, theta_a, theta_b, phi, feed, inclination,
                       immersion, elements=40000):
    """(p, 3) global force (N): a sum over `elements` elements of every helical flute, each inside
    the stock or not by the reference's point test, cutting where ψ mod 360 is in the immersion."""
    model = _Stock(stock)
    dl = flute_length / elements
    l = (np.arange(elements) + 0.5) * dl
    rot = rotation(theta_a, theta_b)
    kappa = np.tan(np.radians(helix)) / radius
    out = np.zeros((len(phi), 3))
    for k in range(flutes):
        psi = np.radians(np.asarray(phi, dtype=float)[:, None] + 360.0 * k / flutes) - kappa * l[None, :]
        local = np.stack([radius * np.sin(psi), radius * np.cos(psi), np.broadcast_to(l, psi.shape)], axis=-1)
        inside = model.inside(np.asarray(cl, dtype=float) + local @ rot.T)
        rel = np.mod(np.degrees(psi) - immersion[0], 360.0)
        cuts = inside & (rel <= immersion[1] - immersion[0])
        h = feed * np.sin(psi) * np.cos(np.radians(inclination))
        ft, fr, fa = ((K.ktc * h + K.kte) * dl, (K.krc * h + K.kre) * dl, (K.kac * h + K.kae) * dl)
        s, c = np.sin(psi), np.cos(psi)
        element = np.stack([-ft * c - fr * s, ft * s - fr * c, fa], axis=-1) * cuts[..., None]
        out += element.sum(axis=1) @ rot.T
    return out, dl


@pytest.mark.parametrize("cl, theta_a, theta_b, immersion, flutes, helix", [
    ((5.3, 1.1, -1.0), 0.0, 0.0, (0.0, 180.0), 2, 30.0),
    ((7.1, -2.3, 0.4), 12.0, -8.0, (30.0, 150.0), 3, 40.0),
    ((27.7, 0.9, -2.2), -6.0, 15.0, (0.0, 90.0), 4, -25.0),
])
def test_helical_forces_match_a_brute_force_element_sum(cl, theta_a, theta_b, immersion, flutes, helix):
    diameter, flute_length, feed, inclination = 12.0, 14.0, 0.11, 7.0
    stock = Staircase(STAIRS.x_min, STAIRS.x_max, STAIRS.y_min, STAIRS.y_max, STAIRS.base_z,
                      STAIRS.z_top, STAIRS.walls)
    settings = CutSettings(feed, inclination, 0.5, 359.5, 9.0)
    forces = pass_forces(stock, Tool(diameter, flutes, flute_length, helix), Toolpath([cl], [theta_a], [theta_b]),
                         settings, K, immersion=immersion)
    want, dl = _brute_force_helix(STAIRS, 0.5 * diameter, flute_length, flutes, helix, cl, theta_a, theta_b,
                                  settings.phi, feed, inclination, immersion)
    assert np.abs(want).max() > 100.0
    per_mm = np.linalg.norm(K.cutting) * feed + np.linalg.norm(K.edge)
    np.testing.assert_allclose(forces.xyz[0], want, rtol=0.0, atol=flutes * 4 * dl * per_mm)


def test_a_tiny_helix_gives_the_straight_forces():
    stock = Staircase(STAIRS.x_min, STAIRS.x_max, STAIRS.y_min, STAIRS.y_max, STAIRS.base_z,
                      STAIRS.z_top, STAIRS.walls)
    path = Toolpath([(7.1, -2.3, 0.4), (27.7, 0.9, -2.2)], [12.0, -6.0], [-8.0, 15.0])
    settings = CutSettings(0.1, 5.0, 0.5, 359.5, 3.0)
    straight = pass_forces(stock, Tool(12.0, 3, 14.0), path, settings, K, immersion=(20.0, 160.0))
    helical = pass_forces(stock, Tool(12.0, 3, 14.0, 1e-7), path, settings, K, immersion=(20.0, 160.0))
    # Two engines (straight-line ABM, helix solver): 1.7e-4 N apart at most, about 1.4e-6 mm of length.
    np.testing.assert_allclose(helical.xyz, straight.xyz, rtol=0.0, atol=1e-3)
    np.testing.assert_allclose(helical.torque, straight.torque, rtol=0.0, atol=1e-2)


def test_engage_helical_forces_from_the_command_line(case, capsys):
    status, out, err = run(BASE + ["--forces", "--ktc", "700", "--krc", "210", "--kac", "120", "--helix", "30"],
                           capsys)
    assert (status, err) == (0, "")
    assert out.splitlines()[1].endswith("step 5° [job.json], helix 30° [--helix]; initial stock (the in-process stock "
                                        "is not available with a helical tool yet)")
    results = read_results(case / "R.csv")
    forces = pass_forces(load_staircase("stock.json"), Tool(12, 2, 30, 30), load_toolpath("toolpath.csv"),
                         CutSettings(0.1, 10, 0, 180, 5, 4000), Coefficients(700, 210, 120))
    np.testing.assert_allclose(results["fz"], forces.xyz[..., 2].reshape(-1), atol=1e-9)
    status, _, err = run(BASE + ["--helix", "95"], capsys)
    assert status == 2 and err.startswith("abm: error: --helix: must be within [-60, 60]°, got 95°")
    status, _, err = run(BASE + ["--helix", "20", "--method", "zmap"], capsys)
    assert status == 2 and err.startswith("abm: error: --helix: needs the abm method")


def test_engage_forces_plot(case, capsys):
    status, out, err = run(BASE + ["--forces", "--material", "al6082-t6", "--plot", "R.png"], capsys)
    assert (status, err) == (0, "")
    assert out.splitlines()[0].endswith("wrote R.csv, R.summary.csv, R.png, R.forces.png")
    assert (case / "R.forces.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_forces_and_scheduling_are_pure_numpy():
    script = textwrap.dedent(
        """
        import sys
        class Block:
            def find_spec(self, name, path=None, target=None):
                if name.split(".")[0] in ("FreeCAD", "FreeCADGui", "Part", "Mesh", "matplotlib"):
                    raise ImportError("blocked: " + name)
        sys.meta_path.insert(0, Block())
        from abm_workbench.engine import CutSettings, Staircase, Tool, Toolpath
        from abm_workbench.forces import material, pass_forces
        from abm_workbench.scheduling import schedule
        from abm_workbench.formats.apt_writer import apt_text
        stock = Staircase(0, 50, -10, 10, -5, [2.0, 4.0], [[[25.0, y] for y in range(-10, 11, 4)]])
        path = Toolpath([[20, 0, 0]], [0], [10])
        forces = pass_forces(stock, Tool(10, 2, 20, 30), path, CutSettings(0.1), material("al7075-t6"))
        plan = schedule(forces, 0.5 * forces.peak.max())
        assert plan.feed[0] < 0.1 and apt_text(path, plan.feed, flutes=2, diameter=10, flute_length=20)
        print("ok")
        """
    )
    run = subprocess.run([sys.executable, "-c", script], cwd=ROOT, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "ok"
