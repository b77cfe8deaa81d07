"""The ABM engine: pure numpy (and scipy), never FreeCAD.

Inputs are validated dataclasses (:class:`Tool`, :class:`Staircase`, :class:`Toolpath`,
:class:`CutSettings`); :func:`engage` returns an :class:`Engagement` of arrays over
CL points × rotation angles; :func:`flute_engagement` a :class:`FluteEngagement` of every
flute's helical edge (docs/HELIX.md). Lengths in mm, angles in degrees.
"""

from .engagement import CASES, SURFACES, Engagement, cut_thickness, edge_lines, engage, segment_letter
from .frames import angles_to_axis, axis_to_angles, rotation_matrix
from .helix import FluteEngagement, flute_engagement
from .model import CutSettings, Staircase, Tool, Toolpath
from .polynomials import k_coefficients
from .walls import Wall
from .zmap import ZMap, tool_floor, zmap_engage
from .interval_engagement import engagement_from_intervals
from .intervals import EdgeIntervals
from .terraced import engage_terraced, terraced_intervals
from .terraced_model import Loop, PlanArc, PlanLine, PlanSpline, Slab, TerracedStock
from .terraced_staircase import staircase_as_terraced

__all__ = [
    "CASES", "SURFACES", "CutSettings", "Engagement", "FluteEngagement", "Staircase", "Tool", "Toolpath", "Wall",
    "angles_to_axis", "axis_to_angles", "cut_thickness", "edge_lines", "engage", "flute_engagement", "k_coefficients",
    "rotation_matrix", "segment_letter", "ZMap", "tool_floor", "zmap_engage",
    "EdgeIntervals", "engagement_from_intervals", "engage_terraced", "terraced_intervals", "Loop", "PlanArc",
    "PlanLine", "PlanSpline", "Slab", "TerracedStock", "staircase_as_terraced",
]
