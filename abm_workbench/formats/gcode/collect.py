"""The operations of a G-code program as the interpreter finds them, made into a :class:`Program`.

An operation collects, in the part frame (mm): its cutting CL points with their tool axes, the
direction of the tool tip's motion arriving at each, their feeds and source lines; its rapid
positions and canned-cycle hole positions apart. A new operation starts at a boundary (a tool
change, a CAM operation named by the file) only once the one so far has cut or drilled: rapids
before the first cut go with the operation that follows them.
"""

import numpy as np

from ..cl.frames import IDENTITY
from ..cl.program import Moves, Operation, Program
from ..cl.tools import ToolSpec


class _Collected:
    """One operation being read: its name, tool, spindle and first line, and what it has so far."""

    def __init__(self, line, tool, spindle):
        self.name, self.tool, self.spindle, self.first_line = "", tool, spindle, line
        self.cut = {key: [] for key in ("points", "axes", "directions", "lines", "feeds", "kinds")}
        self.rapids = {key: [] for key in ("points", "axes", "lines")}
        self.holes = {key: [] for key in ("points", "axes", "lines")}
        self.arcs = 0
        self.cycles = []
        self.frame_words = []

    @property
    def worked(self):
        """Whether the operation has cut or drilled yet."""
        return bool(self.cut["lines"] or self.holes["lines"])


class Collector:
    """The operations read so far, and the one being read (:attr:`current`)."""

    def __init__(self, source):
        """`source` names the program in the operations (messages name it with the line)."""
        self.source = source
        self.done = []
        self.current = _Collected(1, ToolSpec(), None)

    def boundary(self, line, name=None):
        """A new operation from `line` if the current one has worked; `name` names the one that follows."""
        if self.current.worked:
            self.done.append(self.current)
            self.current = _Collected(line, self.current.tool, self.current.spindle)
        if name:
            self.current.name = name

    def tool(self, tool, line):
        """`tool` is loaded on `line`: another tool after the operation has worked starts a new one."""
        if self.current.worked and tool != self.current.tool:
            self.boundary(line)
        if not self.current.worked:
            self.current.tool = tool

    def spindle(self, rpm):
        """The spindle speed in force (rpm or None) becomes the operation's until it has worked."""
        if not self.current.worked:
            self.current.spindle = rpm

    def frame(self, words):
        """Note the words of a frame (work offset, kinematics) the operation moves in, once each."""
        if words and words not in self.current.frame_words:
            self.current.frame_words.append(words)

    def cut(self, points, axes, directions, line, feed, kind):
        """Cutting CL points (k, 3) with their axes and directions of motion (k, 3), from `line`, at `feed`
        (mm/min or mm/rev as `kind` "MMPM" or "MMPR" says; NaN and None before any F word)."""
        op = self.current.cut
        count = len(points)
        op["points"].extend(points)
        op["axes"].extend(axes)
        op["directions"].extend(directions)
        op["lines"].extend([line] * count)
        op["feeds"].extend([feed] * count)
        op["kinds"].extend([kind] * count)

    def rapid(self, point, axis, line):
        """A rapid move's end (3,) with its axis."""
        for key, value in zip(("points", "axes", "lines"), (point, axis, line)):
            self.current.rapids[key].append(value)

    def hole(self, point, axis, line, cycle):
        """A canned cycle's hole (its bottom, (3,)) with its axis, by `cycle` (the G word, "G81")."""
        for key, value in zip(("points", "axes", "lines"), (point, axis, line)):
            self.current.holes[key].append(value)
        if cycle not in self.current.cycles:
            self.current.cycles.append(cycle)

    def program(self, units, ignored, warnings, text, last_line, program_format):
        """The Program of every operation that cut or drilled (warnings: a list that gets the mixed feeds)."""
        self.done.append(self.current)
        operations = []
        for op in self.done:
            if op.worked:
                operations.append(self._operation(op, len(operations) + 1, warnings))
        return Program(self.source, units, tuple(operations), dict(ignored), {}, warnings, program_format, text,
                       last_line)

    def _operation(self, op, number, warnings):
        """The Operation of a collected one."""
        kinds = [kind for kind in op.cut["kinds"] if kind is not None]
        if len(set(kinds)) > 1:
            warnings.append(f"{self.source}:{op.first_line}: operation {number} mixes feeds per minute and per "
                            "revolution; its feeds are reported as written, each in its own kind")
        cut = op.cut
        arrays = [_frozen(cut[key], float, (-1, 3)) for key in ("points", "axes", "directions")]
        return Operation(number, op.name, op.tool, op.spindle, _frozen(cut["feeds"], float, (-1,)),
                         kinds[-1] if kinds else None, _frozen(cut["lines"], int, (-1,)), arrays[0], arrays[1],
                         IDENTITY, "; ".join(op.frame_words), _moves(op.rapids), _moves(op.holes), op.arcs, 0,
                         self.source, op.first_line, tuple(op.cycles), arrays[2])


def _frozen(values, dtype, shape):
    """A read-only array of `values` in `shape`."""
    array = np.array(values, dtype=dtype).reshape(shape)
    array.setflags(write=False)
    return array


def _moves(collected):
    """The Moves of collected points, axes and lines."""
    return Moves(_frozen(collected["points"], float, (-1, 3)), _frozen(collected["axes"], float, (-1, 3)),
                 _frozen(collected["lines"], int, (-1,)))
