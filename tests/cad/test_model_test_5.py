"""Model test 5 as bundled: the NX CLSF reads as one bull-nose operation D16 R3 of 518 CL points with tilted axes
in its MSYS frame, the STEP stock as a 2.5D terraced stock of 7 slabs with B-spline walls; the engine agrees with
the whole-edge boolean at CL points of the first, middle and last passes; tests/cad/run_model_test_5.py writes its
report and annotated document."""

import numpy as np

from abm_workbench.cad.profile_boolean import profile_lengths_by_boolean
from abm_workbench.engine.stocks import engage_stock

from .profile_cases import TOL, differences
from .run_model_test_5 import MODEL, load, main


def test_the_bundled_files_read_as_a_bull_nose_raster():
    operation, toolpath, stock, solid, tool, settings, job, parameters, _ = load(MODEL, 6.0)
    assert (tool.kind, tool.diameter, tool.corner_radius, tool.flutes, tool.flute_length) == ("bull-nose", 16.0, 3.0,
                                                                                             4, 30.0)
    assert "TLDATA" in parameters and operation.frame.startswith("MSYS")
    assert len(toolpath) == 518 and stock.kind == "terraced" and len(stock.model.slabs) == 7
    lean = np.degrees(np.arccos(toolpath.axes[:, 2]))
    assert lean.min() < 2.0 and lean.max() > 40.0 and len(np.unique(np.round(toolpath.axes, 6), axis=0)) > 500
    assert solid.isValid() and settings.spindle_rpm == 8000.0


def test_the_engine_agrees_with_the_boolean_on_model_test_5():
    _, toolpath, stock, solid, tool, settings, *_ = load(MODEL, 6.0)
    part = toolpath.rows(np.array([40, 150, 268, 440]))
    engagement = engage_stock(stock.model, tool, part, settings)
    reference = profile_lengths_by_boolean(solid, tool, part, settings.phi)
    reference.pop("disputed")
    assert max(differences(engagement, reference).values()) < TOL
    assert engagement.engaged.mean() > 0.8 and (engagement.end_length > 0.0).any()


def test_the_script_writes_its_report(tmp_path, capsys):
    report, document = tmp_path / "validation", tmp_path / "validation.FCStd"
    assert main(["--report", str(report), "--fcstd", str(document), "--check", "150", "--cl", "150",
                 "--phi-step", "30", "--removed-every", "1000"]) == 0
    out = capsys.readouterr().out
    assert "max |ABM - boolean|" in out and "What this leaves out" in out
    page = (report / "index.html").read_text()
    assert "bull-nose mill D 16 mm, corner radius 3 mm" in page and "What this leaves out" in page
    assert (report / "comparison.csv").exists() and document.stat().st_size > 0
