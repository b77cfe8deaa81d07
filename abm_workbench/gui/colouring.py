"""Colours of the engaged cutter surface: by UEP surface of the segment, or by a quantity.

:func:`instant_colours` colours engaged instants, given by their CL point, φ row and UEP surface
(the engagement's mesh, :mod:`.surface_mesh`, gives each of its vertices its instant's colour).
Colours are RGB in 0..1.

ColourBy choices (:data:`COLOUR_BY`):

- ``segment``: the colour of the segment's UEP surface (``report.colours.SURFACE_COLOURS``);
- ``length``: length of cut (mm) at the instant, on a colour map;
- ``area``: cut area (mm²), likewise;
- ``force``: resultant cutting force |F| (N) per instant, likewise; only for an engagement
  with forces (``EngagementFeature.forces``).
"""

from dataclasses import dataclass

import numpy as np

#: ColourBy choices, and for the quantities: (attribute of the Engagement, or of the forces for
#: force, label, unit).
COLOUR_BY = ("segment", "length", "area", "force")
QUANTITIES = {"length": ("length", "length of cut", "mm"), "area": ("area", "cut area", "mm²"),
              "force": ("resultant", "resultant cutting force", "N")}
#: matplotlib colour map of the quantities, unless told another (the preferences' ColourMap).
COLOUR_MAP = "viridis"
#: Colour of the chosen CL point, in the 3D view and on the dock's plots.
HIGHLIGHT_COLOUR = (1.0, 0.85, 0.0)


@dataclass(frozen=True)
class Legend:
    """What the colours mean. kind: a COLOUR_BY value. entries: [(name, rgb)] for segments.
    label, unit, low, high: the quantity's name, unit and range of the colour map. colour_map: its
    matplotlib name."""

    kind: str
    entries: tuple = ()
    label: str = ""
    unit: str = ""
    low: float = 0.0
    high: float = 0.0
    colour_map: str = COLOUR_MAP


def instant_colours(result, cl, row, surface, colour_by, forces=None, colour_map=COLOUR_MAP):
    """(colours (n, 3) RGB 0..1, Legend) of n engaged instants for `colour_by` (a COLOUR_BY value).

    cl, row: (n,) int, the instants' CL points and φ rows in `result` (an Engagement); surface:
    (n,) str, their UEP surface names (for ``segment``).

    forces: the engagement's forces (PassForces or Forces), needed for ``force``; ValueError without.
    colour_map: the matplotlib colour map of the quantities.
    """
    from ..report.colours import SURFACE_COLOURS

    if colour_by not in COLOUR_BY:
        raise ValueError(f"colour_by must be one of {COLOUR_BY}, got {colour_by!r}")
    if colour_by == "segment":
        names, which = np.unique(np.asarray(surface, dtype=str), return_inverse=True)
        table = np.array([SURFACE_COLOURS.get(name, SURFACE_COLOURS["none"]) for name in names], dtype=float)
        colours = table.reshape(-1, 3)[which.reshape(-1)]
        shown = [name for name in SURFACE_COLOURS if name in set(names)]
        return colours, Legend("segment", tuple((name, SURFACE_COLOURS[name]) for name in shown))
    attribute, label, unit = QUANTITIES[colour_by]
    if colour_by == "force" and forces is None:
        raise ValueError("colour by force needs the engagement's forces: turn Forces on and recompute")
    values = np.asarray(getattr(forces if colour_by == "force" else result, attribute), dtype=float)[cl, row]
    low, high = (float(values.min()), float(values.max())) if values.size else (0.0, 0.0)
    return quantity_colours(values, low, high, colour_map), Legend(colour_by, (), label, unit, low, high, colour_map)


def quantity_colours(values, low, high, colour_map=COLOUR_MAP):
    """(n, 3) RGB of `values` on the matplotlib colour map `colour_map`, low..high mapped to its two ends."""
    from matplotlib import colormaps

    span = high - low
    fraction = (np.asarray(values, dtype=float) - low) / span if span > 0 else np.zeros(np.shape(values))
    return colormaps[colour_map](np.clip(fraction, 0.0, 1.0))[..., :3]
