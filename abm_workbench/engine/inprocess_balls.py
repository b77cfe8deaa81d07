"""The earlier moves' bounding balls in parts, for the query of which balls a sphere may meet.

The in-process search (:mod:`.inprocess`) bounds each chain of earlier moves by balls and asks,
for spheres around groups of edge-line segments, which balls they meet: centre distance at most
the sum of the two radii. A KD tree answers "all centres within one distance"; over all balls
of a program that distance has to be the largest sphere radius plus the largest ball radius, and
a program's few long straight moves (a pocket's sides, a slot's leg) have balls three times the
radius of the others: nine tenths of the pairs the tree gave were then dropped by the exact test
(docs/BENCHMARKS.md, "The in-process search: balls in parts").

Here the balls are put in parts, each with its own KD tree: by radius (classes 1.5 times apart),
then by program order (runs of BLOCK balls). A query asks each part only within the largest
sphere radius plus that part's largest ball radius, and skips the parts whose balls all belong to
moves after the last one the spheres may meet, and those whose centres' bounding box lies farther
than that distance from the spheres' centres' box (no centre of one can then be nearer a centre of
the other: a real program's runs of moves sweep one area at a time, so most parts are skipped
without a query). The pairs kept are those that meet exactly, the same set whatever the parts:
every pair that meets lies within its part's distance.

Balls may also carry a floor: a height along an axis below which the hull they bound has no point
(the lowest point of a chain of moves whose tool axis is that axis). A query given the top of each
sphere along that axis (the highest point of what it stands for) then drops the pairs whose floor
lies above that top, and skips the parts whose floors all do: a line's material below a ramp's
hull meets none of its balls, though a ball, holding a slice of the tool's disk, reaches about the
tool's radius below the hull. Lengths in mm.
"""

import numpy as np

#: Balls per part at most (of one radius class, consecutive in program order).
BLOCK = 512
#: Ratio of the largest ball radius of a class to the smallest radius of all balls, class by class.
CLASS_RATIO = 1.5
#: Relative margin on a part's query distance, so that the KD tree's own rounding of the distance
#: can never leave out a pair the exact test keeps; also on a floor above a top (relative to their size).
_MARGIN = 1e-9


class BallParts:
    """Balls (centre (B, 3), bound (B,) their radii, move (B,) the first program row of the moves
    they bound, non-decreasing; floor (B,), if given: the height below which their hulls have no point,
    −inf where none is known) in parts of at most `block` balls with a KD tree each
    (scipy.spatial.cKDTree)."""

    def __init__(self, centre, bound, move, floor=None, block=BLOCK):
        from scipy.spatial import cKDTree  # here: scipy.spatial takes a while to import

        centre = np.asarray(centre, dtype=float).reshape(-1, 3)
        bound = np.asarray(bound, dtype=float).reshape(-1)
        move = np.asarray(move).reshape(-1)
        floor = np.full(bound.shape, -np.inf) if floor is None else np.asarray(floor, dtype=float).reshape(-1)
        if bound.shape[0] != centre.shape[0] or move.shape[0] != centre.shape[0] or floor.shape != bound.shape:
            raise ValueError("centre, bound, move and floor must have one row per ball")
        if (np.diff(move) < 0).any():
            raise ValueError("the balls must come in program order (move non-decreasing)")
        self.bound, self.floor = bound, floor
        #: Per part: the balls (ascending indices), their largest radius, the first move, the tree, the
        #: lower and upper corners of its centres' bounding box, and the lowest floor of its balls.
        self.parts = []
        if bound.size == 0:
            return
        smallest = float(bound.min())
        grade = np.floor(np.log(bound / smallest) / np.log(CLASS_RATIO)) if smallest > 0.0 else np.zeros(bound.size)
        for value in np.unique(grade):
            members = np.flatnonzero(grade == value)
            for begin in range(0, members.size, block):
                balls = members[begin:begin + block]
                at = centre[balls]
                self.parts.append((balls, float(bound[balls].max()), move[balls[0]], cKDTree(at), at.min(axis=0),
                                   at.max(axis=0), float(floor[balls].min())))

    def __len__(self):
        return self.bound.size

    def meeting(self, centre, radius, before, top=None):
        """The pairs (sphere i (K,), ball (K,)) whose distance of centres is at most radius[i] plus
        the ball's bound, among the balls of the parts whose first move is at most max(before):
        spheres centre (n, 3), radius (n,), all finite; before: the last program row any of them may
        meet. With top (n,) (each sphere's highest point along the floors' axis), less the pairs whose
        ball's floor lies above the sphere's top (by more than _MARGIN of their size). Order
        unspecified."""
        found_i, found_ball = [np.zeros(0, dtype=np.intp)], [np.zeros(0, dtype=np.intp)]
        if radius.size == 0 or not self.parts:
            return found_i[0], found_ball[0]
        from scipy.spatial import cKDTree

        spheres = cKDTree(centre)
        largest = float(radius.max())
        low, high = centre.min(axis=0), centre.max(axis=0)
        highest = np.inf if top is None else float(top.max())
        for balls, bound, first, tree, part_low, part_high, floor in self.parts:
            if first > before or _above(floor, highest):
                continue
            reach = (largest + bound) * (1.0 + _MARGIN)
            if np.linalg.norm(np.maximum(np.maximum(part_low - high, low - part_high), 0.0)) > reach:
                continue
            near = spheres.sparse_distance_matrix(tree, reach, output_type="ndarray")
            i, ball = near["i"].astype(np.intp), balls[near["j"]]
            keep = near["v"] <= radius[i] + self.bound[ball]
            if top is not None:
                keep &= ~_above(self.floor[ball], top[i])
            found_i.append(i[keep])
            found_ball.append(ball[keep])
        return np.concatenate(found_i), np.concatenate(found_ball)


def _above(floor, top):
    """Whether the floor lies above the top by more than _MARGIN of their size (floats or arrays; a floor of
    −inf never is)."""
    with np.errstate(invalid="ignore"):
        return floor - top > _MARGIN * (1.0 + np.abs(floor) + np.abs(top))
