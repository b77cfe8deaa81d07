"""The annotated FreeCAD document: saved, re-opened, every object valid, colours in GuiDocument.xml."""

import xml.etree.ElementTree as ElementTree
import zipfile

import pytest

from abm_workbench.cad.annotate import gui_document_xml, write_annotated
from abm_workbench.cad.freecad_env import FreeCAD
from abm_workbench.engine import CutSettings, Tool, Toolpath, engage
from abm_workbench.report.colours import SURFACE_COLOURS

from .conftest import STOCKS

TOOL = Tool(12.0, 2, 25.0)
SETTINGS = CutSettings(0.1, phi_start=0, phi_end=180, phi_step=10)
PATH = Toolpath([[21.3, 0.7, 0.9], [44.9, 1.3, 2.1], [73.0, -0.4, 4.3]], [12.0, 0.0, -6.0], [18.0, 25.0, -30.0])


@pytest.fixture
def reopened(tmp_path, solids):
    """(document re-opened from the saved file, engagement, path of the file); closed afterwards."""
    engagement = engage(STOCKS["ridge"], TOOL, PATH, SETTINGS)
    path = tmp_path / "pass.FCStd"
    write_annotated(path, "ABM_pass", solids["ridge"], engagement, PATH, TOOL, cls=[0, 2], intersections=[2])
    assert not [d for d in FreeCAD.listDocuments() if d.startswith("ABM_pass")]  # closed after saving
    document = FreeCAD.openDocument(str(path))
    yield document, engagement, path
    FreeCAD.closeDocument(document.Name)


def test_document_reopens_with_valid_objects(reopened, solids):
    document, engagement, _ = reopened
    for obj in document.Objects:
        assert obj.isValid(), obj.Name
        if obj.TypeId == "Part::Feature":
            assert not obj.Shape.isNull() and obj.Shape.isValid(), obj.Name
    names = {obj.Name for obj in document.Objects}
    segments = {f"CL{cl:03d}_Seg_{s['letter']}_{s['surface']}" for cl in (0, 2) for s in engagement.segments(cl)}
    assert segments <= names
    assert {"Stock", "Toolpath", "CL000", "CL000_LEP", "CL000_UEP", "CL002_Intersection"} <= names
    assert not any(name.startswith("CL001") for name in names) and "CL000_Intersection" not in names
    assert document.getObject("Stock").Shape.Volume == pytest.approx(solids["ridge"].Volume, rel=1e-9)
    group = document.getObject("CL002")
    assert {obj.Name for obj in group.Group} == {name for name in names if name.startswith("CL002_")}


def test_segment_objects_carry_their_data(reopened):
    document, engagement, _ = reopened
    segment = engagement.segments(2)[0]
    obj = document.getObject(f"CL002_Seg_{segment['letter']}_{segment['surface']}")
    assert (obj.ClIndex, obj.Segment, obj.UepSurface) == (2, segment["letter"], segment["surface"])
    assert (obj.PhiStart.Value, obj.PhiEnd.Value) == (segment["phi_start"], segment["phi_end"])
    assert tuple(obj.Colour)[:3] == pytest.approx(SURFACE_COLOURS[segment["surface"]], abs=1 / 255)
    # Ruled between the LEP and UEP polylines: a face per step of φ within the segment.
    steps = round((segment["phi_end"] - segment["phi_start"]) / SETTINGS.phi_step)
    assert len(obj.Shape.Faces) == steps if steps else obj.Shape.ShapeType == "Edge"


def test_colours_are_in_the_gui_document(reopened):
    _, engagement, path = reopened
    with zipfile.ZipFile(path) as archive:
        root = ElementTree.fromstring(archive.read("GuiDocument.xml"))
    providers = {p.get("name"): p for p in root.iter("ViewProvider")}
    assert int(root.find("ViewProviderData").get("Count")) == len(providers)
    segment = engagement.segments(0)[0]
    colour = providers[f"CL000_Seg_{segment['letter']}_{segment['surface']}"].find(
        "Properties/Property[@name='ShapeColor']/PropertyColor").get("value")
    r, g, b = (round(255 * c) for c in SURFACE_COLOURS[segment["surface"]])
    assert int(colour) == (r << 24) | (g << 16) | (b << 8)
    stock = providers["Stock"].find("Properties/Property[@name='Transparency']/Integer")
    assert stock.get("value") == "70"


def test_gui_document_xml_is_well_formed():
    text = gui_document_xml({"A": {"ShapeColor": (1.0, 0.5, 0.0), "LineWidth": 3.0}, "B": {"Transparency": 20}})
    root = ElementTree.fromstring(text)
    assert [p.get("name") for p in root.iter("ViewProvider")] == ["A", "B"]
    assert root.find(".//Property[@name='ShapeColor']/PropertyColor").get("value") == str(0xFF800000)
    shown = ElementTree.fromstring(gui_document_xml({"C": {"Visibility": True}}))
    assert shown.find(".//Property[@name='Visibility']/Bool").get("value") == "true"

