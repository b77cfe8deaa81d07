"""Start-up: the command line imports scipy.interpolate, FreeCAD, matplotlib and dask only where a run uses them.

Each case runs ``python3 -m abm_workbench ...`` in a fresh interpreter that writes, as it exits, the
modules it imported; a structural test, not a timed one (docs/BENCHMARKS.md has the times).
"""

import json
import os
import subprocess
import sys

import pytest

from .test_parallel import MODELS, ROOT

MODEL = os.path.join(MODELS, "model_test_1")
#: Run the command line as ``python -m abm_workbench`` does, then list sys.modules into the file argv[1].
WRAPPER = """
import atexit, json, runpy, sys
out = sys.argv[1]
atexit.register(lambda: json.dump(sorted(sys.modules), open(out, "w")))
sys.argv = ["abm_workbench"] + sys.argv[2:]
runpy.run_module("abm_workbench", run_name="__main__", alter_sys=True)
"""
#: Modules a run imports only where it needs them.
HEAVY = ("scipy.interpolate", "scipy.spatial", "FreeCAD", "Part", "matplotlib", "dask", "distributed")


def imported(tmp_path, *argv):
    """(exit status, the HEAVY modules (and their submodules' roots) imported) of ``abm_workbench argv``."""
    listing = tmp_path / "modules.json"
    done = subprocess.run([sys.executable, "-c", WRAPPER, str(listing), *argv], cwd=ROOT, capture_output=True,
                          text=True, timeout=600)
    modules = json.loads(listing.read_text())
    return done.returncode, {heavy for heavy in HEAVY for name in modules
                             if name == heavy or name.startswith(heavy + ".")}


def json_job(tmp_path, out, *extra):
    return ("engage", "--stock", os.path.join(MODEL, "stock.json"), "--toolpath", os.path.join(MODEL, "toolpath.csv"),
            "--job", os.path.join(MODEL, "job.json"), "--out", str(tmp_path / out), *extra)


@pytest.mark.parametrize("argv", [("--help",), ("engage", "--help"), ("validate", "--help")])
def test_help_imports_none_of_them(tmp_path, argv):
    assert imported(tmp_path, *argv) == (0, set())


def test_a_json_job_against_the_stock_as_given_imports_none_of_them(tmp_path):
    assert imported(tmp_path, *json_job(tmp_path, "R.npz", "--stock-model", "initial")) == (0, set())


def test_a_json_job_against_the_in_process_stock_imports_scipy_spatial_only(tmp_path):
    """The in-process stock finds the swept pieces near each CL point with scipy.spatial's k-d tree."""
    assert imported(tmp_path, *json_job(tmp_path, "R.csv")) == (0, {"scipy.spatial"})


def test_a_plot_imports_matplotlib(tmp_path):
    """The listing sees what a run imports: a plot needs matplotlib."""
    status, heavy = imported(tmp_path, *json_job(tmp_path, "R.npz", "--stock-model", "initial", "--plot",
                                                 str(tmp_path / "R.png")))
    assert status == 0 and heavy == {"matplotlib"}


def modules(tmp_path, *argv):
    """(exit status, every module imported) of ``abm_workbench argv``."""
    listing = tmp_path / "modules.json"
    done = subprocess.run([sys.executable, "-c", WRAPPER, str(listing), *argv], cwd=ROOT, capture_output=True,
                          text=True, timeout=600)
    return done.returncode, set(json.loads(listing.read_text()))


#: What a toolpath CSV job run in this process never needs: the CL file reader, the APT wrapper, and
#: the machinery of worker processes.
NOT_FOR_A_CSV_JOB = {"abm_workbench.formats.cl.reader", "abm_workbench.formats.apt", "concurrent.futures"}


def test_a_json_job_with_a_toolpath_csv_imports_no_cl_reader_nor_process_pool(tmp_path):
    status, found = modules(tmp_path, *json_job(tmp_path, "R.npz", "--stock-model", "initial"))
    assert status == 0 and "abm_workbench.jobs.run" in found and not found & NOT_FOR_A_CSV_JOB


def test_a_cl_file_imports_the_cl_reader(tmp_path):
    """The listing sees the lazy imports: an APT file needs the CL reader."""
    status, found = modules(tmp_path, "toolpath", os.path.join(ROOT, "tests", "fuzz", "model_test_1.apt"))
    assert status == 0 and "abm_workbench.formats.cl.reader" in found


@pytest.mark.parametrize("argv", [("--help",), ("engage", "--help"), ("engage",)])
def test_help_and_usage_errors_import_no_run_machinery(tmp_path, argv):
    status, found = modules(tmp_path, *argv)
    assert status in (0, 2) and not found & ({"abm_workbench.jobs.run", "abm_workbench.jobs.job"} | NOT_FOR_A_CSV_JOB)
