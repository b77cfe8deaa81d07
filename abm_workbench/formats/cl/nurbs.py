"""NX NURBS motion: a B-spline tool path evaluated to a chordal tolerance.

NX writes a spline move as a ``NURBS/`` record followed by ``KNOT/`` and ``CNTRL/`` records
(the knots and the control points x, y, z, optionally a weight, in any grouping, also both on
one line as ``KNOT/u,CNTRL/x,y,z``). The degree is the number of knots less the number of
control points less one. The curve is evaluated with :class:`scipy.interpolate.BSpline`.

Tolerance: on a knot span the second derivative C'' is a convex combination of the second
difference vectors Q2 of the control points that act on the span, so |C''| <= M, the largest
|Q2| there; a chord over a parameter step h stays within M·h²/8 of the curve. Each span is cut
into equal steps small enough for that bound to be <= the tolerance.
"""


import numpy as np


def bspline_points(knots, control, tolerance):
    """Points (k, 3) along the B-spline of `knots` (m,) and `control` points (n, 3), mm.

    The points after the curve's start, up to and including its end, chord error <= `tolerance`
    mm. ValueError for knots that decrease, a count that leaves no degree >= 1, or an inner knot
    repeated more often than the degree (a curve in pieces).
    """
    knots = np.asarray(knots, dtype=float)
    control = np.asarray(control, dtype=float)
    n = len(control)
    degree = len(knots) - n - 1
    if n < 2 or degree < 1:
        raise ValueError(f"{len(knots)} knots and {n} control points give no B-spline of degree 1 or more "
                         "(knots = control points + degree + 1)")
    if np.any(np.diff(knots) < 0.0):
        raise ValueError("the knots decrease")
    low, high = knots[degree], knots[n]
    if not high > low:
        raise ValueError("the knots leave the curve no parameter range")
    inner = knots[(knots > low) & (knots < high)]
    values, counts = np.unique(inner, return_counts=True)
    if (counts > degree).any():
        raise ValueError(f"knot {values[counts > degree][0]:g} is repeated more often than the degree "
                         f"{degree}: the curve breaks there")
    from scipy.interpolate import BSpline  # here: scipy.interpolate takes a while to import

    spline = BSpline(knots, control, degree)
    bound = _second_derivative_bounds(knots, control, degree)
    spans = np.arange(degree, n)
    a, b = knots[spans], knots[spans + 1]
    length = b - a
    keep = length > 0.0
    a, length, bound = a[keep], length[keep], bound[keep]
    counts = np.maximum(1, np.ceil(length * np.sqrt(bound / (8.0 * tolerance)))).astype(int)
    first = np.repeat(np.cumsum(counts) - counts, counts)
    step = np.arange(int(counts.sum())) - first + 1
    parameters = np.repeat(a, counts) + np.repeat(length / counts, counts) * step
    parameters[-1] = high
    return spline(parameters)


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


