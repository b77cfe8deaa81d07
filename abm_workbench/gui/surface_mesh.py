"""The engaged cutter surface as one triangle mesh, built with numpy from an Engagement's arrays.

For a pass of m CL points × p angles, the n engaged instants (CL point i, angle row k) each give
two vertices: the LEP (vertex j) and the UEP (vertex n + j), in mm, in CL point then φ order.
Two instants next to each other in φ, of one engagement segment of one CL point, span a quad
(LEP_k, LEP_k+1, UEP_k+1, UEP_k): two triangles. A segment of one angle has vertices but no
triangle (the object's Shape draws it as a line). Nothing of FreeCAD is needed to build it.
"""

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class SurfaceMesh:
    """points (2n, 3) mm: the LEP of each engaged instant, then its UEP. cl, row (n,) int: the CL
    point and φ row of each instant. triangles (t, 3) int: vertex indices."""

    points: np.ndarray
    cl: np.ndarray
    row: np.ndarray
    triangles: np.ndarray


def surface_mesh(result):
    """The SurfaceMesh of the Engagement `result` (see the module docstring)."""
    segment = np.asarray(result.segment)
    engaged = segment >= 0
    cl, row = np.nonzero(engaged)
    n = cl.size
    index = np.full(segment.shape, -1, dtype=np.int64)
    index[cl, row] = np.arange(n)
    joined = engaged[:, :-1] & (segment[:, :-1] == segment[:, 1:])  # (m, p - 1): row k joins row k + 1
    at_cl, at_row = np.nonzero(joined)
    a, b = index[at_cl, at_row], index[at_cl, at_row + 1]
    triangles = np.concatenate([np.column_stack([a, b, n + b]), np.column_stack([a, n + b, n + a])])
    points = np.concatenate([result.lep_xyz[cl, row], result.uep_xyz[cl, row]]).astype(float)
    return SurfaceMesh(points, cl, row, triangles.astype(np.int64))


def vertex_colours(result, mesh: SurfaceMesh, colour_by, forces=None, colour_map=None):
    """(colours (2n, 3) RGB 0..1 per vertex, colouring.Legend) of the mesh for `colour_by` (a
    colouring.COLOUR_BY value): an instant's LEP and UEP take the instant's colour; by segment,
    the colour of its UEP surface, which is its segment's (a segment is a run of one UEP surface)."""
    from ..engine.engagement import SURFACES
    from .colouring import COLOUR_MAP, instant_colours

    surface = np.asarray(SURFACES, dtype=object)[result.uep_surface[mesh.cl, mesh.row]]
    colours, legend = instant_colours(result, mesh.cl, mesh.row, surface, colour_by, forces,
                                      colour_map or COLOUR_MAP)
    return np.concatenate([colours, colours]), legend


def packed_rgba(colours):
    """(k,) uint32 0xRRGGBBAA of colours (k, 3) RGB 0..1, opaque (Coin's orderedRGBA)."""
    rgb = np.clip(np.rint(np.asarray(colours, dtype=float) * 255.0), 0, 255).astype(np.uint32)
    return (rgb[:, 0] << 24) | (rgb[:, 1] << 16) | (rgb[:, 2] << 8) | np.uint32(0xFF)


def coord_index(triangles):
    """(4t,) Coin coordIndex of triangles (t, 3): each triangle's three vertices, then -1."""
    triangles = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    return np.column_stack([triangles, np.full(len(triangles), -1)]).reshape(-1)
