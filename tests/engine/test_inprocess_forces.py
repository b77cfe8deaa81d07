"""Straight-flute forces against the in-process stock, from an independent reference.

The engine's forces (jobs.run.pass_forces_of with the program's swept pieces: every flute's
length of cut against the in-process stock) are compared with the force model applied to
lengths from the brute-force reference of test_inprocess (dense sampling of each edge line
against the stock and the earlier tool positions, refined by bisection).
"""

import numpy as np

from abm_workbench.engine import CutSettings, Tool, Toolpath
from abm_workbench.engine.inprocess import swept_pieces
from abm_workbench.engine.stocks import engage_in_process
from abm_workbench.forces import Coefficients, edge_forces, pass_forces
from abm_workbench.jobs import run
from abm_workbench.jobs.run import pass_forces_of

from .test_inprocess import AGREE, Program, edge_lines, reference, staircase, straight

COEFFICIENTS = Coefficients(ktc=2000.0, krc=800.0, kac=300.0, kte=20.0, kre=15.0, kae=5.0)
IMMERSION = (0.0, 180.0)


def test_forces_against_the_in_process_stock(monkeypatch):
    """Three flutes on the second of two overlapping passes: flute 1 at φ = 0 … 340°, the others
    at φ + 120° and φ + 240°, so that every flute cuts over part of the revolution."""
    program = Program()
    program.add_pass(straight(5, 55, -5.0, 2.5, 11), 5.0, 12.0)
    rows = program.add_pass(straight(5, 55, 1.0, 2.0, 11), 5.0, 12.0)[3:10:3]
    d = program.as_dict()
    tool = Tool(diameter=10.0, flutes=3, flute_length=12.0)
    settings = CutSettings(feed_per_tooth=0.08, inclination=0.0, phi_start=0.0, phi_end=340.0, phi_step=20.0)
    phi = settings.phi
    toolpath = Toolpath(d["cl"][rows], np.zeros(rows.size), np.zeros(rows.size))
    stock, in_process = staircase(), (swept_pieces(program.moves()), rows)
    engagement = engage_in_process(stock, tool, toolpath, settings, *in_process)[0]
    got = pass_forces_of(stock, tool, toolpath, settings, (COEFFICIENTS, IMMERSION), engagement,
                         in_process=in_process)

    # Reference lengths at the 18 angles; flute k sits at φ + 120·k, i.e. 6·k angles further on.
    origins, directions = edge_lines(d, rows, phi, fixed=True)
    lengths = np.array([sum(e - s for s, e in reference(origins[i], directions[i], 12.0, d, rows[i // phi.size]))
                        for i in range(len(origins))]).reshape(rows.size, phi.size)
    shift = phi.size // tool.flutes
    flutes = np.stack([np.roll(lengths, -shift * k, axis=1) for k in range(tool.flutes)])
    want = edge_forces(flutes, phi, np.repeat(np.eye(3)[None], rows.size, axis=0), tool.radius,
                       settings.inclination, settings.feed_per_tooth, COEFFICIENTS, immersion=IMMERSION)

    # Each flute's length within AGREE moves its force by at most AGREE times its force per mm.
    c = COEFFICIENTS
    per_mm = np.linalg.norm([c.ktc * settings.feed_per_tooth + c.kte, c.krc * settings.feed_per_tooth + c.kre,
                             c.kac * settings.feed_per_tooth + c.kae])
    bound = tool.flutes * AGREE * per_mm
    np.testing.assert_allclose(got.tool_frame, want.tool_frame, rtol=0, atol=bound)
    np.testing.assert_allclose(got.area, want.area, rtol=0, atol=tool.flutes * AGREE * settings.feed_per_tooth)
    # The first pass changed these forces: against the stock as given they differ.
    initial = pass_forces(stock, tool, toolpath, settings, COEFFICIENTS, immersion=IMMERSION)
    assert (np.abs(initial.tool_frame - want.tool_frame).max(axis=(1, 2)) > 10 * bound).all()
    # And the flutes other than the first do cut material the first pass left.
    assert (np.abs(flutes[1:] - flutes[0]).max() > 1.0) and want.resultant.max() > 0.0
    # schedule's path, chunk by chunk (one CL point each here), gives the same forces.
    monkeypatch.setattr(run, "CHUNK_INSTANTS", phi.size)
    engaged, chunked = run._in_process_forces(stock, tool, toolpath, settings, (COEFFICIENTS, IMMERSION), in_process,
                                              np.full(rows.size, settings.feed_per_tooth))
    assert engaged
    np.testing.assert_array_equal(chunked.tool_frame, got.tool_frame)
