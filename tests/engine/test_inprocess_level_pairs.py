"""The level view for tools with a corner (inprocess_level_pairs) against the independent references.

Z-level programs of a bull-nose and a ball-end mill (zig-zag passes joined by half circles as chords, at 45 %
stepover, levels closer than the ball's radius so that its arcs reach into the level above, a ramp between levels)
are checked against the brute-force reference of the whole program (test_inprocess_corner_program: a sampled,
bisected inside flag from the tools' profiles), and against the general search (levels=False) on many more CL
points. Each asserts that the level view took the level moves' pairs, so that a change routing them back to the
general search shows. Then the parts one by one: the arcs' bound (a piece that removes something of an arc's part
holds the part's last point within the earlier tool's radius there) on random placements against the sampled
swept solid, the branch and bound of the sides' nearest pieces against all pieces, and the plan distance of two
segments against a fine sampling with its Lipschitz bound.
Planted errors, tried by hand: the quarters' slack left out of the rounds' test, and the arcs' bound taken at the
part's first point instead of its last, each fail the general-search tests here (the second the reference tests
too).
"""

import numpy as np
import pytest

from abm_workbench.engine import Tool, Toolpath
from abm_workbench.engine import inprocess_level_pairs as pairs
from abm_workbench.engine.inprocess import swept_pieces
from abm_workbench.engine.inprocess_level_pairs import nearest_pieces, segment_distance
from abm_workbench.engine.stocks import in_process_runs

from . import test_inprocess_corner_program as programs
from .test_inprocess_corner import in_swept

PHI = np.arange(0.0, 360.0, 30.0)


def zigzag(z, y0, y1, step, x0=-16.0, x1=16.0):
    """Points of passes along x at height z from y0 by `step` to y1, joined by half circles as 12 chords each (all
    moved by programs.ODD, off the stock's round numbers)."""
    points = []
    ys = np.arange(y0, y1 + 1e-9, step)
    for i, y in enumerate(ys):
        a, b = (x0, x1) if i % 2 == 0 else (x1, x0)
        points.append(programs.straight(a, b, y, z, 9))
        if i + 1 < ys.size:
            side = 1.0 if i % 2 == 0 else -1.0
            t = np.linspace(-0.5 * np.pi, 0.5 * np.pi, 13)[1:] * side
            points.append(np.stack([b + side * 0.5 * step * np.cos(t), y + 0.5 * step + 0.5 * step * np.sin(t),
                                    np.full(t.size, z)], axis=1) + programs.ODD)
    return np.concatenate(points)


def level_program(ratio):
    """A D4 tool of corner radius ratio·R over the staircase (tops 6, 10 and 4 mm): a ramp, then two levels 1.2 mm
    apart (less than the ball's radius: its arcs reach into the level above), the second 0.7 mm across from the
    first; 45 % stepover. (program, tool, rows of the second level)."""
    program = programs.Program()
    tool = Tool(4.0, 2, 12.0, corner_radius=2.0 * ratio)
    args = (tool.radius, tool.flute_length, tool.corner_radius)
    program.add(np.stack([np.linspace(-16.0, -6.0, 8), np.full(8, -9.0), np.linspace(7.0, 5.0, 8)], axis=1), *args)
    program.add(zigzag(5.0, -9.0, 9.0, 1.8), *args)
    rows = program.add(zigzag(3.8, -8.3, 8.0, 1.8), *args)
    return program, tool, rows


def counted(monkeypatch):
    """Counts of the calls into the level view's three edge kinds."""
    seen = {"sides": 0, "ends": 0, "arcs": 0}
    for name in seen:
        function = getattr(pairs, name)

        def call(*args, _name=name, _function=function, **kwargs):
            seen[_name] += 1
            return _function(*args, **kwargs)
        monkeypatch.setattr(pairs, name, call)
    from abm_workbench.engine import inprocess, inprocess_arc_search, inprocess_levels
    monkeypatch.setattr(inprocess, "ends", pairs.ends)
    monkeypatch.setattr(inprocess_levels, "sides", pairs.sides)
    monkeypatch.setattr(inprocess_arc_search, "level_arcs", pairs.arcs)
    return seen


@pytest.mark.parametrize("ratio", [0.25, 1.0])
def test_corner_levels_against_the_reference(ratio, monkeypatch):
    seen = counted(monkeypatch)
    program, tool, rows = level_program(ratio)
    pieces = swept_pieces(program.moves())
    assert pieces.levels is not None and pieces.levels.z.size == 2 and pieces.levels.exact.all()
    assert pieces.rest.move.size == 7  # the ramp alone
    pick = rows[[14, 27, 40, 66, 93]]
    toolpath = Toolpath(program.array("cl")[pick], np.zeros(pick.size), np.zeros(pick.size))
    got, changed, want, _, _ = programs.run(program, "staircase", tool, toolpath, pick, PHI, pieces=pieces)
    assert changed.all()
    assert not programs.mismatches(got, want)
    assert seen["sides"] and seen["arcs"] and (seen["ends"] or ratio == 1.0)


@pytest.mark.parametrize("ratio", [0.25, 0.5, 1.0])
def test_corner_levels_give_the_general_search_numbers(ratio):
    """The peripheral edges' runs and the end edges' lengths with and without the level view, on every third CL
    point of the second level at every 10° and on the pass sides (φ 90°, 270°), to 1e-9 mm."""
    program, tool, rows = level_program(ratio)
    moves = program.moves()
    pick = rows[1::3]
    toolpath = Toolpath(program.array("cl")[pick], np.zeros(pick.size), np.zeros(pick.size))
    phi = np.r_[np.arange(0.0, 360.0, 10.0), 89.0, 91.0]
    runs = [in_process_runs(programs.STAIRCASE, tool, toolpath, phi, swept_pieces(moves, levels=levels), pick)
            for levels in (True, False)]
    np.testing.assert_allclose(runs[0].length, runs[1].length, rtol=0, atol=1e-9)
    assert (runs[0].length > 0.0).any()
    ends = [programs.engine_ends(programs.STAIRCASE, tool, toolpath, phi, swept_pieces(moves, levels=levels), pick)
            for levels in (True, False)]
    for a, b in zip(ends[0]["end"], ends[1]["end"]):
        np.testing.assert_allclose(np.sort(a), np.sort(b), rtol=0, atol=1e-9)


@pytest.mark.parametrize("ratio", [0.25, 1.0])
def test_arcs_beside_a_plunge_give_the_general_search_numbers(ratio):
    """A plunge, then a pass at its bottom's level 1.5 R beside it: the arcs facing the plunge lose what it swept (the
    lengths differ from the pass alone), found by the search among the moves off the levels after the level view
    (whose CL points it takes only where their sphere meets such a move): the general search's numbers to 1e-9 mm
    at every CL point of the pass, every 10°."""
    tool = Tool(4.0, 2, 12.0, corner_radius=2.0 * ratio)
    args = (tool.radius, tool.flute_length, tool.corner_radius)
    phi = np.arange(0.0, 360.0, 10.0)
    runs = []
    for plunge in (True, False):
        program = programs.Program()
        if plunge:
            program.add(np.array([[0.0, 0.0, 8.0], [0.0, 0.0, 3.8]]) + programs.ODD, *args)
        rows = program.add(programs.straight(-8.0, 8.0, 1.5 * tool.radius, 3.8, 41), *args)[1:]
        moves = program.moves()
        toolpath = Toolpath(program.array("cl")[rows], np.zeros(rows.size), np.zeros(rows.size))
        pieces = [swept_pieces(moves, levels=levels) for levels in (True, False)]
        if plunge:
            assert pieces[0].levels is not None and pieces[0].rest.move.size == 1
        runs.append([in_process_runs(programs.STAIRCASE, tool, toolpath, phi, one, rows) for one in pieces])
    np.testing.assert_allclose(runs[0][0].length, runs[0][1].length, rtol=0, atol=1e-9)
    assert np.abs(runs[0][0].length - runs[1][0].length).max() > 0.1


def _profile_radius(h, big, corner):
    """The plan radius of a tool (big, corner) at height h ≥ 0 above its bottom (its corner's, then big)."""
    inside = np.clip(corner - h, 0.0, corner)
    return big - corner + np.sqrt(corner * corner - inside * inside)


@pytest.mark.parametrize("ratio", [0.2, 0.5, 1.0])
def test_arc_bound_against_the_sampled_solid(ratio):
    """For the same tool at the arc's level or above it (rise ≥ 0), every arc point inside a piece's swept solid
    (sampled reference) at ψ ≤ ψ1 has the arc's point at ψ1 within the earlier tool's radius at ψ1's height of the
    piece's path in plan: the bound the arcs' rounds and candidate search use (inprocess_level_pairs.arcs)."""
    rng = np.random.default_rng(7)
    big, flute = 3.0, 10.0
    corner = ratio * big
    checked = 0
    for _ in range(120):
        rise = rng.choice([0.0, rng.uniform(0.0, corner)])
        c0 = np.array([*rng.uniform(-4.0, 4.0, 2), rise])
        move = np.array([*rng.uniform(-3.0, 3.0, 2), 0.0]) * rng.choice([0.0, 1.0, 1.0])
        angle = rng.uniform(0.0, 2.0 * np.pi)
        d = np.array([np.cos(angle), np.sin(angle), 0.0])
        psi = np.linspace(0.0, 0.5 * np.pi, 121)
        plan = (big - corner + corner * np.sin(psi))[:, None] * d
        points = plan + (corner * (1.0 - np.cos(psi)))[:, None] * np.array([0.0, 0.0, 1.0])
        inside = in_swept(points, c0, move, np.array([0.0, 0.0, 1.0]), big, corner, flute)
        if not inside.any():
            continue
        first = psi[np.argmax(inside)]
        for psi1 in psi[psi >= first]:
            at = (big - corner + corner * np.sin(psi1)) * d
            gap = _point_segment(at[None, :2], c0[:2], (c0 + move)[:2])[0]
            reach = _profile_radius(corner * (1.0 - np.cos(psi1)) - rise, big, corner)
            assert gap <= reach + 1e-7, (rise, psi1, gap, reach)
            checked += 1
    assert checked > 300


def _point_segment(p, a, b):
    """Distance (n,) of points p (n, 2) from the segment a … b (2,) (a point where a = b), written here apart."""
    d = b - a
    t = np.clip(((p - a) @ d) / (d @ d), 0.0, 1.0) if d @ d > 0.0 else np.zeros(len(p))
    return np.linalg.norm(p - a - t[:, None] * d, axis=1)


def test_nearest_pieces_against_all_pieces():
    """The sides' branch and bound keeps, for each point, the level's pieces of earlier moves nearest to it in plan
    (within the bound, 2 mm; those within 1e-9 mm of the least distance over all of them, brute force), and none
    farther than the least by more than 2·MARGIN."""
    program, tool, rows = level_program(0.25)
    view = swept_pieces(program.moves()).levels
    rng = np.random.default_rng(3)
    n = 400
    at = np.stack([rng.uniform(-18.0, 18.0, n), rng.uniform(-11.0, 11.0, n)], axis=1)
    k = rng.integers(0, view.z.size, n)
    before = rng.choice(rows, n)
    bound = np.full(n, 2.0)
    query, piece = nearest_pieces(view, np.arange(n), k, at, bound, before, np.ones(n, dtype=bool))
    level_piece = np.flatnonzero(view.piece_level >= 0)
    found = 0
    for i in range(n):
        mine = level_piece[(view.piece_level[level_piece] == k[i]) & (view.move[level_piece] <= before[i])]
        gap = np.array([_point_segment(at[i:i + 1], view.a[j], view.b[j])[0] for j in mine])
        got = set(piece[query == i].tolist())
        if not mine.size or gap.min() > bound[i] + 1e-7:
            assert not got, i
            continue
        assert set(mine[gap <= gap.min() + 1e-9].tolist()) <= got, i
        assert all(gap[mine == j][0] <= gap.min() + 2.0 * pairs.MARGIN + 1e-12 for j in got), i
        found += 1
    assert found > 50



@pytest.mark.parametrize("ratio", [0.25, 1.0])
def test_sides_held_within_the_full_radius(ratio, monkeypatch):
    """A side whose origin stands at least the level tool's corner radius above the level's bottom, in a grid cell
    that a chain holds whole within the tool's radius R, is removed from the corner's top up without the search for
    its nearest pieces: over its material (l ≥ 0) exactly what the nearest pieces remove (the same union, bit for
    bit), and for many lines (a ball's rim R − r is 0: its sides were never held within the rim)."""
    program, tool, rows = level_program(ratio)
    view = swept_pieces(program.moves()).levels
    rng = np.random.default_rng(5)
    n = 3000
    k = rng.integers(0, view.z.size, n)
    # A third at the corner's top exactly (a side of the same tool at its own level), the others above and below.
    lift = np.where(rng.random(n) < 1.0 / 3.0, view.rc[k], rng.uniform(-0.5, 2.5, n) * view.rc[k])
    origin = np.stack([rng.uniform(-18.0, 18.0, n), rng.uniform(-11.0, 11.0, n), view.z[k] + lift], axis=1)
    direction = np.broadcast_to(np.array([0.0, 0.0, 1.0]), (n, 3)).copy()
    before = rng.choice(rows, n)
    line = np.arange(n)

    def covered(found):
        """Per line, the part of 0 … 20 mm its intervals cover, as (start, end) runs."""
        runs = []
        for i in range(n):
            mine = (found[0] == i) & (found[2] > 0.0)
            spans = sorted(zip(np.maximum(found[1][mine], 0.0), found[2][mine]))
            merged = []
            for a, b in spans:
                if merged and a <= merged[-1][1]:
                    merged[-1][1] = max(merged[-1][1], b)
                else:
                    merged.append([a, b])
            runs.append(merged)
        return runs

    held = view.held
    taken = []

    def counting(*args, full=False):
        chain = held(*args, full=full)
        if full:
            taken.append(int((chain >= 0).sum()))
        return chain

    monkeypatch.setattr(view, "held", counting)
    plan = view.plan(origin)
    now = pairs.sides(view, line, k, line, origin, direction, plan, before)
    monkeypatch.setattr(view, "held", lambda *args, full=False: np.full(args[0].size, -1) if full else held(*args))
    searched = pairs.sides(view, line, k, line, origin, direction, plan, before)
    assert covered(now) == covered(searched)
    assert sum(taken) > 300

def test_segment_distance_against_sampling():
    """The plan distance of two segments (crossing, parallel, collinear, degenerate) against the least distance of
    4001 samples of one to the other segment: never above it, and below it by at most half the sample spacing."""
    rng = np.random.default_rng(11)
    cases = [rng.uniform(-2.0, 2.0, (4, 2)) for _ in range(200)]
    cases += [np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]]),  # collinear, apart
              np.array([[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [3.0, 0.0]]),  # collinear, overlapping
              np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]]),  # parallel
              np.array([[0.0, 0.0], [0.0, 0.0], [0.5, 0.5], [0.5, 0.5]]),  # two points
              np.array([[-1.0, 0.0], [1.0, 0.0], [0.0, -1.0], [0.0, 1.0]])]  # crossing
    for p0, p1, a, b in cases:
        got = segment_distance(p0[None], p1[None], a[None], b[None])[0]
        t = np.linspace(0.0, 1.0, 4001)[:, None]
        sampled = _point_segment(p0 + t * (p1 - p0), a, b).min()
        assert got <= sampled + 1e-12
        assert got >= sampled - 0.5 * np.linalg.norm(p1 - p0) / 4000 - 1e-12



def test_segment_distance_of_points_among_segments():
    """Rows whose first segment is a point (an arc's last point), alone, mixed with segments in one call, or all in
    one call, give each row the same number as alone, the number of the general formula for two segments (bit for
    bit: the level view's filters are unchanged by the point's shortcut), and that number is the point's distance
    from the segment (against 4001 samples of the segment)."""
    rng = np.random.default_rng(12)
    p0, a, b = (rng.uniform(-2.0, 2.0, (300, 2)) for _ in range(3))
    p1 = rng.uniform(-2.0, 2.0, (300, 2))
    point = rng.random(300) < 0.6
    p1[point] = p0[point]
    a[:5] = b[:5]  # a few pieces without length
    alone = np.array([segment_distance(p0[i:i + 1], p1[i:i + 1], a[i:i + 1], b[i:i + 1])[0] for i in range(300)])
    assert np.array_equal(segment_distance(p0, p1.copy(), a, b), alone)
    assert np.array_equal(segment_distance(p0[point], p1[point].copy(), a[point], b[point]), alone[point])
    assert np.array_equal(pairs._segment_distance(p0, p1, a, b), alone)
    t = np.linspace(0.0, 1.0, 4001)[:, None]
    for i in np.flatnonzero(point):
        sampled = np.hypot(*(p0[i] - (a[i] + t * (b[i] - a[i]))).T).min()
        assert sampled - 1e-3 <= alone[i] <= sampled + 1e-12

def _above_pair(rng, big, corner, flute, spread):
    """A random arc (tip at the origin, axis z, its direction d across it) against the same tool's move c0 … c0 +
    move at a level 0 < rise < r above its tip (c0 within ±spread in plan): (c0, move, d, decided, start, end), the
    last three as inprocess_plan.arc_level_intervals gives them."""
    from abm_workbench.engine.inprocess_plan import arc_level_intervals
    axis = np.array([0.0, 0.0, 1.0])
    rise = rng.uniform(0.02, 0.98) * corner
    c0 = np.array([*rng.uniform(-spread, spread, 2), rise])
    move = np.array([*rng.uniform(-3.0, 3.0, 2), 0.0]) * rng.choice([0.0, 1.0, 1.0])
    angle = rng.uniform(0.0, 2.0 * np.pi)
    d = np.array([np.cos(angle), np.sin(angle), 0.0])
    one = [np.array([v]) for v in (big, corner, 0.5 * np.pi)]
    decided, start, end = arc_level_intervals(np.zeros((1, 3)), d[None], axis[None], *one, c0[None],
                                              (c0 + move)[None], axis[None], np.array([big]), np.array([flute]),
                                              np.array([corner]))
    return c0, move, d, decided[0], start[0], end[0]


@pytest.mark.parametrize("ratio", [0.2, 0.5, 1.0])
def test_arc_against_the_same_tool_above(ratio):
    """An arc against the same tool's move across the axis at a level 0 < rise < r above its tip (the kind the
    plan view decides by its monotone bisection, inprocess_plan._arc_above): the removed part against the sampled
    swept solid, at 241 points of the arc, away from the part's start by 1e-6 rad."""
    rng = np.random.default_rng(5)
    big, flute = 3.0, 10.0
    corner = ratio * big
    axis = np.array([0.0, 0.0, 1.0])
    psi = np.linspace(0.0, 0.5 * np.pi, 241)
    checked = 0
    for _ in range(80):
        c0, move, d, decided, start, end = _above_pair(rng, big, corner, flute, 4.0)
        assert decided
        points = (big - corner + corner * np.sin(psi))[:, None] * d + (corner * (1.0 - np.cos(psi)))[:, None] * axis
        inside = in_swept(points, c0, move, axis, big, corner, flute)
        if np.isnan(end) or not end > start:
            assert not inside[psi < 0.5 * np.pi - 1e-6].any()
            continue
        clear = np.abs(psi - start) > 1e-6
        np.testing.assert_array_equal(inside[clear], (psi >= start)[clear])
        checked += int(inside.any())
    assert checked > 20


@pytest.mark.parametrize("ratio", [0.2, 0.5, 1.0])
def test_arc_above_finds_its_start_to_rounding(ratio):
    """The start ψ* of an arc's part removed by the same tool above (inprocess_plan._arc_above, false position
    guarded by bisection and probes) against ψ* bracketed from the sampled swept solid alone: 64 points of the
    bracket a round, 9 rounds (a bracket of (π/2)/65⁹, 3·10⁻¹⁷ rad), within 10⁻¹² rad, on 30 random placements
    where ψ* lies inside the arc."""
    rng = np.random.default_rng(11)
    big, flute = 3.0, 10.0
    corner = ratio * big
    axis = np.array([0.0, 0.0, 1.0])
    found = 0
    for _ in range(1000):
        if found == 30:
            break
        c0, move, d, _, start, end = _above_pair(rng, big, corner, flute, 2.0)
        rise = c0[2]

        def inside(psi):
            points = (big - corner + corner * np.sin(psi))[:, None] * d + (corner * (1.0 - np.cos(psi)))[:, None] * axis
            return in_swept(points, c0, move, axis, big, corner, flute)

        low, high = np.arccos(1.0 - rise / corner), 0.5 * np.pi
        if not inside(np.array([high]))[0] or inside(np.array([low]))[0] or np.isnan(end):
            continue  # nothing removed, or all of the arc from the earlier tool's bottom up: other tests
        for _ in range(9):
            psi = np.linspace(low, high, 66)[1:-1]
            hit = inside(psi)
            first = int(np.argmax(hit)) if hit.any() else psi.size
            low, high = (psi[first - 1] if first else low), (psi[first] if first < psi.size else high)
        assert abs(start - high) <= 1e-12, (start, low, high)
        found += 1
    assert found == 30


def test_arc_above_leaves_out_only_parts_within_others():
    """Given each pair's arc, _arc_above solves only the pairs that can hold an arc's least ψ*: per arc the union
    of the parts (ψ* … top) is the same as with every pair solved, bit for bit, each part it does give is the same,
    and parts are left out (an arc of 8 pieces of the level above, placed around it, two levels)."""
    from abm_workbench.engine.inprocess_plan import arc_level_intervals
    rng = np.random.default_rng(23)
    big, corner, flute, arcs, per = 3.0, 3.0, 10.0, 200, 8
    axis = np.tile([0.0, 0.0, 1.0], (arcs * per, 1))
    angle = np.repeat(rng.uniform(0.0, 2.0 * np.pi, arcs), per)
    d = np.stack([np.cos(angle), np.sin(angle), np.zeros(angle.size)], axis=1)
    rise = np.repeat(rng.choice([0.4, 1.1], (arcs, 1)), per, axis=1).ravel() + rng.choice([0.0, 0.7], arcs * per)
    c0 = np.column_stack([rng.uniform(-3.0, 3.0, (arcs * per, 2)), rise])
    c1 = c0 + np.column_stack([rng.uniform(-1.0, 1.0, (arcs * per, 2)), np.zeros(arcs * per)])
    one = [np.full(arcs * per, v) for v in (big, corner, 0.5 * np.pi)]
    tool = [np.full(arcs * per, v) for v in (big, flute, corner)]
    arc = np.repeat(np.arange(arcs), per)
    every = arc_level_intervals(np.zeros((arcs * per, 3)), d, axis, *one, c0, c1, axis, *tool)
    some = arc_level_intervals(np.zeros((arcs * per, 3)), d, axis, *one, c0, c1, axis, *tool, arc=arc)
    assert every[0].all() and some[0].all()
    given = ~np.isnan(some[2])
    np.testing.assert_array_equal(some[1][given], every[1][given])
    np.testing.assert_array_equal(some[2][given], every[2][given])
    least = [np.full(arcs, np.inf), np.full(arcs, np.inf)]
    for got, (_, start, _) in zip(least, (every, some)):
        np.minimum.at(got, arc[~np.isnan(start)], start[~np.isnan(start)])
    np.testing.assert_array_equal(least[0], least[1])
    assert np.isfinite(least[0]).sum() > arcs // 4
    assert (np.isnan(some[2]) & ~np.isnan(every[2])).sum() > arcs // 4


def test_first_least_is_the_stable_sorts_first():
    """The lead of each run of equal keys (the piece a round solves first) is the row a stable sort by (key, value)
    puts first: ties of value (−0 and 0 among them) go to the earlier row."""
    from abm_workbench.engine.inprocess_cover import run_starts
    rng = np.random.default_rng(5)
    for _ in range(500):
        size = int(rng.integers(0, 40))
        key = np.sort(rng.integers(0, 8, size))
        value = rng.integers(0, 4, size) * rng.choice([1.0, -0.0, 0.0], size)
        order = np.lexsort((value, key))
        expected = np.zeros(size, dtype=bool)
        expected[order[run_starts(key[order])[0]]] = True
        assert np.array_equal(pairs._first_least(key, value), expected)


def test_plan_norm_within_an_ulp_of_hypot():
    """The plan lengths of the level view's distances (sqrt of the sum of squares) are hypot's to within one ulp of
    the length, over lengths from 1e-9 to 1e9 mm."""
    rng = np.random.default_rng(6)
    x, y = (rng.normal(size=20000) * 10.0 ** rng.uniform(-9, 9, 20000) for _ in range(2))
    exact = np.hypot(x, y)
    assert np.all(np.abs(pairs.norm(x, y) - exact) <= np.spacing(exact))
