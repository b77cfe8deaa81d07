"""The solid of a flat-end, bull-nose or ball-end mill swept along a constant-axis piece, against lines and points.

The tool solid T of radius R, corner radius r (0 ≤ r ≤ R) and cutting height H, its bottom centre at
c and its unit axis W: the points c + a·W + b, b ⊥ W, with 0 ≤ a ≤ H and |b| ≤ ρ(a), where
ρ(a) = R − r + √(r² − (r − a)²) for a < r (the corner) and R above. It is convex: the points within r
of K = {a ≥ r, |b| ≤ R − r} (a half-infinite cylinder) that lie below a = H. Moving c linearly from
c0 to c1 = c0 + m with W fixed, T sweeps S = T ⊕ [0, 1]·m, convex too (docs/ENGINE.md, "Tools with a
corner in the in-process stock").

* **Gauge.** g(q) = max(dist(q, K) − r, a − H) for r > 0 and max(|b| − R, −a, a − H) for r = 0
  (q = x − c, a = q·W, b its part across W): convex, 1-Lipschitz, ≤ 0 exactly on T. Over the sweep,
  G(x) = min over 0 ≤ s ≤ 1 of g(x − c0 − s·m), convex and 1-Lipschitz, ≤ 0 exactly on S; it comes
  with a subgradient v (|v| ≤ 1), so that G(y) ≥ G(x) + v·(y − x) for every y (:func:`swept_gauge`).
* **Support.** σ(n), the point of T farthest along a unit direction n, is closed form: the corner
  point whose normal is n, or a point of the top rim (:func:`support_points`).
* **Lines.** A line o + l·u meets S in one interval [min l, max l] over the convex set
  F = {(l, s): 0 ≤ s ≤ 1, o + l·u − s·m ∈ T + c0}. Without the bounds on s, the extremes are where the
  line enters and leaves the prism T ⊕ ℝ·m: seen along m, where the line crosses the boundary of the
  convex shadow of T, whose point with outward normal n (n ⊥ m) is σ(n) seen along m. With n turning
  in the plane across m from the line's normal ν to −ν, the signed distance (σ(n) − o)·ν of that
  point from the line falls monotonically, so each crossing is one root on a half-turn: the Illinois
  method on the angle of n, finished by the chord between the support points at its last bracket's
  ends (exact on the shadow's flat edges); for a move across the axis the shadow is the tool's
  profile, crossed in closed form (:func:`_profile_crossings`). The crossing gives the position s* of
  the tool there; where s* lies outside [0, 1] the extreme is where the line enters (leaves) the tool
  standing at the nearer end of the move, found by Newton's method on the convex gauge along the line,
  started outside the tool, whose steps never pass the boundary, or in closed form for a line across
  or along the axis (:func:`_square_entry`) (:func:`line_swept_interval`).

Shapes: K rows, each a point or a line and one piece; (K, 3) vectors and (K,) numbers. Lengths in mm.
"""

import numpy as np

from .swept import row_dot

#: The shadow's crossing is bracketed in the angle of its normal to π/2^42 ≈ 7e-13 rad, so the chord between
#: the support points at the bracket's ends lies within (the shadow's size)·7e-13 mm of its boundary.
SHADOW_STEPS = 42
#: Newton's method on a convex gauge along a line stops when a step is below this (mm).
NEWTON_STEP = 1e-13
#: … or after this many steps (a line grazing the tool converges linearly, halving its distance).
NEWTON_MAX = 200
#: A move shorter than this (mm) is a tool standing still; a line within this angle (rad) of
#: the move's direction runs along it.
STILL = 1e-12
#: Pieces within this (of the gauge's value, mm) of the largest one are active at a point.
ACTIVE = 1e-11


def _unit_across(n, axis):
    """(n·W (K,), |n across W| (K,), unit direction of n across W (K, 3), zero where n ∥ W)."""
    nw = row_dot(n, axis)
    across = n - nw[:, None] * axis
    # Again: for n nearly along W the first difference keeps a part along W far above its own size.
    across = across - row_dot(across, axis)[:, None] * axis
    nb = np.sqrt(row_dot(across, across))
    with np.errstate(divide="ignore", invalid="ignore"):
        e = np.where(nb[:, None] > 0.0, across / np.where(nb > 0.0, nb, 1.0)[:, None], 0.0)
    return nw, nb, e


def top_radius(radius, height, corner):
    """ρ(H) (K,): the tool's radius at the top of its cutting part (below R when the flute ends in the corner)."""
    low = height < corner
    with np.errstate(invalid="ignore"):
        inside = radius - corner + np.sqrt(np.maximum(corner * corner - (corner - height) ** 2, 0.0))
    return np.where(low, inside, radius)


def support_points(n, axis, radius, height, corner):
    """σ(n) − c (K, 3): a point of each tool solid farthest along the unit directions n (K, 3).

    Pointing down or sideways (n·W ≤ 0) at a height r(1 + n·W) within the flute: the corner point
    whose normal is n, r·W + (R − r)·ê + r·n (ê: n across W, unit; the bottom face's centre for
    n = −W); otherwise the top rim, H·W + ρ(H)·ê (the top face's centre for n = W).
    """
    nw, _, e = _unit_across(n, axis)
    on_corner = (nw <= 0.0) & (corner * (1.0 + nw) <= height)
    corner_point = (corner[:, None] * (axis + n) + (radius - corner)[:, None] * e)
    top = height[:, None] * axis + top_radius(radius, height, corner)[:, None] * e
    return np.where(on_corner[:, None], corner_point, top)


def tool_gauge(q, axis, radius, height, corner):
    """(g (K,), pieces (K, 3), gradients (K, 3, 3)) of points q (K, 3) relative to the bottom centre.

    The pieces of the gauge (docs: module) and their gradients: for a corner, dist(q, K) − r, a − H
    and −∞ (none); for a flat end, |b| − R, −a and a − H. g is their largest.
    """
    a = row_dot(q, axis)
    b = q - a[:, None] * axis
    nb = np.sqrt(row_dot(b, b))
    w = np.broadcast_to(axis[:, None, :], (axis.shape[0], 3, 3))
    pieces = np.empty((q.shape[0], 3))
    grads = np.zeros((q.shape[0], 3, 3))
    flat = corner <= 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        unit_b = np.where(nb[:, None] > 0.0, b / np.where(nb > 0.0, nb, 1.0)[:, None], 0.0)
        # Corner: the distance to K = {a ≥ r, |b| ≤ R − r}.
        rim = radius - corner
        da = np.maximum(corner - a, 0.0)
        shrink = np.where(nb > 0.0, np.maximum(1.0 - rim / np.where(nb > 0.0, nb, 1.0), 0.0), 0.0)
        db = shrink[:, None] * b
        dist = np.sqrt(da * da + row_dot(db, db))
        tor_grad = np.where(dist[:, None] > 0.0, (db - da[:, None] * axis) / np.where(dist > 0.0, dist, 1.0)[:, None],
                            0.0)
    pieces[:, 0] = np.where(flat, nb - radius, dist - corner)
    pieces[:, 1] = np.where(flat, -a, -np.inf)
    pieces[:, 2] = a - height
    grads[:, 0] = np.where(flat[:, None], unit_b, tor_grad)
    grads[:, 1] = -w[:, 1]
    grads[:, 2] = w[:, 2]
    return pieces.max(axis=1), pieces, grads


def _subgradient(pieces, grads, m, s):
    """(K, 3) a subgradient v of the swept gauge G at its point: of the gauge's pieces active at the
    minimising position s (K,), the convex combination whose rate along the move m (K, 3) meets the
    optimality of s (v·m = 0 inside (0, 1), v·m ≤ 0 at 0, ≥ 0 at 1)."""
    top = pieces.max(axis=1)
    active = pieces >= (top - ACTIVE)[:, None]
    rate = np.einsum("kij,kj->ki", grads, m)
    # The active piece whose rate is smallest and the one whose rate is largest.
    low = np.argmin(np.where(active, rate, np.inf), axis=1)
    high = np.argmax(np.where(active, rate, -np.inf), axis=1)
    k = np.arange(pieces.shape[0])
    return _blended(rate[k, low], rate[k, high], grads[k, low], grads[k, high], s)


def _blended(r_low, r_high, g_low, g_high, s):
    """(K, 3) the subgradient of two active pieces' gradients g_low, g_high (K, 3) whose rates along the move
    are r_low ≤ r_high (K,), at the minimising position s (K,): where the rates change sign inside (0, 1),
    their convex combination of rate 0; else at s = 0 the smaller (rate ≤ 0), at s = 1 the larger
    (rate ≥ 0), inside the one nearer 0."""
    inner = (s > 0.0) & (s < 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        mix = np.where(r_high > r_low, r_high / (r_high - r_low), 1.0)
    mix = np.clip(mix, 0.0, 1.0)
    crossing = inner & (r_low < 0.0) & (r_high > 0.0)
    return np.where(crossing[:, None], mix[:, None] * g_low + (1.0 - mix)[:, None] * g_high,
                    np.where((s >= 1.0)[:, None] | (inner & (np.abs(r_high) < np.abs(r_low)))[:, None], g_high,
                             g_low))


def swept_gauge(x, c0, move, axis, radius, height, corner, value_only=False):
    """(G (K,), v (K, 3), s (K,), foot (K, 3)) of points x (K, 3) and the tools (axis, radius, height,
    corner) moved from c0 by `move` (all (K, 3) or (K,)); with value_only, G alone (the same numbers).

    G(x) = min over s in [0, 1] of g(x − c0 − s·move), the convex, 1-Lipschitz gauge of the swept solid
    (≤ 0 inside); v a subgradient of G at x (|v| ≤ 1); s the minimising position; foot = c0 + s·move +
    the nearest point of K (the corner's inner cylinder) to x − c0 − s·move, for a flat end the nearest
    point of the axis: for every point y, g(y − c0 − s·move) ≤ max(|y − foot| − r, a − H) (corner) and
    ≤ max(|y − foot| − R, −a, a − H) (flat end), a, the height of y − c0 − s·move along the axis.

    The position s: for a flat end the smallest of the gauge over the closed-form candidates (the ends,
    where |b| is least, where two pieces are equal); for a corner, the root of the rate of the squared
    distance to K along the move (monotone: convex in s) by monotone_root, then the meeting with the top
    piece a − H where that one is larger (_corner_position).
    """
    q = x - c0
    k = q.shape[0]
    s = np.zeros(k)
    flat = corner <= 0.0
    if flat.any():
        s[flat] = _flat_position(q[flat], move[flat], axis[flat], radius[flat], height[flat])
    bent = np.flatnonzero(~flat)
    if bent.size:
        s[bent] = _corner_position(q[bent], move[bent], axis[bent], radius[bent], height[bent], corner[bent])
    qs = q - s[:, None] * move
    if value_only and not flat.any():
        a = row_dot(qs, axis)
        b = qs - a[:, None] * axis
        nb = np.sqrt(row_dot(b, b))
        rim = radius - corner
        with np.errstate(divide="ignore", invalid="ignore"):
            da = np.maximum(corner - a, 0.0)
            shrink = np.where(nb > 0.0, np.maximum(1.0 - rim / np.where(nb > 0.0, nb, 1.0), 0.0), 0.0)
            db = shrink[:, None] * b
        return np.maximum(np.sqrt(da * da + row_dot(db, db)) - corner, a - height)
    if value_only:
        return tool_gauge(qs, axis, radius, height, corner)[0]
    if flat.any():
        value, pieces, grads = tool_gauge(qs, axis, radius, height, corner)
        v = _subgradient(pieces, grads, move, s)
        a = row_dot(qs, axis)
        b = qs - a[:, None] * axis
        nb = np.sqrt(row_dot(b, b))
    else:
        value, v, a, b, nb = _corner_gauge(qs, move, s, axis, radius, height, corner)
    rim = radius - corner
    with np.errstate(divide="ignore", invalid="ignore"):
        scale = np.where(nb > rim, rim / np.where(nb > 0.0, nb, 1.0), 1.0)
    foot = c0 + s[:, None] * move + np.where(flat, a, np.maximum(a, corner))[:, None] * axis
    foot = foot + np.where(flat, 0.0, scale)[:, None] * b
    return value, v, s, foot


def _corner_gauge(q, move, s, axis, radius, height, corner):
    """(g, v, a, b, |b|) for tools with a corner: tool_gauge and _subgradient with their two pieces, dist − r
    and a − H (the same numbers, without the flat end's third piece)."""
    a = row_dot(q, axis)
    b = q - a[:, None] * axis
    nb = np.sqrt(row_dot(b, b))
    rim = radius - corner
    positive = nb > 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        da = np.maximum(corner - a, 0.0)
        shrink = np.where(positive, np.maximum(1.0 - rim / np.where(positive, nb, 1.0), 0.0), 0.0)
        db = shrink[:, None] * b
        dist = np.sqrt(da * da + row_dot(db, db))
        tor_grad = np.where(dist[:, None] > 0.0, (db - da[:, None] * axis) / np.where(dist > 0.0, dist, 1.0)[:, None],
                            0.0)
    tor, top = dist - corner, a - height
    value = np.maximum(tor, top)
    # The active pieces (within ACTIVE of the largest) and their rates along the move.
    tor_on, top_on = tor >= value - ACTIVE, top >= value - ACTIVE
    r_tor, r_top = row_dot(tor_grad, move), row_dot(axis, move)
    both = tor_on & top_on
    # _subgradient's low and high: the smaller and larger rate of the active pieces (ties: the first, dist − r).
    top_low = both & (r_top < r_tor) | ~tor_on
    top_high = both & (r_top > r_tor) | ~tor_on
    r_low, r_high = np.where(top_low, r_top, r_tor), np.where(top_high, r_top, r_tor)
    g_low = np.where(top_low[:, None], axis, tor_grad)
    g_high = np.where(top_high[:, None], axis, tor_grad)
    return value, _blended(r_low, r_high, g_low, g_high, s), a, b, nb


def _flat_position(q, move, axis, radius, height):
    """(K,) the s in [0, 1] minimising max(|b| − R, −a, a − H) at q − s·move: the least over the candidates."""
    a0, da = row_dot(q, axis), row_dot(move, axis)
    b0, bp = q - a0[:, None] * axis, move - da[:, None] * axis
    pp, bd, bb = row_dot(bp, bp), row_dot(b0, bp), row_dot(b0, b0)
    candidates = [np.zeros_like(a0), np.ones_like(a0)]
    with np.errstate(divide="ignore", invalid="ignore"):
        candidates.append(np.where(pp > 0.0, bd / np.where(pp > 0.0, pp, 1.0), 0.0))
        candidates.append(np.where(da != 0.0, (a0 - 0.5 * height) / np.where(da != 0.0, da, 1.0), 0.0))
    # |b(s)| = e(s) with e = (R − a0) + s·da (|b| − R = −a) and e = (a0 − H + R) − s·da (|b| − R = a − H).
    for e0, e1 in ((radius - a0, da), (a0 - height + radius, -da)):
        roots = _quadratic(pp - e1 * e1, -(bd + e0 * e1), bb - e0 * e0)
        candidates.extend(roots)
    s = np.clip(np.nan_to_num(np.stack(candidates, axis=1), nan=0.0), 0.0, 1.0)
    qs = q[:, None, :] - s[..., None] * move[:, None, :]
    a = np.einsum("kcj,kj->kc", qs, axis)
    b = qs - a[..., None] * axis[:, None, :]
    value = np.maximum(np.maximum(np.sqrt(np.einsum("kcj,kcj->kc", b, b)) - radius[:, None], -a),
                       a - height[:, None])
    return s[np.arange(s.shape[0]), np.argmin(value, axis=1)]


def _quadratic(a, b, c):
    """The two real roots t of a·t² + 2b·t + c = 0 (K,) each, NaN where none; a linear root where a = 0."""
    disc = b * b - a * c
    root = np.sqrt(np.maximum(disc, 0.0))
    big = -b - np.copysign(root, b)
    with np.errstate(divide="ignore", invalid="ignore"):
        first = np.where((a != 0.0) & (disc >= 0.0), big / np.where(a != 0.0, a, 1.0), np.nan)
        second = np.where((disc >= 0.0) & (big != 0.0), c / np.where(big != 0.0, big, 1.0), np.nan)
        linear = np.where(b != 0.0, -0.5 * c / np.where(b != 0.0, b, 1.0), np.nan)
    return np.where(a != 0.0, first, linear), np.where(a != 0.0, second, np.nan)


def monotone_root(func, x_neg, x_pos, f_neg, f_pos, tol, accept=0.0, max_steps=200, bracket=False):
    """(n,) a root of each monotone function in its bracket: func(rows, x) gives the values (len(rows),) of
    the functions `rows` (indices 0 … n − 1) at x; f ≤ 0 at x_neg and f > 0 at x_pos (n,), in either
    order. The Illinois method (the secant through the bracket's ends, halving the value of an end kept
    twice running), with a bisection step whenever four steps leave the bracket wider than half what it
    was, until the bracket is within tol (n,) or a value is within accept (n,) of 0 (that point is the
    root: a function flat to rounding there has no better one); otherwise the bracket's middle. With
    `bracket`, (root, x_neg, x_pos, f_neg, f_pos): the last bracket too (x_neg the root where a value was 0)."""
    x_neg, x_pos, f_neg, f_pos = (np.array(v, dtype=float) for v in (x_neg, x_pos, f_neg, f_pos))
    tol = np.broadcast_to(np.asarray(tol, dtype=float), x_neg.shape)
    accept = np.broadcast_to(np.asarray(accept, dtype=float), x_neg.shape)
    root = 0.5 * (x_neg + x_pos)
    kept = np.zeros(x_neg.size, dtype=np.int8)  # +1: the positive end was replaced last, −1 the negative one
    width = np.abs(x_pos - x_neg)
    live = np.flatnonzero(width > tol)
    for step in range(max_steps):
        if live.size == 0:
            break
        xn, xp, fn, fp = x_neg[live], x_pos[live], f_neg[live], f_pos[live]
        with np.errstate(divide="ignore", invalid="ignore"):
            x = xp - fp * (xp - xn) / (fp - fn)
        span = np.abs(xp - xn)
        check = step % 4 == 3
        bisect = check & (span > 0.5 * width[live])
        if check:
            width[live] = span
        low, high = np.minimum(xn, xp), np.maximum(xn, xp)
        x = np.where(bisect | ~np.isfinite(x) | (x <= low) | (x >= high), 0.5 * (xn + xp), x)
        fx = func(live, x)
        up = fx > 0.0
        f_neg[live] = np.where(up, np.where(kept[live] == 1, 0.5 * fn, fn), fx)
        f_pos[live] = np.where(up, fx, np.where(kept[live] == -1, 0.5 * fp, fp))
        x_pos[live] = np.where(up, x, xp)
        x_neg[live] = np.where(up, xn, x)
        kept[live] = np.where(up, 1, -1)
        exact = np.abs(fx) <= accept[live]
        root[live] = np.where(exact, x, 0.5 * (x_neg[live] + x_pos[live]))
        live = live[~exact & (np.abs(x_pos[live] - x_neg[live]) > tol[live])]
    if bracket:
        return root, x_neg, x_pos, f_neg, f_pos
    return root


def _corner_position(q, move, axis, radius, height, corner):
    """(K,) the s in [0, 1] minimising max(dist(q − s·move, K) − r, a − H) for tools with a corner.

    In the numbers of each row (a and |b|² are linear and quadratic in s): first the s minimising the
    distance (convex in s; its rate is monotone, its root found by monotone_root, or where |b| is least for
    a move across the axis); where the top piece
    a − H is the larger there, the minimum of the two is where they meet on the side where a − H falls
    (or at that end of the move): the difference dist − r − (a − H) is convex, and Newton's method
    from that end reaches its root without passing it."""
    a0, da = row_dot(q, axis), row_dot(move, axis)
    b0, bp = q - a0[:, None] * axis, move - da[:, None] * axis
    pp, bd, bb = row_dot(bp, bp), row_dot(b0, bp), row_dot(b0, b0)
    rim = radius - corner

    def pieces(rows, s):
        """(dist − r, half the rate of dist², a − H) at s of the rows. The rate of dist² is continuous (dist² is
        C¹: its pieces (r − a)₊² and (|b| − (R − r))₊² are), so the root of its rate is found fast."""
        a = a0[rows] - s * da[rows]
        square = np.maximum(bb[rows] - s * (2.0 * bd[rows] - s * pp[rows]), 0.0)
        nb = np.sqrt(square)
        low = np.maximum(corner[rows] - a, 0.0)
        out = np.maximum(nb - rim[rows], 0.0)
        dist = np.sqrt(low * low + out * out)
        with np.errstate(divide="ignore", invalid="ignore"):
            shrink = np.where(nb > 0.0, np.maximum(1.0 - rim[rows] / np.where(nb > 0.0, nb, 1.0), 0.0),
                              np.where(rim[rows] > 0.0, 0.0, 1.0))
        rate = low * da[rows] + shrink * (s * pp[rows] - bd[rows])
        return dist - corner[rows], rate, a - height[rows]

    k = q.shape[0]
    if not da.any():
        return _level_position(bb, bd, pp, rim)
    every = np.arange(k)
    zero, one = np.zeros(k), np.ones(k)
    rate0, rate1 = pieces(every, zero)[1], pieces(every, one)[1]
    s = np.where(rate0 >= 0.0, 0.0, 1.0)
    inner = (rate0 < 0.0) & (rate1 > 0.0)
    # A move across the axis (a − r constant): the rate is shrink·(s·|b'|² − b0·b'), zero where |b| is least.
    level = inner & (da == 0.0)
    s[level] = np.clip(bd[level] / pp[level], 0.0, 1.0)
    inner = np.flatnonzero(inner & ~level)
    if inner.size:
        # The rate's size, for a rate that is zero to rounding over a stretch (a move along a face).
        scale = (np.abs(a0) + corner + np.abs(da)) * np.abs(da) + pp + np.abs(bd)
        s[inner] = monotone_root(lambda rows, x: pieces(inner[rows], x)[1], zero[inner], one[inner], rate0[inner],
                                 rate1[inner], 1e-15, 1e-14 * scale[inner])
    tor, _, top = pieces(every, s)
    # Where a − H is the larger piece: towards the end where it falls, to where the pieces meet.
    climb = np.flatnonzero((top > tor) & (da != 0.0))
    if climb.size:
        end = np.where(da[climb] > 0.0, 1.0, 0.0)
        tor_end, _, top_end = pieces(climb, end)
        reach = tor_end - top_end > 0.0
        at = end.copy()
        rows = climb[reach]
        x = end[reach]
        live = np.arange(rows.size)
        for _ in range(NEWTON_MAX):
            if live.size == 0:
                break
            value, half_rate, top_value = pieces(rows[live], x[live])
            gap = value - top_value
            dist = value + corner[rows[live]]
            with np.errstate(divide="ignore", invalid="ignore"):
                rate = np.where(dist > 0.0, half_rate / np.where(dist > 0.0, dist, 1.0), 0.0)
            slope = rate + da[rows[live]]
            with np.errstate(divide="ignore", invalid="ignore"):
                step = np.where(slope != 0.0, gap / slope, 0.0)
            x[live] -= step
            live = live[(np.abs(step) > 1e-16) & (gap > 0.0)]
        at[reach] = np.clip(x, 0.0, 1.0)
        s[climb] = at
    return s


def _level_position(bb, bd, pp, rim):
    """_corner_position for moves across the axis (every row): a is constant, so the rate of dist² is
    shrink·(s·|b'|² − b0·b') (the same numbers as there), and the top piece never decides."""
    def rate(s):
        with np.errstate(divide="ignore", invalid="ignore"):
            nb = np.sqrt(np.maximum(bb - s * (2.0 * bd - s * pp), 0.0))
            shrink = np.where(nb > 0.0, np.maximum(1.0 - rim / np.where(nb > 0.0, nb, 1.0), 0.0),
                              np.where(rim > 0.0, 0.0, 1.0))
        return shrink * (s * pp - bd)

    rate0, rate1 = rate(0.0), rate(1.0)
    s = np.where(rate0 >= 0.0, 0.0, 1.0)
    inner = (rate0 < 0.0) & (rate1 > 0.0)
    s[inner] = np.clip(bd[inner] / pp[inner], 0.0, 1.0)
    return s


def _newton_entry(origin, direction, base, axis, radius, height, corner, start, sign):
    """(K,) where each line origin + l·direction enters the tool standing at `base` (bottom centre),
    walking from l = start (outside) in the direction `sign` (+1 up, −1 down); NaN where it misses.

    Newton's method on the gauge along the line, convex: its tangent lies below it, so every step stays
    short of the boundary, and a point with the gauge positive and not falling ahead proves a miss.
    A line across the axis (direction·W = 0 as computed) or along it is solved in closed form instead
    (_square_entry): Newton's method converges only linearly where such a line grazes a flat face (an
    end edge in the bottom plane of an earlier position of the same tool)."""
    l = np.array(start, dtype=float)
    found = np.full(l.shape, np.nan)
    uw = row_dot(direction, axis)
    across = direction - uw[:, None] * axis
    square = (uw == 0.0) | ~np.any(across, axis=1)
    if square.any():
        rows = np.flatnonzero(square)
        found[rows] = _square_entry(origin[rows], direction[rows], base[rows], axis[rows], radius[rows], height[rows],
                                    corner[rows], l[rows], sign, uw[rows] == 0.0)
    live = np.flatnonzero(~square)
    for _ in range(NEWTON_MAX):
        if live.size == 0:
            break
        q = origin[live] + l[live, None] * direction[live] - base[live]
        value, pieces, grads = tool_gauge(q, axis[live], radius[live], height[live], corner[live])
        top = np.argmax(pieces, axis=1)
        slope = sign * row_dot(grads[np.arange(live.size), top], direction[live])
        inside = value <= 0.0
        miss = ~inside & (slope >= 0.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(inside | miss, 0.0, -value / np.where(slope < 0.0, slope, -1.0))
        l[live] += sign * step
        done = inside | (step <= NEWTON_STEP)
        found[live[done & ~miss]] = l[live[done & ~miss]]
        live = live[~(done | miss)]
    found[live] = l[live]
    return found


def _square_entry(origin, direction, base, axis, radius, height, corner, start, sign, flat):
    """_newton_entry for lines across the axis (flat (K,) True: direction·W = 0) or along it (False).

    Across: the height a is constant along the line, and the tool's section there is a disc: of radius
    R − r + t, t = √(r² − (r − a)₊²), where (r − a)₊ ≤ r and a ≤ H (a corner: dist(q, K) ≤ r); of radius R
    where 0 ≤ a ≤ H (a flat end). The line enters it at a root of |b0 + l·u|² = ρ². Along: |b| is constant,
    and the line is inside where a lies between a_low and H, a_low = r − √(r² − (|b| − (R − r))₊²) (0 for a
    flat end, where |b| ≤ R). The rules of the gauge, so the same points are inside."""
    q = origin - base
    a = row_dot(q, axis)
    b = q - a[:, None] * axis
    bb = row_dot(b, b)
    bend = corner > 0.0
    rim = radius - corner
    with np.errstate(invalid="ignore", divide="ignore"):
        low = np.maximum(corner - a, 0.0)
        reach = np.where(bend, rim + np.sqrt(np.maximum(corner * corner - low * low, 0.0)), radius)
        level = np.where(bend, low <= corner, a >= 0.0) & (a <= height)
        # Across: the roots of uu·l² + 2·bu·l + bb − ρ² = 0.
        uu, bu = row_dot(direction, direction), row_dot(b, direction)
        first, second = _quadratic(uu, bu, bb - reach * reach)
        near, far = np.fmin(first, second), np.fmax(first, second)
        # Along: the heights where the line is inside; a = a0 + l·uw.
        nb = np.sqrt(bb)
        out = np.maximum(nb - rim, 0.0)
        bottom = np.where(bend, corner - np.sqrt(corner * corner - out * out), 0.0)
        fits = np.where(bend, out <= corner, nb <= radius) & (bottom <= height)
        uw = row_dot(direction, axis)
        ends = np.stack([(bottom - a) / uw, (height - a) / uw])
    enter = np.where(flat, near, np.min(ends, axis=0))
    leave = np.where(flat, far, np.max(ends, axis=0))
    hit = np.where(flat, level & ~np.isnan(near), fits)
    if sign > 0.0:
        found = np.where(hit & (leave >= start), np.maximum(enter, start), np.nan)
    else:
        found = np.where(hit & (enter <= start), np.minimum(leave, start), np.nan)
    return found


def line_swept_interval(origin, direction, c0, c1, axis, radius, height, corner):
    """The interval (enter, leave) (K,) mm of each line origin + l·direction (unit) inside the solid of
    the tool (axis, radius, height, corner) moved from c0 to c1; NaN where the line misses it.

    See the module docstring: the crossings with the shadow seen along the move, where the tool's
    position there lies within the move, else Newton's method on the tool standing at the nearer end.
    """
    o, u = np.asarray(origin, dtype=float), np.asarray(direction, dtype=float)
    c0, c1, w = (np.asarray(v, dtype=float) for v in (c0, c1, axis))
    big, h, r = (np.asarray(v, dtype=float) for v in (radius, height, corner))
    m = c1 - c0
    q = o - c0
    k = q.shape[0]
    enter, leave = np.full(k, np.nan), np.full(k, np.nan)
    # The line's span inside a sphere holding the whole solid.
    length = np.sqrt(row_dot(m, m))
    centre = 0.5 * m + 0.5 * h[:, None] * w
    bound = 0.5 * length + np.hypot(big, 0.5 * h)
    along = row_dot(centre - q, u)
    gap = centre - q - along[:, None] * u
    half2 = bound * bound - row_dot(gap, gap)
    near = half2 > 0.0
    half = np.sqrt(np.maximum(half2, 0.0)) * (1.0 + 1e-9) + 1e-9
    low_l, high_l = along - half, along + half
    cross = np.cross(m, u)
    cross_len = np.sqrt(row_dot(cross, cross))
    still = near & (length <= STILL)
    parallel = near & ~still & (cross_len <= STILL * length)
    general = np.flatnonzero(near & ~still & ~parallel)
    fixed = np.flatnonzero(still | parallel)
    if fixed.size:
        # Still, or along the move: the tool at c0, its interval widened by the move's part along the line.
        args = (o[fixed], u[fixed], c0[fixed], w[fixed], big[fixed], h[fixed], r[fixed])
        shift = np.where(parallel[fixed], row_dot(m[fixed], u[fixed]), 0.0)
        first = _newton_entry(*args, low_l[fixed] - np.maximum(shift, 0.0), 1.0)
        last = _newton_entry(*args, high_l[fixed] - np.minimum(shift, 0.0), -1.0)
        enter[fixed] = first + np.minimum(shift, 0.0)
        leave[fixed] = last + np.maximum(shift, 0.0)
    if general.size:
        # A move across the axis (three-axis moves at one height): the shadow is the tool's profile.
        level = row_dot(m[general], w[general]) == 0.0
        l_in, s_in, l_out, s_out = (np.full(general.size, np.nan) for _ in range(4))
        for rows, solve in ((np.flatnonzero(level), _profile_crossings), (np.flatnonzero(~level), None)):
            if rows.size == 0:
                continue
            at = general[rows]
            if solve is None:
                found = _through_shadow(q[at], u[at], m[at], cross[at], cross_len[at], w[at], big[at], h[at], r[at])
            else:
                found = solve(q[at], u[at], m[at], w[at], big[at], h[at], r[at])
            (l_in[rows], s_in[rows]), (l_out[rows], s_out[rows]) = found
        base = (o[general], u[general])
        tool = (w[general], big[general], h[general], r[general])
        for l_val, s_val, start, sign, target in ((l_in, s_in, low_l[general], 1.0, enter),
                                                  (l_out, s_out, high_l[general], -1.0, leave)):
            out = (s_val < 0.0) | (s_val > 1.0)
            result = np.array(l_val)
            rows = np.flatnonzero(out & ~np.isnan(l_val))
            if rows.size:
                at = np.clip(s_val[rows], 0.0, 1.0)
                stand = c0[general][rows] + at[:, None] * m[general][rows]
                result[rows] = _newton_entry(base[0][rows], base[1][rows], stand, *(t[rows] for t in tool),
                                             start[rows], sign)
            target[general] = result
    miss = np.isnan(enter) | np.isnan(leave) | (leave < enter)
    enter[miss] = np.nan
    leave[miss] = np.nan
    return enter, leave


def _through_shadow(q, u, m, cross, cross_len, axis, radius, height, corner):
    """((l_in, s_in), (l_out, s_out)) (K,) each: where the lines q + l·u (relative to c0) enter and leave
    the prism T ⊕ ℝ·m, and the tool's position s there (NaN where they miss it)."""
    nu = cross / cross_len[:, None]
    mm = row_dot(m, m)
    u_across = u - (row_dot(u, m) / mm)[:, None] * m
    speed = np.sqrt(row_dot(u_across, u_across))
    mu = u_across / speed[:, None]
    k = q.shape[0]
    top, top_point = _shadow_signed(np.zeros(k), q, nu, mu, axis, radius, height, corner)
    bottom, bottom_point = _shadow_signed(np.full(k, np.pi), q, nu, mu, axis, radius, height, corner)
    hit = np.flatnonzero((top >= 0.0) & (bottom <= 0.0))
    # Entry on the half-turn π … 2π (the distance rises), exit on π … 0 (it falls): both halves at once, rows
    # hit[i] and then hit[i] again. Keep (angle, value, point) where the distance is ≤ 0 (neg) and > 0 (pos).
    two = np.r_[hit, hit]
    n = hit.size
    q2, u2, m2, mm2, nu2, mu2, speed2 = (v[two] for v in (q, u, m, mm, nu, mu, speed))
    tool = tuple(v[two] for v in (axis, radius, height, corner))
    neg, pos = np.full(2 * n, np.pi), np.r_[np.full(n, 2.0 * np.pi), np.zeros(n)]

    def signed(rows, theta):
        return _shadow_signed(theta, q2[rows], nu2[rows], mu2[rows], *(v[rows] for v in tool))[0]

    # The Illinois method down to the bisection's last bracket (SHADOW_STEPS halvings of π), then the support
    # points at its ends (where a distance was 0, that angle and the last one above).
    _, neg, pos, f_neg, f_pos = monotone_root(signed, neg, pos, bottom[two], top[two], np.pi * 0.5 ** SHADOW_STEPS,
                                              bracket=True)
    f_neg, p_neg = _shadow_signed(neg, q2, nu2, mu2, *tool)
    f_pos, p_pos = _shadow_signed(pos, q2, nu2, mu2, *tool)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(f_pos > f_neg, f_pos / np.where(f_pos > f_neg, f_pos - f_neg, 1.0), 0.0)
    y = p_pos + np.clip(t, 0.0, 1.0)[:, None] * (p_neg - p_pos)
    l = row_dot(y - q2, mu2) / speed2
    s = row_dot(q2 + l[:, None] * u2 - y, m2) / mm2
    out = []
    for half in (slice(0, n), slice(n, 2 * n)):
        l_half, s_half = np.full(k, np.nan), np.full(k, np.nan)
        l_half[hit], s_half[hit] = l[half], s[half]
        out.append((l_half, s_half))
    return out[0], out[1]


def _profile_crossings(q, u, m, axis, radius, height, corner):
    """_through_shadow for moves across the axis (m·W = 0): seen along m the tool is its meridian profile,
    {0 ≤ a ≤ H, |y| ≤ ρ(a)} in the heights a along W and y along e = W × m/|m|, the box |y| ≤ R, 0 ≤ a ≤ H
    less, in each corner {a < r, ±y > R − r}, what lies outside the circle of radius r about (r, ±(R − r)).
    The line's projection enters the box (slabs), and where that point lies in a corner outside its circle,
    the circle (its first root, in closed form at a constant height or along the axis; the line leaves the
    corner inside the circle, so where rounding loses a touching root, there). Likewise where it leaves.
    The tool's position at a point x of the prism's boundary is x·m/|m|² (its part along m)."""
    mm = row_dot(m, m)
    e = np.cross(axis, m)
    e /= np.sqrt(row_dot(e, e))[:, None]
    a0, ua, y0, ue = row_dot(q, axis), row_dot(u, axis), row_dot(q, e), row_dot(u, e)
    rim = radius - corner
    da0 = a0 - corner
    k = q.shape[0]
    with np.errstate(divide="ignore", invalid="ignore"):
        lo, hi = np.full(k, -np.inf), np.full(k, np.inf)
        miss = np.zeros(k, dtype=bool)
        for start, rate, low, high in ((a0, ua, 0.0, height), (y0, ue, -radius, radius)):
            still = rate == 0.0
            miss |= still & ((start < low) | (start > high))
            one, two = (low - start) / rate, (high - start) / rate
            lo = np.where(still, lo, np.maximum(lo, np.minimum(one, two)))
            hi = np.where(still, hi, np.minimum(hi, np.maximum(one, two)))
        miss |= lo > hi
        ends = []
        for end, forward in ((lo, 1.0), (hi, -1.0)):
            end = end.copy()
            for side in (1.0, -1.0):
                a, y = a0 + end * ua, side * (y0 + end * ue)
                out = (a < corner) & (y > rim) & ((a - corner) ** 2 + (y - rim) ** 2 > corner * corner) & ~miss
                if not out.any():
                    continue
                first, second = _quadratic(ua * ua + ue * ue, ua * da0 + side * ue * (side * y0 - rim),
                                           da0 * da0 + (side * y0 - rim) ** 2 - corner * corner)
                near = forward * np.fmin(forward * first, forward * second)
                far = forward * np.fmax(forward * first, forward * second)
                # A projection at a constant height (an end edge) or along the axis, without the quadratic's
                # cancellation where it touches the circle:
                # ±y = R − r + √(r² − (a − r)²), a = r − √(r² − (±y − R + r)²).
                level, upright = ua == 0.0, ue == 0.0
                reach = side * (rim + np.sqrt(np.maximum(corner * corner - da0 * da0, 0.0))) - y0
                y_side = side * y0 - rim
                lift = corner - np.sqrt(np.maximum(corner * corner - y_side * y_side, 0.0)) - a0
                near = np.where(level, reach / ue, np.where(upright, lift / ua, near))
                far = np.where(level | upright, near, far)
                # Where the line leaves the corner, walking from this end: a = r or ±y = R − r.
                leave_a = np.where(forward * ua > 0.0, (corner - a0) / ua, np.inf * forward)
                leave_y = np.where(forward * side * ue < 0.0, (side * rim - y0) / ue, np.inf * forward)
                leave = forward * np.fmin(forward * leave_a, forward * leave_y)
                root = forward * np.fmin(np.fmax(forward * near, forward * end), forward * leave)
                root = np.where(np.isnan(near) | (forward * (far - end) < 0.0), leave, root)
                end = np.where(out, root, end)
            ends.append(end)
        l_in, l_out = ends
        miss |= ~(l_in <= l_out)
    out = []
    for l in (l_in, l_out):
        s = row_dot(q + l[:, None] * u, m) / mm
        out.append((np.where(miss, np.nan, l), np.where(miss, np.nan, s)))
    return out[0], out[1]


def _shadow_signed(theta, q, nu, mu, axis, radius, height, corner):
    """(signed distance (K,), point (K, 3)): the support point σ(n) of each tool for n = cos θ·ν + sin θ·μ,
    and its distance from the line through q along ν (_through_shadow)."""
    n = np.cos(theta)[:, None] * nu + np.sin(theta)[:, None] * mu
    point = support_points(n, axis, radius, height, corner)
    return row_dot(point - q, nu), point
