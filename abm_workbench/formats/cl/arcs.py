"""CIRCLE motion: the points of a circular or helical arc, at most a step apart, within a chordal tolerance.

APT's ``CIRCLE/xc,yc,zc,i,j,k[,r,...]`` followed by the GOTO of the arc's end point moves the
tool from where it is to that end point along the circle about the axis (i, j, k) through the
centre, turning by the right-hand rule about the axis. End point = start point (in the
circle's plane, to within SAME_POINT mm, far below the precision files are written to): a full
turn. An end point at another height along the
axis: a helical arc, the height (and any change of radius between start and end, which a file
only has from rounding) varying in proportion to the angle turned.

The CL points along an arc are at equal angles, as few as keep consecutive points at most `step`
mm apart along the arc and each chord within `tolerance` mm of it (its sagitta); each point comes
with the arc's tangent there, the direction of the tool's motion.
"""

import math

import numpy as np

#: Largest angle (rad) between two interpolated points, however coarse the tolerance.
MAX_STEP = math.pi / 4
#: Start and end points of an arc closer than this (mm, in the circle's plane) make a full turn.
SAME_POINT = 1e-6


def arc_points(start, end, centre, axis, tolerance, step=math.inf):
    """(points (k, 3), tangents (k, 3)) along the arc from `start` to `end` about `centre` and `axis`, mm.

    The points after the start, the last being `end` itself; every point is at the start's radius
    (its height and radius going linearly to the end's), consecutive points at most `step` mm apart
    along the arc and at most the angle whose chord sagitta is `tolerance` (mm). tangents: the unit
    direction of motion along the arc at each point. ValueError when the axis is zero or the start
    or end lies on the axis.
    """
    start, end, centre = (np.asarray(v, dtype=float) for v in (start, end, centre))
    w = np.asarray(axis, dtype=float)
    norm = np.linalg.norm(w)
    if not norm > 0.0:
        raise ValueError("the circle's axis is zero")
    w = w / norm
    a, b = start - centre, end - centre
    height_a, height_b = a @ w, b @ w
    radial_a, radial_b = a - height_a * w, b - height_b * w
    radius_a, radius_b = np.linalg.norm(radial_a), np.linalg.norm(radial_b)
    if radius_a == 0.0 or radius_b == 0.0:
        raise ValueError("the arc's start or end point lies on the circle's axis")
    u = radial_a / radius_a
    v = np.cross(w, u)
    sweep = math.atan2(radial_b @ v, radial_b @ u) % (2.0 * math.pi)
    if np.linalg.norm(radial_b - radial_a) <= SAME_POINT:
        sweep = 2.0 * math.pi
    radius = max(radius_a, radius_b)
    length = math.hypot(sweep * radius, height_b - height_a)
    count = max(1, math.ceil(sweep / step_angle(radius, tolerance)), math.ceil(length / step - 1e-9))
    t = np.arange(1, count + 1) / count
    angle = sweep * t
    radii = radius_a + (radius_b - radius_a) * t
    height = height_a + (height_b - height_a) * t
    cos, sin = np.cos(angle)[:, None], np.sin(angle)[:, None]
    points = centre + radii[:, None] * cos * u + radii[:, None] * sin * v + height[:, None] * w
    points[-1] = end
    # d/dθ of the point: the radius's and height's change per radian, and the turn.
    tangents = ((radius_b - radius_a) / sweep * (cos * u + sin * v) + radii[:, None] * (cos * v - sin * u)
                + (height_b - height_a) / sweep * w)
    return points, tangents / np.linalg.norm(tangents, axis=1)[:, None]


def step_angle(radius, tolerance):
    """The largest angle (rad) whose chord on a circle of `radius` mm has sagitta <= `tolerance` mm."""
    if tolerance >= radius:
        return MAX_STEP
    return min(MAX_STEP, 2.0 * math.acos(1.0 - tolerance / radius))
