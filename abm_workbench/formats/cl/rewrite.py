"""A CL program written back with one operation's feeds changed and every other record as it was.

:func:`rewritten_text` walks the file's records: before each cutting move of the chosen
operation whose new feed differs from the feed in force in the output, it inserts
``FEDRAT/UNIT,f`` (in the file's feed unit at that move: MMPM, MMPR, IPM or IPR); before the
first cutting move outside the operation after that, it inserts the feed the file had in force
there, so the rest of the program runs as written. A CIRCLE arc gets its FEDRAT before the
CIRCLE record, a NURBS curve before the NURBS record. Nothing else changes: the file's lines,
comments and line ends are kept byte for byte.
"""

import os
import re

import numpy as np

from ...errors import InputError
from .. import replacing
from .lexer import lex
from .units import FEED_UNITS, MM_PER_INCH, feed_from_mm

_MOTION = ("GOTO", "GODLTA", "NURBS")
#: A line with its line end, as the lexer counts lines (CR, LF or CRLF, nothing else).
_LINE = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+")


def _line_end(text):
    """The first line end of `text` ("\\n" when it has none)."""
    for end in ("\r\n", "\n", "\r"):
        position = text.find(end[0])
        if position >= 0:
            return "\r\n" if text.startswith("\r\n", position) else text[position]
    return "\n"


def _format(value):
    """Shortest text reading back as the float `value`."""
    text = repr(float(value) + 0.0)
    return text[:-2] if text.endswith(".0") else text


def rewritten_text(program, number, feed):
    """The text of `program` with operation `number`'s cutting feeds set to `feed` (n,).

    feed: per cutting CL point, in the operation's feed_unit ("MMPM" mm/min or "MMPR"
    mm/rev); a move interpolated into several points (an arc, a curve) gets the lowest of them.
    """
    if program.format != "apt":
        raise InputError(f"{program.source}: only a CL (APT) program can be written back with new feeds")
    op = program.operation(number)
    feed = np.asarray(feed, dtype=float).reshape(-1)
    if feed.shape != op.lines.shape:
        raise ValueError(f"feed has {feed.size} values, operation {op.number} {op.lines.size} cutting CL points")
    if not (np.isfinite(feed).all() and (feed > 0.0).all()):
        raise ValueError("every feed written back must be positive")
    per_rev = op.feed_unit == "MMPR"
    wanted = {}
    for line, value in zip(op.lines.tolist(), feed.tolist()):
        wanted[line] = min(value, wanted.get(line, value))
    cutting = {line for other in program.operations for line in other.lines.tolist()}
    records, _, _ = lex(program.text, program.source)
    inserts = {}
    scale, unit, in_force, written, circle_line = 1.0, None, None, None, None
    for record in records:
        word = record.word
        if word in ("UNITS", "UNIT") and record.args:
            scale = MM_PER_INCH if record.args[0].upper().startswith("INCH") else 1.0
        elif word == "FEDRAT":
            values = [float(a) for a in record.args if _is_number(a)]
            words = [a.upper() for a in record.args if a.upper() in FEED_UNITS]
            unit = words[0] if words else _file_unit(None, scale, unit in ("MMPR", "IPR"))
            if values:
                in_force = written = (values[0], unit)
        elif word == "CIRCLE":
            circle_line = record.line
        elif word in _MOTION and record.line in cutting:
            at = circle_line if (word == "GOTO" and circle_line is not None) else record.line
            if record.line in wanted:
                file_unit = _file_unit(unit, scale, per_rev)
                target = (feed_from_mm(wanted[record.line], file_unit), file_unit)
            else:
                target = in_force
            if target is not None and target != written:
                inserts[at] = f"FEDRAT/{target[1]},{_format(target[0])}"
                written = target
        if word == "GOTO":
            circle_line = None
    lines = _LINE.findall(program.text)
    end = _line_end(program.text)
    out = []
    for number_, line in enumerate(lines, start=1):
        if number_ in inserts:
            out.append(inserts[number_] + end)
        out.append(line)
    return "".join(out)


def _file_unit(unit, scale, per_rev):
    """The feed unit word to write: per revolution or minute as `per_rev` says, in inches when
    `unit` (the file's unit in force, or None) is an inch unit or, without one, when `scale` is."""
    inch = unit in ("IPM", "IPR") if unit else scale != 1.0
    return ("IPR" if per_rev else "IPM") if inch else ("MMPR" if per_rev else "MMPM")


def _is_number(text):
    """Whether `text` is a plain number."""
    try:
        float(text)
    except ValueError:
        return False
    return text.strip().lower() not in ("nan", "inf", "-inf", "+inf", "infinity")


def write_rescheduled_program(path, program, number, feed):
    """Write :func:`rewritten_text` to `path`, whole or not at all; returns the path."""
    name = os.fspath(path)
    text = rewritten_text(program, number, feed)
    with replacing(name) as (temporary,):
        with open(temporary, "w", encoding=program.encoding, newline="") as file:
            file.write(text)
    return name
