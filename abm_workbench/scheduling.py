"""Force- or area-limited feed scheduling: the feed per tooth per CL point that keeps every
instant at or under a limit, never above the programmed feed (pure numpy, no FreeCAD).

At every instant the force is affine in the feed per tooth f (forces.py): F(f) = f·A + B,
A the chip-thickness part per mm of feed (N/mm), B the edge part (N). |F(f)| ≤ L is the
quadratic inequality |A|² f² + 2 (A·B) f + |B|² − L² ≤ 0, whose solutions are an interval
[f_lo, f_hi] (empty when the discriminant is negative: the limit is out of reach at any
feed). The total cut area of the cutting flutes is linear in f, f·W ≤ L. Per CL point the
allowed feeds are the intersection over its instants; the scheduled feed is the largest of
them, capped at the programmed feed. A CL point where no feed at or above the floor
(`min_feed`) meets the limit, at the programmed feed or below, is *infeasible*: it gets the floor
and is reported.

Units: N, mm, mm², feed per tooth in mm.
"""

from dataclasses import dataclass

import numpy as np

from .forces import Forces
from .formats.apt import MM_PER_INCH

#: The limits a schedule can keep.
LIMITS = ("force", "area")
#: Default floor as a fraction of the programmed feed.
MIN_FEED_FRACTION = 0.1


@dataclass(frozen=True)
class Schedule:
    """A feed schedule over m CL points.

    kind: "force" (peak resultant, N) or "area" (peak total cut area, mm²); limit in its unit.
    programmed, feed: (m,) feed per tooth before and after (mm). floor: (m,) lowest feed allowed.
    infeasible: (m,) bool, CL points where no feed from the floor up meets the limit (they get the floor).
    before, after: (m,) peak of the limited quantity at each CL point before and after.
    """

    kind: str
    limit: float
    programmed: np.ndarray
    feed: np.ndarray
    floor: np.ndarray
    infeasible: np.ndarray
    before: np.ndarray
    after: np.ndarray

    @property
    def reduced(self):
        """(m,) bool: the feed was lowered at this CL point."""
        return self.feed < self.programmed


def force_feed_bounds(cutting, edge, limit):
    """Feeds per tooth f ≥ 0 with |f·cutting + edge| ≤ limit at each instant.

    cutting: (..., 3) force per mm of feed (N/mm); edge: (..., 3) force at zero feed (N);
    limit: N. Returns lo, hi (...,) (mm; hi may be inf) and ok (...,) bool: the allowed feeds
    are [lo, hi] where ok, none elsewhere.
    """
    cutting, edge = np.asarray(cutting, dtype=float), np.asarray(edge, dtype=float)
    a = np.einsum("...i,...i", cutting, cutting)
    b = np.einsum("...i,...i", cutting, edge)
    c = np.einsum("...i,...i", edge, edge) - limit * limit
    flat = a == 0.0
    disc = b * b - a * c
    root = np.sqrt(np.maximum(disc, 0.0))
    # Roots q/a and c/q with q = −(b + sign(b)·√disc): no cancellation between b and √disc.
    q = -(b + np.where(b >= 0.0, root, -root))
    with np.errstate(divide="ignore", invalid="ignore"):
        r1 = np.where(flat, 0.0, q / np.where(flat, 1.0, a))
        r2 = np.where(q == 0.0, 0.0, c / np.where(q == 0.0, 1.0, q))
    lo = np.maximum(np.where(flat, 0.0, np.minimum(r1, r2)), 0.0)
    hi = np.where(flat, np.inf, np.maximum(r1, r2))
    ok = np.where(flat, c <= 0.0, (disc >= 0.0) & (hi >= 0.0))
    return lo, hi, ok


def schedule(forces: Forces, limit, *, kind="force", min_feed=None):
    """The feed schedule of a pass (see the module docstring).

    forces: Forces of the pass at its programmed feed (forces.feed, (m,) mm per tooth).
    limit: peak resultant force (N) for kind "force", peak total cut area (mm²) for "area".
    min_feed: floor (scalar or (m,) mm; default MIN_FEED_FRACTION × the programmed feed).
    Returns a Schedule. ValueError for a limit that is not positive or an unknown kind.
    """
    if kind not in LIMITS:
        raise ValueError(f"kind must be one of {LIMITS}, got {kind!r}")
    limit = float(limit)
    if not (np.isfinite(limit) and limit > 0.0):
        raise ValueError(f"the force limit must be a positive number, got {limit:g}" if kind == "force" else
                         f"the area limit must be a positive number, got {limit:g}")
    programmed = forces.feed
    floor = MIN_FEED_FRACTION * programmed if min_feed is None else np.broadcast_to(
        np.asarray(min_feed, dtype=float), programmed.shape)
    if not np.isfinite(floor).all() or (floor < 0.0).any():
        raise ValueError("the minimum feed must be finite and not negative")
    if kind == "force":
        lo, hi, ok = force_feed_bounds(forces.cutting, forces.edge, limit)
    else:
        width = forces.area_per_feed
        with np.errstate(divide="ignore"):
            hi = np.where(width > 0.0, limit / np.where(width > 0.0, width, 1.0), np.inf)
        lo, ok = np.zeros_like(hi), np.ones(hi.shape, dtype=bool)
    highest = np.minimum(programmed, hi.min(axis=1))
    lowest = np.maximum(lo.max(axis=1), floor)
    infeasible = ~ok.all(axis=1) | (highest < lowest)
    feed = np.where(infeasible, floor, highest)
    after = forces.with_feed(feed)
    return Schedule(kind, limit, programmed, feed, np.asarray(floor, dtype=float).copy(), infeasible,
                    peak(forces, kind), peak(after, kind))


def peak(forces: Forces, kind="force"):
    """(m,) peak resultant force (N) or peak total cut area (mm²) per CL point."""
    return forces.peak if kind == "force" else forces.area.max(axis=1)


def programmed_feed(m, default, *, feed=None, unit=None, flutes=1, spindle_rpm=None):
    """(m,) programmed feed per tooth (mm) of m CL points.

    feed: (m,) an APT file's feed at each CL point in `unit` (MMPM, MMPR, IPM, IPR), or None;
    where it is NaN (before the first FEDRAT) or not given, `default` (mm per tooth) holds.
    A feed per minute needs the spindle speed: ValueError without it.
    """
    out = np.full(m, float(default))
    if feed is None or unit is None:
        return out
    given = np.asarray(feed, dtype=float) * (MM_PER_INCH if unit.startswith("I") else 1.0) / flutes
    if unit.endswith("PM"):
        if spindle_rpm is None:
            raise ValueError(f"feeds in {unit} need the spindle speed to give a feed per tooth")
        given = given / spindle_rpm
    return np.where(np.isnan(given), out, given)
