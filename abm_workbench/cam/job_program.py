"""A FreeCAD CAM Job as a program: its operations in order, read as its post-processors read them.

The Job's active operations (a dressup in place of the operation it dresses) become the
program's operations, in the Job's order, each named by its label. Their commands go through the
G-code interpreter (formats.gcode.interpreter) as a post writes them: before an operation whose tool
controller differs from the one before, the controller's own commands (``M6 T…``, ``M3 S…``), the
controller's tool being the tool of its number (cam.toolbits); then the operation's commands. F,
which FreeCAD keeps in mm/s, is read in mm/min; an F on a rapid, or of 0, is left out as the posts
leave it out. Coordinates are the document's, the frame of the Job's Stock and Model (the posts
write them as they are; the Job's fixtures G54… are not applied). The Job's Stock is the
program's stock (Program.stock).

Each CL point's line is the 1-based number of the command of its operation's Path that made it;
messages name ``FILE#JOB: OPERATION: command N``.
"""

import re
from dataclasses import replace

from ..errors import InputError
from ..formats.gcode.blocks import Block, Word
from ..formats.gcode.interpreter import Interpreter
from .freecad_cam import is_active, operations, tool_controller
from .toolbits import controller_tool

_NAME = re.compile(r"([A-Za-z])([0-9]+(?:\.[0-9]+)?)")
#: F in FreeCAD's commands is mm/s; the posts and this reader take mm/min.
_SECONDS_PER_MINUTE = 60.0


def job_program(job, path, tolerance, step):
    """The Program of CAM `job` (a document object) of the document at `path` (its name in messages);
    arcs to `tolerance` mm, their CL points at most `step` mm apart. InputError naming the operation and
    the command for anything the interpreter cannot take."""
    source = f"{path}#{job.Label}"
    place = {"what": ""}
    interpreter = Interpreter(source, lambda line: f"{source}: {place['what']}: command {line}", tolerance, step,
                              tools={}, tools_source=f"{path} (its tool controllers)")
    warnings, current = [], None
    for op in operations(job):
        if not is_active(op):
            continue
        interpreter.collector.boundary(1, op.Label)
        controller = tool_controller(op)
        if controller is not None and controller is not current:
            tool, warning = controller_tool(controller)
            if warning and warning not in warnings:
                warnings.append(warning)
            interpreter.tools[int(controller.ToolNumber)] = tool
            place["what"] = controller.Label
            _run(interpreter, controller.Path.Commands)
            current = controller
        place["what"] = op.Label
        _run(interpreter, op.Path.Commands)
    program = interpreter.program("", 0, "fcstd")
    stock = getattr(job, "Stock", None)
    return replace(program, warnings=[f"{source}: {warning}" for warning in warnings] + program.warnings,
                   stock=stock.Name if stock is not None else "")


def job_fingerprint(job):
    """What job_program reads of `job`, as a value that compares equal while none of it changes: each
    operation's name, label, activity and commands, its tool controller's commands and tool."""
    parts = []
    for op in operations(job):
        controller = tool_controller(op)
        held = None if controller is None else (controller.Name, int(controller.ToolNumber),
                                                controller.Path.toGCode(), controller_tool(controller))
        parts.append((op.Name, op.Label, is_active(op), op.Path.toGCode(), held))
    return tuple(parts)


def _run(interpreter, commands):
    """Run Path `commands` through `interpreter`, numbered from 1."""
    for number, command in enumerate(commands, start=1):
        interpreter.run(command_block(command, number, interpreter.where))


def command_block(command, line, where):
    """The Block of a Path command (its name and parameters) on `line`; where(line) names it in errors."""
    name = command.Name.strip()
    if name.startswith("("):
        return Block(line, (), (name.strip("()").strip(),))
    match = _NAME.fullmatch(name)
    if match is None:
        raise InputError(f"{where(line)}: {name}: not a G-code command")
    words = [Word(match.group(1).upper(), float(match.group(2)), name)]
    rapid = words[0].letter == "G" and words[0].value == 0.0
    for key, value in command.Parameters.items():
        letter = key.upper()
        if letter == "F":
            if rapid or value <= 0.0:
                continue
            value = value * _SECONDS_PER_MINUTE
        words.append(Word(letter, float(value), f"{letter}{value:g}"))
    return Block(line, tuple(words), ())
