"""Job loading without FreeCAD: JSON stock, CSV and APT toolpaths, parameters and their sources."""

import json
import subprocess
import sys
import textwrap

import numpy as np
import pytest

from abm_workbench.engine import Staircase, Tool, Toolpath, edge_lines
from abm_workbench.errors import InputError, MissingParameter, ParameterError
from abm_workbench.jobs import PathHints, load_job, load_path, load_stock, option_words, resolve, swept_y_window
from tests.conftest import ROOT

STOCK = {
    "format": "abm-staircase/1", "units": "mm", "base_z": -20, "x_min": 0, "x_max": 130, "y_min": -15,
    "y_max": 15, "sections": [{"z_top": 4.0}, {"z_top": 6.5, "wall": [[40, v] for v in (-15, -9, -3, 3, 9, 15)]}],
}
APT = """\
$$ a pass of three CL points
MULTAX/ON
CUTTER/12,0,6,0,0,0,60
CSI_SET_FLUTE_LENGTH/30
SPINDL/RPM,4000,CLW
FEDRAT/MMPM,800
COOLNT/ON
GOTO/10,0,1,0,0,1
AUXFUN/3
GOTO/20,0,1,0.1736482,0,0.9848078
GOTO/30,0,1,0.1736482,0,0.9848078
AUXFUN/4
END-OF-PATH
"""
NONE = dict.fromkeys(("diameter", "flutes", "flute_length", "feed_per_tooth", "inclination", "spindle_rpm",
                      "phi_start", "phi_end", "phi_step"))


@pytest.fixture
def files(tmp_path):
    """tmp_path with stock.json, path.apt and path.csv (the APT file's CL points)."""
    (tmp_path / "stock.json").write_text(json.dumps(STOCK))
    (tmp_path / "path.apt").write_text(APT)
    (tmp_path / "path.csv").write_text("x,y,z,theta_a,theta_b\n10,0,1,0,0\n20,0,1,0,10\n30,0,1,0,10\n")
    return tmp_path


def test_json_stock(files):
    stock = load_stock(files / "stock.json")
    assert isinstance(stock.staircase, Staircase) and stock.shape is None
    assert stock.walls == "quintic" and stock.y_window == (-15.0, 15.0)
    assert stock.staircase.z_top.tolist() == [4.0, 6.5]


def test_apt_path_and_its_hints(files):
    toolpath, hints = load_path(files / "path.apt")
    csv_path, csv_hints = load_path(files / "path.csv")
    np.testing.assert_allclose(toolpath.cl, csv_path.cl)
    np.testing.assert_allclose(toolpath.theta_b, csv_path.theta_b, atol=1e-6)
    assert (hints.diameter, hints.flute_length, hints.spindle_rpm, hints.feed_unit) == (12.0, 30.0, 4000.0, "MMPM")
    assert hints.feed.tolist() == [800.0] * 3
    assert hints.messages() == [f"{files / 'path.apt'}: records that carry nothing the engine needs, ignored: "
                                "COOLNT (1), AUXFUN (2), END-OF-PATH (1)"]
    assert (csv_hints.diameter, csv_hints.flute_length, csv_hints.spindle_rpm, csv_hints.frame) == (None,) * 4
    assert csv_hints.messages() == []


@pytest.mark.parametrize("name, message", [
    ("stock.txt", "stock.txt: unknown stock file type; expected .json, .step"),
    ("path.nc", "path.nc: empty file: no CL records and no toolpath CSV header"),
])
def test_unknown_file_types(files, name, message):
    (files / name).write_text("")
    with pytest.raises(InputError, match=message.replace(".", r"\.")):
        (load_stock if name.startswith("stock") else load_path)(files / name)


def test_bad_wall_options(files):
    with pytest.raises(ValueError, match="walls must be one of"):
        load_stock(files / "stock.json", walls="spline")
    with pytest.raises(ValueError, match="wall_points must be one of"):
        load_stock(files / "stock.json", wall_points="random")


def test_parameters_apt_over_option_over_job_over_default(files):
    _, hints = load_path(files / "path.apt")
    job = {"diameter": 10.0, "flutes": 2.0, "flute_length": 30.0, "feed_per_tooth": 0.2, "phi_step": 5.0}
    given = {**NONE, "flute_length": 25.0, "spindle_rpm": 5000.0}
    parameters = resolve(given, hints, job, str(files / "job.json"))
    values, sources = parameters.values, parameters.sources
    assert (values["diameter"], sources["diameter"]) == (12.0, ("file", "path.apt CUTTER"))
    assert (values["flute_length"], sources["flute_length"]) == (30.0, ("file", "path.apt CSI_SET_FLUTE_LENGTH"))
    assert (values["flutes"], sources["flutes"]) == (2.0, ("job", "job.json"))
    assert (values["spindle_rpm"], sources["spindle_rpm"]) == (4000.0, ("file", "path.apt SPINDL"))
    # A constant FEDRAT of 800 mm/min at 4000 rpm with 2 flutes: 0.1 mm per tooth.
    assert sources["feed_per_tooth"] == ("file", "path.apt FEDRAT") and values["feed_per_tooth"] == pytest.approx(0.1)
    assert (values["inclination"], sources["inclination"]) == (0.0, ("default", ""))
    assert (values["phi_step"], sources["phi_step"]) == (5.0, ("job", "job.json"))
    # diameter 12 vs the job's 10, flute length 30 vs --flute-length 25, spindle 4000 vs
    # --spindle-rpm 5000, feed per tooth 0.1 vs the job's 0.2
    assert len(parameters.conflicts) == 4
    assert parameters.conflicts[0] == (f"{files / 'path.apt'} gives diameter 12, {files / 'job.json'} 10: "
                                       "using 12, the value the toolpath was made for")
    assert parameters.conflicts[1].startswith(f"{files / 'path.apt'} gives flute_length 30, --flute-length 25: ")
    assert parameters.conflicts[2].startswith(f"{files / 'path.apt'} gives spindle_rpm 4000, --spindle-rpm 5000: ")
    line = parameters.describe()
    assert "diameter 12 mm [path.apt CUTTER]" in line and "flute length 30 mm [path.apt CSI_SET_FLUTE_LENGTH]" in line
    assert "feed 0.1 mm/tooth [path.apt FEDRAT]" in line and "φ 0..180° [default]" in line


@pytest.mark.parametrize("feed, unit, rpm, expected", [
    ([0.2, 0.2], "MMPR", None, 0.1),
    ([0.01, 0.01], "IPR", None, 0.127),
    ([40.0, 40.0], "IPM", 4000.0, 0.127),
    ([800.0, 800.0], "MMPM", None, None),  # per minute, and no spindle speed
    ([800.0, 900.0], "MMPM", 4000.0, None),  # varies along the pass
    ([np.nan, 800.0], "MMPM", 4000.0, None),  # the first move before any FEDRAT
])
def test_feed_per_tooth_from_the_apt_feed(feed, unit, rpm, expected):
    hints = PathHints("p.apt", spindle_rpm=rpm, feed=np.array(feed), feed_unit=unit)
    job = {"diameter": 10.0, "flutes": 2.0, "flute_length": 30.0, "feed_per_tooth": 0.3}
    values = resolve(NONE, hints, job, "job.json").values
    assert values["feed_per_tooth"] == pytest.approx(0.3 if expected is None else expected)


def test_missing_required_parameter():
    with pytest.raises(MissingParameter) as caught:
        resolve({**NONE, "diameter": 10.0}, PathHints("p.csv"), {})
    assert caught.value.field == "flutes"
    assert option_words(caught.value) == "missing --flutes (or 'flutes' in a --job file)"


def test_job_file(files):
    (files / "job.json").write_text(json.dumps({"diameter": 12, "phi_range": [0, 90], "description": "t"}))
    assert load_job(files / "job.json") == {"diameter": 12.0, "phi_start": 0.0, "phi_end": 90.0, "description": "t"}


def test_job_file_values_are_checked_naming_the_file(files):
    (files / "job.json").write_text(json.dumps({"diameter": -1}))
    with pytest.raises(ParameterError) as caught:
        load_job(files / "job.json")
    assert (caught.value.field, caught.value.where) == ("diameter", str(files / "job.json"))
    assert option_words(caught.value) == f"{files / 'job.json'}: diameter: must be positive, got -1 mm"


def test_swept_window_holds_every_edge_point():
    toolpath = Toolpath([[10, 2, 1], [20, -3, 4], [30, 0, 2]], [15, -25, 0], [20, -10, 30])
    tool = Tool(12, 2, 30)
    base, direction = edge_lines(toolpath, tool, np.linspace(0, 360, 721))
    l = np.linspace(0, tool.flute_length, 31)
    y = base[:, :, None, 1] + l[None, None, :] * direction[:, None, None, 1]
    low, high = swept_y_window(toolpath, tool, margin=0.0)
    assert low <= y.min() + 1e-12 and high >= y.max() - 1e-12
    assert y.min() - low < 1e-3 and high - y.max() < 1e-3  # and is tight (to the sampling)
    assert swept_y_window(toolpath, tool) == pytest.approx((low - 1.0, high + 1.0))


def test_swept_window_below_the_stock_top_holds_every_edge_point_below_it():
    toolpath = Toolpath([[10, 2, 1], [20, -3, 4], [30, 0, 2]], [15, -25, 0], [20, -10, 30])
    tool, z_max = Tool(12, 2, 30), 9.0
    base, direction = edge_lines(toolpath, tool, np.linspace(0, 360, 721))
    l = np.linspace(0, tool.flute_length, 3001)
    points = base[:, :, None, :] + l[None, None, :, None] * direction[:, None, None, :]
    below = points[..., 1][points[..., 2] <= z_max]
    low, high = swept_y_window(toolpath, tool, z_max, margin=0.0)
    whole = swept_y_window(toolpath, tool, margin=0.0)
    assert low <= below.min() + 1e-12 and high >= below.max() - 1e-12
    assert whole[0] < low - 1.0 and high < whole[1]  # narrower than the whole flute's sweep


def test_json_jobs_never_import_freecad(files):
    script = textwrap.dedent(f"""
        import sys
        class Block:
            def find_spec(self, name, path=None, target=None):
                if name.split(".")[0] in ("FreeCAD", "FreeCADGui", "Part"):
                    raise ImportError("blocked: " + name)
        sys.meta_path.insert(0, Block())
        from abm_workbench.jobs import load_path, load_stock
        load_stock({str(files / 'stock.json')!r})
        load_path({str(files / 'path.apt')!r})
        print("ok")
    """)
    run = subprocess.run([sys.executable, "-c", script], cwd=ROOT, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "ok"


def test_job_file_values_too_large_are_refused(files):
    (files / "job.json").write_text('{"diameter": 1e300}')
    with pytest.raises(ParameterError) as caught:
        load_job(files / "job.json")
    assert option_words(caught.value) == f"{files / 'job.json'}: diameter: must be at most 1e+12 in size, got 1e+300"
