"""Staircase stock as an exact solid, and solids written to STEP or BREP (mm).

Each section j is the face bounded by its two walls and the lines y = y_min, y = y_max,
drawn at z = base_z and extruded up to z_top[j]; the sections are fused into one solid.
A curved wall is exactly the engine's quintic x = P(y) over [y_min, y_max]: a polynomial over
an interval is a degree-5 Bézier curve, built here as a single-span B-spline whose parameter
is y itself. A straight wall is a line. Each wall's edge is built once and shared by the two
section faces beside it, so the fuse meets identical geometry.
"""

from math import comb

import numpy as np
from numpy.polynomial import Polynomial

from ..engine import Staircase, Wall
from ..formats import replacing
from .freecad_env import FreeCAD, Part

_DEGREE = 5


def bezier_poles(wall, y_lo, y_hi):
    """Control points (6, 2) [x, y] (mm) of the degree-5 Bézier equal to `wall` over [y_lo, y_hi].

    With s = (y − y_lo)/(y_hi − y_lo), P is a quintic in s (power coefficients a_i); its
    Bernstein coefficients are b_k = Σ_{i ≤ k} C(k, i)/C(5, i)·a_i. The y control values are
    evenly spaced, which makes y linear in s.
    """
    span = y_hi - y_lo
    t_of_s = Polynomial([(y_lo - wall.y_mid) / wall.y_half, span / wall.y_half])
    power = np.zeros(_DEGREE + 1)
    composed = Polynomial(wall.coefficients)(t_of_s).coef
    power[: composed.size] = composed
    x = [sum(comb(k, i) / comb(_DEGREE, i) * power[i] for i in range(k + 1)) for k in range(_DEGREE + 1)]
    return np.column_stack([x, y_lo + span * np.arange(_DEGREE + 1) / _DEGREE])


def wall_edge(wall, y_lo, y_hi, z):
    """The wall's footprint x = P(y), y_lo ≤ y ≤ y_hi, at height z (mm) as an edge.

    A straight wall gives a line segment; a curved one a degree-5 B-spline with one span and
    knots [y_lo, y_hi], so that its parameter equals y.
    """
    if wall.is_straight:
        x = float(wall.coefficients[0])
        return Part.LineSegment(FreeCAD.Vector(x, y_lo, z), FreeCAD.Vector(x, y_hi, z)).toShape()
    poles = [FreeCAD.Vector(x, y, z) for x, y in bezier_poles(wall, y_lo, y_hi)]
    curve = Part.BSplineCurve()
    curve.buildFromPolesMultsKnots(poles, [_DEGREE + 1] * 2, [y_lo, y_hi], False, _DEGREE)
    return curve.toShape()


def staircase_solid(stock: Staircase):
    """The staircase as one valid Part.Solid (mm).

    Walls 0 and n are the planes x = x_min and x = x_max. Adjacent sections of equal height
    merge into one top face (removeSplitter), so their wall leaves no face. ValueError for a
    wall that is not the paper's quintic (an exact B-spline wall).
    """
    for j, wall in enumerate(stock.walls, start=1):
        if not isinstance(wall, Wall):
            raise ValueError(f"sections[{j}].wall: staircase_solid builds quintic walls, not {type(wall).__name__}")
    z = stock.base_z

    def line(x0, y0, x1, y1):
        return Part.LineSegment(FreeCAD.Vector(x0, y0, z), FreeCAD.Vector(x1, y1, z)).toShape()

    walls = [line(stock.x_min, stock.y_min, stock.x_min, stock.y_max)]
    walls += [wall_edge(w, stock.y_min, stock.y_max, z) for w in stock.walls]
    walls.append(line(stock.x_max, stock.y_min, stock.x_max, stock.y_max))
    blocks = []
    for j, height in enumerate(stock.z_top):
        left, right = walls[j], walls[j + 1]
        ends = [(e.valueAt(e.FirstParameter), e.valueAt(e.LastParameter)) for e in (left, right)]
        front = Part.LineSegment(ends[0][0], ends[1][0]).toShape()
        back = Part.LineSegment(ends[0][1], ends[1][1]).toShape()
        face = Part.Face(Part.Wire([left, front, right, back]))
        blocks.append(face.extrude(FreeCAD.Vector(0, 0, float(height) - z)))
    fused = blocks[0].multiFuse(blocks[1:]).removeSplitter() if len(blocks) > 1 else blocks[0]
    if len(fused.Solids) != 1:
        raise RuntimeError(f"fusing the {len(blocks)} sections gave {len(fused.Solids)} solids, expected 1")
    solid = fused.Solids[0]
    if not solid.isValid():
        raise RuntimeError("the fused staircase solid is not valid")
    return solid


def export_step(shape, path):
    """Write `shape` to a STEP file (mm), atomically: a temporary file beside `path`, then os.replace."""
    with replacing(path) as (temporary,):
        shape.exportStep(temporary)


def export_brep(shape, path):
    """Write `shape` to an OpenCASCADE BREP file, atomically (as export_step)."""
    with replacing(path) as (temporary,):
        shape.exportBrep(temporary)
