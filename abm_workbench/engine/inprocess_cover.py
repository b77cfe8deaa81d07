"""Runs and covers of intervals along lines: where equal keys run, and how far a line's removals cover its
material from either end without a gap (the narrowing of the in-process searches). Lengths in mm."""

import numpy as np

from .ordering import group_order


def run_starts(key):
    """(start, count): where each run of equal values of key (K,) starts, and its length (both
    (R,) intp; empty for K = 0). Without np.r_, whose per-call cost is several times that of
    the comparison on the arrays met here."""
    new = np.empty(key.size, dtype=bool)
    new[:1] = True
    np.not_equal(key[1:], key[:-1], out=new[1:])
    start = new.nonzero()[0]
    count = np.empty_like(start)
    count[:-1] = start[1:] - start[:-1]
    count[-1:] = key.size - start[-1:]
    return start, count


def narrow(envelope, seg, enter, leave):
    """Narrow the envelopes (2, L) of segments `seg` (K,) by the removals [enter, leave] (K,):
    lo moves up past the removals that cover it without a gap, hi down likewise."""
    if seg.size == 0:
        return
    owners, low = covered_from(envelope[0], seg, enter, leave)
    envelope[0, owners] = low
    owners, high = covered_from(-envelope[1], seg, -leave, -enter)
    envelope[1, owners] = -high


def covered_from(start, seg, enter, leave):
    """(owners, reach): the segments seg (K,) holds once each, and how far from start[owner]
    (start (L,)) the run of their intervals [enter, leave] (K,) covers without a gap (start
    itself where none covers it): a sweep of each segment's intervals in order of enter (no sort where seg holds
    each segment once, in order: most calls of the level view, whose each query takes one piece at a time)."""
    if seg.size > 1 and not (seg[1:] > seg[:-1]).all():
        order = group_order(enter, seg)
        seg, enter, leave = seg[order], enter[order], leave[order]
    head, count = run_starts(seg)
    owners = seg[head]
    begin = start[owners]
    if head.size == seg.size:  # one interval per segment
        return owners, np.where(enter <= begin, np.maximum(begin, leave), begin)
    owner = np.repeat(np.arange(owners.size), count)
    rank = np.arange(seg.size) - np.repeat(head, count)
    # Row j: the j-th interval of each owner (a column); reach[j]: how far the intervals before
    # it cover from start, if they chain; enters past the last interval are +inf (a gap).
    width = int(count.max()) + 1
    enters = np.full((width, owners.size), np.inf)
    reach = np.full((width, owners.size), -np.inf)
    reach[0] = begin
    enters[rank, owner], reach[rank + 1, owner] = enter, leave
    np.maximum.accumulate(reach, axis=0, out=reach)
    gap = np.argmax(enters > reach, axis=0)
    return owners, reach[gap, np.arange(owners.size)]
