"""The modal state machine: CL records, in file order, into the operations of a :class:`Program`.

Motion: ``GOTO/x,y,z`` keeps the tool axis in force (``TLAXIS``, or the last six-number GOTO);
``GOTO/x,y,z,i,j,k`` is always position and axis (``MULTAX`` is accepted, never needed);
``GODLTA/dx,dy,dz`` or ``GODLTA/d`` (along the axis) moves relative to the last position;
``FROM`` sets the position. A GOTO after ``RAPID`` is a rapid move, one inside a canned cycle
(``CYCLE/...`` up to ``CYCLE/OFF``) a hole position; both are kept apart from cutting moves.
``CIRCLE`` makes the next GOTO an arc (:mod:`.arcs`), ``NURBS/`` with its ``KNOT``/``CNTRL``
records a B-spline (:mod:`.nurbs`). Each cutting CL point keeps the direction of the tool's motion
arriving at it (the chord of a straight move, the tangent of an arc or curve), from which the
engine turns its frame to the feed (engine.feed).

Frames: ``MSYS`` and ``CSYS`` give the frame the following records are written in; after
SOLIDWORKS CAM's ``TRNTYP/WORLD`` the GOTOs are already in the world (part) frame, and a ``CSYS``
only names the setup (its Z, the third column, is the tool axis of the moves that give none).
``ROTABL`` turns the indexed table about A, B or C; turns about several axes compose, C the
innermost (the table that carries the part); CAMWorks writes the angles in radians.

Records the engine does not need (spindle, coolant, a tool description it cannot read ...) never
stop the reading: a record of them that cannot be read is skipped with a warning naming its line.

Operations: a new one starts at ``TOOL PATH`` (NX, with the operation's name), ``TRNTYP/WORLD`` (SOLIDWORKS CAM), ``LOADTL`` /
``LOAD/TOOL``, a CATIA ``$$ OPERATION NAME : ...`` comment (or ``PPRINT``), a Creo
``$$-> FEATNO / n`` comment, a tool record describing another tool, and a frame record
(``MSYS``, ``CSYS``, ``ROTABL``) that changes the frame -- each only once the operation so far
has moved; before that they describe the operation being started. Tool, spindle, feed, axis,
units and frame carry over from one operation to the next.
"""

import math
import re

import numpy as np

from ...errors import InputError
from .. import MAX_ANGLE, MAX_MAGNITUDE, NUMBER
from . import units as unit_words
from .arcs import arc_points
from .frames import IDENTITY, compose, csys_frame, msys_frame, table_frame
from .lexer import lex
from .nurbs import bspline_points, resolve
from .program import Moves, Operation, Program
from .tools import KIND_WORDS, ToolSpec, kind_of_name, mill

_NUMBER_TEXT = re.compile(NUMBER)
#: A record whose text after '/' holds only these characters is read by float() at once.
_NUMBER_CHARACTERS = "0123456789+-.eE ,\t"
_WORD = re.compile(r"[A-Za-z][A-Za-z0-9_-]*")
_CREO = re.compile(r"->\s*([A-Za-z_]+)\s*/?\s*(.*)")
_OPERATION_NAME = re.compile(r"OPERATION\s+NAME\s*:\s*(.+)", re.IGNORECASE)
_NURBS_PART = re.compile(r"(KNOT|CNTRL)\s*/", re.IGNORECASE)
#: A number with a word glued to it (SPINDL/900CCLW).
_GLUED = re.compile(f"({NUMBER})([A-Za-z]+)")
#: Records the engine needs (motion, frames, units): one that cannot be read stops the reading.
NEEDED = frozenset({"GOTO", "GODLTA", "FROM", "CIRCLE", "NURBS", "KNOT", "CNTRL", "TLAXIS", "MSYS", "CSYS", "ROTABL",
                    "TRNTYP", "UNITS", "UNIT", "CYCLE", "RAPID"})
#: Directions of a CIRCLE given by a word after its radius (CAMWorks, SOLIDWORKS CAM CLT), seen from its axis.
_CIRCLE_SENSE = {"COUNTERCLOCKWISE": 1.0, "CCLW": 1.0, "CCW": 1.0, "CLOCKWISE": -1.0, "CLW": -1.0, "CW": -1.0}

#: Records known to carry nothing the engine needs: counted in Program.ignored, never warned.
IGNORED = frozenset({
    "PPRINT", "TPRINT", "DPRINT", "PARTNO", "INSERT", "PAINT", "OPFEATSTART", "OPFEATEND", "BOX", "END-OF-PATH",
    "MACHIN", "COOLNT", "STOP", "OPSTOP", "END", "FINI", "INTOL", "OUTTOL", "TOLER", "CUTCOM", "SELECT", "CLRSRF",
    "SEQNO", "DISPLY", "AUTOPS", "GOHOME", "DELAY", "PREFUN", "AUXFUN", "CLAMP", "HEAD", "MODE", "ORIGIN",
    "TLON", "TLONPS", "TLOFPS", "PLABEL", "OPERATION", "AIR", "LINTOL", "CATIA0", "RETRCT", "THRU",
    "MCS", "PITCH", "CHECK", "OPNAME", "TRANS", "PIVOTZ", "UNLOAD", "WCS", "FIXTURE", "LEADER", "SET", "ROTATE",
    "SETUP", "ZERO", "OFSTNO", "MOVNRB",
})


def read_cl_text(text, name, tolerance, step=math.inf):
    """The :class:`Program` of APT / CL `text` read from file `name`; arcs and curves to `tolerance` mm,
    their CL points at most `step` mm apart. InputError ``file:line: WORD: ...`` for a record the
    engine needs that cannot be read."""
    records, comments, last_line = lex(text, name)
    reader = _Reader(name, tolerance, step, _rotabl_in_radians(records, comments))
    events = [(line, 0, comment) for line, comment in comments]
    events += [(record.line, 1, record) for record in records]
    events.sort(key=lambda event: (event[0], event[1]))
    for line, kind, item in events:
        if kind:
            reader.record(item)
        else:
            reader.comment(line, item)
    return reader.program(text, last_line)


def _rotabl_in_radians(records, comments):
    """Whether the file's ROTABL angles are radians: CAMWorks (and SOLIDWORKS CAM, its sibling: a
    ``CSI_`` or ``TRNTYP`` record, or a comment naming it) writes them so. Only when every angle is
    within ±2π and one is not a whole number (a file in degrees indexes by whole degrees)."""
    family = any(record.word.startswith("CSI_") or record.word == "TRNTYP" for record in records) or any(
        "CAMWORKS" in comment.upper() or "SOLIDWORKS CAM" in comment.upper() for _, comment in comments)
    angles = []
    for record in records:
        if record.word == "ROTABL":
            angles += [float(arg) for arg in record.args[:1] if _NUMBER_TEXT.fullmatch(arg)]
    return (family and bool(angles) and all(abs(a) <= 2.0 * math.pi + 1e-6 for a in angles)
            and any(a != round(a) for a in angles))


class _Operation:
    """The operation being read: what it has collected so far (lists, file frame, mm)."""

    def __init__(self, state, line):
        """A new operation starting on `line`, inheriting tool, spindle and frame from `state`."""
        self.name = ""
        self.tool = state.tool
        self.spindle = state.spindle
        self.frame, self.frame_words = state.frame(), state.frame_words()
        self.setup = state.setup
        self.first_line = line
        self.points, self.axes, self.lines, self.feeds, self.kinds, self.directions = [], [], [], [], [], []
        self.rapids, self.rapid_axes, self.rapid_lines = [], [], []
        self.holes, self.hole_axes, self.hole_lines = [], [], []
        self.arcs = self.curves = 0
        self.cycles = []

    @property
    def moved(self):
        """Whether the operation has any motion yet."""
        return bool(self.lines or self.rapid_lines or self.hole_lines)


class _Reader:
    """Modal state and the operations read, fed one record (or comment) at a time."""

    def __init__(self, name, tolerance, step, radians):
        """Start state: mm, axis (0, 0, 1), no tool, no feed, part frame, one empty operation; ROTABL
        angles in radians when `radians`."""
        self.name, self.tolerance, self.step, self.radians = name, float(tolerance), float(step), radians
        self.scale, self.units = 1.0, None
        self.axis = (0.0, 0.0, 1.0)
        self.position = None
        self.rapid = False
        self.circle = None
        self.nurbs = None
        self.cycle = None
        self.feed, self.feed_kind = math.nan, None
        self.spindle = None
        self.tool = ToolSpec()
        self.kind_word = None
        self.tool_name = None  # (name, line) of a tool name waiting for the tool record it introduces
        self.base, self.base_words = IDENTITY, ""
        self.table_angles, self.table_words = {}, ""
        self.world = None  # the line of TRNTYP/WORLD: the GOTOs are in the world frame, CSYS names setups
        self.setup, self.setup_words = None, ""
        self.done = []
        self.ignored, self.unknown, self.warnings = {}, {}, []
        self.warned = set()
        self.op = _Operation(self, 1)

    # State shared with operations.

    def frame(self):
        """(R, t) file -> part of the records read so far."""
        table = self.table()
        return self.base if table is None else compose(self.base, table)

    def table(self):
        """(R, t) of the indexed table's turns (file -> part), C innermost, or None when it is not turned."""
        frame = None
        for axis in ("AAXIS", "BAXIS", "CAXIS"):
            angle = self.table_angles.get(axis, 0.0)
            if angle % 360.0:
                turn = table_frame(angle, axis)
                frame = turn if frame is None else compose(turn, frame)
        return frame

    def frame_words(self):
        """The frame records in force, in words (empty for the part frame)."""
        return " + ".join(words for words in (self.base_words, self.table_words, self.setup_words) if words)

    # Messages.

    def error(self, record, message):
        """InputError ``file:line: WORD: message``."""
        return InputError(f"{self.name}:{record.line}: {record.word}: {message}")

    def warn(self, line, word, message):
        """Add the warning ``file:line: WORD: message``."""
        self.warnings.append(f"{self.name}:{line}: {word}: {message}")

    def warn_once(self, key, line, word, message):
        """warn(), the first time `key` is met only."""
        if key not in self.warned:
            self.warned.add(key)
            self.warn(line, word, message)

    # Records and comments.

    def record(self, record):
        """Apply one record; one the engine does not need is skipped, with a warning, when it cannot be read."""
        word = record.word
        if word == "GOTO":
            self.close_nurbs()
            self.on_goto(record)
            return
        if self.nurbs is not None:
            if word in ("KNOT", "CNTRL"):
                self.nurbs_data(record)
                return
            self.close_nurbs()
        handler = _HANDLERS.get(word)
        if handler is not None:
            try:
                handler(self, record)
            except InputError as error:
                if word in NEEDED:
                    raise
                self.warn(record.line, word, f"{str(error).split(f'{word}: ', 1)[-1]}; the record is skipped "
                                             "(the engine does not need it)")
        elif word in IGNORED or word.startswith("TOOL PATH") or word.startswith("CSI_"):
            self.count(self.ignored, record)
        else:
            self.count(self.unknown, record)

    @staticmethod
    def count(table, record):
        """Count `record` under its word in `table` ({word: (first line, count)})."""
        first, count = table.get(record.word, (record.line, 0))
        table[record.word] = (first, count + 1)

    def comment(self, line, text):
        """A ``$$`` comment: Creo's ``->`` directives and CATIA's operation names; others are text."""
        creo = _CREO.match(text)
        if creo:
            word, rest = creo.group(1).upper(), creo.group(2)
            if word == "CUTTER":
                values = [float(v) for v in _NUMBER_TEXT.findall(rest)]
                if values and values[0] > 0.0:
                    radius = values[1] if len(values) > 1 else 0.0
                    self.set_tool(mill(values[0] * self.scale, radius * self.scale, f"$$-> CUTTER line {line}",
                                       self.kind_word, unit=self.unit_name()), line)
            elif word == "FEATNO":
                self.boundary(line, f"feature {rest.strip().strip('/').strip()}")
            return
        named = _OPERATION_NAME.match(text)
        if named:
            self.boundary(line, named.group(1).strip())

    def unit_name(self):
        """The length unit in force, "mm" or "inch"."""
        return "mm" if self.scale == 1.0 else "inch"

    # Numbers.

    def numbers(self, record):
        """The record's arguments as floats; InputError naming the first that is not a number."""
        if record.rest and not record.rest.strip(_NUMBER_CHARACTERS):
            try:
                values = [float(arg) for arg in record.args]
            except ValueError:
                values = [math.inf]
            if max(map(abs, values), default=0.0) <= MAX_MAGNITUDE:
                return values
        for position, arg in enumerate(record.args, start=1):
            if not _NUMBER_TEXT.fullmatch(arg):
                raise self.error(record, f"argument {position} {arg!r} is not a number"
                                 if arg else f"argument {position} is empty")
            if not abs(float(arg)) <= MAX_MAGNITUDE:
                raise self.error(record, f"argument {position} {arg!r} is not a number of at most "
                                         f"{MAX_MAGNITUDE:g} in magnitude")
        return [float(arg) for arg in record.args]

    def numbers_and_words(self, record):
        """(numbers, upper-case words) of the record's arguments in order; empty arguments skipped; a
        number with a word glued to it (``900CCLW``) gives both."""
        numbers, words = [], []
        for position, arg in enumerate(record.args, start=1):
            if not arg:
                continue
            glued = _GLUED.fullmatch(arg)
            if _NUMBER_TEXT.fullmatch(arg) and abs(float(arg)) <= MAX_MAGNITUDE:
                numbers.append(float(arg))
            elif _WORD.fullmatch(arg):
                words.append(arg.upper())
            elif glued and abs(float(glued.group(1))) <= MAX_MAGNITUDE:
                numbers.append(float(glued.group(1)))
                words.append(glued.group(2).upper())
            else:
                raise self.error(record, f"argument {position} {arg!r} is neither a number nor a word")
        return numbers, words

    def unit_axis(self, record, values):
        """(i, j, k) normalised; InputError when zero."""
        norm = math.sqrt(values[0] ** 2 + values[1] ** 2 + values[2] ** 2)
        if norm == 0.0:
            raise self.error(record, "tool axis (0, 0, 0) is zero")
        return (values[0] / norm, values[1] / norm, values[2] / norm)

    # Operations.

    def boundary(self, line, name=None):
        """Start a new operation on `line` if the current one has moved; name it."""
        if self.op.moved:
            self.done.append(self.op)
            self.op = _Operation(self, line)
        if name:
            self.op.name = name

    def set_tool(self, tool, line, describes=True):
        """Make `tool` the tool in force, named by a tool name given since the last motion (a record that
        `describes` the tool, CUTTER or TLDATA, takes the name for good). Another tool after the operation
        has moved starts a new operation; the same tool again leaves the moved operation's own as it is
        (a repeated tool block's flute length is the next operation's), but gives it a flute length it
        lacks."""
        if self.tool_name is not None:
            tool = tool.named(*self.tool_name)
            if describes:
                self.tool_name = None
        self.tool = tool
        if not self.op.moved:
            self.op.tool = tool
        elif not tool.same_tool(self.op.tool):
            self.boundary(line)
        elif self.op.tool.flute_length is None and tool.flute_length is not None:
            self.op.tool = tool

    def set_frame(self, line):
        """The frame (or the setup named under TRNTYP/WORLD) changed: an operation that has moved ends."""
        frame, setup = self.frame(), self.setup
        old = self.op.frame
        same_setup = (setup is None) == (self.op.setup is None) and (setup is None or (
            np.array_equal(setup[0], self.op.setup[0]) and np.array_equal(setup[1], self.op.setup[1])))
        if np.array_equal(frame[0], old[0]) and np.array_equal(frame[1], old[1]) and same_setup:
            self.op.frame_words = self.frame_words()
            return
        self.boundary(line, self.op.name)  # the same CAM operation goes on in another frame
        self.op.frame, self.op.frame_words, self.op.setup = frame, self.frame_words(), setup

    # Motion.

    def on_goto(self, record):
        """GOTO/x,y,z[,i,j,k]."""
        values = self.numbers(record)
        if len(values) == 6:
            self.axis = self.unit_axis(record, values[3:])
        elif len(values) != 3:
            raise self.error(record, f"takes x,y,z or x,y,z,i,j,k, got {len(values)} number(s)")
        scale = self.scale
        self.move(record, (values[0] * scale, values[1] * scale, values[2] * scale))

    def move(self, record, point):
        """A motion to `point` (file frame, mm) by `record`: rapid, hole, arc or straight cut."""
        self.tool_name = None  # a tool name names the tool record right after it, before any motion
        op = self.op
        line = record.line
        if self.rapid or self.cycle is not None:
            self.circle = None  # a rapid or hole position ends a pending arc: it is not cut
            target = (op.rapids, op.rapid_axes, op.rapid_lines) if self.rapid else (op.holes, op.hole_axes,
                                                                                      op.hole_lines)
            target[0].append(point)
            target[1].append(self.axis)
            target[2].append(line)
            self.rapid = False
            self.position = point
            return
        if self.circle is not None:
            self.arc(record, point)
        else:
            chord = (0.0, 0.0, 0.0) if self.position is None else tuple(p - q for p, q in zip(point, self.position))
            self.cut_points(np.array([point]), line, np.array([chord]))
        self.position = point

    def cut_points(self, points, line, directions):
        """Append cutting points (k, 3) with the directions of the motion arriving at each (k, 3) and the
        axis and feed in force."""
        op = self.op
        count = len(points)
        op.points.extend(map(tuple, points))
        op.directions.extend(map(tuple, directions))
        op.axes.extend([self.axis] * count)
        op.lines.extend([line] * count)
        op.feeds.extend([self.feed] * count)
        op.kinds.extend([self.feed_kind] * count)

    def arc(self, record, end):
        """The GOTO after CIRCLE: the arc from the position to `end`."""
        centre, axis, radius, circle_line = self.circle
        self.circle = None
        if self.position is None:
            raise self.error(record, f"the arc of the CIRCLE on line {circle_line} has no start point "
                             "(no move before it)")
        try:
            points, tangents = arc_points(self.position, end, centre, axis, self.tolerance, self.step)
        except ValueError as error:
            raise self.error(record, f"the arc of the CIRCLE on line {circle_line}: {error}") from None
        if radius is not None:
            w = np.asarray(axis) / np.linalg.norm(axis)
            for label, point in (("start", self.position), ("end", end)):
                offset = np.asarray(point) - centre
                off = abs(np.linalg.norm(offset - (offset @ w) * w) - radius)
                if off > max(self.tolerance, 1e-3 * radius):
                    self.warn(circle_line, "CIRCLE", f"the arc's {label} point is {off:.4g} mm off the circle "
                              f"of radius {radius:g} mm; the arc follows the points")
        self.cut_points(points, record.line, tangents)
        self.op.arcs += 1

    def on_circle(self, record):
        """CIRCLE/xc,yc,zc,i,j,k[,r,...][,CLOCKWISE|COUNTERCLOCKWISE]: the next GOTO moves along this
        circle; a direction word turns the motion as seen from the axis's tip."""
        values, words = self.numbers_and_words(record)
        if len(values) < 6:
            raise self.error(record, f"needs xc,yc,zc,i,j,k[,r], got {len(values)} number(s)")
        senses = [_CIRCLE_SENSE[word] for word in words if word in _CIRCLE_SENSE]
        others = [word for word in words if word not in _CIRCLE_SENSE]
        if others or len(senses) > 1:
            raise self.error(record, f"expected numbers and one direction (CLOCKWISE or COUNTERCLOCKWISE), got "
                                     f"{', '.join(others or words)}")
        centre = np.array(values[:3]) * self.scale
        axis = np.array(values[3:6]) * (senses[0] if senses else 1.0)
        if not np.linalg.norm(axis) > 0.0:
            raise self.error(record, "the circle's axis (0, 0, 0) is zero")
        radius = values[6] * self.scale if len(values) > 6 and values[6] > 0.0 else None
        self.circle = (centre, axis, radius, record.line)

    def on_godlta(self, record):
        """GODLTA/dx,dy,dz or GODLTA/d (along the tool axis): a move relative to the position."""
        values = self.numbers(record)
        if self.position is None:
            raise self.error(record, "a relative move needs a position before it")
        if len(values) == 1:
            delta = [values[0] * self.scale * a for a in self.axis]
        elif len(values) in (3, 6):
            delta = [v * self.scale for v in values[:3]]
            if len(values) == 6:
                self.axis = self.unit_axis(record, values[3:])
        else:
            raise self.error(record, f"takes d or dx,dy,dz, got {len(values)} number(s)")
        self.move(record, tuple(p + d for p, d in zip(self.position, delta)))

    def on_from(self, record):
        """FROM/x,y,z[,i,j,k]: the start position (no move)."""
        values = self.numbers(record)
        if len(values) not in (3, 6):
            raise self.error(record, f"takes x,y,z or x,y,z,i,j,k, got {len(values)} number(s)")
        if len(values) == 6:
            self.axis = self.unit_axis(record, values[3:])
        self.position = tuple(v * self.scale for v in values[:3])

    def on_rapid(self, record):
        """RAPID (with or without '/'): the next move is rapid; RAPID/OFF cancels."""
        self.rapid = [arg.upper() for arg in record.args] != ["OFF"]

    def on_nurbs(self, record):
        """NURBS/[order]: a B-spline move whose KNOT and CNTRL records follow."""
        self.nurbs = {"line": record.line, "record": record, "knots": [], "control": []}

    def nurbs_data(self, record):
        """A KNOT/ or CNTRL/ record (or both on one line) of the open NURBS block."""
        text = f"{record.word}/{record.rest}"
        parts = _NURBS_PART.split(text)
        for word, values in zip(parts[1::2], parts[2::2]):
            numbers = [float(v) for v in _NUMBER_TEXT.findall(values)]
            if not max(map(abs, numbers), default=0.0) <= MAX_MAGNITUDE:
                raise self.error(record, f"{word.upper()}: a number above {MAX_MAGNITUDE:g} in magnitude")
            if word.upper() == "KNOT":
                self.nurbs["knots"].extend(numbers)
            elif len(numbers) in (3, 4):
                self.nurbs["control"].append(numbers)
            elif numbers and len(numbers) % 3 == 0:
                self.nurbs["control"].extend(numbers[i:i + 3] for i in range(0, len(numbers), 3))
            else:
                raise self.error(record, f"a control point needs x,y,z[,w], got {len(numbers)} number(s)")

    def close_nurbs(self):
        """Evaluate the open NURBS block, if any, as cutting points from the tool's position."""
        block, self.nurbs = self.nurbs, None
        if block is None:
            return
        record = block["record"]
        control = block["control"]
        if not control:
            raise self.error(record, "the NURBS block has no CNTRL records")
        widths = {len(point) for point in control}
        if widths == {4} and len({point[3] for point in control}) > 1:
            raise self.error(record, "a rational NURBS (control points of different weights) is not read")
        if len(widths) > 1:
            raise self.error(record, "the control points mix x,y,z and x,y,z,w")
        self.tool_name = None
        points = np.array([point[:3] for point in control]) * self.scale
        try:
            layout, gap = resolve(block["knots"], points, self.position, self.tolerance)
            curve, tangents = bspline_points(layout, self.tolerance, self.step)
        except ValueError as error:
            raise self.error(record, str(error)) from None
        start = layout.control[0]
        if self.position is None or gap:
            if gap:
                self.warn(record.line, record.word, f"the curve ({layout.words}, degree {layout.degree}) starts "
                          f"{gap:.4g} mm from the tool's position; the tool moves there in a straight line")
            chord = np.zeros(3) if self.position is None else start - np.asarray(self.position)
            curve, tangents = np.vstack([start, curve]), np.vstack([chord, tangents])
        self.cut_points(curve, record.line, tangents)
        self.op.curves += 1
        self.position = tuple(curve[-1])

    def on_cycle(self, record):
        """CYCLE/kind,... up to CYCLE/OFF: the GOTOs between are hole positions; a tapping cycle's tool is a tap."""
        words = [arg.upper() for arg in record.args if _WORD.fullmatch(arg)]
        if words[:1] == ["OFF"]:
            self.cycle = None
            return
        self.cycle = words[0] if words else "ON"
        if self.cycle not in self.op.cycles:
            self.op.cycles.append(self.cycle)
        if self.cycle in ("TAP", "RIGID") and self.tool.kind != "tap":
            self.set_tool(self.tool.with_kind("tap", f"CYCLE/{self.cycle} line {record.line}"), record.line,
                          describes=False)

    # Modal settings.

    def on_tlaxis(self, record):
        """TLAXIS/i,j,k: the tool axis of the moves that follow."""
        numbers, words = self.numbers_and_words(record)
        if len(numbers) < 3:
            self.warn(record.line, record.word, f"{','.join(record.args)!r} gives no axis i,j,k; the axis is kept")
            return
        self.axis = self.unit_axis(record, numbers[:3])

    def on_multax(self, record):
        """MULTAX[/ON|OFF]: accepted; six-number GOTOs carry the axis either way."""

    def on_fedrat(self, record):
        """FEDRAT/f[,unit] or FEDRAT/unit,f: the feed of the moves that follow."""
        numbers, words = self.numbers_and_words(record)
        units = [word for word in words if word in unit_words.FEED_UNITS]
        if not numbers:
            self.warn(record.line, record.word, f"{','.join(record.args)!r} gives no feed rate; the feed is kept")
            return
        if numbers[0] <= 0.0:
            raise self.error(record, f"feed rate must be positive, got {numbers[0]:g}")
        if units:
            unit = units[0]
        elif self.feed_kind == "MMPR":
            unit = "IPR" if self.scale != 1.0 else "MMPR"
        else:
            unit = "IPM" if self.scale != 1.0 else "MMPM"
        self.feed, self.feed_kind = unit_words.feed_to_mm(numbers[0], unit)

    def on_spindl(self, record):
        """SPINDL in its forms: [RPM|SFM|SMM,]n[,CLW|CCLW], n,RPM, MAIN,..., ON, OFF, 900CCLW."""
        numbers, words = self.numbers_and_words(record)
        if not numbers:
            return
        speed = numbers[0]
        surface = next((word for word in words if word in unit_words.SURFACE_SPEEDS), None)
        if speed <= 0.0:
            return
        if surface is not None:
            diameter = self.tool.diameter
            if diameter is None or not self.tool.milling:
                self.warn(record.line, record.word, f"surface speed {speed:g} {surface} for "
                          f"{'a tool without a diameter' if diameter is None else self.tool.describe()} gives no "
                          "spindle speed in rpm")
                return
            speed = unit_words.surface_speed_rpm(speed, surface, diameter)
        self.spindle = speed
        self.op.spindle = speed

    def on_units(self, record):
        """UNITS/MM|INCHES, UNIT/MM|INCH: the length unit of the records that follow."""
        word = record.args[0].upper() if record.args else ""
        if word not in unit_words.LENGTH_UNITS:
            raise self.error(record, f"expected MM or INCHES, got {','.join(record.args)!r}")
        label, self.scale = unit_words.LENGTH_UNITS[word]
        if self.units is None:
            self.units = label

    def on_cutcom(self, record):
        """CUTCOM/LEFT|RIGHT|OFF: the control's cutter compensation; the CL points are taken as written
        (the tool tip's centre), which the warning says once."""
        self.count(self.ignored, record)
        if record.args and record.args[0].upper() in ("LEFT", "RIGHT", "ON"):
            self.warn_once("CUTCOM", record.line, record.word, f"{','.join(record.args)}: cutter compensation in the "
                           "control; the CL points are taken as the tool tip's centre as written (an offset the "
                           "control adds, such as wear, is left out)")

    # Tools.

    def on_cutter(self, record):
        """CUTTER/d[,r,e,f,a,b,h]: diameter and corner radius, the tip angle a, the side angle b, the tool's
        height h (tools.mill)."""
        numbers, words = self.numbers_and_words(record)
        if not numbers:
            self.warn(record.line, record.word, f"{','.join(record.args)!r} gives no diameter; not read")
            return
        diameter = numbers[0] * self.scale
        if diameter <= 0.0:
            raise self.error(record, f"diameter must be positive, got {numbers[0]:g}")
        radius = numbers[1] * self.scale if len(numbers) > 1 else 0.0
        tip = numbers[4] if len(numbers) > 4 else 0.0
        side = numbers[5] if len(numbers) > 5 else 0.0
        length = numbers[6] * self.scale if len(numbers) > 6 and numbers[6] > 0.0 else None
        if self.tool.kind in ("turning", "grooving") and not self.op.moved and len(numbers) == 1:
            return  # a turning insert's CUTTER gives its nose radius, not a mill's diameter
        self.set_tool(mill(diameter, radius, f"CUTTER line {record.line}", self.kind_word, tip_angle=tip,
                           side_angle=side, unit=self.unit_name(), length=length), record.line)

    def on_tldata(self, record):
        """TLDATA/kind,d,r,length,taper,...: MILL gives diameter, corner radius, length and taper; DRILL, TURN...
        the kind."""
        kind = record.args[0].upper() if record.args else ""
        numbers = []
        for arg in record.args[1:]:
            if _NUMBER_TEXT.fullmatch(arg):
                numbers.append(float(arg))
        source = f"TLDATA line {record.line}"
        diameter = numbers[0] * self.scale if numbers and numbers[0] > 0.0 else None
        radius = numbers[1] * self.scale if len(numbers) > 1 else 0.0
        length = numbers[2] * self.scale if len(numbers) > 2 and numbers[2] > 0.0 else None
        taper = numbers[3] if len(numbers) > 3 else 0.0
        if kind in KIND_WORDS:
            # A turning insert's first number is its nose radius, not a diameter.
            size = None if KIND_WORDS[kind] in ("turning", "grooving") else diameter
            self.set_tool(ToolSpec(KIND_WORDS[kind], size, None, None, (source,), self.unit_name()), record.line)
        elif kind == "MILL" and diameter is not None:
            self.set_tool(mill(diameter, radius, source, side_angle=taper, unit=self.unit_name(), length=length),
                          record.line)
        else:
            self.set_tool(ToolSpec("unknown", diameter, None, None, (source,), self.unit_name()), record.line)

    def on_toolno(self, record):
        """TOOLNO/n,KIND,... (CATIA): the kind word of the tool in force (TURN, GROOVE, DRILL, TAP ...)."""
        kind = next((KIND_WORDS[arg.upper()] for arg in record.args if arg.upper() in KIND_WORDS), None)
        if kind is not None and kind != self.tool.kind:
            size = None if kind in ("turning", "grooving") else self.tool.diameter
            tool = ToolSpec(kind, size, None, None, self.tool.records + (f"TOOLNO line {record.line}",),
                            self.tool.unit, self.tool.name)
            self.set_tool(tool, record.line)

    def on_turret(self, record):
        """TURRET/... (a lathe's tool change): a new operation with a turning tool."""
        self.boundary(record.line)
        self.kind_word = "TURN"
        self.set_tool(ToolSpec("turning", None, None, None, (f"TURRET line {record.line}",), self.unit_name()),
                      record.line)

    def on_loadtl(self, record):
        """LOADTL / LOAD/TOOL: a tool change (a new operation); a kind word (DRILL, TAP...) names the tool."""
        self.boundary(record.line)
        words = {arg.upper() for arg in record.args}
        kind = next((word for word in words if word in KIND_WORDS), None)
        self.kind_word = kind
        if kind is not None:
            self.set_tool(self.tool.with_kind(KIND_WORDS[kind], f"{record.word} line {record.line}"), record.line,
                          describes=False)
        else:
            self.set_tool(self.tool, record.line, describes=False)

    def on_load(self, record):
        """LOAD/TOOL,n (NX): a tool change."""
        if record.args and record.args[0].upper() == "TOOL":
            self.on_loadtl(record)
        else:
            self.count(self.ignored, record)

    def on_flute_length(self, record):
        """CSI_SET_FLUTE_LENGTH/l (SOLIDWORKS CAM): the flute length of the tool in force."""
        numbers, _ = self.numbers_and_words(record)
        if not numbers or numbers[0] <= 0.0:
            self.warn(record.line, record.word, f"{','.join(record.args)!r} is no flute length; not read")
            return
        self.set_tool(self.tool.with_flute_length(numbers[0] * self.scale, f"{record.word} line {record.line}"),
                      record.line, describes=False)

    def on_insert(self, record):
        """INSERT/text: a tool name when a tool record follows (SOLIDWORKS CAM ``INSERT/[HOLDER=…] name``)."""
        self.count(self.ignored, record)
        text = record.rest.strip()
        holder = re.match(r"\[[^\]]*\]\s*(.*)", text)
        if holder or kind_of_name(text):
            self.tool_name = ((holder.group(1) if holder else text).strip(), f"INSERT line {record.line}")

    def on_tprint(self, record):
        """TPRINT/text (CATIA): the name of the tool in force."""
        self.count(self.ignored, record)
        self.tool_name = (record.rest.strip(), f"TPRINT line {record.line}")
        self.set_tool(self.tool, record.line, describes=False)

    # Frames and operations.

    def on_tool_path(self, record):
        """TOOL PATH/name,TOOL,tool (NX): a new operation named `name`, its tool named `tool`."""
        self.boundary(record.line, record.args[0] if record.args else "")
        self.count(self.ignored, record)
        words = [arg.upper() for arg in record.args]
        if "TOOL" in words[1:] and words.index("TOOL", 1) + 1 < len(record.args):
            self.tool_name = (record.args[words.index("TOOL", 1) + 1], f"TOOL PATH line {record.line}")

    def on_pprint(self, record):
        """PPRINT/text: CATIA's ``OPERATION NAME : ...`` starts an operation; other text is ignored."""
        named = _OPERATION_NAME.match(record.rest.strip())
        if named:
            self.boundary(record.line, named.group(1).strip())
        self.count(self.ignored, record)

    def on_msys(self, record):
        """MSYS/x0,y0,z0,X axis,Y axis (NX): the frame the following records are written in."""
        values = self.numbers(record)
        if len(values) != 9:
            raise self.error(record, f"needs 9 numbers (origin, X axis, Y axis), got {len(values)}")
        self.set_base(record, msys_frame([v * self.scale for v in values[:3]] + values[3:]))

    def on_csys(self, record):
        """CSYS/3 x 4 matrix row by row: the setup frame of the following records; after TRNTYP/WORLD only
        the setup (the GOTOs stay in the world frame; the matrix's Z is the tool axis)."""
        values = self.numbers(record)
        if len(values) != 12:
            raise self.error(record, f"needs 12 numbers (a 3 x 4 matrix, row by row), got {len(values)}")
        for index in (3, 7, 11):
            values[index] *= self.scale
        frame = csys_frame(values)
        if self.world is None:
            self.set_base(record, frame)
            return
        if isinstance(frame, str):
            raise self.error(record, f"not a frame: {frame}")
        self.setup = frame
        self.axis = tuple(frame[0][:, 2])
        self.setup_words = (f"CSYS line {record.line} (a setup: points in the world frame, TRNTYP/WORLD line "
                            f"{self.world})")
        self.set_frame(record.line)

    def on_trntyp(self, record):
        """TRNTYP/WORLD (SOLIDWORKS CAM, at the start of each of its operations): a new operation, whose GOTOs
        are in the world frame; the CSYS that follows names its setup."""
        words = [arg.upper() for arg in record.args if _WORD.fullmatch(arg)]
        self.world = record.line if "WORLD" in words else None
        if self.world is not None:
            self.boundary(record.line)
        if self.world is None:
            self.setup, self.setup_words = None, ""

    def set_base(self, record, frame):
        """Make `frame` (an (R, t), or the text of why the record is not one) the frame of the following
        records (MSYS, CSYS)."""
        if isinstance(frame, str):
            raise self.error(record, f"not a frame: {frame}")
        self.base = frame
        identity = not frame[1].any() and np.allclose(frame[0], np.eye(3), rtol=0.0, atol=1e-12)
        self.base_words = "" if identity else f"{record.word} line {record.line}"
        self.set_frame(record.line)

    def on_rotabl(self, record):
        """ROTABL/a,AAXIS|BAXIS|CAXIS[,CLW|CCLW][,INCR|ATANGL]: the indexed table's angle about that axis;
        turns about several axes compose (C innermost), in radians where the file writes them so."""
        numbers, words = self.numbers_and_words(record)
        if not numbers:
            self.warn(record.line, record.word, f"{','.join(record.args)!r} gives no angle; the table is kept")
            return
        axis = next((word for word in words if word in ("AAXIS", "BAXIS", "CAXIS")), "CAXIS")
        angle = math.degrees(numbers[0]) if self.radians else numbers[0]
        if self.radians:
            self.warn_once("radians", record.line, record.word, f"angles read in radians, as CAMWorks writes them "
                           f"({numbers[0]:g} rad = {angle:.6g} deg)")
        angle = -angle if "CLW" in words else angle
        if "INCR" in words:
            angle += self.table_angles.get(axis, 0.0)
        if not abs(angle) <= MAX_ANGLE:
            raise self.error(record, f"the table's angle {angle:g}° is beyond ±{MAX_ANGLE:g}°")
        self.table_angles[axis] = angle
        turned = [f"{self.table_angles[a]:g} {a}" for a in ("AAXIS", "BAXIS", "CAXIS")
                  if self.table_angles.get(a, 0.0) % 360.0]
        self.table_words = f"ROTABL {' + '.join(turned)} line {record.line}" if turned else ""
        self.set_frame(record.line)

    # The result.

    def program(self, text, last_line):
        """The Program of everything read."""
        self.close_nurbs()
        if self.circle is not None:
            self.warn(self.circle[3], "CIRCLE", "no GOTO follows: the circle is not a move")
        self.done.append(self.op)
        operations = []
        for op in self.done:
            if op.moved:
                operations.append(self.finish(op, len(operations) + 1))
        return Program(self.name, self.units or "mm", tuple(operations), dict(self.ignored), dict(self.unknown),
                       list(self.warnings), "apt", text, last_line)

    def finish(self, op, number):
        """The Operation of a collected operation."""
        kinds = {kind for kind in op.kinds if kind is not None}
        if len(kinds) > 1:
            self.warn(op.first_line, "FEDRAT", f"operation {number} mixes feeds per minute and per revolution; "
                      "its feeds are reported as written, each in its own kind")
        feed_unit = op.kinds[-1] if op.kinds and op.kinds[-1] is not None else (sorted(kinds)[0] if kinds else None)
        return Operation(
            number, op.name, op.tool, op.spindle, _frozen(op.feeds, float, (-1,)), feed_unit,
            _frozen(op.lines, int, (-1,)), _frozen(op.points, float, (-1, 3)), _frozen(op.axes, float, (-1, 3)),
            op.frame, op.frame_words, _moves(op.rapids, op.rapid_axes, op.rapid_lines),
            _moves(op.holes, op.hole_axes, op.hole_lines), op.arcs, op.curves, self.name, op.first_line,
            tuple(op.cycles), _frozen(op.directions, float, (-1, 3)))


def _frozen(values, dtype, shape):
    """A read-only array of `values` reshaped to `shape`."""
    array = np.array(values, dtype=dtype).reshape(shape)
    array.setflags(write=False)
    return array


def _moves(points, axes, lines):
    """Moves of the collected lists."""
    return Moves(_frozen(points, float, (-1, 3)), _frozen(axes, float, (-1, 3)), _frozen(lines, int, (-1,)))


_HANDLERS = {
    "RAPID": _Reader.on_rapid, "CIRCLE": _Reader.on_circle, "GODLTA": _Reader.on_godlta, "FROM": _Reader.on_from,
    "NURBS": _Reader.on_nurbs, "CYCLE": _Reader.on_cycle, "TLAXIS": _Reader.on_tlaxis, "MULTAX": _Reader.on_multax,
    "FEDRAT": _Reader.on_fedrat, "SPINDL": _Reader.on_spindl, "UNITS": _Reader.on_units, "UNIT": _Reader.on_units,
    "CUTTER": _Reader.on_cutter, "TLDATA": _Reader.on_tldata, "LOADTL": _Reader.on_loadtl, "LOAD": _Reader.on_load,
    "CSI_SET_FLUTE_LENGTH": _Reader.on_flute_length, "TOOL PATH": _Reader.on_tool_path, "PPRINT": _Reader.on_pprint,
    "MSYS": _Reader.on_msys, "CSYS": _Reader.on_csys, "ROTABL": _Reader.on_rotabl, "TRNTYP": _Reader.on_trntyp,
    "TOOLNO": _Reader.on_toolno, "TURRET": _Reader.on_turret, "INSERT": _Reader.on_insert,
    "TPRINT": _Reader.on_tprint, "CUTCOM": _Reader.on_cutcom,
}
