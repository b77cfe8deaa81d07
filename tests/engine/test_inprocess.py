"""In-process stock against an independent brute-force reference.

The reference knows nothing of the engine's closed forms: it samples each edge line densely,
calls a point engaged when it is inside the staircase (straight walls: a section lookup) and
inside no volume swept by a cutting move that ends before the CL point, and refines every
change of that predicate by bisection. A point is inside a constant-axis move's volume when
some position s ∈ [0, 1] along the move puts it inside the tool's cylinder: the s for which its
height over the bottom face is within 0 … H and the s for which its distance from the axis is at
most r are two intervals, solved from the point alone, and they must meet. A move whose axis
turns is sampled at SWEEP_SAMPLES positions, each a point-in-cylinder test with the axis
interpolated and normalised.
"""

import numpy as np
import pytest

from abm_workbench.engine import Staircase
from abm_workbench.engine.engagement import SURFACES, inside_intervals
from abm_workbench.engine.inprocess import ProgramMoves, inprocess_intervals, subtract, swept_pieces

SAMPLES = 801           # points per edge line
BISECTION_STEPS = 45    # halvings of a sample step (~1e-15 mm)
SWEEP_SAMPLES = 601     # tool positions per five-axis move
AGREE = 0.01            # mm: lengths, LEP and UEP (the bound)
EXACT = 1e-6            # mm: where the engine is closed form (constant-axis moves)

STOCK = dict(x_min=0.0, x_max=60.0, y_min=-30.0, y_max=30.0, base_z=0.0, z_top=(9.0, 6.0, 8.0),
             walls=(20.0, 41.0))


def staircase():
    """The test stock: three sections, straight walls at x = 20 and 41."""
    y = np.linspace(STOCK["y_min"], STOCK["y_max"], 6)
    points = [np.stack([np.full(6, x), y], axis=1) for x in STOCK["walls"]]
    return Staircase(STOCK["x_min"], STOCK["x_max"], STOCK["y_min"], STOCK["y_max"], STOCK["base_z"],
                     np.array(STOCK["z_top"]), np.array(points))


def in_stock(points):
    """(P,) bool: points (P, 3) inside the test stock (written from STOCK alone)."""
    x, y, z = points.T
    section = np.searchsorted(np.array(STOCK["walls"]), x, side="right")
    top = np.array(STOCK["z_top"])[section]
    return ((x >= STOCK["x_min"]) & (x <= STOCK["x_max"]) & (y >= STOCK["y_min"]) & (y <= STOCK["y_max"])
            & (z >= STOCK["base_z"]) & (z <= top))


def in_hull(points, c0, c1, w, r, h):
    """(P,) bool: points inside the volume of the tool (radius r, height h, axis w) moved from c0 to c1."""
    q = points - c0
    d = c1 - c0
    a0, da = q @ w, d @ w
    b0 = q - a0[:, None] * w
    dp = d - da * w
    # 0 ≤ a0 − s·da ≤ h
    if abs(da) > 1e-15:
        s1, s2 = a0 / da, (a0 - h) / da
        low, high = np.minimum(s1, s2), np.maximum(s1, s2)
    else:
        inside = (a0 >= 0) & (a0 <= h)
        low, high = np.where(inside, -np.inf, np.inf), np.where(inside, np.inf, -np.inf)
    # |b0 − s·dp|² ≤ r²
    aa, bb, cc = dp @ dp, b0 @ dp, (b0 * b0).sum(axis=1) - r * r
    if aa > 1e-20:
        disc = bb * bb - aa * cc
        root = np.sqrt(np.maximum(disc, 0.0))
        r_low = np.where(disc >= 0, (bb - root) / aa, np.inf)
        r_high = np.where(disc >= 0, (bb + root) / aa, -np.inf)
    else:
        r_low, r_high = np.where(cc <= 0, -np.inf, np.inf), np.where(cc <= 0, np.inf, -np.inf)
    return np.maximum.reduce([low, r_low, np.zeros_like(low)]) <= np.minimum.reduce([high, r_high, np.ones_like(low)])


def in_cylinders(points, c0, c1, w0, w1, r, h):
    """(P,) bool: points inside the tool at some of SWEEP_SAMPLES positions of a move whose axis turns."""
    t = np.linspace(0.0, 1.0, SWEEP_SAMPLES)[:, None]
    centres = c0 + t * (c1 - c0)
    axes = (1 - t) * w0 + t * w1
    axes /= np.linalg.norm(axes, axis=1)[:, None]
    hit = np.zeros(len(points), dtype=bool)
    block = max(1, 2_000_000 // max(len(points), 1))
    for first in range(0, SWEEP_SAMPLES, block):
        c, w = centres[first:first + block], axes[first:first + block]
        q = points[:, None, :] - c[None]
        a = np.einsum("psk,sk->ps", q, w)
        b2 = np.einsum("psk,psk->ps", q, q) - a * a
        hit |= ((a >= 0) & (a <= h) & (b2 <= r * r)).any(axis=1)
    return hit


def removed(points, program, k):
    """(P,) bool: points inside the volume of some cutting move j ≤ k − 1 of `program` (a dict)."""
    hit = np.zeros(len(points), dtype=bool)
    for j in range(1, k):
        if not program["cutting"][j]:
            continue
        c0, c1 = program["cl"][j - 1], program["cl"][j]
        w0, w1 = program["axis"][j - 1], program["axis"][j]
        r, h = program["radius"][j], program["flute"][j]
        near = np.linalg.norm(points - 0.5 * (c0 + c1), axis=1) <= np.linalg.norm(c1 - c0) + r + h + 1.0
        if not near.any():
            continue
        if np.allclose(w0, w1, atol=0, rtol=0):
            hit[near] |= in_hull(points[near], c0, c1, w0, r, h)
        else:
            hit[near] |= in_cylinders(points[near], c0, c1, w0, w1, r, h)
    return hit


def reference(origin, direction, length, program, k):
    """Engaged intervals [(start, end), …] of one edge line at CL row k, by sampling and bisection."""
    def engaged(l):
        points = origin + l[:, None] * direction
        return in_stock(points) & ~removed(points, program, k)

    l = np.linspace(0.0, length, SAMPLES)
    state = engaged(l)
    change = np.flatnonzero(state[1:] != state[:-1])
    low, high = l[change], l[change + 1]
    for _ in range(BISECTION_STEPS):
        mid = 0.5 * (low + high)
        same = engaged(mid) == state[change]
        low, high = np.where(same, mid, low), np.where(same, high, mid)
    cuts = 0.5 * (low + high)
    bounds = np.concatenate([[0.0] if state[0] else [], cuts, [length] if state[-1] else []])
    return list(zip(bounds[::2], bounds[1::2]))


def edge_lines(program, rows, phi_deg, fixed=False):
    """Origins and directions (len(rows)·p, 3) of the edge lines of the tool at program rows.

    φ = 90° points along the feed (the move into the row, across the axis), φ = 0 to its left;
    with `fixed`, along +x across the axis whatever the feed (the engine's tool frame).
    """
    phi = np.radians(phi_deg)
    origins, directions = [], []
    for k in rows:
        w = program["axis"][k]
        feed = np.array([1.0, 0.0, 0.0]) if fixed else program["cl"][k] - program["cl"][k - 1]
        feed = feed - (feed @ w) * w
        feed /= np.linalg.norm(feed)
        radial = np.sin(phi)[:, None] * feed + np.cos(phi)[:, None] * np.cross(w, feed)
        origins.append(program["cl"][k] + program["radius"][k] * radial)
        directions.append(np.repeat(w[None], phi.size, axis=0))
    return np.concatenate(origins), np.concatenate(directions)


class Program:
    """A program built pass by pass: each pass starts with a rapid to its first point."""

    def __init__(self):
        self.rows = {"cl": [], "axis": [], "cutting": [], "radius": [], "flute": []}

    def add_pass(self, points, radius, flute, axes=None):
        """Append a pass through `points` (n, 3) with a tool of `radius` and `flute` length;
        axes (n, 3) default +z. Returns the program rows of the pass."""
        n = len(points)
        axes = np.tile([0.0, 0.0, 1.0], (n, 1)) if axes is None else np.asarray(axes, dtype=float)
        axes = axes / np.linalg.norm(axes, axis=1)[:, None]
        first = len(self.rows["cl"])
        for i in range(n):
            self.rows["cl"].append(np.asarray(points[i], dtype=float))
            self.rows["axis"].append(axes[i])
            self.rows["cutting"].append(i > 0)
            self.rows["radius"].append(radius)
            self.rows["flute"].append(flute)
        return np.arange(first, first + n)

    def as_dict(self):
        return {name: np.array(values) for name, values in self.rows.items()}

    def moves(self):
        d = self.as_dict()
        return ProgramMoves(d["cl"], d["axis"], d["cutting"], d["radius"], d["flute"], np.arange(len(d["cl"])) + 1)


def straight(x0, x1, y, z, n):
    """n CL points from (x0, y, z) to (x1, y, z)."""
    return np.stack([np.linspace(x0, x1, n), np.full(n, y), np.full(n, z)], axis=1)


def check(program, rows, phi, tolerance=0.05, agree=AGREE, fixed=False):
    """Engine against reference at program `rows` and angles `phi` (deg): lengths, LEP, UEP;
    returns (engine EdgeIntervals, changed, reference intervals per line)."""
    d = program.as_dict()
    origins, directions = edge_lines(d, rows, phi, fixed)
    flute = d["flute"][rows].max()
    assert np.all(d["flute"][rows] == flute)
    stock_iv = inside_intervals(staircase(), origins, directions, flute)
    got, changed = inprocess_intervals(stock_iv, program.moves(), rows, origins, directions, phi.size,
                                       tolerance=tolerance)
    want = [reference(origins[i], directions[i], flute, d, rows[i // phi.size]) for i in range(len(origins))]
    want_length = np.array([sum(e - s for s, e in w) for w in want])
    np.testing.assert_allclose(got.length, want_length, rtol=0, atol=agree)
    first = np.r_[True, got.rows[1:] != got.rows[:-1]] if got.rows.size else np.zeros(0, bool)
    last = np.r_[got.rows[1:] != got.rows[:-1], True] if got.rows.size else np.zeros(0, bool)
    lep, uep = np.full(len(want), np.nan), np.full(len(want), np.nan)
    lep[got.rows[first]], uep[got.rows[last]] = got.start[first], got.end[last]
    want_lep = np.array([w[0][0] if w else np.nan for w in want])
    want_uep = np.array([w[-1][1] if w else np.nan for w in want])
    real = want_length > agree  # a sliver thinner than the bound may be seen by one side only
    np.testing.assert_allclose(lep[real], want_lep[real], rtol=0, atol=agree)
    np.testing.assert_allclose(uep[real], want_uep[real], rtol=0, atol=agree)
    stock_length = stock_iv.length.reshape(len(rows), phi.size)
    lost = (stock_length - want_length.reshape(len(rows), phi.size)).max(axis=1)
    assert not changed[lost < -agree].any()
    assert changed[lost > agree].all()
    return got, changed, want


PHI = np.arange(0.0, 181.0, 10.0)


def test_curving_pass_meets_its_own_earlier_moves():
    """A pass along an arc, φ measured in a tool frame that does not turn with the feed: its
    flanks meet what its own earlier moves removed."""
    program = Program()
    angle = np.radians(np.linspace(-90, 10, 26))
    arc = np.stack([30 + 14 * np.cos(angle), 14 * np.sin(angle) + 2, np.full(angle.size, 3.0)], axis=1)
    rows = program.add_pass(arc, 5.0, 12.0)
    got, changed, _ = check(program, rows[6:22:3], PHI, fixed=True)
    assert changed.any()


def test_adjacent_passes_with_overlap():
    """Three passes side by side at a stepover of 0.6 D; the later ones lose what the earlier cut."""
    program = Program()
    for y in (-6.0, 0.0, 6.0):
        rows = program.add_pass(straight(5, 55, y, 2.5, 21), 5.0, 12.0)
    got, changed, _ = check(program, rows[3:19:4], PHI)
    assert changed.all()


def test_pass_recrossing_an_earlier_one():
    """A pass along y crosses one along x; a second operation with another tool comes after."""
    program = Program()
    program.add_pass(straight(5, 55, 0.0, 3.0, 18), 5.0, 12.0)
    crossing = np.stack([np.full(15, 30.0), np.linspace(-20, 20, 15), np.full(15, 2.0)], axis=1)
    rows = program.add_pass(crossing, 4.0, 15.0)
    check(program, rows[5:10], PHI)


def test_second_operation_with_another_tool():
    """Operation 1 (D 10, L 12) in two passes, then operation 2 (D 6, L 20) between and below them."""
    program = Program()
    program.add_pass(straight(5, 55, -4.0, 4.0, 15), 5.0, 12.0)
    program.add_pass(straight(55, 5, 4.0, 4.0, 15), 5.0, 12.0)
    rows = program.add_pass(straight(8, 52, 1.0, 1.5, 23), 3.0, 20.0)
    got, changed, _ = check(program, rows[2:21:4], PHI)
    assert changed.all()
    # The deeper tool keeps the material below the first operation's bottom faces.
    assert (got.end_surface == SURFACES.index("machined")).any()


def test_five_axis_moves():
    """A pass whose tool axis leans more and more, then a tilted pass beside it: sub-stepped
    moves against the sampled reference."""
    program = Program()
    n = 12
    lean = np.radians(np.linspace(0, 20, n))
    axes = np.stack([np.sin(lean), np.zeros(n), np.cos(lean)], axis=1)
    program.add_pass(straight(10, 50, -3.0, 3.0, n), 5.0, 12.0, axes)
    tilt = np.radians(np.linspace(-10, 10, n))
    axes2 = np.stack([np.zeros(n), np.sin(tilt), np.cos(tilt)], axis=1)
    rows = program.add_pass(straight(12, 48, 4.0, 2.0, n), 5.0, 12.0, axes2)
    # At the default tolerance the volume is within 0.025 mm of the true one; lines through it
    # at a grazing angle can move their ends by more, so this compares at a finer tolerance.
    got, changed, _ = check(program, rows[2:11:4], PHI, tolerance=0.005)
    assert changed.any()


def test_nothing_earlier_touches_the_edge():
    """A single pass whose earlier moves never reach the leading edge's stock: identical intervals."""
    program = Program()
    program.add_pass(straight(5, 15, -20.0, 3.0, 4), 5.0, 12.0)
    rows = program.add_pass(straight(25, 55, 10.0, 3.0, 16), 5.0, 12.0)
    d = program.as_dict()
    phi = np.arange(0.0, 181.0, 1.0)
    origins, directions = edge_lines(d, rows, phi)
    stock_iv = inside_intervals(staircase(), origins, directions, 12.0)
    got, changed = inprocess_intervals(stock_iv, program.moves(), rows, origins, directions, phi.size)
    assert not changed.any()
    for name in ("rows", "start", "end", "start_surface", "start_section", "start_wall", "end_surface", "end_section",
                 "end_wall"):
        assert np.array_equal(getattr(got, name), getattr(stock_iv, name)), name


def test_closed_form_is_exact_for_constant_axes():
    """Constant-axis moves are intersected exactly: ends agree with the bisected reference to EXACT."""
    program = Program()
    for y in (-5.0, 1.0):
        rows = program.add_pass(straight(5, 55, y, 2.5, 9), 5.0, 12.0)
    check(program, rows[2:8:2], PHI, agree=EXACT)


def test_subtract_keeps_stock_labels_and_marks_machined_ends():
    """Interval arithmetic on two lines, by hand."""
    from abm_workbench.engine.intervals import EdgeIntervals
    stock = EdgeIntervals(2, np.array([0, 0, 1]), np.array([0.0, 5.0, 1.0]), np.array([4.0, 9.0, 3.0]),
                          np.array([4, 2, 4]), np.array([0, 1, 0]), np.array([-1, 1, -1]),
                          np.array([2, 1, 1]), np.array([0, 1, 0]), np.array([1, -1, -1]))
    out = subtract(stock, np.array([0, 0]), np.array([3.0, 6.0]), np.array([5.5, 7.0]))
    assert out.rows.tolist() == [0, 0, 0, 1]
    assert out.start.tolist() == [0.0, 5.5, 7.0, 1.0] and out.end.tolist() == [3.0, 6.0, 9.0, 3.0]
    machined = SURFACES.index("machined")
    assert out.start_surface.tolist() == [4, machined, machined, 4]
    assert out.end_surface.tolist() == [machined, machined, 1, 1]
    assert out.end_section.tolist() == [-1, -1, 1, 0]


def test_program_moves_errors_name_the_row_and_line():
    with pytest.raises(ValueError, match=r"row 1 \(line 12\).*unit"):
        ProgramMoves(np.zeros((2, 3)), [[0, 0, 1], [0, 0, 2]], [False, True], [3, 3], [10, 10], [11, 12])
    with pytest.raises(ValueError, match=r"row 0 \(line 11\): radius"):
        ProgramMoves(np.zeros((2, 3)), [[0, 0, 1], [0, 0, 1]], [False, True], [0, 3], [10, 10], [11, 12])
    with pytest.raises(ValueError, match="180"):
        ProgramMoves(np.zeros((2, 3)), [[0, 0, 1], [0, 0, -1]], [False, True], [3, 3], [10, 10], [11, 12])
    with pytest.raises(ValueError, match="tolerance"):
        swept_pieces(ProgramMoves(np.zeros((2, 3)), [[0, 0, 1]] * 2, [False, True], [3, 3], [10, 10], [1, 2]), 0.0)


def test_transformed_moves_give_the_same_removal():
    """Moving the program and the lines by one rigid motion changes no length."""
    program = Program()
    program.add_pass(straight(5, 55, -4.0, 3.0, 12), 5.0, 12.0)
    rows = program.add_pass(straight(5, 55, 3.0, 3.0, 12), 5.0, 12.0)
    d = program.as_dict()
    origins, directions = edge_lines(d, rows, PHI)
    stock_iv = inside_intervals(staircase(), origins, directions, 12.0)
    got, _ = inprocess_intervals(stock_iv, program.moves(), rows, origins, directions, PHI.size)
    c, s = np.cos(0.7), np.sin(0.7)
    rotation = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]]) @ np.array([[1, 0, 0], [0, np.cos(0.3), -np.sin(0.3)],
                                                                           [0, np.sin(0.3), np.cos(0.3)]])
    shift = np.array([5.0, -3.0, 2.0])
    moved = program.moves().transformed(rotation, shift)
    moved_got, _ = inprocess_intervals(stock_iv, moved, rows, origins @ rotation.T + shift, directions @ rotation.T,
                                       PHI.size)
    np.testing.assert_allclose(moved_got.length, got.length, rtol=0, atol=1e-9)


def test_line_against_one_hull_random():
    """line_hull_interval on random lines, moves and axes (including lines along the axis and
    moves along it) against the point-in-hull test, sampled and bisected."""
    from abm_workbench.engine.swept import line_hull_interval
    rng = np.random.default_rng(7)
    count = 150
    for trial in range(count):
        w = rng.normal(size=3) if trial % 3 else np.array([0.0, 0.0, 1.0])
        w /= np.linalg.norm(w)
        c0 = rng.normal(size=3) * 3
        d = rng.normal(size=3) * rng.choice([0.0, 0.5, 5.0]) if trial % 5 else 2.0 * w
        r, h = rng.uniform(1, 5), rng.uniform(2, 10)
        o = c0 + rng.normal(size=3) * 4
        u = w.copy() if trial % 6 == 0 else rng.normal(size=3)
        u /= np.linalg.norm(u)
        enter, leave = line_hull_interval(o[None], u[None], c0[None], (c0 + d)[None], w[None], np.array([r]),
                                          np.array([h]))
        l = np.linspace(-40, 40, 4001)
        state = in_hull(o + l[:, None] * u, c0, c0 + d, w, r, h)
        if not state.any():
            assert np.isnan(enter[0]) or leave[0] - enter[0] < 1e-6
            continue
        ends = []
        for i in (np.argmax(state) - 1, len(state) - 1 - np.argmax(state[::-1])):
            low, high = l[i], l[i + 1]
            for _ in range(60):
                mid = 0.5 * (low + high)
                if in_hull((o + mid * u)[None], c0, c0 + d, w, r, h)[0] == state[i]:
                    low = mid
                else:
                    high = mid
            ends.append(0.5 * (low + high))
        np.testing.assert_allclose([enter[0], leave[0]], ends, rtol=0, atol=1e-9)


def test_rapid_collisions_name_the_rapid_and_its_line():
    """A rapid that ends 1 mm below the stock's top is reported with its source line; rapids
    above the stock and beside it are not."""
    from abm_workbench.engine.inprocess import rapid_collisions
    program = Program()
    program.add_pass(straight(5, 15, 0.0, 12.0, 2), 5.0, 12.0)          # above the stock (top 9)
    program.add_pass(straight(5, 15, -40.0, 12.0, 2), 5.0, 12.0)        # beside it (y < −30)
    program.add_pass(straight(5, 15, 0.0, 8.0, 2), 5.0, 12.0)           # rapid down into it
    rows, lines, depth = rapid_collisions(staircase(), program.moves())
    assert rows.tolist() == [4] and lines.tolist() == [5]
    # A probe line at the rim from z = 8 up to the top at 9 (section 0).
    np.testing.assert_allclose(depth, [1.0], atol=1e-9)


def test_pass_inprocess_chunks_agree_with_one_call():
    """pass_inprocess in small chunks gives the lengths of one call on the whole pass, and its
    single-pass result without earlier passes equals engage's lengths wherever nothing changed."""
    from abm_workbench.engine import CutSettings, Tool, Toolpath, engage
    from abm_workbench.engine.inprocess import pass_inprocess
    tool = Tool(10.0, 2, 12.0)
    first = Toolpath(straight(5, 55, -3.0, 3.0, 14), np.zeros(14), np.zeros(14))
    second = Toolpath(straight(5, 55, 4.0, 2.5, 14), np.full(14, 3.0), np.full(14, 5.0))
    axes = np.concatenate([np.tile([0, 0, 1.0], (14, 1)), np.tile(
        [np.sin(np.radians(5.0)), -np.sin(np.radians(3.0)) * np.cos(np.radians(5.0)),
         np.cos(np.radians(3.0)) * np.cos(np.radians(5.0))], (14, 1))])
    cl = np.concatenate([first.cl, second.cl])
    moves = ProgramMoves(cl, axes, np.r_[False, np.ones(13, bool), False, np.ones(13, bool)], np.full(28, 5.0),
                         np.full(28, 12.0), np.arange(28))
    pieces = swept_pieces(moves)
    phi = np.arange(0.0, 181.0, 3.0)
    chunks = list(pass_inprocess(staircase(), tool, second, phi, pieces, np.arange(14, 28), chunk_instants=200))
    whole = list(pass_inprocess(staircase(), tool, second, phi, pieces, np.arange(14, 28)))
    assert len(chunks) > 1 and len(whole) == 1
    np.testing.assert_array_equal(np.concatenate([c[2].length for c in chunks]), whole[0][2].length)
    np.testing.assert_array_equal(np.concatenate([c[3] for c in chunks]), whole[0][3])
    assert whole[0][3].any()
    alone = next(pass_inprocess(staircase(), tool, first, phi, pieces, np.arange(14)))
    initial = engage(staircase(), tool, first, CutSettings(0.1, 0.0, 0.0, 180.0, 3.0)).length.reshape(-1)
    same = np.repeat(~alone[3], phi.size)
    np.testing.assert_array_equal(alone[2].length[same], initial[same])


def test_a_program_without_cutting_moves_removes_nothing():
    """Only rapids (no swept piece at all): every edge line keeps its stock intervals."""
    cl = np.array([[20.0, -10.0, 2.0], [20.0, 0.0, 2.0], [20.0, 10.0, 2.0]])
    moves = ProgramMoves(cl, [[0.0, 0.0, 1.0]] * 3, [False, False, False], [5.0] * 3, [12.0] * 3, [1, 2, 3])
    pieces = swept_pieces(moves)
    phi = np.arange(0.0, 181.0, 10.0)
    program = {"cl": cl, "axis": np.array([[0.0, 0.0, 1.0]] * 3), "radius": np.full(3, 5.0)}
    origins, directions = edge_lines(program, [1, 2], phi, fixed=True)
    stock_iv = inside_intervals(staircase(), origins, directions, 12.0)
    got, changed = inprocess_intervals(stock_iv, pieces, np.array([1, 2]), origins, directions, phi.size)
    assert stock_iv.rows.size and not changed.any()
    assert np.array_equal(got.start, stock_iv.start) and np.array_equal(got.end, stock_iv.end)
