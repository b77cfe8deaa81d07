"""The staircase of the paper as a terraced stock: the special case, exactly.

One slab per distinct section height, from the base up; the slab under height z holds every
section whose top is at or above z. Each run of consecutive such sections is one loop: the
line y = y_min from the run's left wall to its right wall, the right wall up to y = y_max, the
line y = y_max back, the left wall down. Walls keep their exact form: a straight wall (and the
x limits) a PlanLine, a quintic wall (``walls.Wall``) the degree-5 Bézier curve it is over the
y window (x a quintic in y, y linear), a B-spline wall (``walls.SplineWall``) its spans over
the y window, each a rational Bézier span of the same degree.
"""

import numpy as np

from .polynomials import compose_linear, real_roots_unit
from .terraced_model import Loop, PlanLine, PlanSpline, Slab, TerracedStock
from .terraced_pieces import bernstein_to_power
from .walls import Wall


def _bezier_knots(degree, spans):
    """Clamped knots ((spans + 1)·degree + 2,) of `spans` Bézier spans joined end to end, over [0, spans]."""
    inner = np.repeat(np.arange(1, spans), degree)
    return np.concatenate([np.zeros(degree + 1), inner, np.full(degree + 1, float(spans))])


def _power_to_control(power):
    """Bernstein coefficients (..., d+1) on [0, 1] of power-basis ones (..., d+1)."""
    degree = power.shape[-1] - 1
    return power @ np.linalg.inv(bernstein_to_power(degree)).T


def _quintic_wall(wall, y_min, y_max, face):
    """A quintic Wall over [y_min, y_max] as a degree-5 PlanSpline running up in y."""
    t0 = (y_min - wall.y_mid) / wall.y_half
    q = (y_max - y_min) / wall.y_half
    x = _power_to_control(compose_linear(wall.coefficients, t0, q))
    y = y_min + (y_max - y_min) * np.arange(6) / 5.0
    y[-1] = y_max
    return PlanSpline(5, _bezier_knots(5, 1), np.column_stack([x, y]), None, face)


def _spline_wall(wall, y_min, y_max, face):
    """A SplineWall's part over [y_min, y_max] as a PlanSpline running up in y; ValueError when
    the wall does not reach across the window."""
    if wall.span_y[0] > y_min or wall.span_y[-1] < y_max:
        raise ValueError(f"{face}: the B-spline runs over y {wall.span_y[0]:.6g} to {wall.span_y[-1]:.6g}, "
                         f"not across the window {y_min:.6g} to {y_max:.6g}")
    spans = np.flatnonzero((wall.span_y[1:] > y_min) & (wall.span_y[:-1] < y_max))
    controls, weights = [], []
    for s in spans:
        bounds = []
        for y, default in ((y_min, 0.0), (y_max, 1.0)):
            if wall.span_y[s] < y < wall.span_y[s + 1]:
                bounds.append(float(real_roots_unit((wall.spans_y[s] - y * wall.spans_w[s])[None])[0, 0]))
            else:
                bounds.append(default)
        u0, u1 = bounds
        parts = [_power_to_control(compose_linear(c, u0, u1 - u0)) for c in (wall.spans_x[s], wall.spans_y[s],
                                                                                wall.spans_w[s])]
        controls.append(np.column_stack([parts[0] / parts[2], parts[1] / parts[2]]))
        weights.append(parts[2])
    control = np.concatenate([controls[0]] + [c[1:] for c in controls[1:]])
    weight = np.concatenate([weights[0]] + [w[1:] for w in weights[1:]])
    control[0, 1], control[-1, 1] = y_min, y_max
    rational = not np.allclose(weight, weight[0], rtol=0.0, atol=0.0)
    return PlanSpline(wall.degree, _bezier_knots(wall.degree, len(spans)), control,
                      weight if rational else None, face)


def _reversed(curve):
    """The same plan curve run the other way."""
    if isinstance(curve, PlanLine):
        return PlanLine(curve.end, curve.start, curve.face)
    knots = curve.knots[-1] + curve.knots[0] - curve.knots[::-1]
    weights = None if curve.weights is None else curve.weights[::-1]
    return PlanSpline(curve.degree, knots, curve.control[::-1], weights, curve.face)


def staircase_as_terraced(staircase):
    """The TerracedStock of a Staircase (same material, the walls exact): see the module docstring.

    Curve faces are named "x_min", "x_max", "y_min", "y_max" and "wall j" (wall j starts section j).
    """
    s = staircase
    walls = [PlanLine((s.x_min, s.y_min), (s.x_min, s.y_max), "x_min")]
    for j, wall in enumerate(s.walls, start=1):
        face = f"wall {j}"
        if wall.is_straight:
            x = float(wall.x_at(np.array([s.y_min]))[0])
            walls.append(PlanLine((x, s.y_min), (x, s.y_max), face))
        elif isinstance(wall, Wall):
            walls.append(_quintic_wall(wall, s.y_min, s.y_max, face))
        else:
            walls.append(_spline_wall(wall, s.y_min, s.y_max, face))
    walls.append(PlanLine((s.x_max, s.y_min), (s.x_max, s.y_max), "x_max"))
    levels = np.unique(s.z_top)
    slabs, bottom = [], s.base_z
    for level in levels:
        full = np.concatenate([[False], s.z_top >= level, [False]])
        starts = np.flatnonzero(full[1:] & ~full[:-1])  # first section of each run
        stops = np.flatnonzero(full[:-1] & ~full[1:])   # one past its last section
        loops = []
        for a, b in zip(starts, stops):
            left, right = walls[a], walls[b]
            (l0, l1), (r0, r1) = left.end_points, right.end_points
            loops.append(Loop((PlanLine(l0, r0, "y_min"), right, PlanLine(r1, l1, "y_max"), _reversed(left))))
        slabs.append(Slab(bottom, float(level), tuple(loops)))
        bottom = float(level)
    return TerracedStock(tuple(slabs))
