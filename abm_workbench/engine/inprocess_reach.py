"""Conservative bounds of groups of edge-line segments, for culling the earlier moves that cannot reach them.

The in-process engine (:mod:`.inprocess`) puts the edge lines of one CL point in groups (runs of
neighbouring angles). Every segment of a group lies in a capsule: the points within `radius` mm
of the axis segment a … b. Edge lines of one CL point are parallel and sit on the tool's rim,
so a run of neighbouring angles gives a capsule as thin as the chord of its arc, far tighter
than a sphere around the same segments; the earlier moves' hulls are then tested against the
capsule (a segment grown by a radius) instead of the sphere. Lengths in mm.
"""

import numpy as np

from .swept import row_dot


def group_capsules(group, n, envelope, origins, directions):
    """Capsules (a (n, 3), b (n, 3), radius (n,)) holding every segment of each group.

    group: (L,) non-decreasing, the group of each line; envelope: (2, L) the part lo … hi (mm
    along the line) that may still hold material (lo ≥ hi: none); origins, directions: (L, 3)
    the lines. A group's capsule axis runs along the mean direction of its live lines, through
    the mean of their segments' ends; it spans the ends' projections on that direction, and its
    radius is the largest distance of an end from the axis. The capsule is convex and holds both
    ends of every segment, so it holds the segments, whatever their directions. A group without
    a live line gets radius −inf (a, b at the origin).
    """
    a, b = np.zeros((n, 3)), np.zeros((n, 3))
    radius = np.full(n, -np.inf)
    live = envelope[0] < envelope[1]
    if not live.any():
        return a, b, radius
    if live.all():
        lo, hi, u, start = envelope[0], envelope[1], directions, origins
        owner = group
    else:
        alive = np.flatnonzero(live)
        lo, hi = envelope[0, alive], envelope[1, alive]
        u, start = np.take(directions, alive, axis=0), np.take(origins, alive, axis=0)
        owner = group[alive]
    lo_end = start + lo[:, None] * u
    hi_end = lo_end + (hi - lo)[:, None] * u
    first = np.flatnonzero(np.r_[True, owner[1:] != owner[:-1]])
    count = np.diff(np.r_[first, owner.size])
    groups = owner[first]
    mean_dir = np.add.reduceat(u, first, axis=0)
    norm = np.sqrt(row_dot(mean_dir, mean_dir))
    # Opposite directions cancel: any axis will do there, the radius then grows to hold the ends.
    axis = np.where(norm[:, None] > 1e-9, mean_dir / np.where(norm > 1e-9, norm, 1.0)[:, None], [1.0, 0.0, 0.0])
    centre = np.add.reduceat(lo_end + hi_end, first, axis=0) / (2.0 * count)[:, None]
    slot = np.repeat(np.arange(first.size), count)
    w, m = np.take(axis, slot, axis=0), np.take(centre, slot, axis=0)
    low_gap, high_gap = lo_end - m, hi_end - m
    along_lo, along_hi = row_dot(low_gap, w), row_dot(high_gap, w)
    # Squared distances from the axis line: |e − m|² − along², never below 0.
    across = np.maximum(row_dot(low_gap, low_gap) - along_lo * along_lo,
                        row_dot(high_gap, high_gap) - along_hi * along_hi)
    low = np.minimum.reduceat(np.minimum(along_lo, along_hi), first)
    high = np.maximum.reduceat(np.maximum(along_lo, along_hi), first)
    a[groups] = centre + low[:, None] * axis
    b[groups] = centre + high[:, None] * axis
    radius[groups] = np.sqrt(np.maximum(np.maximum.reduceat(across, first), 0.0))
    return a, b, radius


def capsule_spheres(a, b, radius):
    """Bounding spheres (centre (n, 3), radius (n,)) of the capsules a … b grown by radius (mm);
    radius −inf stays −inf."""
    return 0.5 * (a + b), 0.5 * np.linalg.norm(b - a, axis=1) + radius
