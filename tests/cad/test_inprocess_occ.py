"""The in-process engine against OpenCASCADE: the stock solid cut by exact solids of the earlier
moves' swept volumes, then the edge lines' sections with it (cad.inprocess_boolean)."""

import numpy as np

from abm_workbench.cad.inprocess_boolean import hull_solid, inprocess_lengths
from abm_workbench.cad.solids import staircase_solid
from abm_workbench.engine.engagement import inside_intervals
from abm_workbench.engine.inprocess import inprocess_intervals, swept_pieces
from tests.engine.test_inprocess import Program, edge_lines, staircase, straight

AGREE = 1e-6  # mm: both sides are exact
PHI = np.arange(0.0, 181.0, 15.0)


def program():
    """A pass along x, a ramping pass beside it (overlap, axis constant), then a tilted tool
    with another diameter and flute length crossing both."""
    prog = Program()
    prog.add_pass(straight(8, 52, -3.0, 3.0, 5), 5.0, 12.0)
    ramp = straight(52, 8, 4.0, 0.0, 5)
    ramp[:, 2] = np.linspace(4.5, 2.0, 5)
    prog.add_pass(ramp, 5.0, 12.0)
    lean = np.tile([0.15, -0.1, 1.0], (4, 1))
    cross = np.stack([np.full(4, 30.0), np.linspace(-16, 14, 4), np.full(4, 1.5)], axis=1)
    rows = prog.add_pass(cross, 3.5, 16.0, lean)
    return prog, rows


def test_hull_solid_volume():
    """By Cavalieri (slices across the axis are stadiums): V = πr²·(H + |d∥|) + 2r·H·|d⊥|."""
    r, h = 2.0, 5.0
    d = np.array([3.0, 0.0, 1.5])
    solid = hull_solid([0, 0, 0], d, [0, 0, 1.0], r, h)
    want = np.pi * r * r * (h + 1.5) + 2 * r * h * 3.0
    assert solid.isValid()
    np.testing.assert_allclose(solid.Volume, want, rtol=1e-9)


def test_engine_matches_booleans():
    prog, rows = program()
    moves = prog.moves()
    pieces = swept_pieces(moves)
    d = prog.as_dict()
    stock = staircase()
    solid = staircase_solid(stock)
    for k in rows[2:]:
        origins, directions = edge_lines(d, [k], PHI)
        flute = d["flute"][k]
        stock_iv = inside_intervals(stock, origins, directions, flute)
        got, changed = inprocess_intervals(stock_iv, pieces, [k], origins, directions, PHI.size)
        want = inprocess_lengths(solid, (moves, pieces), k, origins, directions[0], flute)
        assert want["solid"].isValid()
        np.testing.assert_allclose(got.length, want["length"], rtol=0, atol=AGREE)
        first = np.r_[True, got.rows[1:] != got.rows[:-1]]
        last = np.r_[got.rows[1:] != got.rows[:-1], True]
        lep, uep = np.full(PHI.size, np.nan), np.full(PHI.size, np.nan)
        lep[got.rows[first]], uep[got.rows[last]] = got.start[first], got.end[last]
        np.testing.assert_allclose(lep, want["lep_l"], rtol=0, atol=AGREE)
        np.testing.assert_allclose(uep, want["uep_l"], rtol=0, atol=AGREE)
        assert changed[0] == bool((stock_iv.length - want["length"] > AGREE).any())
