"""load_apt, the one-pass adapter over formats.cl: the records NX and CATIA write, every error naming file and line."""

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from abm_workbench.engine import axis_to_angles
from abm_workbench.errors import InputError
from abm_workbench.formats.apt import AptProgram, load_apt
from abm_workbench.formats.cl import OperationChoiceError, read_program


def write(tmp_path, text, name="path.apt", newline="\n"):
    """Write `text` (written with \\n) to tmp_path/name with the given line ends; its path."""
    path = tmp_path / name
    path.write_bytes(text.replace("\n", newline).encode("utf-8"))
    return path


def load(tmp_path, text, **kwargs):
    """AptProgram of `text` written to a file."""
    return load_apt(write(tmp_path, text, **kwargs))


def fails(tmp_path, text, line, *fragments):
    """Loading `text` raises InputError starting 'file:line:' and holding every fragment."""
    path = write(tmp_path, text)
    with pytest.raises(InputError) as caught:
        load_apt(path)
    message = str(caught.value)
    assert message.startswith(f"{path}:{line}: " if line else f"{path}: "), message
    for fragment in fragments:
        assert fragment in message, message
    return message


def assert_axes(program, axes):
    """The toolpath's angles are those of the tool-axis vectors `axes` (m, 3)."""
    theta_a, theta_b = axis_to_angles(np.array(axes, dtype=float))
    np.testing.assert_allclose(program.toolpath.theta_a, theta_a, atol=1e-12)
    np.testing.assert_allclose(program.toolpath.theta_b, theta_b, atol=1e-12)


NX_FILE = """\
TOOL PATH/VARIABLE_CONTOUR,TOOL,D10
TLDATA/MILL,10.0000,0.0000,75.0000,0.0000,0.0000
MSYS/100.0000,20.0000,5.0000,0.0000000,1.0000000,0.0000000,-1.0000000,0.0000000,0.0000000
$$ centerline data
PAINT/PATH
PAINT/SPEED,10
LOAD/TOOL,1
SPINDL/RPM,8000,CLW
MULTAX/ON
PAINT/COLOR,186
RAPID
GOTO/0.0000,0.0000,50.0000,0.0000000,0.0000000,1.0000000
PAINT/COLOR,211
FEDRAT/MMPM,250.0000
GOTO/1.0000,2.0000,3.0000,0.6000000,0.0000000,0.8000000
GOTO/2.0000,2.0000,3.0000,0.0000000,0.0000000,1.0000000
FEDRAT/300.0000,MMPM
GOTO/3.0000,2.0000,3.0000,0.0000000,0.6000000,0.8000000
PAINT/SPEED,10
END-OF-PATH
"""


def test_nx_file(tmp_path):
    program = load(tmp_path, NX_FILE)
    assert isinstance(program, AptProgram)
    # MSYS: origin (100, 20, 5), X axis (0, 1, 0), Y axis (-1, 0, 0), so Z = (0, 0, 1).
    np.testing.assert_allclose(program.toolpath.cl, [[98, 21, 8], [98, 22, 8], [98, 23, 8]], atol=1e-12)
    assert_axes(program, [[0, 0.6, 0.8], [0, 0, 1], [-0.6, 0, 0.8]])
    assert program.line_numbers.tolist() == [15, 16, 18]
    assert program.feed.tolist() == [250.0, 250.0, 300.0]
    assert program.feed_unit == "MMPM"
    # TLDATA/MILL's third number is the tool's length, not its flute length.
    assert (program.diameter, program.flute_length, program.spindle_rpm) == (10.0, None, 8000.0)
    assert program.unknown == ()
    assert program.warnings == ()


CATIA_FILE = """\
$$ -----------------------------------------------------------------
$$ Generated on Tuesday, 2 April 2024
$$ CATIA APT VERSION 1.0
$$ -----------------------------------------------------------------
$$ Manufacturing Program.1
partno part1
$$*CATIA0
$$ Part Operation.1
multax
$$ TOOLCHANGEBEGINNING
cutter/ 10.000000, .000000, 5.000000, 0.000000, 0.000000, 0.000000,$
 30.000000
loadtl/ 1, adjust, 1, mill
spindl/ 3000.0000, rpm, clw
tlaxis/ 0.000000, 0.000000, 1.000000
coolnt/on
rapid
goto  / 10.00000, -5.00000, 40.00000, 0.000000, 0.000000, 1.000000
fedrat/ 1000.0000, mmpm
goto  / 10.00000, -5.00000, $   $$ continued
  2.50000,$
$$ a comment inside the continued record
 .707107, 0.000000, .707107
goto  / 12.50000, -.25, 2.5e0, 0., 0., 1. $$ trailing comment
Goto/12.50000,5.00000,2.50000
fedrat/ 500.0000
goto  / 1.5E+01, 5.00000, 2.50000, 0.000000, -0.100000, 0.995000
stop
fini
"""


@pytest.mark.parametrize("newline", ["\n", "\r\n", "\r"])
def test_catia_file(tmp_path, newline):
    program = load(tmp_path, CATIA_FILE, newline=newline)
    np.testing.assert_allclose(
        program.toolpath.cl, [[10, -5, 2.5], [12.5, -0.25, 2.5], [12.5, 5, 2.5], [15, 5, 2.5]]
    )
    # The GOTO of x, y, z only under MULTAX keeps the last axis.
    assert_axes(program, [[1, 0, 1], [0, 0, 1], [0, 0, 1], [0, -0.1, 0.995]])
    assert program.line_numbers.tolist() == [20, 24, 25, 27]
    assert program.feed.tolist() == [1000.0, 1000.0, 1000.0, 500.0]
    assert program.feed_unit == "MMPM"
    # CUTTER's seventh number is the tool's height, not its flute length.
    assert (program.diameter, program.flute_length, program.spindle_rpm) == (10.0, None, 3000.0)
    assert program.unknown == ()
    assert program.warnings == ()


def test_program_is_frozen_and_its_arrays_read_only(tmp_path):
    program = load(tmp_path, "GOTO/1,2,3\n")
    with pytest.raises(dataclasses.FrozenInstanceError):
        program.diameter = 3.0
    for array in (program.feed, program.line_numbers):
        with pytest.raises(ValueError):
            array[0] = 0
    assert program.line_numbers.dtype.kind == "i"


def test_three_axis_file_uses_tlaxis_default_and_given(tmp_path):
    program = load(tmp_path, "GOTO/0,0,1\nTLAXIS/0,1,1\nGOTO/1,0,1\nTLAXIS/0,0,7\nGOTO/2,0,1\n")
    np.testing.assert_allclose(program.toolpath.cl[:, 0], [0, 1, 2])
    assert_axes(program, [[0, 0, 1], [0, 1, 1], [0, 0, 1]])
    assert np.isnan(program.feed).all()
    assert (program.feed_unit, program.diameter, program.flute_length, program.spindle_rpm) == (None,) * 4


def test_three_number_goto_keeps_the_axis_in_force_whatever_multax_says(tmp_path):
    # The axis in force is TLAXIS's or the last six-number GOTO's; MULTAX changes nothing.
    text = "TLAXIS/0,.6,.8\nGOTO/9,0,0\nMULTAX\nGOTO/0,0,0,1,0,1\nGOTO/1,0,0\nMULTAX/OFF\nGOTO/2,0,0\n" \
           "GOTO/3,0,0,0,0,1\nmultax/on\nGOTO/4,0,0\n"
    program = load(tmp_path, text)
    assert_axes(program, [[0, 0.6, 0.8], [1, 0, 1], [1, 0, 1], [1, 0, 1], [0, 0, 1], [0, 0, 1]])


def test_tlaxis_under_multax_sets_the_current_axis(tmp_path):
    program = load(tmp_path, "MULTAX/ON\nGOTO/0,0,0,1,0,1\nTLAXIS/0,0,1\nGOTO/1,0,0\n")
    assert_axes(program, [[1, 0, 1], [0, 0, 1]])


def test_rapid_skips_only_the_next_goto(tmp_path):
    program = load(tmp_path, "RAPID\nGOTO/0,0,50\nGOTO/0,0,1\nRAPID\nFEDRAT/100\nGOTO/5,0,50\nGOTO/5,0,1\n")
    assert program.line_numbers.tolist() == [3, 7]
    assert program.feed.tolist()[1] == 100.0 and math.isnan(program.feed[0])


def test_a_rapid_move_may_point_down(tmp_path):
    program = load(tmp_path, "MULTAX\nRAPID\nGOTO/0,0,50,0,0,-1\nGOTO/0,0,1,0,0,1\n")
    assert len(program.toolpath) == 1


@pytest.mark.parametrize("record, unit, feed", [
    ("FEDRAT/MMPM,250", "MMPM", 250.0),
    ("FEDRAT/250,MMPM", "MMPM", 250.0),
    ("fedrat/ 0.1 , mmpr", "MMPR", 0.1),
    ("FEDRAT/IPM,20", "MMPM", 508.0),
    ("FEDRAT/.004,IPR", "MMPR", 0.1016),
    ("FEDRAT/250", "MMPM", 250.0),
])
def test_fedrat_forms(tmp_path, record, unit, feed):
    program = load(tmp_path, f"{record}\nGOTO/1,2,3\n")
    assert program.feed_unit == unit
    np.testing.assert_allclose(program.feed, [feed], rtol=1e-15)
    assert program.toolpath.cl.tolist() == [[1.0, 2.0, 3.0]]


def test_fedrat_without_unit_keeps_the_kind(tmp_path):
    program = load(tmp_path, "FEDRAT/MMPR,0.1\nGOTO/0,0,0\nFEDRAT/0.2\nGOTO/1,0,0\n")
    assert (program.feed_unit, program.feed.tolist(), program.warnings) == ("MMPR", [0.1, 0.2], ())


@pytest.mark.parametrize("record, diameter, length", [
    ("CUTTER/8", 8.0, None),
    ("CUTTER/8,0", 8.0, None),
    ("CUTTER/8,0,4,0,0,0,25", 8.0, None),
    ("TLDATA/MILL,6.0,0.0,40.0,0.0,0.0", 6.0, None),
    ("tldata/mill,6", 6.0, None),
    ("CUTTER/8,0,4,0,0,0,25\nCSI_SET_FLUTE_LENGTH/32.", 8.0, 32.0),
])
def test_tool_records(tmp_path, record, diameter, length):
    program = load(tmp_path, f"{record}\nGOTO/0,0,0\n")
    assert (program.diameter, program.flute_length, program.warnings) == (diameter, length, ())


MILLING_NOT_YET = ("a milling tool the ABM engine does not compute yet (it computes flat-end, bull-nose and "
                   "ball-end mills)")
NOT_MILLING = "not a milling tool (the ABM engine computes flat-end, bull-nose and ball-end mills)"


@pytest.mark.parametrize("record, words, reason", [
    ("CUTTER/10,0,0,0,0,15,30", "tapered mill D10 mm", MILLING_NOT_YET),
    ("TLDATA/DRILL,5,118", "drill D5 mm", NOT_MILLING),
])
def test_a_file_of_other_tools_is_refused_by_name(tmp_path, record, words, reason):
    fails(tmp_path, f"{record}\nGOTO/0,0,0\n", None, f"operation 1: {words}: {reason}")


@pytest.mark.parametrize("record, diameter, corner", [
    ("CUTTER/10,1,4,1,0,0,30", 10.0, 1.0), ("CUTTER/6,3", 6.0, 3.0), ("TLDATA/MILL,32,5,100,0,0", 32.0, 5.0),
])
def test_bull_nose_and_ball_mills_are_read_for_the_engine(tmp_path, record, diameter, corner):
    program = read_program(str(write(tmp_path, f"{record}\nGOTO/0,0,0\nGOTO/1,0,0\n")))
    operation = program.operation()
    assert operation.refusal() is None
    assert (operation.tool.diameter, operation.tool.corner_radius) == (diameter, corner)


@pytest.mark.parametrize("text, line, warning, kept", [
    ("FEDRAT/100,MMPM\nFEDRAT/0,MMPM\nGOTO/0,0,0\n", 2, "FEDRAT: feed rate must be positive, got 0", 100.0),
    ("FEDRAT/100,MMPM\nFEDRAT/MMPM,#1\nGOTO/0,0,0\n", 2, "FEDRAT: argument 2 '#1' is neither a number nor a word",
     100.0),
    ("CUTTER/0\nGOTO/0,0,0\n", 1, "CUTTER: diameter must be positive, got 0", None),
    ("SPINDL/9#00\nGOTO/0,0,0\n", 1, "SPINDL: argument 1 '9#00' is neither a number nor a word", None),
])
def test_records_the_engine_does_not_need_are_skipped_with_a_warning(tmp_path, text, line, warning, kept):
    """An unreadable record the engine does not need (feed, tool, spindle) is skipped, named with its line."""
    program = load(tmp_path, text)
    assert program.warnings == (f"{tmp_path / 'path.apt'}:{line}: {warning}; the record is skipped (the engine "
                                "does not need it)",)
    assert (program.feed.tolist() == [kept]) if kept else program.diameter is None


def test_several_tools_are_several_operations_to_choose_from(tmp_path):
    path = write(tmp_path, "CUTTER/10\nGOTO/0,0,0\nGOTO/1,0,0\nTLDATA/MILL,12,0,40\nGOTO/1,0,0\n")
    with pytest.raises(OperationChoiceError) as caught:
        load_apt(path)
    assert [op.number for op in caught.value.operations] == [1, 2]
    message = str(caught.value)
    assert "1: -, flat-end mill D10 mm, 2 CL points" in message and "2: -, flat-end mill D12 mm, 1 CL points" in message
    assert "--operation N" in message
    second = load_apt(path, operation=2)
    assert (second.diameter, second.operation, second.line_numbers.tolist()) == (12.0, 2, [5])


@pytest.mark.parametrize("record", ["SPINDL/1200", "SPINDL/RPM,1200", "SPINDL/1200,RPM",
                                    "SPINDL/RPM,1200,CCLW", "spindl/ 1200, clw"])
def test_spindl_forms(tmp_path, record):
    program = load(tmp_path, f"{record}\nGOTO/0,0,0\nSPINDL/OFF\n")
    assert program.spindle_rpm == 1200.0


@pytest.mark.parametrize("record, rpm", [
    ("SPINDL/SMM,100,CLW", 100_000 / (math.pi * 10)),
    ("SPINDL/SFM,300", 300 * 304.8 / (math.pi * 10)),
    ("SPINDL/MAIN,RPM,2500,CLW", 2500.0),
    ("SPINDL/RPM,2500,CLW,RANGE,2", 2500.0),
])
def test_spindl_surface_speed_and_other_forms(tmp_path, record, rpm):
    program = load(tmp_path, f"CUTTER/10\n{record}\nGOTO/0,0,0\n")
    assert program.spindle_rpm == pytest.approx(rpm, rel=1e-14)


def test_units_inches_converts_coordinates_tools_and_feeds(tmp_path):
    text = "UNITS/INCHES\nCUTTER/0.5,0,0,0,0,0,1\nFEDRAT/IPM,20\nGOTO/1,2,3\nUNITS/MM\nGOTO/1,2,3\n"
    program = load(tmp_path, text)
    np.testing.assert_allclose(program.toolpath.cl, [[25.4, 50.8, 76.2], [1, 2, 3]])
    assert (program.diameter, program.flute_length) == (12.7, None)
    assert program.feed_unit == "MMPM"
    np.testing.assert_allclose(program.feed, [508.0, 508.0])


def test_msys_in_inches_moves_by_the_converted_origin(tmp_path):
    program = load(tmp_path, "UNITS/INCH\nMSYS/1,0,0,1,0,0,0,1,0\nGOTO/1,0,0\n")
    np.testing.assert_allclose(program.toolpath.cl, [[50.8, 0, 0]])


def test_msys_rotates_points_and_axes(tmp_path):
    # Local frame tilted 30 degrees about the global x axis: X = (1,0,0), Y = (0,cos,sin).
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    text = f"MSYS/0,0,10,1,0,0,0,{c:.7f},{s:.7f}\nMULTAX\nGOTO/0,1,0,0,0,1\n"
    program = load(tmp_path, text)
    np.testing.assert_allclose(program.toolpath.cl, [[0, c, 10 + s]], atol=1e-7)
    assert_axes(program, [[0, -s, c]])


def test_ignored_words_are_accepted_and_others_reported(tmp_path):
    text = """\
PARTNO TEST PART
MACHIN/MILL,1
SELECT/TOOL,1
PPRINT/ROUGHING $$ comment
INSERT/G90
COOLNT/FLOOD
FROM/0,0,100
CUTCOM/LEFT
OPSKIP/ON
GOTO/5,0,0
OPSKIP/OFF
OPSTOP
GOHOME
END
FINI
"""
    program = load(tmp_path, text)
    assert program.unknown == (("OPSKIP", 9, 2),)
    path = tmp_path / "path.apt"
    assert program.warnings == (f"{path}:8: CUTCOM: LEFT: cutter compensation in the control; the CL points are "
                                "taken as the tool tip's centre as written (an offset the control adds, such as "
                                "wear, is left out)",)
    assert program.toolpath.cl.tolist() == [[5.0, 0.0, 0.0]]


def test_canned_cycle_holes_are_not_cutting_moves(tmp_path):
    text = "GOTO/0,0,0\nCYCLE/DRILL,5\nGOTO/1,0,0\nGOTO/2,0,0\nCYCLE/OFF\nGOTO/3,0,0\n"
    assert load(tmp_path, text).line_numbers.tolist() == [1, 6]


def test_blank_lines_spaces_and_no_final_line_end(tmp_path):
    program = load(tmp_path, "\n\n   \n  goto / +1.5 , -2 , 3.  \n\n$$ end")
    assert program.toolpath.cl.tolist() == [[1.5, -2.0, 3.0]]
    assert program.line_numbers.tolist() == [4]


@given(st.lists(st.floats(-1e4, 1e4, allow_nan=False), min_size=3, max_size=3),
       st.sampled_from(["{:.4f}", "{:.6E}", "{:g}", "{!r}", "{:.3e}"]))
def test_number_formats(tmp_path_factory, values, style):
    texts = [style.format(v) for v in values]
    # Bare leading dot, as some posts write it: 0.5 -> .5, -0.5 -> -.5.
    texts = [t.replace("0.", ".", 1) if t.lstrip("-").startswith("0.") else t for t in texts]
    program = load(tmp_path_factory.mktemp("n"), f"GOTO/{','.join(texts)}\n")
    np.testing.assert_array_equal(program.toolpath.cl[0], [float(t) for t in texts])


@given(st.lists(st.integers(0, 31), max_size=4))
def test_continuation_anywhere_gives_the_same_record(tmp_path_factory, cuts):
    record = "GOTO/1.25,-2.5,3.75,0.1,0.2,0.97"
    pieces, start = [], 0
    for cut in sorted(set(cuts)):
        pieces.append(record[start:cut])
        start = cut
    pieces.append(record[start:])
    text = "MULTAX\n" + "$\n".join(pieces) + "\n"
    program = load(tmp_path_factory.mktemp("c"), text)
    np.testing.assert_array_equal(program.toolpath.cl, [[1.25, -2.5, 3.75]])
    assert_axes(program, [[0.1, 0.2, 0.97]])
    assert program.line_numbers.tolist() == [2]


# Errors: every one names the file and the line where the record starts.

@pytest.mark.parametrize("text, line, fragments", [
    ("GOTO/1,2\n", 1, ["GOTO: takes x,y,z or x,y,z,i,j,k, got 2"]),
    ("\nGOTO/1,2,$\n\n", 2, ["continuation mark '$'"]),
    ("GOTO/1,x,3\n", 1, ["GOTO: argument 2 'x' is not a number"]),
    ("GOTO/1,,3\n", 1, ["GOTO: argument 2 is empty"]),
    ("MULTAX\nGOTO 1,2,3\n", 2, ["'1,2,3' is not a number"]),
    ("GOTO/nan,2,3\n", 1, ["'nan' is not a number"]),
    ("GOTO/inf,2,3\n", 1, ["'inf' is not a number"]),
    ("GOTO/1e999,2,3\n", 1, ["'1e999' is not a number"]),
    ("GOTO/1.2.3,2,3\n", 1, ["'1.2.3' is not a number"]),
    ("GOTO/0x10,2,3\n", 1, ["'0x10' is not a number"]),
    ("GOTO/1_0,2,3\n", 1, ["'1_0' is not a number"]),
    ("GOTO/1,2,3,0,0\n", 1, ["GOTO: takes x,y,z or x,y,z,i,j,k, got 5"]),
    ("GOTO/1,2,3,0,0,1,0\n", 1, ["got 7"]),
    ("\nGOTO/1,2,3,0,0,0\n", 2, ["GOTO: tool axis (0, 0, 0) is zero"]),
    ("RAPID\nGOTO/1,2,3,0,0,0\n", 2, ["tool axis (0, 0, 0) is zero"]),
    ("TLAXIS/0,0,0\nGOTO/1,2,3\n", 1, ["TLAXIS: tool axis (0, 0, 0) is zero"]),
    ("UNITS/FEET\n", 1, ["UNITS: expected MM or INCHES, got 'FEET'"]),
    ("UNITS/\n", 1, ["UNITS: expected MM or INCHES"]),
    ("MSYS/0,0,0,1,0,0\n", 1, ["MSYS: needs 9 numbers", "got 6"]),
    ("MSYS/0,0,0,2,0,0,0,1,0\n", 1, ["MSYS: not a frame: its axes are not unit vectors square to each other"]),
    ("MSYS/0,0,0,1,0,0,.6,.8,0\n", 1, ["MSYS: not a frame"]),
    ("CSYS/1,0,0,0,0,1,0,0\n", 1, ["CSYS: needs 12 numbers", "got 8"]),
    ("CSYS/1,0,0,0,0,1,0,0,0,0,-1,0\n", 1, ["CSYS: not a frame: it is a reflection"]),
    ("CIRCLE/0,0,0,0,0,1,5\nGOTO/5,0,0\n", 2, ["GOTO: the arc of the CIRCLE on line 1 has no start point"]),
    ("GOTO/0,0,0\nCIRCLE/0,0,0,0,0,1,5\nGOTO/5,0,0\n", 3, ["start or end point lies on the circle's axis"]),
    ("CIRCLE/0,0,0,0,0\n", 1, ["CIRCLE: needs xc,yc,zc,i,j,k[,r], got 5"]),
    ("GOTO/0,0,0\n/1,2,3\n", 2, ["has no major word"]),
])
def test_malformed_records(tmp_path, text, line, fragments):
    fails(tmp_path, text, line, *fragments)


@pytest.mark.parametrize("text, line, reason", [
    ("$$ nothing here\n\nFINI\n", 3, "no GOTO record"),
    ("RAPID\nGOTO/0,0,50\nFINI\n", 3, "every GOTO is a rapid move or a canned-cycle hole"),
])
def test_no_cutting_move(tmp_path, text, line, reason):
    fails(tmp_path, text, line, "end of file and no cutting move", reason)


@pytest.mark.parametrize("content, fragment", [
    (b"", "empty file"),
    (b"\x00\x01binary\x00", "binary content"),
    (b"hello world\nthis is prose\n", "unknown content"),
])
def test_content_that_is_no_cl_file(tmp_path, content, fragment):
    path = tmp_path / "x.apt"
    path.write_bytes(content)
    with pytest.raises(InputError, match=f"^{path}: {fragment}"):
        load_apt(path)


def test_unreadable_file_names_it(tmp_path):
    path = tmp_path / "missing.apt"
    with pytest.raises(InputError, match="missing.apt: cannot read"):
        load_apt(path)
