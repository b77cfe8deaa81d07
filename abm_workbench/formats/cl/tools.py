"""Cutting tools as CL files describe them: kind and sizes (mm), and which records said so.

- APT ``CUTTER/d[,r,e,f,a,b,h]``: diameter d, corner radius r, (e, f) the corner centre, a the
  tip (bottom) angle, b the side (taper) angle, h the tool's height. h is NOT the flute length.
  A tip angle with no corner radius is a pointed tool (a drill); a side angle makes the tool
  tapered; a corner radius above half the diameter is a tapered ball (its ball is wider than the
  diameter written).
- NX ``TLDATA/MILL,d,r,length,taper,tip[,...]``: diameter and lower corner radius (the length
  is the tool's, not the flutes'), a taper angle; ``TLDATA/DRILL``, ``TLDATA/TURN`` (and GROOVE,
  THREAD) name drills and turning tools.
- CATIA ``TOOLNO/n,KIND,...``: the kind word (MILL, DRILL, TAP, TURN ...); ``TURRET`` (a lathe's).
- Creo's comment ``$$-> CUTTER / d`` (the only place Creo writes the diameter).
- SOLIDWORKS CAM's ``CSI_SET_FLUTE_LENGTH/l``: the flute length.
- A kind word in ``LOADTL`` / ``LOAD/TOOL`` or ``TLDATA`` (MILL, DRILL, TAP, BORE, REAM, TURN...).
- The tool's name where a file writes one (SOLIDWORKS CAM ``INSERT/[HOLDER=…] 6.0mm JOBBER DRILL``,
  CATIA ``TPRINT/T1 End Mill D 8``, NX ``TOOL PATH/op,TOOL,SPOT_DRILL_10``): words such as TAP,
  COUNTERSINK, SPOT DRILL, CENTERDRILL, REAMER, CHAMFER, GROOVING name the kind (:func:`kind_of_name`).

A mill's kind follows from its corner radius: 0 (or none given) flat-end, half the diameter
ball, anything between bull-nose. Only mills are milled; every other kind is named and never
computed as one.
"""

import re
from dataclasses import dataclass, replace
from typing import Optional

#: Kinds of tool an operation may have.
KINDS = ("flat", "ball", "bull-nose", "tapered", "saw", "drill", "spot drill", "countersink", "reamer", "boring bar",
         "tap", "thread mill", "turning", "grooving", "probe", "unknown")
#: The kinds that are milling tools, the engine's (flat-end, bull-nose, ball), the tapered ones and slitting saws.
MILL_KINDS = ("flat", "ball", "bull-nose", "tapered", "saw")
#: Words naming a kind of tool in LOADTL, LOAD/TOOL, TOOLNO and TLDATA records.
KIND_WORDS = {
    "DRILL": "drill", "CDRILL": "spot drill", "SPOT": "spot drill", "CSINK": "countersink", "CBORE": "boring bar",
    "REAM": "reamer", "BORE": "boring bar", "TAP": "tap", "TURN": "turning", "GROOVE": "grooving",
    "THREAD": "turning", "LATHE": "turning",
}
#: Words of a tool's name that name its kind, the more specific first (upper-case name, regex, kind).
_NAME_WORDS = (
    (r"THREAD\s*MILL", "thread mill"), (r"\bTAP\b|TAPPING|\bM\d+(\.\d+)?\s*X\s*\d", "tap"),
    (r"COUNTER\s*SINK|\bC\s*SINK|\bCSK\b", "countersink"),
    (r"SPOT\s*DRILL|CENTER\s*DRILL|CENTRE\s*DRILL|CENTERDRILL|CENTREDRILL|\bNC\s*DRILL", "spot drill"),
    (r"\bREAM", "reamer"), (r"BORING\s*BAR|\bBORE\b", "boring bar"), (r"GROOV", "grooving"),
    (r"TURNING|\bTURN\b|\bINSERT\b.*\b(CNMG|DNMG|VNMG|TNMG|WNMG)", "turning"),
    (r"CHAMFER|ENGRAV|TAPER|DOVETAIL", "tapered"), (r"\bDRILL", "drill"),
)
_NAMES = {"flat": "flat-end mill", "ball": "ball mill", "bull-nose": "bull-nose mill", "tapered": "tapered mill",
          "saw": "slitting saw", "probe": "probe", "drill": "drill", "spot drill": "spot drill",
          "countersink": "countersink", "reamer": "reamer", "boring bar": "boring bar", "tap": "tap",
          "thread mill": "thread mill", "turning": "turning tool", "grooving": "grooving tool",
          "unknown": "tool of unknown kind"}


@dataclass(frozen=True)
class ToolSpec:
    """A tool: kind (one of KINDS), diameter, corner_radius and flute_length in mm or None, and
    the records that gave them (``"WORD line N"`` strings, file order); unit: the length unit its
    sizes were written in ("mm" or "inch"; they are given here in mm); name: its name as the file
    writes it, or ""; length: the tool's whole length (mm) where the file gives it (APT CUTTER's
    height, NX TLDATA's length), else None; flutes: its number of flutes where the file gives it (a
    FreeCAD toolbit's Flutes), else None."""

    kind: str = "unknown"
    diameter: Optional[float] = None
    corner_radius: Optional[float] = None
    flute_length: Optional[float] = None
    records: tuple = ()
    unit: str = "mm"
    name: str = ""
    length: Optional[float] = None
    flutes: Optional[int] = None

    @property
    def milling(self):
        """Whether the tool is a milling tool (or of unknown kind, whose sizes a user may give)."""
        return self.kind in MILL_KINDS or self.kind == "unknown"

    def describe(self):
        """Plain words with units: ``"ball mill D6 R3 mm"``, ``"flat-end mill D10.0076 mm (0.394 in)"``,
        ``"drill D5 mm"``."""
        text = _NAMES[self.kind]
        if self.diameter is not None:
            sizes = [f"D{self.diameter:g}"]
            if self.corner_radius and self.kind in ("ball", "bull-nose", "tapered"):
                sizes.append(f"R{self.corner_radius:g}")
            text += " " + " ".join(sizes) + " mm"
            if self.unit == "inch":
                text += " (" + " ".join(s[0] + f"{float(s[1:]) / 25.4:.4g}" for s in sizes) + " in)"
        return text

    def with_flute_length(self, length, source):
        """This tool with flute length `length` mm, given by record `source`."""
        return replace(self, flute_length=length, records=self.records + (source,))

    def with_kind(self, kind, source):
        """This tool of kind `kind` (a drill, tap or turning tool named by a record)."""
        return replace(self, kind=kind, records=self.records + (source,))

    def named(self, name, source):
        """This tool with its name `name`, and the kind the name says where it names one a mill's
        sizes cannot tell apart (a tap, a countersink, a spot drill...)."""
        kind = kind_of_name(name)
        if kind is None or kind == self.kind or self.kind in ("turning", "grooving"):
            return replace(self, name=name)
        return replace(self, name=name, kind=kind, records=self.records + (source,))

    def same_tool(self, other):
        """Whether `other` describes this tool (kind and sizes; a flute length only one of them gives
        does not make another tool)."""
        lengths = (self.flute_length, other.flute_length)
        return ((self.kind, self.diameter, self.corner_radius) == (other.kind, other.diameter, other.corner_radius)
                and (None in lengths or lengths[0] == lengths[1]))


def kind_of_name(name):
    """The kind a tool's name says (``"M6x1 TAP"`` -> "tap"), or None for a name that names none
    (a mill's, or no name)."""
    text = " ".join(str(name).upper().replace("_", " ").replace("-", " ").split())
    for pattern, kind in _NAME_WORDS:
        if re.search(pattern, text):
            return kind
    return None


def mill(diameter, radius, source, kind_word=None, *, tip_angle=0.0, side_angle=0.0, unit="mm", length=None):
    """The ToolSpec of a mill of `diameter` and corner `radius` (mm), or of the kind `kind_word` names.

    tip_angle (deg): a pointed tool's (a drill) when there is no corner radius; side_angle (deg):
    a tapered tool. A corner radius above half the diameter: a tapered ball.
    """
    kind = KIND_WORDS.get(kind_word or "")
    if kind is None:
        if side_angle or (radius and radius > diameter / 2.0 * (1.0 + 1e-6)):
            kind = "tapered"
        elif not radius and tip_angle:
            kind = "drill"
        elif not radius:
            kind = "flat"
        elif abs(radius - diameter / 2.0) <= 1e-6 * diameter:
            kind = "ball"
        else:
            kind = "bull-nose"
    return ToolSpec(kind, diameter, radius or 0.0, None, (source,), unit, length=length)
