"""Model test 5 against OpenCASCADE, through the Python API: `make model-test-5` runs

    /usr/bin/python3 -m tests.cad.run_model_test_5 --report build/model_test_5/validation \\
        --fcstd build/model_test_5/validation.FCStd [--cl 0,130,300] [--check-every N] [--phi-step DEG] [--workers N]

It reads resources/models/model_test_5/: the NX CLSF toolpath.cls (its one operation: the tool from
TLDATA/MILL, diameter and corner radius; the CL points in the MSYS frame, each with its own axis and its
frame turned to its feed), stock.step (recognised as a 2.5D terraced stock, moved into that frame) and
job.json (flutes, flute length, feed per tooth, rotation angles), runs validation.validate (the engine
against cad.profile_boolean's reference: corner arcs, sides and end edges sectioned with the solid), and
writes the HTML report (report.html's folder with its CSV tables) and the annotated FreeCAD document. It
prints the largest |ABM − boolean| per field and the timings.

The command line's validate reads the same files (`abm validate --job resources/models/model_test_5/job.json
--stock resources/models/model_test_5/stock.json --toolpath resources/models/model_test_5/toolpath.cls
--stock-model initial ...`); this script adds, with --removed-every, the estimate of what earlier passes remove
from the edges (cad.profile_inprocess), which the command line does not give.
"""

import argparse
import os
import re
import sys
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
if ROOT not in sys.path:
    sys.path.insert(0, ROOT)

MODEL = os.path.join(ROOT, "resources", "models", "model_test_5")


def arguments(argv=None):
    parser = argparse.ArgumentParser(prog="run_model_test_5", description=__doc__.split("\n\n")[0])
    parser.add_argument("--report", required=True, help="report folder to write")
    parser.add_argument("--fcstd", help="annotated FreeCAD document to write")
    parser.add_argument("--cl", help="CL points shown in detail, e.g. 40,200,480 (default: chosen)")
    parser.add_argument("--check", help="CL points the boolean checks, e.g. 0,10-20 (default: all)")
    parser.add_argument("--check-every", type=int, help="the boolean checks every N-th CL point (and --check, --cl)")
    parser.add_argument("--phi-step", type=float, help="rotation angle step (deg), default the job's")
    parser.add_argument("--workers", type=int, default=1, help="processes computing the boolean (0: one per core)")
    parser.add_argument("--removed-every", type=int, default=0, metavar="N",
                        help="estimate what earlier moves removed from the edges (cad.profile_inprocess) at every "
                             "N-th CL point and the shown ones, for the report (0: not)")
    parser.add_argument("--model", default=MODEL, help=argparse.SUPPRESS)
    return parser.parse_args(argv)


def load(model, phi_step=None):
    """(operation, Toolpath, Stock, Tool, CutSettings, job dict, parameters text, stock seconds) of the model."""
    from abm_workbench.engine import CutSettings, Tool
    from abm_workbench.formats.cl import read_program
    from abm_workbench.jobs.inputs import load_job, load_stock

    job = load_job(os.path.join(model, "job.json"))
    program = read_program(os.path.join(model, "toolpath.cls"))
    if len(program.operations) != 1:
        raise SystemExit(f"{program.source}: expected one operation, found {len(program.operations)}")
    operation = program.operations[0]
    spec = operation.tool
    if spec.kind not in ("flat", "bull-nose", "ball") or spec.diameter is None:
        raise SystemExit(f"{program.source}: {spec.describe()}: not a mill this script validates")
    toolpath = operation.toolpath()
    rotation, translation = frame = operation.engine_frame()
    same = np.array_equal(rotation, np.eye(3)) and not np.any(translation)
    started = time.perf_counter()
    stock = load_stock(os.path.join(model, "stock.step"), frame=None if same else frame)
    solid = stock.solid()
    stock_seconds = time.perf_counter() - started
    tool = Tool(spec.diameter, job["flutes"], job["flute_length"], corner_radius=spec.corner_radius or 0.0)
    settings = CutSettings(job["feed_per_tooth"], 0.0, job.get("phi_start", 0.0), job.get("phi_end", 180.0),
                           phi_step if phi_step is not None else job.get("phi_step", 1.0), operation.spindle_rpm)
    records = ", ".join(spec.records)
    parameters = (f"{spec.describe()} [{records}]; flutes {tool.flutes}, flute length {tool.flute_length:g} mm, "
                  f"feed {settings.feed_per_tooth:g} mm/tooth [job.json]; spindle {operation.spindle_rpm:g} rpm "
                  f"[SPINDL]; each CL point's inclination to its feed and frame from the file's moves; frame: "
                  f"{operation.frame or 'the file'}")
    return operation, toolpath, stock, solid, tool, settings, job, parameters, stock_seconds


def removal_estimate(operation, toolpath, solid, tool, settings, cls):
    """cad.profile_inprocess.removed_lengths at CL points `cls`: the program's moves in the engine frame."""
    from abm_workbench.cad.profile_inprocess import removed_lengths
    from abm_workbench.formats.cl import read_program
    from abm_workbench.jobs.inputs import program_moves

    program = read_program(operation.source)
    chosen = program.operations[operation.number - 1]
    moves, rows, _ = program_moves(program, chosen, tool)
    moves = moves.transformed(*chosen.engine_frame())
    return removed_lengths(solid, tool, toolpath, settings.phi, moves, rows, cls)


def removal_words(estimate, phi):
    """The estimate in words, for the report and the console."""
    from abm_workbench.cad.profile_inprocess import EDGE_STEP, POSITION_STEP

    removed = estimate.removed
    hit = (removed > 2.0 * EDGE_STEP).any(axis=1) | (estimate.end_removed > 2.0 * EDGE_STEP).any(axis=1)
    n, j = np.unravel_index(np.argmax(removed), removed.shape)
    share = removed.sum() / max(estimate.given.sum(), 1e-12)
    return (f"What this leaves out, estimated at {len(estimate.cls)} CL points (every N-th and those shown; "
            f"cad.profile_inprocess: the exact intervals in the stock as given, less their points, {EDGE_STEP:g} mm "
            f"apart, inside the tool at an earlier position of the program, positions {POSITION_STEP:g} mm apart at "
            f"the rim): earlier moves took material from the cutting edges at {int(hit.sum())} of them, where the "
            f"stock as given overstates the length of cut by up to {removed.max():.3g} mm (CL {estimate.cls[n]}, "
            f"phi {phi[j]:g} deg) and the end edge's by up to {estimate.end_removed.max():.3g} mm; over the "
            f"{len(estimate.cls)} CL points, {100.0 * share:.1f} % of the length of cut in the stock as given lies in "
            f"material earlier moves removed. The estimate is within {2 * EDGE_STEP:g} mm per removed run.")


def main(argv=None):
    begun = time.perf_counter()
    args = arguments(argv)
    from abm_workbench.cad.annotate import write_annotated
    from abm_workbench.jobs.checked import checked_cls
    from abm_workbench.jobs.job import cl_indices
    from abm_workbench.report.html import ReportJob, report_cls, write_report
    from abm_workbench.validation import overall, validate

    operation, toolpath, stock, solid, tool, settings, job, parameters, stock_seconds = load(args.model,
                                                                                               args.phi_step)
    m = len(toolpath)
    shown = cl_indices(args.cl, m) if args.cl else None
    checking = checked_cls(args.check, args.check_every, shown, m)
    print(f"model test 5: {m} CL points, {settings.phi.size} angles, {tool.kind} D {tool.diameter:g} R "
          f"{tool.corner_radius:g}, {stock.describe()}; checking {m if checking is None else len(checking)} CL points",
          flush=True)
    started = time.perf_counter()
    last = [0.0]

    def progress(done, total):
        now = time.perf_counter()
        if now - last[0] > 10.0 or done == total:
            last[0] = now
            print(f"  boolean: {done}/{total} CL points, {now - started:.0f} s", flush=True)

    result = validate(solid, stock.model, tool, toolpath, settings, cls=checking, workers=args.workers,
                      progress=progress)
    total = overall(result.comparison)
    comparison = result.comparison
    checked = comparison.checked
    depth = np.abs(comparison.depth_abm - comparison.depth_ref)[result.checked]
    worst = {
        "length": total["max_abs_difference"], "lep_l": total["max_lep_difference"],
        "uep_l": total["max_uep_difference"], "end_length": total["max_end_difference"],
        "depth": float(np.nanmax(depth)) if np.isfinite(depth).any() else np.nan,
    }
    engaged = int((checked & (comparison.l_ref > 0.0)).sum())
    note = ("initial: the stock as given. The raster's "
            f"passes overlap (stepover 8 mm, tool D {tool.diameter:g} mm): from the second pass on, the stock as "
            "given still holds material the earlier passes removed, so these lengths are those of each CL point "
            "met as if its pass came first; what both sides compute here is the same geometry, and it is that "
            "they are checked on.")
    if args.removed_every:
        picked = sorted(set(range(0, m, args.removed_every)) | {cl for cl, _ in report_cls(result, shown)})
        started = time.perf_counter()
        estimate = removal_estimate(operation, toolpath, solid, tool, settings, picked)
        words = removal_words(estimate, settings.phi)
        note += " " + words
        print(words + f" ({time.perf_counter() - started:.0f} s)")
    report_job = ReportJob(
        f"ABM against booleans: model test 5 ({os.path.basename(operation.source)}, {operation.label()})",
        job.get("description", ""), os.path.join(args.model, "stock.step"), os.path.join(args.model, "toolpath.cls"),
        toolpath, tool, settings, parameters, stock.describe(), None, stock_seconds, note)
    chosen = report_cls(result, shown)
    for path in [args.report] + ([args.fcstd] if args.fcstd else []):
        os.makedirs(os.path.dirname(os.path.abspath(path)) or ".", exist_ok=True)
    os.makedirs(args.report, exist_ok=True)
    write_report(args.report, result, report_job, chosen)
    if args.fcstd:
        name = re.sub(r"[^A-Za-z0-9_]", "_", os.path.splitext(os.path.basename(args.fcstd))[0])
        write_annotated(args.fcstd, f"ABM_{name}", solid, result.engagement, toolpath, tool,
                        cls=[cl for cl, _ in chosen], intersections=[cl for cl, _ in chosen])
    p = settings.phi.size
    print(f"checked {int(result.checked.sum())} of {m} CL points x {p} angles = {int(checked.sum())} instants "
          f"({engaged} engaged by the boolean, {total['relative_instants']} with l_ref >= 1e-3 mm)")
    print("max |ABM - boolean|: " + ", ".join(f"{name} {value:.3g} mm" for name, value in worst.items()))
    print(f"max relative error {total['max_rel_error']:.3g}; mismatched instants {total['mismatched']} (peripheral), "
          f"{total['end_mismatched']} (end edge)")
    print(f"ABM {result.seconds['abm']:.3g} s, boolean {result.seconds['boolean']:.4g} s "
          f"({result.speed_ratio:.0f}x); stock {stock_seconds:.3g} s; shown CL {[cl for cl, _ in chosen]}; edges the "
          f"two local booleans disputed: {int(np.nansum(result.reference['disputed']))}")
    print(f"wrote {os.path.join(args.report, 'index.html')}" + (f" and {args.fcstd}" if args.fcstd else "")
          + f"; {time.perf_counter() - begun:.0f} s in all")
    return 0


if __name__ == "__main__":
    sys.exit(main())
