"""NX NURBS motion: a B-spline tool path, its knot layout resolved, evaluated at most a step apart.

NX writes a spline move as a ``NURBS/`` record followed by ``KNOT/`` and ``CNTRL/`` records
(the knots and the control points x, y, z, optionally a weight, in any grouping, also both on
one line as ``KNOT/u,CNTRL/x,y,z``). With K knots and N control points, the layouts read
(:func:`resolve`):

- ``full``: every knot written, K = N + p + 1, the degree p = K − N − 1;
- ``clamped ends``: the end knots written once, their multiplicity p + 1 implied,
  K = N − p + 1;
- either of them with the curve's start implied: its first control point is the tool's
  current position, not written (N + 1 control points in all).

NX's real files write two knots fewer than control points and leave the start implied. Of the
layouts the counts allow (p ≥ 1), one whose curve starts at the tool's position (within the
tolerance) is taken, those with the start written first; without a position, the first written
one. When none starts there, the first that gives a curve is taken and the tool's move to its
start is straight (the reader warns with the distance).

Tolerance: on a knot span the second derivative C'' is a convex combination of the second
difference vectors Q2 of the control points that act on the span, so |C''| <= M, the largest
|Q2| there; a chord over a parameter step h stays within M·h²/8 of the curve. Each span is cut
into equal steps small enough for that bound to be <= the tolerance, and for the chords to be
at most `step` mm (the span's control polygon, which is longer than the curve, over the count).
"""

import math
from typing import NamedTuple

import numpy as np

from ...errors import note
from .arcs import spend

#: Highest degree read.
MAX_DEGREE = 9


class Layout(NamedTuple):
    """A resolved NURBS block: knots (full vector), control points (n, 3) mm, degree, and its layout in
    words ("full" or "clamped ends", "start implied" added)."""

    knots: np.ndarray
    control: np.ndarray
    degree: int
    words: str


def _candidates(knots, control, start):
    """Layouts the counts allow, those with the start written first."""
    starts = [(control, "")]
    if start is not None:
        starts.append((np.vstack([start, control]), ", start implied"))
    found = []
    for points, implied in starts:
        n, k = len(points), len(knots)
        degree = k - n - 1
        if 1 <= degree <= MAX_DEGREE:
            found.append(Layout(knots, points, degree, "full" + implied))
        degree = n + 1 - k
        if 1 <= degree <= MAX_DEGREE and k >= 2:
            full = np.concatenate([np.repeat(knots[0], degree), knots, np.repeat(knots[-1], degree)])
            found.append(Layout(full, points, degree, "clamped ends" + implied))
    return found


def _check(layout):
    """A reason the layout's knots make no curve, or None."""
    knots, n, degree = layout.knots, len(layout.control), layout.degree
    if np.any(np.diff(knots) < 0.0):
        return note("the knots decrease")
    low, high = knots[degree], knots[n]
    if not high > low:
        return note("the knots leave the curve no parameter range")
    inner = knots[(knots > low) & (knots < high)]
    values, counts = np.unique(inner, return_counts=True)
    if (counts > degree).any():
        knot = values[counts > degree][0]
        return note(f"knot {knot:g} is repeated more often than the degree {degree}: the curve breaks there")
    return None


def resolve(knots, control, start, tolerance):
    """(Layout, gap) of `knots` (K,) and `control` (N, 3) mm for a curve following the tool's position
    `start` (3,) mm (None: unknown). gap: 0, or, when no layout's curve starts at the position, the
    distance (mm) from it to the start of the first layout that gives a curve (the move there is then
    straight). ValueError in words when no layout gives a curve at all."""
    from scipy.interpolate import BSpline  # here: scipy.interpolate takes a while to import

    knots = np.asarray(knots, dtype=float)
    control = np.asarray(control, dtype=float).reshape(-1, 3)
    start = None if start is None else np.asarray(start, dtype=float)
    candidates = _candidates(knots, control, start)
    if not candidates:
        raise ValueError(f"{len(knots)} knots and {len(control)} control points fit no B-spline of degree 1 to "
                         f"{MAX_DEGREE} (knots = control points + degree + 1, or the end knots written once: "
                         "control points - degree + 1)")
    reasons, curves = [], []
    for layout in candidates:
        reason = _check(layout)
        if reason is not None:
            reasons.append(note(f"{layout.words}, degree {layout.degree}: {reason}"))
            continue
        if start is None:
            return layout, 0.0
        first = BSpline(layout.knots, layout.control, layout.degree)(layout.knots[layout.degree])
        gap = float(np.linalg.norm(first - start))
        if gap <= max(tolerance, 1e-6):
            return layout, 0.0
        curves.append((layout, gap))
    if not curves:
        listed = "; ".join(reasons)
        raise ValueError(f"its knots give no curve ({listed})")
    return curves[0]


def bspline_points(layout, tolerance, step=math.inf):
    """(points (k, 3), tangents (k, 3)) along the B-spline of a Layout: the points after the curve's
    start, up to and including its end, chord error <= `tolerance` mm and chords at most `step` mm;
    tangents the unit direction of the motion arriving there."""
    from scipy.interpolate import BSpline

    knots, control, degree, _ = layout
    n = len(control)
    spline = BSpline(knots, control, degree)
    bound = _second_derivative_bounds(knots, control, degree)
    spans = np.arange(degree, n)
    a, b = knots[spans], knots[spans + 1]
    polygon = np.array([np.linalg.norm(np.diff(control[j - degree:j + 1], axis=0), axis=1).sum() for j in spans])
    length = b - a
    keep = length > 0.0
    a, length, bound, polygon = a[keep], length[keep], bound[keep], polygon[keep]
    counts = np.maximum(1, np.ceil(length * np.sqrt(bound / (8.0 * tolerance))))
    if np.isfinite(step):
        counts = np.maximum(counts, np.ceil(polygon / step - 1e-9))
    total = float(counts.sum())
    if not math.isfinite(total):
        raise ValueError("the curve bends too sharply to be interpolated (its second derivative is not finite)")
    spend(total)
    counts = counts.astype(int)
    first = np.repeat(np.cumsum(counts) - counts, counts)
    index = np.arange(int(counts.sum())) - first + 1
    parameters = np.repeat(a, counts) + np.repeat(length / counts, counts) * index
    parameters[-1] = knots[n]
    # The motion arriving at each point: the derivative of the span ending there (just left of a knot).
    tangents = spline.derivative()(np.nextafter(parameters, -np.inf))
    norm = np.linalg.norm(tangents, axis=1)
    tangents = np.where(norm[:, None] > 0.0, tangents / np.where(norm > 0.0, norm, 1.0)[:, None], 0.0)
    return spline(parameters), tangents


def _second_derivative_bounds(knots, control, degree):
    """(n - degree,) bound of |C''| on each span [knots[j], knots[j+1]], j = degree .. n-1."""
    n = len(control)
    if degree < 2:
        return np.zeros(n - degree)
    with np.errstate(divide="ignore", invalid="ignore"):
        gap1 = knots[degree + 1:n + degree] - knots[1:n]
        first = np.where(gap1[:, None] > 0, degree * np.diff(control, axis=0) / gap1[:, None], 0.0)
        gap2 = knots[degree + 1:n + degree - 1] - knots[2:n]
        second = np.where(gap2[:, None] > 0, (degree - 1) * np.diff(first, axis=0) / gap2[:, None], 0.0)
    size = np.linalg.norm(second, axis=1)
    # On span j the second derivative combines Q2[j-degree .. j-2].
    windows = np.lib.stride_tricks.sliding_window_view(size, degree - 1)
    return windows.max(axis=1)
