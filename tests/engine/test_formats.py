"""File formats: staircase JSON, toolpath CSV, results CSV; every bad input names file and line/item."""

import json
import math
import os
import time

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from abm_workbench.engine import CutSettings, Staircase, Tool, Toolpath, engage
from abm_workbench.errors import InputError
from abm_workbench.formats import replacing
from abm_workbench.formats import results_csv
from abm_workbench.formats.results_csv import (
    RESULT_COLUMNS, SUMMARY_COLUMNS, TOOLPATH_COLUMNS, read_results, summary_path, write_results,
)
from abm_workbench.formats.staircase_json import dump_staircase, load_staircase
from abm_workbench.formats.toolpath_csv import load_toolpath

Y6 = [-15.0, -9.0, -3.0, 3.0, 9.0, 15.0]
STRAIGHT_WALL = [[40.0, y] for y in Y6]
CURVED_WALL = [[80.0 + 3.0 * np.sin(y / 5.0), y] for y in Y6]


def stock_data():
    """A valid abm-staircase/1 document: three sections, a straight and a curved wall."""
    return {
        "format": "abm-staircase/1", "units": "mm", "base_z": -20, "x_min": 0, "x_max": 130,
        "y_min": -15, "y_max": 15,
        "sections": [{"z_top": 4.0}, {"z_top": 6.5, "wall": STRAIGHT_WALL}, {"z_top": 3.0, "wall": CURVED_WALL}],
    }


def files_left(folder):
    """Names in `folder`, to check that nothing (not even a temporary) was left behind."""
    return sorted(os.listdir(folder))


# ---------------------------------------------------------------- staircase JSON

def test_staircase_round_trip(tmp_path):
    stock = Staircase(-1.5, 130.25, -15, 15, -20, [4.0, 6.5, 3.0], [STRAIGHT_WALL, CURVED_WALL])
    path = tmp_path / "stock.json"
    dump_staircase(stock, path)
    assert files_left(tmp_path) == ["stock.json"]
    assert json.loads(path.read_text())["format"] == "abm-staircase/1"
    again = load_staircase(path)
    for name in ("x_min", "x_max", "y_min", "y_max", "base_z"):
        assert getattr(again, name) == getattr(stock, name)
    np.testing.assert_array_equal(again.z_top, stock.z_top)
    np.testing.assert_array_equal(again.wall_points, stock.wall_points)


@given(
    z_top=st.lists(st.floats(-19.5, 50.0), min_size=1, max_size=5),
    wiggle=st.floats(0.0, 2.0),
    x_max=st.floats(100.0, 1e4),
)
def test_staircase_round_trip_is_exact(tmp_path_factory, z_top, wiggle, x_max):
    walls = [[[20.0 * j + wiggle * np.sin(y + j), y] for y in Y6] for j in range(1, len(z_top))]
    stock = Staircase(0.0, x_max, -15.0, 15.0, -20.0, z_top, walls)
    path = tmp_path_factory.mktemp("round_trip") / "stock.json"
    dump_staircase(stock, path)
    again = load_staircase(path)
    assert again.x_max == stock.x_max
    np.testing.assert_array_equal(again.z_top, stock.z_top)
    np.testing.assert_array_equal(again.wall_points, stock.wall_points)


def test_staircase_of_one_section(tmp_path):
    data = stock_data()
    data["sections"] = [{"z_top": 4}]
    path = tmp_path / "stock.json"
    path.write_text(json.dumps(data))
    stock = load_staircase(path)
    assert stock.n_sections == 1 and stock.wall_points.shape == (0, 6, 2)


def _set(key, value):
    def change(data):
        data[key] = value
    return change


def _set_section(j, key, value):
    def change(data):
        data["sections"][j][key] = value
    return change


def _drop(key):
    def change(data):
        del data[key]
    return change


@pytest.mark.parametrize(
    "change, message",
    [
        (_set("format", "abm-staircase/2"), "format must be 'abm-staircase/1', got \"abm-staircase/2\""),
        (_set("units", "inch"), "units must be 'mm', got \"inch\""),
        (_drop("format"), "missing key 'format' (a staircase file starts with \"format\": \"abm-staircase/1\")"),
        (_drop("base_z"), "missing key 'base_z'"),
        (_drop("sections"), "missing key 'sections'"),
        (_set("colour", "red"), "unknown key 'colour'"),
        (_set("x_min", True), "x_min: must be a number, got true"),
        (_set("x_max", "130"), "x_max: must be a number, got \"130\""),
        (_set("y_min", None), "y_min: must be a number, got null"),
        (_set("base_z", math.nan), "base_z: must be a finite number, got nan"),  # written as NaN
        (_set("base_z", -math.inf), "base_z: must be a finite number, got -inf"),  # written as -Infinity
        (_set("sections", []), "sections must be a non-empty list"),
        (_set("sections", {"z_top": 1}), "sections must be a non-empty list"),
        (_set_section(0, "wall", STRAIGHT_WALL),
         "sections[0]: the first section starts at x_min and must not have a wall"),
        (_set_section(1, "colour", "red"), "sections[1]: unknown key 'colour'"),
        (_set_section(2, "z_top", "high"), "sections[2].z_top: must be a number, got \"high\""),
        (_set_section(1, "wall", STRAIGHT_WALL[:5]), "sections[1].wall: a wall needs six [x, y] points, got 5 items"),
        (_set_section(1, "wall", 40), "sections[1].wall: a wall needs six [x, y] points, got 40"),
        (_set_section(2, "wall", [*CURVED_WALL[:3], [1, 2, 3], *CURVED_WALL[4:]]),
         "sections[2].wall[3]: expected an [x, y] pair, got [1, 2, 3]"),
        (_set_section(2, "wall", [*CURVED_WALL[:3], [False, 2], *CURVED_WALL[4:]]),
         "sections[2].wall[3][0]: must be a number, got false"),
        # The Staircase constructor's checks, named by item.
        (_set_section(2, "wall", [[30.0, y] for y in Y6]),
         "sections[2].wall: x = 30 at y = -15 is not beyond the wall of section 1"),
        (_set_section(2, "wall", [[140.0, y] for y in Y6]),
         "sections[2].wall: x = 140 at y = -15 is not below x_max (130.0)"),
        (_set_section(1, "wall", [[40.0, 0.0]] * 6), "sections[1].wall: wall points need six distinct y values"),
        (_set_section(1, "z_top", -25), "sections[1]: z_top -25.0 must be above base_z -20.0"),
        (_set("x_min", 200), "x_min (200.0) must be below x_max (130.0)"),
    ],
)
def test_staircase_bad_items(tmp_path, change, message):
    data = stock_data()
    change(data)
    path = tmp_path / "stock.json"
    path.write_text(json.dumps(data))
    with pytest.raises(InputError) as error:
        load_staircase(path)
    assert str(error.value).startswith(f"{path}: ")
    assert message in str(error.value)


def test_staircase_two_unknown_keys_are_both_named(tmp_path):
    data = stock_data()
    data.update(colour="red", weight=3)
    path = tmp_path / "stock.json"
    path.write_text(json.dumps(data))
    with pytest.raises(InputError, match="unknown keys 'colour', 'weight'"):
        load_staircase(path)


@pytest.mark.parametrize(
    "text, message",
    [
        ('{\n  "format": "abm-staircase/1",\n  "units": "mm",,\n}', ":3:17: invalid JSON: Expecting property name"),
        ("", ":1:1: invalid JSON: Expecting value"),
        ("[1, 2]", ": expected a JSON object {...}, got list"),
    ],
)
def test_staircase_bad_json(tmp_path, text, message):
    path = tmp_path / "stock.json"
    path.write_text(text)
    with pytest.raises(InputError) as error:
        load_staircase(path)
    assert str(error.value).startswith(f"{path}{message}")


def test_staircase_unreadable(tmp_path):
    with pytest.raises(InputError, match="nope.json: cannot read: No such file"):
        load_staircase(tmp_path / "nope.json")
    path = tmp_path / "latin1.json"
    path.write_bytes('{"units": "\xb5m"}'.encode("latin-1"))
    with pytest.raises(InputError, match="latin1.json: not UTF-8 text"):
        load_staircase(path)


# ---------------------------------------------------------------- toolpath CSV

def write_csv(tmp_path, text, name="path.csv"):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_toolpath_with_angles(tmp_path):
    """The angles give the axis in the part frame; the frames turn to the feed (the chord 10, 0.5 in plan view)."""
    path = write_csv(tmp_path, "x,y,z,theta_a,theta_b\n10,0,-1,0,10\n20,0.5,-1.5,-5,10\n")
    toolpath = load_toolpath(path)
    np.testing.assert_array_equal(toolpath.cl, [[10, 0, -1], [20, 0.5, -1.5]])
    feed = math.degrees(math.atan2(0.5, 10.0))
    np.testing.assert_allclose(toolpath.alpha, [feed, feed], rtol=1e-15)
    a, b = np.radians([0.0, -5.0]), np.radians([10.0, 10.0])  # Rx(θ_A)·Ry(θ_B)·e_z, in the part frame
    axes = np.stack([np.sin(b), -np.sin(a) * np.cos(b), np.cos(a) * np.cos(b)], axis=1)
    np.testing.assert_allclose(toolpath.axes, axes, rtol=0, atol=1e-15)
    assert toolpath.cc is None and toolpath.inclination is None


def test_toolpath_along_x_keeps_its_angles_bit_for_bit(tmp_path):
    """A pass feeding along +x (α = 0) keeps the angles of its columns as written."""
    path = write_csv(tmp_path, "x,y,z,theta_a,theta_b\n10,0,-1,0.1,10\n20,0,-1.5,-5,10.3\n")
    toolpath = load_toolpath(path)
    assert toolpath.theta_a.tolist() == [0.1, -5] and toolpath.theta_b.tolist() == [10, 10.3]
    assert not toolpath.alpha.any()


def test_toolpath_with_axes_any_order_case_and_comments(tmp_path):
    text = (
        "# pass 1, CL points in mm\n"
        " K , X,i ,Y, j,Z ,ZC,xc,yc\n"
        "\n"
        "1,10,0,0,0,-1,-2,10.5,0\n"
        "   # a comment between rows\n"
        "2,20,1,0.5,-0.5,-1.5,-2.5,20.5,0.5\n"
    )
    toolpath = load_toolpath(write_csv(tmp_path, text))
    feed = math.degrees(math.atan2(0.5, 10.0))  # the CC points' chord in plan view
    expected = Toolpath.from_axes([[10, 0, -1], [20, 0.5, -1.5]], [[0, 0, 1], [1, -0.5, 2]],
                                  [[10.5, 0, -2], [20.5, 0.5, -2.5]], [feed, feed])
    np.testing.assert_allclose(toolpath.alpha, expected.alpha, rtol=1e-15)
    np.testing.assert_array_equal(toolpath.cl, expected.cl)
    np.testing.assert_allclose(toolpath.theta_a, expected.theta_a)
    np.testing.assert_allclose(toolpath.theta_b, expected.theta_b)
    np.testing.assert_array_equal(toolpath.cc, expected.cc)


@pytest.mark.parametrize(
    "text, message",
    [
        ("", ": empty file; expected a header such as 'x,y,z,theta_a,theta_b'"),
        ("# only a comment\n\n", ": empty file"),
        ("x,y,z,theta_a,theta_b\n", ": no CL points: the file has a header but no rows"),
        ("x,y,z,theta_a,theta_b,w\n1,2,3,0,0,1\n", ":1: unknown column 'w'"),
        ("# units mm\nx,y,z,theta_a,theta_b,feed,speed\n", ":2: unknown columns 'feed', 'speed'"),
        ("x,y,theta_a,theta_b\n1,2,0,0\n", ":1: missing column 'z' of the position (x, y, z)"),
        ("x,y,z,X,theta_a,theta_b\n", ":1: duplicate column 'x'"),
        ("x,y,z,theta_a\n1,2,3,0\n", ":1: missing column 'theta_b' of the tool angles"),
        ("x,y,z\n1,2,3\n", ":1: missing column 'theta_a' of the tool angles"),
        ("x,y,z,i,j\n1,2,3,0,0\n", ":1: missing column 'k' of the tool axis"),
        ("x,y,z,i,j,k,theta_a,theta_b\n", ":1: give the tool orientation as theta_a, theta_b or as i, j, k, not both"),
        ("x,y,z,theta_a,theta_b,xc,yc\n", ":1: missing column 'zc' of the cutter-contact point"),
        ("x,y,z,theta_a,theta_b\n1,2,3,0,0\n1,2,3,0\n", ":3: expected 5 fields (x,y,z,theta_a,theta_b), got 4"),
        ("x,y,z,theta_a,theta_b\n" + "1,2,3,0,0\n" * 5 + "1,2,abc,0,0\n", ":7: column 'z': 'abc' is not a number"),
        ("x,y,z,theta_a,theta_b\n1,2,,0,0\n", ":2: column 'z': '' is not a number"),
        ("x,y,z,theta_a,theta_b\n1,2,3,nan,0\n", ":2: column 'theta_a': 'nan' is not a finite number"),
        ("x,y,z,theta_a,theta_b\n1,2,3,0, -inf\n", ":2: column 'theta_b': '-inf' is not a finite number"),
        # Engine checks, CL index translated to the line (comments and blank lines counted).
        ("x,y,z,theta_a,theta_b\n1,2,3,0,0\n# skip\n\n1,2,3,0,95\n",
         ":5: theta_b = 95.0 must be within [-90, 90] degrees"),
        ("x,y,z,theta_a,theta_b\n1,2,3,0,0\n1,2,3,0,0\n1,2,3,0,0\n1,2,3,0,0\n1,2,3,-190,0\n",
         ":6: theta_a = -190.0 must be within [-180, 180] degrees"),
        ("x,y,z,i,j,k\n1,2,3,0,0,1\n1,2,3,0,0,0\n", ":3: tool axis [0.0, 0.0, 0.0] is zero or not finite"),
    ],
)
def test_toolpath_bad_input(tmp_path, text, message):
    path = write_csv(tmp_path, text)
    with pytest.raises(InputError) as error:
        load_toolpath(path)
    assert str(error.value).startswith(f"{path}{message}")


def test_toolpath_missing_file(tmp_path):
    with pytest.raises(InputError, match="nope.csv: cannot read"):
        load_toolpath(tmp_path / "nope.csv")


# ---------------------------------------------------------------- results CSV

STOCK = Staircase(0, 130, -15, 15, -20, [4.0, 6.5, 3.0], [STRAIGHT_WALL, CURVED_WALL])
TOOL = Tool(12, 2, 30)


def small_engagement():
    """Engagement of 4 CL points × 19 angles over STOCK; CL 0 is above the stock."""
    cl = [[20, 0, 50], [20, 0, -1], [40, 2, 0], [82, -1, -2]]
    toolpath = Toolpath(cl, [0, 0, -5, 3], [0, 10, 10, 10])
    return engage(STOCK, TOOL, toolpath, CutSettings(0.1, 10, 0, 180, 10)), toolpath


def test_results_columns_rows_and_values(tmp_path):
    engagement, toolpath = small_engagement()
    path = tmp_path / "R.csv"
    assert write_results(engagement, path) == (str(path), str(tmp_path / "R.summary.csv"))
    assert files_left(tmp_path) == ["R.csv", "R.summary.csv"]
    assert path.read_text().splitlines()[0] == ",".join(RESULT_COLUMNS)
    r = read_results(path)
    m, p = engagement.shape
    assert list(r) == list(RESULT_COLUMNS) and all(column.shape == (m * p,) for column in r.values())
    np.testing.assert_array_equal(r["cl"], np.repeat(np.arange(m), p))
    np.testing.assert_array_equal(r["phi_deg"], np.tile(engagement.phi, m))
    for name in ("lep_l", "uep_l", "length", "area"):
        np.testing.assert_allclose(r[name], getattr(engagement, name).ravel(), rtol=0, atol=1e-9, equal_nan=True)
    for k, name in enumerate(("uep_x", "uep_y", "uep_z")):
        np.testing.assert_allclose(r[name], engagement.uep_xyz[..., k].ravel(), rtol=0, atol=1e-9, equal_nan=True)
    np.testing.assert_allclose(r["h"], engagement.h.reshape(-1), rtol=0, atol=1e-9)
    for name in ("pieces", "uep_section", "uep_wall"):
        np.testing.assert_array_equal(r[name], getattr(engagement, name).ravel())
    np.testing.assert_array_equal(r["uep_surface"], engagement.surface_names().ravel())
    np.testing.assert_array_equal(r["case"], engagement.case_names().ravel())
    assert set(r["segment"][engagement.segment.ravel() == -1]) == {""}
    assert set(r["segment"][engagement.segment.ravel() == 0]) == {"A"}
    assert np.isnan(r["lep_l"][:p]).all() and (r["uep_surface"][:p] == "none").all()


def test_summary_rows(tmp_path):
    engagement, toolpath = small_engagement()
    _, summary = write_results(engagement, tmp_path / "R.csv", toolpath=toolpath)
    s = read_results(summary)
    assert list(s) == [*SUMMARY_COLUMNS, *TOOLPATH_COLUMNS]
    expected_rows = [max(1, len(engagement.segments(cl))) for cl in range(engagement.shape[0])]
    np.testing.assert_array_equal(s["cl"], np.repeat(np.arange(len(expected_rows)), expected_rows))
    # CL 0 is above the stock: one row, empty segment, no depth.
    assert s["segment"][0] == "" and np.isnan(s["depth_of_cut"][0]) and s["uep_surface"][0] == "none"
    rows = s["cl"] == 3
    segments = engagement.segments(3)
    assert list(s["segment"][rows]) == [segment["letter"] for segment in segments]
    np.testing.assert_allclose(s["max_length"][rows], [segment["max_length"] for segment in segments], atol=1e-9)
    np.testing.assert_allclose(s["phi_start"][rows], [segment["phi_start"] for segment in segments])
    np.testing.assert_allclose(s["depth_of_cut"][rows], engagement.depth_of_cut[3], atol=1e-9)
    np.testing.assert_allclose(s["theta_a"][rows], 3.0)
    np.testing.assert_allclose(s["cl_x"][rows], 82.0)


def test_summary_path():
    assert summary_path("out/R.csv") == "out/R.summary.csv"
    assert summary_path("R.CSV") == "R.summary.csv"
    assert summary_path("R.txt") == "R.txt.summary.csv"


def test_results_of_a_paper_sized_pass_are_fast(tmp_path):
    x = np.linspace(10, 120, 53)
    toolpath = Toolpath(np.c_[x, np.zeros(53), x / 60 - 1], np.zeros(53), np.full(53, 10.0))
    engagement = engage(STOCK, TOOL, toolpath, CutSettings(0.1, 10, 0, 180, 1))
    assert engagement.shape == (53, 181)
    started = time.process_time()  # CPU time: other processes on the machine don't count
    write_results(engagement, tmp_path / "R.csv", toolpath=toolpath)
    assert time.process_time() - started < 1.0  # about 0.15 s when measured
    assert len(read_results(tmp_path / "R.csv")["cl"]) == 53 * 181


def test_results_both_or_neither(tmp_path):
    engagement, toolpath = small_engagement()
    path = tmp_path / "R.csv"
    path.write_text("old results\n")
    (tmp_path / "R.summary.csv").write_text("old summary\n")
    short = Toolpath(toolpath.cl[:2], toolpath.theta_a[:2], toolpath.theta_b[:2])
    with pytest.raises(ValueError, match="toolpath has 2 CL points, the engagement 4"):
        write_results(engagement, path, toolpath=short)
    assert path.read_text() == "old results\n"
    assert (tmp_path / "R.summary.csv").read_text() == "old summary\n"
    assert files_left(tmp_path) == ["R.csv", "R.summary.csv"]


def test_results_interrupted_while_writing(tmp_path, monkeypatch):
    engagement, _ = small_engagement()
    written = []

    def interrupt_second(path, text):
        written.append(path)
        if len(written) == 2:
            raise KeyboardInterrupt
        with open(path, "w") as file:
            file.write(text)

    monkeypatch.setattr(results_csv, "write_text", interrupt_second)
    with pytest.raises(KeyboardInterrupt):
        write_results(engagement, tmp_path / "R.csv")
    assert len(written) == 2 and files_left(tmp_path) == []


def test_replacing_swaps_in_only_on_success(tmp_path):
    target = tmp_path / "a.txt"
    target.write_text("old")
    with replacing(target, tmp_path / "b.txt") as (a, b):
        assert os.path.dirname(a) == str(tmp_path) and os.path.exists(b)
        with open(a, "w") as file:
            file.write("new")
        assert target.read_text() == "old"
    assert target.read_text() == "new" and (tmp_path / "b.txt").read_text() == ""
    with pytest.raises(RuntimeError):
        with replacing(target) as (a,):
            with open(a, "w") as file:
                file.write("newer")
            raise RuntimeError
    assert target.read_text() == "new" and files_left(tmp_path) == ["a.txt", "b.txt"]


@pytest.mark.parametrize(
    "text, message",
    [
        ("", ": empty file"),
        ("cl,length\n0,1.5\n1\n", ":3: expected 2 fields, got 1"),
        ("cl,length\n0,1.5\n1,x\n", ":3: column 'length': 'x' is not a number (digits 0-9"),
        ("cl,length\n0.5,1.5\n", ":2: column 'cl': '0.5' is not a valid int"),
    ],
)
def test_read_results_bad_input(tmp_path, text, message):
    path = write_csv(tmp_path, text, "R.csv")
    with pytest.raises(InputError) as error:
        read_results(path)
    assert str(error.value).startswith(f"{path}{message}")
