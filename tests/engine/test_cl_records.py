"""formats.cl record by record: lexical tolerance, the modal state, units, spindle, tools,
operation boundaries, and errors naming file and line; every expected value worked out here."""

import math

import numpy as np
import pytest

from abm_workbench.errors import InputError
from abm_workbench.formats.cl import read_program
from abm_workbench.formats.cl.lexer import lex


def program(tmp_path, text, name="f", **kwargs):
    path = tmp_path / name
    path.write_bytes(text.encode("latin-1"))
    return read_program(path, **kwargs)


@pytest.mark.parametrize("name", ["p.clsf", "p.clt", "p.aptsource", "p.ncl", "p.ncl.3", "p.txt", "p.cl", "p"])
def test_any_file_name_is_read_by_content(tmp_path, name):
    assert program(tmp_path, "GOTO/1,2,3\n", name).operations[0].points_file.tolist() == [[1, 2, 3]]


def test_lexical_tolerance(tmp_path):
    text = ("$$ header comment that goes on $\n   and on $\n   and ends here\n"
            "cutter / 10 , 0 ,\n"
            "Rapid/\n"
            "goto/ 0 , 0 , 5 ,\n"
            "fedrat / 100 , mmpm ,\n"
            "GOTO/1,$\n 0,$\n$$ a comment inside the record\n 5\n"
            "  GOTO  /  2.5E0 , -.5 , +5.  $$ trailing comment\n")
    prog = program(tmp_path, text)
    (op,) = prog.operations
    assert op.points_file.tolist() == [[1, 0, 5], [2.5, -0.5, 5]]
    assert op.lines.tolist() == [8, 12]
    assert op.rapids.lines.tolist() == [6]
    assert (op.tool.describe(), op.feed.tolist()) == ("flat-end mill D10 mm", [100.0, 100.0])
    assert prog.unknown == {} and prog.warnings == []


def test_a_comment_continued_with_dollar_stops_at_a_record():
    records, comments, lines = lex("$$ note $\nGOTO/1,2,3\n$$ more $\n text\nGOTO/4,5,6\n", "f")
    assert [r.line for r in records] == [2, 5]
    assert comments == [(1, "note $"), (3, "more text")]
    assert lines == 5


def test_ignored_records_are_counted_once_and_unknown_ones_listed(tmp_path):
    text = "PPRINT/A\nPPRINT/B\nOPFEATSTART/1\nBOX/0,0,0,1,1,1\nINSERT/M08\nWIDGET/1\nGOTO/0,0,0\nWIDGET/2\n"
    prog = program(tmp_path, text)
    assert prog.ignored == {"PPRINT": (1, 2), "OPFEATSTART": (3, 1), "BOX": (4, 1), "INSERT": (5, 1)}
    assert prog.unknown == {"WIDGET": (6, 2)}
    assert prog.warnings == []


def test_godlta_from_and_tlaxis(tmp_path):
    text = "FROM/0,0,50\nTLAXIS/0,0.6,0.8\nGODLTA/0,0,-45\nGODLTA/-5\nGOTO/1,1,1\n"
    (op,) = program(tmp_path, text).operations
    np.testing.assert_allclose(op.points_file, [[0, 0, 5], [0, -3, 1], [1, 1, 1]], atol=1e-12)
    np.testing.assert_allclose(op.axes_file, [[0, 0.6, 0.8]] * 3)


def test_unit_singular_and_inch_feeds(tmp_path):
    text = "UNIT/INCH\nCUTTER/0.25,0.125\nFEDRAT/IPR,0.002\nGOTO/1,0,0\nFEDRAT/0.01\nGOTO/2,0,0\n"
    prog = program(tmp_path, text)
    (op,) = prog.operations
    assert prog.units == "inch" and op.tool.describe() == "ball mill D6.35 R3.175 mm (D0.25 R0.125 in)"
    np.testing.assert_allclose(op.points_file, [[25.4, 0, 0], [50.8, 0, 0]])
    # A FEDRAT without a unit keeps the kind in force (per revolution here), in inches.
    np.testing.assert_allclose(op.feed, [0.0508, 0.254], rtol=1e-15)
    assert op.feed_unit == "MMPR"


@pytest.mark.parametrize("record, rpm", [
    ("SPINDL/1200", 1200.0), ("SPINDL/RPM,1200,CLW", 1200.0), ("SPINDL/1200,RPM,CCLW", 1200.0),
    ("SPINDL/MAIN,1200,RPM", 1200.0), ("SPINDL/SMM,120", 120_000 / (math.pi * 8)),
    ("SPINDL/SFM,500,CLW", 500 * 304.8 / (math.pi * 8)), ("SPINDL/OFF", None), ("SPINDL/ON", None),
])
def test_spindl_forms(tmp_path, record, rpm):
    (op,) = program(tmp_path, f"CUTTER/8\n{record}\nGOTO/0,0,0\n").operations
    assert op.spindle_rpm == (None if rpm is None else pytest.approx(rpm, rel=1e-14))


def test_each_tool_change_is_an_operation_with_its_tool(tmp_path):
    text = ("CUTTER/10\nGOTO/0,0,0\nGOTO/1,0,0\nCUTTER/10\nGOTO/2,0,0\n"   # the same tool again: no new operation
            "LOADTL/2\nCUTTER/6,1\nGOTO/3,0,0\n"                             # a tool change
            "TLDATA/DRILL,5,118\nGOTO/4,0,0\n")                              # another tool without LOADTL
    ops = program(tmp_path, text).operations
    assert [op.lines.tolist() for op in ops] == [[2, 3, 5], [8], [10]]
    assert [op.tool.describe() for op in ops] == ["flat-end mill D10 mm", "bull-nose mill D6 R1 mm", "drill D5 mm"]
    # The same tool again leaves the operation's own tool (and what its records said) as it was.
    assert [op.tool.records for op in ops] == [("CUTTER line 1",), ("CUTTER line 7",), ("TLDATA line 9",)]


def test_a_cutter_with_a_bottom_angle_and_no_corner_radius_is_a_drill(tmp_path):
    text = "CUTTER/8.5,0,0,2.45,31,0,90\nGOTO/0,0,0\nCUTTER/8,0,4,0,0,0,60\nGOTO/1,0,0\n"
    assert [op.tool.kind for op in program(tmp_path, text).operations] == ["drill", "flat"]


def test_loadtl_kind_words_name_drills_taps_and_turning_tools(tmp_path):
    text = "LOADTL/1,TAP\nCUTTER/8\nGOTO/0,0,0\nLOADTL/2,ADJUST,1,MILL\nCUTTER/8\nGOTO/1,0,0\n"
    ops = program(tmp_path, text).operations
    assert [op.tool.kind for op in ops] == ["tap", "flat"]
    assert ops[0].refusal() == ("operation 1: tap D8 mm: not a milling tool (the ABM engine "
                                "computes flat-end, bull-nose and ball-end mills)")


def test_a_frame_change_after_moves_starts_an_operation(tmp_path):
    text = ("CUTTER/8\nGOTO/0,0,0\nMSYS/0,0,0,1,0,0,0,1,0\nGOTO/1,0,0\n"   # identity MSYS: no change
            "MSYS/10,0,0,1,0,0,0,1,0\nGOTO/2,0,0\n")
    ops = program(tmp_path, text).operations
    assert [op.lines.tolist() for op in ops] == [[2, 4], [6]]
    assert [op.frame for op in ops] == ["", "MSYS line 5"]
    assert [op.name for op in ops] == ["", ""]
    np.testing.assert_allclose(ops[1].points_part, [[12, 0, 0]])


@pytest.mark.parametrize("text, line, fragment", [
    ("NURBS/\nKNOT/0,1,2,3,4,5,6,7,8,9,10,11,12,13,14\nCNTRL/0,0,0\nCNTRL/1,0,0\nGOTO/1,0,0\n", 1,
     "NURBS: 15 knots and 2 control points fit no B-spline of degree 1 to 9"),
    ("NURBS/\nKNOT/0\nGOTO/1,0,0\n", 1, "NURBS: the NURBS block has no CNTRL records"),
    ("NURBS/\nKNOT/0,CNTRL/0,0\n", 2, "KNOT: a control point needs x,y,z[,w], got 2"),
    ("NURBS/\nKNOT/0,0,1,1\nCNTRL/0,0,0,1\nCNTRL/1,0,0,2\n", 1, "a rational NURBS"),
    ("GOTO/0,0,0\nCIRCLE/0,0,0,0,0,0,5\nGOTO/5,0,0\n", 2, "CIRCLE: the circle's axis (0, 0, 0) is zero"),
    ("GODLTA/1,2,3\n", 1, "GODLTA: a relative move needs a position before it"),
    ("FROM/1,2\n", 1, "FROM: takes x,y,z or x,y,z,i,j,k, got 2"),
    ("CSYS/1,0,0,0,0,1,0,0,0,0,1,a\n", 1, "CSYS: argument 12 'a' is not a number"),
])
def test_errors_name_file_line_and_record(tmp_path, text, line, fragment):
    path = tmp_path / "bad.cl"
    path.write_text(text)
    with pytest.raises(InputError) as caught:
        read_program(path)
    assert str(caught.value).startswith(f"{path}:{line}: "), str(caught.value)
    assert fragment in str(caught.value)


def test_an_operation_split_by_a_frame_keeps_its_name(tmp_path):
    text = "TOOL PATH/SIDES,TOOL,EM8\nGOTO/0,0,0\nROTABL/90,CAXIS\nGOTO/1,0,0\nTOOL PATH/TOP\nGOTO/2,0,0\n"
    ops = program(tmp_path, text).operations
    assert [(op.name, op.lines.tolist()) for op in ops] == [("SIDES", [2]), ("SIDES", [4]), ("TOP", [6])]
    np.testing.assert_allclose(ops[1].points_part, [[0, -1, 0]], atol=1e-15)  # table turned +90 about Z


def test_circle_radius_far_from_the_points_is_warned(tmp_path):
    prog = program(tmp_path, "GOTO/10,0,0\nCIRCLE/0,0,0,0,0,1,12\nGOTO/0,10,0\n", "w.cl")
    assert prog.warnings == [f"{tmp_path / 'w.cl'}:2: CIRCLE: the arc's start point is 2 mm off the circle of radius "
                             "12 mm; the arc follows the points",
                             f"{tmp_path / 'w.cl'}:2: CIRCLE: the arc's end point is 2 mm off the circle of radius "
                             "12 mm; the arc follows the points"]


def test_latin1_comments_tolerance_and_step_options(tmp_path):
    """Arcs: each chord within the tolerance of the arc, consecutive CL points at most a step apart."""
    text = "$$ Opération d'ébauche\nGOTO/10,0,0\nCIRCLE/0,0,0,0,0,1,10\nGOTO/0,10,0\n"
    fine = program(tmp_path, text, "a", step=math.inf).operations[0]
    coarse = program(tmp_path, text, "b", tolerance=0.1, step=math.inf).operations[0]
    assert len(coarse.lines) < len(fine.lines)
    for op, tolerance in ((fine, 0.001), (coarse, 0.1)):
        step = np.diff(np.arctan2(op.points_file[:, 1], op.points_file[:, 0]))
        assert (10 * (1 - np.cos(step / 2))).max() <= tolerance
    default, wide = program(tmp_path, text, "c").operations[0], program(tmp_path, text, "d", step=2.0).operations[0]
    sagitta = math.ceil(0.5 * math.pi / (2 * math.acos(1 - 0.001 / 10)))  # turns the 0.001 mm tolerance needs
    for op, step in ((default, 0.1), (wide, 2.0)):  # the default step: about a tooth's feed
        chords = np.linalg.norm(np.diff(np.vstack([[10, 0, 0], op.points_file]), axis=0), axis=1)
        assert chords.max() <= step and (op.lines == 4).sum() == max(math.ceil(5 * math.pi / step), sagitta)


def test_a_program_without_moves_has_no_operation_to_choose(tmp_path):
    prog = program(tmp_path, "CUTTER/10\nSPINDL/1000\nFINI\n", "none.cl")
    assert prog.operations == ()
    with pytest.raises(InputError, match=f"^{tmp_path / 'none.cl'}: no operation: the file has no moves$"):
        prog.operation()
    with pytest.raises(InputError, match="operation 1: the program has operations 1 to 0"):
        prog.operation(1)


def test_rotabl_clockwise_and_incremental(tmp_path):
    text = ("CUTTER/8\nROTABL/30,AAXIS,CLW\nGOTO/0,1,0\nROTABL/30,AAXIS,CCLW,INCR\nGOTO/0,1,0\n"
            "ROTABL/0,AAXIS\nGOTO/0,1,0\n")
    ops = program(tmp_path, text).operations
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    # Table at -30 degrees about X: machine (0, 1, 0) was part Rx(-30)^T (0, 1, 0) = Rx(30) (0, 1, 0) = (0, cos, sin).
    np.testing.assert_allclose(ops[0].points_part, [[0, c, s]], atol=1e-15)
    assert len(ops) == 2 and ops[1].lines.tolist() == [5, 7] and ops[1].frame == ""
    np.testing.assert_allclose(ops[1].points_part, [[0, 1, 0], [0, 1, 0]], atol=1e-15)


def test_inch_csys_moves_by_the_converted_translation(tmp_path):
    (op,) = program(tmp_path, "UNITS/INCHES\nCSYS/1,0,0,1,0,1,0,2,0,0,1,3\nGOTO/1,1,1\n").operations
    np.testing.assert_allclose(op.points_part, [[50.8, 76.2, 101.6]], rtol=1e-15)
