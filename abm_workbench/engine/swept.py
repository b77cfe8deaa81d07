"""Where a line meets the volume swept by a flat-end mill moving with a constant axis.

The tool's cutting part is the cylinder of radius r around the unit axis w from its bottom
centre c up to height H (the flute length). Moving c linearly from c0 to c1 with w fixed, it
sweeps the convex hull of its two end cylinders: the points

    c0 + s·d + a·w + b,   d = c1 − c0,  0 ≤ s ≤ 1,  0 ≤ a ≤ H,  b ⊥ w,  |b| ≤ r.

A line o + l·u meets this convex set in one interval of l. Writing q = o − c0 and splitting
every vector into its part along w and its part across it (q = a0·w + b0, u = ua·w + up,
d = da·w + dp), the point at l is in the volume when some s satisfies

    0 ≤ s ≤ 1,   0 ≤ a0 + l·ua − s·da ≤ H,   |b0 + l·up − s·dp| ≤ r.

These are four half-planes and one convex quadratic region in the (l, s) plane; their
intersection F is convex and bounded, and the interval is [min l, max l] over F. A linear
function on such a set takes its extremes at a corner (two boundaries meeting: two lines, or a
line and the quadratic's boundary) or where the quadratic's boundary is tangent to the
direction of s (∂/∂s |b|² = 0). All these candidates are closed-form roots of quadratics, at
most 14 per pair; the extremes over the feasible ones are the interval. See docs/ENGINE.md.
Lengths in mm.
"""

import numpy as np

#: Slack (mm, and the same number for the dimensionless s) with which a candidate point that
#: lies on the boundaries up to rounding still counts as inside the volume.
FEASIBLE_EPS = 1e-9
#: A squared norm (mm²) below this is zero: the quadratic has no term in that variable.
SQUARED_EPS = 1e-24


def clamp(x, low, high):
    """x clamped to low … high (arrays or numbers; NaN stays NaN), as np.clip, whose checks per call cost
    several times these two ufuncs on the short arrays of the in-process searches."""
    return np.minimum(np.maximum(x, low), high)


def every_column(x):
    """(K,) bool: every column of the (K, n) bool array x true, as np.all(x, axis=1) (which costs numpy about twenty
    times as much over so short an axis)."""
    out = x[:, 0].copy()
    for j in range(1, x.shape[1]):
        out &= x[:, j]
    return out


def rows(table, index):
    """table[index]: the rows index (K,) int of table (N, …), by ndarray.take, which numpy runs five to fifteen times
    faster than indexing for (N, 2) and (N, 3) tables and about twice as fast for (N,) (nor is it dispatched)."""
    return table.take(index, axis=0)


def kept(mask, *arrays):
    """(array[mask], …): the rows where mask (K,) bool holds of each array (K, …), by one nonzero and a take per array
    (boolean indexing costs numpy several times that: about 6 ns a row where the mask is mixed)."""
    index = mask.nonzero()[0]
    return tuple(array.take(index, axis=0) for array in arrays)


def row_cross(a, b):
    """(P, 3): the cross products of the rows of a and b (P, 3), as np.cross computes them (each component one
    difference of two rounded products: the same numbers), without its reshaping, several times slower on the
    short arrays of the in-process searches."""
    out = np.empty(np.broadcast_shapes(a.shape, b.shape))
    out[:, 0] = a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1]
    out[:, 1] = a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2]
    out[:, 2] = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    return out


def row_dot(a, b):
    """Row-wise dot product of (P, 3) arrays: (P,), summed x, y, z in that order (column by
    column: two to three times faster than np.einsum on three columns)."""
    product = a * b
    return product[:, 0] + product[:, 1] + product[:, 2]


def _quadratic_roots(a, b, c, out=None):
    """Real roots t of a·t² + 2b·t + c = 0 for (P,) coefficients: (P, 2), NaN where none
    (or where a is zero: the quadratic then does not depend on t). out: a (P, 2) array (a view
    of a larger one will do) to write them to, returned."""
    disc = b * b - a * c
    ok = (a > SQUARED_EPS) & (disc >= 0.0)
    root = np.sqrt(np.where(ok, disc, 0.0))
    big = -b - np.copysign(root, b)  # no cancellation: |big| = |b| + root
    if out is None:
        out = np.empty((b.shape[0], 2))
    with np.errstate(divide="ignore", invalid="ignore"):
        nonzero = big != 0.0
        out[:, 0] = np.where(ok, np.where(nonzero, big / np.where(ok, a, 1.0), 0.0), np.nan)
        out[:, 1] = np.where(ok, np.where(nonzero, c / big, 0.0), np.nan)
    return out


#: Candidates (l, s) per line in line_hull_interval: 2 roots each of the lines s = 0 and s = 1,
#: of the lines a = 0 and a = H, and of the tangent; the strip's 4 corners.
_CANDIDATES = 14


def line_hull_interval(origin, direction, c0, c1, axis, radius, height):
    """The interval of each line inside the convex hull of two end cylinders (one pair per row).

    origin, direction: (P, 3) points and unit directions of the lines (mm).
    c0, c1: (P, 3) bottom centres of the tool at the move's ends; axis: (P, 3) unit tool axis
    (the same at both ends); radius, height: (P,) tool radius and cutting height (mm).
    Returns enter, leave (P,) in mm along each line (enter ≤ leave), NaN where the line misses
    the volume.

    The candidates are written into one (P, 14) table each for l and s, and a dot product that
    several of them use is computed once (the same operations on the same numbers as one at a
    time: the same bits).
    """
    o, u = np.asarray(origin, dtype=float), np.asarray(direction, dtype=float)
    w = np.asarray(axis, dtype=float)
    c0 = np.asarray(c0, dtype=float)
    d = np.asarray(c1, dtype=float) - c0
    r, h = np.asarray(radius, dtype=float), np.asarray(height, dtype=float)
    q = o - c0
    a0, ua, da = row_dot(q, w), row_dot(u, w), row_dot(d, w)
    b0, up, dp = q - a0[:, None] * w, u - ua[:, None] * w, d - da[:, None] * w
    rr = r * r
    uu = row_dot(up, up)
    l = np.empty((a0.shape[0], _CANDIDATES))
    s = np.empty((a0.shape[0], _CANDIDATES))
    # The lines s = 0 and s = 1 against the quadratic: |b0 − s0·dp + l·up|² = r².
    for column, s0 in ((0, 0.0), (2, 1.0)):
        base = b0 - s0 * dp
        _quadratic_roots(uu, row_dot(up, base), row_dot(base, base) - rr, l[:, column:column + 2])
        s[:, column:column + 2] = s0
    # The lines a = 0 and a = H, (l, s) = P0 + t·(da, ua), against the quadratic.
    norm = ua * ua + da * da
    has_line = norm > SQUARED_EPS
    g = da[:, None] * up - ua[:, None] * dp
    gg = row_dot(g, g)
    zero = np.zeros_like(h)
    for column, c in ((4, zero), (6, h)):
        scale = np.where(has_line, (c - a0) / np.where(has_line, norm, 1.0), np.nan)
        p_l, p_s = scale * ua, -scale * da
        base = b0 + p_l[:, None] * up - p_s[:, None] * dp
        t = _quadratic_roots(gg, row_dot(g, base), row_dot(base, base) - rr)
        l[:, column:column + 2] = p_l[:, None] + t * da[:, None]
        s[:, column:column + 2] = p_s[:, None] + t * ua[:, None]
    # The four corners of the strip 0 ≤ s ≤ 1 with 0 ≤ a ≤ H.
    crossing = np.abs(ua) > 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        for column, c, s0 in ((8, zero, 0.0), (9, zero, 1.0), (10, h, 0.0), (11, h, 1.0)):
            l[:, column] = np.where(crossing, (c - a0 + s0 * da) / ua, np.nan)
            s[:, column] = s0
    # Where the quadratic's boundary runs along s: s = dp·(b0 + l·up)/|dp|², and the part of
    # b0 + l·up across dp has length r.
    dd = row_dot(dp, dp)
    moving = dd > SQUARED_EPS
    unit = dp / np.sqrt(np.where(moving, dd, 1.0))[:, None]
    e0 = b0 - row_dot(b0, unit)[:, None] * unit
    e1 = up - row_dot(up, unit)[:, None] * unit
    roots = _quadratic_roots(np.where(moving, row_dot(e1, e1), 0.0), row_dot(e1, e0), row_dot(e0, e0) - rr,
                             l[:, 12:14])
    bd, ud = row_dot(b0, dp)[:, None], row_dot(up, dp)[:, None]
    with np.errstate(divide="ignore", invalid="ignore"):
        s[:, 12:14] = (bd + roots * ud) / np.where(moving, dd, 1.0)[:, None]

    eps = FEASIBLE_EPS
    # The feasibility of every candidate, in place (the same operations in the same order as
    # the expressions in the comments: the same bits, without a temporary table per step).
    # a = a0 + l·ua − s·da
    a = l * ua[:, None]
    a += a0[:, None]
    a -= s * da[:, None]
    # |b0 + l·up − s·dp|² expanded in the pair's dot products:
    # |b0|² + l·(l·|up|² + 2·(b0·up − s·(up·dp))) + s·(s·|dp|² − 2·(b0·dp))
    with np.errstate(invalid="ignore"):
        inner = s * ud
        np.subtract(row_dot(b0, up)[:, None], inner, out=inner)
        inner *= 2.0
        across = l * uu[:, None]
        across += inner
        across *= l
        across += row_dot(b0, b0)[:, None]
        other = s * dd[:, None]
        other -= 2.0 * bd
        other *= s
        across += other
        feasible = s >= -eps
        feasible &= s <= 1.0 + eps
        feasible &= a >= -eps
        feasible &= a <= h[:, None] + eps
        feasible &= across <= (r[:, None] + eps) ** 2
    hit = feasible.any(axis=1)
    enter = np.where(hit, np.where(feasible, l, np.inf).min(axis=1), np.nan)
    leave = np.where(hit, np.where(feasible, l, -np.inf).max(axis=1), np.nan)
    return enter, leave
