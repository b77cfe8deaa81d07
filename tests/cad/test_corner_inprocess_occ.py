"""validate against the in-process stock for bull-nose and ball-end mills (cad.corner_sweep, cad.corner_inprocess).

The swept solids are checked on their own first: point membership against a brute-force sampler of the tool
along the move (the tool's inside test written here from its definition), volumes against Cavalieri's and
Steiner's formulas. Then the engine's in-process results (engage_in_process: length, LEP, UEP, end edge)
against the OpenCASCADE reference at every CL point of a pass whose earlier passes removed material from its
edges: on the staircase and the terraced stock, vertical, tilted and turning axes, r/R 0.1 to 1, within
AGREE; a planted error in the earlier moves' swept solids shows. A bull-nose mill's shallow ramps, which get
no solids, are decided by the exact inside test (cad.sweep_membership), itself checked against the sampler,
and a planted error in it shows.
"""

import csv
import dataclasses

import numpy as np
import pytest

from abm_workbench.cad import corner_inprocess, corner_sweep
from abm_workbench.cad.boolean import _inside_intervals
from abm_workbench.cad.corner_inprocess import corner_lengths_in_process
from abm_workbench.cad.corner_sweep import NotExactError, SweptParts, sweep_parts
from abm_workbench.cad.inprocess_boolean import BOX_SLACK, ProgramSweep
from abm_workbench.cad.profile_boolean import _edge_length
from abm_workbench.cad.profile_edges import EdgeGeometry
from abm_workbench.cad.sweep_membership import edge_points, exact_intervals
from abm_workbench.cad.solids import staircase_solid
from abm_workbench.engine import CutSettings, Tool, Toolpath
from abm_workbench.engine.inprocess import ProgramMoves, swept_pieces
from abm_workbench.engine.stocks import engage_in_process
from abm_workbench.validation import validate
from tests.engine.test_inprocess import staircase

from .profile_cases import stocks, validate_two_passes

AGREE = 1e-6  # mm: both sides are exact
SETTINGS = CutSettings(0.1, phi_start=2.5, phi_end=357.5, phi_step=15.0)
RADIUS, FLUTE = 5.0, 12.0


# ---- the swept solids on their own ------------------------------------------------------------------

def inside_tool(q, w, radius, corner, height):
    """(n,) the tool's gauge at points q (n, 3) relative to its tip's centre (unit axis w): the largest of
    the distance to the half-infinite cylinder {a ≥ r, |b| ≤ R − r} less r, and a − H; 1-Lipschitz, ≤ 0
    exactly inside the tool."""
    a = q @ w
    b = np.linalg.norm(q - a[:, None] * w, axis=1)
    gap = np.hypot(np.maximum(corner - a, 0.0), np.maximum(b - (radius - corner), 0.0))
    return np.maximum(gap - corner, a - height)


def sampled_sweep(points, c0, m, w, radius, corner, height, steps=2001):
    """(n,) the least gauge over `steps` tool positions c0 + t·m, 0 ≤ t ≤ 1 (a test reference only): within
    |m| / (2 (steps − 1)) above the least over the whole move."""
    best = np.full(len(points), np.inf)
    for t in np.linspace(0.0, 1.0, steps):
        best = np.minimum(best, inside_tool(points - c0 - t * m, w, radius, corner, height))
    return best


#: The direction of the short segments through the test points (none of the solids' axes or moves).
PROBE = np.array([0.31, -0.52, 0.79]) / np.linalg.norm([0.31, -0.52, 0.79])


def occ_inside(swept: SweptParts, points, half=0.5):
    """(n,) bool: points (n, 3) in the swept volume by the solids, as the reference uses them: a segment of
    2·half mm through each point sectioned with each solid whose box meets the segment's (one boolean per
    solid), the point inside when its middle lies in a section. (OpenCASCADE's point classifier, which
    decides a segment crossing no face, misjudges points beside thin oblique extrusions outside their box:
    docs/VALIDATION.md; the reference, like this, never asks it there.)"""
    base = np.asarray(points) - half * PROBE
    ends = np.stack([base, base + 2.0 * half * PROBE])
    low, high = ends.min(axis=0) - BOX_SLACK, ends.max(axis=0) + BOX_SLACK

    def covered(solids):
        hit = np.zeros(len(base), dtype=bool)
        for solid in solids:
            box = solid.BoundBox
            meets = np.flatnonzero(((low <= [box.XMax, box.YMax, box.ZMax]) &
                                    (high >= [box.XMin, box.YMin, box.ZMin])).all(axis=1))
            for k, found in zip(meets, _inside_intervals(solid, base[meets], PROBE, 2.0 * half)):
                hit[k] |= any(a <= half <= b for a, b in found)
        return hit

    inside = covered(swept.union)
    return inside & covered(swept.column) if swept.column is not None else inside


MOVES = {  # (unit axis, move) mm
    "across": (np.array([0.0, 0.0, 1.0]), np.array([7.0, 2.0, 0.0])),
    "across, tilted": (np.array([0.3, -0.2, 1.0]) / np.linalg.norm([0.3, -0.2, 1.0]),
                       np.cross([0.3, -0.2, 1.0], [1.0, 0.0, 0.0]) / np.linalg.norm([0.3, -0.2, 1.0]) * 6.0),
    "along": (np.array([0.0, 0.0, 1.0]), np.array([0.0, 0.0, -4.0])),
    "ramp": (np.array([0.1, 0.2, 1.0]) / np.linalg.norm([0.1, 0.2, 1.0]), np.array([6.0, -2.0, 3.0])),
    "falling ramp": (np.array([0.0, 0.0, 1.0]), np.array([4.0, 3.0, -0.6])),
    "steep ramp": (np.array([0.0, 0.0, 1.0]), np.array([0.05, 0.0, -6.0])),
    "flat ramp": (np.array([0.0, 0.0, 1.0]), np.array([6.0, 0.0, 0.3])),
}


def membership_disagreements(swept, c0, w, m, radius, corner, height, count=300, seed=3):
    """(disagreements, decided): random points about the swept volume classified by its solids and by the
    sampler, those the sampler cannot decide (within its error, or within 1e-6 mm of the boundary) left out."""
    rng = np.random.default_rng(seed)
    ends = np.stack([c0, c0 + height * w, c0 + m, c0 + m + height * w])
    points = rng.uniform(ends.min(axis=0) - radius - 1.0, ends.max(axis=0) + radius + 1.0, (count, 3))
    gauge = sampled_sweep(points, c0, m, w, radius, corner, height)
    error = np.linalg.norm(m) / (2.0 * 2000)
    decided = (gauge < -1e-6) | (gauge > error + 1e-6)
    wrong = int((occ_inside(swept, points[decided]) != (gauge[decided] < 0.0)).sum())
    return wrong, int(decided.sum())


@pytest.mark.parametrize("ratio", [0.1, 0.5, 1.0])
@pytest.mark.parametrize("move", list(MOVES))
def test_the_swept_solids_hold_the_points_the_sampler_finds(move, ratio):
    w, m = MOVES[move]
    c0 = np.array([1.0, -2.0, 0.5])
    corner = ratio * RADIUS
    if move == "flat ramp" and ratio < 1.0:  # no solids: the exact inside test decides (test_the_exact_inside_test…)
        assert corner_sweep.move_kind(c0, c0 + m, w, RADIUS, corner, FLUTE) == "gauge"
        with pytest.raises(NotExactError, match="has no exact solids here"):
            sweep_parts(c0, c0 + m, w, RADIUS, corner, FLUTE)
        return
    swept = sweep_parts(c0, c0 + m, w, RADIUS, corner, FLUTE)
    assert all(solid.isValid() for solid in swept.union + (swept.column or []))
    wrong, decided = membership_disagreements(swept, c0, w, m, RADIUS, corner, FLUTE)
    assert decided >= 250 and wrong == 0


def test_a_planted_error_in_a_swept_solid_shows():
    """The membership check fails on the swept solids of a tool with half the corner radius."""
    w, m = MOVES["across"]
    c0 = np.zeros(3)
    planted = sweep_parts(c0, c0 + m, w, RADIUS, 0.25 * RADIUS, FLUTE)
    wrong, _ = membership_disagreements(planted, c0, w, m, RADIUS, 0.5 * RADIUS, FLUTE, count=600)
    assert wrong > 0


def profile_area(radius, corner, height):
    """The tool's axial section (mm²): the rectangle 2R × H less the two corners' r² − πr²/4 (H ≥ r)."""
    return 2.0 * radius * height - 2.0 * (corner * corner - 0.25 * np.pi * corner * corner)


@pytest.mark.parametrize("ratio", [0.3, 1.0])
def test_swept_volumes_by_cavalieri_and_steiner(ratio):
    """Across the axis: V = V(tool) + |m|·(axial section); along it: V(tool) + |m|·πR² (the volume a convex
    body sweeps is its own plus the move's length times its shadow along the move). The ball's ramp: the
    parallelogram P (area A, perimeter s) grown by r has V = 2rA + (π/2) r² s + (4/3)π r³ (Steiner)."""
    corner = ratio * RADIUS
    c0 = np.zeros(3)
    tool = corner_sweep.placed_tool(c0, [0, 0, 1.0], RADIUS, corner, FLUTE).Volume
    for move, shadow in (("across", profile_area(RADIUS, corner, FLUTE)), ("along", np.pi * RADIUS ** 2)):
        w, m = MOVES[move]
        parts = sweep_parts(c0, c0 + m, w, RADIUS, corner, FLUTE).union
        fused = parts[0].multiFuse(parts[1:])
        np.testing.assert_allclose(fused.Volume, tool + np.linalg.norm(m) * shadow, rtol=1e-9)
    if ratio == 1.0:
        w, m = MOVES["ramp"]
        grown = sweep_parts(c0, c0 + m, w, RADIUS, corner, FLUTE).union
        side = FLUTE * w
        area, perimeter = np.linalg.norm(np.cross(side, m)), 2.0 * (FLUTE + np.linalg.norm(m))
        want = 2 * corner * area + 0.5 * np.pi * corner ** 2 * perimeter + 4.0 / 3.0 * np.pi * corner ** 3
        np.testing.assert_allclose(grown[0].multiFuse(grown[1:]).Volume, want, rtol=1e-9)


# ---- the engine against the reference -----------------------------------------------------------------

def terraced_passes():
    """Two passes over the pocket of the terraced stock (profile_cases.pocket_stock): along x, then back
    lower and beside it; each begins with a plunge along the axis."""
    return [[(-20.0, -2.0, 12.0), (-20.0, -2.0, 3.0), (0.0, -2.0, 3.0), (20.0, -2.0, 3.0)],
            [(20.0, 3.0, 12.0), (20.0, 3.0, 2.0), (0.0, 3.0, 2.0), (-20.0, 3.0, 2.0)]]


def staircase_passes():
    """Two passes over tests.engine.test_inprocess's staircase, as terraced_passes."""
    return [[(8.0, -3.0, 14.0), (8.0, -3.0, 3.0), (30.0, -3.0, 3.0), (52.0, -3.0, 3.0)],
            [(52.0, 4.0, 14.0), (52.0, 4.0, 2.0), (30.0, 4.0, 2.0), (8.0, 4.0, 2.0)]]


#: How much each move after the plunge rises (mm; the moves are 20 to 22 mm long) for the axes "ramp" (0.11 to
#: 0.12 mm per mm: OpenCASCADE's solids) and "shallow ramp" (0.009 to 0.01 per mm: the exact inside test).
RISE = {"ramp": 2.5, "shallow ramp": 0.2}


def program(stock_name, axes, corner):
    """(ProgramMoves, rows of the second pass): the stock's two passes; axes "vertical", "ramp" or "shallow
    ramp" (vertical, the moves after the plunge rising by RISE), "tilted" (fixed, the passes' moves across it
    and the plunges along it) or "turning" (the axis leaning more along each pass; each move a ramp in
    sub-steps)."""
    passes = [np.array(p) for p in (staircase_passes() if stock_name == "staircase" else terraced_passes())]
    cl, axis, cutting = [], [], []
    for points in passes:
        n = len(points)
        if axes in ("vertical", "ramp", "shallow ramp"):
            w = np.tile([0.0, 0.0, 1.0], (n, 1))
            if axes in RISE:
                points = points.copy()
                points[2:, 2] += RISE[axes] * np.arange(1, n - 1)
        elif axes == "tilted":
            w = np.tile(np.array([0.0, 0.3, 1.0]) / np.hypot(0.3, 1.0), (n, 1))
            # keep the moves across the axis: heights follow the tilt (z = z0 − 0.3 (y − y0) stays put, y fixed)
            points = points.copy()
            points[0] = points[1] + 10.0 * w[0]
        else:
            lean = np.linspace(0.0, 0.25, n)
            w = np.column_stack([lean, -0.5 * lean, np.ones(n)])
            w /= np.linalg.norm(w, axis=1)[:, None]
        cl += list(points)
        axis += list(w)
        cutting += [False] + [True] * (n - 1)
    n = len(cl)
    moves = ProgramMoves(np.array(cl), np.array(axis), np.array(cutting), np.full(n, RADIUS), np.full(n, FLUTE),
                         np.arange(n) + 1, np.full(n, corner))
    return moves, np.arange(len(passes[0]), n)


def compare_run(stock_name, axes, ratio, parts=sweep_parts):
    """(engine Engagement, initial lengths, changed, reference dict) of the second pass."""
    stock, solid = stocks()[stock_name] if stock_name == "terraced" else (staircase(), staircase_solid(staircase()))
    moves, rows = program(stock_name, axes, ratio * RADIUS)
    pieces = swept_pieces(moves, 0.01)
    tool = Tool(2.0 * RADIUS, 2, FLUTE, corner_radius=ratio * RADIUS)
    path = Toolpath.from_axes(moves.cl[rows], moves.axis[rows])
    engagement, initial, changed = engage_in_process(stock, tool, path, SETTINGS, pieces, rows)
    reference = corner_lengths_in_process(solid, tool, path, engagement.phi, ProgramSweep(pieces, rows, path),
                                          parts=parts)
    return engagement, initial, changed, reference


def assert_agree(engagement, reference, agree=AGREE):
    for name in ("length", "lep_l", "uep_l", "end_length"):
        got, want = getattr(engagement, name), reference[name]
        np.testing.assert_array_equal(np.isnan(got), np.isnan(want), err_msg=name)
        np.testing.assert_allclose(got, want, rtol=0, atol=agree, err_msg=name)


CASES = [(stock, "vertical", ratio) for stock in ("staircase", "terraced") for ratio in (0.1, 0.3, 0.5, 1.0)] + \
        [(stock, "tilted", ratio) for stock in ("staircase", "terraced") for ratio in (0.3, 1.0)] + \
        [(stock, "turning", 1.0) for stock in ("staircase", "terraced")] + \
        [(stock, "ramp", ratio) for stock in ("staircase", "terraced") for ratio in (0.1, 0.5, 1.0)] + \
        [(stock, "shallow ramp", ratio) for stock in ("staircase", "terraced") for ratio in (0.1, 0.5)] + \
        [("staircase", "turning", 0.3)]


@pytest.mark.parametrize("stock_name,axes,ratio", CASES)
def test_the_engine_agrees_with_the_in_process_reference(stock_name, axes, ratio):
    engagement, initial, changed, reference = compare_run(stock_name, axes, ratio)
    assert_agree(engagement, reference)
    removed = initial - reference["length"]
    assert changed.any() and removed.max() > 0.5 and reference["swept"].max() > 0  # earlier moves took material
    assert (reference["corner_length"] > 0.0).any()
    gauged = axes == "shallow ramp" or (axes == "turning" and ratio < 1.0)
    assert (reference["gauged"].max() > 0) == gauged and reference["undecided"].sum() == 0


@pytest.mark.parametrize("axes", ["vertical", "ramp"])
def test_a_planted_error_in_the_earlier_moves_shows(axes):
    """Half the corner radius in the earlier moves' swept solids: the reference no longer agrees."""
    def planted(c0, c1, axis, radius, corner, height):
        return sweep_parts(c0, c1, axis, radius, 0.5 * corner, height)

    engagement, _, _, reference = compare_run("staircase", axes, 0.5, planted)
    worst = np.nanmax(np.abs(engagement.length - reference["length"]))
    assert worst > 1e-3


def test_a_planted_error_in_the_exact_inside_test_shows(monkeypatch):
    """The exact inside test deciding the shallow ramps with half the corner radius: the reference no longer
    agrees (and with the true one it does: test_the_engine_agrees_with_the_in_process_reference)."""
    real = corner_inprocess.exact_intervals

    def planted(geometry, spans, piece):
        c0, c1, axis, radius, corner, height = piece
        return real(geometry, spans, (c0, c1, axis, radius, 0.5 * corner, height))

    monkeypatch.setattr(corner_inprocess, "exact_intervals", planted)
    engagement, _, _, reference = compare_run("staircase", "shallow ramp", 0.5)
    assert reference["gauged"].max() > 0
    assert np.nanmax(np.abs(engagement.length - reference["length"])) > 1e-3


@pytest.mark.parametrize("kind", ["arc", "side", "end"])
@pytest.mark.parametrize("slope", [0.0, 1e-6, 0.009, 0.5])
def test_the_exact_inside_test_against_the_sampler(kind, slope):
    """sweep_membership.exact_intervals against the sampler (the tool at 1,001 positions along the move,
    the edge at 2,001 points): the lengths inside agree within the sampler's resolution, for edges of a tool
    beside, above and through a bull-nose mill's moves (r/R 0.3), at 12 angles."""
    rng = np.random.default_rng(11)
    tool = Tool(2.0 * RADIUS, 2, FLUTE, corner_radius=0.3 * RADIUS)
    worst, inside = 0.0, 0.0
    for _ in range(4):
        c0 = rng.uniform(-3.0, 3.0, 3)
        m = np.array([8.0, rng.uniform(-3.0, 3.0), 0.0])
        m[2] = slope * np.linalg.norm(m[:2]) / np.sqrt(max(1.0 - slope * slope, 1e-12))
        piece = (c0, c0 + m, np.array([0.0, 0.0, 1.0]), RADIUS, tool.corner_radius, FLUTE)
        tip = c0 + 0.5 * m + rng.uniform([-6.0, -9.0, -1.0], [6.0, 9.0, 2.0])
        geometry = EdgeGeometry.of(tool, tip, corner_sweep.frame_of([0.1, -0.2, 1.0]), np.arange(0.0, 360.0, 30.0))
        spans = {(kind, k): [(0.0, _edge_length(geometry, kind))] for k in range(len(geometry.d))}
        found, undecided = exact_intervals(geometry, spans, piece)
        assert undecided == 0
        for (_, k), intervals in found.items():
            t = np.linspace(0.0, _edge_length(geometry, kind), 2001)
            points = edge_points(geometry, np.full(t.size, kind), np.full(t.size, k), t)
            sampled = sampled_sweep(points, c0, m, piece[2], RADIUS, tool.corner_radius, FLUTE, steps=1001) <= 0.0
            step = t[1] - t[0]
            length = sum(b - a for a, b in intervals)
            worst = max(worst, abs(length - sampled.sum() * step))
            inside += length
    assert inside > 1.0 and worst <= 4 * (_edge_length(geometry, kind) / 2000 + np.linalg.norm(m) / 2000)


def test_validate_a_bull_nose_against_the_in_process_stock():
    stock = staircase()
    moves, rows = program("staircase", "vertical", 0.3 * RADIUS)
    tool = Tool(2.0 * RADIUS, 2, FLUTE, corner_radius=0.3 * RADIUS)
    path = Toolpath.from_axes(moves.cl[rows], moves.axis[rows])
    result = validate(staircase_solid(stock), stock, tool, path, SETTINGS, sweep=(swept_pieces(moves, 0.01), rows))
    comparison = result.comparison
    assert result.in_process is not None and result.in_process.changed.any()
    assert np.nanmax(np.abs(comparison.difference)) <= AGREE
    assert np.nanmax(np.abs(comparison.end_difference)) <= AGREE
    assert (result.in_process.initial - comparison.l_ref).max() > 0.5




@pytest.mark.parametrize("corner", [1.5, 5.0])
def test_cli_validate_a_corner_tool_in_process(tmp_path, monkeypatch, capsys, corner):
    page = validate_two_passes(tmp_path, monkeypatch, capsys, corner)
    assert "in-process: the stock minus the volumes swept" in page and "<h2>In-process stock</h2>" in page
    with open(tmp_path / "report" / "comparison.csv", newline="") as file:
        table = list(csv.DictReader(file))
    initial, ref, abm = (np.array([float(row[name]) if row[name] not in ("", "nan") else np.nan for row in table])
                         for name in ("l_initial", "l_ref", "l_abm"))
    assert np.nanmax(np.abs(abm - ref)) <= AGREE and np.nanmax(initial - ref) > 0.5


def test_the_report_pictures_of_a_corner_tool_show_its_own_swept_volume():
    """inprocess_boolean.stock_heights (the report's pictures of the in-process stock) for a bull-nose mill's
    second pass: the top along vertical lines against the sampler (the stock's sections less every earlier
    move, the tool at 1,001 positions along each, z every 0.01 mm), within the sampling; swept as flat-end
    cylinders, as the pictures once were, the tops differ."""
    from abm_workbench.cad import inprocess_boolean

    ratio = 0.5
    solid = staircase_solid(staircase())
    moves, rows = program("staircase", "vertical", ratio * RADIUS)
    pieces = swept_pieces(moves, 0.01)
    tool = Tool(2.0 * RADIUS, 2, FLUTE, corner_radius=ratio * RADIUS)
    path = Toolpath.from_axes(moves.cl[rows], moves.axis[rows])
    flat = dataclasses.replace(pieces, corner=np.zeros_like(pieces.corner))
    up, z = np.array([0.0, 0.0, 1.0]), np.linspace(-1.0, 11.0, 1201)
    worst, moved = 0.0, 0.0
    for i in (1, 2):
        x, y, top = inprocess_boolean.stock_heights(solid, pieces, rows[i], tool, path, i, cells=5)
        _, _, top_flat = inprocess_boolean.stock_heights(solid, flat, rows[i], tool, path, i, cells=5)
        base = np.array([[x[b], y[a], z[0]] for a in range(5) for b in range(5)])
        for n, found in enumerate(_inside_intervals(solid, base, up, z[-1] - z[0])):
            column = np.column_stack([np.full(z.size, base[n, 0]), np.full(z.size, base[n, 1]), z])
            keep = np.zeros(z.size, dtype=bool)
            for start, end in found:
                keep |= (z - z[0] >= start) & (z - z[0] <= end)
            for k in np.flatnonzero(pieces.move < rows[i]):
                keep &= sampled_sweep(column, pieces.c0[k], pieces.c1[k] - pieces.c0[k], pieces.axis[k],
                                      pieces.radius[k], pieces.corner[k], pieces.height[k], steps=1001) > 0.0
            got, flat_got = top.ravel()[n], top_flat.ravel()[n]
            assert keep.any() != np.isnan(got)
            if keep.any():
                worst = max(worst, abs(z[keep].max() - got))
                moved = max(moved, np.inf if np.isnan(flat_got) else abs(flat_got - got))
    assert worst <= 0.011 and moved > 0.1


@pytest.mark.parametrize("axes,ratio,kind", [("vertical", 0.5, "across"), ("ramp", 1.0, "ball"),
                                             ("shallow ramp", 0.5, "gauge")])
def test_the_annotated_document_draws_a_corner_tools_swept_solids(axes, ratio, kind):
    """CL<i>_Removed of a bull-nose mill's pass: the exact solids of each earlier piece (a point beside a piece's
    middle, under the tool's corner, is outside them, inside the flat-end hull); the pieces without exact
    solids (nearly flat ramps) drawn as the flat-end hull, and the description says how many."""
    from abm_workbench.cad.annotate import annotated_document
    from abm_workbench.cad.freecad_env import FreeCAD
    from abm_workbench.cad.inprocess_boolean import _near_tool

    corner = ratio * RADIUS
    solid = staircase_solid(staircase())
    moves, rows = program("staircase", axes, corner)
    pieces = swept_pieces(moves, 0.01)
    tool = Tool(2.0 * RADIUS, 2, FLUTE, corner_radius=corner)
    path = Toolpath.from_axes(moves.cl[rows], moves.axis[rows])
    engagement, _, _ = engage_in_process(staircase(), tool, path, SETTINGS, pieces, rows)
    document, _ = annotated_document("CornerRemoved", solid, engagement, path, tool, cls=[2], intersections=[2],
                                     sweep=(pieces, rows))
    try:
        removed = document.getObject("CL002_Removed")
        chosen, _ = _near_tool(pieces, rows[2], tool, path, 2)
        k = next(k for k in chosen if corner_sweep.move_kind(pieces.c0[k], pieces.c1[k], pieces.axis[k], RADIUS,
                                                            corner, FLUTE) == kind)
        across = np.cross(pieces.c1[k] - pieces.c0[k], [0.0, 0.0, 1.0])
        across *= np.sign(across @ (pieces.c1[k] - path.cl[2])) / np.linalg.norm(across)  # away from the tool
        middle = 0.5 * (pieces.c0[k] + pieces.c1[k])
        beside = middle + (RADIUS - 0.2) * across + [0.0, 0.0, 0.1]  # in the flat hull, beside the corner
        inside = any(part.isInside(corner_sweep.V(*beside), 1e-9, True) for part in removed.Shape.Solids)
        if kind != "gauge":
            assert not inside and "drawn as the hull" not in removed.Description
        else:
            assert inside and "pieces of a tool with a corner" in removed.Description
    finally:
        FreeCAD.closeDocument(document.Name)


def test_the_in_process_stock_view_says_it_cuts_a_corner_tools_pieces_as_flat_end_hulls():
    """inprocess_boolean.cut_and_removed (the InProcessStock object's shape) cuts a bull-nose mill's pieces as the
    flat-end hulls that hold them and counts them, for the object to say so."""
    from abm_workbench.cad.inprocess_boolean import cut_and_removed, hulls_near

    solid = staircase_solid(staircase())
    moves, rows = program("staircase", "vertical", 0.5 * RADIUS)
    hulls = hulls_near((moves, swept_pieces(moves, 0.01)), int(rows[2]), None)
    cut, removed, outlined = cut_and_removed(solid, hulls)
    assert cut.isValid() and removed > 1.0 and outlined == len(hulls["radius"]) > 0
    flat = {name: value for name, value in hulls.items() if name != "corner"}
    assert cut_and_removed(solid, flat)[2] == 0
