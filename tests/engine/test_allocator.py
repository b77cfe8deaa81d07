"""Freed memory is kept for reuse: repeated engine calls stop page-faulting (allocator.py).

The setting is process-wide and cannot be told apart once made, so each measurement runs in a
fresh interpreter: one with engage's call to keep_freed_memory replaced by a no-op (glibc's
defaults), one as shipped. Both count the minor page faults (memory the kernel had to hand out
anew) of the same engine calls after a warm-up run.
"""

import json
import os
import subprocess
import sys
import textwrap

import pytest

from tests.conftest import ROOT

_MEASURE = textwrap.dedent(
    """
    import json, resource, sys
    import numpy as np
    from abm_workbench.engine import CutSettings, Tool, engagement
    from abm_workbench.engine.engagement import edge_lines, engage, inside_intervals
    from abm_workbench.formats.staircase_json import load_staircase
    from abm_workbench.formats.toolpath_csv import load_toolpath
    if sys.argv[1] == "defaults":
        engagement.keep_freed_memory = lambda: None
    folder = "resources/models/model_test_1/"
    with open(folder + "job.json") as handle:
        job = json.load(handle)
    stock, path = load_staircase(folder + "stock.json"), load_toolpath(folder + "toolpath.csv")
    tool = Tool(job["diameter"], job["flutes"], job["flute_length"])
    settings = CutSettings(job["feed_per_tooth"], job["inclination"], *job["phi_range"], job["phi_step"])
    base, direction = edge_lines(path, tool, settings.phi)
    origins, directions = base.reshape(-1, 3), np.repeat(direction, settings.phi.size, axis=0)

    def calls():
        engage(stock, tool, path, settings)
        inside_intervals(stock, origins, directions, tool.flute_length)

    calls()
    before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    for _ in range(10):
        calls()
    print(json.dumps((resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before) / 10))
    """
)


def _faults_per_call(mode):
    run = subprocess.run([sys.executable, "-c", _MEASURE, mode], cwd=ROOT, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


def _glibc():
    try:
        return bool(os.confstr("CS_GNU_LIBC_VERSION"))
    except (ValueError, AttributeError):
        return False


@pytest.mark.skipif(not _glibc(), reason="the thresholds are glibc's")
def test_repeated_engine_calls_reuse_freed_memory():
    defaults, kept = _faults_per_call("defaults"), _faults_per_call("kept")
    # With glibc's defaults a model-test pass costs a thousand and more faults per call
    # (every large temporary is a fresh mapping); with the memory kept, next to none.
    assert defaults > 200, defaults
    assert kept < 0.1 * defaults, (kept, defaults)


def test_keep_freed_memory_reports_whether_it_applies():
    from abm_workbench.engine.allocator import keep_freed_memory

    assert keep_freed_memory() is _glibc()
    assert keep_freed_memory() is _glibc()  # a second call changes nothing and says the same
