"""The GUI's helpers that need no GUI: face colours (colouring), CL point lists and validation (validate).

FreeCAD headless (Part for the engaged surface, booleans for the validation); no Xvfb.
"""

import os

import numpy as np
import pytest

from abm_workbench.cad.freecad_env import FreeCAD, Part
from abm_workbench.errors import InputError
from abm_workbench.features import create_engagement, create_stock, create_toolpath
from abm_workbench.features.engagement import engaged_surfaces
from abm_workbench.gui.colouring import COLOUR_BY, face_colours, face_map, face_values, quantity_colours
from abm_workbench.gui.validate import Cancelled, cl_indices, validate_engagement
from abm_workbench.report.colours import SURFACE_COLOURS
from tests.conftest import ROOT

MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")


@pytest.fixture(scope="module")
def engagement():
    """Model test 1 (JSON stock, φ step 5°) as a document object, recomputed."""
    doc = FreeCAD.newDocument("ABMHelpers")
    stock = create_stock(doc, os.path.join(MODEL, "stock.json"))
    toolpath = create_toolpath(doc, os.path.join(MODEL, "toolpath.csv"))
    obj = create_engagement(doc, stock, toolpath, diameter=12, flutes=2, flute_length=30, feed_per_tooth=0.1,
                            inclination=10, phi_step=5)
    doc.recompute()
    assert obj.isValid(), obj.getStatusString()
    yield obj
    FreeCAD.closeDocument(doc.Name)


def test_each_face_is_between_the_lep_and_uep_of_its_two_angles(engagement):
    result = engagement.Proxy.result(engagement)
    faces = face_map(result, engagement.Shape)
    assert len(faces.cl) == len(engagement.Shape.Faces) > 100
    corners = np.stack([result.lep_xyz[faces.cl, faces.rows[:, 0]], result.lep_xyz[faces.cl, faces.rows[:, 1]],
                        result.uep_xyz[faces.cl, faces.rows[:, 0]], result.uep_xyz[faces.cl, faces.rows[:, 1]]], 1)
    for face, quad in zip(engagement.Shape.Faces, corners):
        box = face.BoundBox
        assert np.allclose([box.XMin, box.YMin, box.ZMin], quad.min(axis=0), atol=1e-6)
        assert np.allclose([box.XMax, box.YMax, box.ZMax], quad.max(axis=0), atol=1e-6)
    assert all(result.segments(cl)[result.segment[cl, row]]["surface"] == surface
               for cl, row, surface in zip(faces.cl, faces.rows[:, 0], faces.surface))


def test_colours_by_segment_and_by_quantity_with_their_legends(engagement):
    result = engagement.Proxy.result(engagement)
    faces = face_map(result, engagement.Shape)
    colours, legend = face_colours(result, faces, "segment")
    assert np.allclose(colours, [SURFACE_COLOURS[name] for name in faces.surface])
    assert legend.kind == "segment" and {"top", "curved_wall", "straight_wall"} <= {n for n, _ in legend.entries}
    for colour_by, unit in (("length", "mm"), ("area", "mm²")):
        colours, legend = face_colours(result, faces, colour_by)
        values = face_values(getattr(result, colour_by), faces)
        assert (legend.unit, legend.low, legend.high) == (unit, values.min(), values.max())
        assert np.allclose(colours[values.argmin()], quantity_colours([0.0], 0.0, 1.0)[0])
        assert np.allclose(colours[values.argmax()], quantity_colours([1.0], 0.0, 1.0)[0])
    assert COLOUR_BY == ("segment", "length", "area", "force")
    with pytest.raises(ValueError, match="colour_by must be one of"):
        face_colours(result, faces, "depth")
    with pytest.raises(ValueError, match="colour by force needs the engagement's forces"):
        face_colours(result, faces, "force")


def test_colours_by_force_are_the_resultant_per_face(engagement):
    result = engagement.Proxy.result(engagement)
    faces = face_map(result, engagement.Shape)
    engagement.Forces = True
    try:
        engagement.Document.recompute()
        forces = engagement.Proxy.forces(engagement)
        colours, legend = face_colours(result, faces, "force", forces)
        resultant = np.linalg.norm(forces.xyz, axis=-1)  # |F| from the components, not the class's own
        values = 0.5 * (resultant[faces.cl, faces.rows[:, 0]] + resultant[faces.cl, faces.rows[:, 1]])
        assert (legend.kind, legend.unit) == ("force", "N")
        assert legend.low == pytest.approx(values.min(), abs=1e-9) and legend.high == pytest.approx(values.max())
        assert legend.high > 100.0
        np.testing.assert_allclose(colours, quantity_colours(values, values.min(), values.max()), atol=1e-9)
    finally:
        engagement.Forces = False
        engagement.Document.recompute()


def test_a_shape_of_other_results_has_no_face_map(engagement):
    result = engagement.Proxy.result(engagement)
    assert face_map(result, Part.Shape()) is None
    assert face_map(result, Part.makeBox(1, 1, 1)) is None
    other = engaged_surfaces(result)
    assert face_map(result, other) is not None


def test_cl_lists_checked_by_the_job_model_in_the_gui_words():
    assert cl_indices("all", 4) == cl_indices(" ", 4) == [0, 1, 2, 3]
    assert cl_indices("29, 22,22", 53) == [22, 29]
    with pytest.raises(InputError, match=r"^CL points: expected CL indices such as 0,22,40, got '1,x'$"):
        cl_indices("1,x", 53)
    with pytest.raises(InputError, match=r"^CL points: CL point 60 is not in the pass \(0..52\)$"):
        cl_indices("60", 53)


def test_validation_of_an_engagement_object_writes_the_report_or_nothing(engagement, tmp_path):
    folder = tmp_path / "report"
    page = validate_engagement(engagement, [22], str(folder))
    assert page == str(folder / "index.html")
    text = (folder / "index.html").read_text(encoding="utf-8")
    assert "CL points 22 of the pass, numbered 0..0 here." in text and "pass CL 22" in text
    comparison = (folder / "comparison.csv").read_text().splitlines()
    assert len(comparison) == 1 + 37  # one CL point × 37 angles

    def cancel(done, total):
        raise Cancelled("validation cancelled: nothing written")

    before = sorted(os.listdir(folder))
    with pytest.raises(Cancelled):
        validate_engagement(engagement, [0, 1], str(folder), cancel)
    assert sorted(os.listdir(folder)) == before and (folder / "index.html").read_text(encoding="utf-8") == text
    assert sorted(os.listdir(tmp_path)) == ["report"]  # no staging folder left
    with pytest.raises(InputError, match="CL points: choose at least one"):
        validate_engagement(engagement, [], str(tmp_path / "none"))
