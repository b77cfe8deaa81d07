"""A milling tool's cutting edges and body as OpenCASCADE shapes, built from the tool's definition alone.

Nothing of the engine's own solvers is used here (only its input dataclasses, Tool and Toolpath, and their
definitions): the boolean reference (:mod:`.profile_boolean`) is to check the engine, so the geometry is
rebuilt from first principles. A tool of diameter D = 2R, corner radius r (0 ≤ r ≤ R) and flute length L
at a CL point T (the tip's centre) with frame R = Rz(α)·Rx(θ_A)·Ry(θ_B) (columns u, v, w; w the tool axis)
has at rotation angle φ, with the radial direction d = sin φ·u + cos φ·v:

- the corner arc (r > 0): the arc of the circle of radius r about c = T + (R − r)·d + r·w in the plane of d
  and w, from T + (R − r)·d (ψ = 0, height 0) to T + R·d + r·w (ψ = 90°), its points
  c − r cos ψ·w + r sin ψ·d; it stops at height L, ψ_max = acos(1 − L/r), when L < r. Built as a
  Part.ArcOfCircle whose parameter is ψ (XAxis −w, YAxis d, axis d × w): a true circle, never a polyline;
- the straight side (L > r): the segment T + R·d + h·w, r ≤ h ≤ L;
- the end edge (r < R): the segment T + t·d, 0 ≤ t ≤ R − r, in the tip plane.

The peripheral edge (arc, then side) is measured by its arc length s: s = r·ψ on the corner and
s = r·ψ_max + (h − r) on the side; its height above the tip is h = r (1 − cos ψ) on the corner. No edge of
zero length is built: a flat-end mill (r = 0) has no arc, a ball (r = R) no end edge, a flute no longer
than the corner no side.

Shapes: q rotation angles φ (deg) at one CL point; points (3,) or (q, 3), mm.
"""

from dataclasses import dataclass

import numpy as np

from ..engine import Tool, Toolpath
from .freecad_env import FreeCAD, Part

V = FreeCAD.Vector


def tool_frames(toolpath: Toolpath):
    """(m, 3, 3) frames Rz(α)·Rx(θ_A)·Ry(θ_B) of the CL points (angles in degrees), as the product of the
    three rotation matrices; columns u, v, w."""
    a, b, c = (np.radians(np.asarray(values, dtype=float)) for values in
               (toolpath.theta_a, toolpath.theta_b, toolpath.alpha))
    one, zero = np.ones_like(a), np.zeros_like(a)

    def matrix(rows):
        return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)

    rx = matrix([[one, zero, zero], [zero, np.cos(a), -np.sin(a)], [zero, np.sin(a), np.cos(a)]])
    ry = matrix([[np.cos(b), zero, np.sin(b)], [zero, one, zero], [-np.sin(b), zero, np.cos(b)]])
    rz = matrix([[np.cos(c), -np.sin(c), zero], [np.sin(c), np.cos(c), zero], [zero, zero, one]])
    return rz @ rx @ ry


def corner_end(tool: Tool):
    """ψ_max (rad): where the corner arc ends, 90° unless the flute ends within the corner; 0 without one."""
    r, length = tool.corner_radius, tool.flute_length
    if r <= 0.0:
        return 0.0
    return 0.5 * np.pi if length >= r else float(np.arccos(1.0 - length / r))


@dataclass(frozen=True)
class EdgeGeometry:
    """The cutting edges of one CL point at q angles, as numbers (mm; see the module docstring).

    tip, w: (3,) the CL point and the unit tool axis; d: (q, 3) unit radial directions; radius R, corner r,
    flute_length L; psi_max (rad). Derived: centres (q, 3) of the corner circles, normals (q, 3) of their
    planes (d × w), side_start (q, 3), side_length (L − r, or 0), end_length (R − r).
    """

    tip: np.ndarray
    w: np.ndarray
    d: np.ndarray
    radius: float
    corner: float
    flute_length: float
    psi_max: float

    @classmethod
    def of(cls, tool: Tool, tip, frame, phi_deg):
        """The edges of `tool` at CL point `tip` (3,) with frame (3, 3) (columns u, v, w) at angles phi_deg (q,)."""
        frame = np.asarray(frame, dtype=float)
        phi = np.radians(np.atleast_1d(np.asarray(phi_deg, dtype=float)))
        d = np.sin(phi)[:, None] * frame[:, 0] + np.cos(phi)[:, None] * frame[:, 1]
        return cls(np.asarray(tip, dtype=float), frame[:, 2].copy(), d, tool.radius, tool.corner_radius,
                   tool.flute_length, corner_end(tool))

    @property
    def centres(self):
        return self.tip + (self.radius - self.corner) * self.d + self.corner * self.w

    @property
    def normals(self):
        return np.cross(self.d, self.w)

    @property
    def side_start(self):
        return self.tip + self.radius * self.d + self.corner * self.w

    @property
    def side_length(self):
        return max(self.flute_length - self.corner, 0.0)

    @property
    def end_length(self):
        return self.radius - self.corner

    @property
    def corner_length(self):
        """Arc length (mm) of the corner arc, r·ψ_max."""
        return self.corner * self.psi_max

    @property
    def kinds(self):
        """The edge kinds this tool has, of "arc", "side", "end"."""
        return tuple(kind for kind, present in (("arc", self.corner > 0.0), ("side", self.side_length > 0.0),
                                                 ("end", self.end_length > 0.0)) if present)

    def height(self, s):
        """Height (mm) above the tip of the peripheral edge's points at arc lengths s (any shape)."""
        s = np.asarray(s, dtype=float)
        r, top = self.corner, self.corner_length
        with np.errstate(invalid="ignore", divide="ignore"):
            on_arc = r * (1.0 - np.cos(np.where(s <= top, s, 0.0) / (r if r > 0.0 else 1.0)))
        return np.where(s <= top, on_arc, r + (s - top))

    def arc_length(self, height):
        """Arc lengths s (mm) of the peripheral edge's points at heights (mm) above the tip (any shape)."""
        h = np.asarray(height, dtype=float)
        r, top = self.corner, self.corner_length
        corner_top = r * (1.0 - np.cos(self.psi_max))
        with np.errstate(invalid="ignore", divide="ignore"):
            on_arc = 2.0 * r * np.arcsin(np.sqrt(np.clip(h, 0.0, None) / (2.0 * r if r > 0.0 else 1.0)))
        return np.where((h <= corner_top) & (r > 0.0), np.minimum(on_arc, top), top + (h - r))

    def points(self, k, s):
        """Points (n, 3) of the peripheral edge of angle k at arc lengths s (n,) (NaN kept)."""
        s = np.asarray(s, dtype=float).reshape(-1)
        r, top = self.corner, self.corner_length
        psi = np.where(s <= top, s / (r if r > 0.0 else 1.0), 0.0)
        radial = np.where(s <= top, self.radius - r + r * np.sin(psi), self.radius)
        return self.tip + radial[:, None] * self.d[k] + self.height(s)[:, None] * self.w


def arc_shape(centre, normal, x_axis, radius, psi_max):
    """Part.Edge: the arc of the circle of `radius` about `centre` in the plane of `normal`, parameter ψ
    from 0 (at centre + radius·x_axis) to psi_max (rad), turning from x_axis towards normal × x_axis."""
    circle = Part.Circle(V(*centre), V(*normal), float(radius))
    circle.XAxis = V(*x_axis)
    return Part.ArcOfCircle(circle, 0.0, float(psi_max)).toShape()


def segment_shape(start, end):
    """Part.Edge: the segment from `start` to `end` (3,) mm."""
    return Part.LineSegment(V(*start), V(*end)).toShape()


def edge_shapes(geometry: EdgeGeometry):
    """[(kind, k, Part.Edge)]: every edge of `geometry`, angle k = 0..q−1, kinds "arc", "side" and "end"
    (only those of nonzero length)."""
    shapes = []
    centres, normals = geometry.centres, geometry.normals
    for k in range(len(geometry.d)):
        if "arc" in geometry.kinds:
            shapes.append(("arc", k, arc_shape(centres[k], normals[k], -geometry.w, geometry.corner,
                                               geometry.psi_max)))
        if "side" in geometry.kinds:
            start = geometry.side_start[k]
            shapes.append(("side", k, segment_shape(start, start + geometry.side_length * geometry.w)))
        if "end" in geometry.kinds:
            shapes.append(("end", k, segment_shape(geometry.tip, geometry.tip + geometry.end_length * geometry.d[k])))
    return shapes


def profile_piece_shapes(geometry: EdgeGeometry, k, s0, s1, shortest=1e-9):
    """Part.Edges of the peripheral edge of angle k from arc length s0 to s1 (mm, s0 < s1): a piece of the
    corner arc (an arc) and/or of the side (a segment); pieces shorter than `shortest` mm are left out."""
    top = geometry.corner_length
    pieces = []
    if geometry.corner > 0.0 and min(s1, top) - s0 > shortest:
        circle = Part.Circle(V(*geometry.centres[k]), V(*geometry.normals[k]), float(geometry.corner))
        circle.XAxis = V(*(-geometry.w))
        pieces.append(Part.ArcOfCircle(circle, float(s0 / geometry.corner),
                                       float(min(s1, top) / geometry.corner)).toShape())
    if s1 - max(s0, top) > shortest:
        start, end = geometry.points(k, [max(s0, top), s1])
        pieces.append(segment_shape(start, end))
    return pieces


def tool_solid(tool: Tool, tip, frame):
    """Part.Solid of the tool's cutting part at CL point `tip` (3,) with frame (3, 3): the profile (the end
    edge, the corner arc, the side, up to the flute length) turned about the axis; a cylinder for a
    flat-end mill."""
    frame = np.asarray(frame, dtype=float)
    big, r, length = tool.radius, tool.corner_radius, tool.flute_length
    if r <= 0.0:
        return Part.makeCylinder(big, length, V(*tip), V(*frame[:, 2]))
    psi_max = corner_end(tool)
    top = (big - r + r * np.sin(psi_max), r * (1.0 - np.cos(psi_max)))  # (radial, height) where the arc ends
    edges = []
    if big > r:
        edges.append(segment_shape((0.0, 0.0, 0.0), (big - r, 0.0, 0.0)))
    edges.append(arc_shape((big - r, 0.0, r), (0.0, -1.0, 0.0), (0.0, 0.0, -1.0), r, psi_max))
    if length > r:
        edges.append(segment_shape((big, 0.0, r), (big, 0.0, length)))
        top = (big, length)
    edges += [segment_shape((top[0], 0.0, top[1]), (0.0, 0.0, top[1])),
              segment_shape((0.0, 0.0, top[1]), (0.0, 0.0, 0.0))]
    face = Part.Face(Part.Wire(edges))
    solid = face.revolve(V(0, 0, 0), V(0, 0, 1), 360.0)
    solid = Part.Solid(solid) if solid.ShapeType != "Solid" else solid
    solid.Placement = FreeCAD.Placement(FreeCAD.Matrix(*np.column_stack([frame, tip]).ravel(), 0.0, 0.0, 0.0, 1.0))
    return solid


def cutter_solid(tool: Tool, toolpath: Toolpath, i):
    """Part.Solid of the tool's cutting part at CL point i of `toolpath` (:func:`tool_solid` in its frame)."""
    return tool_solid(tool, toolpath.cl[i], tool_frames(toolpath)[i])
