"""Hole cycles (G73, G74, G81–G89) in the XY plane: where the holes are, never cutting moves.

Each block in a cycle mode drills at its X Y (the position in force where it gives none) from the
retract plane R down to Z, L times (repeated at the same place under G90; each time X Y further
under G91), then leaves the tool at the retract plane (G99) or, with G98, at the height it had when
the cycle began if that is higher. Under G90, R and Z are heights; under G91, R is measured from
the height the cycle began at and Z from R. R and Z stay in force for the blocks that follow in the
same cycle. A hole is its bottom point (mm, work coordinate system).
"""

import math

import numpy as np

#: The hole cycles, by their G number.
HOLE_CYCLES = {73.0, 74.0, 81.0, 82.0, 83.0, 84.0, 85.0, 86.0, 87.0, 88.0, 89.0}


class CycleState:
    """The height a cycle began at and its R and Z in force (mm; None before they are given)."""

    def __init__(self):
        self.end()

    def begin(self, height):
        """A cycle mode starts with the tool at `height` (mm, NaN when not known)."""
        self.initial, self.retract, self.bottom = height, None, None

    def end(self):
        """G80 or another motion: no cycle in force."""
        self.initial, self.retract, self.bottom = math.nan, None, None

    def holes(self, target, values, absolute, scale, high_retract):
        """(bottoms: list of (3,) hole bottoms, after: (3,) where the tool is left) of one cycle block.

        target: (3,) the block's X Y as it moves to them;
        values: {letter: Word} of the block; absolute: G90; scale: mm per unit; high_retract: G98.
        ValueError when R or Z is missing or a hole's position is not known.
        """
        if "R" in values:
            given = values["R"].value * scale
            if not absolute and math.isnan(self.initial):
                raise ValueError("an incremental R (G91) from a height not known yet")
            self.retract = given if absolute else self.initial + given
        if "Z" in values:
            given = values["Z"].value * scale
            if not absolute and self.retract is None:
                raise ValueError("an incremental Z (G91) needs R first")
            self.bottom = given if absolute else self.retract + given
        if self.retract is None or self.bottom is None:
            raise ValueError(f"needs {'R (the retract plane)' if self.retract is None else 'Z (the hole bottom)'}")
        if math.isnan(target[0]) or math.isnan(target[1]):
            raise ValueError("a hole whose X Y is not known yet")
        repeats = int(values["L"].value) if "L" in values else 1
        if repeats < 0 or ("L" in values and values["L"].value != repeats):
            raise ValueError("L: the repeats must be a whole number")
        step = np.zeros(2)
        if not absolute:
            step = np.array([values[letter].value * scale if letter in values else 0.0 for letter in "XY"])
        xy = np.array(target[:2])
        bottoms = []
        for repeat in range(repeats):
            at = xy + step * repeat
            bottoms.append(np.array([at[0], at[1], self.bottom]))
        last = xy + step * max(repeats - 1, 0)
        height = self.retract
        if high_retract and not math.isnan(self.initial):
            height = max(self.initial, self.retract)
        return bottoms, np.array([last[0], last[1], height])
