"""The in-process search in waves, against the full computation and against itself.

Where many earlier moves come near its CL points, removal_intervals searches every 16th CL
point of a call in full and the others guided by a neighbour searched before them
(docs/ENGINE.md, "Waves"). The guide only chooses which exact solves come first, so the result
must (1) equal the full computation, which culls nothing, and (2) be the same bit for bit
whichever CL points are seeds: the pass in one call, in chunks of other sizes, or every CL
point searched in full. Planted by hand, each makes the tests fail: trusting a follower's
guided envelope without the search that proves it (1); keeping a removal by its overlap with
the line's current envelope instead of its first range (2); the shift along the earlier
moves dropped (the followers' guide then misses: the spy's count of guided lines falls).
With tool axes that turn (chains that are not rigid, solved span by span), also: the closing
search skipping every span instead of those a guess or probe solved (1); a line's guess
remembering all its candidate spans as solved instead of the one it solved (1).
"""

import numpy as np
import pytest

from abm_workbench.engine import inprocess
from abm_workbench.engine.engagement import inside_intervals
from abm_workbench.engine.inprocess import inprocess_intervals, swept_pieces

from .test_inprocess import Program, edge_lines, staircase
from .test_inprocess_reach import PHI, SAME, ends, full_computation

FIELDS = ("rows", "start", "end", "start_surface", "start_section", "start_wall", "end_surface", "end_section",
          "end_wall")


def program_of_three():
    """Three passes 0.25 mm between CL points and 3 mm apart over the test stock: the first
    with the tool tilted 8° across the feed, the second upright, the third leaning 5° along
    the feed; the rows of the third."""
    program = Program()
    n = 57
    x = np.linspace(24.0, 38.0, n)
    for y, z, axis in ((-6.0, 3.0, [0.0, np.sin(np.radians(8.0)), np.cos(np.radians(8.0))]),
                       (-3.0, 2.6, [0.0, 0.0, 1.0]),
                       (0.0, 2.2, [np.sin(np.radians(5.0)), 0.0, np.cos(np.radians(5.0))])):
        points = np.stack([x, np.full(n, y), z + 0.02 * (x - 24.0)], axis=1)
        rows = program.add_pass(points, 5.0, 12.0, np.tile(axis, (n, 1)))
    return program, rows


def program_turning():
    """Three passes as program_of_three's, their tool axes turning along each pass (sub-steps
    within 0.05 mm: spans of several pieces, chains that are not rigid): the first tilting
    across the feed from 12° to 0°, the second along it from −6° to 6°, the third across it
    from 0° to −10°; the rows of the third."""
    program = Program()
    n = 57
    x = np.linspace(24.0, 38.0, n)
    for y, z, (a0, a1), across in ((-6.0, 3.0, (12.0, 0.0), True), (-3.0, 2.6, (-6.0, 6.0), False),
                                   (0.0, 2.2, (0.0, -10.0), True)):
        points = np.stack([x, np.full(n, y), z + 0.02 * (x - 24.0)], axis=1)
        angle = np.radians(np.linspace(a0, a1, n))
        zero = np.zeros(n)
        axes = np.stack([zero, np.sin(angle), np.cos(angle)] if across else [np.sin(angle), zero, np.cos(angle)], axis=1)
        rows = program.add_pass(points, 5.0, 12.0, axes)
    return program, rows


def intervals_of(program, rows, chunk=None):
    """The engine's in-process intervals of the edge lines at program `rows` (1° apart), in
    one call or in calls of `chunk` CL points, joined."""
    d = program.as_dict()
    origins, directions = edge_lines(d, rows, PHI, True)
    stock_iv = inside_intervals(staircase(), origins, directions, 12.0)
    pieces = swept_pieces(program.moves(), levels=False)  # the general search (z levels would skip it)
    if chunk is None:
        return inprocess_intervals(stock_iv, pieces, rows, origins, directions, PHI.size)[0]
    parts = []
    p = PHI.size
    for first in range(0, rows.size, chunk):
        lines = slice(first * p, min(rows.size, first + chunk) * p)
        part = inside_intervals(staircase(), origins[lines], directions[lines], 12.0)
        got = inprocess_intervals(part, pieces, rows[first:first + chunk], origins[lines], directions[lines], p)[0]
        parts.append({name: getattr(got, name) + (first * p if name == "rows" else 0) for name in FIELDS})
    return {name: np.concatenate([part[name] for part in parts]) for name in FIELDS}


@pytest.fixture
def spied(monkeypatch):
    """Counts of what the wave search did: calls, lines guided by a neighbour, lines left astray."""
    counts = {"waves": 0, "guided": 0, "astray": 0}
    waves, astray = inprocess._waves_searched, inprocess._astray

    def spy_waves(*args):
        counts["waves"] += 1
        return waves(*args)

    def spy_astray(follower, source, envelope):
        lost = astray(follower, source, envelope)
        counts["guided"] += int((~lost).sum())
        counts["astray"] += int(lost.sum())
        return lost

    monkeypatch.setattr(inprocess, "_waves_searched", spy_waves)
    monkeypatch.setattr(inprocess, "_astray", spy_astray)
    return counts


@pytest.mark.parametrize("make, rigid", [(program_of_three, True), (program_turning, False)])
def test_waves_against_full(spied, make, rigid):
    """20 consecutive CL points of the third pass in one call (seeds at the 1st and 17th, the
    others in four waves) against the full computation: with fixed tool axes (rigid chains,
    solved whole) and with turning ones (chains that are not rigid: the closing searches must
    solve their spans), the lines in the engine's frame and along the feed."""
    program, rows = make()
    rows = rows[20:40]
    d = program.as_dict()
    origins, directions = edge_lines(d, rows, PHI, rigid)
    stock_iv = inside_intervals(staircase(), origins, directions, 12.0)
    pieces = swept_pieces(program.moves(), levels=False)  # the general search (z levels would skip it)
    assert pieces.chain_rigid.all() if rigid else not pieces.any_rigid
    got, changed = inprocess_intervals(stock_iv, pieces, rows, origins, directions, PHI.size)
    assert spied["waves"] == 1 and spied["guided"] > spied["astray"] > 0
    want = full_computation(stock_iv, pieces, rows, origins, directions, PHI.size)
    np.testing.assert_allclose(got.length, want.length, rtol=0, atol=SAME)
    for mine, theirs in zip(ends(got), ends(want)):
        np.testing.assert_allclose(mine, theirs, rtol=0, atol=SAME)
    assert changed.all()


@pytest.mark.parametrize("make", [program_of_three, program_turning])
def test_waves_give_the_same_bits_whatever_the_seeds(spied, monkeypatch, make):
    """The third pass's CL points 8 … 47 in one call, in chunks of 7 and of 3 CL points (other
    seeds, other neighbours), and with every CL point searched in full: the same intervals and
    labels, bit for bit; with fixed and with turning tool axes."""
    program, rows = make()
    rows = rows[8:48]
    whole = intervals_of(program, rows)
    whole = {name: getattr(whole, name) for name in FIELDS}
    assert spied["guided"] > 0
    for chunk in (7, 3):
        chunked = intervals_of(program, rows, chunk)
        for name in FIELDS:
            np.testing.assert_array_equal(chunked[name], whole[name], err_msg=f"{name}, chunks of {chunk}")
    monkeypatch.setattr(inprocess, "_SEED_EVERY", 1)
    alone = intervals_of(program, rows)
    for name in FIELDS:
        np.testing.assert_array_equal(getattr(alone, name), whole[name], err_msg=f"{name}, every CL point a seed")
