"""Face colours of the engaged cutter surface: by UEP surface of the segment, or by a quantity.

The engagement object's Shape is a compound with one child per CL point and engagement
segment (``features.engagement.engaged_surface_parts``); a segment over k angles φ is a ruled
surface of k − 1 faces, face i between the angles of rows i and i + 1 (checked for model test
1: all 9315 face centres lie between their LEP and UEP points). :func:`face_map` rebuilds that
correspondence from the results, without building geometry. Colours are RGB in 0..1.

ColourBy choices (:data:`COLOUR_BY`):

- ``segment``: the colour of the segment's UEP surface (``report.colours.SURFACE_COLOURS``);
- ``length``: length of cut (mm), mean of the face's two angles, on a colour map;
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
class FaceMap:
    """Per face of the engagement's Shape (n faces): cl (n,) CL index, rows (n, 2) the φ indices
    of its two edges (equal for a face standing for a whole segment), surface (n,) UEP surface name."""

    cl: np.ndarray
    rows: np.ndarray
    surface: np.ndarray


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


def face_map(result, shape):
    """The FaceMap of `shape` (the engagement object's Shape) for the Engagement `result`, or None
    when they do not match (the Shape is empty or from other results)."""
    children = shape.childShapes() if not shape.isNull() else []
    parts = []  # (cl, rows, surface) per child of the compound
    for cl in range(result.shape[0]):
        for index, segment in enumerate(result.segments(cl)):
            rows = np.flatnonzero(result.segment[cl] == index)
            if len(rows) == 1 and np.linalg.norm(result.uep_xyz[cl, rows[0]] - result.lep_xyz[cl, rows[0]]) <= 1e-9:
                continue  # a segment of zero length has no shape
            parts.append((cl, rows, segment["surface"]))
    if len(parts) != len(children):
        return None
    cls, pairs, surfaces = [], [], []
    for (cl, rows, surface), child in zip(parts, children):
        count = len(child.Faces)
        if count == len(rows) - 1:
            pairs.append(np.column_stack([rows[:-1], rows[1:]]))
        else:  # OCC refused the ruling (the two curves stand in) or a line: the segment as a whole
            pairs.append(np.tile([rows[0], rows[-1]], (count, 1)))
        cls += [cl] * count
        surfaces += [surface] * count
    if len(cls) != len(shape.Faces):
        return None
    rows = np.concatenate(pairs) if pairs else np.zeros((0, 2), dtype=int)
    return FaceMap(np.array(cls, dtype=int), rows.astype(int), np.array(surfaces, dtype=object))


def face_colours(result, faces: FaceMap, colour_by, forces=None, colour_map=COLOUR_MAP):
    """(colours (n, 3) RGB 0..1, Legend) of the faces for `colour_by` (a COLOUR_BY value).

    forces: the engagement's forces (PassForces or Forces), needed for ``force``; ValueError without.
    colour_map: the matplotlib colour map of the quantities.
    """
    from ..report.colours import SURFACE_COLOURS

    if colour_by not in COLOUR_BY:
        raise ValueError(f"colour_by must be one of {COLOUR_BY}, got {colour_by!r}")
    if colour_by == "segment":
        colours = np.array([SURFACE_COLOURS.get(name, SURFACE_COLOURS["none"]) for name in faces.surface],
                           dtype=float).reshape(-1, 3)
        shown = [name for name in SURFACE_COLOURS if name in set(faces.surface)]
        return colours, Legend("segment", tuple((name, SURFACE_COLOURS[name]) for name in shown))
    attribute, label, unit = QUANTITIES[colour_by]
    if colour_by == "force" and forces is None:
        raise ValueError("colour by force needs the engagement's forces: turn Forces on and recompute")
    values = face_values(getattr(forces if colour_by == "force" else result, attribute), faces)
    low, high = (float(values.min()), float(values.max())) if values.size else (0.0, 0.0)
    return quantity_colours(values, low, high, colour_map), Legend(colour_by, (), label, unit, low, high, colour_map)


def face_values(quantity, faces: FaceMap):
    """(n,) value of an (m, p) quantity per face: the mean over the face's two angles."""
    quantity = np.asarray(quantity, dtype=float)
    return 0.5 * (quantity[faces.cl, faces.rows[:, 0]] + quantity[faces.cl, faces.rows[:, 1]])


def quantity_colours(values, low, high, colour_map=COLOUR_MAP):
    """(n, 3) RGB of `values` on the matplotlib colour map `colour_map`, low..high mapped to its two ends."""
    from matplotlib import colormaps

    span = high - low
    fraction = (np.asarray(values, dtype=float) - low) / span if span > 0 else np.zeros(np.shape(values))
    return colormaps[colour_map](np.clip(fraction, 0.0, 1.0))[..., :3]
