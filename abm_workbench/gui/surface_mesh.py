"""The engaged cutter surface as one triangle mesh, built with numpy from an Engagement's arrays.

For a pass of m CL points × p angles, the n engaged instants (CL point i, angle row k) each give
two vertices: the LEP (vertex j) and the UEP (vertex n + j), in mm, in CL point then φ order.
Two instants next to each other in φ, of one engagement segment of one CL point, span a quad
(LEP_k, LEP_k+1, UEP_k+1, UEP_k): two triangles. A segment of one angle has vertices but no
triangle (the object's Shape draws it as a line). Nothing of FreeCAD is needed to build it.

A tool with a corner has a curved edge: given the edge's points between the LEP and the UEP
(`along`), each instant has CURVED_ROWS + 1 vertices up its edge (row r: vertex r·n + j, row 0
the LEP, the last the UEP), and each quad of the straight edge becomes a strip of CURVED_ROWS
quads, so the surface follows the corner's arc.
"""

from dataclasses import dataclass

import numpy as np


#: Quads up the edge of an instant whose edge is curved (a tool with a corner).
CURVED_ROWS = 8


@dataclass(frozen=True)
class SurfaceMesh:
    """points (rows·n, 3) mm: row r of every engaged instant, row 0 its LEP, the last its UEP (rows = 2 for
    a straight edge). cl, row (n,) int: the CL point and φ row of each instant. triangles (t, 3) int:
    vertex indices."""

    points: np.ndarray
    cl: np.ndarray
    row: np.ndarray
    triangles: np.ndarray

    @property
    def rows(self):
        """Vertices up the edge of each instant."""
        return len(self.points) // max(len(self.cl), 1)


def surface_mesh(result, along=None):
    """The SurfaceMesh of the Engagement `result` (see the module docstring). along: None for straight
    edges, or a function (cl (n,), row (n,), t (k,)) -> (n, k, 3) points of each instant's edge at the
    fractions t of the way from its LEP to its UEP (0 and 1 are the LEP and the UEP)."""
    segment = np.asarray(result.segment)
    engaged = segment >= 0
    cl, row = np.nonzero(engaged)
    n = cl.size
    index = np.full(segment.shape, -1, dtype=np.int64)
    index[cl, row] = np.arange(n)
    joined = engaged[:, :-1] & (segment[:, :-1] == segment[:, 1:])  # (m, p - 1): row k joins row k + 1
    at_cl, at_row = np.nonzero(joined)
    a, b = index[at_cl, at_row], index[at_cl, at_row + 1]
    if along is None:
        points = np.concatenate([result.lep_xyz[cl, row], result.uep_xyz[cl, row]]).astype(float)
        rows = 2
    else:
        rows = CURVED_ROWS + 1
        t = np.linspace(0.0, 1.0, rows)
        up = np.asarray(along(cl, row, t), dtype=float).reshape(n, rows, 3)
        up[:, 0], up[:, -1] = result.lep_xyz[cl, row], result.uep_xyz[cl, row]
        points = np.moveaxis(up, 1, 0).reshape(-1, 3)
    triangles = [np.concatenate([np.column_stack([a + k * n, b + k * n, b + (k + 1) * n]),
                                 np.column_stack([a + k * n, b + (k + 1) * n, a + (k + 1) * n])])
                 for k in range(rows - 1)]
    return SurfaceMesh(points, cl, row, np.concatenate(triangles).astype(np.int64))


def vertex_colours(result, mesh: SurfaceMesh, colour_by, forces=None, colour_map=None):
    """(colours (rows·n, 3) RGB 0..1 per vertex, colouring.Legend) of the mesh for `colour_by` (a
    colouring.COLOUR_BY value): every vertex of an instant's edge takes the instant's colour; by segment,
    the colour of its UEP surface, which is its segment's (a segment is a run of one UEP surface)."""
    from ..engine.engagement import SURFACES
    from .colouring import COLOUR_MAP, instant_colours

    surface = np.asarray(SURFACES, dtype=object)[result.uep_surface[mesh.cl, mesh.row]]
    colours, legend = instant_colours(result, mesh.cl, mesh.row, surface, colour_by, forces,
                                      colour_map or COLOUR_MAP)
    return np.tile(colours, (mesh.rows, 1)), legend


def packed_rgba(colours):
    """(k,) uint32 0xRRGGBBAA of colours (k, 3) RGB 0..1, opaque (Coin's orderedRGBA)."""
    rgb = np.clip(np.rint(np.asarray(colours, dtype=float) * 255.0), 0, 255).astype(np.uint32)
    return (rgb[:, 0] << 24) | (rgb[:, 1] << 16) | (rgb[:, 2] << 8) | np.uint32(0xFF)


def coord_index(triangles):
    """(4t,) Coin coordIndex of triangles (t, 3): each triangle's three vertices, then -1."""
    triangles = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    return np.column_stack([triangles, np.full(len(triangles), -1)]).reshape(-1)
