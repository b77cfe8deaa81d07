"""The project's toolpath CSV (also as the ``toolpath --out`` command writes it) as a Program.

Rows are grouped by the ``operation`` column (one operation without it, a single pass), in the
order they come; the tool is the ``tool`` kind with ``diameter`` and ``corner_radius`` of the
operation's first row ("unknown" kind without them); feeds from ``feed_rate`` and ``feed_unit``;
the CL points and axes are taken as they are (part frame = file frame), the ``inclination``
column where there is one; the direction of motion
at each CL point from the ``feed_x, feed_y, feed_z`` columns, else the chords of the CC points
(``xc, yc, zc``), else of the CL points, within each operation, as toolpath_csv.load_toolpath
takes them.
"""

import numpy as np

from ...engine import angles_to_axis
from ...engine.feed import path_directions
from ...errors import InputError
from .. import toolpath_csv
from .frames import IDENTITY
from .program import Moves, Operation, Program
from .tools import KINDS, ToolSpec


def read_csv_program(path, text):
    """The Program of the toolpath CSV at `path` (whose text is `text`)."""
    table = toolpath_csv.load_table(path)
    data, name = table.numbers, table.source
    points = np.stack([data[c] for c in ("x", "y", "z")], axis=1)
    if "i" in data:
        axes = np.stack([data[c] for c in ("i", "j", "k")], axis=1)
    else:
        axes = angles_to_axis(data["theta_a"], data["theta_b"])
    norm = np.linalg.norm(axes, axis=1)
    if (norm == 0.0).any():
        raise InputError(f"{name}:{table.lines[int(np.flatnonzero(norm == 0.0)[0])]}: tool axis (0, 0, 0) is zero")
    axes = axes / norm[:, None]
    numbers = data["operation"] if "operation" in data else np.ones(len(points))
    operations = []
    for number in dict.fromkeys(numbers.tolist()):
        rows = np.flatnonzero(numbers == number)
        if "feed_x" in data:
            directions = np.stack([data[c][rows] for c in ("feed_x", "feed_y", "feed_z")], axis=1)
        else:
            path = np.stack([data[c][rows] for c in ("xc", "yc", "zc")], axis=1) if "xc" in data else points[rows]
            directions = path_directions(path)
        operations.append(_operation(table, rows, len(operations) + 1, points, axes, directions,
                                     "operation" not in data))
    return Program(name, "mm", tuple(operations), {}, {}, [], "csv", text, int(table.lines[-1]))


def _operation(table, rows, number, points, axes, directions, single_pass):
    """The Operation of the CSV `rows`, with the directions of motion (len(rows), 3) at them."""
    first = int(rows[0])
    data, texts = table.numbers, table.texts
    kind = texts["tool"][first] if "tool" in texts else "unknown"
    if kind not in KINDS:
        raise InputError(f"{table.source}:{table.lines[first]}: tool {kind!r} is none of {', '.join(KINDS)}")
    diameter = _value(data, "diameter", first)
    radius = _value(data, "corner_radius", first)
    flute_length = _value(data, "flute_length", first)
    tool = ToolSpec(kind, diameter, radius, flute_length, (f"CSV line {table.lines[first]}",) if diameter else ())
    feed = data["feed_rate"][rows] if "feed_rate" in data else np.full(len(rows), np.nan)
    units = {texts["feed_unit"][row] for row in rows if texts["feed_unit"][row]} if "feed_unit" in texts else set()
    feed_unit = units.pop() if len(units) == 1 else None
    name = texts["name"][first] if "name" in texts else ""
    empty = Moves(np.zeros((0, 3)), np.zeros((0, 3)), np.zeros(0, dtype=int))
    arrays = [np.array(a) for a in (feed, table.lines[rows], points[rows], axes[rows], directions)]
    for array in arrays:
        array.setflags(write=False)
    inclination = np.array(data["inclination"][rows]) if "inclination" in data else None
    return Operation(number, name, tool, None, *arrays[:1], feed_unit, *arrays[1:4], IDENTITY, "", empty, empty,
                     0, 0, table.source, int(table.lines[first]), directions_file=arrays[4], single_pass=single_pass,
                     inclination=inclination)


def _value(data, column, row):
    """data[column][row] as a float, or None when the column is absent or the field empty."""
    if column not in data or not np.isfinite(data[column][row]):
        return None
    return float(data[column][row])
