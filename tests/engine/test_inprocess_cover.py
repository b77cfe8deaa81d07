"""How far a line's removals cover its material from either end (inprocess_cover) against a sweep of the
intervals one by one."""

import numpy as np

from abm_workbench.engine.inprocess_cover import covered_from


def swept(start, seg, enter, leave):
    """covered_from by a plain loop: each segment's intervals by enter, the cover grown while they chain."""
    owners = np.unique(seg)
    reach = []
    for owner in owners:
        mine = np.flatnonzero(seg == owner)
        cover = start[owner]
        for i in mine[np.argsort(enter[mine], kind="stable")]:
            if enter[i] <= cover:
                cover = max(cover, leave[i])
        reach.append(cover)
    return owners, np.array(reach)


def test_covered_from_in_order_or_not():
    """Segments given once each in ascending order (taken without a sort), in ascending order with repeats, or in any
    order: the same owners and covers as the plain sweep."""
    rng = np.random.default_rng(7)
    for _ in range(300):
        lines = int(rng.integers(1, 12))
        start = rng.uniform(-1.0, 1.0, lines)
        count = int(rng.integers(1, 3 * lines))
        kind = rng.integers(3)
        if kind == 0:  # each segment once, in order
            seg = np.sort(rng.choice(lines, min(count, lines), replace=False))
        else:  # in order with repeats (intervals of a segment in any order of enter), or in any order
            seg = rng.integers(0, lines, count)
            seg = np.sort(seg) if kind == 1 else seg
        enter = rng.uniform(-1.5, 1.5, seg.size)
        leave = enter + rng.uniform(0.0, 1.0, seg.size)
        owners, reach = covered_from(start, seg, enter, leave)
        expected = swept(start, seg, enter, leave)
        assert np.array_equal(owners, expected[0])
        assert np.array_equal(reach, expected[1])
