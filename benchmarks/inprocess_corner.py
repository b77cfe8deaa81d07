"""In-process stock with a corner tool: CPU time of a bull-nose and a ball-end mill against the in-process stock.

Run from the repository root: `/usr/bin/python3 benchmarks/inprocess_corner.py` (needs the test suite's stocks, and
so hypothesis). The program (docs/ENGINE.md, "Tools with a corner in the in-process stock", Cost): three straight
passes of a D10 mm tool across the test suite's staircase (or, with `--stock terraced`, its terraced stock), 60 CL
points per pass 0.54 mm apart along x, the passes 4 mm apart in y and each 0.3 mm lower than the one before; the
third pass is evaluated at φ 0 … 358° by 2° (10,800 instants) against what the first two passes and its own earlier
moves removed. Cases, the same program with the tool's corner radius r for every pass:
- initial: `engage_stock` (the stock as given) of the bull-nose mill (r = `--corner`);
- flat-end: `engage_in_process` with r = 0;
- bull-nose: `engage_in_process` with r = `--corner` (2 mm);
- ball: `engage_in_process` with r = 5 mm (the tool's radius).
CPU time (`time.process_time`), best of `--repeats`, the cases taken in turn; the program's swept pieces are built
before the clock starts (once per program). Prints each case's seconds and its ratio to the initial run and to the
flat-end in-process run, the load average, and with `--profile` the functions taking the most CPU time in the
bull-nose run.
"""

import argparse
import cProfile
import os
import pstats
import sys
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from abm_workbench.engine import CutSettings, Tool, Toolpath  # noqa: E402
from abm_workbench.engine.inprocess import ProgramMoves, swept_pieces  # noqa: E402
from abm_workbench.engine.stocks import engage_in_process, engage_stock  # noqa: E402
from tests.engine.test_tool_profiles import STAIRCASE, TERRACED  # noqa: E402

RADIUS, FLUTE = 5.0, 15.0
PASSES, POINTS, STEP = 3, 60, 0.54  # passes, CL points per pass, mm between them
STEPOVER, STEPDOWN = 4.0, 0.3  # mm


def program(corner, top):
    """(ProgramMoves, rows of the last pass) of the three passes with a D10 tool of corner radius `corner`, the first
    pass's CL points at height `top`."""
    x = -16.0 + STEP * np.arange(POINTS)
    cl = np.concatenate([np.stack([x, np.full(POINTS, -4.0 + STEPOVER * k), np.full(POINTS, top - STEPDOWN * k)], 1)
                         for k in range(PASSES)]) + np.array([0.0123457, 0.0213579, 0.0372941])
    n = cl.shape[0]
    cutting = np.tile(np.r_[False, np.ones(POINTS - 1, dtype=bool)], PASSES)
    moves = ProgramMoves(cl, np.tile([0.0, 0.0, 1.0], (n, 1)), cutting, np.full(n, RADIUS), np.full(n, FLUTE),
                         np.arange(n) + 1, np.full(n, corner))
    return moves, np.arange(n - POINTS, n)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3, help="runs of each case (best taken)")
    parser.add_argument("--corner", type=float, default=2.0, help="the bull-nose mill's corner radius (mm)")
    parser.add_argument("--stock", choices=("staircase", "terraced"), default="staircase")
    parser.add_argument("--profile", action="store_true", help="profile the bull-nose in-process run")
    args = parser.parse_args()
    stock, top = (STAIRCASE, 2.5) if args.stock == "staircase" else (TERRACED, 4.0)
    settings = CutSettings(0.1, phi_start=0.0, phi_end=358.0, phi_step=2.0)
    cases = {}
    for name, corner in (("flat-end", 0.0), ("bull-nose", args.corner), ("ball", RADIUS)):
        moves, rows = program(corner, top)
        tool = Tool(2.0 * RADIUS, 2, FLUTE, corner_radius=corner)
        toolpath = Toolpath(moves.cl[rows], np.zeros(rows.size), np.zeros(rows.size))
        cases[name] = (tool, toolpath, swept_pieces(moves), rows)

    def initial():
        tool, toolpath, _, _ = cases["bull-nose"]
        engage_stock(stock, tool, toolpath, settings)

    def in_process(name):
        tool, toolpath, pieces, rows = cases[name]
        return lambda: engage_in_process(stock, tool, toolpath, settings, pieces, rows)

    runs = {"initial": initial, **{name: in_process(name) for name in cases}}
    best = {name: np.inf for name in runs}
    for _ in range(args.repeats):
        for name, run in runs.items():
            start = time.process_time()
            run()
            best[name] = min(best[name], time.process_time() - start)
    instants = POINTS * settings.phi.size
    print(f"{args.stock}, D{2 * RADIUS:g}, third of {PASSES} passes: {POINTS} CL x {settings.phi.size} phi = "
          f"{instants} instants; CPU s, best of {args.repeats}")
    print(f"{'case':<28}{'s':>9}{'/ initial':>11}{'/ flat-end':>12}")
    for name, label in (("initial", f"initial (r = {args.corner:g} mm)"), ("flat-end", "flat-end in-process"),
                        ("bull-nose", f"bull-nose in-process (r = {args.corner:g})"),
                        ("ball", f"ball in-process (r = {RADIUS:g})")):
        print(f"{label:<28}{best[name]:9.3f}{best[name] / best['initial']:11.1f}"
              f"{best[name] / best['flat-end']:12.1f}")
    print(f"load average: {' '.join(f'{v:.2f}' for v in os.getloadavg())}")
    if args.profile:
        profiler = cProfile.Profile()
        profiler.enable()
        runs["bull-nose"]()
        profiler.disable()
        pstats.Stats(profiler).sort_stats("cumulative").print_stats(40)
        pstats.Stats(profiler).sort_stats("tottime").print_stats(25)


if __name__ == "__main__":
    main()
