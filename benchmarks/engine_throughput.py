"""Engine throughput: instants per second for model test 1 and for a toolpath of ≥ 10^6 instants,
and exact against quintic walls on both model tests' STEP solids.

Run with FreeCAD's Python from the repository root: `/usr/bin/python3 benchmarks/engine_throughput.py`
(or `make benchmark`). Times are engine time only (files are loaded before the clock starts),
the best and the median of several runs on one core (numpy is single-threaded for these
operations). Peak memory is what tracemalloc sees numpy allocate during one run.
The walls table reads each stock.step twice, as the command line does: `--walls exact` (the
solid's own B-spline walls, over the whole strip) and `--walls quintic` (the paper's quintics,
fitted over the y range the pass sweeps); the two are timed in alternation, so that a change in
the machine's load falls on both, and their ratio is printed from the same run.
`--steps` prints where one exact and one quintic 53-point pass of each model test spend their
CPU time, step by step (the engine's own functions, each timed inclusively where it is called).
"""

import argparse
import json
import os
import sys
import time
import tracemalloc

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from abm_workbench.engine import CutSettings, Tool, Toolpath, engage  # noqa: E402
from abm_workbench.formats.staircase_json import load_staircase  # noqa: E402
from abm_workbench.formats.toolpath_csv import load_toolpath  # noqa: E402

MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")


def load_model(folder):
    """Stock, tool, toolpath and settings of a bundled model test."""
    with open(os.path.join(folder, "job.json")) as handle:
        job = json.load(handle)
    tool = Tool(job["diameter"], job["flutes"], job["flute_length"])
    settings = CutSettings(job["feed_per_tooth"], job["inclination"], *job["phi_range"], job["phi_step"])
    stock = load_staircase(os.path.join(folder, "stock.json"))
    return stock, tool, load_toolpath(os.path.join(folder, "toolpath.csv")), settings


def densified(toolpath, count):
    """The pass resampled to `count` CL points by linear interpolation along its index."""
    old = np.arange(len(toolpath))
    new = np.linspace(0, len(toolpath) - 1, count)
    cl = np.column_stack([np.interp(new, old, toolpath.cl[:, i]) for i in range(3)])
    return Toolpath(cl, np.interp(new, old, toolpath.theta_a), np.interp(new, old, toolpath.theta_b))


def step_stocks(folder, toolpath, tool):
    """(exact, quintic) Staircases of a model test's stock.step, recognised as the command line does."""
    from abm_workbench.jobs.inputs import load_stock, swept_y_window  # FreeCAD only here

    step = os.path.join(folder, "stock.step")
    exact = load_stock(step, walls="exact").staircase
    quintic = load_stock(step, walls="quintic", y_window=lambda z_max: swept_y_window(toolpath, tool, z_max)).staircase
    return exact, quintic


def alternating(stocks, tool, path, settings, repeats):
    """Best wall-clock and best CPU seconds (per stock) of engage() on each of `stocks`, run in
    turn `repeats` times. CPU time is this process's own: on a machine with more runnable
    processes than cores it is the time of one core, where wall-clock time also counts waiting."""
    for stock in stocks:
        engage(stock, tool, path, settings)
    wall, cpu = [[] for _ in stocks], [[] for _ in stocks]
    for _ in range(repeats):
        for k, stock in enumerate(stocks):
            start, start_cpu = time.perf_counter(), time.process_time()
            engage(stock, tool, path, settings)
            wall[k].append(time.perf_counter() - start)
            cpu[k].append(time.process_time() - start_cpu)
    return [(float(np.min(w)), float(np.min(c))) for w, c in zip(wall, cpu)]


def walls_table(repeats, large):
    """Exact against quintic walls on both model tests' STEP solids: the 53-point pass and ≥ `large` instants."""
    print(f"\nload average before: {' '.join(f'{v:.2f}' for v in os.getloadavg())}")
    print(f"{'case':<34} {'instants':>9} {'clock':>5} {'exact ms':>9} {'quintic ms':>10} {'exact /s':>10} "
          f"{'quintic /s':>10} {'exact/quintic':>13}")
    for number in (1, 2):
        folder = MODEL.replace("model_test_1", f"model_test_{number}")
        _, tool, path, settings = load_model(folder)
        stocks = step_stocks(folder, path, tool)
        p = settings.phi.size
        big = densified(path, -(-large // p))
        for name, toolpath, runs in ((f"model test {number}, 53 CL x {p} phi", path, repeats),
                                     (f"model test {number}, {len(big)} CL x {p} phi", big, 3)):
            (exact_wall, exact_cpu), (quintic_wall, quintic_cpu) = alternating(stocks, tool, toolpath, settings, runs)
            n = len(toolpath) * p
            for clock, exact, quintic in (("wall", exact_wall, quintic_wall), ("cpu", exact_cpu, quintic_cpu)):
                print(f"{name:<34} {n:>9} {clock:>5} {exact * 1e3:>9.1f} {quintic * 1e3:>10.1f} {n / exact:>10.3g} "
                      f"{n / quintic:>10.3g} {exact / quintic:>13.2f}")
    print(f"load average after: {' '.join(f'{v:.2f}' for v in os.getloadavg())}")


#: (label, function name in engagement.py) of the steps --steps times, in the order a chunk runs them.
#: The three solvers call _table1_case; its time is also inside theirs.
STEPS = (("edge lines", "edge_lines"), ("clip to the bounding box", "_clip"),
         ("candidate walls (bands)", "_reachable_walls"), ("quintic crossings", "_wall_crossings"),
         ("exact crossings", "_exact_crossings"), ("one section", "_single_section"),
         ("single crossings", "_single_crossings"), ("breakpoints", "_broken_lines"),
         ("  of which Table 1 cases", "_table1_case"), ("results (area, depth, segments)", "finished_engagement"))


def step_times(stocks, tool, path, settings, repeats):
    """Mean CPU seconds per engage() call of each STEPS function and of the whole call, for each
    of `stocks`, over `repeats` calls of each: a list of {name: seconds}, "engage" the whole. The
    functions are wrapped with a timer for the measurement only. The stocks take turns call by
    call, after ten calls of each: a process's first engine calls are slower (the allocator and
    numpy's caches settling), which would otherwise bias whichever stock runs first."""
    from abm_workbench.engine import engagement

    spent = [{name: 0.0 for _, name in STEPS + (("", "engage"),)} for _ in stocks]
    originals = {name: getattr(engagement, name) for _, name in STEPS}
    current = [None]

    def timed(name):
        def call(*args, **kwargs):
            start = time.process_time()
            try:
                return originals[name](*args, **kwargs)
            finally:
                current[0][name] += time.process_time() - start
        return call

    for _ in range(10):
        for stock in stocks:
            engage(stock, tool, path, settings)
    for name in originals:
        setattr(engagement, name, timed(name))
    try:
        for _ in range(repeats):
            for stock, times in zip(stocks, spent):
                current[0] = times
                start = time.process_time()
                engage(stock, tool, path, settings)
                times["engage"] += time.process_time() - start
    finally:
        for name, function in originals.items():
            setattr(engagement, name, function)
    return [{name: value / repeats for name, value in times.items()} for times in spent]


def steps_table(repeats):
    """Per-step CPU ms of one 53-point pass, exact against quintic walls, on both model tests' STEP solids."""
    print(f"\nload average before: {' '.join(f'{v:.2f}' for v in os.getloadavg())}")
    for number in (1, 2):
        folder = MODEL.replace("model_test_1", f"model_test_{number}")
        _, tool, path, settings = load_model(folder)
        exact, quintic = step_times(step_stocks(folder, path, tool), tool, path, settings, repeats)
        print(f"\nmodel test {number}, 53 CL x {settings.phi.size} phi: mean CPU ms per pass over {repeats} passes")
        print(f"{'step':<34} {'exact':>7} {'quintic':>8}")
        for label, name in STEPS + (("whole engage call", "engage"),):
            print(f"{label:<34} {exact[name] * 1e3:>7.2f} {quintic[name] * 1e3:>8.2f}")
        outside = {k: t["engage"] - sum(t[name] for _, name in STEPS if name != "_table1_case") for k, t in
                   (("exact", exact), ("quintic", quintic))}
        print(f"{'outside the steps':<34} {outside['exact'] * 1e3:>7.2f} {outside['quintic'] * 1e3:>8.2f}")
    print(f"load average after: {' '.join(f'{v:.2f}' for v in os.getloadavg())}")


def measure(stock, tool, path, settings, repeats, chunk):
    """(best seconds, median seconds, peak MiB) of engage() over `repeats` runs."""
    engage(stock, tool, path, settings, chunk_instants=chunk)
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        engage(stock, tool, path, settings, chunk_instants=chunk)
        times.append(time.perf_counter() - start)
    tracemalloc.start()
    engage(stock, tool, path, settings, chunk_instants=chunk)
    peak = tracemalloc.get_traced_memory()[1] / 2**20
    tracemalloc.stop()
    return float(np.min(times)), float(np.median(times)), peak


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=50, help="runs of each 53-point pass")
    parser.add_argument("--large", type=int, default=1_000_000, help="instants in the large toolpath")
    parser.add_argument("--walls-only", action="store_true", help="only the exact against quintic walls table")
    parser.add_argument("--steps", action="store_true", help="only the per-step CPU time of exact and quintic passes")
    args = parser.parse_args()
    if args.steps:
        steps_table(args.repeats)
        return
    if args.walls_only:
        walls_table(args.repeats, args.large)
        return
    print(f"{'case':<46} {'instants':>9} {'best ms':>9} {'median ms':>10} {'instants/s':>11} {'peak MiB':>9}")
    for number in (1, 2):
        stock, tool, path, settings = load_model(MODEL.replace("model_test_1", f"model_test_{number}"))
        p = settings.phi.size
        rows = [(f"model test {number}, 53 CL x {p} phi", path, args.repeats, 1 << 15)]
        if number == 1:
            large = densified(path, -(-args.large // p))
            rows += [(f"{len(large)} CL x {p} phi, chunks of 2^{k} instants", large, 3, 1 << k) for k in (13, 14, 15, 17)]
        for name, toolpath, repeats, chunk in rows:
            best, median, peak = measure(stock, tool, toolpath, settings, repeats, chunk)
            n = len(toolpath) * p
            print(f"{name:<46} {n:>9} {best * 1e3:>9.1f} {median * 1e3:>10.1f} {n / best:>11.3g} {peak:>9.1f}")
    print("paper (MATLAB, i7 2.7 GHz): ABM 713.87 s for one 53-point pass")
    walls_table(args.repeats, args.large)


if __name__ == "__main__":
    main()
