"""Feeds written back into a CL program: only the chosen operation's feeds change, every other
line stays byte for byte, and reading the result gives the new feeds."""

import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from abm_workbench.errors import InputError
from abm_workbench.formats.cl import read_program
from abm_workbench.formats.cl.rewrite import rewritten_text, write_rescheduled_program

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures" / "cl"


def without_inserted(text, original):
    """`text` with the lines that are not in `original` (the inserted FEDRATs) taken out, and those lines."""
    kept, inserted = [], []
    old = original.splitlines(keepends=True)
    position = 0
    for line in text.splitlines(keepends=True):
        if position < len(old) and line == old[position]:
            kept.append(line)
            position += 1
        else:
            inserted.append(line)
    return "".join(kept), inserted


def test_creo_first_feature_slowed_and_the_second_as_it_was(tmp_path):
    path = tmp_path / "creo.ncl.3"
    shutil.copy(FIXTURES / "creo_features.ncl.3", path)
    program = read_program(path)
    new = np.array([400.0, 250.0, 250.0])
    out = tmp_path / "out.ncl"
    write_rescheduled_program(out, program, 1, new)
    text = out.read_text()
    kept, inserted = without_inserted(text, program.text)
    assert kept == program.text
    assert inserted == ["FEDRAT / 400.000000, MMPM\n", "FEDRAT / 250.000000, MMPM\n"]  # the second sets its own
    again = read_program(out)
    assert again.operations[0].feed.tolist() == new.tolist()
    assert again.operations[1].feed.tolist() == [700.0, 700.0]
    assert [op.lines.size for op in again.operations] == [3, 2]


def test_inch_file_gets_inch_feeds_and_arcs_one_fedrat_before_the_circle(tmp_path):
    path = tmp_path / "sw.clt"
    shutil.copy(FIXTURES / "solidworks_cam_inch.clt", path)
    program = read_program(path)
    op = program.operations[0]
    new = np.where(op.lines == 16, 254.0, op.feed)  # slow down the second arc only
    new[op.lines == 16] -= np.arange((op.lines == 16).sum()) * 1e-3   # the lowest of an arc's points is written
    text = rewritten_text(program, 1, new)
    kept, inserted = without_inserted(text, program.text)
    assert kept == program.text
    lowest = (254.0 - ((op.lines == 16).sum() - 1) * 1e-3) / 25.4
    written = math.floor(lowest * 1e6) / 1e6   # rounded down at 6 decimals, trailing zeros dropped as the file does
    assert inserted == [f"FEDRAT/IPM,{written:.6f}".rstrip("0") + "\n"]  # the file's FEDRAT/IPM,15. follows
    lines = text.splitlines()
    assert lines[lines.index(inserted[0].strip()) + 1].startswith("CIRCLE/0.,0.,-0.1,0.,0.,-1.")
    path.write_text(text)
    again = read_program(path).operations[0]
    np.testing.assert_allclose(again.feed[again.lines == 17], written * 25.4, rtol=1e-15)
    assert (again.feed[again.lines == 17] <= lowest * 25.4).all()
    np.testing.assert_allclose(again.points_file, op.points_file, rtol=0, atol=0)


def test_the_feed_in_force_is_restored_for_the_operations_after(tmp_path):
    path = tmp_path / "nx.clsf"
    path.write_bytes((FIXTURES / "nx_two_ops.clsf").read_bytes().replace(b"\n", b"\r\n"))
    program = read_program(path)
    text = rewritten_text(program, 2, [100.0, 100.0, 50.0])
    kept, inserted = without_inserted(text, program.text)
    assert kept == program.text
    assert inserted == ["FEDRAT/MMPM,100.0000\r\n", "FEDRAT/MMPM,50.0000\r\n", "FEDRAT/MMPM,800.0000\r\n"]
    path.write_bytes(text.encode())
    again = read_program(path)
    assert [op.feed.tolist() for op in again.operations[1:]] == [[100.0, 100.0, 50.0], [800.0, 800.0]]
    assert (again.operations[0].feed == 400.0).all()


def test_unchanged_feeds_give_the_same_bytes(tmp_path):
    path = tmp_path / "nx.clsf"
    shutil.copy(FIXTURES / "nx_two_ops.clsf", path)
    program = read_program(path)
    assert rewritten_text(program, 3, program.operations[2].feed) == program.text


def test_bad_feeds_and_csv_programs_are_refused(tmp_path):
    program = read_program(FIXTURES / "nx_two_ops.clsf")
    with pytest.raises(ValueError, match="feed has 1 values, operation 3 2 cutting CL points"):
        rewritten_text(program, 3, [100.0])
    with pytest.raises(ValueError, match="must be positive"):
        rewritten_text(program, 3, [100.0, 0.0])
    csv = tmp_path / "p.csv"
    csv.write_text("x,y,z,i,j,k\n0,0,0,0,0,1\n")
    with pytest.raises(InputError, match="only a CL"):
        rewritten_text(read_program(csv), 1, [1.0])


def test_latin1_file_keeps_its_bytes(tmp_path):
    path = tmp_path / "l.apt"
    original = "$$ Opération d'ébauche\nFEDRAT/MMPM,300\nGOTO/0,0,0\nGOTO/5,0,0\n".encode("latin-1")
    path.write_bytes(original)
    program = read_program(path)
    out = tmp_path / "o.apt"
    write_rescheduled_program(out, program, 1, [300.0, 300.0])
    assert out.read_bytes() == original


def test_floating_error_in_an_unchanged_feed_inserts_nothing_and_a_step_less_does(tmp_path):
    program = read_program(FIXTURES / "nx_two_ops.clsf")
    feed = program.operations[2].feed * (1.0 - 2.0 ** -52)   # 800 as a computation may give it back
    assert rewritten_text(program, 3, feed) == program.text
    _, inserted = without_inserted(rewritten_text(program, 3, [800.0, 799.99999]), program.text)
    assert inserted == ["FEDRAT/MMPM,799.9999\n"]   # rounded down, never up to the feed in force


def test_a_feed_that_rounds_down_to_zero_is_refused_naming_the_operation_and_line(tmp_path):
    path = tmp_path / "turn.cls"
    shutil.copy(FIXTURES / "nx_turning.cls", path)
    program = read_program(path)
    assert rewritten_text(program, 1, [0.1, 0.0001, 0.25]).splitlines()[4:8] == [
        "FEDRAT/MMPR,0.1000", "GOTO/100.0000,30.0000,0.0000", "FEDRAT/MMPR,0.2500", "FEDRAT/MMPR,0.0001"]
    with pytest.raises(InputError, match=r"turn\.cls:7: operation 1 \(ROUGH_TURN_OD\): the feed 5e-05 MMPR rounds "
                                         r"down to 0 at the 4 decimals this file writes its feeds with"):
        rewritten_text(program, 1, [0.1, 0.00005, 0.25])


@pytest.mark.parametrize("first, more, feed, written", [
    ("FEDRAT/MMPM,873.2213", "GOTO/0.0000,0.0000,9.0000\n", 600.0, "FEDRAT/MMPM,600.0000"),  # NX: 4 fixed decimals
    ("FEDRAT/801.963285,MMPM", "GOTO/0.,0.,9.\n", 600.0, "FEDRAT/600.,MMPM"),  # SOLIDWORKS CAM: no trailing zeros
    ("FEDRAT/500,MMPM", "", 600.0, "FEDRAT/600,MMPM"),
    ("FEDRAT/500,MMPM", "", 512.5, "FEDRAT/512.5,MMPM"),
    ("FEDRAT/900.00,MMPM", "FEDRAT/1000,MMPM\n", 512.5, "FEDRAT/512.50,MMPM"),  # another FEDRAT's 2 decimals
    ("FEDRAT/MMPR,0.2500", "", 0.1, "FEDRAT/MMPR,0.1000"),
    ("FEDRAT/MMPR,.25", "", 0.1, "FEDRAT/MMPR,.1"),
    ("FEDRAT/MMPR,0.25", "", 0.1, "FEDRAT/MMPR,0.1"),
    ("FEDRAT/MMPR,1.", "GOTO/-.5,0,9\n", 0.1, "FEDRAT/MMPR,.1"),  # the file writes numbers under 1 as .5
    ("FEDRAT /MMPM ,  400.0000 ,", "", 600.0, "FEDRAT /MMPM ,  600.0000 ,"),
    ("FEDRAT/MMPM,400.0000 $$ roughing", "", 9.87654321, "FEDRAT/MMPM,9.8765"),
])
def test_an_inserted_fedrat_is_written_as_the_one_in_force(tmp_path, first, more, feed, written):
    path = tmp_path / "t.apt"
    path.write_text(f"{first}\n{more}GOTO/0,0,0\nGOTO/1,0,0\n")
    program = read_program(path)
    op = program.operations[-1]
    _, inserted = without_inserted(rewritten_text(program, op.number, [feed] * op.lines.size), program.text)
    assert inserted == [written + "\n"]



@pytest.mark.parametrize("records, written", [
    ("UNITS / MM\nLOADTL / 1\nGOTO / 0.0000000000, 0.0000000000, -1.0000000000\n", "FEDRAT / 873.221282, MMPM"),
    ("loadtl/ 1, adjust, 1, mill\ngoto  / 0.00000, 0.00000, -2.00000\n", "fedrat/ 873.221282, mmpm"),  # CATIA
    ("GOTO/0,0,9\n", "FEDRAT/873.221282,MMPM"),
    ("UNITS/INCHES\nGOTO/0,0,9\n", "FEDRAT/34.378790,IPM"),
])
def test_a_file_without_fedrat_gets_the_case_and_blanks_of_its_records(tmp_path, records, written):
    path = tmp_path / "t.apt"
    path.write_text(f"{records}GOTO/0,0,0\nGOTO/1,0,0\n")
    program = read_program(path)
    text = rewritten_text(program, 1, [873.2212826059239] * 3)
    _, inserted = without_inserted(text, program.text)
    assert inserted == [written + "\n"]
    path.write_text(text)
    assert read_program(path).operations[0].feed.tolist() == [float(written.split("/")[1].split(",")[0]) *
                                                              (25.4 if "IPM" in written else 1.0)] * 3


def test_a_bare_fedrat_gets_its_unit_word_where_a_bare_number_would_read_in_another_unit(tmp_path):
    path = tmp_path / "t.apt"
    path.write_text("UNITS/INCHES\nFEDRAT/20.\nGOTO/0,0,0\nGOTO/1,0,0\nFEDRAT/.004,IPR\nGOTO/2,0,0\n")
    program = read_program(path)   # one operation of feeds per minute, then per revolution: MMPR
    text = rewritten_text(program, 1, [0.1, 0.1, 0.1])
    assert without_inserted(text, program.text)[1] == ["FEDRAT/.003937,IPR\n", "FEDRAT/.003937,IPR\n"]
    path.write_text(text)
    assert read_program(path).operations[0].feed.tolist() == [0.003937 * 25.4] * 3


def test_lines_are_counted_as_the_lexer_counts_them(tmp_path):
    path = tmp_path / "l.apt"   # Latin-1 byte 0x85 reads as U+0085, which str.splitlines takes for a line end
    path.write_bytes("$$ caf\x85 \nFEDRAT/MMPM,300\nGOTO/0,0,0\nGOTO/5,0,0\n".encode("latin-1"))
    program = read_program(path)
    write_rescheduled_program(path, program, 1, [200.0, 200.0])
    assert path.read_bytes() == "$$ caf\x85 \nFEDRAT/MMPM,300\nFEDRAT/MMPM,200\nGOTO/0,0,0\nGOTO/5,0,0\n".encode(
        "latin-1")
    assert read_program(path).operations[0].feed.tolist() == [200.0, 200.0]
