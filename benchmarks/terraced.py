"""Throughput of engage_terraced (instants per second) next to the staircase engine, in one run.

Run from the repository root (about a minute):

    /usr/bin/python3 benchmarks/terraced.py [--repeats 3]

Cases, each the best of --repeats runs after one warm-up run, engine time only:

- "terraced part": a realistic terraced stock, seven levels: a block with a closed pocket
  (rounded corners: lines and arcs), a round boss standing in it, a ring terrace (two circles),
  a ridge across y and a B-spline island; a pass of 53 CL points across it, tilted, φ 0..180°
  at 1° (9593 instants);
- "model test 4": resources/models/model_test_4 (abm-terraced/1) with its own pass and job;
- "model test 1 as terraced": the staircase of resources/models/model_test_1/stock.json through
  staircase_as_terraced and engage_terraced;
- "model test 1, staircase engine": the same stock and pass through engine.engage.

Prints a Markdown table (case, slabs, boundary curves, instants, seconds, instants/s).
"""

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")  # one core, before numpy is imported

import argparse  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from abm_workbench.engine import CutSettings, Tool, Toolpath, engage  # noqa: E402
from abm_workbench.engine.terraced import engage_terraced  # noqa: E402
from abm_workbench.engine.terraced_model import Loop, PlanArc, PlanLine, PlanSpline, Slab, TerracedStock  # noqa: E402
from abm_workbench.engine.terraced_pieces import curve_list  # noqa: E402
from abm_workbench.engine.terraced_staircase import staircase_as_terraced  # noqa: E402
from abm_workbench.formats.staircase_json import load_staircase  # noqa: E402
from abm_workbench.formats.terraced_json import load_terraced  # noqa: E402
from abm_workbench.formats.toolpath_csv import load_toolpath  # noqa: E402
from abm_workbench.jobs import load_job  # noqa: E402

MODELS = os.path.join(ROOT, "resources", "models")


def rectangle(x0, y0, x1, y1):
    """Closed loop of an axis-parallel rectangle (mm)."""
    p = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    return Loop(tuple(PlanLine(p[i], p[(i + 1) % 4]) for i in range(4)))


def rounded(cx, cy, a, b, r):
    """Closed loop of a rectangle of half sizes a, b (mm) with corners of radius r."""
    corners = [(cx + a - r, cy - b + r, -0.5 * np.pi), (cx + a - r, cy + b - r, 0.0),
               (cx - a + r, cy + b - r, 0.5 * np.pi), (cx - a + r, cy - b + r, np.pi)]
    arcs = [PlanArc((x, y), r, s, 0.5 * np.pi) for x, y, s in corners]
    curves = []
    for i, arc in enumerate(arcs):
        curves += [arc, PlanLine(arc.end_points[1], arcs[(i + 1) % 4].end_points[0])]
    return Loop(tuple(curves))


def circle(cx, cy, r):
    """Closed loop of a full circle (mm)."""
    return Loop((PlanArc((cx, cy), r, 0.0, 2 * np.pi),))


def blob(cx, cy, size):
    """A closed cubic B-spline island of about `size` mm across."""
    theta = np.linspace(0, 2 * np.pi, 9, endpoint=False)
    radii = size * np.array([0.5, 0.4, 0.55, 0.45, 0.5, 0.38, 0.52, 0.44, 0.5])
    control = np.column_stack([cx + radii * np.cos(theta), cy + radii * np.sin(theta)])
    control = np.vstack([control, control[:1]])
    knots = np.concatenate([[0, 0, 0], np.linspace(0, 1, len(control) - 2), [1, 1, 1]])
    return Loop((PlanSpline(3, knots, control),))


def terraced_part():
    """Seven levels of a part: pocket, boss, ring terrace, ridge, spline island (mm)."""
    block = rectangle(0, -40, 120, 40)
    slabs = [Slab(0.0, 4.0, (block,))]
    for k, z in enumerate((7.0, 10.0, 13.0, 16.0, 19.0, 22.0)):
        grow = 1.5 * k
        loops = [block, rounded(40, 0, 25 + grow, 25 + grow, 6 + grow)]  # the pocket
        if z <= 16.0:
            loops.append(circle(40, 0, 9 - k))  # the boss in the pocket
        loops += [circle(92, 0, 20 - k), circle(92, 0, 8 + k)]  # the ring terrace: material between
        if z <= 13.0:
            loops.append(blob(92, 0, 6.0))  # an island in the ring's hole
        loops.append(rectangle(70 - 0.5 * k, -40, 72 + 0.5 * k, 40))  # the ridge across y: a trough
        slabs.append(Slab(slabs[-1].z_top, z, tuple(loops)))
    return TerracedStock(tuple(slabs))


def part_pass():
    """53 CL points across the part along x at y = 3, tilted (Toolpath), tool, settings."""
    x = np.linspace(5.0, 115.0, 53)
    cl = np.column_stack([x, np.full(53, 3.0), 6.0 + 8.0 * np.sin(x / 20.0) ** 2])
    roll = np.radians(8.0) * np.sin(np.linspace(0, 2 * np.pi, 53))
    axis = np.column_stack([np.full(53, np.sin(np.radians(10.0))), -np.sin(roll), np.cos(roll)])
    return Toolpath.from_axes(cl, axis), Tool(12.0, 2, 30.0), CutSettings(0.1, 10.0, 0.0, 180.0, 1.0)


def model(number):
    """(toolpath, tool, settings) of resources/models/model_test_<number>."""
    folder = os.path.join(MODELS, f"model_test_{number}")
    job = load_job(os.path.join(folder, "job.json"))
    tool = Tool(job["diameter"], int(job["flutes"]), job["flute_length"])
    settings = CutSettings(job["feed_per_tooth"], job["inclination"], job["phi_start"], job["phi_end"],
                           job["phi_step"])  # jobs.load_job reads phi_range as its two parameters
    return load_toolpath(os.path.join(folder, "toolpath.csv")), tool, settings


def best_time(run, repeats):
    """Best wall time (s) of `repeats` calls of run() after one warm-up call."""
    run()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return min(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    part_path, part_tool, part_settings = part_pass()
    m4_path, m4_tool, m4_settings = model(4)
    m1_path, m1_tool, m1_settings = model(1)
    staircase = load_staircase(os.path.join(MODELS, "model_test_1", "stock.json"))
    cases = [
        ("terraced part (pocket, boss, ring, ridge, spline island)", terraced_part(), part_path, part_tool,
         part_settings, engage_terraced),
        ("model test 4", load_terraced(os.path.join(MODELS, "model_test_4", "stock.json")), m4_path, m4_tool,
         m4_settings, engage_terraced),
        ("model test 1 as terraced", staircase_as_terraced(staircase), m1_path, m1_tool, m1_settings, engage_terraced),
        ("model test 1, staircase engine (engine.engage)", staircase, m1_path, m1_tool, m1_settings, engage),
    ]
    print(f"{platform.processor() or platform.machine()}, Python {platform.python_version()}, numpy {np.__version__}, "
          f"one thread, best of {args.repeats}\n")
    print("| case | slabs | boundary curves | instants | s | instants/s |")
    print("|---|---|---|---|---|---|")
    for name, stock, path, tool, settings, engine in cases:
        seconds = best_time(lambda: engine(stock, tool, path, settings), args.repeats)
        instants = len(path) * settings.phi.size
        if isinstance(stock, TerracedStock):
            slabs, curves = len(stock.slabs), len(curve_list(stock))
        else:
            slabs, curves = stock.n_sections, "-"
        print(f"| {name} | {slabs} | {curves} | {instants} | {seconds:.3f} | {instants / seconds:,.0f} |")


if __name__ == "__main__":
    main()
