"""An Engagement read back from its results file: the CSV :mod:`abm_workbench.formats.results_csv`
writes, or the NumPy archive of columns :mod:`abm_workbench.formats.results_npz` writes (``.npz``).

The engagement object stores its results in that CSV, not in the document; this module turns
the file into the same :class:`~abm_workbench.engine.Engagement` the engine returned, with
every number within 5e-11 of the computed one (the CSV keeps 10 decimals; an .npz every bit).
The depth of cut per CL point is recomputed from the LEP / UEP z, as the engine computes it. With cutting
forces, :func:`read_forces` gives them back as a :class:`PassForces` (forces within 5e-11 N).

The document keeps its results itself, in a compressed NumPy archive (:func:`write_archive`,
:func:`read_archive`): every array of the Engagement and of the PassForces as computed, bit for
bit, and the ResultsDigest of the object they belong to.

Against the in-process stock (docs/ENGINE.md "Whole programs") the results also hold an
:class:`InProcess`: the length of cut in the stock as given per instant (the results CSV's
``length_initial``) and which CL points earlier moves changed (the summary's ``changed``);
:func:`write_results_csv` writes them, :func:`read_in_process` reads them back.
"""

import os
from dataclasses import dataclass, fields
from typing import Optional

import numpy as np

from ..engine import CASES, SURFACES, Engagement
from ..errors import InputError
from ..formats import replacing, results_csv, results_npz
from ..formats.results_columns import ADDED_COLUMNS, FORCE_COLUMNS, RESULT_COLUMNS
from ..formats.results_csv import chunk_texts, summary_path, write_text
from ..forces import ANGLE_EPS


def letter_index(letters):
    """Segment indices (N,) of segment letters ('A' -> 0, 'AA' -> 26, '' -> -1)."""
    out = np.full(len(letters), -1, dtype=np.int64)
    for i, text in enumerate(letters):
        value = 0
        for char in text:
            value = 26 * value + ord(char) - ord("A") + 1
        out[i] = value - 1
    return out


def read_results(path):
    """The results columns of results file `path` (name -> (rows,) array): an .npz by
    formats.results_npz, any other by formats.results_csv."""
    reader = results_npz if os.fspath(path).lower().endswith(".npz") else results_csv
    return reader.read_results(path)


def _pass_shape(name, cl):
    """(m, p) of a results file's cl column (rows,): m CL points of p angles each, in CL point
    order; InputError naming the file `name` otherwise."""
    m = int(cl.max()) + 1 if cl.size else 0
    if m == 0 or cl.size % m:
        raise InputError(f"{name}: {cl.size} rows are not the same number of angles for each of {m} CL points")
    p = cl.size // m
    if not np.array_equal(cl, np.repeat(np.arange(m), p)):
        raise InputError(f"{name}: rows are not in CL point order with {p} angles each")
    return m, p


def read_engagement(path):
    """The Engagement in results file `path` (CSV or .npz); InputError naming the file when it is not one."""
    name = os.fspath(path)
    columns = read_results(path)
    missing = [column for column in RESULT_COLUMNS if column not in columns and column not in ADDED_COLUMNS]
    if missing:
        raise InputError(f"{name}: not a results file: missing column {missing[0]!r}")
    m, p = _pass_shape(name, columns["cl"])

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
        phi=phi, h=grid("h"), lep_l=grid("lep_l"), uep_l=grid("uep_l"), length=length,
        pieces=grid("pieces", np.int32), uep_surface=lookup("uep_surface", SURFACES),
        uep_section=grid("uep_section", np.int32), uep_wall=grid("uep_wall", np.int32),
        case=lookup("case", CASES), segment=letter_index(columns["segment"].tolist()).astype(np.int32).reshape(m, p),
        area=grid("area"), lep_xyz=lep_xyz, uep_xyz=uep_xyz, depth_of_cut=depth,
        lep_surface=lookup("lep_surface", SURFACES), lep_section=grid("lep_section", np.int32),
        lep_wall=grid("lep_wall", np.int32),
        end_length=grid("end_length") if "end_length" in columns else None,
    )


@dataclass(frozen=True)
class PassForces:
    """The cutting forces an engagement object keeps: per instant of m CL points × p angles φ.

    phi: (p,) deg. xyz: (m, p, 3) force on the tool, global frame (N). torque: (m, p) N·mm.
    power: (m, p) W, or None without a spindle speed. feed: (m,) feed per tooth (mm). The
    attributes the results CSV writer and report.forces' figures read of a
    :class:`abm_workbench.forces.Forces`, which is what :meth:`of` keeps.
    """

    phi: np.ndarray
    xyz: np.ndarray
    torque: np.ndarray
    power: Optional[np.ndarray]
    feed: np.ndarray

    @classmethod
    def of(cls, forces):
        """The PassForces of a Forces."""
        return cls(forces.phi, forces.xyz, forces.torque, forces.power, forces.feed)

    @property
    def shape(self):
        """(m, p): CL points × rotation angles."""
        return self.torque.shape

    @property
    def resultant(self):
        """(m, p) magnitude of the force (N)."""
        return np.linalg.norm(self.xyz, axis=-1)

    @property
    def peak(self):
        """(m,) largest resultant over the angles of each CL point (N)."""
        return self.resultant.max(axis=1)

    @property
    def mean(self):
        """(m,) mean resultant over the angles of each CL point, one revolution at most (N), as Forces.mean."""
        return self.resultant[:, self.phi < self.phi[0] + 360.0 - ANGLE_EPS].mean(axis=1)


def read_forces(path, feed):
    """The PassForces in results file `path` (CSV or .npz; its fx, fy, fz, torque and, if there, power columns),
    at feed per tooth `feed` (mm, scalar or (m,)); None when it has no force columns. InputError
    naming the file when the columns are incomplete."""
    name = os.fspath(path)
    columns = read_results(path)
    if "fx" not in columns:
        return None
    missing = [column for column in FORCE_COLUMNS[:4] if column not in columns]
    if missing:
        raise InputError(f"{name}: force columns without {missing[0]!r}")
    m, p = _pass_shape(name, columns["cl"])
    xyz = np.stack([columns[axis].reshape(m, p) for axis in ("fx", "fy", "fz")], axis=-1)
    if not np.isfinite(xyz).all():
        raise InputError(f"{name}: a force column has an empty or non-finite field")
    power = columns["power"].reshape(m, p) if "power" in columns else None
    return PassForces(columns["phi_deg"][:p].astype(float), xyz, columns["torque"].reshape(m, p), power,
                      np.broadcast_to(np.asarray(feed, dtype=float), (m,)).copy())


@dataclass(frozen=True)
class InProcess:
    """What an engagement against the in-process stock adds, for m CL points × p angles φ.

    initial: (m, p) length of cut (mm) in the stock as given, before earlier moves removed
    anything. changed: (m,) bool, earlier moves of the program removed material that an edge
    line of the CL point would meet.
    """

    initial: np.ndarray
    changed: np.ndarray


def write_results_csv(path, result, *, toolpath=None, forces=None, in_process=None):
    """Write the results CSV of the Engagement `result` and its summary beside it, both or neither: the
    command line's bytes (formats.results_csv.chunk_texts), with the force columns for PassForces
    `forces` and, for an InProcess `in_process`, length_initial and changed. toolpath: the Toolpath,
    for the summary's CL point columns, or None."""
    initial, changed = (None, None) if in_process is None else (in_process.initial, in_process.changed)
    texts = chunk_texts(result, 0, toolpath=toolpath, forces=forces, initial=initial, changed=changed)
    with replacing(path, summary_path(path)) as temporaries:
        for temporary, text in zip(temporaries, texts):
            write_text(temporary, text)


def read_in_process(path):
    """The InProcess of results CSV `path` (its length_initial and its summary's changed column), or None
    for results against the stock as given; InputError naming the file when only one of them is there."""
    name, summary = os.fspath(path), summary_path(path)
    columns = read_results(path)
    if "length_initial" not in columns:
        return None
    m, p = _pass_shape(name, columns["cl"])
    segments = read_results(summary)
    if "changed" not in segments:
        raise InputError(f"{summary}: no column 'changed', but {name} has length_initial")
    changed = np.zeros(m, dtype=bool)
    changed[segments["cl"]] = segments["changed"] != 0
    return InProcess(np.asarray(columns["length_initial"], dtype=float).reshape(m, p), changed)


#: Key prefixes of the arrays in an embedded results archive (write_archive).
_ENGAGEMENT, _FORCES, _IN_PROCESS = "engagement.", "forces.", "inprocess."


def write_archive(path, digest, result, forces=None, in_process=None):
    """Write the Engagement `result` (and the PassForces `forces` and InProcess `in_process`, if any) to
    `path` as a compressed NumPy archive (.npz), with `digest`: the ResultsDigest of the object they
    belong to (text)."""
    arrays = {"digest": np.array(digest)}
    arrays.update({_ENGAGEMENT + field.name: getattr(result, field.name) for field in fields(Engagement)})
    if forces is not None:
        arrays.update({_FORCES + field.name: getattr(forces, field.name) for field in fields(PassForces)
                       if getattr(forces, field.name) is not None})
    if in_process is not None:
        arrays.update({_IN_PROCESS + field.name: getattr(in_process, field.name) for field in fields(InProcess)})
    with open(path, "wb") as handle:
        np.savez_compressed(handle, **arrays)


def read_archive(path):
    """(digest, Engagement, PassForces or None, InProcess or None) of an archive written by
    write_archive; InputError naming the file when it is not one."""
    name = os.fspath(path)
    try:
        with np.load(path, allow_pickle=False) as archive:
            arrays = {key: archive[key] for key in archive.files}
    except (OSError, ValueError) as error:
        raise InputError(f"{name}: not a results archive ({error})") from None
    missing = [field.name for field in fields(Engagement) if _ENGAGEMENT + field.name not in arrays]
    if "digest" not in arrays or missing:
        raise InputError(f"{name}: not a results archive: no {missing[0] if missing else 'digest'}")
    result = Engagement(**{field.name: arrays[_ENGAGEMENT + field.name] for field in fields(Engagement)})
    forces = None
    if _FORCES + "xyz" in arrays:
        forces = PassForces(**{field.name: arrays.get(_FORCES + field.name) for field in fields(PassForces)})
    in_process = None
    if _IN_PROCESS + "initial" in arrays:
        in_process = InProcess(**{field.name: arrays[_IN_PROCESS + field.name] for field in fields(InProcess)})
    return str(arrays["digest"]), result, forces, in_process
