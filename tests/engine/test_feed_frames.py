"""φ from the feed: each CL point's frame turned about z to its move's direction in plan view (engine.feed).

Checked against the brute-force reference (tests/engine/reference.py knows only the paper's frame
Rx(θ_A)·Ry(θ_B), feeding along +x): an upright tool turned by α engages at φ as the paper's frame
does at φ − α, and a pass along −x gives at φ what the paper's frame gives at φ + 180°. A whole
set-up turned about z (stock, CL program with arcs, tool axes) gives the same results. The rules
of α and the inclination are checked on paths whose answers are worked out by hand.
"""

import math

import numpy as np
import pytest

from abm_workbench.engine import CutSettings, Tool, Toolpath, engage
from abm_workbench.engine.feed import feed_frame, inclinations, path_directions
from abm_workbench.engine.terraced import engage_terraced
from abm_workbench.formats.cl import read_program
from abm_workbench.formats.staircase_json import load_staircase
from abm_workbench.formats.toolpath_csv import load_toolpath
from tests.conftest import ROOT

from . import reference
from .test_terraced import rotate, square, to_stock

MODEL = f"{ROOT}/resources/models/model_test_{{}}/"
TOOL = Tool(12.0, 2, 30.0)
CUT = CutSettings(0.1, 0.0, 0.0, 180.0, 5.0)


def stair_data(staircase):
    """The reference's plain data of an engine Staircase (its six points per wall)."""
    return reference.StairData(staircase.x_min, staircase.x_max, staircase.y_min, staircase.y_max,
                               staircase.base_z, tuple(staircase.z_top.tolist()),
                               tuple(tuple(map(tuple, wall)) for wall in staircase.wall_points.tolist()))


def fed(cl, axes):
    """The Toolpath of CL points (m, 3) and part-frame axes (m, 3), frames turned to the chords' feed."""
    alpha, _ = feed_frame(path_directions(cl))
    return Toolpath.from_axes(cl, axes, alpha=alpha)


def reference_lengths(stock, cl, theta_a, theta_b, phis):
    """(m, p) reference lengths of cut, the paper's frame (part-frame angles) at angles phis (m, p) deg."""
    return np.array([[reference.reference_engagement(stock, TOOL.radius, TOOL.flute_length, point, a, b, phi).length
                      for phi in row] for point, a, b, row in zip(cl, theta_a, theta_b, phis)])


def test_a_side_cut_along_y_engages_its_leading_half():
    staircase = load_staircase(MODEL.format(1) + "stock.json")
    y = np.arange(-22.0, 14.0, 3.0)
    cl = np.column_stack([np.full(y.size, 60.0), y, np.full(y.size, staircase.z_top.max() - 9.0)])
    path = fed(cl, np.tile([0.0, 0.0, 1.0], (y.size, 1)))
    assert np.allclose(path.alpha, 90.0)  # feeding along +y
    result = engage(staircase, TOOL, path, CUT)
    # In the default range (0..180°, the leading half) the cut has area.
    assert (result.area > 0).any(axis=1).sum() >= 5
    # An upright tool turned by α = 90° engages at φ as the paper's frame does at φ − 90°.
    want = reference_lengths(stair_data(staircase), cl, np.zeros(y.size), np.zeros(y.size),
                             np.tile(CUT.phi - 90.0, (y.size, 1)))
    np.testing.assert_allclose(result.length, want, rtol=0, atol=1e-9)


def test_a_pass_along_minus_x_gives_at_phi_what_plus_x_gave_at_phi_plus_180():
    staircase = load_staircase(MODEL.format(1) + "stock.json")
    x = np.arange(110.0, 15.0, -4.0)
    cl = np.column_stack([x, np.full(x.size, 2.0), np.interp(x, [0, 130], [0.0, 20.0])])
    theta_a, theta_b = np.full(x.size, 6.0), np.full(x.size, -12.0)
    axes = np.column_stack([np.sin(np.radians(theta_b)), -np.sin(np.radians(theta_a)) * np.cos(np.radians(theta_b)),
                            np.cos(np.radians(theta_a)) * np.cos(np.radians(theta_b))])
    path = fed(cl, axes)
    assert np.allclose(path.alpha, 180.0)
    np.testing.assert_allclose(path.axes, axes, rtol=0, atol=1e-15)
    result = engage(staircase, TOOL, path, CUT)
    assert result.engaged.any()
    before = engage(staircase, TOOL, Toolpath(cl, theta_a, theta_b), CutSettings(0.1, 0, 180, 360, 5))
    np.testing.assert_allclose(result.length, before.length, rtol=0, atol=1e-9)
    want = reference_lengths(stair_data(staircase), cl[::3], theta_a[::3], theta_b[::3],
                             np.tile(CUT.phi + 180.0, (len(cl[::3]), 1)))
    np.testing.assert_allclose(result.length[::3], want, rtol=0, atol=1e-9)


@pytest.mark.parametrize("test", [1, 2, 4])
def test_model_test_passes_along_x_keep_their_frames(test):
    """Model tests 1, 2 and 4 feed along +x (1 and 2 by their CC points): α = 0, the angles as read."""
    path = load_toolpath(MODEL.format(test) + "toolpath.csv")
    assert not path.alpha.any() and path.inclination is None


def program_text(angle):
    """A CL program (a pocket's lead-in, two passes in opposite directions, a quarter arc, a ramp) turned
    about z by `angle` (rad): every position, CIRCLE centre and axis turned."""
    def point(x, y, z):
        px, py = rotate([x, y], angle)
        return f"{px!r},{py!r},{z!r}"
    tilt = rotate([0.15, -0.1], angle)
    axis = f"{tilt[0]!r},{tilt[1]!r},1.0"
    return "\n".join([
        "UNITS/MM", "CUTTER/12", "RAPID", f"GOTO/{point(-5, 5, 8)},{axis}", "FEDRAT/MMPM,600",
        f"GOTO/{point(-5, 5, 1.5)}", f"GOTO/{point(25, 5, 1.5)}", f"CIRCLE/{point(25, 10, 1.5)},0,0,1,5",
        f"GOTO/{point(30, 10, 1.5)}", f"GOTO/{point(30, 14, 2.0)}", f"GOTO/{point(-5, 14, 2.5)}",
        f"GOTO/{point(-5, 8, 1.0)}", "END", ""])


def turned_stock(angle):
    """A terraced stock (a block with a raised step and a pocket) turned about z by `angle` (rad)."""
    loops = [(0.0, 3.0, [square(-20, -10, 50, 30), ("circle", (10.0, 10.0), 3.0, 0.0)]),
             (3.0, 6.0, [square(5, -10, 50, 30)])]
    turned = []
    for z0, z1, slab in loops:
        turned.append((z0, z1, [("polygon", rotate(loop[1], angle)) if loop[0] == "polygon" else
                                ("circle", rotate(loop[1], angle), loop[2], loop[3] + angle) for loop in slab]))
    return to_stock(turned)


@pytest.mark.parametrize("degrees", [30.0, 90.0, 137.0, 200.0, 315.0])
def test_a_whole_set_up_turned_about_z_gives_the_same_results(tmp_path, degrees):
    results = []
    for angle in (0.0, math.radians(degrees)):
        path = tmp_path / f"p{angle}.apt"
        path.write_text(program_text(angle))
        toolpath = read_program(path).operation().toolpath()
        results.append(engage_terraced(turned_stock(angle), TOOL, toolpath, CutSettings(0.1, 0, 0, 360, 3)))
    plain, turned = results
    assert plain.engaged.any(axis=1).sum() > 50
    for name in ("length", "lep_l", "uep_l", "area", "h", "depth_of_cut"):
        np.testing.assert_allclose(getattr(turned, name), getattr(plain, name), rtol=0, atol=1e-9, err_msg=name)
    assert np.array_equal(turned.pieces, plain.pieces)


def test_alpha_rules():
    """The move ending at a point gives its α; the first point of a cut: the move leaving it; a zero move
    and a plunge keep the previous α; a path that never moves in plan view has α = 0."""
    points = np.array([[0, 0, 5], [0, 0, 1], [0, 0, 1], [3, 3, 1], [3, 3, 0], [3, 1, 0], [3, 1, 2]], dtype=float)
    alpha, unit = feed_frame(path_directions(points))
    np.testing.assert_allclose(alpha, [45, 45, 45, 45, 45, -90, -90], rtol=0, atol=1e-12)
    np.testing.assert_allclose(unit[1], [0, 0, -1])  # the plunge's own direction, for the inclination
    np.testing.assert_allclose(unit[0], [0, 0, -1])  # the first point: the move leaving it
    still, _ = feed_frame(path_directions(np.array([[0, 0, 5], [0, 0, 1]])))
    assert still.tolist() == [0.0, 0.0]
    starts = np.array([False, False, False, False, True, False, False])
    restarted, _ = feed_frame(path_directions(points, starts))  # no cutting move arrives at point 4
    np.testing.assert_allclose(restarted, [45, 45, 45, 45, -90, -90, -90], rtol=0, atol=1e-12)


def test_inclination_is_the_lead_towards_the_feed():
    """Level feed along +x with the axis leaning 10° towards it: 10°; sideways lean changes nothing; a
    plunge along a vertical axis: 90° (no chip for the side edge); a 30° ramp with a vertical tool: 30°."""
    lean = math.radians(10.0)
    axes = np.array([[math.sin(lean), 0, math.cos(lean)], [0, -math.sin(lean), math.cos(lean)], [0, 0, 1],
                     [0, 0, 1]])
    feed = np.array([[1, 0, 0], [1, 0, 0], [0, 0, -1], [math.cos(math.radians(30)), 0, math.sin(math.radians(30))]])
    np.testing.assert_allclose(inclinations(axes, feed), [10, 0, 90, 30], rtol=0, atol=1e-12)


def test_each_move_thins_its_own_chip(tmp_path):
    """In a CL program h = f·sin φ·cos(inclination of the CL point's own move), whatever the job's value."""
    path = tmp_path / "p.apt"
    path.write_text("CUTTER/12\nGOTO/0,0,10,0,0,1\nGOTO/0,0,2\nGOTO/20,0,2,0.17364817766693036,0,0.984807753012208\n"
                    "GOTO/20,0,2,0,0,1\nGOTO/20,20,2\n")
    toolpath = read_program(path).operation().toolpath()
    np.testing.assert_allclose(toolpath.inclination, [90, 90, 10, 0, 0], rtol=0, atol=1e-9)
    staircase = load_staircase(MODEL.format(1) + "stock.json")
    h = engage(staircase, TOOL, toolpath, CutSettings(0.1, 25.0, 0, 180, 30)).h
    phi = np.radians(np.arange(0, 181, 30))
    np.testing.assert_allclose(h[2], np.maximum(0.1 * np.sin(phi) * math.cos(math.radians(10)), 0), atol=1e-15)
    np.testing.assert_allclose(h[3:], np.tile(np.maximum(0.1 * np.sin(phi), 0), (2, 1)), atol=1e-15)
    assert np.abs(h[:2]).max() < 1e-15
