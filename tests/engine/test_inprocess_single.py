"""engage_in_process: the stock's Engagement where earlier moves remove nothing, the intervals
path where they do.

The engine first runs the stock's own Engagement (engage_stock) and searches removals only
within its LEP … UEP; the CL points that lose material are recomputed from their intervals.
Checked two ways: field by field against engage_stock (untouched CL points) and against the
whole intervals path (inside_intervals, inprocess_intervals, engagement_from_intervals: the
changed ones); and lengths, LEP and UEP against the brute-force reference of test_inprocess.
Planted by hand: no CL point treated as touched makes both tests fail (and the in-process
forces and test_inprocess_reach's); the changed CL points' rows left unspliced make the
brute-force test fail on the lengths (6.5 mm off at CL 1).
"""

import dataclasses

import numpy as np
import pytest

from abm_workbench.engine import CutSettings, Tool, Toolpath
from abm_workbench.engine.engagement import edge_lines, inside_intervals
from abm_workbench.engine.inprocess import inprocess_intervals, swept_pieces
from abm_workbench.engine.interval_engagement import engagement_from_intervals
from abm_workbench.engine.stocks import engage_in_process, engage_stock

from .test_inprocess import AGREE, Program, reference, staircase, straight

TOOL = Tool(10.0, 2, 12.0)


def second_pass(tilted):
    """A program of two passes side by side whose second pass (returned: program, rows,
    Toolpath) runs 6 mm from the first along its first 20 mm and on past its end: its first CL
    points lose material to the first pass, its last ones do not. `tilted`: the second pass's
    tool leans 10° across the feed (five-axis)."""
    program = Program()
    program.add_pass(straight(5, 25, -6.0, 2.5, 11), 5.0, 12.0)
    cl = straight(5, 55, 0.0, 2.5, 26)
    lean = np.radians(10.0 if tilted else 0.0)
    axes = np.tile([0.0, -np.sin(lean), np.cos(lean)], (len(cl), 1))
    rows = program.add_pass(cl, 5.0, 12.0, axes)
    return program, rows, Toolpath.from_axes(cl, axes)


def whole_intervals_path(toolpath, settings, pieces, rows):
    """The Engagement and changed (m,) of every CL point from its lines' intervals, none skipped."""
    p = settings.phi.size
    base, direction = edge_lines(toolpath, TOOL, settings.phi)
    origins, directions = base.reshape(-1, 3), np.repeat(direction, p, axis=0)
    inside = inside_intervals(staircase(), origins, directions, TOOL.flute_length)
    remaining, changed = inprocess_intervals(inside, pieces, rows, origins, directions, p)
    return engagement_from_intervals(remaining, toolpath, TOOL, settings, origins, directions), changed


@pytest.mark.parametrize("tilted", [False, True])
def test_untouched_points_are_the_stock_engagement_touched_ones_the_intervals_path(tilted):
    program, rows, toolpath = second_pass(tilted)
    settings = CutSettings(0.05, 0.0, 0.0, 180.0, 1.0)
    pieces = swept_pieces(program.moves())
    got, initial, changed = engage_in_process(staircase(), TOOL, toolpath, settings, pieces, rows)
    stock = engage_stock(staircase(), TOOL, toolpath, settings)
    whole, whole_changed = whole_intervals_path(toolpath, settings, pieces, rows)
    np.testing.assert_array_equal(changed, whole_changed)
    assert changed[:3].all() and not changed[-8:].any()
    np.testing.assert_array_equal(initial, stock.length)
    for field in dataclasses.fields(got):
        name = field.name
        if name in ("phi", "h"):
            np.testing.assert_array_equal(getattr(got, name), getattr(stock, name), err_msg=name)
            continue
        np.testing.assert_array_equal(getattr(got, name)[~changed], getattr(stock, name)[~changed], err_msg=name)
        np.testing.assert_array_equal(getattr(got, name)[changed], getattr(whole, name)[changed], err_msg=name)
    assert (got.case_names()[changed][got.engaged[changed]] == "2.5D").all()
    assert "2.5D" not in set(got.case_names()[~changed].ravel())


@pytest.mark.parametrize("tilted", [False, True])
def test_lengths_and_ends_against_the_brute_force_reference(tilted):
    """At CL points that lose material and at ones that do not, every 15°."""
    program, rows, toolpath = second_pass(tilted)
    settings = CutSettings(0.05, 0.0, 0.0, 180.0, 15.0)
    got, _, changed = engage_in_process(staircase(), TOOL, toolpath, settings, swept_pieces(program.moves()), rows)
    chosen = [1, 4, 22]
    assert changed[chosen].tolist() == [True, True, False]
    base, direction = edge_lines(toolpath, TOOL, settings.phi)
    d = program.as_dict()
    for i in chosen:
        for k in range(settings.phi.size):
            pieces = reference(base[i, k], direction[i], TOOL.flute_length, d, rows[i])
            where = f"CL {i}, phi {settings.phi[k]}"
            length = sum(end - start for start, end in pieces)
            assert abs(got.length[i, k] - length) <= AGREE, where
            if pieces:
                assert abs(got.lep_l[i, k] - pieces[0][0]) <= AGREE, where
                assert abs(got.uep_l[i, k] - pieces[-1][1]) <= AGREE, where
            else:
                assert np.isnan(got.lep_l[i, k]) and np.isnan(got.uep_l[i, k]), where
