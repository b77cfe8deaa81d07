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

With --peers (``make compare-peers`` runs it in a virtual environment that has the peer's
packages), it compares instead ABM exact, ABM quintic, the Z-map at 0.2 mm and the independent
mesh ray-casting peer (benchmarks/peer_raycast.py) at 0.01 and 0.001 mm chordal deviation, on
both model tests, at the pass's 53 CL points and at the pass resampled to 5,000 CL points (the
same stock; 905,000 instants). Each method runs in a child process of its own, so that its peak
memory is the child's resident set (native memory such as Embree's BVH included); its time is
split into preparation (reading and recognising the STEP solid, or tessellating it and building
the mesh and BVH) and the engagement itself (best of --peer-repeats runs after one warm-up).
Errors are against the boolean: on every CL point of the 53-point pass, and on --subset (53) CL
points evenly spread over the 5,000-point pass (the boolean costs seconds per CL point).
Every method, the Z-map included (no removal along the pass), answers the boolean's question:
the engagement with the initial stock. Writes build/benchmarks/compare_peers.csv.
"""

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")  # one core, before numpy is imported

import argparse  # noqa: E402
import csv  # noqa: E402
import functools  # noqa: E402
import json  # noqa: E402
import platform  # noqa: E402
import resource  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from abm_workbench.engine import CutSettings, Tool, Toolpath, engage, zmap_engage  # noqa: E402
from abm_workbench.jobs import load_job, load_stock, swept_y_window  # noqa: E402
from abm_workbench.formats.toolpath_csv import load_toolpath  # noqa: E402
from abm_workbench.validation import TINY_LENGTH, compare, overall, surface_summary  # noqa: E402

MODELS = os.path.join(ROOT, "resources", "models")
OUT = os.path.join(ROOT, "build", "benchmarks")
GRIDS = (0.2, 0.1, 0.05)
KINDS = ("top", "straight_wall", "curved_wall")


def model_inputs(number):
    """(STEP path, tool, settings, toolpath) of model test `number`, its bundled pass (53 CL points)."""
    folder = os.path.join(MODELS, f"model_test_{number}")
    job = load_job(os.path.join(folder, "job.json"))
    tool = Tool(job["diameter"], int(job["flutes"]), job["flute_length"])
    settings = CutSettings(job["feed_per_tooth"], job["inclination"], job["phi_start"], job["phi_end"], job["phi_step"],
                           job.get("spindle_rpm"))
    return os.path.join(folder, "stock.step"), tool, settings, load_toolpath(os.path.join(folder, "toolpath.csv"))


def load_model(number):
    """(name, tool, toolpath, settings, quintic Stock, exact Stock) of model test `number`."""
    step, tool, settings, toolpath = model_inputs(number)
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


PEER_METHODS = ("ABM exact", "ABM quintic", "Z-map 0.2 mm", "peer 0.01 mm", "peer 0.001 mm")
PEER_POINTS = (53, 5000)
PEER_FIELDS = ("model", "cl_points", "method", "instants", "checked_cl", "repeats", "prepare_s", "best_s",
               "median_s", "ms_per_cl", "instants_per_s", "peak_rss_mib", "growth_mib", "max_abs_difference",
               "mean_abs_difference", "max_lep_difference", "max_uep_difference", "mismatched", "triangles",
               "read_s", "tessellate_s", "mesh_s", "bvh_s", "volume_error_mm3", "unbalanced")


def peak_rss_mib():
    """This process's resident-set high-water mark (MiB): native allocations (Embree, OCC) included."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def model_pass(number, points):
    """(STEP path, tool, settings, toolpath) of model test `number` with its pass at `points` CL points.

    The bundled pass has 53 CL points; any other count resamples it along its index
    (engine_throughput.densified), over the same stock.
    """
    from engine_throughput import densified

    step, tool, settings, toolpath = model_inputs(number)
    return step, tool, settings, toolpath if points == len(toolpath) else densified(toolpath, points)


def peer_child(method, number, points, repeats, save):
    """Measure `method` (one of PEER_METHODS) in this fresh process; its (m, p) arrays go to `save` (.npz).

    Returns the row: prepare_s (stock from the STEP file to what the method works on),
    best_s / median_s (engagement of the whole pass), peak_rss_mib (process high-water mark)
    and growth_mib (over the baseline taken after FreeCAD is imported and the inputs are read),
    and for the peer its mesh and the split of its preparation.
    """
    from abm_workbench.cad.freecad_env import Part  # noqa: F401 (every method's baseline holds FreeCAD)

    step, tool, settings, toolpath = model_pass(number, points)
    baseline = peak_rss_mib()
    row = {}
    started = time.perf_counter()
    if method.startswith("peer"):
        import peer_raycast

        mesh = peer_raycast.mesh_stock(step, float(method.split()[1]))
        run = functools.partial(peer_raycast.edge_lengths_by_ray_casting, mesh, tool, toolpath, settings.phi)
        row = {"triangles": mesh.triangles, "volume_error_mm3": mesh.volume_mesh - mesh.volume_solid,
               **{f"{name}_s": seconds for name, seconds in mesh.seconds.items()}}
    elif method.startswith("Z-map"):
        stock = load_stock(step, walls="exact")
        run = functools.partial(zmap_engage, stock.staircase, tool, toolpath, settings, grid=float(method.split()[1]),
                                remove=False)
    else:
        walls = method.split()[1]
        window = functools.partial(swept_y_window, toolpath, tool) if walls == "quintic" else None
        stock = load_stock(step, walls=walls, y_window=window)
        run = functools.partial(engage, stock.staircase, tool, toolpath, settings)
    prepare = time.perf_counter() - started
    result, best, median = timed(run, repeats)
    arrays = result if isinstance(result, dict) else vars(result)
    np.savez(save, **{name: arrays[name] for name in ("length", "lep_l", "uep_l")})
    peak = peak_rss_mib()
    if "unbalanced" in arrays:
        row["unbalanced"] = arrays["unbalanced"]
    return {**row, "method": method, "repeats": repeats, "prepare_s": prepare, "best_s": best, "median_s": median,
            "peak_rss_mib": peak, "growth_mib": peak - baseline}


def run_child(method, number, points, repeats, folder):
    """(row, arrays) of peer_child run in a child process of this interpreter."""
    save = os.path.join(folder, "arrays.npz")
    command = [sys.executable, os.path.abspath(__file__), "--child", method, "--models", str(number),
               "--points", str(points), "--peer-repeats", str(repeats), "--save", save]
    done = subprocess.run(command, capture_output=True, text=True, cwd=ROOT)
    if done.returncode != 0:
        raise RuntimeError(f"{method} on model test {number} ({points} CL points) failed:\n{done.stderr.strip()}")
    with np.load(save) as data:
        arrays = {name: data[name] for name in data.files}
    return json.loads(done.stdout.strip().splitlines()[-1]), arrays


def errors_against(arrays, reference, cls):
    """Errors (mm) of a method's (m, p) arrays on CL points `cls` against the boolean's (len(cls), p) arrays.

    max / mean |l - l_ref| over every instant; max |LEP - LEP_ref| and |UEP - UEP_ref| (along
    the edge) where both engage; mismatched: instants engaged by one and not the other.
    """
    length = np.abs(arrays["length"][cls] - reference["length"])
    lep = np.abs(arrays["lep_l"][cls] - reference["lep_l"])
    uep = np.abs(arrays["uep_l"][cls] - reference["uep_l"])
    mismatched = np.isnan(arrays["uep_l"][cls]) != np.isnan(reference["uep_l"])
    return {"max_abs_difference": float(length.max()), "mean_abs_difference": float(length.mean()),
            "max_lep_difference": float(np.nanmax(lep, initial=0.0)),
            "max_uep_difference": float(np.nanmax(uep, initial=0.0)), "mismatched": int(mismatched.sum())}


def checked_points(m, subset):
    """Indices of the CL points checked by the boolean: all of them up to `subset`, else `subset` evenly spread."""
    return np.arange(m) if m <= subset else np.unique(np.linspace(0, m - 1, subset).round().astype(int))


def run_peers(args):
    """The --peers comparison: every method of PEER_METHODS on every model and pass size; prints and writes."""
    from abm_workbench.cad.boolean import edge_lengths_by_boolean  # FreeCAD

    os.makedirs(args.out, exist_ok=True)
    rows = []
    started_all = time.perf_counter()
    for number in [int(n) for n in args.models.split(",")]:
        for points in [int(n) for n in args.points.split(",")]:
            step, tool, settings, toolpath = model_pass(number, points)
            m, p = len(toolpath), settings.phi.size
            cls = checked_points(m, args.subset)
            common = {"model": f"model test {number}", "cl_points": m, "instants": m * p, "checked_cl": cls.size}
            print(f"model test {number}, {m} CL x {p} phi = {m * p} instants; boolean on {cls.size} CL points",
                  flush=True)
            solid = load_stock(step, walls="exact").shape
            started = time.perf_counter()
            reference = edge_lengths_by_boolean(solid, tool, Toolpath(toolpath.cl[cls], toolpath.theta_a[cls],
                                                                      toolpath.theta_b[cls]), settings.phi)
            seconds = time.perf_counter() - started
            rows.append({**common, "method": "boolean", "repeats": 1, "best_s": seconds, "median_s": seconds,
                         "ms_per_cl": 1e3 * seconds / cls.size, "instants_per_s": cls.size * p / seconds})
            print(f"  boolean: {seconds:.1f} s", flush=True)
            repeats = args.peer_repeats if m * p <= 10**5 else args.large_repeats
            for method in PEER_METHODS:
                runs = 1 if method.startswith("Z-map") and m * p > 10**5 else repeats
                with tempfile.TemporaryDirectory(prefix="abm-peers-") as folder:
                    row, arrays = run_child(method, number, m, runs, folder)
                row.update(common, ms_per_cl=1e3 * row["best_s"] / m, instants_per_s=m * p / row["best_s"],
                           **errors_against(arrays, reference, cls))
                rows.append(row)
                print(f"  {method}: prepare {row['prepare_s']:.2f} s, engagement {row['best_s']:.3f} s, "
                      f"max |dl| {row['max_abs_difference']:.3g} mm", flush=True)
    print_peers(rows, time.perf_counter() - started_all)
    table = os.path.join(args.out, "compare_peers.csv")
    with open(table, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=PEER_FIELDS, extrasaction="ignore")
        writer.writeheader()
        for r in rows:
            writer.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
    print(f"wrote {table}")


def print_peers(rows, total_seconds):
    """The --peers tables: per method, the peer's time split, ABM exact against the peer, the target."""
    print()
    print(f"machine: {platform.node()}, {os.cpu_count()} CPUs, load average "
          f"{' '.join(f'{x:.2f}' for x in os.getloadavg())}; python {platform.python_version()}, numpy "
          f"{np.__version__} ({np.__file__}); whole run {total_seconds:.0f} s")
    head = (f"{'model':<13} {'CL':>5} {'method':<14} {'prepare':>8} {'engage':>9} {'ms/CL':>8} {'instants/s':>10} "
            f"{'RSS MiB':>8} {'+MiB':>6} {'max|dl|':>9} {'mean|dl|':>9} {'max|dLEP|':>9} {'max|dUEP|':>9} {'mism':>5}")
    print(head)
    print("-" * len(head))
    for r in rows:
        if r["method"] == "boolean":
            print(f"{r['model']:<13} {r['cl_points']:>5} {'boolean':<14} {'':>8} {r['best_s']:>8.1f}s "
                  f"{r['ms_per_cl']:>8.0f} {r['instants_per_s']:>10.3g}   reference on {r['checked_cl']} CL points")
            continue
        print(f"{r['model']:<13} {r['cl_points']:>5} {r['method']:<14} {r['prepare_s']:>7.2f}s {r['best_s']:>8.3f}s "
              f"{r['ms_per_cl']:>8.3f} {r['instants_per_s']:>10.3g} {r['peak_rss_mib']:>8.0f} {r['growth_mib']:>6.0f} "
              f"{fmt(r['max_abs_difference']):>9} {fmt(r['mean_abs_difference']):>9} "
              f"{fmt(r['max_lep_difference']):>9} {fmt(r['max_uep_difference']):>9} {r['mismatched']:>5}")
    print("(prepare: STEP to what the method works on; engage: best of the repeats; RSS: the child process's peak, "
          "+MiB over its baseline with FreeCAD imported)")
    print()
    print("the peer's preparation (s) and mesh:")
    for r in rows:
        if r["method"].startswith("peer") and r["cl_points"] == min(q["cl_points"] for q in rows):
            print(f"  {r['model']}, {r['method']}: read {r['read_s']:.2f}, tessellate {r['tessellate_s']:.2f}, "
                  f"merge and check {r['mesh_s']:.2f}, BVH {r['bvh_s']:.3f}; {r['triangles']} triangles, "
                  f"volume - solid's {r['volume_error_mm3']:.3g} mm3; rays with unbalanced crossings: "
                  f"{r['unbalanced']}")
    print()
    print("ABM exact against the peer (same run): peer time / ABM exact time, engagement only (with preparation); "
          "ABM exact more accurate (max and mean |dl|)")
    met = []
    for key in dict.fromkeys((r["model"], r["cl_points"]) for r in rows):
        by = {r["method"]: r for r in rows if (r["model"], r["cl_points"]) == key}
        exact = by["ABM exact"]
        for method in (name for name in PEER_METHODS if name.startswith("peer")):
            peer = by[method]
            faster = peer["best_s"] / exact["best_s"]
            overall_ratio = (peer["best_s"] + peer["prepare_s"]) / (exact["best_s"] + exact["prepare_s"])
            accurate = (exact["max_abs_difference"] < peer["max_abs_difference"]
                        and exact["mean_abs_difference"] < peer["mean_abs_difference"])
            print(f"  {key[0]}, {key[1]} CL, {method}: {faster:.2f}x ({overall_ratio:.2f}x); more accurate: {accurate}")
            if method == "peer 0.001 mm":
                met.append(faster >= 10.0 and accurate)
    print(f"target (issue): ABM exact >= 10x faster than the peer at 0.001 mm and more accurate: "
          f"{'met' if all(met) else 'NOT met'}")
    print()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--abm-repeats", type=int, default=20)
    parser.add_argument("--zmap-repeats", type=int, default=3)
    parser.add_argument("--models", default="1,2", help="model tests to run, e.g. 1,2")
    parser.add_argument("--out", default=OUT, help="output folder (default build/benchmarks)")
    parser.add_argument("--peers", action="store_true",
                        help="compare ABM with the mesh ray-casting peer instead (needs trimesh, embreex, manifold3d: "
                             "make compare-peers)")
    parser.add_argument("--points", default=",".join(map(str, PEER_POINTS)),
                        help="--peers: CL points per pass, e.g. 53,5000 (53: the bundled pass; more: resampled)")
    parser.add_argument("--subset", type=int, default=53,
                        help="--peers: CL points checked by the boolean, evenly spread over a longer pass "
                             "(default 53: every CL point of the bundled pass)")
    parser.add_argument("--peer-repeats", type=int, default=5, help="--peers: timed runs up to 10^5 instants")
    parser.add_argument("--large-repeats", type=int, default=2,
                        help="--peers: timed runs above 10^5 instants (the Z-map: one)")
    parser.add_argument("--child", help=argparse.SUPPRESS)
    parser.add_argument("--save", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        print(json.dumps(peer_child(args.child, int(args.models), int(args.points), args.peer_repeats, args.save)))
        return
    if args.peers:
        run_peers(args)
        return
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
