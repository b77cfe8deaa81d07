"""The columns of an engagement's results and summary, as arrays: what the CSV and the npz writers share.

Results, one row per instant (CL point × φ, CL points in pass order, φ ascending within each):
:data:`RESULT_COLUMNS`, then :data:`INPROCESS_COLUMNS` against the in-process stock, then
:data:`FORCE_COLUMNS` with cutting forces (power only with a spindle speed). Summary, one row per
CL point and engagement segment (one row with no segment for a CL point without engagement):
:data:`SUMMARY_COLUMNS`, then :data:`TOOLPATH_COLUMNS` when the toolpath is given,
:data:`FORCE_SUMMARY_COLUMNS` with forces, :data:`INPROCESS_SUMMARY_COLUMNS` against the
in-process stock. Units: mm, deg, mm², N, N·mm, W (formats.results_csv's docstring names each).

Every column is an array (rows,) of a fixed dtype (:func:`column_dtype`): float64 (NaN: no value),
an integer, or, for the :data:`TEXT_COLUMNS`, integer codes into the column's labels
(:func:`text_labels`): a surface's or case's name, a segment's letter ('' for none).
"""

import numpy as np

from ..engine import CASES, SURFACES, segment_letter

RESULT_COLUMNS = (
    "cl", "phi_deg", "lep_l", "uep_l", "length", "pieces", "uep_surface", "uep_section", "uep_wall",
    "case", "segment", "h", "area", "lep_x", "lep_y", "lep_z", "uep_x", "uep_y", "uep_z",
    "lep_surface", "lep_section", "lep_wall", "end_length",
)
#: Results columns added after files were first written: a reader takes a file without them (as NaN).
ADDED_COLUMNS = ("end_length",)
SUMMARY_COLUMNS = (
    "cl", "depth_of_cut", "segment", "phi_start", "phi_end", "uep_surface", "uep_section", "uep_wall",
    "max_length", "mean_length",
)
#: Results columns added with forces (power only with a spindle speed), and summary columns.
FORCE_COLUMNS = ("fx", "fy", "fz", "torque", "power")
FORCE_SUMMARY_COLUMNS = ("peak_force", "mean_force", "peak_torque")
#: Columns added against the in-process stock: per instant the length of cut in the stock itself, per CL
#: point whether earlier moves of the program removed material its edges would meet (1) or not (0).
INPROCESS_COLUMNS, INPROCESS_SUMMARY_COLUMNS = ("length_initial",), ("changed",)
#: Summary columns added when the toolpath is given.
TOOLPATH_COLUMNS = ("cl_x", "cl_y", "cl_z", "theta_a", "theta_b")
#: Columns of names, held as integer codes into their labels (text_labels).
TEXT_COLUMNS = ("uep_surface", "lep_surface", "case", "segment")
#: Integer columns and their dtype; every other column not in TEXT_COLUMNS is float64.
INT_COLUMNS = {"cl": np.int64, "pieces": np.int32, "uep_section": np.int32, "uep_wall": np.int32,
               "lep_section": np.int32, "lep_wall": np.int32, "changed": np.int8}
#: dtype of the codes of each text column.
_CODE_DTYPES = {"uep_surface": np.uint8, "lep_surface": np.uint8, "case": np.uint8, "segment": np.int32}


def column_dtype(name):
    """The numpy dtype of column `name`: its integer or code dtype, else float64."""
    return np.dtype(INT_COLUMNS.get(name) or _CODE_DTYPES.get(name) or np.float64)


def text_labels(name, count):
    """The labels (count,) of text column `name` its codes 0 … count − 1 stand for: SURFACES for
    uep_surface and lep_surface, CASES for case (whatever `count`), for segment '' (code 0, no
    segment), then 'A', 'B', …, one per code up to count − 1."""
    if name == "segment":
        return [""] + [segment_letter(index) for index in range(count - 1)]
    return list(CASES if name == "case" else SURFACES)


def result_columns(engagement, *, first_cl=0, forces=None, initial=None):
    """The results columns of an Engagement of m CL points × p angles: dict name -> (m·p,) array
    of column_dtype(name), in column order. first_cl: index of its first CL point in the pass (for
    a chunk of a pass). forces: a Forces of the same CL points (the force columns); initial: (m, p)
    mm, the length of cut in the stock itself (against the in-process stock)."""
    m, p = engagement.shape
    columns = {"cl": first_cl + np.repeat(np.arange(m, dtype=np.int64), p), "phi_deg": np.tile(engagement.phi, m)}
    for name in RESULT_COLUMNS[2:]:
        if name[:4] in ("lep_", "uep_") and name[4:] in ("x", "y", "z"):
            columns[name] = getattr(engagement, f"{name[:3]}_xyz")[..., "xyz".index(name[4])].reshape(-1)
        else:
            columns[name] = getattr(engagement, name).reshape(-1)
    columns["segment"] = columns["segment"] + 1
    if initial is not None:
        columns["length_initial"] = np.asarray(initial, dtype=float).reshape(-1)
    if forces is not None:
        xyz = forces.xyz.reshape(-1, 3)
        columns.update(fx=xyz[:, 0], fy=xyz[:, 1], fz=xyz[:, 2], torque=forces.torque.reshape(-1))
        if forces.power is not None:
            columns["power"] = forces.power.reshape(-1)
    return _typed(columns)


def summary_columns(engagement, *, toolpath=None, first_cl=0, forces=None, changed=None):
    """The summary columns of an Engagement: dict name -> (rows,) array of column_dtype(name), in
    column order, one row per CL point and engagement segment, and one (no segment, depth NaN if it
    does not engage, max and mean length 0) for each CL point without any, in CL order.

    first_cl: index of the engagement's first CL point in its pass (for a chunk of a pass; toolpath,
    forces and changed are then the chunk's). changed: (m,) bool, against the in-process stock:
    earlier moves removed material the CL point's edges would meet.
    """
    table = engagement.segment_table()
    idle = np.flatnonzero(np.bincount(table["cl"], minlength=engagement.shape[0]) == 0)
    order = np.argsort(np.concatenate([table["cl"], idle]), kind="stable")

    def rows(values, idle_value):
        return np.concatenate([values, np.full(idle.size, idle_value, dtype=np.asarray(values).dtype)])[order]

    cl = np.concatenate([table["cl"], idle])[order]
    columns = {
        "cl": cl + first_cl, "depth_of_cut": engagement.depth_of_cut[cl], "segment": rows(table["index"], -1) + 1,
        "phi_start": rows(table["phi_start"], np.nan), "phi_end": rows(table["phi_end"], np.nan),
        "uep_surface": rows(table["surface"], SURFACES.index("none")), "uep_section": rows(table["section"], -1),
        "uep_wall": rows(table["wall"], -1), "max_length": rows(table["max_length"], 0.0),
        "mean_length": rows(table["mean_length"], 0.0),
    }
    if toolpath is not None:
        if len(toolpath) != engagement.shape[0]:
            raise ValueError(f"toolpath has {len(toolpath)} CL points, the engagement {engagement.shape[0]}")
        columns.update({name: toolpath.cl[cl, axis] for axis, name in enumerate(TOOLPATH_COLUMNS[:3])})
        columns.update(theta_a=toolpath.theta_a[cl], theta_b=toolpath.theta_b[cl])
    if forces is not None:
        columns.update(peak_force=forces.peak[cl], mean_force=forces.mean[cl],
                       peak_torque=forces.torque.max(axis=1)[cl])
    if changed is not None:
        columns["changed"] = np.asarray(changed)[cl]
    return _typed(columns)


def chunk_columns(engagement, first_cl, *, toolpath=None, forces=None, initial=None, changed=None):
    """(results columns, summary columns) of a chunk of a pass: the Engagement of CL points first_cl, …;
    toolpath, forces, initial, changed: the chunk's, or None (result_columns, summary_columns)."""
    return (result_columns(engagement, first_cl=first_cl, forces=forces, initial=initial),
            summary_columns(engagement, toolpath=toolpath, first_cl=first_cl, forces=forces, changed=changed))


def _typed(columns):
    """`columns` with each array as its column_dtype (1-D, copied only where the dtype changes)."""
    return {name: np.asarray(values).astype(column_dtype(name), copy=False).reshape(-1)
            for name, values in columns.items()}
