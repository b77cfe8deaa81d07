"""A FreeCAD CAM Job built and posted by FreeCAD itself (tests/cad/freecad_cam_script.py, run by freecadcmd):
read as a document and as its linuxcnc post's G-code, the same rows; the points FreeCAD's Path commands
hold; engaged against its own stock; its scheduled feeds as a dressup that the post writes on the right
moves, the Job without it unchanged; the toolpath object following the Job as it recomputes."""

import csv
import io
import re

import numpy as np
import pytest

from abm_workbench.cad.freecad_env import FreeCAD
from abm_workbench.cli import main
from abm_workbench.errors import InputError
from abm_workbench.formats.cl import read_program
from abm_workbench.formats.cl.summary import toolpath_csv_text
from abm_workbench.formats.gcode.options import ReadOptions
from abm_workbench.jobs import Job
from abm_workbench.jobs import run as runs
from abm_workbench.jobs.job import with_cam_stock
from tests.cad.cam_builds import build_job, freecad_cam

#: (name, tool kind, diameter, corner radius, flute length, flutes, spindle) of the Job's operations.
OPERATIONS = [("Profile", "flat", 5.0, 0.0, 30.0, 2, 8000.0), ("Pocket", "bull-nose", 6.0, 1.5, 40.0, 4, 9000.0),
              ("Adaptive", "ball", 6.0, 3.0, 40.0, 2, 10000.0), ("Drilling", "drill", 5.0, None, None, 2, 3000.0)]
#: The post writes 3 decimals: a number read back is within half a unit of the last, a computed one within one.
DECIMAL = 1e-3


@pytest.fixture(scope="module")
def cam(tmp_path_factory):
    """The folder with job.FCStd, job.ngc (its linuxcnc post) and tools.tbl."""
    return build_job(tmp_path_factory.mktemp("cam"))


def rows(program):
    """The toolpath CSV rows of `program` as dicts."""
    return list(csv.DictReader(io.StringIO(toolpath_csv_text(program))))


def test_the_document_and_its_post_give_the_same_rows_and_tools(cam):
    document = read_program(str(cam / "job.FCStd"))
    posted = read_program(str(cam / "job.ngc"), options=ReadOptions(tool_table=str(cam / "job.FCStd")))
    assert document.stock == "Stock" and posted.format == "gcode" and document.format == "fcstd"
    for program in (document, posted):
        described = [(op.name, op.tool.kind, op.tool.diameter, op.tool.corner_radius, op.tool.flute_length,
                      op.tool.flutes, op.spindle_rpm) for op in program.operations]
        assert described == OPERATIONS
    for ours, theirs in zip(document.operations, posted.operations):
        assert ours.tool == theirs.tool and ours.arcs == theirs.arcs and ours.cycles == theirs.cycles
        np.testing.assert_allclose(ours.cycle_points.points, theirs.cycle_points.points, rtol=0, atol=DECIMAL / 2)
    a, b = rows(document), rows(posted)
    assert len(a) == len(b) > 1500
    for column in ("operation", "name", "tool", "diameter", "corner_radius", "flute_length", "i", "j", "k",
                   "feed_unit"):
        assert [row[column] for row in a] == [row[column] for row in b], column
    for column in ("x", "y", "z", "feed_rate"):
        ours, theirs = (np.array([float(row[column]) for row in table]) for table in (a, b))
        np.testing.assert_allclose(ours, theirs, rtol=0, atol=DECIMAL, err_msg=column)
    for ours, theirs in zip(document.operations, posted.operations):
        # A straight move's direction is its chord, which the rounding of its two ends changes by a decimal at
        # most; an arc's is its unit tangent, turned by the rounding of the centre over the radius.
        np.testing.assert_allclose(ours.directions_file, theirs.directions_file, rtol=0, atol=2 * DECIMAL)


def _commands(op):
    """[(command number, name, end point (3,), centre (3,) or None)] of the moves of a CAM operation's Path."""
    found, here = [], np.full(3, np.nan)
    for number, command in enumerate(op.Path.Commands, start=1):
        parameters = command.Parameters
        start = here.copy()
        for index, letter in enumerate("XYZ"):
            here[index] = parameters.get(letter, here[index])
        if command.Name in ("G0", "G1", "G2", "G3") and not np.isnan(here).any():
            centre = None
            if command.Name in ("G2", "G3"):
                centre = start + [parameters.get("I", 0.0), parameters.get("J", 0.0), 0.0]
                centre[2] = 0.0
            found.append((number, command.Name, here.copy(), centre))
    return found


def test_the_points_are_those_freecads_path_commands_hold(cam):
    program = read_program(str(cam / "job.FCStd"))
    document = FreeCAD.openDocument(str(cam / "job.FCStd"), True)
    try:
        for operation in program.operations:
            cam_op = document.getObject(operation.name)
            checked = 0
            for number, name, end, centre in _commands(cam_op):
                if name == "G0":
                    assert number in operation.rapids.lines
                    continue
                at = operation.points_part[operation.lines == number]
                np.testing.assert_array_equal(at[-1], end)  # every feed move ends at its command's point
                if centre is not None:  # and an arc's points lie on its circle
                    radius = np.linalg.norm((end - centre)[:2])
                    assert np.allclose(np.linalg.norm(at[:, :2] - centre[:2], axis=1), radius, atol=1e-6)
                checked += 1
            assert checked == len(set(operation.lines.tolist()))
    finally:
        FreeCAD.closeDocument(document.Name)


def test_the_post_with_a_linuxcnc_tool_table(cam):
    posted = read_program(str(cam / "job.ngc"), options=ReadOptions(tool_table=str(cam / "tools.tbl")))
    assert [(op.tool.kind, op.tool.diameter, op.tool.corner_radius) for op in posted.operations] == [
        ("flat", 5.0, 0.0), ("bull-nose", 6.0, 1.5), ("ball", 6.0, 3.0), ("drill", 5.0, None)]
    with pytest.raises(InputError, match=r"job.ngc:\d+: T1: M6 loads tool 1, and no tool table names it"):
        read_program(str(cam / "job.ngc"))


def _results(path):
    """{column: (n,) floats} of a results CSV."""
    with open(path, encoding="utf-8") as file:
        table = list(csv.DictReader(file))
    return {key: np.array([float(row[key]) if row[key] else np.nan for row in table]) for key in ("cl", "length")}


def test_engage_runs_against_the_jobs_own_stock(cam, tmp_path, capsys):
    # The Job's profile: its pocket (bull-nose) and adaptive (ball) are for the engine too.
    common = ["--feed-per-tooth", "0.02", "--phi-step", "5", "--stock-model", "initial", "--operation", "1"]
    assert main(["engage", "--toolpath", str(cam / "job.FCStd"), *common, "--out", str(tmp_path / "doc.csv")]) == 0
    out = capsys.readouterr().out
    assert "2 flutes [job.FCStd TC: 5mm_Endmill (T1) toolbit 5mm Endmill]" in out and "spindle 8000 rpm" in out
    assert main(["engage", "--toolpath", str(cam / "job.FCStd"), "--stock", str(cam / "job.FCStd"), "--solid", "Stock",
                 *common, "--out", str(tmp_path / "named.csv")]) == 0
    assert (tmp_path / "doc.csv").read_bytes() == (tmp_path / "named.csv").read_bytes()
    # The post, its tools from a LinuxCNC table, against the Job's document as the stock: its Job's Stock.
    assert main(["engage", "--toolpath", str(cam / "job.ngc"), "--tool-table", str(cam / "tools.tbl"), "--stock",
                 str(cam / "job.FCStd"), "--flutes", "2", "--flute-length", "30", *common,
                 "--out", str(tmp_path / "posted.csv")]) == 0
    document, posted = _results(tmp_path / "doc.csv"), _results(tmp_path / "posted.csv")
    assert np.nanmax(document["length"]) > 1.0
    # The post's rounding moves the CL points by up to half a decimal: the lengths of cut follow.
    np.testing.assert_allclose(posted["length"], document["length"], rtol=0, atol=0.05)
    stock = with_cam_stock(Job(None, str(cam / "job.FCStd")))
    assert (stock.stock, stock.solid) == (str(cam / "job.FCStd"), "Stock")
    assert with_cam_stock(Job(str(cam / "job.FCStd"), str(cam / "job.ngc"))).solid == "Stock"
    with pytest.raises(InputError, match="give the stock"):
        with_cam_stock(Job(None, str(cam / "job.ngc")))


_WORD_F = re.compile(r" F[0-9.]+")


def test_the_scheduled_feeds_as_a_dressup_that_the_post_writes(cam, tmp_path):
    original = (cam / "job.FCStd").read_bytes()
    job = Job(None, str(cam / "job.FCStd"), operation=1, given={"feed_per_tooth": 0.03, "phi_step": 5},
              material="al7075-t6", stock_model="initial")
    result = runs.schedule(with_cam_stock(job), str(tmp_path / "scheduled.FCStd"), max_force=400.0,
                           warn=lambda message: None)
    assert (cam / "job.FCStd").read_bytes() == original  # the Job itself is left as it was
    assert result.plan.reduced.any() and not result.plan.reduced.all()
    operation = result.prepared.hints.operation
    per_minute = result.plan.feed * result.prepared.tool.flutes * result.prepared.settings.spindle_rpm
    # Both documents posted as saved (a post of the Job as built differs in the sign of some -0.000).
    for name in ("job", "scheduled"):
        document = cam / "job.FCStd" if name == "job" else tmp_path / "scheduled.FCStd"
        output = freecad_cam("post", str(document), str(tmp_path / f"{name}.ngc"), cwd=tmp_path)
        assert (tmp_path / f"{name}.ngc").is_file(), output
    before = (tmp_path / "job.ngc").read_text().splitlines()[3:]  # after the header's time
    after = (tmp_path / "scheduled.ngc").read_text().splitlines()[3:]
    assert len(before) == len(after)
    changed = [k for k, (old, new) in enumerate(zip(before, after)) if old != new]
    start = after.index("(begin operation: Profile (scheduled feeds))")
    end = after.index("(finish operation: Profile (scheduled feeds))")
    assert changed[0] == start and changed[-1] == end  # nothing outside the scheduled operation changed
    for k in changed[1:-1]:
        assert _WORD_F.sub("", before[k]) == _WORD_F.sub("", after[k])  # only F words changed
    moves = [line for line in after[start:end] if line.split(" ")[0] in ("G1", "G2", "G3")]
    feeds = [float(_WORD_F.search(line).group()[2:]) for line in moves]
    expected = [per_minute[operation.lines == number].min() for number in sorted(set(operation.lines.tolist()))]
    assert len(feeds) == len(expected)
    np.testing.assert_allclose(feeds, expected, rtol=0, atol=DECIMAL / 2)
    scheduled = read_program(str(tmp_path / "scheduled.FCStd")).operations[0]
    assert scheduled.name == "Profile (scheduled feeds)"
    # Read back from the saved dressup: FreeCAD keeps F in mm/s with 6 decimals.
    np.testing.assert_allclose(scheduled.feed, [expected[sorted(set(operation.lines.tolist())).index(n)]
                                                for n in operation.lines], rtol=1e-6)


def test_the_toolpath_follows_the_job_as_it_recomputes(cam, tmp_path):
    from abm_workbench.cam.freecad_cam import make_importable
    from abm_workbench.features import create_engagement, create_stock, create_toolpath

    assert make_importable()
    path = tmp_path / "live.FCStd"
    path.write_bytes((cam / "job.FCStd").read_bytes())
    document = FreeCAD.openDocument(str(path))
    try:
        job, profile = document.getObject("Job"), document.getObject("Profile")
        stock = create_stock(document, job.Stock)
        toolpath = create_toolpath(document, cam_job=job, cam_operation=profile)
        engagement = create_engagement(document, stock, toolpath, feed_per_tooth=0.02, phi_step=10,
                                       stock_model="initial")
        document.recompute()
        assert engagement.isValid() and toolpath.CLPoints == len(read_program(str(path)).operations[0].lines)
        points, instants = toolpath.CLPoints, engagement.Instants
        profile.setExpression("StepDown", None)
        profile.StepDown = 1.0
        document.recompute()
        assert toolpath.CLPoints > 2 * points and engagement.Instants > 2 * instants and engagement.isValid()
        assert engagement.Diameter.Value == 5.0 and engagement.Flutes == 2
    finally:
        FreeCAD.closeDocument(document.Name)


def test_documents_without_one_job(tmp_path):
    document = FreeCAD.newDocument("NoJob")
    document.addObject("Part::Box", "Box")
    document.recompute()
    document.saveAs(str(tmp_path / "nojob.FCStd"))
    FreeCAD.closeDocument(document.Name)
    with pytest.raises(InputError, match="nojob.FCStd: no FreeCAD CAM Job in the document"):
        read_program(str(tmp_path / "nojob.FCStd"))
    with pytest.raises(InputError, match="no CAM Job named 'Other'"):
        read_program(str(tmp_path / "nojob.FCStd"), options=ReadOptions(cam_job="Other"))
