"""Length, feed and spindle units of CL files, and their conversion to mm, mm/min, mm/rev, rpm.

A CL file without a units record is in mm (CAM systems write ``UNITS/INCHES`` when they are
not). Feeds: ``MMPM`` (mm/min), ``MMPR`` (mm/rev), ``IPM`` (inch/min), ``IPR`` (inch/rev); a
FEDRAT without a unit word is per minute in the file's length unit. Surface speeds: ``SMM``
(m/min) and ``SFM`` (ft/min), turned into rpm with the tool diameter.
"""

import math

MM_PER_INCH = 25.4
#: Length unit words of UNITS/ and UNIT/ -> (the name reported, mm per unit).
LENGTH_UNITS = {"MM": ("mm", 1.0), "MILLIMETERS": ("mm", 1.0), "INCHES": ("inch", MM_PER_INCH),
                "INCH": ("inch", MM_PER_INCH)}
#: Feed unit words -> (per revolution?, mm per unit of length).
FEED_UNITS = {"MMPM": (False, 1.0), "MMPR": (True, 1.0), "IPM": (False, MM_PER_INCH), "IPR": (True, MM_PER_INCH)}
#: Surface speed words -> mm per unit of surface length.
SURFACE_SPEEDS = {"SMM": 1000.0, "SFM": 12.0 * MM_PER_INCH}


def feed_to_mm(value, unit):
    """(feed in mm/min or mm/rev, "MMPM" or "MMPR") of `value` given in the feed unit word `unit`."""
    per_rev, scale = FEED_UNITS[unit]
    return value * scale, "MMPR" if per_rev else "MMPM"


def feed_from_mm(value, unit):
    """The feed `value` (mm/min or mm/rev) in the file's feed unit word `unit` (same kind)."""
    return value / FEED_UNITS[unit][1]


def surface_speed_rpm(speed, word, diameter):
    """Spindle speed (rpm) of a surface `speed` in `word` ("SMM" or "SFM") for a tool of `diameter` mm."""
    return speed * SURFACE_SPEEDS[word] / (math.pi * diameter)
