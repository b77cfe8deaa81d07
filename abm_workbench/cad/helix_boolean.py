"""The boolean reference for helical cutting edges: where each flute's helix lies inside the stock.

Flute k of a tool with helix angle β at CL point T (frame R = Toolpath.frames(): Rz(α)·Rx(θ_A)·Ry(θ_B),
columns u, v, w) and rotation angle φ is the helix of engine/helix.py,

    S_k(l) = T + R·(R_t sin ψ, R_t cos ψ, l),   ψ = φ + 360k/Z − deg(l tan β / R_t),   0 ≤ l ≤ L.

In the tool frame its polar angle is θ = 90° − ψ = 90° − ψ(0) + κl (κ = tan β / R_t), so
it is the straight line from (θ, z) = (90° − ψ(0), 0) to (90° − ψ(0) + κL, L) on the
cylinder of radius R_t about z, placed by R and T; either hand follows from the sign of κ.
For β = 0 the edge is the straight segment of cad/boolean.py. The helices of every φ and
flute at one CL point go into ``shape.common([edges])``, HELICES_PER_BOOLEAN at a time; each
result edge is mapped back to the helix its middle lies on, and the heights l = (P − T)·w of
its two ends give its axial span.

OpenCASCADE keeps the edge as its line on the cylinder plus a B-spline 3D curve within the
edge's Tolerance, 1e-7 mm (measured 2e-8 to 7e-8 mm), and the boolean works on the B-spline;
a crossing met at an angle γ moves by about that deviation / sin γ along the axis.
``Part.makeHelix`` builds the same helix but approximates its 3D curve only to 1e-5 mm, too
coarse for a 1e-6 mm check (docs/HELIX.md, "Checked against OpenCASCADE").
Lengths in mm, angles in degrees.
"""

import numpy as np

from ..engine import Tool, Toolpath
from .boolean import PIECE_EPS, _distinct_angles, _merged
from .freecad_env import FreeCAD, Part

#: A result edge's middle must lie within this distance (mm) of the helix it is mapped to: ten
#: times the 1e-7 mm to which OpenCASCADE approximates the helix by a B-spline.
ON_HELIX_TOL = 1e-6
#: Helices per boolean. A common's cost per helix falls with batching up to about 50 helices and
#: then grows (the arguments are checked against each other): measured 37 ms alone, 12-13 ms in
#: batches of 6 to 48, 18 ms at 90, 30 ms at 180 (model test 1, β = 30°).
HELICES_PER_BOOLEAN = 24


def helix_edge(tool: Tool, cl, frame, psi0_deg):
    """Flute edge S(l), 0 ≤ l ≤ L, as a Part.Edge at CL point `cl` (3,) mm with frame (3, 3)
    (columns u, v, w) and angle ψ(0) = psi0_deg (deg): a straight line on the cylinder of
    radius R_t about z, from (θ, l) = (90° − ψ(0), 0) to (90° − ψ(0) + κL, L), κ = tan β / R_t,
    placed by the frame and the CL point; a straight segment for β = 0."""
    cl, frame = np.asarray(cl, dtype=float), np.asarray(frame, dtype=float)
    psi0 = np.radians(psi0_deg)
    if tool.helix == 0.0:
        start = cl + tool.radius * (np.sin(psi0) * frame[:, 0] + np.cos(psi0) * frame[:, 1])
        end = start + tool.flute_length * frame[:, 2]
        return Part.LineSegment(FreeCAD.Vector(*start), FreeCAD.Vector(*end)).toShape()
    kappa = np.tan(np.radians(tool.helix)) / tool.radius
    cylinder = Part.Cylinder()
    cylinder.Radius = tool.radius
    theta0 = 0.5 * np.pi - psi0
    line = Part.Geom2d.Line2dSegment(FreeCAD.Base.Vector2d(theta0, 0.0),
                                     FreeCAD.Base.Vector2d(theta0 + kappa * tool.flute_length, tool.flute_length))
    edge = line.toShape(cylinder)
    edge.Placement = FreeCAD.Placement(FreeCAD.Matrix(*np.column_stack([frame, cl]).ravel(), 0.0, 0.0, 0.0, 1.0))
    return edge


def flute_lengths_by_boolean(shape, tool: Tool, toolpath: Toolpath, phi_deg, flutes=None, progress=None):
    """Engagement of every CL point × φ × flute by booleans of the helical edges with `shape`.

    shape: the stock (Part.Shape); phi_deg: (p,) angle of flute 0 at the tip (deg); flutes:
    flute indices to solve (default all Z; the others stay unengaged). Returns a dict of
    (m, p, Z) arrays: axial_length (sum of the inside pieces' axial spans, mm), edge_length
    (their length along the helix, mm), lep_l and uep_l (lowest start and highest end of the
    inside pieces along the axis, mm; NaN without engagement), pieces (int).
    `progress(done, total)` is called after each CL point.
    """
    phi = np.atleast_1d(np.asarray(phi_deg, dtype=float))
    if phi.ndim != 1 or not np.isfinite(phi).all():
        raise ValueError(f"phi_deg must be finite angles of shape (p,), got shape {phi.shape}")
    z = tool.flutes
    chosen = np.arange(z) if flutes is None else np.unique(np.asarray(flutes, dtype=int))
    if chosen.size == 0 or chosen.min() < 0 or chosen.max() >= z:
        raise ValueError(f"flutes must be indices in 0..{z - 1}, got {flutes!r}")
    angles = (phi[:, None] + 360.0 * chosen[None, :] / z).ravel()            # (p·c,) ψ(0), flute-major last
    distinct, source = _distinct_angles(angles)
    frames = toolpath.frames()
    m, p = len(toolpath), phi.size
    out = {"axial_length": np.zeros((m, p, z)), "edge_length": np.zeros((m, p, z)),
           "lep_l": np.full((m, p, z), np.nan), "uep_l": np.full((m, p, z), np.nan),
           "pieces": np.zeros((m, p, z), dtype=int)}
    rows, columns = np.divmod(np.arange(angles.size), chosen.size)
    for i in range(m):
        found = _inside_pieces(shape, tool, toolpath.cl[i], frames[i], distinct)
        for j, (row, column) in enumerate(zip(rows, chosen[columns])):
            spans, along = found[source[j]]
            if spans:
                out["axial_length"][i, row, column] = sum(b - a for a, b in spans)
                out["edge_length"][i, row, column] = along
                out["lep_l"][i, row, column], out["uep_l"][i, row, column] = spans[0][0], spans[-1][1]
                out["pieces"][i, row, column] = len(spans)
        if progress is not None:
            progress(i + 1, m)
    return out


def _inside_pieces(shape, tool, cl, frame, psi0_deg):
    """Per helix of angle ψ(0) in psi0_deg (q,): (merged axial (l_start, l_end) spans, length along
    the helix inside, mm), by booleans of HELICES_PER_BOOLEAN helices at CL point `cl` (3,) with
    `frame` (3, 3)."""
    found = []
    for first in range(0, len(psi0_deg), HELICES_PER_BOOLEAN):
        found += _one_boolean(shape, tool, cl, frame, psi0_deg[first:first + HELICES_PER_BOOLEAN])
    return found


def _one_boolean(shape, tool, cl, frame, psi0_deg):
    """_inside_pieces for the helices of psi0_deg (q,) in one common."""
    edges = [helix_edge(tool, cl, frame, psi) for psi in psi0_deg]
    spans = [[] for _ in edges]
    along = np.zeros(len(edges))
    kappa = np.tan(np.radians(tool.helix)) / tool.radius
    for edge in shape.common(edges).Edges:
        first, last = edge.ParameterRange
        points = np.array([tuple(edge.valueAt(u)) for u in (first, 0.5 * (first + last), last)])
        if edge.Length < PIECE_EPS:
            continue
        local = (points - cl) @ frame                                          # (3, 3) tool-frame coordinates
        l_mid = local[1, 2]
        polar = np.arctan2(local[1, 1], local[1, 0])
        expected = np.radians(90.0 - psi0_deg) + kappa * l_mid
        gap = np.abs(np.angle(np.exp(1j * (polar - expected))))
        k = int(np.argmin(gap))
        distance = np.hypot(tool.radius * gap[k], np.hypot(local[1, 0], local[1, 1]) - tool.radius)
        if distance > ON_HELIX_TOL:
            raise RuntimeError(f"a boolean result edge lies on no flute helix (nearest {distance:.3g} mm away)")
        low, high = sorted((float(local[0, 2]), float(local[2, 2])))
        spans[k].append((low, high))
        along[k] += edge.Length
    return [(_merged(s), a) for s, a in zip(spans, along)]

