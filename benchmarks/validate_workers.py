"""Validation's boolean reference on model test 1: one process against N workers, and one OpenCASCADE
common for all the edge lines of a CL point against one common per edge line.

Reads model test 1's STEP solid, recognises its exact-wall staircase, and validates the pass
(all 53 CL points, or --points N of them, φ by --phi-step degrees) once with one process and once
with each N of --workers; prints the wall-clock time of the boolean reference, the speed-up and
whether the references are the same bit for bit, and the CPU time used (this process and its
workers) against one process's: what running on workers costs in CPU (starting them, sending
tasks and results), which the wall-clock ratio hides on a loaded machine. Then, at
--boolean-points CL points, it times the reference of one CL point as the code computes it (all
edge lines in one common) and with one common per edge line, and prints the ratio. Every ratio comes from one run; the load average is
printed before and after each measurement, since other work on the two cores lowers the speed-up.
For a quiet measurement run it alone on an otherwise idle machine:

    /usr/bin/python3 benchmarks/validate_workers.py [--points N] [--phi-step DEG] [--workers 2 ...]
                                                    [--boolean-points K]
"""

import argparse
import json
import os
import resource
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

from abm_workbench.cad.boolean import edge_lengths_by_boolean  # noqa: E402
from abm_workbench.cad.freecad_env import FreeCAD, Part  # noqa: E402
from abm_workbench.cad.recognise import load_solid, recognise  # noqa: E402
from abm_workbench.engine import CutSettings, Tool, Toolpath, edge_lines  # noqa: E402
from abm_workbench.formats.toolpath_csv import load_toolpath  # noqa: E402
from abm_workbench.parallel import toolpath_part  # noqa: E402
from abm_workbench.validation import validate  # noqa: E402

MODEL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "resources", "models", "model_test_1")


def load():
    """Uptime's 1-minute load average, as text."""
    return f"{os.getloadavg()[0]:.2f}"


def cpu_seconds():
    """CPU seconds (user + system) of this process and of its ended children (the workers, once reaped)."""
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def per_line_seconds(solid, tool, toolpath, phi):
    """Seconds of one common per edge line (the edges of the result read off as well) at one CL point."""
    base, direction = edge_lines(toolpath, tool, phi)
    vector = FreeCAD.Vector(*direction[0]) * tool.flute_length
    started = time.perf_counter()
    for b in base[0]:
        for edge in solid.common(Part.LineSegment(FreeCAD.Vector(*b), FreeCAD.Vector(*b) + vector).toShape()).Edges:
            edge.valueAt(edge.FirstParameter)
    return time.perf_counter() - started


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=53)
    parser.add_argument("--phi-step", type=float, default=1.0)
    parser.add_argument("--workers", type=int, nargs="+", default=[2])
    parser.add_argument("--boolean-points", type=int, default=2)
    args = parser.parse_args()
    job = json.load(open(os.path.join(MODEL, "job.json")))
    full = load_toolpath(os.path.join(MODEL, "toolpath.csv"))
    rows = np.linspace(0, len(full) - 1, min(args.points, len(full))).round().astype(int)
    path = Toolpath(full.cl[rows], full.theta_a[rows], full.theta_b[rows])
    solid = load_solid(os.path.join(MODEL, "stock.step"))
    stock = recognise(solid).staircase
    tool = Tool(job["diameter"], job["flutes"], job["flute_length"])
    settings = CutSettings(job["feed_per_tooth"], job["inclination"], 0.0, 180.0, args.phi_step)
    print(f"model test 1: {len(path)} CL points x {settings.phi.size} angles; {os.cpu_count()} CPUs")
    before, cpu = load(), cpu_seconds()
    one = validate(solid, stock, tool, path, settings)
    base, base_cpu = one.seconds["boolean"], cpu_seconds() - cpu
    print(f"workers 1: boolean reference {base:.1f} s, CPU {base_cpu:.1f} s; load average {before} -> {load()}")
    for workers in args.workers:
        before, cpu = load(), cpu_seconds()
        many = validate(solid, stock, tool, path, settings, workers=workers)
        used = cpu_seconds() - cpu
        same = all(np.array_equal(one.reference[k], many.reference[k], equal_nan=one.reference[k].dtype.kind == "f")
                   for k in one.reference)
        seconds = many.seconds["boolean"]
        print(f"workers {workers}: boolean reference {seconds:.1f} s, speed-up {base / seconds:.2f}x, same bits: "
              f"{same}; CPU {used:.1f} s (this process and its workers), {used / base_cpu:.2f}x that of one "
              f"process; load average {before} -> {load()}")
    for i in np.linspace(0, len(path) - 1, min(args.boolean_points, len(path))).round().astype(int):
        point, before = toolpath_part(path, i, i + 1), load()
        started = time.perf_counter()
        edge_lengths_by_boolean(solid, tool, point, settings.phi)
        batched = time.perf_counter() - started
        single = per_line_seconds(solid, tool, point, settings.phi)
        print(f"CL point {rows[i]}: one common for {settings.phi.size} edge lines {batched:.2f} s, one per line "
              f"{single:.2f} s, ratio {single / batched:.1f}x; load average {before} -> {load()}")


if __name__ == "__main__":
    main()
