"""A CL program as read: its operations, each with tool, spindle, feeds, frames and CL points.

Shapes: n cutting CL points per operation; points (n, 3) mm, axes (n, 3) unit vectors, directions
(n, 3) of the tool's motion arriving at each point, feed (n,), lines (n,) 1-based source lines.
Frames are (R (3, 3), t (3,)) pairs, ``part = R @ file + t``.
"""

from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from ...engine import Toolpath
from ...engine.feed import feed_frame, inclinations
from ...errors import CLPointError, InputError, note
from .frames import IDENTITY, engine_frame
from .tools import ToolSpec

#: Tool kinds the engine computes: flat-end, bull-nose and ball-end mills, and tools a file does not describe.
ENGINE_KINDS = ("flat", "bull-nose", "ball", "unknown")


@dataclass(frozen=True, eq=False)
class Moves:
    """Positions that are not cutting moves (rapids, canned-cycle holes): points (k, 3) mm in the
    file frame, axes (k, 3), lines (k,) 1-based."""

    points: np.ndarray
    axes: np.ndarray
    lines: np.ndarray

    def __len__(self):
        return int(len(self.lines))


class OperationChoiceError(InputError):
    """No operation was named and the program has no single milling operation.

    operations: the program's operations (tuple of :class:`Operation`), to word the choice.
    """

    def __init__(self, message, operations):
        super().__init__(message)
        self.operations = tuple(operations)


@dataclass(frozen=True, eq=False)
class Operation:
    """One operation of a CL program (one tool change or CAM operation boundary).

    number: 1-based. name: the CAM operation's name, or "". tool: :class:`ToolSpec`.
    spindle_rpm: rpm or None. feed: (n,) at each cutting point in feed_unit ("MMPM" mm/min or
    "MMPR" mm/rev; NaN before any FEDRAT), feed_unit None when the file gives none.
    lines: (n,). points_file, axes_file: (n, 3) cutting CL points and unit tool axes in the
    file frame, mm. to_part: (R, t). frame: words naming the frame records ("" for none).
    rapids, cycle_points: :class:`Moves`. arcs, curves: CIRCLE and NURBS moves interpolated.
    source: the file. first_line: the line the operation starts on. cycles: the canned-cycle
    kinds used (``"DRILL"``, ``"TAP"`` ...), in order. directions_file: (n, 3) the direction of the
    tool tip's motion arriving at each cutting point (the chord of a straight move, the tangent of
    an arc or curve; zero where no motion arrives), file frame; None: the chords between the points.
    single_pass: a pass a user gives on its own (a toolpath CSV without an operation column), whose
    cut thickness takes the job's one inclination, as the paper's pass does, not each move's.
    inclination: (n,) the tool's inclination to the feed at each cutting point (deg) where the file
    writes it (a toolpath CSV's column), else None.
    """

    number: int
    name: str
    tool: ToolSpec
    spindle_rpm: Optional[float]
    feed: np.ndarray
    feed_unit: Optional[str]
    lines: np.ndarray
    points_file: np.ndarray
    axes_file: np.ndarray
    to_part: tuple = IDENTITY
    frame: str = ""
    rapids: Moves = None
    cycle_points: Moves = None
    arcs: int = 0
    curves: int = 0
    source: str = ""
    first_line: int = 1
    cycles: tuple = field(default=())
    directions_file: np.ndarray = None
    single_pass: bool = False
    inclination: np.ndarray = None

    @property
    def points_part(self):
        """(n, 3) cutting CL points in the part frame, mm."""
        rotation, translation = self.to_part
        return self.points_file @ rotation.T + translation

    @property
    def axes_part(self):
        """(n, 3) unit tool axes in the part frame."""
        return self.axes_file @ self.to_part[0].T

    @property
    def directions_part(self):
        """(n, 3) directions of the motion arriving at each cutting point, part frame (module docstring)."""
        if self.directions_file is None:
            directions = np.zeros_like(self.points_file)
            directions[1:] = np.diff(self.points_file, axis=0)
        else:
            directions = self.directions_file
        return directions @ self.to_part[0].T

    def label(self):
        """``operation N (NAME)``: how messages name the operation."""
        return f"operation {self.number}" + (f" ({self.name})" if self.name else "")

    def engine_frame(self):
        """(R, t) from part coordinates to the frame the engine works in for this operation: the operation's
        own frame (MCS / setup), or one its tool axes point up in on the whole (see :mod:`.frames`)."""
        return engine_frame(self.to_part, self.axes_file)

    def toolpath(self, frame=None):
        """The engine :class:`Toolpath` of the cutting moves in `frame` ((R, t) part -> engine; None:
        :meth:`engine_frame`) coordinates, each CL point's frame turned to its feed (engine.feed) and
        its inclination to that feed its own (the job's one value for a single pass)."""
        if len(self.lines) == 0:
            raise InputError(f"{self.source}:{self.first_line}: {self.label()}: no cutting moves")
        rotation, translation = self.engine_frame() if frame is None else frame
        points = self.points_part @ rotation.T + translation
        axes = self.axes_part @ rotation.T
        alpha, feed = feed_frame(self.directions_part @ rotation.T)
        inclination = self.inclination
        if inclination is None and not self.single_pass:
            inclination = inclinations(axes / np.linalg.norm(axes, axis=1)[:, None], feed)
        try:
            return Toolpath.from_axes(points, axes, alpha=alpha, inclination=inclination)
        except CLPointError as error:
            raise InputError(f"{self.source}:{self.lines[error.index]}: {self.label()}: {error.detail}") from None

    def refusal(self):
        """None for a milling operation of a flat-end, bull-nose or ball-end mill with cutting moves, else
        the plain reason, naming the tool's kind as it is (a tapered mill is a milling tool the engine does
        not compute yet; a drill, tap or turning tool is no milling tool)."""
        if self.tool.kind not in ENGINE_KINDS:
            what = self.tool.describe()
            if self.tool.milling:
                reason = ("a milling tool the ABM engine does not compute yet (it computes flat-end, bull-nose "
                          "and ball-end mills)")
            elif self.tool.kind in ("turning", "grooving"):
                reason = "a turning program, not milling"
            else:
                reason = "not a milling tool (the ABM engine computes flat-end, bull-nose and ball-end mills)"
            return note(f"operation {self.number}: {what}: {reason}")
        if len(self.lines) == 0:
            holes = len(self.cycle_points) if self.cycle_points is not None else 0
            if holes:
                return note(f"operation {self.number}: no cutting moves ({holes} canned-cycle hole positions)")
            return note(f"operation {self.number}: no cutting moves")
        return None

    def summary(self):
        """(number, name, tool, points) in words, for listing operations."""
        return f"{self.number}: {self.name or '-'}, {self.tool.describe()}, {len(self.lines)} CL points"


@dataclass(frozen=True, eq=False)
class Program:
    """A CL program: source file, units as written ("mm" or "inch"), operations (tuple, file
    order), ignored ({major word: (first line, count)} of records known to carry nothing the
    engine needs), unknown (the same for records not understood), warnings (list of
    ``"file:line: ..."``), format ("apt", "csv", "gcode" or "fcstd": a FreeCAD CAM Job), text (the
    file's text, for rewriting), last_line (the file's number of lines), encoding (the text's, for
    rewriting), stock (the name of the object of the file that holds the program's stock solid: a
    CAM Job's Stock; "" for none)."""

    source: str
    units: str
    operations: tuple
    ignored: dict
    unknown: dict
    warnings: list
    format: str = "apt"
    text: str = field(default="", repr=False)
    last_line: int = 0
    encoding: str = "utf-8"
    stock: str = ""

    def milling(self):
        """The operations the engine can run: flat-end, bull-nose and ball-end mills (or undescribed tools)
        with cutting moves."""
        return tuple(op for op in self.operations if op.refusal() is None)

    def operation(self, n=None):
        """Operation `n` (1-based), or with n None the single milling operation.

        OperationChoiceError (an InputError listing every operation) when n is None and there
        is not exactly one milling operation; InputError when n is out of range.
        """
        if n is not None:
            if not 1 <= int(n) <= len(self.operations):
                raise InputError(f"{self.source}: operation {n}: the program has operations 1 to "
                                 f"{len(self.operations)}")
            return self.operations[int(n) - 1]
        milling = self.milling()
        if len(milling) == 1:
            return milling[0]
        if not self.operations:
            raise OperationChoiceError(f"{self.source}: no operation: the file has no moves", ())
        listing = "; ".join(op.summary() + ("" if op.refusal() is None else " (not for the engine)")
                            for op in self.operations)
        if milling:
            reason = f"{len(milling)} milling operations; choose one with --operation N"
        else:
            refusals = "; ".join(op.refusal() for op in self.operations)
            reason = f"no operation the engine can run: {refusals}"
        raise OperationChoiceError(f"{self.source}: {reason}; operations: {listing}", self.operations)
