"""Damaged solid files (issue #15, item 5): a clean ``damaged or unreadable`` error, never a crash.

Model test 1's stock written as BREP by FreeCAD, with one line deleted: line 1853, the curve
record of an edge. OpenCASCADE reads that file, but its validity check ends the process
(exit status 1, no message), as a child process here shows first.
"""

import os
import subprocess
import sys

import pytest

from abm_workbench.cad import recognise
from abm_workbench.cad.freecad_env import DEBIAN_LIB, Part
from abm_workbench.errors import InputError

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")
DELETED = 1853


@pytest.fixture(scope="module")
def damaged(tmp_path_factory):
    """Path of the damaged BREP, after checking that it ends a process that checks it."""
    folder = tmp_path_factory.mktemp("damaged")
    whole = folder / "whole.brep"
    Part.read(os.path.join(MODEL, "stock.step")).exportBrep(str(whole))
    lines = whole.read_text().splitlines(keepends=True)
    path = folder / "stock.brep"
    path.write_text("".join(lines[:DELETED - 1] + lines[DELETED:]))
    script = f"import sys; sys.path.append({DEBIAN_LIB!r}); import FreeCAD, Part; Part.read({str(path)!r}).isValid()"
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert done.returncode != 0 and "Traceback" not in done.stderr, (
        "the damaged file no longer ends the process: FreeCAD writes this BREP differently now")
    return path


def test_load_solid_names_the_damaged_file(damaged):
    with pytest.raises(InputError, match=rf"^{damaged}: damaged or unreadable BREP \(the reader ended"):
        recognise.load_solid(damaged)


def test_the_command_line_gives_one_error_and_no_output(damaged, tmp_path):
    out = tmp_path / "R.csv"
    done = subprocess.run(
        [sys.executable, "-m", "abm_workbench", "engage", "--stock", str(damaged), "--toolpath",
         os.path.join(MODEL, "toolpath.csv"), "--job", os.path.join(MODEL, "job.json"), "--out", str(out)],
        cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert done.returncode == 2
    assert done.stderr.splitlines() == [f"abm: error: {damaged}: damaged or unreadable BREP (the reader ended "
                                        "with exit status 1 and no shape)"]
    assert os.listdir(tmp_path) == []


def test_a_file_read_forever_is_given_up(tmp_path):
    """Line 575 deleted (a vertex's point): OpenCASCADE reads on and on; the child is stopped."""
    whole = tmp_path / "whole.brep"
    Part.read(os.path.join(MODEL, "stock.step")).exportBrep(str(whole))
    lines = whole.read_text().splitlines(keepends=True)
    path = tmp_path / "stock.brep"
    path.write_text("".join(lines[:574] + lines[575:]))
    with pytest.raises(InputError, match=rf"^{path}: damaged or unreadable BREP \(no shape after 2 s\)"):
        recognise._read_in_child(str(path), "BREP", timeout=2.0)


def test_a_sound_file_reads_as_before():
    direct = Part.read(os.path.join(MODEL, "stock.step"))
    shape = recognise.load_solid(os.path.join(MODEL, "stock.step"))
    assert len(shape.Faces) == len(direct.Faces) and shape.isValid()
    assert abs(shape.Volume - direct.Volume) <= 1e-9 * direct.Volume


def test_under_the_gui_the_child_is_a_python_interpreter(monkeypatch):
    """Under FreeCAD's GUI sys.executable is FreeCAD's program, which cannot run the reading child: the
    running Python's own interpreter runs it instead (and starts validation workers)."""
    monkeypatch.setattr(sys, "executable", "/usr/bin/freecad")
    assert os.path.basename(recognise.interpreter()).startswith("python")
    shape = recognise.load_solid(os.path.join(MODEL, "stock.step"))
    assert len(shape.Faces) == len(Part.read(os.path.join(MODEL, "stock.step")).Faces)


def test_a_script_without_a_main_guard_reads_solids(tmp_path):
    """The child is a fresh interpreter, not multiprocessing's: a user's script is not imported again."""
    script = tmp_path / "script.py"
    script.write_text(f"from abm_workbench.cad.recognise import load_solid\n"
                      f"print(len(load_solid({os.path.join(MODEL, 'stock.step')!r}).Faces))\n")
    done = subprocess.run([sys.executable, str(script)], cwd=ROOT, capture_output=True, text=True, timeout=300,
                          env={**os.environ, "PYTHONPATH": ROOT})
    assert done.returncode == 0, done.stderr
    assert int(done.stdout) == len(Part.read(os.path.join(MODEL, "stock.step")).Faces)


def test_a_step_point_of_nan_is_named_not_a_crash(tmp_path):
    """A CARTESIAN_POINT of NAN: OpenCASCADE reads a shape whose vertices are all NaN, and the stock's
    frame then raised FloatingPointError ('invalid bounding box') from FreeCAD's BoundBox (issue #29)."""
    import re

    text = open(os.path.join(MODEL, "stock.step"), encoding="latin-1").read()
    path = tmp_path / "stock.step"
    path.write_text(re.sub(r"CARTESIAN_POINT\('',\(([-0-9.E+]+),", "CARTESIAN_POINT('',(NAN,", text, count=1),
                    encoding="latin-1")
    with pytest.raises(InputError, match=rf"^{path}: damaged STEP: [0-9]+ of the shape's [0-9]+ vertices are not "
                                         "finite numbers"):
        recognise.load_solid(path)
