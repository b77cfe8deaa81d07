"""Feed scheduling (abm_workbench.scheduling) and the re-scheduled toolpath files.

The schedule is checked by recomputing the forces from scratch (the engine solves every
flute again) at the new feeds: every CL point at or under the limit, at least one on it,
none above the programmed feed. The quadratic bounds are checked against a dense scan of
the feed. APT and CSV files written with the feeds read back to the same CL points and feeds.
"""

import csv
import os
import re

import numpy as np
import pytest

from abm_workbench.engine import CutSettings, Tool
from abm_workbench.formats.apt import load_apt
from abm_workbench.formats.apt_writer import apt_text, write_feed_toolpath
from abm_workbench.formats.staircase_json import load_staircase
from abm_workbench.formats.toolpath_csv import load_toolpath
from abm_workbench.forces import material, pass_forces
from abm_workbench.jobs.inputs import load_path
from abm_workbench.scheduling import force_feed_bounds, programmed_feed, schedule

from .test_cl_rewrite import without_inserted
from .test_cli import M, case, run  # noqa: F401  (case is a fixture)

MODEL = os.path.join(os.path.dirname(__file__), "..", "..", "resources", "models", "model_test_1")
TOOL = Tool(12.0, 2, 30.0)
SETTINGS = CutSettings(0.1, 10.0, 0.0, 180.0, 1.0, spindle_rpm=4000.0)
COEFFICIENTS = material("al7075-t6")


@pytest.fixture(scope="module")
def model_pass():
    """(stock, toolpath, Forces at the programmed feed) of model test 1."""
    stock = load_staircase(os.path.join(MODEL, "stock.json"))
    path = load_toolpath(os.path.join(MODEL, "toolpath.csv"))
    return stock, path, pass_forces(stock, TOOL, path, SETTINGS, COEFFICIENTS)


def test_force_bounds_match_a_dense_scan():
    rng = np.random.default_rng(7)
    cutting = rng.normal(size=(200, 3)) * 800.0
    edge = rng.normal(size=(200, 3)) * 30.0
    limit = 60.0
    lo, hi, ok = force_feed_bounds(cutting, edge, limit)
    f = np.linspace(0.0, 0.5, 50001)
    norm = np.linalg.norm(f[None, :, None] * cutting[:, None, :] + edge[:, None, :], axis=-1)
    allowed = norm <= limit
    for i in range(200):
        if not ok[i]:
            assert not allowed[i].any()
            continue
        inside = (f >= lo[i]) & (f <= hi[i])
        # The scan agrees everywhere except within one scan step of the bounds.
        away = np.minimum(np.abs(f - lo[i]), np.abs(f - hi[i])) > 2e-5
        np.testing.assert_array_equal(allowed[i, away], inside[away])
        for bound in (lo[i], hi[i]):
            if 0.0 < bound < np.inf:
                assert np.linalg.norm(bound * cutting[i] + edge[i]) == pytest.approx(limit, rel=1e-12)


def test_force_bounds_without_cutting_part():
    lo, hi, ok = force_feed_bounds(np.zeros((2, 3)), np.array([[3.0, 4.0, 0.0], [30.0, 40.0, 0.0]]), 10.0)
    np.testing.assert_array_equal(ok, [True, False])
    assert lo[0] == 0.0 and hi[0] == np.inf


@pytest.mark.parametrize("fraction", [0.9, 0.6])
def test_force_schedule_keeps_every_cl_point_at_or_under_the_limit(model_pass, fraction):
    stock, path, forces = model_pass
    limit = fraction * forces.peak.max()
    plan = schedule(forces, limit)
    assert not plan.infeasible.any()
    # Recomputed from scratch at the new feeds, not through the schedule's own arithmetic.
    again = pass_forces(stock, TOOL, path, SETTINGS, COEFFICIENTS, feed=plan.feed)
    assert (again.peak <= limit + 1e-9).all()
    assert np.isclose(again.peak, limit, rtol=1e-9, atol=0.0).any()
    assert (plan.feed <= plan.programmed).all() and plan.reduced.any()
    # Where the feed was lowered, the CL point sits on the limit; elsewhere it was already under.
    np.testing.assert_allclose(again.peak[plan.reduced], limit, rtol=1e-9)
    assert (forces.peak[~plan.reduced] <= limit + 1e-9).all()
    np.testing.assert_allclose(plan.after, again.peak, rtol=1e-12)


def test_area_schedule(model_pass):
    stock, path, forces = model_pass
    limit = 0.7 * forces.area.max()
    plan = schedule(forces, limit, kind="area")
    again = pass_forces(stock, TOOL, path, SETTINGS, COEFFICIENTS, feed=plan.feed)
    assert (again.area.max(axis=1) <= limit + 1e-9).all()
    assert np.isclose(again.area.max(axis=1), limit, rtol=1e-9).any()
    assert (plan.feed <= plan.programmed).all()


def test_a_limit_the_edge_forces_alone_exceed_is_infeasible(model_pass):
    _, _, forces = model_pass
    edge_peak = np.linalg.norm(forces.edge, axis=-1).max(axis=1)
    limit = 0.5 * edge_peak.max()
    plan = schedule(forces, limit, min_feed=0.005)
    assert plan.infeasible[edge_peak > limit].all()
    np.testing.assert_array_equal(plan.feed[plan.infeasible], 0.005)
    assert (plan.after[~plan.infeasible] <= limit + 1e-9).all()


def test_a_floor_above_the_allowed_feed_is_infeasible(model_pass):
    _, _, forces = model_pass
    plan = schedule(forces, 0.5 * forces.peak.max(), min_feed=0.09)
    assert plan.infeasible.any()
    assert (plan.after[plan.infeasible] > plan.limit).all()
    np.testing.assert_array_equal(plan.feed[plan.infeasible], 0.09)


@pytest.mark.parametrize("limit, kind, message", [
    (0.0, "force", "force limit must be a positive number"),
    (float("nan"), "area", "area limit must be a positive number"),
    (10.0, "torque", "kind must be one of"),
])
def test_schedule_input_errors(model_pass, limit, kind, message):
    with pytest.raises(ValueError, match=message):
        schedule(model_pass[2], limit, kind=kind)


def test_programmed_feed_conversions():
    feed = np.array([np.nan, 800.0, 1600.0])
    np.testing.assert_allclose(programmed_feed(3, 0.05, feed=feed, unit="MMPM", flutes=2, spindle_rpm=4000.0),
                               [0.05, 0.1, 0.2])
    np.testing.assert_allclose(programmed_feed(3, 0.05, feed=feed / 4000.0, unit="MMPR", flutes=2),
                               [0.05, 0.1, 0.2])
    np.testing.assert_allclose(programmed_feed(3, 0.05, feed=feed / 25.4, unit="IPM", flutes=2, spindle_rpm=4000.0),
                               [0.05, 0.1, 0.2])
    np.testing.assert_array_equal(programmed_feed(2, 0.07), [0.07, 0.07])
    with pytest.raises(ValueError, match="MMPM need the spindle speed"):
        programmed_feed(3, 0.05, feed=feed, unit="MMPM", flutes=2)


@pytest.mark.parametrize("spindle_rpm, unit", [(4000.0, "MMPM"), (None, "MMPR")])
def test_apt_round_trip(model_pass, tmp_path, spindle_rpm, unit):
    _, path, forces = model_pass
    plan = schedule(forces, 0.6 * forces.peak.max())
    out = write_feed_toolpath(tmp_path / "p.apt", path, plan.feed, flutes=2, diameter=12.0, flute_length=30.0,
                              spindle_rpm=spindle_rpm, comment="re-scheduled\nsecond line")
    program = load_apt(out)
    np.testing.assert_array_equal(program.toolpath.cl, path.cl)
    np.testing.assert_allclose(program.toolpath.theta_a, path.theta_a, rtol=0.0, atol=1e-12)
    np.testing.assert_allclose(program.toolpath.theta_b, path.theta_b, rtol=0.0, atol=1e-12)
    np.testing.assert_array_equal(program.feed, plan.feed * 2 * (spindle_rpm or 1.0))
    assert program.feed_unit == unit and program.spindle_rpm == spindle_rpm
    assert (program.diameter, program.flute_length) == (12.0, 30.0)
    assert not program.warnings and not program.unknown
    back = programmed_feed(len(path), 1.0, feed=program.feed, unit=program.feed_unit, flutes=2,
                           spindle_rpm=program.spindle_rpm)
    np.testing.assert_allclose(back, plan.feed, rtol=1e-15)


def test_csv_round_trip(model_pass, tmp_path):
    _, path, forces = model_pass
    plan = schedule(forces, 0.6 * forces.peak.max())
    out = write_feed_toolpath(tmp_path / "p.csv", path, plan.feed, flutes=2, diameter=12.0, flute_length=30.0,
                              spindle_rpm=4000.0)
    again = load_toolpath(out)
    np.testing.assert_array_equal(again.cl, path.cl)
    np.testing.assert_allclose(again.axes, path.axes, rtol=0, atol=1e-15)
    np.testing.assert_allclose(again.alpha, path.alpha, rtol=0, atol=1e-12)
    with open(out, newline="") as file:
        rows = list(csv.DictReader(file))
    np.testing.assert_array_equal([float(r["feed_per_tooth"]) for r in rows], plan.feed)
    np.testing.assert_allclose([float(r["feed_mm_min"]) for r in rows], plan.feed * 8000.0, rtol=1e-15)


def test_apt_writer_refuses_a_zero_feed(model_pass, tmp_path):
    _, path, _ = model_pass
    with pytest.raises(ValueError, match="must be positive"):
        apt_text(path, 0.0, flutes=2, diameter=12.0, flute_length=30.0)
    target = tmp_path / "p.apt"
    target.write_text("old")
    with pytest.raises(ValueError):
        write_feed_toolpath(target, path, np.nan, flutes=2, diameter=12.0, flute_length=30.0)
    assert target.read_text() == "old" and os.listdir(tmp_path) == ["p.apt"]


SCHEDULE = ["schedule", "--stock", "stock.json", "--toolpath", "toolpath.csv", "--job", "job.json",
            "--material", "al7075-t6"]


def test_schedule_command_writes_apt_and_report(case, capsys):
    status, out, err = run(SCHEDULE + ["--max-force", "400", "--out", "out/P.apt", "--report", "rep"], capsys)
    assert (status, err) == (0, "")
    assert out.startswith(f"abm: {M} CL points: peak force ") and "(limit 400)" in out
    program = load_apt(case / "out" / "P.apt")
    path = load_toolpath("toolpath.csv")
    np.testing.assert_array_equal(program.toolpath.cl, path.cl)
    feed = program.feed / (2 * 4000.0)
    assert (feed <= 0.1 + 1e-15).all() and (feed < 0.1).any()
    again = pass_forces(load_staircase("stock.json"), TOOL, path, CutSettings(0.1, 10, 0, 180, 5, 4000),
                        COEFFICIENTS, feed=feed)
    assert (again.peak <= 400 + 1e-9).all() and np.isclose(again.peak.max(), 400, rtol=1e-9)
    assert sorted(os.listdir(case / "rep")) == ["forces.png", "index.html", "schedule.csv", "schedule.png"]
    assert "Feed schedule: test pass" in (case / "rep" / "index.html").read_text()


def test_schedule_command_area_to_csv_and_reading_apt_feeds(case, capsys):
    status, _, err = run(SCHEDULE + ["--max-area", "0.3", "--out", "P.csv"], capsys)
    assert (status, err) == (0, "")
    assert len(load_toolpath("P.csv")) == M
    # An APT file's own feeds are the programmed feed, CL point by CL point.
    path = load_toolpath("toolpath.csv")
    write_feed_toolpath("in.apt", path, np.linspace(0.05, 0.1, M), flutes=2, diameter=12, flute_length=30,
                        spindle_rpm=4000)
    status, out, err = run(["schedule", "--stock", "stock.json", "--toolpath", "in.apt", "--job", "job.json",
                            "--ktc", "700", "--krc", "200", "--kac", "100", "--max-force", "1e6", "--out", "P.apt"],
                           capsys)
    assert status == 0 and "feed lowered at 0 CL points" in out
    np.testing.assert_allclose(load_apt("P.apt").feed, load_apt("in.apt").feed, rtol=1e-15)


def test_schedule_warns_about_cl_points_that_cannot_meet_the_limit(case, capsys):
    status, out, err = run(SCHEDULE + ["--max-force", "5", "--min-feed", "0.02", "--out", "P.apt"], capsys)
    assert status == 0
    assert err.startswith("abm: warning: ") and "cannot keep the force at or under 5 N" in err
    assert "they get the minimum feed: CL " in err
    np.testing.assert_allclose(load_apt("P.apt").feed[load_apt("P.apt").feed < 8000 * 0.1], 0.02 * 8000)


@pytest.mark.parametrize("options, message", [
    (["--max-force", "-1", "--out", "P.apt"], "abm: error: --max-force: must be a positive number"),
    (["--max-area", "1", "--min-feed", "-0.1", "--out", "P.apt"], "abm: error: --min-feed: must be a positive"),
    (["--max-area", "1", "--min-feed", "0", "--out", "P.apt"], "abm: error: --min-feed: must be a positive"),
    (["--max-force", "100", "--out", "P.txt"],
     "abm: error: --out: must end in .apt, .cls, .csv or (for a FreeCAD CAM Job) .FCStd, got P.txt"),
    (["--max-force", "100", "--max-area", "1", "--out", "P.apt"], "abm: error: argument --max-area: not allowed"),
    (["--out", "P.apt"], "abm: error: one of the arguments --max-force --max-area is required"),
    (["--max-force", "100", "--out", "toolpath.csv"], "abm: error: toolpath.csv: is an input"),
])
def test_schedule_option_errors(case, capsys, options, message):
    status, _, err = run(SCHEDULE + options, capsys)
    assert status == 2 and message in err, err
    assert sorted(os.listdir(case)) == ["job.json", "stock.json", "toolpath.csv"]


def test_helical_schedule_keeps_the_limit(model_pass):
    stock, path, _ = model_pass
    tool = Tool(12.0, 2, 30.0, 30.0)
    forces = pass_forces(stock, tool, path, SETTINGS, COEFFICIENTS)
    limit = 0.7 * forces.peak.max()
    plan = schedule(forces, limit)
    again = pass_forces(stock, tool, path, SETTINGS, COEFFICIENTS, feed=plan.feed)
    assert (again.peak <= limit + 1e-9).all() and np.isclose(again.peak, limit, rtol=1e-9).any()


def test_schedule_writes_a_cl_program_back_in_its_own_fedrat_form_under_the_limit(case, capsys):
    # A SOLIDWORKS CAM style program: its post reads the first field of FEDRAT as the feed.
    path = load_toolpath("toolpath.csv")
    write_feed_toolpath("in.apt", path, 0.1, flutes=2, diameter=12, flute_length=30, spindle_rpm=4000)
    original = open("in.apt").read().replace("FEDRAT/MMPM,800\n", "FEDRAT/800.,MMPM\n")
    open("in.apt", "w").write(original)
    status, _, _ = run(["schedule", "--stock", "stock.json", "--toolpath", "in.apt", "--job", "job.json",
                        "--material", "al7075-t6", "--max-force", "400", "--out", "P.apt"], capsys)
    assert status == 0
    kept, inserted = without_inserted(open("P.apt").read(), original)
    assert kept == original and len(inserted) > 1
    for line in inserted:
        assert re.fullmatch(r"FEDRAT/(?:[0-9]+\.|[0-9]+\.[0-9]*[1-9]),MMPM\n", line), line
    rates = load_apt("P.apt").feed
    assert set(rates) <= {float(line[7:].split(",")[0]) for line in inserted} | {800.0}
    feed = rates / (2 * 4000.0)
    program_path, _ = load_path("P.apt")  # the program's own frames and inclinations, as schedule took them
    again = pass_forces(load_staircase("stock.json"), TOOL, program_path, CutSettings(0.1, 10, 0, 180, 5, 4000),
                        COEFFICIENTS, feed=feed)
    # Rounded down at the file's 6 decimals: rounding to the nearest would exceed the limit by up to 2.5e-7 N.
    assert (again.peak <= 400 + 1e-9).all() and (feed < 0.1).any()
