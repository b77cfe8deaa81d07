"""In-process stock on real-shaped programs: CPU time against the stock as given, in one run.

Run from the repository root: `/usr/bin/python3 benchmarks/inprocess_real.py [--program NAME ...]`.

The programs look like a CAM system's roughing output over a block stock (a staircase of one
section, x 0 … 80, y 0 … 60, top z = 0), three-axis (the tool axis +z throughout). Straight moves
are single moves, as a CL file or G-code gives them; arcs come as the short chords the project's
own CL reader makes of them (formats.cl.arcs.arc_points, chordal tolerance 0.001 mm, at most
0.1 mm apart: the reader's defaults), so arcs bring thousands of short moves. Each level starts
with a rapid above its first point and a plunge (a cutting move).

- pocket: z-level roughing of a 44 × 28 mm pocket with rounded corners (radius 5 mm) with a
  D 4 mm tool, three levels 1.5 mm apart; per level two offset (contour-parallel) rings at 40 %
  stepover, then zig-zag passes along x at 50 % stepover joined by semicircular arcs;
- contour: around a round boss (radius 12 mm) in the block, a D 6 mm tool on full circles
  of arc moves from the outside in (tool centre radius 24 … 15 mm, 50 % stepover), two levels
  2 mm apart;
- slot: a curved slot (a half circle of radius 20 mm, then a straight leg) slotted with a D 6 mm
  tool, then widened by passes 2.4 mm (40 %) to either side, alternately, in two levels 3 mm
  apart.

Every cutting CL point of a program is evaluated at φ 0 … 180° by 1°: on the stock as given
(`stocks.engage_stock`, the engine of `--stock-model initial`) and against the in-process stock
(`stocks.engage_in_process` in chunks of parallel.CHUNK_INSTANTS instants, as jobs.run does,
after `swept_pieces` of the whole program, timed with it). CPU time is `time.process_time`;
peak memory is the process's peak resident set after each step (ru_maxrss). `--save DIR`
writes each program's in-process Engagement fields to DIR/<program>.npz, `--compare DIR`
compares them with such a file (bit for bit, else the largest difference).
`--profile` prints the in-process run's top functions (cProfile, by own time). `--corner R` cuts
the same programs with a tool of that corner radius (mm; the tool's radius for a ball-end mill),
on both runs.
"""

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")  # one core, before numpy is imported

import argparse  # noqa: E402
import cProfile  # noqa: E402
import dataclasses  # noqa: E402
import math  # noqa: E402
import pstats  # noqa: E402
import resource  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from abm_workbench.engine import CutSettings, Tool, Toolpath  # noqa: E402
from abm_workbench.engine.inprocess import ProgramMoves, swept_pieces  # noqa: E402
from abm_workbench.engine.model import Staircase  # noqa: E402
from abm_workbench.engine.stocks import engage_in_process, engage_stock  # noqa: E402
from abm_workbench.formats.cl import STEP, TOLERANCE  # noqa: E402
from abm_workbench.formats.cl.arcs import arc_points  # noqa: E402
from abm_workbench.parallel import CHUNK_INSTANTS  # noqa: E402

#: The block stock (mm).
BLOCK = dict(x_min=0.0, x_max=80.0, y_min=0.0, y_max=60.0, base_z=-30.0)
SETTINGS = CutSettings(feed_per_tooth=0.05, phi_start=0.0, phi_end=180.0, phi_step=1.0)


class Path:
    """A three-axis program built move by move: CL points (k, 3) and whether the move into each cuts."""

    def __init__(self):
        self.points, self.cutting = [], []

    @property
    def here(self):
        return self.points[-1]

    def rapid(self, point):
        """A rapid to `point` (removes nothing)."""
        self.points.append(np.asarray(point, dtype=float))
        self.cutting.append(False)

    def line(self, point):
        """One straight cutting move to `point`."""
        self.points.append(np.asarray(point, dtype=float))
        self.cutting.append(True)

    def arc(self, end, centre, clockwise=False):
        """A cutting arc in its plane z = const from here to `end` about `centre`, as the CL reader's chords."""
        start = self.here
        end = np.asarray(end, dtype=float)
        centre = np.array([centre[0], centre[1], start[2]])
        points, _ = arc_points(start, end, centre, (0.0, 0.0, -1.0 if clockwise else 1.0), TOLERANCE, STEP)
        for point in points:
            self.line(point)

    def enter(self, point, clearance=5.0):
        """Rapid above `point`, then plunge (cutting) to it."""
        self.rapid((point[0], point[1], clearance))
        self.line(point)

    def program(self, tool):
        cl = np.array(self.points)
        n = cl.shape[0]
        axis = np.tile([0.0, 0.0, 1.0], (n, 1))
        cutting = np.array(self.cutting)
        cutting[0] = False
        return ProgramMoves(cl, axis, cutting, np.full(n, tool.radius), np.full(n, tool.flute_length), np.arange(n),
                            np.full(n, tool.corner_radius))


def rounded_ring(path, cx, cy, a, b, r, z, first):
    """A closed ring (counter-clockwise) of the rectangle of half sizes a, b with corner radius r about
    (cx, cy) at height z: straight sides as single moves, corners as arcs. Starts at the middle of the
    bottom side; `first`: enter there (else a straight move to it)."""
    start = (cx, cy - b, z)
    path.enter(start) if first else path.line(start)
    corners = [(cx + a - r, cy - b + r), (cx + a - r, cy + b - r), (cx - a + r, cy + b - r), (cx - a + r, cy - b + r)]
    for k, (x, y) in enumerate(corners):
        angle = -0.5 * math.pi + 0.5 * math.pi * k
        begin = (x + r * math.cos(angle), y + r * math.sin(angle), z)
        finish = (x + r * math.cos(angle + 0.5 * math.pi), y + r * math.sin(angle + 0.5 * math.pi), z)
        path.line(begin)
        path.arc(finish, (x, y))
    path.line(start)


def pocket():
    """Z-level roughing of a rounded pocket: offset rings, then zig-zag with arc turns."""
    tool = Tool(4.0, 2, 12.0)
    r = tool.radius
    path = Path()
    cx, cy, half_a, half_b, corner = 40.0, 30.0, 22.0, 14.0, 5.0
    for z in (-1.5, -3.0, -4.5):
        ring = 0.4 * tool.diameter
        for k in range(2):
            off = r + k * ring
            rounded_ring(path, cx, cy, half_a - off, half_b - off, max(corner - off, 0.5), z, first=k == 0)
        # Zig-zag inside the last ring, 50 % stepover, semicircular turns.
        inner_a, inner_b = half_a - r - 2 * ring, half_b - r - 2 * ring
        step = 0.5 * tool.diameter
        rows = int(math.floor(2 * inner_b / step)) + 1
        ys = cy - inner_b + step * np.arange(rows)
        x0, x1 = cx - inner_a + 0.5 * step, cx + inner_a - 0.5 * step
        path.line((x0, ys[0], z))
        for i, y in enumerate(ys):
            right = i % 2 == 0
            path.line((x1 if right else x0, y, z))
            if i + 1 < rows:
                end = (x1 if right else x0, ys[i + 1], z)
                path.arc(end, (end[0], y + 0.5 * step), clockwise=not right)
    return tool, path


def contour():
    """Full circles of arc moves around a round boss, from the outside in, two levels."""
    tool = Tool(6.0, 2, 15.0)
    path = Path()
    cx, cy, boss = 40.0, 30.0, 12.0
    radii = boss + tool.radius + 0.5 * tool.diameter * np.arange(4)[::-1]
    for z in (-2.0, -4.0):
        for k, rho in enumerate(radii):
            start = (cx + rho, cy, z)
            path.enter(start) if k == 0 else path.line(start)
            path.arc((cx - rho, cy, z), (cx, cy))
            path.arc(start, (cx, cy))
    return tool, path


def slot():
    """A curved slot (half circle, then a straight leg), then its widening passes, two levels."""
    tool = Tool(6.0, 2, 15.0)
    path = Path()
    cx, cy, rho, leg = 40.0, 20.0, 20.0, 15.0
    offsets = [0.0, 2.4, -2.4, 4.8, -4.8]
    for z in (-3.0, -6.0):
        for k, d in enumerate(offsets):
            radius = rho + d
            # Alternate directions: the half circle from (cx + radius, cy) over the top, then the leg down.
            a, b = (cx + radius, cy, z), (cx - radius, cy, z)
            if k % 2 == 0:
                path.enter(a)
                path.arc(b, (cx, cy))
                path.line((b[0], b[1] - leg, z))
            else:
                path.enter((b[0], b[1] - leg, z))
                path.line(b)
                path.arc(a, (cx, cy), clockwise=True)
    return tool, path


PROGRAMS = {"pocket": pocket, "contour": contour, "slot": slot}


def peak_mb():
    """The process's peak resident set so far (MB)."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def run(name, args):
    """One program: its figures (a dict), and its in-process Engagement."""
    tool, path = PROGRAMS[name]()
    if args.corner:
        tool = dataclasses.replace(tool, corner_radius=min(args.corner, tool.radius))
    moves = path.program(tool)
    rows = np.flatnonzero(moves.cutting)
    toolpath = Toolpath(moves.cl[rows], np.zeros(rows.size), np.zeros(rows.size))
    stock = Staircase(z_top=[0.0], wall_points=[], **BLOCK)
    p = SETTINGS.phi.size
    start = time.process_time()
    engage_stock(stock, tool, toolpath, SETTINGS)
    initial = time.process_time() - start
    after_initial = peak_mb()
    profile = cProfile.Profile(timer=time.process_time) if args.profile else None
    if profile:
        profile.enable()
    start = time.process_time()
    pieces = swept_pieces(moves)
    sweep = time.process_time() - start
    step = max(1, CHUNK_INSTANTS // p)
    parts, changed = [], 0
    for begin in range(0, rows.size, step):
        stop = min(rows.size, begin + step)
        engagement, _, flags = engage_in_process(stock, tool, toolpath.rows(np.arange(begin, stop)), SETTINGS, pieces,
                                                 rows[begin:stop])
        parts.append(engagement)
        changed += int(flags.sum())
    inproc = time.process_time() - start
    if profile:
        profile.disable()
    fields = {f.name: np.concatenate([getattr(e, f.name) for e in parts]) for f in dataclasses.fields(parts[0])
              if f.name not in ("phi",)}
    figures = dict(program=name, moves=int(moves.cutting.sum()), cl=int(rows.size), instants=int(rows.size * p),
                   initial=initial, sweep=sweep, inproc=inproc, changed=changed, mem_initial=after_initial,
                   mem_inproc=peak_mb(), pieces=int(pieces.move.size), chains=int(pieces.chain_first.size))
    if profile:
        pstats.Stats(profile).sort_stats("tottime").print_stats(25)
    return figures, fields


def compare(name, fields, folder):
    """'bit for bit' or the largest difference of the fields against folder/name.npz."""
    saved = np.load(os.path.join(folder, f"{name}.npz"))
    worst, differ = 0.0, []
    for key, value in fields.items():
        old = saved[key]
        if old.shape != value.shape:
            return f"{key}: shape {old.shape} != {value.shape}"
        same = (old == value) | ((old != old) & (value != value))
        if not same.all():
            differ.append(key)
            if np.issubdtype(value.dtype, np.floating):
                both = ~(np.isnan(old) | np.isnan(value))
                nan_mismatch = int((np.isnan(old) != np.isnan(value)).sum())
                gap = float(np.max(np.abs(old[both] - value[both]))) if both.any() else 0.0
                worst = max(worst, gap)
                differ[-1] += f" (max |diff| {gap:.3g}, NaN mismatches {nan_mismatch})"
            else:
                differ[-1] += f" ({int((~same).sum())} differ)"
    return "bit for bit" if not differ else f"differs: {'; '.join(differ)}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--program", action="append", choices=sorted(PROGRAMS), help="run only these (repeatable)")
    parser.add_argument("--save", help="write each program's in-process Engagement to DIR/<program>.npz")
    parser.add_argument("--compare", help="compare with DIR/<program>.npz")
    parser.add_argument("--profile", action="store_true", help="profile the in-process runs")
    parser.add_argument("--corner", type=float, default=0.0, help="the tool's corner radius (mm; default 0, flat-end)")
    args = parser.parse_args()
    print("| program | cutting moves | CL points | instants | initial s | in-process s (sweep) | ratio | "
          "initial µs/instant | in-process µs/instant | in-process ms/CL | CL changed | "
          "peak MB (initial, in-process) | check |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name in args.program or list(PROGRAMS):
        figures, fields = run(name, args)
        check = ""
        if args.save:
            os.makedirs(args.save, exist_ok=True)
            np.savez(os.path.join(args.save, f"{name}.npz"), **fields)
        if args.compare:
            check = compare(name, fields, args.compare)
        f = figures
        print(f"| {name} | {f['moves']} | {f['cl']} | {f['instants']} | {f['initial']:.2f} | {f['inproc']:.2f} "
              f"({f['sweep']:.2f}) | **{f['inproc'] / f['initial']:.1f}** | {1e6 * f['initial'] / f['instants']:.2f} "
              f"| {1e6 * f['inproc'] / f['instants']:.2f} | {1e3 * f['inproc'] / f['cl']:.2f} | {f['changed']} "
              f"| {f['mem_initial']:.0f}, {f['mem_inproc']:.0f} | {check} |", flush=True)
    print(f"\nload average: {' '.join(f'{v:.2f}' for v in os.getloadavg())}")


if __name__ == "__main__":
    main()
