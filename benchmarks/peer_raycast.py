"""An independent peer for the benchmark: engagement by ray casting a tessellated stock.

Not part of the workbench (which gains no dependency): a benchmark helper built only from
libraries nobody on this project wrote. OpenCASCADE (FreeCAD ``Part``) tessellates the stock
solid to a chordal deviation (mm); trimesh merges the triangles into one indexed mesh and
checks it closed and consistently wound; manifold3d confirms it is a manifold solid; Embree
(through trimesh's ``RayMeshIntersector`` and the ``embreex`` binding) finds every crossing of
each cutting-edge line with the mesh.

Each edge line is the engine's (``abm_workbench.engine.edge_lines``): the straight segment
S(l) = B + l·d, 0 ≤ l ≤ L (mm), from the tool's bottom rim point B at rotation angle φ up the
unit axis d, L the flute length. The ray is cast along +d from a point below B far enough to
lie outside the mesh's bounding box, so it starts outside the solid; sorted along the ray,
each crossing enters the solid (the triangle's outward normal against d) or leaves it, and the
running count of signed crossings (the parity of the crossings, counted with their sense) is
positive exactly where the line is inside. Those inside runs, clipped to 0 ≤ l ≤ L, give the
length of cut, the LEP (lowest l inside) and the UEP (highest l inside) per instant.

Error sources: the mesh's chords (a curved wall is replaced by planes at most `deviation` mm
away, so a crossing moves by about deviation / sin(angle between wall and edge)); Embree's
single precision in finding which triangle is hit (the point itself is then recomputed in
double precision by trimesh); trimesh steps past each hit by 10⁻⁶ of the mesh's size (about
10⁻⁴ mm here) before looking for the next, so two crossings closer than that are seen as one.

Needs trimesh, embreex and manifold3d (``make compare-peers`` installs them in a virtual
environment that sees the system's FreeCAD and numpy).
"""

import os
import sys
import time
from dataclasses import dataclass

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
if ROOT not in sys.path:
    sys.path.insert(0, ROOT)

from abm_workbench.engine import edge_lines  # noqa: E402

#: Rays per Embree query: bounds the memory one query takes.
RAYS_PER_QUERY = 1 << 16
#: Inside runs of one ray closer than this (mm) are one piece of cut.
PIECE_GAP = 1e-9


@dataclass(frozen=True)
class MeshStock:
    """A stock solid as a closed triangle mesh ready for ray casting.

    mesh: the trimesh.Trimesh (mm, outward normals); intersector: its Embree RayMeshIntersector
    with the BVH built; deviation: the chordal deviation asked of OpenCASCADE (mm); seconds:
    {'read', 'tessellate', 'mesh', 'bvh'} wall-clock times (s); volume_solid, volume_mesh: mm³.
    """

    mesh: object
    intersector: object
    deviation: float
    seconds: dict
    volume_solid: float
    volume_mesh: float

    @property
    def triangles(self):
        """Number of triangles of the mesh."""
        return len(self.mesh.faces)


def read_solid(step_path):
    """The Part.Shape of a STEP file, read by OpenCASCADE through FreeCAD."""
    from abm_workbench.cad.freecad_env import Part

    shape = Part.Shape()
    shape.read(step_path)
    if not shape.Solids:
        raise ValueError(f"{step_path}: no solid to tessellate")
    return shape


def mesh_stock(step_path, deviation):
    """The MeshStock of the solid in `step_path` tessellated to `deviation` (mm, chordal).

    Raises ValueError when the tessellation is not a closed, consistently wound manifold.
    """
    import manifold3d
    import trimesh
    from trimesh.ray.ray_pyembree import RayMeshIntersector

    seconds = {}
    started = time.perf_counter()
    shape = read_solid(step_path)
    seconds["read"] = time.perf_counter() - started

    started = time.perf_counter()
    points, facets = shape.tessellate(float(deviation))
    vertices = np.array([tuple(p) for p in points], dtype=float)
    faces = np.array(facets, dtype=np.int64)
    seconds["tessellate"] = time.perf_counter() - started

    started = time.perf_counter()
    mesh = trimesh.Trimesh(vertices, faces, process=True)  # merges coincident vertices
    if not (mesh.is_watertight and mesh.is_winding_consistent):
        raise ValueError(f"{step_path}: the tessellation at {deviation:g} mm is not a closed, consistently "
                         f"wound mesh ({len(mesh.faces)} triangles)")
    if mesh.volume < 0:
        mesh.invert()
    solid = manifold3d.Manifold(manifold3d.Mesh(vert_properties=mesh.vertices.astype(np.float32),
                                                tri_verts=mesh.faces.astype(np.uint32)))
    if solid.status() != manifold3d.Error.NoError:
        raise ValueError(f"{step_path}: manifold3d refuses the tessellation at {deviation:g} mm: {solid.status()}")
    seconds["mesh"] = time.perf_counter() - started

    started = time.perf_counter()
    intersector = RayMeshIntersector(mesh)
    intersector.intersects_first(mesh.vertices[:1] - 1.0, np.array([[0.0, 0.0, 1.0]]))  # builds the BVH
    seconds["bvh"] = time.perf_counter() - started
    return MeshStock(mesh, intersector, float(deviation), seconds, float(shape.Volume), float(mesh.volume))


def edge_lengths_by_ray_casting(stock: MeshStock, tool, toolpath, phi_deg):
    """Engagement of every CL point × φ of `toolpath` by ray casting the mesh of `stock`.

    tool: abm_workbench.engine.Tool (radius, flute_length in mm); phi_deg: (p,) rotation angles
    (deg). Returns a dict of (m, p) arrays: length (mm inside the mesh along the edge), lep_l and
    uep_l (mm along the edge, NaN without engagement), pieces (inside runs, int), and the int
    'unbalanced': rays whose crossings did not leave them outside at the end (a hit lost in a
    crack of the mesh: their numbers are then not to be trusted).
    """
    phi = np.atleast_1d(np.asarray(phi_deg, dtype=float))
    base, direction = edge_lines(toolpath, tool, phi)
    m, p = base.shape[:2]
    origins = base.reshape(-1, 3)
    directions = np.repeat(direction, p, axis=0)
    out = {"length": np.zeros(m * p), "lep_l": np.full(m * p, np.nan), "uep_l": np.full(m * p, np.nan),
           "pieces": np.zeros(m * p, dtype=int), "unbalanced": 0}
    for start in range(0, m * p, RAYS_PER_QUERY):
        stop = min(m * p, start + RAYS_PER_QUERY)
        chunk = _cast(stock, origins[start:stop], directions[start:stop], tool.flute_length)
        for name in ("length", "lep_l", "uep_l", "pieces"):
            out[name][start:stop] = chunk[name]
        out["unbalanced"] += chunk["unbalanced"]
    for name in ("length", "lep_l", "uep_l", "pieces"):
        out[name] = out[name].reshape(m, p)
    return out


def _cast(stock, origins, directions, length):
    """Per line (n,): length, lep_l, uep_l, pieces of the segments origins + l·directions, 0 ≤ l ≤ length.

    origins, directions: (n, 3) mm, directions unit. Adds the int 'unbalanced' (see above).
    """
    n = len(origins)
    low, high = stock.mesh.bounds
    back = np.linalg.norm(high - low) + np.max(np.linalg.norm(origins - 0.5 * (low + high), axis=1)) + 1.0
    starts = origins - back * directions
    triangle, ray, points = stock.intersector.intersects_id(starts, directions, multiple_hits=True,
                                                            max_hits=1000, return_locations=True)
    along = np.einsum("ij,ij->i", points - starts[ray], directions[ray]) - back
    sense = -np.sign(np.einsum("ij,ij->i", stock.mesh.face_normals[triangle], directions[ray])).astype(int)
    order = np.lexsort((along, ray))
    ray, along, sense = ray[order], along[order], sense[order]
    first = np.r_[True, ray[1:] != ray[:-1]] if ray.size else np.zeros(0, bool)
    last = np.r_[ray[1:] != ray[:-1], True] if ray.size else np.zeros(0, bool)
    group_start = np.maximum.accumulate(np.where(first, np.arange(ray.size), 0))
    total = np.cumsum(sense)
    winding = total - np.r_[0, total][group_start]  # signed crossings so far along this ray
    unbalanced = int(np.count_nonzero(winding[last] != 0))

    runs = (winding > 0) & ~last  # inside from this crossing to the next one on the same ray
    run_ray = ray[runs]
    lo = np.clip(along[runs], 0.0, length)
    hi = np.clip(along[np.flatnonzero(runs) + 1], 0.0, length)
    kept = hi > lo
    run_ray, lo, hi = run_ray[kept], lo[kept], hi[kept]

    # The runs are disjoint and in order along each ray: its first run holds the LEP, its last the UEP.
    result = {"length": np.bincount(run_ray, weights=hi - lo, minlength=n), "lep_l": np.full(n, np.nan),
              "uep_l": np.full(n, np.nan), "unbalanced": unbalanced}
    other_ray = run_ray[1:] != run_ray[:-1]
    first = np.r_[True, other_ray][:run_ray.size]
    final = np.r_[other_ray, True][:run_ray.size]
    result["lep_l"][run_ray[first]] = lo[first]
    result["uep_l"][run_ray[final]] = hi[final]
    new_piece = first | np.r_[False, lo[1:] - hi[:-1] > PIECE_GAP][:run_ray.size]
    result["pieces"] = np.bincount(run_ray[new_piece], minlength=n)
    return result
