"""A long three-axis roughing program for memory measurements: `engage` on N CL points.

Run from the repository root: `/usr/bin/python3 benchmarks/big_program.py DIR [--points N]` writes
DIR/stock.json (a block x 0 … 80, y 0 … 60, z −30 … 0, abm-staircase/1) and DIR/toolpath.csv
(x,y,z,i,j,k, every row a cutting move from the one before): z-level zig-zag roughing with a
D 6 mm tool, rows along x 3 mm apart (50 % stepover), CL points 0.1 mm apart, levels 0.2 mm
apart from z = −0.2 down, as many as N CL points take (the last level cut short).
Then e.g. `/usr/bin/time -v /usr/bin/python3 -m abm_workbench engage --stock DIR/stock.json
--toolpath DIR/toolpath.csv --diameter 6 --flutes 2 --flute-length 20 --feed-per-tooth 0.05
--phi-step 10 --out DIR/R.npz` (docs/BENCHMARKS.md, "Memory of a long program").
"""

import argparse
import json
import os

import numpy as np


def level(z):
    """One level's CL points (k, 3): zig-zag rows along x at y 3 … 57, points 0.1 mm apart."""
    x = np.round(np.arange(3.0, 77.0 + 1e-9, 0.1), 10)
    rows = []
    for i, y in enumerate(np.arange(3.0, 57.0 + 1e-9, 3.0)):
        xs = x if i % 2 == 0 else x[::-1]
        rows.append(np.column_stack([xs, np.full(xs.size, y), np.full(xs.size, z)]))
    return np.concatenate(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("--points", type=int, default=1_000_000)
    args = parser.parse_args()
    os.makedirs(args.folder, exist_ok=True)
    stock = {"format": "abm-staircase/1", "units": "mm", "base_z": -30.0, "x_min": 0.0, "x_max": 80.0,
             "y_min": 0.0, "y_max": 60.0, "sections": [{"z_top": 0.0}]}
    with open(os.path.join(args.folder, "stock.json"), "w") as out:
        json.dump(stock, out, indent=1)
    parts, total, k = [], 0, 1
    while total < args.points:
        part = level(-0.2 * k)[: args.points - total]
        parts.append(part)
        total += part.shape[0]
        k += 1
    cl = np.concatenate(parts)
    with open(os.path.join(args.folder, "toolpath.csv"), "w") as out:
        out.write("x,y,z,i,j,k\n")
        np.savetxt(out, np.column_stack([cl, np.zeros((cl.shape[0], 2)), np.ones(cl.shape[0])]), fmt="%.10g",
                   delimiter=",")
    print(f"{cl.shape[0]} CL points in {k - 1} levels")


if __name__ == "__main__":
    main()
