"""The CSV files behind a validation report (lengths in mm, angles in degrees, errors as fractions).

- ``comparison.csv``: one row per instant (CL point × φ): cl, phi_deg, l_abm, l_ref,
  difference (l_abm − l_ref), error (relative where error_kind is ``relative``, the
  difference in mm where it is ``absolute_mm``: l_ref < 1e-3 mm), error_kind, lep_abm, lep_ref,
  uep_abm, uep_ref (along the edge; for a tool with a corner, heights along the axis above the tip),
  pieces_abm, pieces_ref, segment, uep_surface (ABM's), end_abm, end_ref, end_difference (the end
  cutting edge's engaged length by both and ABM − reference; empty where a side did not compute it).
- ``segments.csv``: one row per CL point and engagement segment (validation.segment_summary).
- ``surfaces.csv``: one row per kind of UEP surface (validation.surface_summary).
- ``depth.csv``: one row per CL point: cl, cl_x, cl_y, cl_z, depth_abm, depth_ref, difference,
  checked (1: the boolean checked the CL point, 0: not, its depth_ref empty).

When the boolean checked only some CL points (validate's --check, --check-every), comparison.csv
and segments.csv hold those CL points only, and the statistics are over them.

Against the in-process stock (Validation.in_process), comparison.csv also has l_initial (ABM's
length in the stock as given) and depth.csv changed (earlier moves changed the CL point: 1/0)
and swept (the swept pieces of earlier moves near the tool that the boolean sectioned).

Numbers are written with 12 significant digits; NaN is an empty field.
"""

import numpy as np

from ..validation import letters, segment_summary, surface_summary

COMPARISON_COLUMNS = (
    "cl", "phi_deg", "l_abm", "l_ref", "difference", "error", "error_kind", "lep_abm", "lep_ref", "uep_abm",
    "uep_ref", "pieces_abm", "pieces_ref", "segment", "uep_surface", "end_abm", "end_ref", "end_difference",
)
STATISTICS_COLUMNS = (
    "instants", "relative_instants", "max_rel_error", "mean_rel_error", "max_abs_difference",
    "max_lep_difference", "max_uep_difference", "mismatched", "end_instants", "max_end_difference", "end_mismatched",
)
SEGMENT_COLUMNS = ("cl", "segment", "phi_start", "phi_end", "surface", "section", "wall", *STATISTICS_COLUMNS)
SURFACE_COLUMNS = ("surface", *STATISTICS_COLUMNS)
DEPTH_COLUMNS = ("cl", "cl_x", "cl_y", "cl_z", "depth_abm", "depth_ref", "difference", "checked")
#: The columns added against the in-process stock.
INPROCESS_COMPARISON_COLUMNS = ("l_initial",)
INPROCESS_DEPTH_COLUMNS = ("changed", "swept")
#: The column added against the in-process stock for a tool with a corner: the swept pieces meeting the tool's
#: edges that the reference decided with the exact inside test (cad.sweep_membership) instead of OpenCASCADE's
#: solids.
CORNER_DEPTH_COLUMNS = ("gauged",)


def report_tables(validation, toolpath):
    """{file name: CSV text} of the four tables of a Validation of the pass `toolpath`."""
    engagement, comparison = validation.engagement, validation.comparison
    m, p = engagement.shape
    columns = {
        "cl": np.repeat(np.arange(m), p), "phi_deg": np.tile(engagement.phi, m),
        "l_abm": comparison.l_abm, "l_ref": comparison.l_ref, "difference": comparison.difference,
        "error": comparison.error,
        "error_kind": np.where(comparison.relative, "relative", "absolute_mm"),
        "lep_abm": comparison.lep_abm, "lep_ref": comparison.lep_ref,
        "uep_abm": comparison.uep_abm, "uep_ref": comparison.uep_ref,
        "pieces_abm": engagement.pieces, "pieces_ref": validation.reference["pieces"],
        "segment": letters(engagement), "uep_surface": engagement.surface_names(),
        "end_abm": comparison.end_abm, "end_ref": comparison.end_ref, "end_difference": comparison.end_difference,
    }
    depth = {
        "cl": np.arange(m), "cl_x": toolpath.cl[:, 0], "cl_y": toolpath.cl[:, 1], "cl_z": toolpath.cl[:, 2],
        "depth_abm": comparison.depth_abm, "depth_ref": comparison.depth_ref,
        "difference": comparison.depth_abm - comparison.depth_ref, "checked": validation.checked.astype(int),
    }
    comparison_names, depth_names = COMPARISON_COLUMNS, DEPTH_COLUMNS
    check = validation.in_process
    if check is not None:
        columns["l_initial"] = check.initial
        depth.update(changed=check.changed.astype(int), swept=check.swept)
        comparison_names += INPROCESS_COMPARISON_COLUMNS
        depth_names += INPROCESS_DEPTH_COLUMNS
        if check.gauged is not None:
            depth["gauged"] = check.gauged
            depth_names += CORNER_DEPTH_COLUMNS
    rows = np.ravel(comparison.checked)
    return {
        "comparison.csv": csv_text(comparison_names, [np.ravel(columns[c])[rows] for c in comparison_names]),
        "segments.csv": records_text(SEGMENT_COLUMNS, segment_summary(engagement, comparison)),
        "surfaces.csv": records_text(SURFACE_COLUMNS, surface_summary(engagement, comparison)),
        "depth.csv": csv_text(depth_names, [depth[c] for c in depth_names]),
    }


def records_text(names, records):
    """CSV text of a list of dicts, columns `names` in order."""
    return csv_text(names, [[record[name] for record in records] for name in names])


def csv_text(names, columns):
    """CSV text: a header of `names`, then one line per row of the equal-length `columns`.

    Float columns are written with 12 significant digits ('' for NaN); others as str.
    """
    cells = [_cells(column) for column in columns]
    lines = [",".join(names)] + [",".join(row) for row in zip(*cells)]
    return "\n".join(lines) + "\n"


def _cells(column):
    """List of str cells of one column (any 1-D sequence)."""
    values = np.asarray(column)
    if values.dtype.kind == "f":
        return ["" if np.isnan(v) else format(v + 0.0, ".12g") for v in values.tolist()]
    return [str(v) for v in values.tolist()]


#: Columns of flutes.csv (write_flutes_csv).
FLUTE_COLUMNS = ("cl", "phi_deg", "flute", "axial_abm", "axial_ref", "axial_difference", "edge_length_abm",
                 "edge_length_ref", "lep_abm", "lep_ref", "lep_difference", "uep_abm", "uep_ref", "uep_difference",
                 "pieces_abm", "pieces_ref")


def write_flutes_csv(path, helix_validation):
    """Write flutes.csv of a validation.HelixValidation: one row per CL point × φ × checked flute (flute numbered 1..Z), FLUTE_COLUMNS:
    axial length of cut, length along the helix, LEP and UEP (axial positions l), all mm, by ABM
    and by the boolean, the differences ABM − boolean, and the pieces of each."""
    engagement, reference = helix_validation.engagement, helix_validation.reference
    chosen = list(helix_validation.flutes)
    m, p, _ = engagement.shape
    grid = np.meshgrid(np.arange(m), engagement.phi, np.array(chosen) + 1, indexing="ij")
    columns = {"cl": grid[0], "phi_deg": grid[1], "flute": grid[2]}
    for key, name in (("axial", "axial_length"), ("edge_length", "edge_length"), ("lep", "lep_l"), ("uep", "uep_l"),
                      ("pieces", "pieces")):
        abm, ref = getattr(engagement, name)[..., chosen], reference[name][..., chosen]
        columns[f"{key}_abm"], columns[f"{key}_ref"] = abm, ref
        if key in ("axial", "lep", "uep"):
            columns[f"{key}_difference"] = abm - ref
    with open(path, "w", encoding="utf-8", newline="") as file:
        file.write(csv_text(FLUTE_COLUMNS, [np.ravel(columns[name]) for name in FLUTE_COLUMNS]))
