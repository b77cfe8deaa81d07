"""Five-axis G-code read back to the CL points it was made from (tip 1e-4 mm, axis 1e-6), for the
kinematics a machine file names, with the tool centre point control on and off. The G-code is made
here by a forward kinematics of the test's own (scipy's rotations, the machine's chain followed from
the part to the spindle), never by the reader's inverse."""

import json

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from abm_workbench.errors import InputError
from abm_workbench.formats.cl import read_program
from abm_workbench.formats.gcode.options import ReadOptions

PIVOT, C_OFFSET = np.array([250.0, -120.0, -310.0]), np.array([3.0, -40.0, 25.0])
P_LENGTH, TOOL_LENGTH, C_AXIS = 180.0, 65.0, np.array([310.0, 140.0])
MACHINES = {
    "xyzac-trt": {"kinematics": "xyzac-trt", "pivot": PIVOT.tolist(), "c_offset": C_OFFSET.tolist()},
    "xyzbc-trt": {"kinematics": "xyzbc-trt", "pivot": PIVOT.tolist(), "c_offset": C_OFFSET.tolist()},
    "xyzbc-ht": {"kinematics": "xyzbc-ht", "pivot_length": P_LENGTH, "c_axis": C_AXIS.tolist()},
}
TCP_ON = {"G43.4 H1": "G49", "M128": "M129", "TRAORI": "TRAFOOF", "TCPM": "TCPM OFF"}
Z = np.array([0.0, 0.0, 1.0])


def turn(axis, degrees):
    """The rotation by `degrees` about "x", "y" or "z", by scipy."""
    return Rotation.from_euler(axis, degrees, degrees=True)


def tilt_letter(kind):
    return "A" if kind == "xyzac-trt" else "B"


def axis_in_part(kind, tilt, spin):
    """The tool axis in the part frame: the spindle's +Z carried back through the machine's turns."""
    if kind == "xyzbc-ht":  # the head turns the tool by B; the table turns the part by C
        return turn("z", -spin).apply(turn("y", tilt).apply(Z))
    table = turn("z", spin) * Rotation.identity()  # C rides on the tilting table
    tilting = turn("x" if kind == "xyzac-trt" else "y", tilt)
    return (tilting * table).inv().apply(Z)


def machine_position(kind, tip, tilt, spin):
    """X Y Z a machine without TCP is told for the part-frame tool tip `tip` at the rotary angles: the part
    point carried through the table turns (about their own axis lines) into the machine, and on the
    head-table machine the tip's offset from the head's pivot taken back to B = 0."""
    if kind == "xyzbc-ht":
        centre = np.array([C_AXIS[0], C_AXIS[1], 0.0])
        in_machine = turn("z", spin).apply(tip - centre) + centre
        head = turn("y", tilt).apply(Z)
        return in_machine + (P_LENGTH + TOOL_LENGTH) * (head - Z)
    c_point = PIVOT + C_OFFSET
    on_c = turn("z", spin).apply(tip - c_point) + c_point
    return turn("x" if kind == "xyzac-trt" else "y", tilt).apply(on_c - PIVOT) + PIVOT


def cl_points(seed, count=40):
    """(tips (n, 3) mm, tilt and spin angles (n,) deg) of random CL points."""
    rng = np.random.default_rng(seed)
    return rng.uniform(-80, 80, (count, 3)), rng.uniform(-80, 80, count), rng.uniform(-360, 360, count)


def write(tmp_path, kind, lines):
    """Write the machine file, the tool table and the program; the Program read."""
    (tmp_path / "machine.json").write_text(json.dumps(MACHINES[kind]))
    (tmp_path / "tools.tbl").write_text(f"T1 P1 D10 Z{TOOL_LENGTH} ;10 mm end mill\n")
    (tmp_path / "five.ngc").write_text("\n".join(["G21 G90 G94", "T1 M6", *lines, "M30"]) + "\n")
    options = ReadOptions(tool_table=str(tmp_path / "tools.tbl"), machine=str(tmp_path / "machine.json"))
    return read_program(str(tmp_path / "five.ngc"), options=options)


def assert_read_back(operation, tips, axes):
    np.testing.assert_allclose(operation.points_part, tips, rtol=0, atol=1e-4)
    np.testing.assert_allclose(operation.axes_part, axes, rtol=0, atol=1e-6)


@pytest.mark.parametrize("kind", MACHINES)
@pytest.mark.parametrize("on, off", list(TCP_ON.items()))
def test_with_tcp_the_words_are_the_tip_and_the_rotary_words_the_axis(tmp_path, kind, on, off):
    tips, tilts, spins = cl_points(1)
    letter = tilt_letter(kind)
    lines = [on, f"G0 X{tips[0][0]:.6f} Y{tips[0][1]:.6f} Z{tips[0][2] + 50:.6f} {letter}{tilts[0]:.8f} "
                 f"C{spins[0]:.8f}", "F500"]
    lines += [f"G1 X{x:.6f} Y{y:.6f} Z{z:.6f} {letter}{a:.8f} C{c:.8f}" for (x, y, z), a, c in zip(tips, tilts, spins)]
    operation = write(tmp_path, kind, lines + [off]).operations[0]
    axes = np.array([axis_in_part(kind, a, c) for a, c in zip(tilts, spins)])
    assert_read_back(operation, tips, axes)
    assert f"{kind}, TCP on" in operation.frame


@pytest.mark.parametrize("kind", MACHINES)
def test_without_tcp_the_inverse_kinematics_with_the_offsets_and_the_tool_length(tmp_path, kind):
    tips, tilts, spins = cl_points(2)
    letter = tilt_letter(kind)
    moves = [machine_position(kind, tip, a, c) for tip, a, c in zip(tips, tilts, spins)]
    lines = ["G0 Z500", "F800"]
    lines += [f"G1 X{x:.6f} Y{y:.6f} Z{z:.6f} {letter}{a:.8f} C{c:.8f}" for (x, y, z), a, c in zip(moves, tilts, spins)]
    operation = write(tmp_path, kind, lines).operations[0]
    axes = np.array([axis_in_part(kind, a, c) for a, c in zip(tilts, spins)])
    assert_read_back(operation, tips, axes)
    assert f"{kind}, TCP off" in operation.frame


def test_the_axis_formula_of_the_ac_table_machine(tmp_path):
    """xyzac-trt: A about +X, C about +Z, the table turning the part: the axis is Rz(−C)·Rx(−A)·(0, 0, 1)."""
    operation = write(tmp_path, "xyzac-trt", ["G43.4 H1", "G0 X0 Y0 Z50 A30 C90", "G1 Z0 F100", "G49"]).operations[0]
    a, c = np.radians(30), np.radians(90)
    rx = np.array([[1, 0, 0], [0, np.cos(-a), -np.sin(-a)], [0, np.sin(-a), np.cos(-a)]])
    rz = np.array([[np.cos(-c), -np.sin(-c), 0], [np.sin(-c), np.cos(-c), 0], [0, 0, 1]])
    np.testing.assert_allclose(operation.axes_part[0], rz @ rx @ Z, rtol=0, atol=1e-12)
    np.testing.assert_allclose(operation.axes_part[0], [0.5, 0, np.sqrt(3) / 2], rtol=0, atol=1e-12)


def test_rotary_words_need_the_machines_axes_and_a_head_needs_a_tool_length(tmp_path):
    with pytest.raises(InputError, match=r"five.ngc:4: B10: the machine xyzac-trt has no B axis"):
        write(tmp_path, "xyzac-trt", ["G0 X0 Y0 Z0", "G1 X1 B10 F100"])
    (tmp_path / "notool.tbl").write_text("T1 P1 D10 ;no length\n")
    (tmp_path / "machine.json").write_text(json.dumps(MACHINES["xyzbc-ht"]))
    (tmp_path / "five.ngc").write_text("T1 M6\nG0 X0 Y0 Z0 B10\nG1 X1 F100\n")
    options = ReadOptions(tool_table=str(tmp_path / "notool.tbl"), machine=str(tmp_path / "machine.json"))
    with pytest.raises(InputError, match=r"five.ngc:2: TCP off: the xyzbc-ht machine turns the tool about its pivot: "
                                         r"the tool's length is needed"):
        read_program(str(tmp_path / "five.ngc"), options=options)


@pytest.mark.parametrize("content, words", [
    ({"pivot": [0, 0, 0]}, "missing key 'kinematics'"),
    ({"kinematics": "xyzab-tdr"}, "kinematics: expected one of xyzac-trt, xyzbc-trt, xyzbc-ht, got 'xyzab-tdr'"),
    ({"kinematics": "xyzac-trt", "pivot": [0, 0]}, "pivot: must be a list of 3 numbers"),
    ({"kinematics": "xyzac-trt", "pivot_length": 3}, "unknown key 'pivot_length'"),
])
def test_bad_machine_files(tmp_path, content, words):
    (tmp_path / "machine.json").write_text(json.dumps(content))
    (tmp_path / "five.ngc").write_text("G0 X0 Y0 Z0\n")
    with pytest.raises(InputError, match=words):
        read_program(str(tmp_path / "five.ngc"), options=ReadOptions(machine=str(tmp_path / "machine.json")))
