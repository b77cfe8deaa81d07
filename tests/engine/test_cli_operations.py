"""engage on a CL program of several operations: the choice, each operation's tool, and the toolpath CSV read back."""

import os

import numpy as np
import pytest

from abm_workbench import cli
from abm_workbench.formats.results_csv import read_results

from .test_cli import JOB, M, case, run  # noqa: F401 (case is a fixture)

PROGRAM = """\
$$ two operations, two tools: a rougher D12 and a finisher D8 (flute lengths by CSI_SET_FLUTE_LENGTH)
PARTNO/TWO OPS
UNITS/MM
LOADTL/1
CUTTER/12,0,0,0,0,0,60
CSI_SET_FLUTE_LENGTH/30
SPINDL/RPM,4000,CLW
FEDRAT/MMPM,800
RAPID
GOTO/0,0,20
{first}LOADTL/2
CUTTER/8,0,0,0,0,0,50
CSI_SET_FLUTE_LENGTH/20
SPINDL/RPM,6000,CLW
FEDRAT/MMPM,960
RAPID
GOTO/0,0,20
{second}END
"""


def _moves(z_shift):
    """GOTOs of the test pass (the case's toolpath.csv: upright tool tilted by θ_B = 10°), z shifted (the second
    operation goes 0.5 mm deeper, so it still meets material the first left)."""
    axis = ",".join(f"{v:.12f}" for v in (np.sin(np.radians(10.0)), 0.0, np.cos(np.radians(10.0))))
    return "".join(f"GOTO/{x:.6f},0,{x / 60 - 1 + z_shift:.6f},{axis}\n" for x in np.linspace(10, 120, M))


@pytest.fixture
def program(case):  # noqa: F811 (the fixture imported above)
    (case / "two.cl").write_text(PROGRAM.format(first=_moves(0.0), second=_moves(-0.5)))
    return case


BASE = ["engage", "--stock", "stock.json", "--toolpath", "two.cl", "--job", "job.json", "--out", "R.csv"]


def test_several_operations_need_a_choice(program, capsys):
    status, out, err = run(BASE, capsys)
    assert status == 2 and out == ""
    message = err.splitlines()[-1]
    assert message.startswith("abm: error: two.cl: 2 milling operations; choose one with --operation N")
    assert "1: -, flat-end mill D12 mm, 12 CL points" in message and "2: -, flat-end mill D8 mm, 12 CL points" in message
    assert sorted(os.listdir(program)) == ["job.json", "stock.json", "toolpath.csv", "two.cl"]


@pytest.mark.parametrize("number, diameter, flute_length, rpm", [(1, 12, 30, 4000), (2, 8, 20, 6000)])
def test_each_operation_with_its_own_tool(program, capsys, number, diameter, flute_length, rpm):
    status, out, err = run(BASE + ["--operation", str(number)], capsys)
    assert status == 0, err
    sources = out.splitlines()[1]
    assert f"diameter {diameter} mm [two.cl CUTTER]" in sources
    assert f"flute length {flute_length} mm [two.cl CSI_SET_FLUTE_LENGTH]" in sources
    assert f"spindle {rpm} rpm [two.cl SPINDL]" in sources
    assert len(read_results(program / "R.csv")["cl"]) == M * 37


def test_the_toolpath_csv_of_an_operation_gives_the_same_results(program, capsys):
    assert run(["toolpath", "two.cl", "--out", "ops.csv"], capsys)[0] == 0
    assert run(BASE + ["--operation", "2"], capsys)[0] == 0
    from_cl = read_results(program / "R.csv")
    status, _, err = run(BASE[:4] + ["ops.csv", "--job", "job.json", "--out", "R2.csv", "--operation", "2",
                                     "--flute-length", "20"], capsys)
    # (both against the in-process stock: the CSV holds the cutting moves of both operations, not the rapids
    # between them, which here pass above the stock)
    assert status == 0, err
    from_csv = read_results(program / "R2.csv")
    for column in ("length", "lep_l", "uep_l"):
        np.testing.assert_allclose(from_csv[column], from_cl[column], atol=1e-9, equal_nan=True)
    assert JOB["diameter"] != 8  # the CSV's diameter column gave the tool, not the job


def test_an_operation_whose_material_is_gone_says_so(case, capsys):  # noqa: F811 (the fixture imported above)
    (case / "two.cl").write_text(PROGRAM.format(first=_moves(0.0), second=_moves(0.5)))
    status, _, err = run(BASE + ["--operation", "2"], capsys)
    assert status == 2 and err.splitlines()[-1] == (
        "abm: error: two.cl: earlier moves of the program already removed all the material this operation's tool "
        "would meet (--stock-model initial computes it against the stock as given)")
    status, _, err = run(BASE + ["--operation", "2", "--stock-model", "initial"], capsys)
    assert status == 0, err


def test_ball_and_bull_nose_operations_are_swept_with_their_corner(case):  # noqa: F811 (the fixture imported above)
    """inputs.program_moves: a ball (CUTTER/12,6) and a bull-nose (CUTTER/8,2) operation are swept with their corner
    radii, the chosen one with the job's tool's; a drill among them as a flat-end cylinder, which the notes say."""
    from abm_workbench.engine import Tool
    from abm_workbench.formats.cl import read_program
    from abm_workbench.jobs.inputs import program_moves

    text = PROGRAM.format(first=_moves(0.0), second=_moves(-0.5)).replace("CUTTER/12,0,", "CUTTER/12,6,").replace(
        "CUTTER/8,0,", "CUTTER/8,2,")
    text = text.replace("END\n", "LOADTL/3\nCUTTER/5,0,0,0,118,0,40\nCSI_SET_FLUTE_LENGTH/20\n"
                                 "CYCLE/DRILL,5,2,MMPM,100\n"
                                 "GOTO/50,0,10\nCYCLE/OFF\nRAPID\nGOTO/60,0,20\nGOTO/60,0,4\nEND\n")
    (case / "three.cl").write_text(text)
    program = read_program(str(case / "three.cl"))
    assert [op.tool.kind for op in program.operations] == ["ball", "bull-nose", "drill"]
    first, second, third = program.operations
    moves, rows, notes = program_moves(program, second, Tool(8.0, 2, 20.0, corner_radius=1.5))
    by_line = dict(zip(moves.line.tolist(), moves.corner_radius.tolist()))
    assert {by_line[line] for line in first.lines.tolist()} == {6.0}
    assert {by_line[line] for line in second.lines.tolist()} == {1.5}  # the job's tool, not the file's 2
    assert len(third.lines) and {by_line[line] for line in third.lines.tolist()} == {0.0}
    assert [note for note in notes if "swept as a flat-end cylinder" in note] == [
        f"{third.label()} ({third.tool.describe()}): swept as a flat-end cylinder of its diameter in the in-process "
        "stock"]
