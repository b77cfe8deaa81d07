"""The corner arcs of bull-nose and ball-end mills against a 2.5D terraced stock, exactly.

A tool of radius R with corner radius r has, at rotation angle φ, a peripheral cutting edge whose
lowest part is the quarter arc of the corner (docs/ENGINE.md, "Tools with a corner"):

    P(ψ) = C + r·sin ψ·d − r·cos ψ·w,   0 ≤ ψ ≤ ψ_max,   C = T + (R − r)·d + r·w,

d = sin φ·u + cos φ·v the radial direction of the flute, w the tool axis, ψ the angle along the
arc from its lowest point (height 0 above the tip, radius R − r) to ψ = 90° (height r, radius R);
ψ_max < 90° when the flute is shorter than the corner. Its arc length is s = r·ψ, and ψ is also
the angle κ between the axis and the normal of the tool's surface there.

The arc lies in the plane of d and w, so:

* against a level z = c (a slab's bottom or top) it is a trigonometric equation
  a·cos ψ + b·sin ψ = c' with closed-form roots, at most two in [0, ψ_max];
* its plan projection is the ellipse arc Q(ψ) = C_p + A·cos ψ + B·sin ψ (A = −r·w_p,
  B = r·d_p, the plan parts), whose implicit equation |adj(M)·(Q − C_p)|² − det(M)² = 0
  (M = [A B]) is of degree 2. On a rational Bézier piece of a slab's boundary, of degree k, it
  is a polynomial of degree 2k in the piece's parameter: its changes of sign are the crossings,
  found as terraced.side_changes finds a plan line's (the same side rule at joints, a tangent
  contact no crossing). Each crossing's ψ comes from the point (the 2 × 2 solve, then Newton on
  the distance to the ellipse) and counts when it lies on the arc;
* where the ellipse is flat (its smaller semi-axis below FLAT mm, as for an upright tool, whose
  corner projects onto a radial segment) the plan line through C_p along it is crossed instead
  (terraced.plan_crossings) and each crossing's ψ solves a·cos ψ + b·sin ψ = t.

Along each arc the state inside or outside a slab's region starts from the parity of the
crossings of a ray along +x from the arc's first point, and changes at every crossing; a piece
of the arc between consecutive breakpoints (crossings, levels, its ends) is inside when its
middle is within the slab's levels and inside its region. Runs are merged across slabs as the
terraced lines' are. Labels as terraced: "top", "bottom" (a level), "straight_wall",
"curved_wall" (a boundary curve), "flute_start" (the arc's lowest point inside the material),
"flute_end" (its last point inside the material, when the flute ends within the corner);
CORNER_TOP marks a run that reaches the arc's top at 90°, where the straight side goes on.

Shapes: N arcs; centre, d, w (N, 3) (mm, unit vectors); r and ψ_max floats. Lengths in mm.
"""

import functools

import numpy as np

from .engagement import SURFACES
from .intervals import EdgeIntervals
from .ordering import group_order
from .polynomials import guarded_root, horner, product
from .terraced import merged_intervals, plan_crossings, side_changes
from .terraced_pieces import bernstein_to_power, slab_pieces

_CODE = {name: SURFACES.index(name) for name in ("top", "straight_wall", "curved_wall", "flute_end", "bottom",
                                                    "flute_start")}
#: Label (internal) of a run that reaches the corner's top at 90°, where the straight side continues.
CORNER_TOP = -2
#: A plan ellipse whose smaller semi-axis is below this (mm) is taken as the segment it nearly is.
FLAT = 1e-9
#: Levels of halving in the isolation of a piece's crossings (isolated_changes) before the general root finder.
SPLIT_DEPTH = 6
#: Bound on arcs × pieces held at once.
CHUNK_VALUES = 1 << 20
#: Kinds of breakpoint along an arc.
_START, _END, _PLAN, _BOTTOM, _TOP = range(5)


def corner_intervals(stock, centre, d, w, radius, psi_max, pieces=None):
    """Inside intervals of N corner arcs in a TerracedStock, in arc length s = r·ψ (mm) from each arc's
    lowest point (see the module docstring); EdgeIntervals with the labels there. pieces: the
    stock's slab_pieces when already made."""
    groups, straight = slab_pieces(stock) if pieces is None else pieces
    c = np.asarray(centre, dtype=float).reshape(-1, 3)
    d = np.asarray(d, dtype=float).reshape(-1, 3)
    w = np.asarray(w, dtype=float).reshape(-1, 3)
    n, r, top = c.shape[0], float(radius), float(psi_max)
    # z(ψ) = c_z + a_z cos ψ + b_z sin ψ; plan Q(ψ) = C_p + A cos ψ + B sin ψ.
    a, b = -r * w, r * d
    start_plan = c[:, :2] + a[:, :2]
    wall_code = np.where(straight, _CODE["straight_wall"], _CODE["curved_wall"])
    found = []
    top_slab = len(stock.slabs) - 1
    for k, slab in enumerate(stock.slabs):
        rows = _near_levels(c[:, 2], a[:, 2], b[:, 2], top, slab.z_bottom, slab.z_top)
        if rows.size == 0:
            continue
        events = [_level_events(rows, c[rows, 2], a[rows, 2], b[rows, 2], top, level, kind)
                  for level, kind in ((slab.z_bottom, _BOTTOM), (slab.z_top, _TOP))]
        events.append(_plan_events(groups[k], rows, c[rows, :2], a[rows, :2], b[rows, :2], top))
        ray_rows, ray_at, _ = plan_crossings(groups[k], start_plan[rows, 0], start_plan[rows, 1],
                                             np.ones(rows.size), np.zeros(rows.size), isolated_changes)
        inside_start = np.bincount(ray_rows[ray_at > 0.0], minlength=rows.size) % 2 == 1
        runs = _runs(rows, events, inside_start, c[rows, 2], a[rows, 2], b[rows, 2], top, slab.z_bottom, slab.z_top,
                     k == top_slab, wall_code)
        found.append(runs + (np.full(runs[0].size, k),))
    merged = merged_intervals(n, [(rows, r * s0, r * s1, c0, w0, c1, w1, k) for rows, s0, s1, c0, w0, c1, w1, k
                                  in found])
    return merged


def _near_levels(z0, az, bz, top, z_bottom, z_top):
    """Rows whose arc's z range over [0, top] meets [z_bottom, z_top]."""
    low, high = _range(z0, az, bz, top)
    return np.flatnonzero((high >= z_bottom) & (low <= z_top))


def _range(c, a, b, top):
    """(low, high) of c + a cos ψ + b sin ψ over ψ in [0, top] (N,): at the ends and at the turning point."""
    candidates = [np.zeros_like(c), np.full_like(c, top)]
    turn = np.mod(np.arctan2(b, a), np.pi)  # where −a sin ψ + b cos ψ = 0, in [0, π)
    candidates.append(np.where(turn <= top, turn, 0.0))
    values = np.stack([c + a * np.cos(t) + b * np.sin(t) for t in candidates])
    return values.min(axis=0), values.max(axis=0)


def trig_roots(a, b, c, top):
    """(N, 2) roots ψ in [0, top] of a cos ψ + b sin ψ = c (N,), NaN-padded, ascending; a tangent root once."""
    rho = np.hypot(a, b)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = c / rho
        spread = np.arccos(np.clip(ratio, -1.0, 1.0))
    base = np.arctan2(b, a)
    real = (rho > 0.0) & (np.abs(ratio) <= 1.0)
    roots = np.stack([base - spread, base + spread], axis=1)
    roots = np.mod(roots, 2.0 * np.pi)
    roots = np.where(roots > top + np.pi, roots - 2.0 * np.pi, roots)  # −small angles wrapped to near 2π
    roots = np.where((roots < 0.0) & (roots > -1e-12), 0.0, np.where((roots > top) & (roots < top + 1e-12), top,
                                                                          roots))
    inside = real[:, None] & (roots >= 0.0) & (roots <= top)
    roots = np.where(inside, roots, np.nan)
    roots[:, 1] = np.where(np.isclose(roots[:, 1], roots[:, 0], rtol=0.0, atol=1e-15), np.nan, roots[:, 1])
    return np.sort(roots, axis=1)


def _level_events(rows, z0, az, bz, top, level, kind):
    """Breakpoints where each arc's z is `level`: (local row (E,), ψ (E,), kind, wall −1)."""
    roots = trig_roots(az, bz, level - z0, top)
    local, slot = np.nonzero(~np.isnan(roots))
    return local, roots[local, slot], np.full(local.size, kind), np.full(local.size, -1)


def _plan_events(groups, rows, cp, ap, bp, top):
    """Crossings of each arc's plan ellipse arc with the slab's boundary pieces: (local row, ψ, _PLAN, wall)."""
    det = ap[:, 0] * bp[:, 1] - ap[:, 1] * bp[:, 0]
    major = np.maximum(np.hypot(*ap.T), np.hypot(*bp.T))
    with np.errstate(divide="ignore", invalid="ignore"):
        flat = ~(np.abs(det) / np.where(major > 0.0, major, 1.0) > FLAT)
    parts = [_flat_crossings(groups, np.flatnonzero(flat), cp, ap, bp, top),
             _ellipse_crossings(groups, np.flatnonzero(~flat), cp, ap, bp, det, top)]
    local, psi, wall = (np.concatenate(v) for v in zip(*parts))
    return local, psi, np.full(local.size, _PLAN), wall


def _flat_crossings(groups, rows, cp, ap, bp, top):
    """Crossings of flat ellipses (a segment in plan): the plan line along the longer of A, B, each line
    crossing t solved for ψ (up to two: the segment may be traced back)."""
    if rows.size == 0:
        return np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0, dtype=np.intp)
    longer = np.where((np.hypot(*ap[rows].T) >= np.hypot(*bp[rows].T))[:, None], ap[rows], bp[rows])
    size = np.hypot(*longer.T)
    moving = size > 0.0
    rows, longer, size = rows[moving], longer[moving], size[moving]  # a point in plan (r = 0) crosses nothing
    ux, uy = longer[:, 0] / size, longer[:, 1] / size
    at_rows, at, wall = plan_crossings(groups, cp[rows, 0], cp[rows, 1], ux, uy, isolated_changes)
    g = rows[at_rows]
    along_a = ap[g, 0] * ux[at_rows] + ap[g, 1] * uy[at_rows]
    along_b = bp[g, 0] * ux[at_rows] + bp[g, 1] * uy[at_rows]
    roots = trig_roots(along_a, along_b, at, top)
    pick, slot = np.nonzero(~np.isnan(roots))
    return g[pick], roots[pick, slot], wall[pick]


def _ellipse_crossings(groups, rows, cp, ap, bp, det, top):
    """Crossings of proper ellipse arcs with the pieces: sign changes of the implicit equation on each piece."""
    empty = (np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0, dtype=np.intp))
    if rows.size == 0:
        return empty
    low_x, high_x = _range(cp[rows, 0], ap[rows, 0], bp[rows, 0], top)
    low_y, high_y = _range(cp[rows, 1], ap[rows, 1], bp[rows, 1], top)
    # adj(M) = [[B_y, −B_x], [−A_y, A_x]]: rows of the two linear forms of Q − C_p.
    f1 = np.column_stack([bp[rows, 1], -bp[rows, 0]])
    f2 = np.column_stack([-ap[rows, 1], ap[rows, 0]])
    out = []
    for group in groups:
        k = group.degree
        per = max(1, CHUNK_VALUES // max(1, group.control.shape[0]))
        to_bernstein = _bases(2 * k)[1]
        for first in range(0, rows.size, per):
            sl = slice(first, first + per)
            gap_x = np.maximum(low_x[sl, None] - group.centre[:, 0], group.centre[:, 0] - high_x[sl, None])
            gap_y = np.maximum(low_y[sl, None] - group.centre[:, 1], group.centre[:, 1] - high_y[sl, None])
            near = np.hypot(np.maximum(gap_x, 0.0), np.maximum(gap_y, 0.0)) <= group.radius * (1 + 1e-9) + 1e-9
            arc, piece = np.nonzero(near)
            if arc.size == 0:
                continue
            arc = arc + first
            h = group.homogeneous[piece]                       # (P, k+1, 3) power basis of (wx, wy, w)
            x, y, weight = h[..., 0], h[..., 1], h[..., 2]
            rx, ry = x - cp[rows[arc], 0, None] * weight, y - cp[rows[arc], 1, None] * weight
            l1 = f1[arc, 0, None] * rx + f1[arc, 1, None] * ry
            l2 = f2[arc, 0, None] * rx + f2[arc, 1, None] * ry
            g = product(l1, l1) + product(l2, l2) - det[rows[arc], None] ** 2 * product(weight, weight)
            scale = np.abs(g).max(axis=1, keepdims=True)
            g = g / np.where(scale > 0.0, scale, 1.0)
            bernstein = g @ to_bernstein.T
            # A polynomial whose Bernstein coefficients all lie on one side of 0 keeps that side on the whole
            # piece (it lies in their hull): no crossing; the rest go to the root finder.
            mixed = np.flatnonzero((bernstein >= 0.0).any(axis=1) & (bernstein < 0.0).any(axis=1))
            if mixed.size == 0:
                continue
            arc, piece, h = arc[mixed], piece[mixed], h[mixed]
            pair, u = isolated_changes(2 * k, bernstein[mixed])
            if pair.size == 0:
                continue
            point = horner(np.moveaxis(h[pair], 1, -1), u[:, None])
            q = np.column_stack([point[:, 0] / point[:, 2], point[:, 1] / point[:, 2]])
            at_start, at_end = u == 0.0, u == 1.0
            q = np.where(at_start[:, None], group.control[piece[pair], 0], np.where(
                at_end[:, None], group.control[piece[pair], k], q))
            g_rows = rows[arc[pair]]
            psi = _ellipse_angle(q, cp[g_rows], ap[g_rows], bp[g_rows], det[g_rows])
            keep = (psi >= 0.0) & (psi <= top)
            out.append((g_rows[keep], psi[keep], group.wall[piece[pair]][keep]))
    if not out:
        return empty
    return tuple(np.concatenate(v) for v in zip(*out))


def isolated_changes(degree, bernstein):
    """terraced.side_changes of M polynomials given by their Bernstein coefficients (M, degree + 1) on
    [0, 1]: (pair, u), sorted by pair.

    Descartes' rule of signs in the Bernstein basis isolates the roots: a piece of [0, 1] whose
    coefficients (found by de Casteljau halving) have no change of sign holds no root, and one whose
    coefficients are all nonzero with one change holds exactly one, simple, where the side changes
    once; it is refined in that piece alone. A polynomial the halving does not settle within
    SPLIT_DEPTH levels (roots closer than 2^−SPLIT_DEPTH, a tangency, a coefficient 0 at a
    split) goes whole to side_changes.
    """
    if degree == 1:
        return side_changes(1, bernstein)  # in closed form
    m = bernstein.shape[0]
    owner, lo, width, coefficients = np.arange(m), np.zeros(m), np.ones(m), bernstein
    found_owner, found_lo, found_width, found_coefficients = [], [], [], []
    unsettled = np.zeros(m, dtype=bool)
    for depth in range(SPLIT_DEPTH + 1):
        negative = np.signbit(coefficients) & (coefficients != 0.0)
        variations = (negative[:, 1:] != negative[:, :-1]).sum(axis=1)
        nonzero = (coefficients != 0.0).all(axis=1)
        one_sign = nonzero & (variations == 0) | (negative.all(axis=1) | (coefficients >= 0.0).all(axis=1))
        single = nonzero & (variations == 1)
        found_owner.append(owner[single])
        found_lo.append(lo[single])
        found_width.append(width[single])
        found_coefficients.append(coefficients[single])
        split = ~(one_sign | single)
        if depth == SPLIT_DEPTH:
            unsettled[owner[split]] = True
            break
        owner, lo, width, coefficients = owner[split], lo[split], width[split], coefficients[split]
        if owner.size == 0:
            break
        left, right = _halves(coefficients)
        owner = np.concatenate([owner, owner])
        lo = np.concatenate([lo, lo + 0.5 * width])
        width = np.concatenate([0.5 * width, 0.5 * width])
        coefficients = np.concatenate([left, right])
    owner, lo, width, coefficients = (np.concatenate(v) for v in (found_owner, found_lo, found_width,
                                                                  found_coefficients))
    keep = ~unsettled[owner]
    owner, lo, width, coefficients = owner[keep], lo[keep], width[keep], coefficients[keep]
    power = coefficients @ _bases(degree)[0].T
    local = guarded_root(np.ascontiguousarray(power.T), np.zeros(owner.size), np.ones(owner.size),
                         coefficients[:, 0], coefficients[:, -1])
    rest = np.flatnonzero(unsettled)
    pair, at = side_changes(degree, bernstein[rest]) if rest.size else (np.zeros(0, dtype=np.intp), np.zeros(0))
    pair, at = np.concatenate([owner, rest[pair]]), np.concatenate([lo + width * local, at])
    order = group_order(at, pair)
    return pair[order], at[order]


@functools.lru_cache(maxsize=None)
def _bases(degree):
    """(Bernstein -> power, power -> Bernstein) matrices of one degree, made once."""
    to_power = bernstein_to_power(degree)
    return to_power, np.linalg.inv(to_power)


def _halves(coefficients):
    """Bernstein coefficients (M, d + 1) of each polynomial on the two halves of its interval (de Casteljau)."""
    d = coefficients.shape[1] - 1
    rows = [coefficients]
    for _ in range(d):
        previous = rows[-1]
        rows.append(0.5 * (previous[:, :-1] + previous[:, 1:]))
    left = np.stack([row[:, 0] for row in rows], axis=1)
    right = np.stack([row[:, -1] for row in rows[::-1]], axis=1)
    return left, right


def _ellipse_angle(q, cp, ap, bp, det):
    """ψ (E,) of plan points q (E, 2) on their ellipses C_p + A cos ψ + B sin ψ: the 2 × 2 solve, then
    Newton on (E(ψ) − q)·E'(ψ) = 0, the nearest point's angle; mapped into (−π, π] then the arc's side."""
    rel = q - cp
    cos = (bp[:, 1] * rel[:, 0] - bp[:, 0] * rel[:, 1]) / det
    sin = (ap[:, 0] * rel[:, 1] - ap[:, 1] * rel[:, 0]) / det
    psi = np.arctan2(sin, cos)
    for _ in range(2):
        c, s = np.cos(psi), np.sin(psi)
        point = ap * c[:, None] + bp * s[:, None]
        tangent = -ap * s[:, None] + bp * c[:, None]
        second = -point
        miss = point - rel
        slope = (tangent * tangent).sum(axis=1) + (miss * second).sum(axis=1)
        step = (miss * tangent).sum(axis=1) / np.where(slope != 0.0, slope, 1.0)
        psi = psi - np.where(slope != 0.0, step, 0.0)
    # Angles just below 0 from rounding belong to the arc's start.
    return np.where((psi < 0.0) & (psi > -1e-12), 0.0, psi)


def _runs(rows, events, inside_start, z0, az, bz, top, z_bottom, z_top, is_top, wall_code):
    """Inside runs of the arcs `rows` within one slab: (rows, ψ start, ψ end, start code, start wall, end code,
    end wall), from the breakpoint `events` (local row, ψ, kind, wall) and each arc's starting side."""
    m = rows.size
    local = np.concatenate([np.arange(m), np.arange(m)] + [e[0] for e in events])
    psi = np.concatenate([np.zeros(m), np.full(m, top)] + [e[1] for e in events])
    kind = np.concatenate([np.full(m, _START), np.full(m, _END)] + [e[2] for e in events])
    wall = np.concatenate([np.full(2 * m, -1)] + [e[3] for e in events])
    order = np.lexsort((kind == _END, psi, local))  # the end last at its angle
    local, psi, kind, wall = local[order], psi[order], kind[order], wall[order]
    plan = (kind == _PLAN).astype(np.int64)
    # Plan parity after each breakpoint: the start's, changed at every plan crossing of the row so far.
    first_of_row = np.searchsorted(local, np.arange(m))
    crossed = np.cumsum(plan) - np.repeat(np.cumsum(plan)[first_of_row] - plan[first_of_row], np.bincount(local, minlength=m))
    region = inside_start[local] ^ (crossed % 2 == 1)
    same = local[1:] == local[:-1]
    middle = 0.5 * (psi[1:] + psi[:-1])
    z = z0[local[:-1]] + az[local[:-1]] * np.cos(middle) + bz[local[:-1]] * np.sin(middle)
    within = (z >= z_bottom) & ((z <= z_top) if is_top else (z < z_top))
    inside = same & region[:-1] & within & (psi[1:] > psi[:-1])
    # Runs: maximal sequences of inside pieces (an empty piece between two inside ones keeps the run).
    piece = np.flatnonzero(inside)
    if piece.size == 0:
        empty = np.zeros(0, dtype=np.intp)
        return empty, np.zeros(0), np.zeros(0), empty, empty, empty, empty
    joined = np.zeros(piece.size, dtype=bool)
    gap = piece[1:] - piece[:-1]
    adjacent = (local[piece[1:]] == local[piece[:-1]]) & ((gap == 1) | (
        (gap == 2) & (psi[piece[1:]] == psi[piece[:-1] + 1])))
    joined[1:] = adjacent
    starts = piece[~joined]
    ends = np.append(piece[np.flatnonzero(~joined)[1:] - 1], piece[-1]) + 1

    def label(at):
        """(surface code, wall) of the breakpoints `at`."""
        code = np.select([kind[at] == _START, kind[at] == _PLAN, kind[at] == _BOTTOM, kind[at] == _TOP],
                         [_CODE["flute_start"], wall_code[np.maximum(wall[at], 0)], _CODE["bottom"], _CODE["top"]],
                         default=CORNER_TOP if top >= 0.5 * np.pi else _CODE["flute_end"])
        return code, np.where(kind[at] == _PLAN, wall[at], -1)

    start_code, start_wall = label(starts)
    end_code, end_wall = label(ends)
    return rows[local[starts]], psi[starts], psi[ends], start_code, start_wall, end_code, end_wall
