"""The corner arcs of bull-nose and ball-end mills against the in-process stock: the parts of each arc inside
the solids swept by earlier moves.

An arc of radius r at centre C in the plane of its unit vectors d and w (engine.corner):
P(ψ) = C + r·sin ψ·d − r·cos ψ·w, ψ in [ψ_0, ψ_1] ⊂ [0, π/2], arc length r·ψ. Against one swept solid S
(a constant-axis piece of an earlier move, inprocess_swept) the arc is inside where F(ψ) = G(P(ψ)) ≤ 0,
G the convex, 1-Lipschitz gauge of S. An arc may enter and leave a convex solid more than once, so its
crossings are isolated with bounds that hold on a whole interval [a, b] of ψ (h = b − a), from F and a
subgradient v of G at both ends (docs/ENGINE.md, "Tools with a corner in the in-process stock"):

* below: F(ψ) ≥ F(a) + v_a·(P(ψ) − P(a)) (G is convex), a sinusoid in ψ whose slope at a is
  D(a) = v_a·P'(a) and whose curvature is at most r (|v| ≤ 1, |P''| = r): F is above the larger of the
  two tangent lines at a and b, less r·h²/2. Positive there: no point of [a, b] is inside.
* above: F + (r/2)·ψ² is convex (G convex, P a circle of radius r), so F ≤ max(F(a), F(b)) + r·h²/8;
  and G(y) ≤ max(|y − foot| − r_t, height − H) with the foot of an end (inprocess_swept.swept_gauge),
  whose largest value over [a, b] is closed form (sinusoids): tight where the arc lies on the earlier
  tool's own corner (the same tool again, or its sweep), where it is zero up to rounding: taken as
  inside when it and F at both ends are within COINCIDENT ulps of the coordinates and [a, b] is at least
  COINCIDENT_WIDTH mm of arc (a tangential touch is within rounding over far less). At most zero: all
  of [a, b] is inside. The foot bound is at least F at both ends, so it is only computed where F at both
  ends is within that rounding of inside.
* one crossing: F + (r/2)·ψ² convex makes F'(x) ≤ D(b) + r·(b − x) and F'(x) ≥ D(a) − r·(x − a);
  so with F(a) > 0 ≥ F(b) and D(b) + r·h < 0 (or F(a) ≤ 0 < F(b) and D(a) − r·h > 0) F is monotone
  on [a, b] and crosses zero once: that root is refined by the Illinois method
  (inprocess_swept.monotone_root) to REFINE_TOL mm of arc.
* otherwise [a, b] is halved, down to REFINE_TOL mm of arc, where a change of sign is a crossing at
  the middle and an interval without one takes its ends' side (a sliver thinner than that is lost).
  An arc with more than MAX_OPEN intervals open at once (only where it runs within rounding of a solid's
  boundary over a stretch, not on the earlier tool's corner) has the excess decided as such leaves.

Points on the boundary (G ≤ 0) are inside, as the flat-end closed form takes them.
Shapes: K (arc, piece) pairs, (K, 3) vectors and (K,) numbers; ψ in radians; lengths in mm.
"""

import numpy as np

from .inprocess_swept import monotone_root, swept_gauge
from .ordering import group_order
from .swept import row_dot

#: An arc within this many ulps of its coordinates of lying on the earlier tool's corner (the foot bound) is on
#: it, and inside.
COINCIDENT = 64
#: … over an interval of at least this much arc (mm).
COINCIDENT_WIDTH = 1e-5
#: Crossings are refined, and intervals halved, down to this (mm of arc).
REFINE_TOL = 1e-11
#: Intervals of ψ each arc starts from.
START_INTERVALS = 4
#: Halvings at most (REFINE_TOL is reached within about 45 for radii up to 100 mm).
MAX_LEVELS = 80
#: Intervals of one arc open at once at most; the excess, narrowest first, is decided as leaves.
MAX_OPEN = 64


class _Arcs:
    """K arcs against K swept pieces: the data every evaluation needs."""

    def __init__(self, centre, d, w, radius, c0, c1, axis, big, height, corner):
        self.centre, self.d, self.w = centre, d, w
        self.radius = radius
        self.c0, self.move, self.axis = c0, c1 - c0, axis
        self.big, self.height, self.corner = big, height, corner
        scale = (np.maximum(np.abs(centre).max(axis=1), np.maximum(np.abs(c0).max(axis=1), np.abs(c1).max(axis=1)))
                 + radius + big + height)
        self.noise = COINCIDENT * np.spacing(scale)

    def point(self, pair, psi):
        """(n, 3) P(ψ) of arcs `pair` (n,) at ψ (n,)."""
        r = self.radius[pair]
        return (self.centre[pair] + (r * np.sin(psi))[:, None] * self.d[pair]
                - (r * np.cos(psi))[:, None] * self.w[pair])

    def evaluate(self, pair, psi):
        """(F (n,), D (n,), foot (n, 3), s (n,)) at ψ (n,) of arcs `pair` (n,)."""
        x = self.point(pair, psi)
        value, v, s, foot = swept_gauge(x, self.c0[pair], self.move[pair], self.axis[pair], self.big[pair],
                                        self.height[pair], self.corner[pair])
        r = self.radius[pair]
        slope = r * (np.cos(psi) * row_dot(v, self.d[pair]) + np.sin(psi) * row_dot(v, self.w[pair]))
        return value, slope, foot, s

    def value(self, pair, psi):
        """(n,) F at ψ (n,) of arcs `pair` (n,): evaluate's first number alone."""
        return swept_gauge(self.point(pair, psi), self.c0[pair], self.move[pair], self.axis[pair], self.big[pair],
                           self.height[pair], self.corner[pair], value_only=True)

    def foot_bound(self, pair, a, b, foot, s):
        """(n,) an upper bound of F over [a, b] (n,) from the tool standing at position s (n,) with its foot
        (n, 3) (inprocess_swept.swept_gauge): sinusoids' largest values."""
        r = self.radius[pair]
        centre, d, w, axis = self.centre[pair], self.d[pair], self.w[pair], self.axis[pair]
        rel = centre - foot
        # |P(ψ) − foot|² = |rel|² + r² + 2r·(rel·d) sin ψ − 2r·(rel·w) cos ψ.
        reach = np.sqrt(np.maximum(_largest(row_dot(rel, rel) + r * r, -2.0 * r * row_dot(rel, w),
                                            2.0 * r * row_dot(rel, d), a, b), 0.0))
        base = self.c0[pair] + s[:, None] * self.move[pair]
        level = row_dot(centre - base, axis)
        cos_part, sin_part = -r * row_dot(w, axis), r * row_dot(d, axis)
        top = _largest(level - self.height[pair], cos_part, sin_part, a, b)
        flat = self.corner[pair] <= 0.0
        bottom = np.where(flat, _largest(-level, -cos_part, -sin_part, a, b), -np.inf)
        offset = np.where(flat, self.big[pair], self.corner[pair])
        return np.maximum(np.maximum(reach - offset, top), bottom)


def _largest(constant, cos_part, sin_part, a, b):
    """(n,) the largest value of constant + cos_part·cos ψ + sin_part·sin ψ over ψ in [a, b] (n,)."""
    def at(psi):
        return constant + cos_part * np.cos(psi) + sin_part * np.sin(psi)

    peak = np.arctan2(sin_part, cos_part)  # where the sinusoid is largest, mod 2π
    best = np.maximum(at(a), at(b))
    for turn in (-2.0 * np.pi, 0.0, 2.0 * np.pi):
        psi = peak + turn
        best = np.where((psi > a) & (psi < b), np.maximum(best, at(psi)), best)
    return best


def arc_swept_intervals(centre, d, w, radius, lo, hi, c0, c1, axis, big, height, corner):
    """Where K arcs lie inside K swept solids: (pair (J,), start (J,), end (J,)) in ψ (rad), sorted by pair
    then start, disjoint within a pair.

    centre, d, w (K, 3), radius (K,): the arcs P(ψ) = centre + radius·(sin ψ·d − cos ψ·w) over
    lo ≤ ψ ≤ hi (K,); c0, c1, axis (K, 3), big, height, corner (K,): the tools (radius, cutting height,
    corner radius) moved from c0 to c1 with a constant axis. See the module docstring.
    """
    arcs = _Arcs(*(np.asarray(v, dtype=float) for v in (centre, d, w, radius, c0, c1, axis, big, height, corner)))
    lo, hi = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
    k = lo.size
    tol = REFINE_TOL / arcs.radius
    pair = np.repeat(np.arange(k), START_INTERVALS + 1)
    fraction = np.tile(np.linspace(0.0, 1.0, START_INTERVALS + 1), k)
    psi = lo[pair] + fraction * (hi - lo)[pair]
    f, slope, foot, s = arcs.evaluate(pair, psi)
    left = np.flatnonzero(np.tile(np.arange(START_INTERVALS + 1) < START_INTERVALS, k))
    left = left[(hi > lo)[pair[left]]]
    # Intervals: pair, a, b and at each end F, D, foot, s.
    cur = {"pair": pair[left]}
    for side, at in zip("ab", (left, left + 1)):
        cur.update({side: psi[at], "f" + side: f[at], "d" + side: slope[at], "foot" + side: foot[at],
                    "s" + side: s[at]})
    inside, single, leaves = [], [], []
    for _ in range(MAX_LEVELS):
        if cur["pair"].size == 0:
            break
        p, a, b = cur["pair"], cur["a"], cur["b"]
        fa, fb, da, db = cur["fa"], cur["fb"], cur["da"], cur["db"]
        h = b - a
        r = arcs.radius[p]
        out = _below(a, b, fa, fb, da, db) - 0.5 * r * h * h > 0.0
        full = ~out & (np.maximum(fa, fb) + 0.125 * r * h * h <= 0.0)
        # The foot bound is at least F at both ends: only where both are within rounding of inside can it be at
        # most zero, or within rounding.
        rows = np.flatnonzero(~out & ~full & (np.maximum(fa, fb) <= arcs.noise[p]))
        if rows.size:
            bound = np.minimum(arcs.foot_bound(p[rows], a[rows], b[rows], cur["foota"][rows], cur["sa"][rows]),
                               arcs.foot_bound(p[rows], a[rows], b[rows], cur["footb"][rows], cur["sb"][rows]))
            # On the earlier tool's corner to rounding over a stretch: F at both ends and the bound within
            # rounding, on an interval wide enough that a tangential touch cannot stay within it.
            noise = arcs.noise[p[rows]]
            full[rows] = (bound <= 0.0) | ((bound <= noise) & (np.maximum(np.abs(fa[rows]), np.abs(fb[rows])) <= noise)
                                           & (h[rows] * r[rows] >= COINCIDENT_WIDTH))
        change = (fa > 0.0) != (fb > 0.0)
        falling = change & (fa > 0.0) & (db + r * h < 0.0)
        rising = change & (fa <= 0.0) & (da - r * h > 0.0)
        one = ~out & ~full & (falling | rising)
        tiny = ~out & ~full & ~one & ((h <= tol[p]) | _crowded(p, h, ~out & ~full & ~one))
        inside.append((p[full], a[full], b[full]))
        single.append({key: cur[key][one] for key in ("pair", "a", "b", "fa", "fb")})
        leaves.append({key: cur[key][tiny] for key in ("pair", "a", "b", "fa", "fb")})
        split = np.flatnonzero(~out & ~full & ~one & ~tiny)
        if split.size == 0:
            cur = {"pair": np.zeros(0, dtype=np.intp)}
            break
        mid = 0.5 * (a[split] + b[split])
        fm, dm, footm, sm = arcs.evaluate(p[split], mid)
        halves = {key: np.concatenate([value[split], value[split]]) for key, value in cur.items()}
        n = split.size
        halves["b"][:n] = mid
        halves["a"][n:] = mid
        for name, value in (("f", fm), ("d", dm), ("foot", footm), ("s", sm)):
            halves[name + "b"][:n] = value
            halves[name + "a"][n:] = value
        cur = halves
    else:
        # Out of levels (not reached within REFINE_TOL): what is left is taken as leaves.
        leaves.append({key: cur[key] for key in ("pair", "a", "b", "fa", "fb")})
    parts = [tuple(np.concatenate(v) for v in zip(*inside))]
    one = {key: np.concatenate([part[key] for part in single]) for key in single[0]}
    if one["pair"].size:
        def value(rows, x):
            return arcs.value(one["pair"][rows], x)

        enters = one["fa"] > 0.0
        root = monotone_root(value, np.where(enters, one["b"], one["a"]), np.where(enters, one["a"], one["b"]),
                             np.where(enters, one["fb"], one["fa"]), np.where(enters, one["fa"], one["fb"]),
                             tol[one["pair"]])
        parts.append((one["pair"], np.where(enters, root, one["a"]), np.where(enters, one["b"], root)))
    leaf = {key: np.concatenate([part[key] for part in leaves]) for key in leaves[0]}
    if leaf["pair"].size:
        mid = 0.5 * (leaf["a"] + leaf["b"])
        enters = (leaf["fa"] > 0.0) & (leaf["fb"] <= 0.0)
        exits = (leaf["fa"] <= 0.0) & (leaf["fb"] > 0.0)
        keep = enters | exits | ((leaf["fa"] <= 0.0) & (leaf["fb"] <= 0.0))
        start = np.where(enters, mid, leaf["a"])
        end = np.where(exits, mid, leaf["b"])
        parts.append((leaf["pair"][keep], start[keep], end[keep]))
    return _merged(*(np.concatenate(v) for v in zip(*parts)))


def _crowded(pair, h, open_):
    """(n,) bool: of the open intervals (open_) of each arc (pair, ascending in runs), all but its MAX_OPEN widest
    when it has more than MAX_OPEN (an arc running within rounding of a boundary over a stretch)."""
    crowded = np.zeros(pair.size, dtype=bool)
    rows = np.flatnonzero(open_)
    if rows.size <= MAX_OPEN:
        return crowded
    count = np.bincount(pair[rows])
    many = count[pair[rows]] > MAX_OPEN
    if not many.any():
        return crowded
    rows = rows[many]
    order = group_order(-h[rows], pair[rows])
    rows = rows[order]
    first = np.searchsorted(pair[rows], pair[rows])
    crowded[rows[np.arange(rows.size) - first >= MAX_OPEN]] = True
    return crowded


def _below(a, b, fa, fb, da, db):
    """(n,) min over [a, b] of the larger of the tangent lines fa + da·(ψ − a) and fb + db·(ψ − b)."""
    h = b - a
    at_a = np.maximum(fa, fb - db * h)
    at_b = np.maximum(fa + da * h, fb)
    best = np.minimum(at_a, at_b)
    gap = da - db
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(gap != 0.0, (fb - fa - db * h) / np.where(gap != 0.0, gap, 1.0), -1.0)
    crossing = (t > 0.0) & (t < h)
    return np.where(crossing, np.minimum(best, fa + da * t), best)


def _merged(pair, start, end):
    """The intervals (pair, start, end) sorted by pair and start, with touching or overlapping ones of a pair
    joined (zero-length ones dropped)."""
    keep = end > start
    pair, start, end = pair[keep].astype(np.intp), start[keep], end[keep]
    if pair.size == 0:
        return pair, start, end
    order = group_order(start, pair)
    pair, start, end = pair[order], start[order], end[order]
    first = np.flatnonzero(np.r_[True, pair[1:] != pair[:-1]])
    count = np.diff(np.r_[first, pair.size])
    owner = np.repeat(np.arange(first.size), count)
    rank = np.arange(pair.size) - np.repeat(first, count)
    # The running largest end within each pair: a column per pair, padded with −inf.
    table = np.full((int(count.max()), first.size), -np.inf)
    table[rank, owner] = end
    reach = np.maximum.accumulate(table, axis=0)[rank, owner]
    new = np.r_[True, pair[1:] != pair[:-1]]
    new[1:] |= start[1:] > reach[:-1]
    head = np.flatnonzero(new)
    tail = np.r_[head[1:], pair.size] - 1
    return pair[head], start[head], reach[tail]
