"""Where cutting-edge lines lie inside a solid, as ragged lists of intervals along each line.

A chunk of N edge lines (row r = i·p + k for CL point i and rotation angle k; a line runs
over 0 ≤ l ≤ L mm from the tool's bottom face up its axis) has K inside intervals in all,
stored flat and sorted by row, then by start. Each end of an interval carries the label of the
surface it lies on: a surface code (an index into ``engagement.SURFACES``), the section or
slab whose material holds it (−1 none) and the wall or boundary curve index (−1 none).
"""

from dataclasses import dataclass

import numpy as np



@dataclass(frozen=True)
class EdgeIntervals:
    """K inside intervals of N edge lines.

    n_rows: N. rows: (K,) int, the line of each interval, non-decreasing. start, end: (K,) mm
    along the line, start < end, intervals of one row disjoint and in order. start_surface,
    start_section, start_wall, end_surface, end_section, end_wall: (K,) int labels of each end.
    """

    n_rows: int
    rows: np.ndarray
    start: np.ndarray
    end: np.ndarray
    start_surface: np.ndarray
    start_section: np.ndarray
    start_wall: np.ndarray
    end_surface: np.ndarray
    end_section: np.ndarray
    end_wall: np.ndarray

    def __post_init__(self):
        k = np.shape(self.rows)[0] if np.ndim(self.rows) == 1 else -1
        for name in ("rows", "start", "end", "start_surface", "start_section", "start_wall", "end_surface",
                     "end_section", "end_wall"):
            value = np.asarray(getattr(self, name))
            if value.shape != (k,):
                raise ValueError(f"{name} must have shape (K,) like rows, got {value.shape}")
            object.__setattr__(self, name, value)
        if k and ((np.diff(self.rows) < 0).any() or self.rows[0] < 0 or self.rows[-1] >= self.n_rows):
            raise ValueError(f"rows must be non-decreasing within 0..{self.n_rows - 1}")

    @property
    def length(self):
        """(N,) total inside length of each line (mm)."""
        return np.bincount(self.rows, weights=self.end - self.start, minlength=self.n_rows)

    @property
    def count(self):
        """(N,) number of inside intervals of each line."""
        return np.bincount(self.rows, minlength=self.n_rows)
