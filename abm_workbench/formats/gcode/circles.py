"""G2 / G3 in the planes G17, G18, G19: the arc's centre (I J K or R), its turns, its CL points.

The plane's axes (u, v) and its normal w are right-handed: G17 (X, Y; Z), G18 (Z, X; Y),
G19 (Y, Z; X). G3 turns counter-clockwise seen from the tip of w, right-handed about +w; G2 the
other way. The coordinate along w goes linearly from start to end (a helix). The centre is the
start plus I J K (their part in the plane; G91.1, the default) or I J K themselves (G90.1); or, with
R, the centre at |R| from both ends on the side that makes the arc at most half a turn (R > 0) or
more (R < 0). P, a whole number from 1, gives the turns: P − 1 full turns before the arc. An end
equal to the start in the plane is a full turn. Points come from formats.cl.arcs.arc_points (a
step apart at most, within the chordal tolerance), each with the arc's tangent.

Positions and offsets are in mm; ValueError in plain words for an arc that does not fit.
"""

import math

import numpy as np

from ..cl.arcs import SAME_POINT, afford, arc_points

#: (u, v, w) coordinate indices of each plane.
PLANES = {17: (0, 1, 2), 18: (2, 0, 1), 19: (1, 2, 0)}
#: The letters of the plane's centre offsets, and the one along its normal.
CENTRE_LETTERS = {17: ("I", "J", "K"), 18: ("K", "I", "J"), 19: ("J", "K", "I")}
#: An arc whose end is farther from or nearer to the centre than its start by more than this many mm
#: (or this fraction of the radius, when larger) does not fit.
RADIUS_TOLERANCE = 0.01
RADIUS_FRACTION = 1e-3


def centre_of_offsets(start, offsets, plane, absolute):
    """(3,) centre mm of the arc from `start` (3,) with centre offsets {letter: mm} in `plane`; absolute
    for G90.1. The centre lies at the start's height along the plane's normal."""
    u, v, w = PLANES[plane]
    letters = CENTRE_LETTERS[plane]
    centre = np.array(start, dtype=float)
    for index, letter in zip((u, v), letters[:2]):
        given = offsets.get(letter, 0.0 if not absolute else None)
        if given is None:
            raise ValueError(f"{letter} is needed: with G90.1 the centre is written whole")
        centre[index] = given if absolute else start[index] + given
    centre[w] = start[w]
    return centre


def centre_of_radius(start, end, plane, clockwise, radius, tolerance):
    """(3,) centre mm of the arc of `radius` (mm; negative: more than half a turn) from `start` to `end`.
    ValueError when the ends are the same point or farther apart than 2|R| (beyond `tolerance` mm)."""
    u, v, w = PLANES[plane]
    a = np.array([start[u], start[v]])
    b = np.array([end[u], end[v]])
    chord = b - a
    length = float(np.hypot(*chord))
    if length <= SAME_POINT:
        raise ValueError("an R arc needs an end other than its start (a full circle is written with I J K)")
    half = length / 2.0
    if abs(radius) < half - tolerance:
        raise ValueError(f"radius {abs(radius):.6g} mm does not fit: the ends are {length:.6g} mm apart, more than "
                         "its diameter")
    height = math.sqrt(max(radius * radius - half * half, 0.0))
    left = np.array([-chord[1], chord[0]]) / length  # w × chord: the left of the chord, seen from +w
    side = -1.0 if clockwise else 1.0
    side *= 1.0 if radius > 0.0 else -1.0
    centre = np.array(start, dtype=float)
    centre[u], centre[v] = (a + b) / 2.0 + side * height * left
    centre[w] = start[w]
    return centre


def check_radii(start, end, centre, plane):
    """The arc's radius (mm) at its start; ValueError when the start is the centre or the end's distance to
    the centre differs from the start's by more than RADIUS_TOLERANCE (or RADIUS_FRACTION of it)."""
    u, v, _ = PLANES[plane]
    first = math.hypot(start[u] - centre[u], start[v] - centre[v])
    last = math.hypot(end[u] - centre[u], end[v] - centre[v])
    if first <= SAME_POINT:
        raise ValueError("the centre is the start point")
    if abs(last - first) > max(RADIUS_TOLERANCE, RADIUS_FRACTION * first):
        raise ValueError(f"the end is {last:.6g} mm from the centre, the start {first:.6g} mm: the arc does not fit "
                         f"(at most {RADIUS_TOLERANCE:g} mm apart)")
    return first


def arc_moves(start, end, centre, plane, clockwise, turns, tolerance, step):
    """(points (k, 3), tangents (k, 3)) of the arc from `start` to `end` about `centre` in `plane` (module
    docstring), after `turns` − 1 full turns; the last point is `end`."""
    w = np.zeros(3)
    w[PLANES[plane][2]] = -1.0 if clockwise else 1.0
    start, end, centre = (np.asarray(p, dtype=float) for p in (start, end, centre))
    if turns == 1:
        return arc_points(start, end, centre, w, tolerance, step)
    afford(8 * (turns - 1))  # a full turn is at least 8 CL points (arcs.MAX_STEP)
    radial_end = (end - centre) - ((end - centre) @ w) * w
    reference = (start - centre) - ((start - centre) @ w) * w
    last = math.atan2(np.cross(reference, radial_end) @ w, reference @ radial_end) % (2.0 * math.pi)
    if np.linalg.norm(radial_end - reference) <= SAME_POINT:
        last = 2.0 * math.pi
    total = 2.0 * math.pi * (turns - 1) + last
    rise = (end - start) @ w
    pieces, here = [], start
    for turn in range(1, turns):
        there = start + rise * (2.0 * math.pi * turn / total) * w  # the start again, higher along w
        pieces.append(arc_points(here, there, centre, w, tolerance, step))
        here = there
    pieces.append(arc_points(here, end, centre, w, tolerance, step))
    return np.concatenate([p[0] for p in pieces]), np.concatenate([p[1] for p in pieces])
