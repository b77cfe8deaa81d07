"""The toolpath command: a line per operation, the CSV of every cutting CL point, read back by
the project's toolpath CSV reader and by read_program."""

from pathlib import Path

import numpy as np
import pytest

from abm_workbench.cli import main
from abm_workbench.errors import InputError
from abm_workbench.formats.cl import read_program
from abm_workbench.formats.toolpath_csv import load_toolpath

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures" / "cl"


def run(argv, capsys):
    status = main(argv)
    out, err = capsys.readouterr()
    return status, out, err


def test_summary_lines_per_operation(capsys):
    status, out, err = run(["toolpath", str(FIXTURES / "nx_two_ops.clsf")], capsys)
    assert (status, err) == (0, "")
    lines = out.splitlines()
    assert lines[0].endswith("nx_two_ops.clsf: 3 operation(s), 3 for the engine; units mm")
    cut = len(read_program(FIXTURES / "nx_two_ops.clsf").operations[0].lines)  # the summary reports the reader's count
    assert lines[1].startswith(f"operation 1 (CAVITY_MILL): flat-end mill D10 mm (EM10); {cut} CL points cut, 1 rapid, "
                               "0 canned-cycle; 1 arcs and 1 curves interpolated; axis 180..180 deg from part Z; "
                               "frame MSYS line 3; units mm; spindle 6000 rpm")
    assert lines[2].startswith("operation 2 (VARIABLE_CONTOUR): ball mill D6 R3 mm (BALL6); 3 CL points cut")
    assert "not for the engine" not in lines[2]
    assert lines[4] == ("ignored records: TOOL PATH x3 (first line 1), PAINT x5 (first line 5), "
                        "END-OF-PATH x3 (first line 29)")


@pytest.mark.parametrize("frame", ["part", "file"])
def test_csv_out_is_read_back(tmp_path, capsys, frame):
    out = tmp_path / "points.csv"
    status, text, _ = run(["toolpath", str(FIXTURES / "catia_setups.aptsource"), "--out", str(out), "--frame", frame,
                           "--tolerance", "0.01"], capsys)
    assert status == 0 and text.splitlines()[-1] == f"abm: wrote {out}"
    source = read_program(FIXTURES / "catia_setups.aptsource")
    header = out.read_text().splitlines()[0]
    assert header == ("operation,name,tool,diameter,corner_radius,flute_length,x,y,z,i,j,k,feed_x,feed_y,feed_z,"
                      "feed_rate,feed_unit,line")
    back = read_program(out)
    assert [op.name for op in back.operations] == [op.name for op in source.operations]
    for mine, theirs in zip(back.operations, source.operations):
        expected = theirs.points_part if frame == "part" else theirs.points_file
        np.testing.assert_array_equal(mine.points_file, expected)
        assert (mine.tool.kind, mine.tool.diameter, mine.feed.tolist(), mine.feed_unit) == (
            theirs.tool.kind, theirs.tool.diameter, theirs.feed.tolist(), theirs.feed_unit)
        if frame == "part" and mine.number == 1:  # the CL file's frames: its feed directions kept (its part frame
            # is the setup's moved, so both engine frames are the same)
            np.testing.assert_allclose(mine.toolpath().alpha, theirs.toolpath().alpha, rtol=0, atol=1e-9)
    first = load_toolpath(out, operation=1)
    op = source.operations[0]
    np.testing.assert_array_equal(first.cl, op.points_part if frame == "part" else op.points_file)
    with pytest.raises(InputError, match="2 operations; choose one with --operation N; operations: "
                                         "1: Pocketing.1, flat D8, 3 CL points; 2: Profile"):
        load_toolpath(out)


@pytest.mark.parametrize("content, message", [
    (b"\x00\x01\x02", "binary content"),
    (b"just words\n", "unknown content"),
    (b"GOTO/1,2\n", ":1: GOTO: takes x,y,z or x,y,z,i,j,k, got 2"),
])
def test_bad_files_exit_2_with_the_reason(tmp_path, capsys, content, message):
    path = tmp_path / "bad.ncl.3"
    path.write_bytes(content)
    status, out, err = run(["toolpath", str(path)], capsys)
    assert (status, out) == (2, "")
    assert err.startswith(f"abm: error: {path}") and message in err


def test_drilling_and_turning_programs_are_listed_not_failed(capsys):
    for name in ("mastercam_mill_drill.apt", "nx_turning.cls"):
        status, out, _ = run(["toolpath", str(FIXTURES / name)], capsys)
        assert status == 0 and ("not a milling tool" in out or "a turning program, not milling" in out)
