"""Exact classification of a solid's faces and edges for 2.5D recognition (mm, degrees in messages).

Nothing here samples a face or an edge. Decisions come from the geometry itself, with the one
tolerance :data:`~abm_workbench.engine.tolerances.RECOGNITION_TOL` (``TOL`` below, mm):

- Edges are read as B-splines exactly (lines as degree 1, conics as rational degree 2, Bézier
  curves as one-span B-splines) and cut into Bézier spans. On a span with control points P_i,
  weights w_i, a coordinate is c(t) = C(t)/W(t) with C = Σ w_i P_i B_i, W = Σ w_i B_i in the
  Bernstein basis B_i of degree p; its turning points are the real roots in [0, 1] of
  C′W − CW′, found by exact root isolation
  (:func:`~abm_workbench.engine.polynomials.real_roots_unit`). The coordinate's extremes over
  the edge are among its values at the span ends and at these roots: that gives exact bounding
  boxes (FreeCAD's ``BoundBox`` of B-spline geometry encloses the control polygon, not the
  curve) and decides whether a plan curve has one x per y.
- Edges on any other curve (an offset curve) or without a 3D curve are refused; a degenerated
  edge (a cone's apex, a sphere's pole) is its one point.
- Faces by surface type. A plane by its normal; a cylinder and a surface of extrusion by their
  axis or direction; a B-spline or Bézier surface by its control net, since the surface lies in
  the convex hull of its control points: it is a horizontal plane when all its poles share z
  within TOL, and a vertical wall when along one parameter direction every row of poles shares
  x and y within TOL and the weights factor into a product of the two directions' weights (then
  the plan position depends on the other parameter only: an extrusion of a plan curve along z).
  A plane is horizontal when its z spread over the face (from its edges, exactly) is within TOL,
  vertical when its horizontal drift over the face's height is.
- A trimmed surface is classified by its basis, an offset surface as the surface it equals: the
  offset of a plane is a parallel plane, of a cylinder a coaxial cylinder, of an extrusion of a
  line (or of a circle about the extrusion direction) the extrusion of a parallel line (of a
  concentric circle), placed through the offset surface's own point at the face's middle. Any
  other offset is refused in words.
- A vertical wall's plan curve must have an exact B-spline form: lines, conics (a parabola or
  hyperbola as its rational degree-2 B-spline over the face), B-spline and Bézier curves; any
  other (an offset curve) is refused in words.

A face that is neither is refused with an InputError naming the face, how far it leans and
near which point: "Face7: wall not vertical: leans 26.6° near x = 3, y = 14.2".
"""

from dataclasses import dataclass
from math import comb

import numpy as np

from ..engine.polynomials import real_roots_unit
from ..engine.tolerances import RECOGNITION_TOL as TOL
from ..errors import InputError, note
from .freecad_env import FreeCAD, Part

#: What every refusal adds: what a 2.5D stock must be.
RULE = note("a 2.5D stock has horizontal tops and vertical walls")


@dataclass(frozen=True)
class FaceKind:
    """A face of a 2.5D solid.

    name: "Face7". kind: "up" or "down" (a horizontal face with the material below or above
    it) or "wall" (vertical). z: the height of a horizontal face (mm), NaN for a wall.
    box: (6,) exact x_min, x_max, y_min, y_max, z_min, z_max of the face (mm). plan: for a
    wall whose surface is not a plane, its plan curve as a Part curve (Circle, or the curve
    extruded, a parabola or hyperbola as its exact B-spline over the face, or the B-spline/Bézier
    curve of the control net's rows), to be trimmed; None for planes and horizontal faces.
    surface: the surface classified (:func:`exact_surface`): the face's own, or the plane,
    cylinder or extrusion a trimmed or offset surface equals.
    """

    name: str
    kind: str
    z: float
    box: tuple
    plan: object = None
    surface: object = None


#: Curves whose edges are read exactly as B-splines (lines degree 1, conics rational degree 2).
EXACT_CURVES = (Part.Line, Part.Circle, Part.Ellipse, Part.Parabola, Part.Hyperbola, Part.BSplineCurve,
                Part.BezierCurve)


def edge_curve(edge):
    """The Part curve an edge lies on, or None for a degenerated edge (a point: a cone's apex, a
    sphere's pole). ValueError in words for an edge without a 3D curve, or on a curve that has no
    exact B-spline form (not in EXACT_CURVES: an offset curve)."""
    if edge.Degenerated:
        return None
    try:
        curve = edge.Curve
    except (TypeError, FreeCAD.Base.FreeCADError, Part.OCCError):  # FreeCAD's "undefined curve type"
        raise ValueError(f"the edge {_ends(edge)} has no 3D curve, so its extent cannot be found") from None
    if not isinstance(curve, EXACT_CURVES):
        raise ValueError(f"the edge {_ends(edge)} lies on {_a(type(curve).__name__)}, which has no exact B-spline "
                         "form, so its extent cannot be found exactly")
    return curve


def _ends(edge):
    """'from (x, y, z) to (x, y, z)', or 'at (x, y, z)' for a closed edge: its vertices in words (mm)."""
    points = ["(" + ", ".join(f"{v:.6g}" for v in vertex.Point) + ")" for vertex in edge.Vertexes]
    return f"from {points[0]} to {points[-1]}" if len(points) > 1 else f"at {points[0]}"


def bspline_of_edge(edge):
    """The edge's curve over the edge's own parameter range as a non-periodic Part.BSplineCurve.

    Exact: ``toNurbs`` for lines and conics, the poles and weights themselves for Bézier curves.
    """
    curve = edge.Curve
    if isinstance(curve, Part.BezierCurve):
        curve = bezier_as_bspline(curve)
    else:
        curve = edge.toNurbs().Edges[0].Curve
        if isinstance(curve, Part.BezierCurve):
            curve = bezier_as_bspline(curve)
    curve = curve.copy()
    if curve.isPeriodic():
        curve.setNotPeriodic()
    u0, u1 = edge.FirstParameter, edge.LastParameter
    if (u0, u1) != (curve.FirstParameter, curve.LastParameter):
        curve.segment(u0, u1)
    return curve


def bezier_as_bspline(bezier):
    """A Part.BezierCurve as the equal one-span Part.BSplineCurve on its own range [0, 1]."""
    degree = bezier.Degree
    curve = Part.BSplineCurve()
    curve.buildFromPolesMultsKnots(bezier.getPoles(), [degree + 1, degree + 1], [0.0, 1.0], False, degree,
                                   bezier.getWeights())
    return curve


def _bernstein_to_power(degree):
    """(p+1, p+1) matrix M with power coefficients a = M @ b for Bernstein coefficients b on [0, 1]."""
    p = degree
    matrix = np.zeros((p + 1, p + 1))
    for k in range(p + 1):
        for i in range(k + 1):
            matrix[k, i] = comb(p, k) * comb(k, i) * (-1) ** (k - i)
    return matrix


def critical_points(edge, axis):
    """(k, 3) points of an edge, in order along it: its start, every turning point of coordinate
    `axis` (0 x, 1 y, 2 z) and its end (mm). The coordinate's extremes over the edge, and every
    change of its direction, are among them. All spans at once: (m spans, degree p). A degenerated
    edge gives its one point; ValueError for an edge that cannot be read exactly (:func:`edge_curve`).
    """
    curve = edge_curve(edge)
    if curve is None:
        return np.array([tuple(edge.Vertexes[0].Point)])
    if isinstance(curve, Part.Line):  # no turning points
        return np.array([tuple(edge.valueAt(u)) for u in edge.ParameterRange])
    spans = bspline_of_edge(edge).toBezier()
    p = spans[0].Degree
    poles = np.array([[tuple(pole) for pole in span.getPoles()] for span in spans])  # (m, p+1, 3)
    weights = np.array([span.getWeights() for span in spans])  # (m, p+1)
    to_power = _bernstein_to_power(p).T
    c = (weights * poles[..., axis]) @ to_power
    w = weights @ to_power
    slope = np.arange(1, p + 1)
    numerator = _product(c[:, 1:] * slope, w) - _product(c, w[:, 1:] * slope)  # C′W − CW′, (m, 2p)
    roots = real_roots_unit(numerator) if p > 0 else np.full((len(spans), 0), np.nan)
    t = np.concatenate([np.zeros((len(spans), 1)), np.sort(roots, axis=1), np.ones((len(spans), 1))], axis=1)
    span = np.repeat(np.arange(len(spans)), t.shape[1]).reshape(t.shape)
    keep = np.isfinite(t)
    keep[1:, 0] = False  # a span's start is the previous span's end
    points = _bezier_points(poles[span[keep]], weights[span[keep]], t[keep])
    return points


def _product(a, b):
    """Row-wise products of polynomials: ascending coefficients (m, i), (m, j) -> (m, i + j), zero-padded
    to the same width for any i, j with i + j fixed by the caller."""
    out = np.zeros((a.shape[0], a.shape[1] + b.shape[1]))
    for k in range(a.shape[1]):
        out[:, k:k + b.shape[1]] += a[:, k:k + 1] * b
    return out


def _bezier_points(poles, weights, t):
    """Points (k, 3) of rational Bézier spans with poles (k, p+1, 3), weights (k, p+1) at t (k,) in [0, 1]."""
    p = poles.shape[1] - 1
    i = np.arange(p + 1)
    basis = np.array([comb(p, k) for k in i]) * t[:, None] ** i * (1.0 - t[:, None]) ** (p - i)
    weighted = basis * weights
    return (weighted[..., None] * poles).sum(axis=1) / weighted.sum(axis=1)[:, None]


def edge_box(edge):
    """(6,) exact x_min, x_max, y_min, y_max, z_min, z_max of an edge (mm); ValueError for an edge that
    cannot be read exactly (:func:`edge_curve`)."""
    if edge.Degenerated or isinstance(edge_curve(edge), Part.Line):
        ends = critical_points(edge, 0)
        return tuple(float(v) for pair in zip(ends.min(axis=0), ends.max(axis=0)) for v in pair)
    limits = []
    for axis in range(3):
        values = critical_points(edge, axis)[:, axis]
        limits += [values.min(), values.max()]
    return tuple(float(v) for v in limits)


def shape_box(shape, known=None):
    """(6,) exact x_min, x_max, y_min, y_max, z_min, z_max of a shape's edges (mm).

    A face's extreme points lie on its boundary for the planes, vertical walls and horizontal
    B-spline faces of a 2.5D solid, so the edges give the solid's box. known: a dict of edge
    boxes by ``edge.hashCode()``, read and filled, to compute each edge of a solid once.
    """
    known = {} if known is None else known
    boxes = []
    for edge in shape.Edges:
        key = edge.hashCode()
        if key not in known:
            known[key] = edge_box(edge)
        boxes.append(known[key])
    boxes = np.array(boxes)
    return (boxes[:, 0].min(), boxes[:, 1].max(), boxes[:, 2].min(), boxes[:, 3].max(),
            boxes[:, 4].min(), boxes[:, 5].max())


def fold(points, axis):
    """How far (mm) a curve through `points` (k, 3), in order, turns back in coordinate `axis`
    against its overall direction, and the point (3,) where it does most; 0 for a monotone curve.

    A curve whose two ends share the coordinate (within TOL) but that moves in it turns back by
    its whole spread.
    """
    values = points[:, axis]
    if values[-1] < values[0]:
        values = -values
    if abs(values[-1] - values[0]) <= TOL:
        k = int(np.argmax(np.abs(values - values[0])))
        return float(np.ptp(values)), points[k]
    back = np.maximum.accumulate(values) - values
    k = int(np.argmax(back))
    return float(back[k]), points[k]


def classify_face(face, name, where="", known=None):
    """FaceKind of a face of a 2.5D solid; InputError naming it when it is neither horizontal nor vertical.

    where: prefix of messages, e.g. "part.step: ". known: edge boxes by hash (see shape_box). A face
    with an edge that cannot be read exactly, on an offset surface that equals no plane, cylinder or
    extrusion, or a vertical wall whose plan curve has no exact B-spline form, is refused in words too.
    """
    try:
        box = shape_box(face, known)
        surface = exact_surface(face)
    except ValueError as error:
        raise InputError(f"{where}{name}: {error}") from None
    height = box[5] - box[4]
    if isinstance(surface, Part.Plane):
        normal = np.array(tuple(surface.Axis)) * (-1.0 if face.Orientation == "Reversed" else 1.0)
        if height <= TOL:
            return FaceKind(name, "up" if normal[2] > 0 else "down", _level(face, box), box, surface=surface)
        horizontal = np.hypot(normal[0], normal[1])
        if abs(normal[2]) * height <= TOL * max(horizontal, TOL):
            return FaceKind(name, "wall", float("nan"), box, surface=surface)
        _refuse_plane(face, name, normal, where)
    if isinstance(surface, (Part.Cylinder, Part.SurfaceOfExtrusion)):
        axis = np.array(tuple(surface.Axis if isinstance(surface, Part.Cylinder) else surface.Direction))
        axis = axis / np.linalg.norm(axis)
        if np.hypot(axis[0], axis[1]) * height <= TOL * abs(axis[2]):
            try:
                plan = _axial_plan(surface, face)
            except ValueError as error:
                raise InputError(f"{where}{name}: a vertical wall on {error}") from None
            return FaceKind(name, "wall", float("nan"), box, plan, surface)
        _refuse(face, name, f"a {type(surface).__name__} whose axis is {_degrees(np.arccos(min(1.0, abs(axis[2]))))}° "
                f"from vertical", where)
    if isinstance(surface, (Part.BSplineSurface, Part.BezierSurface)):
        return _net_face(face, name, box, where, surface)
    _refuse(face, name, f"a {type(surface).__name__} surface", where)


def exact_surface(face):
    """The surface classify_face reads for `face` (see the module's docstring): the face's own; a
    trimmed surface's basis; for an offset surface the Part.Plane, Part.Cylinder or
    Part.SurfaceOfExtrusion (of a line, or of a circle) it equals, through the offset surface's own
    point at the middle of the face's parameter range. ValueError in words for any other offset."""
    u0, u1, v0, v1 = face.ParameterRange
    return _unwrapped(face.Surface, 0.5 * (u0 + u1), 0.5 * (v0 + v1))


def _unwrapped(surface, u, v):
    """`surface` without trims and offsets (see exact_surface), at parameters (u, v) of the face's middle."""
    if isinstance(surface, Part.RectangularTrimmedSurface):
        return _unwrapped(surface.BasisSurface, u, v)
    if not isinstance(surface, Part.OffsetSurface):
        return surface
    basis = _unwrapped(surface.BasisSurface, u, v)
    point = surface.value(u, v)
    if isinstance(basis, Part.Plane):
        return Part.Plane(point, basis.Axis)
    if isinstance(basis, Part.Cylinder):
        return _cylinder(basis.Center, basis.Axis, point)
    if isinstance(basis, Part.SurfaceOfExtrusion):
        curve, direction = basis.BasisCurve, basis.Direction
        if isinstance(curve, Part.Line):
            return Part.SurfaceOfExtrusion(Part.Line(point, point + curve.Direction), direction)
        if isinstance(curve, Part.Circle) and curve.Axis.cross(direction).Length <= 1e-12 * direction.Length:
            return _cylinder(curve.Center, direction, point)
    raise ValueError(f"an OffsetSurface ({surface.OffsetValue:g} mm) of {_described(basis)}: its offset has no "
                     "exact form the walls take (offsets of planes, cylinders and extrusions of lines and circles "
                     "are taken)")


def _cylinder(center, axis, point):
    """The Part.Cylinder about the line through `center` along `axis` through `point` (FreeCAD Vectors, mm);
    ValueError when the point lies on the axis."""
    axis = FreeCAD.Vector(axis).normalize()
    offset = point - center
    radial = offset - axis * offset.dot(axis)
    if radial.Length <= TOL:
        raise ValueError("an OffsetSurface that shrinks a cylinder to its axis")
    cylinder = Part.Cylinder()
    cylinder.Center, cylinder.Axis, cylinder.Radius = center, axis, radial.Length
    return cylinder


def _described(surface):
    """'a SurfaceOfExtrusion of an OffsetCurve', 'a Sphere': a surface's type in words."""
    if isinstance(surface, Part.SurfaceOfExtrusion):
        return f"a SurfaceOfExtrusion of {_a(type(surface.BasisCurve).__name__)}"
    return _a(type(surface).__name__)


def _a(name):
    """'an OffsetCurve', 'a Sphere': a type's name with its article."""
    return f"{'an' if name[0] in 'AEIOU' else 'a'} {name}"


def _level(face, box):
    """z (mm) of a horizontal face: the middle of its exact z range."""
    return 0.5 * (box[4] + box[5])


def _degrees(radians):
    """Angle in degrees to one decimal, as text."""
    return f"{np.degrees(radians):.1f}"


def _near(face):
    """'near x = …, y = …' at the face's centre of mass."""
    centre = face.CenterOfMass
    return f"near x = {centre.x:.6g}, y = {centre.y:.6g}, z = {centre.z:.6g}"


def _refuse_plane(face, name, normal, where):
    """InputError for a plane neither horizontal nor vertical: slanted top, overhang or leaning wall."""
    nz = normal[2]
    tilt = _degrees(np.arccos(min(1.0, abs(nz))))
    if nz >= 0.5:
        what = f"slanted top: a plane tilted {tilt}° from horizontal"
    elif nz <= -0.5:
        what = f"overhang: a plane facing down, tilted {tilt}° from horizontal"
    else:
        what = f"wall not vertical: leans {_degrees(np.arcsin(min(1.0, abs(nz))))}°"
    raise InputError(f"{where}{name}: {what} {_near(face)}; {RULE}")


def _refuse(face, name, what, where):
    """InputError for a curved face: a curved top when its middle faces mostly up, else a wall not vertical."""
    u0, u1, v0, v1 = face.ParameterRange
    nz = face.normalAt(0.5 * (u0 + u1), 0.5 * (v0 + v1)).z
    kind = "curved top: not a horizontal plane" if nz >= 0.5 else (
        "overhang: faces down" if nz <= -0.5 else "wall not vertical")
    raise InputError(f"{where}{name}: {kind}: {what} {_near(face)}; {RULE}")


def _axial_plan(surface, face):
    """The plan curve of a vertical cylinder (a Part.Circle at its centre) or extrusion (its basis curve; a
    parabola or hyperbola, unbounded, as its exact rational B-spline over the face's range of the curve's
    parameter). ValueError in words for a basis curve with no exact B-spline form (an offset curve)."""
    if isinstance(surface, Part.Cylinder):
        return Part.Circle(surface.Center, FreeCAD.Vector(0, 0, 1), surface.Radius)
    curve = surface.BasisCurve
    if isinstance(curve, (Part.Parabola, Part.Hyperbola)):
        u0, u1 = face.ParameterRange[:2]
        return bspline_of_edge(Part.Edge(curve, u0, u1))
    if not isinstance(curve, EXACT_CURVES):
        raise ValueError(f"{_described(surface)}, which has no exact B-spline form for the walls")
    return curve


def _net_face(face, name, box, where, surface):
    """FaceKind of a face on a B-spline or Bézier surface (`surface`, untrimmed), decided from its control net."""
    poles = np.array([[tuple(p) for p in row] for row in surface.getPoles()])
    weights = np.array(surface.getWeights(), dtype=float)
    if np.ptp(poles[..., 2]) <= TOL:
        u0, u1, v0, v1 = face.ParameterRange
        up = face.normalAt(0.5 * (u0 + u1), 0.5 * (v0 + v1)).z > 0
        return FaceKind(name, "up" if up else "down", _level(face, box), box, surface=surface)
    for direction in (1, 0):
        rows = poles if direction == 1 else poles.transpose(1, 0, 2)
        w = weights if direction == 1 else weights.T
        spread = np.hypot(np.ptp(rows[..., 0], axis=1), np.ptp(rows[..., 1], axis=1))
        separable = np.allclose(w * w[:1, :1], w[:, :1] * w[:1, :], rtol=1e-12, atol=0.0)
        if spread.max() <= TOL and separable:
            return FaceKind(name, "wall", float("nan"), box, _net_plan(surface, direction, rows[:, 0], w[:, 0]),
                            surface)
    u0, u1, v0, v1 = face.ParameterRange
    if abs(face.normalAt(0.5 * (u0 + u1), 0.5 * (v0 + v1)).z) >= 0.5:
        z = poles[..., 2]
        pole = poles.reshape(-1, 3)[np.argmax(np.abs(z - np.median(z)).ravel())]
        raise InputError(f"{where}{name}: curved top: not a horizontal plane: a {type(surface).__name__} whose "
                         f"control points span z {z.min():.6g} to {z.max():.6g}, near x = {pole[0]:.6g}, "
                         f"y = {pole[1]:.6g}; {RULE}")
    # The lean of the row of poles that leans most, along the direction that runs most in z.
    direction = 1 if np.ptp(poles[..., 2], axis=1).max() >= np.ptp(poles[..., 2], axis=0).max() else 0
    rows = poles if direction == 1 else poles.transpose(1, 0, 2)
    drift = np.hypot(np.ptp(rows[..., 0], axis=1), np.ptp(rows[..., 1], axis=1))
    rise = np.ptp(rows[..., 2], axis=1)
    k = int(np.argmax(drift / np.maximum(rise, TOL)))
    row = rows[k].mean(axis=0)
    raise InputError(f"{where}{name}: wall not vertical: leans up to {_degrees(np.arctan2(drift[k], rise[k]))}° near "
                     f"x = {row[0]:.6g}, y = {row[1]:.6g} (a {type(surface).__name__} whose control points drift "
                     f"{drift[k]:.3g} mm sideways over {rise[k]:.3g} mm of height); {RULE}")


def _net_plan(surface, direction, poles, weights):
    """The plan curve of a vertical B-spline/Bézier face: the curve of one row of its net (z = 0).

    direction: 1 when the rows along v are vertical (the plan runs along u), 0 the other way.
    poles: (n, 3) the row's first poles; weights: (n,).
    """
    points = [FreeCAD.Vector(float(x), float(y), 0.0) for x, y, _ in poles]
    if isinstance(surface, Part.BezierSurface):
        curve = Part.BezierCurve()
        curve.setPoles(points)
        for k, weight in enumerate(weights, start=1):
            curve.setWeight(k, float(weight))
        return bezier_as_bspline(curve)
    if direction == 1:
        knots, mults, degree, periodic = (surface.getUKnots(), surface.getUMultiplicities(), surface.UDegree,
                                          surface.isUPeriodic())
    else:
        knots, mults, degree, periodic = (surface.getVKnots(), surface.getVMultiplicities(), surface.VDegree,
                                          surface.isVPeriodic())
    curve = Part.BSplineCurve()
    curve.buildFromPolesMultsKnots(points, mults, knots, periodic, degree, [float(w) for w in weights])
    return curve
