"""Reading speed of CL files: N cutting CL points (default 20,000) read by formats.cl.read_program.

Writes a seeded random five-axis CLSF-style file (GOTO/x,y,z,i,j,k records without MULTAX,
some three-number GOTOs, FEDRAT and PAINT records between) to a temporary folder, reads it
REPEAT times and prints the best wall-clock and CPU times (on a busy machine the two differ). The goal: 20,000 CL points in under 0.5 s.

    /usr/bin/python3 benchmarks/read_cl.py [--points N] [--repeat R]
"""

import argparse
import os
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

from abm_workbench.formats.cl import read_program  # noqa: E402


def cl_text(points, seed=0):
    """Text of a CL file with `points` cutting moves (seeded random positions and axes)."""
    rng = np.random.default_rng(seed)
    xyz = rng.uniform(-100, 100, (points, 3))
    axes = rng.normal(size=(points, 3)) * [0.3, 0.3, 0.0] + [0, 0, 1]
    axes /= np.linalg.norm(axes, axis=1)[:, None]
    lines = ["TOOL PATH/BENCH,TOOL,EM10", "TLDATA/MILL,10.0000,0.0000,75.0000,0.0000,0.0000", "FEDRAT/MMPM,500.0000"]
    for index, (point, axis) in enumerate(zip(xyz, axes)):
        if index % 1000 == 0:
            lines.append("PAINT/COLOR,42")
        if index % 3 == 2:
            lines.append("GOTO/{:.4f},{:.4f},{:.4f}".format(*point))
        else:
            lines.append("GOTO/{:.4f},{:.4f},{:.4f},{:.7f},{:.7f},{:.7f}".format(*point, *axis))
    lines.append("END-OF-PATH")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=20000)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "bench.clsf")
        with open(path, "w") as file:
            file.write(cl_text(args.points))
        best = cpu = float("inf")
        for _ in range(args.repeat):
            start, start_cpu = time.perf_counter(), time.process_time()
            program = read_program(path)
            best = min(best, time.perf_counter() - start)
            cpu = min(cpu, time.process_time() - start_cpu)
        count = len(program.operations[0].lines)
    print(f"read_program: {count} CL points in {best:.3f} s wall, {cpu:.3f} s CPU (best of {args.repeat}); "
          "goal < 0.5 s for 20,000")


if __name__ == "__main__":
    main()
