"""Dense programs (CL points a fraction of a mm apart) against the brute-force reference.

There each edge line meets dozens of earlier moves, so the engine takes its path for many
pairs: chains of spans tested per line, probe spans per group of lines, envelopes narrowed
round by round. The reference is test_inprocess's (dense sampling and bisection, knowing
nothing of chains or envelopes).
"""

import numpy as np

import abm_workbench.engine.inprocess as inprocess
from abm_workbench.engine.engagement import inside_intervals
from abm_workbench.engine.inprocess import inprocess_intervals

from .test_inprocess import AGREE, Program, check, edge_lines, reference, staircase

PHI = np.arange(0.0, 181.0, 15.0)


def arc(centre_y, radius, z, n):
    """n CL points along a circular arc about (30, centre_y), from −35° to 35° of its top."""
    angle = np.radians(np.linspace(-35.0, 35.0, n))
    return np.stack([30.0 + radius * np.sin(angle), centre_y + radius * np.cos(angle), np.full(n, z)], axis=1)


def test_dense_curved_passes_side_by_side(monkeypatch):
    """Two curved passes 0.25 mm between CL points, 4 mm apart, the first with a tilted tool:
    the second pass's lines lie over the first's pieces, each chain of them curved (slack)."""
    probes = []
    original = inprocess._probe

    def spy(*args):
        probes.append(1)
        return original(*args)

    monkeypatch.setattr(inprocess, "_probe", spy)
    program = Program()
    n = 145
    tilt = np.radians(8.0)
    axes = np.tile([0.0, np.sin(tilt), np.cos(tilt)], (n, 1))
    program.add_pass(arc(-20.0, 30.0, 3.0, n), 5.0, 12.0, axes)
    rows = program.add_pass(arc(-24.0, 30.0, 2.0, n), 5.0, 12.0)
    got, changed, _ = check(program, rows[[60, 100]], PHI, fixed=True)
    assert probes, "the dense path (chains, probes) was not taken"
    assert changed.all()


def test_dense_pass_beside_the_convex_side_of_an_arc():
    """A pass beside the outer, convex side of a tight arc (0.5 mm between CL points, radius
    20 mm): there the pieces bulge out of their chain's chord by up to about 0.15 mm, which
    the chain's slack must cover. The engine takes 40 CL points × 720 angles in one call, as a
    chunk of a real run; the lines within a degree of two places where lines leave the first
    pass's volume through that bulge are compared with the reference."""
    program = Program()
    n = 49
    program.add_pass(arc(-20.0, 20.0, 3.0, n), 5.0, 12.0)
    rows = program.add_pass(arc(-16.0, 20.0, 2.0, n), 5.0, 12.0)[5:45]
    d = program.as_dict()
    phi = np.arange(0.0, 180.0, 0.25)
    origins, directions = edge_lines(d, rows, phi, fixed=True)
    stock = inside_intervals(staircase(), origins, directions, 12.0)
    got, changed = inprocess_intervals(stock, program.moves(), rows, origins, directions, phi.size)
    assert changed.all()
    length = got.length.reshape(rows.size, phi.size)
    for row, at in ((1, 58.25), (20, 85.5)):
        near = np.flatnonzero(np.abs(phi - at) <= 1.0)
        lines = row * phi.size + near
        want = [sum(e - s for s, e in reference(origins[i], directions[i], 12.0, d, rows[row])) for i in lines]
        np.testing.assert_allclose(length[row, near], want, rtol=0, atol=AGREE)
