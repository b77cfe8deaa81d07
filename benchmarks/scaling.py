"""Scaling: time and peak memory from 10^3 to 10^7 instants, one process, local workers, Dask.

Run with FreeCAD's Python from the repository root: `/usr/bin/python3 benchmarks/scaling.py`
(or `make scaling`). The pass is model test 1's (stock.json, job.json: 181 angles φ), its 53
CL points resampled along the pass to ceil(N / 181) CL points for N instants. Each case runs in
a fresh subprocess, so that the peak resident memory (RSS high-water mark, getrusage) belongs to
that case alone:

- api: `engine.engage` on the whole pass, returning one Engagement (all results in memory);
- cli: `python -m abm_workbench engage` in that process, writing the results CSV and its
  summary chunk by chunk (the time includes reading the toolpath CSV and writing the files);
  cli-2: the same with `--workers 2` (chunks engaged and formatted in 2 local processes);
- workers: `parallel.engage_parallel` with 1 or 2 local worker processes;
- dask: the same on a loopback Dask cluster (2 worker processes, 1 thread each), started
  before the clock.

Times are best and median of several runs (one at 10^7). Peak memory: the measuring process's
RSS high-water mark, and for workers and Dask also the largest worker process's; the
interpreter with numpy and the package loaded, before any work, is reported as the baseline.
Writes build/benchmarks/scaling.csv and scaling.png (log-log time and memory against instants).
"""

import argparse
import csv
import json
import math
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from engine_throughput import MODEL, densified, load_model  # noqa: E402

PYTHON = "/usr/bin/python3"
SIZES = (10**3, 10**4, 10**5, 10**6, 10**7)
#: Results held in memory by an Engagement, bytes per instant (measured: ~100), to refuse what cannot fit.
BYTES_PER_INSTANT = 110
COLUMNS = ("case", "instants", "cl_points", "runs", "best_s", "median_s", "instants_per_s", "peak_mib",
           "worker_peak_mib", "baseline_mib", "note")


def peak_mib(who=resource.RUSAGE_SELF):
    """RSS high-water mark (MiB) of this process or (RUSAGE_CHILDREN) its largest finished child."""
    return resource.getrusage(who).ru_maxrss / 1024.0


def pass_of(instants):
    """(stock, tool, toolpath, settings) of model test 1 resampled to about `instants` instants."""
    stock, tool, path, settings = load_model(MODEL)
    return stock, tool, densified(path, math.ceil(instants / settings.phi.size)), settings


def timed(function, runs):
    """(times in s) of `runs` calls of function()."""
    times = []
    for _ in range(runs):
        started = time.perf_counter()
        function()
        times.append(time.perf_counter() - started)
    return times


def child(case, instants, runs):
    """Measure one case in this (fresh) process; return a dict of the row's fields."""
    from abm_workbench.engine import engage
    from abm_workbench.parallel import engage_parallel

    stock, tool, toolpath, settings = pass_of(instants)
    baseline = peak_mib()
    row = {"case": case, "instants": len(toolpath) * settings.phi.size, "cl_points": len(toolpath),
           "baseline_mib": baseline, "worker_peak_mib": "", "note": ""}
    if case == "api":
        times = timed(lambda: engage(stock, tool, toolpath, settings), runs)
    elif case.startswith("workers"):
        workers = int(case.split("-")[1])
        times = timed(lambda: engage_parallel(stock, tool, toolpath, settings, workers=workers), runs)
        row["worker_peak_mib"] = peak_mib(resource.RUSAGE_CHILDREN) if workers > 1 else ""
    elif case == "dask":
        import distributed

        with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                      dashboard_address=None) as cluster:
            times = timed(lambda: engage_parallel(stock, tool, toolpath, settings,
                                                  scheduler=cluster.scheduler_address), runs)
        row["worker_peak_mib"] = peak_mib(resource.RUSAGE_CHILDREN)
    elif case.startswith("cli"):
        workers = int(case.split("-")[1]) if "-" in case else 1
        times, size = cli_times(stock, tool, toolpath, settings, runs, workers)
        row["note"] = f"CSV {size / 2**20:.0f} MiB"
        row["worker_peak_mib"] = peak_mib(resource.RUSAGE_CHILDREN) if workers > 1 else ""
    else:
        raise ValueError(f"unknown case {case!r}")
    row.update(runs=runs, best_s=min(times), median_s=float(np.median(times)), peak_mib=peak_mib())
    return row


def cli_times(stock, tool, toolpath, settings, runs, workers):
    """(times, results CSV bytes) of the engage command on model test 1's stock and this toolpath."""
    from abm_workbench import cli

    folder = tempfile.mkdtemp(prefix="abm-scaling-")
    try:
        path = os.path.join(folder, "toolpath.csv")
        with open(path, "w") as handle:
            handle.write("x,y,z,theta_a,theta_b\n")
            np.savetxt(handle, np.column_stack([toolpath.cl, toolpath.theta_a, toolpath.theta_b]),
                       fmt="%.17g", delimiter=",")
        out = os.path.join(folder, "R.csv")
        argv = ["engage", "--job", os.path.join(MODEL, "job.json"), "--stock", os.path.join(MODEL, "stock.json"),
                "--toolpath", path, "--out", out, "--workers", str(workers)]
        with open(os.devnull, "w") as quiet:
            stdout, sys.stdout = sys.stdout, quiet
            try:
                times = timed(lambda: _check(cli.main(argv)), runs)
            finally:
                sys.stdout = stdout
        return times, os.path.getsize(out)
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def _check(status):
    if status != 0:
        raise RuntimeError(f"engage exited with status {status}")


def runs_for(case, instants):
    """Runs per case: 5 up to 10^5 instants, then 3 (the engine) or 1 (the command line) at 10^6, 1 above."""
    return 5 if instants <= 10**5 else 3 if instants <= 10**6 and not case.startswith("cli") else 1


def measure(case, instants, runs):
    """The row of one case, measured in a fresh subprocess (or a note saying why it was not run)."""
    needed = BYTES_PER_INSTANT * instants
    available = os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    if case == "api" and needed > available / 2:
        return {"case": case, "instants": instants, "note": f"not run: results need ~{needed / 2**30:.1f} GiB, "
                f"{available / 2**30:.1f} GiB free"}
    command = [PYTHON, os.path.abspath(__file__), "--child", case, "--instants", str(instants), "--runs", str(runs)]
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", MKL_NUM_THREADS="1")
    done = subprocess.run(command, capture_output=True, text=True, env=env, cwd=ROOT)
    if done.returncode != 0:
        return {"case": case, "instants": instants, "note": f"failed (status {done.returncode}): "
                f"{done.stderr.strip().splitlines()[-1] if done.stderr.strip() else ''}"}
    return json.loads(done.stdout.strip().splitlines()[-1])


def cases(sizes, cli_max):
    """(case, instants) to run: api at every size, cli up to cli_max, cli-2 from 10^6 on, workers
    and Dask at 10^6."""
    plan = [("api", n) for n in sizes] + [("cli", n) for n in sizes if n <= cli_max]
    plan += [("cli-2", n) for n in sizes if n >= 10**6]
    if 10**6 in sizes:
        plan += [("workers-1", 10**6), ("workers-2", 10**6), ("dask", 10**6)]
    return plan


def _format(value, digits=3):
    return "" if value in ("", None) else f"{value:.{digits}g}" if isinstance(value, float) else str(value)


def print_table(rows):
    """The measured rows, with instants/s and the ratios at 10^6."""
    print(f"{'case':<10} {'instants':>9} {'runs':>4} {'best s':>9} {'median s':>9} {'instants/s':>10} "
          f"{'peak MiB':>9} {'worker MiB':>10} {'base MiB':>8}  note")
    for row in rows:
        print(f"{row['case']:<10} {row['instants']:>9} {_format(row.get('runs')):>4} {_format(row.get('best_s')):>9} "
              f"{_format(row.get('median_s')):>9} {_format(row.get('instants_per_s')):>10} "
              f"{_format(row.get('peak_mib'), 4):>9} {_format(row.get('worker_peak_mib'), 4):>10} "
              f"{_format(row.get('baseline_mib'), 3):>8}  {row.get('note', '')}")
    at_million = {row["case"]: row for row in rows if row.get("best_s") and row["instants"] >= 10**6
                  and row["instants"] < 10**6 + 200}
    reference = at_million.get("api")
    if reference:
        print("\nat 10^6 instants, best time against the single-process engine (api):")
        for name, row in at_million.items():
            print(f"  {name:<10} {row['best_s'] / reference['best_s']:.2f}x the time "
                  f"({reference['best_s'] / row['best_s']:.2f}x the speed)")


def plot(rows, path):
    """Log-log time and peak memory against instants, one line per case."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, (time_axes, memory_axes) = plt.subplots(1, 2, figsize=(11, 4.5))
    for case in dict.fromkeys(row["case"] for row in rows):
        done = [row for row in rows if row["case"] == case and row.get("best_s")]
        if not done:
            continue
        n = [row["instants"] for row in done]
        style = "o-" if len(done) > 1 else "s"
        time_axes.loglog(n, [row["best_s"] for row in done], style, label=case)
        memory_axes.loglog(n, [row["peak_mib"] for row in done], style, label=case)
    reference = [row for row in rows if row["case"] == "api" and row.get("best_s") and row["instants"] >= 10**6]
    if reference:
        n = np.array([1e3, 1e7])
        time_axes.loglog(n, reference[0]["best_s"] * n / reference[0]["instants"], ":", color="grey",
                         label="∝ instants")
    time_axes.set(xlabel="instants (CL points × φ)", ylabel="best time (s)", title="time")
    memory_axes.set(xlabel="instants (CL points × φ)", ylabel="peak RSS (MiB)", title="peak memory (measuring process)")
    for axes in (time_axes, memory_axes):
        axes.grid(True, which="both", alpha=0.3)
        axes.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default=",".join(str(n) for n in SIZES), help="instants, comma-separated")
    parser.add_argument("--cli-max", type=float, default=1e7,
                        help="largest size run through the command line in one process (default 10^7, "
                             "about a minute there)")
    parser.add_argument("--cases", default="api,cli,cli-2,workers-1,workers-2,dask",
                        help="cases to run, comma-separated (default all)")
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "benchmarks"), help="output folder")
    parser.add_argument("--child", help=argparse.SUPPRESS)
    parser.add_argument("--instants", type=int, help=argparse.SUPPRESS)
    parser.add_argument("--runs", type=int, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        print(json.dumps(child(args.child, args.instants, args.runs)))
        return
    rows = []
    chosen = args.cases.split(",")
    plan = [(case, n) for case, n in cases([int(float(n)) for n in args.sizes.split(",")], args.cli_max)
            if case in chosen]
    for case, instants in plan:
        row = measure(case, instants, runs_for(case, instants))
        if row.get("best_s"):
            row["instants_per_s"] = row["instants"] / row["best_s"]
        rows.append(row)
        print(f"# {case} {row['instants']}: {_format(row.get('best_s'))} s {row.get('note', '')}", flush=True)
    print(f"\n{os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f} at the end, "
          f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    print_table(rows)
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "scaling.csv"), "w", newline="") as handle:
        writer = csv.DictWriter(handle, COLUMNS, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    plot(rows, os.path.join(args.out, "scaling.png"))
    print(f"wrote {os.path.join(args.out, 'scaling.csv')}, {os.path.join(args.out, 'scaling.png')}")


if __name__ == "__main__":
    main()
