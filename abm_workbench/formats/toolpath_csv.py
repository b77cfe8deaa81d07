"""One pass of CL points as CSV: positions in mm, tool orientation as angles or axis vectors.

The header names the columns, in any order, case-insensitive, whitespace trimmed:

- ``x, y, z`` (CL point: centre of the tool's bottom face, mm), and either
- ``theta_a, theta_b`` (rotations about x and y, degrees, |θ| < 90) or
- ``i, j, k`` (tool-axis vector, any length, k > 0);
- optionally ``xc, yc, zc`` (cutter-contact point, mm), all three or none;
- optionally ``feed_x, feed_y, feed_z`` (the direction of the tool's motion arriving at the CL
  point, any length, 0,0,0 where none: the tangent of an arc, as ``toolpath --out`` writes it),
  all three or none;
- optionally ``inclination`` (deg): the tool's inclination to the feed at each CL point, which
  thins the chip (h = f·sin φ·cos inclination); without it the job's one value;
- optionally ``feed_per_tooth`` (mm), ``feed_mm_min``: the feeds a ``schedule`` wrote, skipped here;
- optionally the columns the ``toolpath --out`` command writes: ``operation`` (1-based number of
  the CL file's operation), ``name`` (its CAM name), ``tool`` (its kind: flat, ball, ...),
  ``diameter``, ``corner_radius`` (mm, empty when unknown), ``feed_rate`` with ``feed_unit``
  (MMPM mm/min or MMPR mm/rev, empty before any feed), ``line`` (the CL file's line).

One row per CL point in pass order. Blank lines and lines starting with ``#`` are skipped.
The angles or the axis give the tool axis in the part frame; each CL point's frame is turned
about z to its feed (docs/ENGINE.md, "Frames"): the direction in plan view of the motion
arriving at it, from the feed columns, else from the path of the CC points (whose pass the
paper feeds along +x), else of the CL points (engine.feed).
Numbers in the grammar of :func:`abm_workbench.formats.parse_number`; a field holds at most
:data:`MAX_FIELD` characters.
A file with an ``operation`` column holds several passes: :func:`load_toolpath` takes the one
asked for, or the only one.
"""

import csv
import itertools
import math
import os
import re
from dataclasses import dataclass

import numpy as np

from ..engine import Toolpath
from ..engine.feed import feed_frame, path_directions
from ..errors import CLPointError, InputError
from . import MAX_MAGNITUDE, parse_number, read_text

_POSITION = ("x", "y", "z")
_ANGLES = ("theta_a", "theta_b")
_AXIS = ("i", "j", "k")
_CONTACT = ("xc", "yc", "zc")
_DIRECTION = ("feed_x", "feed_y", "feed_z")
_INCLINATION = "inclination"
_FEEDS = ("feed_per_tooth", "feed_mm_min")
#: Columns of the toolpath command's CSV: numbers (empty allowed where marked) and texts.
OPERATION_NUMBERS = ("operation", "diameter", "corner_radius", "flute_length", "feed_rate", "line")
OPERATION_TEXTS = ("name", "tool", "feed_unit")
_MAY_BE_EMPTY = ("diameter", "corner_radius", "flute_length", "feed_rate")
#: Columns of whole numbers, and the least each may be.
_WHOLE_COLUMNS = {"operation": 1, "line": 0}
_EXAMPLE = "x,y,z,theta_a,theta_b"
#: Longest field and line read (characters): far beyond any number, operation name or row.
MAX_FIELD, MAX_LINE = 1000, 64000


@dataclass(frozen=True, eq=False)
class Table:
    """A toolpath CSV read: source, header (lower-case names), lines (n,) 1-based, numbers
    {column: (n,) float, NaN where empty}, texts {column: list of n str}."""

    source: str
    header: list
    lines: np.ndarray
    numbers: dict
    texts: dict


def load_table(path):
    """The :class:`Table` of a toolpath CSV; InputError naming the file and line.

    The text is read in blocks of about :data:`BLOCK_CHARS` characters (whole lines), so that the
    working memory stays a few times the file's size whatever its length. Each block is read
    column by column where it can be (:func:`_columnwise`); any other block (quotes, a bad field, an
    oversized value) is read line by line, which names the bad line.
    """
    name = os.fspath(path)
    blocks = (block for block in _data_blocks(read_text(path)) if block[1])
    first = next(blocks, None)
    if first is None:
        raise InputError(f"{name}: empty file; expected a header such as {_EXAMPLE!r}")
    header_line, header_text = first[0][0], first[1][0]
    header = [field.strip().lower() for field in _fields(header_text, f"{name}:{header_line}")]
    _columns(header, f"{name}:{header_line}")
    pieces, numbers = [], []
    shared = {column: {} for column in header if column in OPERATION_TEXTS}
    for block_numbers, block_lines in itertools.chain([(first[0][1:], first[1][1:])], blocks):
        if not block_lines:
            continue  # the header's block held only the header
        found = _columnwise(header, block_lines)
        if found is None:
            found = _line_by_line(name, header, list(zip(block_numbers, block_lines)))
        for column, seen in shared.items():  # one str object per distinct text
            found[1][column] = [seen.setdefault(text, text) for text in found[1][column]]
        pieces.append(found)
        numbers.append(block_numbers)
    if not pieces:
        raise InputError(f"{name}: no CL points: the file has a header but no rows")
    numeric = {column: np.concatenate([found[0][column] for found in pieces]) for column in pieces[0][0]}
    texts = {column: list(itertools.chain.from_iterable(found[1][column] for found in pieces)) for column in shared}
    numbers = np.concatenate(numbers)
    for column, low in _WHOLE_COLUMNS.items():
        values = numeric.get(column)
        bad = None if values is None else np.flatnonzero((values != np.round(values)) | (values < low))
        if bad is not None and bad.size:
            raise InputError(f"{name}:{numbers[bad[0]]}: column {column!r}: {values[bad[0]]:g} is not a whole number "
                             f"of at least {low}")
    return Table(name, header, numbers, numeric, texts)


def load_toolpath(path, operation=None):
    """Read a toolpath CSV into a :class:`Toolpath`; InputError naming the file and line.

    With an ``operation`` column: the rows of operation `operation` (1-based), or when it is
    None of the only operation; else InputError listing the operations (number, tool, points).
    """
    table = load_table(path)
    name = table.source
    columns = set(table.header)
    data = table.numbers
    rows = _operation_rows(table, operation)
    lines = table.lines[rows]

    def stack(names):
        return np.stack([data[column][rows] for column in names], axis=1)

    cl = stack(_POSITION)
    cc = stack(_CONTACT) if _CONTACT[0] in columns else None
    directions = stack(_DIRECTION) if _DIRECTION[0] in columns else path_directions(cl if cc is None else cc)
    alpha, _ = feed_frame(directions)
    inclination = data[_INCLINATION][rows] if _INCLINATION in columns else None
    try:
        if _AXIS[0] in columns:
            return Toolpath.from_axes(cl, stack(_AXIS), cc, alpha, inclination)
        return Toolpath.from_part_angles(cl, data["theta_a"][rows], data["theta_b"][rows], cc, alpha, inclination)
    except CLPointError as error:
        raise InputError(f"{name}:{lines[error.index]}: {error.detail}") from None
    except ValueError as error:
        raise InputError(f"{name}: {error}") from None


def _operation_rows(table, operation):
    """Indices of the rows of the chosen operation (all rows without an operation column)."""
    if "operation" not in table.numbers:
        if operation not in (None, 1):
            raise InputError(f"{table.source}: operation {operation}: the file has one pass (no operation column)")
        return np.arange(len(table.lines))
    numbers = table.numbers["operation"]
    present = list(dict.fromkeys(numbers.tolist()))
    if operation is None and len(present) == 1:
        operation = present[0]
    if operation is None:
        listing = "; ".join(_describe(table, number) for number in present)
        raise InputError(f"{table.source}: {len(present)} operations; choose one with --operation N; "
                         f"operations: {listing}")
    rows = np.flatnonzero(numbers == float(operation))
    if rows.size == 0:
        raise InputError(f"{table.source}: no operation {operation}; the file has operations "
                         f"{', '.join(f'{n:g}' for n in present)}")
    return rows


def _describe(table, number):
    """``N: name, tool D, k CL points`` of operation `number` of `table`."""
    rows = np.flatnonzero(table.numbers["operation"] == number)
    first = int(rows[0])
    name = table.texts.get("name", [""] * (first + 1))[first] or "-"
    tool = table.texts.get("tool", ["tool"] * (first + 1))[first] or "tool"
    diameter = table.numbers.get("diameter")
    size = f" D{diameter[first]:g}" if diameter is not None and np.isfinite(diameter[first]) else ""
    return f"{number:g}: {name}, {tool}{size}, {rows.size} CL points"


#: About how many characters of the file one block holds (a block ends at the end of a line).
BLOCK_CHARS = 1 << 20


def _data_blocks(text):
    """(line numbers (k,) int, lines: list of k str) of the lines of `text` that are not blank or a #
    comment, block by block, each block about BLOCK_CHARS characters of whole lines (numbered as
    str.splitlines numbers them)."""
    start, first_number = 0, 1
    while start < len(text):
        end = text.find("\n", start + BLOCK_CHARS)
        end = len(text) if end < 0 else end + 1
        lines = text[start:end].splitlines()
        kept = [k for k, line in enumerate(lines) if line.strip() and not line.lstrip().startswith("#")]
        yield np.array(kept, dtype=int) + first_number, [lines[k] for k in kept]
        start, first_number = end, first_number + len(lines)


def _fields(line, where):
    """The CSV fields of one `line`; InputError naming `where` (file:line) for a line longer than
    MAX_LINE, a field longer than MAX_FIELD or a line csv cannot split."""
    if len(line) > MAX_LINE:
        raise InputError(f"{where}: a line of {len(line):,} characters; at most {MAX_LINE:,} are read")
    try:
        fields = next(csv.reader([line]))
    except csv.Error as error:
        raise InputError(f"{where}: not a CSV line: {error}") from None
    longest = max(map(len, fields))
    if longest > MAX_FIELD:
        raise InputError(f"{where}: a field of {longest:,} characters; at most {MAX_FIELD:,} are read")
    return fields


def _line_by_line(name, header, lines):
    """({numeric column: (n,) float}, {text column: list of n str}) of the (line number, line) `lines`,
    each line split and each number parsed on its own; InputError naming the first bad line."""
    texts = {column: [] for column in header if column in OPERATION_TEXTS}
    numeric = [column for column in header if column not in OPERATION_TEXTS]
    values = []
    for number, line in lines:
        fields = _fields(line, f"{name}:{number}")
        values.append(_numbers(fields, header, f"{name}:{number}"))
        for column in texts:
            texts[column].append(fields[header.index(column)].strip())
    table = np.array(values, dtype=float).reshape(len(values), len(numeric))
    return {column: table[:, k] for k, column in enumerate(numeric)}, texts


#: The numeric fields of a block the column-wise reader takes hold only these characters: those of numbers,
#: blanks (spaces, tabs) and the commas and newlines joining them. On them Python's float() takes exactly the
#: NUMBER grammar (blanks around a number dropped, as parse_number does; no words such as nan, no '_', no
#: other scripts' digits).
_NUMERIC_BLOCK = re.compile(r"[0-9.eE+\- \t,\n]*")


def _columnwise(header, lines):
    """({numeric column: (n,) float}, {text column: list of n str}) of the data `lines` (n str) read column
    by column: one split of the whole block, one match of its numeric fields' characters, every number
    converted in one pass; None when the block has a quote or NUL (which csv reads its own way), a line
    without one field per column, a field that is not a number where one is due (or, in a column that may
    be empty, nothing), or a line, field or number over its limit (the line-by-line reader then names the
    line)."""
    width = len(header)
    block = "\n".join(lines)
    if ('"' in block or "\0" in block or max(map(len, lines)) > MAX_LINE
            or set(map(str.count, lines, itertools.repeat(","))) != {width - 1}):
        return None
    fields = block.replace("\n", ",").split(",")
    if max(map(len, fields)) > MAX_FIELD:
        return None
    texts = {column: [field.strip() for field in fields[k::width]]
             for k, column in enumerate(header) if column in OPERATION_TEXTS}
    numeric = [column for column in header if column not in OPERATION_TEXTS]
    if texts:
        fields = list(itertools.chain.from_iterable(
            zip(*(fields[k::width] for k, column in enumerate(header) if column not in OPERATION_TEXTS))))
    if not _NUMERIC_BLOCK.fullmatch(",".join(fields)):
        return None
    may_be_empty = [k for k, column in enumerate(numeric) if column in _MAY_BE_EMPTY]
    for k in may_be_empty:
        fields[k::len(numeric)] = [field if field.strip() else "nan" for field in fields[k::len(numeric)]]
    try:
        table = np.array(list(map(float, fields)), dtype=float).reshape(len(lines), len(numeric))
    except ValueError:
        return None
    small = np.abs(table) <= MAX_MAGNITUDE
    small[:, may_be_empty] |= np.isnan(table[:, may_be_empty])
    if not small.all():
        return None
    return {column: table[:, k] for k, column in enumerate(numeric)}, texts


def _columns(header, where):
    """Check the header's names (already lower-cased, trimmed); return them as a set."""
    known = (*_POSITION, *_ANGLES, *_AXIS, *_CONTACT, *_DIRECTION, _INCLINATION, *_FEEDS, *OPERATION_NUMBERS,
             *OPERATION_TEXTS)
    duplicate = sorted({column for column in header if header.count(column) > 1})
    if duplicate:
        raise InputError(f"{where}: duplicate column {duplicate[0]!r}")
    unknown = [column for column in header if column not in known]
    if unknown:
        names, listed = ", ".join(map(repr, unknown)), ", ".join(known)
        raise InputError(f"{where}: unknown columns {names}; known columns: {listed}" if len(unknown) > 1
                         else f"{where}: unknown column {names}; known columns: {listed}")
    columns = set(header)
    if columns & set(_AXIS) and columns & set(_ANGLES):
        raise InputError(f"{where}: give the tool orientation as theta_a, theta_b or as i, j, k, not both")
    groups = [("position", _POSITION), ("tool axis", _AXIS) if columns & set(_AXIS) else ("tool angles", _ANGLES)]
    if columns & set(_CONTACT):
        groups.append(("cutter-contact point", _CONTACT))
    if columns & set(_DIRECTION):
        groups.append(("feed direction", _DIRECTION))
    for label, group in groups:
        missing = [column for column in group if column not in columns]
        if missing:
            raise InputError(f"{where}: missing column {missing[0]!r} of the {label} ({', '.join(group)})")
    return columns


def _numbers(fields, header, where):
    """The row's numeric fields as finite floats (NaN for an allowed empty one), in header order."""
    if len(fields) != len(header):
        raise InputError(f"{where}: expected {len(header)} fields ({','.join(header)}), got {len(fields)}")
    values = []
    for column, field in zip(header, fields):
        if column in OPERATION_TEXTS:
            continue
        if column in _MAY_BE_EMPTY and not field.strip():
            values.append(math.nan)
            continue
        values.append(parse_number(field, f"{where}: column {column!r}"))
    return values
