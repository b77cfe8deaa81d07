"""Command line of the ABM workbench: ``python -m abm_workbench <command> ...``.

Commands:
  engage    cut geometry of one pass: stock + toolpath -> results CSV (+ PNG); --method zmap
            computes it with the discrete Z-map baseline instead of ABM (docs/ZMAP.md).
  validate  the engine against OpenCASCADE booleans at every instant -> HTML report (+ FCStd).
  schedule  the feed per CL point that keeps the peak force (or cut area) under a limit -> a
            re-scheduled toolpath (APT with FEDRAT records, or CSV) (+ HTML report).
  toolpath  what a CL file or toolpath CSV holds, one line per operation (+ CSV of its CL points).

engage --forces adds the cutting forces of the linear edge-force model (docs/FORCES.md).

The stock is a staircase JSON or a solid (STEP, BREP, FCStd: FreeCAD is then needed), the
toolpath a CSV or an APT / CL file. Cutting parameters come from the command line, else the
APT file (CUTTER/TLDATA diameter and flute length, SPINDL speed, a constant FEDRAT as feed per
tooth), else a --job file, else their defaults; the second line of the output says which.
What the APT file could not read, or had to assume, is printed once as ``abm: warning: ...``.

engage --workers N runs the pass in chunks of CL points on N local processes (0: all cores),
--scheduler tcp://host:port on a Dask cluster; the results are the same bytes (docs/SCALING.md).
The results (CSV, or an .npz of columns) are written chunk by chunk, so memory stays bounded
however long the pass.

This module only parses arguments and prints: the options of the cutting parameters come from
their declarations (``jobs.parameters``), the runs from ``jobs.run``, shared with the GUI and imported
only by the command that runs (``--help`` and a usage error import none of the run machinery).
Every number of the options follows the files' grammar (formats.NUMBER), every input must be a regular
file, and every run's work and memory are estimated before it starts and refused above the limits of
abm_workbench.limits (``--allow-large`` confirms a large run; memory is never overrun).
Errors in the input print ``abm: error: <message>`` on stderr and exit with status 2,
leaving no output behind (an existing one is replaced only on success); a failure to write
exits with 1, an interrupt (Ctrl-C) with 130, under the same rule. Missing output folders are
made before the results are streamed into them, and removed again when the command fails.
"""

import argparse
import contextlib
import math
import os
import re
import signal
import sys
import threading
import time
import warnings

import numpy as np

from .errors import InputError, ParameterError
from .forces import COEFFICIENT_NAMES, MATERIALS
from .formats import BEFORE_MOVES
from .formats.cl import STEP, TOLERANCE
from .jobs import BY_NAME, CUTTING, REQUIRED, WALL_MODELS, WALL_POINTS, option_words
from .parallel import ChunkError

PROG = "abm"
#: Methods of the engage command.
METHODS = ("abm", "zmap")


class _Parser(argparse.ArgumentParser):
    """ArgumentParser whose errors read ``abm: error: ...`` (exit status 2) in every subcommand."""

    def error(self, message):
        self.print_usage(sys.stderr)
        self.exit(2, f"{PROG}: error: {message}\n")


def main(argv=None):
    """Run the command line with `argv` (default sys.argv[1:]); return the exit status.

    SIGTERM and SIGHUP stop a run as Ctrl-C does (the same clean-up: no temporary file, staging
    folder or newly made folder left), exit status 128 + the signal's number; from the first of
    them on, SIGINT, SIGTERM and SIGHUP are ignored until the clean-up is done, so a second signal
    cannot cut it short. Once the outputs start moving into place (formats.BEFORE_MOVES) the run is
    finishing and the three are ignored, so that it cannot end with some outputs new and others old.
    numpy's floating-point warnings are not printed.
    """
    previous = {}
    try:
        _stopping_signals(previous)
        BEFORE_MOVES.append(_ignore_stops)
        return _main(argv)
    except KeyboardInterrupt as interrupt:
        _ignore_stops()
        # On a terminal, end the line a progress bar (or the ^C echo) may have left open.
        stop = interrupt.args[0] if isinstance(interrupt, _Stopped) else signal.SIGINT
        words = "interrupted" if stop == signal.SIGINT else f"stopped by {signal.Signals(stop).name}"
        print(("\n" if sys.stderr.isatty() else "") + f"{PROG}: {words}", file=sys.stderr)
        return 128 + stop
    finally:
        with contextlib.suppress(ValueError):
            BEFORE_MOVES.remove(_ignore_stops)
        for number, handler in previous.items():
            signal.signal(number, handler)


def _main(argv):
    """main without the signals: parse `argv`, run the command, print its error; the exit status."""
    parser = _build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exit_:  # usage errors (2) and --help (0)
        return exit_.code
    from .limits import allowing_large

    with np.errstate(all="ignore"), warnings.catch_warnings(), allowing_large(getattr(args, "allow_large", False)):
        warnings.simplefilter("ignore", RuntimeWarning)
        try:
            _check_inputs(args)
            return args.run(args)
        except ParameterError as error:
            print(f"{PROG}: error: {option_words(error)}", file=sys.stderr)
            return 2
        except InputError as error:
            print(f"{PROG}: error: {error}", file=sys.stderr)
            return 2
        except MemoryError as error:
            print(f"{PROG}: error: out of memory{f' ({error})' if str(error) else ''}; the run was larger than "
                  "this machine can hold", file=sys.stderr)
            return 1
        except (OSError, ChunkError) as error:
            print(f"{PROG}: error: {error}", file=sys.stderr)
            return 1


#: The signals that stop a run.
_STOPS = tuple(getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, name))


class _Stopped(KeyboardInterrupt):
    """SIGINT, SIGTERM or SIGHUP received (args[0] the signal's number): unwound like Ctrl-C."""


def _stopping_signals(previous):
    """In the main thread: SIGINT, SIGTERM and SIGHUP raise _Stopped, and the first of them makes all
    three ignored so that the clean-up runs to its end. Each handler replaced goes into dict `previous`
    ({signal: handler}, before the new one is set), for main to put back; in another thread nothing."""
    if threading.current_thread() is not threading.main_thread():
        return

    def stop(number, frame):
        _ignore_stops()
        raise _Stopped(number)

    for number in _STOPS:
        previous[number] = signal.getsignal(number)
        signal.signal(number, stop)


def _ignore_stops():
    """Ignore SIGINT, SIGTERM and SIGHUP from now on (in the main thread; elsewhere nothing)."""
    if threading.current_thread() is threading.main_thread():
        for number in _STOPS:
            signal.signal(number, signal.SIG_IGN)


#: An option's whole number: ASCII digits and an optional sign, as the files' integers.
_WHOLE = re.compile(r"[+-]?[0-9]+")


#: nan and the infinities as Python writes them: read, so that the option's own check says "must be a
#: finite number" in one line.
_NOT_FINITE = re.compile(r"[+-]?(?:nan|inf|infinity)", re.IGNORECASE)


def _float(text):
    """An option's number in the readers' one grammar (formats.NUMBER: ASCII digits, sign, point,
    exponent; no '1_2', no other scripts' digits); ValueError otherwise, which argparse words as
    "invalid float value". nan and inf are read, and refused by each option's check (_check_inputs,
    the parameters' declarations)."""
    from .formats import NUMBER

    if not (re.fullmatch(NUMBER, text.strip()) or _NOT_FINITE.fullmatch(text.strip())):
        raise ValueError(text)
    return float(text)


def _int(text):
    """An option's whole number (ASCII digits, optional sign; at most 18 digits); ValueError otherwise."""
    if not _WHOLE.fullmatch(text.strip()) or len(text.strip().lstrip("+-")) > 18:
        raise ValueError(text)
    return int(text)


_float.__name__, _int.__name__ = "float", "int"  # argparse's words: "invalid float value: '1_2'"


def _build_parser():
    """The argument parser: one subparser per command, each with `run` set to its function."""
    parser = _Parser(prog=PROG, description="Analytical cut geometry of five-axis milling (flat-end, bull-nose and "
                                                "ball-end mills) on staircase and 2.5D stock.")
    commands = parser.add_subparsers(title="commands", dest="command", required=True, metavar="COMMAND")
    engage_parser = commands.add_parser(
        "engage", help="cut geometry of one pass", description=(
            "Length of cut, engagement points, cut area and depth of cut of a flat-end, bull-nose or ball-end "
            "mill along one pass over staircase or 2.5D stock, and the engaged length of its end edge. Lengths in mm, angles in degrees. Writes OUT: a CSV (one row per CL point and "
            "rotation angle) and its summary with .summary.csv (one row per CL point and engagement segment), "
            "or, for a name ending in .npz, both as columns of one NumPy archive; with --plot, a PNG."),
    )
    _input_arguments(engage_parser)
    outputs = engage_parser.add_argument_group("outputs")
    outputs.add_argument("--out", required=True, metavar="R.csv|R.npz",
                         help="results CSV, the summary going to R.summary.csv; or, ending in .npz, a NumPy archive "
                              "of one array per column, the summary's as summary/<column> (docs/USAGE.md)")
    outputs.add_argument("--plot", metavar="R.png", help="also write a PNG of the pass (with --forces, and "
                         "R.forces.png: force along the pass and over φ at chosen CL points)")
    method = engage_parser.add_argument_group("method")
    method.add_argument("--method", choices=METHODS, default="abm",
                        help="abm: the analytical boundary method (default); zmap: the discrete Z-map baseline "
                             "(height grid updated CL point by CL point, edge sampled; docs/ZMAP.md)")
    method.add_argument("--grid", type=_float, metavar="MM",
                        help="Z-map cell size (mm), default 0.2; --method zmap only")
    method.add_argument("--edge-step", type=_float, metavar="MM",
                        help="Z-map sampling step along the cutting edge (mm), default the grid size; "
                             "--method zmap only")
    _force_arguments(engage_parser)
    parallel = engage_parser.add_argument_group("parallel runs (--method abm; docs/SCALING.md)")
    parallel.add_argument("--workers", type=_int, default=1, metavar="N",
                          help="local processes computing chunks of CL points: 1 (default) this process only, "
                               "0 all cores; the results are the same bytes")
    parallel.add_argument("--scheduler", metavar="tcp://HOST:PORT",
                          help="run the chunks on the Dask cluster behind this scheduler (its workers must be able "
                               "to import abm_workbench) instead of local processes")
    _size_arguments(engage_parser)
    engage_parser.set_defaults(run=_run_engage)

    validate_parser = commands.add_parser(
        "validate", help="the engine against OpenCASCADE booleans, as an HTML report", description=(
            "Length of cut by the engine (ABM) and by OpenCASCADE booleans of the cutting edges with the "
            "stock solid, at every CL point and rotation angle; errors as the paper defines them, per "
            "engagement segment and per UEP surface; timings. Writes the folder DIR (index.html and CSV "
            "files) and, with --fcstd, an annotated FreeCAD document. Needs FreeCAD."),
    )
    _input_arguments(validate_parser)
    outputs = validate_parser.add_argument_group("outputs")
    outputs.add_argument("--report", required=True, metavar="DIR",
                         help="report folder (index.html, comparison.csv, segments.csv, surfaces.csv, depth.csv); "
                              "an older report there is replaced")
    outputs.add_argument("--fcstd", metavar="OUT.FCStd", help="also write an annotated FreeCAD document")
    outputs.add_argument("--cl", metavar="I,J,...",
                         help="CL points (0-based) shown in detail and annotated in the FCStd "
                              "(default: deepest, shallowest, middle and largest error; the FCStd all)")
    checking = validate_parser.add_argument_group(
        "CL points checked by the boolean (default all; those of --cl always; the engine computes all)")
    checking.add_argument("--check", metavar="I,J,A-B",
                          help="check these CL points (0-based; A-B a range, both ends included)")
    checking.add_argument("--check-every", type=_int, metavar="N",
                          help="check every N-th CL point from 0 (with --check: both)")
    helical = validate_parser.add_argument_group("helical edges (docs/HELIX.md)")
    helical.add_argument("--helix", type=_float, default=0.0, metavar="DEG",
                         help="helix angle β (deg), default 0: straight edges; otherwise every checked flute's "
                              "helix against booleans of the exact helices; the report shows the first checked "
                              "flute, flutes.csv all of them per instant")
    helical.add_argument("--flute", type=_int, metavar="K", help="check only flute K (1..Z), default all; with --helix")
    validate_parser.add_argument("--workers", type=_int, default=1, metavar="N",
                                 help="processes computing the boolean reference: 1 (default) this process only, 0 "
                                      "all cores (each its own FreeCAD); the results are identical")
    validate_parser.add_argument("--scheduler", metavar="tcp://HOST:PORT",
                                 help="compute the boolean reference on the Dask cluster behind this scheduler (each "
                                      "Dask worker its own FreeCAD; they must be able to import abm_workbench)")
    _force_arguments(validate_parser, helix=False)
    _size_arguments(validate_parser)
    validate_parser.set_defaults(run=_run_validate)

    schedule_parser = commands.add_parser(
        "schedule", help="force- or area-limited feed per CL point", description=(
            "The feed per tooth at every CL point that keeps every instant at or under a limit on the peak "
            "resultant force (--max-force) or the total cut area (--max-area), never above the programmed "
            "feed (the APT file's FEDRAT per move, else --feed-per-tooth). Writes the re-scheduled toolpath: "
            "APT / CL (.apt, .cls) with FEDRAT records in mm/min (mm/rev without a spindle speed), or CSV "
            "with feed columns; with --report, an HTML report of force and feed along the pass before and after."),
    )
    _input_arguments(schedule_parser)
    _force_arguments(schedule_parser, always=True)
    limits = schedule_parser.add_argument_group("limit (one of)").add_mutually_exclusive_group(required=True)
    limits.add_argument("--max-force", type=_float, metavar="N", help="peak resultant force on the tool (N)")
    limits.add_argument("--max-area", type=_float, metavar="MM2",
                        help="peak total cut area of the cutting flutes (mm²)")
    schedule_parser.add_argument("--min-feed", type=_float, metavar="MM",
                                 help="lowest feed per tooth allowed (mm), default a tenth of the programmed feed; "
                                      "CL points that cannot meet the limit at or above it get it, with a warning")
    outputs = schedule_parser.add_argument_group("outputs")
    outputs.add_argument("--out", required=True, metavar="P.apt|P.cls|P.csv", help="re-scheduled toolpath")
    outputs.add_argument("--report", metavar="DIR", help="also write an HTML report (index.html, schedule.csv)")
    _size_arguments(schedule_parser)
    schedule_parser.set_defaults(run=_run_schedule)

    toolpath_parser = commands.add_parser(
        "toolpath", help="what a CL file (APT, CLSF, ...) or toolpath CSV holds, per operation", description=(
            "Reads a CL file as CAM systems write it (NX, CATIA, Creo, SOLIDWORKS CAM, Mastercam, PowerMill APT; "
            "the file type is judged by content) and prints one line per operation (docs/CL_FILES.md); with "
            "--out, writes every cutting CL point as CSV."),
    )
    toolpath_parser.add_argument("file", metavar="FILE", help="CL file, toolpath CSV, G-code or FreeCAD document "
                                                              "(FCStd) holding a CAM Job")
    toolpath_parser.add_argument("--out", metavar="P.csv", help="CSV of every cutting CL point "
                                 "(operation, name, tool, diameter, corner_radius, x, y, z, i, j, k, ...)")
    toolpath_parser.add_argument("--frame", choices=("part", "file"), default="part",
                                 help="part (default): MSYS / CSYS / ROTABL applied; file: as written, in mm")
    _arc_arguments(toolpath_parser)
    _program_arguments(toolpath_parser, "--job")
    _size_arguments(toolpath_parser)
    toolpath_parser.set_defaults(run=_run_toolpath)
    return parser


def _run_toolpath(args):
    """The toolpath command: the program's summary, and with --out its CSV; returns 0."""
    from .formats.cl import read_program
    from .jobs import run as runs
    from .formats.cl.summary import summary_lines, write_toolpath_csv

    if args.out is not None:
        runs.check_outputs([args.out], [args.file])
    tolerance, step = _arc_options(args)
    program = read_program(args.file, tolerance=tolerance, step=step, options=_read_options(args))
    for warning in program.warnings:
        print(f"{PROG}: warning: {warning}", file=sys.stderr)
    print("\n".join(summary_lines(program, args.frame)))
    if args.out is not None:
        with runs.output_folders([args.out]):
            write_toolpath_csv(program, args.out, args.frame)
        print(f"{PROG}: wrote {args.out}")
    return 0


def _force_arguments(parser, *, always=False, helix=True):
    """The helix angle (unless helix is False) and the cutting-force options (engage, validate: only with
    --forces; schedule: always used), from the parameters' declarations."""
    if helix:
        _parameter_option(parser, "helix", "default 0: straight flutes; a helical tool's engagement comes from "
                                           "the helix solver (every flute's exact helix)")
    group = parser.add_argument_group(
        "cutting forces (linear edge-force model, docs/FORCES.md)" + ("" if always else ": with --forces"))
    if not always:
        group.add_argument("--forces", action="store_true",
                           help="engage: add fx, fy, fz (N, global frame), torque (N·mm) and power (W, with a "
                                "spindle speed) to the results, peak and mean force per CL point to the summary; "
                                "validate: a cutting-forces section in the report (and forces.png)")
    group.add_argument("--material", type=str.lower, metavar="NAME",
                       help=f"coefficients of a material: {', '.join(MATERIALS)}; --ktc ... override single values")
    for name in COEFFICIENT_NAMES:
        _parameter_option(group, name, "" if name.endswith("c") else "default 0")
    group.add_argument("--immersion", metavar="START:END",
                       help="angles (deg) where a flute cuts, 0 <= START < END <= 180; default 0:180 (full slot); "
                            "--phi-range only chooses the angles reported")


def _parameter_option(group, name, extra=""):
    """The option of parameter `name`: its declared option, type, unit and help."""
    parameter = BY_NAME[name]
    unit = {"deg": "DEG", "mm": "MM", "": "N"}.get(parameter.unit, parameter.unit.replace("²", "2").upper())
    text = f"{parameter.help} ({parameter.unit})" if parameter.unit else parameter.help
    group.add_argument(parameter.option, dest=name, type=_int if parameter.whole else _float, metavar=unit,
                       help=", ".join(filter(None, [text, extra])))


def _input_arguments(parser):
    """Input files, cutting parameters and stock options, shared by engage and validate."""
    files = parser.add_argument_group("inputs")
    files.add_argument("--stock", metavar="STOCK",
                       help="staircase stock: abm-staircase/1 JSON, or a solid (.step, .stp, .brep, .brp, .FCStd); "
                            "required unless --toolpath is a FreeCAD document whose CAM Job's Stock it then is")
    files.add_argument("--toolpath", required=True, metavar="PATH",
                       help="CL points: a CL file as CAM systems write it (APT, NX CLSF, CATIA, Creo NCL, "
                            "SOLIDWORKS CAM, Mastercam, PowerMill; any name, read by its content) or a toolpath CSV "
                            "(x,y,z,theta_a,theta_b or x,y,z,i,j,k; + optional xc,yc,zc; docs/CL_FILES.md)")
    files.add_argument("--operation", type=_int, metavar="N",
                       help="the toolpath file's operation N (1-based; the toolpath command lists them); default "
                            "its one milling operation")
    files.add_argument("--stock-model", choices=("in-process", "initial"),
                       help="in-process: the stock minus what the program's earlier cutting moves removed (default "
                            "where available: straight flutes, ABM); initial: the stock as given")
    files.add_argument("--sweep-tolerance", type=_float, default=0.05, metavar="MM",
                       help="sub-step of five-axis moves at the tool's rim for the in-process stock (mm), default 0.05")
    _arc_arguments(files)
    _program_arguments(files)
    files.add_argument("--job", metavar="JOB.json",
                       help="JSON of default cutting parameters (keys as the options below, with _ for -; "
                            "phi_range as [start, end]; description); options and the APT file override it")
    cutting = parser.add_argument_group(
        "cutting parameters (the APT file's tool, spindle and feed win where it gives them; "
        "options override --job)")
    for name in CUTTING:
        if name == "phi_start":
            cutting.add_argument("--phi-range", metavar="START:END", help="tool rotation angles φ (deg), default "
                                 "0:180 (--phi-range=-10:190 for a negative start)")
        elif name != "phi_end":
            default = BY_NAME[name].default
            _parameter_option(cutting, name, "required" if default is REQUIRED else
                              "" if default is None else f"default {default:g}")
    solid = parser.add_argument_group("solid stock (STEP, BREP, FCStd) only")
    solid.add_argument("--solid", metavar="NAME",
                       help="the solid to use in a file holding several: an FCStd object's Name or Label, or "
                            "Solid1, Solid2, ... in a STEP or BREP file's order")
    solid.add_argument("--walls", choices=WALL_MODELS,
                       help="wall model: the solid's own curves (exact, default) or the paper's quintic through "
                            "six points (quintic)")
    solid.add_argument("--wall-points", choices=WALL_POINTS,
                       help="where the six points of each wall lie over the y window (default chebyshev)")
    solid.add_argument("--y-window", metavar="whole|swept|Y0:Y1",
                       help="y range recognised (mm): the stock's whole range (whole, the default for exact "
                            "walls), the range the cutting edges sweep below the stock's top in the pass plus 1 mm "
                            "(swept, the default for quintic walls: the paper's six points cover the pass), or "
                            "Y0:Y1 (--y-window=-10:10 for a negative start)")



def _size_arguments(parser):
    """--allow-large: run even where the run's estimated work is above what runs without confirmation."""
    parser.add_argument("--allow-large", action="store_true",
                        help="run even when the estimated work (CL points x angles, interpolated arc points, swept "
                             "pieces of the in-process stock, boolean checks) or output size is above what runs "
                             "without confirmation; memory beyond what this process may use is refused all the same "
                             "(docs/USAGE.md, \"Limits\")")


def _arc_arguments(group):
    """--tolerance and --step: how a CL file's arcs and curves become CL points."""
    group.add_argument("--tolerance", type=_float, default=TOLERANCE, metavar="MM",
                       help=f"chordal tolerance of interpolated arcs and curves (mm), default {TOLERANCE:g}")
    group.add_argument("--step", type=_float, default=STEP, metavar="MM",
                       help=f"largest distance between the CL points along arcs and curves (mm), default {STEP:g}, "
                            "about a tooth's feed")


def _program_arguments(group, *job_aliases):
    """--cam-job (and `job_aliases`), --tool-table, --machine, --offsets: what reading a FreeCAD CAM Job or
    G-code needs besides the file (docs/GCODE.md)."""
    group.add_argument(*job_aliases, "--cam-job", dest="cam_job", metavar="NAME",
                       help="the FreeCAD CAM Job (its Name or Label) of a toolpath FCStd; default its one Job")
    group.add_argument("--tool-table", metavar="FILE",
                       help="G-code: the tools of its T words, a LinuxCNC tool table (T P D Z ;comment lines) or "
                            "the FreeCAD document (FCStd) that posted it")
    group.add_argument("--machine", metavar="FILE",
                       help="G-code: a machine file (JSON) naming the kinematics of its rotary words A B C "
                            "(xyzac-trt, xyzbc-trt, xyzbc-ht) and their pivots")
    group.add_argument("--offsets", metavar="FILE",
                       help="G-code: the work offsets G54-G59.3, a LinuxCNC parameter file or JSON; default all zero")
    group.add_argument("--machine-units", choices=("mm", "inch"),
                       help="G-code: the unit of the LinuxCNC tool table's and parameter file's lengths, the "
                            "machine's (default mm; a program in inches with such a file needs it said)")


def _read_options(args):
    """The ReadOptions of the parsed arguments."""
    from .formats.gcode.options import ReadOptions

    return ReadOptions(args.cam_job, args.tool_table, args.machine, args.offsets, args.machine_units)


def _arc_options(args):
    """(tolerance, step) mm of the parsed arguments; ParameterError unless each is a number of mm from
    formats.cl.arcs.MIN_TOLERANCE (a nanometre) up."""
    from .formats.cl.arcs import MIN_TOLERANCE

    for name in ("tolerance", "step"):
        value = getattr(args, name)
        if not (np.isfinite(value) and value >= MIN_TOLERANCE):
            raise ParameterError(name, f"must be at least {MIN_TOLERANCE:g} mm, got {value:g}")
    return args.tolerance, args.step


#: File options and what each names, for the errors.
_INPUT_FILES = {"stock": "stock", "toolpath": "toolpath", "job": "job", "tool_table": "tool table",
                "machine": "machine", "offsets": "work offsets", "file": "toolpath"}
#: Options of numbers that are no job parameter (those are checked by their declarations).
_NUMBERS = ("tolerance", "step", "grid", "edge_step", "sweep_tolerance", "max_force", "max_area", "min_feed")


def _check_inputs(args):
    """Before anything is read: every input file given that exists is a regular file (not a folder, FIFO,
    socket or device, whose reading would block or never end), every number option finite and at most
    formats.MAX_MAGNITUDE in size; empty file names refused (the CL lists are checked as they are read,
    jobs.checked).
    InputError / ParameterError otherwise."""
    from .formats import MAX_MAGNITUDE, check_input_file

    for name, what in _INPUT_FILES.items():
        path = getattr(args, name, None)
        if path is not None:
            if not path.strip():
                raise ParameterError(name, f"is empty; give the {what} file")
            if os.path.lexists(path):  # a missing file is its reader's to name, with the kinds it reads
                check_input_file(path, what)
    for name in _NUMBERS:
        value = getattr(args, name, None)
        if value is not None and not math.isfinite(value):
            raise ParameterError(name, f"must be a finite number, got {value!r}")
        if value is not None and not abs(value) <= MAX_MAGNITUDE:
            raise ParameterError(name, f"must be at most {MAX_MAGNITUDE:g} in size, got {value:g}")
    for name in ("out", "report", "fcstd", "plot"):
        text = getattr(args, name, None)
        if text is not None and not text.strip():
            raise ParameterError(name, "is empty; give a file name" if name != "report" else "is empty; give a folder")
    workers = getattr(args, "workers", None)
    if isinstance(workers, int) and workers > 1:
        from .limits import usable_cores

        if workers > usable_cores():
            _warn(f"--workers {workers}: this process may run on {usable_cores()} cores; {usable_cores()} worker "
                  "processes are started")


def _job(args):
    """The Job of the parsed arguments: the cutting and force options by parameter name; without --stock, the
    Stock of the toolpath's FreeCAD CAM Job."""
    from .jobs import Job
    from .jobs.job import with_cam_stock

    given = {name: getattr(args, name, None) for name in BY_NAME if name not in
             ("phi_start", "phi_end", "immersion_start", "immersion_end")}
    if args.phi_range is not None:
        given["phi_start"], given["phi_end"] = _pair(args.phi_range, "phi_start", "START:END in degrees such as 0:180")
    forces = getattr(args, "forces", True)
    if getattr(args, "immersion", None) is not None:
        given["immersion_start"], given["immersion_end"] = _pair(args.immersion, "immersion_start",
                                                                 "START:END in degrees such as 0:180")
    if not forces:
        extra = [f"--{name}" for name in ("material", *COEFFICIENT_NAMES, "immersion") if getattr(args, name) is not None]
        if extra:
            raise InputError(f"{extra[0]} applies with --forces")
    tolerance, step = _arc_options(args)
    window = args.y_window
    if window is not None and window not in ("whole", "swept"):
        window = _pair(window, "y_window", "whole, swept or Y0:Y1 in mm such as -10:10")
    job = Job(args.stock, args.toolpath, args.job, given, forces=forces, material=getattr(args, "material", None),
              walls=args.walls, wall_points=args.wall_points, y_window=window, operation=args.operation,
              solid=args.solid, stock_model=args.stock_model, sweep_tolerance=args.sweep_tolerance,
              tolerance=tolerance, step=step, options=_read_options(args))
    return with_cam_stock(job)


def _pair(text, field, expected):
    """(a, b) floats from 'A:B'; ParameterError naming `field` and what was `expected` otherwise."""
    parts = text.split(":")
    try:
        if len(parts) != 2:
            raise ValueError
        pair = _float(parts[0]), _float(parts[1])
        if not all(map(math.isfinite, pair)):
            raise ValueError
        return pair
    except ValueError:
        raise ParameterError(field, f"expected {expected}, got {text!r}") from None


def _warn(message):
    """Print a warning on stderr."""
    print(f"{PROG}: warning: {message}", file=sys.stderr)


def _parameters_line(prepared, stock):
    """The second output line: each parameter and where it came from, the helix, the stock's model."""
    helix = f", helix {prepared.tool.helix:g}° [--helix]" if prepared.tool.helix else ""
    model = "" if stock.shape is None and stock.staircase is not None else f"; stock: {stock.describe()}"
    return f"{PROG}: parameters: {prepared.parameters.describe()}{helix}{model}"


def _run_engage(args):
    """The engage command; returns 0 or raises InputError."""
    from .jobs import run as runs

    method = runs.Method(args.method, args.grid, args.edge_step, args.workers, args.scheduler)
    progress = _engine_progress() if sys.stderr.isatty() else None
    result = runs.engage(_job(args), args.out, plot=args.plot, method=method, warn=_warn, progress=progress)
    prepared, depth, peak = result.prepared, result.depth, result.peak
    if args.method == "abm":
        workers = runs.worker_count(args.workers)
        where = (f" on the Dask cluster at {args.scheduler}" if args.scheduler else
                 f" on {workers} processes" if workers > 1 else "")
    else:
        grid, step = runs.zmap_cells(method)
        where = f" (Z-map, grid {grid:g} mm, edge step {step:g} mm)"
    m, p = len(prepared.toolpath), prepared.settings.phi.size
    print(f"{PROG}: {m} CL points x {p} angles = {m * p} instants in {1e3 * result.seconds:.0f} ms{where} "
          f"(files included); depth of cut {np.nanmin(depth):.3f}-{np.nanmax(depth):.3f} mm "
          f"({int(np.count_nonzero(~np.isnan(depth)))} CL points engage)"
          + ("" if peak is None else f"; peak force {np.nanmax(peak):.4g} N at CL {int(np.nanargmax(peak))}")
          + f"; wrote {', '.join(result.written)}")
    model = (f"initial stock{f' ({result.model_note})' if result.model_note else ''}" if result.changed is None
             else f"in-process stock ({int(result.changed.sum())} of {m} CL points changed by earlier moves)")
    print(_parameters_line(prepared, result.stock) + f"; {model}")
    return 0


def _run_validate(args):
    """The validate command; returns 0 or raises InputError."""
    from .jobs import run as runs
    from .validation import overall

    label = "boolean reference" if not args.helix and args.flute is None else "helix boolean reference"
    if args.workers < 0:
        raise ParameterError("workers", f"must be 0 (all cores) or a positive number of processes, got {args.workers}")
    result = runs.validate(_job(args), args.report, fcstd=args.fcstd, cls=args.cl, check=args.check,
                           check_every=args.check_every, flute=args.flute,
                           workers=args.workers, scheduler=args.scheduler, warn=_warn,
                           progress=_Progress(label, sys.stderr))
    validation, forces = result.validation, result.forces
    total = overall(validation.comparison)
    m, p = validation.engagement.shape
    print(f"{PROG}: {m} CL points x {p} angles: length of cut max |relative error| "
          f"{100 * total['max_rel_error']:.3g} % (mean {100 * total['mean_rel_error']:.3g} %, "
          f"{total['relative_instants']} instants), max |difference| {total['max_abs_difference']:.3g} mm; "
          f"ABM {validation.seconds['abm']:.3g} s, boolean {validation.seconds['boolean']:.3g} s "
          f"({validation.speed_ratio:.0f}x)"
          + ("" if forces is None else f"; peak force {forces.peak.max():.4g} N at CL {int(np.argmax(forces.peak))}")
          + f"; wrote {', '.join(result.written)}")
    if result.helix is not None:
        print(f"{PROG}: {runs.flutes_text(result.helix)}")
    print(_parameters_line(result.prepared, result.stock))
    return 0


def _run_schedule(args):
    """The schedule command; returns 0 or raises InputError."""
    from .jobs import run as runs

    result = runs.schedule(_job(args), args.out, max_force=args.max_force, max_area=args.max_area,
                           min_feed=args.min_feed, report=args.report, warn=_warn)
    plan, kind = result.plan, result.kind
    unit = "N" if kind == "force" else "mm²"
    print(f"{PROG}: {len(result.prepared.toolpath)} CL points: peak {kind} {plan.before.max():.4g} -> "
          f"{plan.after.max():.4g} {unit} (limit {result.limit:g}); feed lowered at {int(plan.reduced.sum())} CL "
          f"points, to {plan.feed.min():.4g} mm/tooth at least; {int(plan.infeasible.sum())} cannot meet the limit; "
          f"wrote {', '.join(result.written)}")
    print(_parameters_line(result.prepared, result.stock))
    return 0


def _engine_progress():
    """Progress callback for engage on a terminal: a bar redrawn on one line of stderr with the CL
    points done, the time elapsed and an estimate of the time left (_Progress), which long runs
    against the in-process stock need most."""
    return _Progress("engage", sys.stderr)


class _Progress:
    """Progress of a long per-CL-point loop on `stream`, with elapsed time and ETA.

    On a terminal one line redrawn as a bar; otherwise one line per CL point.
    """

    #: Width of the bar (characters).
    BAR = 30

    def __init__(self, label, stream):
        self.label, self.stream = label, stream
        self.started = time.perf_counter()
        self.terminal = stream.isatty()

    def __call__(self, done, total):
        elapsed = time.perf_counter() - self.started
        eta = elapsed / done * (total - done)
        timing = f"{elapsed:.1f} s elapsed, ETA {eta:.0f} s"
        if self.terminal:
            filled = round(self.BAR * done / total)
            bar = "#" * filled + "." * (self.BAR - filled)
            end = "\n" if done == total else ""
            print(f"\r{PROG}: {self.label} [{bar}] {done}/{total} CL points, {timing}", end=end, file=self.stream,
                  flush=True)
        else:
            # One write with its newline: print's separate write of the newline could be cut off
            # by SIGTERM, and the stop message would then continue this line.
            self.stream.write(f"{PROG}: {self.label}: CL point {done}/{total}, {timing}\n")
            self.stream.flush()
