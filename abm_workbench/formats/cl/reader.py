"""The modal state machine: CL records, in file order, into the operations of a :class:`Program`.

Motion: ``GOTO/x,y,z`` keeps the tool axis in force (``TLAXIS``, or the last six-number GOTO);
``GOTO/x,y,z,i,j,k`` is always position and axis (``MULTAX`` is accepted, never needed);
``GODLTA/dx,dy,dz`` or ``GODLTA/d`` (along the axis) moves relative to the last position;
``FROM`` sets the position. A GOTO after ``RAPID`` is a rapid move, one inside a canned cycle
(``CYCLE/...`` up to ``CYCLE/OFF``) a hole position; both are kept apart from cutting moves.
``CIRCLE`` makes the next GOTO an arc (:mod:`.arcs`), ``NURBS/`` with its ``KNOT``/``CNTRL``
records a B-spline (:mod:`.nurbs`).

Operations: a new one starts at ``TOOL PATH`` (NX, with the operation's name), ``LOADTL`` /
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
from .. import MAX_MAGNITUDE, NUMBER
from . import units as unit_words
from .arcs import arc_points
from .frames import IDENTITY, compose, csys_frame, msys_frame, table_frame
from .lexer import lex
from .nurbs import bspline_points
from .program import Moves, Operation, Program
from .tools import KIND_WORDS, ToolSpec, mill

_NUMBER_TEXT = re.compile(NUMBER)
#: A record whose text after '/' holds only these characters is read by float() at once.
_NUMBER_CHARACTERS = "0123456789+-.eE ,\t"
_WORD = re.compile(r"[A-Za-z][A-Za-z0-9_-]*")
_CREO = re.compile(r"->\s*([A-Za-z_]+)\s*/?\s*(.*)")
_OPERATION_NAME = re.compile(r"OPERATION\s+NAME\s*:\s*(.+)", re.IGNORECASE)
_NURBS_PART = re.compile(r"(KNOT|CNTRL)\s*/", re.IGNORECASE)

#: Records known to carry nothing the engine needs: counted in Program.ignored, never warned.
IGNORED = frozenset({
    "PPRINT", "TPRINT", "DPRINT", "PARTNO", "INSERT", "PAINT", "OPFEATSTART", "OPFEATEND", "BOX", "END-OF-PATH",
    "MACHIN", "COOLNT", "STOP", "OPSTOP", "END", "FINI", "INTOL", "OUTTOL", "TOLER", "CUTCOM", "SELECT", "CLRSRF",
    "SEQNO", "DISPLY", "AUTOPS", "GOHOME", "DELAY", "PREFUN", "AUXFUN", "CLAMP", "HEAD", "MODE", "TURRET", "ORIGIN",
    "TLON", "TLONPS", "TLOFPS", "PLABEL", "OPERATION", "TOOLNO", "AIR", "LINTOL", "CATIA0", "RETRCT", "THRU",
    "MCS", "PITCH", "CHECK", "OPNAME", "TRANS", "PIVOTZ", "UNLOAD", "WCS", "FIXTURE", "LEADER", "SET", "ROTATE",
})


def read_cl_text(text, name, tolerance):
    """The :class:`Program` of APT / CL `text` read from file `name`; arcs and curves to
    `tolerance` mm. InputError ``file:line: WORD: ...`` for a record that cannot be read."""
    records, comments, last_line = lex(text, name)
    reader = _Reader(name, tolerance)
    events = [(line, 0, comment) for line, comment in comments]
    events += [(record.line, 1, record) for record in records]
    events.sort(key=lambda event: (event[0], event[1]))
    for line, kind, item in events:
        if kind:
            reader.record(item)
        else:
            reader.comment(line, item)
    return reader.program(text, last_line)


class _Operation:
    """The operation being read: what it has collected so far (lists, file frame, mm)."""

    def __init__(self, state, line):
        """A new operation starting on `line`, inheriting tool, spindle and frame from `state`."""
        self.name = ""
        self.tool = state.tool
        self.spindle = state.spindle
        self.frame, self.frame_words = state.frame(), state.frame_words()
        self.first_line = line
        self.points, self.axes, self.lines, self.feeds, self.kinds = [], [], [], [], []
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

    def __init__(self, name, tolerance):
        """Start state: mm, axis (0, 0, 1), no tool, no feed, part frame, one empty operation."""
        self.name, self.tolerance = name, float(tolerance)
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
        self.base, self.base_words = IDENTITY, ""
        self.table, self.table_words = None, ""
        self.done = []
        self.ignored, self.unknown, self.warnings = {}, {}, []
        self.op = _Operation(self, 1)

    # State shared with operations.

    def frame(self):
        """(R, t) file -> part of the records read so far."""
        return self.base if self.table is None else compose(self.base, self.table)

    def frame_words(self):
        """The frame records in force, in words (empty for the part frame)."""
        return " + ".join(words for words in (self.base_words, self.table_words) if words)

    # Messages.

    def error(self, record, message):
        """InputError ``file:line: WORD: message``."""
        return InputError(f"{self.name}:{record.line}: {record.word}: {message}")

    def warn(self, line, word, message):
        """Add the warning ``file:line: WORD: message``."""
        self.warnings.append(f"{self.name}:{line}: {word}: {message}")

    # Records and comments.

    def record(self, record):
        """Apply one record."""
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
            handler(self, record)
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
                                       self.kind_word), line)
            elif word == "FEATNO":
                self.boundary(line, f"feature {rest.strip().strip('/').strip()}")
            return
        named = _OPERATION_NAME.match(text)
        if named:
            self.boundary(line, named.group(1).strip())

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
        """(numbers, upper-case words) of the record's arguments in order; empty arguments skipped."""
        numbers, words = [], []
        for position, arg in enumerate(record.args, start=1):
            if not arg:
                continue
            if _NUMBER_TEXT.fullmatch(arg) and abs(float(arg)) <= MAX_MAGNITUDE:
                numbers.append(float(arg))
            elif _WORD.fullmatch(arg):
                words.append(arg.upper())
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

    def set_tool(self, tool, line):
        """Make `tool` the tool in force; another tool after motion starts a new operation."""
        same = (tool.kind, tool.diameter, tool.corner_radius) == (
            self.op.tool.kind, self.op.tool.diameter, self.op.tool.corner_radius)
        if not same:
            self.boundary(line)
        self.tool = tool
        self.op.tool = tool

    def set_frame(self, line):
        """The frame changed: an operation that has moved ends."""
        frame = self.frame()
        old = self.op.frame
        if np.array_equal(frame[0], old[0]) and np.array_equal(frame[1], old[1]):
            self.op.frame_words = self.frame_words()
            return
        self.boundary(line, self.op.name)  # the same CAM operation goes on in another frame
        self.op.frame, self.op.frame_words = frame, self.frame_words()

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
            op.points.append(point)
            op.axes.append(self.axis)
            op.lines.append(line)
            op.feeds.append(self.feed)
            op.kinds.append(self.feed_kind)
        self.position = point

    def cut_points(self, points, line):
        """Append interpolated cutting points (k, 3) with the axis and feed in force."""
        op = self.op
        count = len(points)
        op.points.extend(map(tuple, points))
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
            points = arc_points(self.position, end, centre, axis, self.tolerance)
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
        self.cut_points(points, record.line)
        self.op.arcs += 1

    def on_circle(self, record):
        """CIRCLE/xc,yc,zc,i,j,k[,r,...]: the next GOTO moves along this circle."""
        values = self.numbers(record)
        if len(values) < 6:
            raise self.error(record, f"needs xc,yc,zc,i,j,k[,r], got {len(values)} number(s)")
        centre = np.array(values[:3]) * self.scale
        axis = np.array(values[3:6])
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
        """Evaluate the open NURBS block, if any, as cutting points."""
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
        points = np.array([point[:3] for point in control]) * self.scale
        try:
            curve = bspline_points(block["knots"], points, self.tolerance)
        except ValueError as error:
            raise self.error(record, str(error)) from None
        start = points[0]
        if self.position is None or np.linalg.norm(np.asarray(self.position) - start) > self.tolerance:
            curve = np.vstack([start, curve])
        self.cut_points(curve, record.line)
        self.op.curves += 1
        self.position = tuple(curve[-1])

    def on_cycle(self, record):
        """CYCLE/kind,... up to CYCLE/OFF: the GOTOs between are hole positions."""
        words = [arg.upper() for arg in record.args if _WORD.fullmatch(arg)]
        if words[:1] == ["OFF"]:
            self.cycle = None
            return
        self.cycle = words[0] if words else "ON"
        if self.cycle not in self.op.cycles:
            self.op.cycles.append(self.cycle)

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
        """SPINDL in its forms: [RPM|SFM|SMM,]n[,CLW|CCLW], n,RPM, MAIN,..., ON, OFF."""
        numbers, words = self.numbers_and_words(record)
        if not numbers:
            return
        speed = numbers[0]
        surface = next((word for word in words if word in unit_words.SURFACE_SPEEDS), None)
        if speed <= 0.0:
            return
        if surface is not None:
            diameter = self.tool.diameter
            if diameter is None:
                self.warn(record.line, record.word, f"surface speed {speed:g} {surface} without a tool diameter "
                          "gives no spindle speed")
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

    # Tools.

    def on_cutter(self, record):
        """CUTTER/d[,r,e,f,a,b,h]: diameter and corner radius (h is the tool's height); a bottom
        angle a with no corner radius makes it a drill."""
        numbers, words = self.numbers_and_words(record)
        if not numbers:
            self.warn(record.line, record.word, f"{','.join(record.args)!r} gives no diameter; not read")
            return
        diameter = numbers[0] * self.scale
        if diameter <= 0.0:
            raise self.error(record, f"diameter must be positive, got {numbers[0]:g}")
        radius = numbers[1] * self.scale if len(numbers) > 1 else 0.0
        # A bottom angle (the fifth number) with no corner radius: a pointed tool, a drill.
        pointed = len(numbers) > 4 and numbers[4] != 0.0 and radius == 0.0
        kind_word = self.kind_word or ("DRILL" if pointed else None)
        self.set_tool(mill(diameter, radius, f"CUTTER line {record.line}", kind_word), record.line)

    def on_tldata(self, record):
        """TLDATA/kind,d,r,...: MILL gives diameter and corner radius; DRILL, TURN... the kind."""
        kind = record.args[0].upper() if record.args else ""
        numbers = []
        for arg in record.args[1:]:
            if _NUMBER_TEXT.fullmatch(arg):
                numbers.append(float(arg))
        source = f"TLDATA line {record.line}"
        diameter = numbers[0] * self.scale if numbers and numbers[0] > 0.0 else None
        radius = numbers[1] * self.scale if len(numbers) > 1 else 0.0
        if kind in KIND_WORDS:
            # A turning insert's first number is its nose radius, not a diameter.
            size = None if KIND_WORDS[kind] == "turning" else diameter
            self.set_tool(ToolSpec(KIND_WORDS[kind], size, None, None, (source,)), record.line)
        elif kind == "MILL" and diameter is not None:
            self.set_tool(mill(diameter, radius, source), record.line)
        else:
            self.set_tool(ToolSpec("unknown", diameter, None, None, (source,)), record.line)

    def on_loadtl(self, record):
        """LOADTL / LOAD/TOOL: a tool change (a new operation); a kind word (DRILL, TAP...) names the tool."""
        self.boundary(record.line)
        words = {arg.upper() for arg in record.args}
        kind = next((word for word in words if word in KIND_WORDS), None)
        self.kind_word = kind
        if kind is not None:
            self.set_tool(self.tool.with_kind(KIND_WORDS[kind], f"{record.word} line {record.line}"), record.line)

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
        self.tool = self.tool.with_flute_length(numbers[0] * self.scale, f"{record.word} line {record.line}")
        self.op.tool = self.tool

    # Frames and operations.

    def on_tool_path(self, record):
        """TOOL PATH/name,TOOL,tool (NX): a new operation named `name`."""
        self.boundary(record.line, record.args[0] if record.args else "")
        self.count(self.ignored, record)

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
        """CSYS/3 x 4 matrix row by row: the setup frame of the following records."""
        values = self.numbers(record)
        if len(values) != 12:
            raise self.error(record, f"needs 12 numbers (a 3 x 4 matrix, row by row), got {len(values)}")
        for index in (3, 7, 11):
            values[index] *= self.scale
        self.set_base(record, csys_frame(values))

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
        """ROTABL/a,AAXIS|BAXIS|CAXIS[,CLW|CCLW][,INCR|ATANGL]: the indexed table's angle."""
        numbers, words = self.numbers_and_words(record)
        if not numbers:
            self.warn(record.line, record.word, f"{','.join(record.args)!r} gives no angle; the table is kept")
            return
        axis = next((word for word in words if word in ("AAXIS", "BAXIS", "CAXIS")), "CAXIS")
        angle = -numbers[0] if "CLW" in words else numbers[0]
        previous = self.table_angle if self.table is not None and self.table_axis == axis else 0.0
        if "INCR" in words:
            angle += previous
        self.table_angle, self.table_axis = angle, axis
        self.table = None if angle % 360.0 == 0.0 else table_frame(angle, axis)
        self.table_words = "" if self.table is None else f"ROTABL {angle:g} {axis} line {record.line}"
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
            tuple(op.cycles))


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
    "MSYS": _Reader.on_msys, "CSYS": _Reader.on_csys, "ROTABL": _Reader.on_rotabl,
}
