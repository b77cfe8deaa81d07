"""Stocks and passes the profile-reference tests share: a staircase solid and a terraced (pocket and island)
solid, tools of every corner ratio, and seeded CL points with tilted, sideways and downward axes."""

import numpy as np

from abm_workbench.cad.solids import staircase_solid
from abm_workbench.cad.terraced_solids import terraced_solid
from abm_workbench.engine import Toolpath
from abm_workbench.engine.terraced_model import Loop, PlanArc, PlanLine, PlanSpline, Slab, TerracedStock

from .conftest import STOCKS

TOL = 1e-6  # mm
RATIOS = (0.0, 0.1, 0.3, 0.5, 1.0)  # r / R
#: (x, y) ranges where the CL points go and the height of the stock's top there (mm): each stock's features.
AREAS = {
    "staircase": [((20.0, 32.0), (-6.0, 6.0), 9.0), ((44.0, 56.0), (-6.0, 6.0), 6.0),
                  ((68.0, 80.0), (-6.0, 6.0), 12.0)],
    "terraced": [((-18.0, -10.0), (-8.0, 8.0), 7.0), ((-5.0, 9.0), (-5.0, 7.0), 4.0),
                 ((10.0, 20.0), (-12.0, 12.0), 7.0)],
}


def rounded_rectangle(centre, a, b, r):
    """The closed loop of a rectangle of half sizes a, b with corners of radius r: four lines, four arcs."""
    cx, cy = centre
    corners = [(cx + a - r, cy - b + r, -0.5 * np.pi), (cx + a - r, cy + b - r, 0.0),
               (cx - a + r, cy + b - r, 0.5 * np.pi), (cx - a + r, cy - b + r, np.pi)]
    curves = []
    for i, (x, y, start) in enumerate(corners):
        arc = PlanArc((x, y), r, start, 0.5 * np.pi)
        following = corners[(i + 1) % 4]
        nxt = PlanArc((following[0], following[1]), r, following[2], 0.5 * np.pi)
        curves += [arc, PlanLine(arc.end_points[1], nxt.end_points[0])]
    return Loop(tuple(curves))


def block(x0, y0, x1, y1):
    p = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    return Loop(tuple(PlanLine(p[i], p[(i + 1) % 4]) for i in range(4)))


def spline_island(centre, radius, count=9):
    """A closed cubic B-spline about `centre`, its control points on a wavy circle."""
    theta = np.linspace(0.0, 2.0 * np.pi, count, endpoint=False)
    radii = radius * (1.0 + 0.15 * np.cos(3.0 * theta))
    points = np.asarray(centre) + radii[:, None] * np.stack([np.cos(theta), np.sin(theta)], axis=1)
    control = np.vstack([points, points[:1]])
    knots = np.concatenate([[0, 0, 0], np.linspace(0, 1, len(control) - 2), [1, 1, 1]])
    return Loop((PlanSpline(3, knots, control),))


def pocket_stock():
    """A block x −30..30, y −25..25 from z −10, with a pocket (rounded rectangle, wider going up) from z 0,
    a round island in it up to z 4 and a spline-bounded island from 4 to 7 (mm)."""
    outer = block(-30.0, -25.0, 30.0, 25.0)
    return TerracedStock((
        Slab(-10.0, 0.0, (outer,)),
        Slab(0.0, 4.0, (outer, rounded_rectangle((0.0, 0.0), 14.0, 10.0, 4.0), Loop((PlanArc((2.0, 1.0), 4.0, 0.3,
                                                                                               2 * np.pi),)))),
        Slab(4.0, 7.0, (outer, rounded_rectangle((0.0, 0.0), 16.0, 12.0, 5.0), spline_island((2.5, 1.0), 2.6))),
    ))


def stocks():
    """{name: (engine stock, Part solid)}: "staircase" (tests/cad/conftest's ridge: curved and straight
    walls) and "terraced" (pocket_stock)."""
    ridge = STOCKS["ridge"]
    terraced = pocket_stock()
    return {"staircase": (ridge, staircase_solid(ridge)), "terraced": (terraced, terraced_solid(terraced))}


def axes_of(kind, rng, n):
    """(θ_A, θ_B, α) (n,) each, deg: "tilted" (up to 45° each way), "sideways" (axis within 20° of
    horizontal), "down" (axis pointing down, up to 70° from straight down)."""
    alpha = rng.uniform(-180.0, 180.0, n)
    if kind == "tilted":
        return rng.uniform(-45.0, 45.0, n), rng.uniform(-45.0, 45.0, n), alpha
    if kind == "sideways":
        side = rng.choice([-1.0, 1.0], n)
        return side * rng.uniform(70.0, 110.0, n), rng.uniform(-20.0, 20.0, n), alpha
    side = rng.choice([-1.0, 1.0], n)
    return side * rng.uniform(110.0, 180.0, n), rng.uniform(-40.0, 40.0, n), alpha


def seeded_pass(stock_name, kind, seed, n=6):
    """A Toolpath of n CL points over the stock's areas (tips from 3 mm below to 1.5 mm above the local
    top), axes of `kind`, all from the seed."""
    rng = np.random.default_rng(seed)
    areas = AREAS[stock_name]
    cl = []
    for i in range(n):
        (x0, x1), (y0, y1), top = areas[i % len(areas)]
        cl.append([rng.uniform(x0, x1), rng.uniform(y0, y1), top + rng.uniform(-3.0, 1.5)])
    theta_a, theta_b, alpha = axes_of(kind, rng, n)
    return Toolpath(np.array(cl), theta_a, theta_b, alpha=alpha)


def differences(engagement, reference):
    """{field: max |engine − reference|} over length, lep_l, uep_l, end_length, lep_xyz, uep_xyz (mm), after
    checking that both engage at the same instants with the same number of pieces (AssertionError)."""
    assert np.array_equal(engagement.pieces, reference["pieces"]), "pieces differ"
    worst = {}
    for name in ("length", "lep_l", "uep_l", "end_length", "lep_xyz", "uep_xyz"):
        a, b = np.asarray(getattr(engagement, name), dtype=float), np.asarray(reference[name], dtype=float)
        assert np.array_equal(np.isnan(a), np.isnan(b)), f"{name}: engaged at different instants"
        worst[name] = float(np.nanmax(np.abs(a - b), initial=0.0))
    return worst


#: Two passes of a D10 tool (corner radius {corner} mm, flute length 12) along x at y −3 and 4 over a part, as an
#: APT CL file: the second pass beside what the first removed (the in-process stock's validation tests).
TWO_PASSES_APT = """UNITS/MM
MULTAX/ON
CUTTER/10,{corner},0,0,0,0,40
CSI_SET_FLUTE_LENGTH/12
SPINDL/RPM,4000,CLW
RAPID
GOTO/8,-3,20,0,0,1
GOTO/8,-3,3,0,0,1
GOTO/30,-3,3,0,0,1
GOTO/52,-3,3,0,0,1
GOTO/52,-3,20,0,0,1
RAPID
GOTO/52,4,20,0,0,1
GOTO/52,4,2,0,0,1
GOTO/30,4,2,0,0,1
GOTO/8,4,2,0,0,1
GOTO/8,4,20,0,0,1
FINI
"""


def validate_two_passes(folder, monkeypatch, capsys, corner, stock_model="in-process", report="report"):
    """`validate --stock-model STOCK_MODEL` of TWO_PASSES_APT (corner radius `corner` mm) over the in-process tests'
    staircase, in `folder`; the report's index.html text (the report in folder/`report`)."""
    from abm_workbench import cli
    from abm_workbench.formats.staircase_json import dump_staircase
    from tests.engine.test_inprocess import staircase

    dump_staircase(staircase(), folder / "stock.json")
    (folder / "path.apt").write_text(TWO_PASSES_APT.format(corner=corner))
    monkeypatch.chdir(folder)
    status = cli.main(["validate", "--stock", "stock.json", "--toolpath", "path.apt", "--flutes", "2",
                       "--feed-per-tooth", "0.1", "--phi-step", "30", "--report", report, "--stock-model",
                       stock_model])
    _, err = capsys.readouterr()
    assert status == 0, err
    return (folder / report / "index.html").read_text(encoding="utf-8")
