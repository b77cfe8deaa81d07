"""A G-code file's text into a :class:`~abm_workbench.formats.cl.program.Program` (docs/GCODE.md).

The tools of its T words come from the tool table of the options (a LinuxCNC tool table, or the
FreeCAD document that posted the program), the kinematics of its rotary words from the machine
file, the work offsets from the offsets file (all zero without one).
"""

import math
import os

from ...errors import InputError
from .. import check_input_file
from ..cl.lexer import split_lines
from ..cl.units import MM_PER_INCH
from .blocks import blocks_of_text
from .interpreter import Interpreter
from .machine import load_machine
from .offsets import load_offsets
from .options import ReadOptions
from .tool_table import load_tool_table

#: The start of a zip file: a tool table given as a FreeCAD document.
_ZIP = b"PK\x03\x04"


def read_gcode_text(text, name, tolerance, step=math.inf, options=None):
    """The Program of G-code `text` read from file `name`; arcs to `tolerance` mm, their CL points at most
    `step` mm apart; options a ReadOptions (None: no tool table, machine or offsets). InputError
    ``file:line: word: reason`` for anything the reader cannot take."""
    options = options or ReadOptions()
    scale = MM_PER_INCH if options.machine_units == "inch" else 1.0
    unitless = []  # the files whose numbers are in the machine's units
    tools, tools_source = None, ""
    if options.tool_table is not None:
        tools_source = os.fspath(options.tool_table)
        tools, in_machine_units = load_tools(tools_source, scale)
        unitless += [tools_source] if in_machine_units else []
    machine = None if options.machine is None else load_machine(options.machine)
    offsets = None
    if options.offsets is not None:
        offsets, in_machine_units = load_offsets(options.offsets, scale)
        unitless += [os.fspath(options.offsets)] if in_machine_units else []
    interpreter = Interpreter(name, lambda line: f"{name}:{line}", tolerance, step, tools, tools_source, machine,
                              offsets)
    for block in blocks_of_text(text, name):
        interpreter.run(block)
    if unitless and options.machine_units is None and interpreter.first_inch is not None:
        files = " and ".join(os.path.basename(file) for file in unitless)
        raise interpreter.error(interpreter.first_inch, "G20", f"the program works in inches, and {files} "
                                f"{'give' if len(unitless) > 1 else 'gives'} lengths in the machine's units, which "
                                "LinuxCNC does not write in the file: say them (--machine-units mm or inch)")
    return interpreter.program(text, len(split_lines(text)), "gcode")


def load_tools(path, scale=1.0):
    """({tool number: ToolSpec}, in_machine_units) of a tool table: a FreeCAD document's tool controllers (a
    file whose name ends in .FCStd or that is a zip; in mm), else a LinuxCNC tool table (in the machine's
    units: its lengths times `scale`, the machine's unit in mm)."""
    name = os.fspath(path)
    check_input_file(name, "tool table")
    try:
        with open(name, "rb") as file:
            zipped = file.read(4) == _ZIP
    except OSError as error:
        raise InputError(f"{name}: cannot read: {error.strerror or error}") from None
    if zipped or name.lower().endswith(".fcstd"):
        from ...cam.documents import document_tools  # FreeCAD only for a document

        return document_tools(name), False
    return load_tool_table(name, scale), True
