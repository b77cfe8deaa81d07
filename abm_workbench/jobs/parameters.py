"""Every job parameter declared once: name, plain label, unit, range, default, help, and where it may come from.

The command line builds its options from these declarations (``--diameter``), the job file
reads its keys from them (``"diameter"``), the engagement object names its properties after
them (``Diameter``) and the task panel its fields. :meth:`Parameter.check` is the one check
of a value; it raises :class:`~abm_workbench.errors.ParameterError` carrying the parameter's
name, which each front end words its own way (:func:`option_words`, :func:`label_words`).

Lengths in mm, angles in degrees, spindle speed in rpm, force coefficients in N/mm² (cutting)
and N/mm (edge).
"""

import json
import math
from dataclasses import dataclass
from typing import Optional

from ..errors import MissingParameter, ParameterError
from ..formats import MAX_MAGNITUDE
from ..forces import COEFFICIENT_NAMES, FULL_SLOT, MATERIALS

#: Marks a parameter without a default: it must be given.
REQUIRED = object()
#: Most rotation angles one run may report.
MAX_ANGLES = 10 ** 6


@dataclass(frozen=True)
class Parameter:
    """One parameter.

    name: the job file's key and the engine's word. label: plain words for messages and the
    GUI. unit: "mm", "deg", "rpm", "N/mm²", "N/mm" or "" (a count). whole: a whole number.
    default: a value, None (optional, no value) or REQUIRED. low, high: the allowed range
    (None: unbounded), open at `low` when low_open, at `high` when high_open. prop: the
    engagement object's property. option: the command-line option (pairs such as φ start and
    end share one, ``--phi-range START:END``). record: the toolpath-file record that can give
    the value, or "". help: one sentence for --help and tooltips.
    """

    name: str
    label: str
    unit: str
    default: object
    low: Optional[float] = None
    high: Optional[float] = None
    low_open: bool = False
    high_open: bool = False
    whole: bool = False
    prop: str = ""
    option: str = ""
    record: str = ""
    help: str = ""

    def check(self, value, where=None):
        """`value` as float (int for a whole number) inside the range; ParameterError otherwise.

        where: the file the value came from, for the error (None: the front end's own input).
        """
        shown = "" if not self.unit else " mm" if self.unit == "mm" else "°" if self.unit == "deg" else f" {self.unit}"
        if isinstance(value, (bool, str)) or value is None:
            raise ParameterError(self.name, f"must be a number, got {json.dumps(value)}", where)
        try:
            number = float(value)
        except (TypeError, ValueError, OverflowError):
            raise ParameterError(self.name, f"must be a number, got {value!r}", where) from None
        if not math.isfinite(number):
            raise ParameterError(self.name, f"must be a finite number, got {number!r}", where)
        if abs(number) > MAX_MAGNITUDE:
            raise ParameterError(self.name, f"must be at most {MAX_MAGNITUDE:g} in size, got {number:g}", where)
        if self.whole and number != int(number):
            raise ParameterError(self.name, f"must be a whole number, got {number:g}", where)
        below = self.low is not None and (number <= self.low if self.low_open else number < self.low)
        above = self.high is not None and (number >= self.high if self.high_open else number > self.high)
        if below or above:
            raise ParameterError(self.name, f"must be {self.range_text()}, got {number:g}{shown}", where)
        return int(number) if self.whole else number

    def range_text(self):
        """The allowed range in words: 'positive', 'within (-90, 90)°', 'at least 1', ..."""
        unit = "" if not self.unit else "°" if self.unit == "deg" else f" {self.unit}"
        if self.low == 0.0 and self.low_open and self.high is None:
            return "positive"
        if self.high is None:
            return f"{'above' if self.low_open else 'at least'} {self.low:g}{unit}"
        if self.low is None:
            return f"{'below' if self.high_open else 'at most'} {self.high:g}{unit}"
        return (f"within {'(' if self.low_open else '['}{self.low:g}, {self.high:g}{')' if self.high_open else ']'}"
                f"{unit}")


def _coefficient(name):
    """The declaration of force coefficient `name` (ktc ... kae)."""
    direction = {"t": "tangential", "r": "radial", "a": "axial"}[name[1]]
    cutting = name.endswith("c")
    return Parameter(
        name, f"K{name[1:]} ({direction} {'cutting' if cutting else 'edge'} coefficient)",
        "N/mm²" if cutting else "N/mm", None, 0.0 if name == "ktc" else None, low_open=name == "ktc",
        prop=name.capitalize(), option=f"--{name}",
        help=f"{direction} {'cutting-force' if cutting else 'edge-force'} coefficient of the linear edge-force model")


#: The parameters, in the order they are shown.
PARAMETERS = (
    Parameter("diameter", "tool diameter", "mm", REQUIRED, 0.0, low_open=True, prop="Diameter",
              option="--diameter", record="CUTTER", help="tool diameter D"),
    Parameter("flutes", "number of flutes", "", REQUIRED, 1.0, 1000.0, whole=True, prop="Flutes",
              option="--flutes", help="number of flutes Z"),
    Parameter("flute_length", "flute length", "mm", REQUIRED, 0.0, low_open=True, prop="FluteLength",
              option="--flute-length", record="CUTTER", help="length of the cutting edge L"),
    Parameter("corner_radius", "corner radius", "mm", 0.0, 0.0, prop="CornerRadius", option="--corner-radius",
              record="CUTTER", help="corner radius r of the tool: 0 a flat-end mill, half the diameter a ball-end "
              "mill, between a bull-nose (torus) mill"),
    Parameter("helix", "helix angle", "deg", 0.0, -60.0, 60.0, False, False, prop="HelixAngle", option="--helix",
              help="helix angle β of the flutes, |β| ≤ 60° (flat-end mills); 0 for straight flutes"),
    Parameter("feed_per_tooth", "feed per tooth", "mm", REQUIRED, 0.0, low_open=True, prop="FeedPerTooth",
              option="--feed-per-tooth", record="FEDRAT", help="feed per tooth f"),
    Parameter("spindle_rpm", "spindle speed", "rpm", None, 0.0, low_open=True, prop="SpindleSpeed",
              option="--spindle-rpm", record="SPINDL", help="spindle speed n"),
    Parameter("inclination", "inclination angle", "deg", 0.0, -90.0, 90.0, True, True, prop="Inclination",
              option="--inclination", help="tool inclination angle α"),
    Parameter("phi_start", "first rotation angle φ", "deg", 0.0, prop="PhiStart", option="--phi-range",
              help="first tool rotation angle φ reported"),
    Parameter("phi_end", "last rotation angle φ", "deg", 180.0, prop="PhiEnd", option="--phi-range",
              help="last tool rotation angle φ reported"),
    Parameter("phi_step", "step of φ", "deg", 1.0, 0.0, low_open=True, prop="PhiStep", option="--phi-step",
              help="step of the tool rotation angle φ"),
    *(_coefficient(name) for name in COEFFICIENT_NAMES),
    Parameter("immersion_start", "start of immersion", "deg", FULL_SLOT[0], 0.0, 180.0, high_open=True,
              prop="ImmersionStart", option="--immersion", help="angle from which a flute cuts"),
    Parameter("immersion_end", "end of immersion", "deg", FULL_SLOT[1], 0.0, 180.0, low_open=True,
              prop="ImmersionEnd", option="--immersion", help="angle up to which a flute cuts"),
)
#: name -> Parameter.
BY_NAME = {parameter.name: parameter for parameter in PARAMETERS}
#: The cutting parameters a job file, the command line or the engagement object give, with the
#: toolpath file's tool, spindle and feed winning (jobs.resolve).
CUTTING = ("diameter", "flutes", "flute_length", "corner_radius", "feed_per_tooth", "inclination", "spindle_rpm", "phi_start",
           "phi_end", "phi_step")
#: The sub-step of five-axis moves for the in-process stock: a run option, not a cutting parameter
#: (kept out of PARAMETERS, so neither the job file nor the cutting options take it).
SWEEP_TOLERANCE = Parameter("sweep_tolerance", "sweep tolerance", "mm", 0.05, 0.0, low_open=True,
                            prop="SweepTolerance", option="--sweep-tolerance",
                            help="sub-step of five-axis moves at the tool's rim for the in-process stock")
#: Material choices: the force table's, or custom (the coefficients as given).
MATERIAL_CHOICES = tuple(MATERIALS) + ("custom",)


def option_words(error):
    """A ParameterError in the command line's words: '--diameter: must be positive, got -3 mm'."""
    parameter = BY_NAME.get(error.field)
    option = parameter.option if parameter else "--" + error.field.replace("_", "-")
    if isinstance(error, MissingParameter):
        return f"missing {option} (or {_job_key(error.field)!r} in a --job file)"
    if error.where:
        return f"{error.where}: {_job_key(error.field)}: {error.detail}"
    return f"{option}: {error.detail}"


#: What a MissingParameter says in label_words.
REQUIRED_WORDS = "is required: the toolpath file does not give it"


def label_words(error, label=None, detail=None):
    """A ParameterError in plain words for the GUI: 'Tool diameter must be positive, got -3 mm.' label, detail:
    functions giving the words shown for the parameter's label and for what is wrong (a translation; without
    them, as they are)."""
    parameter = BY_NAME.get(error.field)
    words = parameter.label if parameter else error.field.replace("_", " ")
    words = label(words) if label and parameter else words
    what = REQUIRED_WORDS if isinstance(error, MissingParameter) else error.detail
    what = detail(what) if detail else what
    text = f"{words[:1].upper()}{words[1:]} {what}"
    return f"{error.where}: {text}." if error.where else f"{text}."


def _job_key(name):
    """The job file's key of parameter `name` (φ start and end are one pair, phi_range)."""
    return {"phi_start": "phi_range", "phi_end": "phi_range", "immersion_start": "immersion",
            "immersion_end": "immersion"}.get(name, name)


def check_pairs(values):
    """Cross-checks of checked `values` {name: value}: φ end not below φ start, at most MAX_ANGLES
    angles, the corner radius at most half the diameter, immersion start below its end. ParameterError
    naming the later field."""
    start, end, step = (values.get(name) for name in ("phi_start", "phi_end", "phi_step"))
    if start is not None and end is not None:
        if end < start:
            raise ParameterError("phi_end", f"must not be below the first rotation angle {start:g}°, got {end:g}°")
        if step is not None and (end - start) / step > MAX_ANGLES:
            raise ParameterError("phi_step", f"gives more than {MAX_ANGLES:,} angles from {start:g}° to {end:g}°; "
                                             "take a larger step")
    diameter, corner = values.get("diameter"), values.get("corner_radius")
    if diameter is not None and corner is not None and corner > 0.5 * diameter:
        raise ParameterError("corner_radius", f"must be at most half the tool diameter ({0.5 * diameter:g} mm: a "
                                              f"ball-end mill), got {corner:g} mm")
    low, high = values.get("immersion_start"), values.get("immersion_end")
    if low is not None and high is not None and not low < high:
        raise ParameterError("immersion_end", f"must be above the start of immersion {low:g}°, got {high:g}°")
