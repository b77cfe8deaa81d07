"""The runs both front ends share: engage, validate and schedule a job, writing their outputs.

Each run takes a :class:`~.job.Job` and its own options, reports warnings and progress through
callbacks, writes its files whole or not at all (an older file at the same path is replaced only
on success; folders it made are removed again on failure) and returns what it found for the front
end to show. The engine of flute 1 is the straight-edge ABM or, for a helical tool, flute 1 of the
helix solver (:func:`flute_1`); the validation follows the tool likewise (:func:`validation`).

Lengths in mm, angles in degrees, forces in N.
"""

import contextlib
import dataclasses
import math
import os
import re
import time
from typing import Optional

import numpy as np

from ..engine import Staircase, flute_engagement, zmap_engage
from ..engine.stocks import engage_in_process, engage_stock, in_process_lengths, in_process_runs
from ..errors import InputError, ParameterError, note
from ..formats import check_output_path, replacing, results_npz
from ..formats.results_columns import chunk_columns
from ..formats.results_csv import chunk_texts, summary_path, write_chunks
from ..forces import joined_forces, pass_forces
from ..parallel import CHUNK_INSTANTS, PassAssembly, map_chunks, toolpath_part, worker_count
from .checked import checked_cls
from .job import Job, cl_indices, load_job_stock, prepare


#: Why a helical tool is refused on a general 2.5D stock.
HELIX_NEEDS_STAIRCASE = note("needs a staircase stock: the helix solver does not take a general 2.5D stock yet "
                              "(use straight flutes, helix 0)")


def flute_1(stock, tool, toolpath, settings, progress=None):
    """Engagement of flute 1 over `stock` (a Staircase or a TerracedStock): the straight engine of its
    model (engine.stocks.engage_stock), or flute 0 of the helix solver for a helical tool (staircase only)."""
    if tool.helix == 0.0:
        return engage_stock(stock, tool, toolpath, settings, progress=progress)
    if not isinstance(stock, Staircase):
        raise ParameterError("helix", HELIX_NEEDS_STAIRCASE)
    return flute_engagement(stock, tool, toolpath, settings, progress=progress).as_engagement(0)


def in_process_1(stock, tool, toolpath, settings, pieces, rows, progress=None):
    """(Engagement of flute 1 against the in-process stock, initial length (m, p) mm, changed (m,)) of a pass:
    engine.stocks.engage_in_process in chunks of about parallel.CHUNK_INSTANTS instants, progress(done, m)
    after each (a CL point's result depends on its program row alone, so chunks change nothing)."""
    m = len(toolpath)
    step = max(1, CHUNK_INSTANTS // max(settings.phi.size, 1))
    whole, initial, changed = PassAssembly(m), [], []
    for start in range(0, m, step):
        stop = min(m, start + step)
        engagement, chunk_initial, chunk_changed = engage_in_process(stock, tool, toolpath_part(toolpath, start, stop),
                                                                     settings, pieces, rows[start:stop])
        whole.add(engagement, start)
        initial.append(chunk_initial)
        changed.append(chunk_changed)
        if progress is not None:
            progress(stop, m)
    return whole.engagement(), np.concatenate(initial), np.concatenate(changed)


#: Choices of the stock model.
STOCK_MODELS = ("in-process", "initial")


def in_process_sweep(prepared, method="abm", warn=None):
    """((SweptPieces of the prepared job's whole program in its engine frame, (m,) program rows of its CL
    points) for a run against the in-process stock, or None for the stock as given; why not, or '').

    The job's stock_model decides; by default in-process where the engine has it (the straight-edge ABM of
    flat-end, bull-nose and ball-end mills, with or without the straight-flute forces), else the stock as
    given, the reason said. What the
    in-process stock leaves out or takes otherwise (inputs.program_moves' notes) is told to warn(),
    with how arcs and curves are swept. ParameterError when in-process is asked for where it is not
    available, or the stock model is unknown.
    """
    from ..engine.inprocess import swept_pieces
    from .inputs import program_moves

    job, tool = prepared.job, prepared.tool
    if job.stock_model not in (None, *STOCK_MODELS):
        raise ParameterError("stock_model", f"must be one of {', '.join(STOCK_MODELS)}, got {job.stock_model!r}")
    if job.stock_model == "initial":
        return None, ""
    missing = note("a helical tool") if tool.helix else note("the Z-map method") if method != "abm" else None
    if missing is not None:
        if job.stock_model == "in-process":
            raise ParameterError("stock_model", f"in-process is not available with {missing} yet: use initial")
        return None, note(f"the in-process stock is not available with {missing} yet")
    if not (np.isfinite(job.sweep_tolerance) and job.sweep_tolerance > 0.0):
        raise ParameterError("sweep_tolerance", f"must be a positive number of mm, got {job.sweep_tolerance:g}")
    hints = prepared.hints
    moves, rows, notes = program_moves(hints.program, hints.operation, tool)
    if hints.frame is not None:
        moves = moves.transformed(*hints.frame)
    curved = sum(op.arcs + op.curves for op in hints.program.operations)
    if curved:
        notes.append(f"the in-process stock sweeps the program's {curved} arcs and curves as the chords between "
                     f"their CL points, each within {job.tolerance:g} mm of the arc (at most {job.step:g} mm long)")
    check_sweep(moves, job.sweep_tolerance, job.toolpath)
    for noted in notes if warn is not None else ():
        warn(f"{job.toolpath}: {noted}")
    return (swept_pieces(moves, job.sweep_tolerance), rows), ""


#: Bytes of memory per constant-axis piece, span and bounding ball of the in-process stock's sweep
#: (its arrays and the temporaries that make them; engine.inprocess.SweptPieces).
PIECE_BYTES, SPAN_BYTES, BALL_BYTES = 400, 400, 160


def sweep_size(moves, tolerance):
    """(pieces, spans, balls) that engine.inprocess.swept_pieces(moves, tolerance) makes of the cutting
    moves of `moves` (a ProgramMoves), counted as it counts them but in floats, so that no count can
    overflow: pieces and spans exactly, balls (each chain's height in slices as tall as its radius) as an
    upper bound."""
    from ..engine.inprocess import _CHAIN, _SPAN_PIECES  # the engine's own constants, so the counts follow it

    j = np.flatnonzero(moves.cutting[1:]) + 1
    if not j.size:
        return 0.0, 0.0, 0.0
    radius, height = moves.radius[j], moves.flute_length[j]
    rho = np.hypot(radius, height)
    turn = np.arccos(np.clip(np.einsum("ij,ij->i", moves.axis[j - 1], moves.axis[j]), -1.0, 1.0))
    length = np.linalg.norm(moves.cl[j] - moves.cl[j - 1], axis=1)
    with np.errstate(all="ignore"):
        steps = np.ceil(turn * rho / tolerance)
        spans = np.maximum(np.maximum(np.ceil(length / rho), np.ceil(steps / _SPAN_PIECES)), 1.0)
        pieces = spans * np.maximum(np.ceil(steps / spans), 1.0)
        # A chain starts where a run of consecutive moves of one tool starts, after every _CHAIN spans of
        # the run and after every radius of its path: at most runs + Σ spans / _CHAIN + Σ length / radius.
        slices = np.maximum(np.ceil(height / radius), 1.0)
        runs = 1 + np.flatnonzero((np.diff(j) > 1) | (np.diff(radius) != 0) | (np.diff(height) != 0)).size
        balls = (spans / _CHAIN + length / radius) * slices
        balls = np.append(balls, runs * slices.max())
    return float(pieces.sum()), float(spans.sum()), float(balls.sum())


def check_sweep(moves, tolerance, toolpath):
    """TooLarge (naming the toolpath and what makes the sweep large) unless the in-process stock's sweep
    of `moves` at `tolerance` mm is within limits.LARGE_PIECES pieces and the memory available."""
    from ..limits import LARGE_PIECES, check_large, check_memory, count_text

    pieces, spans, balls = sweep_size(moves, tolerance)
    remedy = note("give a larger --sweep-tolerance or --stock-model initial (the stock as given)" if pieces > 2 * spans
                  else "give --stock-model initial (the stock as given)")
    why = f"{toolpath}: {note('the in-process stock')}"  # the phrase a message of its own, after the file
    check_large(toolpath, note(f"the in-process stock would sweep the program's cutting moves into "
                               f"{count_text(pieces + balls)} pieces and bounding balls"), pieces + balls, LARGE_PIECES,
                remedy)
    check_memory(PIECE_BYTES * pieces + SPAN_BYTES * spans + BALL_BYTES * balls, why,
                 note(f"its sweep ({count_text(pieces)} pieces, {count_text(balls)} bounding balls)"), remedy)


#: Bytes of memory per instant (CL point × angle): the engine's temporaries while it computes a chunk
#: (measured: about 1.5 KiB); an Engagement's arrays kept for a whole pass; a whole pass drawn (its
#: Engagement, and with forces its Forces, and the figure's arrays: measured about 450 B); a validation's
#: arrays per instant besides the Engagement; the forces of a whole pass (every flute, schedule).
ENGINE_BYTES, RESULT_BYTES, PLOT_BYTES, VALIDATION_BYTES, FORCE_BYTES = 2048, 160, 500, 400, 600
#: Bytes written per instant: a results CSV row (with its share of the summary), an archive's columns.
CSV_BYTES, NPZ_BYTES = 200, 150


def check_run_size(job, prepared, *, command="engage", workers=1, whole=False, out=None, boolean=None):
    """Before any file is written: TooLarge when the run's instants (CL points × angles) are above
    limits.LARGE_INSTANTS, its estimated memory above what this process may use, or its results `out`
    above the free space of their file system; with `boolean` (CL points the boolean reference checks,
    None: all) when the boolean reference's instants are above limits.LARGE_BOOLEAN_INSTANTS.
    workers: processes computing chunks at once; whole: the pass is also kept whole (a plot, validate,
    schedule)."""
    from ..limits import (BASE_MEMORY, LARGE_BOOLEAN_INSTANTS, LARGE_INSTANTS, check_disk, check_large, check_memory,
                          count_text)

    m, p = len(prepared.toolpath), prepared.settings.phi.size
    instants = m * p
    why = f"{job.toolpath}: {count_text(m)} CL points x {count_text(p)} angles"
    remedy = note("give a larger --phi-step or a shorter --phi-range")
    check_large(job.toolpath, note(f"{count_text(m)} CL points x {count_text(p)} angles = {count_text(instants)} "
                                   f"instants"), instants, LARGE_INSTANTS, remedy)
    chunk = max(p, CHUNK_INSTANTS)
    per_instant = (RESULT_BYTES + (PLOT_BYTES if command == "engage" else VALIDATION_BYTES if command == "validate"
                                   else FORCE_BYTES)) if whole else 0
    if command == "schedule":
        per_instant = FORCE_BYTES * prepared.tool.flutes
    needed = (BASE_MEMORY + max(1, workers) * chunk * (ENGINE_BYTES + IN_FLIGHT_CHUNKS * CSV_BYTES)
              + per_instant * instants)
    check_memory(needed, why, note(f"the {command} run"), remedy)
    if out is not None:
        check_disk((NPZ_BYTES if os.fspath(out).lower().endswith(".npz") else CSV_BYTES) * instants, out, why)
    if boolean is not None or command == "validate":
        checked = m if boolean is None else len(boolean)
        flutes = prepared.tool.flutes if prepared.tool.helix else 1
        many, angles, total = count_text(checked), count_text(p), count_text(checked * p * flutes)
        what = note(f"would check {many} CL points x {angles} angles x {flutes} flutes = {total} instants"
                    if flutes > 1 else f"would check {many} CL points x {angles} angles = {total} instants")
        check_large(f"{job.toolpath}: {note('the boolean reference')}", what, checked * p * flutes,
                    LARGE_BOOLEAN_INSTANTS, note("check fewer CL points (--check, --check-every) or give a larger "
                                                 "--phi-step"))


def check_zmap_size(staircase, tool, m, p, method):
    """Before the Z-map baseline runs on `staircase` with `tool`, m CL points and p angles: ParameterError
    naming --grid when its cells are more than engine.zmap.MAX_CELLS or their memory above what this
    process may use, naming --edge-step (--grid when the edge step is the grid's default) when a CL
    point's edge samples are more than engine.zmap.MAX_SAMPLES; TooLarge when the run's edge samples (CL
    points x angles x points along the edge) are above limits.LARGE_ZMAP_SAMPLES."""
    from ..engine.zmap import MAX_CELLS, MAX_SAMPLES
    from ..limits import LARGE_ZMAP_SAMPLES, check_large, check_memory, count_text

    grid, edge_step = zmap_cells(method)
    cells = (max(1.0, math.ceil((staircase.x_max - staircase.x_min) / grid - 1e-9))
             * max(1.0, math.ceil((staircase.y_max - staircase.y_min) / grid - 1e-9)))
    if cells > MAX_CELLS:
        raise ParameterError("grid", f"{grid:g} mm gives the stock {cells:,.0f} Z-map cells, more than the Z-map "
                                     f"holds ({MAX_CELLS:,}): give a larger --grid")
    check_memory(ZMAP_CELL_BYTES * cells, "--grid", note(f"the Z-map's {cells:,.0f} cells"),
                 note("give a larger --grid"))
    field, option = ("edge_step", "--edge-step") if method.edge_step is not None else ("grid", "--grid")
    given = method.edge_step is not None
    along = max(1, math.ceil(tool.flute_length / edge_step - 1e-9)) + 1  # as engine.zmap.zmap_engage samples
    if p * along > MAX_SAMPLES:
        length, each = tool.flute_length, p * along
        raise ParameterError(field, f"an edge step of {edge_step:g} mm samples the {length:g} mm flute at {along:,} "
                                    f"points, {p:,} angles x {along:,} = {each:,} per CL point, more than the Z-map "
                                    f"takes ({MAX_SAMPLES:,}): give a larger {option} or --phi-step" if given else
                                    f"an edge step of {edge_step:g} mm samples the {length:g} mm flute at {along:,} "
                                    f"points (the edge step is the grid's unless --edge-step is given), {p:,} angles "
                                    f"x {along:,} = {each:,} per CL point, more than the Z-map takes "
                                    f"({MAX_SAMPLES:,}): give a larger {option} or --phi-step")
    samples = count_text(float(m) * p * along)
    what = note(f"the Z-map would sample {samples} edge points ({m:,} CL points x {p:,} angles x {along:,} along the "
                f"edge)" if given else
                f"the Z-map would sample {samples} edge points ({m:,} CL points x {p:,} angles x {along:,} along the "
                f"edge) (the edge step is the grid's unless --edge-step is given)")
    check_large(option, what, float(m) * p * along, LARGE_ZMAP_SAMPLES,
                note(f"give a larger {option} or --phi-step"))


#: Bytes of memory per Z-map cell (its heights, sections and the temporaries of an update).
ZMAP_CELL_BYTES = 48
#: Chunks of results a worker may have in flight (computing, or waiting to be written in order).
IN_FLIGHT_CHUNKS = 4


def check_model(stock, method="abm", helix=0.0):
    """ParameterError where a run needs the staircase model and `stock` (a Stock) is a general 2.5D one."""
    if stock.staircase is not None:
        return
    if helix:
        raise ParameterError("helix", HELIX_NEEDS_STAIRCASE)
    if method != "abm":
        raise ParameterError("method", f"the Z-map baseline needs a staircase stock; {stock.source} is a general "
                                       "2.5D stock")


def pass_forces_of(staircase, tool, toolpath, settings, model, engagement, feed=None, in_process=None):
    """The Forces of a pass under force model (Coefficients, immersion (start, end) deg), reusing flute 1's
    straight-edge lengths of `engagement`; feed: (m,) feed per tooth (mm) per CL point, or None.
    in_process: (SweptPieces, (m,) program rows of the CL points) to take every flute's lengths (a tool
    with a corner: its runs along the peripheral edge) against the in-process stock (straight flutes),
    or None for the stock as given."""
    coefficients, immersion = model
    lengths_at = runs_at = None
    if in_process is not None and tool.corner_radius > 0.0:
        def runs_at(phi):
            return in_process_runs(staircase, tool, toolpath, phi, *in_process)
    elif in_process is not None:
        def lengths_at(shifted):
            return in_process_lengths(staircase, tool, toolpath, shifted.phi, *in_process)
    return pass_forces(staircase, tool, toolpath, settings, coefficients, immersion=immersion, feed=feed,
                       first=engagement.length if tool.helix == 0.0 else None, lengths_at=lengths_at,
                       runs_at=runs_at)


def _in_process_forces(staircase, tool, toolpath, settings, model, in_process, feed):
    """(whether any edge line is engaged, the Forces of the pass) against the in-process stock,
    chunk by chunk (parallel.CHUNK_INSTANTS instants each) so that memory stays bounded;
    in_process and feed (m,) as for pass_forces_of."""
    pieces, rows = in_process
    step = max(1, CHUNK_INSTANTS // settings.phi.size)
    engaged, parts = False, []
    for start in range(0, len(toolpath), step):
        stop = min(len(toolpath), start + step)
        part = toolpath_part(toolpath, start, stop)
        engagement = engage_in_process(staircase, tool, part, settings, pieces, rows[start:stop])[0]
        engaged |= bool(engagement.engaged.any())
        parts.append(pass_forces_of(staircase, tool, part, settings, model, engagement, feed=feed[start:stop],
                                    in_process=(pieces, rows[start:stop])))
    return engaged, joined_forces(parts)


def in_part_frame(engagement, frame):
    """`engagement` with its LEP and UEP points (mm) moved back from the engine frame to part coordinates;
    frame: (R, t) from part to engine coordinates (PathHints.frame), or None (the same frame). Depth of
    cut and the CL points stay in the operation's frame, whose z is its tool's up."""
    if frame is None:
        return engagement
    rotation, translation = frame
    return dataclasses.replace(engagement, lep_xyz=(engagement.lep_xyz - translation) @ rotation,
                               uep_xyz=(engagement.uep_xyz - translation) @ rotation)


def no_engagement(job: Job):
    """The error for a pass whose tool never touches the stock."""
    return InputError(f"{job.toolpath}: the tool never touches the stock: no CL point of the pass engages it "
                      f"(are the toolpath and {job.stock} in the same frame?)")


def validation(solid, staircase, tool, toolpath, settings, *, flutes=None, progress=None, workers=1,
               scheduler=None, sweep=None, cls=None, apart=False):
    """(Validation of flute 1 or the first checked flute, HelixValidation or None) of the engine against
    OpenCASCADE booleans: straight edges by ``validation.validate`` (against the in-process stock when
    `sweep` = (SweptPieces, program rows) is given), a helical tool (or chosen `flutes`, 0-based) by
    ``validation.validate_helix``. validation.NoEngagementError when the tool never touches the stock.
    workers, scheduler, apart: where the boolean reference runs (``validation.reference_by_workers``). cls: the
    CL points the boolean checks (None: all; straight edges only)."""
    from ..validation import validate, validate_helix

    if tool.helix == 0.0 and flutes is None:
        return validate(solid, staircase, tool, toolpath, settings, progress=progress, workers=workers,
                        scheduler=scheduler, sweep=sweep, cls=cls, apart=apart), None
    if not isinstance(staircase, Staircase):
        raise ParameterError("helix", HELIX_NEEDS_STAIRCASE)
    helix = validate_helix(solid, staircase, tool, toolpath, settings, flutes=flutes, progress=progress,
                           workers=workers, scheduler=scheduler, apart=apart)
    return helix.flute(helix.flutes[0]), helix


def check_outputs(outputs, inputs, files=None):
    """Output paths checked before any work: InputError if an output's folder cannot be made, or
    outputs clash with each other or with an input (links resolved); `files` (default all of
    `outputs`) must also be usable file names (formats.check_output_path: not empty, no folder,
    not too long)."""
    for path in outputs if files is None else files:
        check_output_path(path)
    seen = {}
    for path in outputs:
        folder = os.path.dirname(os.path.abspath(path))
        while not os.path.exists(folder):
            folder = os.path.dirname(folder)
        if not os.path.isdir(folder):
            raise InputError(f"{path}: cannot write: {folder} is not a folder")
        key = os.path.normcase(os.path.realpath(path))
        if key in seen:
            raise InputError(f"{path}: written twice (as {seen[key]} too); choose another name")
        seen[key] = path
    for path in inputs:
        if os.path.normcase(os.path.realpath(path)) in seen:
            raise InputError(f"{path}: is an input and would be overwritten by an output")


def _inputs(job):
    """The input files of a job."""
    return [job.stock, job.toolpath] + ([job.job_file] if job.job_file else [])


#: The files a report folder (validate, schedule) holds: an older report of only these is replaced.
REPORT_FILES = frozenset({"index.html", "comparison.csv", "segments.csv", "surfaces.csv", "depth.csv", "flutes.csv",
                          "forces.png", "schedule.csv", "schedule.png"})


def check_report_outputs(job, report, fcstd=None):
    """The report folder and FCStd can be written, replace nothing but an older report, hold no input."""
    inputs = _inputs(job)
    check_outputs([report] + ([fcstd] if fcstd else []), inputs, files=[fcstd] if fcstd else [])
    folder = os.path.realpath(report)
    if os.path.exists(folder) and not os.path.isdir(folder):
        raise ParameterError("report", f"must be a folder, and {report} is a file")
    if os.path.isdir(folder) and os.listdir(folder) and not os.path.isfile(os.path.join(folder, "index.html")):
        raise InputError(f"{report}: folder holds files but no report (index.html); it would be replaced "
                         "as a whole: choose a new or empty folder")
    foreign = sorted(set(os.listdir(folder)) - REPORT_FILES) if os.path.isdir(folder) else []
    if foreign:
        more = f" and {len(foreign) - 1} more" if foreign[1:] else ""
        raise InputError(f"{report}: folder holds {foreign[0]!r}{more}, which no report writes; an older report "
                         "there is replaced as a whole, which would delete it: choose a new or empty folder, or move "
                         "it away")
    inside = [path for path in inputs + ([fcstd] if fcstd else [])
              if os.path.realpath(path).startswith(folder + os.sep)]
    if inside:
        raise InputError(f"{inside[0]}: lies inside the report folder {report}, which is replaced as a whole")
    if fcstd and not fcstd.lower().endswith(".fcstd"):
        raise ParameterError("fcstd", f"must end in .FCStd, got {fcstd}")


@contextlib.contextmanager
def output_folders(outputs):
    """Make the missing folders of `outputs`; remove the ones made (if empty) when the block fails.

    Each folder is listed before it is made (a stop signal can raise between any two steps: one right
    after os.mkdir returned must still find it listed); one that appeared meanwhile is not ours."""
    made = []
    try:
        for path in outputs:
            folder, missing = os.path.dirname(os.path.abspath(path)), []
            while not os.path.exists(folder):
                folder, missing = os.path.dirname(folder), missing + [folder]
            for folder in reversed(missing):
                made.append(folder)
                try:
                    os.mkdir(folder)
                except FileExistsError:
                    made.pop()
        yield
    except BaseException:
        for folder in reversed(made):
            with contextlib.suppress(OSError):
                os.rmdir(folder)
        raise


# ---- engage --------------------------------------------------------------------------------------

@dataclasses.dataclass(frozen=True)
class Method:
    """How engage computes: "abm" (in chunks on `workers` local processes, 0 all cores, or on the Dask
    cluster at `scheduler`) or "zmap" (the Z-map baseline with cells of `grid` mm, the edge sampled every
    `edge_step` mm)."""

    name: str = "abm"
    grid: Optional[float] = None
    edge_step: Optional[float] = None
    workers: int = 1
    scheduler: Optional[str] = None


@dataclasses.dataclass(frozen=True)
class EngageResult:
    """What engage found: the Prepared job, the Stock, the outputs written, the depth of cut (m,) (NaN
    where a CL point does not engage), the peak force (m,) or None, which CL points earlier moves
    changed (m,) against the in-process stock or None against the stock as given (model_note: why, when
    it was not asked for), the seconds it took."""

    prepared: object
    stock: object
    written: list
    depth: np.ndarray
    peak: Optional[np.ndarray]
    changed: Optional[np.ndarray]
    model_note: str
    seconds: float


@dataclasses.dataclass(frozen=True)
class ChunkResult:
    """What a chunk task of engage gives back: its (results, summary) as CSV text or as columns
    (formats.results_columns) and the depth of cut (n,); the chunk's Engagement and Forces when kept
    for the plots; the peak resultant force (n,) when forces are computed; against the in-process
    stock, which CL points earlier moves changed (n,)."""

    parts: tuple
    depth: np.ndarray
    engagement: object = None
    forces: object = None
    peak: object = None
    changed: object = None


@dataclasses.dataclass(frozen=True)
class ResultsChunk:
    """Task of a parallel engage: a chunk of CL points engaged (flute 1, straight or helical) and,
    when force_model = (Coefficients, immersion) is given, its forces, as a ChunkResult of CSV text
    or, when `columnar`, of columns (for an .npz); the Engagement and Forces are kept for the plots
    when `keep`. frame: the operation's (R, t) from part to engine coordinates, or None: LEP and
    UEP points are written in part coordinates. in_process: (SweptPieces of the program in the
    engine frame, (m,) program row of each CL point) to engage against the in-process stock, or
    None for the stock as given."""

    keep: bool
    force_model: object = None
    frame: object = None
    in_process: object = None
    columnar: bool = False

    def __call__(self, job, start, stop):
        stock, tool, toolpath, settings = job
        part = toolpath_part(toolpath, start, stop)
        initial = changed = None
        if self.in_process is None:
            engagement = flute_1(stock, tool, part, settings)
        else:
            pieces, rows = self.in_process
            engagement, initial, changed = engage_in_process(stock, tool, part, settings, pieces, rows[start:stop])
        forces = None
        if self.force_model is not None:
            forces = pass_forces_of(stock, tool, part, settings, self.force_model, engagement,
                                    in_process=None if self.in_process is None else (pieces, rows[start:stop]))
        engagement = in_part_frame(engagement, self.frame)
        parts = (chunk_columns if self.columnar else chunk_texts)(engagement, start, toolpath=part, forces=forces,
                                                                   initial=initial, changed=changed)
        return ChunkResult(parts, engagement.depth_of_cut,
                           engagement if self.keep else None, forces if self.keep else None,
                           None if forces is None else forces.peak, changed)


def _kept(chunks, depth, peak, changed, whole, force_parts):
    """The (results, summary) parts of (job, start, stop, ChunkResult) `chunks`, in order; each
    chunk's depth of cut, peak force and changed flags stored into `depth`, `peak` and `changed`
    (m,), its Engagement added to `whole` (a PassAssembly) and its Forces appended to
    `force_parts`, when these are given."""
    for _, start, stop, result in chunks:
        depth[start:stop] = result.depth
        if result.peak is not None:
            peak[start:stop] = result.peak
        if result.changed is not None:
            changed[start:stop] = result.changed
        if whole is not None:
            whole.add(result.engagement, start)
        if force_parts is not None:
            force_parts.append(result.forces)
        yield result.parts


def check_method(method: Method, forces, helix):
    """ParameterError (grid, edge_step, workers, scheduler, method) for options that do not fit the method."""

    if method.name == "abm":
        for name in ("grid", "edge_step"):
            if getattr(method, name) is not None:
                raise ParameterError(name, "applies to the Z-map method (zmap), not to abm")
        try:
            worker_count(method.workers)
        except ValueError:
            raise ParameterError("workers", f"must be 0 (all cores) or a positive number of processes, got "
                                            f"{method.workers}") from None
        if method.scheduler is not None and not re.fullmatch(r"[a-z][a-z0-9+.-]*://\S+", method.scheduler):
            raise ParameterError("scheduler", f"expected a Dask scheduler address such as tcp://127.0.0.1:8786, "
                                              f"got {method.scheduler!r}")
        return
    if method.workers != 1 or method.scheduler:
        raise ParameterError("workers" if method.workers != 1 else "scheduler",
                             "applies to the abm method: the Z-map updates its stock CL point by CL point")
    for name in ("grid", "edge_step"):
        value = getattr(method, name)
        if value is not None and not (np.isfinite(value) and value > 0.0):
            raise ParameterError(name, f"must be a positive number of mm, got {value:g}")
    if forces:
        raise ParameterError("forces", "needs the abm method")
    if helix:
        raise ParameterError("helix", "needs the abm method")


def zmap_cells(method: Method):
    """(grid, edge step) mm of the Z-map method: the paper's 0.2 mm grid and the grid as edge step by default."""
    grid = 0.2 if method.grid is None else method.grid
    return grid, grid if method.edge_step is None else method.edge_step


def engage(job: Job, out, *, plot=None, method=Method(), warn=print, progress=None):
    """Engage a job: the results `out` (R.csv, its summary beside it as R.summary.csv; or R.npz, results
    and summary columns in one NumPy archive, formats.results_npz) and, with `plot`, the PNG (and with
    forces its force PNG). Returns an EngageResult. warn(message) is told each warning."""
    helix = job.given.get("helix")
    check_method(method, job.forces, helix not in (None, 0.0))
    prepared = prepare(job)
    for message in prepared.warnings():
        warn(message)
    toolpath, tool, settings = prepared.toolpath, prepared.tool, prepared.settings
    columnar = os.fspath(out).lower().endswith(".npz")
    results = [out] if columnar else [out, summary_path(out)]
    outputs = results + ([plot] if plot else [])
    if plot and prepared.force_model is not None:
        outputs.append(os.path.splitext(plot)[0] + ".forces.png")
    check_outputs(outputs, _inputs(job))
    check_run_size(job, prepared, workers=worker_count(method.workers) if method.name == "abm" and not method.scheduler
                   else 1, whole=bool(plot), out=out)
    if method.name != "abm" and tool.corner_radius:
        corner = tool.corner_radius
        raise ParameterError("method", f"the Z-map baseline samples a flat-end mill's edge; this ball mill (corner "
                                       f"radius {corner:g} mm) is computed by the ABM engine only"
                             if tool.kind == "ball" else
                             f"the Z-map baseline samples a flat-end mill's edge; this bull-nose mill (corner "
                             f"radius {corner:g} mm) is computed by the ABM engine only")
    prepared, stock, _ = load_job_stock(prepared)
    toolpath = prepared.toolpath  # in the frame of the stock (load_job_stock)
    check_model(stock, method.name, tool.helix)
    if method.name != "abm":
        check_zmap_size(stock.model, tool, len(toolpath), settings.phi.size, method)
    in_process, model_note = in_process_sweep(prepared, method.name, warn)

    started = time.perf_counter()
    whole = PassAssembly(len(toolpath)) if plot else None
    force_parts = [] if plot and prepared.force_model is not None else None
    depth, peak = np.full(len(toolpath), np.nan), np.full(len(toolpath), np.nan)
    changed = np.zeros(len(toolpath), dtype=bool)
    with output_folders(outputs), replacing(*outputs) as temporaries:
        if method.name == "abm":
            chunks = map_chunks(ResultsChunk(keep=whole is not None, force_model=prepared.force_model,
                                             frame=prepared.hints.frame, in_process=in_process, columnar=columnar),
                                [(stock.model, tool, toolpath, settings)],
                                workers=method.workers, scheduler=method.scheduler, progress=progress)
        else:
            grid, step = zmap_cells(method)
            try:
                engagement = in_part_frame(zmap_engage(stock.model, tool, toolpath, settings, grid=grid,
                                                   edge_step=step, progress=progress), prepared.hints.frame)
            except ValueError as error:
                raise ParameterError("method", f"the Z-map method: {error}") from None
            parts = (chunk_columns if columnar else chunk_texts)(engagement, 0, toolpath=toolpath)
            chunks = [(0, 0, len(toolpath), ChunkResult(parts, engagement.depth_of_cut, engagement))]
        kept = _kept(chunks, depth, peak, changed, whole, force_parts)
        if columnar:
            results_npz.write_chunks(kept, temporaries[0], len(toolpath) * settings.phi.size)
        else:
            write_chunks(kept, temporaries[0], temporaries[1])
        if np.isnan(depth).all():
            if in_process is not None and engage_stock(stock.model, tool, toolpath, settings).engaged.any():
                raise InputError(f"{job.toolpath}: earlier moves of the program already removed all the material "
                                 "this operation's tool would meet (--stock-model initial computes it against the "
                                 "stock as given)")
            raise no_engagement(job)
        if whole is not None:
            from ..report.plots import pass_figure  # here: matplotlib takes a while to import
            title = prepared.description or (
                f"{os.path.basename(job.stock)} / {os.path.basename(job.toolpath)}: D {tool.diameter:g} mm, "
                f"{tool.flutes} flutes, f {settings.feed_per_tooth:g} mm/tooth, α {settings.inclination:g}°")
            pass_figure(whole.engagement(), title=title).savefig(temporaries[len(results)], format="png")
        if force_parts is not None:
            from ..report.forces import chosen_cl, force_over_phi_figure
            forces = joined_forces(force_parts)
            figure = force_over_phi_figure(forces, chosen_cl(forces), along=True)
            figure.savefig(temporaries[len(results) + 1], format="png")
    return EngageResult(prepared, stock, outputs, depth, None if prepared.force_model is None else peak,
                        None if in_process is None else changed, model_note, time.perf_counter() - started)


# ---- validate ------------------------------------------------------------------------------------

@dataclasses.dataclass(frozen=True)
class ValidateResult:
    """What validate found: the Prepared job, the Stock, the Validation (flute 1 or the first checked
    flute), the HelixValidation or None, the Forces or None, the files written."""

    prepared: object
    stock: object
    validation: object
    helix: object
    forces: object
    written: list


def validate(job: Job, report, *, fcstd=None, cls=None, check=None, check_every=None, flute=None, workers=1,
             scheduler=None, warn=print, progress=None):
    """Validate a job against OpenCASCADE booleans: the HTML report folder `report` and, with `fcstd`, an
    annotated FreeCAD document. cls: CL indices shown in detail ('0,22,40'), None: chosen. flute: check
    only this flute (1-based) of a helical tool. check ('0,27,80-100'), check_every (N): the CL points the
    boolean checks besides those of cls (jobs.checked.checked_cls), default all. workers: processes
    computing the boolean reference (1 this one, 0 one per core); scheduler: a Dask scheduler's address
    to compute it on instead.
    Returns a ValidateResult."""
    from ..report.html import ReportJob, report_cls, write_report
    from ..report.staging import staged
    from ..report.tables import write_flutes_csv
    from ..validation import NoEngagementError

    check_method(Method(workers=workers, scheduler=scheduler), forces=False, helix=0.0)
    prepared = prepare(job)
    for message in prepared.warnings():
        warn(message)
    toolpath, tool, settings = prepared.toolpath, prepared.tool, prepared.settings
    chosen = cl_indices(cls, len(toolpath)) if cls else None
    checking = checked_cls(check, check_every, chosen, len(toolpath))
    flutes = None
    if flute is not None:
        if not 1 <= flute <= tool.flutes:
            raise ParameterError("flute", f"must be 1..{tool.flutes} (the tool has {tool.flutes} flutes), got {flute}")
        flutes = [flute - 1]
    if checking is not None and (tool.helix or flutes):
        raise ParameterError("check", "is not available with helical edges (--helix, --flute) yet")
    check_report_outputs(job, report, fcstd)
    check_run_size(job, prepared, command="validate", whole=True, boolean=checking)
    prepared, stock, stock_seconds = load_job_stock(prepared)
    toolpath = prepared.toolpath  # in the frame of the stock (load_job_stock)
    in_process, model_note = _validated_sweep(job, prepared, flutes, warn)
    if model_note:
        warn(f"{job.toolpath}: {model_note}; validating against the stock as given")
    check_model(stock, helix=tool.helix)
    started = time.perf_counter()
    try:
        solid = stock.solid()
    except InputError:
        raise
    except Exception as error:  # OpenCASCADE's errors, or a stock the solid builders do not take
        raise InputError(f"{job.stock}: the boolean reference cannot build the stock's solid "
                         f"({type(error).__name__}: {error})") from None
    stock_seconds += time.perf_counter() - started

    try:
        checked, helix = validation(solid, stock.model, tool, toolpath, settings, flutes=flutes,
                                    progress=progress, workers=workers, scheduler=scheduler,
                                    sweep=in_process, cls=checking)
    except NoEngagementError:
        raise no_engagement(job) from None
    engagement = checked.engagement
    forces = None if prepared.force_model is None else pass_forces_of(
        stock.model, tool, toolpath, settings, prepared.force_model, engagement, in_process=in_process)
    shown = report_cls(checked, chosen)
    # The report adds the staircase's y window itself.
    walls = ("the paper's quintic walls (JSON)" if stock.shape is None and stock.staircase is not None else
             f"{stock.walls} walls" if stock.staircase is not None else stock.describe())
    run = "ABM against booleans" if helix is None else (
        f"Helical edges (β = {tool.helix:g}°), flute {helix.flutes[0] + 1} of {tool.flutes}, ABM against booleans")
    title = f"{run}: {os.path.basename(job.stock)} / {os.path.basename(job.toolpath)}"
    description = prepared.description if helix is None else " ".join(filter(None, [
        prepared.description, flutes_text(helix)]))
    report_job = ReportJob(title, description, job.stock, job.toolpath, toolpath, tool, settings,
                           prepared.parameters.describe(), walls, stock.y_window, stock_seconds,
                           _stock_model_text(job, prepared, in_process, model_note))
    views = None if in_process is None else _stock_views(
        solid, in_process, tool, toolpath, [cl for cl, _ in shown if checked.in_process.changed[cl]])

    with output_folders([report] + ([fcstd] if fcstd else [])), staged(report, folder=True) as folder, \
            (staged(fcstd) if fcstd else contextlib.nullcontext()) as document:
        page = write_report(folder, checked, report_job, shown, forces, views)
        if helix is not None:
            write_flutes_csv(os.path.join(folder, "flutes.csv"), helix)
        if document:
            from ..cad.annotate import write_annotated
            name = re.sub(r"[^A-Za-z0-9_]", "_", os.path.splitext(os.path.basename(fcstd))[0])
            write_annotated(document, f"ABM_{name}", solid, engagement, toolpath, tool, cls=chosen,
                            intersections=[cl for cl, _ in shown], sweep=in_process, tops=views)
    written = [os.path.join(report, os.path.basename(page))] + ([fcstd] if fcstd else [])
    return ValidateResult(prepared, stock, checked, helix, forces, written)


def _validated_sweep(job, prepared, flutes, warn):
    """(in_process_sweep's (SweptPieces, rows) or None, why not or '') for validate: the rule of engage,
    and the stock as given when single flutes of a tool are checked (the helix boolean); ParameterError then
    when in-process was asked for."""
    if flutes is not None:
        if job.stock_model == "in-process":
            raise ParameterError("stock_model", "in-process is not available for validate with --flute (the helix "
                                                "boolean) yet: use initial")
        return None, "" if job.stock_model == "initial" else \
            "the in-process stock is not available for validate with --flute (the helix boolean) yet"
    return in_process_sweep(prepared, warn=warn)


def _stock_model_text(job, prepared, in_process, model_note):
    """The stock model the report checked, in words."""
    if in_process is None:
        return "initial: the stock as given" + (f" ({model_note})" if model_note else "")
    pieces, _ = in_process
    operation = prepared.hints.operation
    where = f", operation {operation.number}" if operation is not None else ""
    return (f"in-process: the stock minus the volumes swept by every cutting move of {os.path.basename(job.toolpath)}"
            f" before each CL point{where} ({len(pieces.c0)} swept pieces, five-axis moves in sub-steps of at most "
            f"{job.sweep_tolerance:g} mm at the tool's rim)")


def _stock_views(solid, in_process, tool, toolpath, cls):
    """{CL index: (x (c,), y (c,), z (c, c)) mm}: the top of the in-process stock around each CL point of
    `cls` (cad.inprocess_boolean.stock_heights), for the report's pictures: the shown CL points that
    earlier moves changed (each picture costs c² lines sectioned against every swept solid near)."""
    from ..cad.inprocess_boolean import stock_heights
    from ..report.html import STOCK_VIEWS

    pieces, rows = in_process
    return {cl: stock_heights(solid, pieces, rows[cl], tool, toolpath, cl) for cl in cls[:STOCK_VIEWS]}


def flutes_text(helix_validation):
    """One line per checked flute's largest |ABM − boolean| of axial length, LEP and UEP (mm)."""
    parts = [f"flute {row['flute'] + 1}: max |Δ axial length| {row['max_axial_difference']:.3g} mm, "
             f"|Δ LEP| {row['max_lep_difference']:.3g} mm, |Δ UEP| {row['max_uep_difference']:.3g} mm, "
             f"{row['mismatched']} mismatched of {row['instants']} instants"
             for row in helix_validation.flute_summary()]
    return "Helical edges against the helix boolean: " + "; ".join(parts) + " (per instant in flutes.csv)."


# ---- schedule ------------------------------------------------------------------------------------

@dataclasses.dataclass(frozen=True)
class ScheduleResult:
    """What schedule found: the Prepared job, the Stock, the Schedule (feeds before and after), the
    limit's kind ("force" or "area") and value, and the files written."""

    prepared: object
    stock: object
    plan: object
    kind: str
    limit: float
    written: list


def schedule(job: Job, out, *, max_force=None, max_area=None, min_feed=None, report=None, warn=print):
    """The feed per CL point that keeps the peak force (max_force, N) or the cut area (max_area, mm²)
    at or under the limit, never above the programmed feed nor below `min_feed` (mm/tooth): the
    toolpath rewritten to `out` (APT / CL or CSV) and, with `report`, an HTML report. Returns a
    ScheduleResult; CL points that cannot meet the limit are told to warn(). A CL program written to
    .apt / .cls keeps every record but the chosen operation's feeds (FEDRAT records added before
    each changed move); otherwise the cutting moves are written with their feeds."""
    from ..formats.apt_writer import write_feed_toolpath
    from ..report.staging import staged
    from ..scheduling import programmed_feed
    from ..scheduling import schedule as feed_schedule

    kind, limit = ("force", max_force) if max_force is not None else ("area", max_area)
    if not (np.isfinite(limit) and limit > 0.0):
        raise ParameterError(f"max_{kind}", f"must be a positive number, got {limit:g}")
    if min_feed is not None and not (np.isfinite(min_feed) and min_feed > 0.0):
        raise ParameterError("min_feed", f"must be a positive feed per tooth (mm), got {min_feed:g}")
    suffix = os.path.splitext(out)[1].lower()
    if suffix not in (".apt", ".cls", ".csv", ".fcstd"):
        raise ParameterError("out", f"must end in .apt, .cls, .csv or (for a FreeCAD CAM Job) .FCStd, got {out}")
    prepared = prepare(job, forces=True)
    if suffix == ".fcstd" and prepared.hints.program.format != "fcstd":
        raise ParameterError("out", f"a FreeCAD document (.FCStd) is written for a FreeCAD CAM Job's program only, "
                                    f"not for {job.toolpath}")
    for message in prepared.warnings():
        warn(message)
    toolpath, tool, settings, hints = prepared.toolpath, prepared.tool, prepared.settings, prepared.hints
    try:
        programmed = programmed_feed(len(toolpath), settings.feed_per_tooth, feed=hints.feed, unit=hints.feed_unit,
                                     flutes=tool.flutes, spindle_rpm=settings.spindle_rpm)
    except ValueError as error:
        raise InputError(f"{job.toolpath}: {error}") from None
    if report:
        check_report_outputs(job, report)
    check_outputs([out] + ([report] if report else []), _inputs(job), files=[out])
    check_run_size(job, prepared, command="schedule", whole=True)
    prepared, stock, _ = load_job_stock(prepared)
    toolpath = prepared.toolpath  # in the frame of the stock (load_job_stock)
    check_model(stock, helix=tool.helix)
    in_process, model_note = in_process_sweep(prepared, warn=warn)
    if model_note:
        warn(f"{model_note}: the feeds are scheduled against the stock as given")
    if in_process is None:
        engagement = flute_1(stock.model, tool, toolpath, settings)
        engaged = engagement.engaged.any()
        forces = pass_forces_of(stock.model, tool, toolpath, settings, prepared.force_model, engagement,
                                feed=programmed) if engaged else None
    else:
        engaged, forces = _in_process_forces(stock.model, tool, toolpath, settings, prepared.force_model, in_process,
                                             programmed)
    if not engaged:
        raise no_engagement(job)
    plan = feed_schedule(forces, limit, kind=kind, min_feed=min_feed)
    unit = "N" if kind == "force" else "mm²"
    if plan.infeasible.any():
        shown = ", ".join(f"CL {i} (peak {plan.after[i]:.4g} {unit})" for i in np.flatnonzero(plan.infeasible)[:10])
        more = "" if plan.infeasible.sum() <= 10 else f" and {int(plan.infeasible.sum()) - 10} more"
        count = int(plan.infeasible.sum())
        warn(f"{count} CL points cannot keep the force at or under {limit:g} N at any feed from the minimum feed up; "
             f"they get the minimum feed: {shown}{more}" if kind == "force" else
             f"{count} CL points cannot keep the area at or under {limit:g} mm² at any feed from the minimum feed "
             f"up; they get the minimum feed: {shown}{more}")
    comment = (f"re-scheduled by abm schedule: peak {kind} <= {limit:g} {unit}, feed per tooth "
               f"{plan.feed.min():.6g}..{plan.feed.max():.6g} mm (programmed {plan.programmed.max():.6g} mm)")
    with output_folders([out] + ([report] if report else [])), \
            (staged(report, folder=True) if report else contextlib.nullcontext()) as folder:
        if folder:
            from ..report.forces import write_schedule_report
            title = prepared.description or f"{os.path.basename(job.stock)} / {os.path.basename(job.toolpath)}"
            write_schedule_report(folder, forces, plan, title=f"Feed schedule: {title}",
                                  parameters=prepared.parameters.describe())
        program = hints.program
        if suffix == ".fcstd":
            _write_dressup(out, job, hints.operation, plan.feed, tool.flutes, settings.spindle_rpm, comment)
        elif program is not None and program.format == "apt" and suffix != ".csv":
            _write_program_feeds(out, program, hints.operation, plan.feed, tool.flutes, settings.spindle_rpm)
        else:
            write_feed_toolpath(out, toolpath, plan.feed, flutes=tool.flutes, diameter=tool.diameter,
                                flute_length=tool.flute_length, spindle_rpm=settings.spindle_rpm, comment=comment)
    written = [out] + ([os.path.join(report, "index.html")] if report else [])
    return ScheduleResult(prepared, stock, plan, kind, limit, written)


def _write_dressup(out, job, operation, feed_per_tooth, flutes, spindle_rpm, comment):
    """The FreeCAD document of `job`'s CAM Job written to `out` with `operation` dressed with the scheduled feeds
    (cam.dressup; mm/min, so a spindle speed is needed)."""
    from ..cam.dressup import write_scheduled_document

    if spindle_rpm is None:
        raise InputError(f"{job.toolpath}: {operation.label()}: the dressup's feeds are per minute and need a "
                         "spindle speed (its tool controller's, or give the spindle speed)")
    write_scheduled_document(job.toolpath, out, getattr(job.options, "cam_job", None), operation,
                             feed_per_tooth * flutes * spindle_rpm, comment)


def _write_program_feeds(out, program, operation, feed_per_tooth, flutes, spindle_rpm):
    """The CL program written to `out` with only `operation`'s feeds changed to `feed_per_tooth` (m,) mm,
    every other record as it was: per revolution where the operation's feed is, else per minute."""
    from ..formats.cl.rewrite import write_rescheduled_program

    if operation.feed_unit == "MMPR":
        feed = feed_per_tooth * flutes
    elif spindle_rpm is not None:
        feed = feed_per_tooth * flutes * spindle_rpm
    else:
        raise InputError(f"{program.source}: {operation.label()}: feeds per minute need a spindle speed (SPINDL, or "
                         "give the spindle speed)")
    write_rescheduled_program(out, program, operation.number, feed)
