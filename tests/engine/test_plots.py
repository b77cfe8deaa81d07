"""Pass plots: a readable PNG for ordinary, degenerate and empty engagements; no pyplot."""

import os
import struct
import subprocess

import numpy as np
import pytest

from abm_workbench.engine import CutSettings, Staircase, Tool, Toolpath, engage
from abm_workbench.report.plots import plot_pass, representative_cl

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# Two sections with a straight wall at x = 50 between them (mm).
STOCK = Staircase(0, 100, -10, 10, -10, [2.0, 5.0], [[[50.0, y] for y in np.linspace(-10, 10, 6)]])


def pass_over_step(m=20, z=-1.0, phi_step=2.0):
    """Engagement of m CL points crossing the step at height z, tool tilted 8° about y."""
    x = np.linspace(5, 95, m)
    toolpath = Toolpath(np.c_[x, np.zeros(m), np.full(m, z)], np.zeros(m), np.full(m, 8.0))
    return engage(STOCK, Tool(10, 3, 25), toolpath, CutSettings(0.12, 5, 0, 180, phi_step))


def png_size(path):
    """(width, height) in pixels from the PNG header; asserts the PNG signature."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and data[12:16] == b"IHDR"
    return struct.unpack(">II", data[16:24])


def test_plot_pass_writes_a_png(tmp_path):
    path = tmp_path / "pass.png"
    plot_pass(pass_over_step(), path, title="step at x = 50 mm")
    assert png_size(path) == (1200, 1200)
    assert 30_000 < path.stat().st_size < 2_000_000
    assert os.listdir(tmp_path) == ["pass.png"]


@pytest.mark.parametrize(
    "engagement",
    [pass_over_step(m=1), pass_over_step(m=2, phi_step=180.0), pass_over_step(z=40.0)],
    ids=["one CL point", "one angle per half turn", "never engaged"],
)
def test_plot_pass_degenerate_passes(tmp_path, engagement):
    path = tmp_path / "pass.png"
    plot_pass(engagement, path)
    assert png_size(path) == (1200, 1200)


def test_representative_cl():
    depth = np.array([np.nan, 3.0, 5.0, 4.0, 4.5, 1.0, np.nan])
    assert representative_cl(depth) == [(2, "deepest"), (5, "shallowest"), (3, "middle")]
    assert representative_cl(np.array([np.nan, 2.0, 2.0])) == [(1, "deepest"), (2, "middle")]
    assert representative_cl(np.array([np.nan, 2.0])) == [(1, "deepest")]
    assert representative_cl(np.full(3, np.nan)) == []


def test_plots_never_touch_pyplot():
    code = "import sys, abm_workbench.report.plots; assert 'matplotlib.pyplot' not in sys.modules"
    subprocess.run(["/usr/bin/python3", "-c", code], cwd=ROOT, check=True, timeout=120)
