"""The feed of each CL point: its direction in plan view (α) and the tool's inclination to it.

The paper's pass feeds along +x and measures the rotation angle φ from the tool frame's +v.
Real moves run in every direction, so the tool frame of a CL point is turned about z by the
direction in plan view of the tool tip's motion on the move ending there (docs/ENGINE.md,
"Frames"): R = Rz(α)·Rx(θ_A)·Ry(θ_B).

Shapes: m CL points; directions (m, 3) of the motion arriving at each point (any length, zero
where there is none); α (m,) degrees; inclination (m,) degrees.

Rules, in order:
- the move ending at a CL point gives its feed (an arc or curve: its tangent there); the first
  CL point of a cut, where no cutting move ends, takes the move leaving it;
- a move of zero length keeps the previous point's feed, and a move with no motion in plan view
  (a plunge along z) the previous point's α; before any motion (in plan view), the first that
  follows; a path with none at all has α = 0;
- the inclination is the angle between the motion and the plane square to the tool axis,
  asin |f̂·w|: the paper's inclination α (its tool leans by α towards the feed), for any feed.
  The chip a side edge cuts is the feed's part square to the axis, f·cos(inclination).
"""

import numpy as np

#: A motion shorter than this (mm) is no motion.
STILL = 1e-9
#: A motion whose part in plan view is shorter than this fraction of it has none in plan view.
PLAN_FRACTION = 1e-7


def path_directions(points, starts=None):
    """(m, 3) chord of the move arriving at each of `points` (m, 3) mm; zero for the first point (the
    rules take the motion that follows), and wherever `starts` (m,) bool marks the first point of a
    cut (no cutting move arrives there) the chord of the move leaving it."""
    points = np.asarray(points, dtype=float).reshape(-1, 3)
    directions = np.zeros_like(points)
    chords = np.diff(points, axis=0)
    directions[1:] = chords
    if starts is not None:
        first = np.flatnonzero(np.asarray(starts, dtype=bool).reshape(-1))
        directions[first] = 0.0
        leaving = first[first < len(chords)]
        directions[leaving] = chords[leaving]
    return directions


def _filled(valid):
    """(m,) index of the row each row takes its value from: itself where `valid`, else the last
    valid row before it, else the first valid row after it; -1 where no row is valid."""
    m = valid.size
    index = np.where(valid, np.arange(m), -1)
    np.maximum.accumulate(index, out=index)
    first = np.flatnonzero(valid)
    if first.size:
        index[index < 0] = first[0]
    return index


def feed_frame(directions):
    """(α (m,) deg, unit feed directions (m, 3)) of the motions `directions` (m, 3) arriving at
    each CL point, by the rules of the module docstring. Rows with no motion take the unit
    direction they are filled from (zero when the path never moves)."""
    directions = np.asarray(directions, dtype=float).reshape(-1, 3)
    length = np.sqrt((directions * directions).sum(axis=1))
    moving = np.isfinite(length) & (length > STILL)
    source = _filled(moving)
    unit = np.zeros_like(directions)
    rows = source >= 0
    unit[rows] = directions[source[rows]] / length[source[rows], None]
    plan = np.hypot(unit[:, 0], unit[:, 1])
    in_plan = rows & (plan > PLAN_FRACTION)
    plan_source = _filled(in_plan)
    alpha = np.zeros(len(directions))
    has = plan_source >= 0
    x, y = np.ascontiguousarray(unit[plan_source[has], :2].T)
    alpha[has] = np.degrees(np.arctan2(y, x))
    return alpha, unit


def inclinations(axes, feed):
    """(m,) angle (deg) between the unit feed directions `feed` (m, 3) and the plane square to the
    unit tool axes `axes` (m, 3): asin |f̂·w|; 0 where there is no feed."""
    axes = np.asarray(axes, dtype=float).reshape(-1, 3)
    feed = np.asarray(feed, dtype=float).reshape(-1, 3)
    along = np.abs((axes * feed).sum(axis=1))
    return np.degrees(np.arcsin(np.clip(along, 0.0, 1.0)))
