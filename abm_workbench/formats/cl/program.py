"""A CL program as read: its operations, each with tool, spindle, feeds, frames and CL points.

Shapes: n cutting CL points per operation; points (n, 3) mm, axes (n, 3) unit vectors, feed
(n,), lines (n,) 1-based source lines. Frames are (R (3, 3), t (3,)) pairs, ``part = R @ file + t``.
"""

from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from ...engine import Toolpath
from ...errors import CLPointError, InputError
from .frames import IDENTITY, engine_frame
from .tools import ToolSpec

#: Tool kinds the engine computes: flat-end mills, and tools a file does not describe.
MILLING_KINDS = ("flat", "unknown")


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
    kinds used (``"DRILL"``, ``"TAP"`` ...), in order.
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

    @property
    def points_part(self):
        """(n, 3) cutting CL points in the part frame, mm."""
        rotation, translation = self.to_part
        return self.points_file @ rotation.T + translation

    @property
    def axes_part(self):
        """(n, 3) unit tool axes in the part frame."""
        return self.axes_file @ self.to_part[0].T

    def label(self):
        """``operation N (NAME)``: how messages name the operation."""
        return f"operation {self.number}" + (f" ({self.name})" if self.name else "")

    def engine_frame(self):
        """(R, t) from part coordinates to the frame the engine works in for this operation.

        The operation's own frame (MCS / setup), in which its tool axes point up (see
        :mod:`.frames`). InputError naming the operation, the line and the reason for a CL
        point whose axis turns 90 degrees or more from that frame.
        """
        frame, bad = engine_frame(self.to_part, self.axes_file)
        if bad is not None:
            axis = ", ".join(f"{v:.6g}" for v in self.axes_file[bad])
            written = f"the frame of {self.frame}" if self.frame else "the file's frame (no MSYS, CSYS or ROTABL)"
            raise InputError(f"{self.source}:{self.lines[bad]}: {self.label()}: tool axis ({axis}), written in "
                             f"{written}, turns 90 degrees or more from the operation's frame (its axes span more "
                             "than a half-space), so the engine, which needs the tool pointing up in one frame per "
                             "operation, cannot take it")
        return frame

    def toolpath(self):
        """The engine :class:`Toolpath` of the cutting moves in :meth:`engine_frame` coordinates."""
        if len(self.lines) == 0:
            raise InputError(f"{self.source}:{self.first_line}: {self.label()}: no cutting moves")
        rotation, translation = self.engine_frame()
        points = self.points_part @ rotation.T + translation
        axes = self.axes_part @ rotation.T
        try:
            return Toolpath.from_axes(points, axes)
        except CLPointError as error:
            raise InputError(f"{self.source}:{self.lines[error.index]}: {self.label()}: {error.detail}") from None

    def refusal(self):
        """None for a flat-end milling operation with cutting moves, else the plain reason."""
        if self.tool.kind not in MILLING_KINDS:
            what = "turning program" if self.tool.kind == "turning" else self.tool.describe()
            return f"operation {self.number}: {what}: the ABM engine is for flat-end mills"
        if len(self.lines) == 0:
            holes = len(self.cycle_points) if self.cycle_points is not None else 0
            extra = f" ({holes} canned-cycle hole positions)" if holes else ""
            return f"operation {self.number}: no cutting moves{extra}"
        return None

    def summary(self):
        """(number, name, tool, points) in words, for listing operations."""
        return f"{self.number}: {self.name or '-'}, {self.tool.describe()}, {len(self.lines)} CL points"


@dataclass(frozen=True, eq=False)
class Program:
    """A CL program: source file, units as written ("mm" or "inch"), operations (tuple, file
    order), ignored ({major word: (first line, count)} of records known to carry nothing the
    engine needs), unknown (the same for records not understood), warnings (list of
    ``"file:line: ..."``), format ("apt" or "csv"), text (the file's text, for rewriting),
    last_line (the file's number of lines), encoding (the text's, for rewriting)."""

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

    def milling(self):
        """The operations the engine can run: flat-end mills (or undescribed tools) with cutting moves."""
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
        listing = "; ".join(op.summary() + ("" if op.refusal() is None else " (not milling)")
                            for op in self.operations)
        if milling:
            reason = f"{len(milling)} milling operations; choose one with --operation N"
        else:
            reason = "no operation the engine can run: " + "; ".join(op.refusal() for op in self.operations)
        raise OperationChoiceError(f"{self.source}: {reason}; operations: {listing}", self.operations)
