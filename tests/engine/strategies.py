"""Hypothesis strategies for engine tests: staircase stock, tool orientations, whole jobs.

Stocks are drawn as :class:`reference.StairData` (plain data, mm); :func:`engine_inputs`
turns a :class:`Job` into the engine's dataclasses. Walls are quintics of bounded
amplitude around increasing x positions, so they never cross each other or the x limits
inside [y_min, y_max].
"""

from typing import NamedTuple

import numpy as np
from hypothesis import strategies as st

from abm_workbench.engine import CutSettings, Staircase, Tool, Toolpath

from .reference import StairData

MAX_ANGLE = 40.0        # deg, largest |θ_A|, |θ_B| drawn
MIN_ANGLE = 0.5         # deg, smallest non-zero |θ| drawn (tinier tilts are ill-conditioned)
WALL_FILL = 0.3         # a wall's amplitude is at most this fraction of its neighbouring widths
WALL_BEND = 0.2         # ... and at most this fraction of half the y span (gentle curves)
# Irrational offsets (mm) added to CL coordinates and flute lengths: hypothesis favours
# simple values (integers, bounds), and without these a CL point would often sit exactly
# on a wall or an edge end exactly on a top, where the answer depends on rounding.
JITTER = np.sqrt([2.0, 3.0, 5.0, 7.0]) / 100.0


class Job(NamedTuple):
    """One pass: stock, tool (mm), m CL points (m, 3) with angles (m,) deg, φ grid settings (deg)."""

    stock: StairData
    diameter: float
    flute_length: float
    cl: np.ndarray
    theta_a: np.ndarray
    theta_b: np.ndarray
    phi_start: float
    phi_end: float
    phi_step: float


def _floats(lo, hi):
    """Finite floats in [lo, hi]."""
    return st.floats(lo, hi, allow_nan=False, allow_infinity=False)


def _wall_nodes(kind, y_min, y_max):
    """Six y values (6,) spanning [y_min, y_max]: 'even' or 'chebyshev' spacing, ascending."""
    k = np.arange(6)
    u = np.linspace(-1.0, 1.0, 6) if kind == "even" else -np.cos((2 * k + 1) * np.pi / 12)
    return 0.5 * (y_min + y_max) + 0.5 * (y_max - y_min) * u


@st.composite
def wall_shapes(draw):
    """Weights (5,) of T_1..T_5 (Chebyshev) with Σ|w| = 1, so |Σ w_k T_k(t)| ≤ 1 on [−1, 1]."""
    w = np.array(draw(st.lists(_floats(-1.0, 1.0), min_size=5, max_size=5)))
    if not np.any(np.abs(w) > 1e-3):
        w = np.array([1.0, 0, 0, 0, 0])
    return w / np.sum(np.abs(w))


@st.composite
def staircases(draw, min_sections=1, max_sections=6, curved=None):
    """StairData with min_sections–max_sections sections; tops ascending, descending or
    mixed; walls straight or curved.

    Tops are 2–40 mm above the base in steps of 1/8 mm, so two tops are equal or clearly
    different (tops a rounding error apart would make the Table 1 case depend on rounding).

    curved: None draws each wall's kind, True / False forces curved / straight walls.
    """
    n = draw(st.integers(min_sections, max_sections))
    x_min = draw(_floats(-60.0, 20.0))
    widths = np.array(draw(st.lists(_floats(4.0, 25.0), min_size=n, max_size=n)))
    y_min = draw(_floats(-60.0, 0.0))
    y_max = y_min + draw(_floats(10.0, 80.0))
    base_z = draw(_floats(-10.0, 10.0))
    tops = sorted(draw(st.lists(st.integers(16, 320), min_size=n, max_size=n)))
    order = draw(st.sampled_from(["ascending", "descending", "mixed"]))
    if order == "descending":
        tops = tops[::-1]
    elif order == "mixed":
        tops = draw(st.permutations(tops))
    edges = x_min + np.concatenate([[0.0], np.cumsum(widths)])
    ys = _wall_nodes(draw(st.sampled_from(["even", "chebyshev"])), y_min, y_max)
    half_span = 0.5 * (y_max - y_min)
    t = (ys - (y_min + half_span)) / half_span
    walls = []
    for j in range(1, n):
        is_curved = draw(st.booleans()) if curved is None else curved
        xs = np.full(6, edges[j])
        if is_curved:
            amp = draw(_floats(0.05, 1.0)) * min(WALL_FILL * min(widths[j - 1], widths[j]), WALL_BEND * half_span)
            xs = xs + amp * np.polynomial.chebyshev.chebval(t, np.concatenate([[0.0], draw(wall_shapes())]))
        walls.append(tuple(zip(xs.tolist(), ys.tolist())))
    return StairData(float(x_min), float(edges[-1]), float(y_min), float(y_max), float(base_z),
                     tuple(float(base_z + z / 8.0) for z in tops), tuple(walls))


def angles():
    """One tool rotation θ (deg): exactly 0, or MIN_ANGLE ≤ |θ| ≤ MAX_ANGLE of either sign."""
    tilt = _floats(MIN_ANGLE, MAX_ANGLE)
    return st.one_of(st.just(0.0), tilt, tilt.map(lambda a: -a))


@st.composite
def cl_points(draw, stock: StairData, radius, margin=3.0):
    """A CL point (3,) mm: anywhere over the stock (± margin in x, y, z; up to 10 mm above
    the tops), or near a wall (within radius + margin in x, below the higher adjacent top);
    shifted by JITTER."""
    y = draw(_floats(stock.y_min - margin, stock.y_max + margin))
    if stock.walls and draw(st.booleans()):
        j = draw(st.integers(1, len(stock.walls)))
        wall_x = float(np.mean([p[0] for p in stock.walls[j - 1]]))
        x = wall_x + draw(_floats(-radius - margin, radius + margin))
        z = draw(_floats(stock.base_z, max(stock.z_top[j - 1], stock.z_top[j])))
    else:
        x = draw(_floats(stock.x_min - margin, stock.x_max + margin))
        z = draw(_floats(stock.base_z - margin, max(stock.z_top) + 10.0))
    return np.array([x, y, z]) + JITTER[:3]


@st.composite
def jobs(draw, stocks=None, theta_a=None, theta_b=None, max_points=3):
    """A Job: a stock, a tool of diameter 4–20 mm and flute length 5–40 mm, 1–max_points CL points.

    stocks, theta_a, theta_b: strategies overriding the defaults (staircases(), angles()).
    The φ grid covers 180° from a start in [−180, 0] in 7–13 steps.
    """
    stock = draw(stocks if stocks is not None else staircases())
    diameter = draw(_floats(4.0, 20.0))
    m = draw(st.integers(1, max_points))
    cl = np.array([draw(cl_points(stock, diameter / 2)) for _ in range(m)])
    ta = np.array([draw(theta_a if theta_a is not None else angles()) for _ in range(m)])
    tb = np.array([draw(theta_b if theta_b is not None else angles()) for _ in range(m)])
    phi_start = draw(_floats(-180.0, 0.0))
    steps = draw(st.integers(6, 12))
    return Job(stock, diameter, draw(_floats(5.0, 40.0 - JITTER[3])) + JITTER[3], cl, ta, tb,
               phi_start, phi_start + 180.0, 180.0 / steps)


def engine_stock(stock: StairData) -> Staircase:
    """The engine's Staircase for a StairData."""
    walls = np.asarray(stock.walls, dtype=float).reshape(-1, 6, 2)
    return Staircase(stock.x_min, stock.x_max, stock.y_min, stock.y_max, stock.base_z,
                     np.asarray(stock.z_top, dtype=float), walls)


def engine_inputs(job: Job):
    """(Staircase, Tool, Toolpath, CutSettings) for a Job (feed 0.1 mm/tooth, 2 flutes)."""
    return (engine_stock(job.stock), Tool(job.diameter, 2, job.flute_length),
            Toolpath(job.cl, job.theta_a, job.theta_b),
            CutSettings(0.1, phi_start=job.phi_start, phi_end=job.phi_end, phi_step=job.phi_step))
