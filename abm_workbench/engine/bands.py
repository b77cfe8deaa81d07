"""Where each wall can be, and how steep it is, over any y interval of the stock's window, fast.

The window [y_min, y_max] is cut into BINS equal bins. Per wall and bin: the x range (exact
for quintic walls, from their critical points; a safe bound for B-spline walls, from their
control polygons) and the largest |dx/dy| (exact for quintics, infinite for B-splines). A
sparse table over the bins (ranges of 2^k bins, k = 0..log2 BINS) answers "over y in [a, b],
where can wall j be and how steep is it" for many (a, b, j) at once with two look-ups, so
the engine only solves the walls an edge line can reach, and proves most crossings unique.
"""

import numpy as np

#: Bins across the y window.
BINS = 64


class WallBands:
    """x ranges and slope bounds of n_w walls over y intervals of [y_min, y_max] (mm).

    low, high, slope: (levels, n_w, BINS) sparse tables: entry [k, j, b] covers bins
    b .. b + 2^k − 1. whole: (n_w, 2) x range of each wall over the whole window.
    reach_low, reach_high: (n_w,) monotone envelopes of whole (the least low of walls j and
    after, the greatest high of walls j and before), so that the walls whose x range meets an
    interval are a run found by bisection (whole itself need not be monotone for bounds).
    """

    def __init__(self, walls, y_min, y_max):
        self.y_min, self.y_max = float(y_min), float(y_max)
        self.n_walls = len(walls)
        edges = np.linspace(self.y_min, self.y_max, BINS + 1)
        per_bin = np.array([w.bins(edges) for w in walls]).reshape(self.n_walls, 3, BINS)
        self.low = sparse_table(per_bin[:, 0], np.minimum)
        self.high = sparse_table(per_bin[:, 1], np.maximum)
        self.slope = sparse_table(per_bin[:, 2], np.maximum)
        self.whole = np.column_stack([per_bin[:, 0].min(axis=1), per_bin[:, 1].max(axis=1)]).reshape(-1, 2)
        self.reach_low = np.minimum.accumulate(self.whole[::-1, 0])[::-1]
        self.reach_high = np.maximum.accumulate(self.whole[:, 1])
        # The same tables flat, and the scale from y to bins, for query's look-ups.
        self._flat = tuple(table.reshape(-1) for table in (self.low, self.high, self.slope))
        self._scale = BINS / (self.y_max - self.y_min)

    def query(self, y_a, y_b, walls):
        """(low, high, slope), each (P,): x range and max |dx/dy| of wall walls[i] over y between
        y_a[i] and y_b[i]."""
        first, last = (np.minimum(np.maximum(np.floor((y - self.y_min) * self._scale), 0.0), BINS - 1.0).astype(np.intp)
                       for y in (np.minimum(y_a, y_b), np.maximum(y_a, y_b)))
        level = _FLOOR_LOG2[last - first + 1]
        row = (level * self.n_walls + walls) * BINS
        at_first, at_second = row + first, row + last - (1 << level) + 1
        low, high, slope = self._flat
        return (np.minimum(low.take(at_first), low.take(at_second)),
                np.maximum(high.take(at_first), high.take(at_second)),
                np.maximum(slope.take(at_first), slope.take(at_second)))


#: ⌊log2 k⌋ for k = 0..BINS (entry 0 unused): the sparse-table level covering k bins.
_FLOOR_LOG2 = np.concatenate([[0], np.floor(np.log2(np.arange(1, BINS + 1)))]).astype(np.intp)


def sparse_table(per_bin, combine):
    """Range look-ups of per_bin (n_w, n_bins), by `combine` (np.minimum or np.maximum): (levels, n_w,
    n_bins), level k combining bins b .. b + 2^k − 1 (clamped at the last bin)."""
    levels, width = [per_bin], 1
    while 2 * width <= per_bin.shape[1]:
        previous = levels[-1]
        shifted = np.concatenate([previous[:, width:], previous[:, -width:]], axis=1)
        levels.append(combine(previous, shifted))
        width *= 2
    return np.stack(levels)
