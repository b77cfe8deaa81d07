"""formats.terraced_json: abm-terraced/1 read back as written, and errors naming file and JSON path."""

import json

import numpy as np
import pytest

from abm_workbench.engine.terraced_model import Loop, PlanArc, PlanLine, PlanSpline, Slab, TerracedStock
from abm_workbench.errors import InputError
from abm_workbench.formats.terraced_json import dump_terraced, load_terraced


def example_stock():
    """Two slabs: a square with a round hole holding a spline island, then a stadium."""
    square = Loop(tuple(PlanLine(a, b, "Face1") for a, b in
                        [((0, 0), (10, 0)), ((10, 0), (10, 10)), ((10, 10), (0, 10)), ((0, 10), (0, 0))]))
    hole = Loop((PlanArc((5, 5), 3.0, 0.25, 2 * np.pi, "Face2"),))
    control = np.array([[4.0, 5.0], [5.0, 3.5], [6.0, 5.0], [5.0, 6.5], [4.0, 5.0]])
    island = Loop((PlanSpline(2, [0, 0, 0, 0.4, 0.6, 1, 1, 1], control, [1, 0.7, 1.2, 0.9, 1]),))
    stadium = Loop((PlanLine((3, 4), (7, 4)), PlanArc((7, 5), 1.0, -np.pi / 2, np.pi),
                    PlanLine((7, 6), (3, 6)), PlanArc((3, 5), 1.0, np.pi / 2, np.pi)))
    return TerracedStock((Slab(-2.0, 1.5, (square, hole, island)), Slab(1.5, 4.0, (stadium,))))


def test_round_trip(tmp_path):
    stock = example_stock()
    path = tmp_path / "stock.json"
    dump_terraced(stock, path)
    again = load_terraced(path)
    assert json.loads(path.read_text())["format"] == "abm-terraced/1"
    assert again.levels.tolist() == stock.levels.tolist()
    for a, b in zip(stock.slabs, again.slabs):
        for la, lb in zip(a.loops, b.loops):
            for ca, cb in zip(la.curves, lb.curves):
                assert type(ca) is type(cb) and ca.face == cb.face
                if isinstance(ca, PlanArc):
                    assert np.allclose([ca.start_angle, ca.sweep], [cb.start_angle, cb.sweep], rtol=1e-15, atol=1e-15)
                    assert ca.center.tolist() == cb.center.tolist() and ca.radius == cb.radius
                elif isinstance(ca, PlanLine):
                    assert ca.start.tolist() == cb.start.tolist() and ca.end.tolist() == cb.end.tolist()
                else:
                    assert ca.knots.tolist() == cb.knots.tolist() and ca.control.tolist() == cb.control.tolist()
                    assert ca.weights.tolist() == cb.weights.tolist()


def write(tmp_path, data):
    path = tmp_path / "stock.json"
    path.write_text(json.dumps(data))
    return path


def valid():
    return {"format": "abm-terraced/1", "units": "mm", "base_z": 0, "slabs": [
        {"z_top": 2, "loops": [[
            {"type": "line", "start": [0, 0], "end": [4, 0]},
            {"type": "line", "start": [4, 0], "end": [4, 3]},
            {"type": "arc", "center": [2, 3], "radius": 2, "start_angle": 0, "sweep": 180},
            {"type": "line", "start": [0, 3], "end": [0, 0]}]]}]}


def test_valid_example_loads(tmp_path):
    stock = load_terraced(write(tmp_path, valid()))
    assert len(stock.slabs) == 1 and len(stock.slabs[0].loops[0].curves) == 4


@pytest.mark.parametrize("change, message", [
    (lambda d: d.update(format="abm-staircase/1"), "format must be 'abm-terraced/1'"),
    (lambda d: d.update(units="inch"), "units must be 'mm'"),
    (lambda d: d.update(extra=1), "unknown key 'extra'"),
    (lambda d: d["slabs"][0].update(z_top=-1), r"slabs\[0\]: z_top -1.0 must be above z_bottom"),
    (lambda d: d["slabs"][0]["loops"][0][2].update(radius="2"), r"slabs\[0\].loops\[0\]\[2\].radius: must be a number"),
    (lambda d: d["slabs"][0]["loops"][0][2].update(type="circle"), r"slabs\[0\].loops\[0\]\[2\].type: must be"),
    (lambda d: d["slabs"][0]["loops"][0][0].update(end=[4, 0, 1]), r"loops\[0\]\[0\].end: expected an \[x, y\] pair"),
    (lambda d: d["slabs"][0]["loops"][0][3].update(end=[0, 1]), r"slabs\[0\].loops\[0\]: curves\[3\] ends at"),
    (lambda d: d["slabs"][0]["loops"][0].append({"type": "spline", "degree": 2, "knots": [0, 1],
                                                  "control": [[0, 0], [1, 1], [2, 0]]}),
     r"slabs\[0\].loops\[0\]\[4\]: knots must have"),
    (lambda d: d["slabs"][0].update(loops=[]), r"slabs\[0\].loops: must be a non-empty list"),
])
def test_errors_name_file_and_path(tmp_path, change, message):
    data = valid()
    change(data)
    with pytest.raises(InputError, match=message) as raised:
        load_terraced(write(tmp_path, data))
    assert str(raised.value).startswith(str(tmp_path / "stock.json"))


def test_failed_write_leaves_no_file(tmp_path):
    path = tmp_path / "out.json"
    with pytest.raises(AttributeError):
        dump_terraced("not a stock", path)
    assert not path.exists() and list(tmp_path.iterdir()) == []
