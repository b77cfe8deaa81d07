"""What the ``toolpath`` command prints and writes: one line per operation, every cutting CL point as CSV.

CSV columns: ``operation`` (1-based), ``name`` (the CAM operation's name), ``tool`` (kind),
``diameter``, ``corner_radius``, ``flute_length`` (mm, empty when unknown), ``x, y, z`` (mm),
``i, j, k`` (unit tool axis), ``feed_x, feed_y, feed_z`` (the unit direction of the tool tip's
motion arriving at the point: an arc's tangent; 0, 0, 0 where none), ``feed_rate`` and ``feed_unit`` (MMPM mm/min or MMPR mm/rev, empty before any
feed), ``line`` (the CL file's line of the move). Frame "part" (MSYS / CSYS / ROTABL applied)
or "file" (as written, in mm). :mod:`abm_workbench.formats.toolpath_csv` reads it back.
"""

import csv
import io
import os

import numpy as np

from .. import replacing

FRAMES = ("part", "file")
COLUMNS = ("operation", "name", "tool", "diameter", "corner_radius", "flute_length", "x", "y", "z", "i", "j", "k",
           "feed_x", "feed_y", "feed_z", "feed_rate", "feed_unit", "line")


def _number(value):
    """Shortest text reading back as the float `value`; empty for None or NaN."""
    if value is None or not np.isfinite(value):
        return ""
    text = repr(float(value) + 0.0)
    return text[:-2] if text.endswith(".0") else text


def _coordinates(op, frame):
    """(points, axes, unit directions of motion) of `op`'s cutting moves in `frame` ("part" or "file")."""
    if frame == "file":
        points, axes, directions = op.points_file, op.axes_file, op.directions_part @ op.to_part[0]
    else:
        points, axes, directions = op.points_part, op.axes_part, op.directions_part
    length = np.linalg.norm(directions, axis=1)
    return points, axes, directions / np.where(length > 0.0, length, 1.0)[:, None]


def operation_line(op, frame="part", units="mm"):
    """One line of words about operation `op` of a program in `units` as written (see the module
    docstring for `frame`)."""
    _, axes, _ = _coordinates(op, frame)
    if len(axes):
        tilt = np.degrees(np.arccos(np.clip(axes[:, 2], -1.0, 1.0)))
        axis = f"axis {tilt.min():.4g}..{tilt.max():.4g} deg from {frame} Z"
    else:
        axis = "no cutting axis"
    parts = [
        f"{op.label()}: {op.tool.describe()}" + (f" ({op.tool.name})" if op.tool.name else ""),
        f"{len(op.lines)} CL points cut, {len(op.rapids)} rapid, {len(op.cycle_points)} canned-cycle",
        f"{op.arcs} arcs and {op.curves} curves interpolated",
        axis,
        f"frame {op.frame or 'none (file = part)'}",
        "units mm" if units == "mm" else f"units {units} (converted to mm)",
    ]
    if op.spindle_rpm is not None:
        parts.append(f"spindle {op.spindle_rpm:.6g} rpm")
    refusal = op.refusal()
    if refusal is not None:
        parts.append("not for the engine: " + refusal.split(": ", 1)[1])
    return "; ".join(parts)


def summary_lines(program, frame="part"):
    """Lines describing `program`: a header, one line per operation, then ignored and unknown records."""
    lines = [f"{program.source}: {len(program.operations)} operation(s), {len(program.milling())} for the engine; "
             f"units {program.units}" + (" (converted to mm)" if program.units != "mm" else "")]
    lines += [operation_line(op, frame, program.units) for op in program.operations]
    if program.ignored:
        lines.append("ignored records: " + ", ".join(f"{word} x{count} (first line {first})"
                                                     for word, (first, count) in program.ignored.items()))
    if program.unknown:
        lines.append("records not understood: " + ", ".join(f"{word} x{count} (first line {first})"
                                                            for word, (first, count) in program.unknown.items()))
    return lines


def toolpath_csv_text(program, frame="part"):
    """CSV text of every cutting CL point of `program` (see the module docstring)."""
    if frame not in FRAMES:
        raise ValueError(f"frame must be one of {FRAMES}, got {frame!r}")
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(COLUMNS)
    for op in program.operations:
        points, axes, directions = _coordinates(op, frame)
        head = [str(op.number), op.name, op.tool.kind, _number(op.tool.diameter), _number(op.tool.corner_radius),
                _number(op.tool.flute_length)]
        unit = op.feed_unit or ""
        for point, axis, direction, feed, line in zip(points, axes, directions, op.feed, op.lines):
            rate = _number(feed)
            writer.writerow(head + [_number(v) for v in (*point, *axis, *direction)] + [rate, unit if rate else "",
                                                                                         str(line)])
    return buffer.getvalue()


def write_toolpath_csv(program, path, frame="part"):
    """Write :func:`toolpath_csv_text` to `path`, whole or not at all; returns the path."""
    name = os.fspath(path)
    text = toolpath_csv_text(program, frame)
    with replacing(name) as (temporary,):
        with open(temporary, "w", encoding="utf-8", newline="") as file:
            file.write(text)
    return name
