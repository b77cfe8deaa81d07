"""An Engagement as CSV: one row per (CL point, φ), and a summary per engagement segment.

``R.csv`` columns, one row per instant, CL points in pass order and φ ascending within each:
cl (0-based), phi_deg, lep_l, uep_l, length (mm along the edge), pieces, uep_surface (name),
uep_section, uep_wall, case (Table 1 name), segment (letter, empty without engagement),
h (mm), area (mm²), lep_x, lep_y, lep_z, uep_x, uep_y, uep_z (mm).

``R.summary.csv`` columns, one row per CL point and engagement segment (one row with an
empty segment for a CL point without engagement): cl, depth_of_cut (mm), segment,
phi_start, phi_end (deg), uep_surface, uep_section, uep_wall, max_length, mean_length (mm);
then, when the toolpath is given, cl_x, cl_y, cl_z (mm), theta_a, theta_b (deg).

With cutting forces (abm_workbench.forces) the results gain FORCE_COLUMNS: fx, fy, fz (N,
global frame, summed over the flutes cutting at that angle of flute 1), torque (N·mm) and,
with a spindle speed, power (W); the summary gains FORCE_SUMMARY_COLUMNS per CL point:
peak_force, mean_force (resultant, N), peak_torque (N·mm).

Numbers are rounded to DECIMALS places and written in the shortest form that reads back as
the rounded value; NaN is an empty field.
"""

import os

import numpy as np

from ..engine import segment_letter
from ..errors import InputError
from . import read_text, replacing

#: Decimal places kept (mm, deg, mm²): values read back within 5e-11 of what was computed.
DECIMALS = 10
RESULT_COLUMNS = (
    "cl", "phi_deg", "lep_l", "uep_l", "length", "pieces", "uep_surface", "uep_section", "uep_wall",
    "case", "segment", "h", "area", "lep_x", "lep_y", "lep_z", "uep_x", "uep_y", "uep_z",
)
SUMMARY_COLUMNS = (
    "cl", "depth_of_cut", "segment", "phi_start", "phi_end", "uep_surface", "uep_section", "uep_wall",
    "max_length", "mean_length",
)
#: Results columns added with forces (power only with a spindle speed), and summary columns.
FORCE_COLUMNS = ("fx", "fy", "fz", "torque", "power")
FORCE_SUMMARY_COLUMNS = ("peak_force", "mean_force", "peak_torque")
#: Summary columns added when the toolpath is given.
TOOLPATH_COLUMNS = ("cl_x", "cl_y", "cl_z", "theta_a", "theta_b")
_TEXT_COLUMNS = {"uep_surface", "case", "segment"}
_INT_COLUMNS = {"cl", "pieces", "uep_section", "uep_wall"}


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


def results_text(engagement, *, first_cl=0, forces=None):
    """The results CSV of an Engagement (m CL points × p angles: m·p rows) as one string;
    with `forces` (a Forces of the same CL points) the force columns too.

    first_cl: index of the engagement's first CL point in its pass (for a chunk of a pass).
    """
    m, p = engagement.shape
    flat = {name: getattr(engagement, name).reshape(-1) for name in (
        "lep_l", "uep_l", "length", "pieces", "uep_section", "uep_wall", "area")}
    columns = {
        "cl": np.repeat(np.arange(first_cl, first_cl + m), p).astype(str),
        "phi_deg": np.tile(_numbers(engagement.phi), m),
        **{name: _numbers(flat[name]) for name in ("lep_l", "uep_l", "length")},
        "pieces": flat["pieces"].astype(str),
        "uep_surface": engagement.surface_names().reshape(-1),
        "uep_section": flat["uep_section"].astype(str),
        "uep_wall": flat["uep_wall"].astype(str),
        "case": engagement.case_names().reshape(-1),
        "segment": _letters(engagement.segment.reshape(-1)),
        "h": np.tile(_numbers(engagement.h), m),
        "area": _numbers(flat["area"]),
    }
    for point in ("lep", "uep"):
        xyz = getattr(engagement, f"{point}_xyz").reshape(-1, 3)
        for axis, name in enumerate("xyz"):
            columns[f"{point}_{name}"] = _numbers(xyz[:, axis])
    names = RESULT_COLUMNS
    if forces is not None:
        names += FORCE_COLUMNS[:4] if forces.power is None else FORCE_COLUMNS
        xyz = forces.xyz.reshape(-1, 3)
        columns.update(fx=_numbers(xyz[:, 0]), fy=_numbers(xyz[:, 1]), fz=_numbers(xyz[:, 2]),
                       torque=_numbers(forces.torque.reshape(-1)))
        if forces.power is not None:
            columns["power"] = _numbers(forces.power.reshape(-1))
    return _csv(names, [columns[name] for name in names])


def summary_text(engagement, *, toolpath=None, first_cl=0, forces=None):
    """The summary CSV of an Engagement as one string (see the module docstring).

    first_cl: index of the engagement's first CL point in its pass (for a chunk of a pass;
    toolpath and forces are then the chunk's).
    """
    records = []
    for cl in range(engagement.shape[0]):
        segments = engagement.segments(cl) or [
            {"letter": "", "phi_start": np.nan, "phi_end": np.nan, "surface": "none", "section": -1, "wall": -1,
             "max_length": 0.0, "mean_length": 0.0}
        ]
        records += [(cl, segment) for segment in segments]
    cl = np.array([cl for cl, _ in records], dtype=int)

    def field(key):
        return [segment[key] for _, segment in records]

    columns = [
        (cl + first_cl).astype(str), _numbers(engagement.depth_of_cut[cl]), field("letter"),
        _numbers(field("phi_start")), _numbers(field("phi_end")), field("surface"),
        np.array(field("section")).astype(str), np.array(field("wall")).astype(str),
        _numbers(field("max_length")), _numbers(field("mean_length")),
    ]
    names = SUMMARY_COLUMNS
    if toolpath is not None:
        if len(toolpath) != engagement.shape[0]:
            raise ValueError(f"toolpath has {len(toolpath)} CL points, the engagement {engagement.shape[0]}")
        names += TOOLPATH_COLUMNS
        columns += [_numbers(toolpath.cl[cl, axis]) for axis in range(3)]
        columns += [_numbers(toolpath.theta_a[cl]), _numbers(toolpath.theta_b[cl])]
    if forces is not None:
        names += FORCE_SUMMARY_COLUMNS
        columns += [_numbers(forces.peak[cl]), _numbers(forces.mean[cl]), _numbers(forces.torque.max(axis=1)[cl])]
    return _csv(names, columns)


def chunk_texts(engagement, first_cl, *, toolpath=None, forces=None):
    """(results, summary) CSV text of a chunk of a pass: the Engagement of CL points first_cl, ….

    toolpath, forces: the chunk's Toolpath and Forces, or None. Header lines only in the first chunk (first_cl = 0),
    so the texts of a pass's chunks, concatenated in order, are write_results' two files byte
    for byte (each CL point's rows depend on that CL point alone).
    """
    texts = (results_text(engagement, first_cl=first_cl, forces=forces),
             summary_text(engagement, toolpath=toolpath, first_cl=first_cl, forces=forces))
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


def _numbers(values):
    """Text (same shape) of float `values`: rounded to DECIMALS places, '' for NaN.

    Python's repr, the shortest text that reads back as the value (as numpy's str of a float64).
    """
    values = np.asarray(values, dtype=float)
    rounded = (np.round(values, DECIMALS) + 0.0).reshape(-1).tolist()  # + 0.0 turns -0.0 into 0.0
    text = np.array(list(map(repr, rounded)), dtype=object).reshape(values.shape)
    text[np.isnan(values)] = ""
    return text


def _letters(segment):
    """Segment letters for segment indices (N,), '' for −1."""
    names = np.array([segment_letter(s) for s in range(int(segment.max(initial=-1)) + 1)] + [""])
    return names[segment]


def _csv(names, columns):
    """CSV text: a header of `names`, then one line per row of the equal-length `columns` (of text)."""
    lists = []
    for column in columns:
        column = np.asarray(column)
        lists.append((column if column.dtype.kind in "UO" else column.astype(str)).tolist())
    return "\n".join([",".join(names), *map(",".join, zip(*lists))]) + "\n"


def read_results(path):
    """Columns of a results or summary CSV written here, as a dict name -> (rows,) array.

    uep_surface, case and segment are str arrays; cl, pieces, uep_section and uep_wall int
    arrays; every other column float (NaN for an empty field). InputError naming the file
    and line for a malformed file.
    """
    name = os.fspath(path)
    lines = read_text(path).splitlines()
    if not lines:
        raise InputError(f"{name}: empty file; expected a results header {','.join(RESULT_COLUMNS[:3])},...")
    header = lines[0].split(",")
    rows = [line.split(",") for line in lines[1:]]
    for number, row in enumerate(rows, start=2):
        if len(row) != len(header):
            raise InputError(f"{name}:{number}: expected {len(header)} fields, got {len(row)}")
    table = np.array(rows, dtype=str).reshape(len(rows), len(header))
    return {column: _parse(column, table[:, c], name) for c, column in enumerate(header)}


def _parse(column, text, name):
    """One column's text (rows,) as str, int or float array (see read_results)."""
    if column in _TEXT_COLUMNS:
        return text
    kind = int if column in _INT_COLUMNS else float
    values = []
    for row, field in enumerate(text.tolist(), start=2):
        try:
            values.append(kind(field) if field or kind is int else np.nan)
        except ValueError:
            raise InputError(f"{name}:{row}: column {column!r}: {field!r} is not a valid {kind.__name__}") from None
    return np.array(values, dtype=kind)
