"""Fuzz tier: the bundled inputs mutated, and the command line's promises checked on each.

The inputs are model test 1's stock.json, toolpath.csv and job.json and a small APT program
over the same stock (model_test_1.apt, its first 12 CL points). Each case mutates one of them
(one to three of: a flipped bit, a deleted, duplicated or swapped line, a number replaced by a
hostile one (huge, NaN words, other scripts' digits, '_' separators), a truncation) and runs
``engage`` on the result. Whatever the mutation, the run must

- end with status 0, or 2 with exactly one ``abm: error:`` line naming an input file (or,
  for a parameter given nowhere, its option);
- print no traceback (an exception escaping main fails the test with it);
- leave no output on failure (neither the results nor the folder made for them) and no hidden
  temporary file on success;
- leave every input file as it was.

Cases: ABM_FUZZ_EXAMPLES (default 250) in-process through ``cli.main``, plus a handful of fixed
mutations as ``python -m abm_workbench`` subprocesses.
"""

import contextlib
import io
import os
import re
import subprocess
import sys
import tempfile

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from abm_workbench import cli

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")
SOURCES = {"stock.json": os.path.join(MODEL, "stock.json"), "toolpath.csv": os.path.join(MODEL, "toolpath.csv"),
           "job.json": os.path.join(MODEL, "job.json"),
           "program.apt": os.path.join(os.path.dirname(os.path.abspath(__file__)), "model_test_1.apt")}
ORIGINALS = {name: open(path, "rb").read() for name, path in SOURCES.items()}
EXAMPLES = int(os.environ.get("ABM_FUZZ_EXAMPLES", "250"))
#: Texts put in place of a number.
HOSTILE = ["nan", "NaN", "-inf", "Infinity", "١٣.٥", "٣", "１２", "1_0.5", "1e309", "-1e13", "1" + "0" * 5000,
           "-9" * 200, "1e-400", "0x10", "", "1e", "--1", "+", "1.2.3", '"7"', "null", "true", "[]", "{}"]
_NUMBER = re.compile(rb"-?[0-9]+(?:\.[0-9]*)?(?:[eE][+-]?[0-9]+)?")


@st.composite
def mutated(draw):
    """(name of the file mutated, its new bytes, toolpath file to use)."""
    name = draw(st.sampled_from(sorted(ORIGINALS)))
    data = ORIGINALS[name]
    for _ in range(draw(st.integers(1, 3))):
        data = draw(st.sampled_from([_flip, _lines, _number, _truncate]))(draw, data)
    toolpath = "program.apt" if name == "program.apt" else draw(st.sampled_from(["toolpath.csv", "program.apt"]))
    return name, data, toolpath


def _flip(draw, data):
    """One bit of one byte flipped."""
    if not data:
        return data
    at = draw(st.integers(0, len(data) - 1))
    return data[:at] + bytes([data[at] ^ (1 << draw(st.integers(0, 7)))]) + data[at + 1:]


def _lines(draw, data):
    """A line deleted, duplicated or swapped with the next."""
    lines = data.split(b"\n")
    at = draw(st.integers(0, len(lines) - 1))
    how = draw(st.sampled_from(["delete", "duplicate", "swap"]))
    if how == "delete":
        del lines[at]
    elif how == "duplicate":
        lines.insert(at, lines[at])
    elif at + 1 < len(lines):
        lines[at], lines[at + 1] = lines[at + 1], lines[at]
    return b"\n".join(lines)


def _number(draw, data):
    """A number replaced by a hostile text or by any float's repr (huge, tiny, NaN, inf)."""
    found = list(_NUMBER.finditer(data))
    if not found:
        return data
    match = draw(st.sampled_from(found))
    text = draw(st.one_of(st.sampled_from(HOSTILE), st.floats().map(repr)))
    return data[:match.start()] + text.encode("utf-8") + data[match.end():]


def _truncate(draw, data):
    """The file cut short anywhere."""
    return data[:draw(st.integers(0, len(data)))]


def prepare(folder, name, data):
    """Write the inputs into `folder`, file `name` replaced by `data`; return {name: path}."""
    paths = {}
    for each, original in ORIGINALS.items():
        paths[each] = os.path.join(folder, each)
        with open(paths[each], "wb") as file:
            file.write(data if each == name else original)
    return paths


def argv(paths, toolpath, out):
    return ["engage", "--stock", paths["stock.json"], "--toolpath", paths[toolpath], "--job", paths["job.json"],
            "--phi-range", "0:180", "--phi-step", "30", "--out", out]


def check(folder, paths, name, data, status, err):
    """The promises of the module docstring for one finished run."""
    inputs = {each: data if each == name else original for each, original in ORIGINALS.items()}
    assert "Traceback" not in err
    lines = err.splitlines()
    errors = [line for line in lines if line.startswith("abm: error: ")]
    assert status in (0, 2), err
    if status == 2:
        assert len(errors) == 1 and errors[0] == lines[-1], err
        named = [os.path.basename(path) for path in paths.values() if os.path.basename(path) in errors[0]]
        assert named or " --" in errors[0], f"the error names no input file or option: {err}"
        assert sorted(os.listdir(folder)) == sorted(ORIGINALS), err
    else:
        assert errors == [], err
        assert sorted(os.listdir(os.path.join(folder, "out"))) == ["R.csv", "R.summary.csv"]
    for each, path in paths.items():
        assert open(path, "rb").read() == inputs[each], f"{each} changed"


@settings(max_examples=EXAMPLES)
@given(mutated())
def test_mutated_inputs_in_process(case):
    name, data, toolpath = case
    with tempfile.TemporaryDirectory(prefix="abm-fuzz-") as folder:
        paths = prepare(folder, name, data)
        stderr = io.StringIO()
        with contextlib.redirect_stderr(stderr), contextlib.redirect_stdout(io.StringIO()):
            status = cli.main(argv(paths, toolpath, os.path.join(folder, "out", "R.csv")))
        check(folder, paths, name, data, status, stderr.getvalue())


FIXED = {
    "arabic digits in the toolpath": ("toolpath.csv",
                                      ORIGINALS["toolpath.csv"].replace(b"13.0,", "١٣.٠,".encode(), 1)),
    "a stock nested 100,000 deep": ("stock.json", ORIGINALS["stock.json"].replace(
        b'"units"', b'"deep": ' + b"[" * 100_000 + b"]" * 100_000 + b', "units"', 1)),
    "a job key given twice": ("job.json", ORIGINALS["job.json"].replace(b'"flutes": 2,', b'"flutes": 2, "flutes": 3,')),
    "an APT program cut short": ("program.apt", ORIGINALS["program.apt"][:len(ORIGINALS["program.apt"]) // 2] + b"$"),
    "a wall point at 1e308": ("stock.json", re.sub(rb"\[\s*76\.0", b"[1e308", ORIGINALS["stock.json"], count=1)),
}


@pytest.mark.parametrize("label", sorted(FIXED))
def test_mutated_inputs_as_subprocess(label, tmp_path):
    name, data = FIXED[label]
    assert data != ORIGINALS[name]
    paths = prepare(str(tmp_path), name, data)
    toolpath = "program.apt" if name == "program.apt" else "toolpath.csv"
    out = str(tmp_path / "out" / "R.csv")
    done = subprocess.run([sys.executable, "-m", "abm_workbench", *argv(paths, toolpath, out)],
                          cwd=ROOT, capture_output=True, text=True, timeout=300)
    check(str(tmp_path), paths, name, data, done.returncode, done.stderr)
    assert done.returncode == 2
