"""Closed forms in plan view for the edges of a tool with a corner against an earlier move across its axis.

A three-axis or 3+2 program cuts most of its material with moves across the tool axis W (m·W = 0): the earlier
tool (radius R_e, corner r_e, cutting height H_e) moved from c0 to c1 = c0 + m sweeps the points at height
h above its bottom (0 ≤ h ≤ H_e) whose distance across W from the segment c0 … c1 is at most ρ_e(h)
(ρ_e(h) = R_e − r_e + √(r_e² − (r_e − h)²) below r_e, R_e above). When the current tool has the same axis W,
each of its cutting edges meets that solid in closed form (docs/ENGINE.md, "Plan view"):

* a corner arc at the level of the earlier move (its tip at h = 0), of the same tool (R, r equal, H_e ≥ r):
  the arc's point at ψ stands at height r·(1 − cos ψ) and at ρ = R − r + r·sin ψ from the axis, where the
  earlier tool's radius is ρ too; so it is inside where dist(A + ρ·d, segment) ≤ ρ (A the tip seen across W,
  d the edge's direction). dist − ρ is convex in ρ, so that set is one interval, and each of its three parts
  (the discs at the ends, the strip along the segment) is bounded by conditions linear in ρ (the ρ² terms
  cancel). Then ψ = asin((ρ − R + r)/r). An arc whose whole height lies at or below the earlier bottom
  (the tip r or more below it, seen from the earlier move: level ≤ −r) meets it at most in a point.
* a corner arc against an earlier tool whose radius is the same, R_e, at every height of the arc (a flat-end
  mill, or a corner r_e at or below the arc's tip): inside where its plan line A + ρ·d lies within R_e of the
  segment (as an end edge, below) and its height r·(1 − cos ψ) + level within the earlier tool's 0 … H_e
  (ψ = acos of it, exact where the arc stands upright).
* a straight side (a line along W): its distance D across W from the segment is constant, so it is inside
  where ρ_e(h) ≥ D: above h* = r_e − √(r_e² − (D − R_e + r_e)²) (0 for D ≤ R_e − r_e), up to H_e.
* an end edge (a line across W at height h of the earlier move): inside where its distance from the segment
  is at most ρ_e(h), a constant: each disc's chord, linear conditions for the strip.

Points on the boundary are inside; an edge within inprocess_arc.COINCIDENT ulps of its coordinates of a
boundary over its whole length runs along it, and is inside (as inprocess_arc decides such arcs); whether a
straight side meets the solid at all is decided exactly. Shapes: K (edge, piece) pairs, (K, 3)
vectors and (K,) numbers; ψ in radians, lengths in mm.
"""

import numpy as np

from .inprocess_arc import COINCIDENT, arc_swept_intervals
from .inprocess_cover import run_starts
from .inprocess_swept import line_swept_interval
from .ordering import group_order
from .swept import clamp, every_column, line_hull_interval, row_cross, row_dot, rows


def _noise(*vectors, size):
    """(K,) COINCIDENT ulps of the largest coordinate of the vectors (K, 3) plus size (K,)."""
    return COINCIDENT * np.spacing(sum(_largest_column(np.abs(v)) for v in vectors) + size)


def _largest_column(v):
    """(K,) the largest of the three columns of v (K, 3) (np.max over axis 1, in a tenth of its time)."""
    return np.maximum(np.maximum(v[:, 0], v[:, 1]), v[:, 2])


def across(c0, c1, axis):
    """(K,) bool: the moves c0 → c1 (K, 3) that run exactly across their unit axis (K, 3) (m·W = 0)."""
    return row_dot(c1 - c0, axis) == 0.0


def _frame(m, axis):
    """(u, n, length) of the moves m (K, 3) across the axis: unit along, unit across (W × u), length;
    u = n = 0 where the move has no length."""
    length = np.sqrt(row_dot(m, m))
    safe = np.where(length > 0.0, length, 1.0)
    u = m / safe[:, None]
    n = row_cross(axis, u)
    return u, n, length


def _linear(a, b, span, slack):
    """(low, high) (K,): the ρ with a + b·ρ ≤ 0 (an empty one as low > high). span: (low, high) (K,) the range of
    ρ that matters; a condition within slack (K,) of holding over all of it holds everywhere (an edge running
    along that boundary to rounding)."""
    along = np.maximum(a + b * span[0], a + b * span[1]) <= slack
    a, b = np.where(along, -np.inf, a), np.where(along, 0.0, b)
    with np.errstate(divide="ignore", invalid="ignore"):
        root = -a / np.where(b != 0.0, b, 1.0)
    low = np.where(b < 0.0, root, -np.inf)
    high = np.where(b > 0.0, root, np.inf)
    empty = (b == 0.0) & (a > 0.0)
    return np.where(empty, np.inf, low), np.where(empty, -np.inf, high)


def _joined(parts, span):
    """(low, high) (K,): the union of intervals within span (low, high) (K,) known to be one interval there (the
    hull of their non-empty parts within span)."""
    low, high = np.full(parts[0][0].shape, np.inf), np.full(parts[0][0].shape, -np.inf)
    for a, b in parts:
        a, b = np.maximum(a, span[0]), np.minimum(b, span[1])
        full = a <= b
        low = np.where(full, np.minimum(low, a), low)
        high = np.where(full, np.maximum(high, b), high)
    return low, high


def _meet(*parts):
    """(low, high): the intersection of intervals."""
    return np.max([p[0] for p in parts], axis=0), np.min([p[1] for p in parts], axis=0)


def arc_kinds(tip, axis, big, corner, c0, c1, p_axis, p_big, p_height, p_corner):
    """(below, level, steady, above) (K,) bool: the (arc, earlier move) pairs arc_level_intervals decides: as outside
    (the arc r or more below the move), in closed form at its level (the same tool), in closed form where the
    earlier tool's radius is the same at every height of the arc (a flat end, or its corner below the arc), and by
    the monotone bisection of the same tool's level above the arc's tip (less than r above); arguments as there."""
    same_axis = every_column(p_axis == axis) & across(c0, c1, p_axis)
    level = row_dot(tip - c0, axis)
    below = same_axis & (level <= -corner)
    bent = corner > 0.0
    same_tool = (p_big == big) & (p_corner == corner) & (p_height >= corner) & bent
    level_arc = same_axis & (level == 0.0) & same_tool
    steady = same_axis & ~below & ~level_arc & bent & ((p_corner == 0.0) | (level >= p_corner))
    above = same_axis & ~below & (level < 0.0) & same_tool
    return below, level_arc, steady, above


def arc_level_intervals(tip, d, axis, big, corner, top, c0, c1, p_axis, p_big, p_height, p_corner, arc=None,
                        kinds=None):
    """(decided (K,) bool, start, end (K,) ψ in rad) of corner arcs against earlier moves, where the plan view
    decides them (module docstring); start ≥ end (or NaN) where an arc decided here lies outside.

    tip, d, axis (K, 3): the arc's tool tip, its edge's unit direction across the axis and the unit axis; big,
    corner, top (K,): the tool's radius, corner radius and the arc's last ψ; c0, c1, p_axis (K, 3), p_big,
    p_height, p_corner (K,): the earlier move and its tool. arc (K,) ints, if given, names each pair's arc: a pair
    against the same tool above whose removed part lies within another's of the same arc may then come out NaN
    (_arc_above; the union of each arc's parts is the same). kinds: arc_kinds of these pairs, if known."""
    below, level_arc, steady, above = arc_kinds(tip, axis, big, corner, c0, c1, p_axis, p_big, p_height, p_corner) \
        if kinds is None else kinds
    start, end = np.full(tip.shape[0], np.nan), np.full(tip.shape[0], np.nan)
    for kind, solve in ((above, _above_pairs), (level_arc, _level_pairs), (steady, _steady_pairs)):
        at = np.flatnonzero(kind)
        if at.size:
            c0_at = rows(c0, at)
            start[at], end[at] = solve(rows(tip, at) - c0_at, rows(c1, at) - c0_at, *(
                rows(part, at) for part in (d, axis, big, corner, top, p_big, p_height)),
                None if arc is None else rows(arc, at))
    return below | level_arc | steady | above, start, end


def _above_pairs(q, m, d, axis, big, corner, top, p_big, p_height, arc):
    """_arc_above of arc_level_intervals' pairs above (q: the tip from c0, m the move; the others as there)."""
    rise = -row_dot(q, axis)
    return _arc_above(q + rise[:, None] * axis, rise, m, d, big, corner, top, arc)


def _level_pairs(q, m, d, axis, big, corner, top, p_big, p_height, arc):
    """_arc_in_level of arc_level_intervals' pairs at their level (arguments as _above_pairs)."""
    return _arc_in_level(q, m, d, axis, big, corner, top)


def _steady_pairs(q, m, d, axis, big, corner, top, p_big, p_height, arc):
    """_arc_in_cylinder of arc_level_intervals' steady pairs (arguments as _above_pairs)."""
    level = row_dot(q, axis)
    return _arc_in_cylinder(q - level[:, None] * axis, level, m, d, axis, big, corner, top, p_big, p_height)


def arc_piece_intervals(tip, d, axis, centre, big, corner, top, c0, c1, p_axis, p_big, p_height, p_corner,
                        arc=None, kinds=None):
    """(pair, start, end) (K,): the (arc, piece) pairs (K inputs) whose piece removes part of the arc, and that part
    in ψ (rad): arc_level_intervals where the plan view decides, inprocess_arc.arc_swept_intervals for the others
    (each over the whole arc, 0 … top). tip, d, axis, centre (K, 3) and big, corner, top (K,) as there; c0, c1,
    p_axis (K, 3), p_big, p_height, p_corner (K,): the earlier piece and its tool; arc (K,), if given, each pair's
    arc: the pairs may then leave out some whose part lies within another's (each arc's union the same); kinds:
    arc_kinds of the pairs, if known."""
    plan, start, end = arc_level_intervals(tip, d, axis, big, corner, top, c0, c1, p_axis, p_big, p_height, p_corner,
                                           arc, kinds)
    pair = np.flatnonzero(plan & (end > start))
    start, end = rows(start, pair), rows(end, pair)
    rest = np.flatnonzero(~plan)
    if rest.size:
        found = arc_swept_intervals(*(rows(part, rest) for part in (centre, d, axis, corner)), np.zeros(rest.size),
                                    *(rows(part, rest) for part in (top, c0, c1, p_axis, p_big, p_height, p_corner)))
        pair, start, end = np.r_[pair, rest[found[0]]], np.r_[start, found[1]], np.r_[end, found[2]]
    return pair, start, end


#: _arc_above's bracket of ψ* ends at most this wide (rad; r·ABOVE_WIDTH mm along the arc, far below the rounding
#: of the lengths), within ABOVE_STEPS evaluations: where it is more than half as wide as two steps before, the
#: next point bisects it, so from π/2 it takes at most 2 × 51 + 2; a false-position point is kept ABOVE_WIDTH / 4
#: (more than a rounding step of ψ ≤ π/2) inside the bracket, and after a short move of the inner end a probe twice
#: as far beyond it closes the bracket there: about 15 where g is smooth near ψ*.
ABOVE_WIDTH = 1e-15
ABOVE_STEPS = 104


def _arc_above(g0, rise, m, d, big, corner, top, arc=None):
    """(start, end) ψ of arcs against the same tool's earlier move across the axis at a level rise (K,) above the
    arc's tip, 0 < rise < r (g0: the tip from c0 across the axis; m the move). The arc's point at ψ stands at height
    a = r·(1 − cos ψ), where the earlier tool's radius is ρ_e = R − r + √(r² − (r·cos ψ + rise)²) (from
    ψ₀ = acos(1 − rise/r) on; below it the earlier tool is not there), at ρ = R − r + r·sin ψ from the axis. Its
    distance from the segment less ρ_e, g(ψ), is non-increasing (the distance changes no faster than ρ, ρ_e grows at
    least as fast: docs/ENGINE.md, "The level view for tools with a corner"), so the removed part is a suffix
    ψ* … top, ψ* the first ψ where g ≤ 0, bracketed by false position (Illinois) guarded by bisection down to
    ABOVE_WIDTH; NaN where the arc's top is outside. With arc (K,) (each pair's arc) only the least ψ* of an arc
    matters (its pairs' parts all end at top): first the pairs removing the arc from the earlier tool's bottom up
    (ψ* = ψ₀) and, of each other arc, its pair deepest inside at the top are solved; then of the other pairs only
    those inside at their arc's least ψ* so far (g ≤ 0 there: ψ* no later) — the rest remove a part within it
    (g > 0 there, g non-increasing and nothing below ψ₀: their ψ* lies later) and come out NaN."""
    rim = big - corner
    length = row_dot(m, m)
    inverse = np.where(length > 0.0, 1.0 / np.where(length > 0.0, length, 1.0), 0.0)

    def gather(at):
        return tuple(rows(part, at) for part in (g0, rim, corner, d, m, inverse, rise))

    def gap(psi, pairs):
        g0, rim, corner, d, m, inverse, rise = pairs
        q = g0 + (rim + corner * np.sin(psi))[:, None] * d
        t = clamp(row_dot(q, m) * inverse, 0.0, 1.0)
        foot = q - t[:, None] * m
        depth = corner * np.cos(psi) + rise
        return np.sqrt(row_dot(foot, foot)) - rim - np.sqrt(np.maximum(corner ** 2 - depth * depth, 0.0))

    every = (g0, rim, corner, d, m, inverse, rise)
    first = np.minimum(np.arccos(clamp(1.0 - rise / corner, -1.0, 1.0)), top)
    at_top, at_first = gap(top, every), gap(first, every)
    start = np.where(at_first <= 0.0, first, top)
    open_ = np.flatnonzero((at_top <= 0.0) & (at_first > 0.0))
    if arc is None or open_.size == 0:
        _bracketed(gap, gather, open_, first, top, at_first, at_top, start)
    else:
        key = arc[open_]
        order = group_order(at_top[open_], key)
        lead = np.zeros(open_.size, dtype=bool)
        lead[order[run_starts(key[order])[0]]] = True
        least = np.full(arc.max() + 1, np.inf)
        whole = np.flatnonzero((at_top <= 0.0) & (at_first <= 0.0))
        np.minimum.at(least, arc[whole], first[whole])
        lead &= np.isinf(least[key])
        _bracketed(gap, gather, open_[lead], first, top, at_first, at_top, start)
        np.minimum.at(least, key[lead], start[open_[lead]])
        rest = open_[~lead]
        later = gap(least[arc[rest]], gather(rest)) > 0.0
        _bracketed(gap, gather, rest[~later], first, top, at_first, at_top, start)
        start[rest[later]] = np.nan
    inside = (at_top <= 0.0) & ~np.isnan(start)
    return np.where(inside, start, np.nan), np.where(inside, top, np.nan)


def _bracketed(gap, gather, rows, first, top, at_first, at_top, start):
    """Fill start[rows] with ψ* of _arc_above's pairs rows (g(first) > 0 ≥ g(top)): false position with probes and
    guarded bisection (ABOVE_WIDTH, ABOVE_STEPS); gap(ψ, gather(rows)) is g of those rows (their data gathered
    once, and again only as pairs finish)."""
    NUDGE = 0.25 * ABOVE_WIDTH
    if rows.size == 0:
        return
    pairs = gather(rows)
    outer, inner, g_outer, g_inner = first[rows], top[rows], at_first[rows], at_top[rows]  # g_outer > 0 ≥ g_inner
    back, earlier = np.full(rows.size, np.inf), np.full(rows.size, np.inf)  # the width one and two steps back
    moved = np.zeros(rows.size, dtype=np.int8)
    step = np.full(rows.size, np.inf)  # how far the last point moved the inner end (inf: it did not)
    for _ in range(ABOVE_STEPS):
        width = inner - outer
        live = width > ABOVE_WIDTH
        if not live.all():  # the arcs done leave the arrays
            start[rows[~live]] = inner[~live]
            rows, outer, inner, g_outer, g_inner, back, earlier, moved, step, width = (
                part[live] for part in (rows, outer, inner, g_outer, g_inner, back, earlier, moved, step, width))
            if rows.size == 0:
                break
            pairs = tuple(part[live] for part in pairs)
        with np.errstate(invalid="ignore", divide="ignore"):
            x = clamp(inner - g_inner * width / (g_inner - g_outer), outer + NUDGE, inner - NUDGE)
        x = np.where((x > outer) & (x < inner), x, 0.5 * (outer + inner))
        x = np.where(4.0 * step < width, inner - 2.0 * step, x)
        x = np.where(width > 0.5 * earlier, 0.5 * (outer + inner), x)
        g = gap(x, pairs)
        out = g > 0.0
        # Illinois: an end kept twice in a row has its value halved, so that the next point moves past it.
        g_inner = np.where(out, np.where(moved == 1, 0.5 * g_inner, g_inner), g)
        g_outer = np.where(out, g, np.where(moved == -1, 0.5 * g_outer, g_outer))
        step = np.where(out, np.inf, np.maximum(inner - x, NUDGE))
        outer, inner = np.where(out, x, outer), np.where(out, inner, x)
        moved = np.where(out, 1, -1).astype(np.int8)
        back, earlier = width, back
    start[rows] = inner


def _arc_in_level(g0, m, d, axis, big, corner, top):
    """(start, end) ψ of arcs of tools at the level of an earlier move of the same tool (conditions linear in ρ;
    module docstring): g0 the tip from c0 (across the axis), m the move."""
    u, n, length = _frame(m, axis)
    rim = big - corner
    span = (rim, rim + corner * np.sin(top))
    noise = _noise(g0, m, size=big)
    parts = [_linear(row_dot(g, g), 2.0 * row_dot(g, d), span, 2.0 * big * noise) for g in (g0, g0 - m)]
    along, side = row_dot(u, g0), row_dot(n, g0)
    ud, nd = row_dot(u, d), clamp(row_dot(n, d), -1.0, 1.0)
    strip = _meet(_linear(-along, -ud, span, noise), _linear(along - length, ud, span, noise),
                  _linear(side, nd - 1.0, span, noise), _linear(-side, -nd - 1.0, span, noise))
    parts.append((np.where(length > 0.0, strip[0], np.inf), np.where(length > 0.0, strip[1], -np.inf)))
    low, high = _joined(parts, span)
    return _psi(low, high, rim, corner, top)


def _arc_in_cylinder(g0, level, m, d, axis, big, corner, top, p_big, p_height):
    """(start, end) ψ of arcs against earlier moves whose tool has the radius p_big at every height of the arc
    (a flat end, or a corner below the arc; module docstring): the arc's points within p_big of the segment
    across the axis (the plan line A + ρ·d, _stadium) and within the earlier tool's heights 0 … p_height. g0: the
    tip from c0 across the axis; level: the tip's height above c0; m the move."""
    start, end = _psi(*_stadium(g0, d, m, axis, p_big, _noise(g0, m, size=big + p_big)), big - corner, corner, top)
    # The heights, a = r·(1 − cos ψ) above the tip, from −level (the earlier bottom) up to p_height − level.
    low_a, high_a = -level, p_height - level
    with np.errstate(invalid="ignore"):
        start = np.maximum(start, np.where(low_a > 0.0, np.arccos(clamp(1.0 - low_a / corner, -1.0, 1.0)), 0.0))
        end = np.minimum(end, np.where(high_a < corner, np.arccos(clamp(1.0 - high_a / corner, -1.0, 1.0)), top))
    return start, np.where((high_a >= 0.0) & (start <= end), end, np.nan)


def _psi(low, high, rim, corner, top):
    """(start, end) ψ of the arcs' points at ρ = rim + r·sin ψ from low to high (ρ, mm), within 0 … top; end NaN
    where low > high."""
    low = np.maximum(low, rim)
    high = np.minimum(high, rim + corner * np.sin(top))
    with np.errstate(invalid="ignore"):
        start = np.arcsin(clamp((low - rim) / corner, 0.0, 1.0))
        end = np.arcsin(clamp((high - rim) / corner, 0.0, 1.0))
    start = np.where(low <= rim, 0.0, np.minimum(start, top))
    end = np.where(high >= rim + corner * np.sin(top), top, end)
    return start, np.where(low <= high, end, np.nan)


def earlier_radius(h, big, corner):
    """ρ_e(h) (K,): the radius of tools (big, corner (K,)) at height h (K,) above their bottom, within their
    cutting height."""
    with np.errstate(invalid="ignore"):
        bent = big - corner + np.sqrt(np.maximum(corner * corner - (corner - h) ** 2, 0.0))
    return np.where(h < corner, bent, big)


def line_level_interval(origin, direction, c0, c1, axis, big, height, corner):
    """(decided (K,) bool, enter, leave (K,) mm) of lines origin + l·direction (unit) in the solids of earlier
    moves across their axis, where the plan view decides them: lines along the axis (straight sides) and
    across it (end edges); NaN where a decided line misses the solid (module docstring)."""
    moves = across(c0, c1, axis)
    upright = moves & every_column(direction == axis)
    flat = moves & (row_dot(direction, axis) == 0.0)
    enter, leave = np.full(origin.shape[0], np.nan), np.full(origin.shape[0], np.nan)
    rows = np.flatnonzero(upright)
    if rows.size:
        enter[rows], leave[rows] = _side_in_move(origin[rows] - c0[rows], c1[rows] - c0[rows], axis[rows],
                                                 big[rows], height[rows], corner[rows])
    rows = np.flatnonzero(flat)
    if rows.size:
        enter[rows], leave[rows] = _end_in_move(origin[rows] - c0[rows], direction[rows], c1[rows] - c0[rows],
                                                axis[rows], big[rows], height[rows], corner[rows])
    return upright | flat, enter, leave


def piece_line_interval(origin, direction, c0, c1, axis, big, height, corner):
    """(enter, leave) (K,) mm of the lines origin + l·direction (unit, (K, 3)) in the solids swept by pieces (c0, c1,
    axis (K, 3), big, height, corner (K,)), NaN where one misses: swept.line_hull_interval for flat-end tools (closed
    form), line_level_interval where the plan view decides (moves across the axis, lines along or across it),
    inprocess_swept.line_swept_interval for the others."""
    bent = corner > 0.0
    if not bent.any():
        return line_hull_interval(origin, direction, c0, c1, axis, big, height)
    enter, leave = np.full(corner.size, np.nan), np.full(corner.size, np.nan)
    hulls = (c0, c1, axis, big, height)
    flat = np.flatnonzero(~bent)
    if flat.size:
        enter[flat], leave[flat] = line_hull_interval(origin[flat], direction[flat], *(h[flat] for h in hulls))
    bent = np.flatnonzero(bent)
    plan, enter[bent], leave[bent] = line_level_interval(origin[bent], direction[bent], *(h[bent] for h in hulls),
                                                         corner[bent])
    bent = bent[~plan]
    if bent.size:
        enter[bent], leave[bent] = line_swept_interval(origin[bent], direction[bent], *(h[bent] for h in hulls),
                                                       corner[bent])
    return enter, leave


def _side_in_move(q, m, axis, big, height, corner):
    """(enter, leave) of lines along the axis from q (the origin from c0): module docstring."""
    up = row_dot(q, axis)
    g = q - up[:, None] * axis
    u, _, length = _frame(m, axis)
    t = clamp(row_dot(g, u), 0.0, length)
    gap = g - t[:, None] * u
    dist = np.sqrt(row_dot(gap, gap))
    reach = earlier_radius(height, big, corner)
    # Compared exactly, as inprocess_swept's Newton entry from outside decides it.
    on = dist <= reach
    rim = big - corner
    with np.errstate(invalid="ignore"):
        lift = corner - np.sqrt(np.maximum(corner * corner - (dist - rim) ** 2, 0.0))
    lift = np.where(dist <= rim, 0.0, np.minimum(lift, height))
    return np.where(on, lift - up, np.nan), np.where(on, height - up, np.nan)


def _end_in_move(q, direction, m, axis, big, height, corner):
    """(enter, leave) of lines across the axis from q (the origin from c0): module docstring."""
    h = row_dot(q, axis)
    inside = (h >= 0.0) & (h <= height)
    f = earlier_radius(clamp(h, 0.0, height), big, corner)
    low, high = _stadium(q - h[:, None] * axis, direction, m, axis, f, _noise(q, m, size=big + height))
    hit = inside & (low <= high)
    return np.where(hit, low, np.nan), np.where(hit, high, np.nan)


def _stadium(g0, direction, m, axis, f, noise):
    """(low, high) (K,): where the lines g0 + l·direction (across the axis, g0 from c0) lie within f (K,) of the
    segments 0 … m (an empty one as low > high): each disc's chord and the strip's four linear conditions (module
    docstring); noise (K,): the rounding within which a line is tangent, or runs along the strip's side."""
    u, n, length = _frame(m, axis)
    dd = row_dot(direction, direction)
    parts = []
    for g in (g0, g0 - m):
        # The disc's chord: half-length √(f² − p²) about the foot of the centre, p the centre's distance from the
        # line; a line within rounding of tangent touches it at the foot.
        foot = -row_dot(g, direction) / dd
        cross = np.cross(g, direction)
        p = np.sqrt(row_dot(cross, cross) / dd)
        gap = f - p
        half = np.where(gap > noise, np.sqrt(np.maximum(gap * (f + p), 0.0) / dd), 0.0)
        meets = gap >= -noise
        parts.append((np.where(meets, foot - half, np.inf), np.where(meets, foot + half, -np.inf)))
    along, side = row_dot(u, g0), row_dot(n, g0)
    ud, nd = row_dot(u, direction), row_dot(n, direction)
    # Beyond this far along the line no point is within f of the segment.
    far = np.sqrt(row_dot(g0, g0)) + length + f
    span = (-far, far)
    strip = _meet(_linear(-along, -ud, span, noise), _linear(along - length, ud, span, noise),
                  _linear(side - f, nd, span, noise), _linear(-side - f, -nd, span, noise))
    parts.append((np.where(length > 0.0, strip[0], np.inf), np.where(length > 0.0, strip[1], -np.inf)))
    return _joined(parts, span)
