"""A toolpath with a feed per CL point as an APT / CL file, or as a toolpath CSV with feeds.

APT: ``UNITS/MM``, ``CUTTER/d`` (diameter, mm; APT's seventh CUTTER number would be the
tool's height, not its flute length), ``CSI_SET_FLUTE_LENGTH/h`` (flute length, mm, the record
SOLIDWORKS CAM writes it in), ``SPINDL/RPM,n,CLW`` when the speed is known, ``MULTAX/ON``, then per CL point a
``FEDRAT/MMPM,F`` (mm/min, F = f_z·Z·n; ``FEDRAT/MMPR,F`` in mm/rev, F = f_z·Z, without a
spindle speed) whenever the feed changes, and ``GOTO/x,y,z,i,j,k`` (the CL point and the unit
tool axis); ``END``. Every number is written in the shortest form that reads back as the
same float, so :func:`abm_workbench.formats.apt.load_apt` gives back the same CL points,
feeds and tool sizes. A CL program read by :mod:`abm_workbench.formats.cl` is written back with
only one operation's feeds changed by :func:`abm_workbench.formats.cl.rewrite.write_rescheduled_program`.

CSV: the toolpath CSV columns ``x,y,z,i,j,k`` (mm, the unit tool axis in the part frame),
``feed_x,feed_y,feed_z`` (the feed direction in plan view each CL point's frame is turned to),
``inclination`` (deg) where the toolpath has one per CL point, and ``feed_per_tooth`` (mm), plus
``feed_mm_min`` when the spindle speed is known; the toolpath reader accepts and skips the feed
columns.

Files are written whole or not at all (:func:`abm_workbench.formats.replacing`).
"""

import os

import numpy as np

from . import replacing


def _number(value):
    """Shortest text that reads back as the float `value` (no exponent for ordinary sizes)."""
    text = repr(float(value) + 0.0)
    return text[:-2] if text.endswith(".0") else text


def apt_text(toolpath, feed_per_tooth, *, flutes, diameter, flute_length, spindle_rpm=None, comment=""):
    """APT text of `toolpath` (m CL points) with feed per tooth (m,) mm (see the module docstring)."""
    feed = np.broadcast_to(np.asarray(feed_per_tooth, dtype=float), (len(toolpath),))
    if not np.isfinite(feed).all() or (feed <= 0.0).any():
        raise ValueError("every feed per tooth written to an APT file must be positive")
    per = flutes * (1.0 if spindle_rpm is None else float(spindle_rpm))
    unit = "MMPR" if spindle_rpm is None else "MMPM"
    axes = toolpath.axes
    lines = [f"$$ {line}" for line in comment.splitlines()]
    lines += ["UNITS/MM", f"CUTTER/{_number(diameter)}", f"CSI_SET_FLUTE_LENGTH/{_number(flute_length)}"]
    if spindle_rpm is not None:
        lines.append(f"SPINDL/RPM,{_number(spindle_rpm)},CLW")
    lines.append("MULTAX/ON")
    previous = None
    for point, axis, rate in zip(toolpath.cl, axes, feed * per):
        if rate != previous:
            lines.append(f"FEDRAT/{unit},{_number(rate)}")
            previous = rate
        lines.append("GOTO/" + ",".join(_number(v) for v in (*point, *axis)))
    lines.append("END")
    return "\n".join(lines) + "\n"


def toolpath_feed_csv_text(toolpath, feed_per_tooth, *, flutes, spindle_rpm=None):
    """Toolpath CSV text with feed columns (see the module docstring)."""
    feed = np.broadcast_to(np.asarray(feed_per_tooth, dtype=float), (len(toolpath),))
    turn = np.radians(toolpath.alpha)
    header = ["x", "y", "z", "i", "j", "k", "feed_x", "feed_y", "feed_z"]
    columns = [*toolpath.cl.T, *toolpath.axes.T, np.cos(turn), np.sin(turn), np.zeros(len(toolpath))]
    if toolpath.inclination is not None:
        header.append("inclination")
        columns.append(toolpath.inclination)
    header.append("feed_per_tooth")
    columns.append(feed)
    if spindle_rpm is not None:
        header.append("feed_mm_min")
        columns.append(feed * flutes * float(spindle_rpm))
    rows = [",".join(_number(v) for v in row) for row in zip(*columns)]
    return "\n".join([",".join(header), *rows]) + "\n"


def write_feed_toolpath(path, toolpath, feed_per_tooth, *, flutes, diameter, flute_length, spindle_rpm=None,
                        comment=""):
    """Write `toolpath` with its feeds to `path`, atomically: APT for .apt / .cls, else CSV."""
    name = os.fspath(path)
    if os.path.splitext(name)[1].lower() in (".apt", ".cls"):
        text = apt_text(toolpath, feed_per_tooth, flutes=flutes, diameter=diameter, flute_length=flute_length,
                        spindle_rpm=spindle_rpm, comment=comment)
    else:
        text = toolpath_feed_csv_text(toolpath, feed_per_tooth, flutes=flutes, spindle_rpm=spindle_rpm)
    with replacing(name) as (temporary,):
        with open(temporary, "w", encoding="utf-8", newline="") as file:
            file.write(text)
    return name
