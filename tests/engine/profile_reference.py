"""Brute-force reference for the whole cutting edge of a flat-end, bull-nose or ball-end mill.

Independent of the code under test: nothing here imports ``abm_workbench``. The tool is plain
numbers: radius R, corner radius r, flute length L (mm). Its frame at a CL point is built here
from the axis angles and the feed's turn, R = Rz(α)·Rx(θ_A)·Ry(θ_B), columns u, v, w.

The peripheral edge at rotation angle φ is parametrised by its arc length s: with
d = sin φ·u + cos φ·v, on the corner (0 ≤ s ≤ r·ψ_max, ψ = s/r)

    P(s) = T + (R − r + r sin ψ)·d + r (1 − cos ψ)·w,

ψ_max = 90° unless L < r (then cos ψ_max = 1 − L/r), and on the straight side
P(s) = T + R·d + (r + s − r·ψ_max)·w up to height L. Its height above the tip is
r (1 − cos ψ) on the corner and r + s − r·ψ_max on the side. The end edge is T + t·d,
0 ≤ t ≤ R − r.

A membership test inside(points (n, 3)) -> (n,) bool (the reference stocks' own) is sampled on
a dense grid of s, with extra samples where the edge meets each given level; every change of
the flag is refined by bisection to BISECT_TOL. Runs shorter than MIN_RUN are dropped.
"""

import numpy as np

SAMPLES = 6001
BISECT_TOL = 1e-13
MIN_RUN = 1e-10


def frame(theta_a, theta_b, alpha=0.0):
    """(3, 3) Rz(α)·Rx(θ_A)·Ry(θ_B), angles in degrees; columns u, v, w."""
    a, b, c = np.radians([theta_a, theta_b, alpha])
    rx = np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])
    ry = np.array([[np.cos(b), 0, np.sin(b)], [0, 1, 0], [-np.sin(b), 0, np.cos(b)]])
    rz = np.array([[np.cos(c), -np.sin(c), 0], [np.sin(c), np.cos(c), 0], [0, 0, 1]])
    return rz @ rx @ ry


def corner_end(radius, corner, flute_length):
    """ψ_max (rad)."""
    if corner <= 0.0:
        return 0.0
    return 0.5 * np.pi if flute_length >= corner else float(np.arccos(1.0 - flute_length / corner))


def edge_span(radius, corner, flute_length):
    """Arc length (mm) of the whole peripheral edge."""
    top = corner_end(radius, corner, flute_length)
    return corner * top + max(flute_length - corner, 0.0)


def profile_points(s, tip, d, w, radius, corner, flute_length):
    """Points (n, 3) of the peripheral edge at arc lengths s (n,)."""
    top = corner_end(radius, corner, flute_length)
    s = np.asarray(s, dtype=float)
    on_corner = s <= corner * top
    psi = np.where(on_corner, s / (corner if corner > 0 else 1.0), 0.0)
    out_radial = np.where(on_corner, radius - corner + corner * np.sin(psi), radius)
    up = np.where(on_corner, corner * (1.0 - np.cos(psi)), corner + s - corner * top)
    return tip + out_radial[:, None] * d + up[:, None] * w


def height(s, radius, corner, flute_length):
    """Height (mm) above the tip of the peripheral edge's point at arc length s."""
    top = corner_end(radius, corner, flute_length)
    s = np.asarray(s, dtype=float)
    return np.where(s <= corner * top, corner * (1.0 - np.cos(np.minimum(s, corner * top) / max(corner, 1e-300))),
                    corner + s - corner * top)


def curve_runs(inside, point_at, span, extra=()):
    """Inside runs [(s0, s1), …] of a curve point_at(s (n,)) -> (n, 3) over 0 ≤ s ≤ span."""
    s = np.unique(np.concatenate([np.linspace(0.0, span, SAMPLES), np.asarray(extra, dtype=float)]))
    s = s[(s >= 0.0) & (s <= span)]
    flags = inside(point_at(s))
    cuts = []
    for c in np.flatnonzero(flags[1:] != flags[:-1]):
        lo, hi, f_lo = s[c], s[c + 1], flags[c]
        while hi - lo > BISECT_TOL:
            mid = 0.5 * (lo + hi)
            if inside(point_at(np.array([mid])))[0] == f_lo:
                lo = mid
            else:
                hi = mid
        cuts.append(0.5 * (lo + hi))
    bounds = np.concatenate([[0.0], cuts, [span]])
    state, runs = bool(flags[0]), []
    for a, b in zip(bounds[:-1], bounds[1:]):
        if state and b - a > MIN_RUN:
            runs.append((float(a), float(b)))
        state = not state
    return runs


def level_hits(levels, z0, dz_of, span):
    """Arc lengths near which a curve may meet the levels: a dense grid's sign changes, both sides."""
    s = np.linspace(0.0, span, SAMPLES * 4)
    z = dz_of(s)
    hits = []
    for level in levels:
        change = np.flatnonzero(np.diff(np.sign(z - level)) != 0)
        for c in change:
            hits.extend([s[c], s[c + 1]])
    return hits


def reference_instant(inside, levels, tip, theta_a, theta_b, alpha, phi, radius, corner, flute_length):
    """One instant: dict of length, lep_l, uep_l (heights), lep_xyz, uep_xyz, end_length, runs."""
    rot = frame(theta_a, theta_b, alpha)
    u, v, w = rot[:, 0], rot[:, 1], rot[:, 2]
    ph = np.radians(phi)
    d = np.sin(ph) * u + np.cos(ph) * v
    tip = np.asarray(tip, dtype=float)
    span = edge_span(radius, corner, flute_length)

    def point_at(s):
        return profile_points(s, tip, d, w, radius, corner, flute_length)

    extra = level_hits(levels, tip[2], lambda s: point_at(s)[:, 2], span)
    runs = curve_runs(inside, point_at, span, extra)
    end = radius - corner
    end_runs = curve_runs(inside, lambda t: tip + t[:, None] * d, end,
                          level_hits(levels, tip[2], lambda t: tip[2] + t * d[2], end)) if end > 0 else []
    result = {"runs": runs, "length": sum(b - a for a, b in runs),
              "end_length": sum(b - a for a, b in end_runs)}
    if runs:
        lo, hi = runs[0][0], runs[-1][1]
        result.update(lep_l=float(height(lo, radius, corner, flute_length)),
                      uep_l=float(height(hi, radius, corner, flute_length)),
                      lep_xyz=point_at(np.array([lo]))[0], uep_xyz=point_at(np.array([hi]))[0])
    else:
        result.update(lep_l=np.nan, uep_l=np.nan, lep_xyz=np.full(3, np.nan), uep_xyz=np.full(3, np.nan))
    return result
