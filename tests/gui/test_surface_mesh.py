"""The engaged surface as one mesh (gui.surface_mesh) and its vertex colours (gui.colouring), headless.

The references are built here instant by instant, with plain loops over the results and their
segments (``Engagement.segments``), independently of the mesh's vectorised bookkeeping.
"""

import os

import numpy as np
import pytest
from matplotlib import colormaps

from abm_workbench.cad.freecad_env import FreeCAD
from abm_workbench.features import create_engagement, create_stock, create_toolpath
from abm_workbench.gui.colouring import COLOUR_BY
from abm_workbench.gui.surface_mesh import coord_index, packed_rgba, surface_mesh, vertex_colours
from abm_workbench.report.colours import SURFACE_COLOURS
from tests.conftest import ROOT

MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")


@pytest.fixture(scope="module")
def engagement():
    """Model test 1 (JSON stock, φ step 5°, forces on) as a document object, recomputed."""
    doc = FreeCAD.newDocument("ABMMesh")
    stock = create_stock(doc, os.path.join(MODEL, "stock.json"))
    toolpath = create_toolpath(doc, os.path.join(MODEL, "toolpath.csv"))
    obj = create_engagement(doc, stock, toolpath, diameter=12, flutes=2, flute_length=30, feed_per_tooth=0.1,
                            inclination=10, phi_step=5, forces=True)
    doc.recompute()
    assert obj.isValid(), obj.getStatusString()
    yield obj
    FreeCAD.closeDocument(doc.Name)


def segment_of(result, cl, row):
    """The segment dict (Engagement.segments) whose φ range holds row `row` of CL point `cl`, or None."""
    phi = result.phi[row]
    found = [s for s in result.segments(cl) if s["phi_start"] <= phi <= s["phi_end"]]
    return found[0] if found else None


def reference_triangles(result):
    """Per pair of neighbouring angles of one segment: its two triangles, as sorted corner coordinates."""
    triangles = []
    m, p = result.segment.shape
    for cl in range(m):
        for row in range(p - 1):
            here, there = segment_of(result, cl, row), segment_of(result, cl, row + 1)
            if here is None or there is None or here["letter"] != there["letter"]:
                continue
            lep0, lep1 = result.lep_xyz[cl, row], result.lep_xyz[cl, row + 1]
            uep0, uep1 = result.uep_xyz[cl, row], result.uep_xyz[cl, row + 1]
            triangles += [(lep0, lep1, uep1), (lep0, uep1, uep0)]
    return triangles


def as_keys(triangles):
    """Each triangle's corners rounded to 1e-9 mm, in a set (so the order of triangles does not count)."""
    return {tuple(np.round(np.asarray(corners, dtype=float), 9).ravel()) for corners in triangles}


def test_the_mesh_is_every_strip_between_lep_and_uep_of_each_segment(engagement):
    result = engagement.Proxy.result(engagement)
    mesh = surface_mesh(result)
    engaged = [(cl, row) for cl in range(result.shape[0]) for row in range(result.shape[1])
               if segment_of(result, cl, row) is not None]
    assert len(mesh.points) == 2 * len(engaged) > 200
    mine = mesh.points[mesh.triangles]
    assert len(mine) == len(reference_triangles(result))
    assert as_keys(mine) == as_keys(reference_triangles(result))
    # coordIndex: three corners then -1 per triangle
    index = coord_index(mesh.triangles)
    assert list(index[:8]) == [*mesh.triangles[0], -1, *mesh.triangles[1], -1]


def test_vertex_colours_by_segment_and_by_quantity(engagement):
    result = engagement.Proxy.result(engagement)
    forces = engagement.Proxy.forces(engagement)
    mesh = surface_mesh(result)
    # the instant of each vertex found by its coordinates among all engaged LEPs and UEPs
    instants = {}
    for cl in range(result.shape[0]):
        for row in range(result.shape[1]):
            if segment_of(result, cl, row) is not None:
                for end in (result.lep_xyz[cl, row], result.uep_xyz[cl, row]):
                    instants.setdefault(tuple(np.round(end, 9)), (cl, row))
    at = [instants[tuple(np.round(point, 9))] for point in mesh.points]

    colours, legend = vertex_colours(result, mesh, "segment")
    expected = [SURFACE_COLOURS[segment_of(result, cl, row)["surface"]] for cl, row in at]
    np.testing.assert_allclose(colours, expected, atol=1e-12)
    assert legend.kind == "segment" and {"top", "curved_wall", "straight_wall"} <= {n for n, _ in legend.entries}

    resultant = np.sqrt((np.asarray(forces.xyz) ** 2).sum(axis=-1))
    for colour_by, table, unit in (("length", result.length, "mm"), ("area", result.area, "mm²"),
                                   ("force", resultant, "N")):
        values = np.array([table[cl, row] for cl, row in at])
        colours, legend = vertex_colours(result, mesh, colour_by, forces, "plasma")
        assert (legend.kind, legend.unit, legend.colour_map) == (colour_by, unit, "plasma")
        assert (legend.low, legend.high) == (pytest.approx(values.min()), pytest.approx(values.max()))
        expected = colormaps["plasma"]((values - values.min()) / (values.max() - values.min()))[:, :3]
        np.testing.assert_allclose(colours, expected, atol=1e-9)
    assert COLOUR_BY == ("segment", "length", "area", "force")
    with pytest.raises(ValueError, match="colour_by must be one of"):
        vertex_colours(result, mesh, "depth")
    with pytest.raises(ValueError, match="colour by force needs the engagement's forces"):
        vertex_colours(result, mesh, "force")


def test_packed_colours_are_coin_rgba():
    packed = packed_rgba([(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0), (0.5, 0.25, 1.0)])
    assert packed.dtype == np.uint32
    assert [int(v) for v in packed] == [0xFF0000FF, 0x00FF00FF, 0x0000FFFF, (128 << 24) | (64 << 16) | (255 << 8) | 255]


@pytest.fixture(scope="module")
def ball():
    """Model test 1 with a D12 ball-end mill and an MSYS-free CL pass, as a document object, recomputed."""
    doc = FreeCAD.newDocument("ABMMeshBall")
    stock = create_stock(doc, os.path.join(MODEL, "stock.json"))
    toolpath = create_toolpath(doc, os.path.join(MODEL, "toolpath.csv"))
    obj = create_engagement(doc, stock, toolpath, diameter=12, flutes=2, flute_length=30, corner_radius=6,
                            feed_per_tooth=0.1, inclination=10, phi_step=5)
    doc.recompute()
    assert obj.isValid(), obj.getStatusString()
    yield obj
    FreeCAD.closeDocument(doc.Name)


def test_a_ball_mills_surface_follows_its_corner(ball):
    """Every vertex lies on the tool: below the height r = R of the ball's centre T + r·w, at distance r from
    that centre; above it, at distance R from the axis."""
    result = ball.Proxy.result(ball)
    mesh = surface_mesh(result, ball.Proxy.edge_along(ball))
    assert mesh.rows > 2 and len(mesh.points) == mesh.rows * len(mesh.cl)
    toolpath = ball.Toolpath.Proxy.load(ball.Toolpath)[0]
    axes = toolpath.axes[np.tile(mesh.cl, mesh.rows)]
    relative = mesh.points - toolpath.cl[np.tile(mesh.cl, mesh.rows)]
    height = (relative * axes).sum(axis=1)
    across = np.linalg.norm(relative - height[:, None] * axes, axis=1)
    from_centre = np.linalg.norm(relative - 6.0 * axes, axis=1)
    np.testing.assert_allclose(np.where(height < 6.0, from_centre, across), 6.0, atol=1e-9)
    assert (height < 6.0).sum() > 100  # the corner is drawn
    # Each instant's first and last vertices are its LEP and UEP.
    n = len(mesh.cl)
    np.testing.assert_array_equal(mesh.points[:n], result.lep_xyz[mesh.cl, mesh.row])
    np.testing.assert_array_equal(mesh.points[-n:], result.uep_xyz[mesh.cl, mesh.row])
    colours, _ = vertex_colours(result, mesh, "segment")
    assert colours.shape == (len(mesh.points), 3)
