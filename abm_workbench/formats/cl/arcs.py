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

import contextlib
import contextvars
import math

import numpy as np

from ...errors import note
from ...limits import LARGE_INTERPOLATION, check_large, check_memory, count_text

#: Largest angle (rad) between two interpolated points, however coarse the tolerance.
MAX_STEP = math.pi / 4
#: Start and end points of an arc closer than this (mm, in the circle's plane) make a full turn.
SAME_POINT = 1e-6
#: Smallest chordal tolerance and step (mm) of arcs and curves: a nanometre, far below what CL files
#: are written to.
MIN_TOLERANCE = 1e-6
#: Memory an interpolated CL point takes in a program being read (bytes).
POINT_BYTES = 512

_SPENT = contextvars.ContextVar("abm_interpolated", default=None)


@contextlib.contextmanager
def interpolation_budget():
    """Within the block (reading one program), the arcs and curves interpolated share one budget of CL
    points (:func:`spend`)."""
    token = _SPENT.set([0])
    try:
        yield
    finally:
        _SPENT.reset(token)


def afford(count):
    """spend's check of `count` more interpolated CL points, without taking them (for a loop that will
    take them piece by piece, such as a helix of many turns)."""
    _check(count, "at least ")


def spend(count):
    """Take `count` interpolated CL points from the program's budget before they are made: TooLarge (a
    ValueError, which the readers give the record's line) when the program's arcs and curves together
    would make more than limits.LARGE_INTERPOLATION of them and large runs are not allowed, or more
    than the memory this process may use."""
    total = _check(count)
    spent = _SPENT.get()
    if spent is not None:
        spent[0] = total


def _check(count, words=""):
    """The program's interpolated CL points with `count` more; TooLarge as spend says."""
    spent = _SPENT.get()
    total = count + (spent[0] if spent is not None else 0)
    remedy = note("give a coarser --tolerance or --step")
    more, so_far = count_text(count), count_text(total)
    what = note(f"at least {more} CL points (the program's arcs and curves so far: {so_far})" if words else
                f"{more} CL points (the program's arcs and curves so far: {so_far})")
    check_large(note("interpolating it"), what, total, LARGE_INTERPOLATION, remedy)
    check_memory(total * POINT_BYTES, note("interpolating it"), note(f"{so_far} CL points"), remedy)
    return total


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
    count = max(1, math.ceil(sweep / step_angle(radius, tolerance)), math.ceil(min(length / step - 1e-9, 1e300)))
    spend(count)
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
    if tolerance < 1e-6 * radius:  # 1 − t/r would round away: the same angle as 4·asin(√(t / 2r))
        return 4.0 * math.asin(math.sqrt(0.5 * tolerance / radius))
    return min(MAX_STEP, 2.0 * math.acos(1.0 - tolerance / radius))
