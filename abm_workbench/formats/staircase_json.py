"""Staircase stock as JSON, format ``abm-staircase/1`` (lengths in mm).

    {"format": "abm-staircase/1", "units": "mm", "base_z": -20,
     "x_min": 0, "x_max": 130, "y_min": -15, "y_max": 15,
     "sections": [{"z_top": 4.0},
                  {"z_top": 6.5, "wall": [[x0, y0], [x1, y1], ..., [x5, y5]]}, ...]}

Sections are ordered along +x. Section 0 starts at x_min and has no wall; section j ≥ 1
starts at its wall, the curve x = P(y) through six [x, y] points on the wall's top edge.
"""

import json
import os

from ..engine import Staircase
from ..errors import InputError
from . import check_keys, json_number, load_json_object, replacing

FORMAT = "abm-staircase/1"
_LIMITS = ("base_z", "x_min", "x_max", "y_min", "y_max")
_TOP_KEYS = ("format", "units", *_LIMITS, "sections")


def load_staircase(path):
    """Read a staircase file into a :class:`Staircase`; InputError naming file and item."""
    name = os.fspath(path)
    data = load_json_object(path)
    if "format" not in data:
        raise InputError(f"{name}: missing key 'format' (a staircase file starts with \"format\": \"{FORMAT}\")")
    if data["format"] != FORMAT:
        raise InputError(f"{name}: format must be {FORMAT!r}, got {json.dumps(data['format'])}")
    check_keys(data, _TOP_KEYS, (), name)
    if data["units"] != "mm":
        raise InputError(f"{name}: units must be 'mm', got {json.dumps(data['units'])}")
    limits = {key: json_number(data[key], f"{name}: {key}") for key in _LIMITS}
    sections = data["sections"]
    if not isinstance(sections, list) or not sections:
        raise InputError(f"{name}: sections must be a non-empty list of sections, got {json.dumps(sections)}")
    z_top, walls = [], []
    for j, section in enumerate(sections):
        where = f"{name}: sections[{j}]"
        if not isinstance(section, dict):
            raise InputError(f"{where}: expected an object {{\"z_top\": ...}}, got {json.dumps(section)}")
        if j == 0 and "wall" in section:
            raise InputError(f"{where}: the first section starts at x_min and must not have a wall")
        check_keys(section, ("z_top",) if j == 0 else ("z_top", "wall"), (), where)
        z_top.append(json_number(section["z_top"], f"{where}.z_top"))
        if j:
            walls.append(_wall_points(section["wall"], f"{where}.wall"))
    try:
        return Staircase(z_top=z_top, wall_points=walls, **limits)
    except ValueError as error:
        raise InputError(f"{name}: {error}") from None


def _wall_points(wall, where):
    """Six [x, y] pairs of finite numbers as a list of [float, float]."""
    if not isinstance(wall, list) or len(wall) != 6:
        got = f"{len(wall)} items" if isinstance(wall, list) else json.dumps(wall)
        raise InputError(f"{where}: a wall needs six [x, y] points, got {got}")
    points = []
    for k, point in enumerate(wall):
        if not isinstance(point, list) or len(point) != 2:
            raise InputError(f"{where}[{k}]: expected an [x, y] pair, got {json.dumps(point)}")
        points.append([json_number(value, f"{where}[{k}][{c}]") for c, value in enumerate(point)])
    return points


def dump_staircase(stock, path):
    """Write `stock` (a Staircase) to `path` as ``abm-staircase/1`` JSON, atomically.

    Numbers are written with Python's shortest round-trip repr, so load_staircase gives
    back exactly the same values.
    """
    sections = [{"z_top": float(stock.z_top[0])}]
    for z, points in zip(stock.z_top[1:], stock.wall_points):
        sections.append({"z_top": float(z), "wall": points.tolist()})
    head = {"format": FORMAT, "units": "mm", **{key: getattr(stock, key) for key in _LIMITS}}
    lines = [f"  {json.dumps(key)}: {json.dumps(value)}," for key, value in head.items()]
    body = ",\n".join(f"    {json.dumps(section)}" for section in sections)
    text = "{\n" + "\n".join(lines) + '\n  "sections": [\n' + body + "\n  ]\n}\n"
    with replacing(path) as (temporary,):
        with open(temporary, "w", encoding="utf-8") as file:
            file.write(text)
