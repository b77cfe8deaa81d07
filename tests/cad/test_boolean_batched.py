"""The boolean reference computes all the edge lines of a CL point in one OpenCASCADE common; here
each edge line is cut by the solid on its own (one common per line, its pieces read off in the test)
and the two must agree to 1e-9 mm in length, LEP, UEP and number of pieces, on both model tests'
STEP solids at CL points over curved walls, straight walls and tops, every 6° of φ."""

import json
import os

import numpy as np
import pytest

from abm_workbench.cad.boolean import edge_lengths_by_boolean
from abm_workbench.cad.freecad_env import FreeCAD, Part
from abm_workbench.cad.recognise import load_solid
from abm_workbench.engine import Tool, Toolpath, edge_lines
from abm_workbench.formats.toolpath_csv import load_toolpath

MODELS = os.path.join(os.path.dirname(__file__), "..", "..", "resources", "models")
TOL = 1e-9  # mm
PHI = np.arange(0.0, 181.0, 6.0)  # deg: 31 edge lines per CL point (one common per line costs 0.1-0.6 s)


def one_by_one(solid, tool, toolpath, phi):
    """{length, lep_l, uep_l, pieces} (m, p): every edge line cut by `solid` on its own."""
    base, direction = edge_lines(toolpath, tool, phi)
    m, p = base.shape[:2]
    out = {"length": np.zeros((m, p)), "lep_l": np.full((m, p), np.nan), "uep_l": np.full((m, p), np.nan),
           "pieces": np.zeros((m, p), dtype=int)}
    for i in range(m):
        for k in range(p):
            start = FreeCAD.Vector(*base[i, k])
            line = Part.LineSegment(start, start + FreeCAD.Vector(*direction[i]) * tool.flute_length).toShape()
            intervals = []
            for edge in solid.common(line).Edges:
                ends = sorted((edge.valueAt(u) - start).dot(FreeCAD.Vector(*direction[i])) for u in edge.ParameterRange)
                if ends[1] - ends[0] > 1e-9:
                    intervals.append(ends)
            joined = []
            for a, b in sorted(intervals):
                if joined and a - joined[-1][1] < 1e-9:
                    joined[-1][1] = max(joined[-1][1], b)
                else:
                    joined.append([a, b])
            if joined:
                out["length"][i, k] = sum(b - a for a, b in joined)
                out["lep_l"][i, k], out["uep_l"][i, k] = joined[0][0], joined[-1][1]
                out["pieces"][i, k] = len(joined)
    return out


@pytest.mark.parametrize("name, rows", [("model_test_1", [3, 44]), ("model_test_2", [5, 35])])
def test_one_common_for_all_edge_lines_equals_one_per_line(name, rows):
    folder = os.path.join(MODELS, name)
    job = json.load(open(os.path.join(folder, "job.json")))
    full = load_toolpath(os.path.join(folder, "toolpath.csv"))
    rows = [row for row in rows if row < len(full)]
    path = Toolpath(full.cl[rows], full.theta_a[rows], full.theta_b[rows])
    tool = Tool(job["diameter"], job["flutes"], job["flute_length"])
    solid = load_solid(os.path.join(folder, "stock.step"))
    batched = edge_lengths_by_boolean(solid, tool, path, PHI)
    single = one_by_one(solid, tool, path, PHI)
    assert (single["length"] > 0).any()
    assert np.array_equal(batched["pieces"], single["pieces"])
    for field in ("length", "lep_l", "uep_l"):
        assert np.array_equal(np.isnan(batched[field]), np.isnan(single[field])), field
        assert np.nanmax(np.abs(batched[field] - single[field])) <= TOL, field
