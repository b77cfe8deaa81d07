"""What reading a program may need besides its own file: a CAM Job's name, tools, machine, work offsets."""

from dataclasses import dataclass
from typing import Optional

from ...errors import InputError


@dataclass(frozen=True)
class ReadOptions:
    """cam_job: the Name or Label of the FreeCAD CAM Job to read from an FCStd (None: its one Job).
    tool_table: the tools of a G-code program's T words, a LinuxCNC tool table or the FreeCAD document
    (FCStd) that posted it (None: none). machine: the machine file (JSON) naming a five-axis program's
    kinematics (None: rotary words are refused). offsets: the work offsets G54–G59.3, a LinuxCNC
    parameter file or JSON (None: all zero). machine_units: "mm" or "inch", the unit of the numbers of a
    LinuxCNC tool table and parameter file, which LinuxCNC keeps in the machine's units (None: not said;
    mm, and a program that switches to inches with such a file is refused). Paths as given
    (docs/GCODE.md)."""

    cam_job: Optional[str] = None
    tool_table: Optional[str] = None
    machine: Optional[str] = None
    offsets: Optional[str] = None
    machine_units: Optional[str] = None

    def check(self, kind, name):
        """InputError naming the option when one is given that file `name` of `kind` ("fcstd", "gcode", "apt",
        "csv") does not take: the CAM Job's name is for a FreeCAD document, the others for G-code."""
        wanted = {"cam_job": ("fcstd",), "tool_table": ("gcode",), "machine": ("gcode",), "offsets": ("gcode",),
                  "machine_units": ("gcode",)}
        words = {"fcstd": "a FreeCAD document (FCStd)", "gcode": "G-code"}
        for option, kinds in wanted.items():
            if getattr(self, option) is not None and kind not in kinds:
                raise InputError(f"{name}: --{option.replace('_', '-')} applies to {words[kinds[0]]}, and this file "
                                 f"is {words.get(kind, 'a CL file or toolpath CSV')}")
