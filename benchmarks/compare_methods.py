"""ABM, the Z-map and the OpenCASCADE boolean side by side: engine time and error against the boolean.

Run with FreeCAD's Python from the repository root (about 2-3 minutes, mostly the booleans):

    /usr/bin/python3 benchmarks/compare_methods.py

For each bundled model test (resources/models/model_test_{1,2}: stock.step with its true
contour walls, toolpath.csv, job.json; 53 CL points x 181 angles at 1 deg), in one process:

- ABM, quintic walls: stock.step recognised with walls="quintic" over the swept y window
  (``swept_y_window``), as the command line does by default for --walls quintic;
- ABM, exact walls: stock.step recognised with walls="exact" (the solid's own wall curves);
- the Z-map (``zmap_engage``, edge step = grid, removal along the pass as on the command line)
  at 0.2, 0.1 and 0.05 mm, on the exact-wall staircase: the same true stock as the boolean;
- the boolean reference (``edge_lengths_by_boolean``) on the STEP solid itself.

Times are engine time only (the stock, toolpath and job are loaded before the clock starts):
the best of --abm-repeats runs for ABM, of --zmap-repeats runs for the Z-map (one warm-up run
each first), one run for the boolean. Errors are those of abm_workbench.validation.compare
against the boolean: |l - l_ref| (mm) over every instant, the relative error (l - l_ref)/l_ref
where l_ref >= TINY_LENGTH (1e-3 mm), the absolute difference where l_ref is smaller; and per
UEP surface kind (top, straight_wall, curved_wall) with validation.surface_summary. The
boolean does not name surfaces, so the kind of each instant is the one exact-wall ABM gives
(its UEP matches the reference's to within the printed "UEP check"); every method is thus
summarised over the same instants.

Writes build/benchmarks/compare_methods.csv (one row per model test, method and scope: all
instants or one surface kind) and build/benchmarks/error_vs_time.png (max |l - l_ref| against
engine time, log-log, one point per method and model test).
"""

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")  # one core, before numpy is imported

import argparse  # noqa: E402
import csv  # noqa: E402
import functools  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from abm_workbench.engine import CutSettings, Tool, engage, zmap_engage  # noqa: E402
from abm_workbench.jobs import load_job, load_stock, swept_y_window  # noqa: E402
from abm_workbench.formats.toolpath_csv import load_toolpath  # noqa: E402
from abm_workbench.validation import TINY_LENGTH, compare, overall, surface_summary  # noqa: E402

MODELS = os.path.join(ROOT, "resources", "models")
OUT = os.path.join(ROOT, "build", "benchmarks")
GRIDS = (0.2, 0.1, 0.05)
KINDS = ("top", "straight_wall", "curved_wall")


def load_model(number):
    """(name, tool, toolpath, settings, quintic Stock, exact Stock) of model test `number`."""
    folder = os.path.join(MODELS, f"model_test_{number}")
    job = load_job(os.path.join(folder, "job.json"))
    tool = Tool(job["diameter"], int(job["flutes"]), job["flute_length"])
    settings = CutSettings(job["feed_per_tooth"], job["inclination"], job["phi_start"], job["phi_end"], job["phi_step"],
                           job.get("spindle_rpm"))
    toolpath = load_toolpath(os.path.join(folder, "toolpath.csv"))
    step = os.path.join(folder, "stock.step")
    quintic = load_stock(step, walls="quintic", y_window=functools.partial(swept_y_window, toolpath, tool))
    exact = load_stock(step, walls="exact")
    return f"model test {number}", tool, toolpath, settings, quintic, exact


def timed(run, repeats):
    """(result, best seconds, median seconds) of `run()` over `repeats` timed runs after one warm-up."""
    result = run()
    times = []
    for _ in range(repeats):
        started = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - started)
    return result, float(np.min(times)), float(np.median(times))


def statistics(comparison, engagement_for_kinds):
    """{scope: dict of error statistics}: 'all' and each surface kind present (validation functions)."""
    total = overall(comparison)
    tiny = ~comparison.relative
    rows = {"all": {**total, "mean_abs_difference": float(np.abs(comparison.difference).mean()),
                    "max_abs_tiny": float(np.abs(comparison.difference[tiny]).max()) if tiny.any() else np.nan,
                    "tiny_instants": int(tiny.sum())}}
    for row in surface_summary(engagement_for_kinds, comparison):
        if row["surface"] in KINDS:
            mask = engagement_for_kinds.uep_surface == KINDS.index(row["surface"]) + 1
            small = mask & tiny
            rows[row["surface"]] = {
                **row, "mean_abs_difference": float(np.abs(comparison.difference[mask]).mean()),
                "max_abs_tiny": float(np.abs(comparison.difference[small]).max()) if small.any() else np.nan,
                "tiny_instants": int(small.sum())}
    return rows


def fmt(value, digits=3):
    return "-" if value is None or not np.isfinite(value) else f"{value:.{digits}g}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--abm-repeats", type=int, default=20)
    parser.add_argument("--zmap-repeats", type=int, default=3)
    parser.add_argument("--models", default="1,2", help="model tests to run, e.g. 1,2")
    parser.add_argument("--out", default=OUT, help="output folder (default build/benchmarks)")
    args = parser.parse_args()
    from abm_workbench.cad.boolean import edge_lengths_by_boolean  # FreeCAD

    os.makedirs(args.out, exist_ok=True)
    records, ratios = [], []
    started_all = time.perf_counter()
    for number in [int(n) for n in args.models.split(",")]:
        name, tool, toolpath, settings, quintic, exact = load_model(number)
        m, p = len(toolpath), settings.phi.size
        n = m * p
        print(f"{name}: {m} CL x {p} phi = {n} instants; quintic y window "
              f"{quintic.y_window[0]:.3f}..{quintic.y_window[1]:.3f} mm, exact {exact.y_window[0]:g}.."
              f"{exact.y_window[1]:g} mm", flush=True)
        methods = []  # (method, engagement, best s, median s, repeats)
        for label, stock in (("ABM quintic", quintic), ("ABM exact", exact)):
            result, best, median = timed(lambda s=stock: engage(s.staircase, tool, toolpath, settings),
                                         args.abm_repeats)
            methods.append((label, result, best, median, args.abm_repeats))
            print(f"  {label}: best {best * 1e3:.2f} ms, median {median * 1e3:.2f} ms", flush=True)
        for grid in GRIDS:
            result, best, median = timed(
                lambda g=grid: zmap_engage(exact.staircase, tool, toolpath, settings, grid=g), args.zmap_repeats)
            methods.append((f"Z-map {grid:g} mm", result, best, median, args.zmap_repeats))
            print(f"  Z-map {grid:g} mm: best {best * 1e3:.1f} ms, median {median * 1e3:.1f} ms", flush=True)
        started = time.perf_counter()
        reference = edge_lengths_by_boolean(exact.shape, tool, toolpath, settings.phi)
        boolean_seconds = time.perf_counter() - started
        print(f"  boolean: {boolean_seconds:.1f} s", flush=True)

        labels = methods[1][1]  # exact-wall ABM names the UEP surface kind of each instant
        uep_check = compare(labels, reference, toolpath, tool)
        uep_gap = float(np.nanmax(np.abs(uep_check.uep_difference)))
        for label, result, best, median, repeats in methods:
            comparison = compare(result, reference, toolpath, tool)
            for scope, stats in statistics(comparison, labels).items():
                records.append({"model": name, "method": label, "scope": scope, "instants_total": n,
                                "repeats": repeats, "best_s": best, "median_s": median,
                                "instants_per_s": n / best, **stats})
        records.append({"model": name, "method": "boolean", "scope": "all", "instants_total": n, "repeats": 1,
                        "best_s": boolean_seconds, "median_s": boolean_seconds,
                        "instants_per_s": n / boolean_seconds, "instants": n})
        t = {label: best for label, _, best, _, _ in methods}
        by = {r["method"]: r for r in records if r["model"] == name and r["scope"] == "all"}
        ratios.append({
            "model": name, "uep_gap": uep_gap,
            "zmap02_over_abm_quintic": t["Z-map 0.2 mm"] / t["ABM quintic"],
            "zmap02_over_abm_exact": t["Z-map 0.2 mm"] / t["ABM exact"],
            "boolean_over_abm_quintic": boolean_seconds / t["ABM quintic"],
            "boolean_over_abm_exact": boolean_seconds / t["ABM exact"],
            "abm_quintic_per_s": n / t["ABM quintic"], "abm_exact_per_s": n / t["ABM exact"],
            "quintic_more_accurate_max": by["ABM quintic"]["max_abs_difference"] < by["Z-map 0.2 mm"]["max_abs_difference"],
            "quintic_more_accurate_mean": by["ABM quintic"]["mean_abs_difference"] < by["Z-map 0.2 mm"]["mean_abs_difference"],
        })
    total_seconds = time.perf_counter() - started_all

    # The table.
    print()
    print(f"machine: {platform.node()}, {os.cpu_count()} CPUs, {platform.processor() or platform.machine()}, "
          f"load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}; python {platform.python_version()}, "
          f"numpy {np.__version__}; whole run {total_seconds:.0f} s")
    head = (f"{'model':<13} {'method':<13} {'time (best)':>12} {'median':>10} {'instants/s':>11} "
            f"{'max|dl| mm':>10} {'mean|dl| mm':>11} {'max rel':>9} {'mean rel':>9} {'max|dl| tiny':>12}")
    print(head)
    print("-" * len(head))
    for r in records:
        if r["scope"] != "all":
            continue
        boolean = r["method"] == "boolean"
        time_text = f"{r['best_s']:.1f} s" if boolean else f"{r['best_s'] * 1e3:.2f} ms"
        median_text = "(1 run)" if boolean else f"{r['median_s'] * 1e3:.2f} ms"
        if boolean:
            errors = f"{'reference':>10}"
        else:
            errors = (f"{fmt(r['max_abs_difference']):>10} {fmt(r['mean_abs_difference']):>11} "
                      f"{fmt(100 * r['max_rel_error']) + ' %':>9} {fmt(100 * r['mean_rel_error']) + ' %':>9} "
                      f"{fmt(r['max_abs_tiny']):>12}")
        print(f"{r['model']:<13} {r['method']:<13} {time_text:>12} {median_text:>10} "
              f"{r['instants_per_s']:>11.3g} {errors}")
    print(f"(relative error over instants with l_ref >= {TINY_LENGTH:g} mm; 'tiny': max |l - l_ref| mm "
          f"over the others)")
    print()
    print("per UEP surface kind (from exact-wall ABM): max / mean |relative error| %, max |dl| mm, instants")
    head = f"{'model':<13} {'method':<13}" + "".join(f" {kind:>32}" for kind in KINDS)
    print(head)
    print("-" * len(head))
    for model in dict.fromkeys(r["model"] for r in records):
        for method in dict.fromkeys(r["method"] for r in records if r["model"] == model and r["method"] != "boolean"):
            cells = []
            for kind in KINDS:
                found = [r for r in records if r["model"] == model and r["method"] == method and r["scope"] == kind]
                if found:
                    r = found[0]
                    cells.append(f"{fmt(100 * r['max_rel_error'])}/{fmt(100 * r['mean_rel_error'])} %, "
                                 f"{fmt(r['max_abs_difference'])} mm, {r['instants']}")
                else:
                    cells.append("-")
            print(f"{model:<13} {method:<13}" + "".join(f" {c:>32}" for c in cells))
    print()
    print("ratios (same run):")
    for q in ratios:
        print(f"  {q['model']}: Z-map 0.2 mm / ABM quintic {q['zmap02_over_abm_quintic']:.1f}x "
              f"(/ ABM exact {q['zmap02_over_abm_exact']:.1f}x); boolean / ABM quintic "
              f"{q['boolean_over_abm_quintic']:.3g}x (/ ABM exact {q['boolean_over_abm_exact']:.3g}x); "
              f"ABM {q['abm_quintic_per_s']:.3g} instants/s quintic, {q['abm_exact_per_s']:.3g} exact; "
              f"ABM quintic more accurate than Z-map 0.2 mm: max {q['quintic_more_accurate_max']}, "
              f"mean {q['quintic_more_accurate_mean']}; UEP check |uep exact ABM - uep ref| <= "
              f"{q['uep_gap']:.2g} mm")
    print()
    print("targets (issue):")
    checks = [
        ("ABM >= 100x faster than the Z-map at 0.2 mm", "zmap02_over_abm_quintic", 100.0),
        ("ABM >= 10^4x faster than the boolean", "boolean_over_abm_quintic", 1e4),
        ("ABM >= 10^6 instants/s on one core", "abm_quintic_per_s", 1e6),
    ]
    for text, key, target in checks:
        values = ", ".join(f"{q[key]:.3g}" for q in ratios)
        met = all(q[key] >= target for q in ratios)
        print(f"  {text} (ABM quintic): {values} -> {'met' if met else 'NOT met'}")
    accurate = all(q["quintic_more_accurate_max"] and q["quintic_more_accurate_mean"] for q in ratios)
    print(f"  ABM quintic more accurate than the Z-map at 0.2 mm (max and mean |dl|): "
          f"{'met' if accurate else 'NOT met'}")

    # The CSV.
    fields = ["model", "method", "scope", "instants_total", "repeats", "best_s", "median_s", "instants_per_s",
              "instants", "relative_instants", "tiny_instants", "max_abs_difference", "mean_abs_difference",
              "max_rel_error", "mean_rel_error", "max_abs_tiny", "max_lep_difference", "max_uep_difference",
              "mismatched"]
    table = os.path.join(args.out, "compare_methods.csv")
    with open(table, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=fields, extrasaction="ignore")
        writer.writeheader()
        for r in records:
            writer.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
    ratio_table = os.path.join(args.out, "compare_methods_ratios.csv")
    with open(ratio_table, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(ratios[0]))
        writer.writeheader()
        for q in ratios:
            writer.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in q.items()})

    # The plot.
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    figure = Figure(figsize=(8, 5.5), dpi=110)
    FigureCanvasAgg(figure)
    axes = figure.add_subplot(1, 1, 1)
    floor = 1e-12
    markers = {"model test 1": "o", "model test 2": "s"}
    colours = {"ABM quintic": "tab:blue", "ABM exact": "tab:green", "Z-map 0.2 mm": "tab:red",
               "Z-map 0.1 mm": "tab:orange", "Z-map 0.05 mm": "tab:brown"}
    for r in records:
        if r["scope"] != "all" or r["method"] == "boolean":
            continue
        error = max(r["max_abs_difference"], floor)
        axes.loglog([r["best_s"]], [error], markers.get(r["model"], "^"), color=colours.get(r["method"], "k"),
                    markersize=8, label=f"{r['method']}, {r['model']}")
        second = r["model"].endswith("2")
        axes.annotate(f"{r['method']} ({r['model'][-1]})", (r["best_s"], error), textcoords="offset points",
                      xytext=(6, -10 if second else 5), fontsize=7)
    for r in records:
        if r["method"] == "boolean":
            axes.axvline(r["best_s"], color="grey", linestyle=":" if r["model"].endswith("1") else "--",
                         label=f"boolean (reference), {r['model']}: {r['best_s']:.0f} s")
    axes.set_xlabel("engine time (s, best of repeats; log)")
    axes.set_ylabel("max |l − l_ref| over all instants (mm; log)")
    axes.set_title("Length of cut against the OpenCASCADE boolean: error vs time\n"
                   f"53 CL × 181 φ per model test; {os.cpu_count()}-CPU machine")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=7, loc="best")
    figure.tight_layout()
    plot = os.path.join(args.out, "error_vs_time.png")
    figure.savefig(plot)
    print()
    print(f"wrote {table}, {ratio_table}, {plot}")


if __name__ == "__main__":
    main()
