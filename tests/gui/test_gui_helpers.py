"""The GUI's helpers that need no GUI: CL point lists and validation (validate).

FreeCAD headless (booleans for the validation); no Xvfb. The mesh and its colours: test_surface_mesh.py.
"""

import os

import pytest

from abm_workbench.cad.freecad_env import FreeCAD
from abm_workbench.errors import InputError
from abm_workbench.features import create_engagement, create_stock, create_toolpath
from abm_workbench.gui.validate import Cancelled, cl_indices, validate_engagement
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


def test_the_report_of_a_validation_from_the_gui_is_in_its_language(engagement, tmp_path, monkeypatch):
    """The GUI's translation (here ABM_de.ts's German, context ABM, in place of Qt's) words the report's
    headings and sentences and what the GUI says of the job; its numbers and the CSV files as they are."""
    from abm_workbench.gui import validate
    from abm_workbench.gui.i18n import FOLDER, read_translations

    german = read_translations(os.path.join(FOLDER, "ABM_de.ts"))

    def translate(text, context="ABM", **values):
        return german.get((context, text), text).format(**values) if values else german.get((context, text), text)

    monkeypatch.setattr(validate, "translate", translate)
    monkeypatch.setattr(validate, "language", lambda: "de")
    folder = tmp_path / "bericht"
    text = open(validate_engagement(engagement, [22], str(folder)), encoding="utf-8").read()
    assert "<html lang='de'>" in text and "<h2>Auftrag</h2>" in text and "<h2>Laufzeiten</h2>" in text
    assert "CL-Punkte 22 des Durchgangs, hier mit 0..0 nummeriert." in text and "0 (CL 22 des Durchgangs)" in text
    assert "<title>ABM gegen boolesche Operationen: " in text and "<h2>Zwischenrohteil</h2>" in text
    assert "Zwischenrohteil: das Rohteil ohne das, was frühere Schnittbewegungen des Programms entfernt haben" in text
    assert (folder / "comparison.csv").read_text().splitlines()[0].startswith("cl,phi_deg,")
