"""Colours shared by the report's figures and the annotated FreeCAD document (RGB, 0..1).

Pure data: no matplotlib, no FreeCAD.
"""

#: Per kind of UEP surface (engine.SURFACES).
SURFACE_COLOURS = {
    "none": (0.6, 0.6, 0.6),
    "top": (0.12, 0.47, 0.71),
    "straight_wall": (1.0, 0.5, 0.05),
    "curved_wall": (0.84, 0.15, 0.16),
    "flute_end": (0.58, 0.4, 0.74),
    "stock_side": (0.55, 0.34, 0.29),
    "immersion_end": (0.17, 0.63, 0.17),
    "bottom": (0.09, 0.75, 0.81),
    "flute_start": (0.74, 0.74, 0.13),
    "machined": (0.89, 0.47, 0.76),
}

#: Per engagement segment, by index (A, B, C, …), repeating after ten.
SEGMENT_COLOURS = (
    (0.12, 0.47, 0.71), (1.0, 0.5, 0.05), (0.17, 0.63, 0.17), (0.84, 0.15, 0.16), (0.58, 0.4, 0.74),
    (0.55, 0.34, 0.29), (0.89, 0.47, 0.76), (0.5, 0.5, 0.5), (0.74, 0.74, 0.13), (0.09, 0.75, 0.81),
)


def segment_colour(index):
    """RGB of segment `index` (0 = A)."""
    return SEGMENT_COLOURS[int(index) % len(SEGMENT_COLOURS)]
