"""engage on a general 2.5D terraced stock (abm-terraced/1): the terraced engine's results, and what needs a staircase."""

import os

import numpy as np
import pytest

from abm_workbench import cli
from abm_workbench.engine import CutSettings, Tool, engage_terraced
from abm_workbench.formats.results_csv import read_results
from abm_workbench.formats.terraced_json import load_terraced
from abm_workbench.formats.toolpath_csv import load_toolpath
from tests.conftest import ROOT

MODEL = os.path.join(ROOT, "resources", "models", "model_test_4")
BASE = ["engage", "--stock", os.path.join(MODEL, "stock.json"), "--toolpath", os.path.join(MODEL, "toolpath.csv"),
        "--job", os.path.join(MODEL, "job.json"), "--phi-step", "5"]


def test_engage_on_a_terraced_stock_writes_the_terraced_engine_results(tmp_path, capsys):
    assert cli.main(BASE + ["--out", str(tmp_path / "R.csv"), "--stock-model", "initial"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[1].endswith("; stock: 2.5D terraced stock, 6 slabs; initial stock")
    written = read_results(tmp_path / "R.csv")
    want = engage_terraced(load_terraced(os.path.join(MODEL, "stock.json")), Tool(10, 2, 25),
                           load_toolpath(os.path.join(MODEL, "toolpath.csv")), CutSettings(0.1, 10, 0, 180, 5, 4000))
    np.testing.assert_allclose(written["length"], want.length.reshape(-1), atol=1e-9)
    np.testing.assert_allclose(written["lep_l"], want.lep_l.reshape(-1), atol=1e-9, equal_nan=True)
    assert (written["length"] > 0).sum() > 1000 and set(written["case"][written["length"] > 0]) == {"2.5D"}


@pytest.mark.parametrize("options, message", [
    (["--helix", "30"], "--helix: needs a staircase stock"),
    (["--method", "zmap"], "--method: the Z-map baseline needs a staircase stock"),
])
def test_what_needs_a_staircase_is_refused_on_a_terraced_stock(tmp_path, capsys, options, message):
    assert cli.main(BASE + ["--out", str(tmp_path / "R.csv")] + options) == 2
    assert capsys.readouterr().err.startswith(f"abm: error: {message}")
    assert os.listdir(tmp_path) == []


def test_forces_and_schedule_take_a_terraced_stock(tmp_path, capsys):
    """The force model and the feed schedule run on a general 2.5D stock as on a staircase: the forces are
    the API's (flute lengths by the terraced engine), and the scheduled feeds keep the force limit."""
    from abm_workbench.forces import material, pass_forces

    stock = load_terraced(os.path.join(MODEL, "stock.json"))
    toolpath = load_toolpath(os.path.join(MODEL, "toolpath.csv"))
    settings = CutSettings(0.1, 10, 0, 180, 5, 4000)
    forces = pass_forces(stock, Tool(10, 2, 25), toolpath, settings, material("al7075-t6"))
    assert forces.peak.max() > 0
    assert cli.main(BASE + ["--out", str(tmp_path / "R.csv"), "--forces", "--material", "al7075-t6",
                            "--stock-model", "initial"]) == 0
    written = read_results(tmp_path / "R.csv")
    np.testing.assert_allclose(written["fx"], forces.xyz[..., 0].reshape(-1), atol=1e-9)
    limit = 0.7 * forces.peak.max()
    out = tmp_path / "P.csv"
    assert cli.main(["schedule", *BASE[1:], "--material", "al7075-t6", "--max-force", f"{limit!r}",
                     "--stock-model", "initial", "--out", str(out)]) == 0
    feed = np.loadtxt(out, delimiter=",", skiprows=1, usecols=-2)  # feed_per_tooth, then feed_mm_min
    again = pass_forces(stock, Tool(10, 2, 25), toolpath, settings, material("al7075-t6"), feed=feed)
    assert (again.peak <= limit * (1 + 1e-9)).all() and (feed < 0.1).any()
    capsys.readouterr()
