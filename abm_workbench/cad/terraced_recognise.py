"""Any 2.5D solid recognised as a terraced stock: slabs of planar regions bounded by the walls' plan curves (mm).

:func:`recognise_terraced` takes a solid bounded by horizontal planar faces and vertical walls,
in any orientation about z, with pockets, islands, bosses, rings and ridges, and returns the
:class:`~abm_workbench.engine.terraced_model.TerracedStock`. :func:`recognise_any` returns the
staircase of the paper when the solid is one (its engine is faster), the terraced stock
otherwise, and says which.

How (decisions exact, with the one tolerance
:data:`~abm_workbench.engine.tolerances.RECOGNITION_TOL`, ``TOL``):

1. One closed, valid solid; every face horizontal or vertical (:func:`.faces.classify_face`,
   which names the face that is neither, how much it leans and where).
2. Levels: the distinct heights of the solid's vertices (within TOL). Every horizontal face
   and every end of a vertical edge lies on one, so between two consecutive levels the solid
   is a prism: a slab.
3. Per slab, OpenCASCADE's section of the solid at the slab's mid height tells which wall
   faces bound the slab and where each piece of them starts and ends; each piece of section
   is matched to its wall face (the face whose plan geometry passes through the piece's middle,
   and whose domain holds it when several do), and replaced by the face's own exact plan
   geometry between the piece's ends, which are snapped onto the solid's vertical edges:
   a plane gives a :class:`PlanLine`, a vertical cylinder a :class:`PlanArc` (centre, radius,
   start angle, signed sweep), any other wall the B-spline of its plan curve cut to the piece
   (:class:`PlanSpline`; Bézier and conic curves converted exactly, rational ones with weights;
   parabolas and hyperbolas as their rational quadratic B-splines over the face). A trimmed or
   offset surface is read as the plane, cylinder or extrusion it equals (:func:`.faces.exact_surface`).
   Each curve names its face (``face="Face7"``).
4. Each curve runs with the material on its left (from the face's outward normal), and the
   curves are chained end to end into closed loops. The slab's region is their even-odd fill.
5. Checks, not decisions: every curve's middle point lies on the face it names (OCC's
   distance, within 10·TOL), and the region's area from the loops (closed form for lines and
   arcs, Gauss–Legendre on the spline spans) equals the area of OpenCASCADE's section face to
   :data:`AREA_CHECK` relative, the precision of OpenCASCADE's own area integration over spline
   boundaries; otherwise InputError.
"""

from dataclasses import dataclass

import numpy as np
from scipy.interpolate import BSpline

from ..engine.terraced_model import Loop, PlanArc, PlanLine, PlanSpline, Slab, TerracedStock
from ..engine.tolerances import RECOGNITION_TOL as TOL
from ..errors import InputError, note
from .faces import bezier_as_bspline, classify_face
from .freecad_env import FreeCAD, Part
from .recognise import recognise, single_solid

V = FreeCAD.Vector
#: The slab areas from the loops and from OpenCASCADE's section must agree to this, relative.
#: OpenCASCADE's own area integration over faces bounded by periodic B-spline edges was measured
#: up to 2e-4 relative off for the section's face (and 2e-2 for the volume of a common), where
#: two independent quadratures of the exact curves agree to 1e-12; so the check is coarse: it
#: catches a missing, doubled or reversed loop or a wrong part of a closed curve. Small errors
#: are excluded by construction and by the check that every curve's middle lies on its face.
AREA_CHECK = 1e-2
#: Gauss–Legendre points per B-spline span in the area check.
GAUSS_POINTS = 24


@dataclass(frozen=True)
class StockRecognition:
    """What :func:`recognise_any` found.

    kind: "staircase" when the solid is the paper's staircase along +x (then ``staircase`` is
    its :class:`~abm_workbench.cad.recognise.Recognition`), else "terraced" (then ``terraced``
    is the TerracedStock). reason: why the solid is not a staircase ("" when it is).
    """

    kind: str
    terraced: TerracedStock = None
    staircase: object = None
    reason: str = ""


def recognise_any(shape, *, walls="exact", wall_points="chebyshev", y_window=None, source=""):
    """The stock of a 2.5D solid as a StockRecognition: the staircase when it is one, else the terraced stock.

    The staircase recognition runs first (with walls, wall_points, y_window, see
    :func:`~abm_workbench.cad.recognise.recognise`): a staircase keeps its fast engine. Its
    refusal becomes ``reason``, and the terraced recognition follows: InputError when the solid
    is not 2.5D at all (its message names the face), or when the paper's quintic walls were
    asked for (they need a staircase).
    """
    try:
        staircase = recognise(shape, walls=walls, wall_points=wall_points, y_window=y_window, source=source)
    except InputError as error:
        if walls == "quintic":
            raise InputError(f"{error} (the paper's quintic walls need a staircase stock)") from None
        return StockRecognition("terraced", recognise_terraced(shape, source=source), None, str(error))
    return StockRecognition("staircase", None, staircase, "")


def recognise_terraced(shape, *, source=""):
    """The TerracedStock of a Part.Shape holding one 2.5D solid (see the module's docstring).

    source names the input in messages (e.g. the file). InputError naming the face and where,
    when the solid is not 2.5D.
    """
    where = f"{source}: " if source else ""
    solid = single_solid(shape, where)
    names = {face.hashCode(): f"Face{k}" for k, face in enumerate(shape.Faces, start=1)}
    known = {}
    kinds = [(face, classify_face(face, names[face.hashCode()], where, known)) for face in solid.Faces]
    walls = [(face, kind) for face, kind in kinds if kind.kind == "wall"]
    faces = {kind.name: face for face, kind in kinds}
    levels = _levels(solid)
    corners = _vertical_edge_points(solid)
    slabs = []
    for k, (z_bottom, z_top) in enumerate(zip(levels[:-1], levels[1:])):
        z_mid = 0.5 * (z_bottom + z_top)
        spanning = [(face, kind) for face, kind in walls if kind.box[4] - TOL <= z_mid <= kind.box[5] + TOL]
        pieces = []
        wires = solid.slice(V(0, 0, 1), z_mid)
        for wire in wires:
            for edge in wire.Edges:
                pieces += _plan_pieces(edge, spanning, corners, z_mid, where, k)
        slab = Slab(z_bottom, z_top, _loops(pieces, where, k))
        _check_on_faces(slab, faces, k, where)
        _check_area(wires, slab, k, where)
        slabs.append(slab)
    return TerracedStock(slabs)


def _levels(solid):
    """(m,) increasing distinct z of the solid's vertices (mm), those within TOL of each other merged."""
    z = np.sort([vertex.Point.z for vertex in solid.Vertexes])
    breaks = np.flatnonzero(np.diff(z) > TOL) + 1
    return np.array([group.mean() for group in np.split(z, breaks)])


def _vertical_edge_points(solid):
    """(k, 2) plan positions [x, y] (mm) of the solid's vertical edges, onto which section ends are snapped."""
    points = []
    for edge in solid.Edges:
        ends = [vertex.Point for vertex in edge.Vertexes]
        if (len(ends) == 2 and abs(ends[0].z - ends[1].z) > TOL
                and np.hypot(ends[0].x - ends[1].x, ends[0].y - ends[1].y) <= TOL):
            points.append((ends[0].x, ends[0].y))
    return np.array(points).reshape(-1, 2)


def _snap(point, corners):
    """point (2,) moved onto the nearest vertical edge's plan position when within 10·TOL (mm)."""
    if corners.size:
        distance = np.hypot(*(corners - point).T)
        k = int(np.argmin(distance))
        if distance[k] <= 10 * TOL:
            return corners[k].copy()
    return point


def _plan_pieces(edge, spanning, corners, z_mid, where, k):
    """The exact plan curves (material on their left) of one edge of the section at z_mid."""
    u0, u1 = edge.FirstParameter, edge.LastParameter
    middle = edge.valueAt(0.5 * (u0 + u1))
    face, kind = _face_of(middle, spanning, where, k)
    start = _snap(np.array([edge.valueAt(u0).x, edge.valueAt(u0).y]), corners)
    end = _snap(np.array([edge.valueAt(u1).x, edge.valueAt(u1).y]), corners)
    mid = np.array([middle.x, middle.y])
    closed = edge.isClosed() or np.hypot(*(end - start)) <= TOL
    first = edge.derivative1At(u0)
    heading = np.array([first.x, first.y])
    plan = kind.plan
    if plan is None or isinstance(plan, (Part.Line, Part.LineSegment)):
        curves = [PlanLine(start, end, face=kind.name)]
    elif isinstance(plan, Part.Circle):
        curves = [_arc(plan, start, end, mid, heading, closed, kind.name)]
    else:
        curves = _spline_pieces(plan, start, end, mid, heading, closed, kind.name)
    normal = face.normalAt(*face.Surface.parameter(middle))
    tangent = edge.derivative1At(0.5 * (u0 + u1))
    # The section edge runs start to end like the curves; the material must lie on the left.
    if normal.x * -tangent.y + normal.y * tangent.x > 0:
        curves = [_reversed(curve) for curve in reversed(curves)]
    return curves


def _face_of(point, spanning, where, k):
    """(face, FaceKind) of the wall face through a section point (3D); InputError when none or several."""
    near = [(face, kind) for face, kind in spanning if _plan_distance(kind, point) <= 10 * TOL]
    if len(near) > 1:
        near = [(face, kind) for face, kind in near if face.isPartOfDomain(*face.Surface.parameter(point))]
    if len(near) != 1:
        found = ", ".join(kind.name for _, kind in near) or note("no wall face")
        raise InputError(f"{where}slab {k}: the section at z = {point.z:.6g} near x = {point.x:.6g}, "
                         f"y = {point.y:.6g} lies on {found}; expected one vertical wall")
    return near[0]


def _plan_distance(kind, point):
    """Plan distance (mm) from a point to a wall face's surface, extended beyond the face."""
    if kind.plan is None:
        normal = kind.surface.Axis
        return abs(normal.dot(point - kind.surface.Position)) / max(np.hypot(normal.x, normal.y), TOL)
    plan = kind.plan
    level = V(point.x, point.y, plan.value(plan.FirstParameter).z)
    nearest = plan.value(plan.parameter(level))
    return float(np.hypot(nearest.x - point.x, nearest.y - point.y))


def _angle(center, point):
    """Polar angle (radians) of point (2,) about center (2,)."""
    return float(np.arctan2(point[1] - center[1], point[0] - center[0]))


def _arc(circle, start, end, mid, heading, closed, name):
    """PlanArc on a circle from start through mid to end ((2,) mm each); when closed, the full circle
    leaving start in the direction `heading` (2,)."""
    center = np.array([circle.Center.x, circle.Center.y])
    a0 = _angle(center, start)
    if closed:
        radial = start - center
        turn = radial[0] * heading[1] - radial[1] * heading[0]
        return PlanArc(center, circle.Radius, a0, 2.0 * np.pi if turn > 0 else -2.0 * np.pi, face=name)
    forward = (_angle(center, end) - a0) % (2.0 * np.pi)
    to_mid = (_angle(center, mid) - a0) % (2.0 * np.pi)
    sweep = forward if to_mid < forward else forward - 2.0 * np.pi
    return PlanArc(center, circle.Radius, a0, sweep, face=name)


def _as_bspline(curve):
    """A plan curve as a Part.BSplineCurve, exactly (Bézier by its poles, others by toNurbs)."""
    if isinstance(curve, Part.BSplineCurve):
        return curve.copy()
    if isinstance(curve, Part.BezierCurve):
        return bezier_as_bspline(curve)
    return curve.toNurbs(curve.FirstParameter, curve.LastParameter)


def _spline_pieces(plan, start, end, mid, heading, closed, name):
    """PlanSplines of the plan curve from start through mid to end ((2,) mm each), one or two
    (two when the piece runs across the start of a closed curve); when closed, the whole curve
    leaving start in the direction `heading` (2,)."""
    curve = _as_bspline(plan)
    first, last = curve.FirstParameter, curve.LastParameter

    def at(point):
        return curve.parameter(V(float(point[0]), float(point[1]), curve.StartPoint.z))

    u_a, u_m, u_b = at(start), at(mid), at(end)
    if closed and min(u_a - first, last - u_a) <= 1e-12 * (last - first):
        middle = 0.5 * (first + last)
        ranges = [(first, middle), (middle, last)]
    elif closed:
        ranges = [(u_a, last), (first, u_a)]
    elif min(u_a, u_b) <= u_m <= max(u_a, u_b):
        ranges = [(u_a, u_b)]
    else:
        # the piece runs over the closed curve's seam
        ranges = [(u_a, last), (first, u_b)] if u_a > u_b else [(u_a, first), (last, u_b)]
    pieces = [_segment(curve, lo, hi, name) for lo, hi in ranges if hi != lo]
    if closed:
        ahead = curve.getD1(u_a)[1]
        if ahead.x * heading[0] + ahead.y * heading[1] < 0:
            pieces = [_reversed(piece) for piece in reversed(pieces)]
    pieces[0] = _with_end(pieces[0], 0, start)
    pieces[-1] = _with_end(pieces[-1], -1, start if closed else end)
    return pieces


def _segment(curve, u_from, u_to, name):
    """PlanSpline of a Part.BSplineCurve between parameters u_from and u_to (not its whole range when it
    is periodic), running from u_from; clamped (``toBSpline`` cuts it exactly)."""
    piece = curve.toBSpline(min(u_from, u_to), max(u_from, u_to))
    if u_from > u_to:
        piece.reverse()
    knots = np.repeat(piece.getKnots(), piece.getMultiplicities())
    control = np.array([(p.x, p.y) for p in piece.getPoles()])
    weights = np.array(piece.getWeights())
    return PlanSpline(piece.Degree, knots, control, None if np.ptp(weights) == 0.0 else weights, face=name)


def _with_end(spline, index, point):
    """The spline with its first (index 0) or last (−1) control point set to point (2,)."""
    control = np.array(spline.control)
    control[index] = point
    return PlanSpline(spline.degree, spline.knots, control, spline.weights, face=spline.face)


def _reversed(curve):
    """The same plan curve run the other way."""
    if isinstance(curve, PlanLine):
        return PlanLine(curve.end, curve.start, face=curve.face)
    if isinstance(curve, PlanArc):
        return PlanArc(curve.center, curve.radius, curve.start_angle + curve.sweep, -curve.sweep, face=curve.face)
    knots = curve.knots[0] + curve.knots[-1] - curve.knots[::-1]
    weights = None if curve.weights is None else curve.weights[::-1]
    return PlanSpline(curve.degree, knots, curve.control[::-1], weights, face=curve.face)


def _loops(pieces, where, k):
    """The pieces (plan curves with the material on their left) chained into closed Loops."""
    left = list(pieces)
    loops = []
    while left:
        chain = [left.pop(0)]
        while np.hypot(*(chain[-1].end_points[1] - chain[0].end_points[0])) > TOL:
            end = chain[-1].end_points[1]
            gaps = [np.hypot(*(end - piece.end_points[0])) for piece in left]
            if not gaps or min(gaps) > 10 * TOL:
                raise InputError(f"{where}slab {k}: the section's curve ending at x = {end[0]:.6g}, "
                                 f"y = {end[1]:.6g} ({chain[-1].face}) does not continue: the walls do not close")
            chain.append(left.pop(int(np.argmin(gaps))))
        loops.append(Loop(_joined(chain)))
    return loops


def _joined(chain):
    """The curves of a closed chain with each start set exactly onto the previous curve's end."""
    joined = [chain[0]]
    for curve in chain[1:] + chain[:1]:
        end = joined[-1].end_points[1]
        if isinstance(curve, PlanLine):
            curve = PlanLine(end, curve.end, face=curve.face)
        elif isinstance(curve, PlanSpline):
            curve = _with_end(curve, 0, end)
        joined.append(curve)
    return tuple(joined[1:])


def region_area(slab):
    """Area (mm²) of a slab's region whose loops run with the material on their left: Σ ½∮(x dy − y dx)."""
    return sum(_curve_area(curve) for loop in slab.loops for curve in loop.curves)


def _curve_area(curve):
    """½∫(x dy − y dx) along one plan curve (mm²)."""
    if isinstance(curve, PlanLine):
        (x0, y0), (x1, y1) = curve.start, curve.end
        return 0.5 * (x0 * y1 - x1 * y0)
    if isinstance(curve, PlanArc):
        (cx, cy), r = curve.center, curve.radius
        a, b = curve.start_angle, curve.start_angle + curve.sweep
        return 0.5 * (r * r * curve.sweep + r * cx * (np.sin(b) - np.sin(a)) - r * cy * (np.cos(b) - np.cos(a)))
    weights = np.ones(len(curve.control)) if curve.weights is None else curve.weights
    homogeneous = BSpline(curve.knots, np.column_stack([curve.control * weights[:, None], weights]), curve.degree)
    slope = homogeneous.derivative()
    nodes, gauss = np.polynomial.legendre.leggauss(GAUSS_POINTS)
    breaks = np.unique(curve.knots[curve.degree:len(curve.control) + 1])
    lo, hi = breaks[:-1, None], breaks[1:, None]
    t = (0.5 * (lo + hi) + 0.5 * (hi - lo) * nodes).ravel()
    factor = (0.5 * (hi - lo) * gauss).ravel()
    (X, Y, W), (dX, dY, _) = homogeneous(t).T, slope(t).T
    # x dy − y dx = (X dY − Y dX) / W² for x = X/W, y = Y/W
    return 0.5 * float(np.sum(factor * (X * dY - Y * dX) / (W * W)))


def _middle(curve):
    """(2,) the point halfway along a plan curve's parameter (mm)."""
    if isinstance(curve, PlanLine):
        return 0.5 * (curve.start + curve.end)
    if isinstance(curve, PlanArc):
        return curve.at(curve.start_angle + 0.5 * curve.sweep)
    weights = np.ones(len(curve.control)) if curve.weights is None else curve.weights
    homogeneous = BSpline(curve.knots, np.column_stack([curve.control * weights[:, None], weights]), curve.degree)
    x, y, w = homogeneous(0.5 * (curve.knots[curve.degree] + curve.knots[len(curve.control)]))
    return np.array([x / w, y / w])


def _check_on_faces(slab, faces, k, where):
    """InputError unless every curve's middle point, at the slab's mid height, lies on its face (10·TOL)."""
    z = 0.5 * (slab.z_bottom + slab.z_top)
    for loop in slab.loops:
        for curve in loop.curves:
            x, y = _middle(curve)
            distance = faces[curve.face].distToShape(Part.Vertex(V(x, y, z)))[0]
            if distance > 10 * TOL:
                raise InputError(f"{where}slab {k}: the curve recognised on {curve.face} passes {distance:.3g} mm "
                                 f"from it near x = {x:.6g}, y = {y:.6g}: not recognised")


def _check_area(wires, slab, k, where):
    """InputError unless the slab's region area equals that of the face OpenCASCADE makes of the section's
    wires (holes and islands nested by FreeCAD's bullseye face maker), to AREA_CHECK relative."""
    expected = Part.makeFace(wires, "Part::FaceMakerBullseye").Area
    found = region_area(slab)
    if abs(found - expected) > AREA_CHECK * max(expected, 1.0):
        raise InputError(f"{where}slab {k} (z {slab.z_bottom:.6g} to {slab.z_top:.6g}): the region recognised has "
                         f"area {found:.12g} mm² but the solid's section {expected:.12g} mm²: not recognised")
