"""A CL program written back with one operation's feeds changed and every other record as it was.

:func:`rewritten_text` walks the file's records: before each cutting move of the chosen
operation whose new feed differs from the feed in force in the output, it inserts a FEDRAT
record (in the file's feed unit at that move: MMPM, MMPR, IPM or IPR); before the first cutting
move outside the operation after that, it inserts the feed the file had in force there, its
number as the file wrote it, so the rest of the program runs as written. A CIRCLE arc gets its
FEDRAT before the CIRCLE record, a NURBS curve before the NURBS record.

Each inserted record is written as the file's own CAM system writes FEDRAT (:mod:`.feed_style`),
learnt from the FEDRAT in force before it, else from the file's first FEDRAT: case, blanks,
order, unit word (none when the file writes none and the reader would take the bare number in
the right unit), decimals and number form. A new feed is rounded down at the file's decimals,
so it never exceeds the feed asked for; one that would round to 0 is refused. Nothing else
changes: the file's lines, comments and line ends are kept byte for byte.
"""

import os
import re

import numpy as np

from ...errors import InputError
from .. import replacing
from .feed_style import FileNumbers, default_style, number_text, record_text, rounded_down, style_of, unit_word, \
    value_text
from .lexer import lex
from .units import MM_PER_INCH, feed_from_mm

_MOTION = ("GOTO", "GODLTA", "NURBS")
#: A line with its line end, as the lexer counts lines (CR, LF or CRLF, nothing else).
_LINE = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+")


def _line_end(text):
    """The first line end of `text` ("\\n" when it has none)."""
    match = re.search(r"\r\n|\r|\n", text)
    return match.group() if match else "\n"


def rewritten_text(program, number, feed):
    """The text of `program` with operation `number`'s cutting feeds set to `feed` (n,).

    feed: per cutting CL point, in the operation's feed_unit ("MMPM" mm/min or "MMPR"
    mm/rev); a move interpolated into several points (an arc, a curve) gets the lowest of them.
    InputError naming the operation and line when a feed rounds down to 0 at the file's decimals.
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
    lines = _LINE.findall(program.text)
    styles = _Styles(records, lines)
    inserts = {}
    scale, unit, in_force, written, circle_line, source = 1.0, None, None, None, None, None
    for record in records:
        word = record.word
        if word in ("UNITS", "UNIT") and record.args:
            scale = MM_PER_INCH if record.args[0].upper().startswith("INCH") else 1.0
        elif word == "FEDRAT" and value_text(record) is not None:   # the reader keeps the feed of one without
            unit = (unit_word(record) or _file_unit(None, scale, unit in ("MMPR", "IPR"))).upper()
            source, in_force = record, (value_text(record), unit)
            written = (float(in_force[0]), unit)
        elif word == "CIRCLE":
            circle_line = record.line
        elif word in _MOTION and record.line in cutting:
            at = circle_line if (word == "GOTO" and circle_line is not None) else record.line
            style = styles.at(source)
            if record.line in wanted:
                file_unit = _file_unit(unit, scale, per_rev)
                target = (_feed_text(wanted[record.line], file_unit, style, op, record, program.source), file_unit)
            else:
                target = in_force
            if target is not None and (float(target[0]), target[1]) != written:
                inserts[at] = _inserted(style, target, written, scale)
                written = (float(target[0]), target[1])
        if word == "GOTO":
            circle_line = None
    end = _line_end(program.text)
    out = []
    for number_, line in enumerate(lines, start=1):
        if number_ in inserts:
            out.append(inserts[number_] + end)
        out.append(line)
    return "".join(out)


class _Styles:
    """The FeedStyle of each FEDRAT record of a file, learnt once: :meth:`at`."""

    def __init__(self, records, lines):
        """records: the file's lexed records; lines: its source lines (with their ends)."""
        self.lines = lines
        self.numbers = FileNumbers.of(records)
        self.first = next((record for record in records if value_text(record) is not None), None)
        self.default = default_style(records, lines) if self.first is None else None
        self.learnt = {}

    def at(self, source):
        """The style of FEDRAT record `source` (the one in force), else of the file's first, else the default."""
        record = source or self.first
        if record is None:
            return self.default
        if record.line not in self.learnt:
            self.learnt[record.line] = style_of(record, self.lines[record.line - 1], self.numbers)
        return self.learnt[record.line]


def _inserted(style, target, written, scale):
    """The FEDRAT record in `style` setting `target` (number text, feed unit word); without its unit
    word when the style writes none and the reader takes a bare number in that unit, after the feed
    `written` (value, unit word, or None) in force in the output, `scale` mm per the file's length unit."""
    bare = _file_unit(None, scale, written is not None and written[1] in ("MMPR", "IPR"))
    return record_text(style, target[0], None if style.order == "bare" and target[1] == bare else target[1])


def _feed_text(value, unit, style, op, record, source):
    """The number text of the feed `value` (mm/min or mm/rev) in the file's feed unit word `unit`,
    rounded down at the style's decimals; InputError naming the operation and line if that is 0."""
    exact = feed_from_mm(value, unit)
    rounded = rounded_down(exact, style.decimals)
    if not rounded:
        raise InputError(f"{source}:{record.line}: {op.label()}: the feed {exact:.6g} {unit} rounds down to 0 "
                         f"at the {style.decimals} decimals this file writes its feeds with")
    return number_text(rounded, style)


def _file_unit(unit, scale, per_rev):
    """The feed unit word to write: per revolution or minute as `per_rev` says, in inches when
    `unit` (the file's unit in force, or None) is an inch unit or, without one, when `scale` is."""
    inch = unit in ("IPM", "IPR") if unit else scale != 1.0
    return ("IPR" if per_rev else "IPM") if inch else ("MMPR" if per_rev else "MMPM")


def write_rescheduled_program(path, program, number, feed):
    """Write :func:`rewritten_text` to `path`, whole or not at all; returns the path."""
    name = os.fspath(path)
    text = rewritten_text(program, number, feed)
    with replacing(name) as (temporary,):
        with open(temporary, "w", encoding=program.encoding, newline="") as file:
            file.write(text)
    return name
