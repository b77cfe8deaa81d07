"""A job's inputs from whichever files hold them: stock, toolpath, cutting parameters.

- :func:`load_stock`: a staircase JSON (``.json``), or a solid (``.step``, ``.stp``,
  ``.brep``, ``.brp``, ``.FCStd``) recognised as a staircase. FreeCAD is imported only for
  solids, so JSON jobs never need it. :func:`solid_in_part` reads a solid and the engine frame
  its own 2.5D direction asks for; :func:`path_in_frame` takes the toolpath into that frame.
- :func:`load_path`: a toolpath CSV, an APT / CL file, G-code or a FreeCAD CAM Job (read by
  content), with what the file says about the tool, spindle and feed (:class:`PathHints`).
- :func:`load_job`: a job JSON of default parameters, each checked by its declaration.

The y window of a recognised solid is the stock's whole y range by default: the staircase
then describes every point of the solid, so the engine and the boolean reference see the same
stock wherever the edge goes. :func:`swept_y_window` gives the narrower window the paper fits
its six wall points over (the y range the cutting edges sweep in the pass); it only changes
quintic walls (``walls="quintic"``), whose fit it tightens.

Lengths in mm, angles in degrees, spindle speed in rpm. Bad input raises
:class:`~abm_workbench.errors.InputError` naming the file.
"""

import dataclasses
import os
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from ..engine import Staircase, TerracedStock, Tool, Toolpath
from ..errors import InputError
from ..formats import check_keys, load_json_object
from ..formats.staircase_json import load_staircase
from ..formats.terraced_json import FORMAT as TERRACED_FORMAT
from ..formats.terraced_json import load_terraced
from .parameters import BY_NAME

SOLID_SUFFIXES = (".step", ".stp", ".brep", ".brp", ".fcstd")
WALL_MODELS = ("exact", "quintic")
WALL_POINTS = ("chebyshev", "even")
#: Extra width (mm) on each side of the swept y window.
SWEPT_MARGIN = 1.0
@dataclass(frozen=True)
class Stock:
    """A loaded stock, in the frame the engine works in.

    staircase: the Staircase the engine works on (the paper's model, its fast engine), or None
    for a general 2.5D stock, then held by `terraced` (a TerracedStock; None for a staircase).
    source: the file. shape: the Part.Shape read from a solid file (moved into the engine frame),
    or None for a JSON stock. walls: "quintic" (JSON, or a solid recognised with the paper's
    quintics) or "exact" (a solid's own wall curves). frame: (R, t) from part coordinates to the
    engine frame the stock was moved into, or None. reason: why a solid is not a staircase
    (for a terraced stock recognised from one).
    """

    staircase: Optional[Staircase]
    source: str
    shape: object = None
    walls: str = "quintic"
    frame: Optional[tuple] = None
    terraced: Optional[TerracedStock] = None
    reason: str = ""

    @property
    def model(self):
        """What the engine works on: the Staircase, or the TerracedStock."""
        return self.staircase if self.staircase is not None else self.terraced

    @property
    def kind(self):
        """"staircase" or "terraced"."""
        return "staircase" if self.staircase is not None else "terraced"

    @property
    def y_window(self):
        """(y_min, y_max) of the staircase (mm); None for a terraced stock (it has no y window)."""
        return None if self.staircase is None else (self.staircase.y_min, self.staircase.y_max)

    def describe(self):
        """The stock's model in words: 'exact walls, y window -15..15 mm' or '2.5D terraced stock, 4 slabs'."""
        if self.staircase is None:
            return f"2.5D terraced stock, {len(self.terraced.slabs)} slabs"
        y0, y1 = self.y_window
        return f"{self.walls} walls, y window {y0:.6g}..{y1:.6g} mm"

    def solid(self):
        """The stock as a Part.Shape: the solid read, or for JSON the model built as a solid."""
        if self.shape is not None:
            return self.shape
        if self.staircase is None:
            from ..cad.terraced_solids import terraced_solid
            return terraced_solid(self.terraced)
        from ..cad.solids import staircase_solid
        return staircase_solid(self.staircase)


@dataclass(frozen=True)
class PathHints:
    """What a toolpath file says besides the CL points of the chosen operation.

    diameter, flute_length, corner_radius: mm, or None where the file does not give them. flutes: the
    number of flutes where the file gives it (a FreeCAD toolbit's), else None. spindle_rpm: rpm.
    feed: (m,) feed at each CL point in feed_unit ("MMPM" or "MMPR"; NaN before the first
    FEDRAT), or None. records: {parameter name: the record that gave it} where it differs from
    the parameter's declared record. unknown: (major word, first line, count) of records not
    understood; ignored: the same of records known to carry nothing the engine needs.
    warnings: messages ``file:line: ...``. source: the file. program, operation: the
    formats.cl Program and its chosen Operation (None for hints made by hand). frame: (R (3, 3),
    t (3,)) from part coordinates to the operation's engine frame, or None (the same frame).
    """

    source: str
    diameter: Optional[float] = None
    flute_length: Optional[float] = None
    spindle_rpm: Optional[float] = None
    feed: Optional[np.ndarray] = None
    feed_unit: Optional[str] = None
    unknown: tuple = ()
    warnings: tuple = ()
    records: dict = field(default_factory=dict)
    ignored: tuple = ()
    program: object = field(default=None, repr=False, compare=False)
    operation: object = field(default=None, repr=False, compare=False)
    frame: Optional[tuple] = field(default=None, repr=False, compare=False)
    flutes: Optional[int] = None
    corner_radius: Optional[float] = None

    def messages(self):
        """Every warning, each record kind not understood, and the records ignored (one line), as text
        for warnings."""
        warnings = list(self.warnings)
        for word, line, count in self.unknown:
            warnings.append(f"{self.source}:{line}: {word}: record not understood, ignored ({count} times)" if count > 1
                            else f"{self.source}:{line}: {word}: record not understood, ignored")
        if self.ignored:
            records = ", ".join(f"{word} ({count})" for word, _, count in self.ignored)
            warnings.append(f"{self.source}: records that carry nothing the engine needs, ignored: {records}")
        return warnings


def load_stock(path, *, walls="exact", wall_points="chebyshev", y_window=None, frame=None, solid=None, shape=None):
    """The stock in `path` as a :class:`Stock`, in the frame the engine works in.

    A ``.json`` file is read as an abm-staircase/1 staircase (its walls are the paper's
    quintics) or an abm-terraced/1 terraced stock; walls, wall_points and y_window do not apply.
    A solid is recognised as a staircase (:func:`abm_workbench.cad.recognise.recognise`), else
    as a general 2.5D terraced stock (``cad.terraced_recognise``): walls "exact" keeps the solid's
    own wall curves, "quintic" fits the paper's quintic through six points per wall placed by
    wall_points ("chebyshev" or "even") over y_window ((y0, y1) mm, cut to the stock's y range;
    None: the whole range; or a function of the solid's highest z giving (y0, y1), as
    :func:`swept_y_window` does). frame: (R (3, 3), t (3,)) from part coordinates to the
    operation's engine frame (PathHints.frame), or None: the stock is moved there first (a JSON
    staircase only by a translation). A solid refused there because its own 2.5D direction is not
    that frame's z says so (:func:`solid_in_part` gives the frame it is). solid: the name of the
    solid in a file that holds several (``cad.recognise.load_solid``). shape: that solid already
    read, in part coordinates, or None. InputError naming the file for anything else.
    """
    name = os.fspath(path)
    suffix = os.path.splitext(name)[1].lower()
    if walls not in WALL_MODELS:
        raise ValueError(f"walls must be one of {WALL_MODELS}, got {walls!r}")
    if wall_points not in WALL_POINTS:
        raise ValueError(f"wall_points must be one of {WALL_POINTS}, got {wall_points!r}")
    if suffix == ".json":
        return _json_stock(name, frame)
    if suffix not in SOLID_SUFFIXES:
        raise InputError(f"{name}: unknown stock file type; expected .json, .step, .stp, .brep, .brp or .FCStd")
    from ..cad.recognise import load_solid  # FreeCAD only for solids
    from ..cad.solids import moved
    part = load_solid(name, solid) if shape is None else shape
    shape = part if frame is None else moved(part, *frame)
    if callable(y_window):
        y_window = y_window(shape.BoundBox.ZMax)
    if y_window is not None:
        box = shape.BoundBox
        low, high = max(float(y_window[0]), box.YMin), min(float(y_window[1]), box.YMax)
        if not low < high:
            raise InputError(f"{name}: y window {y_window[0]:g}..{y_window[1]:g} mm misses the stock's y range "
                             f"{box.YMin:g}..{box.YMax:g} mm")
        y_window = (low, high)
    try:
        return recognised(shape, name, walls=walls, wall_points=wall_points, y_window=y_window, frame=frame)
    except InputError:
        _refuse_turned(part, frame, name)
        raise


def _refuse_turned(part, frame, name):
    """InputError in words when the solid `part` (part coordinates) is 2.5D along another direction than
    the z of the engine frame `frame` (cad.stock_frame): a stock refused in `frame` for that reason."""
    from ..cad.stock_frame import stock_frame
    turned = stock_frame(part, frame)
    if turned is not frame:
        up = (np.eye(3) if frame is None else frame[0])[2]
        angle = np.degrees(np.arccos(np.clip(turned[0][2] @ up, -1.0, 1.0)))
        raise InputError(f"{name}: the stock is 2.5D along ({_vector_words(turned[0][2])}) in the part, {angle:.3g}° "
                         "from the z of the operation's frame: the operation must be computed in its frame turned "
                         "to the stock (abm engage, validate and schedule do)") from None


def recognised(shape, name, *, walls="exact", wall_points="chebyshev", y_window=None, frame=None):
    """The Stock of a solid `shape` (already in the engine frame `frame`) named `name` in messages:
    a staircase when it is one, else a general 2.5D terraced stock, the staircase's refusal kept as
    its reason (cad.terraced_recognise.recognise_any). InputError naming the face when the solid
    is not 2.5D at all."""
    from ..cad.terraced_recognise import recognise_any
    found = recognise_any(shape, walls=walls, wall_points=wall_points, y_window=y_window, source=name)
    if found.staircase is None:
        return Stock(None, name, shape, walls, frame, found.terraced, found.reason)
    return Stock(found.staircase.staircase, name, shape, walls, frame)


def solid_in_part(path, solid=None, frame=None):
    """(Part.Shape, engine frame) of a stock solid file: the solid in part coordinates
    (``cad.recognise.load_solid``; solid: its name in a file holding several) and the frame (R, t),
    part -> engine, it is computed in: `frame` (the operation's, PathHints.frame; None: the part's)
    when the stock is 2.5D along its z, else `frame` turned the least to the stock's own 2.5D
    direction (``cad.stock_frame.stock_frame``; `frame` itself when kept)."""
    from ..cad.recognise import load_solid
    from ..cad.stock_frame import stock_frame
    shape = load_solid(os.fspath(path), solid)
    return shape, stock_frame(shape, frame)


def path_in_frame(toolpath, hints, frame):
    """(Toolpath, PathHints) of the operation of `hints` in the engine frame `frame` ((R, t), part ->
    engine, or None), as load_path gives them in the operation's own: the same when `frame` is
    hints.frame, else its CL points, tool axes and feed directions taken into `frame` (each CL point's
    frame turned to its feed there, engine.feed) and hints.frame set to it. Tool axes may point any way
    in `frame` (sideways, down): the engine takes every direction."""
    if frame is hints.frame:
        return toolpath, hints
    turned = (np.eye(3), np.zeros(3)) if frame is None else frame
    return hints.operation.toolpath(turned), dataclasses.replace(hints, frame=frame)


def _vector_words(vector):
    """'0, -0.984808, 0.173648': a unit vector's components to 6 digits, rounding's dust (1e-12) dropped."""
    return ", ".join(f"{v:.6g}" for v in np.round(vector, 12) + 0.0)


def _json_stock(name, frame):
    """The Stock of a staircase (abm-staircase/1) or terraced (abm-terraced/1) JSON file, moved by a
    translation into `frame`'s engine frame (InputError when the frame turns)."""
    kind = load_json_object(name).get("format")
    if frame is not None and not np.allclose(frame[0], np.eye(3), rtol=0.0, atol=1e-12):
        raise InputError(f"{name}: the operation's frame is turned against the part's, and a stock JSON can only "
                         "be moved, not turned: give the stock as a solid (STEP, BREP, FCStd)")
    if kind == TERRACED_FORMAT:
        terraced = load_terraced(name)
        if frame is not None:
            terraced = terraced.translated(frame[1])
        return Stock(None, name, terraced=terraced, frame=frame)
    staircase = load_staircase(name)
    if frame is not None:
        staircase = staircase.translated(frame[1])
    return Stock(staircase, name, frame=frame)


def load_path(path, operation=None, *, tolerance=None, step=None, options=None, program=None):
    """(Toolpath, PathHints) of operation `operation` (1-based; None: the file's one milling operation)
    of a toolpath file of any name, read by its content (formats.cl: APT / CL text, the toolpath CSV,
    G-code or a FreeCAD CAM Job, with `options`, a formats.gcode.options.ReadOptions or None; arcs and
    curves to `tolerance` mm, their CL points at most `step` mm apart, None: the defaults), or of
    `program` (a Program already read, named `path`). The Toolpath is in the operation's engine frame
    (PathHints.frame). InputError naming the file for an operation the engine cannot run
    (formats.cl.OperationChoiceError when the file has several and none is chosen)."""
    from ..formats.cl import STEP, TOLERANCE, read_program

    name = os.fspath(path)
    if program is None:
        program = read_program(name, TOLERANCE if tolerance is None else tolerance, STEP if step is None else step,
                               options)
    chosen = program.operation(operation)
    refusal = chosen.refusal()
    if refusal is not None:
        raise InputError(f"{name}: {refusal}")
    toolpath = chosen.toolpath()
    rotation, translation = frame = chosen.engine_frame()
    tool = chosen.tool
    records = {}
    if program.format == "csv":
        records = {"diameter": "diameter column", "corner_radius": "corner_radius column"}
    elif program.format in ("gcode", "fcstd"):
        records = {"spindle_rpm": "S word", "feed_per_tooth": "F words",
                   **{key: tool.records[0] for key in ("diameter", "corner_radius", "flute_length", "flutes")
                      if tool.records}}
    else:
        sizes = next((record.split()[0] for record in tool.records if record.split()[0] in ("CUTTER", "TLDATA")), None)
        if sizes is not None and sizes != "CUTTER":
            records = {"diameter": sizes, "corner_radius": sizes}
        if tool.flute_length is not None and any(record.startswith("CSI_SET_FLUTE_LENGTH") for record in tool.records):
            records["flute_length"] = "CSI_SET_FLUTE_LENGTH"
    same = np.array_equal(rotation, np.eye(3)) and not np.any(translation)
    hints = PathHints(name, tool.diameter, tool.flute_length, chosen.spindle_rpm, chosen.feed, chosen.feed_unit,
                      tuple((word, line, count) for word, (line, count) in program.unknown.items()),
                      tuple(program.warnings), records,
                      tuple((word, line, count) for word, (line, count) in program.ignored.items()),
                      program, chosen, None if same else frame, tool.flutes, tool.corner_radius)
    return toolpath, hints


def swept_y_window(toolpath: Toolpath, tool: Tool, z_max=np.inf, margin=SWEPT_MARGIN):
    """(y0, y1) mm: the y range the cutting edges sweep below z_max over the pass, widened by `margin`.

    An edge point's y is y_T + R_t (sin φ sA sB + cos φ cA) − l sA cB (notes §2): over φ the
    middle term reaches ±R_t·hypot(sA sB, cA), and l runs over 0..L, or only as far as an
    edge can still be below z_max (the stock's top): z = z_T + R_t (−sin φ cA sB + cos φ sA)
    + l cA cB, whose lowest start is z_T − R_t·hypot(cA sB, sA).
    """
    rotation = toolpath.frames()  # (m, 3, 3)
    radial = tool.radius * np.hypot(rotation[:, 1, 0], rotation[:, 1, 1])
    lowest = toolpath.cl[:, 2] - tool.radius * np.hypot(rotation[:, 2, 0], rotation[:, 2, 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        reach = np.where(rotation[:, 2, 2] > 0.0, np.clip((z_max - lowest) / rotation[:, 2, 2], 0.0, tool.flute_length),
                         tool.flute_length)  # an axis level or pointing down: the whole flute
    along = reach * rotation[:, 1, 2]
    y = toolpath.cl[:, 1]
    low = y - radial + np.minimum(along, 0.0)
    high = y + radial + np.maximum(along, 0.0)
    return float(low.min() - margin), float(high.max() + margin)


#: Job-file keys holding a [start, end] pair -> the parameters they give.
PAIRS = {"phi_range": ("phi_start", "phi_end"), "immersion": ("immersion_start", "immersion_end")}
#: Job-file keys: every parameter (pairs as one key), the material and a description.
JOB_KEYS = tuple(name for name in BY_NAME if not any(name in pair for pair in PAIRS.values())) + (
    *PAIRS, "material", "description")


def load_job(path):
    """Parameters of a job JSON file: {parameter name: checked value, "material": name,
    "description": text}; a pair such as "phi_range": [0, 180] gives its two parameters.
    ParameterError naming the file for a bad value, InputError for a bad key or file."""
    name = os.fspath(path)
    data = load_json_object(name)
    check_keys(data, (), JOB_KEYS, name)
    job = {}
    for key, value in data.items():
        if key in ("description", "material"):
            if not isinstance(value, str):
                raise InputError(f"{name}: {key}: must be a string")
            job[key] = value
        elif key in PAIRS:
            if not isinstance(value, list) or len(value) != 2:
                raise InputError(f"{name}: {key}: must be [start, end] in degrees, e.g. [0, 180]")
            for pair_name, item in zip(PAIRS[key], value):
                job[pair_name] = BY_NAME[pair_name].check(item, name)
        else:
            job[key] = BY_NAME[key].check(value, name)
    return job


def _swept_corner(operation, chosen, tool, radius):
    """The corner radius (mm) an operation's tool is swept with in the in-process stock: the chosen
    operation's resolved `tool`'s; a ball or bull-nose mill's from the file (a ball's radius where it gives
    none), at most `radius`; 0 for a flat-end mill or a tool of unknown kind; None for any other kind (swept
    as a flat-end cylinder, which the notes say)."""
    if operation is chosen:
        return min(tool.corner_radius, radius)
    spec = operation.tool
    if spec.kind in ("flat", "unknown"):
        return 0.0
    if spec.kind == "ball":
        return radius if spec.corner_radius is None else min(spec.corner_radius, radius)
    if spec.kind == "bull-nose" and spec.corner_radius is not None:
        return min(spec.corner_radius, radius)
    return None


def program_moves(program, chosen, tool):
    """(ProgramMoves of every CL point of `program` in program order, in part coordinates; (m,) the rows
    of the cutting CL points of operation `chosen`; notes: what the in-process stock leaves out or
    takes otherwise, one sentence per operation, naming it and how much).

    Each operation's cutting moves and rapids are merged by their source line (a rapid removes
    nothing; nor does the move into an operation's first CL point, which follows a tool change or
    a retract). An operation's tool is its own (diameter, flute length) where the file gives it,
    else `tool`'s (the resolved Tool of the job) for the chosen operation. Another operation whose
    file gives a diameter but no flute length removes material with its whole length: the tool's
    length where the file gives it, else the extent of the program (the diagonal of the box of all
    its moves, which reaches through any stock the program comes near); one with no diameter, a
    turning operation and canned-cycle hole positions are not swept; the notes say so. A ball or
    bull-nose mill is swept with its corner radius (the chosen operation's: `tool`'s), every other tool
    as a flat-end cylinder of its diameter and that length (a tapered mill, a saw or a drill among
    them, the notes say so).
    """
    from ..engine.inprocess import ProgramMoves

    everything = [op.points_part for op in program.operations] + [
        op.rapids.points @ op.to_part[0].T + op.to_part[1] for op in program.operations if len(op.rapids)]
    corners = np.concatenate(everything) if everything else np.zeros((1, 3))
    reach = float(np.linalg.norm(corners.max(axis=0) - corners.min(axis=0)))
    parts, rows, start, notes = [], None, 0, []
    for operation in program.operations:
        what = f"{operation.label()} ({operation.tool.describe()})"
        holes = len(operation.cycle_points) if operation.cycle_points is not None else 0
        if holes and operation is not chosen:
            notes.append(f"{what}: its {holes} canned-cycle holes are not in the in-process stock (holes are not "
                         "swept)")
        if operation.tool.kind in ("turning", "grooving") or not len(operation.lines):
            continue
        diameter = operation.tool.diameter or (tool.diameter if operation is chosen else None)
        length = operation.tool.flute_length or (tool.flute_length if operation is chosen else None)
        if diameter is None:
            notes.append(f"{what}: the file gives no diameter, so its {len(operation.lines)} cutting moves are not in "
                         "the in-process stock")
            continue
        if length is None:
            length = operation.tool.length or max(reach, diameter)
            whence = "the tool's length in the file" if operation.tool.length else "the program's extent"
            notes.append(f"{what}: the file gives no flute length: in the in-process stock it removes material with "
                         f"its whole length, {length:.4g} mm ({whence})")
        corner = _swept_corner(operation, chosen, tool, 0.5 * diameter)
        if corner is None:
            corner = 0.0
            notes.append(f"{what}: swept as a flat-end cylinder of its diameter in the in-process stock")
        rotation, translation = operation.to_part
        rapids = operation.rapids
        points = np.concatenate([operation.points_file, rapids.points]) @ rotation.T + translation
        axes = np.concatenate([operation.axes_file, rapids.axes]) @ rotation.T
        lines = np.concatenate([operation.lines, rapids.lines])
        order = np.argsort(lines, kind="stable")
        cut = (np.arange(lines.size) < operation.lines.size)[order]  # the operation's cutting CL points
        cutting = cut.copy()
        cutting[0] = False
        parts.append((points[order], axes[order], cutting, np.full(lines.size, 0.5 * diameter),
                      np.full(lines.size, length), lines[order], np.full(lines.size, corner)))
        if operation is chosen:
            rows = start + np.flatnonzero(cut)
        start += lines.size
    columns = [np.concatenate(column) for column in zip(*parts)]
    try:
        return ProgramMoves(*columns), rows, notes
    except ValueError as error:  # a cutting move the sweep cannot take (its axis turned right round)
        raise InputError(f"{program.source}: the in-process stock cannot sweep the program: {error}; the stock "
                         "model initial (the stock as given) can") from None
