"""Exact OpenCASCADE solids for the volume a bull-nose or ball-end mill sweeps along a straight move.

The tool of radius R, corner radius r (0 < r ≤ R) and cutting height H with its tip's centre at c and its
unit axis w is the solid T of the points c + a·w + b (b ⊥ w) with 0 ≤ a ≤ H and |b| ≤ ρ(a), ρ(a) = R − r +
√(r² − (r − a)²) below a = r and R above (profile_edges.tool_solid builds it). Moving c straight from c0
to c1 = c0 + m with w fixed, it sweeps S = T ⊕ [0, 1]·m. docs/VALIDATION.md ("Exact solids for a corner
tool's swept volume") proves the constructions used here:

* **Across or along the axis** (m·w = 0, or m ∥ w; any r): S = T(c0) ∪ T(c1) ∪ (Σ ⊕ [0, 1]·m), Σ a plane
  section of T that every line parallel to m meeting T crosses: for a move across the axis, the axial
  profile (the section by the plane through the axis perpendicular to m: two corner arcs, two sides, the
  end edge and the top), extruded into circular cylinders and planes; for a move along it, the widest disc.
* **Ball-end, any direction** (r = R ≤ H): T = K ∩ P with K the points within r of the axis segment
  from height r to H + r and P the column of radius R from height −r to H; then S = (K ⊕ [0, 1]·m) ∩
  (P ⊕ [0, 1]·m). The first is the parallelogram (axis segment ⊕ move) grown by r: a slab, four
  cylinders, four spheres; the second the flat-end hull (hull_solids.hull_parts).
* **Bull-nose, any other direction** (r < R ≤ H): T is its corner part T₁ (heights 0 to r) and the
  cylinder above, whose sweep is the flat-end hull; T₁ sweeps T₁(c0) ∪ T₁(c1) ∪ (Σ ⊕ [0, 1]·m) with Σ the
  disc of radius R at height r and the crescent of the torus between it and the torus's silhouette seen
  along m (:func:`silhouette_crescent`: the silhouette is an exact offset curve).

Two kinds of move get no solids here (kind "gauge"): a bull-nose move within RAMP_SLOPE of the plane across
the axis but not in it, whose solids have nearly degenerate faces OpenCASCADE misjudges, and a move neither
across nor along the axis of a tool shorter than its corner radius. The reference finds the edges in their
volumes with the exact inside test of cad.sweep_membership instead.

A swept volume is returned as a SweptParts: the volume is (the union of `union`) ∩ (the union of
`column`, when given), so that a line or an arc is sectioned with each part alone, never a boolean of
solids. Lengths in mm.
"""

from dataclasses import dataclass
from typing import Optional

import numpy as np

from ..engine import Tool
from .freecad_env import FreeCAD, Part
from .hull_solids import FLAT_EPS, hull_parts
from .profile_edges import segment_shape, tool_solid

V = FreeCAD.Vector


#: A bull-nose mill's move rising or falling less than this per mm (the sine of its angle to the plane across
#: the axis) has no solids here: the extrusion of a circle along a direction close to its plane is a nearly
#: degenerate surface (its normal's length is that sine where the circle runs along the move), and OpenCASCADE's
#: point classifier then misjudges points beside the solid (33 of 3000 points about a disc of radius 5 mm
#: extruded along a move of slope 0.0083, outside the solid's box; inside it 1 to 3 of 3000 at slopes up to
#: 0.0083), its booleans miss crossings (an arc's 0.23 mm in the solids of a move of slope 0.009), and below
#: about 10⁻⁴ it no longer splits the torus along the silhouette (docs/VALIDATION.md).
RAMP_SLOPE = 0.1


class NotExactError(ValueError):
    """OpenCASCADE did not build the exact solids of a move's swept volume."""


@dataclass(frozen=True)
class SweptParts:
    """A swept volume as solids (Part.Shape): the union of `union`, cut to the union of `column` when
    that is not None. kind: "still", "across", "along", "ball" or "ramp" (the construction used)."""

    union: list
    column: Optional[list]
    kind: str


def move_kind(c0, c1, axis, radius, corner, height):
    """"still", "across", "along", "ball" or "ramp": the construction :func:`sweep_parts` uses for the move
    c0 → c1 ((3,) mm) of a tool with unit axis `axis`, or "gauge" when it has none (module docstring). A
    component of the move below FLAT_EPS mm counts as zero."""
    d = np.asarray(c1, dtype=float) - np.asarray(c0, dtype=float)
    w = np.asarray(axis, dtype=float)
    along = float(d @ w)
    across = float(np.linalg.norm(d - along * w))
    if abs(along) <= FLAT_EPS and across <= FLAT_EPS:
        return "still"
    if abs(along) <= FLAT_EPS:
        return "across"
    if across <= FLAT_EPS:
        return "along"
    if height < corner:
        return "gauge"
    if corner >= radius:
        return "ball"
    return "ramp" if abs(along) >= RAMP_SLOPE * float(np.linalg.norm(d)) else "gauge"


def frame_of(axis):
    """(3, 3) a right-handed frame whose third column is the unit `axis` (3,)."""
    w = np.asarray(axis, dtype=float)
    w = w / np.linalg.norm(w)
    helper = np.array([1.0, 0.0, 0.0]) if abs(w[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = np.cross(helper, w)
    u /= np.linalg.norm(u)
    return np.column_stack([u, np.cross(w, u), w])


def placed_tool(c, axis, radius, corner, height):
    """Part.Solid of the tool (radius, corner radius, cutting height, mm) with its tip's centre at c (3,)
    and unit axis `axis` (3,): profile_edges.tool_solid."""
    tool = Tool(2.0 * float(radius), 1, float(height), corner_radius=float(corner))
    return tool_solid(tool, np.asarray(c, dtype=float), frame_of(axis))


def axial_profile(c, axis, across, radius, corner, height):
    """Part.Face: the tool's section by the plane through its axis (tip centre c, unit `axis`) containing
    the unit direction `across` (⊥ axis): the end edge, the corner arcs (true arcs), the sides and the top
    (mm). A ball has no end edge; a tool shorter than its corner radius ends within the arcs."""
    c, w, e = (np.asarray(v, dtype=float) for v in (c, axis, across))
    rim = radius - corner
    psi_top = 0.5 * np.pi if height >= corner else float(np.arccos(1.0 - height / corner))
    top_radius = rim + corner * np.sin(psi_top)

    def arc(side):
        """The corner arc on the `side` (±1) of the axis, from the end edge up (ψ 0 to psi_top)."""
        centre = c + side * rim * e + corner * w
        points = [centre + corner * (np.sin(psi) * side * e - np.cos(psi) * w) for psi in (0.0, 0.5 * psi_top, psi_top)]
        return Part.Arc(*(V(*x) for x in points)).toShape()

    top_right, top_left = c + top_radius * e + height * w, c - top_radius * e + height * w
    edges = [segment_shape(c - rim * e, c + rim * e)] if rim > FLAT_EPS else []
    edges.append(arc(1.0))
    if height > corner:
        edges.append(segment_shape(c + radius * e + corner * w, top_right))
    edges.append(segment_shape(top_right, top_left))
    if height > corner:
        edges.append(segment_shape(top_left, c - radius * e + corner * w))
    edges.append(arc(-1.0).reversed())
    return Part.Face(Part.Wire(edges))


def widest_disc(c, axis, radius, corner, height):
    """Part.Face: the tool's widest section across its axis (tip centre c, unit `axis`): radius R at height
    r, or, for a tool shorter than its corner radius, its top (mm)."""
    c, w = (np.asarray(v, dtype=float) for v in (c, axis))
    if height >= corner:
        level, size = corner, radius
    else:
        level = height
        size = radius - corner + np.sqrt(corner * corner - (corner - height) ** 2)
    return Part.Face(Part.Wire(Part.makeCircle(float(size), V(*(c + level * w)), V(*w))))


def _rounded_parallelogram(corner0, side, move, r):
    """[Part.Shape]: the parallelogram corner0 + [0, 1]·side + [0, 1]·move ((3,) each, not parallel) grown
    by r (mm): the slab of its points within r along its normal, the cylinders of radius r about its four
    edges and the balls of radius r about its four corners; their union is exactly the grown set."""
    p, a, b = (np.asarray(v, dtype=float) for v in (corner0, side, move))
    normal = np.cross(a, b)
    normal /= np.linalg.norm(normal)
    corners = [p, p + a, p + a + b, p + b]
    face = Part.Face(Part.makePolygon([V(*x) for x in corners + corners[:1]]))
    face.translate(V(*(-r * normal)))
    parts = [face.extrude(V(*(2.0 * r * normal)))]
    for start, end in zip(corners, corners[1:] + corners[:1]):
        edge = end - start
        parts.append(Part.makeCylinder(r, float(np.linalg.norm(edge)), V(*start), V(*edge)))
    parts += [Part.makeSphere(r, V(*x)) for x in corners]
    return parts


def sweep_parts(c0, c1, axis, radius, corner, height):
    """SweptParts of the volume the tool (radius R, corner radius r with 0 < r ≤ R, cutting height H, mm;
    tip centre c0 (3,), unit axis (3,)) sweeps moving straight to c1 with its axis fixed (module
    docstring). NotExactError where move_kind gives "gauge", or where OpenCASCADE fails to build them."""
    c0, c1, w = (np.asarray(v, dtype=float) for v in (c0, c1, axis))
    kind = move_kind(c0, c1, w, radius, corner, height)
    m = c1 - c0
    if kind == "gauge":
        raise NotExactError(f"the move from {_point(c0)} to {_point(c1)} mm has no exact solids here")
    ends = [placed_tool(c0, w, radius, corner, height)]
    if kind == "still":
        return SweptParts(ends, None, kind)
    ends.append(placed_tool(c1, w, radius, corner, height))
    if kind == "across":
        across = np.cross(w, m)
        across /= np.linalg.norm(across)
        return SweptParts(ends + [axial_profile(c0, w, across, radius, corner, height).extrude(V(*m))], None, kind)
    if kind == "along":
        return SweptParts(ends + [widest_disc(c0, w, radius, corner, height).extrude(V(*m))], None, kind)
    if kind == "ball":
        grown = _rounded_parallelogram(c0 + corner * w, height * w, m, corner)
        return SweptParts(grown, hull_parts(c0 - corner * w, c1 - corner * w, w, radius, height + corner), kind)
    low = [placed_tool(c, w, radius, corner, corner) for c in (c0, c1)]
    upper = hull_parts(c0 + corner * w, c1 + corner * w, w, radius, height - corner) if height > corner else []
    disc = Part.Face(Part.Wire(Part.makeCircle(float(radius), V(*(c0 + corner * w)), V(*w)))).extrude(V(*m))
    return SweptParts(low + upper + [disc, silhouette_crescent(c0, w, m, radius, corner).extrude(V(*m))], None, kind)


def swept_solid(c0, c1, axis, radius, corner, height):
    """Part.Shape: the volume of sweep_parts (same arguments) as one shape to cut a stock by (the `union`
    fused; a ball's ramp, that fusion's common with the `column` fused), or None where the move has no exact
    solids here (move_kind "gauge") or OpenCASCADE fails to build or fuse them into a valid shape (seen on
    model test 5's five-axis ramps: "Multi fuse failed")."""
    def fused(parts):
        return parts[0] if len(parts) == 1 else parts[0].multiFuse(parts[1:])

    try:
        swept = sweep_parts(c0, c1, axis, radius, corner, height)
        shape = fused(swept.union)
        if swept.column is not None:
            shape = shape.common(fused(swept.column))
    except (NotExactError, RuntimeError, Part.OCCError):
        return None
    return shape if not shape.isNull() and shape.isValid() else None


def silhouette_crescent(c, axis, move, radius, corner):
    """Part.Face: the part of a bull-nose corner's torus (tip centre c, unit axis w, radius R, corner radius
    r < R, mm) between its silhouette seen along `move` m (neither across nor along w) and its widest circle
    (radius R at height r), on the half of the tool where the radial direction e has e·m of the sign of m·w.
    The silhouette is where the torus's normal n is ⊥ m: n = sin ψ·e − cos ψ·w with tan ψ = (m·w)/(e·m),
    the point C(θ) + r·n, C the circle of the tube's centres (radius R − r at height r). n ⊥ m and ⊥ C'
    make it the offset curve of C by r in the direction C' × m (an exact Geom_OffsetCurve). The face is the
    corner's quarter torus over that half, split along the curve (OpenCASCADE computes the curve's
    parameter curve on the torus within its 1e-7 mm tolerance; the 3D curve and the surface are exact)."""
    c, w, m = (np.asarray(v, dtype=float) for v in (c, axis, move))
    along = float(m @ w)
    toward = np.sign(along) * (m - along * w)
    toward /= np.linalg.norm(toward)
    rim = radius - corner
    circle = Part.Circle(V(*(c + corner * w)), V(*w), float(rim))
    circle.XAxis = V(*toward)
    unit = m / np.linalg.norm(m)
    curves = [Part.OffsetCurve(circle, sign * corner, V(*unit)) for sign in (1.0, -1.0)]
    # the branch through the lower, outer quarter of the tube: below the tube's centre at θ = 0
    curve = min(curves, key=lambda curve: float(np.array(tuple(curve.value(0.0))) @ w))
    edge = curve.toShape(-0.5 * np.pi, 0.5 * np.pi)
    start = c + rim * toward
    middle = c + rim * toward + corner * w + corner * np.sqrt(0.5) * (toward - w)
    arc = Part.Arc(V(*start), V(*middle), V(*(c + radius * toward + corner * w))).toShape()
    arc.rotate(V(*c), V(*w), -90.0)
    quarter = arc.revolve(V(*c), V(*w), 180.0).Faces[0]
    pieces = quarter.generalFuse([edge])[0].Faces
    crescent = [face for face in pieces if len(face.Edges) == 2]
    if len(pieces) != 2 or len(crescent) != 1 or not crescent[0].isValid():
        raise NotExactError(f"OpenCASCADE did not split the corner's torus along its silhouette for the move "
                            f"{_point(m)} mm (axis {_point(w)})")
    return crescent[0]


def _point(x):
    return "(" + ", ".join(f"{v:.6g}" for v in x) + ")"
