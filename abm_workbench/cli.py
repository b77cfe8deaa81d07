"""Command line of the ABM workbench: ``python -m abm_workbench <command> ...``.

Commands:
  engage   cut geometry of one pass: staircase JSON + toolpath CSV -> results CSV (+ PNG).

Errors in the input print ``abm: error: <message>`` on stderr and exit with status 2,
leaving no output file behind (an existing one is replaced only on success); a failure to
write exits with 1, an interrupt with 130, under the same rule. Missing output folders are
made once the results are ready to be written.
"""

import argparse
import os
import sys
import time

import numpy as np

from .engine import CutSettings, Tool, engage
from .errors import InputError
from .formats import check_keys, json_number, load_json_object, replacing
from .formats.results_csv import results_text, summary_path, summary_text, write_text
from .formats.staircase_json import load_staircase
from .formats.toolpath_csv import load_toolpath

PROG = "abm"
_REQUIRED = object()
#: Cutting parameters given by options or by a --job file, and their defaults.
_PARAMETERS = {
    "diameter": _REQUIRED, "flutes": _REQUIRED, "flute_length": _REQUIRED, "feed_per_tooth": _REQUIRED,
    "inclination": 0.0, "spindle_rpm": None, "phi_range": (0.0, 180.0), "phi_step": 1.0,
}


class _Parser(argparse.ArgumentParser):
    """ArgumentParser whose errors read ``abm: error: ...`` (exit status 2) in every subcommand."""

    def error(self, message):
        self.print_usage(sys.stderr)
        self.exit(2, f"{PROG}: error: {message}\n")


def main(argv=None):
    """Run the command line with `argv` (default sys.argv[1:]); return the exit status."""
    parser = _build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exit_:  # usage errors (2) and --help (0)
        return exit_.code
    try:
        return args.run(args)
    except InputError as error:
        print(f"{PROG}: error: {error}", file=sys.stderr)
        return 2
    except OSError as error:
        print(f"{PROG}: error: {error}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print(f"{PROG}: interrupted", file=sys.stderr)
        return 130


def _build_parser():
    """The argument parser: one subparser per command, each with `run` set to its function."""
    parser = _Parser(prog=PROG, description="Analytical cut geometry of flat-end five-axis milling on staircase stock.")
    commands = parser.add_subparsers(title="commands", dest="command", required=True, metavar="COMMAND")
    engage_parser = commands.add_parser(
        "engage", help="cut geometry of one pass", description=(
            "Length of cut, engagement points, cut area and depth of cut of a flat-end mill along one pass "
            "over staircase stock. Lengths in mm, angles in degrees. Writes OUT (one row per CL point and "
            "rotation angle), OUT with .summary.csv (one row per CL point and engagement segment) and, "
            "with --plot, a PNG."),
    )
    _engage_arguments(engage_parser)
    engage_parser.set_defaults(run=_run_engage)
    return parser


def _engage_arguments(parser):
    """Options of the engage command."""
    files = parser.add_argument_group("files")
    files.add_argument("--stock", required=True, metavar="STOCK.json", help="staircase stock (abm-staircase/1 JSON)")
    files.add_argument("--toolpath", required=True, metavar="PATH.csv",
                       help="CL points: x,y,z,theta_a,theta_b or x,y,z,i,j,k (+ optional xc,yc,zc)")
    files.add_argument("--out", required=True, metavar="R.csv", help="results CSV; the summary goes to R.summary.csv")
    files.add_argument("--plot", metavar="R.png", help="also write a PNG of the pass")
    files.add_argument("--job", metavar="JOB.json",
                       help="JSON of default cutting parameters (keys as the options below, with _ for -; "
                            "phi_range as [start, end]; description); options given here override it")
    cutting = parser.add_argument_group("cutting parameters (required ones may come from --job)")
    cutting.add_argument("--diameter", type=float, help="tool diameter (mm), required")
    cutting.add_argument("--flutes", type=int, help="number of flutes, required")
    cutting.add_argument("--flute-length", type=float, help="flute length (mm), required")
    cutting.add_argument("--feed-per-tooth", type=float, help="feed per tooth f (mm), required")
    cutting.add_argument("--inclination", type=float, help="tool inclination angle α (deg), default 0")
    cutting.add_argument("--spindle-rpm", type=float, help="spindle speed (rpm)")
    cutting.add_argument("--phi-range", metavar="START:END",
                         help="tool rotation angles φ (deg), default 0:180 (--phi-range=-10:190 for a negative start)")
    cutting.add_argument("--phi-step", type=float, help="step of φ (deg), default 1")


def _run_engage(args):
    """The engage command; returns 0 or raises InputError."""
    job = _load_job(args.job) if args.job else {}
    given = {key: getattr(args, key) for key in _PARAMETERS}
    if args.phi_range is not None:
        given["phi_range"] = _phi_range(args.phi_range)
    values = {}
    for key, default in _PARAMETERS.items():
        values[key] = given[key] if given[key] is not None else job.get(key, default)
        if values[key] is _REQUIRED:
            raise InputError(f"missing --{key.replace('_', '-')} (or {key!r} in a --job file)")
    try:
        tool = Tool(values["diameter"], values["flutes"], values["flute_length"])
    except ValueError as error:
        raise InputError(f"tool: {error}") from None
    try:
        settings = CutSettings(values["feed_per_tooth"], values["inclination"], *values["phi_range"],
                               values["phi_step"], values["spindle_rpm"])
    except ValueError as error:
        raise InputError(f"cut settings: {error}") from None
    outputs = [args.out, summary_path(args.out)] + ([args.plot] if args.plot else [])
    _check_outputs(outputs, [args.stock, args.toolpath] + ([args.job] if args.job else []))
    stock = load_staircase(args.stock)
    toolpath = load_toolpath(args.toolpath)

    started = time.perf_counter()
    engagement = engage(stock, tool, toolpath, settings, progress=_progress() if sys.stderr.isatty() else None)
    elapsed_ms = 1e3 * (time.perf_counter() - started)
    if not engagement.engaged.any():
        raise InputError(f"{args.toolpath}: the tool never touches the stock: no CL point of the pass engages it "
                         f"(are the toolpath and {args.stock} in the same frame?)")

    texts = (results_text(engagement), summary_text(engagement, toolpath=toolpath))
    title = job.get("description") or (
        f"{os.path.basename(args.stock)} / {os.path.basename(args.toolpath)}: D {tool.diameter:g} mm, "
        f"{tool.flutes} flutes, f {settings.feed_per_tooth:g} mm/tooth, α {settings.inclination:g}°")
    figure = None
    if args.plot:
        from .report.plots import pass_figure  # here: matplotlib takes a while to import
        figure = pass_figure(engagement, title=title)
    for path in outputs:  # only now, so that bad input leaves no folder behind either
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with replacing(*outputs) as temporaries:
        for temporary, text in zip(temporaries, texts):
            write_text(temporary, text)
        if figure is not None:
            figure.savefig(temporaries[2], format="png")

    m, p = engagement.shape
    depth = engagement.depth_of_cut
    print(f"{PROG}: {m} CL points x {p} angles = {m * p} instants in {elapsed_ms:.0f} ms; "
          f"depth of cut {np.nanmin(depth):.3f}-{np.nanmax(depth):.3f} mm "
          f"({int(np.count_nonzero(~np.isnan(depth)))} CL points engage); "
          f"wrote {', '.join(outputs)}")
    return 0


def _load_job(path):
    """Cutting parameters of a --job JSON file as a dict (keys as in _PARAMETERS, + description)."""
    data = load_json_object(path)
    check_keys(data, (), (*_PARAMETERS, "description"), path)
    job = {}
    for key, value in data.items():
        where = f"{path}: {key}"
        if key == "description":
            if not isinstance(value, str):
                raise InputError(f"{where}: must be a string")
            job[key] = value
        elif key == "phi_range":
            if not isinstance(value, list) or len(value) != 2:
                raise InputError(f"{where}: must be [start, end] in degrees, e.g. [0, 180]")
            job[key] = tuple(json_number(v, f"{where}[{i}]") for i, v in enumerate(value))
        else:
            job[key] = json_number(value, where)
    return job


def _phi_range(text):
    """(start, end) in degrees from 'START:END'; InputError naming --phi-range otherwise."""
    parts = text.split(":")
    try:
        if len(parts) != 2:
            raise ValueError
        return float(parts[0]), float(parts[1])
    except ValueError:
        raise InputError(f"--phi-range: expected START:END in degrees such as 0:180, got {text!r}") from None


def _check_outputs(outputs, inputs):
    """InputError if an output's folder cannot be made, or outputs clash with each other or an input."""
    seen = {}
    for path in outputs:
        folder = os.path.dirname(os.path.abspath(path))
        while not os.path.exists(folder):
            folder = os.path.dirname(folder)
        if not os.path.isdir(folder):
            raise InputError(f"{path}: cannot write: {folder} is not a folder")
        key = os.path.normcase(os.path.abspath(path))
        if key in seen:
            raise InputError(f"{path}: written twice (as {seen[key]} too); choose another --plot or --out")
        seen[key] = path
    for path in inputs:
        if os.path.normcase(os.path.abspath(path)) in seen:
            raise InputError(f"{path}: is an input and would be overwritten by an output")


def _progress():
    """Progress callback for engage: 'abm: CL points 120/530' on one line of stderr."""
    def report(done, total):
        end = "\n" if done == total else ""
        print(f"\r{PROG}: CL points {done}/{total}", end=end, file=sys.stderr, flush=True)
    return report

