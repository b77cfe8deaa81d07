"""Where helical cutting edges cross the staircase's walls x = W_j(y) (mm).

Along a helix the wall function g(l) = x(l) − W(y(l)) is transcendental (x and y are
sine-lines, helix_roots.py). Its roots are isolated by subdivision with proven bounds: on a
piece [m − h, m + h], Taylor's theorem with |g″| ≤ M₂ gives

    |g(l) − g(m) − g′(m)(l − m)| ≤ M₂ h² / 2,

so the piece holds no root when |g(m)| > |g′(m)| h + M₂ h²/2, and g is strictly monotone on
it (one root at most, bracketed by the signs at its ends) when |g′(m)| > M₂ h. Other
pieces are halved. M₂ = max|x″| + max|W″|·max|y′|² + max|W′|·max|y″|, with the sine-lines'
bounds and each wall's bounds on |W′| and |W″| over the stock's y window (exact for
quintics, from their critical points; for B-spline walls from the span polynomials, see
:func:`spline_bounds`). Before that, a piece is dropped when the x range the helix can
reach over it misses the wall's x band over the y range it can reach (engine bands).

A piece still undecided at MIN_WIDTH holds g ≈ 0 with g′ ≈ 0 (a tangency): a sign change
across it still gives a root; without one, any pair of roots inside lies within
MIN_WIDTH of each other and the piece between them is below LENGTH_EPS.
"""

import numpy as np

from .helix_roots import safeguarded_root
from .polynomials import compose_linear, derivative, horner, product, real_roots_unit
from .walls import SplineTable, SplineWall

#: Pieces narrower than this (mm) are no longer split (see the module docstring).
MIN_WIDTH = 1e-10
#: Rounding allowance (mm) on the no-root test: |g(m)| must beat the bound by this much.
EVAL_MARGIN = 1e-12


def _max_abs_unit(coefficients):
    """max |p| over [0, 1] of each polynomial (S, d+1) ascending -> (S,), exact: ends and critical points."""
    c = np.atleast_2d(np.asarray(coefficients, dtype=float))
    u = np.column_stack([np.zeros(c.shape[0]), np.ones(c.shape[0])])
    if c.shape[1] > 2:
        u = np.concatenate([u, real_roots_unit(derivative(c))], axis=1)
    return np.nanmax(np.abs(horner(c[:, None, :], u)), axis=1)


def _min_abs_unit(coefficients):
    """min |p| over [0, 1] of each polynomial (S, d+1) ascending -> (S,): 0 where it has a root there."""
    c = np.atleast_2d(np.asarray(coefficients, dtype=float))
    low = np.abs(c.sum(axis=1))  # at u = 1; the rest below
    if c.shape[1] > 1:
        u = np.column_stack([np.zeros(c.shape[0]), np.ones(c.shape[0])])
        if c.shape[1] > 2:
            u = np.concatenate([u, real_roots_unit(derivative(c))], axis=1)
        low = np.nanmin(np.abs(horner(c[:, None, :], u)), axis=1)
        low = np.where((~np.isnan(real_roots_unit(c))).any(axis=1), 0.0, low)
    return low


def _minus(p, q):
    """Row-wise differences of polynomials (S, a) and (S, b), ascending."""
    width = max(p.shape[1], q.shape[1])
    return np.pad(p, ((0, 0), (0, width - p.shape[1]))) - np.pad(q, ((0, 0), (0, width - q.shape[1])))


def _slope_rows(c):
    """Derivatives (S, max(d, 1)) of polynomials (S, d+1), ascending (a constant gives 0)."""
    return derivative(c) if c.shape[1] > 1 else np.zeros((c.shape[0], 1))


def quintic_bounds(wall, y_min, y_max):
    """(max |W′|, max |W″|) of a quintic wall over [y_min, y_max] (mm), exact."""
    t_lo, t_hi = (y_min - wall.y_mid) / wall.y_half, (y_max - wall.y_mid) / wall.y_half
    first = derivative(np.asarray(wall.coefficients, dtype=float))
    second = derivative(first)
    scale = t_hi - t_lo
    # p(t) over [t_lo, t_hi] is p(t_lo + scale·u) over u in [0, 1].
    on_unit = [compose_linear(c, np.float64(t_lo), np.float64(scale)) for c in (first, second)]
    return float(_max_abs_unit(on_unit[0])[0]) / wall.y_half, float(_max_abs_unit(on_unit[1])[0]) / wall.y_half ** 2


def spline_bounds(wall):
    """(max |W′|, max |W″|) of a B-spline wall x = W(y) over the whole curve.

    Per span, with x = X/Ω, y = Y/Ω in the local u: dx/du = A/Ω², dy/du = B/Ω² where
    A = X′Ω − XΩ′, B = Y′Ω − YΩ′, so W′ = A/B and W″ = (A′B − AB′)Ω²/B³: bounded by the
    exact max and min of |polynomials| over [0, 1], all spans at once. ValueError if dy/du
    vanishes on a span (the curve has a vertical tangent in y and W″ is unbounded).
    """
    x, y, w = wall.spans_x, wall.spans_y, wall.spans_w
    a = _minus(product(_slope_rows(x), w), product(x, _slope_rows(w)))
    b = _minus(product(_slope_rows(y), w), product(y, _slope_rows(w)))
    low = _min_abs_unit(b)
    if (low <= 0.0).any():
        j = int(np.flatnonzero(low <= 0.0)[0])
        raise ValueError(f"B-spline wall: dy/du vanishes on span {j}; a helical edge needs a wall with bounded curvature")
    curl = product(_minus(product(_slope_rows(a), b), product(a, _slope_rows(b))), product(w, w))
    return float((_max_abs_unit(a) / low).max()), float((_max_abs_unit(curl) / low ** 3).max())


def _spline_x_and_slope(wall, y):
    """W(y) and W′(y) of a B-spline wall at y (any shape)."""
    table = SplineTable((wall,))
    span, u = table.span_parameter(np.zeros(np.shape(y), dtype=np.intp), y)
    x, yy, w = (horner(c[span], u) for c in (table.spans_x, table.spans_y, table.spans_w))
    dx, dy, dw = (horner(derivative(c)[span], u) for c in (table.spans_x, table.spans_y, table.spans_w))
    return x / w, (dx * w - x * dw) / (dy * w - yy * dw)


class WallModels:
    """Value, slope and derivative bounds of every wall of a staircase, for the subdivision."""

    def __init__(self, stock):
        self.stock = stock
        self.walls = stock.walls
        bounds = [spline_bounds(w) if isinstance(w, SplineWall) else quintic_bounds(w, stock.y_min, stock.y_max)
                  for w in self.walls]
        self.s1 = np.array([b[0] for b in bounds]).reshape(-1)
        self.s2 = np.array([b[1] for b in bounds]).reshape(-1)

    def x_and_slope(self, walls, y):
        """W_j(y) and W_j′(y) (P,) for wall indices walls (P,) (0-based) at y (P,)."""
        x, slope = np.empty(y.shape), np.empty(y.shape)
        for j in np.unique(walls):
            on = walls == j
            wall = self.walls[j]
            if isinstance(wall, SplineWall):
                x[on], slope[on] = _spline_x_and_slope(wall, y[on])
            else:
                x[on], slope[on] = wall.x_at(y[on]), wall.slope_at(y[on])
        return x, slope


def wall_crossings(models, xs, ys, rows, walls, lo, hi):
    """Roots of x(l) − W_j(y(l)) on [lo, hi] for each (helix rows[i], wall walls[i]) (P,).

    xs, ys: SineLines of the helices' x and y (N helices); the y of
    every point of [lo, hi] must lie in the stock's y window (the caller passes pieces inside
    the stock's box). Returns (rows, walls, l) of every root found (R,), mm.
    """
    x1, x2 = xs.bounds()
    y1, y2 = ys.bounds()
    stock = models.stock
    brackets = ([], [], [], [])
    a, b = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
    rows, walls = np.asarray(rows), np.asarray(walls)
    while rows.size:
        h, m = 0.5 * (b - a), 0.5 * (a + b)
        xm = xs.value(rows, m)
        ym = ys.value(rows, m)
        reach_y = y1[rows] * h
        low, high, _ = stock.bands.query(np.clip(ym - reach_y, stock.y_min, stock.y_max),
                                         np.clip(ym + reach_y, stock.y_min, stock.y_max), walls)
        reach_x = x1[rows] * h
        near = (xm + reach_x >= low) & (xm - reach_x <= high)
        rows, walls, a, b, h, m, xm, ym = (v[near] for v in (rows, walls, a, b, h, m, xm, ym))
        wx, wslope = models.x_and_slope(walls, ym)
        g = xm - wx
        slope = xs.slope(rows, m) - wslope * ys.slope(rows, m)
        m2 = x2[rows] + models.s2[walls] * y1[rows] ** 2 + models.s1[walls] * y2[rows]
        free = np.abs(g) > np.abs(slope) * h + 0.5 * m2 * h * h + EVAL_MARGIN
        flat = np.abs(g) + np.abs(slope) * h + 0.5 * m2 * h * h <= EVAL_MARGIN  # the edge runs in the wall
        settled = ~free & ~flat & ((np.abs(slope) > m2 * h) | (2.0 * h <= MIN_WIDTH))
        for store, values in zip(brackets, (rows, walls, a, b)):
            store.append(values[settled])
        split = ~free & ~flat & ~settled
        rows, walls = np.repeat(rows[split], 2), np.repeat(walls[split], 2)
        a, m, b = a[split], m[split], b[split]
        a, b = np.column_stack([a, m]).reshape(-1), np.column_stack([m, b]).reshape(-1)
    rows, walls, a, b = (np.concatenate(v) if v else np.empty(0) for v in brackets)
    rows, walls = rows.astype(np.intp), walls.astype(np.intp)
    if rows.size == 0:
        return rows, walls, a

    def g_and_slope(sub, l):
        r, j = rows[sub], walls[sub]
        wx, wslope = models.x_and_slope(j, ys.value(r, l))
        return xs.value(r, l) - wx, xs.slope(r, l) - wslope * ys.slope(r, l)

    everyone = np.arange(rows.size)
    g_a, _ = g_and_slope(everyone, a)
    g_b, _ = g_and_slope(everyone, b)
    # A root on a piece's end may be found from both neighbours: a repeated breakpoint is harmless.
    sign_change = (np.sign(g_a) * np.sign(g_b) < 0.0) | (g_a == 0.0) | (g_b == 0.0)
    keep = np.flatnonzero(sign_change)
    if keep.size == 0:
        return rows[:0], walls[:0], a[:0]
    l = safeguarded_root(lambda sub, x: g_and_slope(keep[sub], x), a[keep], b[keep], g_a[keep], g_b[keep])
    return rows[keep], walls[keep], l
