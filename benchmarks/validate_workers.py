"""Speed-up of validation.validate(..., workers=N) over one process on model test 1.

Reads model test 1's STEP solid, recognises its exact-wall staircase, and validates the pass
(all 53 CL points, or --points N of them, φ by --phi-step degrees) once with one process and
once with each N of --workers; prints the wall-clock time of the boolean reference, the
speed-up and whether the references are the same bit for bit. The machine's load average is
printed too: other work on the cores lowers the speed-up.

    /usr/bin/python3 benchmarks/validate_workers.py [--points N] [--phi-step DEG] [--workers 2 ...]
"""

import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

from abm_workbench.cad.recognise import load_solid, recognise  # noqa: E402
from abm_workbench.engine import CutSettings, Tool, Toolpath  # noqa: E402
from abm_workbench.formats.toolpath_csv import load_toolpath  # noqa: E402
from abm_workbench.validation import validate  # noqa: E402

MODEL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "resources", "models", "model_test_1")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=53)
    parser.add_argument("--phi-step", type=float, default=1.0)
    parser.add_argument("--workers", type=int, nargs="+", default=[2])
    args = parser.parse_args()
    job = json.load(open(os.path.join(MODEL, "job.json")))
    full = load_toolpath(os.path.join(MODEL, "toolpath.csv"))
    rows = np.linspace(0, len(full) - 1, min(args.points, len(full))).round().astype(int)
    path = Toolpath(full.cl[rows], full.theta_a[rows], full.theta_b[rows])
    solid = load_solid(os.path.join(MODEL, "stock.step"))
    stock = recognise(solid).staircase
    tool = Tool(job["diameter"], job["flutes"], job["flute_length"])
    settings = CutSettings(job["feed_per_tooth"], job["inclination"], 0.0, 180.0, args.phi_step)
    print(f"model test 1: {len(path)} CL points x {settings.phi.size} angles; load average {os.getloadavg()[0]:.2f}")
    one = validate(solid, stock, tool, path, settings)
    base = one.seconds["boolean"]
    print(f"workers 1: boolean reference {base:.1f} s")
    for workers in args.workers:
        many = validate(solid, stock, tool, path, settings, workers=workers)
        same = all(np.array_equal(one.reference[k], many.reference[k], equal_nan=one.reference[k].dtype.kind == "f")
                   for k in one.reference)
        seconds = many.seconds["boolean"]
        print(f"workers {workers}: boolean reference {seconds:.1f} s, speed-up {base / seconds:.2f}x, "
              f"same bits: {same}; load average {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
