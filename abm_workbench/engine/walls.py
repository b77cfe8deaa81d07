"""Wall curves: the paper's quintic x = P(y) through six points on a wall's top edge (notes §3),
and the exact B-spline top edge of a wall read from a solid.

The polynomial is kept in the centred, scaled variable t = (y − y_mid) / y_half, where
y_mid and y_half are the middle and half-span of the six points' y values: in raw y the 6×6
Vandermonde system of Eq. (6) is hopelessly ill-conditioned. Lengths in mm.
"""

from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from .polynomials import (bracketed_root, compose_linear, horner, monotone_root_unit, proved_monotone_unit,
                          real_roots_unit)
from .rows import row_sum

#: Six x values within this (mm) of each other make a straight wall.
STRAIGHT_EPS = 1e-12


def _real_roots_between(ascending, lo, hi):
    """Real roots of a small polynomial (ascending coefficients) inside [lo, hi]."""
    trimmed = np.trim_zeros(np.asarray(ascending, dtype=float), "b")
    if trimmed.size <= 1:
        return np.empty(0)
    roots = np.roots(trimmed[::-1])
    real = roots[np.abs(roots.imag) <= 1e-9 * (1.0 + np.abs(roots.real))].real
    return real[(real >= lo) & (real <= hi)]


def _extremes_per_bin(ascending, t):
    """min and max (B,) of a polynomial over each bin [t[b], t[b+1]] of increasing t (B+1,)."""
    at_edges = horner(ascending, t)
    low = np.minimum(at_edges[:-1], at_edges[1:])
    high = np.maximum(at_edges[:-1], at_edges[1:])
    critical = _real_roots_between(_derivative(ascending), t[0], t[-1])
    where = np.clip(np.searchsorted(t, critical, side="right") - 1, 0, t.size - 2)
    values = horner(ascending, critical)
    np.minimum.at(low, where, values)
    np.maximum.at(high, where, values)
    return low, high


def _derivative(ascending):
    """Ascending coefficients of the derivative."""
    return ascending[1:] * np.arange(1, ascending.size)


@dataclass(frozen=True)
class Wall:
    """One wall x = P(y) = Σ c_k t^k with t = (y − y_mid) / y_half.

    points: (6, 2) float, the [x, y] points it interpolates (mm).
    coefficients: (6,) float, c_0..c_5 in t (mm).
    """

    points: np.ndarray
    y_mid: float
    y_half: float
    coefficients: np.ndarray

    @classmethod
    def from_points(cls, points):
        """Interpolate six [x, y] points (6, 2); ValueError for a wrong shape or repeated y."""
        points = np.array(points, dtype=float)
        if points.shape != (6, 2):
            raise ValueError(f"a wall needs six [x, y] points, shape (6, 2); got {points.shape}")
        if not np.isfinite(points).all():
            raise ValueError("wall points must be finite numbers")
        x, y = points[:, 0], points[:, 1]
        y_lo, y_hi = y.min(), y.max()
        y_mid, y_half = 0.5 * (y_lo + y_hi), 0.5 * (y_hi - y_lo)
        gaps = np.diff(np.sort(y))
        if y_half <= 0.0 or gaps.min() <= 1e-9 * y_half:
            raise ValueError(f"wall points need six distinct y values, got {y.tolist()}")
        if np.ptp(x) <= STRAIGHT_EPS:
            coefficients = np.array([x.mean(), 0.0, 0.0, 0.0, 0.0, 0.0])
        else:
            t = (y - y_mid) / y_half
            coefficients = np.linalg.solve(np.vander(t, 6, increasing=True), x)
        points.setflags(write=False)
        coefficients.setflags(write=False)
        return cls(points, float(y_mid), float(y_half), coefficients)

    @property
    def is_straight(self):
        """True when the six points share one x: the wall is the plane x = c_0."""
        return not self.coefficients[1:].any()

    def x_at(self, y):
        """x = P(y) for y of any shape (mm)."""
        return horner(self.coefficients, (np.asarray(y, dtype=float) - self.y_mid) / self.y_half)

    def slope_at(self, y):
        """dP/dy for y of any shape."""
        t = (np.asarray(y, dtype=float) - self.y_mid) / self.y_half
        return horner(_derivative(self.coefficients), t) / self.y_half

    def x_range(self, y_lo, y_hi):
        """(min, max) of P over y in [y_lo, y_hi], from its critical points."""
        t_lo, t_hi = (y_lo - self.y_mid) / self.y_half, (y_hi - self.y_mid) / self.y_half
        t = np.concatenate([[t_lo, t_hi], _real_roots_between(_derivative(self.coefficients), t_lo, t_hi)])
        x = horner(self.coefficients, t)
        return float(x.min()), float(x.max())

    def translated(self, dx, dy):
        """The same wall moved by (dx, dy) mm."""
        return Wall.from_points(self.points + np.array([dx, dy]))

    def bins(self, edges):
        """Per bin [edges[b], edges[b+1]] of y (B+1,): min x, max x and max |dP/dy|, each (B,), exact."""
        t = (np.asarray(edges, dtype=float) - self.y_mid) / self.y_half
        first = _derivative(self.coefficients)
        low, high = _extremes_per_bin(self.coefficients, t)
        slope_low, slope_high = _extremes_per_bin(first, t)
        return low, high, np.maximum(np.abs(slope_low), np.abs(slope_high)) / self.y_half


@dataclass(frozen=True)
class SplineWall:
    """A wall's exact top-edge curve C(s) = (x(s), y(s)), a (rational) B-spline, as in the solid.

    degree: p; knots: (k+p+1,) float; poles: (k, 2) [x, y] (mm); weights: (k,) or None.
    The curve must be monotone in y (one x per y over the window: recognition checks it).
    Each knot span is kept as power-basis polynomials in a local u ∈ [0, 1]:
    spans_x, spans_y, spans_w: (S, p+1) ascending, so that x = X(u)/W(u), y = Y(u)/W(u).
    span_y: (S+1,) y at the span ends, increasing; span_boxes: (S, 4) x_min, x_max, y_min,
    y_max of each span's control polygon (the span lies inside it).
    """

    degree: int
    knots: np.ndarray
    poles: np.ndarray
    weights: Optional[np.ndarray]
    spans_x: np.ndarray = field(init=False, repr=False)
    spans_y: np.ndarray = field(init=False, repr=False)
    spans_w: np.ndarray = field(init=False, repr=False)
    span_y: np.ndarray = field(init=False, repr=False)
    span_boxes: np.ndarray = field(init=False, repr=False)

    def __post_init__(self):
        poles = np.array(self.poles, dtype=float)
        knots = np.array(self.knots, dtype=float)
        p = int(self.degree)
        if poles.ndim != 2 or poles.shape[1] != 2 or poles.shape[0] < p + 1 or knots.size != poles.shape[0] + p + 1:
            raise ValueError(f"B-spline wall: {poles.shape[0]} poles of degree {p} need {poles.shape[0] + p + 1} knots")
        weights = np.ones(poles.shape[0]) if self.weights is None else np.array(self.weights, dtype=float)
        if weights.shape != (poles.shape[0],) or not (weights > 0).all():
            raise ValueError("B-spline wall: weights must be positive, one per pole")
        pieces = [_power_spans(knots, weights * poles[:, i], p) for i in range(2)] + [_power_spans(knots, weights, p)]
        (sx, first), (sy, _), (sw, _) = pieces
        boxes = np.array([[poles[i:i + p + 1, 0].min(), poles[i:i + p + 1, 0].max(),
                           poles[i:i + p + 1, 1].min(), poles[i:i + p + 1, 1].max()] for i in first])
        ends_y = np.concatenate([sy[:, 0] / sw[:, 0], [sy[-1].sum() / sw[-1].sum()]])
        if ends_y[-1] < ends_y[0]:  # keep spans in increasing y
            sx, sy, sw = (_reverse(c) for c in (sx, sy, sw))
            boxes, ends_y = boxes[::-1], ends_y[::-1]
        if not (np.diff(ends_y) > 0).all():
            raise ValueError("B-spline wall: y must be strictly monotone along the curve")
        for name, value in (("degree", p), ("knots", knots), ("poles", poles), ("weights", weights),
                            ("spans_x", sx), ("spans_y", sy), ("spans_w", sw), ("span_y", ends_y), ("span_boxes", boxes)):
            if isinstance(value, np.ndarray):
                value.setflags(write=False)
            object.__setattr__(self, name, value)

    @property
    def is_straight(self):
        """True when every pole has the same x: the wall is the plane x = const."""
        return bool(np.ptp(self.poles[:, 0]) <= STRAIGHT_EPS)

    def translated(self, dx, dy):
        """The same wall moved by (dx, dy) mm."""
        return SplineWall(self.degree, self.knots, self.poles + np.array([dx, dy]), self.weights)

    def x_at(self, y):
        """x = W(y) for y of any shape (mm); beyond the curve's ends, the end's x."""
        y = np.asarray(y, dtype=float)
        return SplineTable((self,)).x_at(np.zeros(y.shape, dtype=np.intp), y)

    def x_range(self, y_lo, y_hi):
        """(min, max) bound of x over y in [y_lo, y_hi], from the control polygons (conservative)."""
        boxes = self.span_boxes[(self.span_boxes[:, 3] >= y_lo) & (self.span_boxes[:, 2] <= y_hi)]
        ends = self.x_at(np.array([y_lo, y_hi]))
        low = min(ends.min(), boxes[:, 0].min()) if boxes.size else ends.min()
        high = max(ends.max(), boxes[:, 1].max()) if boxes.size else ends.max()
        return float(low), float(high)

    def bins(self, edges):
        """Per bin [edges[b], edges[b+1]] of y (B+1,): bounds of x (B,), (B,) and slope bound (inf).

        The bounds are those of x_range, for all bins at once.
        """
        edges = np.asarray(edges, dtype=float)
        at_edges = self.x_at(edges)
        low = np.minimum(at_edges[:-1], at_edges[1:])
        high = np.maximum(at_edges[:-1], at_edges[1:])
        boxes = self.span_boxes
        meets = (boxes[:, 3, None] >= edges[None, :-1]) & (boxes[:, 2, None] <= edges[None, 1:])  # (S, B)
        low = np.minimum(low, np.where(meets, boxes[:, 0, None], np.inf).min(axis=0))
        high = np.maximum(high, np.where(meets, boxes[:, 1, None], -np.inf).max(axis=0))
        return low, high, np.full(low.size, np.inf)


class SplineTable:
    """The SplineWall walls of a stock stacked span by span, so that crossings with lines and
    x = W(y) are found for many (line, wall) pairs in one set of array operations.

    walls: the stock's walls (index j); only the SplineWall ones are stacked, and only their
    indices may be asked for. Spans of all walls share the highest degree (zero-padded).
    """

    def __init__(self, walls):
        index = [j for j, w in enumerate(walls) if isinstance(w, SplineWall)]
        splines = [walls[j] for j in index]
        degree = max((w.degree for w in splines), default=0)

        def stacked(name, columns):
            parts = [np.pad(getattr(w, name), ((0, 0), (0, columns - getattr(w, name).shape[1]))) for w in splines]
            return np.concatenate(parts) if parts else np.empty((0, columns))

        self.spans_x, self.spans_y, self.spans_w = (stacked(name, degree + 1) for name in ("spans_x", "spans_y", "spans_w"))
        self.span_boxes = stacked("span_boxes", 4)
        # y at the start and the end of every span, (S,) each.
        self.span_y0 = np.concatenate([w.span_y[:-1] for w in splines]) if splines else np.empty(0)
        self.span_y1 = np.concatenate([w.span_y[1:] for w in splines]) if splines else np.empty(0)
        spans = np.array([w.spans_x.shape[0] for w in splines], dtype=np.intp)
        self.n_spans, self.first_span, self.first_end, self.slot = (np.zeros(len(walls), dtype=np.intp) for _ in range(4))
        self.n_spans[index] = spans
        self.first_span[index] = np.cumsum(spans) - spans
        self.first_end[index] = np.cumsum(spans + 1) - (spans + 1)
        self.slot[index] = np.arange(len(index))
        self.y_first, self.y_last = np.zeros(len(walls)), np.zeros(len(walls))
        self.y_first[index] = [w.span_y[0] for w in splines]
        self.y_last[index] = [w.span_y[-1] for w in splines]
        # Span ends of wall slot k, shifted by k·shift past every other wall's: one sorted array.
        ends = [w.span_y for w in splines]
        self.base = min((e[0] for e in ends), default=0.0)
        self.shift = max((e[-1] for e in ends), default=0.0) - self.base + 1.0
        self.keys = np.concatenate([e - self.base + k * self.shift for k, e in enumerate(ends)]) if ends else np.empty(0)

    def _local_span(self, walls, y, side):
        """Index within wall walls[i] of the span whose start is the last one below (side
        "left") or at or below ("right") y[i], y clipped to the wall's ends; may be −1 or n."""
        y = np.clip(y, self.y_first[walls], self.y_last[walls])
        key = y - self.base + self.slot[walls] * self.shift
        return np.searchsorted(self.keys, key, side=side) - 1 - self.first_end[walls]

    def span_parameter(self, walls, y):
        """Span (index into the stacked spans) and local u ∈ [0, 1] where wall walls[i] has
        height y[i] (same shapes; y clipped to the curve's ends; u NaN where y is NaN)."""
        walls, y = np.broadcast_arrays(np.asarray(walls, dtype=np.intp), np.asarray(y, dtype=float))
        flat_w, flat_y = walls.reshape(-1), y.reshape(-1)
        span = self.first_span[flat_w].copy()
        u = np.full(flat_y.size, np.nan)
        known = np.flatnonzero(~np.isnan(flat_y))
        w, yk = flat_w[known], np.clip(flat_y[known], self.y_first[flat_w[known]], self.y_last[flat_w[known]])
        span[known] += np.clip(self._local_span(w, yk, "right"), 0, self.n_spans[w] - 1)
        c = self.spans_y[span[known]] - yk[:, None] * self.spans_w[span[known]]
        u[known] = bracketed_root(np.ascontiguousarray(c.T), np.zeros(known.size), np.ones(known.size), c[:, 0],
                                  row_sum(c))
        return span.reshape(y.shape), u.reshape(y.shape)

    def x_at(self, walls, y):
        """x = W_j(y) (mm) of wall walls[i] at y[i] (same shapes); beyond a curve's ends, the
        end's x; NaN where y is NaN."""
        span, u = self.span_parameter(walls, y)
        return horner(self.spans_x[span], u) / horner(self.spans_w[span], u)

    def crossings(self, walls, x0, y0, dx, dy, lo, hi):
        """Edge parameters l (k, r) in [lo, hi] where line i, (x0 + l·dx, y0 + l·dy), meets wall
        walls[i]; all (k,). NaN-padded; a line with dx = dy = 0 never crosses.

        Per span, (X(u) − x0·W(u))·dy − (Y(u) − y0·W(u))·dx = 0 is a polynomial in u; its real
        roots in [0, 1] give the points, and l their projection on the line. Only spans whose y
        range meets the segment's (a run, as y is monotone along the curve) and whose control
        box meets the segment's x range over that y range are solved; one bracketed root where
        the polynomial is proved monotone.
        """
        k = np.size(x0)
        sy = np.stack([y0 + dy * lo, y0 + dy * hi])
        y_lo, y_hi = sy.min(0), sy.max(0)
        first = np.maximum(self._local_span(walls, y_lo, "left"), 0)
        last = np.minimum(self._local_span(walls, y_hi, "right"), self.n_spans[walls] - 1)
        meets = (y_hi >= self.y_first[walls]) & (y_lo <= self.y_last[walls])
        count = np.where(meets, last - first + 1, 0).clip(0)
        line = np.repeat(np.arange(k), count)
        span = self.first_span[walls[line]] + first[line] + np.arange(line.size) - np.repeat(np.cumsum(count) - count, count)
        with np.errstate(divide="ignore", invalid="ignore"):
            at = (np.stack([self.span_y0[span], self.span_y1[span]]) - y0[line]) / dy[line]
        level = np.abs(dy[line]) <= STRAIGHT_EPS  # a segment along x: its whole x range
        l1 = np.where(level, lo[line], np.clip(at.min(axis=0), lo[line], hi[line]))
        l2 = np.where(level, hi[line], np.clip(at.max(axis=0), lo[line], hi[line]))
        xa, xb = x0[line] + dx[line] * l1, x0[line] + dx[line] * l2
        b = self.span_boxes[span]
        meet = (np.maximum(xa, xb) >= b[:, 0]) & (np.minimum(xa, xb) <= b[:, 1])
        line, span = line[meet], span[meet]
        if line.size == 0:
            return np.full((k, 0), np.nan)
        poly = ((self.spans_x[span] - x0[line, None] * self.spans_w[span]) * dy[line, None]
                - (self.spans_y[span] - y0[line, None] * self.spans_w[span]) * dx[line, None])
        u = np.full((line.size, poly.shape[1] - 1), np.nan)
        single = proved_monotone_unit(poly)
        u[single, 0] = monotone_root_unit(np.ascontiguousarray(poly[single].T))
        u[~single] = real_roots_unit(poly[~single])
        w = horner(self.spans_w[span][:, None, :], u)
        px = horner(self.spans_x[span][:, None, :], u) / w
        py = horner(self.spans_y[span][:, None, :], u) / w
        d2 = dx[line] ** 2 + dy[line] ** 2
        with np.errstate(divide="ignore", invalid="ignore"):
            l = ((px - x0[line, None]) * dx[line, None] + (py - y0[line, None]) * dy[line, None]) / d2[:, None]
        l = np.where((l >= lo[line, None]) & (l <= hi[line, None]) & (d2[:, None] > 0), l, np.nan)
        rank = np.arange(line.size) - np.searchsorted(line, line)
        out = np.full((k, int(rank.max()) + 1, u.shape[1]), np.nan)
        out[line, rank] = l
        out = out.reshape(k, -1)
        return out[:, ~np.isnan(out).all(axis=0)]


def _power_spans(knots, coefficients, degree):
    """Power-basis coefficients (S, p+1) in local u ∈ [0, 1] of each non-empty knot span, and
    the index of each span's first pole."""
    from scipy.interpolate import BSpline, PPoly  # here: scipy.interpolate takes a while to import

    spline = BSpline(knots, coefficients, degree, extrapolate=False)
    pp = PPoly.from_spline(spline)
    widths = np.diff(pp.x)
    keep = np.flatnonzero(widths > 0)
    keep = keep[(pp.x[keep] >= knots[degree]) & (pp.x[keep + 1] <= knots[-degree - 1])]
    local = pp.c[::-1, keep].T  # ascending in (s − s_i)
    scaled = local * widths[keep, None] ** np.arange(degree + 1)
    first = np.searchsorted(knots, pp.x[keep], side="right") - 1 - degree
    return scaled, first


def _reverse(coefficients):
    """Coefficients of each span in u' = 1 − u, spans in reverse order."""
    d = coefficients.shape[1] - 1
    return compose_linear(coefficients[::-1], np.ones(coefficients.shape[0]), -np.ones(coefficients.shape[0]))[:, : d + 1]
