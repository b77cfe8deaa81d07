"""CL files as CAM systems write them: APT / CLDATA text, NX CLSF, CATIA, Creo NCL, SOLIDWORKS
CAM / CAMWorks, Mastercam and PowerMill APT, and the project's toolpath CSV; G-code
(formats.gcode) and FreeCAD CAM Jobs (abm_workbench.cam) read into the same programs.

:func:`read_program` reads a file (by its content, whatever its name) into a :class:`Program`
of :class:`Operation` objects; docs/CL_FILES.md tells which records are read and what each
becomes, docs/GCODE.md the same of G-code. Lengths in mm, angles in degrees, feeds in mm/min or
mm/rev, spindle in rpm.

Modules: :mod:`.sniff` (content), :mod:`.lexer` (records), :mod:`.reader` (the modal state
machine), :mod:`.arcs` (CIRCLE), :mod:`.nurbs` (NX NURBS), :mod:`.units`, :mod:`.tools`,
:mod:`.frames`, :mod:`.program` (the dataclasses), :mod:`.csv_program` (the toolpath CSV),
:mod:`.summary` (the ``toolpath`` command's lines and CSV), :mod:`.rewrite` (feeds written back),
:mod:`.feed_style` (FEDRAT written as the file writes it).
"""

import os
from dataclasses import replace

from ...errors import InputError
from .arcs import MIN_TOLERANCE, interpolation_budget
from .sniff import read_file

#: Default chordal tolerance (mm) of interpolated arcs and curves.
TOLERANCE = 0.001
#: Default largest distance (mm) between the CL points along arcs and curves: about a tooth's feed.
STEP = 0.1


def read_program(path, tolerance=TOLERANCE, step=STEP, options=None):
    """The :class:`Program` of the CL file, toolpath CSV, G-code or FreeCAD document (its CAM Job) at `path`;
    arcs and curves to `tolerance` mm, their CL points at most `step` mm apart; options: a
    formats.gcode.options.ReadOptions (the CAM Job's name, tool table, machine, work offsets) or None.
    InputError naming the file (and line) for anything unreadable."""
    name = os.fspath(path)
    if not tolerance >= MIN_TOLERANCE:
        raise InputError(f"{name}: the chordal tolerance must be at least {MIN_TOLERANCE:g} mm, got {tolerance:g} mm")
    if not step >= MIN_TOLERANCE:
        raise InputError(f"{name}: the step along arcs and curves must be at least {MIN_TOLERANCE:g} mm, got "
                         f"{step:g} mm")
    with interpolation_budget():
        return _read_program(name, tolerance, step, options)


def _read_program(name, tolerance, step, options):
    """read_program of a file whose tolerance and step are checked."""
    kind, text, encoding = read_file(name)
    if options is not None:
        options.check(kind, name)
    if kind == "fcstd":
        from ...cam.documents import read_job_file  # FreeCAD only for a document

        return read_job_file(name, options, tolerance, step)
    if kind == "gcode":
        from ..gcode.reader import read_gcode_text

        return replace(read_gcode_text(text, name, tolerance, step, options), encoding=encoding)
    if kind == "csv":
        from .csv_program import read_csv_program

        return read_csv_program(name, text)
    from .reader import read_cl_text  # here: a toolpath CSV needs none of the CL state machine

    return replace(read_cl_text(text, name, tolerance, step), encoding=encoding)


def __getattr__(name):
    """The names this package gives from its modules, each module imported when first asked for."""
    if name in ("Moves", "Operation", "OperationChoiceError", "Program"):
        from . import program as module
    elif name in ("rewritten_text", "write_rescheduled_program"):
        from . import rewrite as module
    elif name == "ToolSpec":
        from . import tools as module
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(module, name)


__all__ = ["Moves", "Operation", "OperationChoiceError", "Program", "STEP", "TOLERANCE", "ToolSpec", "read_program",
           "rewritten_text", "write_rescheduled_program"]
