"""A job: one run's inputs as any front end gives them, resolved into what the engine runs on.

:class:`Job` holds the input files and the front end's own values (the command line's
options, the engagement object's properties, the task panel's fields) by parameter name.
:func:`prepare` reads the job file and the toolpath, resolves every parameter
(:mod:`.resolve`) and checks it (:mod:`.parameters`); :func:`load_job_stock` reads the stock
with the job's wall model and y window. Bad input raises InputError naming the file, or
ParameterError naming the parameter, which the front end words its own way.

Lengths in mm, angles in degrees.
"""

import dataclasses
import functools
import os
import time
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from ..errors import InputError, ParameterError
from ..forces import COEFFICIENT_NAMES, Coefficients, material
from ..formats.cl import STEP, TOLERANCE
from .inputs import SOLID_SUFFIXES, load_job, load_path, load_stock, path_in_frame, solid_in_part, swept_y_window
from .parameters import BY_NAME, check_pairs
from .resolve import resolve, tool_and_settings

#: y window choices besides a (y0, y1) pair.
Y_WINDOW_WORDS = ("whole", "swept")


@dataclass(frozen=True)
class Job:
    """One run's inputs.

    stock, toolpath: file paths. job_file: a job JSON of defaults, or None. given: {parameter
    name: value or None} the front end's own values (None or missing: not given). forces: compute
    the cutting forces. material: a material name (forces.MATERIALS) or None (the coefficients as
    given). walls ("exact" / "quintic"), wall_points ("chebyshev" / "even"), y_window ("whole",
    "swept" or (y0, y1) mm): a solid stock's recognition, None for the default. operation: the
    toolpath file's operation (1-based), None for its one milling operation. solid: the solid's
    name in a stock file holding several, or None. stock_model: "in-process" (the stock minus what
    earlier cutting moves of the program removed) or "initial" (the stock as given, the paper's
    assumption); None: in-process where the engine has it (straight flutes, ABM), else
    initial. sweep_tolerance: mm, the sub-step of five-axis moves at the tool's rim. tolerance, step:
    mm, the chordal tolerance of a CL file's arcs and curves and the largest distance between their CL
    points (formats.cl.read_program). options: what reading the toolpath needs besides it (a FreeCAD
    CAM Job's name, a G-code program's tool table, machine and work offsets:
    formats.gcode.options.ReadOptions), or None.
    """

    stock: str
    toolpath: str
    job_file: Optional[str] = None
    given: dict = field(default_factory=dict)
    forces: bool = False
    material: Optional[str] = None
    walls: Optional[str] = None
    wall_points: Optional[str] = None
    y_window: object = None
    operation: Optional[int] = None
    solid: Optional[str] = None
    stock_model: Optional[str] = None
    sweep_tolerance: float = 0.05
    tolerance: float = TOLERANCE
    step: float = STEP
    options: Optional[object] = None


def with_cam_stock(job: Job):
    """`job` with the Stock of a FreeCAD CAM Job where it names none: with no stock, its toolpath's document
    (an FCStd) as the stock file and that Job's Stock as its solid; with an FCStd stock and no solid named,
    the Stock of the CAM Job that document holds, if it holds one. InputError when it names no stock and its
    toolpath is no FreeCAD document."""
    name = getattr(job.options, "cam_job", None)
    if job.stock is None:
        if not os.fspath(job.toolpath).lower().endswith(".fcstd"):
            raise InputError(f"{job.toolpath}: give the stock (--stock): only a FreeCAD CAM Job's document (FCStd) "
                             "holds its own")
        from ..cam.documents import job_stock  # FreeCAD only for a document

        return dataclasses.replace(job, stock=job.toolpath, solid=job.solid or job_stock(job.toolpath, name))
    if job.solid is None and os.fspath(job.stock).lower().endswith(".fcstd"):
        from ..cam.documents import job_stock

        same = os.path.abspath(job.stock) == os.path.abspath(job.toolpath)
        solid = job_stock(job.stock, name if same else None, required=False)
        return dataclasses.replace(job, solid=solid) if solid else job
    return job


@dataclass(frozen=True)
class Prepared:
    """A job resolved: the job file's values (with "description"), the Toolpath and PathHints,
    the Parameters, the Tool (with its helix) and CutSettings, and the force model
    ((Coefficients, immersion (start, end) deg) or None without forces)."""

    job: Job
    defaults: dict
    toolpath: object
    hints: object
    parameters: object
    tool: object
    settings: object
    force_model: object

    @property
    def description(self):
        """The job file's description, or ''."""
        return self.defaults.get("description", "")

    def warnings(self):
        """What the toolpath file could not read and where the sources disagree, as messages."""
        return [*self.hints.messages(), *self.parameters.conflicts]


def prepare(job: Job, *, forces=None):
    """The Prepared job (the stock is read apart, by load_job_stock). forces: override job.forces."""
    defaults = load_job(job.job_file) if job.job_file else {}
    toolpath, hints = load_path(job.toolpath, job.operation, tolerance=job.tolerance, step=job.step,
                                options=job.options)
    parameters = resolve(job.given, hints, defaults, job.job_file)
    helix = _value("helix", job, defaults)
    tool, settings = tool_and_settings(parameters.values, helix)
    model = force_model(job, defaults) if (job.forces if forces is None else forces) else None
    return Prepared(job, defaults, toolpath, hints, parameters, tool, settings, model)


def _value(name, job, defaults):
    """A parameter outside the cutting ones (helix, coefficients, immersion): given, else the job
    file's, else its default; checked."""
    parameter = BY_NAME[name]
    if job.given.get(name) is not None:
        return parameter.check(job.given[name])
    return defaults.get(name, parameter.default)


def force_model(job: Job, defaults=None):
    """(Coefficients, immersion (start, end) deg) of the job's material and coefficients.

    The material (given, else the job file's) fills every coefficient; single coefficients given
    override it. ParameterError naming the material or the coefficient that is bad or missing.
    """
    defaults = defaults or {}
    name = job.material if job.material is not None else defaults.get("material")
    values = {}
    if name is not None:
        try:
            values = dataclasses.asdict(material(name))
        except ValueError as error:
            raise ParameterError("material", str(error)) from None
    for key in COEFFICIENT_NAMES:
        value = _value(key, job, defaults)
        if value is not None:
            values[key] = value
    missing = [key for key in ("ktc", "krc", "kac") if key not in values]
    if missing:
        raise ParameterError(missing[0], "is required for the forces: give a material or the coefficients "
                                         "ktc, krc and kac")
    immersion = {key: _value(key, job, defaults) for key in ("immersion_start", "immersion_end")}
    check_pairs(immersion)
    return Coefficients(**values), (immersion["immersion_start"], immersion["immersion_end"])


def is_solid(path):
    """Whether the stock file `path` is a solid (STEP, BREP, FCStd) rather than a staircase JSON."""
    return os.path.splitext(path)[1].lower() in SOLID_SUFFIXES


def load_job_stock(prepared: Prepared):
    """(Prepared, Stock, seconds to read it) of a prepared job: a solid's options checked, the y window
    chosen. A solid stock is computed in its operation's frame turned to the stock's own 2.5D
    direction (inputs.solid_in_part), a JSON stock in the part when the operation's frame is turned: the
    Prepared returned is then the job with its toolpath and hints in that frame (inputs.path_in_frame),
    else `prepared` itself.

    ParameterError naming walls, wall_points or y_window when they are given for a JSON stock.
    """
    job = prepared.job
    if not is_solid(job.stock):
        for name in ("walls", "wall_points", "y_window", "solid"):
            if getattr(job, name) is not None:
                raise ParameterError(name, f"applies to a solid stock (.step, .stp, .brep, .brp, .FCStd), not to "
                                           f"{job.stock}")
    window = job.y_window or ("swept" if job.walls == "quintic" else "whole")
    if not (window in Y_WINDOW_WORDS if isinstance(window, str) else isinstance(window, tuple) and len(window) == 2):
        raise InputError(f"y window must be whole, swept or (y0, y1), got {window!r}")
    started = time.perf_counter()
    shape = None
    if is_solid(job.stock):
        shape, frame = solid_in_part(job.stock, job.solid, prepared.hints.frame)
        toolpath, hints = path_in_frame(prepared.toolpath, prepared.hints, frame)
        prepared = dataclasses.replace(prepared, toolpath=toolpath, hints=hints)
    elif prepared.hints.frame is not None and not np.allclose(prepared.hints.frame[0], np.eye(3), rtol=0.0, atol=1e-12):
        # A JSON stock stands in the part and can only be moved: the operation is computed in the part, its
        # tool axes as they come (the engine takes every direction).
        toolpath, hints = path_in_frame(prepared.toolpath, prepared.hints, None)
        prepared = dataclasses.replace(prepared, toolpath=toolpath, hints=hints)
    if window == "whole":
        window = None
    elif window == "swept":
        window = functools.partial(swept_y_window, prepared.toolpath, prepared.tool)  # with the solid's top z
    stock = load_stock(job.stock, walls=job.walls or "exact", wall_points=job.wall_points or "chebyshev",
                       y_window=window, frame=prepared.hints.frame, solid=job.solid, shape=shape)
    return prepared, stock, time.perf_counter() - started


def cl_indices(text, m, field="cl"):
    """Sorted distinct CL indices from '0,22,40'; ParameterError(field) unless each is an integer (ASCII digits)
    in 0..m−1."""
    from .checked import INDEX

    indices = set()
    for part in text.split(","):
        try:
            if not INDEX.fullmatch(part.strip()):
                raise ValueError(part)
            index = int(part)
        except ValueError:
            raise ParameterError(field, f"expected CL indices such as 0,22,40, got {text!r}") from None
        if not 0 <= index < m:
            raise ParameterError(field, f"CL point {index} is not in the pass (0..{m - 1})")
        indices.add(index)
    return sorted(indices)
