"""An Engagement as CSV: one row per (CL point, φ), and a summary per engagement segment.

``R.csv`` columns, one row per instant, CL points in pass order and φ ascending within each:
cl (0-based), phi_deg, lep_l, uep_l (mm along the tool axis above the tip), length (mm along
the peripheral edge, arc length on a corner), pieces, uep_surface (name), uep_section, uep_wall,
case (Table 1 name, or "2.5D", "corner"), segment (letter, empty without engagement), h (mm),
area (mm²), lep_x, lep_y, lep_z, uep_x, uep_y, uep_z (mm), lep_surface, lep_section, lep_wall,
end_length (mm, the engaged length of the end edge; a file written before it was added reads
without it, as NaN).

``R.summary.csv`` columns, one row per CL point and engagement segment (one row with an
empty segment for a CL point without engagement): cl, depth_of_cut (mm), segment,
phi_start, phi_end (deg), uep_surface, uep_section, uep_wall, max_length, mean_length (mm);
then, when the toolpath is given, cl_x, cl_y, cl_z (mm), theta_a, theta_b (deg).

With cutting forces (abm_workbench.forces) the results gain FORCE_COLUMNS: fx, fy, fz (N,
global frame, summed over the flutes cutting at that angle of flute 1), torque (N·mm) and,
with a spindle speed, power (W); the summary gains FORCE_SUMMARY_COLUMNS per CL point:
peak_force, mean_force (resultant, N), peak_torque (N·mm).

Numbers are rounded to decimal_text.DECIMALS (10) places and written in the shortest form
that reads back as the rounded value; NaN is an empty field. The columns themselves come from
formats.results_columns, which formats.results_npz writes as arrays.
"""

import os
import re

import numpy as np

from ..errors import InputError
from . import parse_number, read_text, replacing
from .decimal_text import WORD, integer_field, number_field, text_field
from .results_columns import (FORCE_COLUMNS, FORCE_SUMMARY_COLUMNS, INPROCESS_COLUMNS, INPROCESS_SUMMARY_COLUMNS,
                              INT_COLUMNS, RESULT_COLUMNS, SUMMARY_COLUMNS, TEXT_COLUMNS, TOOLPATH_COLUMNS,
                              result_columns, summary_columns, text_labels)

__all__ = ["FORCE_COLUMNS", "FORCE_SUMMARY_COLUMNS", "INPROCESS_COLUMNS", "INPROCESS_SUMMARY_COLUMNS", "RESULT_COLUMNS",
           "SUMMARY_COLUMNS", "TOOLPATH_COLUMNS", "chunk_texts", "read_results", "results_text", "summary_path",
           "summary_text", "table_text", "write_chunks", "write_results"]

#: Rows formatted at a time (formats.decimal_text): a text matrix of about 6 MB.
BLOCK_ROWS = 2**14
#: A comma and a line end in the last byte of a word (decimal_text.WORD).
_COMMA, _NEWLINE = np.uint64(ord(",") << 56), np.uint64(ord("\n") << 56)
#: An integer field: ASCII digits with an optional minus sign.
_INTEGER = re.compile(r"-?[0-9]+")


def summary_path(path):
    """Path of the summary beside results `path`: R.csv -> R.summary.csv (R.txt -> R.txt.summary.csv)."""
    path = os.fspath(path)
    stem = path[:-4] if path.lower().endswith(".csv") else path
    return stem + ".summary.csv"


def write_results(engagement, path, *, toolpath=None, forces=None):
    """Write the results and the summary CSV of `engagement`, both or neither.

    toolpath: the Toolpath of the pass, to add each CL point's position and angles to the
    summary. forces: the pass's Forces, to add the force columns. Returns (path, summary path) as str.
    """
    path, summary = os.fspath(path), summary_path(path)
    texts = (results_text(engagement, forces=forces), summary_text(engagement, toolpath=toolpath, forces=forces))
    with replacing(path, summary) as temporaries:
        for temporary, text in zip(temporaries, texts):
            write_text(temporary, text)
    return path, summary


def write_text(path, text):
    """Write `text` to `path` as UTF-8 with \\n line ends."""
    with open(path, "w", encoding="utf-8", newline="") as file:
        file.write(text)


def results_text(engagement, *, first_cl=0, forces=None, initial=None):
    """The results CSV of an Engagement (m CL points × p angles: m·p rows) as one string;
    with `forces` (a Forces of the same CL points) the force columns too, with `initial` ((m, p) mm,
    the length of cut in the stock itself, for an engagement against the in-process stock) its column.

    first_cl: index of the engagement's first CL point in its pass (for a chunk of a pass).
    Formatted BLOCK_ROWS rows at a time (formats.decimal_text), so its working memory is bounded.
    """
    return table_text(result_columns(engagement, first_cl=first_cl, forces=forces, initial=initial))


def summary_text(engagement, *, toolpath=None, first_cl=0, forces=None, changed=None):
    """The summary CSV of an Engagement as one string (see the module docstring).

    first_cl: index of the engagement's first CL point in its pass (for a chunk of a pass;
    toolpath, forces and changed are then the chunk's). changed: (m,) bool, against the
    in-process stock: earlier moves removed material the CL point's edges would meet.
    """
    return table_text(summary_columns(engagement, toolpath=toolpath, first_cl=first_cl, forces=forces, changed=changed))


def table_text(columns):
    """CSV text of `columns` (a dict name -> (rows,) array of formats.results_columns): a header of
    the names, then one line per row, formatted BLOCK_ROWS rows at a time (formats.decimal_text)."""
    rows = next(iter(columns.values())).size
    blocks = (_fields(columns, slice(start, start + BLOCK_ROWS)) for start in range(0, rows, BLOCK_ROWS))
    return _csv(list(columns), blocks)


def _fields(columns, rows):
    """The decimal_text fields of `rows` (a slice) of every one of `columns` (results_columns), in order."""
    fields = []
    for name, values in columns.items():
        values = values[rows]
        if name in TEXT_COLUMNS:
            fields.append(text_field(text_labels(name, int(columns[name].max(initial=0)) + 1))[:, values])
        else:
            fields.append(integer_field(values) if name in INT_COLUMNS else number_field(values))
    return fields


def chunk_texts(engagement, first_cl, *, toolpath=None, forces=None, initial=None, changed=None):
    """(results, summary) CSV text of a chunk of a pass: the Engagement of CL points first_cl, ….

    toolpath, forces, initial, changed: the chunk's Toolpath, Forces, initial length of cut and
    changed flags (results_text, summary_text), or None. Header lines only in the first chunk (first_cl = 0),
    so the texts of a pass's chunks, concatenated in order, are write_results' two files byte
    for byte (each CL point's rows depend on that CL point alone).
    """
    texts = (results_text(engagement, first_cl=first_cl, forces=forces, initial=initial),
             summary_text(engagement, toolpath=toolpath, first_cl=first_cl, forces=forces, changed=changed))
    return texts if first_cl == 0 else tuple(text.split("\n", 1)[1] for text in texts)


def write_chunks(parts, path, summary):
    """Write (results, summary) text pairs from the iterable `parts`, in order, to files `path` and
    `summary` (UTF-8, \\n line ends), one pair in memory at a time. Returns the number of pairs.

    Write to temporaries (formats.replacing) for all-or-nothing output.
    """
    count = 0
    with open(path, "w", encoding="utf-8", newline="") as results, \
            open(summary, "w", encoding="utf-8", newline="") as segments:
        for results_part, summary_part in parts:
            results.write(results_part)
            segments.write(summary_part)
            count += 1
    return count


def _csv(names, blocks):
    """CSV text: a header of `names`, then one line per value of each block, a list of fields
    (decimal_text) in the order of `names`."""
    parts, buffer = [",".join(names).encode("utf-8") + b"\n"], bytearray()
    for fields in blocks:
        shape = fields[0].shape[1], sum(field.shape[0] for field in fields)
        if len(buffer) < shape[0] * shape[1] * WORD.itemsize:
            buffer = bytearray(shape[0] * shape[1] * WORD.itemsize)
        parts.append(_lines(fields, shape, buffer))
    return b"".join(parts).decode("utf-8")


def _lines(fields, shape, buffer):
    """CSV lines (bytes, each ending in \\n) of `fields` (decimal_text, of n values each) as the
    columns of an (n, their total width) = `shape` matrix of WORD at the start of bytearray
    `buffer` (reused from block to block, NUL after the matrix): a comma (a line end for the
    last) in each field's last byte, then the non-NUL bytes."""
    everything = np.frombuffer(buffer, dtype=WORD)
    everything[shape[0] * shape[1]:] = 0
    words = everything[:shape[0] * shape[1]].reshape(shape)
    at = 0
    for number, field in enumerate(fields, start=1):
        for row in field[:-1]:
            words[:, at] = row
            at += 1
        np.bitwise_or(field[-1], _NEWLINE if number == len(fields) else _COMMA, out=words[:, at])
        at += 1
    return buffer.translate(None, b"\0")


#: Longest field and line of a results CSV read (characters): numbers and labels are far shorter.
MAX_FIELD, MAX_LINE = 100, 10000
#: Most digits of an integer field (an int64 holds 18).
_INTEGER_DIGITS = 18


def read_results(path):
    """Columns of a results or summary CSV written here, as a dict name -> (rows,) array.

    uep_surface, case and segment are str arrays; cl, pieces, uep_section and uep_wall int
    arrays; every other column float (NaN for an empty field). InputError naming the file
    and line for a malformed file, a line longer than MAX_LINE, a field longer than MAX_FIELD
    or an integer of more than 18 digits; memory stays a few times the file's size.
    """
    name = os.fspath(path)
    lines = read_text(path).splitlines()
    if not lines:
        raise InputError(f"{name}: empty file; expected a results header {','.join(RESULT_COLUMNS[:3])},...")
    header = _split(lines[0], name, 1)
    if len(set(header)) != len(header):
        raise InputError(f"{name}:1: a column named twice in the header")
    columns = [[] for _ in header]
    for number, line in enumerate(lines[1:], start=2):
        row = _split(line, name, number)
        if len(row) != len(header):
            raise InputError(f"{name}:{number}: expected {len(header)} fields, got {len(row)}")
        for column, field in zip(columns, row):
            column.append(field)
    return {column: _parse(column, fields, name) for column, fields in zip(header, columns)}


def _split(line, name, number):
    """The comma-separated fields of `line` (line `number` of file `name`), each at most MAX_FIELD long."""
    if len(line) > MAX_LINE:
        raise InputError(f"{name}:{number}: a line of {len(line):,} characters; at most {MAX_LINE:,} are read")
    fields = line.split(",")
    longest = max(map(len, fields))
    if longest > MAX_FIELD:
        raise InputError(f"{name}:{number}: a field of {longest:,} characters; at most {MAX_FIELD} are read")
    return fields


def _parse(column, fields, name):
    """One column's fields (list of str, rows) as str, int or float array (see read_results)."""
    if column in TEXT_COLUMNS:
        return np.array(fields, dtype=str)
    if column not in INT_COLUMNS:
        return np.array([parse_number(field, f"{name}:{row}: column {column!r}") if field else np.nan
                         for row, field in enumerate(fields, start=2)], dtype=float)
    values = []
    for row, field in enumerate(fields, start=2):
        if not _INTEGER.fullmatch(field) or len(field.lstrip("-")) > _INTEGER_DIGITS:
            raise InputError(f"{name}:{row}: column {column!r}: {field!r} is not a valid int")
        values.append(int(field))
    return np.array(values, dtype=np.int64)
