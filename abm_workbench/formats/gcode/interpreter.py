"""The RS-274 interpreter: blocks, in order, into the operations of a program (docs/GCODE.md).

Modal state as LinuxCNC keeps it: units (G20 inch, G21 mm), distance mode (G90, G91) and arc
centres (G90.1, G91.1), plane (G17–G19), motion (G0–G3, the hole cycles G73, G74, G81–G89, G80),
feed mode (G93 inverse time, G94 per minute, G95 per revolution) and F, spindle S (G96 surface
speed, G97 rpm), the tool (T selects, M6 or M61 loads), the work coordinate system (G54–G59.3 with
its offsets, G10 L2 setting one, G53 for one block), the retract plane of the cycles (G98, G99)
and the tool centre point control (G43.4, G43.5, M128, TRAORI, TCPM on; G49, M129, TRAFOOF off).
Each block runs in LinuxCNC's order: feed mode, F, S, T, tool change, spindle, plane, units,
compensation, tool length and TCP, coordinate system, distance modes, retract mode, G10, G28/G30,
then the motion with the block's axis words.

What becomes of the motion: G0 a rapid; G1, G2, G3 cutting CL points, in the part frame (the work
offset added and, with a machine file, the kinematics applied: :mod:`.machine`), each with the
direction of the tool tip's motion arriving at it (a chord, an arc's tangent); a hole cycle a hole
position (its bottom), never a cutting move. A word or code the reader does not know, a move to
an unknown position, an arc that does not fit, a rotary word without a machine file, a tool no
table names: InputError ``file:line: word: reason``.
"""

import math
import re

import numpy as np

from ...errors import InputError
from .. import MAX_ANGLE
from ..cl.tools import ToolSpec
from ..cl.units import MM_PER_INCH, surface_speed_rpm
from . import circles
from .codes import GROUP_OF, IGNORED_M, CodeError, code_text, sorted_words
from .collect import Collector
from .cycles import HOLE_CYCLES, CycleState
from .offsets import SYSTEMS, zero_offsets

_Z = np.array([0.0, 0.0, 1.0])
_BEGIN_OPERATION = re.compile(r"begin operation:\s*(.+)", re.IGNORECASE)


class Interpreter:
    """The modal state of a G-code program and the operations it makes (module docstring).

    source: the program's name in the operations; where(line) the place of a line in messages
    (``"prog.ngc:12"``). tolerance, step: mm, of the arcs' CL points (formats.cl.arcs). tools: a
    {number: ToolSpec} of the tool table (None: none given), tools_source its file. machine: a
    machine.Machine or None. offsets: {system: (6,)} of the work offsets or None (all zero).
    """

    def __init__(self, source, where, tolerance, step, tools=None, tools_source="", machine=None, offsets=None):
        self.source, self.where, self.tolerance, self.step = source, where, float(tolerance), float(step)
        self.tools, self.tools_source, self.machine = tools, tools_source, machine
        self.offsets = {key: np.array(value, dtype=float) for key, value in (offsets or zero_offsets()).items()}
        self.collector = Collector(source)
        self.scale, self.units = 1.0, None
        self.first_inch = None  # the line of the first G20
        self.absolute, self.arc_absolute, self.plane = True, False, 17
        self.motion = None
        self.feed_mode, self.feed = 94.0, math.nan
        self.spindle, self.surface_speed = None, None
        self.selected, self.tool = None, ToolSpec()
        self.position = np.full(3, math.nan)  # X Y Z in the work coordinate system, mm
        self.angles = {"A": 0.0, "B": 0.0, "C": 0.0}  # degrees, as programmed (the offsets' added when used)
        self.system, self.tcp, self.high_retract = "G54", False, True
        self.cycle = CycleState()
        self.ignored, self.warnings, self.warned = {}, [], set()

    # Messages.

    def error(self, line, word, reason):
        """InputError ``where(line): word: reason``."""
        return InputError(f"{self.where(line)}: {word}: {reason}")

    def warn_once(self, key, line, word, message):
        """The warning ``where(line): word: message``, the first time `key` is met."""
        if key not in self.warned:
            self.warned.add(key)
            self.warnings.append(f"{self.where(line)}: {word}: {message}")

    def note_ignored(self, line, word):
        """Count `word` (a code carrying nothing the engine needs) in the ignored table."""
        first, count = self.ignored.get(word, (line, 0))
        self.ignored[word] = (first, count + 1)

    # Blocks.

    def comment(self, line, text):
        """A comment: FreeCAD's posts' ``(begin operation: NAME)`` starts the operation NAME."""
        begun = _BEGIN_OPERATION.fullmatch(text.strip())
        if begun:
            self.collector.boundary(line, begun.group(1).strip())

    def run(self, block):
        """Apply one block (blocks.Block)."""
        for text in block.comments:
            self.comment(block.line, text)
        if block.tcp is not None:
            self.tcp = block.tcp
            return
        if not block.words:
            return
        line = block.line
        try:
            g_codes, m_codes, values = sorted_words(block.words)
        except CodeError as error:
            raise self.error(line, error.word, error.reason) from None
        for code in m_codes:
            if code in IGNORED_M:
                self.note_ignored(line, code_text("M", code))
        if 93.0 in g_codes or 94.0 in g_codes or 95.0 in g_codes:
            self.feed_mode = next(code for code in (93.0, 94.0, 95.0) if code in g_codes)
        self.units_of(g_codes, line)
        if "F" in values:
            self.set_feed(values["F"], line)
        elif self.feed_mode == 93.0:
            self.feed = math.nan  # inverse time: every feed move gives its own F
        if "S" in values:
            self.set_spindle(values["S"].value, g_codes, line)
        if "T" in values:
            self.selected = int(values["T"].value)
        if 6.0 in m_codes or 61.0 in m_codes:
            number = self.selected if 6.0 in m_codes else int(self.word(values, "Q", line, "M61").value)
            self.load_tool(number, line, "M6" if 6.0 in m_codes else "M61")
        self.modes(g_codes, m_codes, values, line)
        if 10.0 in g_codes:
            self.set_offsets(values, line)
            return
        if 28.0 in g_codes or 30.0 in g_codes:
            self.go_home(values, line)
            return
        motion = next((code for code in g_codes if GROUP_OF[code] == "motion"), None)
        if motion == 80.0:
            self.motion = None
            self.cycle.end()
        elif motion is not None:
            if motion in HOLE_CYCLES and self.motion != motion:
                self.cycle.begin(self.position[2])
            self.motion = motion
        axis_words = [letter for letter in "XYZABC" if letter in values]
        if not axis_words:
            if self.motion in (2.0, 3.0) and any(letter in values for letter in "IJKR"):
                raise self.error(line, code_text("G", self.motion), "an arc needs its end: the axis words of its "
                                                                     "plane (the start's, for a full circle)")
            return
        if self.motion is None:
            raise self.error(line, values[axis_words[0]].text, "an axis word with no motion in force (G0, G1, G2, "
                                                               "G3 or a hole cycle)")
        self.move(values, line, machine_frame=53.0 in g_codes)

    def word(self, values, letter, line, code):
        """The word `letter` of the block; InputError naming `code` when the block lacks it."""
        if letter not in values:
            raise self.error(line, code, f"needs a {letter} word")
        return values[letter]

    # Modal settings.

    def units_of(self, g_codes, line):
        """G20 / G21: the length unit of what follows (first_inch: the line of the first G20)."""
        if 20.0 in g_codes and self.first_inch is None:
            self.first_inch = line
        for code, scale, label in ((20.0, MM_PER_INCH, "inch"), (21.0, 1.0, "mm")):
            if code in g_codes:
                self.scale = scale
                self.units = self.units or label

    def set_feed(self, word, line):
        """F: per minute or revolution in the length unit in force, or inverse time (G93); F0 is no feed."""
        if word.value < 0.0:
            raise self.error(line, word.text, "a feed cannot be negative")
        self.feed = word.value * (1.0 if self.feed_mode == 93.0 else self.scale) if word.value else math.nan

    def set_spindle(self, speed, g_codes, line):
        """S: rpm (G97), or a surface speed in m/min or ft/min (G96) made rpm with the tool's diameter."""
        if 96.0 in g_codes or (self.surface_speed is not None and 97.0 not in g_codes):
            unit = "SFM" if self.scale != 1.0 else "SMM"
            self.surface_speed = (speed, unit)
            if self.tool.diameter is None:
                self.warn_once("G96", line, "G96", "a surface speed with a tool of unknown diameter gives no spindle "
                                                   "speed in rpm")
                self.spindle = None
            else:
                self.spindle = surface_speed_rpm(speed, unit, self.tool.diameter)
        else:
            self.spindle = speed if speed > 0.0 else None
        self.collector.spindle(self.spindle)

    def load_tool(self, number, line, code):
        """M6 (the tool T selected) or M61 Q: the tool `number` of the tool table is in the spindle."""
        if number is None:
            raise self.error(line, code, "no T word has selected a tool to load")
        if number == 0:
            tool = ToolSpec()
        elif self.tools is None:
            raise self.error(line, f"T{number}", f"{code} loads tool {number}, and no tool table names it: give the "
                                                 "tool table (--tool-table FILE: a LinuxCNC tool table, or the "
                                                 "FreeCAD document that posted the program)")
        elif number not in self.tools:
            known = ", ".join(str(n) for n in sorted(self.tools)) or "none"
            raise self.error(line, f"T{number}", f"{code} loads tool {number}, which {self.tools_source} does not "
                                                 f"name (its tools: {known})")
        else:
            tool = self.tools[number]
        self.tool = tool
        self.collector.tool(tool, line)

    def modes(self, g_codes, m_codes, values, line):
        """Plane, compensation, tool length and TCP, coordinate system, distance and retract modes."""
        for code in g_codes:
            if code in (17.0, 18.0, 19.0):
                self.plane = int(code)
            elif code in (90.0, 91.0):
                self.absolute = code == 90.0
            elif code in (90.1, 91.1):
                self.arc_absolute = code == 90.1
            elif code in (98.0, 99.0):
                self.high_retract = code == 98.0
            elif code in (41.0, 42.0, 41.1, 42.1):
                self.warn_once("compensation", line, code_text("G", code), "cutter compensation in the control; the "
                               "moves are taken as the tool tip's path as written")
            elif code in (43.4, 43.5):
                self.tcp = True
            elif code == 49.0:
                self.tcp = False
            elif GROUP_OF[code] == "coordinate system":
                self.change_system(SYSTEMS[[float(s[1:]) for s in SYSTEMS].index(code)])
            elif code in (40.0, 43.0, 43.1, 61.0, 61.1, 64.0, 97.0, 4.0, 92.1, 92.2, 28.1, 30.1):
                self.note_ignored(line, code_text("G", code))
        if 128.0 in m_codes:
            self.tcp = True
        if 129.0 in m_codes:
            self.tcp = False
        if 97.0 in g_codes:
            self.surface_speed = None

    def change_system(self, system):
        """Another work coordinate system: the position is the same point, in the new system's numbers."""
        self.position = self.position + self.offsets[self.system][:3] - self.offsets[system][:3]
        self.system = system

    def set_offsets(self, values, line):
        """G10 L2 P n X Y Z A B C: system n's offsets (P0: the one in force), in the units in force."""
        kind = self.word(values, "L", line, "G10").value
        if kind != 2.0:
            raise self.error(line, "G10", f"L{kind:g} is not read (only L2: a work offset written whole)")
        number = int(self.word(values, "P", line, "G10 L2").value)
        if not 0 <= number <= len(SYSTEMS):
            raise self.error(line, "G10 L2", f"P{number}: the work coordinate systems are P1 (G54) to P9 (G59.3)")
        system = self.system if number == 0 else SYSTEMS[number - 1]
        before = self.offsets[self.system][:3].copy()
        for index, letter in enumerate("XYZABC"):
            if letter in values:
                self.offsets[system][index] = values[letter].value * (self.scale if index < 3 else 1.0)
        if system == self.system:
            self.position = self.position + before - self.offsets[system][:3]

    def go_home(self, values, line):
        """G28 / G30: a rapid through the point of the block's axis words, then home, a position not known."""
        if any(letter in values for letter in "XYZABC"):
            self.rapid(self.target(values, line, False), line)
        self.position = np.full(3, math.nan)

    # Positions.

    def target(self, values, line, machine_frame):
        """((3,) X Y Z mm in the work system, {letter: degrees}) the block's axis words move to (G53: the words
        are machine coordinates)."""
        position = self.position.copy()
        offset = self.offsets[self.system]
        for index, letter in enumerate("XYZ"):
            if letter not in values:
                continue
            value = values[letter].value * self.scale
            if machine_frame:
                position[index] = value - offset[index]
            elif self.absolute:
                position[index] = value
            elif math.isnan(position[index]):
                raise self.error(line, values[letter].text, f"an incremental move (G91) from a {letter} position not "
                                                            "known yet")
            else:
                position[index] += value
        angles = dict(self.angles)
        for letter in "ABC":
            if letter not in values:
                continue
            if self.machine is None:
                raise self.error(line, values[letter].text, "a rotary axis word, and no machine file names the "
                                                            "kinematics: give --machine FILE (docs/GCODE.md)")
            if letter not in self.machine.rotary:
                raise self.error(line, values[letter].text, f"the machine {self.machine.kinematics} has no "
                                                            f"{letter} axis (its rotary axes: "
                                                            f"{' '.join(self.machine.rotary)})")
            value = values[letter].value
            angles[letter] = value if self.absolute or machine_frame else angles[letter] + value
            if not abs(angles[letter]) <= MAX_ANGLE:
                raise self.error(line, values[letter].text, f"the {letter} axis at {angles[letter]:g}° is beyond "
                                                            f"±{MAX_ANGLE:g}°")
        return position, angles

    def pose(self, angles, line):
        """(R (3, 3), t (3,), axis (3,)): the part-frame tip = R @ X Y Z + t, with the work offset in t (module
        docstring); the identity and +Z without a machine file. The operation notes the frame it moves in."""
        offset = self.offsets[self.system]
        if offset[:3].any():
            self.collector.frame(f"{self.system} offset " + ", ".join(f"{v:g}" for v in offset[:3]) + " mm")
        if self.machine is None:
            return np.eye(3), offset[:3].copy(), _Z
        turned = {letter: angles[letter] + offset[3 + "ABC".index(letter)] for letter in "ABC"}
        length = None
        if self.machine.needs_tool_length and not self.tcp:
            length = self.tool.length if self.tool.length is not None else self.machine.tool_length
            if length is None:
                raise self.error(line, "TCP off", f"the {self.machine.kinematics} machine turns the tool about its "
                                 "pivot: the tool's length is needed (Z in the tool table, or tool_length in "
                                 f"{self.machine.source})")
        rotation, shift, axis = self.machine.pose(turned, self.tcp, length)
        words = f"{self.machine.kinematics}, TCP {'on' if self.tcp else 'off'}"
        self.collector.frame(words)
        return rotation, rotation @ offset[:3] + shift, axis

    def tip(self, position, angles, line):
        """((3,) the part-frame tool tip, (3,) axis) of the work-system `position` at `angles`."""
        rotation, shift, axis = self.pose(angles, line)
        return rotation @ position + shift, axis

    # Motion.

    def move(self, values, line, machine_frame):
        """The motion in force to the block's target."""
        position, angles = self.target(values, line, machine_frame)
        code = code_text("G", self.motion)
        if self.motion == 0.0:
            self.rapid((position, angles), line)
            return
        if self.motion in HOLE_CYCLES:
            self.holes(values, position, angles, line, code)
            return
        unknown = [letter for letter, value in zip("XYZ", position) if math.isnan(value)]
        if unknown:
            raise self.error(line, code, f"a feed move to a point whose {' '.join(unknown)} is not known yet (no "
                                         f"{unknown[0]} word since the start or the last G28 / G30)")
        if self.motion == 1.0:
            self.straight(position, angles, line, code)
        else:
            self.arc(values, position, angles, line, code)

    def rapid(self, target, line):
        """G0 to `target` (position, angles): a rapid, kept where the whole position is known."""
        position, angles = target
        self.position, self.angles = position, angles
        if not np.isnan(position).any():
            point, axis = self.tip(position, angles, line)
            self.collector.rapid(point, axis, line)

    def start_tip(self, line):
        """The part-frame tip of the position before a feed move, or None where it is not known."""
        if np.isnan(self.position).any():
            return None
        return self.tip(self.position, self.angles, line)[0]

    def straight(self, position, angles, line, code):
        """G1: one cutting CL point, its direction the chord from the tip before."""
        before = self.start_tip(line)
        point, axis = self.tip(position, angles, line)
        chord = np.zeros(3) if before is None else point - before
        feed = self.feed_of(float(np.linalg.norm(chord)), line, code)
        self.collector.cut([point], [axis], [chord], line, *feed)
        self.position, self.angles = position, angles

    def arc(self, values, position, angles, line, code):
        """G2 / G3: the arc's CL points with their tangents (module circles)."""
        if angles != self.angles:
            raise self.error(line, code, "an arc that also turns a rotary axis is not read")
        if np.isnan(self.position).any():
            raise self.error(line, code, "an arc from a position not known yet")
        clockwise = self.motion == 2.0
        offsets = {letter: values[letter].value * self.scale for letter in "IJK" if letter in values}
        try:
            if "R" in values:
                centre = circles.centre_of_radius(self.position, position, self.plane, clockwise,
                                                  values["R"].value * self.scale, circles.RADIUS_TOLERANCE)
            else:
                normal = circles.CENTRE_LETTERS[self.plane][2]
                if normal in offsets and abs(offsets[normal] - (self.position[circles.PLANES[self.plane][2]]
                                                                if self.arc_absolute else 0.0)) > 1e-9:
                    raise ValueError(f"{normal} is along the normal of the plane G{self.plane}: it gives no centre")
                if not offsets:
                    raise ValueError("needs its centre (I J K) or its radius (R)")
                centre = circles.centre_of_offsets(self.position, offsets, self.plane, self.arc_absolute)
            circles.check_radii(self.position, position, centre, self.plane)
            turns = int(values["P"].value) if "P" in values else 1
            if turns < 1 or "P" in values and values["P"].value != turns:
                raise ValueError(f"P{values['P'].value:g}: the turns must be a whole number from 1")
            points, tangents = circles.arc_moves(self.position, position, centre, self.plane, clockwise, turns,
                                                 self.tolerance, self.step)
        except ValueError as error:
            raise self.error(line, code, str(error)) from None
        rotation, shift, axis = self.pose(angles, line)
        tips = points @ rotation.T + shift
        length = float(np.linalg.norm(np.diff(np.vstack([rotation @ self.position + shift, tips]), axis=0),
                                      axis=1).sum())
        feed = self.feed_of(length, line, code)
        self.collector.cut(tips, [axis] * len(tips), tangents @ rotation.T, line, *feed)
        self.collector.current.arcs += 1
        self.position, self.angles = position, angles

    def feed_of(self, length, line, code):
        """(feed, kind) of a feed move `length` mm long: mm/min ("MMPM") or mm/rev ("MMPR") in force; with G93
        the move's length times its F (inverse time, 1/min)."""
        if self.feed_mode == 93.0:
            if math.isnan(self.feed):
                raise self.error(line, code, "inverse time feed (G93) needs an F word on every feed move")
            return length * self.feed, "MMPM"
        if math.isnan(self.feed):
            return math.nan, None
        return self.feed, "MMPR" if self.feed_mode == 95.0 else "MMPM"

    def holes(self, values, position, angles, line, code):
        """A hole cycle's block: its holes (the bottoms) and the position it leaves the tool at."""
        if self.plane != 17:
            raise self.error(line, code, "hole cycles are read in the XY plane (G17) only")
        try:
            bottoms, after = self.cycle.holes(position, values, self.absolute, self.scale,
                                              self.high_retract)
        except ValueError as error:
            raise self.error(line, code, str(error)) from None
        if self.motion in (74.0, 84.0) and self.tool.kind != "tap":
            self.tool = self.tool.with_kind("tap", f"{code} line {line}")
            self.collector.tool(self.tool, line)
        for bottom in bottoms:
            point, axis = self.tip(bottom, angles, line)
            self.collector.hole(point, axis, line, code)
        self.position, self.angles = after, angles

    # The result.

    def program(self, text, last_line, program_format):
        """The Program of the blocks run."""
        return self.collector.program(self.units or "mm", self.ignored, self.warnings, text, last_line,
                                      program_format)
