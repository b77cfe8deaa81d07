"""The Z-map baseline: convergence to ABM, the removal rule, the command line."""

import json
import math

import numpy as np
import pytest

from abm_workbench import cli
from abm_workbench.engine import SURFACES, CutSettings, Staircase, Tool, Toolpath, engage
from abm_workbench.engine.zmap import ZMap, tool_floor, zmap_engage
from abm_workbench.formats.results_csv import RESULT_COLUMNS, read_results

THETA_B = 10.0
TOOL = Tool(diameter=12, flutes=2, flute_length=20)
SETTINGS = CutSettings(feed_per_tooth=0.1, inclination=10, phi_start=0, phi_end=180, phi_step=5)
#: The whole revolution: the rear half climbs back over the wall behind the tool.
TURN = CutSettings(feed_per_tooth=0.1, inclination=10, phi_start=0, phi_end=360, phi_step=5)


def straight_staircase():
    """Three sections, straight walls at x = 20 and 32 (up, then down), x 0..50, y -12..12."""
    walls = [[[x, y] for y in np.linspace(-12, 12, 6)] for x in (20.0, 32.0)]
    return Staircase(0.0, 50.0, -12.0, 12.0, -6.0, np.array([2.0, 5.0, 1.0]), walls)


def single_point(theta_a=4.0, theta_b=THETA_B):
    """One CL point beside the down-step at x = 32: over the revolution the UEP lies on the top
    of section 1, on the wall at 32 (Table 1 A.4) and, behind, the edge climbs over the wall
    at 20 (B.1, B.3 with two pieces)."""
    return Toolpath(np.array([[25.5, 0.5, -1.0]]), [theta_a], [theta_b])


def test_length_converges_to_abm_within_the_grid_bound():
    stock, path = straight_staircase(), single_point()
    exact = engage(stock, TOOL, path, TURN)
    assert exact.engaged.all() and exact.pieces.max() == 2
    assert {"top", "straight_wall"} <= set(exact.surface_names().ravel())
    errors = {}
    for grid in (0.4, 0.05):
        zmap = zmap_engage(stock, TOOL, path, TURN, grid=grid)
        error = np.abs(zmap.length - exact.length)
        errors[grid] = error
        # Classification differs from the truth only where the sample and its cell centre lie on
        # either side of a wall (|x − x_w| < c_x/2 ≤ grid/2: an l range of grid/|w_x| per wall);
        # the cell-section is monotone along the (straight) edge, so the Z-map's inside set has
        # at most one run per section, and each run end is within s/2 of it (half-step ends).
        w_x = math.sin(math.radians(THETA_B))
        bound = stock.n_sections * grid + len(stock.walls) * grid / w_x
        assert error.max() <= bound + 1e-9, (grid, error.max(), bound)
    assert errors[0.05].max() < errors[0.4].max()
    assert errors[0.05].mean() < errors[0.4].mean()
    assert errors[0.05].mean() < 0.1


def test_edge_step_defaults_to_grid_and_refines_alone():
    stock, path = straight_staircase(), single_point()
    exact = engage(stock, TOOL, path, SETTINGS)
    same = zmap_engage(stock, TOOL, path, SETTINGS, grid=0.1)
    explicit = zmap_engage(stock, TOOL, path, SETTINGS, grid=0.1, edge_step=0.1)
    np.testing.assert_array_equal(same.length, explicit.length)
    # An upright tool well inside one section: only the sampling at the ends matters, and the
    # half-step ends make the length exact whenever the run reaches l = 0.
    upright = Toolpath(np.array([[8.0, 0.0, -1.0]]), [0.0], [0.0])
    exact = engage(stock, TOOL, upright, SETTINGS)
    for step in (0.3, 0.07):
        zmap = zmap_engage(stock, TOOL, upright, SETTINGS, grid=0.5, edge_step=step)
        assert np.abs(zmap.length - exact.length).max() <= 0.5 * step + 1e-9
        np.testing.assert_array_equal(zmap.pieces, 1)
        assert set(np.asarray(SURFACES)[zmap.uep_surface].ravel()) == {"top"}


def test_fields_match_engage_shapes_and_meaning():
    stock, path = straight_staircase(), single_point()
    exact = engage(stock, TOOL, path, TURN)
    zmap = zmap_engage(stock, TOOL, path, TURN, grid=0.05)
    for name in ("phi", "h", "lep_l", "uep_l", "length", "pieces", "uep_surface", "uep_section", "uep_wall",
                 "case", "segment", "area", "lep_xyz", "uep_xyz", "depth_of_cut"):
        assert getattr(zmap, name).shape == getattr(exact, name).shape, name
        assert getattr(zmap, name).dtype == getattr(exact, name).dtype, name
    np.testing.assert_array_equal(zmap.case, 0)
    np.testing.assert_allclose(zmap.area, zmap.length * zmap.h)
    np.testing.assert_allclose(zmap.lep_l, exact.lep_l, atol=0.05 + 1e-9)
    # UEP: the same surface, section and wall as ABM here (the walls are straight), within a
    # step plus the reach of a half cell across a wall (0.025 / sin 10° along the edge).
    np.testing.assert_array_equal(zmap.uep_surface, exact.uep_surface)
    np.testing.assert_array_equal(zmap.uep_section, exact.uep_section)
    np.testing.assert_array_equal(zmap.uep_wall, exact.uep_wall)
    np.testing.assert_array_equal(zmap.segment, exact.segment)
    assert np.abs(zmap.uep_l - exact.uep_l).max() < 0.05 + 0.025 / math.sin(math.radians(THETA_B))
    np.testing.assert_array_equal(zmap.pieces, exact.pieces)
    np.testing.assert_allclose(zmap.depth_of_cut, exact.depth_of_cut, atol=0.05)
    assert [s["surface"] for s in zmap.segments(0)] == ["top", "straight_wall", "top"]


def brute_floor(x, y, base, axis, radius, length, dz=2e-3):
    """Lowest z of the cylinder on the vertical line (x, y): scan z in steps of dz for the first
    point inside (radial distance ≤ R, 0 ≤ axial ≤ L), then bisect the step before it; inf if none."""
    def inside(z):
        r = np.stack(np.broadcast_arrays(x - base[0], y - base[1], z - base[2]), axis=-1)
        along = r @ axis
        radial = np.linalg.norm(r - along[..., None] * axis, axis=-1)
        return (along >= 0.0) & (along <= length) & (radial <= radius)

    z = np.arange(base[2] - radius - 1.0, base[2] + length + radius + 1.0, dz)
    hit = np.flatnonzero(inside(z))
    if hit.size == 0:
        return np.inf
    low, high = z[hit[0]] - dz, z[hit[0]]
    for _ in range(40):
        middle = 0.5 * (low + high)
        low, high = (low, middle) if inside(middle) else (middle, high)
    return high


@pytest.mark.parametrize("theta_a, theta_b, cl", [
    (0.0, 0.0, (5.3, 0.7, 1.4)), (7.0, -12.0, (5.3, 0.7, 1.4)), (-25.0, 30.0, (5.3, 0.7, 1.4)),
    (60.0, 5.0, (5.3, 0.7, 1.4)), (20.0, -15.0, (0.8, -4.6, 0.5)),  # the last one overhangs a corner
])
def test_removal_lowers_exactly_the_cells_under_the_tool(theta_a, theta_b, cl):
    stock = Staircase(0.0, 12.0, -5.0, 5.0, -8.0, np.array([1.0, 3.0]),
                      [[[6.0, y] for y in np.linspace(-5, 5, 6)]])
    zmap = ZMap(stock, grid=0.5)
    assert (zmap.nx, zmap.ny) == (24, 20)
    before = zmap.height.copy()
    path = Toolpath(np.array([cl]), [theta_a], [theta_b])
    axis = np.array([math.sin(math.radians(theta_b)), -math.sin(math.radians(theta_a)) * math.cos(math.radians(theta_b)),
                     math.cos(math.radians(theta_a)) * math.cos(math.radians(theta_b))])
    radius, length = 2.5, 4.0
    changed = zmap.remove(path.cl[0], axis, radius, length)
    brute = np.array([[brute_floor(x, y, path.cl[0], axis, radius, length) for y in zmap.y] for x in zmap.x])
    lowered = brute < before
    assert changed == lowered.sum() > 0
    np.testing.assert_array_equal(zmap.height[~lowered], before[~lowered])
    np.testing.assert_allclose(zmap.height[lowered], brute[lowered], atol=1e-9)
    # The closed form itself, on every cell (not only the lowered ones).
    floor = tool_floor(zmap.x[:, None], zmap.y[None, :], path.cl[0], axis, radius, length)
    np.testing.assert_array_equal(np.isinf(floor), np.isinf(brute))
    np.testing.assert_allclose(floor[np.isfinite(floor)], brute[np.isfinite(brute)], atol=1e-9)


def test_removal_changes_what_later_cl_points_see():
    stock = straight_staircase()
    # The second CL point 2 mm behind and 0.5 mm above the first, upright: its leading edges
    # at 17°..163° lie more than a quarter mm inside the disc the first one cleared.
    path = Toolpath(np.array([[8.0, 0.0, -1.0], [6.0, 0.0, -0.5]]), [0.0, 0.0], [0.0, 0.0])
    kept = zmap_engage(stock, TOOL, path, SETTINGS, grid=0.1, remove=False)
    assert kept.engaged.all()
    cut = zmap_engage(stock, TOOL, path, SETTINGS, grid=0.1)
    np.testing.assert_array_equal(cut.length[0], kept.length[0])
    cleared = (SETTINGS.phi >= 20) & (SETTINGS.phi <= 160)
    assert not cut.engaged[1, cleared].any()
    assert cut.engaged[1, [0, -1]].all()  # at the sides the edge meets material the first left


def test_bad_arguments_raise():
    stock, path = straight_staircase(), single_point()
    for options in ({"grid": 0}, {"grid": -1}, {"grid": float("nan")}, {"edge_step": 0}, {"grid": 1e-5}):
        with pytest.raises(ValueError):
            zmap_engage(stock, TOOL, path, SETTINGS, **options)


@pytest.fixture
def case(tmp_path, monkeypatch):
    """stock.json and toolpath.csv of a small pass over a step and a curved wall, in tmp_path (the cwd)."""
    y = [-15.0, -9.0, -3.0, 3.0, 9.0, 15.0]
    stock = {
        "format": "abm-staircase/1", "units": "mm", "base_z": -20, "x_min": 0, "x_max": 130,
        "y_min": -15, "y_max": 15,
        "sections": [{"z_top": 4.0}, {"z_top": 6.5, "wall": [[40, v] for v in y]},
                     {"z_top": 3.0, "wall": [[80 + 3 * np.sin(v / 5), v] for v in y]}],
    }
    (tmp_path / "stock.json").write_text(json.dumps(stock))
    rows = [f"{x:.6f},0,{x / 60 - 1:.6f},0,10" for x in np.linspace(10, 120, 6)]
    (tmp_path / "toolpath.csv").write_text("x,y,z,theta_a,theta_b\n" + "\n".join(rows) + "\n")
    monkeypatch.chdir(tmp_path)
    return tmp_path


ARGS = ["engage", "--stock", "stock.json", "--toolpath", "toolpath.csv", "--diameter", "12", "--flutes", "2",
        "--flute-length", "30", "--feed-per-tooth", "0.1", "--phi-step", "10"]


def test_cli_zmap_end_to_end(case, capsys):
    assert cli.main(ARGS + ["--out", "A.csv"]) == 0
    assert cli.main(ARGS + ["--out", "Z.csv", "--method", "zmap", "--grid", "0.25", "--edge-step", "0.1"]) == 0
    out, err = capsys.readouterr()
    assert err == ""
    assert "(Z-map, grid 0.25 mm, edge step 0.1 mm)" in out.splitlines()[2]
    assert (case / "Z.summary.csv").exists()
    abm, zmap = read_results(case / "A.csv"), read_results(case / "Z.csv")
    assert list(zmap) == list(RESULT_COLUMNS)
    np.testing.assert_array_equal(zmap["cl"], abm["cl"])
    np.testing.assert_array_equal(zmap["phi_deg"], abm["phi_deg"])
    assert set(zmap["case"]) == {"none"}
    # CL points 2.2 mm apart: the later ones cut what the earlier left, so compare loosely.
    assert np.nanmean(np.abs(np.asarray(zmap["length"], float) - np.asarray(abm["length"], float))) < 1.0
    assert cli.main(ARGS + ["--out", "D.csv", "--method", "zmap"]) == 0
    assert "(Z-map, grid 0.2 mm, edge step 0.2 mm)" in capsys.readouterr()[0]


@pytest.mark.parametrize("options, message", [
    (["--grid", "0.2"], "--grid: applies to the Z-map method"),
    (["--method", "abm", "--edge-step", "0.1"], "--edge-step: applies to the Z-map method"),
    (["--method", "zmap", "--grid", "0"], "--grid: must be a positive"),
    (["--method", "zmap", "--grid", "nan"], "--grid: must be a finite number, got nan"),
    (["--method", "zmap", "--edge-step", "-0.1"], "--edge-step: must be a positive"),
    (["--method", "zmap", "--grid", "0.00001"], "--grid: 1e-05 mm gives the stock 39,000,000,000,000 Z-map cells, "
                                                "more than the Z-map holds (50,000,000)"),
    (["--method", "fast"], "invalid choice"),
    (["--method", "zmap", "--grid", "x"], "invalid float value"),
])
def test_cli_bad_options_exit_2(case, capsys, options, message):
    assert cli.main(ARGS + ["--out", "R.csv"] + options) == 2
    assert message in capsys.readouterr()[1]
    assert not (case / "R.csv").exists()


@pytest.mark.parametrize("grid", [0.7, 0.25])
def test_grid_heights_are_the_staircase_at_the_cell_centres(grid):
    y = np.linspace(-15, 15, 6)
    stock = Staircase(0.0, 130.0, -15.0, 15.0, -20.0, np.array([4.0, 6.5, 3.0, 5.0]),
                      [[[40.0, v] for v in y], [[80 + 3 * np.sin(v / 5), v] for v in y],
                       [[100 + 0.02 * v * v, v] for v in y]])
    zmap = ZMap(stock, grid)
    assert zmap.cell_x <= grid and zmap.cell_y <= grid
    assert zmap.nx * zmap.cell_x == pytest.approx(130.0) and zmap.ny * zmap.cell_y == pytest.approx(30.0)
    sections = stock.section_at(zmap.x[:, None], zmap.y[None, :])
    np.testing.assert_array_equal(zmap.section, sections)
    np.testing.assert_array_equal(zmap.height, stock.z_top[sections])
    single = ZMap(Staircase(0.0, 3.0, 0.0, 2.0, -1.0, np.array([1.0]), np.empty((0, 6, 2))), grid)
    np.testing.assert_array_equal(single.height, 1.0)


def test_a_helical_tool_is_refused():
    """The Z-map samples a straight edge: a helix angle is an error, not silently ignored."""
    stock = Staircase(0, 40, 0, 30, 0, [10.0], np.empty((0, 6, 2)))
    path = Toolpath(np.array([[20.0, 15.0, 0.0]]), np.zeros(1), np.zeros(1))
    with pytest.raises(ValueError, match="helix angle of 30 deg"):
        zmap_engage(stock, Tool(10, 2, 20, helix=30.0), path, CutSettings(0.1))
