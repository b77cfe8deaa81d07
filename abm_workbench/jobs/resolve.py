"""Each parameter's value from the sources that can give it, and where it came from.

Precedence: the toolpath file where it really gives a value (the tool and feed the path was
made for: CUTTER / TLDATA diameter, corner radius and flute length, a FreeCAD toolbit's flutes,
SPINDL, a constant FEDRAT), else the
front end's own input (command-line options, the engagement object's properties, the task
panel's fields), else the job file, else the default. A source is recorded as (kind, text):
("file", "path.apt CUTTER"), ("given", ""), ("job", "job.json") or ("default", ""); each front
end names "given" in its own words (the option, or the property).

Lengths in mm, angles in degrees, spindle speed in rpm.
"""

import os
from dataclasses import dataclass

import numpy as np

from ..engine import CutSettings, Tool
from ..errors import MissingParameter, ParameterError
from ..formats.cl.units import MM_PER_INCH
from .parameters import BY_NAME, CUTTING, REQUIRED, check_pairs

#: A feed that varies by less than this fraction along the pass counts as constant.
_FEED_SPREAD = 1e-9


@dataclass(frozen=True)
class Parameters:
    """Resolved cutting parameters (the names of parameters.CUTTING) and where each came from.

    values: {name: value}. sources: {name: (kind, text)} as the module says. conflicts: messages
    where the toolpath file and another source disagree (the file's value is used).
    """

    values: dict
    sources: dict
    conflicts: tuple

    def source_text(self, name, given_word):
        """Where `name` came from in words; given_word(Parameter) names a front end's own input."""
        kind, text = self.sources[name]
        return given_word(BY_NAME[name]) if kind == "given" else text if text else kind

    def fixed_by_file(self, name):
        """Whether the toolpath file gave `name`."""
        return self.sources[name][0] == "file"

    def describe(self, given_word=lambda parameter: parameter.option):
        """One line: each parameter, its value and [its source]."""
        v = self.values
        spindle = "none" if v["spindle_rpm"] is None else f"{v['spindle_rpm']:g} rpm"
        items = [
            ("diameter", f"diameter {v['diameter']:g} mm"), ("flutes", f"{v['flutes']:g} flutes"),
            ("flute_length", f"flute length {v['flute_length']:g} mm"),
            ("corner_radius", f"corner radius {v['corner_radius']:g} mm"),
            ("feed_per_tooth", f"feed {v['feed_per_tooth']:g} mm/tooth"),
            ("inclination", f"inclination {v['inclination']:g}°"), ("spindle_rpm", f"spindle {spindle}"),
            ("phi_start", f"φ {v['phi_start']:g}..{v['phi_end']:g}°"), ("phi_step", f"step {v['phi_step']:g}°"),
        ]
        return ", ".join(f"{text} [{self.source_text(name, given_word)}]" for name, text in items)


def resolve(given, hints, job, job_source=None, words=lambda parameter: parameter.option):
    """The Parameters of the cutting parameters.

    given: {name: value or None} of the front end's own input (keys of parameters.CUTTING;
    missing or None: not given); words(parameter): how that front end names a parameter in a message
    (the command line's option, the GUI's property). hints: the toolpath file's PathHints. job: {name: value} of a
    job file (already checked), job_source its path. ParameterError for a value out of range, MissingParameter for
    a required value given nowhere (a ParameterError naming the job file when its value is bad).
    The feed per tooth comes from the toolpath file only when its feed is the same at every CL
    point and, for a feed per minute, the spindle speed is known: f_z = F / (n · Z) (mm/min),
    F / Z (mm/rev), inches converted.
    """
    values, sources, conflicts = {}, {}, []
    from_file = {"diameter": hints.diameter, "flute_length": hints.flute_length, "corner_radius": hints.corner_radius,
                 "spindle_rpm": hints.spindle_rpm, "flutes": hints.flutes}
    order = [name for name in CUTTING if name != "feed_per_tooth"] + ["feed_per_tooth"]
    for name in order:
        parameter = BY_NAME[name]
        if name == "feed_per_tooth":
            from_file[name] = _feed_per_tooth(hints, values["flutes"], values["spindle_rpm"])
        file_value, mine, theirs = from_file.get(name), given.get(name), job.get(name)
        if mine is not None:
            mine = parameter.check(mine)
        if file_value is not None:
            values[name] = parameter.check(file_value, hints.source)
            sources[name] = ("file", f"{os.path.basename(hints.source)} {hints.records.get(name, parameter.record)}")
            for other, where in ((mine, words(parameter)), (theirs, job_source)):
                if other is not None and not np.isclose(other, file_value, rtol=1e-9, atol=0.0):
                    conflicts.append(f"{hints.source} gives {name} {file_value:g}, {where} {other:g}: "
                                     f"using {file_value:g}, the value the toolpath was made for")
        elif mine is not None:
            values[name], sources[name] = mine, ("given", "")
        elif theirs is not None:
            values[name], sources[name] = theirs, ("job", os.path.basename(job_source or "job file"))
        elif parameter.default is REQUIRED:
            raise MissingParameter(name)
        else:
            values[name], sources[name] = parameter.default, ("default", "")
    check_pairs(values)
    return Parameters(values, sources, tuple(conflicts))


def tool_and_settings(values, helix=0.0):
    """(Tool, CutSettings) of checked parameter values (Parameters.values) and a helix angle (deg).
    ParameterError for a helix on a tool with a corner radius (not computed)."""
    helix = BY_NAME["helix"].check(helix)
    corner = values.get("corner_radius", 0.0)
    if helix and corner:
        raise ParameterError("helix", f"is {helix:g}°, but helical flutes on a corner are not computed: a tool with a "
                                      f"corner radius ({corner:g} mm) needs straight flutes (helix 0)")
    tool = Tool(values["diameter"], values["flutes"], values["flute_length"], helix, corner)
    settings = CutSettings(values["feed_per_tooth"], values["inclination"], values["phi_start"], values["phi_end"],
                           values["phi_step"], values["spindle_rpm"])
    return tool, settings


def _feed_per_tooth(hints, flutes, spindle_rpm):
    """Feed per tooth (mm) from a constant toolpath-file feed, or None (see resolve)."""
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
