"""The whole command line, start to exit: ``python3 -m abm_workbench engage ... --out R.npz`` at ≥ 10^6 instants.

Run with FreeCAD's Python from the repository root: ``/usr/bin/python3 benchmarks/end_to_end.py``
(``--instants``, ``--repeats``). The job: model test 1's staircase stock (JSON) and job file, its
pass resampled to ceil(instants / 181) CL points (a toolpath CSV written to a temporary folder).

Prints, from one run:
1. start-up: a fresh interpreter doing nothing, importing numpy, importing the command line, and
   the start-up of a JSON job: the interpreter plus every import of ``engage`` on model test 1's
   JSON job (.npz, stock as given), summed from ``-X importtime``'s top-level entries;
2. the whole process (wall clock start to exit, and the CPU time of the child; the best and the
   median of the repeats) for .npz and .csv outputs, against the stock as given (``--stock-model
   initial``, the default here) or the in-process stock (``--stock-model in-process``: much slower
   on this pass); with ``--baseline CHECKOUT``, the same runs of another checkout's command line
   (e.g. ``git archive main | tar -x -C /tmp/base``) and its time over this one's;
3. the split of one .npz run measured inside one process: start-up (as in 1), reading (job,
   toolpath, stock), the in-process sweep (with --stock-model in-process), engine (every chunk's
   columns), writing the .npz;
4. with ``--baseline``, the .npz writer of each checkout on the same columns (in this process, the
   baseline's imported beside this one's); the engine and the .npz writer of the pass together,
   chunks written while the next is computed (as a run does) and one after the other (against the
   stock as given); the toolpath CSV read column by column and line by line (the reader's two
   paths, same numbers);
5. the results CSV text of the same columns by formats.decimal_text and by a plain writer
   (Python's repr of each rounded value, joined row by row), checked to be the same bytes.
Ratios are printed beside the times, so that a loaded machine's figures still compare.
"""

import argparse
import contextlib
import importlib
import importlib.util
import inspect
import math
import os
import re
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")
PYTHON = "/usr/bin/python3"


def resampled_toolpath(source, path, count):
    """Write to `path` the toolpath CSV `source` (x, y, z, i, j, k, ... columns) resampled to `count` CL
    points: positions linear in the CL index, the tool axis likewise then normalised."""
    with open(source) as handle:
        names = handle.readline().strip().split(",")
    data = np.loadtxt(source, delimiter=",", skiprows=1)
    old, new = np.arange(len(data)), np.linspace(0.0, len(data) - 1.0, count)
    table = np.column_stack([np.interp(new, old, data[:, c]) for c in range(data.shape[1])])
    axis = [names.index(name) for name in "ijk"]
    table[:, axis] /= np.linalg.norm(table[:, axis], axis=1, keepdims=True)
    np.savetxt(path, table, delimiter=",", header=",".join(names), comments="", fmt="%.17g")


def cached_bytecode(folder):
    """The environment of a Python that keeps its compiled modules in `folder` (as an installed
    package has them), whatever PYTHONDONTWRITEBYTECODE says here (this machine sets it)."""
    environment = {key: value for key, value in os.environ.items() if key != "PYTHONDONTWRITEBYTECODE"}
    environment["PYTHONPYCACHEPREFIX"] = folder
    return environment


def timed_runs(cases, repeats, environment=None):
    """{key: (best, median wall-clock seconds, best CPU seconds (user + system of the child))} of `repeats`
    runs of each case of {key: (command, folder to run it in)}, each checked to exit 0, in `environment`
    (default this one's). Every repeat runs each case once in turn, so that a load that comes and goes
    falls on all of them alike."""
    times = {key: ([], []) for key in cases}
    for _ in range(repeats):
        for key, (command, root) in cases.items():
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            start = time.perf_counter()
            subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True, cwd=root,
                           env=environment)
            times[key][0].append(time.perf_counter() - start)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            times[key][1].append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
    return {key: (min(wall), float(np.median(wall)), min(cpu)) for key, (wall, cpu) in times.items()}


#: A top-level entry of ``-X importtime`` (a module imported by the program itself): its cumulative µs.
_TOP_IMPORT = re.compile(r"^import time:\s+\d+ \|\s+(\d+) \| \S", re.MULTILINE)


def job_imports(roots, environment, repeats):
    """{checkout: best seconds} that engage of model test 1's JSON job (.npz, stock as given) spends
    importing modules, by the command line of each checkout of {checkout: folder}: the sum of ``-X
    importtime``'s top-level entries, best of `repeats` runs taking the checkouts in turn."""
    best = dict.fromkeys(roots, math.inf)
    with tempfile.TemporaryDirectory() as folder:
        command = [PYTHON, "-X", "importtime", "-m", "abm_workbench", "engage", "--stock",
                   os.path.join(MODEL, "stock.json"), "--toolpath", os.path.join(MODEL, "toolpath.csv"), "--job",
                   os.path.join(MODEL, "job.json"), "--stock-model", "initial", "--out", os.path.join(folder, "R.npz")]
        for _ in range(repeats):
            for checkout, root in roots.items():
                done = subprocess.run(command, capture_output=True, text=True, check=True, cwd=root, env=environment)
                seconds = sum(int(entry) for entry in _TOP_IMPORT.findall(done.stderr)) / 1e6
                best[checkout] = min(best[checkout], seconds)
    return best


#: The start-up cases: a fresh interpreter running each of these.
STARTS = (("python -c pass", "pass"), ("import numpy", "import numpy"),
          ("import abm_workbench.cli", "import abm_workbench.cli"))


def start_up(roots, environment, repeats):
    """{checkout: {case: best seconds}} of a fresh interpreter that does nothing, imports numpy, imports
    the command line, for each checkout of {checkout: folder}; with a JSON job's imports (job_imports)
    and its start-up (the interpreter doing nothing plus those imports)."""
    runs = timed_runs({(checkout, name): ([PYTHON, "-c", code], root) for checkout, root in roots.items()
                       for name, code in STARTS}, repeats, environment)
    imports = job_imports(roots, environment, repeats)
    found = {}
    for checkout in roots:
        times = {name: runs[checkout, name][0] for name, _ in STARTS}
        times["a JSON job's imports"] = imports[checkout]
        times["start-up of a JSON job"] = times["python -c pass"] + imports[checkout]
        found[checkout] = times
    return found


class _Clock:
    """Wall-clock and CPU seconds (this process) of each part measured with `part(name)`, in order."""

    def __init__(self):
        self.wall, self.cpu = {}, {}

    @contextlib.contextmanager
    def part(self, name):
        wall, cpu = time.perf_counter(), time.process_time()
        yield
        self.wall[name], self.cpu[name] = time.perf_counter() - wall, time.process_time() - cpu


def split(folder, model, start):
    """The parts of one .npz engage against stock model `model`, measured in this process (start-up: `start`
    s, a JSON job's wall-clock time as start_up measures it, in both clocks), and the columns of every
    chunk: (_Clock of the parts, [(results, summary) columns], instants)."""
    from abm_workbench.formats import replacing, results_npz
    from abm_workbench.jobs import Job
    from abm_workbench.jobs.job import load_job_stock, prepare
    from abm_workbench.jobs.run import ResultsChunk, in_process_sweep
    from abm_workbench.parallel import map_chunks

    clock = _Clock()
    clock.wall["start-up"] = clock.cpu["start-up"] = start
    with clock.part("reading"):
        job = Job(os.path.join(MODEL, "stock.json"), os.path.join(folder, "toolpath.csv"),
                  os.path.join(MODEL, "job.json"), {}, stock_model=model)
        prepared = prepare(job)
        stock, _ = load_job_stock(prepared)
    if model == "in-process":
        with clock.part("in-process sweep"):
            in_process, _ = in_process_sweep(prepared)
    else:
        in_process = None
    with clock.part("engine"):
        task = ResultsChunk(keep=False, frame=prepared.hints.frame, in_process=in_process, columnar=True)
        parts = [result.parts for *_, result in map_chunks(task, [(stock.model, prepared.tool, prepared.toolpath,
                                                                    prepared.settings)])]
    instants = len(prepared.toolpath) * prepared.settings.phi.size
    with clock.part("writing .npz"), replacing(os.path.join(folder, "split.npz")) as temporaries:
        results_npz.write_chunks(iter(parts), temporaries[0], instants)
    return clock, parts, instants


def overlap(folder, model, repeats):
    """{"overlapped" / "one after the other": best wall-clock seconds} of the engine and the .npz writer
    of one pass together, as a run does them (chunks written in a second thread while the next is
    computed), and with the writer's consumer replaced by a plain loop; taken in turn `repeats` times."""
    from abm_workbench.formats import replacing, results_npz
    from abm_workbench.jobs import Job
    from abm_workbench.jobs.job import load_job_stock, prepare
    from abm_workbench.jobs.run import ResultsChunk
    from abm_workbench.parallel import map_chunks

    def one_after_the_other(items, consume):
        count = 0
        for item in items:
            consume(item)
            count += 1
        return count

    prepared = prepare(Job(os.path.join(MODEL, "stock.json"), os.path.join(folder, "toolpath.csv"),
                           os.path.join(MODEL, "job.json"), {}, stock_model=model))
    stock, _ = load_job_stock(prepared)
    task = ResultsChunk(keep=False, frame=prepared.hints.frame, columnar=True)
    job = (stock.model, prepared.tool, prepared.toolpath, prepared.settings)
    instants = len(prepared.toolpath) * prepared.settings.phi.size
    consumers = {"overlapped": results_npz.consume_overlapped, "one after the other": one_after_the_other}
    clocks = {name: _Clock() for name in consumers}
    try:
        for repeat in range(repeats):
            for name, consumer in consumers.items():
                results_npz.consume_overlapped = consumer
                with clocks[name].part(repeat), replacing(os.path.join(folder, "overlap.npz")) as temporaries:
                    results_npz.write_chunks((result.parts for *_, result in map_chunks(task, [job])),
                                             temporaries[0], instants)
    finally:
        results_npz.consume_overlapped = consumers["overlapped"]
    return {name: min(clock.wall.values()) for name, clock in clocks.items()}


def baseline_module(checkout, name):
    """Module `name` (e.g. "formats.results_npz") of the checkout `checkout`'s abm_workbench, imported as
    abm_baseline.<name> beside this checkout's."""
    package = importlib.util.spec_from_file_location("abm_baseline", os.path.join(checkout, "abm_workbench",
                                                                                 "__init__.py"),
                                                     submodule_search_locations=[os.path.join(checkout,
                                                                                              "abm_workbench")])
    if "abm_baseline" not in sys.modules:
        sys.modules["abm_baseline"] = importlib.util.module_from_spec(package)
        package.loader.exec_module(sys.modules["abm_baseline"])
    return importlib.import_module(f"abm_baseline.{name}")


def npz_writers(folder, parts, instants, checkout, repeats):
    """{"this checkout" / `checkout`: (best wall-clock s, best CPU s)} of writing the .npz of `parts` by
    each checkout's results_npz.write_chunks, taken in turn `repeats` times."""
    from abm_workbench.formats import replacing, results_npz

    writers = {"this checkout": lambda path: results_npz.write_chunks(iter(parts), path, instants)}
    older = baseline_module(checkout, "formats.results_npz").write_chunks
    takes_rows = len(inspect.signature(older).parameters) == 3
    writers[checkout] = lambda path: older(iter(parts), path, *([instants] if takes_rows else []))
    clocks = {name: _Clock() for name in writers}
    for repeat in range(repeats):
        for name, write in writers.items():
            with clocks[name].part(repeat), replacing(os.path.join(folder, "writer.npz")) as temporaries:
                write(temporaries[0])
    return {name: (min(clock.wall.values()), min(clock.cpu.values())) for name, clock in clocks.items()}


def plain_csv(parts):
    """The results CSV text of `parts` by a plain writer: each value's text by Python (repr of the
    float rounded to decimal_text.DECIMALS places, '' for NaN, str of an int, a label), rows joined."""
    from abm_workbench.formats.decimal_text import DECIMALS
    from abm_workbench.formats.results_columns import INT_COLUMNS, TEXT_COLUMNS, text_labels

    lines = [",".join(parts[0][0]) + "\n"]
    for results, _ in parts:
        texts = []
        for name, values in results.items():
            if name in TEXT_COLUMNS:
                labels = np.array(text_labels(name, int(values.max(initial=0)) + 1))
                texts.append(labels[values].tolist())
            elif name in INT_COLUMNS:
                texts.append([str(value) for value in values.tolist()])
            else:
                rounded = (np.round(values, DECIMALS) + 0.0).tolist()
                texts.append(["" if value != value else repr(value) for value in rounded])
        lines.extend(",".join(row) + "\n" for row in zip(*texts))
    return "".join(lines)


def csv_writers(parts):
    """(seconds of decimal_text, seconds of the plain writer, same text?) for the results CSV of `parts`."""
    from abm_workbench.formats.results_csv import table_text

    started = time.perf_counter()
    texts = [table_text(results) for results, _ in parts]
    fast = "".join(texts[:1] + [text.split("\n", 1)[1] for text in texts[1:]])
    fast_seconds = time.perf_counter() - started
    started = time.perf_counter()
    plain = plain_csv(parts)
    return fast_seconds, time.perf_counter() - started, fast == plain


def toolpath_readers(path):
    """(seconds column by column, seconds line by line, same numbers?) of the toolpath CSV `path`."""
    from abm_workbench.formats import read_text
    from abm_workbench.formats.toolpath_csv import _columnwise, _data_lines, _fields, _line_by_line

    lines = _data_lines(read_text(path))
    header = [field.strip().lower() for field in _fields(lines[0][1], path)]
    started = time.perf_counter()
    fast = _columnwise(header, [line for _, line in lines[1:]])
    fast_seconds = time.perf_counter() - started
    started = time.perf_counter()
    slow = _line_by_line(path, header, lines[1:])
    slow_seconds = time.perf_counter() - started
    same = fast is not None and all(fast[0][name].tobytes() == slow[0][name].tobytes() for name in header)
    return fast_seconds, slow_seconds, same


def print_start_up(starts):
    """The start-up table of {case: start_up(...)}, with the load average now."""
    load = os.getloadavg()
    print(f"Start-up, best of the repeats (s), load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} after; the "
          "command line's own share is its time less numpy's:")
    print("| bytecode | python -c pass | import numpy | import abm_workbench.cli | its own | a JSON job's imports | "
          "start-up of a JSON job |")
    print("|---|---|---|---|---|---|---|")
    for name, times in starts.items():
        cells = [times[key] for key in ("python -c pass", "import numpy", "import abm_workbench.cli")]
        cells += [times["import abm_workbench.cli"] - times["import numpy"], times["a JSON job's imports"],
                  times["start-up of a JSON job"]]
        print(f"| {name} | {' | '.join(f'{value:.3f}' for value in cells)} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--instants", type=int, default=10**6, help="at least this many instants (default 10^6)")
    parser.add_argument("--start-up-only", action="store_true", help="only the start-up table")
    parser.add_argument("--repeats", type=int, default=3, help="runs per whole-process figure (default 3)")
    parser.add_argument("--stock-model", choices=("initial", "in-process"), default="initial",
                        help="the stock as given (default) or the in-process stock")
    parser.add_argument("--baseline", metavar="CHECKOUT",
                        help="also the start-up and the whole runs of another checkout's command line (e.g. the "
                             "main branch's), and its time over this one's")
    args = parser.parse_args()
    load = os.getloadavg()
    with tempfile.TemporaryDirectory() as folder:
        resampled_toolpath(os.path.join(MODEL, "toolpath.csv"), os.path.join(folder, "toolpath.csv"),
                           math.ceil(args.instants / 181))
        base = [PYTHON, "-m", "abm_workbench", "engage", "--stock", os.path.join(MODEL, "stock.json"),
                "--toolpath", os.path.join(folder, "toolpath.csv"), "--job", os.path.join(MODEL, "job.json"),
                "--stock-model", args.stock_model, "--out"]
        cached = cached_bytecode(os.path.join(folder, "bytecode"))
        roots = {"this checkout": ROOT} if not args.baseline else {"this checkout": ROOT, args.baseline: args.baseline}
        # compiles every module once
        timed_runs({root: (base + [os.path.join(folder, "warm.npz")], root) for root in roots.values()}, 1, cached)
        uncached = {key: value for key, value in os.environ.items() if key != "PYTHONPYCACHEPREFIX"}
        uncached["PYTHONDONTWRITEBYTECODE"] = "1"  # the project compiled at every run (without a __pycache__)
        starts = {"project not cached": start_up({"this": ROOT}, uncached, args.repeats)["this"]}
        cached_starts = start_up(roots, cached, args.repeats)
        starts["bytecode cached"] = cached_starts.pop("this checkout")
        starts.update({f"bytecode cached, {checkout}": times for checkout, times in cached_starts.items()})
        if args.start_up_only:
            print_start_up(starts)
            return
        clock, parts, instants = split(folder, args.stock_model, starts["bytecode cached"]["start-up of a JSON job"])
        whole = timed_runs({(checkout, suffix): (base + [os.path.join(folder, f"R.{suffix}")], root)
                            for checkout, root in roots.items() for suffix in ("npz", "csv")}, args.repeats, cached)
        reading = toolpath_readers(os.path.join(folder, "toolpath.csv"))
        together = overlap(folder, args.stock_model, args.repeats) if args.stock_model == "initial" else None
        writers = npz_writers(folder, parts, instants, args.baseline, args.repeats) if args.baseline else None
        fast, plain, same = csv_writers(parts)
    print_start_up(starts)
    print(f"\nWhole command line (bytecode cached), {instants:,} instants (model test 1, JSON stock); load average "
          f"{load[0]:.2f} {load[1]:.2f} {load[2]:.2f} at the start, {os.cpu_count()} cores")
    print("| checkout | stock model | output | best s | median s | CPU s (best) | instants/s (best) | "
          ".csv time / this | baseline time / this |")
    print("|---|---|---|---|---|---|---|---|---|")
    for (checkout, suffix), (best, median, cpu) in whole.items():
        baseline = f"{whole[args.baseline, suffix][0] / best:.2f}" if args.baseline else "-"
        print(f"| {checkout} | {args.stock_model} | .{suffix} | {best:.2f} | {median:.2f} | {cpu:.2f} | "
              f"{instants / best:,.0f} | {whole[checkout, 'csv'][0] / best:.2f} | {baseline} |")
    wall, cpu = sum(clock.wall.values()), sum(clock.cpu.values())
    print(f"\nSplit of one .npz run ({args.stock_model} stock), sum {wall:.2f} s wall clock ({instants / wall:,.0f} "
          f"instants/s), {cpu:.2f} s CPU ({instants / cpu:,.0f} instants/s; the start-up's wall clock time in both):")
    print("| part | wall s | CPU s | share of the CPU |")
    print("|---|---|---|---|")
    for part, value in clock.wall.items():
        print(f"| {part} | {value:.3f} | {clock.cpu[part]:.3f} | {100 * clock.cpu[part] / cpu:.0f} % |")
    if writers:
        (wall, cpu), (old_wall, old_cpu) = writers["this checkout"], writers[args.baseline]
        print(f"\n.npz writer on the same columns, best of {args.repeats} in turn: this checkout {wall:.3f} s "
              f"({cpu:.3f} s CPU), {args.baseline} {old_wall:.3f} s ({old_cpu:.3f} s CPU): {old_wall / wall:.2f}x "
              f"({old_cpu / cpu:.2f}x CPU)")
    if together:
        print(f"\nEngine and .npz writer of the pass together, best of {args.repeats} in turn: chunks written while "
              f"the next is computed {together['overlapped']:.3f} s, one after the other "
              f"{together['one after the other']:.3f} s ({together['one after the other'] / together['overlapped']:.2f}x)")
    column, line, equal = reading
    print(f"\nToolpath CSV of {math.ceil(args.instants / 181):,} CL points: column by column {column:.3f} s, line by "
          f"line {line:.3f} s ({line / column:.1f}x slower); same numbers: {equal}")
    print(f"\nResults CSV text of the same {instants:,} rows: decimal_text {fast:.2f} s, plain writer {plain:.2f} s "
          f"({plain / fast:.1f}x slower); same bytes: {same}")


if __name__ == "__main__":
    main()
