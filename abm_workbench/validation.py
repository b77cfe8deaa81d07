"""The engine against the boolean reference, instant by instant, as the paper reports it.

The paper's error of the length of cut is relative: (l_ABM − l_ref) / l_ref. Where the
reference length is tiny (l_ref < TINY_LENGTH = 1e-3 mm: the edge grazes the stock, or only
one of the two methods engages) a relative error means nothing, and the absolute difference
l_ABM − l_ref (mm) is reported instead; the two kinds are kept apart in every summary.

Arrays are over m CL points × p rotation angles φ. Lengths in mm, angles in degrees,
relative errors as fractions (0.01 = 1 %). Every tool is checked along its whole cutting edge: the
peripheral edge (a flat-end mill's side line; a bull-nose or ball-end mill's corner arc and side, its
length of cut the arc length along both, LEP and UEP heights along the axis above the tip) and the end
edge (its engaged length compared apart: Comparison.end_abm, end_ref). Everything here is numpy, except
:func:`validate`, which runs the boolean reference through :mod:`abm_workbench.cad.profile_boolean` (FreeCAD;
a flat-end mill's side lines by :mod:`abm_workbench.cad.boolean`, as before), and
:func:`validate_helix`, its counterpart for helical edges (:mod:`abm_workbench.cad.helix_boolean`):
per instant and flute the axial length of cut, LEP and UEP (axial positions l) of
flute_engagement against the helix boolean.

Both take ``workers=N``: the reference of each CL point is then computed in one of N local
processes (:mod:`abm_workbench.worker_processes`: spawned, a Python interpreter even under the GUI,
each with its own FreeCAD and its own copy of the solid, sent once as BREP text), CL points handed
out one at a time as processes become free; or ``scheduler="tcp://host:port"``: on the Dask
cluster behind that scheduler, the BREP text scattered to every Dask worker once. Each CL point's
reference depends on that CL point alone, so the result is the same, bit for bit, as in one
process. progress(done, total) is still called once per CL point, as they finish; an interrupt
(KeyboardInterrupt, the command line's SIGTERM / SIGHUP, a progress callback that raises) ends
every local worker at once, and no worker is left whenever it comes.
"""

import contextlib
import threading
import time
from dataclasses import dataclass
from typing import Optional

import numpy as np

from .engine import (SURFACES, Engagement, FluteEngagement, Tool, Toolpath, edge_lines, flute_engagement,
                     segment_letter)
from .engine.stocks import engage_in_process, engage_stock

#: Below this reference length (mm) the error is absolute, not relative.
TINY_LENGTH = 1e-3


class NoEngagementError(ValueError):
    """The engine finds no instant of the pass at which the tool touches the stock."""


@dataclass(frozen=True)
class Comparison:
    """ABM against the reference at every instant, (m, p) arrays unless said.

    l_abm, l_ref: length of cut (mm). difference: l_abm − l_ref (mm). relative: bool, the
    error is relative (l_ref ≥ TINY_LENGTH). error: difference / l_ref where relative, else
    difference (mm). lep_abm, lep_ref, uep_abm, uep_ref: LEP and UEP along the edge (mm, NaN
    without engagement). lep_difference, uep_difference: ABM − reference (mm, NaN unless both
    engage). depth_abm, depth_ref: (m,) depth of cut (mm, NaN without engagement). end_abm, end_ref: engaged
    length of the end cutting edge (mm; NaN where a side did not compute it: an engine's CL points
    against the in-process stock, a reference without end edges); end_difference: end_abm − end_ref (NaN
    unless both are known). For a tool with a corner, l is the arc length along the peripheral edge (corner
    arc and straight side) and LEP, UEP are heights along the tool axis above the tip.
    """

    l_abm: np.ndarray
    l_ref: np.ndarray
    difference: np.ndarray
    relative: np.ndarray
    error: np.ndarray
    lep_abm: np.ndarray
    lep_ref: np.ndarray
    uep_abm: np.ndarray
    uep_ref: np.ndarray
    lep_difference: np.ndarray
    uep_difference: np.ndarray
    depth_abm: np.ndarray
    depth_ref: np.ndarray
    end_abm: np.ndarray = None
    end_ref: np.ndarray = None
    end_difference: np.ndarray = None

    def __post_init__(self):
        for name in ("end_abm", "end_ref", "end_difference"):
            if getattr(self, name) is None:
                object.__setattr__(self, name, np.full(np.shape(self.l_abm), np.nan))

    @property
    def relative_error(self):
        """(m, p) relative error, NaN where the error is absolute."""
        return np.where(self.relative, self.error, np.nan)

    @property
    def checked(self):
        """(m, p) bool: the reference was computed at the instant (validate's cls); NaN l_ref elsewhere."""
        return ~np.isnan(self.l_ref)

    @property
    def mismatched(self):
        """(m, p) bool: exactly one of ABM and the reference engages (checked instants only)."""
        return self.checked & ((self.l_abm > 0.0) != (self.l_ref > 0.0))

    @property
    def end_checked(self):
        """(m, p) bool: both sides give the end edge's engaged length (checked instants only)."""
        return self.checked & np.isfinite(self.end_abm) & np.isfinite(self.end_ref)

    @property
    def end_mismatched(self):
        """(m, p) bool: exactly one side finds the end edge in the stock (instants of end_checked)."""
        return self.end_checked & ((np.nan_to_num(self.end_abm) > 0.0) != (np.nan_to_num(self.end_ref) > 0.0))


@dataclass(frozen=True)
class InProcessCheck:
    """What a validation against the in-process stock adds: initial (m, p) the engine's length of
    cut in the stock as given (mm); changed (m,) bool, earlier moves removed material from some
    edge line of the CL point (the engine's finding); swept (m,) int, the swept pieces of earlier
    moves near the tool that the reference sectioned at each CL point; gauged (m,) int, those of them that
    meet the edges and that it decided with the exact inside test instead of OpenCASCADE's solids
    (cad.sweep_membership: a bull-nose mill's nearly flat ramps), None for a flat-end mill."""

    initial: np.ndarray
    changed: np.ndarray
    swept: np.ndarray
    gauged: np.ndarray = None


@dataclass(frozen=True)
class Validation:
    """A validated pass: the engine's Engagement, the reference, their Comparison, the timings.

    reference: dict of (m, p) arrays length, lep_l, uep_l, pieces, end_length, end_pieces (cad.profile_boolean;
    a tool with a corner also corner_length, and (m, p, 3) lep_xyz, uep_xyz).
    seconds: {"abm": engine time, "boolean": reference time} (s). in_process: an InProcessCheck
    when both sides worked against the in-process stock, None against the stock as given.
    """

    engagement: Engagement
    reference: dict
    comparison: Comparison
    seconds: dict
    in_process: Optional[InProcessCheck] = None

    @property
    def checked(self):
        """(m,) bool: the CL points the reference was computed at (all unless validate's cls chose)."""
        return self.comparison.checked.any(axis=1)

    @property
    def speed_ratio(self):
        """Boolean time / ABM time (how many times faster the engine is)."""
        return self.seconds["boolean"] / max(self.seconds["abm"], 1e-9)


def compare(engagement: Engagement, reference, toolpath: Toolpath, tool: Tool):
    """The Comparison of an Engagement (m × p) with a reference dict of (m, p) arrays.

    reference: length, lep_l, uep_l (mm along the edge, or for a tool with a corner heights along the axis
    above the tip; NaN without engagement), at the same CL points of `toolpath` and the same angles
    engagement.phi; optionally end_length (the end edge's engaged length, mm) and lep_xyz, uep_xyz ((m, p, 3)
    the LEP and UEP points, mm). The reference depth of cut is taken from the z of its LEP and UEP points
    where it gives them, else computed from its LEP and UEP on the edge lines of `tool` (a flat-end mill's).
    """
    arrays = _reference_arrays(engagement, reference)
    if "lep_xyz" in reference and "uep_xyz" in reference:
        z_lep, z_uep = (np.asarray(reference[name], dtype=float)[..., 2] for name in ("lep_xyz", "uep_xyz"))
    else:
        if tool.corner_radius > 0.0:
            raise ValueError("a reference for a tool with a corner must give lep_xyz and uep_xyz")
        base, direction = edge_lines(toolpath, tool, engagement.phi)
        z_lep = base[..., 2] + arrays["lep_l"] * direction[:, None, 2]
        z_uep = base[..., 2] + arrays["uep_l"] * direction[:, None, 2]
    return _comparison(engagement, arrays, z_lep, z_uep)


def _reference_arrays(engagement, reference):
    """{length, lep_l, uep_l, end_length}: the reference's (m, p) float arrays, shape-checked against
    `engagement` (end_length NaN where the reference has none)."""
    m, p = engagement.shape
    arrays = {}
    for name in ("length", "lep_l", "uep_l", "end_length"):
        if name == "end_length" and name not in reference:
            arrays[name] = np.full((m, p), np.nan)
            continue
        array = np.asarray(reference[name], dtype=float)
        if array.shape != (m, p):
            raise ValueError(f"reference[{name!r}] must have shape {(m, p)}, got {array.shape}")
        arrays[name] = array
    return arrays


def _comparison(engagement, arrays, z_lep, z_uep):
    """The Comparison of `engagement` with the reference `arrays`, whose LEP and UEP lie at heights
    z_lep, z_uep (m, p) mm."""
    l_abm, l_ref = engagement.length, arrays["length"]
    difference = l_abm - l_ref
    relative = l_ref >= TINY_LENGTH
    error = np.where(relative, difference / np.where(relative, l_ref, 1.0), difference)
    end_abm = np.asarray(engagement.end_length, dtype=float)
    return Comparison(
        l_abm, l_ref, difference, relative, error,
        engagement.lep_l, arrays["lep_l"], engagement.uep_l, arrays["uep_l"],
        engagement.lep_l - arrays["lep_l"], engagement.uep_l - arrays["uep_l"],
        engagement.depth_of_cut, _depth(z_lep, z_uep), end_abm, arrays["end_length"], end_abm - arrays["end_length"],
    )


def _depth(z_lep, z_uep):
    """(m,) highest UEP z − lowest LEP z per row of (m, p) heights; NaN for a row without any."""
    engaged = ~np.isnan(z_uep)
    high = np.where(engaged, z_uep, -np.inf).max(axis=1)
    low = np.where(engaged, z_lep, np.inf).min(axis=1)
    return np.where(engaged.any(axis=1), high - low, np.nan)


def _statistics(comparison, mask):
    """Error statistics over the checked instants of bool `mask` (m, p): a dict (see segment_summary)."""
    mask = mask & comparison.checked
    relative = mask & comparison.relative
    rel = np.abs(comparison.error[relative])
    lep = np.abs(comparison.lep_difference[mask])
    uep = np.abs(comparison.uep_difference[mask])
    return {
        "instants": int(mask.sum()),
        "relative_instants": int(relative.sum()),
        "max_rel_error": float(rel.max()) if rel.size else np.nan,
        "mean_rel_error": float(rel.mean()) if rel.size else np.nan,
        "max_abs_difference": float(np.abs(comparison.difference[mask]).max()) if mask.any() else np.nan,
        "max_lep_difference": float(np.nanmax(lep)) if np.isfinite(lep).any() else np.nan,
        "max_uep_difference": float(np.nanmax(uep)) if np.isfinite(uep).any() else np.nan,
        "mismatched": int((mask & comparison.mismatched).sum()),
        "end_instants": int((mask & comparison.end_checked).sum()),
        "max_end_difference": _largest(np.abs(comparison.end_difference[mask & comparison.end_checked])),
        "end_mismatched": int((mask & comparison.end_mismatched).sum()),
    }


def segment_summary(engagement: Engagement, comparison: Comparison, cls=None):
    """The error per CL point and engagement segment (the paper's Fig. 8(c), 8(e)): a list of dicts.

    cls: CL indices to summarise (default those the reference checked). Each dict: cl, segment
    (letter), phi_start, phi_end (deg), surface, section, wall (the UEP's, as Engagement.segments), instants,
    relative_instants (of them, those with l_ref ≥ TINY_LENGTH), max_rel_error,
    mean_rel_error (|relative error| over those, NaN if none), max_abs_difference
    (max |l_ABM − l_ref| over all instants, mm), max_lep_difference, max_uep_difference (mm),
    mismatched (instants where the reference finds no engagement: ABM engages throughout a
    segment); end_instants (those where both sides give the end edge's engaged length),
    max_end_difference (max |end_ABM − end_ref| over them, mm, NaN if none), end_mismatched (those
    where only one side finds the end edge in the stock). Instants without an ABM segment are
    counted in surface_summary's "none".
    """
    rows = []
    for cl in np.flatnonzero(comparison.checked.any(axis=1)) if cls is None else cls:
        for index, segment in enumerate(engagement.segments(cl)):
            mask = np.zeros(engagement.shape, dtype=bool)
            mask[cl] = engagement.segment[cl] == index
            rows.append({"cl": int(cl), "segment": segment["letter"], "phi_start": segment["phi_start"],
                         "phi_end": segment["phi_end"], "surface": segment["surface"],
                         "section": segment["section"], "wall": segment["wall"], **_statistics(comparison, mask)})
    return rows


def surface_summary(engagement: Engagement, comparison: Comparison):
    """The error per kind of UEP surface over the whole pass: a list of dicts, in SURFACES order.

    Each dict: surface, then the statistics of segment_summary. Kinds that never hold the UEP
    are left out; "none" holds the instants ABM finds no engagement at, and it is listed only
    when the reference engages at some of them.
    """
    rows = []
    for code, name in enumerate(SURFACES):
        mask = engagement.uep_surface == code
        if name == "none":
            mask &= comparison.l_ref > 0.0
        if mask.any():
            rows.append({"surface": name, **_statistics(comparison, mask)})
    return rows


def overall(comparison: Comparison):
    """The statistics of segment_summary over every instant of the pass."""
    return _statistics(comparison, np.ones(comparison.l_abm.shape, dtype=bool))


def letters(engagement: Engagement):
    """(m, p) str array of segment letters, '' without engagement."""
    names = np.array([segment_letter(s) for s in range(int(engagement.segment.max(initial=-1)) + 1)] + [""])
    return names[engagement.segment]


def validate(solid, staircase, tool: Tool, toolpath: Toolpath, settings, *, progress=None, workers=1,
             scheduler=None, sweep=None, cls=None, apart=False):
    """Run the engine on one pass and the boolean reference at its CL points `cls`; a Validation.

    solid: the stock as a Part.Shape (the reference's stock); staircase: the engine's (a Staircase or a
    TerracedStock). The reference sections every cutting edge of the tool (cad.profile_boolean): a flat-end
    mill's side lines (cad.boolean's reference, unchanged) and end edges; a bull-nose or ball-end mill's
    corner arcs (true circular arcs), side lines and end edges. sweep: (SweptPieces of the whole program,
    (m,) program row of each CL point), both in the pass's frame, to check against the in-process stock (the
    engine's engage_in_process against cad.profile_boolean.flat_lengths_in_process, or for a tool with a
    corner cad.corner_inprocess.corner_lengths_in_process), or None for the stock as given. progress(done,
    total) is called after each CL point of the reference. cls: the CL indices (0-based, distinct) the
    reference checks, None: all; elsewhere the reference's arrays are NaN (Comparison.checked) and the
    statistics leave those CL points out (ValueError, before any work, for a list that is empty, repeats
    an index or leaves 0..m−1). workers: processes computing the reference
    (1: this one; 0: one per core; see the module docstring; against the in-process stock a pass that
    repeats a CL point exactly is computed as one task, its CL points not being told apart in a task of
    one);
    scheduler: a Dask scheduler's address to compute it on instead (reference_by_workers). apart: the
    reference in worker processes also for 1 worker (reference_by_workers). Raises
    NoEngagementError, before running the reference, when the engine finds no engagement at
    all. Needs FreeCAD.
    """
    from .cad.corner_inprocess import corner_lengths_in_process
    from .cad.inprocess_boolean import ProgramSweep
    from .cad.profile_boolean import flat_lengths_by_boolean, flat_lengths_in_process, profile_lengths_by_boolean

    chosen = _checked_rows(cls, len(toolpath))
    started = time.perf_counter()
    if sweep is None:
        engagement = engage_stock(staircase, tool, toolpath, settings)
    else:
        pieces, rows = sweep
        engagement, initial, changed = engage_in_process(staircase, tool, toolpath, settings, pieces, rows)
    abm_seconds = time.perf_counter() - started
    if not engagement.engaged.any():
        raise NoEngagementError("no CL point of the pass engages the stock")
    part = toolpath if chosen is None else toolpath.rows(chosen)
    started = time.perf_counter()
    if sweep is None:
        function = profile_lengths_by_boolean if tool.corner_radius > 0.0 else flat_lengths_by_boolean
        extra = ()
    else:
        part_rows = np.asarray(rows) if chosen is None else np.asarray(rows)[chosen]
        function = corner_lengths_in_process if tool.corner_radius > 0.0 else flat_lengths_in_process
        extra = (ProgramSweep(pieces, part_rows, part),)
    whole = sweep is not None and _repeats_cl_point(part)
    reference = reference_by_workers(function, solid, tool, part, engagement.phi, extra,
                                     workers=1 if whole else workers, scheduler=scheduler, progress=progress,
                                     apart=apart, whole=whole)
    if chosen is not None:
        reference = _spread(reference, chosen, len(toolpath))
    boolean_seconds = time.perf_counter() - started
    comparison = compare(engagement, reference, toolpath, tool)
    check = None if sweep is None else InProcessCheck(initial, changed, reference["swept"], reference.get("gauged"))
    return Validation(engagement, reference, comparison, {"abm": abm_seconds, "boolean": boolean_seconds}, check)


def _checked_rows(cls, m):
    """(k,) int CL indices of `cls` (distinct, each in 0..m−1, at least one), or None for all."""
    if cls is None:
        return None
    chosen = np.asarray(cls, dtype=int).reshape(-1)
    if chosen.size == 0 or np.unique(chosen).size != chosen.size or chosen.min() < 0 or chosen.max() >= m:
        raise ValueError(f"cls must be distinct CL indices in 0..{m - 1}, at least one; got {list(cls)!r}")
    return chosen


def _spread(reference, chosen, m):
    """The reference dict of k checked CL points (arrays over k first) spread over the m CL points of
    the pass: row chosen[i] holds row i, the other rows NaN (integer arrays become float)."""
    spread = {}
    for name, values in reference.items():
        values = np.asarray(values)
        full = np.full((m,) + values.shape[1:], np.nan)
        full[chosen] = values
        spread[name] = full
    return spread


def _repeats_cl_point(toolpath: Toolpath):
    """Whether two CL points of `toolpath` are equal in position and frame."""
    values = np.column_stack([toolpath.cl, toolpath.theta_a, toolpath.theta_b, toolpath.alpha])
    return len(np.unique(values, axis=0)) < len(values)


@dataclass(frozen=True)
class HelixValidation:
    """A pass with helical edges: flute_engagement against the helix boolean, every flute apart.

    engagement: the FluteEngagement (m, p, Z). reference: dict of (m, p, Z) arrays
    axial_length, edge_length, lep_l, uep_l, pieces (cad.helix_boolean; flutes not checked stay
    unengaged). flutes: the checked flutes (0-based). seconds: {"abm", "boolean"} (s) of the
    whole run.
    """

    engagement: FluteEngagement
    reference: dict
    flutes: tuple
    toolpath: Toolpath
    tool: Tool
    seconds: dict

    def differences(self):
        """{axial_length, lep_l, uep_l}: (m, p, c) |ABM − boolean| (mm) over the checked flutes
        (c of them, in `flutes` order); NaN where a LEP or UEP exists on one side only or on none."""
        chosen = list(self.flutes)
        return {name: np.abs(getattr(self.engagement, name)[..., chosen] - self.reference[name][..., chosen])
                for name in ("axial_length", "lep_l", "uep_l")}

    def flute_summary(self):
        """Per checked flute a dict: flute (0-based), instants, engaged_abm, engaged_ref, mismatched
        (instants where one side engages), max_axial_difference, max_lep_difference,
        max_uep_difference (mm, NaN if none)."""
        differences = self.differences()
        rows = []
        for column, flute in enumerate(self.flutes):
            abm = self.engagement.axial_length[..., flute] > 0.0
            ref = self.reference["axial_length"][..., flute] > 0.0
            worst = {f"max_{key}_difference": _largest(differences[name][..., column])
                     for key, name in (("axial", "axial_length"), ("lep", "lep_l"), ("uep", "uep_l"))}
            rows.append({"flute": int(flute), "instants": int(abm.size), "engaged_abm": int(abm.sum()),
                         "engaged_ref": int(ref.sum()), "mismatched": int((abm != ref).sum()), **worst})
        return rows

    def flute(self, flute):
        """The Validation of flute `flute` (0-based, one of `flutes`) alone, for the report: the
        engine's Engagement of that flute (FluteEngagement.as_engagement: length = axial length of
        cut, LEP and UEP as axial positions l), the reference's (m, p) arrays, their Comparison
        (depth of cut from the helix points at the reference's LEP and UEP) and the run's seconds."""
        if flute not in self.flutes:
            raise ValueError(f"flute {flute} was not checked; checked: {list(self.flutes)}")
        engagement = self.engagement.as_engagement(flute)
        reference = {"length": self.reference["axial_length"][..., flute],
                     **{name: self.reference[name][..., flute] for name in ("lep_l", "uep_l", "pieces")}}
        arrays = _reference_arrays(engagement, reference)
        z_lep, z_uep = (self._helix_height(arrays[name], flute) for name in ("lep_l", "uep_l"))
        return Validation(engagement, reference, _comparison(engagement, arrays, z_lep, z_uep), self.seconds)

    def _helix_height(self, l, flute):
        """z (m, p) mm of flute `flute`'s helix at axial positions l (m, p) mm (NaN kept)."""
        frames = self.toolpath.frames()
        psi = np.radians(self.engagement.angle_at(l, flute))
        radial = np.sin(psi) * frames[:, None, 2, 0] + np.cos(psi) * frames[:, None, 2, 1]
        return self.toolpath.cl[:, None, 2] + self.tool.radius * radial + l * frames[:, None, 2, 2]


def _largest(values):
    """max of the finite values (float), NaN if none."""
    finite = values[np.isfinite(values)]
    return float(finite.max()) if finite.size else np.nan


def validate_helix(solid, staircase, tool: Tool, toolpath: Toolpath, settings, *, flutes=None, progress=None,
                   workers=1, scheduler=None, apart=False):
    """Run the helix solver and the helix boolean reference on one pass; a HelixValidation.

    solid: the stock as a Part.Shape; staircase: the engine's. tool.helix may be any allowed β
    (0 too: the boolean then uses straight segments). flutes: 0-based flutes to check (default
    all). progress(done, total) after each CL point of the reference. workers, scheduler, apart: as validate. Raises
    NoEngagementError, before the reference runs, when no checked flute engages anywhere.
    Needs FreeCAD.
    """
    from .cad.helix_boolean import flute_lengths_by_boolean

    chosen = tuple(range(tool.flutes)) if flutes is None else tuple(sorted({int(k) for k in flutes}))
    if not chosen or min(chosen) < 0 or max(chosen) >= tool.flutes:
        raise ValueError(f"flutes must be indices in 0..{tool.flutes - 1}, got {flutes!r}")
    started = time.perf_counter()
    engagement = flute_engagement(staircase, tool, toolpath, settings)
    abm_seconds = time.perf_counter() - started
    if not (engagement.axial_length[..., list(chosen)] > 0.0).any():
        raise NoEngagementError("no CL point of the pass engages the stock with the checked flutes")
    started = time.perf_counter()
    reference = reference_by_workers(flute_lengths_by_boolean, solid, tool, toolpath, engagement.phi, (chosen,),
                                     workers=workers, scheduler=scheduler, progress=progress, apart=apart)
    boolean_seconds = time.perf_counter() - started
    return HelixValidation(engagement, reference, chosen, toolpath, tool,
                           {"abm": abm_seconds, "boolean": boolean_seconds})


def reference_by_workers(reference, solid, tool, toolpath, phi, extra=(), *, workers=1, scheduler=None,
                         progress=None, apart=False, whole=False):
    """reference(solid, tool, toolpath, phi, *extra, progress): a boolean reference (a dict of
    arrays over CL points first), computed in `workers` processes or on a Dask cluster, one CL
    point per task.

    reference: a module-level function of cad (profile_lengths_by_boolean, flat_lengths_by_boolean,
    flat_lengths_in_process, corner_lengths_in_process, flute_lengths_by_boolean).
    workers: 1 (or a pass of one CL point) runs it here; N > 1 in N spawned processes
    (worker_processes.WorkerProcesses); 0 one per core. apart: 1 runs it in one spawned process too
    (FreeCAD's GUI: its Python bindings hold the interpreter's lock through each OpenCASCADE call, so a
    boolean in a thread of FreeCAD's process stalls the GUI's thread as long). whole: the pass as one
    task (one process; progress(1, 1) at its end), for a pass whose CL points a task of one cannot tell
    apart. scheduler: the address of a Dask scheduler ("tcp://host:port"), instead of local processes.
    progress(done, total) after each CL point. On any exception (KeyboardInterrupt too) every local
    worker is ended before it propagates.
    """
    from .parallel import worker_count

    if scheduler is not None:
        from .parallel import map_cl_points

        task = _DaskReference(reference, tool, toolpath, phi, extra)
        with contextlib.closing(map_cl_points(task, solid.exportBrepToString(), len(toolpath), scheduler)) as finished:
            return _assembled(finished, len(toolpath), progress)
    count = min(worker_count(workers), len(toolpath))
    if count <= 1 and not apart:
        return reference(solid, tool, toolpath, phi, *extra, progress)
    from .parallel import toolpath_part
    from .worker_processes import WorkerProcesses

    if whole:
        count, tasks = 1, [(reference, tool, toolpath, phi, extra)]
    else:
        tasks = [(reference, tool, toolpath_part(toolpath, i, i + 1), phi, extra) for i in range(len(toolpath))]
    with WorkerProcesses(max(count, 1), _start_worker, (solid.exportBrepToString(),)) as processes:
        return _assembled(processes.map_unordered(_reference_task, tasks), len(tasks), progress)


def _assembled(finished, m, progress):
    """The reference dict of a pass of m CL points from (CL index, reference of that CL point alone) pairs
    in any order; progress(done, m) after each."""
    parts = [None] * m
    for done, (i, part) in enumerate(finished, start=1):
        parts[i] = part
        if progress is not None:
            progress(done, m)
    return {name: np.concatenate([part[name] for part in parts]) for name in parts[0]}


_SOLID = None  # a worker's stock (Part.Shape), set once by _start_worker


def _start_worker(brep):
    """In a worker: read the stock from BREP text."""
    global _SOLID
    from .cad.freecad_env import Part

    _SOLID = Part.Shape()
    _SOLID.importBrepFromString(brep)


def _reference_task(reference, tool, toolpath, phi, extra):
    """In a worker: the reference of `toolpath` (one CL point) against the worker's stock."""
    return reference(_SOLID, tool, toolpath, phi, *extra, None)


@dataclass(frozen=True)
class _DaskReference:
    """The reference of CL points start:stop of a pass, as a Dask task on the stock's BREP text: each
    Dask worker process imports its own FreeCAD and reads the BREP once (kept for the next tasks)."""

    reference: object
    tool: Tool
    toolpath: Toolpath
    phi: np.ndarray
    extra: tuple

    def __call__(self, brep, start, stop):
        from .parallel import toolpath_part

        global _SOLID_BREP
        with _SOLID_LOCK:  # one boolean at a time per process: a Dask worker may run tasks in several threads
            if _SOLID_BREP != brep:
                _start_worker(brep)
                _SOLID_BREP = brep
            return self.reference(_SOLID, self.tool, toolpath_part(self.toolpath, start, stop), self.phi,
                                  *self.extra, None)


_SOLID_BREP = None  # in a Dask worker: the BREP text _SOLID was read from
_SOLID_LOCK = threading.Lock()
