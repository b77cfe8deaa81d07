"""APT / CL data files (``.apt``, ``.cls``) as NX, CATIA and other post-processors write them.

What is read, record by record (major and minor words are case-insensitive):

- ``GOTO/x,y,z[,i,j,k]``: a move to CL point (x, y, z), the centre of the tool's bottom
  face. With ``MULTAX`` on, i, j, k give the tool axis (normalised; a GOTO of only x, y, z
  keeps the axis of the move before, or of a TLAXIS after it). With ``MULTAX`` off the
  axis is the last ``TLAXIS/i,j,k`` (default 0, 0, 1) and a GOTO with more than x, y, z is
  an error. Every GOTO is a cutting move unless it follows ``RAPID``, which makes the next
  GOTO a rapid move, left out of the toolpath.
- ``MULTAX`` / ``MULTAX/ON`` / ``MULTAX/OFF``, ``TLAXIS/i,j,k``, ``RAPID``.
- ``FEDRAT/f``, ``FEDRAT/unit,f``, ``FEDRAT/f,unit`` with unit MMPM, MMPR, IPM or IPR: the
  feed (modal) is kept per cutting move in the file's unit, never converted.
- ``CUTTER/d[,r,e,f,a,b,h]``: diameter d, flute length h (7-parameter form only).
  ``TLDATA/MILL,d,r,h,...`` (NX): diameter d and length h, taken as the flute length.
  A non-zero corner radius r gives a warning: the engine models a flat-end mill.
- ``SPINDL/rpm``, ``SPINDL/RPM,rpm[,CLW|CCLW]`` in either order, ``SPINDL/OFF``.
- ``UNITS/INCHES`` (``UNITS/MM`` back): coordinates and tool sizes in the records after it
  are converted to mm (with a warning); feeds keep the file's unit.
- ``MSYS/x0,y0,z0,xi,xj,xk,yi,yj,yk`` (NX): the local frame the following records are
  written in: its origin, then the direction cosines of its X axis, then of its Y axis, all
  in the global frame. A local point p becomes ``origin + px·X + py·Y + pz·Z`` (Z = X × Y),
  a local axis a becomes ``ax·X + ay·Y + az·Z``; a non-identity MSYS gives a warning.
- Records that carry no geometry (``TOOL PATH``, ``END-OF-PATH``, ``PAINT``, ``PPRINT``,
  ``LOADTL``, ``COOLNT``, ``FINI`` ... see ``_SILENT``) are accepted silently; any other
  major word is listed in :attr:`AptProgram.unknown`, once per word.

Lexical rules: ``$$`` starts a comment (whole line or trailing); a ``$`` ending a line
continues the record on the next non-blank line (the pieces are joined as they are);
numbers may have a bare leading dot (``.5``, ``-.25``) and an exponent (``1.5E+02``); blank
lines and any line ends are accepted.

Units: CL points and tool sizes in mm, spindle speed in rpm. A malformed record raises
:class:`abm_workbench.errors.InputError` as ``file:line: WORD: message``, the line being
where the record starts.
"""

import math
import os
import re
from dataclasses import dataclass
from typing import Optional

import numpy as np

from ..engine import Toolpath
from ..errors import CLPointError, InputError
from . import read_text

MM_PER_INCH = 25.4
FEED_UNITS = ("MMPM", "MMPR", "IPM", "IPR")
_SPINDLE_WORDS = ("RPM", "CLW", "CCLW", "ON", "OFF")
_LENGTH_UNITS = {"MM": 1.0, "INCHES": MM_PER_INCH, "INCH": MM_PER_INCH}
# Direction cosines of an MSYS frame must be unit and orthogonal to within this.
_FRAME_TOLERANCE = 1e-3
# Known major words that carry no geometry the engine needs (FROM and GOHOME are
# non-cutting positions).
_SILENT = frozenset({
    "TOOL PATH", "END-OF-PATH", "PAINT", "PPRINT", "TPRINT", "PARTNO", "MACHIN", "LOAD",
    "LOADTL", "SELECT", "INSERT", "COOLNT", "FROM", "GOHOME", "STOP", "OPSTOP", "END", "FINI",
    "INTOL", "OUTTOL",
})
_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_WORD = re.compile(r"[A-Za-z][A-Za-z0-9_-]*")


@dataclass(frozen=True, eq=False)
class AptProgram:
    """The cutting moves of an APT / CL file and what it says about tool, feed and spindle.

    toolpath: the m cutting moves (rapid moves left out), CL points in mm, global frame.
    diameter, flute_length: tool sizes in mm from the last CUTTER or TLDATA/MILL, or None.
    spindle_rpm: the last spindle speed given (rpm), or None.
    feed: (m,) feed in force at each cutting move, in the file's unit; NaN before any FEDRAT.
    feed_unit: the last feed unit given ("MMPM", "MMPR", "IPM", "IPR"), or None.
    line_numbers: (m,) 1-based line where the GOTO record of each CL point starts.
    unknown: (major word, first line, count) of each record kind not understood, in file order.
    warnings: messages ``file:line: ...`` about what was converted, assumed or changed.
    """

    toolpath: Toolpath
    diameter: Optional[float]
    flute_length: Optional[float]
    spindle_rpm: Optional[float]
    feed: np.ndarray
    feed_unit: Optional[str]
    line_numbers: np.ndarray
    unknown: tuple
    warnings: tuple


@dataclass(frozen=True)
class _Record:
    """One record: the line it starts on, its major word (upper case) and raw arguments."""

    line: int
    word: str
    args: tuple


def load_apt(path):
    """Read an APT / CL data file into an :class:`AptProgram`; InputError naming file and line."""
    name = os.fspath(path)
    statements, last_line = _statements(read_text(path), name)
    reader = _Reader(name)
    for line, statement in statements:
        reader.read(_record(line, statement, name))
    return reader.program(last_line)


def _statements(text, name):
    """(first line, text) of each record: comments stripped, continuations joined.

    Also returns the number of the file's last line. Blank and comment-only lines are
    skipped, also inside a continued record.
    """
    lines = re.split(r"\r\n|\r|\n", text)
    if len(lines) > 1 and not lines[-1]:
        lines.pop()  # the final line end does not start another line
    statements, pieces, start = [], [], 0
    for number, raw in enumerate(lines, start=1):
        piece = raw.split("$$", 1)[0].strip()
        if not piece:
            continue
        if not pieces:
            start = number
        continued = piece.endswith("$")
        pieces.append(piece[:-1].strip() if continued else piece)
        if not continued:
            statements.append((start, "".join(pieces)))
            pieces = []
    if pieces:
        raise InputError(f"{name}:{start}: the record ends with the continuation mark '$' "
                         "but the file ends before it is continued")
    return statements, len(lines)


def _record(line, statement, name):
    """Split a statement into major word and arguments.

    ``WORD/a, b, c`` gives the comma-separated arguments, stripped; a statement without
    ``/`` (``RAPID``, ``END-OF-PATH``, ``PARTNO text``) is its first word, with the rest of
    the text, if any, as a single argument.
    """
    head, slash, rest = statement.partition("/")
    if slash:
        word = " ".join(head.split()).upper()
        args = tuple(arg.strip() for arg in rest.split(","))
    else:
        word, *args = statement.split(None, 1)
        word, args = word.upper(), tuple(args)
    if not word:
        raise InputError(f"{name}:{line}: record {statement!r} has no major word before '/'")
    return _Record(line, word, args)


def _number(text):
    """`text` as a finite float if it is an APT number, else None."""
    if _NUMBER.fullmatch(text):
        value = float(text)
        if math.isfinite(value):
            return value
    return None


def _show(value):
    """A value for a message: numbers with %g, None as 'none'."""
    if value is None:
        return "none"
    return f"{value:g}" if isinstance(value, float) else str(value)


class _Reader:
    """The state machine: modal settings and the moves collected, fed one record at a time."""

    def __init__(self, name):
        """Start state: MULTAX off, tool axis (0, 0, 1), mm, global frame, nothing set."""
        self.name = name
        self.multax = False
        self.tlaxis = np.array([0.0, 0.0, 1.0])
        self.axis = self.tlaxis
        self.rapid = False
        self.scale = 1.0
        self.origin = np.zeros(3)
        self.frame = np.eye(3)
        self.feed = math.nan
        self.feed_unit = None
        self.diameter = None
        self.flute_length = None
        self.spindle_rpm = None
        self.moves = 0
        self.tool_paths = 0
        self.points, self.axes, self.lines, self.feeds = [], [], [], []
        self.unknown = {}
        self.warnings = []

    def read(self, record):
        """Apply one record: its handler, silence for known words, else count it as unknown."""
        handler = _HANDLERS.get(record.word)
        if handler is not None:
            handler(self, record)
        elif record.word not in _SILENT:
            first, count = self.unknown.get(record.word, (record.line, 0))
            self.unknown[record.word] = (first, count + 1)

    def program(self, last_line):
        """The AptProgram of everything read; InputError if there is no cutting move."""
        if not self.points:
            reason = "no GOTO record" if self.moves == 0 else "every GOTO follows RAPID"
            raise InputError(f"{self.name}:{last_line}: end of file and no cutting move ({reason})")
        lines = np.array(self.lines, dtype=int)
        try:
            toolpath = Toolpath.from_axes(np.array(self.points), np.array(self.axes))
        except CLPointError as error:
            raise InputError(f"{self.name}:{lines[error.index]}: GOTO: {error.detail}") from None
        feed = np.array(self.feeds, dtype=float)
        for array in (lines, feed):
            array.setflags(write=False)
        unknown = tuple((word, first, count) for word, (first, count) in self.unknown.items())
        return AptProgram(toolpath, self.diameter, self.flute_length, self.spindle_rpm, feed,
                          self.feed_unit, lines, unknown, tuple(self.warnings))

    # Helpers shared by the handlers.

    def error(self, record, message):
        """InputError ``file:line: WORD: message`` for `record`."""
        return InputError(f"{self.name}:{record.line}: {record.word}: {message}")

    def warn(self, record, message):
        """Add the warning ``file:line: WORD: message``."""
        self.warnings.append(f"{self.name}:{record.line}: {record.word}: {message}")

    def numbers(self, record, args):
        """All of `args` as floats; InputError naming the first that is not a number."""
        values = []
        for position, arg in enumerate(args, start=1):
            value = _number(arg)
            if value is None:
                raise self.error(record, f"argument {position} {arg!r} is not a number"
                                 if arg else f"argument {position} is empty")
            values.append(value)
        return values

    def numbers_and_words(self, record):
        """The record's arguments split into numbers and minor words (upper case), in order."""
        numbers, words = [], []
        for position, arg in enumerate(record.args, start=1):
            value = _number(arg)
            if value is not None:
                numbers.append(value)
            elif _WORD.fullmatch(arg):
                words.append(arg.upper())
            else:
                raise self.error(record, f"argument {position} {arg!r} is neither a number nor a word"
                                 if arg else f"argument {position} is empty")
        return numbers, words

    def unit_axis(self, record, values):
        """The axis (i, j, k) normalised; InputError if it is zero."""
        axis = np.array(values)
        norm = np.linalg.norm(axis)
        if norm == 0.0:
            raise self.error(record, "tool axis (0, 0, 0) is zero")
        return axis / norm

    def positive(self, record, label, value):
        """`value` if positive, else InputError naming `label`."""
        if value <= 0.0:
            raise self.error(record, f"{label} must be positive, got {value:g}")
        return value

    def update(self, record, field, value):
        """Set a reported setting; warn if it replaces a different earlier value."""
        old = getattr(self, field)
        if old is not None and old != value:
            self.warn(record, f"{field} changes from {_show(old)} to {_show(value)}; "
                      "the last value is reported")
        setattr(self, field, value)

    # Record handlers.

    def on_goto(self, record):
        """A move: cutting unless it follows RAPID; points and axes to the global frame."""
        values = self.numbers(record, record.args)
        if len(values) < 3:
            raise self.error(record, f"needs at least x, y, z, got {len(values)} number(s)")
        if self.multax and len(values) == 6:
            self.axis = self.unit_axis(record, values[3:])
        elif self.multax and len(values) != 3:
            raise self.error(record, f"with MULTAX on takes x,y,z or x,y,z,i,j,k, got {len(values)} numbers")
        elif not self.multax and len(values) != 3:
            raise self.error(record, f"takes x,y,z without MULTAX, got {len(values)} numbers "
                             "(a five-axis file needs MULTAX/ON before its moves)")
        elif not self.multax:
            self.axis = self.tlaxis
        self.moves += 1
        if self.rapid:
            self.rapid = False
            return
        point = np.array(values[:3]) * self.scale
        self.points.append(self.origin + point @ self.frame)
        self.axes.append(self.axis @ self.frame)
        self.lines.append(record.line)
        self.feeds.append(self.feed)

    def on_rapid(self, record):
        """RAPID: the next GOTO is a rapid move."""
        if record.args:
            raise self.error(record, f"takes no arguments, got {','.join(record.args)!r}")
        self.rapid = True

    def on_multax(self, record):
        """MULTAX, MULTAX/ON, MULTAX/OFF: whether GOTO records carry the tool axis."""
        words = [arg.upper() for arg in record.args]
        if words not in ([], ["ON"], ["OFF"]):
            raise self.error(record, f"expected ON or OFF, got {','.join(record.args)!r}")
        self.multax = words != ["OFF"]

    def on_tlaxis(self, record):
        """TLAXIS/i,j,k: the fixed tool axis (and the current one under MULTAX)."""
        values = self.numbers(record, record.args)
        if len(values) != 3:
            raise self.error(record, f"needs i, j, k, got {len(values)} number(s)")
        self.tlaxis = self.axis = self.unit_axis(record, values)

    def on_fedrat(self, record):
        """FEDRAT/f, FEDRAT/unit,f or FEDRAT/f,unit: the feed of the following moves."""
        numbers, words = self.numbers_and_words(record)
        if len(numbers) != 1 or len(words) > 1:
            raise self.error(record, "expected a feed rate and at most one unit, "
                             f"got {','.join(record.args)!r}")
        if words and words[0] not in FEED_UNITS:
            raise self.error(record, f"unknown feed unit {words[0]!r} (expected {', '.join(FEED_UNITS)})")
        self.feed = self.positive(record, "feed rate", numbers[0])
        if words:
            self.update(record, "feed_unit", words[0])

    def on_cutter(self, record):
        """CUTTER/d[,r,e,f,a,b,h]: diameter, and flute length h in the 7-parameter form."""
        values = self.numbers(record, record.args)
        if not 1 <= len(values) <= 7:
            raise self.error(record, f"expected 1 to 7 numbers d,r,e,f,a,b,h, got {len(values)}")
        length = values[6] if len(values) == 7 else None
        self.set_tool(record, values[0], values[1] if len(values) > 1 else 0.0, length)

    def on_tldata(self, record):
        """TLDATA/MILL,d,r,h,...: diameter d, length h as flute length; other kinds are not read."""
        kind = record.args[0].upper() if record.args else ""
        if kind != "MILL":
            self.warn(record, f"only TLDATA/MILL gives the tool size; TLDATA/{kind} is not read")
            return
        values = self.numbers(record, record.args[1:])
        if not values:
            raise self.error(record, "MILL needs at least the diameter")
        self.set_tool(record, values[0], values[1] if len(values) > 1 else 0.0,
                  values[2] if len(values) > 2 else None)

    def set_tool(self, record, diameter, radius, length):
        """Record a tool description (file units): sizes to mm, warn on a corner radius."""
        diameter = self.positive(record, "diameter", diameter) * self.scale
        if length is not None:
            length = self.positive(record, "flute length", length) * self.scale
        if radius != 0.0:
            self.warn(record, f"corner radius {radius:g} is ignored: the engine models a flat-end mill")
        self.update(record, "diameter", diameter)
        self.update(record, "flute_length", length)

    def on_spindl(self, record):
        """SPINDL/rpm, SPINDL/RPM,rpm[,CLW|CCLW] in any order, SPINDL/ON|OFF."""
        numbers, words = self.numbers_and_words(record)
        strange = [word for word in words if word not in _SPINDLE_WORDS]
        if strange:
            raise self.error(record, f"unknown word {strange[0]!r} (expected {', '.join(_SPINDLE_WORDS)})")
        if len(numbers) > 1:
            raise self.error(record, f"expected one speed, got {len(numbers)} numbers")
        if numbers:
            self.update(record, "spindle_rpm", self.positive(record, "spindle speed", numbers[0]))

    def on_units(self, record):
        """UNITS/INCHES or UNITS/MM: the length unit of the following records."""
        word = record.args[0].upper() if len(record.args) == 1 else ""
        if word not in _LENGTH_UNITS:
            raise self.error(record, f"expected INCHES or MM, got {','.join(record.args)!r}")
        self.scale = _LENGTH_UNITS[word]
        if self.scale != 1.0:
            self.warn(record, "coordinates and tool sizes that follow are converted from inches to mm "
                      "(feeds keep the file's unit)")

    def on_msys(self, record):
        """MSYS/origin, X axis, Y axis: the local frame of the following records."""
        values = self.numbers(record, record.args)
        if len(values) != 9:
            raise self.error(record, f"needs 9 numbers (origin, X axis, Y axis), got {len(values)}")
        x_axis, y_axis = np.array(values[3:6]), np.array(values[6:9])
        for label, axis in (("X", x_axis), ("Y", y_axis)):
            if abs(np.linalg.norm(axis) - 1.0) > _FRAME_TOLERANCE:
                raise self.error(record, f"{label} axis {axis.tolist()} is not a unit vector")
        if abs(x_axis @ y_axis) > _FRAME_TOLERANCE:
            raise self.error(record, f"X axis {x_axis.tolist()} and Y axis {y_axis.tolist()} "
                             "are not orthogonal")
        x_axis = x_axis / np.linalg.norm(x_axis)
        y_axis = y_axis - (y_axis @ x_axis) * x_axis
        y_axis = y_axis / np.linalg.norm(y_axis)
        self.origin = np.array(values[:3]) * self.scale
        self.frame = np.array([x_axis, y_axis, np.cross(x_axis, y_axis)])
        if self.origin.any() or not np.array_equal(self.frame, np.eye(3)):
            self.warn(record, "CL points and tool axes that follow are moved from this local frame "
                      "to the global frame")

    def on_tool_path(self, record):
        """TOOL PATH/...: the start of an operation; a second one is appended to the same pass."""
        self.tool_paths += 1
        if self.tool_paths == 2:
            self.warn(record, "a second operation: its moves are appended to the same toolpath")

    def on_cycle(self, record):
        """CYCLE/...: warn that the GOTO points of a canned cycle are read as plain moves."""
        if [arg.upper() for arg in record.args] != ["OFF"]:
            self.warn(record, "the GOTO points of a canned cycle are read as plain cutting moves")


_HANDLERS = {
    "GOTO": _Reader.on_goto,
    "RAPID": _Reader.on_rapid,
    "MULTAX": _Reader.on_multax,
    "TLAXIS": _Reader.on_tlaxis,
    "FEDRAT": _Reader.on_fedrat,
    "CUTTER": _Reader.on_cutter,
    "TLDATA": _Reader.on_tldata,
    "SPINDL": _Reader.on_spindl,
    "UNITS": _Reader.on_units,
    "MSYS": _Reader.on_msys,
    "TOOL PATH": _Reader.on_tool_path,
    "CYCLE": _Reader.on_cycle,
}
