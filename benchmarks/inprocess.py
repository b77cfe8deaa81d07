"""In-process stock: instants per second against the initial stock, for a single pass and a program.

Run with FreeCAD's Python from the repository root: `/usr/bin/python3 benchmarks/inprocess.py`.
Cases (engine time only; files are loaded before the clock starts; one core):
- model test 1 (53 CL points × 181 angles, a five-axis pass): `engage` on the initial stock
  against the in-process path, `inside_intervals` + `inprocess_intervals` with the pass as its
  own program (its swept pieces built once, included in the time);
- a program of `--passes` adjacent five-axis passes over the model test 1 stock (the pass's
  heights and tool axes, each pass shifted by `--stepover` in y) with `--points` CL points in
  all, at 1°, in chunks of `--chunk` instants: `engage` against the in-process path, over
  `--evaluate` CL points from the middle of the middle pass (the whole program is swept and
  indexed; only those points are evaluated, to keep the run short).
Prints a table: case, instants, seconds, instants/s; then the ratios, measured in this one
run: in-process over initial for each case, and the program's in-process time per instant over
the single pass's; and the load average.
"""

import argparse
import os
import sys
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)
sys.path.insert(0, os.path.join(ROOT, "benchmarks"))

from engine_throughput import MODEL, densified, load_model  # noqa: E402

from abm_workbench.engine import Toolpath, engage  # noqa: E402
from abm_workbench.engine.engagement import edge_lines, inside_intervals  # noqa: E402
from abm_workbench.engine.frames import rotation_matrix  # noqa: E402
from abm_workbench.engine.inprocess import ProgramMoves, inprocess_intervals, swept_pieces  # noqa: E402


def program_of(passes, tool):
    """ProgramMoves of toolpaths `passes` run one after the other with `tool`; the first move of
    each pass is a rapid."""
    cl = np.concatenate([t.cl for t in passes])
    axis = np.concatenate([rotation_matrix(t.theta_a, t.theta_b)[:, :, 2] for t in passes])
    cutting = np.concatenate([np.r_[False, np.ones(len(t) - 1, dtype=bool)] for t in passes])
    n = cl.shape[0]
    return ProgramMoves(cl, axis, cutting, np.full(n, tool.radius), np.full(n, tool.flute_length), np.arange(n))


def in_process(stock, tool, toolpath, settings, moves, first_row, chunk, tolerance):
    """Seconds for the in-process intervals of every CL point of `toolpath` (program rows from
    first_row), chunk by chunk, the swept pieces built once; and how many CL points changed."""
    start = time.perf_counter()
    pieces = swept_pieces(moves, tolerance)
    p = settings.phi.size
    step = max(1, chunk // p)
    changed = 0
    for begin in range(0, len(toolpath), step):
        stop = min(len(toolpath), begin + step)
        part = Toolpath(toolpath.cl[begin:stop], toolpath.theta_a[begin:stop], toolpath.theta_b[begin:stop])
        base, direction = edge_lines(part, tool, settings.phi)
        origins, directions = base.reshape(-1, 3), np.repeat(direction, p, axis=0)
        stock_iv = inside_intervals(stock, origins, directions, tool.flute_length)
        _, flags = inprocess_intervals(stock_iv, pieces, first_row + np.arange(begin, stop), origins, directions, p)
        changed += int(flags.sum())
    return time.perf_counter() - start, changed


def best_of(repeats, *runs):
    """Best seconds of `repeats` calls of each of runs() (each returns seconds first), the calls
    taken in turn so that a change of the machine's load touches them alike; and the last
    result of each."""
    results = [[run() for run in runs] for _ in range(repeats)]
    return [(min(r[i][0] for r in results), results[-1][i]) for i in range(len(runs))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="runs of the single pass (best taken)")
    parser.add_argument("--points", type=int, default=20_000, help="CL points of the program")
    parser.add_argument("--passes", type=int, default=16, help="passes of the program")
    parser.add_argument("--stepover", type=float, default=1.5, help="mm between passes")
    parser.add_argument("--chunk", type=int, default=1 << 15, help="instants per chunk")
    parser.add_argument("--evaluate", type=int, default=300, help="CL points of the program evaluated")
    parser.add_argument("--tolerance", type=float, default=0.05, help="five-axis sub-step tolerance (mm)")
    args = parser.parse_args()
    stock, tool, path, settings = load_model(MODEL)
    p = settings.phi.size
    rows = []

    def timed_engage(toolpath):
        start = time.perf_counter()
        engage(stock, tool, toolpath, settings, chunk_instants=args.chunk)
        return (time.perf_counter() - start,)

    moves = program_of([path], tool)
    (initial, _), (inproc, (_, changed)) = best_of(
        args.repeats, lambda: timed_engage(path),
        lambda: in_process(stock, tool, path, settings, moves, 0, args.chunk, args.tolerance))
    n = len(path) * p
    rows.append((f"model test 1, 53 CL x {p} phi, initial (engage)", n, initial, ""))
    rows.append((f"model test 1, 53 CL x {p} phi, in-process", n, inproc, f"{changed} CL changed"))

    per_pass = args.points // args.passes
    base = densified(path, per_pass)
    offsets = (np.arange(args.passes) - 0.5 * (args.passes - 1)) * args.stepover
    passes = [Toolpath(base.cl + [0.0, y, 0.0], base.theta_a, base.theta_b) for y in offsets]
    program = program_of(passes, tool)
    first = (args.passes // 2) * per_pass + max(0, (per_pass - args.evaluate) // 2)
    last = min(first + args.evaluate, len(program))
    theta_a = np.concatenate([t.theta_a for t in passes])
    theta_b = np.concatenate([t.theta_b for t in passes])
    chosen = Toolpath(program.cl[first:last], theta_a[first:last], theta_b[first:last])
    n = len(chosen) * p
    (initial, _), (inproc, (_, changed)) = best_of(
        1, lambda: timed_engage(chosen),
        lambda: in_process(stock, tool, chosen, settings, program, first, args.chunk, args.tolerance))
    name = (f"{args.passes * per_pass}-point program ({args.passes} passes, stepover {args.stepover} mm), "
            f"{len(chosen)} CL x {p} phi")
    rows.append((f"{name}, initial (engage)", n, initial, ""))
    rows.append((f"{name}, in-process", n, inproc, f"{changed} CL changed"))

    print("| case | instants | seconds | instants/s | note |\n|---|---|---|---|---|")
    for name, count, seconds, note in rows:
        print(f"| {name} | {count} | {seconds:.3f} | {count / seconds:.3g} | {note} |")
    single = rows[1][2] / rows[0][2]
    program_ratio = rows[3][2] / rows[2][2]
    per_single = rows[1][2] / rows[1][1]
    per_program = rows[3][2] / rows[3][1]
    print(f"\nsingle pass: in-process / initial = {single:.2f} (target <= 2)")
    print(f"program: in-process / initial = {program_ratio:.1f}; in-process time per instant = "
          f"{per_program / per_single:.1f} x the single pass's (target: within ~10)")
    print(f"load average: {' '.join(f'{v:.2f}' for v in os.getloadavg())}")


if __name__ == "__main__":
    main()
