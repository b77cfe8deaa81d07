"""The engagement object against the in-process stock.

On model test 3, operation 2 (the D8 passes after the D12 passes of operation 1), its results
equal what the command line writes with ``--stock-model in-process`` byte for byte. On a
three-axis program of two adjacent passes (:func:`write_two_passes`: few swept volumes near each
CL point, so the booleans take seconds), its lengths, LEP and UEP at chosen CL points equal an
independent OpenCASCADE reference: the stock solid cut by exact solids of the earlier moves'
swept volumes (cad.inprocess_boolean), sectioned by the edge lines; the in-process stock object
holds what the engagement found engaged.
"""

import os
import subprocess
import sys

import numpy as np
import pytest

from abm_workbench.cad.freecad_env import FreeCAD
from abm_workbench.cad.inprocess_boolean import inprocess_lengths
from abm_workbench.engine import Tool
from abm_workbench.engine.engagement import edge_lines
from abm_workbench.errors import InputError
from abm_workbench.features import create_engagement, create_stock, create_toolpath
from abm_workbench.features import engagement as engagement_module
from abm_workbench.features.inprocess_stock import create_inprocess_stock
from abm_workbench.features.stored import read_in_process
from abm_workbench.formats.results_csv import read_results, summary_path
from abm_workbench.jobs import load_path
from abm_workbench.jobs.inputs import program_moves
from tests.conftest import ROOT

MODEL = os.path.join(ROOT, "resources", "models", "model_test_3")
STOCK, PROGRAM, JOB = (os.path.join(MODEL, name) for name in ("stock.step", "program.apt", "job.json"))
OPERATION, PHI_STEP = 2, 5.0
#: The job file's values (the program gives the tool, spindle and feed).
SETTINGS = dict(flutes=2, feed_per_tooth=0.1, inclination=10.0, phi_step=PHI_STEP)
AGREE = 0.01  # mm, engine against the OpenCASCADE booleans
MODEL_1_STOCK = os.path.join(ROOT, "resources", "models", "model_test_1", "stock.json")
#: Two passes of a D12 tool at these y (mm), x from 4 to 64 mm in 6 moves, z 2 mm, axis +z.
PASSES, XS, Z = (-4.0, 4.0), np.linspace(4.0, 64.0, 7), 2.0


def write_two_passes(path):
    """An APT program of one operation (D12, flute length 30 mm): two passes, rapids between."""
    lines = ["UNITS/MM", "MULTAX/ON", "TOOL PATH/TWO_PASSES,TOOL,T1", "LOADTL/1", "CUTTER/12,0,0,0,0,0,75",
             "CSI_SET_FLUTE_LENGTH/30", "SPINDL/RPM,4000,CLW"]
    for y in PASSES:
        lines += ["RAPID", f"GOTO/{XS[0]},{y},40,0,0,1", "FEDRAT/MMPM,800"]
        lines += [f"GOTO/{x},{y},{Z},0,0,1" for x in XS]
        lines += ["RAPID", f"GOTO/{XS[-1]},{y},40,0,0,1"]
    lines += ["END-OF-PATH", "FINI"]
    with open(path, "w", encoding="utf-8") as file:
        file.write("\n".join(lines) + "\n")


def new_engagement(doc, stock=STOCK, program=PROGRAM, operation=OPERATION, **options):
    """Stock, toolpath and engagement in `doc` (default: model test 3, operation 2), recomputed."""
    stock = create_stock(doc, stock)
    toolpath = create_toolpath(doc, program)
    toolpath.Operation = operation
    engagement = create_engagement(doc, stock, toolpath, **{**SETTINGS, **options})
    engagement.ShowSurfaces = False
    doc.recompute()
    assert engagement.isValid(), engagement.getStatusString()
    return engagement


@pytest.fixture
def doc():
    document = FreeCAD.newDocument("ABMInProcess")
    name = document.Name
    yield document
    if name in FreeCAD.listDocuments():
        FreeCAD.closeDocument(name)


@pytest.fixture(scope="module")
def computed():
    """(document, engagement) against the in-process stock, shared by the tests that only read it."""
    document = FreeCAD.newDocument("ABMInProcessShared")
    yield document, new_engagement(document)
    FreeCAD.closeDocument(document.Name)


def test_results_are_the_command_lines(computed, tmp_path):
    _, engagement = computed
    out = tmp_path / "R.csv"
    subprocess.run([sys.executable, "-m", "abm_workbench", "engage", "--stock", STOCK, "--toolpath", PROGRAM,
                    "--job", JOB, "--operation", str(OPERATION), "--phi-step", str(PHI_STEP), "--stock-model",
                    "in-process", "--out", str(out)], cwd=ROOT, check=True, capture_output=True)
    mine = engagement.ResultsFile
    for theirs, ours in ((out, mine), (summary_path(out), summary_path(mine))):
        with open(theirs, "rb") as a, open(ours, "rb") as b:
            assert a.read() == b.read(), ours
    columns, segments = read_results(out), read_results(summary_path(out))
    in_process = engagement.Proxy.in_process(engagement)
    result = engagement.Proxy.result(engagement)
    np.testing.assert_allclose(result.length.reshape(-1), columns["length"], rtol=0.0, atol=5e-11)  # 10 decimals
    np.testing.assert_allclose(in_process.initial.reshape(-1), columns["length_initial"], rtol=0.0, atol=5e-11)
    changed = np.unique(segments["cl"][segments["changed"] == 1])
    np.testing.assert_array_equal(np.flatnonzero(in_process.changed), changed)
    assert engagement.ChangedCLPoints == changed.size > 0
    assert engagement.StockModel == engagement.StockModelUsed == "in-process"


@pytest.fixture
def two_passes(doc, tmp_path):
    """The engagement of the two-pass program over the model test 1 stock (JSON), at φ step 10°."""
    program = tmp_path / "two_passes.apt"
    write_two_passes(program)
    return new_engagement(doc, MODEL_1_STOCK, str(program), 0, phi_step=10.0), str(program)


def test_lengths_agree_with_the_boolean_in_process_stock(two_passes):
    engagement, program = two_passes
    result, in_process = engagement.Proxy.result(engagement), engagement.Proxy.in_process(engagement)
    toolpath, hints = load_path(program, None)
    assert hints.frame is None  # the engine's frame is the part's: the booleans need no transform
    tool = Tool(engagement.Diameter.Value, engagement.Flutes, engagement.FluteLength.Value)
    moves, rows, _ = program_moves(hints.program, hints.operation, tool)
    np.testing.assert_allclose(moves.cl[rows], toolpath.cl, rtol=0.0, atol=1e-9)
    # the CL points where earlier moves removed the most, one of the first pass and one of the second
    removed = (in_process.initial - result.length).max(axis=1)
    chosen = sorted({*np.argsort(removed)[-2:].tolist(), 3, len(XS) + 3})
    assert removed[chosen].max() > 1.0  # the check meets material earlier moves removed
    solid = engagement.Stock.Shape
    base, direction = edge_lines(toolpath, tool, result.phi)
    for cl in chosen:
        want = inprocess_lengths(solid, moves, rows[cl], base[cl], direction[cl], tool.flute_length)
        np.testing.assert_allclose(result.length[cl], want["length"], rtol=0.0, atol=AGREE, err_msg=f"CL {cl}")
        np.testing.assert_allclose(result.lep_l[cl], want["lep_l"], rtol=0.0, atol=AGREE, err_msg=f"CL {cl}")
        np.testing.assert_allclose(result.uep_l[cl], want["uep_l"], rtol=0.0, atol=AGREE, err_msg=f"CL {cl}")
        assert in_process.changed[cl] == bool((in_process.initial[cl] - want["length"] > AGREE).any())


def test_in_process_stock_object_holds_what_the_engagement_found(two_passes):
    engagement, _ = two_passes
    result, in_process = engagement.Proxy.result(engagement), engagement.Proxy.in_process(engagement)
    cl = int(np.argmax((in_process.initial - result.length).max(axis=1)))
    doc = engagement.Document
    obj = create_inprocess_stock(doc, engagement, cl)
    doc.recompute()
    assert obj.isValid(), obj.getStatusString()
    assert obj.Shape.isValid() and obj.ProgramRow > cl  # the program's rows count its rapids too
    stock_volume = engagement.Stock.Shape.Volume
    assert obj.RemovedVolume > 0.0 and abs(stock_volume - obj.Shape.Volume - obj.RemovedVolume) < 1e-6 * stock_volume
    # the engaged parts of the edges lie inside it, where material was removed from an edge they do not
    lep, uep = result.lep_xyz[cl], result.uep_xyz[cl]
    for k in np.flatnonzero(result.pieces[cl] == 1):
        middle = 0.5 * (lep[k] + uep[k])
        assert obj.Shape.isInside(FreeCAD.Vector(*middle), 1e-7, True), f"φ {result.phi[k]:g}°"
    assert cl >= len(XS)  # in the second pass, off the first pass's flanks
    gone = np.flatnonzero((result.length[cl] == 0.0) & (in_process.initial[cl] > 0.5))
    assert gone.size > 0
    base, direction = edge_lines(load_path(engagement.Toolpath.File, None)[0],
                                 Tool(engagement.Diameter.Value, 2, engagement.FluteLength.Value), result.phi)
    for k in gone:
        points = base[cl, k] + np.linspace(0.0, engagement.FluteLength.Value, 61)[:, None] * direction[cl]
        assert not any(obj.Shape.isInside(FreeCAD.Vector(*p), -1e-7, False) for p in points), f"φ {result.phi[k]:g}°"


def test_initial_stock_and_back_takes_the_kept_results(doc, monkeypatch):
    engagement = new_engagement(doc)
    in_process = engagement.Proxy.in_process(engagement)
    engagement.StockModel = "initial"
    doc.recompute()
    assert engagement.StockModelUsed == "initial" and engagement.ChangedCLPoints == 0
    assert engagement.Proxy.in_process(engagement) is None
    assert "length_initial" not in read_results(engagement.ResultsFile)
    # the initial lengths kept with the in-process results are those against the stock as given
    np.testing.assert_allclose(engagement.Proxy.result(engagement).length, in_process.initial, rtol=0.0, atol=1e-12)

    def no_engine(*args, **kwargs):
        raise AssertionError("the engine ran again")

    monkeypatch.setattr(engagement_module, "engage_in_process", no_engine)
    engagement.StockModel = "in-process"
    doc.recompute()
    kept = engagement.Proxy.in_process(engagement)
    assert engagement.StockModelUsed == "in-process" and engagement.ChangedCLPoints == in_process.changed.sum()
    np.testing.assert_array_equal(kept.initial, in_process.initial)
    np.testing.assert_array_equal(read_in_process(engagement.ResultsFile).changed, in_process.changed)


def test_saved_document_restores_the_in_process_results(doc, tmp_path, monkeypatch):
    engagement = new_engagement(doc)
    in_process = engagement.Proxy.in_process(engagement)
    path = tmp_path / "program.FCStd"
    doc.saveAs(str(path))
    FreeCAD.closeDocument(doc.Name)
    for name in ("flute_1", "engage_in_process"):
        monkeypatch.setattr(engagement_module, name, lambda *args, **kwargs: pytest.fail("the engine ran"))
    reopened = FreeCAD.openDocument(str(path))
    try:
        engagement = reopened.getObject("Engagement")
        restored = engagement.Proxy.in_process(engagement)
        np.testing.assert_array_equal(restored.initial, in_process.initial)
        np.testing.assert_array_equal(restored.changed, in_process.changed)
        assert "Touched" not in engagement.State and engagement.StockModelUsed == "in-process"
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_helical_tool_falls_back_to_the_initial_stock_and_says_why(doc):
    engagement = new_engagement(doc, helix=30.0, phi_step=15.0)
    why = "the in-process stock is not available with a helical tool yet"
    assert engagement.StockModel == "in-process" and engagement.StockModelUsed == f"initial: {why}"
    assert why in engagement.Warnings and engagement.ChangedCLPoints == 0
    assert engagement.Proxy.in_process(engagement) is None


def test_sweep_tolerance_must_be_positive(doc):
    engagement = new_engagement(doc, stock_model="initial")
    engagement.SweepTolerance = 0.0
    engagement.StockModel = "in-process"
    with pytest.raises(InputError, match=r"Sweep tolerance must be positive, got 0 mm \(property SweepTolerance\)"):
        engagement.Proxy.execute(engagement)
