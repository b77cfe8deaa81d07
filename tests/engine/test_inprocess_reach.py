"""The in-process engine's culling against the full computation, which culls nothing.

The full computation solves every (edge line, swept piece) pair whose move ends before the
line's CL point in closed form and subtracts all of them: what the engine's bounds (group
capsules, chains, spans, sure-miss tests, narrowed envelopes) leave out must change nothing.
The closed form itself is checked against the brute-force sampler in test_inprocess. The
angles are 1° apart, as in a real run, so that the groups of neighbouring lines are those a
run makes. A bound made 1 mm too tight, tried by hand: a group capsule's radius makes the
curving, adjacent, recrossing, five-axis and dense cases fail; a chain's radius (the per-line
chain test, which only many nearby moves reach) makes the dense case fail.
"""

import numpy as np
import pytest

from abm_workbench.engine import CutSettings, Tool, Toolpath
from abm_workbench.engine.engagement import inside_intervals
from abm_workbench.engine.inprocess import ProgramMoves, inprocess_intervals, subtract, swept_pieces
from abm_workbench.engine.inprocess_reach import capsule_spheres, group_capsules
from abm_workbench.engine.stocks import engage_in_process
from abm_workbench.engine.swept import line_hull_interval

from .test_inprocess import Program, edge_lines, staircase, straight

PHI = np.arange(0.0, 181.0, 1.0)
SAME = 1e-9  # mm: the culling drops only pairs that remove nothing


def full_computation(stock_iv, pieces, rows, origins, directions, p):
    """The stock intervals minus every piece that precedes each line's CL point, none culled."""
    n, count = origins.shape[0], pieces.move.size
    line, piece = np.repeat(np.arange(n), count), np.tile(np.arange(count), n)
    earlier = pieces.move[piece] <= rows[line // p] - 1
    line, piece = line[earlier], piece[earlier]
    enter, leave = line_hull_interval(origins[line], directions[line], pieces.c0[piece], pieces.c1[piece],
                                      pieces.axis[piece], pieces.radius[piece], pieces.height[piece])
    hit = np.isfinite(enter) & (leave > enter)
    return subtract(stock_iv, line[hit], enter[hit], leave[hit])


def ends(intervals):
    """(LEP, UEP) (N,) of each line's first start and last end, NaN where it has none."""
    lep, uep = np.full(intervals.n_rows, np.nan), np.full(intervals.n_rows, np.nan)
    if intervals.rows.size:
        first = np.r_[True, intervals.rows[1:] != intervals.rows[:-1]]
        last = np.r_[intervals.rows[1:] != intervals.rows[:-1], True]
        lep[intervals.rows[first]], uep[intervals.rows[last]] = intervals.start[first], intervals.end[last]
    return lep, uep


def against_full(program, rows, fixed=False, tolerance=0.05, levels=(True, False)):
    """The engine at program `rows` (1° apart) against the full computation, with the program's z levels in
    plan view and without (every move to the general search: `levels`); returns changed (m,)."""
    d = program.as_dict()
    origins, directions = edge_lines(d, rows, PHI, fixed)
    flute = d["flute"][rows].max()
    stock_iv = inside_intervals(staircase(), origins, directions, flute)
    want = None
    for plan in levels:
        pieces = swept_pieces(program.moves(), tolerance, levels=plan)
        got, changed = inprocess_intervals(stock_iv, pieces, rows, origins, directions, PHI.size)
        if want is None:
            want = full_computation(stock_iv, pieces, rows, origins, directions, PHI.size)
        np.testing.assert_allclose(got.length, want.length, rtol=0, atol=SAME)
        for mine, theirs in zip(ends(got), ends(want)):
            np.testing.assert_allclose(mine, theirs, rtol=0, atol=SAME)
        lost = (stock_iv.length - want.length).reshape(rows.size, PHI.size).max(axis=1)
        assert np.array_equal(changed, lost > SAME)
    return changed


def test_curving_pass_against_full():
    """A pass along a tight arc, in a tool frame that does not turn with the feed: its flanks
    lose material to its own earlier moves."""
    program = Program()
    angle = np.radians(np.linspace(-90, 10, 41))
    arc = np.stack([30 + 12 * np.cos(angle), 12 * np.sin(angle) + 2, np.full(angle.size, 3.0)], axis=1)
    rows = program.add_pass(arc, 5.0, 12.0)
    changed = against_full(program, rows[3:40:3], fixed=True)
    assert changed.any()


def test_adjacent_passes_against_full():
    """Three passes side by side, 0.6 D apart, the third checked."""
    program = Program()
    for y in (-6.0, 0.0, 6.0):
        rows = program.add_pass(straight(5, 55, y, 2.5, 31), 5.0, 12.0)
    assert against_full(program, rows[2:30:3]).all()


def test_recrossing_pass_against_full():
    """A pass along y crosses two along x, then comes back along x over the first."""
    program = Program()
    program.add_pass(straight(5, 55, 0.0, 3.0, 18), 5.0, 12.0)
    program.add_pass(straight(55, 5, 9.0, 3.0, 18), 5.0, 12.0)
    crossing = np.stack([np.full(15, 30.0), np.linspace(-20, 20, 15), np.full(15, 2.0)], axis=1)
    program.add_pass(crossing, 4.0, 12.0)
    rows = program.add_pass(straight(50, 10, 2.0, 2.5, 21), 5.0, 12.0)
    changed = against_full(program, rows[1:21:2])
    assert changed.all()


def test_five_axis_moves_against_full():
    """A pass whose tool leans more and more, then a tilted pass beside it (sub-stepped moves)."""
    program = Program()
    n = 16
    lean = np.radians(np.linspace(0, 20, n))
    program.add_pass(straight(10, 50, -3.0, 3.0, n), 5.0, 12.0,
                     np.stack([np.sin(lean), np.zeros(n), np.cos(lean)], axis=1))
    tilt = np.radians(np.linspace(-10, 10, n))
    rows = program.add_pass(straight(12, 48, 4.0, 2.0, n), 5.0, 12.0,
                            np.stack([np.zeros(n), np.sin(tilt), np.cos(tilt)], axis=1))
    assert against_full(program, rows[1:16:2]).any()


@pytest.mark.parametrize("y, z", [(9.0, 4.0), (3.0, 0.5)], ids=["tops", "rims"])
def test_swinging_tool_against_full(y, z):
    """A tool swinging its axis by 70° while it creeps 2 mm, so that a chain's pieces lean far
    from the chain's mean axis; then a pass beside it at height z, y mm to the side: its lines
    meet the swung tops (y = 9: the lean's bound across the axis) or pass under and along the
    dipping rims (y = 3: the bound along the axis, and pairs that graze a side, which only
    the sure-miss test's clearance keeps from being dropped by rounding). Each of these three
    bounds, left out by hand, makes its case fail."""
    program = Program()
    n = 15
    swing = np.radians(np.linspace(-35.0, 35.0, n))
    program.add_pass(straight(8.0, 10.0, 0.0, 1.0, n), 5.0, 12.0,
                     np.stack([np.zeros(n), np.sin(swing), np.cos(swing)], axis=1))
    rows = program.add_pass(straight(4.0, 14.0, y, z, 11), 5.0, 12.0)
    assert against_full(program, rows[1:11]).any()


def test_dense_curved_passes_against_full():
    """Two curved passes 0.25 mm between CL points, 4 mm apart, the first with a tilted tool:
    many lines meet many chains, so the per-line chain test is used."""
    n = 145
    angle = np.radians(np.linspace(-35.0, 35.0, n))
    program = Program()
    tilt = np.radians(8.0)
    for centre_y, z, axes in ((-20.0, 3.0, np.tile([0.0, np.sin(tilt), np.cos(tilt)], (n, 1))), (-24.0, 2.0, None)):
        arc = np.stack([30.0 + 30.0 * np.sin(angle), centre_y + 30.0 * np.cos(angle), np.full(n, z)], axis=1)
        rows = program.add_pass(arc, 5.0, 12.0, axes)
    assert against_full(program, rows[[40, 60, 100]], fixed=True).all()


def test_untouched_instants_keep_the_initial_result():
    """engage_in_process: CL points that nothing earlier touches report exactly what the initial
    stock's intervals give (lengths, ends, labels, case); the others lose material."""
    program = Program()
    program.add_pass(straight(5, 25, -6.0, 2.5, 11), 5.0, 12.0)
    rows = program.add_pass(straight(5, 55, 0.0, 2.5, 26), 5.0, 12.0)
    d = program.as_dict()
    tool = Tool(10.0, 2, 12.0)
    path = Toolpath(d["cl"][rows], np.zeros(rows.size), np.zeros(rows.size))
    settings = CutSettings(0.05, 0.0, 0.0, 180.0, 1.0)
    pieces = swept_pieces(program.moves())
    got, initial, changed = engage_in_process(staircase(), tool, path, settings, pieces, rows)
    # The same pass with no earlier moves at all: the initial stock's Engagement.
    alone = Program()
    alone_rows = alone.add_pass(d["cl"][rows], 5.0, 12.0)
    first, _, untouched = engage_in_process(staircase(), tool, path, settings, swept_pieces(alone.moves()), alone_rows)
    assert not untouched.any()
    np.testing.assert_array_equal(first.length, initial)
    keep = ~changed
    assert keep[-5:].all() and changed[:5].all()
    for name in ("length", "lep_l", "uep_l", "case", "lep_surface", "uep_surface", "pieces"):
        np.testing.assert_array_equal(getattr(got, name)[keep], getattr(first, name)[keep], err_msg=name)
    assert (got.length[changed].sum(axis=1) < initial[changed].sum(axis=1)).all()


def test_group_capsules_hold_their_segments():
    """Every point of every live segment lies in its group's capsule, lines of mixed directions
    too; the capsules of parallel lines on a small arc are thin; dead groups get −inf."""
    rng = np.random.default_rng(7)
    n = 400
    group = np.sort(rng.integers(0, 30, n))
    directions = rng.normal(size=(n, 3)) + [0.0, 0.0, 4.0]
    directions /= np.linalg.norm(directions, axis=1)[:, None]
    origins = rng.uniform(-20, 20, (n, 3))
    lo = rng.uniform(0, 5, n)
    envelope = np.stack([lo, lo + rng.uniform(-1, 10, n)])
    a, b, radius = group_capsules(group, 31, envelope, origins, directions)
    live = envelope[0] < envelope[1]
    t = np.linspace(0.0, 1.0, 11)
    for i in np.flatnonzero(live):
        points = origins[i] + (envelope[0, i] + t * (envelope[1, i] - envelope[0, i]))[:, None] * directions[i]
        axis = b[group[i]] - a[group[i]]
        s = np.clip((points - a[group[i]]) @ axis / max(axis @ axis, 1e-300), 0.0, 1.0)
        gap = np.linalg.norm(points - a[group[i]] - s[:, None] * axis, axis=1)
        assert gap.max() <= radius[group[i]] + 1e-9
    dead = np.setdiff1d(np.arange(31), group[live])
    assert dead.size and np.all(radius[dead] == -np.inf)
    centre, bound = capsule_spheres(a, b, radius)
    for i in np.flatnonzero(live):
        assert np.linalg.norm(origins[i] + envelope[:, i, None] * directions[i] - centre[group[i]], axis=1).max() \
            <= bound[group[i]] + 1e-9
    # Parallel lines 5 mm from an axis, 10° of arc: a capsule about as thin as the arc's chord.
    phi = np.radians(np.arange(0.0, 10.5, 1.0))
    arc = np.stack([5 * np.cos(phi), 5 * np.sin(phi), np.zeros(phi.size)], axis=1)
    a, b, radius = group_capsules(np.zeros(phi.size, dtype=np.intp), 1, np.stack([np.zeros(phi.size),
                                  np.full(phi.size, 12.0)]), arc, np.tile([0.0, 0.0, 1.0], (phi.size, 1)))
    assert radius[0] <= 5 * np.radians(10.0) / 2 + 1e-9
    np.testing.assert_allclose(np.linalg.norm(b[0] - a[0]), 12.0)


def test_rapids_only_remove_nothing():
    """A program whose only move is a rapid through the stock: no pieces, the intervals come back unchanged."""
    cl = np.array([[5.0, 0.0, 2.0], [45.0, 0.0, 2.0]])
    moves = ProgramMoves(cl, np.tile([0.0, 0.0, 1.0], (2, 1)), [False, False], [5.0, 5.0], [12.0, 12.0], [1, 2])
    origins, directions = edge_lines({"cl": cl, "axis": moves.axis, "radius": moves.radius}, [1], PHI)
    stock_iv = inside_intervals(staircase(), origins, directions, 12.0)
    got, changed = inprocess_intervals(stock_iv, moves, np.array([1]), origins, directions, PHI.size)
    assert stock_iv.rows.size and not changed.any() and np.array_equal(got.length, stock_iv.length)


def test_a_non_finite_edge_line_is_named():
    """A NaN in the edge lines is refused with the item that holds it, before any work."""
    cl = np.array([[5.0, 0.0, 2.0], [45.0, 0.0, 2.0]])
    moves = ProgramMoves(cl, np.tile([0.0, 0.0, 1.0], (2, 1)), [False, True], [5.0, 5.0], [12.0, 12.0], [1, 2])
    origins, directions = edge_lines({"cl": cl, "axis": moves.axis, "radius": moves.radius}, [1], PHI)
    stock_iv = inside_intervals(staircase(), origins, directions, 12.0)
    origins[7, 2] = np.nan
    with pytest.raises(ValueError, match=r"origins\[7, 2\] is not a finite number"):
        inprocess_intervals(stock_iv, moves, np.array([1]), origins, directions, PHI.size)
