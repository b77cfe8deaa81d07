#!/usr/bin/env python3
"""Generate model test 5: a two-bump part roughed in z-levels, and a five-axis semi-finishing pass of a
bull-nose mill over it, as Siemens NX writes it (CLSF). Writes into ``resources/models/model_test_5/``:

* ``stock.json``  -- the roughed stock, format ``abm-terraced/1`` (its walls closed B-splines);
* ``stock.step``  -- the same stock as a solid (``cad.terraced_solids.terraced_solid``);
* ``toolpath.cls`` -- the semi-finishing operation in NX CLSF: ``TOOL PATH/``, ``TLDATA/MILL,16,4,...``
  (D 16 mm, corner radius 3 mm), ``MSYS`` (the MCS at the top centre of the part), ``GOTO/x,y,z,i,j,k``
  at every point, FEDRAT, RAPID, PAINT records;
* ``job.json``    -- what the CL file does not give: flutes, flute length, feed per tooth, rotation angles.

The design part (mm): a block x 0..120, y -45..45 on z 0 whose top is the surface

    f(x, y) = 3 + 16 G((x - 42)/15, (y + 4)/13) + 13 G((x - 80)/13, (y - 5)/16),   G(u, v) = exp(-(u² + v²)/2),

two bumps (crests 19.16 and 16.58 mm high) joined by a saddle at about 13.9 mm. Z-level roughing with an
allowance of 1 mm at the levels 6.5, 9, ..., 21.5 (step-down 2.5) leaves in the slab between two levels
the material inside the contour f + 1 = (the lower level): one loop up to level 14 (the last one pinched at
the saddle), two loops at 16.5, the higher bump's alone at 19; below 6.5 the whole block. Each contour is
found exactly along rays from a centre (scipy brentq on f + a - z along each of 144 rays, the first
crossing), and the wall is the periodic cubic B-spline through those points (OpenCASCADE's interpolation,
made non-periodic exactly), within CONTOUR_FIT mm of the contour (checked at the rays' midpoints).

The semi-finishing operation: raster passes along x (zig-zag) at y = -24, -16, ..., 24 (stepover 8 mm, half
the diameter), CL points every 1.5 mm from x 6 to 114 (73 per pass), the bull-nose touching the offset
surface f + 0.4 (the finishing allowance) with its corner torus: the axis is the surface normal led by 10°
towards the feed and tilted sideways by 8° sin(...) varying along each pass, so every CL point has its own
axis; the CL point T = C + r n - r w - (R - r) e for the contact C, normal n, axis w and e the radial
direction of the torus's normal there (-n). Between passes: a retract of 3 mm along the axis, a rapid to 3 mm
above the next pass's start, an engage. 511 cutting CL points on the passes, 539 in the operation with the
engage and retract moves.

Run with FreeCAD's Python from the repository root (deterministic but for the STEP header's time):

    /usr/bin/python3 resources/models/make_model_test_5.py
"""

import json
import sys
from pathlib import Path

import numpy as np
from scipy.optimize import brentq

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from abm_workbench.cad.freecad_env import FreeCAD, Part  # noqa: E402
from abm_workbench.cad.solids import export_step  # noqa: E402
from abm_workbench.cad.terraced_solids import terraced_solid  # noqa: E402
from abm_workbench.engine.terraced_model import Loop, PlanLine, PlanSpline, Slab, TerracedStock  # noqa: E402
from abm_workbench.formats.terraced_json import dump_terraced  # noqa: E402

OUT = ROOT / "resources" / "models" / "model_test_5"
BLOCK = (0.0, -45.0, 120.0, 45.0)
BASE_Z = 0.0
LEVELS = (6.5, 9.0, 11.5, 14.0, 16.5, 19.0, 21.5)
ALLOWANCE = 1.0          # roughing
FINISH_ALLOWANCE = 0.4   # what semi-finishing leaves
BUMPS = ((16.0, 42.0, -4.0, 15.0, 13.0), (13.0, 80.0, 5.0, 13.0, 16.0))  # height, x, y, sx, sy
RAYS = 144
CONTOUR_FIT = 2e-3       # mm: the spline walls against the exact contours
DIAMETER, CORNER, FLUTES, FLUTE_LENGTH, TOOL_LENGTH = 16.0, 3.0, 4, 30.0, 75.0
PASS_Y = (-24.0, -16.0, -8.0, 0.0, 8.0, 16.0, 24.0)
PASS_X = np.linspace(6.0, 114.0, 73)
LEAD, TILT = 10.0, 8.0   # deg
CLEAR = 3.0              # mm: retract and approach along the axis
MCS = np.array([60.0, 0.0, 21.5])  # MSYS origin (part coordinates), axes those of the part
SPINDLE, FEED = 8000.0, 2400.0     # rpm, mm/min: 0.075 mm per tooth with 4 flutes
ENGAGE_FEED = 800.0


def surface(x, y):
    """f(x, y) (mm) and its gradient (f_x, f_y), arrays."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    value, fx, fy = np.full(np.broadcast(x, y).shape, 3.0), 0.0, 0.0
    for height, cx, cy, sx, sy in BUMPS:
        u, v = (x - cx) / sx, (y - cy) / sy
        g = height * np.exp(-0.5 * (u * u + v * v))
        value = value + g
        fx, fy = fx - g * u / sx, fy - g * v / sy
    return value, fx, fy


def contour_points(centre, z, rays=RAYS, reach=90.0):
    """(rays, 2) points of the contour f + ALLOWANCE = z met first along rays from `centre` (inside)."""
    points = []
    for theta in np.linspace(0.0, 2.0 * np.pi, rays, endpoint=False):
        direction = np.array([np.cos(theta), np.sin(theta)])

        def level(rho):
            return surface(*(centre + rho * direction))[0] + ALLOWANCE - z

        samples = np.linspace(0.0, reach, 3601)
        values = surface(*(centre + samples[:, None] * direction).T)[0] + ALLOWANCE - z
        if values[0] <= 0.0:
            raise RuntimeError(f"contour {z}: the centre {centre} is not inside")
        k = int(np.flatnonzero(values <= 0.0)[0])
        rho = brentq(level, samples[k - 1], samples[k], xtol=1e-13)
        points.append(centre + rho * direction)
    return np.array(points)


def closed_spline(points):
    """PlanSpline: the periodic cubic B-spline through `points` (n, 2) (OpenCASCADE's interpolation), made
    non-periodic and clamped exactly (its end knots raised to multiplicity degree + 1 by knot insertion)."""
    curve = Part.BSplineCurve()
    curve.interpolate([FreeCAD.Vector(x, y, 0.0) for x, y in points], PeriodicFlag=True)
    first, last = curve.FirstParameter, curve.LastParameter
    curve.setNotPeriodic()
    curve.segment(first, last)  # clamped: end knots of multiplicity degree + 1, the same curve
    knots = np.repeat(curve.getKnots(), curve.getMultiplicities())
    poles = np.array([tuple(p)[:2] for p in curve.getPoles()])
    return PlanSpline(curve.Degree, knots, poles, face="roughed wall")


#: Centres of the loops of each level below the top (the loops' own points; checked to be inside).
CENTRES = {6.5: [(60.0, 0.0)], 9.0: [(60.0, 0.0)], 11.5: [(60.0, 0.0)], 14.0: [(62.0, 0.5)],
           16.5: [(42.0, -4.0), (80.0, 5.0)], 19.0: [(42.0, -4.0)]}


def loops_of(z):
    """[(PlanSpline, points (RAYS, 2), centre)] of the level-z contour's loops."""
    found = []
    for centre in CENTRES[z]:
        points = contour_points(np.array(centre), z)
        found.append((closed_spline(points), points, np.array(centre)))
    return found


def roughed_stock():
    """The TerracedStock left by the z-level roughing, and {level: loops_of(level)}."""
    x0, y0, x1, y1 = BLOCK
    corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    block = Loop(tuple(PlanLine(corners[i], corners[(i + 1) % 4], "block side") for i in range(4)))
    slabs, contours = [Slab(BASE_Z, LEVELS[0], (block,))], {}
    for below, top in zip(LEVELS[:-1], LEVELS[1:]):
        contours[below] = loops_of(below)
        slabs.append(Slab(below, top, tuple(Loop((spline,)) for spline, _, _ in contours[below])))
    return TerracedStock(tuple(slabs)), contours


def check_contours(contours):
    """Raise unless each spline wall lies within CONTOUR_FIT of the exact contour (at the rays' midpoints, by
    the contour's value along the curve's normal) and the level's region is what the loops enclose (on a
    0.25 mm grid, away from the walls). Returns the largest deviation (mm)."""
    from scipy.interpolate import BSpline
    from matplotlib.path import Path as PlanPath

    worst = 0.0
    x = np.arange(BLOCK[0] + 0.125, BLOCK[2], 0.25)
    y = np.arange(BLOCK[1] + 0.125, BLOCK[3], 0.25)
    gx, gy = np.meshgrid(x, y)
    for z, loops in contours.items():
        inside_any = np.zeros(gx.shape, dtype=bool)
        for spline, points, centre in loops:
            curve = BSpline(np.array(spline.knots), np.array(spline.control), spline.degree)
            u = np.linspace(spline.knots[0], spline.knots[-1], 20 * RAYS + 1)
            dense = curve(u)
            # the value f + a - z at the curve over the gradient's length: the distance to the contour
            value, fx, fy = surface(dense[:, 0], dense[:, 1])
            distance = np.abs(value + ALLOWANCE - z) / np.hypot(fx, fy)
            worst = max(worst, float(distance.max()))
            inside_any |= PlanPath(dense).contains_points(np.column_stack([gx.ravel(), gy.ravel()])).reshape(gx.shape)
        value, fx, fy = surface(gx, gy)
        margin = np.abs(value + ALLOWANCE - z) / np.maximum(np.hypot(fx, fy), 1e-12) > 0.01
        wrong = margin & (inside_any != (value + ALLOWANCE > z))
        if wrong.any():
            raise RuntimeError(f"level {z}: the loops enclose another region than f + a > z ({int(wrong.sum())} "
                               "grid points)")
    if worst > CONTOUR_FIT:
        raise RuntimeError(f"a spline wall is {worst:.3g} mm off its contour (allowed {CONTOUR_FIT})")
    return worst


def unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def semi_finishing():
    """[(CL points (73, 3), axes (73, 3))] of the passes, part coordinates (mm), in machining order."""
    radius, corner = 0.5 * DIAMETER, CORNER
    passes = []
    for j, y in enumerate(PASS_Y):
        x = PASS_X if j % 2 == 0 else PASS_X[::-1]
        yy = np.full(x.shape, y)
        z, fx, fy = surface(x, yy)
        contact = np.column_stack([x, yy, z + FINISH_ALLOWANCE])
        normal = unit(np.column_stack([-fx, -fy, np.ones_like(x)]))
        along = np.array([1.0 if j % 2 == 0 else -1.0, 0.0, 0.0])
        feed = unit(along - (normal @ along)[:, None] * normal)
        side = np.cross(normal, feed)
        lead, tilt = np.radians(LEAD), np.radians(TILT * np.sin(2.0 * np.pi * (x - 6.0) / 108.0 + 0.9 * j))
        axis = unit(np.cos(lead) * np.cos(tilt)[:, None] * normal + np.sin(lead) * feed
                    + np.cos(lead) * np.sin(tilt)[:, None] * side)
        radial = -(normal - np.einsum("ij,ij->i", normal, axis)[:, None] * axis)
        radial = unit(radial)
        cl = contact + corner * normal - corner * axis - (radius - corner) * radial
        passes.append((cl, axis))
    return passes


def cls_text(passes):
    """The operation as NX writes a CLSF (file coordinates: part minus the MSYS origin)."""
    def goto(point, axis):
        p = point - MCS
        return (f"GOTO/{p[0]:.4f},{p[1]:.4f},{p[2]:.4f},{axis[0]:.7f},{axis[1]:.7f},{axis[2]:.7f}")

    lines = [
        "TOOL PATH/VARIABLE_CONTOUR_SEMI,TOOL,BN16R3",
        f"TLDATA/MILL,{DIAMETER:.4f},{CORNER:.4f},{TOOL_LENGTH:.4f},0.0000,0.0000",
        f"MSYS/{MCS[0]:.4f},{MCS[1]:.4f},{MCS[2]:.4f},1.0000000,0.0000000,0.0000000,0.0000000,1.0000000,0.0000000",
        "$$ centerline data",
        "PAINT/PATH",
        "PAINT/SPEED,10",
        "LOAD/TOOL,1",
        f"SPINDL/RPM,{SPINDLE:.1f},CLW",
    ]
    for j, (cl, axis) in enumerate(passes):
        approach = cl[0] + CLEAR * axis[0]
        lines += ["PAINT/COLOR,186", "RAPID", goto(approach + np.array([0.0, 0.0, 10.0]), axis[0]), "RAPID",
                  goto(approach, axis[0]), "PAINT/COLOR,211", f"FEDRAT/MMPM,{ENGAGE_FEED:.4f}", goto(cl[0], axis[0]),
                  "PAINT/COLOR,31", f"FEDRAT/MMPM,{FEED:.4f}"]
        lines += [goto(p, a) for p, a in zip(cl[1:], axis[1:])]
        lines += ["PAINT/COLOR,37", goto(cl[-1] + CLEAR * axis[-1], axis[-1])]
    lines += ["PAINT/SPEED,10", "PAINT/TOOL,NOMORE", "END-OF-PATH", ""]
    return "\n".join(lines)


def check_program(path, passes):
    """Read the written CLSF back with the project's reader: one bull-nose operation D16 R3 whose cutting CL
    points are every pass's points and its retract, with their axes, as written (to the file's 4 and 7
    decimals; the engage moves come after a rapid, as in NX: the first point of each pass is a cutting
    move's end). Returns the operation."""
    from abm_workbench.formats.cl import read_program

    program = read_program(str(path))
    if len(program.operations) != 1:
        raise RuntimeError(f"{path}: {len(program.operations)} operations, expected 1")
    operation = program.operations[0]
    tool = operation.tool
    if (tool.kind, tool.diameter, tool.corner_radius) != ("bull-nose", DIAMETER, CORNER):
        raise RuntimeError(f"{path}: read the tool as {tool.describe()}")
    points, axes = operation.points_part, operation.axes_part
    written = np.concatenate([np.vstack([cl, cl[-1] + CLEAR * axis[-1]]) for cl, axis in passes])
    written_axes = np.concatenate([np.vstack([axis, axis[-1]]) for _, axis in passes])
    if points.shape != written.shape or np.abs(points - written).max() > 6e-5:
        raise RuntimeError(f"{path}: {len(points)} cutting CL points read, not the {len(written)} written")
    if np.abs(axes - written_axes).max() > 1e-6:
        raise RuntimeError(f"{path}: the axes are not read back as written")
    return operation


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    stock, contours = roughed_stock()
    deviation = check_contours(contours)
    dump_terraced(stock, OUT / "stock.json")
    solid = terraced_solid(stock)
    export_step(solid, OUT / "stock.step")
    passes = semi_finishing()
    (OUT / "toolpath.cls").write_text(cls_text(passes))
    operation = check_program(OUT / "toolpath.cls", passes)
    axes = np.concatenate([a for _, a in passes])
    lean = np.degrees(np.arccos(np.clip(axes[:, 2], -1.0, 1.0)))
    job = {
        "description": (
            "Model test 5: a two-bump part roughed in z-levels 6.5 to 21.5 mm (step-down 2.5, allowance 1 mm; "
            "closed B-spline walls, abm-terraced/1), semi-finished by a D16 R3 bull-nose mill in a five-axis "
            f"raster of {len(PASS_Y)} zig-zag passes along x (stepover 8 mm), the axis led 10 deg and tilted "
            "+-8 deg from the surface normal, NX CLSF (TOOL PATH, TLDATA/MILL, MSYS, GOTO/x,y,z,i,j,k). "
            "Generated by resources/models/make_model_test_5.py."),
        "flutes": FLUTES, "flute_length": FLUTE_LENGTH, "feed_per_tooth": FEED / (SPINDLE * FLUTES),
        "phi_range": [0, 180], "phi_step": 2,
    }
    (OUT / "job.json").write_text(json.dumps(job, indent=1) + "\n")
    print(f"wrote {OUT}: {len(stock.slabs)} slabs ({sum(len(s.loops) for s in stock.slabs[1:])} spline walls, "
          f"within {deviation:.2g} mm of their contours), solid volume {solid.Volume:.1f} mm3, "
          f"{len(operation.points_part)} cutting CL points in {len(PASS_Y)} passes, axes {lean.min():.2f}.."
          f"{lean.max():.2f} deg from vertical")


if __name__ == "__main__":
    main()
