"""The in-process search's closed form and deep-inside test against independent references.

swept.line_hull_interval writes its candidates into one table and evaluates their feasibility
in place, and inprocess._inside takes several points against one hull at once
(docs/BENCHMARKS.md, "The pocket's search, leaner"). Here:
- a point lies deep inside a hull (inprocess._deep_inside) exactly when a dense sampling of the
  positions s along the move finds one that puts it inside the shrunk cylinder (checked only
  where the sampling is sure: the point is inside a hull shrunk by 0.01 mm more, or outside one
  grown by 0.01 mm);
- line_hull_interval gives each row the same bits alone as in a batch, and in a batch whose
  rows come in another order (each row's arithmetic is its own, whatever the table around it);
- the pair of each segment tested first (inprocess._latest) is the one of its largest span or
  chain, against a loop over the segments.
Lengths in mm.
"""

import numpy as np

from abm_workbench.engine.inprocess import _deep_inside, _latest
from abm_workbench.engine.swept import line_hull_interval

S_SAMPLES = 2001   # positions s ∈ [0, 1] along a move (a step of at most 0.005 mm here)
MARGIN = 0.01      # mm: points nearer the boundary than this are not judged by the sampling


def sampled_inside(x, c0, c1, w, r, low, high):
    """(P,) bool: some sampled s ∈ [0, 1] puts the point x (P, 3) within r of the axis w through
    c0 + s·(c1 − c0), at a height low … high above that point (one move, written from the
    definition: the tool's cylinder at each sampled position)."""
    s = np.linspace(0.0, 1.0, S_SAMPLES)
    centre = c0[None, :] + s[:, None] * (c1 - c0)[None, :]                 # (S, 3)
    q = x[:, None, :] - centre[None, :, :]                                 # (P, S, 3)
    height = q @ w
    across = np.linalg.norm(q - height[..., None] * w, axis=2)
    return ((height >= low) & (height <= high) & (across <= r)).any(axis=1)


def test_deep_inside_against_sampled_positions():
    """Random segments against random moves (some along the axis, some still, some tilted): both
    ends at least `slack` inside the hull, as _deep_inside says, exactly where the sampling is sure."""
    rng = np.random.default_rng(11)
    judged = 0
    for trial in range(40):
        w = rng.normal(size=3) if trial % 3 else np.array([0.0, 0.0, 1.0])
        w /= np.linalg.norm(w)
        c0 = rng.normal(size=3)
        d = rng.normal(size=3) * rng.choice([0.0, 0.5, 3.0]) if trial % 5 else 1.5 * w
        c1 = c0 + d
        r, h, slack = rng.uniform(1.0, 3.0), rng.uniform(2.0, 6.0), rng.choice([0.0, 0.05])
        n = 100
        a = c0 + rng.normal(size=(n, 3)) * 1.5 + 0.5 * h * w
        b = a + rng.normal(size=(n, 3)) * 0.5
        rows = lambda v: np.repeat(np.atleast_2d(v), n, axis=0)  # noqa: E731
        found = _deep_inside(a, b, rows(c0), rows(c1), rows(w), np.full(n, r), np.full(n, h), np.full(n, slack),
                             np.zeros(n))
        sure_in = (sampled_inside(a, c0, c1, w, r - slack - MARGIN, slack + MARGIN, h - slack - MARGIN)
                   & sampled_inside(b, c0, c1, w, r - slack - MARGIN, slack + MARGIN, h - slack - MARGIN))
        sure_out = (~sampled_inside(a, c0, c1, w, r - slack + MARGIN, slack - MARGIN, h - slack + MARGIN)
                    | ~sampled_inside(b, c0, c1, w, r - slack + MARGIN, slack - MARGIN, h - slack + MARGIN))
        assert found[sure_in].all(), trial
        assert not found[sure_out].any(), trial
        judged += int(sure_in.sum() + sure_out.sum())
    assert judged > 0.9 * 40 * 100


def test_line_hull_interval_rows_alone_and_in_any_order():
    """Every row of a batch (lines along the axis, across it, moves along it and still, misses)
    gets the same bits when solved alone and when the batch comes reversed."""
    rng = np.random.default_rng(3)
    n = 400
    w = rng.normal(size=(n, 3))
    w[::4] = [0.0, 0.0, 1.0]
    w /= np.linalg.norm(w, axis=1)[:, None]
    c0 = rng.normal(size=(n, 3)) * 2.0
    d = rng.normal(size=(n, 3)) * rng.choice([0.0, 0.3, 3.0], size=(n, 1))
    d[1::7] = 2.0 * w[1::7]
    u = rng.normal(size=(n, 3))
    u[::3] = w[::3]
    u /= np.linalg.norm(u, axis=1)[:, None]
    o = c0 + rng.normal(size=(n, 3)) * 3.0
    r, h = rng.uniform(0.5, 3.0, n), rng.uniform(2.0, 8.0, n)
    enter, leave = line_hull_interval(o, u, c0, c0 + d, w, r, h)
    assert np.isfinite(enter).sum() > n // 5 and np.isnan(enter).sum() > n // 10
    back = slice(None, None, -1)
    enter_r, leave_r = line_hull_interval(o[back], u[back], c0[back], (c0 + d)[back], w[back], r[back], h[back])
    np.testing.assert_array_equal(enter_r[back].view(np.int64), enter.view(np.int64))
    np.testing.assert_array_equal(leave_r[back].view(np.int64), leave.view(np.int64))
    for i in range(0, n, 9):
        one = slice(i, i + 1)
        e, l = line_hull_interval(o[one], u[one], c0[one], (c0 + d)[one], w[one], r[one], h[one])
        assert e.view(np.int64)[0] == enter.view(np.int64)[i] and l.view(np.int64)[0] == leave.view(np.int64)[i]


def test_latest_pair_of_each_segment_against_a_loop():
    """inprocess._latest (which pair of each segment is tested for deep inside first): one row per
    distinct segment, holding its largest item, the first such row; segments in order, in runs
    out of order, and empty."""
    rng = np.random.default_rng(4)
    for trial in range(30):
        n = int(rng.integers(0, 60))
        seg = np.sort(rng.integers(0, 12, n)) if trial % 2 else rng.integers(0, 12, n)
        item = rng.integers(0, 5, n)
        rows = _latest(seg, item)
        expected = []
        for s in np.unique(seg):
            mine = np.flatnonzero(seg == s)
            expected.append(mine[np.argmax(item[mine])])  # argmax: the first of the largest
        assert sorted(rows.tolist()) == sorted(expected), trial
