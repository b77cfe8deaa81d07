"""The validation report: its CSV tables, the self-contained HTML page, and outputs staged whole."""

import base64
import csv
import json
import os
import re

import numpy as np
import pytest

from abm_workbench import cli
from abm_workbench.engine import CutSettings, Tool, Toolpath, engage
from abm_workbench.forces import material, pass_forces
from abm_workbench.formats.staircase_json import dump_staircase
from abm_workbench.formats.toolpath_csv import load_toolpath
from abm_workbench.report.html import ReportJob, paper_model_test, report_cls, write_report
from abm_workbench.report.staging import staged
from abm_workbench.report.tables import (COMPARISON_COLUMNS, DEPTH_COLUMNS, SEGMENT_COLUMNS, SURFACE_COLUMNS,
                                         csv_text)
from abm_workbench.validation import Validation, compare

from .conftest import STOCKS

TOOL = Tool(12.0, 2, 25.0)
SETTINGS = CutSettings(0.1, phi_start=0, phi_end=180, phi_step=15)
PATH = Toolpath([[21.3, 0.7, 0.9], [44.9, 1.3, 2.1], [73.0, -0.4, 4.3]], [12.0, 0.0, -6.0], [18.0, 25.0, -30.0])


@pytest.fixture(scope="module")
def validation():
    """A Validation whose reference is the engine's result with 1 % added to the lengths."""
    engagement = engage(STOCKS["ridge"], TOOL, PATH, SETTINGS)
    reference = {"length": engagement.length * 1.01, "lep_l": engagement.lep_l, "uep_l": engagement.uep_l,
                 "pieces": engagement.pieces}
    return Validation(engagement, reference, compare(engagement, reference, PATH, TOOL),
                      {"abm": 0.01, "boolean": 2.0})


def read_csv(path):
    """{column: list of str} of a CSV file, columns in order."""
    with open(path, newline="", encoding="utf-8") as file:
        rows = list(csv.reader(file))
    return {name: [row[k] for row in rows[1:]] for k, name in enumerate(rows[0])}


def job(description="Model test 1 (after Hendriko 2020): a test"):
    return ReportJob("ABM against booleans: s.json / p.csv", description, "s.json", "p.csv", PATH, TOOL, SETTINGS,
                     "diameter 12 mm [job.json]", "quintic walls", (-12.0, 12.0), 0.5)


def test_report_folder(tmp_path, validation):
    page = write_report(tmp_path, validation, job(), report_cls(validation))
    assert page == os.path.join(tmp_path, "index.html")
    assert sorted(os.listdir(tmp_path)) == ["comparison.csv", "depth.csv", "index.html", "segments.csv",
                                            "surfaces.csv"]
    m, p = validation.engagement.shape
    comparison = read_csv(tmp_path / "comparison.csv")
    assert tuple(comparison) == COMPARISON_COLUMNS and len(comparison["cl"]) == m * p
    errors = [float(e) for e, kind in zip(comparison["error"], comparison["error_kind"]) if kind == "relative"]
    np.testing.assert_allclose(errors, -0.01 / 1.01, rtol=1e-9)
    assert set(comparison["error_kind"]) <= {"relative", "absolute_mm"}
    segments = read_csv(tmp_path / "segments.csv")
    assert tuple(segments) == SEGMENT_COLUMNS
    assert len(segments["cl"]) == sum(len(validation.engagement.segments(cl)) for cl in range(m))
    assert tuple(read_csv(tmp_path / "surfaces.csv")) == SURFACE_COLUMNS
    depth = read_csv(tmp_path / "depth.csv")
    assert tuple(depth) == DEPTH_COLUMNS and depth["cl"] == [str(cl) for cl in range(m)]


def test_page_is_self_contained(tmp_path, validation):
    text = open(write_report(tmp_path, validation, job(), [(0, "chosen"), (2, "chosen")]), encoding="utf-8").read()
    assert text.startswith("<!DOCTYPE html>") and text.rstrip().endswith("</html>")
    images = re.findall(r"<img [^>]*src='([^']*)'", text)
    assert len(images) == 6 and all(src.startswith("data:image/png;base64,iVBOR") for src in images)
    links = re.findall(r"(?:href|src)='([^']*)'", text)
    assert {link for link in links if not link.startswith("data:")} == {
        "comparison.csv", "segments.csv", "surfaces.csv", "depth.csv"}
    for heading in ("Error by UEP surface", "Length of cut along the pass", "Depth of cut along the pass",
                    "cut area over φ", "Shape of the cut", "Error per engagement segment", "Timings"):
        assert heading in text
    assert "1.78–7.32 mm" in text and "This job is model test 1." in text
    assert "0.99 %" in text  # |relative error|: ABM is 1/1.01 of the reference
    assert "200 ×" in text  # boolean / ABM


def test_paper_model_tests():
    assert paper_model_test("Model test 2 (after Hendriko 2020): ...") == 2
    assert paper_model_test("A pass of model test 1") == 1
    assert paper_model_test("model test 12") is None and paper_model_test("") is None
    assert paper_model_test("Model test 3: the model test 1 stock machined by two operations, five-axis tool "
                            "axes as in model test 1.") is None


def test_cl_points_shown(validation):
    assert report_cls(validation, [2, 0]) == [(2, "chosen"), (0, "chosen")]
    shown = report_cls(validation)
    assert [why for _, why in shown][:3] == ["deepest", "shallowest", "middle"]


def test_csv_text():
    text = csv_text(("a", "b", "c"), [np.array([1.5, np.nan]), ["x", "y"], np.array([-0.0, 1e-20])])
    assert text == "a,b,c\n1.5,x,0\n,y,1e-20\n"


def test_staged_folder_replaces_an_old_one_whole(tmp_path):
    (tmp_path / "report").mkdir()
    (tmp_path / "report" / "old.txt").write_text("old")
    with staged(tmp_path / "report", folder=True) as folder:
        assert os.path.dirname(folder) == str(tmp_path) and os.path.basename(folder).startswith(".report.")
        (tmp_path / "report" / "old.txt").read_text()  # the old one is untouched meanwhile
        open(os.path.join(folder, "index.html"), "w").close()
    assert os.listdir(tmp_path) == ["report"] and os.listdir(tmp_path / "report") == ["index.html"]
    assert (os.stat(tmp_path / "report").st_mode & 0o777) == 0o777 & ~_umask()


def test_staged_outputs_left_as_they_were_on_an_interrupt(tmp_path):
    (tmp_path / "report").mkdir()
    (tmp_path / "out.FCStd").write_text("old")
    with pytest.raises(KeyboardInterrupt):
        with staged(tmp_path / "report", folder=True) as folder, staged(tmp_path / "out.FCStd") as fcstd:
            assert fcstd.endswith(os.sep + "out.FCStd") and fcstd != str(tmp_path / "out.FCStd")
            open(fcstd, "w").close()
            open(os.path.join(folder, "index.html"), "w").close()
            raise KeyboardInterrupt
    assert sorted(os.listdir(tmp_path)) == ["out.FCStd", "report"]
    assert os.listdir(tmp_path / "report") == [] and (tmp_path / "out.FCStd").read_text() == "old"


def _umask():
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def test_forces_section_and_png_only_with_forces(tmp_path, validation):
    forces = pass_forces(STOCKS["ridge"], TOOL, PATH, SETTINGS, material("al6082-t6"))
    with_forces, without = tmp_path / "with", tmp_path / "without"
    with_forces.mkdir()
    without.mkdir()
    text = open(write_report(with_forces, validation, job(), [(2, "chosen"), (0, "chosen")], forces),
                encoding="utf-8").read()
    plain = open(write_report(without, validation, job(), [(2, "chosen"), (0, "chosen")]), encoding="utf-8").read()
    assert "<h2>Cutting forces</h2>" in text and "Cutting forces" not in plain
    assert "forces.png" in os.listdir(with_forces) and "forces.png" not in os.listdir(without)
    png = (with_forces / "forces.png").read_bytes()
    images = re.findall(r"<img [^>]*src='data:image/png;base64,([^']*)'", text)
    assert len(images) == 7 and base64.b64decode(images[-1]) == png and png.startswith(b"\x89PNG")
    worst = int(np.argmax(forces.peak))
    assert f"{forces.peak[worst]:.4g} N at CL {worst}" in text and forces.peak[worst] > 10.0
    assert "over φ at CL 0, 2" in text


def test_validate_command_with_forces(tmp_path, monkeypatch, capsys):
    dump_staircase(STOCKS["ridge"], tmp_path / "stock.json")
    (tmp_path / "path.csv").write_text("x,y,z,theta_a,theta_b\n" + "".join(
        f"{x},{y},{z},{a},{b}\n" for (x, y, z), a, b in zip(PATH.cl, PATH.theta_a, PATH.theta_b)))
    (tmp_path / "job.json").write_text(json.dumps({"diameter": 12, "flutes": 2, "flute_length": 25,
                                                   "feed_per_tooth": 0.1, "phi_step": 15}))
    monkeypatch.chdir(tmp_path)
    base = ["validate", "--stock", "stock.json", "--toolpath", "path.csv", "--job", "job.json", "--report", "report"]
    assert cli.main(base + ["--material", "al6082-t6"]) == 2
    assert capsys.readouterr().err.splitlines()[-1] == "abm: error: --material applies with --forces"
    assert cli.main(base + ["--forces", "--ktc", "600", "--krc", "100", "--kac", "200", "--immersion", "0:200"]) == 2
    assert capsys.readouterr().err.splitlines()[-1].startswith("abm: error: --immersion: must be within (0, 180]°, got 200°")
    assert not os.path.exists("report")
    assert cli.main(base + ["--forces", "--material", "al6082-t6", "--immersion", "0:90"]) == 0
    out = capsys.readouterr().out
    read_back = load_toolpath("path.csv")  # its frames turned to the feed of its CL points
    expected = pass_forces(STOCKS["ridge"], TOOL, read_back, SETTINGS, material("al6082-t6"), immersion=(0, 90))
    assert f"; peak force {expected.peak.max():.4g} N at CL {int(np.argmax(expected.peak))}" in out
    assert "forces.png" in os.listdir("report")
    assert "<h2>Cutting forces</h2>" in (tmp_path / "report" / "index.html").read_text(encoding="utf-8")


def test_in_process_section(tmp_path, validation):
    """Against the in-process stock the page names the stock model, counts the changed CL points, shows
    the stock around the chosen ones, and the CSVs carry the length in the stock as given."""
    import dataclasses

    from abm_workbench.report import figures
    from abm_workbench.report.tables import INPROCESS_COMPARISON_COLUMNS, INPROCESS_DEPTH_COLUMNS
    from abm_workbench.validation import InProcessCheck

    m, _ = validation.engagement.shape
    initial = validation.engagement.length + np.array([[0.0], [1.5], [0.0]])
    check = InProcessCheck(initial, np.array([False, True, False]), np.array([0, 7, 2]))
    inprocess = dataclasses.replace(validation, in_process=check)
    x = y = np.linspace(-5.0, 5.0, 6)
    views = {1: (x + PATH.cl[1, 0], y + PATH.cl[1, 1], np.full((6, 6), 3.0))}
    model = "in-process: the stock minus the volumes swept by every cutting move of p.apt before each CL point"
    page = open(write_report(tmp_path, inprocess, dataclasses.replace(job(), stock_model=model),
                             [(1, "chosen")], views=views), encoding="utf-8").read()
    assert model in page and "<h2>In-process stock</h2>" in page
    assert "Earlier moves changed 1 of 3 CL points" in page
    comparison = read_csv(tmp_path / "comparison.csv")
    assert tuple(comparison) == COMPARISON_COLUMNS + INPROCESS_COMPARISON_COLUMNS
    np.testing.assert_allclose([float(v) for v in comparison["l_initial"]], initial.ravel(), rtol=1e-11)
    depth = read_csv(tmp_path / "depth.csv")
    assert tuple(depth) == DEPTH_COLUMNS + INPROCESS_DEPTH_COLUMNS
    assert depth["changed"] == ["0", "1", "0"] and depth["swept"] == ["0", "7", "2"]
    os.makedirs(tmp_path / "plain")
    plain = open(write_report(tmp_path / "plain", validation, job(), [(1, "chosen")]), encoding="utf-8").read()
    assert "initial: the stock as given" in plain and "In-process stock" not in plain
    assert page.count("data:image/png;base64,") == plain.count("data:image/png;base64,") + 1  # the stock picture
    figures.inprocess_figure(inprocess, views, PATH, TOOL).savefig(tmp_path / "inprocess.png")


def test_in_process_section_says_what_the_exact_test_decided(tmp_path, validation):
    """A corner tool's check: the swept pieces the reference decided with its exact inside test are counted on
    the page, per CL point in its table and in depth.csv's column gauged; none, no sentence."""
    import dataclasses

    from abm_workbench.report.tables import CORNER_DEPTH_COLUMNS, INPROCESS_DEPTH_COLUMNS
    from abm_workbench.validation import InProcessCheck

    initial = validation.engagement.length + np.array([[0.0], [1.5], [0.0]])
    for gauged, said in (([0, 3, 2], True), ([0, 0, 0], False)):
        check = InProcessCheck(initial, np.array([False, True, False]), np.array([0, 7, 2]), np.array(gauged))
        folder = tmp_path / str(said)
        os.makedirs(folder)
        page = open(write_report(folder, dataclasses.replace(validation, in_process=check), job(), [(1, "chosen")]),
                    encoding="utf-8").read()
        assert ("5 of the swept pieces that meet the tool's edges (summed over the checked CL points) are moves "
                "OpenCASCADE has no reliable solids for" in page) == said
        assert ("7 (3 by the exact test)" in page) == said
        depth = read_csv(folder / "depth.csv")
        assert tuple(depth) == DEPTH_COLUMNS + INPROCESS_DEPTH_COLUMNS + CORNER_DEPTH_COLUMNS
        assert depth["gauged"] == [str(n) for n in gauged]


def test_the_page_in_german_where_words_are_given(tmp_path, validation, monkeypatch):
    """With the GUI's translation (here ABM_de.ts's German, context ABM) the headings and sentences are German,
    the numbers, file names and the CSV files as they are; every text the page translates is in the translation
    template and has German with the same placeholders."""
    from abm_workbench.gui.i18n import REPORT, TEMPLATE, messages, read_translations
    from abm_workbench.report import html

    german = read_translations(os.path.join(os.path.dirname(TEMPLATE), "ABM_de.ts"))
    texts = messages(REPORT)["ABM"]
    assert len(texts) > 60 and all(("ABM", text) in german for text in texts)
    assert all(sorted(re.findall(r"\{(\w+)\}", german[("ABM", text)])) == sorted(re.findall(r"\{(\w+)\}", text))
               for text in texts)
    monkeypatch.setattr(html, "_image", lambda figure: "<img alt=''>")
    cls = [(2, "deepest"), (0, "chosen")]
    english = html.report_page(validation, job(), cls)
    page = html.report_page(validation, job(), cls, words=lambda text: german.get(("ABM", text), text),
                            language="de")
    assert html.report_page(validation, job(), cls) == english  # the language is the call's only
    assert "<html lang='de'>" in page and "<html lang='en'>" in english
    for heading in ("Auftrag", "Fehler nach UEP-Fläche, ganzer Durchgang", "Laufzeiten", "Dateien",
                    "Schnittlänge entlang des Durchgangs <small>(Abb. 6(e)/(f))</small>"):
        assert f"<h2>{heading}</h2>" in page
    assert "Gezeigte CL-Punkte: 2 (tiefster), 0 (gewählt). Schattiert: die Eingriffssegmente (ABM)." in page
    assert "Schaftfräser D 12 mm, 2 Schneiden, Schneidenlänge 25 mm" in page
    assert "{path}" not in page and "Error" not in page.replace("error_kind", "")
    headings = re.findall(r"<h2>(.*?)</h2>", english)
    assert len(re.findall(r"<h2>(.*?)</h2>", page)) == len(headings)
    assert not set(headings) & set(re.findall(r"<h2>(.*?)</h2>", page))
    # the numbers of the English page are all on the German one, as they were
    def numbers(text):
        return set(re.findall(r"\d+(?:\.\d+)?(?:e[-+]\d+)?", re.sub(r"<[^>]*>|&#?\w+;", " ", text)))

    assert numbers(english) <= numbers(page)
