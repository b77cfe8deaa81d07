"""Hostile input (issue #15, item 5): each defect of the list, with the input that showed it.

The references are independent of the readers under test: Python's own ``repr`` for written
numbers, and the text of the files before and after a refused run.
"""

import json
import os
import re
import subprocess
import sys

import numpy as np
import pytest

from abm_workbench import cli
from abm_workbench.engine import Tool, Toolpath
from abm_workbench.errors import InputError
from abm_workbench.formats import (MAX_JSON_DEPTH, STAGING_EXTRA, check_output_path, load_json_object, parse_number,
                                   replacing)
from abm_workbench.formats.cl import read_program
from abm_workbench.formats.decimal_text import number_field
from abm_workbench.formats.staircase_json import load_staircase
from abm_workbench.formats.toolpath_csv import MAX_FIELD, load_toolpath

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")
HEADER = "x,y,z,theta_a,theta_b"


@pytest.fixture
def model(tmp_path, monkeypatch):
    """tmp_path holding model test 1's stock.json, toolpath.csv and job.json (working directory)."""
    for name in ("stock.json", "toolpath.csv", "job.json"):
        (tmp_path / name).write_bytes(open(os.path.join(MODEL, name), "rb").read())
    monkeypatch.chdir(tmp_path)
    return tmp_path


def run(argv, capsys):
    """cli.main(argv) -> (status, stderr lines)."""
    status = cli.main(argv)
    return status, capsys.readouterr().err.splitlines()


def engage(out="R.csv", *more):
    return ["engage", "--stock", "stock.json", "--toolpath", "toolpath.csv", "--job", "job.json",
            "--phi-step", "30", "--out", out, *more]


def snapshot(folder):
    """{relative path: bytes} of every file under `folder`, and the set of its folders."""
    files, folders = {}, set()
    for top, dirs, names in os.walk(folder):
        folders.update(os.path.relpath(os.path.join(top, d), folder) for d in dirs)
        for name in names:
            path = os.path.join(top, name)
            files[os.path.relpath(path, folder)] = open(path, "rb").read()
    return files, folders


# One number grammar.

@pytest.mark.parametrize("text", ["١٣.٥", "1_0.5", "nan", "-inf", "Infinity", "0x10", "1.2.3", "1e", "", "٣"])
def test_the_grammar_refuses(text):
    with pytest.raises(InputError, match=r"^f\.csv:3: column 'x': .* not a (finite )?number"):
        parse_number(text, "f.csv:3: column 'x'")


@pytest.mark.parametrize("text, value", [("13.5", 13.5), (" -1e3 ", -1000.0), ("+.5", 0.5), ("7.", 7.0),
                                         ("1E-2", 0.01), ("-0", 0.0), ("1e12", 1e12)])
def test_the_grammar_reads(text, value):
    assert parse_number(text, "here") == value


@pytest.mark.parametrize("field", ["١٣.٥", "1_0.5", "nan", "1e13", "-2e308", "1e999"])
def test_toolpath_csv_refuses_a_bad_number_naming_the_line(tmp_path, field):
    path = tmp_path / "path.csv"
    path.write_text(f"{HEADER}\n1,2,3,0,0\n{field},2,3,0,0\n")
    with pytest.raises(InputError, match=rf"^{path}:3: column 'x': "):
        load_toolpath(path)


@pytest.mark.parametrize("field", ["١", "1_0", "1e13"])
def test_cl_reader_refuses_a_bad_number_naming_the_line(tmp_path, field):
    path = tmp_path / "p.apt"
    path.write_text(f"GOTO/1,2,3\nGOTO/{field},2,3\n")
    with pytest.raises(InputError, match=rf"^{path}:2: "):
        read_program(path)


def _stock(**changes):
    data = json.load(open(os.path.join(MODEL, "stock.json")))
    data.update(changes)
    return data


@pytest.mark.parametrize("value", ["1e308", "-1e13", "1" + "0" * 4400, "-1" + "0" * 400 + ".5"],
                         ids=["1e308", "-1e13", "4401-digit integer", "401-digit decimal"])
def test_a_huge_wall_point_is_refused_naming_it(tmp_path, value):
    data = _stock()
    data["sections"][1]["wall"][2][0] = "HUGE"
    path = tmp_path / "stock.json"
    path.write_text(json.dumps(data).replace('"HUGE"', value))
    with pytest.raises(InputError, match=rf"^{path}: sections\[1\]\.wall\[2\]\[0\]: .*(too large|finite)"):
        load_staircase(path)


# Values too large to write.

@pytest.mark.parametrize("value", [1.8e298, 1e300, -1.7976931348623157e308, 3.3e299, 9.999e297])
def test_a_finite_value_is_never_written_as_inf(value):
    field = number_field(np.array([value, 1.25]))
    texts = [bytes(field[:, i].tobytes()).replace(b"\0", b"").decode() for i in range(2)]
    assert texts == [repr(value), "1.25"]


# JSON limits.

def test_deep_json_is_refused(tmp_path):
    path = tmp_path / "deep.json"
    path.write_text('{"a": ' + "[" * 100_000 + "]" * 100_000 + "}")
    with pytest.raises(InputError, match=rf"^{path}: JSON nested 100001 deep; at most {MAX_JSON_DEPTH}"):
        load_json_object(path)


def test_json_at_the_depth_limit_is_read(tmp_path):
    path = tmp_path / "deep.json"
    path.write_text('{"a": ' + "[" * (MAX_JSON_DEPTH - 1) + "]" * (MAX_JSON_DEPTH - 1) + ', "b": "[[[["}')
    assert load_json_object(path)["b"] == "[[[["


def test_duplicate_json_keys_are_refused_naming_key_and_line(tmp_path):
    path = tmp_path / "job.json"
    path.write_text('{\n "diameter": 12,\n "flutes": 2,\n "diameter": 10\n}\n')
    with pytest.raises(InputError, match=rf"^{path}:4: duplicate key 'diameter'"):
        load_json_object(path)


def test_a_job_integer_of_thousands_of_digits_is_one_clean_error(model, capsys):
    text = open("job.json").read().replace('"flutes": 2', '"flutes": ' + "9" * 5000)
    open("job.json", "w").write(text)
    status, err = run(engage(), capsys)
    assert status == 2 and len(err) == 1 and err[0].startswith("abm: error: job.json: ") and "flutes" in err[0]
    assert not os.path.exists("R.csv")


def test_a_stock_integer_of_thousands_of_digits_is_one_clean_error(model, capsys):
    open("stock.json", "w").write(json.dumps(_stock(base_z="HUGE")).replace('"HUGE"', "-1" + "0" * 4400))
    status, err = run(engage(), capsys)
    assert status == 2 and len(err) == 1 and err[0].startswith("abm: error: stock.json: base_z: ")
    assert "too large" in err[0] and not os.path.exists("R.csv")


# CSV limits.

@pytest.mark.parametrize("length, what", [(MAX_FIELD + 1, "field"), (200_000, "line")])
def test_a_long_csv_field_is_refused_naming_the_line(tmp_path, length, what):
    line = f"1,2,3,{'1' * length},0"
    path = tmp_path / "path.csv"
    path.write_text(f"{HEADER}\n1,2,3,0,0\n{line}\n")
    count = length if what == "field" else len(line)
    with pytest.raises(InputError, match=rf"^{path}:3: a {what} of {count:,} characters; at most"):
        load_toolpath(path)


# Helix angle.

def test_the_helix_is_limited_to_60_degrees(model, capsys):
    assert Tool(12, 2, 30, helix=-60.0).helix == -60.0
    with pytest.raises(ValueError, match=r"helix must be within \[-60, 60\] degrees .*flat-end mills"):
        Tool(12, 2, 30, helix=60.5)
    status, err = run(engage("R.csv", "--helix", "89.9"), capsys)
    assert status == 2 and err == ["abm: error: --helix: must be within [-60, 60]°, got 89.9°"]


# Tool axes of extreme but valid length.

@pytest.mark.parametrize("scale", [1e-200, 1e-310, 1e200, 1e307])
def test_axes_of_any_finite_length_are_read(scale):
    axes = np.array([[0.0, 0.0, 1.0], [0.3, -0.2, 0.9], [-1.0, 0.0, 1.0]])
    reference = Toolpath.from_axes(np.zeros((3, 3)), axes)
    scaled = Toolpath.from_axes(np.zeros((3, 3)), axes * scale)
    np.testing.assert_allclose(scaled.theta_a, reference.theta_a, atol=1e-12)
    np.testing.assert_allclose(scaled.theta_b, reference.theta_b, atol=1e-12)


# Outputs through links.

@pytest.mark.parametrize("command", ["engage", "engage-plot", "schedule"])
def test_an_output_through_a_linked_folder_onto_an_input_is_refused(model, capsys, command):
    os.symlink(model, "link")
    before = snapshot(model)
    if command == "schedule":
        argv = ["schedule", "--stock", "stock.json", "--toolpath", "toolpath.csv", "--job", "job.json",
                "--phi-step", "30", "--material", "al7075-t6", "--max-force", "500", "--out", "link/toolpath.csv"]
    elif command == "engage":
        argv = engage("link/stock.json")
    else:
        argv = engage("R.csv", "--plot", "link/job.json")
    status, err = run(argv, capsys)
    assert status == 2 and len(err) == 1 and "is an input and would be overwritten" in err[0]
    assert snapshot(model) == before


def test_a_report_folder_through_a_link_holding_the_inputs_is_refused(model, capsys):
    os.symlink(model, "link")
    before = snapshot(model)
    status, err = run(["validate", "--stock", "stock.json", "--toolpath", "toolpath.csv", "--job", "job.json",
                       "--phi-step", "30", "--report", "link"], capsys)
    assert status == 2 and len(err) == 1 and "abm: error: " in err[0]
    assert snapshot(model) == before


# numpy warnings.

def test_numpy_warnings_do_not_reach_stderr(model):
    """In a child process (pytest would catch the warnings itself): a run whose numpy arithmetic
    divides by zero and which warns prints nothing on stderr."""
    script = (
        "import sys, warnings, numpy as np\n"
        f"sys.path.insert(0, {ROOT!r})\n"
        "from abm_workbench import cli\n"
        "def noisy(args):\n"
        "    np.log(np.zeros(2)); np.float64(1.0) / np.float64(0.0)\n"
        "    warnings.warn('overflow encountered', RuntimeWarning)\n"
        "    return 0\n"
        "cli._run_engage = noisy\n"
        f"sys.exit(cli.main({engage()!r}))\n")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert (done.returncode, done.stderr) == (0, "")


# Output paths that cannot be written, refused before any computation (formats.check_output_path).

@pytest.mark.parametrize("path, message", [("", "an output path is empty"), ("  ", "an output path is empty"),
                                           (".", ": is a folder"), ("sub/", ": is a folder")])
def test_output_paths_that_name_no_file_are_refused(tmp_path, monkeypatch, path, message):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "sub").mkdir()
    with pytest.raises(InputError, match=re.escape(message)):
        check_output_path(path)


def test_the_longest_output_name_is_what_staging_can_write(tmp_path):
    """The longest name allowed works with formats.replacing (its hidden twin fits); one more
    byte is refused, by check_output_path, with the lengths."""
    longest = os.pathconf(tmp_path, "PC_NAME_MAX") - STAGING_EXTRA
    fits = tmp_path / ("a" * (longest - 4) + ".csv")
    check_output_path(fits)
    with replacing(fits) as (temporary,):
        open(temporary, "w").write("x")
    assert fits.read_text() == "x" and os.listdir(tmp_path) == [fits.name]
    too_long = tmp_path / ("é" + "a" * (longest - 5) + ".csv")
    with pytest.raises(InputError, match=rf"the file name is {longest + 1} bytes long; at most {longest}"):
        check_output_path(too_long)


@pytest.mark.parametrize("value", ["1e400", "-2e13"])
def test_a_huge_nurbs_number_is_refused_naming_the_line(tmp_path, value):
    path = tmp_path / "p.cls"
    path.write_text(f"MULTAX\nGOTO/0,0,0,0,0,1\nNURBS/3\nKNOT/0,0,0,1,1,1\nCNTRL/0,0,0\nCNTRL/1,{value},0\n"
                    "CNTRL/2,0,0\nGOTO/2,0,0,0,0,1\n")
    with pytest.raises(InputError, match=rf"^{path}:6: .*CNTRL: a number above 1e\+12 in magnitude"):
        read_program(path)
