#!/usr/bin/env python3
"""Build the model tests' stock solids with their true contour walls, as STEP files.

For each ``resources/models/model_test_<n>/`` this reads ``stock.json`` (limits, base, section
tops) and ``walls.json`` (points on the true contour of every wall, written by
``make_model_tests.py``) and writes ``stock.step``: the staircase solid whose walls are

* the line x = const where ``walls.json`` says a wall is straight,
* else the cubic B-spline x(y) interpolating the wall's contour points with not-a-knot end
  conditions, as a curve (x(s), y(s)) = (spline(s), s): its poles are the spline's
  coefficients paired with the knots' Greville abscissae (which reproduce y(s) = s exactly).

``make_model_tests.py`` checks that this spline is within 1e-4 mm of the true contour. The
solid is then read back from the STEP file and recognised with exact walls; the script raises
unless the recognised walls pass through every contour point to 1e-9 mm and the tops match.
Run it with FreeCAD's Python, after ``make_model_tests.py``::

    /usr/bin/python3 resources/models/make_model_solids.py

Lengths in mm. The STEP header carries the time of writing; the geometry is deterministic.
"""

import json
import sys
from pathlib import Path

import numpy as np
from scipy.interpolate import make_interp_spline

OUT_DIR = Path(__file__).resolve().parent
sys.path.insert(0, str(OUT_DIR.parent.parent))

from abm_workbench.cad.recognise import load_solid, recognise  # noqa: E402
from abm_workbench.cad.solids import export_step, staircase_solid  # noqa: E402
from abm_workbench.engine import Staircase  # noqa: E402
from abm_workbench.engine.walls import SplineWall  # noqa: E402
from abm_workbench.formats.staircase_json import load_staircase  # noqa: E402

WALLS_FORMAT = "abm-contour-walls/1"
INTERPOLATION = "cubic B-spline x(y), not-a-knot"
#: The recognised walls must pass through the contour points to within this (mm).
ROUND_TRIP_TOL = 1e-9


def contour_wall(points, straight):
    """SplineWall of one wall from its contour points (N, 2) [x, y] (mm), y increasing.

    A straight wall is the degree-1 line over the points' y range; a curved one the cubic
    interpolating B-spline described in the module docstring.
    """
    x, y = points[:, 0], points[:, 1]
    if straight:
        return SplineWall(1, [y[0], y[0], y[-1], y[-1]], [[x[0], y[0]], [x[0], y[-1]]], None)
    spline = make_interp_spline(y, x, k=3)
    knots = spline.t
    greville = np.array([knots[i + 1:i + 4].mean() for i in range(spline.c.size)])
    return SplineWall(3, knots, np.column_stack([spline.c, greville]), None)


def load_contour_walls(path, n_walls):
    """(points (N, 2) per wall, straight flags) from walls.json; ValueError if it does not fit."""
    data = json.loads(Path(path).read_text())
    if data.get("format") != WALLS_FORMAT or data.get("interpolation") != INTERPOLATION:
        raise ValueError(f"{path}: expected format {WALLS_FORMAT!r} with interpolation {INTERPOLATION!r}")
    walls = data["walls"]
    if [w["section"] for w in walls] != list(range(1, n_walls + 1)):
        raise ValueError(f"{path}: expected walls of sections 1..{n_walls}")
    return [np.array(w["points"], dtype=float) for w in walls], [bool(w["straight"]) for w in walls]


def true_stock(folder):
    """The Staircase of folder/stock.json with the contour walls of folder/walls.json as wall_curves,
    and the contour points (list of (N, 2))."""
    stock = load_staircase(folder / "stock.json")
    points, straight = load_contour_walls(folder / "walls.json", stock.n_sections - 1)
    curves = tuple(contour_wall(p, s) for p, s in zip(points, straight))
    return Staircase(stock.x_min, stock.x_max, stock.y_min, stock.y_max, stock.base_z, stock.z_top,
                     stock.wall_points, curves), points


def check_round_trip(step, stock, points):
    """Read `step` back and recognise it (exact walls): tops equal, walls through every point.

    Returns the largest deviation (mm); RuntimeError when above ROUND_TRIP_TOL.
    """
    found = recognise(load_solid(step), source=str(step)).staircase
    if found.n_sections != stock.n_sections or np.abs(found.z_top - stock.z_top).max() > ROUND_TRIP_TOL:
        raise RuntimeError(f"{step}: the tops read back differ from stock.json")
    deviation = max(np.abs(w.x_at(p[:, 1]) - p[:, 0]).max() for w, p in zip(found.walls, points))
    if deviation > ROUND_TRIP_TOL:
        raise RuntimeError(f"{step}: a recognised wall is {deviation:.2e} mm off its contour points")
    return deviation


def quintic_gap(stock):
    """Largest |quintic wall − true wall| (mm) over 2001 y of the window: the paper's quintics
    through the stock's six wall points against its wall_curves."""
    y = np.linspace(stock.y_min, stock.y_max, 2001)
    quintic = Staircase(stock.x_min, stock.x_max, stock.y_min, stock.y_max, stock.base_z, stock.z_top,
                        stock.wall_points).walls
    return max(np.abs(q.x_at(y) - w.x_at(y)).max() for q, w in zip(quintic, stock.walls))


def main():
    """Write stock.step for every model test folder holding stock.json and walls.json."""
    folders = sorted(f for f in OUT_DIR.glob("model_test_*") if (f / "walls.json").is_file())
    if not folders:
        raise SystemExit("no model_test_*/walls.json: run make_model_tests.py first")
    for folder in folders:
        stock, points = true_stock(folder)
        solid = staircase_solid(stock)
        step = folder / "stock.step"
        export_step(solid, step)
        deviation = check_round_trip(step, stock, points)
        curved = sum(not w.is_straight for w in stock.walls)
        print(f"{folder.name}: {len(solid.Faces)} faces, {curved} B-spline walls "
              f"({points[0].shape[0]} contour points each); read back through every point to "
              f"{deviation:.1e} mm; quintic walls of stock.json up to {quintic_gap(stock):.4f} mm "
              "from the true walls")
        print(f"  wrote {step.relative_to(OUT_DIR.parent.parent)}")


if __name__ == "__main__":
    main()
