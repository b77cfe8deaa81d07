"""A terraced stock's boundary curves as rational Bézier pieces, grouped by degree, per slab.

Every plan curve becomes one or more pieces: a :class:`PlanLine` one piece of degree 1, a
:class:`PlanArc` rational quadratic pieces of at most 90° each, a :class:`PlanSpline` its
Bézier spans (found by knot insertion until every knot in its range has multiplicity equal to
the degree). Within a loop each piece ends exactly on the first control point of the next one
(the loop's joints, at most ``terraced_model.LOOP_GAP`` apart, are closed by moving the end
point onto the next start), so the side of a line a joint lies on is decided once.

Curves are numbered over the whole stock, slab by slab, loop by loop, curve by curve from 0:
the "wall" index of a label. :func:`curve_list` gives the (slab, loop, curve, object) of
every index, so a label's face name is ``curve_list(stock)[wall][3].face``.
"""

from dataclasses import dataclass
from math import comb

import numpy as np

from .terraced_model import PlanArc, PlanLine, PlanSpline

#: Largest sweep of one rational quadratic arc piece (radians).
ARC_PIECE = 0.5 * np.pi


def curve_list(stock):
    """[(slab k, loop i, curve c, curve object)] in wall-index order over the whole stock."""
    return [(k, i, c, curve) for k, slab in enumerate(stock.slabs) for i, loop in enumerate(slab.loops)
            for c, curve in enumerate(loop.curves)]


def _insert_knot(knots, homogeneous, degree, t):
    """Boehm's insertion of knot t once: (knots (n+p+1,), homogeneous control (n, 3)) -> (n+p+2,), (n+1, 3)."""
    k = int(np.searchsorted(knots, t, side="right")) - 1
    out = np.empty((homogeneous.shape[0] + 1, 3))
    out[: k - degree + 1] = homogeneous[: k - degree + 1]
    out[k + 1:] = homogeneous[k:]
    i = np.arange(k - degree + 1, k + 1)
    alpha = ((t - knots[i]) / (knots[i + degree] - knots[i]))[:, None]
    out[i] = (1.0 - alpha) * homogeneous[i - 1] + alpha * homogeneous[i]
    return np.insert(knots, k + 1, t), out


def spline_pieces(spline):
    """Bézier spans of a PlanSpline over knots[p] .. knots[n]: control (S, p+1, 2) mm, weights (S, p+1)."""
    p = spline.degree
    knots = np.array(spline.knots, dtype=float)
    weights = np.ones(len(spline.control)) if spline.weights is None else np.array(spline.weights, dtype=float)
    homogeneous = np.column_stack([spline.control * weights[:, None], weights])
    t_lo, t_hi = knots[p], knots[len(spline.control)]
    for t in np.unique(knots[(knots >= t_lo) & (knots <= t_hi)]):
        for _ in range(p - int(np.count_nonzero(knots == t))):
            knots, homogeneous = _insert_knot(knots, homogeneous, p, t)
    n = homogeneous.shape[0]
    spans = [i for i in range(p, n) if knots[i + 1] > knots[i] and knots[i] >= t_lo and knots[i + 1] <= t_hi]
    blocks = np.array([homogeneous[i - p: i + 1] for i in spans])
    return blocks[..., :2] / blocks[..., 2:], blocks[..., 2]


def arc_pieces(arc):
    """Rational quadratic pieces of a PlanArc: control (S, 3, 2) mm, weights (S, 3)."""
    count = int(np.ceil(abs(arc.sweep) / ARC_PIECE - 1e-12))
    step = arc.sweep / count
    a0 = arc.start_angle + step * np.arange(count)
    a1 = arc.start_angle + step * np.arange(1, count + 1)
    middle = arc.center + arc.radius / np.cos(0.5 * step) * np.stack(
        [np.cos(0.5 * (a0 + a1)), np.sin(0.5 * (a0 + a1))], axis=-1)
    control = np.stack([arc.at(a0), middle, arc.at(a1)], axis=1)
    weights = np.tile([1.0, np.cos(0.5 * step), 1.0], (count, 1))
    return control, weights


def curve_pieces(curve):
    """(control (S, d+1, 2), weights (S, d+1)) of any plan curve."""
    if isinstance(curve, PlanLine):
        return np.stack([curve.start, curve.end])[None], np.ones((1, 2))
    if isinstance(curve, PlanArc):
        return arc_pieces(curve)
    if isinstance(curve, PlanSpline):
        return spline_pieces(curve)
    raise ValueError(f"not a plan curve: {type(curve).__name__}")


def bernstein_to_power(degree):
    """(d+1, d+1) matrix M with a = M·b: power-basis coefficients on [0, 1] of Bernstein ones."""
    return np.array([[comb(degree, k) * comb(k, i) * (-1) ** (k - i) if i <= k else 0.0 for i in range(degree + 1)]
                     for k in range(degree + 1)])


@dataclass(frozen=True)
class PieceGroup:
    """Pieces of one degree d of one slab: control (P, d+1, 2) mm, weights (P, d+1), wall (P,)
    the flat curve index of each, homogeneous (P, d+1, 3) power-basis coefficients on u ∈
    [0, 1] of (w·x, w·y, w) to evaluate points, and a circle holding each piece's control
    points: centre (P, 2) mm, radius (P,) mm."""

    degree: int
    control: np.ndarray
    weights: np.ndarray
    wall: np.ndarray
    homogeneous: np.ndarray
    centre: np.ndarray
    radius: np.ndarray


def slab_pieces(stock):
    """Per slab, a list of PieceGroup (one per degree present); and (W,) bool, whether each
    flat curve is a straight line (a PlanLine)."""
    groups, straight, wall = [], [], 0
    for slab in stock.slabs:
        by_degree = {}
        for loop in slab.loops:
            pieces = []
            for curve in loop.curves:
                control, weights = curve_pieces(curve)
                pieces.extend((c, w, wall) for c, w in zip(control, weights))
                straight.append(isinstance(curve, PlanLine))
                wall += 1
            for i, (control, weights, index) in enumerate(pieces):
                control = control.copy()
                control[-1] = pieces[(i + 1) % len(pieces)][0][0]  # close the joint exactly
                by_degree.setdefault(control.shape[0] - 1, []).append((control, weights, index))
        slab_groups = []
        for degree in sorted(by_degree):
            control = np.array([c for c, _, _ in by_degree[degree]])
            weights = np.array([w for _, w, _ in by_degree[degree]])
            homogeneous = np.concatenate([control * weights[..., None], weights[..., None]], axis=-1)
            power = np.einsum("ki,pic->pkc", bernstein_to_power(degree), homogeneous)
            centre = 0.5 * (control.min(axis=1) + control.max(axis=1))
            radius = np.sqrt(((control - centre[:, None]) ** 2).sum(axis=2)).max(axis=1)
            slab_groups.append(PieceGroup(degree, control, weights,
                                          np.array([i for _, _, i in by_degree[degree]], dtype=np.intp), power,
                                          centre, radius))
        groups.append(slab_groups)
    return groups, np.array(straight, dtype=bool)


def split_pieces(groups, longest, depth=8):
    """The same slab pieces (slab_pieces' groups) with every piece of degree ≥ 2 whose circle is wider than
    `longest` mm halved (de Casteljau on its homogeneous control points) until it is not, at most `depth`
    times: the same curves, in pieces whose circles are tighter, so fewer are near any one place. The
    halves of a piece meet exactly (one computed point ends one and starts the other)."""
    out = []
    for slab_groups in groups:
        refined = []
        for group in slab_groups:
            if group.degree < 2:
                refined.append(group)
                continue
            homogeneous = np.concatenate([group.control * group.weights[..., None], group.weights[..., None]], axis=-1)
            wall, radius = group.wall, group.radius
            for _ in range(depth):
                wide = radius > longest
                if not wide.any():
                    break
                left, right = _halved(homogeneous[wide])
                homogeneous = np.concatenate([homogeneous[~wide], np.stack([left, right], axis=1).reshape(
                    -1, *left.shape[1:])])
                wall = np.concatenate([wall[~wide], np.repeat(wall[wide], 2)])
                control = homogeneous[..., :2] / homogeneous[..., 2:]
                centre = 0.5 * (control.min(axis=1) + control.max(axis=1))
                radius = np.sqrt(((control - centre[:, None]) ** 2).sum(axis=2)).max(axis=1)
            weights = homogeneous[..., 2]
            control = homogeneous[..., :2] / homogeneous[..., 2:]
            centre = 0.5 * (control.min(axis=1) + control.max(axis=1))
            refined.append(PieceGroup(group.degree, control, weights, wall,
                                      np.einsum("ki,pic->pkc", bernstein_to_power(group.degree), homogeneous), centre,
                                      np.sqrt(((control - centre[:, None]) ** 2).sum(axis=2)).max(axis=1)))
        out.append(refined)
    return out


def _halved(homogeneous):
    """Homogeneous control points (P, d+1, 3) of each piece's halves u ∈ [0, ½] and [½, 1] (de Casteljau)."""
    rows = [homogeneous]
    for _ in range(homogeneous.shape[1] - 1):
        rows.append(0.5 * (rows[-1][:, :-1] + rows[-1][:, 1:]))
    return np.stack([row[:, 0] for row in rows], axis=1), np.stack([row[:, -1] for row in rows[::-1]], axis=1)
