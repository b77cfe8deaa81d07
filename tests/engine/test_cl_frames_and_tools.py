"""CL files as their CAM systems mean them: frames (SOLIDWORKS CAM's TRNTYP/WORLD, ROTABL on several axes,
CAMWorks's radians), tools (turning inserts, taps, countersinks, tapered and inch tools, a repeated
SOLIDWORKS CAM tool block), records the engine does not need, CIRCLE's direction word and NX NURBS blocks
as NX writes them. Each file is written here in the shape of that system's real output; every expected
value is worked out here (rotations built from their own matrices, curves evaluated by scipy)."""

import math

import numpy as np
import pytest
from scipy.interpolate import BSpline

from abm_workbench.formats.cl import read_program
from abm_workbench.jobs.inputs import program_moves
from abm_workbench.engine import Tool


def program(tmp_path, text, name="p.apt", **kwargs):
    path = tmp_path / name
    path.write_text(text)
    return read_program(path, **kwargs)


def turn(axis, degrees):
    """Right-handed rotation (3, 3) by `degrees` about the unit vector of axis 'x', 'y' or 'z'."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return {"x": np.array([[1, 0, 0], [0, c, -s], [0, s, c]]), "y": np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
            "z": np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])}[axis]


SOLIDWORKS_SETUPS = """\
PARTNO/1
UNIT/MM
INSERT/[HOLDER=C40-M12EM2] 10MM CRB 4FL 22 LOC
CUTTER/10.,0,5.,0,0,0,72.
LOAD/TOOL,3
CSI_SET_FLUTE_LENGTH/22.
CSI_SET_EXTENSION_LENGTH/40.
SELECT/TOOL,7
COOLNT/FLOOD
SPINDL/6400,RPM,CLW
INSERT/Stock Size X200. Y100. Z30.
TRNTYP/WORLD,0,0,0
CSYS/1.,0,0,0,0,1.,0,0,0,0,1.,0
SETUP/START,1
RAPID/
GOTO/20.,20.,25.
FEDRAT/300.,MMPM
GOTO/20.,20.,-4.
FEDRAT/900.,MMPM
GOTO/80.,20.,-4.
CIRCLE/80.,30.,-4.,0,0,1.
GOTO/90.,30.,-4.
RAPID/
GOTO/90.,30.,25.
SETUP/END,1
TRNTYP/WORLD,0,0,0
CSYS/-1.,0,0,200.,0,-1.,0,100.,0,0,1.,0
SETUP/START,2
RAPID/
GOTO/180.,80.,25.
FEDRAT/300.,MMPM
GOTO/180.,80.,-4.
GOTO/120.,80.,-4.
RAPID/
GOTO/120.,80.,25.
SETUP/END,2
TRNTYP/WORLD,0,0,0
CSYS/1.,0,0,0,0,0,-1.,0,0,1.,0,0
SETUP/START,3
RAPID/
GOTO/50.,-20.,15.
FEDRAT/300.,MMPM
GOTO/50.,-5.,15.
GOTO/150.,-5.,15.
SETUP/END,3
FINI
"""


def test_solidworks_cam_world_points_stay_on_their_stated_stock(tmp_path):
    """After TRNTYP/WORLD the GOTOs are world coordinates: a CSYS only names a setup (a new operation) and
    gives the tool axis of the moves that give none (its third column); it never moves the points."""
    prog = program(tmp_path, SOLIDWORKS_SETUPS)
    first, second, third = prog.operations
    assert [op.frame.split(" (")[0] for op in prog.operations] == ["CSYS line 13", "CSYS line 27", "CSYS line 38"]
    for op in prog.operations:
        np.testing.assert_array_equal(op.points_part, op.points_file)  # as written
        # On the stated stock (Stock Size X200 Y100 Z30, top at z = 0) or above it, never far off.
        assert (op.points_part[:, 0] >= -6).all() and (op.points_part[:, 0] <= 206).all()
        assert (op.points_part[:, 2] <= 25).all() and (op.points_part[:, 2] >= -30).all()
    np.testing.assert_array_equal(second.points_part[-1], [120, 80, -4])
    np.testing.assert_allclose(second.axes_part, [[0, 0, 1]] * 2)  # the 180° setup's Z is the world's
    np.testing.assert_allclose(third.axes_part, [[0, -1, 0]] * 2)  # the side setup: its Z, the CSYS's third column
    assert [op.tool.describe() for op in prog.operations] == ["flat-end mill D10 mm"] * 3
    assert [op.tool.flute_length for op in prog.operations] == [22.0] * 3
    assert first.tool.name == "10MM CRB 4FL 22 LOC"
    assert "SETUP" in prog.ignored and not prog.unknown


def test_a_repeated_solidworks_tool_block_keeps_its_own_flute_length(tmp_path):
    block = "INSERT/[HOLDER=C40] 14MM CRB 4FL {0} LOC\nCUTTER/14.,0,7.,0,0,0,84.\nLOAD/TOOL,{1}\nCSI_SET_FLUTE_LENGTH/{0}.\n"
    text = ("UNIT/MM\n" + block.format(32, 5) + "FEDRAT/500.,MMPM\nGOTO/0,0,0\nGOTO/10,0,0\n"
            + block.format(45, 1) + "GOTO/10,10,0\n")
    first, second = program(tmp_path, text).operations
    assert (first.tool.flute_length, second.tool.flute_length) == (32.0, 45.0)
    assert first.lines.tolist() == [7, 8] and second.lines.tolist() == [13]


def test_rotabl_on_two_axes_composes_the_table_c_innermost(tmp_path):
    """ROTABL/30,AAXIS then ROTABL/90,CAXIS: the table turned by A carries the C table, which carries the
    part. A machine point m is the part point R_A·R_C·p, so p = R_Cᵀ·R_Aᵀ·m."""
    text = "CUTTER/10\nROTABL/30,AAXIS\nROTABL/90,CAXIS\nGOTO/10,20,30\nGOTO/11,20,30\n"
    (op,) = program(tmp_path, text).operations
    part = turn("z", 90).T @ turn("x", 30).T @ np.array([10.0, 20.0, 30.0])
    np.testing.assert_allclose(op.points_part[0], part, atol=1e-12)
    assert op.frame == "ROTABL 30 AAXIS + 90 CAXIS line 3"
    # INCR adds to that axis only; the other keeps its angle.
    text = "CUTTER/10\nROTABL/30,AAXIS\nROTABL/90,CAXIS\nROTABL/15,AAXIS,INCR\nGOTO/10,20,30\n"
    (op,) = program(tmp_path, text, "q.apt").operations
    np.testing.assert_allclose(op.points_part[0], turn("z", 90).T @ turn("x", 45).T @ [10, 20, 30], atol=1e-12)


def test_camworks_writes_rotabl_angles_in_radians(tmp_path):
    text = "UNIT/MM\nCUTTER/10.,0,5.,0,0,0,50.\nCSI_SET_FLUTE_LENGTH/20.\nROTABL/1.5707963,AAXIS\nGOTO/0,10,0\n"
    prog = program(tmp_path, text)
    (op,) = prog.operations
    np.testing.assert_allclose(op.points_part[0], turn("x", math.degrees(1.5707963)).T @ [0, 10, 0], atol=1e-12)
    assert any("radians" in warning for warning in prog.warnings)
    # The same angle in a file of another system is in degrees.
    (plain,) = program(tmp_path, "CUTTER/10\nROTABL/1.5707963,AAXIS\nGOTO/0,10,0\n", "nx.cl").operations
    np.testing.assert_allclose(plain.points_part[0], turn("x", 1.5707963).T @ [0, 10, 0], atol=1e-12)


@pytest.mark.parametrize("text, kind, describe", [
    ("LOADTL/1,1,1,1\nCUTTER/0.8\nTOOLNO/1,TURN,0.8,80,0,0\nSPINDL/SMM,200,CLW\nGOTO/50,0,0\nGOTO/40,0,0\n",
     "turning", "turning tool"),
    ("TURRET/1\nCUTTER/0.4\nSPINDL/SFM,600\nGOTO/50,0,0\nGOTO/40,0,0\n", "turning", "turning tool"),
    ("INSERT/[HOLDER=ER20] M6X1.0 SPIRAL TAP\nCUTTER/6.,0,3.,0,0,0,60.\nLOAD/TOOL,9\nCYCLE/INIT\nCYCLE/TAP,FEDTO,10\n"
     "GOTO/0,0,0\nCYCLE/OFF\n", "tap", "tap D6 mm"),
    ("CUTTER/8.,0,4.,0,0,0,60.\nCYCLE/TAP,10,MMPR,1.25\nGOTO/0,0,0\nCYCLE/OFF\n", "tap", "tap D8 mm"),
    ("INSERT/[HOLDER=ER20] 12MM 90DEG COUNTERSINK\nCUTTER/12.,0,6.,0,0,0,60.\nLOAD/TOOL,4\nGOTO/0,0,0\n",
     "countersink", "countersink D12 mm"),
    ("TPRINT/T4 Spot Drill D 10\nLOADTL/4\nCUTTER/10,0,0,0,45,0,50\nGOTO/0,0,0\n", "spot drill", "spot drill D10 mm"),
    ("CUTTER/6,4,0,0,0,0,50\nGOTO/0,0,0\n", "tapered", "tapered mill D6 R4 mm"),
    ("CUTTER/10,1,4,1,0,3,60\nGOTO/0,0,0\n", "tapered", "tapered mill D10 R1 mm"),
    ("TLDATA/MILL,10,0,75,5,0\nGOTO/0,0,0\n", "tapered", "tapered mill D10 mm"),
    ("UNITS/INCHES\nCUTTER/0.394,0,0,0,0,0,2.5\nGOTO/0,0,0\n", "flat", "flat-end mill D10.0076 mm (D0.394 in)"),
])
def test_tools_as_the_file_means_them(tmp_path, text, kind, describe):
    prog = program(tmp_path, text)
    op = prog.operations[0]
    assert (op.tool.kind, op.tool.describe()) == (kind, describe)
    if kind in ("turning",):
        assert op.spindle_rpm is None  # a surface speed on an insert's nose radius gives no rpm
        assert op.refusal().endswith("a turning program, not milling")
    elif kind == "tapered":
        assert "a milling tool the ABM engine does not compute yet" in op.refusal()
    else:
        assert "not a milling tool" in (op.refusal() or "not a milling tool")


def test_records_the_engine_does_not_need_never_stop_the_reading(tmp_path):
    text = "CUTTER/10\nSPINDL/900CCLW\nCOOLNT/FLOOD,#9\nFEDRAT/500,MMPM\nGOTO/0,0,0\nGOTO/5,0,0\n"
    prog = program(tmp_path, text)
    (op,) = prog.operations
    assert op.spindle_rpm == 900.0 and len(op.lines) == 2  # 900CCLW: 900 rpm, counter-clockwise
    assert prog.ignored["COOLNT"] == (3, 1)


@pytest.mark.parametrize("word, sense", [("COUNTERCLOCKWISE", 1), ("CLOCKWISE", -1), ("CCLW", 1), ("CLW", -1)])
def test_circle_with_a_direction_word_after_its_radius(tmp_path, word, sense):
    """CAMWorks / SOLIDWORKS CAM CLT: CIRCLE/cx,cy,cz,i,j,k,r,<direction>, seen from the axis's tip."""
    text = f"CUTTER/10\nGOTO/10,0,0\nCIRCLE/0,0,0,0,0,1,10,{word}\nGOTO/0,10,0\n"
    (op,) = program(tmp_path, text).operations
    arc = op.points_file[op.lines == 4]
    turned = np.unwrap(np.arctan2(arc[:, 1], arc[:, 0]))
    assert turned[-1] == pytest.approx(math.pi / 2 if sense > 0 else -3 * math.pi / 2)
    np.testing.assert_allclose(np.hypot(arc[:, 0], arc[:, 1]), 10.0, rtol=0, atol=1e-12)


def nx_nurbs(start, control, knots):
    """An NX NURBS block: CNTRL without the start (the tool's position), KNOT without the end knots'
    multiplicity, as NX writes them (KNOT/u,CNTRL/x,y,z lines, then the knots left)."""
    rows = [f"KNOT/{k:.7f},CNTRL/{p[0]:.4f},{p[1]:.4f},{p[2]:.4f}" for k, p in zip(knots, control)]
    rows += [f"CNTRL/{p[0]:.4f},{p[1]:.4f},{p[2]:.4f}" for p in control[len(knots):]]
    return "NURBS/\n" + "\n".join(rows) + "\n"


def test_nx_nurbs_as_nx_writes_them_join_the_moves_around_them(tmp_path):
    """Two knots fewer than control points, the start implied: the curve starts at the tool's position and
    ends at its last control point, where the next GOTO goes on from."""
    start = np.array([10.0, 0.0, 5.0])
    control = np.array([[15, 4, 5], [22, 2, 5.5], [28, 9, 6], [33, 5, 6], [40, 12, 6], [46, 10, 6.5], [50, 14, 6.5]])
    inner = [0.2, 0.35, 0.55]
    written = [0.0, *inner, 1.0]  # the inner knots and the two ends once: two fewer than control points
    assert len(written) == len(control) - 2
    degree = 4  # 8 control points with the start, 13 knots with the ends' multiplicity
    full = np.concatenate([np.zeros(degree + 1), inner, np.ones(degree + 1)])
    assert len(full) == len(control) + 1 + degree + 1
    curve = BSpline(full, np.vstack([start, control]), degree)
    text = ("TOOL PATH/CONTOUR,TOOL,EM10\nTLDATA/MILL,10.0000,0.0000,75.0000,0.0000,0.0000\nLOAD/TOOL,1\n"
            "FEDRAT/MMPM,500.0000\nGOTO/10.0000,0.0000,5.0000,0.0000000,0.0000000,1.0000000\n"
            + nx_nurbs(start, control, written) + "GOTO/55.0000,14.0000,6.5000\nEND-OF-PATH\n")
    prog = program(tmp_path, text, "nx.cls")
    (op,) = prog.operations
    assert not prog.warnings and op.curves == 1
    points = op.points_file[op.lines == 6]
    np.testing.assert_allclose(points[-1], control[-1], atol=1e-12)  # ends on the last control point
    dense = curve(np.linspace(0, 1, 400001))
    nearest = np.array([np.linalg.norm(dense - p, axis=1).min() for p in points])
    assert nearest.max() < 2e-4  # on the curve that starts at the tool's position
    chords = np.linalg.norm(np.diff(np.vstack([start, points]), axis=0), axis=1)
    assert chords.max() <= 0.1 + 1e-12  # at most a step apart, from the tool's position on
    np.testing.assert_allclose(op.points_file[-1], [55, 14, 6.5])
    # Its tangents turn the frames along the curve: each CL point's feed is the curve's direction there.
    toolpath = op.toolpath()
    u = np.linspace(0, 1, 400001)[[np.argmin(np.linalg.norm(dense - p, axis=1)) for p in points[::25]]]
    lead = curve.derivative()(u)
    np.testing.assert_allclose(toolpath.alpha[1::25], np.degrees(np.arctan2(lead[:, 1], lead[:, 0])), atol=0.01)


def test_an_operation_without_a_flute_length_removes_with_its_whole_length(tmp_path):
    """NX, CATIA and Creo give no flute length: such an earlier operation still enters the in-process
    stock, with the tool's whole length (the file's, else the program's extent), and the notes say so;
    canned-cycle holes are named as left out."""
    text = ("TOOL PATH/ROUGH,TOOL,EM16\nTLDATA/MILL,16.0000,0.0000,75.0000,0.0000,0.0000\nLOAD/TOOL,1\n"
            "FEDRAT/MMPM,500\nGOTO/0,0,0\nGOTO/50,0,0\nEND-OF-PATH\n"
            "TOOL PATH/CREO_LIKE,TOOL,EM8\nLOAD/TOOL,2\n$$-> CUTTER / 8.000000\nGOTO/0,20,0\nGOTO/50,20,0\nEND-OF-PATH\n"
            "TOOL PATH/DRILL,TOOL,DR5\nTLDATA/DRILL,5,118\nLOAD/TOOL,3\nCYCLE/DRILL,10\nGOTO/5,5,0\nCYCLE/OFF\n"
            "END-OF-PATH\nTOOL PATH/FINISH,TOOL,EM10\nTLDATA/MILL,10.0000,0.0000,75.0000,0.0000,0.0000\n"
            "LOAD/TOOL,4\nGOTO/0,10,0\nGOTO/50,10,0\nEND-OF-PATH\n")
    prog = program(tmp_path, text, "nx.cls")
    rough, creo, drill, finish = prog.operations
    moves, rows, notes = program_moves(prog, finish, Tool(10.0, 2, 20.0))
    lengths = sorted(np.unique(moves.flute_length).tolist())
    assert lengths == [20.0, pytest.approx(math.hypot(50, 20)), 75.0]
    assert any("ROUGH" in note and "75 mm (the tool's length in the file)" in note for note in notes)
    assert any("CREO_LIKE" in note and "the program's extent" in note for note in notes)
    assert any("DRILL" in note and "1 canned-cycle holes are not in the in-process stock" in note for note in notes)
    assert len(rows) == 2
