"""The tool of a CAM tool controller as a ToolSpec: its kind, sizes (mm) and flutes.

A toolbit (FreeCAD 0.19 on) names its shape (``ShapeName``, else the file of ``BitShape``) and
carries the shape's parameters: ``Diameter``, ``CuttingEdgeHeight`` (the flute length), ``Length``
(the whole tool's), ``Flutes`` (0: not given), a bull-nose's ``CornerRadius`` or ``FlatRadius``
(the corner radius is then D/2 − FlatRadius). The shapes FreeCAD ships are read as what they are:

=============== ================  ================ ================
endmill         flat-end mill     ballend          ball mill (R = D/2)
bullnose        bull-nose mill    v-bit, chamfer   tapered mill
drill           drill             thread-mill      thread mill
slittingsaw     slitting saw      probe            probe
=============== ================  ================ ================

Another shape is named by the words of its name (a drill, tap, reamer …: formats.cl.tools'
``kind_of_name``), else of unknown kind, said in a warning. FreeCAD 0.20's legacy tools
(``Path.Tool``, with ``ToolType``) are read alike.
"""

import os

from ..errors import note
from ..formats.cl.tools import ToolSpec, kind_of_name

#: Toolbit shape names -> kinds.
SHAPE_KINDS = {"endmill": "flat", "ballend": "ball", "bullnose": "bull-nose", "v-bit": "tapered",
               "chamfer": "tapered", "drill": "drill", "thread-mill": "thread mill", "slittingsaw": "saw",
               "probe": "probe"}
#: Legacy tool types -> kinds.
LEGACY_KINDS = {"EndMill": "flat", "BallEndMill": "ball", "BullNose": "bull-nose", "ChamferMill": "tapered",
                "Engraver": "tapered", "CornerRound": "tapered", "SlotCutter": "saw", "Drill": "drill",
                "CenterDrill": "spot drill", "CounterSink": "countersink", "CounterBore": "boring bar",
                "Reamer": "reamer", "Tap": "tap"}


def _length(value):
    """mm of a Quantity or a number; None for none or 0."""
    number = float(getattr(value, "Value", value)) if value is not None else 0.0
    return number if number > 0.0 else None


def controller_tool(controller):
    """(ToolSpec, warning or "") of tool controller `controller`'s tool (module docstring)."""
    tool = controller.Tool
    source = f"{controller.Label} (T{controller.ToolNumber})"
    if hasattr(tool, "ToolType"):
        return _legacy_tool(tool, source), ""
    names = getattr(tool, "PropertiesList", ())
    shape = getattr(tool, "ShapeName", "") or os.path.splitext(os.path.basename(getattr(tool, "BitShape", "")))[0]
    kind = SHAPE_KINDS.get(shape.lower()) or kind_of_name(f"{shape} {tool.Label}")
    warning = "" if kind else note(f"{source}: toolbit {tool.Label!r} of shape {shape!r}: a shape the reader does "
                                   "not know; its kind is unknown")
    kind = kind or "unknown"
    diameter = _length(getattr(tool, "Diameter", None))
    radius = {"flat": 0.0, "ball": None if diameter is None else diameter / 2.0}.get(kind)
    if kind == "bull-nose":
        if "CornerRadius" in names:
            radius = _length(tool.CornerRadius)
        elif "FlatRadius" in names and diameter is not None:
            radius = diameter / 2.0 - float(tool.FlatRadius.Value)
    flutes = int(getattr(tool, "Flutes", 0) or 0)
    return ToolSpec(kind, diameter, radius, _length(getattr(tool, "CuttingEdgeHeight", None)),
                    (f"{source} toolbit {tool.Label}",), name=tool.Label,
                    length=_length(getattr(tool, "Length", None)), flutes=flutes if flutes > 0 else None), warning


def _legacy_tool(tool, source):
    """The ToolSpec of a legacy Path.Tool."""
    kind = LEGACY_KINDS.get(str(tool.ToolType)) or kind_of_name(tool.Name) or "unknown"
    diameter = _length(tool.Diameter)
    radius = {"flat": 0.0, "ball": None if diameter is None else diameter / 2.0}.get(kind)
    if kind == "bull-nose":
        radius = _length(tool.CornerRadius)
    return ToolSpec(kind, diameter, radius, _length(tool.CuttingEdgeHeight), (f"{source} tool {tool.Name}",),
                    name=tool.Name, length=_length(getattr(tool, "LengthOffset", None)))
