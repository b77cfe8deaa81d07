"""Brute-force reference for lines in a terraced stock, independent of the code under test.

A stock is plain data: slabs (z_bottom, z_top, loops); a loop is one of
("polygon", (k, 2) vertices), ("circle", centre, radius), ("stadium", a, b, radius) (the
points within `radius` of the segment a-b), or ("polyline", (k, 2) closed fine polyline of
any curve). A point is inside a slab's region when it is inside an odd number of its loops;
each loop's own test is exact for polygons (crossing number), circles and stadiums (a
distance), and as good as the polyline for the rest (matplotlib's Path.contains_points).

A line is sampled on a dense grid of l, with the points where it meets each level (and
just either side of them) added; every change of the inside flag is refined by
bisection to BISECT_TOL, and the surface at each end of an inside run found by looking at
what changed there (a level, or a loop: then its nearest side).
"""

import numpy as np
from matplotlib.path import Path

SAMPLES = 4001
BISECT_TOL = 1e-13
LEVEL_TOL = 1e-9


def _inside_polygon(points, vertices):
    """(n,) bool: crossing-number test of points (n, 2) against a closed polygon (k, 2)."""
    x, y = points[:, 0:1], points[:, 1:2]
    a, b = vertices, np.roll(vertices, -1, axis=0)
    ax, ay, bx, by = a[:, 0], a[:, 1], b[:, 0], b[:, 1]
    straddles = (ay > y) != (by > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        cross_x = ax + (y - ay) * (bx - ax) / (by - ay)
    return (straddles & (x < cross_x)).sum(axis=1) % 2 == 1


def inside_loop(points, loop):
    """(n,) bool: points (n, 2) inside one loop."""
    kind = loop[0]
    if kind == "polygon":
        return _inside_polygon(points, np.asarray(loop[1], dtype=float))
    if kind == "polyline":  # many vertices: matplotlib's compiled crossing test
        return Path(np.asarray(loop[1], dtype=float), closed=False).contains_points(points)
    if kind == "circle":
        return np.hypot(*(points - np.asarray(loop[1])).T) < loop[2]
    a, b, r = np.asarray(loop[1], float), np.asarray(loop[2], float), loop[3]
    t = np.clip((points - a) @ (b - a) / ((b - a) @ (b - a)), 0.0, 1.0)
    return np.hypot(*(points - (a + t[:, None] * (b - a))).T) < r


def inside(points, slabs):
    """(n,) bool: 3-D points (n, 3) inside the stock (z within a slab, plan point in its region)."""
    result = np.zeros(points.shape[0], dtype=bool)
    for k, (z0, z1, loops) in enumerate(slabs):
        in_z = (points[:, 2] >= z0) & ((points[:, 2] < z1) | ((k == len(slabs) - 1) & (points[:, 2] <= z1)))
        if not in_z.any():
            continue
        odd = np.zeros(in_z.sum(), dtype=bool)
        for loop in loops:
            odd ^= inside_loop(points[in_z, :2], loop)
        result[np.flatnonzero(in_z)[odd]] = True
    return result


def line_runs(slabs, origin, direction, length):
    """Inside runs [(l0, l1), …] of origin + l·direction, 0 ≤ l ≤ length (mm)."""
    origin, direction = np.asarray(origin, float), np.asarray(direction, float)
    l = np.linspace(0.0, length, SAMPLES)
    if abs(direction[2]) > 0.0:  # where the line meets each level, and just either side of it
        levels = np.array([z for z0, z1, _ in slabs for z in (z0, z1)])
        at = (levels - origin[2]) / direction[2]
        at = np.concatenate([at, at - 1e-9, at + 1e-9])
        l = np.unique(np.concatenate([l, at[(at > 0.0) & (at < length)]]))
    flags = inside(origin + l[:, None] * direction, slabs)
    changes = np.flatnonzero(flags[1:] != flags[:-1])
    cuts = []
    for c in changes:
        lo, hi, f_lo = l[c], l[c + 1], flags[c]
        while hi - lo > BISECT_TOL:
            mid = 0.5 * (lo + hi)
            if inside((origin + mid * direction)[None], slabs)[0] == f_lo:
                lo = mid
            else:
                hi = mid
        cuts.append(0.5 * (lo + hi))
    bounds = np.concatenate([[0.0], cuts, [length]])
    state = flags[0]
    runs = []
    for a, b in zip(bounds[:-1], bounds[1:]):
        if state and b - a > 1e-12:
            runs.append((a, b))
        state = not state
    return runs


def surface_at(slabs, point):
    """What bounds the material at a 3-D point on its boundary: ("level", z) or ("loop", slab k, loop i)."""
    for z0, z1, _ in slabs:
        for z in (z0, z1):
            if abs(point[2] - z) < LEVEL_TOL:
                return ("level", z)
    for k, (z0, z1, loops) in enumerate(slabs):
        if z0 <= point[2] <= z1:
            best, which = np.inf, -1
            for i, loop in enumerate(loops):
                d = distance_to_loop(point[:2], loop)
                if d < best:
                    best, which = d, i
            return ("loop", k, which)
    return ("none",)


def distance_to_loop(p, loop):
    """Distance (mm) from a plan point (2,) to a loop's boundary."""
    kind = loop[0]
    if kind == "circle":
        return abs(np.hypot(*(p - np.asarray(loop[1]))) - loop[2])
    if kind == "stadium":
        a, b, r = np.asarray(loop[1], float), np.asarray(loop[2], float), loop[3]
        t = np.clip((p - a) @ (b - a) / ((b - a) @ (b - a)), 0.0, 1.0)
        return abs(np.hypot(*(p - (a + t * (b - a)))) - r)
    v = np.asarray(loop[1], float)
    a, b = v, np.roll(v, -1, axis=0)
    t = np.clip(np.einsum("ij,ij->i", p - a, b - a) / np.einsum("ij,ij->i", b - a, b - a), 0.0, 1.0)
    return np.min(np.hypot(*(p - (a + t[:, None] * (b - a))).T))
