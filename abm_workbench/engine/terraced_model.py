"""The general 2.5D terraced stock: horizontal slabs, each a planar region bounded by closed plan curves.

What z-level roughing leaves: terraces with closed contours, pockets, islands and bosses, steps
running in any horizontal direction. The stock is a stack of slabs from the base up; slab k
holds the points (x, y, z) with ``z_bottom ≤ z ≤ z_top`` and (x, y) inside its region. A
region is given by closed loops of plan curves and filled by the even-odd rule: a point is
inside when a ray from it crosses its loops an odd number of times, so an outer contour with
a pocket inside it, an island inside the pocket, and so on, need no orientation.

Plan curves (x, y in mm): :class:`PlanLine`, :class:`PlanArc` (angles in radians, the sweep
signed, counter-clockwise positive) and :class:`PlanSpline` (a clamped, possibly rational
B-spline). Each curve may name the face of the solid it came from (``face``), for messages and
labels. The staircase of the paper is the special case whose slabs are bounded by the
stock's x and y limits and its walls.

Every dataclass is frozen and checked on construction; a bad value raises ValueError naming
the slab, loop and curve.
"""

from dataclasses import dataclass

import numpy as np

from .model import finite_number

#: End points of consecutive curves of a loop must meet within this (mm).
LOOP_GAP = 1e-7


def _point(name, value):
    """A finite (2,) float array, read-only."""
    array = np.array(value, dtype=float)
    if array.shape != (2,) or not np.isfinite(array).all():
        raise ValueError(f"{name} must be a finite [x, y] point, got {value!r}")
    array.setflags(write=False)
    return array


@dataclass(frozen=True)
class PlanLine:
    """The plan segment from `start` to `end` ((2,) mm), not of zero length."""

    start: np.ndarray
    end: np.ndarray
    face: str = ""

    def __post_init__(self):
        object.__setattr__(self, "start", _point("start", self.start))
        object.__setattr__(self, "end", _point("end", self.end))
        if np.hypot(*(self.end - self.start)) <= LOOP_GAP:
            raise ValueError(f"line from {self.start.tolist()} to {self.end.tolist()} has no length")

    @property
    def end_points(self):
        """((2,), (2,)): where the curve starts and ends (mm)."""
        return self.start, self.end


@dataclass(frozen=True)
class PlanArc:
    """The circular arc about `center` ((2,) mm) of `radius` (mm) from angle `start_angle` over
    `sweep` (radians; counter-clockwise positive, |sweep| ≤ 2π; 2π: a full circle)."""

    center: np.ndarray
    radius: float
    start_angle: float
    sweep: float
    face: str = ""

    def __post_init__(self):
        object.__setattr__(self, "center", _point("center", self.center))
        object.__setattr__(self, "radius", finite_number("radius", self.radius, positive=True))
        object.__setattr__(self, "start_angle", finite_number("start_angle", self.start_angle))
        sweep = finite_number("sweep", self.sweep)
        if sweep == 0.0 or abs(sweep) > 2.0 * np.pi + 1e-12:
            raise ValueError(f"sweep must be non-zero and at most 2π in size, got {sweep}")
        object.__setattr__(self, "sweep", sweep)

    def at(self, angle):
        """Points (..., 2) on the circle at `angle` (radians)."""
        angle = np.asarray(angle, dtype=float)
        return self.center + self.radius * np.stack([np.cos(angle), np.sin(angle)], axis=-1)

    @property
    def end_points(self):
        """((2,), (2,)): where the curve starts and ends (mm)."""
        return self.at(self.start_angle), self.at(self.start_angle + self.sweep)


@dataclass(frozen=True)
class PlanSpline:
    """A clamped B-spline of `degree` ≥ 1 in the plan: `knots` (n + degree + 1,) non-decreasing,
    `control` (n, 2) mm, `weights` (n,) positive or None (non-rational). It runs over
    knots[degree] .. knots[n]."""

    degree: int
    knots: np.ndarray
    control: np.ndarray
    weights: np.ndarray = None
    face: str = ""

    def __post_init__(self):
        degree = finite_number("degree", self.degree, positive=True)
        if degree != int(degree):
            raise ValueError(f"degree must be a whole number, got {self.degree!r}")
        degree = int(degree)
        control = np.array(self.control, dtype=float)
        knots = np.array(self.knots, dtype=float)
        if control.ndim != 2 or control.shape[1] != 2 or control.shape[0] < degree + 1:
            raise ValueError(f"control must be (n, 2) with n ≥ degree + 1 = {degree + 1}, got {control.shape}")
        n = control.shape[0]
        if knots.shape != (n + degree + 1,):
            raise ValueError(f"knots must have n + degree + 1 = {n + degree + 1} values, got {knots.shape}")
        if not (np.isfinite(control).all() and np.isfinite(knots).all()):
            raise ValueError("knots and control points must be finite")
        if (np.diff(knots) < 0.0).any() or not knots[n] > knots[degree]:
            raise ValueError("knots must be non-decreasing with knots[n] > knots[degree]")
        weights = None
        if self.weights is not None:
            weights = np.array(self.weights, dtype=float)
            if weights.shape != (n,) or not (np.isfinite(weights).all() and (weights > 0.0).all()):
                raise ValueError(f"weights must be {n} positive numbers")
            weights.setflags(write=False)
        for array in (control, knots):
            array.setflags(write=False)
        object.__setattr__(self, "degree", degree)
        object.__setattr__(self, "knots", knots)
        object.__setattr__(self, "control", control)
        object.__setattr__(self, "weights", weights)

    @property
    def end_points(self):
        """((2,), (2,)): where the curve starts and ends (mm); a clamped spline ends on its end control points."""
        return self.control[0], self.control[-1]


PLAN_CURVES = (PlanLine, PlanArc, PlanSpline)


@dataclass(frozen=True)
class Loop:
    """A closed plan contour: `curves` end to end, the last one ending where the first starts."""

    curves: tuple

    def __post_init__(self):
        curves = tuple(self.curves)
        if not curves:
            raise ValueError("a loop needs at least one curve")
        for c, curve in enumerate(curves):
            if not isinstance(curve, PLAN_CURVES):
                raise ValueError(f"curves[{c}] must be a PlanLine, PlanArc or PlanSpline, got {type(curve).__name__}")
            following = curves[(c + 1) % len(curves)]
            gap = np.hypot(*(curve.end_points[1] - following.end_points[0]))
            if gap > LOOP_GAP:
                raise ValueError(f"curves[{c}] ends at {curve.end_points[1].tolist()} but the next curve starts "
                                 f"{gap:.3g} mm away: a loop must be closed")
        object.__setattr__(self, "curves", curves)


@dataclass(frozen=True)
class Slab:
    """The material between heights `z_bottom` < `z_top` (mm) inside `loops` (even-odd rule)."""

    z_bottom: float
    z_top: float
    loops: tuple

    def __post_init__(self):
        object.__setattr__(self, "z_bottom", finite_number("z_bottom", self.z_bottom))
        object.__setattr__(self, "z_top", finite_number("z_top", self.z_top))
        if not self.z_top > self.z_bottom:
            raise ValueError(f"z_top {self.z_top} must be above z_bottom {self.z_bottom}")
        loops = tuple(self.loops)
        if not loops or not all(isinstance(loop, Loop) for loop in loops):
            raise ValueError("a slab needs one or more Loop objects")
        object.__setattr__(self, "loops", loops)


@dataclass(frozen=True)
class TerracedStock:
    """A stack of slabs from the base up, each starting where the one below ends."""

    slabs: tuple

    def __post_init__(self):
        slabs = tuple(self.slabs)
        if not slabs:
            raise ValueError("a terraced stock needs at least one slab")
        for k, slab in enumerate(slabs):
            if not isinstance(slab, Slab):
                raise ValueError(f"slabs[{k}] must be a Slab, got {type(slab).__name__}")
            if k and slab.z_bottom != slabs[k - 1].z_top:
                raise ValueError(f"slabs[{k}] starts at z {slab.z_bottom:g} but slabs[{k - 1}] ends at "
                                 f"{slabs[k - 1].z_top:g}: slabs must be stacked without gaps")
        object.__setattr__(self, "slabs", slabs)

    @property
    def base_z(self):
        """The lowest z of the stock (mm)."""
        return self.slabs[0].z_bottom

    @property
    def levels(self):
        """(n + 1,) the slabs' boundaries in z, bottom up (mm)."""
        return np.array([self.slabs[0].z_bottom] + [slab.z_top for slab in self.slabs])

    def translated(self, offset):
        """The same stock moved by offset (3,) mm."""
        dx, dy, dz = (float(v) for v in offset)
        shift = np.array([dx, dy])

        def moved(curve):
            if isinstance(curve, PlanLine):
                return PlanLine(curve.start + shift, curve.end + shift, curve.face)
            if isinstance(curve, PlanArc):
                return PlanArc(curve.center + shift, curve.radius, curve.start_angle, curve.sweep, curve.face)
            return PlanSpline(curve.degree, curve.knots, curve.control + shift, curve.weights, curve.face)

        return TerracedStock(tuple(
            Slab(slab.z_bottom + dz, slab.z_top + dz, tuple(Loop(tuple(map(moved, loop.curves))) for loop in slab.loops))
            for slab in self.slabs))
