"""One pass of CL points as CSV: positions in mm, tool orientation as angles or axis vectors.

The header names the columns, in any order, case-insensitive, whitespace trimmed:

- ``x, y, z`` (CL point: centre of the tool's bottom face, mm), and either
- ``theta_a, theta_b`` (rotations about x and y, degrees, |θ| < 90) or
- ``i, j, k`` (tool-axis vector, any length, k > 0);
- optionally ``xc, yc, zc`` (cutter-contact point, mm), all three or none;
- optionally ``feed_per_tooth`` (mm), ``feed_mm_min``: the feeds a ``schedule`` wrote, skipped here.

One row per CL point in pass order. Blank lines and lines starting with ``#`` are skipped.
"""

import csv
import math
import os

import numpy as np

from ..engine import Toolpath
from ..errors import CLPointError, InputError
from . import read_text

_POSITION = ("x", "y", "z")
_ANGLES = ("theta_a", "theta_b")
_AXIS = ("i", "j", "k")
_CONTACT = ("xc", "yc", "zc")
_FEEDS = ("feed_per_tooth", "feed_mm_min")
_EXAMPLE = "x,y,z,theta_a,theta_b"


def load_toolpath(path):
    """Read a toolpath CSV into a :class:`Toolpath`; InputError naming the file and line."""
    name = os.fspath(path)
    rows = _rows(read_text(path))
    if not rows:
        raise InputError(f"{name}: empty file; expected a header such as {_EXAMPLE!r}")
    header_line, fields = rows[0]
    header = [field.strip().lower() for field in fields]
    columns = _columns(header, f"{name}:{header_line}")
    if len(rows) == 1:
        raise InputError(f"{name}: no CL points: the file has a header but no rows")
    lines = [line for line, _ in rows[1:]]
    table = np.array([_numbers(fields, header, f"{name}:{line}") for line, fields in rows[1:]])
    data = {column: table[:, index] for index, column in enumerate(header)}

    def stack(names):
        return np.stack([data[column] for column in names], axis=1)

    cc = stack(_CONTACT) if _CONTACT[0] in columns else None
    try:
        if _AXIS[0] in columns:
            return Toolpath.from_axes(stack(_POSITION), stack(_AXIS), cc)
        return Toolpath(stack(_POSITION), data["theta_a"], data["theta_b"], cc)
    except CLPointError as error:
        raise InputError(f"{name}:{lines[error.index]}: {error.detail}") from None
    except ValueError as error:
        raise InputError(f"{name}: {error}") from None


def _rows(text):
    """(line number, fields) of every line that is not blank or a # comment."""
    rows = []
    for number, line in enumerate(text.splitlines(), start=1):
        stripped = line.strip()
        if stripped and not stripped.startswith("#"):
            rows.append((number, next(csv.reader([line]))))
    return rows


def _columns(header, where):
    """Check the header's names (already lower-cased, trimmed); return them as a set."""
    known = (*_POSITION, *_ANGLES, *_AXIS, *_CONTACT, *_FEEDS)
    duplicate = sorted({column for column in header if header.count(column) > 1})
    if duplicate:
        raise InputError(f"{where}: duplicate column {duplicate[0]!r}")
    unknown = [column for column in header if column not in known]
    if unknown:
        raise InputError(
            f"{where}: unknown column{'s' if len(unknown) > 1 else ''} "
            f"{', '.join(map(repr, unknown))}; known columns: {', '.join(known)}"
        )
    columns = set(header)
    if columns & set(_AXIS) and columns & set(_ANGLES):
        raise InputError(f"{where}: give the tool orientation as theta_a, theta_b or as i, j, k, not both")
    groups = [("position", _POSITION), ("tool axis", _AXIS) if columns & set(_AXIS) else ("tool angles", _ANGLES)]
    if columns & set(_CONTACT):
        groups.append(("cutter-contact point", _CONTACT))
    for label, group in groups:
        missing = [column for column in group if column not in columns]
        if missing:
            raise InputError(f"{where}: missing column {missing[0]!r} of the {label} ({', '.join(group)})")
    return columns


def _numbers(fields, header, where):
    """The row's fields as finite floats, in header order."""
    if len(fields) != len(header):
        raise InputError(f"{where}: expected {len(header)} fields ({','.join(header)}), got {len(fields)}")
    values = []
    for column, field in zip(header, fields):
        try:
            value = float(field)
        except ValueError:
            raise InputError(f"{where}: column {column!r}: {field.strip()!r} is not a number") from None
        if not math.isfinite(value):
            raise InputError(f"{where}: column {column!r}: {field.strip()!r} is not a finite number")
        values.append(value)
    return values
