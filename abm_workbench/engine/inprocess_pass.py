"""A pass against the in-process stock that solves its edge lines in the stock once.

stocks.engage_in_process needs two things of the stock as given: its Engagement (Table 1 cases,
the end edge's lengths) for the CL points no earlier move reaches, and the inside intervals of
the edge lines of the others, from which the removals are subtracted. Found separately, every
edge line of the pass was solved in the stock twice (engage, then inside_intervals for the CL
points with a removal) and the end edge's lines once more for CL points whose end length is then
dropped (an in-process CL point has none). The staircase engine's solver gives both from one
solve (engagement._solve_lines with its intervals: the same lines, the same arithmetic, so the
per-instant values are those engage gives and the intervals those inside_intervals gives, bit for
bit); the end edge is solved only for the CL points that keep the stock's Engagement.

Here: a Staircase, a flat-end tool with straight flutes, every tool axis rising (w_z ≥ 0), the
cases engage itself solves in one piece; stocks.engage_in_process takes the general path for the
others. Lengths in mm.
"""

import dataclasses

import numpy as np

from .engagement import _edge_components, _solve_lines, edge_lines, empty_results, finished_engagement
from .intervals import EdgeIntervals
from .model import Staircase
from .profile import end_lengths


def shared(stock, tool, toolpath):
    """Whether `shared_solve` applies: a Staircase, a flat-end tool with straight flutes, no
    tool axis pointing down."""
    return (isinstance(stock, Staircase) and tool.corner_radius == 0.0 and tool.helix == 0.0
            and not (toolpath.axes[:, 2] < 0.0).any())


def shared_solve(stock, tool, toolpath, settings):
    """The pass's edge lines solved in the stock once: (out, lep_xyz, uep_xyz, intervals, base,
    direction). out: the per-instant arrays (m, p) engagement.engage fills; lep_xyz, uep_xyz (m, p, 3);
    intervals: EdgeIntervals of the m·p lines (row i·p + k); base (m, p, 3), direction (m, 3): the
    lines (engagement.edge_lines)."""
    phi = settings.phi
    m, p = len(toolpath), phi.size
    out, lep_xyz, uep_xyz = empty_results(m, p)
    base, direction = edge_lines(toolpath, tool, phi)
    solved = _solve_lines(stock, tool.flute_length, *_edge_components(base, direction), intervals=True)
    intervals = solved.pop("intervals")
    for name in out:
        out[name][:] = solved[name].reshape(m, p)
    lep_xyz[:] = base + solved["lep_l"].reshape(m, p, 1) * direction[:, None, :]
    uep_xyz[:] = base + solved["uep_l"].reshape(m, p, 1) * direction[:, None, :]
    return out, lep_xyz, uep_xyz, intervals, base, direction


def stock_engagement(solve, stock, tool, toolpath, settings, keep):
    """The stock's Engagement (as stocks.engage_stock gives it) of the pass from `solve`
    (shared_solve's result), with the end edge's lengths at the CL points `keep` (int array) only,
    NaN elsewhere (those CL points take the in-process Engagement)."""
    out, lep_xyz, uep_xyz = solve[:3]
    found = finished_engagement(settings.phi, settings, out, lep_xyz, uep_xyz, toolpath.inclinations(settings))
    end = np.full(out["length"].shape, np.nan)
    if keep.size:
        end[keep] = end_lengths(stock, tool, toolpath.rows(keep), settings.phi)
    return dataclasses.replace(found, end_length=end)


def cl_rows(intervals: EdgeIntervals, cl, p):
    """The intervals of the lines of CL points `cl` (ascending int array) of p angles each,
    renumbered i·p + k by the rank i of the CL point among them."""
    rank = np.full(intervals.n_rows // p, -1, dtype=np.intp)
    rank[cl] = np.arange(cl.size)
    owner = rank[intervals.rows // p]
    keep = np.flatnonzero(owner >= 0)
    rows = owner[keep] * p + intervals.rows[keep] % p
    fields = {f.name: getattr(intervals, f.name)[keep] for f in dataclasses.fields(intervals)
              if f.name not in ("n_rows", "rows")}
    return EdgeIntervals(cl.size * p, rows, **fields)
