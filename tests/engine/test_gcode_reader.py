"""G-code read as machines run it: moves, arcs in every plane, units and modes, work offsets, hole cycles,
tools, operations, and one clear error with the line for what the reader cannot take. References are
the tests' own: points and circles computed here, the numbers the programs write."""

import math
import os

import numpy as np
import pytest

from abm_workbench.cli import main
from abm_workbench.errors import InputError
from abm_workbench.formats.cl import read_program
from abm_workbench.formats.gcode.options import ReadOptions

TABLE = "T1 P1 D10 Z+40 ;10mm end mill\nT2 P2 D6 Z+35 ;6 mm ball end\nT3 P3 D8 ;bull nose R1.5\nT4 D5 ;5mm drill\n"


def read(tmp_path, text, name="prog.ngc", table=True, **options):
    """The Program of G-code `text` written to `name` (with TABLE as its tool table when `table`)."""
    path = tmp_path / name
    path.write_text(text)
    if table:
        (tmp_path / "tools.tbl").write_text(TABLE)
        options.setdefault("tool_table", str(tmp_path / "tools.tbl"))
    return read_program(str(path), options=ReadOptions(**options))


def refused(tmp_path, text, **options):
    """The message of the InputError reading `text` raises."""
    with pytest.raises(InputError) as error:
        read(tmp_path, text, **options)
    return str(error.value)


def test_a_program_is_gcode_by_its_content_whatever_its_name(tmp_path):
    text = "%\n(a comment first)\n; and another\nN10 G21 G90\nT1 M6\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10\n%\n"
    for name in ("prog.ngc", "prog.apt", "PROG", "prog.csv.txt"):
        program = read(tmp_path, text, name)
        assert program.format == "gcode" and len(program.operations) == 1
        np.testing.assert_array_equal(program.operations[0].points_file, [[0, 0, -1], [10, 0, -1]])


def test_straight_moves_their_chords_feeds_and_lines(tmp_path):
    program = read(tmp_path, "G21 G90 G94\nT1 M6\nS4000 M3\nG0 X1 Y2 Z10\nG1 Z0 F120\nX5 Y5\nG1 X5 Y9 F300\nM30\n")
    op = program.operations[0]
    np.testing.assert_array_equal(op.points_file, [[1, 2, 0], [5, 5, 0], [5, 9, 0]])
    np.testing.assert_array_equal(op.directions_file, [[0, 0, -10], [4, 3, 0], [0, 4, 0]])
    np.testing.assert_array_equal(op.axes_file, np.tile([0.0, 0.0, 1.0], (3, 1)))
    np.testing.assert_array_equal(op.feed, [120, 120, 300])
    assert op.feed_unit == "MMPM" and op.spindle_rpm == 4000 and op.lines.tolist() == [5, 6, 7]
    np.testing.assert_array_equal(op.rapids.points, [[1, 2, 10]])
    assert op.tool.kind == "flat" and op.tool.diameter == 10 and op.tool.length == 40


def test_inches_incremental_moves_and_feed_per_revolution(tmp_path):
    op = read(tmp_path, "G20 G90\nT1 M6\nG0 X1 Y1 Z1\nG91 G95\nG1 X1 Z-1 F0.004\nY-0.5\n",
              machine_units="mm").operations[0]
    np.testing.assert_allclose(op.points_file, [[50.8, 25.4, 0.0], [50.8, 12.7, 0.0]], rtol=0, atol=1e-12)
    np.testing.assert_allclose(op.feed, 0.004 * 25.4)
    assert op.feed_unit == "MMPR" and op.tool.diameter == 10
    assert read(tmp_path, "G20\nG0 X0 Y0 Z0\nG1 X1 F10\n", table=False).units == "inch"


def test_the_machine_units_of_a_tool_table_and_a_parameter_file(tmp_path):
    """LinuxCNC keeps its tool table and parameter file in the machine's units: a program in inches with
    either is refused until they are said; said in inches, their lengths (not their angles) become mm."""
    program = "G21\nT2 M6\nG55\nG0 X0 Y0 Z1\nG20\nG1 X1 F10\n"
    (tmp_path / "linuxcnc.var").write_text("5241 1.0\n5242 -2.0\n5243 0.5\n5244 90.0\n")
    message = refused(tmp_path, program)
    assert ("prog.ngc:5: G20: the program works in inches, and tools.tbl gives lengths in the machine's units"
            in message and "--machine-units mm or inch" in message)
    assert "tools.tbl and linuxcnc.var give" in refused(tmp_path, program, offsets=str(tmp_path / "linuxcnc.var"))
    (tmp_path / "inch.tbl").write_text("T2 P2 D0.25 Z+1.5 ;quarter inch bull nose R0.03\n")
    op = read(tmp_path, program, tool_table=str(tmp_path / "inch.tbl"), offsets=str(tmp_path / "linuxcnc.var"),
              machine_units="inch").operations[0]
    assert op.tool.kind == "bull-nose" and op.tool.unit == "inch"
    np.testing.assert_allclose([op.tool.diameter, op.tool.corner_radius, op.tool.length],
                               [6.35, 0.762, 38.1], rtol=0, atol=1e-12)
    # G55's offset (1, -2, 0.5) inch added to X1 inch, Y0 and Z1 mm (written before G20)
    np.testing.assert_allclose(op.points_file[-1], [2 * 25.4, -2 * 25.4, 1.0 + 0.5 * 25.4], rtol=0, atol=1e-12)
    # a program in mm throughout needs no word; a JSON offsets file is in mm
    assert read(tmp_path, "G21\nT1 M6\nG0 X0 Y0 Z0\nG1 X1 F10\n").operations[0].tool.diameter == 10
    (tmp_path / "offsets.json").write_text('{"G54": [1, 2, 3]}')
    op = read(tmp_path, "G20\nG0 X0 Y0 Z0\nG1 X1 F10\n", table=False,
              offsets=str(tmp_path / "offsets.json")).operations[0]
    np.testing.assert_allclose(op.points_file[-1], [25.4 + 1.0, 2.0, 3.0], rtol=0, atol=1e-12)


def test_blanks_inside_words_block_delete_and_comments_anywhere(tmp_path):
    op = read(tmp_path, "T1M6\nG0X0Y0Z0\n/G 1 X 1 0 . 5 (half way) F 1 0 0 ; then on\nG1 (x) Y2\n").operations[0]
    np.testing.assert_array_equal(op.points_file, [[10.5, 0, 0], [10.5, 2, 0]])


def _turns(points, centre, normal):
    """Signed angles (rad) between consecutive points about `normal` through `centre`, from the first point."""
    radial = points - centre
    radial -= np.outer(radial @ normal, normal)
    cross = np.cross(radial[:-1], radial[1:]) @ normal
    dot = np.einsum("ij,ij->i", radial[:-1], radial[1:])
    return np.arctan2(cross, dot)


@pytest.mark.parametrize("plane, normal, start, end, centre_words, centre", [
    ("G17", (0, 0, 1), (10, 0, 0), (0, 10, 0), "I-10 J0", (0, 0, 0)),
    ("G18", (0, 1, 0), (10, 5, 0), (0, 5, 10), "I-10 K0", (0, 5, 0)),
    ("G19", (1, 0, 0), (3, 10, 0), (3, 0, 10), "J-10 K0", (3, 0, 0)),
])
@pytest.mark.parametrize("code, sense", [("G2", -1.0), ("G3", 1.0)])
def test_arcs_in_every_plane_turn_as_seen_from_the_normal(tmp_path, plane, normal, start, end, centre_words, centre,
                                                          code, sense):
    letters = dict(zip("XYZ", end))
    text = (f"T1 M6\n{plane}\nG0 X{start[0]} Y{start[1]} Z{start[2]}\n"
            f"{code} X{letters['X']} Y{letters['Y']} Z{letters['Z']} {centre_words} F100\n")
    op = read(tmp_path, text).operations[0]
    points, normal, centre = op.points_file, np.array(normal, float), np.array(centre, float)
    path = np.vstack([start, points])
    assert np.allclose(np.linalg.norm(path - centre, axis=1), 10.0, atol=1e-9)  # on the circle, in its plane
    assert np.allclose((path - centre) @ normal, 0.0, atol=1e-9)
    turns = _turns(path, centre, normal)
    assert (np.sign(turns) == sense).all()  # G3 counter-clockwise seen from the normal's tip, G2 the other way
    a, b = np.array(start) - centre, np.array(end) - centre
    counter_clockwise = math.atan2(np.cross(a, b) @ normal, a @ b) % (2 * math.pi)
    assert abs(turns.sum()) == pytest.approx(counter_clockwise if sense > 0 else 2 * math.pi - counter_clockwise)
    np.testing.assert_array_equal(points[-1], end)
    tangents = op.directions_file
    assert np.allclose(np.einsum("ij,ij->i", tangents, points - centre), 0.0, atol=1e-9)
    assert (np.cross(points - centre, tangents) @ normal * sense > 0).all()
    assert op.arcs == 1 and np.linalg.norm(np.diff(path, axis=0), axis=1).max() <= 0.1 + 1e-12


def test_g17_quarter_and_three_quarter_arcs_pass_where_a_compass_says(tmp_path):
    clockwise = read(tmp_path, "T1 M6\nG0 X10 Y0 Z0\nG2 X0 Y-10 I-10 J0 F100\n").operations[0].points_file
    counter = read(tmp_path, "T1 M6\nG0 X10 Y0 Z0\nG3 X0 Y-10 I-10 J0 F100\n").operations[0].points_file
    assert np.isclose(np.linalg.norm(clockwise - [7.0710678, -7.0710678, 0], axis=1).min(), 0.0, atol=0.06)
    for passed in ([0, 10, 0], [-10, 0, 0]):
        assert np.linalg.norm(counter - passed, axis=1).min() < 0.06


def test_arc_centres_absolute_and_incremental_and_by_radius(tmp_path):
    incremental = read(tmp_path, "T1 M6\nG0 X10 Y0 Z0\nG3 X0 Y10 I-10 J0 F100\n").operations[0]
    absolute = read(tmp_path, "T1 M6\nG90.1\nG0 X10 Y0 Z0\nG3 X0 Y10 I0 J0 F100\n").operations[0]
    short = read(tmp_path, "T1 M6\nG0 X10 Y0 Z0\nG3 X0 Y10 R10 F100\n").operations[0]
    long = read(tmp_path, "T1 M6\nG0 X10 Y0 Z0\nG3 X0 Y10 R-10 F100\n").operations[0]
    np.testing.assert_allclose(absolute.points_file, incremental.points_file, rtol=0, atol=1e-12)
    np.testing.assert_allclose(short.points_file, incremental.points_file, rtol=0, atol=1e-9)
    centre = np.array([10.0, 10.0, 0.0])  # the long way round: the other centre, three quarters of a turn
    assert np.allclose(np.linalg.norm(long.points_file - centre, axis=1), 10.0, atol=1e-9)
    assert abs(_turns(np.vstack([[10, 0, 0], long.points_file]), centre, np.array([0, 0, 1.0])).sum()) == \
        pytest.approx(1.5 * math.pi)


def test_helices_and_full_turns(tmp_path):
    op = read(tmp_path, "T1 M6\nG0 X5 Y0 Z0\nG2 X5 Y0 Z-3 I-5 J0 P3 F100\n").operations[0]
    points = np.vstack([[5, 0, 0], op.points_file])
    turned = -np.cumsum(_turns(points, np.zeros(3), np.array([0, 0, 1.0])))
    assert turned[-1] == pytest.approx(6 * math.pi)
    np.testing.assert_allclose(points[1:, 2], -3.0 * turned / (6 * math.pi), rtol=0, atol=1e-9)  # Z with the angle
    full = read(tmp_path, "T1 M6\nG0 X5 Y0 Z0\nG3 X5 Y0 I-5 J0 F100\n").operations[0].points_file
    assert len(full) > 300 and np.allclose(np.linalg.norm(full[:, :2], axis=1), 5.0)


def test_work_offsets_from_a_table_and_g10(tmp_path):
    (tmp_path / "offsets.json").write_text('{"G54": [100, 0, -50], "G55": [0, 200, 0]}')
    (tmp_path / "linuxcnc.var").write_text("5220 1\n5221 100.0\n5222 0\n5223 -50\n5241 0\n5242 200.0\n")
    text = "T1 M6\nG54 G0 X0 Y0 Z0\nG1 X1 F100\nG55\nG1 X2\nG1 X2 Y0 Z0\nG10 L2 P2 X0 Y300\nG1 X3 Y0 Z0\n"
    for table in ("offsets.json", "linuxcnc.var"):
        op = read(tmp_path, text, offsets=str(tmp_path / table)).operations[0]
        # G55 takes over where the tool is (Y and Z stay), X2 moves in G55's numbers, G10 moves G55 itself.
        np.testing.assert_allclose(op.points_file, [[101, 0, -50], [2, 0, -50], [2, 200, 0], [3, 300, 0]],
                                   rtol=0, atol=1e-12)
    machine = read(tmp_path, "T1 M6\nG0 X0 Y0 Z0\nG1 X1 F100\nG53 G1 X5\n", offsets=str(tmp_path / "offsets.json"))
    np.testing.assert_array_equal(machine.operations[0].points_file, [[101, 0, -50], [5, 0, -50]])
    plain = read(tmp_path, text)  # no table: every offset zero
    np.testing.assert_array_equal(plain.operations[0].points_file, [[1, 0, 0], [2, 0, 0], [2, 0, 0], [3, 300, 0]])


def test_hole_cycles_are_hole_positions_never_cuts(tmp_path):
    text = ("T4 M6\nG0 X0 Y0 Z20\nG98 G81 X10 Y10 Z-5 R2 F50\nX20\nG91 G99 G81 X5 Y0 Z-4 R-8 L3\nG80\n"
            "G90 G1 X0 Y0 Z1 F100\nG84 X1 Y1 Z-3 R5\nG80\n")
    drill, tap = read(tmp_path, text).operations
    assert drill.cycles == ("G81",) and drill.tool.kind == "drill"
    # G98: back to the start height 20; then G91: R is 20 - 8 = 12 over that, Z 4 under R, X by 5 each time.
    np.testing.assert_array_equal(drill.cycle_points.points, [[10, 10, -5], [20, 10, -5], [25, 10, 8], [30, 10, 8],
                                                             [35, 10, 8]])
    np.testing.assert_array_equal(drill.points_file, [[0, 0, 1]])  # the one cut: the G1 after G80
    np.testing.assert_array_equal(drill.directions_file, [[-35, -10, -11]])  # from the retract plane R (G99)
    assert len(tap.lines) == 0 and tap.cycles == ("G84",)
    np.testing.assert_array_equal(tap.cycle_points.points, [[1, 1, -3]])
    assert tap.tool.kind == "tap" and tap.refusal() == ("operation 2: tap D5 mm: not a milling tool (the ABM engine "
                                                        "computes flat-end, bull-nose and ball-end mills)")


def test_tools_from_a_linuxcnc_table_by_their_comments(tmp_path):
    text = "T1 M6\nG0 X0 Y0 Z0\nG1 X1 F1\nT2 M6\nG1 X2\nT3\nM6\nG1 X3\nM61 Q1\nG1 X4\n"
    flat, ball, bull, again = read(tmp_path, text).operations
    assert (flat.tool.kind, flat.tool.diameter, flat.tool.corner_radius) == ("flat", 10, 0)
    assert (ball.tool.kind, ball.tool.diameter, ball.tool.corner_radius) == ("ball", 6, 3)
    assert (bull.tool.kind, bull.tool.diameter, bull.tool.corner_radius) == ("bull-nose", 8, 1.5)
    assert again.tool == flat.tool and ball.tool.name == "6 mm ball end"
    assert ball.refusal() is None and bull.refusal() is None  # the engine computes them


def test_freecad_posts_operations_are_operations(tmp_path):
    text = ("(begin operation: G54)\nG54\nG0 Z16\n(begin operation: TC: Mill)\nM6 T1\nM3 S1000\n"
            "(begin operation: Profile)\nG0 X0 Y0\nG1 Z0 F100\nG1 X5\n(finish operation: Profile)\n"
            "(begin operation: Finish)\nG1 X6\n")
    profile, finish = read(tmp_path, text).operations
    assert (profile.name, finish.name) == ("Profile", "Finish") and profile.spindle_rpm == 1000
    assert profile.rapids.points.tolist() == [[0, 0, 16]] and finish.points_file.tolist() == [[6, 0, 0]]


def test_inverse_time_feeds_are_each_moves_length_times_f(tmp_path):
    op = read(tmp_path, "T1 M6\nG0 X0 Y0 Z0\nG93 G1 X3 Y4 F10\nG1 X3 Y10 F2\nG94 G1 X4 F100\n").operations[0]
    np.testing.assert_allclose(op.feed, [50, 12, 100])


@pytest.mark.parametrize("text, line, words", [
    ("T1 M6\nG0 X0 Y0 Z0\nG5.2 X1\n", 3, "G5.2: not a G code this reader knows"),
    ("T1 M6\nG0 X0 Y0 Z0\nM98 P100\n", 3, "M98: subprogram calls are not read"),
    ("T1 M6\nG0 X0 Y0 Z0\nM42\n", 3, "M42: not an M code this reader knows"),
    ("T1 M6\nG0 X0 Y0 Z0 U1\n", 2, "U1: the letter U is not read"),
    ("T1 M6\n#1=5\n", 2, "#1=5: parameters and expressions"),
    ("T1 M6\no100 sub\n", 2, "O100: O-words (subroutines, loops, conditions) are not read"),
    ("T1 M6\nG0 X=10\n", 2, "X=10: assignments"),
    ("T1 M6\nG0 X1 (open\n", 2, "a comment '(' is not closed"),
    ("T1 M6\nG0 X0 Y0 Z0\nG2 X10 Y0 I3 J0 F100\n", 3, "G2: the end is 7 mm from the centre, the start 3 mm"),
    ("T1 M6\nG0 X0 Y0 Z0\nG2 X10 Y0 R2 F100\n", 3, "G2: radius 2 mm does not fit: the ends are 10 mm apart"),
    ("T1 M6\nG0 X0 Y0 Z0\nG1 X1 A30 F100\n", 3, "A30: a rotary axis word, and no machine file names the kinematics"),
    ("T1 M6\nG0 X0 Y0 Z0\nT9 M6\n", 3, "T9: M6 loads tool 9, which"),
    ("T1 M6\nX5\n", 2, "X5: an axis word with no motion in force"),
    ("T1 M6\nG91 G0 X5\n", 2, "X5: an incremental move (G91) from a X position not known yet"),
    ("T1 M6\nG0 X0 Y0\nG1 X5 F100\n", 3, "G1: a feed move to a point whose Z is not known yet"),
    ("T1 M6\nG0 X0 Y0 Z0\nG1 G2 X5 F100\n", 3, "G1 and G2 in one block: both set the motion"),
    ("T1 M6\nG0 X0 Y0 Z0\nG1 X1 X2 F100\n", 3, "X2: X is given twice in one block"),
    ("T1 M6\nG0 X0 Y0 Z0\nG92 X0\n", 3, "G92: coordinate offsets set by the program (G92) are not read"),
    ("T1 M6\nG0 X0 Y0 Z0\nG93 G1 X1\n", 3, "G1: inverse time feed (G93) needs an F word on every feed move"),
    ("T1 M6\nG0 X0 Y0 Z0\nG81 X1 Y1 Z-1\n", 3, "G81: needs R (the retract plane)"),
    ("T1 M6\nG0 X0 Y0 Z0\nG1 X1 F-5\n", 3, "F-5: a feed cannot be negative"),
])
def test_bad_gcode_gets_one_error_with_its_line(tmp_path, text, line, words):
    message = refused(tmp_path, text)
    assert message.startswith(f"{tmp_path / 'prog.ngc'}:{line}: ") and words in message, message


def test_a_tool_no_table_names(tmp_path):
    message = refused(tmp_path, "G0 X0 Y0 Z0\nT3 M6\nG1 X1 F1\n", table=False)
    assert message == (f"{tmp_path / 'prog.ngc'}:2: T3: M6 loads tool 3, and no tool table names it: give the tool "
                       "table (--tool-table FILE: a LinuxCNC tool table, or the FreeCAD document that posted the "
                       "program)")
    program = read(tmp_path, "G0 X0 Y0 Z0\nG1 X1 F1\n", table=False)
    assert program.operations[0].tool.kind == "unknown"  # a program that loads no tool


def test_bad_tool_tables_offsets_and_options(tmp_path):
    (tmp_path / "bad.tbl").write_text("T1 P1 D6\nT2 P2 Dx ;broken\n")
    assert refused(tmp_path, "T1 M6\n", tool_table=str(tmp_path / "bad.tbl")).startswith(
        f"{tmp_path / 'bad.tbl'}:2: Dx: not a tool table word")
    (tmp_path / "bad.json").write_text('{"G60": [1, 2, 3]}')
    assert "'G60' is not a work coordinate system" in refused(tmp_path, "G0 X0\n", offsets=str(tmp_path / "bad.json"))
    (tmp_path / "prog.apt").write_text("GOTO/1,2,3\n")
    with pytest.raises(InputError, match="--tool-table applies to G-code, and this file is a CL file"):
        read_program(str(tmp_path / "prog.apt"), options=ReadOptions(tool_table="x.tbl"))


def test_the_command_line_lists_gcode_and_refuses_bad_gcode_in_one_line(tmp_path, capsys):
    (tmp_path / "tools.tbl").write_text(TABLE)
    (tmp_path / "good.ngc").write_text("T1 M6\nS3000 M3\nG0 X0 Y0 Z2\nG1 Z-1 F200\nG2 X10 Y0 I5 J0\n")
    status = main(["toolpath", str(tmp_path / "good.ngc"), "--tool-table", str(tmp_path / "tools.tbl"),
                   "--out", str(tmp_path / "P.csv")])
    out = capsys.readouterr().out
    assert status == 0 and "operation 1: flat-end mill D10 mm (10mm end mill)" in out and "1 arcs" in out
    (tmp_path / "bad.ngc").write_text("T1 M6\nG0 X0 Y0 Z2\nG2 X10 Y0 R4 F100\n")
    status = main(["toolpath", str(tmp_path / "bad.ngc"), "--tool-table", str(tmp_path / "tools.tbl"),
                   "--out", str(tmp_path / "Q.csv")])
    err = capsys.readouterr().err
    assert status == 2 and err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith(f"abm: error: {tmp_path / 'bad.ngc'}:3: G2: radius 4 mm does not fit")
    assert not os.path.exists(tmp_path / "Q.csv")
