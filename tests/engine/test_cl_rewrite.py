"""Feeds written back into a CL program: only the chosen operation's feeds change, every other
line stays byte for byte, and reading the result gives the new feeds."""

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
    assert inserted == ["FEDRAT/MMPM,400\n", "FEDRAT/MMPM,250\n"]  # the second feature sets its own feed
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
    assert inserted == [f"FEDRAT/IPM,{lowest!r}\n"]  # the file's own FEDRAT/IPM,15. follows the arc
    lines = text.splitlines()
    assert lines[lines.index(inserted[0].strip()) + 1].startswith("CIRCLE/0.,0.,-0.1,0.,0.,-1.")
    path.write_text(text)
    again = read_program(path).operations[0]
    np.testing.assert_allclose(again.feed[again.lines == 17], lowest * 25.4, rtol=1e-15)
    np.testing.assert_allclose(again.points_file, op.points_file, rtol=0, atol=0)


def test_the_feed_in_force_is_restored_for_the_operations_after(tmp_path):
    path = tmp_path / "nx.clsf"
    path.write_bytes((FIXTURES / "nx_two_ops.clsf").read_bytes().replace(b"\n", b"\r\n"))
    program = read_program(path)
    text = rewritten_text(program, 2, [100.0, 100.0, 50.0])
    kept, inserted = without_inserted(text, program.text)
    assert kept == program.text
    assert inserted == ["FEDRAT/MMPM,100\r\n", "FEDRAT/MMPM,50\r\n", "FEDRAT/MMPM,800\r\n"]
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


def test_lines_are_counted_as_the_lexer_counts_them(tmp_path):
    path = tmp_path / "l.apt"   # Latin-1 byte 0x85 reads as U+0085, which str.splitlines takes for a line end
    path.write_bytes("$$ caf\x85 \nFEDRAT/MMPM,300\nGOTO/0,0,0\nGOTO/5,0,0\n".encode("latin-1"))
    program = read_program(path)
    write_rescheduled_program(path, program, 1, [200.0, 200.0])
    assert path.read_bytes() == "$$ caf\x85 \nFEDRAT/MMPM,300\nFEDRAT/MMPM,200\nGOTO/0,0,0\nGOTO/5,0,0\n".encode(
        "latin-1")
    assert read_program(path).operations[0].feed.tolist() == [200.0, 200.0]
