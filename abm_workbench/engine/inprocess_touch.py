"""Earlier moves that only touch a line's remaining material at its end: dropped without solving.

The in-process search (:mod:`.inprocess`) keeps a line's remaining material within an envelope
lo … hi and drops an earlier move's piece (or span, or chain) when a sure-miss test proves it
cannot reach that envelope. Once a removal has narrowed the envelope, its end lies exactly on
the boundary of the hull that made it; on real roughing programs dozens to hundreds of other
earlier moves have their boundary at that same place up to rounding: the moves of one z level
all have their bottom in one plane, and a line of a later, deeper level, parallel to the tool
axis, ends its material exactly there. The sure-miss test must keep them (it proves a miss only
with a clearance of 2·10⁻⁹ mm), and each was solved in closed form and tested again round after
round: 80–90 % of the in-process time on such programs (docs/BENCHMARKS.md, "In-process stock on
real-shaped programs").

:func:`touching` drops, in addition, the pairs whose line segment reaches into the hull's axial
range (grown by the test's own bounds) by at most TOUCH mm measured along the segment: the
segment is straight, so the part of it beyond the hull's bottom (or top) plane is shorter than
TOUCH, and so is all the material such a hull could remove from the envelope. Across the axis
(the hull's side) nothing is relaxed: a line parallel to the axis grazing the side would lose
its whole length. Lengths in mm.
"""

import numpy as np

from .swept import FEASIBLE_EPS, row_dot

#: A hull reaching into a line's envelope along its axis by at most this (mm, measured along the
#: line) is dropped unsolved.
TOUCH = 1e-11
#: The sure-miss test's own clearance (inprocess._CLEAR), given back with the allowance.
_CLEAR = 2.0 * FEASIBLE_EPS


def touching(a, b, aa, ab, floor, ceiling):
    """(K,) bool: the segments a … b (K, 3) that lie wholly below the `floor` (K,) or above the
    `ceiling` (K,) of a hull's axial range, or reach beyond it by less than (TOUCH + _CLEAR)·c,
    c = |(b − a)·w| / |b − a| the cosine of the segment with the axis w (aa, ab (K,): a and b
    along w, relative to the hull; floor and ceiling already lowered and raised by the sure-miss
    test's bounds and its clearance _CLEAR). Such a segment lies within TOUCH·c + _CLEAR·(c − 1)
    ≤ TOUCH·c of the grown hull's bottom (or top) plane over the part of it beyond that plane, a
    part shorter than TOUCH along the segment. The allowance is worked out only for the segments
    within the largest one (c = 1) of the floor or the ceiling."""
    top, bottom = np.maximum(aa, ab), np.minimum(aa, ab)
    wide = TOUCH + _CLEAR
    found = (top < floor + wide) | (bottom > ceiling - wide)
    near = np.flatnonzero(found)
    top, bottom, floor, ceiling = top[near], bottom[near], floor[near], ceiling[near]
    strict = (top < floor) | (bottom > ceiling)
    edge = np.flatnonzero(~strict)
    if edge.size:
        at = near[edge]
        d = np.take(b, at, axis=0) - np.take(a, at, axis=0)
        length = np.sqrt(row_dot(d, d))
        rise = np.abs(ab[at] - aa[at])
        allowance = wide * np.where(length > 0.0, rise / np.where(length > 0.0, length, 1.0), 0.0)
        strict[edge] = (top[edge] < floor[edge] + allowance) | (bottom[edge] > ceiling[edge] - allowance)
    found[near] = strict
    return found
