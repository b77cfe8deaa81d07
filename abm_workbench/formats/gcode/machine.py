"""Five-axis machines: the kinematics a machine file names, and where a block puts the tool in the part.

A machine file is a JSON object (lengths in mm, in the machine coordinates that X Y Z are written
in once the work offset is added; angles in degrees):

``{"kinematics": "xyzac-trt", "pivot": [x, y, z], "c_offset": [dx, dy, dz]}``
    A tilting table turning about the machine's X axis (A) carrying a rotary table turning about
    its own Z axis (C), LinuxCNC's ``xyzac-trt``. `pivot` is a point of the A axis; `c_offset`
    goes from `pivot` to a point of the C axis with A at 0 (default 0: the axes meet at `pivot`).
``{"kinematics": "xyzbc-trt", "pivot": …, "c_offset": …}``
    The same with the tilt about the machine's Y axis (B), LinuxCNC's ``xyzbc-trt``.
``{"kinematics": "xyzbc-ht", "pivot_length": P, "c_axis": [x, y], "tool_length": L}``
    A head-table machine: B tilts the spindle head about a line along Y, P mm above the spindle
    nose (where tool lengths are measured from); C turns the table about a line along Z through
    (x, y). `tool_length` is the length taken when the tool table gives none.

With the tool centre point control on (TCP: ``G43.4``, ``M128``, ``TRAORI``, ``TCPM``), X Y Z are the
tool tip in the part frame and the rotary words only give the tool axis there:
Rz(−C)·Rx(−A)·(0, 0, 1) on xyzac-trt, Rz(−C)·Ry(−B)·(0, 0, 1) on xyzbc-trt (the table turns the
part, so the axis turns the other way in it), Rz(−C)·Ry(B)·(0, 0, 1) on xyzbc-ht (the head turns
the tool, the table the part). The offsets are not needed then.

With TCP off, X Y Z are the machine's own axes: on a table-table machine, where the tool tip is
in the machine (the tool stays along +Z); on the head-table machine, where the tip would be with B
at 0 (a three-axis machine's tool length compensation), the tip being P + L from the head's pivot
along the tilted axis. The part frame is the table's frame, which is the machine's with every
rotary axis at 0; the tip is taken into it through the turns of the tables about their axes.
Rotations are right-handed about +X, +Y, +Z (Rx, Ry, Rz).
"""

import math
import os
from dataclasses import dataclass
from typing import Optional

import numpy as np

from ...errors import InputError
from .. import check_keys, json_number, load_json_object

#: The kinematics read, with their rotary axes (tilt, turn).
KINEMATICS = {"xyzac-trt": ("A", "C"), "xyzbc-trt": ("B", "C"), "xyzbc-ht": ("B", "C")}
_KEYS = {"xyzac-trt": ("pivot", "c_offset"), "xyzbc-trt": ("pivot", "c_offset"),
         "xyzbc-ht": ("pivot_length", "c_axis", "tool_length")}
_Z = np.array([0.0, 0.0, 1.0])


def turn(axis, degrees):
    """(3, 3) right-handed rotation by `degrees` about machine axis "X", "Y" or "Z"."""
    index = "XYZ".index(axis)
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    j, k = (index + 1) % 3, (index + 2) % 3
    rotation = np.eye(3)
    rotation[j, j], rotation[j, k], rotation[k, j], rotation[k, k] = c, -s, s, c
    return rotation


@dataclass(frozen=True)
class Machine:
    """A five-axis machine (module docstring): kinematics (a key of KINEMATICS), pivot and c_offset
    (3,) mm (table-table), pivot_length mm and c_axis (2,) mm (head-table), tool_length mm or None,
    source: the machine file."""

    kinematics: str
    pivot: np.ndarray
    c_offset: np.ndarray
    pivot_length: float
    c_axis: np.ndarray
    tool_length: Optional[float]
    source: str

    @property
    def rotary(self):
        """The rotary axis letters, tilt first: ("A", "C") or ("B", "C")."""
        return KINEMATICS[self.kinematics]

    @property
    def needs_tool_length(self):
        """Whether TCP-off blocks need the tool's length (the head turns the tool about a pivot)."""
        return self.kinematics == "xyzbc-ht"

    def axis(self, angles):
        """(3,) unit tool axis in the part frame for `angles` {letter: degrees}."""
        tilt, spin = self.rotary
        tilt_axis = "X" if tilt == "A" else "Y"
        sign = 1.0 if self.kinematics == "xyzbc-ht" else -1.0
        return turn("Z", -angles[spin]) @ turn(tilt_axis, sign * angles[tilt]) @ _Z

    def pose(self, angles, tcp, tool_length=None):
        """(R (3, 3), t (3,), axis (3,)): tip in the part frame = R @ p + t for X Y Z `p` (mm, work offset
        added) of a block at `angles` {letter: degrees}, TCP on or off; axis the unit tool axis there.
        tool_length: mm, the head-table machine's with TCP off."""
        axis = self.axis(angles)
        if tcp:
            return np.eye(3), np.zeros(3), axis
        tilt, spin = self.rotary
        table = turn("Z", -angles[spin])
        if self.kinematics == "xyzbc-ht":
            centre = np.array([self.c_axis[0], self.c_axis[1], 0.0])
            reach = self.pivot_length + tool_length
            head = turn("Y", angles[tilt]) @ _Z
            return table, table @ (reach * (_Z - head) - centre) + centre, axis
        tilted = turn("X" if tilt == "A" else "Y", -angles[tilt])
        rotation = table @ tilted
        c_point = self.pivot + self.c_offset
        return rotation, table @ (self.pivot - tilted @ self.pivot - c_point) + c_point, axis


def load_machine(path):
    """The :class:`Machine` of the machine file at `path`; InputError naming the file and the key."""
    name = os.fspath(path)
    data = load_json_object(name)
    if "kinematics" not in data:
        raise InputError(f"{name}: missing key 'kinematics' (one of {', '.join(KINEMATICS)})")
    kind = data["kinematics"]
    if not isinstance(kind, str) or kind not in KINEMATICS:
        raise InputError(f"{name}: kinematics: expected one of {', '.join(KINEMATICS)}, got {kind!r}")
    check_keys(data, ("kinematics",), _KEYS[kind], name)
    pivot = _vector(data, "pivot", 3, name)
    c_offset = _vector(data, "c_offset", 3, name)
    c_axis = _vector(data, "c_axis", 2, name)
    pivot_length = json_number(data.get("pivot_length", 0.0), f"{name}: pivot_length")
    tool_length = data.get("tool_length")
    if tool_length is not None:
        tool_length = json_number(tool_length, f"{name}: tool_length")
        if tool_length < 0.0:
            raise InputError(f"{name}: tool_length: must not be negative, got {tool_length:g}")
    return Machine(kind, pivot, c_offset, pivot_length, c_axis, tool_length, name)


def _vector(data, key, size, name):
    """(size,) floats of `data[key]` (zeros when absent); InputError unless a list of `size` numbers."""
    value = data.get(key, [0.0] * size)
    if not isinstance(value, list) or len(value) != size:
        raise InputError(f"{name}: {key}: must be a list of {size} numbers (mm)")
    return np.array([json_number(item, f"{name}: {key}[{index}]") for index, item in enumerate(value)])
