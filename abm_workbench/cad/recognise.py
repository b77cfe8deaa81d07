"""Solids read from files, and a solid recognised as staircase stock (mm).

:func:`load_solid` reads STEP, BREP or FCStd into a Part.Shape. :func:`recognise` finds
in a solid the shape of the paper's staircase and returns it as a
:class:`~abm_workbench.engine.Staircase` over a y window, with one of two wall models:

- ``walls="exact"`` (default): each wall is its top edge itself, as one (rational) B-spline
  x(s), y(s) (:class:`~abm_workbench.engine.walls.SplineWall`). Every edge of the top edge is
  converted exactly (``edge.toNurbs()``: lines become degree 1, conics rational degree 2) and
  cut to the edge's own parameter range; the pieces are raised to one degree, turned to run
  towards +y and joined end to end into one curve: their knot vectors are concatenated (each
  shifted to start where the previous one ends), with multiplicity p at each junction (C0
  there) and the junction's two end poles merged (rational pieces are first rescaled so that
  the weights meet). The curve is then cut to the window.
- ``walls="quintic"``: the paper's model, the quintic through six points on the top edge.

Either way the Staircase records six points on each wall (``wall_points``), placed at
Chebyshev nodes (or evenly) over the window.

What the solid must be, checked face by face (faces are named as FreeCAD names them,
``Face1``, ``Face2``, … in ``shape.Faces`` order):

- one closed, valid solid;
- every face horizontal or vertical: tops face up (+z), the base faces down at the lowest z,
  the stock's four sides are planes on its bounding box, every other vertical face is a wall;
- each wall's top edge (one edge, or a chain of edges over several faces) has one x for every
  y in the window: the stock is 2.5D along x;
- the walls split the stock into sections ordered along +x, each with exactly one top face,
  and each wall rises from the lower to the higher of the two tops beside it.

A wall's faces, edges and exact curve stay available in :class:`RecognisedWall`.
"""

import os
from dataclasses import dataclass

import numpy as np

from ..engine import Staircase
from ..engine.walls import SplineWall
from ..errors import InputError
from .freecad_env import FreeCAD, Part
from .solids import bspline_curve, parameter_at_y, trimmed_to_y

#: A face is horizontal when its normal's horizontal part, vertical when its n_z, is below this.
NORMAL_TOL = 1e-7
#: Points closer than this (mm) coincide; a face within this of a bounding-box limit lies on it.
LENGTH_TOL = 1e-6
#: Normals are sampled on a NORMAL_GRID × NORMAL_GRID grid of each face's parameter range.
NORMAL_GRID = 5
#: Least number of samples along each top edge for the one-x-per-y check.
EDGE_SAMPLES = 257
#: Number of y levels across the window at which every wall must have exactly one x.
Y_LEVELS = 256

_SUFFIXES = {".step": "STEP", ".stp": "STEP", ".brep": "BREP", ".brp": "BREP", ".fcstd": "FCStd"}


@dataclass(frozen=True)
class RecognisedWall:
    """One wall of a recognised staircase.

    faces: names of its vertical faces (``"Face7"``, …). edges: its top edge as Part.Edge
    objects, in order along +y (an edge may run either way). y_range: (2,) y span of the top
    edge (mm). z_range: (2,) lowest and highest z of the wall's faces (mm). points: (6, 2)
    [x, y] on the top edge at the window's sample y values (mm). is_straight: every edge is a
    line at one x, and the six x values (and the curve's poles' x) are set exactly equal.
    curve: the top edge over the window as one SplineWall (the exact wall model).
    """

    faces: tuple
    edges: tuple
    y_range: tuple
    z_range: tuple
    points: np.ndarray
    is_straight: bool
    curve: SplineWall


@dataclass(frozen=True)
class Recognition:
    """A solid recognised as a staircase.

    staircase: the Staircase over the y window (its y_min, y_max are the window's).
    walls: RecognisedWall per wall 1..n−1, in order along +x. tops: (n,) name of each section's
    top face. y_window: (2,) mm. box: (6,) the solid's x_min, x_max, y_min, y_max, z_min, z_max.
    """

    staircase: Staircase
    walls: tuple
    tops: tuple
    y_window: tuple
    box: tuple


def load_solid(path, name=None):
    """The shape in a STEP (.step, .stp), BREP (.brep, .brp) or FreeCAD (.FCStd) file.

    For FCStd, the shape of the object named `name` (its Name or Label), or else of the one
    top-level object holding a solid; a document already open is used as it is and left open.
    InputError naming the file when it is missing, unreadable, empty, or when the document
    holds no or several candidate solids.
    """
    path = os.fspath(path)
    kind = _SUFFIXES.get(os.path.splitext(path)[1].lower())
    if kind is None:
        raise InputError(f"{path}: unknown file type; expected .step, .stp, .brep, .brp or .FCStd")
    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file")
    if kind == "FCStd":
        return _load_document_solid(path, name)
    if name is not None:
        raise InputError(f"{path}: name= selects an object of a .FCStd document, not of a {kind} file")
    try:
        shape = Part.read(path)
    except Exception as error:  # FreeCAD raises RuntimeError or Part.OCCError
        raise InputError(f"{path}: cannot read as {kind}: {error}") from None
    if shape.isNull() or not shape.Faces:
        raise InputError(f"{path}: the {kind} file holds no shape")
    return shape


def _load_document_solid(path, name):
    """Shape of the chosen object of a FreeCAD document (see load_solid)."""
    already = [d for d in FreeCAD.listDocuments().values() if d.FileName and _same_file(d.FileName, path)]
    try:
        document = already[0] if already else FreeCAD.openDocument(path, True)
    except Exception as error:
        raise InputError(f"{path}: cannot open as a FreeCAD document: {error}") from None
    try:
        solid_objects = [o for o in document.Objects if _has_solid(o)]
        if name is not None:
            chosen = [o for o in solid_objects if o.Name == name] or [o for o in solid_objects if o.Label == name]
            if len(chosen) != 1:
                found = "no" if not chosen else "several"
                names = ", ".join(o.Name for o in solid_objects) or "none"
                raise InputError(f"{path}: {found} object with a solid named {name!r} (objects with solids: {names})")
        else:
            chosen = [o for o in solid_objects if not any(_has_solid(parent) for parent in o.InList)]
            if len(chosen) != 1:
                names = ", ".join(o.Name for o in chosen)
                detail = "no object holds a solid" if not chosen else f"several solids ({names}); choose one with name="
                raise InputError(f"{path}: {detail}")
        return chosen[0].Shape
    finally:
        if not already:
            FreeCAD.closeDocument(document.Name)


def _same_file(a, b):
    """True when paths a and b name the same existing file."""
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False


def _has_solid(obj):
    """True when a document object has a Shape with at least one solid."""
    shape = getattr(obj, "Shape", None)
    return isinstance(shape, Part.Shape) and not shape.isNull() and bool(shape.Solids)


def recognise_staircase(shape, *, walls="exact", wall_points="chebyshev", y_window=None, source=""):
    """The Staircase of a solid: ``recognise(...).staircase`` (see :func:`recognise`)."""
    return recognise(shape, walls=walls, wall_points=wall_points, y_window=y_window, source=source).staircase


def recognise(shape, *, walls="exact", wall_points="chebyshev", y_window=None, source=""):
    """Recognise a Part.Shape holding one solid as a staircase along +x; returns a Recognition.

    walls: "exact" gives the Staircase the walls' own curves (``wall_curves``, one SplineWall
    per wall, see the module's docstring); "quintic" the quintics through the six points.
    wall_points: "chebyshev" places the six points of each wall at the Chebyshev nodes
    y_mid − y_half·cos((2k+1)π/12), k = 0..5, of the window; "even" at six evenly spaced y
    including the window's ends. y_window: (y0, y1) in mm inside the stock's y range, default
    the whole range; only the window is recognised and the Staircase's y limits are the
    window's. source names the input in messages (e.g. the file). Raises InputError naming
    the face and what is wrong when the solid is not such a staircase.
    """
    where = f"{source}: " if source else ""
    if walls not in ("exact", "quintic"):
        raise ValueError(f"walls must be 'exact' or 'quintic', got {walls!r}")
    if wall_points not in ("chebyshev", "even"):
        raise ValueError(f"wall_points must be 'chebyshev' or 'even', got {wall_points!r}")
    solid = _single_solid(shape, where)
    names = {face.hashCode(): f"Face{k}" for k, face in enumerate(shape.Faces, start=1)}
    box = solid.BoundBox
    limits = (box.XMin, box.XMax, box.YMin, box.YMax, box.ZMin, box.ZMax)
    window = _window(y_window, box, where)
    tops, wall_faces = [], []
    for face in solid.Faces:
        role = _face_role(face, names[face.hashCode()], limits, where)
        if role == "top":
            tops.append(face)
        elif role == "wall":
            wall_faces.append(face)
    if not tops:
        raise InputError(f"{where}the solid has no top face facing +z")
    y_samples = _sample_ys(window, wall_points)
    found = [_wall(chain, names, window, y_samples, where) for chain in _chains(wall_faces, names, where)]
    # Sections are told apart at an inner sample y, where every wall's x is known.
    found.sort(key=lambda w: w.points[2, 0])
    x_probe = [box.XMin] + [w.points[2, 0] for w in found] + [box.XMax]
    top_faces = _section_tops(tops, names, x_probe, y_samples[2], box, where)
    z_top = [face.BoundBox.ZMax for face in top_faces]
    for j, wall in enumerate(found, start=1):
        _check_wall_heights(wall, j, z_top[j - 1], z_top[j], where)
    curves = tuple(w.curve for w in found) if walls == "exact" else None
    try:
        staircase = Staircase(box.XMin, box.XMax, window[0], window[1], box.ZMin, z_top,
                              [w.points for w in found], curves)
    except ValueError as error:
        raise InputError(f"{where}{error}") from None
    return Recognition(staircase, tuple(found), tuple(names[f.hashCode()] for f in top_faces), window, limits)


def _single_solid(shape, where):
    """The one closed, valid solid of `shape`; InputError otherwise."""
    solids = shape.Solids
    if not solids:
        for shell in shape.Shells:
            if not shell.isClosed():
                raise InputError(f"{where}not a closed solid: an open shell, {_free_edges(shape)}")
        raise InputError(f"{where}holds no solid (a {shape.ShapeType} of {len(shape.Faces)} faces)")
    if len(solids) > 1:
        raise InputError(f"{where}holds {len(solids)} solids; a staircase is one solid")
    solid = solids[0]
    if len(shape.Faces) != len(solid.Faces):
        raise InputError(f"{where}holds {len(shape.Faces) - len(solid.Faces)} faces outside its solid")
    if any(not shell.isClosed() for shell in solid.Shells):
        raise InputError(f"{where}not a closed solid: {_free_edges(shape)}")
    if not shape.isValid():
        raise InputError(f"{where}the solid is not valid (shape.check() says why)")
    return solid


def _free_edges(shape):
    """'Face2, Face5 have edges bordering no other face' for the faces of an open shell."""
    count = {}
    for face in shape.Faces:
        for edge in face.Edges:
            count[edge.hashCode()] = count.get(edge.hashCode(), 0) + 1
    faces = [
        f"Face{k}" for k, face in enumerate(shape.Faces, start=1)
        if any(count[edge.hashCode()] == 1 for edge in face.Edges)
    ]
    return f"{', '.join(faces)} {'has an edge' if len(faces) == 1 else 'have edges'} bordering no other face"


def _window(y_window, box, where):
    """(y0, y1) inside the stock's y range: y_window, or the whole range."""
    if y_window is None:
        return (box.YMin, box.YMax)
    y0, y1 = (float(v) for v in y_window)
    if not (box.YMin - LENGTH_TOL <= y0 < y1 <= box.YMax + LENGTH_TOL):
        raise InputError(
            f"{where}y_window ({y0}, {y1}) must be increasing and inside the stock's y range "
            f"[{box.YMin}, {box.YMax}]"
        )
    return (max(y0, box.YMin), min(y1, box.YMax))


def _sample_ys(window, wall_points):
    """(6,) increasing y values (mm) of the wall points over the window."""
    y0, y1 = window
    if wall_points == "even":
        return np.linspace(y0, y1, 6)
    nodes = -np.cos((2 * np.arange(6) + 1) * np.pi / 12)
    return 0.5 * (y0 + y1) + 0.5 * (y1 - y0) * nodes


def _face_role(face, name, limits, where):
    """'top', 'base', 'side' or 'wall'; InputError for a face that is neither horizontal nor vertical."""
    normals = _normals(face)
    nz = normals[:, 2]
    horizontal = np.hypot(normals[:, 0], normals[:, 1]).max() <= NORMAL_TOL
    box = face.BoundBox
    x_min, x_max, y_min, y_max, z_min, _ = limits
    if horizontal and nz[0] > 0:
        return "top"
    if horizontal:
        if abs(box.ZMax - z_min) > LENGTH_TOL:
            raise InputError(
                f"{where}{name}: overhang: faces downwards at z = {box.ZMax:.6g}, above the base (z = {z_min:.6g})"
            )
        return "base"
    if np.abs(nz).max() <= NORMAL_TOL:
        on_box = isinstance(face.Surface, Part.Plane) and (
            (box.XLength <= LENGTH_TOL and min(abs(box.XMin - x_min), abs(box.XMax - x_max)) <= LENGTH_TOL)
            or (box.YLength <= LENGTH_TOL and min(abs(box.YMin - y_min), abs(box.YMax - y_max)) <= LENGTH_TOL)
        )
        return "side" if on_box else "wall"
    if nz.min() < -NORMAL_TOL:
        raise InputError(f"{where}{name}: overhang: faces downwards (normal z-component down to {nz.min():.3g})")
    planar = isinstance(face.Surface, Part.Plane)
    if nz.mean() >= 0.5:
        what = "slanted top: a plane not horizontal" if planar else "curved top: not a horizontal plane"
    else:
        what = "wall not vertical" + ("" if planar else ", and curved across its height")
    spread = f"{nz.min():.3g}" if np.ptp(nz) <= NORMAL_TOL else f"{nz.min():.3g} to {nz.max():.3g}"
    raise InputError(f"{where}{name}: {what} (normal z-component {spread})")


def _normals(face):
    """(NORMAL_GRID², 3) outward unit normals of a face on a grid inside its parameter range."""
    u0, u1, v0, v1 = face.ParameterRange
    inset = (np.arange(NORMAL_GRID) + 0.5) / NORMAL_GRID
    return np.array([
        tuple(face.normalAt(u0 + a * (u1 - u0), v0 + b * (v1 - v0))) for a in inset for b in inset
    ])


def _chains(wall_faces, names, where):
    """Wall faces grouped into walls: lists of (face, top edge) whose top edges join end to end."""
    items = []
    for face in wall_faces:
        z_top = face.BoundBox.ZMax
        top_edges = [
            e for e in face.Edges
            if e.BoundBox.ZLength <= LENGTH_TOL and abs(e.BoundBox.ZMax - z_top) <= LENGTH_TOL
        ]
        if not top_edges:
            raise InputError(f"{where}{names[face.hashCode()]}: wall has no horizontal top edge")
        items += [(face, edge) for edge in top_edges]
    group = list(range(len(items)))

    def root(i):
        while group[i] != i:
            group[i] = group[group[i]]
            i = group[i]
        return i

    ends = [[v.Point for v in edge.Vertexes] for _, edge in items]
    for i in range(len(items)):
        for k in range(i + 1, len(items)):
            if any(p.distanceToPoint(q) <= LENGTH_TOL for p in ends[i] for q in ends[k]):
                group[root(k)] = root(i)
    chains = {}
    for i, item in enumerate(items):
        chains.setdefault(root(i), []).append(item)
    return list(chains.values())


def _wall(chain, names, window, y_samples, where):
    """RecognisedWall of a chain of (face, top edge); InputError unless it has one x per y in the window."""
    faces = sorted({names[face.hashCode()] for face, _ in chain}, key=lambda n: int(n[4:]))
    label = ", ".join(faces)
    edges = _ordered_edges([edge for _, edge in chain])
    samples = [_edge_samples(edge) for edge in edges]
    y_all = np.concatenate([s[:, 2] for s in samples])
    y0, y1 = window
    levels = y0 + (np.arange(Y_LEVELS) + 0.5) / Y_LEVELS * (y1 - y0)
    crossings = sum(_crossing_counts(s[:, 2], levels) for s in samples)
    if (crossings > 1).any():
        y = levels[np.argmax(crossings > 1)]
        raise InputError(f"{where}{label}: wall has more than one x for y = {y:.6g} (its top edge turns back in y)")
    if (crossings == 0).any():
        y = levels[np.argmax(crossings == 0)]
        raise InputError(
            f"{where}{label}: wall does not run across the y window [{y0:.6g}, {y1:.6g}]: no x at y = {y:.6g} "
            f"(its top edge spans y {y_all.min():.6g} to {y_all.max():.6g})"
        )
    x = [_x_at(edges, samples, y) for y in y_samples]
    if None in x:
        y = y_samples[x.index(None)]
        raise InputError(f"{where}{label}: wall's top edge has no point at y = {y:.6g} (it spans y "
                         f"{y_all.min():.6g} to {y_all.max():.6g})")
    points = np.column_stack([x, y_samples])
    straight = all(isinstance(e.Curve, Part.Line) for e in edges) and np.ptp(
        np.concatenate([s[:, 1] for s in samples])) <= LENGTH_TOL
    if straight:
        points[:, 0] = points[:, 0].mean()
    try:
        curve = _exact_curve(edges, window, points[0, 0] if straight else None)
    except ValueError as error:
        raise InputError(f"{where}{label}: {error}") from None
    z_low = min(face.BoundBox.ZMin for face, _ in chain)
    z_high = max(face.BoundBox.ZMax for face, _ in chain)
    return RecognisedWall(tuple(faces), tuple(edges), (float(y_all.min()), float(y_all.max())),
                          (z_low, z_high), points, straight, curve)


def _exact_curve(edges, window, straight_x):
    """The top edge's edges (in order along +y) as one SplineWall over the window (mm).

    straight_x: the common x of a straight wall, set on every pole, or None. ValueError from
    SplineWall when the joined curve is not monotone in y.
    """
    pieces = [_edge_bspline(edge) for edge in edges]
    degree = max(piece.Degree for piece in pieces)
    for piece in pieces:
        piece.increaseDegree(degree)
    knots, poles, weights = _joined([_bspline_data(piece) for piece in pieces], degree)
    curve = trimmed_to_y(bspline_curve(degree, knots, poles, weights, 0.0), *window)
    knots, poles, weights = _bspline_data(curve)
    if straight_x is not None:
        poles[:, 0] = straight_x
    return SplineWall(degree, knots, poles, None if np.ptp(weights) == 0.0 else weights)


def _edge_bspline(edge):
    """The edge's curve over its own parameter range as a Part.BSplineCurve running towards +y.

    ``edge.toNurbs()`` converts exactly (a line to degree 1, a conic to a rational B-spline)
    and keeps the edge's range; the curve is then cut to that range.
    """
    nurbs = edge.toNurbs().Edges[0]
    curve = nurbs.Curve.copy()
    if curve.isPeriodic():
        curve.setNotPeriodic()
    if (nurbs.FirstParameter, nurbs.LastParameter) != (curve.FirstParameter, curve.LastParameter):
        curve.segment(nurbs.FirstParameter, nurbs.LastParameter)
    if curve.StartPoint.y > curve.EndPoint.y:
        curve.reverse()
    return curve


def _bspline_data(curve):
    """(knots (k+p+1,), poles (k, 2) [x, y] mm, weights (k,)) of a Part.BSplineCurve."""
    knots = np.repeat(curve.getKnots(), curve.getMultiplicities())
    poles = np.array([(pole.x, pole.y) for pole in curve.getPoles()])
    return knots, poles, np.array(curve.getWeights())


def _joined(pieces, degree):
    """One clamped B-spline (knots, poles (k, 2), weights) from pieces of one degree, end to end.

    pieces: (knots, poles, weights) each, in order, each ending where the next starts. Each
    piece's knots are shifted to start at the previous piece's last knot; the junction keeps p
    copies of that knot (one fewer than a clamped end), so the curve is C0 there and passes
    through the junction pole, the mean of the two pieces' end poles. A piece's weights are
    scaled to meet the previous piece's last weight, which leaves its curve unchanged.
    """
    knots, poles, weights = pieces[0]
    for next_knots, next_poles, next_weights in pieces[1:]:
        shifted = next_knots - next_knots[0] + knots[-1]
        scaled = next_weights * (weights[-1] / next_weights[0])
        junction = 0.5 * (poles[-1] + next_poles[0])
        knots = np.concatenate([knots[:-1], shifted[degree + 1:]])
        poles = np.concatenate([poles[:-1], [junction], next_poles[1:]])
        weights = np.concatenate([weights, scaled[1:]])
    return knots, poles, weights


def _ordered_edges(edges):
    """Edges of a chain in order along +y (by the y of their middle points)."""
    return sorted(edges, key=lambda e: e.valueAt(0.5 * (e.FirstParameter + e.LastParameter)).y)


def _edge_samples(edge):
    """(k, 4) samples [u, x, y, z] along an edge's parameter range."""
    u0, u1 = edge.FirstParameter, edge.LastParameter
    knots = len(edge.Curve.getKnots()) if isinstance(edge.Curve, Part.BSplineCurve) else 2
    u = np.linspace(u0, u1, max(EDGE_SAMPLES, 16 * knots))
    return np.array([(t, *edge.valueAt(t)) for t in u])


def _crossing_counts(y, levels):
    """(L,) how many times the polyline with ordinates y (k,) crosses each level (a touch from one side counts 0)."""
    above = y[None, :] >= levels[:, None]
    return (above[:, 1:] != above[:, :-1]).sum(axis=1)


def _x_at(edges, samples, y):
    """x (mm) of a wall's top edge at y: safeguarded Newton on the edge parameter; None if none.

    samples: per edge, its _edge_samples, which bracket y. Beyond the chain's ends by at most
    LENGTH_TOL, the nearest end's x is used.
    """
    for edge, edge_samples in zip(edges, samples):
        rel = edge_samples[:, 2] - y
        change = np.flatnonzero((rel[:-1] <= 0) != (rel[1:] <= 0))
        if change.size:
            k = change[0]
            return edge.valueAt(parameter_at_y(edge.Curve, y, edge_samples[k, 0], edge_samples[k + 1, 0])).x
    ends = [(abs(edge.valueAt(u).y - y), edge.valueAt(u).x) for edge in edges for u in edge.ParameterRange]
    distance, x = min(ends)
    return x if distance <= LENGTH_TOL else None


def _section_tops(tops, names, x_probe, y_probe, box, where):
    """(n,) the top face of each section; at y = y_probe, section j lies between x_probe[j] and x_probe[j+1]."""
    n = len(x_probe) - 1
    found = [[] for _ in range(n)]
    for face in tops:
        z = face.BoundBox.ZMax
        probe = Part.LineSegment(FreeCAD.Vector(box.XMin - 1, y_probe, z), FreeCAD.Vector(box.XMax + 1, y_probe, z))
        pieces = face.common(probe.toShape()).Edges
        if not pieces:
            raise InputError(
                f"{where}{names[face.hashCode()]}: top face at z = {z:.6g} does not reach y = {y_probe:.6g}: "
                "a section must have one top across the y window"
            )
        longest = max(pieces, key=lambda e: e.Length)
        x = longest.valueAt(0.5 * (longest.FirstParameter + longest.LastParameter)).x
        found[min(max(int(np.searchsorted(x_probe, x)) - 1, 0), n - 1)].append(face)
    for j, faces in enumerate(found):
        if len(faces) != 1:
            listed = ", ".join(names[f.hashCode()] for f in faces)
            what = f"more than one top face: {listed}" if faces else "no top face"
            raise InputError(
                f"{where}section {j} (x {x_probe[j]:.6g} to {x_probe[j + 1]:.6g} at y = {y_probe:.6g}) has {what}"
            )
    return [faces[0] for faces in found]


def _check_wall_heights(wall, j, z_left, z_right, where):
    """Wall j must rise from the lower to the higher top beside it."""
    low, high = min(z_left, z_right), max(z_left, z_right)
    if abs(wall.z_range[0] - low) > LENGTH_TOL or abs(wall.z_range[1] - high) > LENGTH_TOL:
        raise InputError(
            f"{where}{', '.join(wall.faces)}: wall between sections {j - 1} and {j} spans z "
            f"{wall.z_range[0]:.6g} to {wall.z_range[1]:.6g}, but the tops beside it are at {low:.6g} and {high:.6g}"
        )
