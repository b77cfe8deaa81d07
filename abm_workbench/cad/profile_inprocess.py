"""How much a validation against the stock as given leaves out for a tool with a corner: an estimate of the
material earlier moves of the program removed from its cutting edges.

Where validate checks a bull-nose or ball-end mill against the stock as given (asked for, or because an
earlier move's swept volume has no exact solid: cad.corner_sweep), and for a report to say what that misses,
:func:`removed_lengths` estimates, at chosen CL points, how much of each edge's length of cut in the stock as
given (the exact intervals of cad.profile_boolean.edge_intervals) lies inside the tool at some earlier
position of the program: every cutting move before the CL point is sampled at tool positions at most
POSITION_STEP mm apart at the rim (position interpolated linearly, axis normalised, as engine.inprocess
takes a move), and each inside interval at points EDGE_STEP mm apart (their middles); a point is removed
when it lies in the tool's body (cad.profile_edges' profile turned about the axis: radius R − r + √(r² −
(r − h)²) at height h < r, R above, up to the flute length) at one of those positions. The removed length is
the count of removed points times EDGE_STEP: within EDGE_STEP of the truth at each end of a removed run
(and the sampled positions miss slivers of depth about POSITION_STEP² / (8 R) between them). Numpy only
past the intervals; lengths in mm, angles in degrees.
"""

from dataclasses import dataclass

import numpy as np

from ..engine import Tool, Toolpath
from .profile_boolean import edge_intervals
from .profile_edges import EdgeGeometry, tool_frames

#: Spacing (mm) of the sample points along the edges' inside intervals.
EDGE_STEP = 0.01
#: Largest motion (mm) of any point of the tool's cutting part between two sampled positions of a move.
POSITION_STEP = 0.05
#: (point, position) pairs tested at once.
BATCH = 1 << 20


@dataclass(frozen=True)
class RemovedEstimate:
    """At k CL points × p angles: given, the peripheral edge's length of cut in the stock as given (exact,
    OpenCASCADE); removed, the estimate of the part of it inside the tool at an earlier position (mm, within
    2·EDGE_STEP per removed run); end_given, end_removed the same for the end edge; positions (k,), the
    earlier tool positions tested near each CL point."""

    cls: np.ndarray
    given: np.ndarray
    removed: np.ndarray
    end_given: np.ndarray
    end_removed: np.ndarray
    positions: np.ndarray

    @property
    def in_process(self):
        """(k, p) the estimated length of cut in the in-process stock (mm)."""
        return self.given - self.removed


def tool_positions(moves, upto, tool: Tool, step=POSITION_STEP):
    """(n, 3) bottom centres and (n, 3) unit axes of the tool at positions along every cutting move of
    `moves` (engine.inprocess.ProgramMoves) into rows 1 .. upto − 1, at most `step` mm apart at the rim
    (both ends of each move included)."""
    centres, axes = [], []
    for j in np.flatnonzero(moves.cutting[1:upto]) + 1:
        c0, c1, w0, w1 = moves.cl[j - 1], moves.cl[j], moves.axis[j - 1], moves.axis[j]
        turn = np.arccos(np.clip(w0 @ w1, -1.0, 1.0))
        reach = np.linalg.norm(c1 - c0) + turn * np.hypot(tool.radius, tool.flute_length)
        t = np.linspace(0.0, 1.0, max(2, int(np.ceil(reach / step)) + 1))[:, None]
        axis = (1.0 - t) * w0 + t * w1
        centres.append(c0 + t * (c1 - c0))
        axes.append(axis / np.linalg.norm(axis, axis=1, keepdims=True))
    if not centres:
        return np.empty((0, 3)), np.empty((0, 3))
    return np.concatenate(centres), np.concatenate(axes)


def inside_tool(points, centres, axes, tool: Tool):
    """(n,) bool: points (n, 3) inside the tool's body at one of the positions (centres, axes (q, 3)). Only
    the pairs whose point lies within the body's bounding sphere of a position are tested (a KD tree)."""
    from scipy.spatial import cKDTree

    big, r, length = tool.radius, tool.corner_radius, tool.flute_length
    hit = np.zeros(len(points), dtype=bool)
    if not len(points) or not len(centres):
        return hit
    middles = centres + 0.5 * length * axes
    pairs = cKDTree(middles).query_ball_tree(cKDTree(points), np.hypot(big, 0.5 * length) + 1e-9)
    position = np.repeat(np.arange(len(pairs)), [len(found) for found in pairs])
    point = np.fromiter((i for found in pairs for i in found), dtype=np.intp, count=position.size)
    for start in range(0, position.size, BATCH):
        q, n = position[start:start + BATCH], point[start:start + BATCH]
        keep = ~hit[n]
        q, n = q[keep], n[keep]
        offset = points[n] - centres[q]
        height = np.einsum("ik,ik->i", offset, axes[q])
        radial = np.linalg.norm(offset - height[:, None] * axes[q], axis=1)
        low = np.clip(r - height, 0.0, r)
        limit = big - r + np.sqrt(np.maximum(r * r - low * low, 0.0))
        hit[n[(height >= 0.0) & (height <= length) & (radial <= limit)]] = True
    return hit


def _samples(intervals, step):
    """Sample positions (middles of cells of about `step` mm) along merged intervals, and their cell sizes."""
    where, size = [], []
    for a, b in intervals:
        count = max(1, int(np.ceil((b - a) / step)))
        cell = (b - a) / count
        where.append(a + cell * (np.arange(count) + 0.5))
        size.append(np.full(count, cell))
    if not where:
        return np.empty(0), np.empty(0)
    return np.concatenate(where), np.concatenate(size)


def removed_lengths(shape, tool: Tool, toolpath: Toolpath, phi_deg, moves, rows, cls, progress=None):
    """A RemovedEstimate at CL points `cls` (indices into `toolpath`) at angles phi_deg (p,): toolpath the pass
    in the frame of `moves` (engine.inprocess.ProgramMoves of the whole program), rows (m,) the program row of
    each CL point of the pass; shape the stock as given (Part.Shape). progress(done, total) after each CL."""
    phi = np.atleast_1d(np.asarray(phi_deg, dtype=float))
    cls = np.asarray(cls, dtype=int).reshape(-1)
    frames = tool_frames(toolpath)
    k, p = cls.size, phi.size
    given, removed = np.zeros((k, p)), np.zeros((k, p))
    end_given, end_removed = np.zeros((k, p)), np.zeros((k, p))
    counts = np.zeros(k, dtype=int)
    reach = 2.0 * np.hypot(tool.radius, 0.5 * tool.flute_length)
    for n, i in enumerate(cls):
        geometry = EdgeGeometry.of(tool, toolpath.cl[i], frames[i], phi)
        found = edge_intervals(shape, geometry)
        centres, axes = tool_positions(moves, int(rows[i]), tool)
        middle = toolpath.cl[i] + 0.5 * tool.flute_length * geometry.w
        near = np.linalg.norm(centres + 0.5 * tool.flute_length * axes - middle, axis=1) <= reach
        centres, axes = centres[near], axes[near]
        counts[n] = len(centres)
        for j in range(p):
            runs = [(a, b) for a, b in found.get("arc", [[]] * p)[j]]
            runs += [(a + geometry.corner_length, b + geometry.corner_length) for a, b in found.get("side", [[]] * p)[j]]
            s, cell = _samples(runs, EDGE_STEP)
            given[n, j] = sum(b - a for a, b in runs)
            if s.size and len(centres):
                removed[n, j] = float(cell[inside_tool(geometry.points(j, s), centres, axes, tool)].sum())
            ends = found.get("end", [[]] * p)[j]
            t, cell = _samples(ends, EDGE_STEP)
            end_given[n, j] = sum(b - a for a, b in ends)
            if t.size and len(centres):
                points = geometry.tip + t[:, None] * geometry.d[j]
                end_removed[n, j] = float(cell[inside_tool(points, centres, axes, tool)].sum())
        if progress is not None:
            progress(n + 1, k)
    return RemovedEstimate(cls, given, removed, end_given, end_removed, counts)
