"""Cutting tools as CL files describe them: kind and sizes (mm), and which records said so.

- APT ``CUTTER/d[,r,e,f,a,b,h]``: diameter d, corner radius r, (e, f) the corner centre, a, b
  the side and bottom angles, h the tool's height. h is NOT the flute length.
- NX ``TLDATA/MILL,d,r,length,taper,tip[,...]``: diameter and lower corner radius (the length
  is the tool's, not the flutes'); ``TLDATA/DRILL``, ``TLDATA/TURN`` (and GROOVE, THREAD) name
  drills and turning tools.
- Creo's comment ``$$-> CUTTER / d`` (the only place Creo writes the diameter).
- SOLIDWORKS CAM's ``CSI_SET_FLUTE_LENGTH/l``: the flute length.
- A kind word in ``LOADTL`` / ``LOAD/TOOL`` or ``TLDATA`` (MILL, DRILL, TAP, BORE, REAM, TURN...).

A mill's kind follows from its corner radius: 0 (or none given) flat-end, half the diameter
ball, anything between bull-nose.
"""

from dataclasses import dataclass, replace
from typing import Optional

#: Kinds of tool an operation may have.
KINDS = ("flat", "ball", "bull-nose", "drill", "tap", "turning", "unknown")
#: Words naming a kind of tool in LOADTL, LOAD/TOOL and TLDATA records.
KIND_WORDS = {
    "DRILL": "drill", "CDRILL": "drill", "SPOT": "drill", "CSINK": "drill", "CBORE": "drill", "REAM": "drill",
    "BORE": "drill", "TAP": "tap", "TURN": "turning", "GROOVE": "turning", "THREAD": "turning", "LATHE": "turning",
}
_NAMES = {"flat": "flat-end mill", "ball": "ball mill", "bull-nose": "bull-nose mill", "drill": "drill",
          "tap": "tap", "turning": "turning tool", "unknown": "tool of unknown kind"}


@dataclass(frozen=True)
class ToolSpec:
    """A tool: kind (one of KINDS), diameter, corner_radius and flute_length in mm or None, and
    the records that gave them (``"WORD line N"`` strings, file order)."""

    kind: str = "unknown"
    diameter: Optional[float] = None
    corner_radius: Optional[float] = None
    flute_length: Optional[float] = None
    records: tuple = ()

    def describe(self):
        """Plain words: ``"ball mill D6 R3"``, ``"flat-end mill D10"``, ``"drill D5"``."""
        text = _NAMES[self.kind]
        if self.diameter is not None:
            text += f" D{self.diameter:g}"
        if self.corner_radius and self.kind in ("ball", "bull-nose"):
            text += f" R{self.corner_radius:g}"
        return text

    def with_flute_length(self, length, source):
        """This tool with flute length `length` mm, given by record `source`."""
        return replace(self, flute_length=length, records=self.records + (source,))

    def with_kind(self, kind, source):
        """This tool of kind `kind` (a drill, tap or turning tool named by a record)."""
        return replace(self, kind=kind, records=self.records + (source,))


def mill(diameter, radius, source, kind_word=None):
    """The ToolSpec of a mill of `diameter` and corner `radius` (mm), or of the kind `kind_word` names."""
    kind = KIND_WORDS.get(kind_word or "")
    if kind is None:
        if not radius:
            kind = "flat"
        elif abs(radius - diameter / 2.0) <= 1e-6 * diameter:
            kind = "ball"
        else:
            kind = "bull-nose"
    return ToolSpec(kind, diameter, radius or 0.0, None, (source,))
