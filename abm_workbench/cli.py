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
The results CSV is written chunk by chunk, so memory stays bounded however long the pass.

Errors in the input print ``abm: error: <message>`` on stderr and exit with status 2,
leaving no output behind (an existing one is replaced only on success); a failure to write
exits with 1, an interrupt (Ctrl-C) with 130, under the same rule. Missing output folders are
made before the results are streamed into them, and removed again when the command fails.
"""

import argparse
import contextlib
import dataclasses
import functools
import os
import re
import sys
import time

import numpy as np

from .engine import engage, flute_engagement, zmap_engage
from .errors import InputError
from .formats import replacing
from .formats.results_csv import chunk_texts, summary_path, write_chunks
from .forces import (COEFFICIENT_NAMES, FULL_SLOT, MATERIALS, Coefficients, check_immersion, joined_forces, material,
                     pass_forces)
from .parallel import ChunkError, PassAssembly, map_chunks, toolpath_part, worker_count
from .jobs import (PARAMETERS, SOLID_SUFFIXES, WALL_MODELS, WALL_POINTS, load_job, load_path, load_stock,
                   resolve_parameters, swept_y_window, tool_and_settings)

PROG = "abm"
#: Methods of the engage command.
METHODS = ("abm", "zmap")
#: Default Z-map cell size (mm), the paper's.
ZMAP_GRID = 0.2


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
    except (OSError, ChunkError) as error:
        print(f"{PROG}: error: {error}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        # On a terminal, end the line a progress bar (or the ^C echo) may have left open.
        print(("\n" if sys.stderr.isatty() else "") + f"{PROG}: interrupted", file=sys.stderr)
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
    _input_arguments(engage_parser)
    outputs = engage_parser.add_argument_group("outputs")
    outputs.add_argument("--out", required=True, metavar="R.csv", help="results CSV; the summary goes to R.summary.csv")
    outputs.add_argument("--plot", metavar="R.png", help="also write a PNG of the pass (with --forces, and "
                         "R.forces.png: force along the pass and over φ at chosen CL points)")
    method = engage_parser.add_argument_group("method")
    method.add_argument("--method", choices=METHODS, default="abm",
                        help="abm: the analytical boundary method (default); zmap: the discrete Z-map baseline "
                             "(height grid updated CL point by CL point, edge sampled; docs/ZMAP.md)")
    method.add_argument("--grid", type=float, metavar="MM",
                        help="Z-map cell size (mm), default 0.2; --method zmap only")
    method.add_argument("--edge-step", type=float, metavar="MM",
                        help="Z-map sampling step along the cutting edge (mm), default the grid size; "
                             "--method zmap only")
    _force_arguments(engage_parser)
    parallel = engage_parser.add_argument_group("parallel runs (--method abm; docs/SCALING.md)")
    parallel.add_argument("--workers", type=int, default=1, metavar="N",
                          help="local processes computing chunks of CL points: 1 (default) this process only, "
                               "0 all cores; the results are the same bytes")
    parallel.add_argument("--scheduler", metavar="tcp://HOST:PORT",
                          help="run the chunks on the Dask cluster behind this scheduler (its workers must be able "
                               "to import abm_workbench) instead of local processes")
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
    helical = validate_parser.add_argument_group("helical edges (docs/HELIX.md)")
    helical.add_argument("--helix", type=float, default=0.0, metavar="DEG",
                         help="helix angle β (deg), default 0: straight edges; otherwise every checked flute's "
                              "helix against booleans of the exact helices; the report shows the first checked "
                              "flute, flutes.csv all of them per instant")
    helical.add_argument("--flute", type=int, metavar="K", help="check only flute K (1..Z), default all; with --helix")
    _force_arguments(validate_parser, helix=False)
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
    limits.add_argument("--max-force", type=float, metavar="N", help="peak resultant force on the tool (N)")
    limits.add_argument("--max-area", type=float, metavar="MM2",
                        help="peak total cut area of the cutting flutes (mm²)")
    schedule_parser.add_argument("--min-feed", type=float, metavar="MM",
                                 help="lowest feed per tooth allowed (mm), default a tenth of the programmed feed; "
                                      "CL points that cannot meet the limit at or above it get it, with a warning")
    outputs = schedule_parser.add_argument_group("outputs")
    outputs.add_argument("--out", required=True, metavar="P.apt|P.cls|P.csv", help="re-scheduled toolpath")
    outputs.add_argument("--report", metavar="DIR", help="also write an HTML report (index.html, schedule.csv)")
    schedule_parser.set_defaults(run=_run_schedule)

    toolpath_parser = commands.add_parser(
        "toolpath", help="what a CL file (APT, CLSF, ...) or toolpath CSV holds, per operation", description=(
            "Reads a CL file as CAM systems write it (NX, CATIA, Creo, SOLIDWORKS CAM, Mastercam, PowerMill APT; "
            "the file type is judged by content) and prints one line per operation (docs/CL_FILES.md); with "
            "--out, writes every cutting CL point as CSV."),
    )
    toolpath_parser.add_argument("file", metavar="FILE", help="CL file or toolpath CSV")
    toolpath_parser.add_argument("--out", metavar="P.csv", help="CSV of every cutting CL point "
                                 "(operation, name, tool, diameter, corner_radius, x, y, z, i, j, k, ...)")
    toolpath_parser.add_argument("--frame", choices=("part", "file"), default="part",
                                 help="part (default): MSYS / CSYS / ROTABL applied; file: as written, in mm")
    toolpath_parser.add_argument("--tolerance", type=float, default=0.001, metavar="MM",
                                 help="chordal tolerance of interpolated arcs and curves (mm), default 0.001")
    toolpath_parser.set_defaults(run=_run_toolpath)
    return parser


def _run_toolpath(args):
    """The toolpath command: the program's summary, and with --out its CSV; returns 0."""
    from .formats.cl import read_program
    from .formats.cl.summary import summary_lines, write_toolpath_csv

    if args.out:
        _check_outputs([args.out], [args.file])
    program = read_program(args.file, tolerance=args.tolerance)
    for warning in program.warnings:
        print(f"{PROG}: warning: {warning}", file=sys.stderr)
    print("\n".join(summary_lines(program, args.frame)))
    if args.out:
        os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
        write_toolpath_csv(program, args.out, args.frame)
        print(f"{PROG}: wrote {args.out}")
    return 0


def _force_arguments(parser, *, always=False, helix=True):
    """The helix angle (unless helix is False) and the cutting-force options (engage, validate: only with
    --forces; schedule: always used)."""
    if helix:
        parser.add_argument("--helix", type=float, default=0.0, metavar="DEG",
                            help="helix angle β of the flutes (deg), default 0: straight flutes; a helical tool's "
                                 "engagement comes from the helix solver (every flute's exact helix)")
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
        unit = "N/mm²" if name.endswith("c") else "N/mm"
        group.add_argument(f"--{name}", type=float, metavar=unit.replace("²", "2"),
                           help=f"K_{name[1:]} ({unit})" + ("" if name.endswith("c") else ", default 0"))
    group.add_argument("--immersion", metavar="START:END",
                       help="angles (deg) where a flute cuts, 0 <= START < END <= 180; default 0:180 (full slot); "
                            "--phi-range only chooses the angles reported")


def _input_arguments(parser):
    """Input files, cutting parameters and stock options, shared by engage and validate."""
    files = parser.add_argument_group("inputs")
    files.add_argument("--stock", required=True, metavar="STOCK",
                       help="staircase stock: abm-staircase/1 JSON, or a solid (.step, .stp, .brep, .brp, .FCStd)")
    files.add_argument("--toolpath", required=True, metavar="PATH",
                       help="CL points: CSV (x,y,z,theta_a,theta_b or x,y,z,i,j,k; + optional xc,yc,zc) "
                            "or APT / CL file (.apt, .cls)")
    files.add_argument("--job", metavar="JOB.json",
                       help="JSON of default cutting parameters (keys as the options below, with _ for -; "
                            "phi_range as [start, end]; description); options and the APT file override it")
    cutting = parser.add_argument_group(
        "cutting parameters (the APT file's tool, spindle and feed win where it gives them; "
        "options override --job)")
    cutting.add_argument("--diameter", type=float, help="tool diameter (mm), required")
    cutting.add_argument("--flutes", type=int, help="number of flutes, required")
    cutting.add_argument("--flute-length", type=float, help="flute length (mm), required")
    cutting.add_argument("--feed-per-tooth", type=float, help="feed per tooth f (mm), required")
    cutting.add_argument("--inclination", type=float, help="tool inclination angle α (deg), default 0")
    cutting.add_argument("--spindle-rpm", type=float, help="spindle speed (rpm)")
    cutting.add_argument("--phi-range", metavar="START:END",
                         help="tool rotation angles φ (deg), default 0:180 (--phi-range=-10:190 for a negative start)")
    cutting.add_argument("--phi-step", type=float, help="step of φ (deg), default 1")
    solid = parser.add_argument_group("solid stock (STEP, BREP, FCStd) only")
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


def _prepare(args):
    """(job dict, Toolpath, Parameters, Tool, CutSettings) of the command line; warnings printed."""
    job = load_job(args.job) if args.job else {}
    toolpath, hints = load_path(args.toolpath)
    given = {key: getattr(args, key) for key in PARAMETERS}
    if args.phi_range is not None:
        given["phi_range"] = _phi_range(args.phi_range)
    parameters = resolve_parameters(given, hints, job, args.job)
    for message in [*hints.messages(), *parameters.conflicts]:
        print(f"{PROG}: warning: {message}", file=sys.stderr)
    tool, settings = tool_and_settings(parameters.values)
    return job, toolpath, parameters, tool, settings


def _load_stock(args, toolpath, tool):
    """(Stock, seconds to read it): solid options checked, the y window chosen."""
    is_solid = os.path.splitext(args.stock)[1].lower() in SOLID_SUFFIXES
    options = {"--walls": args.walls, "--wall-points": args.wall_points, "--y-window": args.y_window}
    for option, value in options.items():
        if value is not None and not is_solid:
            raise InputError(f"{option} applies to a solid stock (.step, .stp, .brep, .brp, .FCStd), not to "
                             f"{args.stock}")
    window = args.y_window or ("swept" if args.walls == "quintic" else "whole")
    if window == "whole":
        window = None
    elif window == "swept":
        window = functools.partial(swept_y_window, toolpath, tool)  # completed with the solid's top z
    else:
        window = _pair(window, "--y-window", "whole, swept or Y0:Y1 in mm such as -10:10")
    started = time.perf_counter()
    stock = load_stock(args.stock, walls=args.walls or "exact", wall_points=args.wall_points or "chebyshev",
                       y_window=window)
    return stock, time.perf_counter() - started


def _stock_line(stock):
    """'; stock: exact walls, y window -15..15 mm' for a solid stock, '' for JSON."""
    if stock.shape is None:
        return ""
    y0, y1 = stock.y_window
    return f"; stock: {stock.walls} walls, y window {y0:.6g}..{y1:.6g} mm"


def _force_model(args, always=False):
    """(Coefficients, immersion (start, end) deg) of the force options, or None without --forces."""
    if not (always or args.forces):
        given = [f"--{name}" for name in ("material", *COEFFICIENT_NAMES, "immersion")
                 if getattr(args, name) is not None]
        if given:
            raise InputError(f"{given[0]} applies with --forces")
        return None
    values = {}
    if args.material is not None:
        try:
            values = dataclasses.asdict(material(args.material))
        except ValueError as error:
            raise InputError(f"--material: {error}") from None
    values.update({name: getattr(args, name) for name in COEFFICIENT_NAMES if getattr(args, name) is not None})
    missing = [name for name in ("ktc", "krc", "kac") if name not in values]
    if missing:
        raise InputError(f"missing --{missing[0]}: the forces need --material NAME or --ktc, --krc and --kac")
    try:
        coefficients = Coefficients(**values)
    except ValueError as error:
        raise InputError(f"--{str(error).split()[0]}: {error}") from None
    immersion = FULL_SLOT
    if args.immersion is not None:
        pair = _pair(args.immersion, "--immersion", "START:END in degrees such as 0:180")
        try:
            immersion = check_immersion(pair)
        except ValueError as error:
            raise InputError(f"--immersion: {error}") from None
    return coefficients, immersion


def _helical(args, tool):
    """`tool` with the --helix angle; InputError naming --helix if it is out of range."""
    try:
        return dataclasses.replace(tool, helix=args.helix)
    except ValueError as error:
        raise InputError(f"--helix: {error}") from None


def _flute_1(stock, tool, toolpath, settings, progress=None):
    """Engagement of flute 1: the straight engine, or flute 0 of the helix solver for a helical tool."""
    if tool.helix == 0.0:
        return engage(stock, tool, toolpath, settings, progress=progress)
    return flute_engagement(stock, tool, toolpath, settings, progress=progress).as_engagement(0)


def _run_engage(args):
    """The engage command; returns 0 or raises InputError."""
    compute, method_text = _engage_method(args)
    force_model = _force_model(args)
    if force_model is not None and args.method != "abm":
        raise InputError("--forces needs --method abm")
    if args.helix != 0.0 and args.method != "abm":
        raise InputError("--helix needs --method abm")
    job, toolpath, parameters, tool, settings = _prepare(args)
    tool = _helical(args, tool)
    outputs = [args.out, summary_path(args.out)] + ([args.plot] if args.plot else [])
    if args.plot and force_model is not None:
        outputs.append(os.path.splitext(args.plot)[0] + ".forces.png")
    _check_outputs(outputs, [args.stock, args.toolpath] + ([args.job] if args.job else []))
    stock, _ = _load_stock(args, toolpath, tool)

    progress = _engine_progress() if sys.stderr.isatty() else None
    started = time.perf_counter()
    whole = PassAssembly(len(toolpath)) if args.plot else None
    force_parts = [] if args.plot and force_model is not None else None
    depth, peak = np.full(len(toolpath), np.nan), np.full(len(toolpath), np.nan)
    with _output_folders(outputs), replacing(*outputs) as temporaries:
        if compute is None:
            chunks = map_chunks(_CsvChunk(keep=whole is not None, force_model=force_model),
                                [(stock.staircase, tool, toolpath, settings)],
                                workers=args.workers, scheduler=args.scheduler, progress=progress)
        else:
            engagement = compute(stock.staircase, tool, toolpath, settings, progress=progress)
            chunks = [(0, 0, len(toolpath), ChunkResult(chunk_texts(engagement, 0, toolpath=toolpath),
                                                        engagement.depth_of_cut, engagement))]
        write_chunks(_kept(chunks, depth, peak, whole, force_parts), temporaries[0], temporaries[1])
        if np.isnan(depth).all():
            raise InputError(_no_engagement(args))
        if whole is not None:
            from .report.plots import pass_figure  # here: matplotlib takes a while to import
            title = job.get("description") or (
                f"{os.path.basename(args.stock)} / {os.path.basename(args.toolpath)}: D {tool.diameter:g} mm, "
                f"{tool.flutes} flutes, f {settings.feed_per_tooth:g} mm/tooth, α {settings.inclination:g}°")
            pass_figure(whole.engagement(), title=title).savefig(temporaries[2], format="png")
        if force_parts is not None:
            from .report.forces import chosen_cl, force_over_phi_figure
            forces = joined_forces(force_parts)
            force_over_phi_figure(forces, chosen_cl(forces), along=True).savefig(temporaries[3], format="png")
    elapsed_ms = 1e3 * (time.perf_counter() - started)

    m, p = len(toolpath), settings.phi.size
    print(f"{PROG}: {m} CL points x {p} angles = {m * p} instants in {elapsed_ms:.0f} ms{method_text} (files included); "
          f"depth of cut {np.nanmin(depth):.3f}-{np.nanmax(depth):.3f} mm "
          f"({int(np.count_nonzero(~np.isnan(depth)))} CL points engage)"
          + ("" if force_model is None else f"; peak force {np.nanmax(peak):.4g} N at CL {int(np.nanargmax(peak))}")
          + f"; wrote {', '.join(outputs)}")
    print(f"{PROG}: parameters: {parameters.describe()}{_helix_text(tool)}{_stock_line(stock)}")
    return 0


def _helix_text(tool):
    """', helix 30° [--helix]' for a helical tool, '' for straight flutes."""
    return f", helix {tool.helix:g}° [--helix]" if tool.helix else ""


@dataclasses.dataclass(frozen=True)
class ChunkResult:
    """What a chunk task of engage gives back: (results, summary) CSV text and the depth of cut
    (n,); the chunk's Engagement and Forces when kept for the plots; the peak resultant force
    (n,) when forces are computed."""

    texts: tuple
    depth: np.ndarray
    engagement: object = None
    forces: object = None
    peak: object = None


@dataclasses.dataclass(frozen=True)
class _CsvChunk:
    """Task of a parallel engage: a chunk of CL points engaged (flute 1, straight or helical) and,
    when force_model = (Coefficients, immersion) is given, its forces, as a ChunkResult; the
    Engagement and Forces are kept for the plots when `keep`."""

    keep: bool
    force_model: object = None

    def __call__(self, job, start, stop):
        stock, tool, toolpath, settings = job
        part = toolpath_part(toolpath, start, stop)
        engagement = _flute_1(stock, tool, part, settings)
        forces = None
        if self.force_model is not None:
            coefficients, immersion = self.force_model
            forces = pass_forces(stock, tool, part, settings, coefficients, immersion=immersion,
                                 first=engagement.length if tool.helix == 0.0 else None)
        return ChunkResult(chunk_texts(engagement, start, toolpath=part, forces=forces), engagement.depth_of_cut,
                           engagement if self.keep else None, forces if self.keep else None,
                           None if forces is None else forces.peak)


def _kept(chunks, depth, peak, whole, force_parts):
    """The CSV texts of (job, start, stop, ChunkResult) `chunks`, in order; each chunk's depth of
    cut and peak force stored into `depth` and `peak` (m,), its Engagement added to `whole` (a
    PassAssembly) and its Forces appended to `force_parts`, when these are given."""
    for _, start, stop, result in chunks:
        depth[start:stop] = result.depth
        if result.peak is not None:
            peak[start:stop] = result.peak
        if whole is not None:
            whole.add(result.engagement, start)
        if force_parts is not None:
            force_parts.append(result.forces)
        yield result.texts


@contextlib.contextmanager
def _output_folders(outputs):
    """Make the missing folders of `outputs`; remove the ones made (if empty) when the block fails."""
    made = []
    for path in outputs:
        folder, missing = os.path.dirname(os.path.abspath(path)), []
        while not os.path.exists(folder):
            folder, missing = os.path.dirname(folder), missing + [folder]
        for folder in reversed(missing):
            os.mkdir(folder)
            made.append(folder)
    try:
        yield
    except BaseException:
        for folder in reversed(made):
            with contextlib.suppress(OSError):
                os.rmdir(folder)
        raise


def _engage_method(args):
    """(function computing the Engagement, text for the output line) of --method, --grid, --edge-step;
    (None, text) for ABM, which runs in chunks (--workers, --scheduler)."""
    if args.method == "abm":
        given = [option for option, value in (("--grid", args.grid), ("--edge-step", args.edge_step))
                 if value is not None]
        if given:
            raise InputError(f"{given[0]} applies to --method zmap, not to --method abm")
        try:
            workers = worker_count(args.workers)
        except ValueError:
            raise InputError(f"--workers: must be 0 (all cores) or a positive number of processes, got "
                             f"{args.workers}") from None
        if args.scheduler is not None and not re.fullmatch(r"[a-z][a-z0-9+.-]*://\S+", args.scheduler):
            raise InputError(f"--scheduler: expected a Dask scheduler address such as tcp://127.0.0.1:8786, "
                             f"got {args.scheduler!r}")
        where = (f" on the Dask cluster at {args.scheduler}" if args.scheduler else
                 f" on {workers} processes" if workers > 1 else "")
        return None, where
    parallel = [option for option, given in (("--workers", args.workers != 1), ("--scheduler", args.scheduler))
                if given]
    if parallel:
        raise InputError(f"{parallel[0]} applies to --method abm: the Z-map updates its stock CL point by CL point")
    grid = ZMAP_GRID if args.grid is None else args.grid
    step = grid if args.edge_step is None else args.edge_step
    for option, value in (("--grid", grid), ("--edge-step", step)):
        if not (np.isfinite(value) and value > 0.0):
            raise InputError(f"{option}: must be a positive number of mm, got {value:g}")

    def compute(stock, tool, toolpath, settings, progress=None):
        try:
            return zmap_engage(stock, tool, toolpath, settings, grid=grid, edge_step=step, progress=progress)
        except ValueError as error:
            raise InputError(f"--method zmap: {error}") from None
    return compute, f" (Z-map, grid {grid:g} mm, edge step {step:g} mm)"


def _run_validate(args):
    """The validate command; returns 0 or raises InputError."""
    from .report.html import ReportJob, report_cls, write_report
    from .report.staging import staged
    from .validation import NoEngagementError, overall, validate, validate_helix, write_flutes_csv

    force_model = _force_model(args)
    job, toolpath, parameters, tool, settings = _prepare(args)
    cls = cl_indices(args.cl, len(toolpath)) if args.cl else None
    helical = _helical_validation(args, tool)
    _check_validate_outputs(args)
    stock, stock_seconds = _load_stock(args, toolpath, tool)
    started = time.perf_counter()
    solid = stock.solid()
    stock_seconds += time.perf_counter() - started

    try:
        if helical is None:
            validation = validate(solid, stock.staircase, tool, toolpath, settings,
                                  progress=_Progress("boolean reference", sys.stderr))
        else:
            tool, flutes = helical
            helix_validation = validate_helix(solid, stock.staircase, tool, toolpath, settings, flutes=flutes,
                                              progress=_Progress("helix boolean reference", sys.stderr))
            validation = helix_validation.flute(helix_validation.flutes[0])
    except NoEngagementError:
        raise InputError(_no_engagement(args)) from None
    engagement = validation.engagement
    forces = None
    if force_model is not None:
        coefficients, immersion = force_model
        forces = pass_forces(stock.staircase, tool, toolpath, settings, coefficients, immersion=immersion,
                             first=engagement.length if tool.helix == 0.0 else None)
    shown = report_cls(validation, cls)
    walls = "the paper's quintic walls (JSON)" if stock.shape is None else f"{stock.walls} walls"
    run = "ABM against booleans" if helical is None else (
        f"Helical edges (β = {tool.helix:g}°), flute {helix_validation.flutes[0] + 1} of {tool.flutes}, "
        "ABM against booleans")
    title = f"{run}: {os.path.basename(args.stock)} / {os.path.basename(args.toolpath)}"
    description = job.get("description", "") if helical is None else " ".join(filter(None, [
        job.get("description", ""), _flutes_text(helix_validation)]))
    report_job = ReportJob(title, description, args.stock, args.toolpath, toolpath, tool, settings,
                           parameters.describe(), walls, stock.y_window, stock_seconds)

    outputs = [args.report] + ([args.fcstd] if args.fcstd else [])
    for path in outputs:
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with staged(args.report, folder=True) as folder, \
            (staged(args.fcstd) if args.fcstd else contextlib.nullcontext()) as fcstd:
        page = write_report(folder, validation, report_job, shown, forces)
        if helical is not None:
            write_flutes_csv(os.path.join(folder, "flutes.csv"), helix_validation)
        if fcstd:
            from .cad.annotate import write_annotated
            name = re.sub(r"[^A-Za-z0-9_]", "_", os.path.splitext(os.path.basename(args.fcstd))[0])
            write_annotated(fcstd, f"ABM_{name}", solid, engagement, toolpath, tool, cls=cls,
                            intersections=[cl for cl, _ in shown])
    total = overall(validation.comparison)
    m, p = engagement.shape
    written = [os.path.join(args.report, os.path.basename(page))] + ([args.fcstd] if args.fcstd else [])
    print(f"{PROG}: {m} CL points x {p} angles: length of cut max |relative error| "
          f"{100 * total['max_rel_error']:.3g} % (mean {100 * total['mean_rel_error']:.3g} %, "
          f"{total['relative_instants']} instants), max |difference| {total['max_abs_difference']:.3g} mm; "
          f"ABM {validation.seconds['abm']:.3g} s, boolean {validation.seconds['boolean']:.3g} s "
          f"({validation.speed_ratio:.0f}x)"
          + ("" if forces is None else f"; peak force {forces.peak.max():.4g} N at CL {int(np.argmax(forces.peak))}")
          + f"; wrote {', '.join(written)}")
    if helical is not None:
        print(f"{PROG}: {_flutes_text(helix_validation)}")
    print(f"{PROG}: parameters: {parameters.describe()}{_helix_text(tool)}{_stock_line(stock)}")
    return 0


def _helical_validation(args, tool):
    """None for a straight run, else (tool with --helix, 0-based flutes to check); InputError for a bad
    --helix or --flute."""
    if args.helix == 0.0 and args.flute is None:
        return None
    tool = _helical(args, tool)
    if args.flute is None:
        return tool, None
    if not 1 <= args.flute <= tool.flutes:
        raise InputError(f"--flute: must be 1..{tool.flutes} (the tool has {tool.flutes} flutes), got {args.flute}")
    return tool, [args.flute - 1]


def _flutes_text(helix_validation):
    """One line per checked flute's largest |ABM − boolean| of axial length, LEP and UEP (mm)."""
    parts = [f"flute {row['flute'] + 1}: max |Δ axial length| {row['max_axial_difference']:.3g} mm, "
             f"|Δ LEP| {row['max_lep_difference']:.3g} mm, |Δ UEP| {row['max_uep_difference']:.3g} mm, "
             f"{row['mismatched']} mismatched of {row['instants']} instants"
             for row in helix_validation.flute_summary()]
    return "Helical edges against the helix boolean: " + "; ".join(parts) + " (per instant in flutes.csv)."


def _run_schedule(args):
    """The schedule command; returns 0 or raises InputError."""
    from .formats.apt_writer import write_feed_toolpath
    from .report.staging import staged
    from .scheduling import programmed_feed, schedule

    coefficients, immersion = _force_model(args, always=True)
    kind, limit = ("force", args.max_force) if args.max_force is not None else ("area", args.max_area)
    option = f"--max-{kind}"
    if not (np.isfinite(limit) and limit > 0.0):
        raise InputError(f"{option}: must be a positive number, got {limit:g}")
    if args.min_feed is not None and not (np.isfinite(args.min_feed) and args.min_feed > 0.0):
        raise InputError(f"--min-feed: must be a positive feed per tooth (mm), got {args.min_feed:g}")
    if os.path.splitext(args.out)[1].lower() not in (".apt", ".cls", ".csv"):
        raise InputError(f"{args.out}: --out must end in .apt, .cls or .csv")
    job, toolpath, parameters, tool, settings = _prepare(args)
    tool = _helical(args, tool)
    _, hints = load_path(args.toolpath)  # the feed of every move, which _prepare reduces to one value
    try:
        programmed = programmed_feed(len(toolpath), settings.feed_per_tooth, feed=hints.feed, unit=hints.feed_unit,
                                     flutes=tool.flutes, spindle_rpm=settings.spindle_rpm)
    except ValueError as error:
        raise InputError(f"{args.toolpath}: {error}") from None
    inputs = [args.stock, args.toolpath] + ([args.job] if args.job else [])
    if args.report:
        _check_validate_outputs(argparse.Namespace(stock=args.stock, toolpath=args.toolpath, job=args.job,
                                                   report=args.report, fcstd=None))
    _check_outputs([args.out] + ([args.report] if args.report else []), inputs)
    stock, _ = _load_stock(args, toolpath, tool)
    engagement = _flute_1(stock.staircase, tool, toolpath, settings)
    if not engagement.engaged.any():
        raise InputError(_no_engagement(args))
    forces = pass_forces(stock.staircase, tool, toolpath, settings, coefficients, immersion=immersion,
                         feed=programmed, first=engagement.length if tool.helix == 0.0 else None)
    plan = schedule(forces, limit, kind=kind, min_feed=args.min_feed)
    unit = "N" if kind == "force" else "mm²"
    if plan.infeasible.any():
        shown = ", ".join(f"CL {i} (peak {plan.after[i]:.4g} {unit})" for i in np.flatnonzero(plan.infeasible)[:10])
        more = "" if plan.infeasible.sum() <= 10 else f" and {int(plan.infeasible.sum()) - 10} more"
        print(f"{PROG}: warning: {int(plan.infeasible.sum())} CL points cannot keep the {kind} at or under "
              f"{limit:g} {unit} at any feed from the minimum feed up; they get the minimum feed: {shown}{more}",
              file=sys.stderr)
    comment = (f"re-scheduled by abm schedule: peak {kind} <= {limit:g} {unit}, feed per tooth "
               f"{plan.feed.min():.6g}..{plan.feed.max():.6g} mm (programmed {plan.programmed.max():.6g} mm)")
    for path in [args.out] + ([args.report] if args.report else []):
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with (staged(args.report, folder=True) if args.report else contextlib.nullcontext()) as folder:
        if folder:
            from .report.forces import write_schedule_report
            title = job.get("description") or f"{os.path.basename(args.stock)} / {os.path.basename(args.toolpath)}"
            write_schedule_report(folder, forces, plan, title=f"Feed schedule: {title}",
                                  parameters=parameters.describe())
        write_feed_toolpath(args.out, toolpath, plan.feed, flutes=tool.flutes, diameter=tool.diameter,
                            flute_length=tool.flute_length, spindle_rpm=settings.spindle_rpm, comment=comment)
    written = [args.out] + ([os.path.join(args.report, "index.html")] if args.report else [])
    print(f"{PROG}: {len(toolpath)} CL points: peak {kind} {plan.before.max():.4g} -> {plan.after.max():.4g} {unit} "
          f"(limit {limit:g}); feed lowered at {int(plan.reduced.sum())} CL points, to "
          f"{plan.feed.min():.4g} mm/tooth at least; {int(plan.infeasible.sum())} cannot meet the limit; "
          f"wrote {', '.join(written)}")
    print(f"{PROG}: parameters: {parameters.describe()}{_helix_text(tool)}{_stock_line(stock)}")
    return 0


def _no_engagement(args):
    """The message for a pass whose tool never touches the stock."""
    return (f"{args.toolpath}: the tool never touches the stock: no CL point of the pass engages it "
            f"(are the toolpath and {args.stock} in the same frame?)")


def _phi_range(text):
    """(start, end) in degrees from 'START:END'; InputError naming --phi-range otherwise."""
    return _pair(text, "--phi-range", "START:END in degrees such as 0:180")


def _pair(text, option, expected):
    """(a, b) floats from 'A:B'; InputError naming `option` and what was `expected` otherwise."""
    parts = text.split(":")
    try:
        if len(parts) != 2:
            raise ValueError
        return float(parts[0]), float(parts[1])
    except ValueError:
        raise InputError(f"{option}: expected {expected}, got {text!r}") from None


def cl_indices(text, m):
    """Sorted distinct CL indices from '0,22,40'; InputError unless each is an integer in 0..m−1."""
    indices = set()
    for part in text.split(","):
        try:
            index = int(part)
        except ValueError:
            raise InputError(f"--cl: expected CL indices such as 0,22,40, got {text!r}") from None
        if not 0 <= index < m:
            raise InputError(f"--cl: CL point {index} is not in the pass (0..{m - 1})")
        indices.add(index)
    return sorted(indices)


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
            raise InputError(f"{path}: written twice (as {seen[key]} too); choose another name")
        seen[key] = path
    for path in inputs:
        if os.path.normcase(os.path.abspath(path)) in seen:
            raise InputError(f"{path}: is an input and would be overwritten by an output")


def _check_validate_outputs(args):
    """The report folder and FCStd can be written, replace nothing but an older report, hold no input."""
    inputs = [args.stock, args.toolpath] + ([args.job] if args.job else [])
    _check_outputs([args.report] + ([args.fcstd] if args.fcstd else []), inputs)
    report = os.path.abspath(args.report)
    if os.path.exists(report) and not os.path.isdir(report):
        raise InputError(f"{args.report}: --report must be a folder, and this is a file")
    if os.path.isdir(report) and os.listdir(report) and not os.path.isfile(os.path.join(report, "index.html")):
        raise InputError(f"{args.report}: folder holds files but no report (index.html); it would be replaced "
                         "as a whole: choose a new or empty folder")
    inside = [path for path in inputs + ([args.fcstd] if args.fcstd else [])
              if os.path.abspath(path).startswith(report + os.sep)]
    if inside:
        raise InputError(f"{inside[0]}: lies inside the --report folder {args.report}, which is replaced as a whole")
    if args.fcstd and not args.fcstd.lower().endswith(".fcstd"):
        raise InputError(f"{args.fcstd}: --fcstd must end in .FCStd")


def _engine_progress():
    """Progress callback for engage: 'abm: CL points 120/530' on one line of stderr."""
    def report(done, total):
        end = "\n" if done == total else ""
        print(f"\r{PROG}: CL points {done}/{total}", end=end, file=sys.stderr, flush=True)
    return report


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
            print(f"{PROG}: {self.label}: CL point {done}/{total}, {timing}", file=self.stream, flush=True)
