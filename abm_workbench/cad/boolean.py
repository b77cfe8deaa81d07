"""The boolean reference: where the cutting edge lies inside the stock, by OpenCASCADE.

This mirrors the paper's check against Siemens NX. For each CL point, the cutting-edge
segments S(l), 0 ≤ l ≤ L, of every rotation angle φ (the engine's own :func:`edge_lines`)
go into ONE ``shape.common([edges])``; each edge of the result is mapped back to the segment
it lies on, and its ends projected on that segment give its l range. Lengths in mm, φ in
degrees. One boolean costs a few ms, plus per segment about 0.5 ms against straight walls and
up to 7 ms when the segments pass many curved (B-spline) walls.
"""

import numpy as np

from ..engine import Tool, Toolpath, edge_lines
from .freecad_env import FreeCAD, Part
from .profile_edges import cutter_solid

#: A result edge must lie within this distance (mm) of the segment it is mapped to.
ON_LINE_TOL = 1e-6
#: Result edges shorter than this (mm) are touching points, not pieces of cut; pieces closer
#: than this along one segment are one piece.
PIECE_EPS = 1e-9
#: Rotation angles closer than this (deg) modulo 360 share one segment. Segments closer than
#: OpenCASCADE's confusion tolerance (1e-7 mm: 1e-6° at R_t ≈ 6 mm) are merged by the boolean anyway.
SAME_ANGLE = 1e-6


def edge_lengths_by_boolean(shape, tool: Tool, toolpath: Toolpath, phi_deg, progress=None):
    """Engagement of every CL point × φ by booleans with `shape` (a Part.Shape, the stock).

    phi_deg: (p,) rotation angles (deg). Returns a dict of (m, p) arrays: length (total length
    of the segment inside the stock, mm), lep_l and uep_l (lowest start and highest end of the
    inside pieces along the segment, mm; NaN without engagement), pieces (number of inside
    pieces, int). `progress(done, total)` is called after each CL point. A KeyboardInterrupt
    raised meanwhile propagates.
    """
    phi = np.atleast_1d(np.asarray(phi_deg, dtype=float))
    if phi.ndim != 1 or not np.isfinite(phi).all():
        raise ValueError(f"phi_deg must be finite angles of shape (p,), got shape {phi.shape}")
    distinct, source = _distinct_angles(phi)
    base, direction = edge_lines(toolpath, tool, distinct)
    m, p = base.shape[0], phi.size
    out = {
        "length": np.zeros((m, p)), "lep_l": np.full((m, p), np.nan), "uep_l": np.full((m, p), np.nan),
        "pieces": np.zeros((m, p), dtype=int),
    }
    for i in range(m):
        intervals = _inside_intervals(shape, base[i], direction[i], tool.flute_length)
        for k, pieces in enumerate(intervals[j] for j in source):
            if pieces:
                out["length"][i, k] = sum(b - a for a, b in pieces)
                out["lep_l"][i, k], out["uep_l"][i, k] = pieces[0][0], pieces[-1][1]
                out["pieces"][i, k] = len(pieces)
        if progress is not None:
            progress(i + 1, m)
    return out


def _distinct_angles(phi):
    """Angles (q,) that give distinct segments, and per angle of phi (p,) the index of its own.

    Angles within SAME_ANGLE of each other modulo 360° give one segment (the boolean would
    merge coincident segments and leave one of them empty), so each is solved once.
    """
    key = np.mod(phi, 360.0)
    key[key > 360.0 - SAME_ANGLE] = 0.0
    order = np.argsort(key, kind="stable")
    starts = np.diff(key[order], prepend=-np.inf) > SAME_ANGLE
    source = np.empty(phi.size, dtype=int)
    source[order] = np.cumsum(starts) - 1
    return phi[order[starts]], source


def _inside_intervals(shape, base, direction, length):
    """Per segment (p lists), the merged (l_start, l_end) intervals inside `shape`, increasing.

    base: (p, 3) points at l = 0; direction: (3,) unit, shared by all segments (mm).
    """
    vector = FreeCAD.Vector(*direction)
    segments = [
        Part.LineSegment(FreeCAD.Vector(*b), FreeCAD.Vector(*b) + vector * length).toShape() for b in base
    ]
    found = [[] for _ in segments]
    for edge in shape.common(segments).Edges if segments else ():
        ends = np.array([tuple(edge.valueAt(u)) for u in edge.ParameterRange])
        if np.linalg.norm(ends[1] - ends[0]) < PIECE_EPS:
            continue
        middle = ends.mean(axis=0) - base
        along = middle @ direction
        distance = np.linalg.norm(middle - along[:, None] * direction, axis=1)
        k = int(np.argmin(distance))
        if distance[k] > ON_LINE_TOL:
            raise RuntimeError(f"a boolean result edge lies on no cutting edge (nearest {distance[k]:.3g} mm away)")
        l_ends = np.sort((ends - base[k]) @ direction)
        found[k].append((float(l_ends[0]), float(l_ends[1])))
    return [_merged(pieces) for pieces in found]


def _merged(pieces):
    """Intervals sorted and joined where they touch (gap below PIECE_EPS)."""
    merged = []
    for start, end in sorted(pieces):
        if merged and start - merged[-1][1] < PIECE_EPS:
            merged[-1] = (merged[-1][0], max(merged[-1][1], end))
        else:
            merged.append((start, end))
    return merged


def cutter_intersection(shape, tool: Tool, toolpath: Toolpath, i):
    """The stock material inside the cutter at CL point i: a Part.Shape (mm).

    The cutter is the cylinder of radius R_t and height L (flute length) standing on the CL
    point with axis R·e_z; a tool with a corner radius is its own body, the profile with the rounded
    corner turned about the axis (cad.profile_edges.tool_solid).
    """
    if tool.corner_radius > 0.0:
        return shape.common(cutter_solid(tool, toolpath, i))
    _, direction = edge_lines(toolpath, tool, [0.0])
    cylinder = Part.makeCylinder(
        tool.radius, tool.flute_length, FreeCAD.Vector(*toolpath.cl[i]), FreeCAD.Vector(*direction[i])
    )
    return shape.common(cylinder)
