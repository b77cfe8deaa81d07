#!/usr/bin/env python3
"""Generate model test 4: a part with a pocket and an island, roughed in z-levels, and a
five-axis pass across it. Writes into ``resources/models/model_test_4/``:

* ``stock.json``   -- the roughed stock, format ``abm-terraced/1``;
* ``stock.step``   -- the same stock as a solid (``cad.terraced_solids.terraced_solid``);
* ``toolpath.csv`` -- 53 CL points with unit tool axis (x, y, z, i, j, k);
* ``job.json``     -- tool and cut settings.

The design part (mm): a block x 0..100, y -40..40, top z 20, with a pocket whose floor is at
z 4 and whose walls slope outwards (half sizes 30 + (z - 4)/2 in x and 20 + (z - 4)/2 in y,
corner radius 6 + (z - 4)/2, centre (50, 0)), and in the pocket a conical island about
(56, 4) of radius 10 - 0.6 (z - 4), topped flat at z 14. Z-level roughing at the levels 5,
8, 11, 14, 17, 20 with an allowance of 1 mm leaves, in the slab under each level z, the
block minus the pocket's section at z shrunk by the allowance (a rounded rectangle: lines and
arcs), plus the island's section at z grown by the allowance (a circle) while the island
reaches z. Below z 5 the block is whole (the floor's allowance).

The pass runs along x at y = 2 across the pocket and over the island, its CL points on the
design surface, the tool leaning 10° forward and rolling ±6° about x along the pass.

Run with FreeCAD's Python from the repository root (deterministic):

    /usr/bin/python3 resources/models/make_model_test_4.py
"""

import json
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from abm_workbench.cad.solids import export_step  # noqa: E402
from abm_workbench.cad.terraced_solids import terraced_solid  # noqa: E402
from abm_workbench.engine.terraced_model import Loop, PlanArc, PlanLine, Slab, TerracedStock  # noqa: E402
from abm_workbench.formats.terraced_json import dump_terraced  # noqa: E402

OUT = ROOT / "resources" / "models" / "model_test_4"
BLOCK = (0.0, -40.0, 100.0, 40.0)
BASE_Z, TOP_Z = 0.0, 20.0
LEVELS = (5.0, 8.0, 11.0, 14.0, 17.0, 20.0)
ALLOWANCE = 1.0
POCKET_CENTRE, FLOOR_Z = np.array([50.0, 0.0]), 4.0
ISLAND_CENTRE, ISLAND_TOP = np.array([56.0, 4.0]), 14.0
PASS_Y, CL_POINTS = 2.0, 53
DIAMETER, FLUTES, FLUTE_LENGTH = 10.0, 2, 25.0
LEAN, ROLL = 10.0, 6.0  # deg


def pocket_size(z):
    """(half size x, half size y, corner radius) of the pocket's section at height z (mm)."""
    grow = 0.5 * (z - FLOOR_Z)
    return 30.0 + grow, 20.0 + grow, 6.0 + grow


def island_radius(z):
    """Radius of the island's section at height z (mm); the island ends at ISLAND_TOP."""
    return 10.0 - 0.6 * (z - FLOOR_Z)


def rectangle(x0, y0, x1, y1, face):
    """The closed loop of an axis-parallel rectangle."""
    p = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    return Loop(tuple(PlanLine(p[i], p[(i + 1) % 4], face) for i in range(4)))


def rounded_rectangle(centre, a, b, r, face):
    """The closed loop of a rectangle of half sizes a, b with corners rounded to radius r,
    counter-clockwise: four lines and four quarter arcs."""
    cx, cy = centre
    corners = [(cx + a - r, cy - b + r, -0.5 * np.pi), (cx + a - r, cy + b - r, 0.0),
               (cx - a + r, cy + b - r, 0.5 * np.pi), (cx - a + r, cy - b + r, np.pi)]
    curves = []
    for i, (x, y, start) in enumerate(corners):
        arc = PlanArc((x, y), r, start, 0.5 * np.pi, face)
        following = corners[(i + 1) % 4]
        nxt = PlanArc((following[0], following[1]), r, following[2], 0.5 * np.pi, face)
        curves += [arc, PlanLine(arc.end_points[1], nxt.end_points[0], face)]
    return Loop(tuple(curves))


def roughed_stock():
    """The TerracedStock left by z-level roughing (see the module docstring)."""
    slabs, bottom = [Slab(BASE_Z, LEVELS[0], (rectangle(*BLOCK, "block side"),))], LEVELS[0]
    for z in LEVELS[1:]:
        a, b, r = pocket_size(z)
        loops = [rectangle(*BLOCK, "block side"),
                 rounded_rectangle(POCKET_CENTRE, a - ALLOWANCE, b - ALLOWANCE, r - ALLOWANCE, "pocket wall")]
        if z <= ISLAND_TOP:
            loops.append(Loop((PlanArc(ISLAND_CENTRE, island_radius(z) + ALLOWANCE, 0.0, 2 * np.pi, "island"),)))
        slabs.append(Slab(bottom, z, tuple(loops)))
        bottom = z
    return TerracedStock(tuple(slabs))


def design_height(x, y):
    """Height (mm) of the design part at plan points x, y (arrays)."""
    px, py = np.abs(x - POCKET_CENTRE[0]), np.abs(y - POCKET_CENTRE[1])
    # the pocket wall at height z passes through the point when its rounded-rectangle
    # distance equals the half sizes at z: solve for z along the slope (1/2 mm per mm up)
    a0, b0, r0 = pocket_size(FLOOR_Z)
    qx, qy = np.maximum(px - (a0 - r0), 0.0), np.maximum(py - (b0 - r0), 0.0)
    outside = np.hypot(qx, qy) - r0 + np.minimum(np.maximum(px - (a0 - r0), py - (b0 - r0)), 0.0)
    pocket = np.clip(FLOOR_Z + 2.0 * np.maximum(outside, 0.0), FLOOR_Z, TOP_Z)
    rho = np.hypot(x - ISLAND_CENTRE[0], y - ISLAND_CENTRE[1])
    island = np.where(rho <= island_radius(ISLAND_TOP), ISLAND_TOP, FLOOR_Z + (10.0 - rho) / 0.6)
    return np.maximum(pocket, np.minimum(island, ISLAND_TOP))


def toolpath():
    """CL points (53, 3) mm and unit tool axes (53, 3) of the pass."""
    x = np.linspace(8.0, 92.0, CL_POINTS)
    y = np.full(CL_POINTS, PASS_Y)
    z = design_height(x, y)
    lean, roll = np.radians(LEAN), np.radians(ROLL) * np.sin(np.linspace(0.0, 2 * np.pi, CL_POINTS))
    axis = np.column_stack([np.full(CL_POINTS, np.sin(lean)) * np.cos(roll), -np.sin(roll),
                            np.cos(lean) * np.cos(roll)])
    return np.column_stack([x, y, z]), axis / np.linalg.norm(axis, axis=1, keepdims=True)


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    stock = roughed_stock()
    dump_terraced(stock, OUT / "stock.json")
    export_step(terraced_solid(stock), OUT / "stock.step")
    cl, axis = toolpath()
    rows = ["x,y,z,i,j,k"] + [",".join(repr(float(v)) for v in (*p, *a)) for p, a in zip(cl, axis)]
    (OUT / "toolpath.csv").write_text("\n".join(rows) + "\n")
    job = {
        "description": ("Model test 4: a block with a pocket (sloped walls, rounded corners) and a conical island, "
                        "roughed in z-levels 5, 8, 11, 14, 17, 20 mm with 1 mm allowance (abm-terraced/1). One "
                        "five-axis pass of 53 CL points along x at y = 2 on the design surface, leaning 10 deg "
                        "forward and rolling +-6 deg. Generated by resources/models/make_model_test_4.py."),
        "diameter": DIAMETER, "flutes": FLUTES, "flute_length": FLUTE_LENGTH, "feed_per_tooth": 0.1,
        "inclination": LEAN, "spindle_rpm": 4000, "phi_range": [0, 180], "phi_step": 1,
    }
    (OUT / "job.json").write_text(json.dumps(job, indent=1) + "\n")
    print(f"wrote {OUT}: {len(stock.slabs)} slabs, {len(cl)} CL points")


if __name__ == "__main__":
    main()
