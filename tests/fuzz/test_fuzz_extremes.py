"""Fuzz tier, values the readers accept but no machine can run (issue #29): each under a memory limit.

Every case runs ``python -m abm_workbench`` in a child limited to harness.MEMORY bytes of address space
(``resource.setrlimit``) and a time limit, and must end within seconds with one error line (or, where the
run is small enough after all, its results): the run's work and memory are estimated before it starts
(abm_workbench.limits), a program's arcs and curves are interpolated within a budget of CL points, the
in-process stock's sweep is counted before it is made, and no number of the command line or the files
makes an allocation of gigabytes to terabytes, an integer overflow or a loop without end.
"""

import os

import pytest

from tests.fuzz.harness import MODEL_1, abm, check_promises, copy_inputs, snapshot

INPUTS = {name: os.path.join(MODEL_1, name) for name in ("stock.json", "toolpath.csv", "job.json")}
ENGAGE = ["engage", "--stock", "stock.json", "--toolpath", "toolpath.csv", "--job", "job.json", "--phi-step", "30",
          "--out", "out/R.csv"]

#: (extra options of engage, text the error must hold); None: the run may succeed.
EXTREME_OPTIONS = {
    "a 1e12 mm tool (in-process sweep)": (["--diameter", "1e12"], "the in-process stock would sweep"),
    "a 1e-300 mm tool (in-process sweep)": (["--diameter", "1e-300"], "the in-process stock"),
    "a 1e12 mm flute (in-process sweep)": (["--flute-length", "1e12"], "the in-process stock"),
    "a sweep tolerance of 1e-6 mm": (["--sweep-tolerance", "1e-6"], "--sweep-tolerance"),
    "a 1e-300 mm tool against the stock as given": (["--diameter", "1e-300", "--stock-model", "initial"], None),
    "10^6 angles": (["--phi-step", "0.00018"], "angles"),
    "10^6 angles drawn": (["--phi-step", "0.00018", "--plot", "out/R.png"], "angles"),
    "more than 10^6 angles": (["--phi-step", "1e-4"], "--phi-step"),
    "100,000 workers": (["--workers", "100000", "--stock-model", "initial"], None),
    "a Z-map grid of 1e-6 mm": (["--method", "zmap", "--grid", "1e-6", "--stock-model", "initial"], "--grid"),
    "a Z-map edge step of 1e-9 mm": (["--method", "zmap", "--edge-step", "1e-9", "--stock-model", "initial"],
                                     "--edge-step"),
    "a Z-map edge step of 1e-5 mm": (["--method", "zmap", "--edge-step", "1e-5", "--stock-model", "initial"],
                                     "--edge-step"),
    "a chordal tolerance of 1e-16 mm": (["--tolerance", "1e-16"], "--tolerance"),
    "a chordal tolerance of 1e300 mm": (["--tolerance", "1e300"], "--tolerance"),
    "a step of 1e-15 mm": (["--step", "1e-15"], "--step"),
}


@pytest.mark.parametrize("label", sorted(EXTREME_OPTIONS))
def test_extreme_options_end_at_once_under_a_memory_limit(tmp_path, label):
    extra, message = EXTREME_OPTIONS[label]
    copy_inputs(str(tmp_path), INPUTS)
    before = snapshot(tmp_path)
    done = abm(ENGAGE + extra, tmp_path, timeout=180)
    check_promises(done, before, snapshot(tmp_path), names=["toolpath.csv", "stock.json"],
                   outputs=["out", "out/R.csv", "out/R.summary.csv"])
    if message is not None:
        assert done.status == 2 and message in done.errors[0], done.err
        assert done.seconds < 60, f"refused only after {done.seconds:.0f} s"


#: (file name, text, extra options of `toolpath`, text the error must hold): CL files and G-code whose
#: numbers are all within the readers' bound of 1e12 but whose arcs and curves have no end.
EXTREME_PROGRAMS = {
    "a circle of radius 1e9 mm": (
        "big.apt", "UNITS/MM\nCUTTER/12\nGOTO/1e9,0,0\nCIRCLE/0,0,0,0,0,1,1e9\nGOTO/1e9,0,0\nFINI\n", [],
        "big.apt:5: GOTO: the arc of the CIRCLE on line 4: interpolating it"),
    "a circle at a tolerance of 1e-6 mm and step of 1e-6 mm": (
        "fine.apt", "UNITS/MM\nCUTTER/12\nGOTO/100,0,0\nCIRCLE/0,0,0,0,0,1,100\nGOTO/100,0,0\nFINI\n",
        ["--tolerance", "1e-6", "--step", "1e-6"], "fine.apt:5: GOTO"),
    "many circles together": (
        "many.apt", "UNITS/MM\nCUTTER/12\nGOTO/100,0,0\n" + "CIRCLE/0,0,0,0,0,1,100\nGOTO/100,0,0\n" * 400 + "FINI\n",
        ["--step", "0.01"], "many.apt:67: GOTO: the arc of the CIRCLE on line 66"),
    "a NURBS of 1e11 mm": (
        "curve.cls", "MULTAX\nGOTO/0,0,0,0,0,1\nNURBS/3\nKNOT/0,0,0,1,1,1\nCNTRL/0,0,0\nCNTRL/1e11,1e11,0\n"
                     "CNTRL/2e11,0,0\nGOTO/2e11,0,0,0,0,1\n", [], "curve.cls:3"),
    "a G-code arc of radius 1e9 mm": (
        "arc.ngc", "G21 G90 G17\nT1 M6\nG0 X1000000000 Y0 Z0\nG3 X1000000000 Y0 I-1000000000 J0 F100\nM30\n",
        ["--tool-table", "tools.tbl"], "arc.ngc:4"),
    "a G-code helix of 1e12 turns": (
        "turns.ngc", "G21 G90 G17\nT1 M6\nG0 X10 Y0 Z0\nG3 X10 Y0 Z1 I-10 J0 P1000000000000 F100\nM30\n",
        ["--tool-table", "tools.tbl"], "turns.ngc:4"),
    "a table turned by 1e12 degrees": (
        "table.apt", "UNITS/MM\nCUTTER/12\nMULTAX/ON\nROTABL/1e12,CAXIS\nGOTO/0,0,0,0,0,1\nGOTO/1,0,0,0,0,1\nFINI\n",
        [], "table.apt:4: ROTABL"),
}


@pytest.mark.parametrize("label", sorted(EXTREME_PROGRAMS))
def test_extreme_programs_end_at_once_under_a_memory_limit(tmp_path, label):
    name, text, extra, message = EXTREME_PROGRAMS[label]
    (tmp_path / name).write_text(text)
    (tmp_path / "tools.tbl").write_text("T1 P1 D12 Z30 ;flat end mill\n")
    before = snapshot(tmp_path)
    done = abm(["toolpath", name, "--out", "P.csv", *extra], tmp_path, timeout=180)
    check_promises(done, before, snapshot(tmp_path), names=[name])
    assert done.status == 2 and done.errors[0].startswith(f"abm: error: {message}"), done.err
    assert done.seconds < 60, f"refused only after {done.seconds:.0f} s"


def test_a_move_of_1e12_mm_is_refused_by_the_in_process_stock_and_computed_without_it(tmp_path):
    copy_inputs(str(tmp_path), INPUTS)
    lines = (tmp_path / "toolpath.csv").read_text().splitlines()
    lines.append("999999999999," + ",".join(lines[-1].split(",")[1:]))
    (tmp_path / "toolpath.csv").write_text("\n".join(lines) + "\n")
    before = snapshot(tmp_path)
    done = abm(ENGAGE, tmp_path, timeout=180)
    check_promises(done, before, snapshot(tmp_path), names=["toolpath.csv"])
    assert done.status == 2 and "toolpath.csv: the in-process stock would sweep" in done.errors[0], done.err
    done = abm(ENGAGE + ["--stock-model", "initial"], tmp_path, timeout=180)
    assert done.status == 0, done.err


def test_allow_large_lets_a_large_run_through_but_not_past_the_memory(tmp_path):
    """--sweep-tolerance 1e-4 (a sweep of a few million pieces) runs; 1e-6 is refused as large, and with
    --allow-large still refused where its memory is beyond the limit."""
    copy_inputs(str(tmp_path), INPUTS)
    done = abm(ENGAGE + ["--sweep-tolerance", "1e-4"], tmp_path, timeout=300)
    assert done.status == 0, done.err
    done = abm(ENGAGE + ["--sweep-tolerance", "1e-7", "--allow-large"], tmp_path, timeout=180, memory=2 << 30)
    assert done.status == 2 and "of memory, and this process may use" in done.errors[0], done.err


#: A results CSV of 4 MB whose one long field made the reader build a 4.2 GB table, and others.
def _wide_csv():
    header = "cl,phi_deg,length"
    return header + "\n" + "0,0," + "1" * 4_000_000 + "\n" + "0,1,2\n" * 1000


READER_CASES = {
    "a 4 MB field": _wide_csv,
    "an integer of 40 digits": lambda: "cl,phi_deg\n" + "9" * 40 + ",0\n",
    "a header of 100,000 columns": lambda: ",".join(f"c{i}" for i in range(100_000)) + "\n",
}


@pytest.mark.parametrize("label", sorted(READER_CASES))
def test_the_results_csv_reader_stays_within_memory(tmp_path, label):
    (tmp_path / "R.csv").write_text(READER_CASES[label]())
    script = ("import sys\nfrom abm_workbench.errors import InputError\n"
              "from abm_workbench.formats.results_csv import read_results\n"
              "try:\n    read_results('R.csv')\nexcept InputError as error:\n    print(error)\n")
    done = _python(script, tmp_path)
    assert done.returncode == 0 and done.stdout.startswith("R.csv:"), done.stderr


def _python(script, cwd, memory=1 << 30):
    import subprocess
    import sys

    from tests.fuzz.harness import environment, limited

    return subprocess.run([sys.executable, "-c", script], cwd=cwd, capture_output=True, text=True, timeout=120,
                          env=environment(), preexec_fn=limited(memory))
