"""In-process stock: CPU time against the initial stock, for a single pass and a program.

Run with FreeCAD's Python from the repository root: `/usr/bin/python3 benchmarks/inprocess.py`.
Cases (engine CPU time, `time.process_time`, only; files are loaded before the clock starts):
- model test 1 (53 CL points × 181 angles, a five-axis pass): `engage` on the initial stock
  against `stocks.engage_in_process` (the full Engagement against the in-process stock) with
  the pass as its own program, its swept pieces built inside the timing;
- with `--dense N`, the same for the pass resampled to N CL points (0.1 mm apart for N = 500),
  where a curving pass's flanks meet its own earlier moves;
- a program of `--passes` adjacent five-axis passes over the model test 1 stock (the pass's
  heights and tool axes, each pass shifted by `--stepover` in y) with `--points` CL points in
  all, at 1°, in chunks of `--chunk` instants: `engage` against `engage_in_process` over
  `--evaluate` CL points from the middle of the middle pass, best of `--program-repeats` (the
  single passes are best of `--repeats`). The whole program is swept and indexed once, timed
  apart (a program pays it once, not per evaluated CL point). With
  `--upright` the program's tool axis is vertical throughout (a three-axis program: straight
  runs of moves with one axis, whose chains are rigid).
Prints a table: case, instants, CPU seconds, instants/s; then the ratios, measured in this one
run: in-process over initial for each case, and the program's in-process time per instant over
the single pass's; and the load average. `--profile` adds, for the program's evaluation, the
functions taking the most CPU time and how many (line, swept piece) pairs were tested for a
sure miss and solved in closed form.
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
sys.path.insert(0, os.path.join(ROOT, "benchmarks"))

from engine_throughput import MODEL, densified, load_model  # noqa: E402

from abm_workbench.engine import Toolpath, engage, inprocess, swept  # noqa: E402
from abm_workbench.engine.inprocess import ProgramMoves, swept_pieces  # noqa: E402
from abm_workbench.engine.stocks import engage_in_process  # noqa: E402


def program_of(passes, tool):
    """ProgramMoves of toolpaths `passes` run one after the other with `tool`; the first move of
    each pass is a rapid."""
    cl = np.concatenate([t.cl for t in passes])
    axis = np.concatenate([t.axes for t in passes])
    cutting = np.concatenate([np.r_[False, np.ones(len(t) - 1, dtype=bool)] for t in passes])
    n = cl.shape[0]
    return ProgramMoves(cl, axis, cutting, np.full(n, tool.radius), np.full(n, tool.flute_length), np.arange(n))


def in_process(stock, tool, toolpath, settings, pieces, first_row, chunk, tolerance):
    """CPU seconds for the in-process Engagement of every CL point of `toolpath` (program rows
    from first_row), chunk by chunk; `pieces` the program's SweptPieces, or its ProgramMoves
    (then swept inside the timing, sub-steps within `tolerance` mm); and how many CL points changed."""
    start = time.process_time()
    if isinstance(pieces, ProgramMoves):
        pieces = swept_pieces(pieces, tolerance)
    step = max(1, chunk // settings.phi.size)
    changed = 0
    for begin in range(0, len(toolpath), step):
        stop = min(len(toolpath), begin + step)
        part = Toolpath(toolpath.cl[begin:stop], toolpath.theta_a[begin:stop], toolpath.theta_b[begin:stop])
        _, _, flags = engage_in_process(stock, tool, part, settings, pieces, first_row + np.arange(begin, stop))
        changed += int(flags.sum())
    return time.process_time() - start, changed


def best_of(repeats, *runs):
    """Best seconds of `repeats` calls of each of runs() (each returns seconds first), the calls
    taken in turn so that a change of the machine's load touches them alike; and the last
    result of each."""
    results = [[run() for run in runs] for _ in range(repeats)]
    return [(min(r[i][0] for r in results), results[-1][i]) for i in range(len(runs))]


def counted(calls):
    """Wrap inprocess._apart and swept.line_hull_interval (as inprocess uses them) so that
    `calls` counts the pairs each meets: sure-miss tests, their misses, closed-form solves.
    Returns a function that puts the originals back."""
    apart, solve = inprocess._apart, inprocess.line_hull_interval

    def counting_apart(*args, **kwargs):
        result = apart(*args, **kwargs)
        calls["sure-miss tests"] += result.size
        calls["sure misses"] += int(result.sum())
        return result

    def counting_solve(origins, *args):
        calls["closed-form solves"] += len(origins)
        return solve(origins, *args)

    inprocess._apart, inprocess.line_hull_interval = counting_apart, counting_solve

    def restore():
        inprocess._apart, inprocess.line_hull_interval = apart, solve
    assert solve is swept.line_hull_interval
    return restore


def single_pass(name, stock, tool, path, settings, args):
    """Table rows (initial, in-process) for one pass run as its own program, best of --repeats."""
    moves = program_of([path], tool)
    (initial, _), (inproc, (_, changed)) = best_of(
        args.repeats, lambda: timed_engage(stock, tool, path, settings, args.chunk),
        lambda: in_process(stock, tool, path, settings, moves, 0, args.chunk, args.tolerance))
    n = len(path) * settings.phi.size
    return [(f"{name}, initial (engage)", n, initial, f"best of {args.repeats}"),
            (f"{name}, in-process (engage_in_process)", n, inproc, f"best of {args.repeats}; {changed} CL changed")]


def timed_engage(stock, tool, toolpath, settings, chunk):
    """CPU seconds of `engage` over the initial stock, as a 1-tuple."""
    start = time.process_time()
    engage(stock, tool, toolpath, settings, chunk_instants=chunk)
    return (time.process_time() - start,)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="runs of the single pass (best taken)")
    parser.add_argument("--program-repeats", type=int, default=3,
                        help="runs of the program's evaluation (best taken; 1 before 2026-11-26)")
    parser.add_argument("--dense", type=int, default=0, help="also time the pass resampled to this many CL points")
    parser.add_argument("--points", type=int, default=20_000, help="CL points of the program")
    parser.add_argument("--passes", type=int, default=16, help="passes of the program")
    parser.add_argument("--stepover", type=float, default=1.5, help="mm between passes")
    parser.add_argument("--chunk", type=int, default=1 << 15, help="instants per chunk")
    parser.add_argument("--evaluate", type=int, default=300, help="CL points of the program evaluated")
    parser.add_argument("--tolerance", type=float, default=0.05, help="five-axis sub-step tolerance (mm)")
    parser.add_argument("--upright", action="store_true", help="the program with a vertical tool axis (three-axis)")
    parser.add_argument("--profile", action="store_true", help="profile the program's in-process evaluation")
    args = parser.parse_args()
    stock, tool, path, settings = load_model(MODEL)
    p = settings.phi.size
    rows = single_pass(f"model test 1, 53 CL x {p} phi", stock, tool, path, settings, args)
    if args.dense:
        rows += single_pass(f"model test 1 resampled, {args.dense} CL x {p} phi", stock, tool,
                            densified(path, args.dense), settings, args)

    per_pass = args.points // args.passes
    base = densified(path, per_pass)
    offsets = (np.arange(args.passes) - 0.5 * (args.passes - 1)) * args.stepover
    if args.upright:
        base = Toolpath(base.cl, np.zeros(len(base)), np.zeros(len(base)))
    passes = [Toolpath(base.cl + [0.0, y, 0.0], base.theta_a, base.theta_b) for y in offsets]
    program = program_of(passes, tool)
    first = (args.passes // 2) * per_pass + max(0, (per_pass - args.evaluate) // 2)
    last = min(first + args.evaluate, len(program))
    theta_a = np.concatenate([t.theta_a for t in passes])
    theta_b = np.concatenate([t.theta_b for t in passes])
    chosen = Toolpath(program.cl[first:last], theta_a[first:last], theta_b[first:last])
    start = time.process_time()
    pieces = swept_pieces(program, args.tolerance)
    sweep = time.process_time() - start
    name = (f"{args.passes * per_pass}-point {'three-axis ' if args.upright else ''}program ({args.passes} passes, "
            f"stepover {args.stepover} mm)")
    rows.append((f"{name}: swept pieces of the whole program (once)", len(program), sweep, "CL points swept"))
    (initial, _), (inproc, (_, changed)) = best_of(
        args.program_repeats, lambda: timed_engage(stock, tool, chosen, settings, args.chunk),
        lambda: in_process(stock, tool, chosen, settings, pieces, first, args.chunk, args.tolerance))
    n = len(chosen) * p
    rows.append((f"{name}, {len(chosen)} CL x {p} phi, initial (engage)", n, initial,
                 f"best of {args.program_repeats}"))
    rows.append((f"{name}, {len(chosen)} CL x {p} phi, in-process (engage_in_process)", n, inproc,
                 f"best of {args.program_repeats}; {changed} CL changed"))

    print("| case | instants | CPU seconds | instants/s | note |\n|---|---|---|---|---|")
    for label, count, seconds, note in rows:
        print(f"| {label} | {count} | {seconds:.3f} | {count / seconds:.3g} | {note} |")
    single = rows[1][2] / rows[0][2]
    print(f"\nsingle pass: in-process / initial = {single:.2f} (target <= 2)")
    if args.dense:
        print(f"dense pass ({args.dense} CL): in-process / initial = {rows[3][2] / rows[2][2]:.2f}")
    per_single = rows[1][2] / rows[1][1]
    per_program = rows[-1][2] / rows[-1][1]
    print(f"program: in-process / initial = {rows[-1][2] / rows[-2][2]:.1f}; in-process time per instant = "
          f"{per_program / per_single:.1f} x the single pass's (target: within ~10)")
    print(f"load average: {' '.join(f'{v:.2f}' for v in os.getloadavg())}")
    if args.profile:
        calls = {"sure-miss tests": 0, "sure misses": 0, "closed-form solves": 0}
        restore = counted(calls)
        profile = cProfile.Profile(timer=time.process_time)
        profile.enable()
        in_process(stock, tool, chosen, settings, pieces, first, args.chunk, args.tolerance)
        profile.disable()
        restore()
        print(f"\nprogram, {len(chosen)} CL: " + "; ".join(f"{key} {value} ({value / len(chosen):.0f} per CL point)"
                                                        for key, value in calls.items()))
        pstats.Stats(profile).sort_stats("tottime").print_stats(15)


if __name__ == "__main__":
    main()
