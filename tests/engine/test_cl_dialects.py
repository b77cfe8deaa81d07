"""formats.cl on fixtures written in each CAM system's dialect (tests/fixtures/cl): operations,
tools, frames, units, arcs and curves, every value checked against numbers worked out by hand
from the fixture's own records."""

import math
from pathlib import Path

import numpy as np
import pytest

from abm_workbench.errors import InputError
from abm_workbench.formats.cl import OperationChoiceError, read_program

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures" / "cl"
INCH = 25.4


def read(name, **kwargs):
    return read_program(FIXTURES / name, **kwargs)


def rows_of(op, line):
    """The cutting points of `op` written by the record on `line`."""
    return op.points_file[op.lines == line]


def assert_ends_in_order(op, ends):
    """Each (line, point) of `ends` is the last cutting point of that record, lines in file order."""
    assert list(dict.fromkeys(op.lines.tolist())) == [line for line, _ in ends]
    for line, point in ends:
        np.testing.assert_allclose(rows_of(op, line)[-1], point, rtol=0, atol=1e-12)


def test_nx_clsf_operations_tools_msys_arcs_and_nurbs():
    program = read("nx_two_ops.clsf")
    assert [op.name for op in program.operations] == ["CAVITY_MILL", "VARIABLE_CONTOUR", "FLOOR_FINISH"]
    assert [op.tool.describe() for op in program.operations] == ["flat-end mill D10 mm", "ball mill D6 R3 mm",
                                                                 "flat-end mill D10 mm"]
    assert all(op.tool.flute_length is None for op in program.operations)  # TLDATA's 75 is the tool length
    assert program.ignored == {"TOOL PATH": (1, 3), "PAINT": (5, 5), "END-OF-PATH": (29, 3)}
    assert (program.unknown, program.warnings, program.units) == ({}, [], "mm")
    rough = program.operations[0]
    assert_ends_in_order(rough, [(14, [0, 0, 5]), (15, [20, 0, 5]), (17, [30, 10, 5]), (18, [40, 30, 5]),
                                 (27, [40, 40, 5])])
    assert (rough.arcs, rough.curves, rough.spindle_rpm, rough.feed_unit) == (1, 1, 6000.0, "MMPM")
    assert (rough.feed == 400.0).all()
    assert len(rough.rapids) == 1 and rough.rapids.lines.tolist() == [11]
    # The CIRCLE (centre (20, 10, 5), axis +z, r 10) from (20, 0) to (30, 10): a quarter turn counter-clockwise.
    arc = rows_of(rough, 17) - [20, 10, 5]
    np.testing.assert_allclose(np.hypot(arc[:, 0], arc[:, 1]), 10.0, rtol=0, atol=1e-12)
    np.testing.assert_allclose(arc[:, 2], 0.0, atol=1e-12)
    angle = np.arctan2(arc[:, 1], arc[:, 0])
    assert (np.diff(angle) > 0).all() and angle[0] > -math.pi / 2 and angle[-1] == 0.0
    # MSYS: origin (50, 0, 40), X = (1, 0, 0), Y = (0, -1, 0), so Z points down in the part.
    np.testing.assert_allclose(rough.points_part[0], [50, 0, 35], atol=1e-12)
    np.testing.assert_allclose(rough.axes_part, np.tile([0, 0, -1], (len(rough.lines), 1)), atol=1e-12)
    toolpath = rough.toolpath()  # the engine works in the MCS, where the tool points up
    np.testing.assert_allclose(toolpath.cl, rough.points_file, atol=1e-12)
    assert not toolpath.theta_a.any() and not toolpath.theta_b.any()
    contour = program.operations[1]
    # GOTO/x,y,z,i,j,k without MULTAX is position and axis; the three-number GOTO after keeps the axis.
    np.testing.assert_allclose(contour.axes_file, [[0, 0.6, 0.8], [0, 0.6, 0.8], [0, 0, 1]], atol=1e-15)
    assert contour.refusal() is None  # a ball mill is computed
    with pytest.raises(OperationChoiceError) as caught:
        program.operation()
    assert [op.number for op in caught.value.operations] == [1, 2, 3]
    assert "3 milling operations; choose one with --operation N" in str(caught.value)
    assert program.operation(3).lines.tolist() == [43, 44]
    assert [op.number for op in program.milling()] == [1, 2, 3]


def test_nx_nurbs_points_lie_on_the_cubic_and_keep_the_chord_error():
    rough = read("nx_two_ops.clsf").operations[0]
    points = rows_of(rough, 18)
    control = np.array([[30, 10, 5], [30, 20, 5], [40, 20, 5], [40, 30, 5]], dtype=float)
    t = np.linspace(0.0, 1.0, 20001)[:, None]
    bezier = ((1 - t) ** 3 * control[0] + 3 * (1 - t) ** 2 * t * control[1] + 3 * (1 - t) * t ** 2 * control[2]
              + t ** 3 * control[3])
    # Every point is on the curve (to the dense sampling's own spacing).
    nearest = np.array([np.linalg.norm(bezier - p, axis=1).min() for p in points])
    assert nearest.max() < 2e-3 / 2 and np.array_equal(points[-1], control[-1])
    # Every curve sample is within the tolerance of the chords.
    chords = np.vstack([[30, 10, 5], points])
    a, b = chords[:-1], chords[1:]
    worst = 0.0
    for sample in bezier[::7]:
        along = np.clip(np.einsum("ij,ij->i", sample - a, b - a) / np.einsum("ij,ij->i", b - a, b - a), 0, 1)
        worst = max(worst, np.linalg.norm(a + along[:, None] * (b - a) - sample, axis=1).min())
    assert worst <= 0.001


def test_catia_setups_csys_names_continuations_and_lower_case():
    program = read("catia_setups.aptsource")
    first, second = program.operations
    assert first.name == "Pocketing.1"
    assert second.name == "Profile Contouring.2 this comment goes on over a second line"
    assert first.tool.describe() == "flat-end mill D8 mm" and first.tool.flute_length is None
    assert (first.spindle_rpm, first.feed.tolist()) == (5000.0, [600.0] * 3)
    assert_ends_in_order(first, [(21, [0, 0, -2]), (22, [15, 0, -2]), (23, [15, 10, -2])])
    np.testing.assert_allclose(first.points_part, first.points_file + [10, 20, 0])
    assert_ends_in_order(second, [(36, [1, 2, 3]), (37, [6, 2, 3]), (38, [6, 8, 3])])
    # The second setup's matrix rows (0,0,-1 | 0), (0,1,0 | 0), (1,0,0 | 5): its Z is the part's -X.
    np.testing.assert_allclose(second.points_part[0], [-3, 2, 6], atol=1e-12)
    np.testing.assert_allclose(second.axes_part[0], [-1, 0, 0], atol=1e-12)
    np.testing.assert_allclose(second.axes_file[1], np.array([0, 0.1, 0.994987]) / np.linalg.norm([0, 0.1, 0.994987]))
    rotation, translation = second.engine_frame()
    np.testing.assert_allclose(second.points_part @ rotation.T + translation, second.points_file, atol=1e-12)
    assert set(program.ignored) == {"PARTNO", "TPRINT", "PPRINT", "STOP", "FINI"}
    assert program.unknown == {} and program.warnings == []


def test_creo_ncl_features_and_cutter_comment():
    program = read("creo_features.ncl.3")
    assert [op.name for op in program.operations] == ["feature 45", "feature 52"]
    assert [op.tool.diameter for op in program.operations] == [3.0, 6.0]
    assert [op.spindle_rpm for op in program.operations] == [12000.0, 8000.0]
    assert [op.feed.tolist() for op in program.operations] == [[500.0] * 3, [700.0] * 2]
    assert [len(op.rapids) for op in program.operations] == [2, 1]
    assert_ends_in_order(program.operations[1], [(27, [20, 0, -3]), (28, [30, 0, -3])])


def test_solidworks_cam_inch_circles_without_radius_and_flute_length():
    program = read("solidworks_cam_inch.clt")
    (op,) = program.operations
    assert program.units == "inch"
    assert (op.tool.kind, op.tool.diameter, op.tool.flute_length) == ("flat", 0.5 * INCH, 1.25 * INCH)
    assert op.spindle_rpm == pytest.approx(400 * 12 * INCH / (math.pi * 0.5 * INCH), rel=1e-14)
    np.testing.assert_allclose(op.feed[op.lines == 18], 15 * INCH)
    assert (op.feed[op.lines < 18] == 30 * INCH).all()
    z = -0.1 * INCH
    assert_ends_in_order(op, [(12, [INCH, 0, z]), (14, [INCH, 0, z]), (16, [0, INCH, z]), (18, [0, 2 * INCH, z])])
    # CIRCLE/0,0,-0.1,0,0,1 back to its start: a full turn counter-clockwise about +z.
    full = np.vstack([[INCH, 0, z], rows_of(op, 14)])
    turned = np.unwrap(np.arctan2(full[:, 1], full[:, 0]))
    assert turned[-1] == pytest.approx(2 * math.pi, abs=1e-12) and (np.diff(turned) > 0).all()
    # CIRCLE about -z from (1, 0) to (0, 1): three quarters clockwise seen from +z.
    three = np.vstack([[INCH, 0, z], rows_of(op, 16)])
    turned = np.unwrap(np.arctan2(three[:, 1], three[:, 0]))
    assert turned[-1] == pytest.approx(-1.5 * math.pi, abs=1e-12) and (np.diff(turned) < 0).all()
    for arc in (full, three):
        np.testing.assert_allclose(np.hypot(arc[:, 0], arc[:, 1]), INCH, rtol=1e-15)
        step = np.abs(np.diff(np.unwrap(np.arctan2(arc[:, 1], arc[:, 0]))))
        assert (INCH * (1 - np.cos(step / 2))).max() <= 0.001


def test_mastercam_unit_rapid_slash_trailing_commas_helix_and_drilling():
    program = read("mastercam_mill_drill.apt")
    mill, drill = program.operations
    assert mill.tool.describe() == "flat-end mill D12 mm" and mill.tool.flute_length is None
    assert_ends_in_order(mill, [(10, [30, 0, 0]), (12, [0, 30, -2]), (13, [0, 40, -2])])
    helix = np.vstack([[30, 0, 0], rows_of(mill, 12)])
    np.testing.assert_allclose(np.hypot(helix[:, 0], helix[:, 1]), 30.0, rtol=1e-15)
    angle = np.arctan2(helix[:, 1], helix[:, 0])
    np.testing.assert_allclose(helix[:, 2], -2 * angle / (math.pi / 2), atol=1e-12)
    assert drill.refusal() == ("operation 2: drill D6.8 mm: not a milling tool (the ABM engine computes flat-end, "
                               "bull-nose and ball-end mills)")
    assert (len(drill.lines), drill.cycle_points.lines.tolist(), drill.cycles) == (0, [20, 21, 22], ("DRILL",))
    assert program.operation() is mill


def test_powermill_indexed_axis_gets_its_own_frame():
    (op,) = read("powermill_indexed.cl").operations
    assert op.axes_file[:3].tolist() == [[0, -1, 0]] * 3 and op.axes_file[3:].tolist() == [[0, 0, 1]] * 2
    rotation, translation = op.engine_frame()
    # The rule for a file without frame records: Z is the mean of the five cutting axes.
    np.testing.assert_allclose(rotation[2], np.array([0, -3, 2]) / math.sqrt(13), atol=1e-12)
    toolpath = op.toolpath()
    tilt = np.degrees(np.arccos(np.array([3, 2]) / math.sqrt(13)))
    np.testing.assert_allclose(np.degrees(np.arccos(toolpath.axes[:, 2])), np.repeat(tilt, [3, 2]), atol=1e-12)


def test_a_single_horizontal_axis_is_the_operation_frame(tmp_path):
    path = tmp_path / "side"
    path.write_text("CUTTER/10\nTLAXIS/0,-1,0\nGOTO/0,20,0\nGOTO/30,20,0\n")
    op = read_program(path).operation()
    rotation, translation = op.engine_frame()
    np.testing.assert_allclose(rotation[2], [0, -1, 0], atol=1e-15)
    toolpath = op.toolpath()
    assert not toolpath.theta_a.any() and not toolpath.theta_b.any()
    np.testing.assert_allclose(toolpath.cl @ rotation - rotation.T @ translation, op.points_part, atol=1e-12)


def test_axes_beyond_a_half_space_are_taken_as_they_come(tmp_path):
    """Up, sideways and down in one operation: the engine takes every direction, in the file's frame."""
    path = tmp_path / "wild.cl"
    path.write_text("CUTTER/10\nGOTO/0,0,0,0,0,1\nGOTO/1,0,0,1,0,0\nGOTO/2,0,0,-1,0,0\nGOTO/3,0,0,0,0,-1\n")
    op = read_program(path).operation()
    toolpath = op.toolpath()
    np.testing.assert_allclose(toolpath.axes, [[0, 0, 1], [1, 0, 0], [-1, 0, 0], [0, 0, -1]], atol=1e-15)
    np.testing.assert_allclose(toolpath.cl, op.points_part, atol=1e-15)


def test_rotabl_turns_the_following_points_into_the_part():
    first, second = read("rotabl_setups.apt").operations
    np.testing.assert_allclose(first.points_part, [[0, 0, 10], [10, 0, 10]])
    # Table turned +90 degrees about Y: machine (0, 0, 10) was part (-10, 0, 0); the tool is along part -X.
    np.testing.assert_allclose(second.points_part, [[-10, 0, 0], [-10, 5, 0]], atol=1e-12)
    np.testing.assert_allclose(second.axes_part, [[-1, 0, 0]] * 2, atol=1e-12)
    assert second.frame == "ROTABL 90 BAXIS line 7"


def test_turning_program_is_named_not_computed():
    program = read("nx_turning.cls")
    (op,) = program.operations
    assert op.tool.kind == "turning" and op.tool.diameter is None
    assert op.refusal() == "operation 1: turning tool: a turning program, not milling"
    with pytest.raises(OperationChoiceError, match="no operation the engine can run: operation 1: turning tool: a turning program, not milling"):
        program.operation()
