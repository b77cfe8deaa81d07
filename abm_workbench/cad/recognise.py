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

What the solid must be, decided exactly from its geometry (:mod:`.faces`, one tolerance
:data:`~abm_workbench.engine.tolerances.RECOGNITION_TOL`), checked face by face (faces are
named as FreeCAD names them, ``Face1``, ``Face2``, … in ``shape.Faces`` order):

- one closed, valid solid;
- every face a horizontal plane or a vertical wall: tops face up (+z), the base faces down at
  the lowest z, the stock's four sides are vertical faces in the planes of its exact bounding box, every other
  vertical face is a wall; faces stacked on each other in z belong to one wall;
- each wall's top edge (one edge, or a chain of edges over several faces) has one x for every
  y in the window: each of its edges runs one way in y (no turning point of y(t) where the
  edge turns back by more than the tolerance) and the edges follow each other in y without
  overlap or gap: the stock is 2.5D along x;
- the walls split the stock into sections ordered along +x, each with exactly one top face,
  and each wall rises from the lower to the higher of the two tops beside it.

A staircase recognised over a y window describes the stock only inside that window:
:func:`check_window` tells whether a toolpath's swept y range stays inside it.

A wall's faces, edges and exact curve stay available in :class:`RecognisedWall`.
"""

import multiprocessing
import os
import subprocess
import sys
import tempfile
from dataclasses import dataclass

import numpy as np

from ..engine import Staircase
from ..engine.tolerances import RECOGNITION_TOL as TOL
from ..engine.walls import SplineWall
from ..errors import InputError, note
from .faces import bspline_of_edge, classify_face, critical_points, fold, shape_box
from .freecad_env import DEBIAN_LIB, FreeCAD, Part
from .solids import bspline_curve, parameter_at_y, trimmed_to_y

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

    name chooses one solid when the file holds several: for FCStd the object's Name or Label (its
    shape where the document shows it: :func:`placed_shape`); for STEP and BREP "Solid1",
    "Solid2", … in the file's order. Without it, the file's one solid (or one top-level object
    holding solids); a document already open is used as it is and left open. InputError naming the file when it is missing, unreadable, empty, when
    `name` matches nothing, or when several solids are there and none is chosen: the message
    lists the names and says "choose one with --solid NAME", and when the shape's points are not all
    finite numbers (a STEP point of NAN: every box and recognition of it would fail far from the cause).
    """
    path = os.fspath(path)
    kind = _SUFFIXES.get(os.path.splitext(path)[1].lower())
    if kind is None:
        raise InputError(f"{path}: unknown file type; expected .step, .stp, .brep, .brp or .FCStd")
    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file")
    if kind == "FCStd":
        return _finite(_load_document_solid(path, name), path, kind)
    shape = _read_in_child(path, kind)
    if shape.isNull() or not shape.Faces:
        raise InputError(f"{path}: the {kind} file holds no shape")
    solids = shape.Solids
    names = [f"Solid{k}" for k in range(1, len(solids) + 1)]
    if name is None:
        if len(solids) > 1:
            raise InputError(f"{path}: several solids ({', '.join(names)}); choose one with --solid NAME")
        return _finite(shape, path, kind)
    if not names:
        raise InputError(f"{path}: no solid named {name!r} in the {kind} file (its solids: none)")
    if name not in names:
        listed = ", ".join(names)
        raise InputError(f"{path}: no solid named {name!r} in the {kind} file (its solids: {listed})")
    return _finite(solids[names.index(name)], path, kind)


def _finite(shape, path, kind):
    """`shape` itself when its vertices are finite numbers; InputError naming the file otherwise."""
    points = np.array([tuple(vertex.Point) for vertex in shape.Vertexes], dtype=float).reshape(-1, 3)
    bad = ~np.isfinite(points).all(axis=1)
    if bad.any():
        raise InputError(f"{path}: damaged {kind}: {np.count_nonzero(bad)} of the shape's {len(points)} vertices are "
                         "not finite numbers (NaN or infinite coordinates)")
    return shape


#: Longest a child process may take to read a STEP or BREP file (s) before it is taken as damaged.
READ_TIMEOUT = 300.0


def _read_in_child(path, kind, timeout=READ_TIMEOUT):
    """The Part.Shape in STEP or BREP file `path`, read by a child process.

    A damaged file can make OpenCASCADE end the process that reads or checks it (exit status 1,
    no message: a BREP with one line deleted does so in ``isValid()``) or read forever; the
    child takes that risk: a fresh interpreter (:func:`interpreter`, not multiprocessing, so a
    user's script is never imported again) reads the file, runs the validity check once and
    writes the shape as BREP, read back here (about 0.4 s in all). InputError ``FILE: damaged or
    unreadable STEP (...)`` when the child raises, ends without a shape or takes over `timeout` s.
    """
    with tempfile.TemporaryDirectory(prefix="abm-read-") as folder:
        brep = os.path.join(folder, "shape.brep")
        try:
            done = subprocess.run([interpreter(), "-c", _CHILD_READ, path, brep, DEBIAN_LIB], capture_output=True,
                                  text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            raise InputError(f"{path}: damaged or unreadable {kind} (no shape after {timeout:g} s)") from None
        if done.returncode == 0 and os.path.isfile(brep):
            shape = Part.Shape()
            shape.read(brep)
            return shape
    if done.returncode == _READ_FAILED:
        detail = f"cannot read as {kind}: {done.stderr.strip().splitlines()[-1]}"
    else:
        detail = f"the reader ended with exit status {done.returncode} and no shape"
    raise InputError(f"{path}: damaged or unreadable {kind} ({detail})")


#: Exit status of the reading child when FreeCAD raised (its message is the last line of stderr).
_READ_FAILED = 3
#: The reading child's program: argv = [file, BREP to write, FreeCAD's library folder].
_CHILD_READ = f"""
import sys
sys.path.append(sys.argv[3])
import FreeCAD, Part
try:
    shape = Part.read(sys.argv[1])
    if not shape.isNull():
        shape.isValid()  # the check that can end the process on a damaged file
    shape.exportBrep(sys.argv[2])
except Exception as error:
    print(str(error).splitlines()[0] if str(error) else type(error).__name__, file=sys.stderr)
    sys.exit({_READ_FAILED})
"""


def interpreter():
    """The Python interpreter to start children with: this one, or under the GUI (where
    sys.executable is FreeCAD's own program) the interpreter of the running Python's own
    installation (``<sys.base_exec_prefix>/bin/pythonX.Y``, /usr/bin/python3.11 for Debian's
    FreeCAD), not one found on PATH, which may be another Python without FreeCAD's numpy."""
    if os.path.basename(sys.executable).lower().startswith("python"):
        return sys.executable
    version = f"python{sys.version_info.major}.{sys.version_info.minor}"
    candidate = os.path.join(sys.base_exec_prefix, "bin", version)
    return candidate if os.path.isfile(candidate) else sys.executable


def spawn_context():
    """The multiprocessing spawn context, its children started by :func:`interpreter`."""
    context = multiprocessing.get_context("spawn")
    context.set_executable(interpreter())
    return context


def check_window(y_window, swept, *, source=""):
    """Raise InputError unless the swept y range lies inside the recognised y window.

    A staircase recognised over a y window knows the stock only there; a toolpath whose cutting
    edges reach beyond it would meet no material outside, silently. y_window: (y0, y1) mm, the
    window recognised; swept: (y0, y1) mm, the y range the cutting edges sweep. The message gives
    both ranges. source names the input in messages.
    """
    where = f"{source}: " if source else ""
    w0, w1 = (float(v) for v in y_window)
    s0, s1 = (float(v) for v in swept)
    if s0 < w0 - TOL or s1 > w1 + TOL:
        raise InputError(f"{where}the cutting edges sweep y {s0:.6g} to {s1:.6g} mm, beyond the y window "
                         f"{w0:.6g} to {w1:.6g} mm that the stock was recognised over: widen the window")


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
                detail = ("no object holds a solid" if not chosen
                          else f"several solids ({names}); choose one with --solid NAME")
                raise InputError(f"{path}: {detail}")
        return placed_shape(chosen[0])
    finally:
        if not already:
            FreeCAD.closeDocument(document.Name)


def placed_shape(obj):
    """The shape of a document object where the document shows it (mm): its own placement and those of
    the containers above it (App::Part and other groups with a placement) applied, a link (App::Link)
    taken as the object it shows with the link's placement; ``Part.getShape`` along the object's path
    from its top-level container (an object belongs to one container at most), or of the object
    itself at the top."""
    paths = obj.Parents
    if paths:
        root, path = paths[0]
        return Part.getShape(root, path, needSubElement=False)
    return Part.getShape(obj)


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
    solid = single_solid(shape, where)
    names = {face.hashCode(): f"Face{k}" for k, face in enumerate(shape.Faces, start=1)}
    known = {}
    kinds = {face.hashCode(): classify_face(face, names[face.hashCode()], where, known) for face in solid.Faces}
    limits = shape_box(solid, known)
    window = _window(y_window, limits, where)
    tops, wall_faces = [], []
    for face in solid.Faces:
        role = _face_role(face, kinds[face.hashCode()], limits, where)
        if role == "top":
            tops.append(face)
        elif role == "wall":
            wall_faces.append(face)
    if not tops:
        raise InputError(f"{where}the solid has no top face facing +z")
    y_samples = _sample_ys(window, wall_points)
    found = [_wall(chain, names, kinds, window, y_samples, where) for chain in _chains(wall_faces, tops, names, kinds)]
    # Sections are told apart at an inner sample y, where every wall's x is known.
    found.sort(key=lambda w: w.points[2, 0])
    x_probe = [limits[0]] + [w.points[2, 0] for w in found] + [limits[1]]
    top_faces = _section_tops(tops, names, kinds, x_probe, y_samples[2], limits, where)
    z_top = [kinds[face.hashCode()].z for face in top_faces]
    for j, wall in enumerate(found, start=1):
        _check_wall_heights(wall, j, z_top[j - 1], z_top[j], where)
    curves = tuple(w.curve for w in found) if walls == "exact" else None
    try:
        staircase = Staircase(limits[0], limits[1], window[0], window[1], limits[4], z_top,
                              [w.points for w in found], curves)
    except ValueError as error:
        raise InputError(f"{where}{error}") from None
    return Recognition(staircase, tuple(found), tuple(names[f.hashCode()] for f in top_faces), window, limits)


def single_solid(shape, where):
    """The one closed, valid solid of `shape`; InputError otherwise."""
    solids = shape.Solids
    if not solids:
        for shell in shape.Shells:
            if not shell.isClosed():
                raise InputError(f"{where}not a closed solid: an open shell, {_free_edges(shape)}")
        raise InputError(f"{where}holds no solid (a {shape.ShapeType} of {len(shape.Faces)} faces)")
    if len(solids) > 1:
        raise InputError(f"{where}holds {len(solids)} solids; a stock is one solid")
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
    listed = ", ".join(faces)
    return note(f"{listed} has an edge bordering no other face" if len(faces) == 1 else
                f"{listed} have edges bordering no other face")


def _window(y_window, limits, where):
    """(y0, y1) inside the stock's y range: y_window, or the whole range."""
    y_min, y_max = limits[2], limits[3]
    if y_window is None:
        return (y_min, y_max)
    y0, y1 = (float(v) for v in y_window)
    if not (y_min - TOL <= y0 < y1 <= y_max + TOL):
        raise InputError(
            f"{where}y_window ({y0}, {y1}) must be increasing and inside the stock's y range [{y_min}, {y_max}]"
        )
    return (max(y0, y_min), min(y1, y_max))


def _sample_ys(window, wall_points):
    """(6,) increasing y values (mm) of the wall points over the window."""
    y0, y1 = window
    if wall_points == "even":
        return np.linspace(y0, y1, 6)
    nodes = -np.cos((2 * np.arange(6) + 1) * np.pi / 12)
    return 0.5 * (y0 + y1) + 0.5 * (y1 - y0) * nodes


def _face_role(face, kind, limits, where):
    """'top', 'base', 'side' or 'wall' of a face whose FaceKind is `kind`; InputError for an overhang."""
    if kind.kind == "up":
        return "top"
    if kind.kind == "down":
        if abs(kind.z - limits[4]) > TOL:
            raise InputError(f"{where}{kind.name}: overhang: faces downwards at z = {kind.z:.6g}, above the base "
                             f"(z = {limits[4]:.6g}); a staircase stands on its base")
        return "base"
    x0, x1, y0, y1 = kind.box[:4]
    on_box = (
        (x1 - x0 <= TOL and min(abs(x0 - limits[0]), abs(x1 - limits[1])) <= TOL)
        or (y1 - y0 <= TOL and min(abs(y0 - limits[2]), abs(y1 - limits[3])) <= TOL)
    )
    return "side" if on_box else "wall"


def _chains(wall_faces, tops, names, kinds):
    """Wall faces grouped into walls: lists of (face, top edge), the top edges joining end to end.

    Wall faces that share an edge belong to one wall: faces side by side along the wall, and
    faces stacked in z. A wall's top edges are the edges it shares with a top face at the
    wall's highest z. A group without one (no top face above it) is returned with an empty
    list of top edges, and refused by _wall.
    """
    top_edges = {edge.hashCode() for face in tops for edge in face.Edges}
    group = list(range(len(wall_faces)))

    def root(i):
        while group[i] != i:
            group[i] = group[group[i]]
            i = group[i]
        return i

    owner = {}
    for i, face in enumerate(wall_faces):
        for edge in face.Edges:
            k = owner.setdefault(edge.hashCode(), i)
            group[root(i)] = root(k)
    members = {}
    for i, face in enumerate(wall_faces):
        members.setdefault(root(i), []).append(face)
    chains = []
    for faces in members.values():
        z_top = max(kinds[face.hashCode()].box[5] for face in faces)
        chain = [(face, None) for face in faces]
        chain += [
            (face, edge) for face in faces for edge in face.Edges
            if edge.hashCode() in top_edges and np.abs(_edge_z(edge) - z_top).max() <= TOL
        ]
        chains.append(chain)
    return chains


def _edge_z(edge):
    """(k,) z of an edge's vertices (mm)."""
    return np.array([vertex.Point.z for vertex in edge.Vertexes])


def _wall(chain, names, kinds, window, y_samples, where):
    """RecognisedWall of a chain of (face, top edge or None); InputError unless its top edge has one x
    per y across the window (decided exactly: :func:`.faces.critical_points`)."""
    faces = sorted({names[face.hashCode()] for face, _ in chain}, key=lambda n: int(n[4:]))
    label = ", ".join(faces)
    edges = [edge for _, edge in chain if edge is not None]
    if not edges:
        raise InputError(f"{where}{label}: wall has no top edge along a top face")
    y0, y1 = window
    spans = []
    for edge in edges:
        points = critical_points(edge, 1)
        back, at = fold(points, 1)
        x_values = critical_points(edge, 0)[:, 0]
        if np.ptp(points[:, 1]) <= TOL and np.ptp(x_values) > TOL:
            raise InputError(f"{where}{label}: wall has more than one x for y = {points[0, 1]:.6g} (its top edge runs "
                             f"along x there, from x = {x_values.min():.6g} to {x_values.max():.6g}); {_ALONG_X}")
        if back > TOL:
            raise InputError(f"{where}{label}: wall has more than one x for y = {at[1]:.6g} (its top edge turns back "
                             f"by {back:.3g} mm in y near x = {at[0]:.6g}); {_ALONG_X}")
        spans.append((points[:, 1].min(), points[:, 1].max(), edge))
    spans.sort(key=lambda span: span[0])
    for (_, high, _), (low, _, _) in zip(spans[:-1], spans[1:]):
        if low < high - TOL:
            raise InputError(f"{where}{label}: wall has more than one x for y = {0.5 * (low + high):.6g} (two of its "
                             f"top edges overlap in y from {low:.6g} to {high:.6g}); {_ALONG_X}")
        if low > high + TOL:
            raise InputError(f"{where}{label}: wall does not run across the y window [{y0:.6g}, {y1:.6g}]: no x at "
                             f"y = {0.5 * (low + high):.6g} (its top edges leave a gap from {high:.6g} to {low:.6g})")
    y_low, y_high = spans[0][0], spans[-1][1]
    if y_low > y0 + TOL or y_high < y1 - TOL:
        y = y0 if y_low > y0 + TOL else y1
        raise InputError(f"{where}{label}: wall does not run across the y window [{y0:.6g}, {y1:.6g}]: no x at "
                         f"y = {y:.6g} (its top edge spans y {y_low:.6g} to {y_high:.6g}); {_ALONG_X}")
    edges = [edge for _, _, edge in spans]
    points = np.column_stack([[_x_at(edges, y) for y in y_samples], y_samples])
    x_all = np.concatenate([critical_points(edge, 0)[:, 0] for edge in edges])
    straight = all(isinstance(e.Curve, Part.Line) for e in edges) and np.ptp(x_all) <= TOL
    if straight:
        points[:, 0] = points[:, 0].mean()
    try:
        curve = _exact_curve(edges, window, points[0, 0] if straight else None)
    except ValueError as error:
        raise InputError(f"{where}{label}: {error}") from None
    z_low = min(kinds[face.hashCode()].box[4] for face, _ in chain)
    z_high = max(kinds[face.hashCode()].box[5] for face, _ in chain)
    return RecognisedWall(tuple(faces), tuple(edges), (float(y_low), float(y_high)), (z_low, z_high), points,
                          straight, curve)


#: What a staircase's walls must be, added to refusals of its walls.
_ALONG_X = note("a staircase's walls run across y with one x for each y")


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
    """The edge's curve over its own parameter range as a Part.BSplineCurve running towards +y (exact:
    :func:`.faces.bspline_of_edge`)."""
    curve = bspline_of_edge(edge)
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


def _x_at(edges, y):
    """x (mm) of a wall's top edge at y: edges (each monotone in y, in order along y), safeguarded Newton on
    the parameter of the edge whose y range holds y; beyond the chain's ends by at most TOL, the nearest end's x.
    """
    for edge in edges:
        u0, u1 = edge.ParameterRange
        y_a, y_b = edge.valueAt(u0).y, edge.valueAt(u1).y
        if min(y_a, y_b) <= y <= max(y_a, y_b):
            return edge.valueAt(parameter_at_y(edge.Curve, y, u0, u1)).x
    ends = [(abs(edge.valueAt(u).y - y), edge.valueAt(u).x) for edge in edges for u in edge.ParameterRange]
    return min(ends)[1]


def _section_tops(tops, names, kinds, x_probe, y_probe, limits, where):
    """(n,) the top face of each section; at y = y_probe, section j lies between x_probe[j] and x_probe[j+1]."""
    n = len(x_probe) - 1
    found = [[] for _ in range(n)]
    for face in tops:
        z = kinds[face.hashCode()].z
        probe = Part.LineSegment(FreeCAD.Vector(limits[0] - 1, y_probe, z), FreeCAD.Vector(limits[1] + 1, y_probe, z))
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
    if abs(wall.z_range[0] - low) > TOL or abs(wall.z_range[1] - high) > TOL:
        raise InputError(
            f"{where}{', '.join(wall.faces)}: wall between sections {j - 1} and {j} spans z "
            f"{wall.z_range[0]:.6g} to {wall.z_range[1]:.6g}, but the tops beside it are at {low:.6g} and {high:.6g}"
        )
