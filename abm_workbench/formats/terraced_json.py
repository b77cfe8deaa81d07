"""Terraced stock as JSON, format ``abm-terraced/1`` (lengths in mm, angles in degrees).

    {"format": "abm-terraced/1", "units": "mm", "base_z": -10,
     "slabs": [
       {"z_top": 0, "loops": [[curve, curve, ...], ...]},
       ...]}

Slabs go from the base up: slab 0 spans base_z .. its z_top, slab k the previous z_top .. its
own. A slab's region is filled by the even-odd rule from its closed loops (an outer contour, a
pocket inside it, an island inside the pocket, …; no orientation needed). A loop is a list of
curves, each starting where the one before ends, the last ending where the first starts:

    {"type": "line", "start": [x, y], "end": [x, y]}
    {"type": "arc", "center": [x, y], "radius": r, "start_angle": a, "sweep": s}
        (degrees; counter-clockwise positive; sweep 360: a full circle)
    {"type": "spline", "degree": p, "knots": [...], "control": [[x, y], ...]}
        (a clamped B-spline; optional "weights": [...] makes it rational)

Any curve may carry "face": "name" (the solid's face it came from). Errors name the file and
the JSON path of the item, e.g. ``stock.json: slabs[2].loops[0][3].radius: ...``.
"""

import json
import os

import numpy as np

from ..engine.terraced_model import Loop, PlanArc, PlanLine, PlanSpline, Slab, TerracedStock
from ..errors import InputError, note
from . import check_keys, json_number, load_json_object, replacing

FORMAT = "abm-terraced/1"
_CURVE_KEYS = {
    "line": (("type", "start", "end"), ("face",)),
    "arc": (("type", "center", "radius", "start_angle", "sweep"), ("face",)),
    "spline": (("type", "degree", "knots", "control"), ("weights", "face")),
}


def _list(value, where, what):
    """`value` if it is a non-empty JSON list, else InputError saying `what` it must be."""
    if not isinstance(value, list) or not value:
        raise InputError(f"{where}: must be {what}, got {json.dumps(value)}")
    return value


def _point(value, where):
    """An [x, y] pair of finite numbers."""
    if not isinstance(value, list) or len(value) != 2:
        raise InputError(f"{where}: expected an [x, y] pair, got {json.dumps(value)}")
    return [json_number(v, f"{where}[{c}]") for c, v in enumerate(value)]


def _curve(data, where):
    """One plan curve of a loop."""
    if not isinstance(data, dict):
        raise InputError(f"{where}: expected a curve object {{\"type\": ...}}, got {json.dumps(data)}")
    kind = data.get("type")
    if kind not in _CURVE_KEYS:
        raise InputError(f"{where}.type: must be \"line\", \"arc\" or \"spline\", got {json.dumps(kind)}")
    check_keys(data, *_CURVE_KEYS[kind], where)
    face = data.get("face", "")
    if not isinstance(face, str):
        raise InputError(f"{where}.face: must be a string, got {json.dumps(face)}")
    try:
        if kind == "line":
            return PlanLine(_point(data["start"], f"{where}.start"), _point(data["end"], f"{where}.end"), face)
        if kind == "arc":
            return PlanArc(_point(data["center"], f"{where}.center"), json_number(data["radius"], f"{where}.radius"),
                           np.radians(json_number(data["start_angle"], f"{where}.start_angle")),
                           np.radians(json_number(data["sweep"], f"{where}.sweep")), face)
        knots = [json_number(v, f"{where}.knots[{i}]") for i, v in enumerate(_list(data["knots"], f"{where}.knots",
                                                                                    note("a list of numbers")))]
        control = [_point(v, f"{where}.control[{i}]") for i, v in enumerate(_list(data["control"], f"{where}.control",
                                                                                   note("a list of [x, y] points")))]
        weights = None
        if "weights" in data:
            weights = [json_number(v, f"{where}.weights[{i}]")
                       for i, v in enumerate(_list(data["weights"], f"{where}.weights", note("a list of numbers")))]
        degree = data["degree"]
        if isinstance(degree, bool) or not isinstance(degree, int):
            raise InputError(f"{where}.degree: must be a whole number, got {json.dumps(degree)}")
        return PlanSpline(degree, knots, control, weights, face)
    except ValueError as error:
        if isinstance(error, InputError):
            raise
        raise InputError(f"{where}: {error}") from None


def load_terraced(path):
    """Read an abm-terraced/1 file into a TerracedStock; InputError naming file and JSON path."""
    name = os.fspath(path)
    data = load_json_object(path)
    if data.get("format") != FORMAT:
        raise InputError(f"{name}: format must be {FORMAT!r}, got {json.dumps(data.get('format'))}")
    check_keys(data, ("format", "units", "base_z", "slabs"), (), name)
    if data["units"] != "mm":
        raise InputError(f"{name}: units must be 'mm', got {json.dumps(data['units'])}")
    bottom = json_number(data["base_z"], f"{name}: base_z")
    slabs = []
    for k, slab in enumerate(_list(data["slabs"], f"{name}: slabs", note("a non-empty list of slabs"))):
        where = f"{name}: slabs[{k}]"
        if not isinstance(slab, dict):
            raise InputError(f"{where}: expected an object {{\"z_top\": ..., \"loops\": [...]}}, got {json.dumps(slab)}")
        check_keys(slab, ("z_top", "loops"), (), where)
        z_top = json_number(slab["z_top"], f"{where}.z_top")
        loops = []
        for i, loop in enumerate(_list(slab["loops"], f"{where}.loops", note("a non-empty list of loops"))):
            curves = [_curve(c, f"{where}.loops[{i}][{c_index}]")
                      for c_index, c in enumerate(_list(loop, f"{where}.loops[{i}]",
                                                        note("a non-empty list of curves")))]
            try:
                loops.append(Loop(tuple(curves)))
            except ValueError as error:
                raise InputError(f"{where}.loops[{i}]: {error}") from None
            _check_area(loops[-1], f"{where}.loops[{i}]")
        _check_distinct(loops, where)
        try:
            slabs.append(Slab(bottom, z_top, tuple(loops)))
        except ValueError as error:
            raise InputError(f"{where}: {error}") from None
        bottom = z_top
    return TerracedStock(tuple(slabs))


#: Points along each arc and spline of a loop for its area.
_AREA_SAMPLES = 64
#: A loop whose area is below this fraction of its bounding box's encloses no material.
_THIN = 1e-9


def _loop_points(loop):
    """(k, 2) points around `loop` (mm), in order: lines' ends, arcs and splines sampled."""
    from scipy.interpolate import BSpline

    points = []
    for curve in loop.curves:
        if isinstance(curve, PlanLine):
            points.append(curve.start[None, :])
        elif isinstance(curve, PlanArc):
            points.append(curve.at(curve.start_angle + curve.sweep * np.linspace(0.0, 1.0, _AREA_SAMPLES,
                                                                                 endpoint=False)))
        else:
            n, degree = len(curve.control), curve.degree
            knots = np.array(curve.knots, dtype=float)  # writable copies: scipy's evaluation refuses read-only arrays
            t = np.linspace(knots[degree], knots[n], _AREA_SAMPLES, endpoint=False)
            weights = np.ones(n) if curve.weights is None else np.array(curve.weights, dtype=float)
            numerator = BSpline(knots, curve.control * weights[:, None], degree)(t)
            points.append(numerator / BSpline(knots, weights, degree)(t)[:, None])
    return np.concatenate(points)


def _check_area(loop, where):
    """InputError unless `loop` encloses some area (a loop that goes out and back along the same path
    encloses none: a region of zero area, which no solid has)."""
    points = _loop_points(loop)
    x, y = points[:, 0] - points[:, 0].mean(), points[:, 1] - points[:, 1].mean()
    area = 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
    box = float(np.ptp(points[:, 0])) * float(np.ptp(points[:, 1]))
    if not area > _THIN * max(box, np.ptp(points, axis=0).max() ** 2):
        raise InputError(f"{where}: encloses no area ({area:.3g} mm²): a loop must bound a region")


def _check_distinct(loops, where):
    """InputError when two loops of a slab are the same contour: by the even-odd rule they cancel, and
    leave a region of zero area between them."""
    seen = {}
    for i, loop in enumerate(loops):
        key = tuple(sorted(tuple(np.round(_loop_points(loop), 9).ravel())))
        if key in seen:
            raise InputError(f"{where}.loops[{i}]: the same contour as loops[{seen[key]}]; by the even-odd rule "
                             "the two cancel and bound no region")
        seen[key] = i


def _curve_json(curve):
    """The JSON object of one plan curve."""
    if isinstance(curve, PlanLine):
        data = {"type": "line", "start": curve.start.tolist(), "end": curve.end.tolist()}
    elif isinstance(curve, PlanArc):
        data = {"type": "arc", "center": curve.center.tolist(), "radius": curve.radius,
                "start_angle": float(np.degrees(curve.start_angle)), "sweep": float(np.degrees(curve.sweep))}
    else:
        data = {"type": "spline", "degree": curve.degree, "knots": curve.knots.tolist(),
                "control": curve.control.tolist()}
        if curve.weights is not None:
            data["weights"] = curve.weights.tolist()
    if curve.face:
        data["face"] = curve.face
    return data


def dump_terraced(stock, path):
    """Write `stock` (a TerracedStock) to `path` as abm-terraced/1 JSON, atomically: one curve a line.

    Lengths are written with Python's shortest round-trip repr (read back exactly); arc angles
    are converted to degrees and back, exact to rounding.
    """
    slabs = []
    for slab in stock.slabs:
        loops = ",\n".join("        [\n" + ",\n".join(f"          {json.dumps(_curve_json(c))}" for c in loop.curves)
                           + "\n        ]" for loop in slab.loops)
        slabs.append(f'    {{"z_top": {json.dumps(slab.z_top)}, "loops": [\n{loops}\n    ]}}')
    text = (f'{{\n  "format": "{FORMAT}",\n  "units": "mm",\n  "base_z": {json.dumps(stock.base_z)},\n'
            f'  "slabs": [\n' + ",\n".join(slabs) + "\n  ]\n}\n")
    with replacing(path) as (temporary,):
        with open(temporary, "w", encoding="utf-8") as file:
            file.write(text)
