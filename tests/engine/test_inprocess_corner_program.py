"""Programs with bull-nose and ball-end mills against the in-process stock: engage_in_process and in_process_lengths
against the brute-force reference of test_inprocess_corner, on a staircase and a terraced stock, upright, tilted and
turning tool axes, r/R in {0, 0.1, 0.3, 0.5, 1} and several tool kinds in one program: length, lep_l, uep_l and
end_length within 1e-6 mm.

The reference knows the program as plain numbers: each cutting move of a constant axis is one solid (the tool swept
from its start to its end); a move whose axis turns is taken as the constant-axis pieces the engine sweeps it as
(their ends and axes read from SweptPieces: what is checked is that they are removed exactly; how close they come to
the turning tool is checked apart, at the sweep tolerance). An edge point is engaged when the stock's own reference
holds it and no solid of a move ending before its CL point does. A planted error (the earlier tools swept with the
wrong corner radius) must make the comparison fail.
"""

import dataclasses

import numpy as np
import pytest

from abm_workbench.engine import CutSettings, Tool, Toolpath
from abm_workbench.engine.inprocess import ProgramMoves, removal_intervals, subtract, swept_pieces
from abm_workbench.engine.profile import profile_intervals
from abm_workbench.engine.stocks import _CornerEdges, engage_in_process, engage_stock, in_process_lengths, \
    stock_intervals

from . import profile_reference as pref
from .test_inprocess_corner import batch_runs, in_swept, tool_distance
from .test_tool_profiles import STAIRCASE, STOCKS, TERRACED

TOL = 1e-6  # mm
RATIOS = (0.0, 0.1, 0.3, 0.5, 1.0)  # r / R of the tool whose edges are evaluated


class Program:
    """A program built pass by pass (each pass starts with a rapid to its first point), every row with its tool."""

    def __init__(self):
        self.columns = {name: [] for name in ("cl", "axis", "cutting", "radius", "flute", "corner")}

    def add(self, points, radius, flute, corner, axes=None, cutting=True):
        """Append a pass through points (n, 3) with a tool (radius, flute length, corner radius); axes (n, 3)
        (default +z); without `cutting`, each point is reached by a rapid. Returns its program rows."""
        n = len(points)
        axes = np.tile([0.0, 0.0, 1.0], (n, 1)) if axes is None else np.asarray(axes, dtype=float)
        axes = axes / np.linalg.norm(axes, axis=1)[:, None]
        first = len(self.columns["cl"])
        for i in range(n):
            for name, value in (("cl", points[i]), ("axis", axes[i]), ("cutting", cutting and i > 0), ("radius", radius),
                                ("flute", flute), ("corner", corner)):
                self.columns[name].append(value)
        return np.arange(first, first + n)

    def array(self, name):
        return np.array(self.columns[name], dtype=bool if name == "cutting" else float)

    def moves(self, corner_scale=1.0):
        n = len(self.columns["cl"])
        return ProgramMoves(self.array("cl"), self.array("axis"), self.array("cutting"), self.array("radius"),
                            self.array("flute"), np.arange(n) + 1, self.array("corner") * corner_scale)

    def solids(self, pieces=None):
        """(c0, move, axis, R, r, H, row) (Q, …) of every cutting move's solid; the moves whose axis turns as the
        pieces of `pieces` (SweptPieces) instead."""
        cl, axis, cutting = self.array("cl"), self.array("axis"), self.array("cutting")
        big, flute, corner = self.array("radius"), self.array("flute"), self.array("corner")
        rows = np.flatnonzero(cutting)
        still = np.all(axis[rows] == axis[rows - 1], axis=1)
        j = rows[still]
        out = [cl[j - 1], cl[j] - cl[j - 1], axis[j], big[j], corner[j], flute[j], j]
        turning = rows[~still]
        if turning.size:
            assert pieces is not None, "a program whose axis turns needs the engine's pieces"
            keep = np.isin(pieces.move, turning)
            row = pieces.move[keep]
            more = [pieces.c0[keep], pieces.c1[keep] - pieces.c0[keep], pieces.axis[keep], big[row], corner[row],
                    flute[row], row]
            out = [np.concatenate([a, b]) for a, b in zip(out, more)]
        return out


#: Off the stocks' walls, loops and levels by an odd offset: an edge starting on a boundary to within rounding may
#: be in or out (the stock's own engine decides it from the edge's first point), as test_tool_profiles avoids too.
ODD = np.array([0.0123457, 0.0213579, 0.0372941])


def straight(x0, x1, y, z, n):
    """n CL points from (x0, y, z) to (x1, y, z), moved by ODD."""
    return np.stack([np.linspace(x0, x1, n), np.full(n, y), np.full(n, z)], axis=1) + ODD


def engine_ends(stock, tool, toolpath, phi, pieces, rows):
    """The engine's run ends per instant (s along the peripheral edge, t along the end edge), only as extra sample
    positions for the reference."""
    edges = _CornerEdges(tool, toolpath, phi) if tool.corner_radius > 0 else None
    m, p = len(toolpath), phi.size
    ends = {"peripheral": [[] for _ in range(m * p)], "end": [[] for _ in range(m * p)]}
    if edges is not None:
        inside = profile_intervals(stock, tool, toolpath, phi)
        first = np.flatnonzero(np.r_[True, inside.rows[1:] != inside.rows[:-1]]) if inside.rows.size else inside.rows
        last = np.r_[first[1:], inside.rows.size] - 1
        got = subtract(inside, *edges.removals(pieces, rows, inside.rows[first], inside.start[first],
                                               inside.end[last]))
        for r, a, b in zip(got.rows, got.start, got.end):
            ends["peripheral"][r] += [a, b]
    reach = tool.radius - tool.corner_radius
    if reach > 0:
        frames = toolpath.frames()
        rad = np.radians(phi)
        d = (np.sin(rad)[None, :, None] * frames[:, None, :, 0] + np.cos(rad)[None, :, None] * frames[:, None, :, 1])
        tip = np.repeat(toolpath.cl, p, axis=0)
        inside = stock_intervals(stock, tip, d.reshape(-1, 3), reach)
        first = np.flatnonzero(np.r_[True, inside.rows[1:] != inside.rows[:-1]]) if inside.rows.size else inside.rows
        last = np.r_[first[1:], inside.rows.size] - 1
        got = subtract(inside, *removal_intervals(pieces, rows, inside.rows[first], inside.start[first],
                                                  inside.end[last], tip, d.reshape(-1, 3), p))
        for r, a, b in zip(got.rows, got.start, got.end):
            ends["end"][r] += [a, b]
    return ends


def reference(stock_name, tool, toolpath, rows, phi, solids, extra=None):
    """{field: (m, p)} of length, lep_l, uep_l (heights above the tip) and end_length by the reference."""
    _, inside, levels = STOCKS[stock_name]
    c0, move, axis, big, corner, flute, move_row = solids
    m, p = len(toolpath), phi.size
    big_t, corner_t, flute_t = tool.radius, tool.corner_radius, tool.flute_length
    tips, ds, ws, befores = [], [], [], []
    for i in range(m):
        frame = pref.frame(toolpath.theta_a[i], toolpath.theta_b[i], toolpath.alpha[i])
        for angle in np.radians(phi):
            ds.append(np.sin(angle) * frame[:, 0] + np.cos(angle) * frame[:, 1])
            ws.append(frame[:, 2])
            tips.append(toolpath.cl[i])
            befores.append(rows[i])
    tips, ds, ws, befores = (np.array(v) for v in (tips, ds, ws, befores))
    n = m * p
    span = pref.edge_span(big_t, corner_t, flute_t)
    reach = big_t - corner_t
    # Edge e < n: the peripheral edge of instant e; e ≥ n: the end edge of instant e − n.
    spans = np.concatenate([np.full(n, span), np.full(n, reach)])

    def points(edge, t):
        peripheral = edge < n
        k = np.where(peripheral, edge, edge - n)
        out = tips[k] + t[:, None] * ds[k]
        at = np.flatnonzero(peripheral)
        if at.size:
            kk = k[at]
            top = pref.corner_end(big_t, corner_t, flute_t)
            s = t[at]
            on_corner = s <= corner_t * top
            psi = np.where(on_corner, s / (corner_t if corner_t > 0 else 1.0), 0.0)
            radial = np.where(on_corner, big_t - corner_t + corner_t * np.sin(psi), big_t)
            up = np.where(on_corner, corner_t * (1.0 - np.cos(psi)), corner_t + s - corner_t * top)
            out[at] = tips[kk] + radial[:, None] * ds[kk] + up[:, None] * ws[kk]
        return out, k

    centre = c0 + 0.5 * move + 0.5 * flute[:, None] * axis
    bound = 0.5 * np.linalg.norm(move, axis=1) + np.hypot(big, 0.5 * flute) + 1e-6
    still = np.all(move == 0.0, axis=1)

    def flag(edge, t):
        x, k = points(edge, t)
        engaged = inside(x)
        at = np.flatnonzero(engaged)
        removed = np.zeros(at.size, dtype=bool)
        for first in range(0, len(c0), 64):
            block = slice(first, first + 64)
            near = (np.linalg.norm(x[at, None, :] - centre[None, block], axis=2) <= bound[None, block]) & \
                (move_row[None, block] <= befores[k[at]][:, None] - 1) & ~removed[:, None]
            pt, q = np.nonzero(near)
            q = q + first
            fixed = still[q]
            hit = np.zeros(pt.size, dtype=bool)
            # A tool standing still (a position of the turning tool): the point-in-tool test alone.
            hit[fixed] = tool_distance(x[at][pt[fixed]] - c0[q[fixed]], axis[q[fixed]], big[q[fixed]],
                                       corner[q[fixed]], flute[q[fixed]]) <= 0.0
            swept = ~fixed
            hit[swept] = in_swept(x[at][pt[swept]], c0[q[swept]], move[q[swept]], axis[q[swept]], big[q[swept]],
                                  corner[q[swept]], flute[q[swept]])
            np.logical_or.at(removed, pt[hit], True)
        engaged[at[removed]] = False
        return engaged

    # Extra samples where the edges meet the stock's levels, and at the engine's ends.
    more = []
    for e in range(2 * n):
        k = e % n
        if e < n:
            hits = pref.level_hits(levels, tips[k][2], lambda s: points(np.full(s.size, e), s)[0][:, 2], span)
        else:
            hits = pref.level_hits(levels, tips[k][2], lambda s: tips[k][2] + s * ds[k][2], reach) if reach > 0 else []
        if extra is not None:
            own = extra["peripheral" if e < n else "end"][k]
            hits = list(hits) + [v + x for v in own for x in (-1e-8, 0.0, 1e-8)]
        more.append(hits)
    found = batch_runs(flag, spans, more, samples=1201)
    out = {name: np.full(n, np.nan) for name in ("length", "lep_l", "uep_l", "end_length")}
    for k in range(n):
        runs = found[k]
        out["length"][k] = sum(b - a for a, b in runs)
        if runs:
            out["lep_l"][k] = pref.height(runs[0][0], big_t, corner_t, flute_t)
            out["uep_l"][k] = pref.height(runs[-1][1], big_t, corner_t, flute_t)
        out["end_length"][k] = sum(b - a for a, b in found[n + k]) if reach > 0 else 0.0
    return {name: values.reshape(m, p) for name, values in out.items()}


def mismatches(engagement, want, tol=TOL, fields=("length", "lep_l", "uep_l", "end_length")):
    """[(CL, φ index, field, engine, reference)] where they differ by more than tol."""
    bad = []
    for name in fields:
        got, ref = getattr(engagement, name), want[name]
        same = (np.isnan(got) & np.isnan(ref)) | (np.abs(got - ref) <= tol)
        if name in ("lep_l", "uep_l"):  # a sliver below tol may be seen by one side only
            same |= (want["length"] <= tol) & (engagement.length <= tol)
        for i, k in zip(*np.nonzero(~same)):
            bad.append((int(i), int(k), name, float(got[i, k]), float(ref[i, k])))
    return bad


def run(program, stock_name, tool, toolpath, rows, phi, tolerance=0.05, pieces=None):
    """(engine Engagement, changed, reference fields, pieces) for the CL points of toolpath (program rows `rows`)."""
    stock = STOCKS[stock_name][0]
    pieces = swept_pieces(program.moves(), tolerance) if pieces is None else pieces
    settings = CutSettings(0.1, phi_start=float(phi[0]), phi_end=float(phi[-1]), phi_step=float(phi[1] - phi[0]))
    got, initial, changed = engage_in_process(stock, tool, toolpath, settings, pieces, rows)
    want = reference(stock_name, tool, toolpath, rows, settings.phi, program.solids(pieces),
                     engine_ends(stock, tool, toolpath, settings.phi, pieces, rows))
    return got, changed, want, pieces, settings


PHI = np.arange(0.0, 360.0, 30.0)


def two_passes(ratio):
    """A D10 R2 pass, then one beside it (4.5 mm over, 0.5 mm lower) with a D8 tool of corner radius ratio·R,
    across the staircase's walls."""
    program = Program()
    program.add(straight(-16, 16, -3.0, 3.0, 9), 5.0, 15.0, 2.0)
    tool = Tool(8.0, 2, 12.0, corner_radius=4.0 * ratio)
    rows = program.add(straight(-16, 16, 1.5, 2.5, 9), tool.radius, tool.flute_length, tool.corner_radius)
    return program, tool, rows


@pytest.mark.parametrize("ratio", RATIOS)
def test_second_pass_beside_a_bull_nose_pass_on_the_staircase(ratio):
    program, tool, rows = two_passes(ratio)
    pick = [2, 4, 6]
    toolpath = Toolpath(program.array("cl")[rows[pick]], np.zeros(3), np.zeros(3))
    got, changed, want, _, _ = run(program, "staircase", tool, toolpath, rows[pick], PHI)
    assert changed.all()
    # A flat-end mill's end_length against the in-process stock is not computed (docs/ENGINE.md).
    assert not mismatches(got, want, fields=("length", "lep_l", "uep_l") + (("end_length",) if ratio else ()))
    assert (got.length < engage_stock(STAIRCASE, tool, toolpath, CutSettings(0.1, 0.0, 0.0, 330.0, 30.0)).length
            - 1e-3).any()


def mixed_program(tilt):
    """A D32 R5 roughing pass, a D20 flat-end pass and a D10 ball-end pass across the terraced stock (one program,
    three tool kinds), the last tool's axis tilted by `tilt` degrees across the feed and 10° along it."""
    program = Program()
    program.add(straight(-14, 14, -6.0, 7.0, 8), 16.0, 25.0, 5.0)
    program.add(straight(14, -14, 8.0, 8.0, 8), 10.0, 20.0, 0.0)
    lean, along = np.radians(tilt), np.radians(10.0)
    axis = np.array([np.sin(along), -np.sin(lean) * np.cos(along), np.cos(lean) * np.cos(along)])
    tool = Tool(10.0, 2, 15.0, corner_radius=5.0)
    rows = program.add(straight(-14, 14, 1.0, 4.0, 8), tool.radius, tool.flute_length, tool.corner_radius,
                       np.tile(axis, (8, 1)))
    return program, tool, rows, axis


@pytest.mark.parametrize("tilt", [0.0, 25.0])
def test_mixed_tool_kinds_on_the_terraced_stock(tilt):
    program, tool, rows, axis = mixed_program(tilt)
    pick = [1, 3, 5]
    toolpath = Toolpath.from_axes(program.array("cl")[rows[pick]], np.tile(axis, (3, 1)))
    got, changed, want, _, _ = run(program, "terraced", tool, toolpath, rows[pick], PHI)
    assert changed.any()
    assert not mismatches(got, want)


def turning_program():
    """A bull-nose pass whose axis leans from 0° to 20° along it, then a ball-end pass beside it leaning across."""
    program = Program()
    n = 7
    lean = np.radians(np.linspace(0, 20, n))
    program.add(straight(-12, 12, -2.5, 6.0, n), 5.0, 12.0, 1.5, np.stack([np.sin(lean), 0 * lean, np.cos(lean)], 1))
    tilt = np.radians(np.linspace(-10, 10, n))
    axes = np.stack([0 * tilt, np.sin(tilt), np.cos(tilt)], axis=1)
    tool = Tool(8.0, 2, 12.0, corner_radius=4.0)
    rows = program.add(straight(-12, 12, 3.0, 5.0, n), tool.radius, tool.flute_length, tool.corner_radius, axes)
    return program, tool, rows, axes


def test_turning_axes_remove_their_pieces_exactly():
    """Moves whose axis turns: the engine's constant-axis pieces are removed exactly (the reference takes the same
    pieces)."""
    program, tool, rows, axes = turning_program()
    pick = [2, 4]
    toolpath = Toolpath.from_axes(program.array("cl")[rows[pick]], axes[pick])
    got, changed, want, pieces, _ = run(program, "staircase", tool, toolpath, rows[pick], PHI, tolerance=0.05)
    assert (pieces.span_count > 1).any() or pieces.c0.shape[0] > len(rows)
    assert changed.any()
    assert not mismatches(got, want)


def test_turning_axes_against_the_turning_tool():
    """The same against the tool turning as the program says (standing at 201 positions per move): within the
    sweep tolerance's bound on lines that do not graze (here 0.01 mm at a tolerance of 0.002 mm)."""
    program, tool, rows, axes = turning_program()
    pick = [3]
    toolpath = Toolpath.from_axes(program.array("cl")[rows[pick]], axes[pick])
    pieces = swept_pieces(program.moves(), 0.002)
    settings = CutSettings(0.1, 0.0, 0.0, 300.0, 60.0)
    got, _, _ = engage_in_process(STAIRCASE, tool, toolpath, settings, pieces, rows[pick])
    # The true motion: the interpolated tool standing at 201 positions per move (the material between two
    # positions, at most (step)²/(8·r) thick, is far below the tolerance).
    cl, axis = program.array("cl"), program.array("axis")
    big, flute, corner = program.array("radius"), program.array("flute"), program.array("corner")
    parts = []
    for j in np.flatnonzero(program.array("cutting")):
        t = np.linspace(0.0, 1.0, 201)
        centres = cl[j - 1] + t[:, None] * (cl[j] - cl[j - 1])
        w = (1 - t)[:, None] * axis[j - 1] + t[:, None] * axis[j]
        w /= np.linalg.norm(w, axis=1)[:, None]
        parts.append((centres, np.zeros_like(centres), w, np.full(t.size, big[j]), np.full(t.size, corner[j]),
                      np.full(t.size, flute[j]), np.full(t.size, j)))
    solids = [np.concatenate(column) for column in zip(*parts)]
    want = reference("staircase", tool, toolpath, rows[pick], settings.phi, solids)
    assert not mismatches(got, want, tol=0.01)


def test_in_process_lengths_are_the_engagements():
    """in_process_lengths gives engage_in_process's lengths (bit for bit), at any angles."""
    program, tool, rows, axis = mixed_program(25.0)
    toolpath = Toolpath.from_axes(program.array("cl")[rows], np.tile(axis, (len(rows), 1)))
    pieces = swept_pieces(program.moves())
    settings = CutSettings(0.1, 0.0, 0.0, 350.0, 10.0)
    got, _, _ = engage_in_process(TERRACED, tool, toolpath, settings, pieces, rows)
    lengths = in_process_lengths(TERRACED, tool, toolpath, settings.phi, pieces, rows)
    np.testing.assert_array_equal(lengths, got.length)


def test_untouched_points_keep_the_stocks_engagement():
    """CL points that earlier moves leave alone report engage_stock's Engagement, field by field; changed ones keep
    case "corner" and label the ends made by a removal "machined"."""
    program = Program()
    program.add(straight(-16, -4, -4.0, 3.0, 5), 5.0, 15.0, 2.0)
    tool = Tool(8.0, 2, 12.0, corner_radius=1.5)
    # Each evaluated CL point reached by a rapid: only the first pass can have removed material there.
    rows = program.add(straight(-16, 16, 0.5, 2.5, 9), tool.radius, tool.flute_length, tool.corner_radius,
                       cutting=False)
    toolpath = Toolpath(program.array("cl")[rows], np.zeros(9), np.zeros(9))
    settings = CutSettings(0.1, 0.0, 0.0, 350.0, 10.0)
    got, initial, changed = engage_in_process(STAIRCASE, tool, toolpath, settings, swept_pieces(program.moves()), rows)
    stock = engage_stock(STAIRCASE, tool, toolpath, settings)
    assert changed[:3].any() and not changed[-3:].any()
    np.testing.assert_array_equal(initial, stock.length)
    for field in dataclasses.fields(got):
        values, expected = getattr(got, field.name), getattr(stock, field.name)
        if field.name in ("phi", "h"):
            np.testing.assert_array_equal(values, expected)
        else:
            np.testing.assert_array_equal(values[~changed], expected[~changed], err_msg=field.name)
    assert set(got.case_names()[got.engaged].ravel()) == {"corner"}
    from abm_workbench.engine.engagement import SURFACES
    assert (got.lep_surface[changed] == SURFACES.index("machined")).any() or \
        (got.uep_surface[changed] == SURFACES.index("machined")).any()


def test_a_wrong_corner_radius_fails_the_comparison():
    """Planted error: the earlier tools swept with half their corner radius (more material removed near their
    corners) must make the comparison with the reference fail."""
    program, tool, rows = two_passes(0.3)
    pick = [2, 4, 6]
    toolpath = Toolpath(program.array("cl")[rows[pick]], np.zeros(3), np.zeros(3))
    wrong = swept_pieces(program.moves(corner_scale=0.5))
    got, _, want, _, _ = run(program, "staircase", tool, toolpath, rows[pick], PHI, pieces=wrong)
    assert mismatches(got, want)


def test_flat_end_programs_keep_their_bits():
    """Without corner radii (None) and with zeros, the swept pieces and the in-process results are the same bits."""
    program, _, rows = two_passes(0.0)
    program.columns["corner"] = [0.0] * len(program.columns["corner"])
    moves = program.moves()
    plain = ProgramMoves(moves.cl, moves.axis, moves.cutting, moves.radius, moves.flute_length, moves.line)
    a, b = swept_pieces(moves), swept_pieces(plain)
    for field in dataclasses.fields(a):
        if field.name != "tree":
            np.testing.assert_array_equal(getattr(a, field.name), getattr(b, field.name), err_msg=field.name)
    tool = Tool(8.0, 2, 12.0)
    toolpath = Toolpath(moves.cl[rows], np.zeros(rows.size), np.zeros(rows.size))
    settings = CutSettings(0.1, 0.0, 0.0, 180.0, 5.0)
    one, two = (engage_in_process(STAIRCASE, tool, toolpath, settings, pieces, rows)[0] for pieces in (a, b))
    for field in dataclasses.fields(one):
        np.testing.assert_array_equal(getattr(one, field.name), getattr(two, field.name), err_msg=field.name)


def test_corner_radius_errors_name_the_row():
    with pytest.raises(ValueError, match=r"row 1 \(line 12\): corner_radius"):
        ProgramMoves(np.zeros((2, 3)), [[0, 0, 1]] * 2, [False, True], [3, 3], [10, 10], [11, 12], [0.0, 3.5])
    with pytest.raises(ValueError, match=r"row 0 \(line 11\): corner_radius"):
        ProgramMoves(np.zeros((2, 3)), [[0, 0, 1]] * 2, [False, True], [3, 3], [10, 10], [11, 12], [-1.0, 0.0])
    with pytest.raises(ValueError, match="corner_radius"):
        ProgramMoves(np.zeros((2, 3)), [[0, 0, 1]] * 2, [False, True], [3, 3], [10, 10], [11, 12], [0.0])


def test_forces_take_the_in_process_runs():
    """jobs.run.pass_forces_of against the in-process stock with a tool with a corner: every flute's runs are
    in_process_runs (flute 1's lengths are engage_in_process's, checked against the reference above); CL points
    no earlier move touched keep the forces against the stock as given, changed ones lose some."""
    from abm_workbench.forces import material, pass_forces
    from abm_workbench.jobs.run import pass_forces_of
    from abm_workbench.engine.stocks import in_process_runs

    program = Program()
    program.add(straight(-16, -4, -4.0, 3.0, 5), 5.0, 15.0, 2.0)
    tool = Tool(8.0, 3, 12.0, corner_radius=2.0)
    # Each CL point reached by a rapid: only the first pass can have removed material there.
    rows = program.add(straight(-16, 16, 0.5, 2.5, 9), tool.radius, tool.flute_length, tool.corner_radius,
                       cutting=False)
    toolpath = Toolpath(program.array("cl")[rows], np.zeros(rows.size), np.zeros(rows.size))
    pieces = swept_pieces(program.moves())
    settings = CutSettings(0.1, 0.0, 0.0, 355.0, 5.0)
    got, _, changed = engage_in_process(STAIRCASE, tool, toolpath, settings, pieces, rows)
    runs = in_process_runs(STAIRCASE, tool, toolpath, settings.phi, pieces, rows)
    np.testing.assert_array_equal(runs.length.reshape(got.length.shape), got.length)
    model = (material("al7075-t6"), (0.0, 180.0))
    inside = pass_forces_of(STAIRCASE, tool, toolpath, settings, model, got, in_process=(pieces, rows))
    given = pass_forces(STAIRCASE, tool, toolpath, settings, model[0], immersion=model[1])
    assert changed.any() and not changed.all()
    np.testing.assert_array_equal(inside.cutting[~changed], given.cutting[~changed])
    assert (np.abs(inside.cutting[changed] - given.cutting[changed]).max(axis=(1, 2)) > 1e-6).all()
