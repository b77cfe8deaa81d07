"""An Engagement read back from its results CSV (the file :mod:`abm_workbench.formats.results_csv` writes).

The engagement object stores its results in that CSV, not in the document; this module turns
the file into the same :class:`~abm_workbench.engine.Engagement` the engine returned, with
every number within 5e-11 of the computed one (the CSV keeps 10 decimals). The depth of cut
per CL point is recomputed from the LEP / UEP z, as the engine computes it.
"""

import os

import numpy as np

from ..engine import CASES, SURFACES, Engagement
from ..errors import InputError
from ..formats.results_csv import RESULT_COLUMNS, read_results


def letter_index(letters):
    """Segment indices (N,) of segment letters ('A' -> 0, 'AA' -> 26, '' -> -1)."""
    out = np.full(len(letters), -1, dtype=np.int64)
    for i, text in enumerate(letters):
        value = 0
        for char in text:
            value = 26 * value + ord(char) - ord("A") + 1
        out[i] = value - 1
    return out


def read_engagement(path):
    """The Engagement in results CSV `path`; InputError naming the file when it is not one."""
    name = os.fspath(path)
    columns = read_results(path)
    missing = [column for column in RESULT_COLUMNS if column not in columns]
    if missing:
        raise InputError(f"{name}: not a results CSV: missing column {missing[0]!r}")
    cl = columns["cl"]
    m = int(cl.max()) + 1 if cl.size else 0
    if m == 0 or cl.size % m:
        raise InputError(f"{name}: {cl.size} rows are not the same number of angles for each of {m} CL points")
    p = cl.size // m
    if not np.array_equal(cl, np.repeat(np.arange(m), p)):
        raise InputError(f"{name}: rows are not in CL point order with {p} angles each")

    def grid(column, dtype=float):
        return np.asarray(columns[column], dtype=dtype).reshape(m, p)

    def lookup(column, names):
        index = {text: i for i, text in enumerate(names)}
        unknown = sorted(set(columns[column].tolist()) - set(index))
        if unknown:
            raise InputError(f"{name}: column {column!r}: unknown value {unknown[0]!r}")
        return np.array([index[text] for text in columns[column].tolist()], dtype=np.int8).reshape(m, p)

    phi = columns["phi_deg"][:p].astype(float)
    lep_xyz = np.stack([grid(f"lep_{axis}") for axis in "xyz"], axis=-1)
    uep_xyz = np.stack([grid(f"uep_{axis}") for axis in "xyz"], axis=-1)
    length = grid("length")
    engaged = length > 0.0
    with np.errstate(invalid="ignore"):
        top = np.where(engaged, uep_xyz[..., 2], -np.inf).max(axis=1)
        bottom = np.where(engaged, lep_xyz[..., 2], np.inf).min(axis=1)
    depth = np.where(engaged.any(axis=1), top - bottom, np.nan)
    return Engagement(
        phi=phi, h=columns["h"][:p].astype(float), lep_l=grid("lep_l"), uep_l=grid("uep_l"), length=length,
        pieces=grid("pieces", np.int32), uep_surface=lookup("uep_surface", SURFACES),
        uep_section=grid("uep_section", np.int32), uep_wall=grid("uep_wall", np.int32),
        case=lookup("case", CASES), segment=letter_index(columns["segment"].tolist()).reshape(m, p),
        area=grid("area"), lep_xyz=lep_xyz, uep_xyz=uep_xyz, depth_of_cut=depth,
    )
