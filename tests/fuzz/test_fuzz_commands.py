"""Fuzz tier, every command (issue #29): toolpath, engage, validate, schedule and the results readers.

Real inputs are mutated as test_fuzz_inputs.py mutates model test 1's (flipped bits, lines deleted,
duplicated or swapped, numbers replaced by hostile texts, files cut short) and run through a command:

- ``toolpath`` on the CL files of real CAM dialects (tests/fixtures/cl: NX CLSF, CATIA, Creo NCL,
  SOLIDWORKS CAM, Mastercam, PowerMill) and on G-code with its tool table;
- ``engage`` on a general 2.5D terraced stock (model test 4's abm-terraced/1 JSON) and, in child
  processes, on the STEP solid of model test 1;
- ``schedule`` on model test 1 and its APT program;
- ``validate`` (FreeCAD's booleans: a few seconds a run) on a handful of mutated stocks;
- the results readers (CSV and .npz) on mutated results of a real run: they return columns or raise
  InputError, nothing else, within memory.

The promises are harness.py's. Examples per property: ABM_FUZZ_COMMAND_EXAMPLES (default 40).
"""

import contextlib
import io
import os
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from abm_workbench import cli
from abm_workbench.errors import InputError
from tests.fuzz.harness import FIXTURES, FUZZ, MODEL_1, MODELS, abm, check_promises, copy_inputs, slow, snapshot

EXAMPLES = int(os.environ.get("ABM_FUZZ_COMMAND_EXAMPLES", "40"))
#: Texts put in place of a number (as test_fuzz_inputs.HOSTILE, and numbers within the readers' bound
#: that are extreme for what they stand for).
HOSTILE = ["nan", "-inf", "١٣.٥", "1_0.5", "1e309", "-1e13", "1" + "0" * 400, "1e-400", "0x10", "", "1e", "--1",
           "1e12", "-1e12", "999999999999", "1e-300", "0", "-0", "1.5", "1e-12"]
_NUMBER = re.compile(rb"-?[0-9]+(?:\.[0-9]*)?(?:[eE][+-]?[0-9]+)?")


def _mutations(draw, data):
    """`data` mutated one to three times (harness docstring)."""
    for _ in range(draw(st.integers(1, 3))):
        how = draw(st.sampled_from(["flip", "lines", "number", "number", "truncate"]))
        if how == "flip" and data:
            at = draw(st.integers(0, len(data) - 1))
            data = data[:at] + bytes([data[at] ^ (1 << draw(st.integers(0, 7)))]) + data[at + 1:]
        elif how == "lines":
            lines = data.split(b"\n")
            at = draw(st.integers(0, len(lines) - 1))
            what = draw(st.sampled_from(["delete", "duplicate", "swap"]))
            if what == "delete":
                del lines[at]
            elif what == "duplicate":
                lines.insert(at, lines[at])
            elif at + 1 < len(lines):
                lines[at], lines[at + 1] = lines[at + 1], lines[at]
            data = b"\n".join(lines)
        elif how == "number":
            found = list(_NUMBER.finditer(data))
            if found:
                match = draw(st.sampled_from(found))
                text = draw(st.one_of(st.sampled_from(HOSTILE), st.floats().map(repr)))
                data = data[:match.start()] + text.encode("utf-8") + data[match.end():]
        else:
            data = data[:draw(st.integers(0, len(data)))]
    return data


@st.composite
def mutated_file(draw, sources):
    """(name, mutated bytes) of one of `sources` ({name: bytes})."""
    name = draw(st.sampled_from(sorted(sources)))
    return name, _mutations(draw, sources[name])


def in_process(argv, folder):
    """cli.main(argv) in `folder`: (status, stderr)."""
    stderr = io.StringIO()
    previous = os.getcwd()
    os.chdir(folder)
    try:
        with contextlib.redirect_stderr(stderr), contextlib.redirect_stdout(io.StringIO()):
            status = cli.main(argv)
    finally:
        os.chdir(previous)
    return status, stderr.getvalue()


class _Done:
    def __init__(self, status, err):
        self.status, self.err, self.out = status, err, ""

    @property
    def errors(self):
        return [line for line in self.err.splitlines() if line.startswith("abm: error: ")]


def run_checked(argv, folder, names, outputs):
    """Run `argv` in this process in `folder` and check harness.check_promises on it."""
    before = snapshot(folder)
    status, err = in_process(argv, folder)
    done = _Done(status, err)
    check_promises(done, before, snapshot(folder), names=names, outputs=outputs)
    return done


def _read(path):
    with open(path, "rb") as file:
        return file.read()


# toolpath on real CL dialects and G-code.

DIALECTS = {name: _read(os.path.join(FIXTURES, name)) for name in sorted(os.listdir(FIXTURES))}
DIALECTS["model_test_1.apt"] = _read(os.path.join(FUZZ, "model_test_1.apt"))
DIALECTS["program.ngc"] = (b"%\n(model test 1, a few moves)\nG21 G90 G17 G54\nT1 M6\nS4000 M3\nG0 X0 Y0 Z20\n"
                           b"G1 Z2.5 F400\nG1 X30 Y0 F800\nG2 X40 Y10 I0 J10\nG3 X30 Y20 R10\nG1 X0 Y20\n"
                           b"G2 X0 Y20 Z0 I0 J-10 P3\nG0 Z20\nM5\nM30\n%\n")
TOOL_TABLE = b"T1 P1 D12 Z30 ;flat end mill 12\nT2 P2 D6 Z20 ;ball end mill 6\n"


@settings(max_examples=EXAMPLES)
@given(mutated_file(DIALECTS))
def test_toolpath_on_mutated_cl_dialects_and_gcode(tmp_path_factory, case):
    name, data = case
    folder = str(tmp_path_factory.mktemp("dialect"))
    with open(os.path.join(folder, name), "wb") as file:
        file.write(data)
    with open(os.path.join(folder, "tools.tbl"), "wb") as file:
        file.write(TOOL_TABLE)
    extra = ["--tool-table", "tools.tbl"] if name.endswith(".ngc") else []
    run_checked(["toolpath", name, "--out", "out/P.csv", *extra], folder, [name, "tools.tbl"], ["out", "out/P.csv"])


@pytest.mark.parametrize("name", sorted(DIALECTS))
def test_toolpath_reads_every_dialect_unmutated(tmp_path, name):
    (tmp_path / name).write_bytes(DIALECTS[name])
    (tmp_path / "tools.tbl").write_bytes(TOOL_TABLE)
    extra = ["--tool-table", "tools.tbl"] if name.endswith(".ngc") else []
    done = run_checked(["toolpath", name, "--out", "P.csv", *extra], str(tmp_path), [name], ["P.csv"])
    assert done.status == 0, done.err


# engage on a terraced JSON stock.

MODEL_4 = os.path.join(MODELS, "model_test_4")
TERRACED = {"stock.json": _read(os.path.join(MODEL_4, "stock.json"))}


@settings(max_examples=EXAMPLES)
@given(mutated_file(TERRACED))
def test_engage_on_a_mutated_terraced_stock(tmp_path_factory, case):
    _, data = case
    folder = str(tmp_path_factory.mktemp("terraced"))
    copy_inputs(folder, {name: os.path.join(MODEL_4, name) for name in ("toolpath.csv", "job.json")})
    with open(os.path.join(folder, "stock.json"), "wb") as file:
        file.write(data)
    run_checked(["engage", "--stock", "stock.json", "--toolpath", "toolpath.csv", "--job", "job.json",
                 "--phi-step", "45", "--stock-model", "initial", "--out", "out/R.npz"], folder,
                ["stock.json", "toolpath.csv", "job.json"], ["out", "out/R.npz"])


# schedule on model test 1 and its APT program.

SCHEDULED = {"stock.json": _read(os.path.join(MODEL_1, "stock.json")),
             "program.apt": _read(os.path.join(FUZZ, "model_test_1.apt"))}


@settings(max_examples=EXAMPLES)
@given(mutated_file(SCHEDULED), st.sampled_from(["P.apt", "P.csv"]))
def test_schedule_on_mutated_inputs(tmp_path_factory, case, out):
    name, data = case
    folder = str(tmp_path_factory.mktemp("schedule"))
    for each, original in SCHEDULED.items():
        with open(os.path.join(folder, each), "wb") as file:
            file.write(data if each == name else original)
    run_checked(["schedule", "--stock", "stock.json", "--toolpath", "program.apt", "--flutes", "2",
                 "--flute-length", "30", "--phi-step", "30", "--material", "al7075-t6", "--max-force", "300",
                 "--out", f"out/{out}"], folder, ["stock.json", "program.apt"], ["out", f"out/{out}"])


# The results readers.

@pytest.fixture(scope="module")
def results(tmp_path_factory):
    """{name: bytes} of a real run's R.csv, R.summary.csv and R.npz (model test 1, φ every 30°)."""
    folder = tmp_path_factory.mktemp("results")
    base = ["engage", "--stock", os.path.join(MODEL_1, "stock.json"), "--toolpath",
            os.path.join(MODEL_1, "toolpath.csv"), "--job", os.path.join(MODEL_1, "job.json"), "--phi-step", "30",
            "--stock-model", "initial", "--forces", "--material", "al7075-t6"]
    for out in ("R.csv", "R.npz"):
        assert in_process(base + ["--out", str(folder / out)], str(folder))[0] == 0
    return {name: _read(folder / name) for name in ("R.csv", "R.summary.csv", "R.npz")}


@settings(max_examples=3 * EXAMPLES)
@given(st.data())
def test_the_results_readers_return_columns_or_input_error(tmp_path_factory, results, data):
    from abm_workbench.formats import results_csv, results_npz

    name = data.draw(st.sampled_from(sorted(results)))
    mutated = _mutations(data.draw, results[name])
    folder = tmp_path_factory.mktemp("reader")
    path = folder / name
    path.write_bytes(mutated)
    reader = results_npz.read_tables if name.endswith(".npz") else results_csv.read_results
    try:
        reader(path)
    except InputError as error:
        assert str(error).startswith(str(path)), error


# validate and solids: FreeCAD.

def _freecad():
    """Whether FreeCAD can be imported (without importing it here)."""
    import importlib.util

    return os.path.isdir("/usr/lib/freecad-python3/lib") or importlib.util.find_spec("FreeCAD") is not None


def _stock_variants():
    """{label: (model folder, stock JSON text)}: stocks engage accepted whose validation crashed (a terraced
    loop enclosing no area: "the terraced stock gave no solid"), and changes of model test 1's."""
    import json

    staircase = _read(os.path.join(MODEL_1, "stock.json")).decode()
    terraced = json.loads(_read(os.path.join(MODEL_4, "stock.json")))
    out_and_back = json.loads(json.dumps(terraced))
    out_and_back["slabs"][0]["loops"].append([{"type": "line", "start": [10, 10], "end": [20, 10]},
                                             {"type": "line", "start": [20, 10], "end": [10, 10]}])
    twice = json.loads(json.dumps(terraced))
    twice["slabs"][1]["loops"].append(twice["slabs"][1]["loops"][0])
    return {
        "staircase as given": (MODEL_1, staircase),
        "staircase, a wall point moved far out": (MODEL_1, re.sub(r"\[\s*76\.0", "[129.99", staircase, count=1)),
        "staircase, a base 1e6 mm down": (MODEL_1, staircase.replace('"base_z": -20', '"base_z": -1000000', 1)),
        "terraced, a loop of zero area": (MODEL_4, json.dumps(out_and_back)),
        "terraced, a loop given twice": (MODEL_4, json.dumps(twice)),
    }


@pytest.mark.parametrize("label", sorted(_stock_variants()))
def test_validate_on_stocks_engage_accepts(tmp_path, label):
    """validate ends as engage does on every stock engage takes: results, or one error line naming the stock."""
    if not _freecad():
        pytest.skip("validate needs FreeCAD")
    model, text = _stock_variants()[label]
    copy_inputs(str(tmp_path), {name: os.path.join(model, name) for name in ("toolpath.csv", "job.json")})
    (tmp_path / "stock.json").write_text(text)
    base = ["--stock", "stock.json", "--toolpath", "toolpath.csv", "--job", "job.json", "--phi-step", "60",
            "--stock-model", "initial"]
    engaged = abm(["engage", *base, "--out", "R.csv"], tmp_path, memory=None, timeout=300)
    assert "Traceback" not in engaged.err and engaged.status in (0, 2), engaged.err
    before = snapshot(tmp_path)
    done = abm(["validate", *base, "--check", "0,22", "--report", "rep"], tmp_path, memory=None, timeout=600)
    check_promises(done, before, snapshot(tmp_path), names=["stock.json", "toolpath.csv"], outputs=["rep"])
    if engaged.status == 0:
        assert done.status == 0 or "stock.json" in done.errors[0], done.err
    if "terraced" in label:
        assert engaged.status == 2 and "stock.json: slabs[" in engaged.errors[0], engaged.err


STEP_MUTATIONS = {
    "cut short": lambda text: text[:len(text) // 2],
    "a point at 1e12": lambda text: re.sub(r"CARTESIAN_POINT\('',\(([-0-9.E+]+),", r"CARTESIAN_POINT('',(1.E12,",
                                           text, count=1),
    "a point at nan": lambda text: re.sub(r"CARTESIAN_POINT\('',\(([-0-9.E+]+),", r"CARTESIAN_POINT('',(NAN,", text,
                                          count=1),
    "a line deleted": lambda text: "\n".join(line for k, line in enumerate(text.splitlines()) if k != 40),
}


@pytest.mark.parametrize("label", sorted(STEP_MUTATIONS))
def test_engage_on_a_mutated_step_solid(tmp_path, label):
    if not _freecad():
        pytest.skip("a solid stock needs FreeCAD")
    copy_inputs(str(tmp_path), {name: os.path.join(MODEL_1, name) for name in ("toolpath.csv", "job.json")})
    text = _read(os.path.join(MODEL_1, "stock.step")).decode("latin-1")
    mutated = STEP_MUTATIONS[label](text)
    assert mutated != text
    (tmp_path / "stock.step").write_text(mutated, encoding="latin-1")
    before = snapshot(tmp_path)
    done = abm(["engage", "--stock", "stock.step", "--toolpath", "toolpath.csv", "--job", "job.json", "--phi-step",
                "30", "--stock-model", "initial", "--out", "out/R.csv"], tmp_path, memory=None, timeout=600)
    check_promises(done, before, snapshot(tmp_path), names=["stock.step"], outputs=["out", "out/R.csv",
                                                                                    "out/R.summary.csv"])


@slow
@pytest.mark.parametrize("seed", range(20))
def test_engage_on_randomly_mutated_step_solids(tmp_path, seed):
    """Slow (FreeCAD reads and recognises each solid): ABM_FUZZ_SLOW=1."""
    import random

    if not _freecad():
        pytest.skip("a solid stock needs FreeCAD")
    rng = random.Random(seed)
    copy_inputs(str(tmp_path), {name: os.path.join(MODEL_1, name) for name in ("toolpath.csv", "job.json")})
    lines = _read(os.path.join(MODEL_1, "stock.step")).decode("latin-1").splitlines()
    for _ in range(rng.randint(1, 3)):
        at = rng.randrange(len(lines))
        numbers = list(re.finditer(r"-?[0-9]+\.[0-9]*(?:E[+-]?[0-9]+)?", lines[at]))
        if numbers:
            match = rng.choice(numbers)
            lines[at] = lines[at][:match.start()] + rng.choice(["1.E12", "-1.E12", "0.", "1.E-300", "7."]) + \
                lines[at][match.end():]
        else:
            del lines[at]
    (tmp_path / "stock.step").write_text("\n".join(lines) + "\n", encoding="latin-1")
    before = snapshot(tmp_path)
    done = abm(["engage", "--stock", "stock.step", "--toolpath", "toolpath.csv", "--job", "job.json", "--phi-step",
                "30", "--stock-model", "initial", "--out", "out/R.csv"], tmp_path, memory=None, timeout=600)
    check_promises(done, before, snapshot(tmp_path), names=["stock.step"], outputs=["out", "out/R.csv",
                                                                                    "out/R.summary.csv"])

