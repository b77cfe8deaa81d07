"""APT / CL files as one pass for the engine: a thin adapter over :mod:`abm_workbench.formats.cl`.

:func:`load_apt` reads the file with :func:`abm_workbench.formats.cl.read_program` (every
dialect and record that package reads; docs/CL_FILES.md), takes its single milling operation
(an :class:`~abm_workbench.formats.cl.OperationChoiceError`, an InputError listing the
operations, when there are several or none) and gives its cutting moves in the part frame
(MSYS / CSYS / ROTABL applied) with what the file says about tool, spindle and feed.
"""

import os
from dataclasses import dataclass
from typing import Optional

import numpy as np

from ..engine import Toolpath
from ..errors import CLPointError, InputError
from .cl import read_program
from .cl.units import MM_PER_INCH

__all__ = ["AptProgram", "MM_PER_INCH", "load_apt"]


@dataclass(frozen=True, eq=False)
class AptProgram:
    """The cutting moves of the milling operation of an APT / CL file, and its tool, feed and spindle.

    toolpath: the m cutting moves (rapids and canned-cycle holes left out; arcs and curves
    interpolated), CL points in mm, part frame.
    diameter, flute_length: tool sizes in mm where the file gives them, else None.
    spindle_rpm: the operation's spindle speed (rpm), or None.
    feed: (m,) feed at each cutting move in feed_unit ("MMPM" mm/min or "MMPR" mm/rev, inch
    feeds converted); NaN before any FEDRAT. feed_unit: None when the file gives no feed.
    line_numbers: (m,) 1-based line of the record of each CL point.
    unknown: (major word, first line, count) of each record kind not understood, in file order.
    warnings: messages ``file:line: ...`` about what was converted, assumed or changed.
    operation: the operation's 1-based number in the program.
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
    operation: int = 1


def load_apt(path, operation=None):
    """Read operation `operation` (1-based; None: the single milling one) of an APT / CL file.

    InputError naming file and line for a record that cannot be read, a file without cutting
    moves, or a choice of operation that has to be made (OperationChoiceError).
    """
    name = os.fspath(path)
    program = read_program(name)
    if not any(len(op.lines) for op in program.operations):
        moved = any(len(op.rapids) or len(op.cycle_points) for op in program.operations)
        reason = "every GOTO is a rapid move or a canned-cycle hole" if moved else "no GOTO record"
        raise InputError(f"{name}:{program.last_line}: end of file and no cutting move ({reason})")
    op = program.operation(operation)
    refusal = op.refusal()
    if refusal is not None:
        raise InputError(f"{name}: {refusal}")
    try:
        toolpath = Toolpath.from_axes(op.points_part, op.axes_part)
    except CLPointError as error:
        raise InputError(f"{name}:{op.lines[error.index]}: GOTO: {error.detail}") from None
    unknown = tuple((word, first, count) for word, (first, count) in program.unknown.items())
    return AptProgram(toolpath, op.tool.diameter, op.tool.flute_length, op.spindle_rpm, op.feed, op.feed_unit,
                      op.lines, unknown, tuple(program.warnings), op.number)
