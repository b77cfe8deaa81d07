"""An exact inside test for the volume a tool sweeps along a straight move, written from the tool's definition
(independent of OpenCASCADE and of the engine), and the edges' intervals in it, for the swept volumes
OpenCASCADE's solids do not give reliably (a bull-nose mill's shallow ramp: cad.corner_sweep).

The tool of radius R, corner radius r (0 ≤ r ≤ R) and cutting height H, tip centre c, unit axis w, is the set
of points where the gauge γ(q) = max(dist(q, Z) − r, q·w − H) ≤ 0, q = x − c, Z the half-infinite column
{q·w ≥ r, |q − (q·w)·w| ≤ R − r}: γ is convex (a distance to a convex set, and a linear function) and
1-Lipschitz. The volume swept by c moving straight from c0 to c0 + m with w fixed is where
Γ(x) = min over t in [0, 1] of γ(x − c0 − t·m) ≤ 0; t ↦ γ(x − c0 − t·m) is convex and |m|-Lipschitz, so a
golden-section search finds its least value to |m|·0.618^GOLDEN_STEPS. Γ is 1-Lipschitz in x.

:func:`exact_intervals` finds where a cutting edge lies in that volume: along the edge, parametrised by arc
length, Γ is 1-Lipschitz, so on a piece of half-length δ whose middle has |Γ| > δ the sign of Γ is that of
the middle throughout. Pieces are halved until that holds, or until they are shorter than 2·HALF_EPS (their
middle's sign decides them): every crossing is found to within 10⁻¹⁰ mm. An edge lying in the volume's
boundary (a repeated pass) would be halved without end: past BUDGET pieces at once, those left count as
inside (the volume is closed) and are reported. Lengths in mm.
"""

import numpy as np

from .boolean import PIECE_EPS, _merged
from .profile_edges import EdgeGeometry

#: Golden-section steps: 0.618^60 < 3·10⁻¹³ of the move's parameter range.
GOLDEN_STEPS = 60
#: A piece of an edge shorter than twice this (mm) is decided by its middle.
HALF_EPS = 5e-11
#: At most this many pieces of edges are halved at once; past it the rest count as inside.
BUDGET = 200_000


def tool_gauge(q, axis, radius, corner, height):
    """(n,) the tool's gauge γ at points q (n, 3) relative to its tip's centre (unit axis, mm; module
    docstring): ≤ 0 exactly inside the tool, 1-Lipschitz."""
    q = np.asarray(q, dtype=float)
    w = np.asarray(axis, dtype=float)
    a = q @ w
    b = np.linalg.norm(q - a[:, None] * w, axis=1)
    gap = np.hypot(np.maximum(corner - a, 0.0), np.maximum(b - (radius - corner), 0.0))
    return np.maximum(gap - corner, a - height)


def swept_gauge(points, c0, c1, axis, radius, corner, height):
    """(n,) Γ at points (n, 3): the least tool gauge over the move c0 → c1 ((3,) mm, axis fixed); ≤ 0 exactly
    inside the swept volume (module docstring)."""
    points = np.asarray(points, dtype=float)
    c0 = np.asarray(c0, dtype=float)
    m = np.asarray(c1, dtype=float) - c0

    def gauge(t):
        return tool_gauge(points - c0 - t[:, None] * m, axis, radius, corner, height)

    ratio = 0.5 * (np.sqrt(5.0) - 1.0)
    a, b = np.zeros(len(points)), np.ones(len(points))
    c, d = b - ratio * (b - a), a + ratio * (b - a)
    f_c, f_d = gauge(c), gauge(d)
    for _ in range(GOLDEN_STEPS):
        left = f_c <= f_d  # the least value lies in [a, d]: keep it, else [c, b]
        a, b = np.where(left, a, c), np.where(left, d, b)
        c, d = np.where(left, b - ratio * (b - a), d), np.where(left, c, a + ratio * (b - a))
        f_new = gauge(np.where(left, c, d))
        f_c, f_d = np.where(left, f_new, f_d), np.where(left, f_c, f_new)
    ends = np.minimum(gauge(np.zeros(len(points))), gauge(np.ones(len(points))))
    return np.minimum(np.minimum(f_c, f_d), ends)


def edge_points(geometry: EdgeGeometry, kinds, ks, t):
    """(n, 3) the points at positions t (n,) mm, in each edge's own coordinate (cad.profile_boolean's: arc
    length on the corner arc, height above its start on the side, distance from the tip on the end edge), of
    the edges (kinds[i], ks[i])."""
    kinds, ks, t = np.asarray(kinds), np.asarray(ks, dtype=int), np.asarray(t, dtype=float)
    d = geometry.d[ks]
    r = geometry.corner
    psi = t / (r if r > 0.0 else 1.0)
    arc = geometry.centres[ks] + r * (np.sin(psi)[:, None] * d - np.cos(psi)[:, None] * geometry.w)
    side = geometry.side_start[ks] + t[:, None] * geometry.w
    end = geometry.tip + t[:, None] * d
    return np.where((kinds == "arc")[:, None], arc, np.where((kinds == "side")[:, None], side, end))


def exact_intervals(geometry: EdgeGeometry, spans, piece):
    """({(kind, k): merged intervals}, undecided): where the spans `spans` ({(kind, k): [(a, b), ...]}, in each
    edge's own coordinate: module docstring) of the edges of `geometry` lie in the volume the constant-axis
    move `piece` (c0, c1, axis, radius, corner, height; mm) sweeps, and how many pieces of edges the BUDGET
    left undecided."""
    keys = list(spans)
    kinds = np.array([kind for kind, _ in keys])
    ks = np.array([k for _, k in keys], dtype=int)
    found, undecided = curve_intervals(lambda owner, t: edge_points(geometry, kinds[owner], ks[owner], t),
                                       [spans[key] for key in keys], piece)
    return dict(zip(keys, found)), undecided


def curve_intervals(points_at, spans, piece):
    """(n lists of merged intervals, undecided): where the spans (n lists of (a, b)) of n unit-speed curves lie
    in the volume the constant-axis move `piece` sweeps (module docstring); points_at(owner (k,), t (k,)) gives
    the points (k, 3) of curves `owner` at parameters t."""
    rows = [(i, x, y) for i, found in enumerate(spans) for x, y in found]
    owner = np.array([i for i, _, _ in rows], dtype=int)
    a = np.array([x for _, x, _ in rows], dtype=float)
    b = np.array([y for _, _, y in rows], dtype=float)
    move = float(np.linalg.norm(np.asarray(piece[1], dtype=float) - np.asarray(piece[0], dtype=float)))
    slack = 1e-12 * (1.0 + move)  # the golden-section search's error and rounding
    found, undecided = [], 0
    while owner.size:
        middle, half = 0.5 * (a + b), 0.5 * (b - a)
        gauge = swept_gauge(points_at(owner, middle), *piece)
        done = (np.abs(gauge) > half + slack) | (half <= HALF_EPS)
        if owner.size > BUDGET:
            undecided += int((~done).sum())
            done[:] = True
            gauge = np.where(np.abs(gauge) > half + slack, gauge, -1.0)
        found += [(int(i), x, y) for i, x, y in zip(owner[done & (gauge <= 0.0)], a[done & (gauge <= 0.0)],
                                                      b[done & (gauge <= 0.0)])]
        owner, a, b, middle = owner[~done], a[~done], b[~done], middle[~done]
        owner, a, b = np.concatenate([owner, owner]), np.concatenate([a, middle]), np.concatenate([middle, b])
    pieces = [[] for _ in spans]
    for i, x, y in found:
        pieces[i].append((x, y))
    return [[(x, y) for x, y in _merged(value) if y - x >= PIECE_EPS] for value in pieces], undecided
