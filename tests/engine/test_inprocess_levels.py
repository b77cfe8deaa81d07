"""The level view of the in-process search (inprocess_levels) against the independent sampled reference.

Programs shaped like z-level roughing (zig-zag and offset passes at 40 % and exactly 50 % stepover, arcs as
short chords, a ramp between levels, a second tool, a level of another tool's flute length) are checked with
test_inprocess.check: every edge line's material against the sampled stock minus the sampled swept volumes.
Each test also asserts that the level view took the program's level moves, so that a change routing them back
to the general search shows. A tilted axis (3+2, not a coordinate axis) takes the view's closed-form path, as
does a program turned from a file's frame, whose heights along the axis differ in their last bits.
Planted errors, tried by hand: a cell held whole without the half diagonal (`gap <= -slack - MARGIN`), a
chain's slack left out of its chord test (`gap < -MARGIN`), and levels asked from the highest down (`level`
from the top) each fail the reference tests here.
"""

import numpy as np

from abm_workbench.engine.inprocess import swept_pieces, subtract, removal_intervals
from abm_workbench.engine.inprocess_levels import CELLS_PER_PIECE, MIN_CELLS, MIN_MOVES, LevelView, level_moves
from abm_workbench.engine.engagement import inside_intervals

from .test_inprocess import PHI, Program, check, edge_lines, staircase, straight


def zigzag(program, z, y0, y1, step, radius, flute, x0=8.0, x1=52.0):
    """Passes along x at height z from y0 by `step` to y1, joined by half circles as 12 chords each."""
    rows = []
    ys = np.arange(y0, y1 + 1e-9, step)
    for i, y in enumerate(ys):
        a, b = (x0, x1) if i % 2 == 0 else (x1, x0)
        points = [straight(a, b, y, z, 9)]
        if i + 1 < ys.size:
            t = np.linspace(-0.5 * np.pi, 0.5 * np.pi, 13)[1:] * (1 if i % 2 == 0 else -1)
            cx = b
            side = 1.0 if i % 2 == 0 else -1.0
            arc = np.stack([cx + side * 0.5 * step * np.cos(t), y + 0.5 * step + 0.5 * step * np.sin(t),
                            np.full(t.size, z)], axis=1)
            points.append(arc)
        rows.append(np.concatenate(points))
    return program.add_pass(np.concatenate(rows), radius, flute)


def ramp(program, start, z0, z1, radius, flute, n=12):
    """A straight ramp along x from (start, z0) down to z1: moves not across the axis (the general search)."""
    x, y = start
    points = np.stack([np.linspace(x, x + 10.0, n), np.full(n, y), np.linspace(z0, z1, n)], axis=1)
    return program.add_pass(points, radius, flute)


def levels_program(shift=0.37):
    """Three levels of a D 8 mm tool at 50 % stepover (sides of a pass exactly on the next pass's axis), a ramp
    before each, then a level of a D 6 mm tool at 40 % and one of the D 8 tool with a shorter flute length.
    Each level's passes lie `shift` (mm) across from the level above's: with 0, a line on a pass's side lies
    exactly on the wall the level above left (a tie the sampled reference decides by its own rounding)."""
    program = Program()
    rows = {}
    for k, z in enumerate((7.0, 5.5, 4.0)):
        ramp(program, (10.0, -14.0), z + 2.0, z, 4.0, 12.0)
        rows[z] = zigzag(program, z, -14.0 + k * shift, 14.0, 4.0, 4.0, 12.0)
    rows["second tool"] = zigzag(program, 3.0, -12.0, 12.0, 2.4, 3.0, 12.0, 12.0, 48.0)
    rows["short flute"] = zigzag(program, 2.0, -8.0, 8.0, 4.0, 4.0, 3.0, 14.0, 46.0)
    return program, rows


def test_level_moves_and_chains():
    program, _ = levels_program()
    moves = program.moves()
    w, level = level_moves(moves)
    assert w.tolist() == [0.0, 0.0, 1.0]
    d = program.as_dict()
    across = np.r_[False, (d["cl"][1:, 2] == d["cl"][:-1, 2]) & d["cutting"][1:]]
    np.testing.assert_array_equal(level >= 0, across)  # every move of a level, no ramp, no rapid
    assert np.unique(level[across]).size == 5
    pieces = swept_pieces(moves)
    view = pieces.levels
    assert view.aligned and view.z.size == 5 and view.exact.all()
    assert pieces.rest.move.size == 3 * 11  # the ramps' moves alone
    # Every chain's pieces lie within its slack of its chord (measured here from the pieces' ends).
    for chain in range(view.chain_start.size):
        piece = view.chain_piece[view.chain_start[chain]:view.chain_start[chain] + view.chain_count[chain]]
        a, b = view.chain_a[chain], view.chain_b[chain]
        for end in np.concatenate([view.a[piece], view.b[piece]]):
            t = np.clip((end - a) @ (b - a) / max((b - a) @ (b - a), 1e-300), 0.0, 1.0)
            assert np.linalg.norm(end - a - t * (b - a)) <= view.chain_slack[chain] + 1e-12
    assert view.chain_count.max() > 1


def test_levels_against_the_reference():
    program, rows = levels_program()
    phi = np.arange(0.0, 181.0, 20.0)
    for key in (5.5, 4.0):
        got, changed, _ = check(program, rows[key][3:80:25], phi)
        assert changed.mean() > 0.5
    check(program, rows["second tool"][5:90:30], phi)
    check(program, rows["short flute"][2:40:13], phi)


def test_levels_in_the_feed_frame_at_the_pass_sides():
    """φ 0 and 180° lie on the sides of the pass, exactly at the tool radius from its own earlier moves and
    on the axis of the pass beside it (50 % stepover)."""
    program, rows = levels_program()
    check(program, rows[4.0][20:60:7], np.array([0.0, 1.0, 45.0, 90.0, 135.0, 179.0, 180.0]))


def test_levels_give_the_general_search_numbers():
    """The same removals' union as the general search (levels=False), to rounding, on every line of a level,
    ties included: levels on one another's paths, lines on the pass sides (φ 0 and 180°), where the closed
    form's own slack decides and the level view must leave it to it."""
    program, rows = levels_program(shift=0.0)
    moves = program.moves()
    d = program.as_dict()
    sample = np.concatenate([rows[4.0][1::3], rows["second tool"][1::5]])
    phi = np.r_[PHI, 1.0, 179.0]
    origins, directions = edge_lines(d, sample, phi)
    p = phi.size
    stock = inside_intervals(staircase(), origins, directions, 12.0)
    first = np.flatnonzero(np.r_[True, stock.rows[1:] != stock.rows[:-1]])
    last = np.r_[first[1:], stock.rows.size] - 1
    args = (sample, stock.rows[first], stock.start[first], stock.end[last], origins, directions, p)
    result = [subtract(stock, *removal_intervals(swept_pieces(moves, levels=levels), *args))
              for levels in (True, False)]
    np.testing.assert_allclose(result[0].length, result[1].length, rtol=0, atol=1e-9)
    assert (result[0].length < stock.length).mean() > 0.5


def tilted_program():
    """Levels across the axis w = (1, 0, 1)/√2 (not a coordinate axis): passes along y, each level's moves
    with the same dot product along w bit for bit."""
    w = np.array([1.0, 0.0, 1.0]) / np.sqrt(2.0)
    program = Program()
    rows = []
    for depth in (1.5, 3.0):
        for k, offset in enumerate((-3.0, 0.0, 3.0)):
            base = np.array([30.0, 0.0, 6.0]) - depth * w + offset * np.array([1.0, 0.0, -1.0]) / np.sqrt(2.0)
            y = np.linspace(-12.0, 12.0, MIN_MOVES + 2) * (1 if k % 2 == 0 else -1)
            points = base + y[:, None] * np.array([0.0, 1.0, 0.0])
            rows.append(program.add_pass(points, 3.0, 10.0, np.tile(w, (y.size, 1))))
    return program, rows


def test_tilted_levels_against_the_reference():
    program, rows = tilted_program()
    pieces = swept_pieces(program.moves())
    assert pieces.levels is not None and not pieces.levels.aligned
    assert np.isin(np.flatnonzero(program.as_dict()["cutting"]), pieces.levels.move).mean() > 0.5
    # φ 90° (the feed) left out: that line lies on the wall its own pass leaves, a tie the reference's sampling
    # splits into slivers.
    for later in rows[3:]:
        got, changed, _ = check(program, later[2:17:4], np.arange(5.0, 180.0, 10.0))
        assert changed.any()


def turned_program():
    """Two levels of zig-zag passes (D 6 mm, 40 % stepover) written in a file frame, then turned by 25° about y
    and 10° about z and moved, as a 3+2 program's points are: the heights along the turned axis of one level's
    points then differ in their last bits."""
    a, b = np.radians(25.0), np.radians(10.0)
    turn_y = np.array([[np.cos(a), 0.0, np.sin(a)], [0.0, 1.0, 0.0], [-np.sin(a), 0.0, np.cos(a)]])
    turn_z = np.array([[np.cos(b), -np.sin(b), 0.0], [np.sin(b), np.cos(b), 0.0], [0.0, 0.0, 1.0]])
    rotation = turn_z @ turn_y
    shift = np.array([28.0, -2.0, 4.0])
    program = Program()
    rows = []
    for depth in (-0.8, -2.0):
        local = []
        for i, y in enumerate(np.arange(-8.0, 8.01, 2.4)):
            x = np.linspace(-9.0, 9.0, 10) * (1 if i % 2 == 0 else -1)
            local.append(np.column_stack([x, np.full(x.size, y), np.full(x.size, depth)]))
        points = np.concatenate(local) @ rotation.T + shift
        rows.append(program.add_pass(points, 3.0, 10.0, np.tile(rotation[:, 2], (points.shape[0], 1))))
    return program, rows


def test_turned_levels_against_the_reference():
    program, rows = turned_program()
    d = program.as_dict()
    w = d["axis"][rows[1][0]]
    heights = d["cl"][rows[1]] @ w
    assert np.unique(heights).size > 1  # not one height bit for bit
    pieces = swept_pieces(program.moves())
    view = pieces.levels
    assert view is not None and not view.aligned and view.z.size == 2
    assert np.isin(np.flatnonzero(d["cutting"]), view.move).mean() > 0.9
    # CL points inside the rows (at a row's ends the feed turns across the rows, and lines there lie on the wall
    # of the row before: ties the sampled reference splits into slivers).
    got, changed, _ = check(program, rows[1][[3, 14, 25, 36, 46, 55, 64]], np.arange(5.0, 180.0, 10.0))
    assert changed.mean() > 0.5


def test_grid_stays_bounded_on_a_long_level():
    """A level 2 m long cut by a D 1 mm tool: its grid is coarsened to the cells allowed per piece (cells of r/2
    would be 8 million), and still answers as the general search does."""
    program = Program()
    program.add_pass(straight(-1000.0, 1000.0, 0.0, 5.0, 41), 0.5, 10.0)
    rows = program.add_pass(straight(1000.0, -1000.0, 0.6, 5.0, 41), 0.5, 10.0)[19:21]  # x 50 and 0: in the stock
    pieces = swept_pieces(program.moves())
    view = pieces.levels
    assert isinstance(view, LevelView)
    bound = max(MIN_CELLS, CELLS_PER_PIECE * view.chain_piece.size)
    assert int(view.offset[-1]) <= bound < 8e6
    d = program.as_dict()
    origins, directions = edge_lines(d, rows, PHI)
    stock = inside_intervals(staircase(), origins, directions, 10.0)
    first = np.flatnonzero(np.r_[True, stock.rows[1:] != stock.rows[:-1]])
    last = np.r_[first[1:], stock.rows.size] - 1
    args = (rows, stock.rows[first], stock.start[first], stock.end[last], origins, directions, PHI.size)
    got = [subtract(stock, *removal_intervals(p, *args)) for p in (pieces, swept_pieces(program.moves(), levels=False))]
    np.testing.assert_allclose(got[0].length, got[1].length, rtol=0, atol=1e-9)
    assert (got[0].length < stock.length).any()


def test_levels_begun_before_a_cl_point():
    """Levels cut out of height order (5, 3, 4, 2, 6 mm): for any level index and program row, the first level at
    or after it begun by that row, against a loop over the levels."""
    program = Program()
    for z in (5.0, 3.0, 4.0, 2.0, 6.0):
        program.add_pass(straight(10.0, 50.0, 0.0, z, MIN_MOVES + 1), 3.0, 10.0)
    view = swept_pieces(program.moves()).levels
    assert view.z.tolist() == [2.0, 3.0, 4.0, 5.0, 6.0]
    k, before = np.meshgrid(np.arange(6), np.arange(-1, len(program.rows["cl"]) + 1))
    k, before = k.ravel(), before.ravel()
    want = [next((j for j in range(a, 5) if view.first[j] <= b), 5) for a, b in zip(k, before)]
    np.testing.assert_array_equal(view._begun(k, before), want)

