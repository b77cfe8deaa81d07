"""Tools with a corner in the in-process stock: the swept solid of a bull-nose or ball-end mill against lines and
corner arcs, against an independent brute-force reference.

The reference (nothing from abm_workbench for its geometry): a tool is plain numbers R, r, H; its solid in a
meridian half-plane (ρ = distance from the axis, a = height above the bottom centre) is the convex region
0 ≤ a ≤ H, ρ ≤ ρ(a) (ρ(a) = R − r + √(r² − (r − a)²) on the corner, R above), whose Euclidean distance from a
point is the least over its boundary's pieces (bottom, corner arc, side, top; zero inside). A point x lies in the
solid swept from c0 to c0 + m with axis w when the distance of x − c0 − s·m from the tool, convex in s, is zero for
some s in [0, 1]: a ternary search over s (TERNARY steps). An edge (line or arc) is sampled densely and every
change of the flag is bisected (BISECT steps). The engine's own ends may be added as extra sample positions (never
as answers), so that a sliver thinner than a sample step is looked at by both.
"""

import numpy as np
import pytest

from abm_workbench.engine.inprocess_arc import arc_swept_intervals
from abm_workbench.engine.inprocess_swept import line_swept_interval

TERNARY = 90
BISECT = 48
SAMPLES = 2001
SLACK = 1e-14  # mm: in_swept's slack (see there)
EXACT = 1e-9  # mm: the engine against the reference for one solid
RATIOS = (0.0, 0.1, 0.3, 0.5, 1.0)  # r / R


# ----------------------------------------------------------------------------------------------------------------
# Reference geometry


def _segment_distance(px, py, ax, ay, bx, by):
    """Distance (n,) from points (px, py) to the segments (ax, ay)–(bx, by) (broadcast)."""
    dx, dy = bx - ax, by - ay
    dd = dx * dx + dy * dy
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(dd > 0, ((px - ax) * dx + (py - ay) * dy) / np.where(dd > 0, dd, 1.0), 0.0)
    t = np.clip(t, 0.0, 1.0)
    return np.hypot(px - ax - t * dx, py - ay - t * dy)


def profile_distance(rho, a, big, corner, height):
    """Euclidean distance (n,) from meridian points (ρ ≥ 0, a) to tools' profile regions (0 inside); big, corner,
    height (n,) or numbers."""
    rho, a, big, corner, height = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (rho, a, big, corner,
                                                                                               height)))
    inner = big - corner
    with np.errstate(invalid="ignore", divide="ignore"):
        rho_top = np.where(height >= corner, big,
                           inner + np.sqrt(np.maximum(corner * corner - (corner - height) ** 2, 0.0)))
        rho_at = np.where(a >= corner, big,
                          inner + np.sqrt(np.maximum(corner * corner - (corner - np.minimum(a, corner)) ** 2, 0.0)))
    inside = (a >= 0) & (a <= height) & (rho <= rho_at)
    far = np.full(rho.shape, np.inf)
    bottom = _segment_distance(rho, a, 0.0, 0.0, inner, 0.0)
    top = _segment_distance(rho, a, 0.0, height, rho_top, height)
    side = np.where(height > corner, _segment_distance(rho, a, big, corner, big, height), far)
    # The corner arc: centre (R − r, r), from angle −90° up to where it meets the top (angle ≤ 0).
    with np.errstate(invalid="ignore", divide="ignore"):
        end = np.arcsin(np.clip((np.minimum(height, corner) - corner) / np.where(corner > 0, corner, 1.0), -1.0, 1.0))
    angle = np.arctan2(a - corner, rho - inner)
    within = (angle >= -0.5 * np.pi) & (angle <= end)
    radial = np.abs(np.hypot(rho - inner, a - corner) - corner)
    ends = np.minimum(np.hypot(rho - inner, a), np.hypot(rho - (inner + corner * np.cos(end)),
                                                         a - (corner + corner * np.sin(end))))
    arc = np.where(corner > 0, np.where(within, radial, ends), far)
    return np.where(inside, 0.0, np.minimum(np.minimum(bottom, top), np.minimum(side, arc)))


def tool_distance(q, axis, big, corner, height):
    """Distance (n,) of points q (n, 3) (relative to the bottom centre) from tool solids (axis (n, 3) or (3,))."""
    a = np.sum(q * axis, axis=-1)
    rho = np.linalg.norm(q - a[:, None] * axis, axis=1)
    return profile_distance(rho, a, big, corner, height)


def in_swept(points, c0, move, axis, big, corner, height):
    """(n,) bool: points (n, 3) in the solids swept from c0 along `move` (one piece each, constant axis; (n, 3) or
    (3,), and (n,) or numbers).

    The distance of x − c0 − s·m from the tool is convex in s: a ternary search keeps a minimiser in its bracket.
    A point is inside when some position tried has distance exactly 0, or the bracket's ends come within SLACK of
    the solid (the bracket ends 1.5e-16 wide around a zero of the distance, so within |m|·1e-16 of it). SLACK is
    kept far below 1e-12: where an edge touches an earlier tool's surface tangentially (distance ~ κ·δ²/2 a
    distance δ from the touch), a slack ε moves the edge's end by √(2ε/κ), 4 µm at 1e-12 for κ = 1/8 mm⁻¹."""
    lo, hi = np.zeros(len(points)), np.ones(len(points))
    q = points - c0
    hit = np.zeros(len(points), dtype=bool)
    for _ in range(TERNARY):
        m1, m2 = lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0
        g1 = tool_distance(q - m1[:, None] * move, axis, big, corner, height)
        g2 = tool_distance(q - m2[:, None] * move, axis, big, corner, height)
        hit |= (g1 == 0.0) | (g2 == 0.0)
        left = g1 < g2
        hi, lo = np.where(left, m2, hi), np.where(left, lo, m1)
    s = 0.5 * (lo + hi)
    best = np.minimum.reduce([tool_distance(q - v[:, None] * move, axis, big, corner, height) for v in (lo, s, hi)])
    return hit | (best <= SLACK)


def batch_runs(flag_at, spans, extra=None, samples=SAMPLES):
    """Inside runs of E edges, each parametrised over [0, spans[e]]: a list of [(t0, t1), …] per edge.

    flag_at(edge (n,), t (n,)) -> (n,) bool; extra: per edge, further sample positions (or None)."""
    spans = np.asarray(spans, dtype=float)
    edges = spans.size
    edge = np.repeat(np.arange(edges), samples)
    t = np.tile(np.linspace(0.0, 1.0, samples), edges) * spans[edge]
    if extra is not None:
        more = [np.clip(np.asarray(x, dtype=float), 0.0, spans[e]) for e, x in enumerate(extra)]
        edge = np.concatenate([edge] + [np.full(x.size, e) for e, x in enumerate(more)])
        t = np.concatenate([t] + more)
    order = np.lexsort((t, edge))
    edge, t = edge[order], t[order]
    flags = flag_at(edge, t)
    change = np.flatnonzero((flags[1:] != flags[:-1]) & (edge[1:] == edge[:-1]))
    low, high, owner = t[change], t[change + 1], edge[change]
    for _ in range(BISECT):
        mid = 0.5 * (low + high)
        same = flag_at(owner, mid) == flags[change]
        low, high = np.where(same, mid, low), np.where(same, high, mid)
    cuts = 0.5 * (low + high)
    first = np.searchsorted(edge, np.arange(edges))
    out = []
    for e in range(edges):
        mine = cuts[owner == e]
        bounds = np.concatenate([[0.0], mine, [spans[e]]])
        state, found = bool(flags[first[e]]), []
        for a, b in zip(bounds[:-1], bounds[1:]):
            if state and b - a > 1e-12:
                found.append((float(a), float(b)))
            state = not state
        out.append(found)
    return out


def arc_point(centre, d, w, radius, psi):
    """Points (n, 3) of arcs (centre, d, w (n, 3) or (3,), radius (n,) or a number) at ψ (n,)."""
    radius = np.asarray(radius, dtype=float)
    radius = radius[:, None] if radius.ndim else radius
    return centre + radius * (np.sin(psi)[:, None] * d - np.cos(psi)[:, None] * w)


# ----------------------------------------------------------------------------------------------------------------
# One solid: the engine's solvers against the reference


def random_piece(rng, trial, corner_ratio=None):
    """(c0, move, axis, R, r, H) of a random piece: vertical or tilted axis, moves along, across and oblique to it,
    still; flutes shorter than the corner, than the corner's diameter, and long."""
    axis = rng.normal(size=3) if trial % 3 else np.array([0.0, 0.0, 1.0])
    axis /= np.linalg.norm(axis)
    c0 = rng.normal(size=3) * 3.0
    kind = trial % 6
    if kind == 0:
        move = np.zeros(3)
    elif kind == 1:
        move = rng.uniform(0.5, 3.0) * axis
    else:
        move = rng.normal(size=3) * rng.choice([0.3, 2.0, 6.0])
        if kind == 2:
            move -= (move @ axis) * axis  # a level move with an upright tool
    big = rng.uniform(1.0, 6.0)
    ratio = rng.choice(RATIOS[1:]) if corner_ratio is None else corner_ratio
    corner = big * ratio
    height = rng.choice([rng.uniform(0.3, 0.9) * corner if corner > 0 else 0.5, rng.uniform(corner, 2 * corner + 0.1),
                         rng.uniform(2 * corner + 0.5, max(12.0, 2 * corner + 1.0))])
    return c0, move, axis, big, corner, max(height, 0.2)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_line_against_one_swept_corner_tool(seed):
    """line_swept_interval on random lines and pieces (r/R in 0.1 … 1, any flute length, moves along, across and
    oblique to the axis, lines along the axis and along the move) against the reference, to EXACT."""
    rng = np.random.default_rng(seed)
    cases = []
    for trial in range(60):
        c0, move, axis, big, corner, height = random_piece(rng, trial)
        origin = c0 + 0.5 * move + rng.normal(size=3) * 3.0
        u = axis.copy() if trial % 7 == 0 else rng.normal(size=3)
        if trial % 11 == 5 and np.linalg.norm(move) > 0:
            u = move.copy()
        cases.append((origin, u / np.linalg.norm(u), c0, move, axis, big, corner, height))
    origin, u, c0, move, axis, big, corner, height = (np.array(column) for column in zip(*cases))
    enter, leave = line_swept_interval(origin, u, c0, c0 + move, axis, big, height, corner)
    extra = [[] if np.isnan(e) else [v + 40.0 + x for v in (e, l) for x in (-1e-7, 0.0, 1e-7)]
             for e, l in zip(enter, leave)]

    def flag(edge, t):
        points = origin[edge] + (t - 40.0)[:, None] * u[edge]
        return in_swept(points, c0[edge], move[edge], axis[edge], big[edge], corner[edge], height[edge])

    want = batch_runs(flag, np.full(len(cases), 80.0), extra, samples=1601)
    hits = 0
    for k, found in enumerate(want):
        if not found:
            assert np.isnan(enter[k]) or leave[k] - enter[k] < 1e-9, k
            continue
        hits += 1
        assert len(found) == 1, "a line meets a convex solid in one interval"
        np.testing.assert_allclose([enter[k] + 40, leave[k] + 40], found[0], rtol=0, atol=EXACT, err_msg=str(k))
    assert hits >= 15


def random_arc(rng):
    """(centre, d, w, radius) of a random corner arc."""
    d = rng.normal(size=3)
    d /= np.linalg.norm(d)
    w = rng.normal(size=3)
    w -= (w @ d) * d
    w /= np.linalg.norm(w)
    return rng.normal(size=3) * 3.0, d, w, rng.uniform(0.3, 5.0)


@pytest.mark.parametrize("seed", [4, 5])
@pytest.mark.parametrize("ratio", RATIOS)
def test_arc_against_one_swept_tool(seed, ratio):
    """arc_swept_intervals on random arcs near random pieces of every tool kind (flat end, bull-nose, ball) against
    the reference: every run's ends to EXACT mm of arc."""
    rng = np.random.default_rng(seed * 10 + int(ratio * 10))
    cases = []
    for trial in range(40):
        centre, d, w, radius = random_arc(rng)
        c0, move, axis, big, corner, height = random_piece(rng, trial, ratio)
        c0 = centre + rng.normal(size=3) * 3.0
        lo, hi = sorted(rng.uniform(0.0, 0.5 * np.pi, 2)) if trial % 4 == 0 else (0.0, 0.5 * np.pi)
        cases.append((centre, d, w, radius, lo, hi, c0, move, axis, big, corner, height))
    centre, d, w, radius, lo, hi, c0, move, axis, big, corner, height = (np.array(column) for column in zip(*cases))
    pair, start, end = arc_swept_intervals(centre, d, w, radius, lo, hi, c0, c0 + move, axis, big, height, corner)
    got = [list(zip(start[pair == k], end[pair == k])) for k in range(len(cases))]
    extra = [[v - lo[k] + x for a, b in found for v in (a, b) for x in (-1e-9, 0.0, 1e-9)]
             for k, found in enumerate(got)]

    def flag(edge, t):
        points = arc_point(centre[edge], d[edge], w[edge], radius[edge], lo[edge] + t)
        return in_swept(points, c0[edge], move[edge], axis[edge], big[edge], corner[edge], height[edge])

    want = batch_runs(flag, hi - lo, extra)
    hits = 0
    for k in range(len(cases)):
        reference = [(a + lo[k], b + lo[k]) for a, b in want[k]]
        hits += bool(reference)
        assert len(got[k]) == len(reference), (k, got[k], reference)
        for (a, b), (x, y) in zip(got[k], reference):
            assert abs(a - x) * radius[k] <= EXACT and abs(b - y) * radius[k] <= EXACT, (k, got[k], reference)
    assert hits >= 5


def test_arc_on_the_same_tool_is_inside_and_cheap():
    """An arc of a tool lying on the surface of the same tool standing where it is (a move of zero length, or one
    that ends there) is inside its whole length, decided by the bound from the tool's foot."""
    import abm_workbench.engine.inprocess_arc as arcs

    calls = []
    evaluate = arcs._Arcs.evaluate

    def counted(self, pair, psi):
        calls.append(pair.size)
        return evaluate(self, pair, psi)

    big, corner, height = 5.0, 2.0, 12.0
    axis = np.array([0.0, 0.0, 1.0])
    phi = np.radians(np.arange(0.0, 360.0, 30.0))
    d = np.stack([np.sin(phi), np.cos(phi), np.zeros_like(phi)], axis=1)
    centre = (big - corner) * d + corner * axis
    n = phi.size
    for start in (np.zeros(3), np.array([-3.0, 0.0, 0.0])):
        calls.clear()
        arcs._Arcs.evaluate = counted
        try:
            pair, a, b = arc_swept_intervals(centre, d, np.tile(axis, (n, 1)), np.full(n, corner), np.zeros(n),
                                             np.full(n, 0.5 * np.pi), np.tile(start, (n, 1)), np.zeros((n, 3)),
                                             np.tile(axis, (n, 1)), np.full(n, big), np.full(n, height),
                                             np.full(n, corner))
        finally:
            arcs._Arcs.evaluate = evaluate
        assert pair.tolist() == list(range(n))
        np.testing.assert_array_equal(a, 0.0)
        np.testing.assert_allclose(b, 0.5 * np.pi, rtol=0, atol=1e-15)
        assert sum(calls) <= 5 * n
