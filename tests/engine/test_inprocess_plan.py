"""The plan view's closed forms (engine/inprocess_plan.py) against the independent brute-force reference of
test_inprocess_corner (a sampled, bisected inside flag from the tool's profile, nothing from the engine's
geometry).

The cases are those of three-axis and 3+2 programs: earlier moves across the axis (upright, or a horizontal
spindle: a move's dot product with the axis exactly zero, as in a program's one z level), the current tool
with the same axis: its arcs at the level of the same tool, or at any level against a tool of one radius over
the arc's heights; its sides and end edges at any level; and the special placements real programs make: the
tool at the end of the earlier move, on its line ahead of it, beside it at a stepover of exactly its radius or
of R − r (an edge running along the sweep's boundary), moves of no length. Last, a z-level program against the
reference of the whole program.
"""

import numpy as np
import pytest

from abm_workbench.engine import Tool, Toolpath
from abm_workbench.engine import inprocess_plan as plan
from abm_workbench.engine.inprocess_plan import arc_level_intervals, line_level_interval

from . import test_inprocess_corner_program as programs
from .test_inprocess_corner import arc_point, batch_runs, in_swept

EXACT = 1e-9  # mm of edge, away from tangent touches
AXES = (np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]))


def _across(axis, rng):
    """A random unit direction exactly across `axis` (one of AXES): no component along it."""
    v = rng.normal(size=3)
    v[axis != 0.0] = 0.0
    return v / np.linalg.norm(v)


def _placements(rng, axis, big, corner):
    """(tip, c0, move) of the current tool and an earlier move across the axis, all at one level (the tip's and
    c0's difference across the axis)."""
    u = _across(axis, rng)
    length = rng.choice([0.0, rng.uniform(0.2, 6.0)])
    c0 = np.array([10.0, 20.0, -1.5])
    move = length * u if length else np.zeros(3)
    n = np.cross(axis, u)
    kind = rng.integers(6)
    if kind == 0:      # at the end of the move
        tip = c0 + move
    elif kind == 1:    # on its line, ahead of it or behind
        tip = c0 + move + rng.uniform(-2.0, 2.0) * big * u
    elif kind == 2:    # beside it at a stepover of R or R − r
        tip = c0 + rng.uniform(-0.5, 1.5) * move + rng.choice([big, big - corner, 2.0 * big]) * n
    else:
        tip = c0 + rng.uniform(-0.3, 1.3) * move + rng.normal() * big * (u + n)
    return tip, c0, move


def _case(rng, trial, ratios, short):
    """(axis, R, r, H, tip, c0, move, d): a tool (r/R one of ratios; its flutes short·r or longer than r), an
    earlier move and the current tool's tip (_placements), an edge's direction across the axis."""
    axis = AXES[trial % 2]
    big = rng.uniform(1.0, 6.0)
    corner = big * rng.choice(ratios)
    height = rng.choice([short * corner, corner + rng.uniform(0.5, 10.0)])
    tip, c0, move = _placements(rng, axis, big, corner)
    return axis, big, corner, height, tip, c0, move, _across(axis, rng)


def _check_arcs(tip, d, axis, big, corner, top, c0, move, earlier, decided, start, end):
    """The decided arcs' intervals (start, end) against the reference (each arc's tool tip, d, axis, R, r and top;
    the earlier moves c0 … c0 + move of the tools earlier = (R_e, r_e, H_e)), to EXACT mm of arc; at least 20 arcs
    with something inside."""
    centre = tip + (big - corner)[:, None] * d + corner[:, None] * axis
    extra = [[] if not b > a else [v + x for v in (a, b) for x in (-1e-9, 0.0, 1e-9)] for a, b in zip(start, end)]
    p_big, p_corner, p_height = earlier

    def flag(edge, t):
        return in_swept(arc_point(centre[edge], d[edge], axis[edge], corner[edge], t), c0[edge], move[edge],
                        axis[edge], p_big[edge], p_corner[edge], p_height[edge])

    want = batch_runs(flag, top, extra)
    hits = 0
    for k in np.flatnonzero(decided):
        got = [(start[k], end[k])] if end[k] > start[k] else []
        # A touch at one point (the reference's sliver thinner than what rounding decides) is no interval.
        found = [(a, b) for a, b in want[k] if (b - a) * corner[k] > 1e-6]
        hits += bool(found)
        assert len(got) == len(found), (k, got, want[k])
        for (a, b), (x, y) in zip(got, found):
            assert abs(a - x) * corner[k] <= EXACT and abs(b - y) * corner[k] <= EXACT, (k, got, want[k])
    assert hits >= 20


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_arcs_at_the_level_of_an_earlier_move(seed):
    """Corner arcs of bull-nose and ball-end mills (r/R 0.1 … 1) at the level of an earlier move of the same tool,
    at all the placements of _placements and every angle: arc_level_intervals against the reference, to EXACT mm
    of arc (a touch at a single point may be a sliver up to √(rounding) long in the reference)."""
    rng = np.random.default_rng(seed)
    cases = []
    for trial in range(80):
        axis, big, corner, height, tip, c0, move, d = _case(rng, trial, (0.1, 0.25, 0.5, 1.0), 1.0)
        cases.append((tip, d, axis, big, corner, c0, move, height))
    tip, d, axis, big, corner, c0, move, height = (np.array(column) for column in zip(*cases))
    top = np.full(len(cases), 0.5 * np.pi)
    decided, start, end = arc_level_intervals(tip, d, axis, big, corner, top, c0, c0 + move, axis, big, height,
                                              corner)
    assert decided.all()
    _check_arcs(tip, d, axis, big, corner, top, c0, move, (big, corner, height), decided, start, end)


@pytest.mark.parametrize("seed", [11, 12, 13])
def test_arcs_against_earlier_tools_of_one_radius(seed):
    """Corner arcs of bull-nose and ball-end mills against earlier moves of another tool whose radius is the same at
    every height of the arc: flat-end mills at any level from r below the arc's tip up (their bottom or top cutting
    the arc), and bull-nose mills whose corner lies below the arc: arc_level_intervals against the reference."""
    rng = np.random.default_rng(seed)
    cases = []
    for trial in range(80):
        axis, big, corner, _, tip, c0, move, d = _case(rng, trial, (0.1, 0.25, 0.5, 1.0), 1.0)
        p_big = rng.uniform(0.5, 8.0)
        if trial % 3:
            p_corner, level = 0.0, rng.choice([0.0, rng.uniform(-0.95, 1.5) * corner])
        else:
            p_corner = rng.uniform(0.1, 1.0) * p_big
            level = p_corner + rng.choice([0.0, rng.uniform(0.0, 2.0)])
        p_height = rng.choice([rng.uniform(0.2, 1.5) * corner, 20.0])
        cases.append((tip + level * axis, d, axis, big, corner, c0, move, p_big, p_corner, p_height))
    tip, d, axis, big, corner, c0, move, p_big, p_corner, p_height = (np.array(column) for column in zip(*cases))
    top = np.full(len(cases), 0.5 * np.pi)
    decided, start, end = arc_level_intervals(tip, d, axis, big, corner, top, c0, c0 + move, axis, p_big, p_height,
                                              p_corner)
    # (A bull-nose's corner exactly at the arc's tip may come out a rounding below it, and is not decided here.)
    assert decided.sum() >= 70
    _check_arcs(tip, d, axis, big, corner, top, c0, move, (p_big, p_corner, p_height), decided, start, end)


def test_arc_below_an_earlier_move_meets_nothing():
    """An arc whose tool tip lies r or more below an earlier move across the axis is decided as outside; the
    reference finds no inside point on it."""
    axis = np.array([0.0, 0.0, 1.0])
    n = 24
    phi = np.radians(np.arange(n) * 15.0)
    d = np.stack([np.cos(phi), np.sin(phi), np.zeros(n)], axis=1)
    big, corner, height = np.full(n, 3.0), np.full(n, 1.0), np.full(n, 10.0)
    tip = np.tile([0.5, 0.2, -2.0], (n, 1))
    c0, c1 = np.tile([-4.0, 0.0, -1.0], (n, 1)), np.tile([4.0, 0.0, -1.0], (n, 1))
    decided, start, end = arc_level_intervals(tip, d, np.tile(axis, (n, 1)), big, corner, np.full(n, 0.5 * np.pi),
                                              c0, c1, np.tile(axis, (n, 1)), big, height, corner)
    assert decided.all() and not (end > start).any()
    centre = tip + 2.0 * d + axis
    want = batch_runs(lambda e, t: in_swept(arc_point(centre[e], d[e], axis, 1.0, t), c0[e], c1[e] - c0[e], axis,
                                            3.0, 1.0, 10.0), np.full(n, 0.5 * np.pi))
    assert all(sum(b - a for a, b in runs) < 1e-6 for runs in want)


@pytest.mark.parametrize("seed", [5, 6, 7])
def test_sides_and_end_edges_against_earlier_moves(seed):
    """Lines along the axis (a tool's straight sides) and across it (its end edges) at any level against earlier
    moves across the axis of any tool with a corner (r/R 0.1 … 1, short and long flutes): line_level_interval
    against the reference, to EXACT mm."""
    rng = np.random.default_rng(seed)
    cases = []
    for trial in range(90):
        axis, big, corner, height, tip, c0, move, d = _case(rng, trial, (0.1, 0.3, 0.5, 1.0), 0.6)
        if trial % 3 == 0:
            origin, direction = tip + rng.uniform(0.2, 1.5) * big * d + rng.uniform(-1.0, 3.0) * axis, axis
        else:
            origin, direction = tip + rng.choice([0.0, rng.uniform(-1.0, 2.5)]) * axis, d
        cases.append((origin, direction, c0, move, axis, big, height, corner))
    origin, direction, c0, move, axis, big, height, corner = (np.array(column) for column in zip(*cases))
    decided, enter, leave = line_level_interval(origin, direction, c0, c0 + move, axis, big, height, corner)
    assert decided.sum() >= 60
    reach = 40.0
    extra = [[] if np.isnan(e) else [v + reach + x for v in (e, l) for x in (-1e-7, 0.0, 1e-7)]
             for e, l in zip(enter, leave)]

    # A line in the earlier tool's bottom plane touches its corner tangentially there; the sampled reference's
    # slack would move its ends by √(2r·slack). There the solid's section is known exactly: the points within
    # R − r of the segment, seen across the axis (the tool's profile at a = 0).
    bottom = np.sum((origin - c0) * axis, axis=1) == 0.0

    def flag(edge, t):
        points = origin[edge] + (t - reach)[:, None] * direction[edge]
        q = points - c0[edge]
        q -= np.sum(q * axis[edge], axis=1)[:, None] * axis[edge]
        t_move = np.clip(np.sum(q * move[edge], axis=1) / np.maximum(np.sum(move[edge] ** 2, axis=1), 1e-300), 0, 1)
        plan = np.linalg.norm(q - t_move[:, None] * move[edge], axis=1) <= big[edge] - corner[edge]
        return np.where(bottom[edge] & ~np.all(direction[edge] == axis[edge], axis=1), plan,
                        in_swept(points, c0[edge], move[edge], axis[edge], big[edge], corner[edge], height[edge]))

    want = batch_runs(flag, np.full(len(cases), 2.0 * reach), extra, samples=1601)
    hits = 0
    for k in np.flatnonzero(decided):
        found = [(a, b) for a, b in want[k] if b - a > 1e-6]
        if not found:
            assert np.isnan(enter[k]) or leave[k] - enter[k] < 1e-6, (k, enter[k], leave[k], want[k])
            continue
        hits += 1
        assert len(found) == 1
        np.testing.assert_allclose([enter[k] + reach, leave[k] + reach], found[0], rtol=0, atol=EXACT,
                                   err_msg=str(k))
    assert hits >= 25


def test_moves_not_across_the_axis_are_left_to_the_general_solvers():
    """A move with a part along the axis (a ramp), another axis, or an arc at another level of a different tool (a
    level above of another corner radius, the same level of another radius) is not decided here; the same tool's
    level above is (by the monotone bisection, inprocess_plan._arc_above)."""
    axis = np.tile([0.0, 0.0, 1.0], (4, 1))
    tilted = np.tile([0.0, 0.6, 0.8], (4, 1))
    tip = np.zeros((4, 3))
    d = np.tile([1.0, 0.0, 0.0], (4, 1))
    c0 = np.array([[-1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [-1.0, 0.0, 0.3], [-1.0, 0.0, 0.0]])
    c1 = np.array([[1.0, 0.0, 0.01], [1.0, 0.0, 0.0], [1.0, 0.0, 0.3], [1.0, 0.0, 0.0]])
    other = np.array([axis[0], tilted[0], axis[0], axis[0]])
    big, corner = np.full(4, 3.0), np.full(4, 1.0)
    p_big = np.array([3.0, 3.0, 3.0, 2.5])
    p_corner = np.array([1.0, 1.0, 0.8, 1.0])
    decided, _, _ = arc_level_intervals(tip, d, axis, big, corner, np.full(4, 0.5 * np.pi), c0, c1, other, p_big,
                                        np.full(4, 10.0), p_corner)
    assert not decided.any()
    decided, _, _ = arc_level_intervals(tip, d, axis, big, corner, np.full(4, 0.5 * np.pi), c0, c1, other, p_big,
                                        np.full(4, 10.0), corner)
    assert decided.tolist() == [False, False, True, False]
    decided, _, _ = line_level_interval(tip, np.tile([0.3, 0.4, 0.866], (4, 1)), c0, c1, axis, big, np.full(4, 10.0),
                                        corner)
    assert not decided.any()


def z_level_program(ratio):
    """Three passes of one D8 tool (corner radius ratio·R) at one z level, 4 mm apart (50 % stepover), back and
    forth, then a pass 1 mm lower between the first two: z-level roughing, whose pairs the plan view decides."""
    program = programs.Program()
    tool = Tool(8.0, 2, 12.0, corner_radius=4.0 * ratio)
    args = (tool.radius, tool.flute_length, tool.corner_radius)
    program.add(programs.straight(-16, 16, -4.0, 3.0, 9), *args)
    rows = [program.add(programs.straight(16, -16, 0.0, 3.0, 9), *args),
            program.add(programs.straight(-16, 16, 4.0, 3.0, 9), *args),
            program.add(programs.straight(16, -16, -2.0, 2.0, 9), *args)]
    return program, tool, np.concatenate([r[[2, 5, 8]] for r in rows])


@pytest.mark.parametrize("ratio", [0.25, 1.0])
def test_z_level_program_against_the_reference(ratio, monkeypatch):
    """A z-level program of a bull-nose and of a ball-end mill: engage_in_process (its pairs mostly in plan view)
    against the brute-force reference of the whole program (length, LEP, UEP, end length to 1e-6 mm), and the share
    of pairs the plan view decided (so that a change routing them to the general solvers shows)."""
    counts = {"plan": 0, "general": 0}

    def counted(key, function, decided=None):
        def call(*args):
            result = function(*args)
            counts[key] += int(result[0].sum()) if decided else len(args[0])
            return result
        return call

    for name, key, decided in (("arc_level_intervals", "plan", True), ("arc_swept_intervals", "general", False),
                               ("line_level_interval", "plan", True), ("line_swept_interval", "general", False)):
        monkeypatch.setattr(plan, name, counted(key, getattr(plan, name), decided))
    program, tool, rows = z_level_program(ratio)
    toolpath = Toolpath(program.array("cl")[rows], np.zeros(rows.size), np.zeros(rows.size))
    got, changed, want, _, _ = programs.run(program, "staircase", tool, toolpath, rows, programs.PHI)
    assert changed.sum() >= 6
    assert not programs.mismatches(got, want)
    share = counts["plan"] / (counts["plan"] + counts["general"])
    assert share >= (0.95 if ratio < 1.0 else 0.8), counts
