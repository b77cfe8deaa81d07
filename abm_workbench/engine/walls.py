"""Wall curves: the paper's quintic x = P(y) through six points on a wall's top edge (notes §3),
and the exact B-spline top edge of a wall read from a solid.

The polynomial is kept in the centred, scaled variable t = (y − y_mid) / y_half, where
y_mid and y_half are the middle and half-span of the six points' y values: in raw y the 6×6
Vandermonde system of Eq. (6) is hopelessly ill-conditioned. Lengths in mm.
"""

from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from .bands import sparse_table
from .bucket_search import BucketSearch
from .polynomials import (bernstein_unit, bracketed_root, compose_linear, derivative, horner, monotone_root_unit,
                          product, proved_monotone_unit, real_roots_unit)
from .rows import row_sum

#: Six x values within this (mm) of each other make a straight wall.
STRAIGHT_EPS = 1e-12
#: Relative width by which a span's bounds on dx/dy are widened against rounding.
SLOPE_MARGIN = 1e-9


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
    y_max of each span's control polygon (the span lies inside it); span_slopes: (S, 2) least
    and greatest dx/dy over each span (−inf, inf where dy/du is not proved positive); straight:
    every pole has the same x; table: the SplineTable of this wall alone (for x_at).
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
    span_slopes: np.ndarray = field(init=False, repr=False)
    straight: bool = field(init=False, repr=False)
    table: "SplineTable" = field(init=False, repr=False, compare=False)

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
        slopes = _slope_bounds(sx, sy, sw)
        object.__setattr__(self, "straight", bool(np.ptp(poles[:, 0]) <= STRAIGHT_EPS))
        for name, value in (("degree", p), ("knots", knots), ("poles", poles), ("weights", weights),
                            ("spans_x", sx), ("spans_y", sy), ("spans_w", sw), ("span_y", ends_y),
                            ("span_boxes", boxes), ("span_slopes", slopes)):
            if isinstance(value, np.ndarray):
                value.setflags(write=False)
            object.__setattr__(self, name, value)
        object.__setattr__(self, "table", SplineTable((self,)))

    @property
    def is_straight(self):
        """True when every pole has the same x: the wall is the plane x = const."""
        return self.straight

    def translated(self, dx, dy):
        """The same wall moved by (dx, dy) mm."""
        return SplineWall(self.degree, self.knots, self.poles + np.array([dx, dy]), self.weights)

    def x_at(self, y):
        """x = W(y) for y of any shape (mm); beyond the curve's ends, the end's x."""
        y = np.asarray(y, dtype=float)
        return self.table.x_at(np.zeros(y.shape, dtype=np.intp), y)

    def x_range(self, y_lo, y_hi):
        """(min, max) bound of x over y in [y_lo, y_hi], from the control polygons (conservative)."""
        boxes = self.span_boxes[(self.span_boxes[:, 3] >= y_lo) & (self.span_boxes[:, 2] <= y_hi)]
        ends = self.x_at(np.array([y_lo, y_hi]))
        low = min(ends.min(), boxes[:, 0].min()) if boxes.size else ends.min()
        high = max(ends.max(), boxes[:, 1].max()) if boxes.size else ends.max()
        return float(low), float(high)

    def bins(self, edges):
        """Per bin [edges[b], edges[b+1]] of y (B+1,): min x, max x and a bound on |dx/dy|, each (B,).

        The x range is exact: x at the bin's ends and at the curve's turning points in x inside
        it (roots of dx/du per span). The slope bound is the largest |dx/dy| bound (span_slopes)
        of the spans meeting the bin (inf where one is unbounded).
        """
        edges = np.asarray(edges, dtype=float)
        at_edges = self.x_at(edges)
        low = np.minimum(at_edges[:-1], at_edges[1:])
        high = np.maximum(at_edges[:-1], at_edges[1:])
        turning = product(derivative(self.spans_x), self.spans_w) - product(self.spans_x, derivative(self.spans_w))
        roots = real_roots_unit(turning)
        span, k = np.nonzero(~np.isnan(roots))
        u = roots[span, k]
        w = horner(self.spans_w[span], u)
        x, y = horner(self.spans_x[span], u) / w, horner(self.spans_y[span], u) / w
        where = np.searchsorted(edges, y, side="right") - 1
        inside = (where >= 0) & (where < low.size)
        np.minimum.at(low, where[inside], x[inside])
        np.maximum.at(high, where[inside], x[inside])
        steep = np.abs(self.span_slopes).max(axis=1)
        meets = (self.span_y[1:, None] >= edges[None, :-1]) & (self.span_y[:-1, None] <= edges[None, 1:])  # (S, B)
        return low, high, np.where(meets, steep[:, None], 0.0).max(axis=0)


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
        self.knot_y = np.concatenate(ends) if ends else np.empty(0)
        self.key_search = BucketSearch(self.keys)  # np.searchsorted into keys, without bisection
        # The curve's homogeneous point (X, Y, Ω) at every span end, in the order of keys: (3, E);
        # the spans' coefficients as columns: (3, p+1, S); Ω ≡ 1 unless some wall is rational.
        self.knot_points = np.array([np.concatenate([np.append(getattr(w, name)[:, 0], getattr(w, name)[-1].sum())
                                                     for w in splines]) if splines else np.empty(0)
                                     for name in ("spans_x", "spans_y", "spans_w")])
        self.span_columns = np.ascontiguousarray(np.stack([self.spans_x.T, self.spans_y.T, self.spans_w.T]))
        self.rational = bool((self.spans_w[:, 1:] != 0.0).any() or (self.spans_w[:, 0] != 1.0).any())
        # Sparse tables of the spans' slope bounds: entry [k, s] covers spans s .. s + 2^k − 1.
        slopes = stacked("span_slopes", 2)
        self.slope_low = sparse_table(slopes[None, :, 0], np.minimum)[:, 0]
        self.slope_high = sparse_table(slopes[None, :, 1], np.maximum)[:, 0]
        # Least and greatest dx/dy of each wall over all its spans, (2, walls).
        self.wall_slopes = np.array([[-np.inf, np.inf]] * len(walls)).reshape(-1, 2).T.copy()
        self.wall_slopes[:, index] = [[w.span_slopes[:, 0].min() for w in splines],
                                      [w.span_slopes[:, 1].max() for w in splines]]

    def _local_span(self, walls, y, side):
        """Index within wall walls[i] of the span whose start is the last one below (side
        "left") or at or below ("right") y[i], y clipped to the wall's ends; may be −1 or n."""
        y = np.clip(y, self.y_first[walls], self.y_last[walls])
        key = y - self.base + self.slot[walls] * self.shift
        return self.key_search.search(key, side) - 1 - self.first_end[walls]

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

    def crossings(self, walls, x0, y0, dx, dy, lo, hi, sides=False):
        """Edge parameters l (k, r) in [lo, hi] where line i, (x0 + l·dx, y0 + l·dy), meets wall
        walls[i]; all (k,). NaN-padded; a line with dx = dy = 0 never crosses. With `sides`,
        also whether each line is at or beyond its wall (x ≥ W(y)) at lo and at hi, (k,) bool each.

        Only the spans whose y range meets the segment's are looked at (a run, as y is monotone
        along the curve). Where the line's direction lies outside every tangent direction of
        those spans (span_slopes: the wall's bound first, then the run's), the line crosses them
        at most once: the span is found from the knots' sides of the line (regula falsi, then
        bisection) and its one root by bracketed Newton (_monotone_crossings), and the sides follow
        from the crossing. The other pairs go through _spans_crossings and x_at.
        """
        walls = np.asarray(walls, dtype=np.intp)
        k = walls.size
        y_a, y_b = y0 + dy * lo, y0 + dy * hi
        y_lo, y_hi = np.minimum(y_a, y_b), np.maximum(y_a, y_b)
        y_first, y_last, first_end = self.y_first[walls], self.y_last[walls], self.first_end[walls]
        key = self.slot[walls] * self.shift - self.base  # + y: the key of y on wall walls[i]
        first = self.key_search.search(np.minimum(np.maximum(y_lo, y_first), y_last) + key, "left") - 1
        last = self.key_search.search(np.minimum(np.maximum(y_hi, y_first), y_last) + key, "right") - 1
        first = np.maximum(first - first_end, 0)
        last = np.minimum(last - first_end, self.n_spans[walls] - 1)
        meets = (y_hi >= y_first) & (y_lo <= y_last)
        within = (y_lo >= y_first) & (y_hi <= y_last) & (last >= first)
        # The wall's slope bound over all its spans proves most pairs; the others try their own run's.
        with np.errstate(invalid="ignore"):
            ahead, behind = dx - self.wall_slopes[1, walls] * dy, dx - self.wall_slopes[0, walls] * dy
            proved = within & (ahead * behind > 0.0)
            again = np.flatnonzero(within & ~proved)
            if again.size:
                span_first = self.first_span[walls[again]]
                low, high = self._slopes(span_first + first[again], span_first + last[again])
                ahead[again], behind[again] = dx[again] - high * dy[again], dx[again] - low * dy[again]
                proved[again] = ahead[again] * behind[again] > 0.0
        roots = np.full((k, 1), np.nan)
        at_lo, at_hi = np.zeros(k, dtype=bool), np.zeros(k, dtype=bool)
        slow = np.flatnonzero(~proved)
        if slow.size == 0:
            roots[:, 0], at_lo, at_hi = self._monotone_crossings(
                walls, x0, y0, dx, dy, lo, hi, first_end + first, first_end + last + 1, key, ahead > 0.0)
        elif slow.size < k:
            f = np.flatnonzero(proved)
            roots[f, 0], at_lo[f], at_hi[f] = self._monotone_crossings(
                walls[f], x0[f], y0[f], dx[f], dy[f], lo[f], hi[f], first_end[f] + first[f],
                first_end[f] + last[f] + 1, key[f], ahead[f] > 0.0)
        if slow.size:
            s = slow
            found = self._spans_crossings(walls[s], x0[s], y0[s], dx[s], dy[s], lo[s], hi[s], first[s], last[s],
                                          meets[s])
            if found.shape[1] > roots.shape[1]:
                roots = np.pad(roots, ((0, 0), (0, found.shape[1] - roots.shape[1])), constant_values=np.nan)
            roots[s, : found.shape[1]] = found
            if sides:
                ends = np.stack([lo[s], hi[s]], axis=1)
                at = x0[s, None] + dx[s, None] * ends >= self.x_at(walls[s, None], y0[s, None] + dy[s, None] * ends)
                at_lo[s], at_hi[s] = at[:, 0], at[:, 1]
        roots = roots[:, ~np.isnan(roots).all(axis=0)]
        return (roots, at_lo, at_hi) if sides else roots

    def _slopes(self, start, stop):
        """Least and greatest dx/dy (P,) over the stacked spans start[i] .. stop[i] (inclusive)."""
        level = np.frexp(stop - start + 1)[1] - 1  # ⌊log2 of the span count⌋
        other = stop - (1 << level) + 1
        low, high = self.slope_low.reshape(-1), self.slope_high.reshape(-1)
        row = level * self.slope_low.shape[1]
        return (np.minimum(low.take(row + start), low.take(row + other)),
                np.maximum(high.take(row + start), high.take(row + other)))

    def _knot_side(self, knot, x0, y0, dx, dy):
        """(X − x0·Ω)·dy − (Y − y0·Ω)·dx at stacked knots `knot` (P,): Ω times the cross product of
        the line's direction with the vector from (x0, y0) to the knot's point."""
        x, y, w = self.knot_points.take(knot, axis=1)
        if self.rational:
            return (x - x0 * w) * dy - (y - y0 * w) * dx
        return (x - x0) * dy - (y - y0) * dx

    def _monotone_crossings(self, walls, x0, y0, dx, dy, lo, hi, knot_lo, knot_hi, key, rising):
        """The crossing (P,) (NaN: none in [lo, hi]) and the sides at lo and hi (P,) bool of lines
        that meet the spans between stacked knots knot_lo < knot_hi of wall walls[i] at most once.

        The cross product h of the line's direction with the curve point is then strictly monotone
        along those spans: the knot pair where h changes sign (_bracketing_knots) brackets the one
        root, found in that span's polynomial by bracketed Newton. key: what added to a y gives its
        key on the wall (keys). `rising`: x − W(y) grows along the line (dx − W′·dy > 0 on the
        spans), which gives the sides from the crossing; without one, the side at the first knot
        holds all along.
        """
        h_lo = self._knot_side(knot_lo, x0, y0, dx, dy)
        h_hi = self._knot_side(knot_hi, x0, y0, dx, dy)
        cross = np.sign(h_lo) * np.sign(h_hi) <= 0.0
        r = np.flatnonzero(cross)
        every = r.size == cross.size  # the usual case: no gathering
        x0r, y0r, dxr, dyr, knot_a, knot_b, f_a, f_b, key_r, wr = (
            v if every else v[r] for v in (x0, y0, dx, dy, knot_lo, knot_hi, h_lo, h_hi, key, walls))
        a, f_lo, f_hi = self._bracketing_knots(x0r, y0r, dxr, dyr, knot_a, knot_b, f_a, f_b, key_r)
        span = a - self.first_end[wr] + self.first_span[wr]
        if self.rational:
            sx, sy, sw = self.span_columns.take(span, axis=2)
            poly = (sx - x0r * sw) * dyr - (sy - y0r * sw) * dxr
        else:
            sx, sy = self.span_columns[:2].take(span, axis=2)
            poly = sx * dyr - sy * dxr
            poly[0] -= x0r * dyr - y0r * dxr
        u = bracketed_root(poly, np.zeros(r.size), np.ones(r.size), f_lo, f_hi)
        px, py = horner(sx.T, u), horner(sy.T, u)
        if self.rational:
            w = horner(sw.T, u)
            px, py = px / w, py / w
        along = ((px - x0r) * dxr + (py - y0r) * dyr) / (dxr * dxr + dyr * dyr)
        if every:
            at = along
        else:
            at = np.full(x0.size, np.nan)
            at[r] = along
        with np.errstate(invalid="ignore"):
            root = np.where((at >= lo) & (at <= hi), at, np.nan)
            ahead = h_lo * dy < 0.0
            side_lo = np.where(cross, (lo >= at) == rising, ahead)
            side_hi = np.where(cross, (hi >= at) == rising, ahead)
        return root, side_lo, side_hi

    def _bracketing_knots(self, x0, y0, dx, dy, a, b, f_a, f_b, key):
        """The stacked knot a (P,) of line i's wall, between knots a[i] < b[i], such that the sides
        f (_knot_side) at a and a + 1 differ in sign (or one vanishes), and f at both, given f_a,
        f_b of opposite signs (or one zero) and f strictly monotone along the knots.

        First one step of regula falsi: the knot interval holding the y where f, interpolated
        linearly in y between a and b, vanishes; it brackets the root unless the curve bends much
        within [a, b]. The few others go on by bisection on the knots. key: as _monotone_crossings.
        """
        with np.errstate(divide="ignore", invalid="ignore"):
            guess = self.knot_y[a] + (self.knot_y[b] - self.knot_y[a]) * (f_a / (f_a - f_b))
        probe = self.key_search.search(guess + key, "right") - 1
        probe = np.minimum(np.maximum(probe, a), b - 1)  # a NaN guess (f_a = f_b = 0) searches to the end
        f_p = self._knot_side(probe, x0, y0, dx, dy)
        f_q = self._knot_side(probe + 1, x0, y0, dx, dy)
        sign_a = np.sign(f_a)
        past_start = (np.sign(f_p) == sign_a) & (f_p != 0.0)  # the root lies past the probe's start
        past_end = (np.sign(f_q) == sign_a) & (f_q != 0.0)  # ... and past its end
        found = past_start & ~past_end
        if found.all():
            return probe, f_p, f_q
        # Elsewhere the root lies in [a, probe] (then probe > a, or f_a = 0 and it is at a) or [probe + 1, b].
        rest = np.flatnonzero(~found)
        before = ~past_start[rest] & (probe[rest] > a[rest])
        ra = np.where(past_end[rest], probe[rest] + 1, a[rest])
        rb = np.where(past_end[rest], b[rest], np.where(before, probe[rest], probe[rest] + 1))
        fa = np.where(past_end[rest], f_q[rest], f_a[rest])
        fb = np.where(past_end[rest], f_b[rest], np.where(before, f_p[rest], f_q[rest]))
        x0, y0, dx, dy = x0[rest], y0[rest], dx[rest], dy[rest]
        while (rb - ra > 1).any():
            mid = (ra + rb) // 2
            f_mid = self._knot_side(mid, x0, y0, dx, dy)
            up = (np.sign(f_mid) == np.sign(fa)) & (f_mid != 0.0)
            ra, fa = np.where(up, mid, ra), np.where(up, f_mid, fa)
            rb, fb = np.where(up, rb, mid), np.where(up, fb, f_mid)
        probe[rest], f_p[rest], f_q[rest] = ra, fa, fb
        return probe, f_p, f_q

    def _spans_crossings(self, walls, x0, y0, dx, dy, lo, hi, first, last, meets):
        """Crossings (k, r), NaN-padded, of lines with spans first .. last of wall walls[i] (where
        `meets`): per span, (X(u) − x0·W(u))·dy − (Y(u) − y0·W(u))·dx = 0 is a polynomial in u;
        its real roots in [0, 1] give the points, and l their projection on the line. Only spans
        whose control box meets the segment's x range over their y range are solved; one bracketed
        root where the polynomial is proved monotone."""
        k = np.size(x0)
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


def _slope_bounds(sx, sy, sw):
    """Least and greatest dx/dy (S, 2) over each span of x = X/Ω, y = Y/Ω, given as power-basis
    polynomials in u ∈ [0, 1] (S, p+1) each.

    dx/du = A/Ω² and dy/du = B/Ω² with A = X′Ω − XΩ′, B = Y′Ω − YΩ′. Where B's Bernstein
    coefficients b_i on [0, 1] are all positive, dx/dy = A/B = Σ a_i β_i / Σ b_i β_i is a
    weighted mean of the ratios a_i/b_i and lies between the least and the greatest of them;
    elsewhere the bounds are (−inf, inf). Widened by SLOPE_MARGIN.
    """
    a = bernstein_unit(product(derivative(sx), sw) - product(sx, derivative(sw)))
    b = bernstein_unit(product(derivative(sy), sw) - product(sy, derivative(sw)))
    positive = (b > 1e-12 * np.abs(b).max(axis=1, keepdims=True)).all(axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = a / b
    low, high = ratio.min(axis=1), ratio.max(axis=1)
    widen = SLOPE_MARGIN * (1.0 + np.maximum(np.abs(low), np.abs(high)))
    return np.column_stack([np.where(positive, low - widen, -np.inf), np.where(positive, high + widen, np.inf)])


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
