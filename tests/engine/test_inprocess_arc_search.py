"""The corner arcs' search for removals (engine/inprocess_arc_search.py): its work arrays are bounded by a block of CL
points, not by the call, and the blocks do not change the result; the sure-miss test of a move along the tool axis
(a plunge).

Before 2026-11-26 the search made one table of (arc, chain) pairs for every arc of a call and expanded it to (arc,
span) pairs: 3.5 GB on FreeCAD CAM's Adaptive with a D6 ball-end mill (docs/BENCHMARKS.md). The bound checked here
is what keeps that from coming back; the brute-force comparisons of the arcs' results are in
test_inprocess_corner_program.py.
"""

import dataclasses

import numpy as np

import abm_workbench.engine.inprocess_arc_search as search
import abm_workbench.engine.inprocess_plan as plan
from abm_workbench.engine import CutSettings, Tool, Toolpath
from abm_workbench.engine.inprocess import _apart, swept_pieces
from abm_workbench.engine.stocks import engage_in_process

from .test_inprocess_corner_program import Program, straight
from .test_tool_profiles import STAIRCASE

PHI = CutSettings(0.1, 0.0, 0.0, 350.0, 10.0)  # 36 angles


def ball_program():
    """Five passes of a D8 R3 bull-nose mill across the staircase, 2.5 mm apart and each 0.4 mm lower, then a sixth of
    a D8 ball-end mill between the last two: (program, tool, rows of the sixth pass). The earlier tool is another
    one, so the plan view decides none of the ball's arcs against it (inprocess_plan.arc_kinds): every pair goes
    through the search's sure-miss tests and the arc solver checked here."""
    program = Program()
    tool = Tool(8.0, 2, 12.0, corner_radius=4.0)
    for k in range(5):
        program.add(straight(-12, 12, -5.0 + 2.5 * k, 2.8 - 0.4 * k, 13), tool.radius, tool.flute_length, 3.0)
    rows = program.add(straight(-12, 12, 3.75, 1.0, 13), tool.radius, tool.flute_length, tool.corner_radius)
    return program, tool, rows


def largest_arrays(monkeypatch, block, pairs):
    """Run the sixth pass with ARC_BLOCK = block arcs and ROUND_PAIRS = pairs; (Engagement, the largest number of
    rows given to the sure-miss test, the largest given to the arc solver)."""
    program, tool, rows = ball_program()
    pieces = swept_pieces(program.moves())
    toolpath = Toolpath(program.array("cl")[rows], np.zeros(rows.size), np.zeros(rows.size))
    seen = {"apart": 0, "solve": 0}

    def counting(name, function):
        def counted(first, *args, **kwargs):
            seen[name] = max(seen[name], len(first))
            return function(first, *args, **kwargs)
        return counted

    monkeypatch.setattr(search, "ARC_BLOCK", block)
    monkeypatch.setattr(search, "ROUND_PAIRS", pairs)
    monkeypatch.setattr(search, "_apart", counting("apart", search._apart))
    monkeypatch.setattr(plan, "arc_swept_intervals", counting("solve", plan.arc_swept_intervals))
    engagement = engage_in_process(STAIRCASE, tool, toolpath, PHI, pieces, rows)[0]
    return engagement, seen["apart"], seen["solve"], pieces


def test_work_is_bounded_by_the_block(monkeypatch):
    """With blocks of two CL points (72 arcs) and rounds of at most 100 pairs, no array of the search holds more
    rows than a round's pairs or a block's (CL point, piece) candidates, however many CL points the call has (13 x
    36 = 468 arcs, about 20 pieces near each: one table for the whole call would hold thousands); and the result is
    the same, bit for bit, as with one block and large rounds."""
    p = PHI.phi.size
    small, apart_rows, solve_rows, pieces = largest_arrays(monkeypatch, 2 * p, 100)
    # A block's candidates: 2 CL points x every piece of the program at most; a round: 100 pairs or one per arc.
    bound = max(100, 2 * p, 2 * pieces.move.size)
    assert 0 < apart_rows <= bound
    assert 0 < solve_rows <= bound
    whole, apart_whole, _, _ = largest_arrays(monkeypatch, 1 << 20, 1 << 20)
    assert apart_whole > bound  # the call as one block does exceed it: the bound above is not vacuous
    assert small.engaged.any()
    for field in dataclasses.fields(small):
        a, b = getattr(small, field.name), getattr(whole, field.name)
        assert np.array_equal(a, b, equal_nan=np.asarray(a).dtype.kind == "f"), field.name


def test_blocks_are_whole_cl_points():
    """_blocks cuts only between CL points, at most ARC_BLOCK arcs each, a larger CL point alone."""
    cl = np.repeat([0, 1, 2, 3, 4], [3, search.ARC_BLOCK + 1, 2, 2, search.ARC_BLOCK - 3])
    blocks = search._blocks(cl)
    assert blocks[0][0] == 0 and blocks[-1][1] == cl.size
    assert all(a[1] == b[0] for a, b in zip(blocks, blocks[1:]))
    for begin, end in blocks:
        assert begin == 0 or cl[begin] != cl[begin - 1]
        assert end == cl.size or cl[end] != cl[end - 1]
        assert end - begin <= search.ARC_BLOCK or np.unique(cl[begin:end]).size == 1
    assert [np.unique(cl[b:e]).tolist() for b, e in blocks] == [[0], [1], [2, 3], [4]]


def test_sure_miss_of_a_plunge():
    """A move along its tool's axis (a plunge) is a point seen along the axis: a segment passing over that point
    is not apart from it, one passing beside it farther than the radius is (the test once took only the
    segment's first end)."""
    c0, c1, axis = np.array([[0.0, 0.0, 2.0]]), np.array([[0.0, 0.0, 0.0]]), np.array([[0.0, 0.0, 1.0]])
    hull = (c0, c1, axis, np.array([1.0]), np.array([5.0]))
    across = _apart(np.array([[-3.0, 0.2, 1.0]]), np.array([[3.0, 0.2, 1.0]]), *hull, np.array([0.0]))
    beside = _apart(np.array([[-3.0, 1.5, 1.0]]), np.array([[3.0, 1.5, 1.0]]), *hull, np.array([0.0]))
    assert not across[0]
    assert beside[0]


def random_arcs(rng, n, radius):
    """n arcs (centres, d, w) of one corner radius at random places and orientations (d ⊥ w, unit)."""
    centres = rng.uniform(-5.0, 5.0, (n, 3))
    w = rng.normal(size=(n, 3))
    w /= np.linalg.norm(w, axis=1)[:, None]
    d = rng.normal(size=(n, 3))
    d -= (d * w).sum(axis=1)[:, None] * w
    d /= np.linalg.norm(d, axis=1)[:, None]
    return centres, d, w


def test_cluster_spheres_hold_their_arcs():
    """Each cluster's sphere j holds the points of every arc of the cluster over part j of the cluster's range of ψ,
    sampled at 2,001 points per part (the arcs written out here as C + r·(sin ψ·d − cos ψ·w), not by the module);
    arcs of a cluster at nearby angles, as a CL point's are, and far apart, with ranges of every width."""
    rng = np.random.default_rng(7)
    radius, top = 3.0, 0.5 * np.pi
    for spread in (0.05, 3.0):
        n = 40
        centres, d, w = random_arcs(rng, n, radius)
        centres = centres[:1] + spread * (centres - centres[:1]) / 10.0
        lo = rng.uniform(0.0, top, n) * rng.integers(0, 2, n)
        hi = np.minimum(lo + rng.uniform(0.0, top, n) ** 2, top)
        hi[::7] = lo[::7] + 1e-9  # a range almost closed
        line = np.arange(n)
        arcs = search._Arcs(line, lo, hi, (centres, d, w, centres - radius * w, radius, radius, top))
        live = np.arange(n)
        first = np.array([0, 1, 5, 13, 21, 29, 37])
        centre, size = arcs.spheres(live, first)
        cluster = np.repeat(np.arange(first.size), np.diff(np.r_[first, n]))
        low = np.minimum.reduceat(lo, first)
        high = np.maximum.reduceat(hi, first)
        worst = np.full(first.size, -np.inf)
        for i in range(n):
            c = cluster[i]
            for j in range(search.PARTS):
                psi = np.linspace(low[c] + j * (high[c] - low[c]) / search.PARTS,
                                  low[c] + (j + 1) * (high[c] - low[c]) / search.PARTS, 2001)
                points = centres[i] + radius * (np.sin(psi)[:, None] * d[i] - np.cos(psi)[:, None] * w[i])
                gap = np.linalg.norm(points - centre[c, j], axis=1).max() - size[c, j]
                worst[c] = max(worst[c], gap)
        assert (worst <= 0.0).all(), worst
        # Tight for a cluster of one arc (its part's ends are the farthest points): a sphere too small by 10⁻⁶ mm
        # would fail above.
        assert worst[0] > -1e-6, worst[0]


def test_clusters_change_no_result(monkeypatch):
    """Clusters of up to CLUSTER arcs drop pairs before each arc's own test; with clusters of one arc, or (as good as)
    without the clusters' test, every Engagement field is the same, bit for bit, and the clusters leave fewer pairs
    to the arcs' own test."""
    program, tool, rows = ball_program()
    pieces = swept_pieces(program.moves())
    toolpath = Toolpath(program.array("cl")[rows], np.zeros(rows.size), np.zeros(rows.size))
    tested = {}

    def run(name):
        seen = [0]
        near = search._Arcs.near

        def counted(self, seg, *args):
            seen[0] += len(seg)
            return near(self, seg, *args)

        monkeypatch.setattr(search._Arcs, "near", counted)
        out = engage_in_process(STAIRCASE, tool, toolpath, PHI, pieces, rows)[0]
        monkeypatch.setattr(search._Arcs, "near", near)
        tested[name] = seen[0]
        return out

    clustered = run("clusters")
    monkeypatch.setattr(search, "CLUSTER", 1)
    single = run("single")
    monkeypatch.setattr(search, "_clusters_near", lambda arcs, units, live, first, group, pos, count, pieces:
                        np.ones(int(count.sum()), dtype=bool))
    without = run("without")
    assert clustered.engaged.any()
    for other in (single, without):
        for field in dataclasses.fields(clustered):
            a, b = getattr(clustered, field.name), getattr(other, field.name)
            assert np.array_equal(a, b, equal_nan=np.asarray(a).dtype.kind == "f"), field.name
    assert tested["clusters"] < tested["without"], tested
