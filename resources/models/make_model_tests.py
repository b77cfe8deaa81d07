#!/usr/bin/env python3
"""Generate the two ABM model tests: staircase stock and one five-axis pass each.

Hendriko (2020) tested the analytical boundary method on two free-form parts that had
been rough-milled in 2.5D layers; their geometry is unpublished. This script builds two
stand-ins that exercise the same things and writes, for each, into
``resources/models/model_test_<n>/``:

* ``stock.json``  -- the staircase left by layer roughing (format ``abm-staircase/1``),
  each wall given by six points for the paper's quintic,
* ``walls.json``  -- the true contour walls: per wall, CONTOUR_POINTS points on the contour
  across the window (the solids in ``stock.step`` interpolate them, see
  ``make_model_solids.py``),
* ``toolpath.csv`` -- 53 CL points with unit tool axis and CC point,
* ``job.json``     -- the cut settings (tool, feed, inclination, rotation range).

How the models are made (design surface, layers, wall points, CC -> CL) is written up in
``docs/MODEL_TESTS.md``; the functions below follow it one to one. Before writing a model
test the script checks it, including a brute-force engagement of sampled cutting edges
against the staircase, prints a summary and raises ``SelfCheckError`` if an invariant fails
(that model test is then not written).

Run it with an interpreter that has numpy and scipy::

    /usr/bin/python3 resources/models/make_model_tests.py

It is deterministic (no random numbers). Units: lengths in mm; angles in degrees in the
files and model parameters, in radians inside the numeric functions (said where used).
The script imports neither FreeCAD nor the ``abm_workbench`` package, so that it stays an
independent generator of test data for them.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np
from scipy.interpolate import make_interp_spline
from scipy.optimize import brentq

OUT_DIR = Path(__file__).resolve().parent

N_CC = 53  # CC points in the pass (as in the paper)
N_WALL_POINTS = 6  # points per wall: the engine's quintic x = P(y)
FIT_TOL = 0.05  # mm, allowed |P(y) - true contour| over [y_min, y_max]
CONTOUR_POINTS = 65  # evenly spaced points per wall on the true contour (walls.json)
SPLINE_TOL = 1e-4  # mm, allowed |cubic spline through them - true contour|
STRAIGHT_TOL = 1e-9  # mm, spread of six contour points that makes a wall straight
X_SCAN_STEP = 0.02  # mm, x grid used to bracket the contour crossings
N_Y_CHECK = 241  # y samples for the wall checks
EDGE_STEP = 0.02  # mm, sampling of the cutting edge in the brute-force check
BISECT_STEPS = 40  # bisection steps refining an engagement point (0.02 mm / 2**40)
GOUGE_TOL = 0.01  # mm, allowed dip of the tool's bottom face under the design surface
COMPLEX_STEP = 1e-30  # complex-step differentiation of the design surface

Surface = Callable[[np.ndarray, np.ndarray], np.ndarray]


class SelfCheckError(RuntimeError):
    """A model test breaks one of the invariants the script promises."""


def require(condition, message: str) -> None:
    """Raise SelfCheckError(message) unless condition holds (unlike assert, never skipped)."""
    if not condition:
        raise SelfCheckError(message)


# --------------------------------------------------------------------------- surfaces


def gauss(u):
    """exp(-u^2 / 2), elementwise; u real or complex (n,) or scalar."""
    return np.exp(-0.5 * u * u)


def smooth_step(t):
    """C-infinity step: 0 for t <= 0, 1 for t >= 1, smooth in between.

    s(t) = b(t) / (b(t) + b(1 - t)) with b(t) = exp(-1/t) for t > 0, else 0. Works for
    complex t with a tiny imaginary part (complex-step differentiation): the branch is
    chosen on the real part.
    """
    t = np.asarray(t)

    def b(u):
        positive = np.real(u) > 0
        return np.where(positive, np.exp(-1.0 / np.where(positive, u, 1.0)), 0.0)

    return b(t) / (b(t) + b(1.0 - t))


# Model test 1: a fanned double ridge. The profile g1 rises to a main ridge, falls into a
# valley and rises again towards a second, lower ridge. Each section y = const is g1
# stretched along x about the station x = X_RULING_1 by the factor m(y):
# f1(x, y) = g1(X_RULING_1 + (x - X_RULING_1) m(y)). All sections pass through the same
# point at that station, so the line x = X_RULING_1, z = g1(X_RULING_1) lies on the surface;
# the roughing layer at its height plus the allowance leaves a straight wall there.
X_RULING_1 = 76.0
ALLOWANCE_1 = 1.4


def profile_1(xi):
    """Model test 1 profile g1(xi) in mm: main ridge, valley, second lower ridge."""
    return 21.0 * gauss((xi - 50.0) / 19.0) + 8.0 * gauss((xi - 136.0) / 17.0)


def surface_1(x, y):
    """Design surface of model test 1, z = f1(x, y) in mm; x, y arrays of one shape."""
    stretch = 1.0 + 0.010 * y + 0.0004 * y * y
    return profile_1(X_RULING_1 + (x - X_RULING_1) * stretch)


# Model test 2: a bent, skewed dome ridge on a gentle slope whose entry flank is an
# extruded (y-invariant) profile. The crest line x_c(x, y) = 64 + s(x) (0.25 y - 0.012 y^2)
# is straight (x_c = 64) for x <= X_EXTRUDED_2, where the blend s is exactly 0: there the
# surface does not depend on y and every contour, hence every wall, is straight.
X_EXTRUDED_2 = 20.5


def surface_2(x, y):
    """Design surface of model test 2, z = f2(x, y) in mm; x, y arrays of one shape."""
    blend = smooth_step((x - X_EXTRUDED_2) / 20.0)
    crest = 64.0 + blend * (0.25 * y - 0.012 * y * y)
    return 24.0 * gauss((x - crest) / 29.0) + 0.04 * x


def surface_gradient(surface: Surface, x, y):
    """(df/dx, df/dy) of a design surface at real x, y (arrays of one shape).

    Complex-step differentiation: df/dx = Im f(x + i h, y) / h, exact to rounding.
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    h = COMPLEX_STEP
    fx = np.imag(surface(x + 1j * h, y + 0j)) / h
    fy = np.imag(surface(x + 0j, y + 1j * h)) / h
    return fx, fy


# --------------------------------------------------------------------------- model data


@dataclass(frozen=True)
class ModelTest:
    """Everything that defines one model test (mm, degrees)."""

    name: str
    shape: str  # one line on the design surface and where the straight walls come from
    surface: Surface
    level_ref: float  # one roughing layer height; the others are level_ref + k * layer_step
    allowance: float  # roughing allowance left above the design surface
    layer_step: float  # 2.5D roughing step-down
    x_min: float
    x_max: float
    y_min: float
    y_max: float
    base_z: float
    cc_x: tuple[float, float]  # first and last CC point x on the pass line y = 0
    diameter: float
    flutes: int
    flute_length: float
    inclination: float  # deg, tool axis tilted from the normal towards the feed
    feed_per_tooth: float
    spindle_rpm: int

    @property
    def tool_radius(self) -> float:
        """Tool radius R_t in mm."""
        return 0.5 * self.diameter

    @property
    def description(self) -> str:
        """One paragraph for job.json."""
        return (
            f"{self.name.replace('_', ' ').capitalize()} (after Hendriko 2020): {self.shape} "
            f"Stock: 2.5D layer roughing, {self.layer_step} mm step-down, {self.allowance} mm "
            f"allowance, strip x {self.x_min}..{self.x_max}, y {self.y_min}..{self.y_max}. "
            f"One pass of {N_CC} CC points along +x at y = 0. Tool: {self.flutes}-flute flat "
            f"end mill D {self.diameter} mm, flute length {self.flute_length} mm, inclination "
            f"{self.inclination} deg, {self.feed_per_tooth} mm/tooth, {self.spindle_rpm} rpm. "
            "Generated by resources/models/make_model_tests.py (see docs/MODEL_TESTS.md)."
        )

    def layer_index(self, x, y):
        """k of the lowest layer z_k = level_ref + k * layer_step with z_k >= f + allowance.

        x, y arrays of one shape; returns floats with integer values. A point exactly on a
        level (to 1e-12 of a step) gets that level.
        """
        excess = self.surface(x, y) + self.allowance - self.level_ref
        return np.ceil(excess / self.layer_step - 1e-12)

    def stock_top(self, x, y):
        """Exact stock top after layer roughing, z_k of layer_index, mm."""
        return self.level_ref + self.layer_step * self.layer_index(x, y)


MODEL_TESTS = (
    ModelTest(
        name="model_test_1",
        shape=(
            "fanned double ridge; the pass climbs the main ridge, descends into a valley and "
            f"climbs again. The wall at x = {X_RULING_1} lies at the height of a horizontal "
            "straight line of the surface and is straight; all other walls are curved."
        ),
        surface=surface_1,
        level_ref=float(profile_1(X_RULING_1)) + ALLOWANCE_1,
        allowance=ALLOWANCE_1,
        layer_step=3.0,
        x_min=0.0,
        x_max=130.0,
        y_min=-15.0,
        y_max=15.0,
        base_z=-20.0,
        cc_x=(13.0, 125.0),
        diameter=12.0,
        flutes=2,
        flute_length=30.0,
        inclination=10.0,
        feed_per_tooth=0.1,
        spindle_rpm=4000,
    ),
    ModelTest(
        name="model_test_2",
        shape=(
            "bent, skewed dome ridge with an extruded (y-invariant) entry flank; the pass "
            "climbs the flank and the dome and descends the far side. The walls on the "
            f"extruded flank (x < {X_EXTRUDED_2}) are straight, the others curved."
        ),
        surface=surface_2,
        level_ref=1.9,
        allowance=1.0,
        layer_step=2.5,
        x_min=0.0,
        x_max=130.0,
        y_min=-15.0,
        y_max=15.0,
        base_z=-20.0,
        cc_x=(14.0, 125.0),
        diameter=14.0,
        flutes=2,
        flute_length=30.0,
        inclination=5.0,
        feed_per_tooth=0.15,
        spindle_rpm=4000,
    ),
)


# --------------------------------------------------------------------------- walls


def chebyshev_nodes(lo: float, hi: float, n: int = N_WALL_POINTS) -> np.ndarray:
    """(n,) Chebyshev points of the first kind on [lo, hi], ascending."""
    k = np.arange(n)
    return np.sort(0.5 * (lo + hi) + 0.5 * (hi - lo) * np.cos((2 * k + 1) * np.pi / (2 * n)))


def contour_crossings(model: ModelTest, y: float) -> tuple[np.ndarray, np.ndarray]:
    """Where the offset surface f(x, y) + allowance crosses a layer level along x.

    Returns (x (m,), level (m,)) in +x order for x_min < x < x_max: each crossing
    bracketed on an X_SCAN_STEP grid and solved with brentq.
    """
    xs = np.arange(model.x_min, model.x_max + 0.5 * X_SCAN_STEP, X_SCAN_STEP)
    band = model.layer_index(xs, np.full_like(xs, y))
    idx = np.nonzero(band[1:] != band[:-1])[0]
    one_level = np.all(np.abs(band[idx + 1] - band[idx]) == 1)
    require(one_level, f"{model.name}: two levels in one scan step, y={y}")
    levels = model.level_ref + model.layer_step * np.minimum(band[idx], band[idx + 1])

    def root(i, level):
        def g(x):
            return float(model.surface(np.array(x), np.array(y))) + model.allowance - level

        return brentq(g, xs[i], xs[i + 1], xtol=1e-13, rtol=4 * np.finfo(float).eps)

    return np.array([root(i, lv) for i, lv in zip(idx, levels)]), levels


def make_walls(model: ModelTest) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Wall points and section tops of the roughed staircase.

    Returns (wall_y (6,), wall_x (n_walls, 6), z_top (n_walls + 1,)). The crossing pattern
    (which levels, in which order) must be the same at every y of the window, else the
    contours do not form an x-ordered staircase. A wall whose six roots agree to within
    STRAIGHT_TOL is a straight contour: its six x are set to one value (rounded to 1e-9 mm).
    """
    ref_x, ref_levels = contour_crossings(model, 0.0)
    for y in np.linspace(model.y_min, model.y_max, N_Y_CHECK):
        _, levels = contour_crossings(model, y)
        require(np.array_equal(levels, ref_levels), f"{model.name}: contour pattern changes at y={y:.3f}")

    wall_y = chebyshev_nodes(model.y_min, model.y_max)
    wall_x = np.array([contour_crossings(model, y)[0] for y in wall_y]).T
    for row in wall_x:
        if np.ptp(row) < STRAIGHT_TOL:
            row[:] = np.round(row[2], 9)

    x_bounds = np.concatenate(([model.x_min], ref_x, [model.x_max]))
    mid = 0.5 * (x_bounds[:-1] + x_bounds[1:])
    z_top = model.stock_top(mid, np.zeros_like(mid))
    return wall_y, wall_x, z_top


def make_contours(model: ModelTest, wall_x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The true contour walls: CONTOUR_POINTS evenly spaced y over the window, x of every wall.

    wall_x: (n_walls, 6) from make_walls; its straight rows (six equal x) give the straight
    walls, whose dense x must agree with that value to STRAIGHT_TOL and are set to it.
    Returns (y (N,), x (n_walls, N)).
    """
    y = np.linspace(model.y_min, model.y_max, CONTOUR_POINTS)
    x = np.array([contour_crossings(model, yy)[0] for yy in y]).T
    for row, six in zip(x, wall_x):
        if np.all(six == six[0]):
            require(np.abs(row - six[0]).max() < STRAIGHT_TOL, f"{model.name}: straight wall x = {six[0]} bends")
            row[:] = six[0]
    return y, x


def contour_spline(y: np.ndarray, x_row: np.ndarray):
    """The wall curve a solid is built with: the cubic B-spline x(y) interpolating the points
    (y (N,) increasing, x_row (N,)), not-a-knot end conditions (scipy's make_interp_spline)."""
    return make_interp_spline(y, x_row, k=3)


def check_contour_splines(model: ModelTest, y: np.ndarray, x: np.ndarray) -> float:
    """Largest |spline - true contour| (mm) over all walls, at the midpoints between the points
    and at N_Y_CHECK values of y; must be below SPLINE_TOL."""
    y_check = np.concatenate([0.5 * (y[1:] + y[:-1]), np.linspace(model.y_min, model.y_max, N_Y_CHECK)])
    true = np.array([contour_crossings(model, yy)[0] for yy in y_check]).T
    deviation = max(np.abs(contour_spline(y, row)(y_check) - t).max() for row, t in zip(x, true))
    require(deviation < SPLINE_TOL, f"{model.name}: contour spline off its contour by {deviation:.2e} mm")
    return float(deviation)


# --------------------------------------------------------------------------- staircase


def scaled_y(y, y_min: float, y_max: float):
    """t = (y - y_mid) / y_half, the window mapped onto [-1, 1] (keeps the quintic well
    conditioned); y any shape."""
    return (np.asarray(y) - 0.5 * (y_min + y_max)) / (0.5 * (y_max - y_min))


@dataclass(frozen=True)
class Staircase:
    """The stock as the engine sees it: quintic walls through the six points (mm)."""

    x_min: float
    x_max: float
    y_min: float
    y_max: float
    base_z: float
    z_top: np.ndarray  # (n,) section tops
    wall_coef: np.ndarray  # (n - 1, 6) quintic coefficients in t = (y - y_mid) / y_half
    straight: np.ndarray  # (n - 1,) bool, all six x equal

    @classmethod
    def from_points(cls, model: ModelTest, wall_y, wall_x, z_top) -> "Staircase":
        """Interpolate each wall's six points (Vandermonde solve in the scaled variable)."""
        t = scaled_y(wall_y, model.y_min, model.y_max)
        vander = np.vander(t, N_WALL_POINTS, increasing=True)
        coef = np.linalg.solve(vander, np.asarray(wall_x).T).T
        straight = np.all(wall_x == wall_x[:, :1], axis=1)
        limits = (model.x_min, model.x_max, model.y_min, model.y_max, model.base_z)
        return cls(*limits, np.asarray(z_top), coef, straight)

    def wall_x(self, y):
        """x of every wall at y: (n - 1, *y.shape)."""
        t = scaled_y(y, self.y_min, self.y_max)
        return np.polynomial.polynomial.polyval(t, self.wall_coef.T)

    def section(self, x, y):
        """Index of the section holding (x, y): number of walls with P_j(y) <= x."""
        return np.sum(self.wall_x(y) <= np.asarray(x), axis=0)

    def top(self, x, y):
        """Stock top height at (x, y), mm."""
        return self.z_top[self.section(x, y)]

    def in_limits(self, p):
        """(...,) bool: p (..., 3) inside the strip's x, y limits and above the base."""
        x, y, z = p[..., 0], p[..., 1], p[..., 2]
        in_x = (x >= self.x_min) & (x <= self.x_max)
        return in_x & (y >= self.y_min) & (y <= self.y_max) & (z >= self.base_z)

    def inside(self, p):
        """(...,) bool: p (..., 3) inside the stock."""
        return self.in_limits(p) & (p[..., 2] <= self.top(p[..., 0], p[..., 1]))


# --------------------------------------------------------------------------- the pass


def rotation(theta_a, theta_b):
    """R = Rx(theta_a) @ Ry(theta_b), angles in radians, (3, 3)."""
    ca, sa, cb, sb = np.cos(theta_a), np.sin(theta_a), np.cos(theta_b), np.sin(theta_b)
    return np.array([[cb, 0.0, sb], [sa * sb, ca, -sa * cb], [-ca * sb, sa, ca * cb]])


def make_pass(model: ModelTest) -> dict[str, np.ndarray]:
    """CC points, normals, feed directions, tool axes, CL points and angles of the pass.

    CC points C = (x, 0, f(x, 0)) at N_CC evenly spaced x. n = (-f_x, -f_y, 1)/|.|;
    f = pass tangent (1, 0, f_x) made perpendicular to n and normalised; tool axis
    w = cos(a) n + sin(a) f; rim direction to the contact e = cos(a) f - sin(a) n;
    CL point T = C - R_t e. Angles (degrees): theta_B = asin(w_x),
    theta_A = atan2(-w_y, w_z). Every array is (N_CC, 3) or (N_CC,).
    """
    x = np.linspace(*model.cc_x, N_CC)
    y = np.zeros_like(x)
    cc = np.stack([x, y, model.surface(x, y)], axis=1)
    fx, fy = surface_gradient(model.surface, x, y)
    normal = np.stack([-fx, -fy, np.ones_like(x)], axis=1)
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    tangent = np.stack([np.ones_like(x), np.zeros_like(x), fx], axis=1)
    feed = tangent - np.sum(tangent * normal, axis=1, keepdims=True) * normal
    feed /= np.linalg.norm(feed, axis=1, keepdims=True)
    alpha = np.radians(model.inclination)
    axis = np.cos(alpha) * normal + np.sin(alpha) * feed
    rim = np.cos(alpha) * feed - np.sin(alpha) * normal
    cl = cc - model.tool_radius * rim
    theta_b = np.degrees(np.arcsin(axis[:, 0]))
    theta_a = np.degrees(np.arctan2(-axis[:, 1], axis[:, 2]))
    return {"cc": cc, "normal": normal, "feed": feed, "axis": axis, "rim": rim, "cl": cl,
            "theta_a": theta_a, "theta_b": theta_b}


# --------------------------------------------------------------------------- writing


def write_model(model: ModelTest, wall_y, wall_x, z_top, path: dict[str, np.ndarray]) -> Path:
    """Write stock.json, toolpath.csv and job.json into OUT_DIR / model.name."""
    folder = OUT_DIR / model.name
    folder.mkdir(parents=True, exist_ok=True)
    sections = [{"z_top": float(z_top[0])}]
    for j in range(1, len(z_top)):
        wall = [[float(x), float(y)] for x, y in zip(wall_x[j - 1], wall_y)]
        sections.append({"z_top": float(z_top[j]), "wall": wall})
    stock = {
        "format": "abm-staircase/1",
        "units": "mm",
        "base_z": model.base_z,
        "x_min": model.x_min,
        "x_max": model.x_max,
        "y_min": model.y_min,
        "y_max": model.y_max,
        "sections": sections,
    }
    (folder / "stock.json").write_text(json.dumps(stock, indent=1) + "\n")

    rows = ["x,y,z,i,j,k,xc,yc,zc"]
    for t, w, c in zip(path["cl"], path["axis"], path["cc"]):
        rows.append(",".join(repr(float(v) + 0.0) for v in (*t, *w, *c)))  # + 0.0: no "-0.0"
    (folder / "toolpath.csv").write_text("\n".join(rows) + "\n")

    job = {
        "description": model.description,
        "diameter": model.diameter,
        "flutes": model.flutes,
        "flute_length": model.flute_length,
        "feed_per_tooth": model.feed_per_tooth,
        "inclination": model.inclination,
        "spindle_rpm": model.spindle_rpm,
        "phi_range": [0, 180],
        "phi_step": 1,
    }
    (folder / "job.json").write_text(json.dumps(job, indent=1) + "\n")
    return folder


def write_contour_walls(model: ModelTest, folder: Path, z_top, contour_y, contour_x, deviation: float) -> None:
    """Write walls.json: per wall j = 1..n-1 its contour level, straightness and [x, y] points."""
    walls = []
    for j, row in enumerate(contour_x, start=1):
        walls.append({
            "section": j,
            "level": float(min(z_top[j - 1], z_top[j])),
            "straight": bool(np.all(row == row[0])),
            "points": [[float(x), float(y)] for x, y in zip(row, contour_y)],
        })
    data = {
        "format": "abm-contour-walls/1",
        "units": "mm",
        "description": (
            f"True walls of {model.name}: wall j (where section j starts) is the contour "
            "f(x, y) + allowance = level of the design surface; points on it at evenly spaced y "
            "over the window. A solid's wall is the line x = const when straight, else the cubic "
            "B-spline x(y) interpolating the points with not-a-knot end conditions."
        ),
        "interpolation": "cubic B-spline x(y), not-a-knot",
        "max_interpolation_error": deviation,
        "walls": walls,
    }
    (folder / "walls.json").write_text(json.dumps(data, indent=1) + "\n")


# --------------------------------------------------------------------------- self-check


def check_walls(model: ModelTest, stair: Staircase) -> dict[str, float]:
    """Walls ordered, inside the x limits, quintic within FIT_TOL of the true contour.

    Also checks the stock against the design surface on a grid over the strip:
    f + allowance - FIT_TOL <= top <= f + allowance + layer_step + FIT_TOL (the band the
    quintic walls can shift by their fit error). Returns summary numbers (mm).
    """
    y = np.linspace(model.y_min, model.y_max, N_Y_CHECK)
    walls = stair.wall_x(y)
    inside = np.all(walls[0] > model.x_min) and np.all(walls[-1] < model.x_max)
    require(inside, f"{model.name}: a wall leaves the strip")
    require(np.all(np.diff(walls, axis=0) > 1.0), f"{model.name}: walls closer than 1 mm or crossing")
    true = np.array([contour_crossings(model, yy)[0] for yy in y]).T
    deviation = np.abs(walls - true)
    require(deviation.max() < FIT_TOL, f"{model.name}: quintic off its contour by {deviation.max():.4f} mm")
    both = stair.straight.any() and not stair.straight.all()
    require(both, f"{model.name}: needs straight and curved walls")

    gx, gy = np.meshgrid(np.arange(model.x_min, model.x_max, 0.1), np.linspace(model.y_min, model.y_max, 121))
    excess = stair.top(gx, gy) - model.surface(gx, gy) - model.allowance
    in_band = excess.min() > -FIT_TOL and excess.max() < model.layer_step + FIT_TOL
    require(in_band, f"{model.name}: stock top outside [f + a, f + a + step] by more than FIT_TOL")
    span = np.ptp(walls[~stair.straight], axis=1)
    return {"fit_dev": deviation.max(), "excess_min": excess.min(), "excess_max": excess.max(),
            "span_min": span.min(), "span_max": span.max()}


def check_pass(model: ModelTest, stair: Staircase, path: dict[str, np.ndarray]) -> dict[str, float]:
    """The CC -> CL geometry, the angles, and the tool bottom against surface and stock.

    Checks: unit axis at the inclination from the normal; contact rim point T + R_t e = C;
    every rim point on or above the tangent plane (height R_t sin(a) (1 - cos psi));
    R(theta_A, theta_B) e_z = w; both signs of theta_A and theta_B; the bottom face not
    below the design surface by more than GOUGE_TOL; each CC point inside the stock at
    least allowance - FIT_TOL below its top. Returns {"gouge": largest dip, mm, >= 0}.
    """
    rt, alpha = model.tool_radius, np.radians(model.inclination)
    cc, normal, axis, cl = path["cc"], path["normal"], path["axis"], path["cl"]
    name = model.name
    require(np.allclose(np.linalg.norm(axis, axis=1), 1.0, atol=1e-12), f"{name}: tool axis not unit")
    require(np.allclose(np.sum(axis * normal, axis=1), np.cos(alpha), atol=1e-12), f"{name}: axis tilt")
    require(np.allclose(cl + rt * path["rim"], cc, atol=1e-12), f"{name}: contact rim point is not C")
    feed_dot_n = np.sum(path["feed"] * normal, axis=1)
    require(np.allclose(feed_dot_n, 0.0, atol=1e-12), f"{name}: feed not perpendicular to n")

    psi = np.radians(np.arange(0.0, 360.0, 1.0))
    gouge = 0.0
    for k in range(N_CC):
        rot = rotation(np.radians(path["theta_a"][k]), np.radians(path["theta_b"][k]))
        require(np.allclose(rot[:, 2], axis[k], atol=1e-12), f"{name}: angles do not give the axis, CL {k}")
        side = np.cross(axis[k], path["rim"][k])
        rim = cl[k] + rt * (np.cos(psi)[:, None] * path["rim"][k] + np.sin(psi)[:, None] * side)
        height = (rim - cc[k]) @ normal[k]
        expected = rt * np.sin(alpha) * (1 - np.cos(psi))
        require(np.allclose(height, expected, atol=1e-9), f"{name}: rim below the tangent plane, CL {k}")
        rho = np.linspace(0.0, rt, 15)[:, None, None]
        disc = cl[k] + rho * (np.sin(psi)[:, None] * rot[:, 0] + np.cos(psi)[:, None] * rot[:, 1])
        gouge = max(gouge, float(np.max(model.surface(disc[..., 0], disc[..., 1]) - disc[..., 2])))
    require(gouge < GOUGE_TOL, f"{name}: tool bottom {gouge:.4f} mm below the design surface")
    for angle in ("theta_a", "theta_b"):
        require(path[angle].min() < 0 < path[angle].max(), f"{name}: {angle} keeps one sign")
    clearance = stair.top(cc[:, 0], cc[:, 1]) - cc[:, 2]
    require(clearance.min() > model.allowance - FIT_TOL, f"{name}: a CC point is not inside the stock")
    return {"gouge": gouge}


UEP_CLASSES = ("top", "straight wall", "curved wall", "stock limit")


def refine(stair: Staircase, edge, lo, hi):
    """Bisect l between lo (inside) and hi (outside) per angle; edge(l) gives (m, 3)."""
    for _ in range(BISECT_STEPS):
        mid = 0.5 * (lo + hi)
        inside = stair.inside(edge(mid))
        lo, hi = np.where(inside, mid, lo), np.where(inside, hi, mid)
    return lo, hi


def brute_force_engagement(model: ModelTest, stair: Staircase, path: dict[str, np.ndarray]):
    """Crude engagement of the side cutting edge, sampled, for every CL point and angle.

    The edge S(phi, l) = T + R (R_t sin phi, R_t cos phi, l), R = Rx(theta_A) Ry(theta_B),
    is sampled every EDGE_STEP along 0 <= l <= flute_length for phi = 0..180 deg (1 deg)
    and tested against the staircase. The LEP (start of the first inside piece) and UEP
    (end of the last) are refined by bisection; the UEP is classed by what the edge
    leaves through (UEP_CLASSES). Returns (depth (N_CC,) mm, uep_class (N_CC, 181) int,
    -1 where the edge misses the stock).
    """
    rt = model.tool_radius
    phi = np.radians(np.arange(0.0, 181.0, 1.0))
    ell = np.arange(0.0, model.flute_length + 0.5 * EDGE_STEP, EDGE_STEP)
    depth = np.empty(N_CC)
    uep_class = np.full((N_CC, phi.size), -1)
    for k in range(N_CC):
        rot = rotation(np.radians(path["theta_a"][k]), np.radians(path["theta_b"][k]))
        radial = np.sin(phi)[:, None] * rot[:, 0] + np.cos(phi)[:, None] * rot[:, 1]
        foot = path["cl"][k] + rt * radial  # (181, 3) bottom points of the edges

        inside = stair.inside(foot[:, None, :] + ell[None, :, None] * rot[:, 2])
        on = np.nonzero(inside.any(axis=1))[0]
        require(on.size, f"{model.name}: CL {k} does not engage the stock")
        first = np.argmax(inside[on], axis=1)
        last = ell.size - 1 - np.argmax(inside[on, ::-1], axis=1)
        require(np.all(last < ell.size - 1), f"{model.name}: CL {k} engaged up to the flute end")

        def edge(l_values):
            return foot[on] + l_values[:, None] * rot[:, 2]

        uep_l, out_l = refine(stair, edge, ell[last], ell[last + 1])
        before = ell[np.maximum(first - 1, 0)]  # the outside sample before the first inside one
        lep_l = np.where(first > 0, refine(stair, edge, ell[first], before)[0], 0.0)
        uep, out = edge(uep_l), edge(out_l)
        lep = edge(lep_l)
        depth[k] = uep[:, 2].max() - lep[:, 2].min()

        s_in, s_out = stair.section(uep[:, 0], uep[:, 1]), stair.section(out[:, 0], out[:, 1])
        on_top = s_in == s_out
        wall = np.where(on_top, 0, np.maximum(s_in, s_out) - 1)
        gap_top = np.abs(uep[:, 2] - stair.z_top[s_in])
        gap_wall = np.abs(uep[:, 0] - stair.wall_x(uep[:, 1])[wall, np.arange(wall.size)])
        in_limits = stair.in_limits(out)
        gap = np.where(on_top, gap_top, gap_wall)[in_limits]
        require(np.all(gap < 1e-9), f"{model.name}: UEP off its surface by {gap.max():.2e} mm, CL {k}")
        cls = np.where(on_top, 0, np.where(stair.straight[wall], 1, 2))
        uep_class[k, on] = np.where(in_limits, cls, 3)
    return depth, uep_class


def self_check(model: ModelTest, stair: Staircase, path: dict[str, np.ndarray]) -> None:
    """Run all checks on one model test, print the summary, raise on a failed invariant."""
    walls = check_walls(model, stair)
    bottom = check_pass(model, stair, path)
    depth, uep_class = brute_force_engagement(model, stair, path)
    counts = [int(np.sum(uep_class == c)) for c in range(len(UEP_CLASSES))]
    cl_counts = [int(np.sum(np.any(uep_class == c, axis=1))) for c in range(len(UEP_CLASSES))]

    n_straight = int(stair.straight.sum())
    print(f"{model.name}: {len(stair.z_top)} sections, {n_straight} straight + "
          f"{len(stair.straight) - n_straight} curved walls, "
          f"tops {np.round(stair.z_top, 3).tolist()}")
    print(f"  quintic wall fit: max |P(y) - contour| = {walls['fit_dev']:.5f} mm over y in "
          f"[{model.y_min}, {model.y_max}]; curved walls span {walls['span_min']:.2f} .. "
          f"{walls['span_max']:.2f} mm in x over the window")
    print(f"  stock top - (surface + allowance): "
          f"{walls['excess_min']:.4f} .. {walls['excess_max']:.4f} mm")
    print(f"  tool bottom below design surface: max {bottom['gouge']:.5f} mm")
    print(f"  theta_A {path['theta_a'].min():.3f} .. {path['theta_a'].max():.3f} deg, "
          f"theta_B {path['theta_b'].min():.3f} .. {path['theta_b'].max():.3f} deg")
    print(f"  depth of cut (brute force): {depth.min():.3f} .. {depth.max():.3f} mm "
          f"(CL {int(depth.argmin())} .. CL {int(depth.argmax())})")
    print("  UEP on: " + ", ".join(
        f"{name} {n} instants / {m} CL" for name, n, m in zip(UEP_CLASSES, counts, cl_counts)))
    straight_cl = np.nonzero(np.any(uep_class == 1, axis=1))[0]
    print(f"  CL points (from 0) with a UEP on a straight wall: {straight_cl.tolist()}")
    print(f"  instants without engagement: {int(np.sum(uep_class == -1))} of {uep_class.size}")
    require(all(counts[:3]), f"{model.name}: UEP must occur on a top, a straight and a curved wall")
    require(counts[3] == 0, f"{model.name}: UEP on the strip's side limits: widen the strip")


def main() -> None:
    """Build and check both model tests, then write each one's files."""
    for model in MODEL_TESTS:
        wall_y, wall_x, z_top = make_walls(model)
        stair = Staircase.from_points(model, wall_y, wall_x, z_top)
        path = make_pass(model)
        self_check(model, stair, path)
        contour_y, contour_x = make_contours(model, wall_x)
        deviation = check_contour_splines(model, contour_y, contour_x)
        print(f"  contour walls: {CONTOUR_POINTS} points each; cubic spline through them: "
              f"max |S(y) - contour| = {deviation:.2e} mm")
        folder = write_model(model, wall_y, wall_x, z_top, path)
        write_contour_walls(model, folder, z_top, contour_y, contour_x, deviation)
        print(f"  wrote {folder.relative_to(OUT_DIR.parent.parent)}")


if __name__ == "__main__":
    main()
