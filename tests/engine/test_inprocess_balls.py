"""The balls' query in parts (inprocess_balls.BallParts) and the chains' rise (inprocess._chains).

BallParts.meeting is checked against every (sphere, ball) pair by brute force (numpy distances):
the same set of pairs, for balls of very different radii and for queries that skip later moves.
A chain's rise is checked against each piece's ends measured along the chain's axis, and the
sure-miss test that uses it (inprocess._apart with rise) against the closed form of every piece
of the chain (swept.line_hull_interval, itself checked against a sampler in test_inprocess).
Planted errors, tried by hand: a part queried within the largest sphere radius only (without its
balls' radius) fails the first test; rise taken as 0 for every chain fails the last two.
"""

import numpy as np
import pytest

from abm_workbench.engine.inprocess import ProgramMoves, _apart, swept_pieces
from abm_workbench.engine.inprocess_balls import BLOCK, BallParts
from abm_workbench.engine.swept import line_hull_interval, row_dot


def brute_pairs(centre, radius, before, balls, bound, move):
    """The set of (sphere, ball) pairs whose centres lie within radius + bound, of the balls of moves at most
    `before` (callers drop later moves themselves), from every pair's distance."""
    gap = np.linalg.norm(centre[:, None, :] - balls[None, :, :], axis=2)
    i, j = np.nonzero((gap <= radius[:, None] + bound[None, :]) & (move[None, :] <= before))
    return set(zip(i.tolist(), j.tolist()))


@pytest.mark.parametrize("before", [10 ** 9, 700, 0])
def test_meeting_finds_every_pair(before):
    rng = np.random.default_rng(7)
    n = 3 * BLOCK + 100  # several parts per radius class
    balls = rng.uniform(0.0, 40.0, (n, 3))
    # Mostly small balls, a few three to six times larger (long moves), as in a real program.
    bound = np.where(rng.random(n) < 0.1, rng.uniform(6.0, 12.0, n), rng.uniform(1.5, 2.5, n))
    move = np.sort(rng.integers(0, 1000, n))
    parts = BallParts(balls, bound, move)
    assert len(parts.parts) > 4
    centre = rng.uniform(0.0, 40.0, (300, 3))
    radius = rng.uniform(0.2, 3.0, 300)
    i, ball = parts.meeting(centre, radius, before)
    assert len(set(zip(i.tolist(), ball.tolist()))) == i.size  # no pair twice
    got = {(a, b) for a, b in zip(i.tolist(), ball.tolist()) if move[b] <= before}
    assert got == brute_pairs(centre, radius, before, balls, bound, move)
    # Every pair given meets: nothing is given that the exact test would drop.
    gap = np.linalg.norm(centre[i] - balls[ball], axis=1)
    assert (gap <= radius[i] + bound[ball]).all()


def test_meeting_without_balls_or_spheres():
    empty = BallParts(np.zeros((0, 3)), np.zeros(0), np.zeros(0, dtype=int))
    i, ball = empty.meeting(np.zeros((2, 3)), np.ones(2), 5)
    assert i.size == 0 and ball.size == 0
    parts = BallParts(np.zeros((3, 3)), np.ones(3), np.arange(3))
    i, ball = parts.meeting(np.zeros((0, 3)), np.zeros(0), 5)
    assert i.size == 0 and ball.size == 0


def test_balls_must_come_in_program_order():
    with pytest.raises(ValueError, match="program order"):
        BallParts(np.zeros((3, 3)), np.ones(3), np.array([0, 2, 1]))
    with pytest.raises(ValueError, match="one row per ball"):
        BallParts(np.zeros((3, 3)), np.ones(2), np.arange(3))


def ramp_program():
    """Three runs along a circle of radius 10 mm: a wavy ramp down (its height going up and down from move to
    move) with the tool axis tilting along it; the same waves with the axis fixed; a level of moves in a plane.
    Returns the moves and the first row of each run."""
    t = np.linspace(0.0, 3.0 * np.pi, 61)
    circle = np.stack([10.0 * np.cos(t), 10.0 * np.sin(t)], axis=1)
    wave = 0.4 * (np.arange(t.size) % 2)
    tilt = 0.3 * np.sin(t)
    up = np.tile([0.0, 0.0, 1.0], (t.size, 1))
    runs = [(np.column_stack([circle, -0.1 * t - wave]), np.stack([np.sin(tilt), np.zeros_like(t), np.cos(tilt)], 1)),
            (np.column_stack([circle, -1.5 - wave]), up), (np.column_stack([circle, np.full_like(t, -2.0)]), up)]
    cl, axis = np.vstack([r[0] for r in runs]), np.vstack([r[1] for r in runs])
    n = cl.shape[0]
    first = np.arange(3) * t.size
    cutting = np.ones(n, dtype=bool)
    cutting[first] = False
    return ProgramMoves(cl, axis, cutting, np.full(n, 3.0), np.full(n, 12.0), np.arange(n)), first


def test_rise_bounds_the_pieces_along_the_chain_axis():
    moves, first = ramp_program()
    pieces = swept_pieces(moves, 0.05)
    chain = np.searchsorted(pieces.chain_first, np.searchsorted(pieces.span_first, np.arange(pieces.move.size),
                                                                side="right") - 1, side="right") - 1
    w = pieces.chain_axis[chain]
    start, d = pieces.chain_c0[chain], pieces.chain_c1[chain] - pieces.chain_c0[chain]
    da = row_dot(d, w)
    for end in (pieces.c0, pieces.c1):
        a = row_dot(end - start, w)
        beyond = np.maximum(np.minimum(da, 0.0) - a, a - np.maximum(da, 0.0))
        assert (beyond <= pieces.chain_rise[chain] + 1e-12).all()
    assert (pieces.chain_rise <= pieces.chain_slack).all()
    # The wavy runs' chains of more than one span rise (by up to the waves' 0.4 mm), the level's (one plane across
    # a constant axis) do not.
    level = pieces.chain_move > first[2]
    several = ~level & (pieces.chain_count > 1)
    assert (pieces.chain_rise[several] > 0.0).mean() > 0.6 and pieces.chain_rise[several].max() > 0.35
    assert (pieces.chain_rise[level] == 0.0).all()


def test_apart_with_rise_drops_only_pairs_no_piece_reaches():
    """Segments near the chains: every (segment, chain) pair the sure-miss test drops with the chain's rise gets
    no point from any piece of the chain (closed form). Random segments, and short level ones just above a piece's
    end that lies below the axial range of its chain's path (the wavy run with a fixed axis: the rise alone
    reaches them)."""
    moves, first = ramp_program()
    pieces = swept_pieces(moves, 0.05)
    rng = np.random.default_rng(3)
    k = 4000
    chain = rng.integers(0, pieces.chain_first.size, k)
    middle = 0.5 * (pieces.chain_c0[chain] + pieces.chain_c1[chain])
    a = middle + rng.normal(0.0, 3.0, (k, 3)) + [0.0, 0.0, -1.0]
    b = a + rng.normal(0.0, 2.0, (k, 3))
    wavy = np.flatnonzero((pieces.move > first[1]) & (pieces.move < first[2]))
    low = wavy[pieces.c1[wavy, 2] < -1.7]
    piece_chain = np.searchsorted(pieces.chain_first, np.searchsorted(pieces.span_first, low, side="right") - 1,
                                  side="right") - 1
    start = pieces.c1[low] + [0.0, 0.0, 0.05] + rng.uniform(-1.0, 1.0, (low.size, 3)) * [1.0, 1.0, 0.0]
    a, b = np.vstack([a, start]), np.vstack([b, start + [0.5, 0.5, 0.0]])
    chain = np.r_[chain, piece_chain]
    k = chain.size
    apart = _apart(a, b, *pieces.hulls("chain", chain), pieces.chain_slack[chain], pieces.chain_lean[chain],
                   rise=pieces.chain_rise[chain])
    assert 0.05 * k < apart.sum() < 0.95 * k
    dropped = np.flatnonzero(apart)
    owner = np.repeat(dropped, pieces.chain_count[chain[dropped]])
    span = pieces.chain_first[chain[owner]] + (np.arange(owner.size) - np.repeat(
        np.cumsum(pieces.chain_count[chain[dropped]]) - pieces.chain_count[chain[dropped]],
        pieces.chain_count[chain[dropped]]))
    seg = np.repeat(owner, pieces.span_count[span])
    piece = np.repeat(pieces.span_first[span], pieces.span_count[span]) + (np.arange(seg.size) - np.repeat(
        np.cumsum(pieces.span_count[span]) - pieces.span_count[span], pieces.span_count[span]))
    length = np.linalg.norm(b[seg] - a[seg], axis=1)
    direction = (b[seg] - a[seg]) / length[:, None]
    enter, leave = line_hull_interval(a[seg], direction, *pieces.hulls("piece", piece))
    overlap = np.minimum(leave, length) - np.maximum(enter, 0.0)
    assert not (overlap > 0.0).any()


def test_meeting_skips_far_parts_and_finds_every_pair():
    """Balls laid out as a program lays them, one area after another (each part's balls in a 10 mm square of its
    own): the spheres near one area meet the balls there only, and the parts whose boxes lie beyond reach are
    skipped; the pairs are still every pair that meets (brute force)."""
    rng = np.random.default_rng(11)
    n = 6 * BLOCK
    area = np.repeat(np.arange(6), BLOCK)
    balls = rng.uniform(0.0, 10.0, (n, 3)) + np.stack([30.0 * area, np.zeros(n), np.zeros(n)], axis=1)
    bound = rng.uniform(1.5, 2.0, n)
    move = np.arange(n)
    parts = BallParts(balls, bound, move)
    centre = rng.uniform(0.0, 10.0, (200, 3)) + np.array([60.0, 0.0, 0.0])
    centre[:20, 0] = 70.0 + rng.uniform(0.0, 4.0, 20)  # some between two areas
    radius = rng.uniform(0.5, 3.0, 200)
    i, ball = parts.meeting(centre, radius, 10 ** 9)
    assert set(zip(i.tolist(), ball.tolist())) == brute_pairs(centre, radius, 10 ** 9, balls, bound, move)
    assert set(area[ball].tolist()) == {2}


@pytest.mark.parametrize("block", [BLOCK, 16])
def test_meeting_below_a_floor_finds_every_pair_at_or_above_it(block):
    """With floors (heights along z below which a ball's hull has no point; −inf for some) and the spheres'
    tops, the pairs are those of brute force whose floor is not above the sphere's top; in parts of 16 balls,
    parts whose floors all lie above every top are skipped without losing a pair (a part skipped by the
    lowest top instead of the highest fails this)."""
    rng = np.random.default_rng(11)
    n = 700
    balls = rng.uniform(0.0, 40.0, (n, 3))
    bound = rng.uniform(1.5, 6.0, n)
    move = np.arange(n)
    # Floors fall in program order, as the ramps of a z-level program do; a tenth unknown.
    floor = np.where(rng.random(n) < 0.1, -np.inf, 40.0 - 40.0 * move / n + rng.uniform(-2.0, 2.0, n))
    parts = BallParts(balls, bound, move, floor, block)
    centre = rng.uniform(0.0, 40.0, (400, 3))
    radius = rng.uniform(0.2, 3.0, 400)
    top = centre[:, 2] + radius
    top[:5] = floor[np.isfinite(floor)][:5]  # tops exactly on a floor: a touch, kept
    i, ball = parts.meeting(centre, radius, n, top)
    assert len(set(zip(i.tolist(), ball.tolist()))) == i.size
    want = {(a, b) for a, b in brute_pairs(centre, radius, n, balls, bound, move) if floor[b] <= top[a]}
    assert set(zip(i.tolist(), ball.tolist())) == want
    assert len(want) < len(brute_pairs(centre, radius, n, balls, bound, move))  # the floors do drop pairs


def test_the_other_moves_floors_are_their_pieces_lowest_bottoms():
    """A program with levels: its other moves (ramps between the levels, one leaning move) get, per chain, the
    least height of their pieces' bottom centres along the levels' axis, −inf where a piece's axis is not it."""
    from abm_workbench.engine.inprocess import _floors

    cl, axis = [], []
    for k, z in enumerate((6.0, 4.0)):
        cl += [[0.0, 0.0, z + 2.0]] + [[x, 0.0, z + 2.0 - 2.0 * x / 30.0] for x in np.linspace(1.0, 30.0, 6)]
        axis += [[0.0, 0.0, 1.0]] * 7
        cl += [[30.0 - x, 5.0 + k, z] for x in np.linspace(0.0, 30.0, 20)]
        axis += [[0.0, 0.0, 1.0]] * 20
    cl += [[0.0, 20.0, 3.0], [5.0, 20.0, 2.5]]
    axis += [[0.0, 0.0, 1.0], [0.0, np.sin(0.2), np.cos(0.2)]]
    n = len(cl)
    moves = ProgramMoves(np.array(cl), np.array(axis), np.r_[False, np.ones(n - 1, dtype=bool)], np.full(n, 3.0),
                         np.full(n, 10.0), np.arange(n))
    rest = swept_pieces(moves).rest
    assert rest is not None and rest.chain_first.size >= 3
    piece_start = rest.span_first[rest.chain_first]
    piece_end = np.r_[piece_start[1:], rest.c0.shape[0]]
    floor = _floors(rest.c0, rest.c1, rest.axis, piece_start, np.array([0.0, 0.0, 1.0]))
    for c in range(piece_start.size):
        mine = slice(piece_start[c], piece_end[c])
        if (rest.axis[mine] == [0.0, 0.0, 1.0]).all():
            assert floor[c] == min(rest.c0[mine, 2].min(), rest.c1[mine, 2].min())
        else:
            assert floor[c] == -np.inf
    assert np.isinf(floor).any() and np.isfinite(floor).any()
    # The balls carry their chain's floor.
    np.testing.assert_array_equal(rest.tree.floor, floor[rest.ball_chain])
