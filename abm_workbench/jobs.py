"""A job's inputs from whichever files hold them: stock, toolpath, cutting parameters.

- :func:`load_stock`: a staircase JSON (``.json``), or a solid (``.step``, ``.stp``,
  ``.brep``, ``.brp``, ``.FCStd``) recognised as a staircase. FreeCAD is imported only for
  solids, so JSON jobs never need it.
- :func:`load_path`: a toolpath CSV (``.csv``) or an APT / CL file (``.apt``, ``.cls``), with
  what an APT file says about the tool, spindle and feed (:class:`PathHints`).
- :func:`load_job`: a ``--job`` JSON of default cutting parameters.
- :func:`resolve_parameters`: each parameter from the command line, else the APT file, else
  the job file, else its default, remembering where it came from.

The y window of a recognised solid is the stock's whole y range by default: the staircase
then describes every point of the solid, so the engine and the boolean reference see the same
stock wherever the edge goes. :func:`swept_y_window` gives the narrower window the paper fits
its six wall points over (the y range the cutting edges sweep in the pass); it only changes
quintic walls (``walls="quintic"``), whose fit it tightens.

Lengths in mm, angles in degrees, spindle speed in rpm. Bad input raises
:class:`~abm_workbench.errors.InputError` naming the file.
"""

import os
from dataclasses import dataclass
from typing import Optional

import numpy as np

from .engine import CutSettings, Staircase, Tool, Toolpath, rotation_matrix
from .errors import InputError
from .formats import check_keys, json_number, load_json_object
from .formats.apt import MM_PER_INCH, load_apt
from .formats.staircase_json import load_staircase
from .formats.toolpath_csv import load_toolpath

SOLID_SUFFIXES = (".step", ".stp", ".brep", ".brp", ".fcstd")
APT_SUFFIXES = (".apt", ".cls")
WALL_MODELS = ("exact", "quintic")
WALL_POINTS = ("chebyshev", "even")
#: Extra width (mm) on each side of the swept y window.
SWEPT_MARGIN = 1.0
#: A feed that varies by less than this fraction along the pass counts as constant.
_FEED_SPREAD = 1e-9

#: Marks a parameter without a default.
REQUIRED = object()
#: Cutting parameters (as the --job keys) and their defaults.
PARAMETERS = {
    "diameter": REQUIRED, "flutes": REQUIRED, "flute_length": REQUIRED, "feed_per_tooth": REQUIRED,
    "inclination": 0.0, "spindle_rpm": None, "phi_range": (0.0, 180.0), "phi_step": 1.0,
}


@dataclass(frozen=True)
class Stock:
    """A loaded stock.

    staircase: the Staircase the engine works on. source: the file. shape: the Part.Shape read
    from a solid file, or None for a JSON stock. walls: "quintic" (JSON, or a solid recognised
    with the paper's quintics) or "exact" (a solid's own wall curves). y_window: (2,) mm, the
    staircase's y range.
    """

    staircase: Staircase
    source: str
    shape: object = None
    walls: str = "quintic"

    @property
    def y_window(self):
        """(y_min, y_max) of the staircase (mm)."""
        return (self.staircase.y_min, self.staircase.y_max)

    def solid(self):
        """The stock as a Part.Shape: the solid read, or for JSON the staircase built as a solid."""
        if self.shape is not None:
            return self.shape
        from .cad.solids import staircase_solid
        return staircase_solid(self.staircase)


@dataclass(frozen=True)
class PathHints:
    """What a toolpath file says besides the CL points (all None / empty for a CSV).

    diameter, flute_length: mm. spindle_rpm: rpm. feed: (m,) feed at each CL point in
    feed_unit ("MMPM", "MMPR", "IPM" or "IPR"; NaN before the first FEDRAT), or None.
    unknown: (major word, first line, count) of APT records not understood. warnings: messages
    ``file:line: ...``. source: the file.
    """

    source: str
    diameter: Optional[float] = None
    flute_length: Optional[float] = None
    spindle_rpm: Optional[float] = None
    feed: Optional[np.ndarray] = None
    feed_unit: Optional[str] = None
    unknown: tuple = ()
    warnings: tuple = ()

    def messages(self):
        """Every warning and each unknown APT record kind, once, as text for ``abm: warning: ...``."""
        unknown = [
            f"{self.source}:{line}: {word}: record not understood, ignored"
            + (f" ({count} times)" if count > 1 else "")
            for word, line, count in self.unknown
        ]
        return list(self.warnings) + unknown


def load_stock(path, *, walls="exact", wall_points="chebyshev", y_window=None):
    """The stock in `path` as a :class:`Stock`.

    A ``.json`` file is read as an abm-staircase/1 staircase (its walls are the paper's
    quintics; walls, wall_points and y_window do not apply). A solid is recognised as a
    staircase (:func:`abm_workbench.cad.recognise.recognise`): walls "exact" keeps the solid's
    own wall curves, "quintic" fits the paper's quintic through six points per wall placed by
    wall_points ("chebyshev" or "even") over y_window ((y0, y1) mm, cut to the stock's y range;
    None: the whole range; or a function of the solid's highest z giving (y0, y1), as
    :func:`swept_y_window` does). InputError naming the file for anything else.
    """
    name = os.fspath(path)
    suffix = os.path.splitext(name)[1].lower()
    if walls not in WALL_MODELS:
        raise ValueError(f"walls must be one of {WALL_MODELS}, got {walls!r}")
    if wall_points not in WALL_POINTS:
        raise ValueError(f"wall_points must be one of {WALL_POINTS}, got {wall_points!r}")
    if suffix == ".json":
        return Stock(load_staircase(name), name)
    if suffix not in SOLID_SUFFIXES:
        raise InputError(f"{name}: unknown stock file type; expected .json, .step, .stp, .brep, .brp or .FCStd")
    from .cad.recognise import load_solid, recognise  # FreeCAD only for solids
    shape = load_solid(name)
    if callable(y_window):
        y_window = y_window(shape.BoundBox.ZMax)
    if y_window is not None:
        box = shape.BoundBox
        low, high = max(float(y_window[0]), box.YMin), min(float(y_window[1]), box.YMax)
        if not low < high:
            raise InputError(f"{name}: y window {y_window[0]:g}..{y_window[1]:g} mm misses the stock's y range "
                             f"{box.YMin:g}..{box.YMax:g} mm")
        y_window = (low, high)
    recognition = recognise(shape, walls=walls, wall_points=wall_points, y_window=y_window, source=name)
    return Stock(recognition.staircase, name, shape, walls)


def load_path(path):
    """(Toolpath, PathHints) of a toolpath CSV (``.csv``) or APT / CL file (``.apt``, ``.cls``)."""
    name = os.fspath(path)
    suffix = os.path.splitext(name)[1].lower()
    if suffix == ".csv":
        return load_toolpath(name), PathHints(name)
    if suffix not in APT_SUFFIXES:
        raise InputError(f"{name}: unknown toolpath file type; expected .csv, .apt or .cls")
    program = load_apt(name)
    hints = PathHints(name, program.diameter, program.flute_length, program.spindle_rpm, program.feed,
                      program.feed_unit, program.unknown, program.warnings)
    return program.toolpath, hints


def swept_y_window(toolpath: Toolpath, tool: Tool, z_max=np.inf, margin=SWEPT_MARGIN):
    """(y0, y1) mm: the y range the cutting edges sweep below z_max over the pass, widened by `margin`.

    An edge point's y is y_T + R_t (sin φ sA sB + cos φ cA) − l sA cB (notes §2): over φ the
    middle term reaches ±R_t·hypot(sA sB, cA), and l runs over 0..L, or only as far as an
    edge can still be below z_max (the stock's top): z = z_T + R_t (−sin φ cA sB + cos φ sA)
    + l cA cB, whose lowest start is z_T − R_t·hypot(cA sB, sA).
    """
    rotation = rotation_matrix(toolpath.theta_a, toolpath.theta_b)  # (m, 3, 3)
    radial = tool.radius * np.hypot(rotation[:, 1, 0], rotation[:, 1, 1])
    lowest = toolpath.cl[:, 2] - tool.radius * np.hypot(rotation[:, 2, 0], rotation[:, 2, 1])
    reach = np.clip((z_max - lowest) / rotation[:, 2, 2], 0.0, tool.flute_length)
    along = reach * rotation[:, 1, 2]
    y = toolpath.cl[:, 1]
    low = y - radial + np.minimum(along, 0.0)
    high = y + radial + np.maximum(along, 0.0)
    return float(low.min() - margin), float(high.max() + margin)


def load_job(path):
    """Cutting parameters of a --job JSON file: a dict with keys of PARAMETERS (+ description)."""
    data = load_json_object(path)
    check_keys(data, (), (*PARAMETERS, "description"), path)
    job = {}
    for key, value in data.items():
        where = f"{path}: {key}"
        if key == "description":
            if not isinstance(value, str):
                raise InputError(f"{where}: must be a string")
            job[key] = value
        elif key == "phi_range":
            if not isinstance(value, list) or len(value) != 2:
                raise InputError(f"{where}: must be [start, end] in degrees, e.g. [0, 180]")
            job[key] = tuple(json_number(v, f"{where}[{i}]") for i, v in enumerate(value))
        else:
            job[key] = json_number(value, where)
    return job


@dataclass(frozen=True)
class Parameters:
    """Resolved cutting parameters (keys of PARAMETERS) and where each came from.

    values: {name: value}. sources: {name: "--option", "<path file> <RECORD>", "<job file>" or
    "default"}. conflicts: messages where the toolpath file and the job file disagree.
    """

    values: dict
    sources: dict
    conflicts: tuple

    def describe(self):
        """One line: each parameter, its value and [its source]."""
        v, s = self.values, self.sources
        spindle = "none" if v["spindle_rpm"] is None else f"{v['spindle_rpm']:g} rpm"
        start, end = v["phi_range"]
        items = [
            ("diameter", f"diameter {v['diameter']:g} mm"), ("flutes", f"{v['flutes']:g} flutes"),
            ("flute_length", f"flute length {v['flute_length']:g} mm"),
            ("feed_per_tooth", f"feed {v['feed_per_tooth']:g} mm/tooth"),
            ("inclination", f"inclination {v['inclination']:g}°"), ("spindle_rpm", f"spindle {spindle}"),
            ("phi_range", f"φ {start:g}..{end:g}°"), ("phi_step", f"step {v['phi_step']:g}°"),
        ]
        return ", ".join(f"{text} [{s[key]}]" for key, text in items)


def resolve_parameters(given, hints: PathHints, job, job_source=None):
    """Each cutting parameter from the toolpath file where it gives it (the tool and feed the
    path was made for), else from `given` (command-line values, None when not given), else the
    job, else its default; InputError for a missing required one. Where the file and the
    command line or the job disagree, the file's value is used and `conflicts` says so.

    given: {name: value or None} for the keys of PARAMETERS. The feed per tooth comes from the
    APT feed only when it is the same at every CL point and, for a feed per minute, the spindle
    speed is known: f_z = F / (n · Z) (mm/min), F / Z (mm/rev), inches converted.
    """
    values, sources, conflicts = {}, {}, []
    from_path = {"diameter": (hints.diameter, "CUTTER"), "flute_length": (hints.flute_length, "CUTTER"),
                 "spindle_rpm": (hints.spindle_rpm, "SPINDL")}
    order = [key for key in PARAMETERS if key != "feed_per_tooth"] + ["feed_per_tooth"]
    for key in order:
        if key == "feed_per_tooth":
            from_path[key] = (_feed_per_tooth(hints, values["flutes"], values["spindle_rpm"]), "FEDRAT")
        file_value, record = from_path.get(key, (None, None))
        if file_value is not None:
            values[key], sources[key] = file_value, f"{os.path.basename(hints.source)} {record}"
            option = f"--{key.replace('_', '-')}"
            for other, where in ((given.get(key), option), (job.get(key), job_source)):
                if other is not None and not np.isclose(other, file_value, rtol=1e-9, atol=0.0):
                    conflicts.append(f"{hints.source} gives {key} {file_value:g}, {where} {other:g}: "
                                     f"using {file_value:g}, the value the toolpath was made for")
        elif given.get(key) is not None:
            values[key], sources[key] = given[key], f"--{key.replace('_', '-')}"
        elif key in job:
            values[key], sources[key] = job[key], os.path.basename(job_source)
        elif PARAMETERS[key] is REQUIRED:
            raise InputError(f"missing --{key.replace('_', '-')} (or {key!r} in a --job file)")
        else:
            values[key], sources[key] = PARAMETERS[key], "default"
    return Parameters(values, sources, tuple(conflicts))


def tool_and_settings(values):
    """(Tool, CutSettings) of resolved parameter values (Parameters.values); InputError if invalid."""
    try:
        tool = Tool(values["diameter"], values["flutes"], values["flute_length"])
    except ValueError as error:
        raise InputError(f"tool: {error}") from None
    try:
        settings = CutSettings(values["feed_per_tooth"], values["inclination"], *values["phi_range"],
                               values["phi_step"], values["spindle_rpm"])
    except ValueError as error:
        raise InputError(f"cut settings: {error}") from None
    return tool, settings


def _feed_per_tooth(hints, flutes, spindle_rpm):
    """Feed per tooth (mm) from a constant APT feed, or None (see resolve_parameters)."""
    feed = hints.feed
    if feed is None or hints.feed_unit is None or not np.isfinite(feed).all() or flutes is None:
        return None
    if np.ptp(feed) > _FEED_SPREAD * np.abs(feed).max():
        return None
    value = float(feed[0]) * (MM_PER_INCH if hints.feed_unit.startswith("I") else 1.0) / flutes
    if hints.feed_unit.endswith("PM"):
        if spindle_rpm is None:
            return None
        value /= spindle_rpm
    return value if value > 0 else None
