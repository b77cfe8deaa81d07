"""The engine's inputs: tool, staircase stock, toolpath and cut settings (mm, degrees).

Each is a frozen dataclass validated on construction; a bad value raises ValueError naming
the field (and the section or CL index) that is wrong.
"""

from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from ..errors import CLPointError
from .bands import WallBands
from .frames import angles_to_axis, axis_to_angles, rotation_matrix
from .tolerances import WALL_CHECK_SAMPLES
from .walls import SplineTable, SplineWall, Wall


class NotANumber(TypeError, ValueError):
    """A value that is not a real number where one is needed (a str, None, a list, ...): a TypeError
    naming the argument, and a ValueError as every bad input value of the engine is."""


def finite_number(name, value, *, positive=False, largest=None):
    """A finite real number as float, at most `largest` in size if given; NotANumber (a TypeError and a
    ValueError) naming `name` for anything that is not a real number (str, bytes, None, a sequence,
    complex), ValueError for NaN, infinities, booleans and values out of range."""
    if isinstance(value, (str, bytes, complex)) or value is None:
        raise NotANumber(f"{name} must be a number, got {type(value).__name__} {value!r}")
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise NotANumber(f"{name} must be a number, got {type(value).__name__} {value!r}") from None
    if isinstance(value, bool) or not np.isfinite(number):
        raise ValueError(f"{name} must be a finite number, got {value!r}")
    if positive and number <= 0.0:
        raise ValueError(f"{name} must be positive, got {value!r}")
    if largest is not None and abs(number) > largest:
        raise ValueError(f"{name} must be at most {largest:g} in size, got {number:g}")
    return number


#: Largest tool size (mm) computed: the readers' bound on every number; far beyond any tool, and where
#: the engine's polynomials in the tool's radius still hold their precision (a 1e300 mm tool overflows).
MAX_TOOL_SIZE = 1e12


def _array(name, value, shape):
    """A finite float array of the given shape (None in `shape` matches any length); NotANumber for
    anything that is not numbers (a str, None, a dict)."""
    if isinstance(value, (str, bytes, dict)) or value is None:
        raise NotANumber(f"{name} must be an array of numbers, got {type(value).__name__}")
    try:
        array = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise NotANumber(f"{name} must be an array of numbers") from None
    if array.ndim != len(shape) or any(s is not None and s != a for s, a in zip(shape, array.shape)):
        expected = "(" + ", ".join("n" if s is None else str(s) for s in shape) + ")"
        raise ValueError(f"{name} must have shape {expected}, got {array.shape}")
    bad = ~np.isfinite(array)
    if bad.any():
        index = tuple(int(i) for i in np.argwhere(bad)[0])
        raise ValueError(f"{name}{list(index)} is not a finite number")
    array.setflags(write=False)
    return array


#: Most flutes of a tool (the job parameters' bound).
MAX_FLUTES = 1000
#: Largest helix angle |β| of a flat-end mill (deg): steeper edges are not end mills, and the
#: helical engine's time and memory per CL point grow without bound as |β| nears 90°.
MAX_HELIX = 60.0


@dataclass(frozen=True)
class Tool:
    """A milling tool: diameter D = 2R and flute length L in mm, number of flutes, helix angle β in deg
    (0: straight edges; |β| ≤ MAX_HELIX), corner radius r in mm (0 ≤ r ≤ R): 0 a flat-end mill, R a
    ball-end mill, between a bull-nose (torus) mill (engine.profile). Helical flutes are for tools
    without a corner."""

    diameter: float
    flutes: int
    flute_length: float
    helix: float = 0.0
    corner_radius: float = 0.0

    def __post_init__(self):
        object.__setattr__(self, "diameter", finite_number("diameter", self.diameter, positive=True,
                                                          largest=MAX_TOOL_SIZE))
        object.__setattr__(self, "flute_length", finite_number("flute_length", self.flute_length, positive=True,
                                                              largest=MAX_TOOL_SIZE))
        flutes = finite_number("flutes", self.flutes, positive=True, largest=MAX_FLUTES)
        if flutes != int(flutes):
            raise ValueError(f"flutes must be a whole number, got {self.flutes!r}")
        object.__setattr__(self, "flutes", int(flutes))
        helix = finite_number("helix", self.helix)
        if not -MAX_HELIX <= helix <= MAX_HELIX:
            raise ValueError(f"helix must be within [-{MAX_HELIX:g}, {MAX_HELIX:g}] degrees (flat-end mills have "
                             f"helix angles up to about {MAX_HELIX:g}°), got {helix:g}")
        object.__setattr__(self, "helix", helix)
        corner = finite_number("corner_radius", self.corner_radius)
        if not 0.0 <= corner <= 0.5 * self.diameter:
            raise ValueError(f"corner_radius must be within [0, {0.5 * self.diameter:g}] mm (half the diameter: a ball), "
                             f"got {corner:g}")
        if corner and helix:
            raise ValueError("helical flutes on a corner are not computed: a tool with a corner radius needs "
                             "straight flutes (helix 0)")
        object.__setattr__(self, "corner_radius", corner)

    @property
    def radius(self):
        """R_t = diameter / 2 (mm)."""
        return 0.5 * self.diameter

    @property
    def kind(self):
        """"flat", "bull-nose" or "ball", by the corner radius."""
        if self.corner_radius == 0.0:
            return "flat"
        return "ball" if self.corner_radius == self.radius else "bull-nose"


@dataclass(frozen=True)
class Staircase:
    """Staircase stock of n sections ordered along +x (notes §1).

    z_top: (n,) top height of each section (mm).
    wall_points: (n−1, 6, 2) [x, y] points of walls 1..n−1; wall j is where section j starts.
    wall_curves: None (the walls are the quintics through wall_points, the paper's model) or
    n−1 exact wall curves (SplineWall, or Wall) that replace them; wall_points then only
    record six points on each.
    Inside means x_min ≤ x ≤ x_max, y_min ≤ y ≤ y_max and base_z ≤ z ≤ z_top of the section
    holding (x, y); section j holds W_j(y) ≤ x < W_{j+1}(y).
    Derived: walls (n−1 Wall or SplineWall), bands (WallBands: where each wall can be,
    and how steep it is, over any y interval of the window) and splines (SplineTable: the
    SplineWall walls stacked, to solve many of them at once).
    """

    x_min: float
    x_max: float
    y_min: float
    y_max: float
    base_z: float
    z_top: np.ndarray
    wall_points: np.ndarray
    wall_curves: Optional[tuple] = field(default=None, repr=False, compare=False)
    walls: tuple = field(init=False, repr=False, compare=False)
    bands: WallBands = field(init=False, repr=False, compare=False)
    splines: SplineTable = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        for name in ("x_min", "x_max", "y_min", "y_max", "base_z"):
            object.__setattr__(self, name, finite_number(name, getattr(self, name)))
        if self.x_min >= self.x_max:
            raise ValueError(f"x_min ({self.x_min}) must be below x_max ({self.x_max})")
        if self.y_min >= self.y_max:
            raise ValueError(f"y_min ({self.y_min}) must be below y_max ({self.y_max})")
        z_top = _array("z_top", self.z_top, (None,))
        if z_top.size == 0:
            raise ValueError("a staircase needs at least one section")
        low = np.flatnonzero(z_top <= self.base_z)
        if low.size:
            j = int(low[0])
            raise ValueError(f"sections[{j}]: z_top {z_top[j]} must be above base_z {self.base_z}")
        object.__setattr__(self, "z_top", z_top)
        points = np.array(self.wall_points, dtype=float).reshape(-1, 6, 2) if np.size(self.wall_points) else np.empty((0, 6, 2))
        if points.shape[0] != z_top.size - 1:
            raise ValueError(f"{z_top.size} sections need {z_top.size - 1} walls, got {points.shape[0]}")
        walls = []
        for j, p in enumerate(points, start=1):
            try:
                walls.append(Wall.from_points(p))
            except ValueError as error:
                raise ValueError(f"sections[{j}].wall: {error}") from None
        if self.wall_curves is not None:
            curves = tuple(self.wall_curves)
            if len(curves) != len(walls) or not all(isinstance(c, (Wall, SplineWall)) for c in curves):
                raise ValueError(f"wall_curves must be {len(walls)} Wall or SplineWall objects")
            walls = list(curves)
            object.__setattr__(self, "wall_curves", curves)
        object.__setattr__(self, "wall_points", _array("wall_points", points, (None, 6, 2)))
        object.__setattr__(self, "walls", tuple(walls))
        self._check_wall_order()
        object.__setattr__(self, "bands", WallBands(walls, self.y_min, self.y_max))
        object.__setattr__(self, "splines", SplineTable(walls))

    def _check_wall_order(self):
        """Walls must lie strictly inside (x_min, x_max) and in order along +x over the y window."""
        y = np.linspace(self.y_min, self.y_max, WALL_CHECK_SAMPLES)
        previous, previous_name = np.full_like(y, self.x_min), "x_min"
        for j, wall in enumerate(self.walls, start=1):
            x = wall.x_at(y)
            crossing = np.flatnonzero(x <= previous)
            if crossing.size:
                k = int(crossing[0])
                raise ValueError(
                    f"sections[{j}].wall: x = {x[k]:.6g} at y = {y[k]:.6g} is not beyond "
                    f"{previous_name} ({previous[k]:.6g}); walls must be ordered along +x "
                    "inside [y_min, y_max]"
                )
            previous, previous_name = x, f"the wall of section {j}"
        beyond = np.flatnonzero(previous >= self.x_max)
        if self.walls and beyond.size:
            k = int(beyond[0])
            raise ValueError(
                f"sections[{len(self.walls)}].wall: x = {previous[k]:.6g} at y = {y[k]:.6g} "
                f"is not below x_max ({self.x_max})"
            )

    @property
    def n_sections(self):
        """Number of sections n."""
        return int(self.z_top.size)

    def section_at(self, x, y):
        """Index of the section holding (x, y): the number of walls with W_j(y) ≤ x (int array).

        Inside the y window a wall is only evaluated where x falls in its band at that y.
        """
        x, y = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
        shape = x.shape
        x, y = x.reshape(-1), y.reshape(-1)
        in_window = (y >= self.y_min) & (y <= self.y_max)
        count = np.zeros(x.shape, dtype=np.intp)
        for j, wall in enumerate(self.walls):
            low, high, _ = self.bands.query(y, y, np.full(y.shape, j))
            sure = in_window & ((x < low) | (x > high))
            count += sure & (x > high)
            rows = np.flatnonzero(~sure)
            count[rows] += x[rows] >= wall.x_at(y[rows])
        return count.reshape(shape)

    def translated(self, offset):
        """The same staircase moved by offset (3,) mm."""
        dx, dy, dz = (float(v) for v in offset)
        points = self.wall_points + np.array([dx, dy])
        curves = None if self.wall_curves is None else tuple(c.translated(dx, dy) for c in self.wall_curves)
        return Staircase(self.x_min + dx, self.x_max + dx, self.y_min + dy, self.y_max + dy,
                         self.base_z + dz, self.z_top + dz, points, curves)


@dataclass(frozen=True)
class Toolpath:
    """CL points of one pass with their tool frames (docs/ENGINE.md, "Frames").

    cl: (m, 3) centres of the tool's bottom face (mm), in pass order.
    theta_a, theta_b: (m,) rotations about x and y (degrees), |θ_A| ≤ 180, |θ_B| ≤ 90, of the frame turned
    by α: every tool axis direction, also pointing sideways or down.
    cc: (m, 3) cutter-contact points (mm), or None.
    alpha: (m,) direction of the feed in plan view (degrees from +x towards +y), the turn of
    each CL point's frame about z; None: 0, the paper's pass along +x.
    inclination: (m,) the tool's inclination to each move's feed (degrees, engine.feed), which
    thins the chip (h = f·sin φ·cos inclination); None: the job's one value (CutSettings).
    Tool frame R = Rz(α)·Rx(θ_A)·Ry(θ_B) (:meth:`frames`).
    """

    cl: np.ndarray
    theta_a: np.ndarray
    theta_b: np.ndarray
    cc: Optional[np.ndarray] = None
    alpha: Optional[np.ndarray] = None
    inclination: Optional[np.ndarray] = None

    def __post_init__(self):
        cl = _array("cl", self.cl, (None, 3))
        if cl.shape[0] == 0:
            raise ValueError("a toolpath needs at least one CL point")
        object.__setattr__(self, "cl", cl)
        for name, limit in (("theta_a", 180.0), ("theta_b", 90.0)):
            angles = _array(name, getattr(self, name), (cl.shape[0],))
            steep = np.flatnonzero(np.abs(angles) > limit)
            if steep.size:
                i = int(steep[0])
                raise CLPointError(i, f"{name} = {angles[i]} must be within [-{limit:g}, {limit:g}] degrees")
            object.__setattr__(self, name, angles)
        if self.cc is not None:
            object.__setattr__(self, "cc", _array("cc", self.cc, (cl.shape[0], 3)))
        alpha = np.zeros(cl.shape[0]) if self.alpha is None else self.alpha
        object.__setattr__(self, "alpha", _array("alpha", alpha, (cl.shape[0],)))
        if self.inclination is not None:
            inclination = _array("inclination", self.inclination, (cl.shape[0],))
            steep = np.flatnonzero(np.abs(inclination) > 90.0)
            if steep.size:
                i = int(steep[0])
                raise CLPointError(i, f"inclination = {inclination[i]} must be within [-90, 90] degrees")
            object.__setattr__(self, "inclination", inclination)

    def rows(self, index):
        """The Toolpath of the CL points `index` (a slice or an int array), in that order (CC points,
        feed directions and inclinations too)."""
        cc = None if self.cc is None else self.cc[index]
        inclination = None if self.inclination is None else self.inclination[index]
        return Toolpath(self.cl[index], self.theta_a[index], self.theta_b[index], cc, self.alpha[index],
                        inclination)

    @classmethod
    def from_axes(cls, cl, axes, cc=None, alpha=None, inclination=None):
        """Toolpath from tool-axis vectors (m, 3) in the part frame, of any nonzero finite length
        (normalised; any direction), with frames turned about z by alpha (m,) deg (None: 0).

        A row whose largest component lies outside [1e-150, 1e150] (where its squared length would
        underflow or overflow) is first scaled exactly by a power of two to a largest component in
        [0.5, 1), so vectors such as (0, 0, 1e-200) or (1e200, 0, 1e200) are read, not refused as
        zero or not finite.
        """
        axes = np.asarray(axes, dtype=float)
        if axes.ndim == 2 and axes.shape[1] == 3:
            largest = np.max(np.abs(axes), axis=1, initial=0.0)
            with np.errstate(invalid="ignore"):
                extreme = np.isfinite(largest) & (largest > 0.0) & ((largest < 1e-150) | (largest > 1e150))
            _, exponent = np.frexp(np.where(extreme, largest, 1.0))
            axes = np.where(extreme[:, None], np.ldexp(axes, -exponent[:, None]), axes)
        theta_a, theta_b = axis_to_angles(axes, alpha)
        return cls(cl, theta_a, theta_b, cc, alpha, inclination)

    @classmethod
    def from_part_angles(cls, cl, theta_a, theta_b, cc=None, alpha=None, inclination=None):
        """Toolpath from angles θ_A, θ_B (m,) deg that give the tool axis in the part frame
        (Rx(θ_A)·Ry(θ_B)·e_z, as a toolpath CSV's columns do), with frames turned about z by alpha (m,)
        deg (None: 0); CL points whose α is 0 keep the angles as given, bit for bit."""
        given = cls(cl, theta_a, theta_b, cc)  # the angles checked as given
        if alpha is None or not np.any(alpha):
            return cls(given.cl, given.theta_a, given.theta_b, given.cc, alpha, inclination)
        turned_a, turned_b = axis_to_angles(angles_to_axis(given.theta_a, given.theta_b), alpha)
        still = np.asarray(alpha) == 0.0
        return cls(given.cl, np.where(still, given.theta_a, turned_a), np.where(still, given.theta_b, turned_b),
                   given.cc, alpha, inclination)

    def frames(self):
        """(m, 3, 3) tool frames R = Rz(α)·Rx(θ_A)·Ry(θ_B); columns u, v, w (w the tool axis)."""
        return rotation_matrix(self.theta_a, self.theta_b, self.alpha)

    @property
    def axes(self):
        """(m, 3) unit tool axes w in the part frame."""
        return angles_to_axis(self.theta_a, self.theta_b, self.alpha)

    def inclinations(self, settings):
        """(m,) inclination (deg) of each CL point: its own, else the one of `settings` (CutSettings)."""
        if self.inclination is not None:
            return self.inclination
        return np.full(len(self), float(settings.inclination))

    def __len__(self):
        return int(self.cl.shape[0])

    def translated(self, offset):
        """The same toolpath moved by offset (3,) mm."""
        offset = np.asarray(offset, dtype=float)
        return Toolpath(self.cl + offset, self.theta_a, self.theta_b,
                        None if self.cc is None else self.cc + offset, self.alpha, self.inclination)


@dataclass(frozen=True)
class CutSettings:
    """Feed per tooth (mm), inclination α (deg), the rotation angles φ reported (deg), spindle (rpm)."""

    feed_per_tooth: float
    inclination: float = 0.0
    phi_start: float = 0.0
    phi_end: float = 180.0
    phi_step: float = 1.0
    spindle_rpm: Optional[float] = None

    def __post_init__(self):
        object.__setattr__(self, "feed_per_tooth", finite_number("feed_per_tooth", self.feed_per_tooth, positive=True))
        inclination = finite_number("inclination", self.inclination)
        if not -90.0 < inclination < 90.0:
            raise ValueError(f"inclination must be within (-90, 90) degrees, got {inclination}")
        object.__setattr__(self, "inclination", inclination)
        object.__setattr__(self, "phi_start", finite_number("phi_start", self.phi_start))
        object.__setattr__(self, "phi_end", finite_number("phi_end", self.phi_end))
        object.__setattr__(self, "phi_step", finite_number("phi_step", self.phi_step, positive=True))
        if self.phi_end < self.phi_start:
            raise ValueError(f"phi range {self.phi_start}:{self.phi_end} must not be decreasing")
        if (self.phi_end - self.phi_start) / self.phi_step > 1e6:
            raise ValueError("phi range / phi step gives more than 10^6 angles")
        if self.spindle_rpm is not None:
            object.__setattr__(self, "spindle_rpm", finite_number("spindle_rpm", self.spindle_rpm, positive=True))

    @property
    def phi(self):
        """Rotation angles φ (p,) in degrees: start, start + step, … up to end (inclusive)."""
        count = int(np.floor((self.phi_end - self.phi_start) / self.phi_step + 1e-9)) + 1
        return self.phi_start + self.phi_step * np.arange(count)
