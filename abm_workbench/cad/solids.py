"""Staircase stock as an exact solid, and solids written to STEP or BREP (mm).

Each section j is the face bounded by its two walls and the lines y = y_min, y = y_max,
drawn at z = base_z and extruded up to z_top[j]; the sections are fused into one solid.
A wall is built from the Staircase's own wall model:

- a straight wall (quintic or B-spline) is a line x = const;
- a quintic x = P(y) over [y_min, y_max] is a degree-5 Bézier curve, built as a single-span
  B-spline whose parameter is y itself;
- an exact wall (:class:`~abm_workbench.engine.walls.SplineWall`) is its own (rational)
  B-spline, with its degree, knots, poles and weights, trimmed to [y_min, y_max].

Each wall's edge is built once and shared by the two section faces beside it, so the fuse
meets identical geometry. Every wall edge runs towards +y.
"""

from math import comb

import numpy as np
from numpy.polynomial import Polynomial

from ..engine import Staircase
from ..engine.walls import SplineWall
from ..formats import replacing
from .freecad_env import FreeCAD, Part

_DEGREE = 5
#: A B-spline wall whose end lies within this (mm) of the window's y limit is snapped onto it;
#: one that stops short of the limit by more is refused, one that runs beyond is trimmed.
END_TOL = 1e-9
#: The parameter solve for a given y stops when |y(u) − y| is below this (mm).
Y_SOLVE_TOL = 1e-13
#: Least number of samples along a curve when bracketing the parameter of a given y.
CURVE_SAMPLES = 257


def bezier_poles(wall, y_lo, y_hi):
    """Control points (6, 2) [x, y] (mm) of the degree-5 Bézier equal to `wall` over [y_lo, y_hi].

    With s = (y − y_lo)/(y_hi − y_lo), P is a quintic in s (power coefficients a_i); its
    Bernstein coefficients are b_k = Σ_{i ≤ k} C(k, i)/C(5, i)·a_i. The y control values are
    evenly spaced, which makes y linear in s.
    """
    span = y_hi - y_lo
    t_of_s = Polynomial([(y_lo - wall.y_mid) / wall.y_half, span / wall.y_half])
    power = np.zeros(_DEGREE + 1)
    composed = Polynomial(wall.coefficients)(t_of_s).coef
    power[: composed.size] = composed
    x = [sum(comb(k, i) / comb(_DEGREE, i) * power[i] for i in range(k + 1)) for k in range(_DEGREE + 1)]
    return np.column_stack([x, y_lo + span * np.arange(_DEGREE + 1) / _DEGREE])


def bspline_curve(degree, knots, poles, weights, z):
    """A Part.BSplineCurve in the plane z (mm) from B-spline data.

    degree: p; knots: (k+p+1,) full knot vector (multiplicities repeated); poles: (k, 2) [x, y]
    (mm); weights: (k,) or None (non-rational).
    """
    values, mults = np.unique(np.asarray(knots, dtype=float), return_counts=True)
    points = [FreeCAD.Vector(float(x), float(y), float(z)) for x, y in np.asarray(poles, dtype=float)]
    curve = Part.BSplineCurve()
    weights = None if weights is None else [float(w) for w in weights]
    curve.buildFromPolesMultsKnots(points, mults.tolist(), values.tolist(), False, int(degree), weights)
    return curve


def parameter_at_y(curve, y, lo, hi):
    """Parameter u in [lo, hi] of a Part curve where its y equals `y` (mm).

    The sign of y(u) − y must differ at lo and hi. Safeguarded Newton: a step leaving the
    bracket is replaced by bisection; stops at |y(u) − y| ≤ Y_SOLVE_TOL or a bracket of 1e-15.
    """
    f_lo = curve.value(lo).y - y
    u = 0.5 * (lo + hi)
    for _ in range(100):
        f = curve.value(u).y - y
        if abs(f) <= Y_SOLVE_TOL:
            return u
        if (f <= 0) == (f_lo <= 0):
            lo, f_lo = u, f
        else:
            hi = u
        slope = curve.getD1(u)[1].y
        newton = u - f / slope if slope else lo
        u = newton if lo < newton < hi else 0.5 * (lo + hi)
        if hi - lo <= 1e-15 * max(1.0, abs(hi)):
            break
    return u


def _first_crossing(curve, y):
    """Parameter where a Part.BSplineCurve first reaches height y (mm), from its start."""
    u = np.linspace(curve.FirstParameter, curve.LastParameter, max(CURVE_SAMPLES, 16 * curve.NbKnots))
    above = np.array([curve.value(t).y for t in u]) >= y
    k = int(np.argmax(above[1:] != above[:-1]))
    return parameter_at_y(curve, y, u[k], u[k + 1])


def trimmed_to_y(curve, y_lo, y_hi):
    """A copy of a Part.BSplineCurve running towards +y from exactly y_lo to exactly y_hi (mm).

    The copy is reversed if it runs towards −y, cut where it first reaches y_lo and y_hi if it
    runs beyond them, and its end poles are set onto the two y values (a move of at most
    END_TOL). ValueError when the curve stops short of either by more than END_TOL.
    """
    trimmed = curve.copy()
    if trimmed.StartPoint.y > trimmed.EndPoint.y:
        trimmed.reverse()
    start, end = trimmed.StartPoint.y, trimmed.EndPoint.y
    if start > y_lo + END_TOL or end < y_hi - END_TOL:
        raise ValueError(f"the B-spline wall spans y {start:.9g} to {end:.9g}, not all of [{y_lo:.9g}, {y_hi:.9g}]")
    lo = _first_crossing(trimmed, y_lo) if start < y_lo - END_TOL else trimmed.FirstParameter
    hi = _first_crossing(trimmed, y_hi) if end > y_hi + END_TOL else trimmed.LastParameter
    if (lo, hi) != (trimmed.FirstParameter, trimmed.LastParameter):
        trimmed.segment(lo, hi)
    for index, y in ((1, y_lo), (trimmed.NbPoles, y_hi)):
        pole = trimmed.getPole(index)
        trimmed.setPole(index, FreeCAD.Vector(pole.x, y, pole.z), trimmed.getWeight(index))
    return trimmed


def _straight_x(wall):
    """x (mm) of a straight wall: its constant term (quintic) or its poles' common x (B-spline)."""
    return float(wall.poles[0, 0] if isinstance(wall, SplineWall) else wall.coefficients[0])


def wall_edge(wall, y_lo, y_hi, z):
    """The wall's footprint over y_lo ≤ y ≤ y_hi at height z (mm) as an edge running towards +y.

    A straight wall gives a line segment; a quintic a degree-5 B-spline with one span and
    knots [y_lo, y_hi], so that its parameter equals y; a SplineWall its own B-spline, trimmed
    to [y_lo, y_hi] (ValueError if it does not span it).
    """
    if wall.is_straight:
        x = _straight_x(wall)
        return Part.LineSegment(FreeCAD.Vector(x, y_lo, z), FreeCAD.Vector(x, y_hi, z)).toShape()
    if isinstance(wall, SplineWall):
        curve = bspline_curve(wall.degree, wall.knots, wall.poles, wall.weights, z)
        return trimmed_to_y(curve, y_lo, y_hi).toShape()
    poles = [FreeCAD.Vector(x, y, z) for x, y in bezier_poles(wall, y_lo, y_hi)]
    curve = Part.BSplineCurve()
    curve.buildFromPolesMultsKnots(poles, [_DEGREE + 1] * 2, [y_lo, y_hi], False, _DEGREE)
    return curve.toShape()


def staircase_solid(stock: Staircase):
    """The staircase as one valid Part.Solid (mm), with the stock's own walls (quintic or exact).

    Walls 0 and n are the planes x = x_min and x = x_max. Adjacent sections of equal height
    merge into one top face (removeSplitter), so their wall leaves no face. ValueError naming
    the section for a B-spline wall that does not span [y_min, y_max].
    """
    z = stock.base_z

    def line(x0, y0, x1, y1):
        return Part.LineSegment(FreeCAD.Vector(x0, y0, z), FreeCAD.Vector(x1, y1, z)).toShape()

    walls = [line(stock.x_min, stock.y_min, stock.x_min, stock.y_max)]
    for j, wall in enumerate(stock.walls, start=1):
        try:
            walls.append(wall_edge(wall, stock.y_min, stock.y_max, z))
        except ValueError as error:
            raise ValueError(f"sections[{j}].wall: {error}") from None
    walls.append(line(stock.x_max, stock.y_min, stock.x_max, stock.y_max))
    blocks = []
    for j, height in enumerate(stock.z_top):
        left, right = walls[j], walls[j + 1]
        ends = [(e.valueAt(e.FirstParameter), e.valueAt(e.LastParameter)) for e in (left, right)]
        front = Part.LineSegment(ends[0][0], ends[1][0]).toShape()
        back = Part.LineSegment(ends[0][1], ends[1][1]).toShape()
        face = Part.Face(Part.Wire([left, front, right, back]))
        blocks.append(face.extrude(FreeCAD.Vector(0, 0, float(height) - z)))
    fused = blocks[0].multiFuse(blocks[1:]).removeSplitter() if len(blocks) > 1 else blocks[0]
    if len(fused.Solids) != 1:
        raise RuntimeError(f"fusing the {len(blocks)} sections gave {len(fused.Solids)} solids, expected 1")
    solid = fused.Solids[0]
    if not solid.isValid():
        raise RuntimeError("the fused staircase solid is not valid")
    return solid


def export_step(shape, path):
    """Write `shape` to a STEP file (mm), atomically: a temporary file beside `path`, then os.replace."""
    with replacing(path) as (temporary,):
        shape.exportStep(temporary)


def export_brep(shape, path):
    """Write `shape` to an OpenCASCADE BREP file, atomically (as export_step)."""
    with replacing(path) as (temporary,):
        shape.exportBrep(temporary)


def moved(shape, rotation, translation):
    """A copy of `shape` moved rigidly: p -> rotation @ p + translation (rotation (3, 3), translation (3,) mm).

    The geometry keeps its kind (planes, B-splines ...): only the shape's placement changes.
    """
    rotation, translation = np.asarray(rotation, dtype=float), np.asarray(translation, dtype=float)
    matrix = FreeCAD.Matrix(*rotation[0], translation[0], *rotation[1], translation[1], *rotation[2], translation[2],
                            0.0, 0.0, 0.0, 1.0)
    copy = shape.copy()
    copy.transformShape(matrix)
    return copy
