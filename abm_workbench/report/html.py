"""A validation report as one self-contained HTML page, with the CSV files behind it.

:func:`write_report` writes into a folder: ``index.html`` (plain HTML and a little CSS; every
plot a PNG embedded as base64) and the tables of :mod:`.tables`; with cutting forces, a
"Cutting forces" section (force over φ at the CL points shown, peak force along the pass) whose
figure is also ``forces.png``. Lengths in mm, angles in degrees, times in s, relative errors in
%, forces in N.

The page's headings and sentences are English, or in the reader's language where ``words`` is given
(:func:`translate`; the GUI gives Qt's translation of the workbench's context ``ABM``, whose template gathers
the texts passed to :func:`translate` here). The plots, the CSV files and their column names stay English.
"""

import base64
import contextvars
import html
import io
import os
import re
from dataclasses import dataclass

import numpy as np

from ..engine import CutSettings, Tool, Toolpath
from ..validation import TINY_LENGTH, overall, segment_summary, surface_summary
from . import figures
from .forces import SHOWN_CL, force_over_phi_figure
from .plots import representative_cl
from .tables import report_tables

#: Depth of cut over the pass in the paper (mm), per model test.
PAPER_DEPTH = {1: (1.78, 7.32), 2: (2.68, 6.38)}
#: The paper's times for one pass of 53 CC points (MATLAB, Core i7 2.7 GHz), s.
PAPER_SECONDS = {"ABM": 713.87, "Z-map (0.2 mm grid)": 2633.65}
_MODEL_TEST = re.compile(r"\bmodel test ([12])\b", re.IGNORECASE)
_OWN_MODEL_TEST = re.compile(r"\s*model test (\d+)\b", re.IGNORECASE)
#: At most this many CL points get plots over φ (the 3D view: four).
DETAIL_PLOTS = 8
#: At most this many CL points get a picture of the in-process stock.
STOCK_VIEWS = 4

#: The report's words in the reader's language: a function of an English text (a template with {placeholders})
#: that gives its translation, or None for English (:func:`translate`).
_WORDS = contextvars.ContextVar("report_words", default=None)


def translate(text, **values):
    """`text`, words of the report (a template with {placeholders}), in the language the report is written
    in (report_page's `words`; English where none is given), its placeholders filled with `values`. A
    translation whose placeholders are not the text's (a translator's slip) is not used."""
    words = _WORDS.get()
    shown = text if words is None else words(text)
    if not values:
        return shown
    try:
        return shown.format(**values)
    except (KeyError, IndexError, ValueError):
        return text.format(**values)


def noop(text):
    """`text` unchanged, marked for the translation template: translated where it is shown (:func:`translate`)."""
    return text


#: Why a CL point is shown in detail (report_cls, plots.representative_cl), for the translation template.
WHY_WORDS = (noop("chosen"), noop("largest error"), noop("deepest"), noop("shallowest"), noop("middle"))

_CSS = """
body { font: 15px/1.45 system-ui, -apple-system, "Segoe UI", sans-serif; color: #222; background: #f6f7f9;
       margin: 0; }
main { max-width: 1120px; margin: 0 auto; padding: 24px 32px 48px; background: #fff; }
h1 { font-size: 1.6em; margin: 0 0 4px; }
h2 { font-size: 1.2em; margin: 36px 0 8px; padding-bottom: 4px; border-bottom: 2px solid #e3e6ea; }
p.lead { color: #555; margin-top: 0; }
table { border-collapse: collapse; margin: 8px 0 12px; font-size: 0.92em; }
th, td { padding: 4px 10px; border-bottom: 1px solid #e3e6ea; text-align: left; vertical-align: top; }
th { background: #f0f2f5; font-weight: 600; }
td.n { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
table.wide { font-size: 0.85em; }
table.wide td { white-space: nowrap; }
.cards { display: flex; flex-wrap: wrap; gap: 12px; margin: 12px 0; }
.card { flex: 1 1 150px; border: 1px solid #e3e6ea; border-radius: 6px; padding: 10px 14px; background: #fafbfc; }
.card b { display: block; font-size: 1.35em; }
.card span { color: #666; font-size: 0.88em; }
img { width: 100%; height: auto; border: 1px solid #eee; }
.note { color: #555; font-size: 0.92em; }
code { background: #f0f2f5; padding: 0 3px; border-radius: 3px; }
"""


@dataclass(frozen=True)
class ReportJob:
    """What the report says about the job.

    title: heading. description: the job's description ('' if none). stock, path: the input
    files. toolpath, tool, settings: the pass as computed. parameters: one line of parameters
    and their sources (jobs.Parameters.describe). walls: the stock's model in words. y_window:
    (2,) mm, or None for a terraced stock. stock_seconds: time to read or build the stock's solid and model (s).
    stock_model: which stock both sides checked, in words (the stock as given, or the in-process stock).
    """

    title: str
    description: str
    stock: str
    path: str
    toolpath: Toolpath
    tool: Tool
    settings: CutSettings
    parameters: str
    walls: str
    y_window: tuple
    stock_seconds: float
    stock_model: str = "initial: the stock as given"


def paper_model_test(description):
    """1 or 2 when `description` names the paper's model test 1 or 2 ('Model test 1 …'), else None;
    a description that starts by naming another model test ('Model test 3: the model test 1 stock
    machined by …') is not the paper's pass."""
    own = _OWN_MODEL_TEST.match(description or "")
    match = own if own else _MODEL_TEST.search(description or "")
    return int(match.group(1)) if match and match.group(1) in ("1", "2") else None


def report_cls(validation, requested=None):
    """The CL points shown in detail, as (index, why): `requested`, or the deepest, shallowest and
    middle engaged CL points and the one with the largest relative error, among those the boolean checked."""
    if requested:
        return [(int(cl), "chosen") for cl in requested]
    chosen = representative_cl(np.where(validation.checked, validation.comparison.depth_abm, np.nan))
    error = np.abs(validation.comparison.relative_error)
    if np.isfinite(error).any():
        worst = int(np.unravel_index(np.nanargmax(error), error.shape)[0])
        if worst not in [cl for cl, _ in chosen]:
            chosen.append((worst, "largest error"))
    return chosen


def write_report(folder, validation, job: ReportJob, cls, forces=None, views=None, words=None, language="en"):
    """Write index.html and the four CSV tables of `validation` into `folder` (which exists).

    cls: (index, why) of the CL points shown in detail. forces: the pass's Forces (or an
    engagement object's PassForces), for the "Cutting forces" section and forces.png; None: no
    forces. views: for a validation against the in-process stock, {cl: (x (c,), y (c,), z (c, c))
    mm} the top of the in-process stock around those CL points (cad.inprocess_boolean.stock_heights),
    pictured in the "In-process stock" section. words, language: the page's language (see report_page).
    Returns the path of index.html.
    """
    for name, text in report_tables(validation, job.toolpath).items():
        with open(os.path.join(folder, name), "w", encoding="utf-8", newline="") as file:
            file.write(text)
    force_png = None
    if forces is not None:
        buffer = io.BytesIO()
        force_figure(forces, cls).savefig(buffer, format="png")
        force_png = buffer.getvalue()
        with open(os.path.join(folder, "forces.png"), "wb") as file:
            file.write(force_png)
    page = os.path.join(folder, "index.html")
    with open(page, "w", encoding="utf-8") as file:
        file.write(report_page(validation, job, cls, forces, force_png, views, words, language))
    return page


def force_figure(forces, cls):
    """The report's force figure: peak and mean resultant along the pass, force over φ at the first
    SHOWN_CL CL points of `cls` ((index, why) pairs)."""
    return force_over_phi_figure(forces, sorted({cl for cl, _ in cls[:SHOWN_CL]}), along=True)


def report_page(validation, job: ReportJob, cls, forces=None, force_png=None, views=None, words=None, language="en"):
    """The HTML text of the report; with `forces`, the "Cutting forces" section showing `force_png`
    (force_figure's PNG bytes, made here when not given); against the in-process stock, the
    "In-process stock" section (pictures of `views`, see write_report). words: a function of each English
    text of the page (a template with {placeholders}) giving it in the reader's language (None: English),
    `language` its code for the page's ``lang`` ("en", "de")."""
    token = _WORDS.set(words)
    try:
        return _page(validation, job, cls, forces, force_png, views, language)
    finally:
        _WORDS.reset(token)


def _page(validation, job, cls, forces, force_png, views, language):
    """report_page's text, in the language :func:`translate` gives."""
    shown = [cl for cl, _ in cls][:DETAIL_PLOTS]
    model = paper_model_test(job.description)
    paper_range = PAPER_DEPTH.get(model)
    parts = [
        f"<h1>{_e(job.title)}</h1>",
        f"<p class='lead'>{_e(job.description)}</p>" if job.description else "",
        _headline(validation, paper_range),
        _heading(translate("Job")), _job_table(validation, job),
        _inprocess_section(validation, job, cls, views or {}) if validation.in_process is not None else "",
        _heading(translate("Error by UEP surface, whole pass")), _error_definition(job.tool),
        _surface_table(validation),
        _note(translate("The paper (Siemens NX reference): negligible error with the UEP on a top or a straight "
                        "wall, below 6 % with the UEP on a curved wall.")),
        _heading(translate("Length of cut along the pass"), "Fig. 6(e)/(f)"),
        _image(figures.pass_length_figure(validation)),
        _heading(translate("Depth of cut along the pass")), _depth_text(validation, model),
        _image(figures.depth_figure(validation, paper_range, f"paper, model test {model}")),
        _heading(translate("Length of cut and cut area over φ"), "Fig. 7"),
        _note(_shown_words(cls)),
        _image(figures.phi_figure(validation, shown)),
        _heading(translate("Shape of the cut"), "Fig. 6(c)/(d)"),
        _image(figures.shape_figure(validation, shown[:4])),
        _heading(translate("Error per engagement segment"), "Fig. 8(c), 8(e)"),
        _image(figures.error_figure(validation, shown)), _segment_table(validation, shown),
        _heading(translate("Error over the pass")), _image(figures.error_pass_figure(validation)),
        _force_section(forces, cls, force_png) if forces is not None else "",
        _heading(translate("Timings")), _timings(validation, job),
        _heading(translate("Files")), _files(),
    ]
    body = "\n".join(part for part in parts if part)
    return (f"<!DOCTYPE html>\n<html lang='{_e(language)}'>\n<head>\n<meta charset='utf-8'>\n"
            f"<title>{_e(job.title)}</title>\n"
            f"<style>{_CSS}</style>\n</head>\n<body>\n<main>\n{body}\n</main>\n</body>\n</html>\n")


def _heading(text, figure=""):
    """An <h2> of `text` (escaped), with the paper's `figure` it matches in small print ("Fig. 7")."""
    small = f" <small>({_e(translate('Fig.'))}{_e(figure[len('Fig.'):])})</small>" if figure else ""
    return f"<h2>{_e(text)}{small}</h2>"


def _note(text):
    """A paragraph of class note of `text` (escaped)."""
    return f"<p class='note'>{_e(text)}</p>"


def _shown_words(cls):
    """Which CL points the plots over φ show, in words."""
    listed = _cl_list(cls[:DETAIL_PLOTS])
    if len(cls) > DETAIL_PLOTS:
        return translate("CL points shown: {listed} (the first {count} of {total}). Shaded: the engagement segments "
                         "(ABM).", listed=listed, count=DETAIL_PLOTS, total=len(cls))
    return translate("CL points shown: {listed}. Shaded: the engagement segments (ABM).", listed=listed)


def _headline(validation, paper_range):
    """The cards at the top: largest error, depth of cut, speed."""
    total = overall(validation.comparison)
    comparison, seconds = validation.comparison, validation.seconds
    depth = f"{np.nanmin(comparison.depth_abm):.2f}–{np.nanmax(comparison.depth_abm):.2f} mm"
    cards = [
        (_percent(total["max_rel_error"]),
         translate("largest |relative error| over {count} instants", count=total["relative_instants"])),
        (_percent(total["mean_rel_error"]), translate("mean |relative error|")),
        (f"{total['max_abs_difference']:.3g} mm", translate("largest |l_ABM − l_ref|, all instants")),
        (f"{_mm(total['max_end_difference'])} mm",
         translate("largest |Δ end edge| over {count} instants", count=total["end_instants"])),
        (depth, translate("depth of cut (ABM); paper {low}–{high} mm", low=f"{paper_range[0]:g}",
                          high=f"{paper_range[1]:g}") if paper_range else
         translate("depth of cut (ABM); paper: not a model test")),
        (f"{validation.speed_ratio:.0f} ×",
         translate("ABM {abm} s vs boolean {boolean} s", abm=f"{seconds['abm']:.3g}",
                   boolean=f"{seconds['boolean']:.3g}")),
    ]
    items = "".join(f"<div class='card'><b>{_e(value)}</b><span>{_e(text)}</span></div>" for value, text in cards)
    return f"<div class='cards'>{items}</div>"


def _job_table(validation, job):
    """Inputs and parameters of the job."""
    m, p = validation.engagement.shape
    settings = job.settings
    tool, window = job.tool, job.y_window
    size = dict(tool=tool_words(tool), flutes=tool.flutes, length=f"{tool.flute_length:g}")
    feed = dict(feed=f"{settings.feed_per_tooth:g}", inclination=f"{settings.inclination:g}")
    rows = [
        (translate("stock"), f"{job.stock} ({job.walls})" if window is None else
         translate("{stock} ({walls}; y window {low}..{high} mm)", stock=job.stock, walls=job.walls,
                   low=f"{window[0]:.6g}", high=f"{window[1]:.6g}")),
        (translate("toolpath"), translate("{path}: {count} CL points", path=job.path, count=m)),
        (translate("CL points checked"), _checked_words(validation.checked)),
        (translate("rotation angles"),
         translate("φ {start}..{end}° step {step}°: {count} angles, {instants} instants",
                   start=f"{settings.phi_start:g}", end=f"{settings.phi_end:g}", step=f"{settings.phi_step:g}",
                   count=p, instants=m * p)),
        (translate("tool"), translate("{tool}, {flutes} flutes, flute length {length} mm, helix {helix}°",
                                      helix=f"{tool.helix:g}", **size) if tool.helix else
         translate("{tool}, {flutes} flutes, flute length {length} mm", **size)),
        (translate("cutting"), translate("feed {feed} mm/tooth, inclination {inclination}°, {speed} rpm",
                                         speed=f"{settings.spindle_rpm:g}", **feed) if settings.spindle_rpm else
         translate("feed {feed} mm/tooth, inclination {inclination}°", **feed)),
        (translate("parameters [from]"), job.parameters),
        (translate("stock model"), job.stock_model),
    ]
    return _table(("", ""), rows, header=False)


def tool_words(tool):
    """'flat end mill D 12 mm', 'bull-nose mill D 16 mm, corner radius 4 mm', 'ball-end mill D 6 mm (R 3 mm)'."""
    size = dict(diameter=f"{tool.diameter:g}", corner=f"{tool.corner_radius:g}")
    if tool.corner_radius == 0.0:
        return translate("flat end mill D {diameter} mm", **size)
    if tool.corner_radius == tool.radius:
        return translate("ball-end mill D {diameter} mm (R {corner} mm)", **size)
    return translate("bull-nose mill D {diameter} mm, corner radius {corner} mm", **size)


def _checked_words(checked):
    """Which CL points the boolean checked ((m,) bool), in words: 'all 53', or 'k of m: 0, 27, 80–82'."""
    m, chosen = checked.size, np.flatnonzero(checked)
    if chosen.size == m:
        return translate("all {count} (the statistics are over every instant)", count=m)
    runs = np.split(chosen, np.flatnonzero(np.diff(chosen) > 1) + 1)
    spans = ", ".join(str(run[0]) if run.size == 1 else f"{run[0]}–{run[-1]}" for run in runs)
    return translate("{checked} of {count}: {spans} (the statistics, comparison.csv and segments.csv are over these; "
                     "the engine computed all {count})", checked=chosen.size, count=m, spans=spans)


def _inprocess_section(validation, job, cls, views):
    """What earlier moves changed: counts over the pass, per CL point shown its lengths in the stock as
    given and in the in-process stock, and the pictures of the in-process stock around the tool."""
    check, comparison = validation.in_process, validation.comparison
    m = check.changed.size
    differs = np.abs(check.initial - comparison.l_abm) > TINY_LENGTH
    rows = []
    gauged = check.gauged
    for cl, why in cls:
        near = f"{check.swept[cl]:.0f}" if gauged is None or not gauged[cl] > 0 else translate(
            "{swept} ({gauged} by the exact test)", swept=f"{check.swept[cl]:.0f}", gauged=f"{gauged[cl]:.0f}")
        rows.append([f"{cl} ({translate(why)})", translate("yes") if check.changed[cl] else translate("no"), near,
                     str(int(differs[cl].sum())), _mm(check.initial[cl].max()), _mm(comparison.l_abm[cl].max()),
                     _mm(comparison.l_ref[cl].max()), _mm(np.abs(comparison.difference[cl]).max())])
    head = ("CL", translate("changed"), translate("swept pieces near"), translate("angles changed"),
            translate("max l, stock as given (ABM)"), translate("max l, in-process (ABM)"),
            translate("max l, in-process (boolean)"), translate("max |Δl| (mm)"))
    exact_test = ""
    if gauged is not None and np.nansum(gauged) > 0:
        exact_test = "<p>" + translate(
            "{count} of the swept pieces that meet the tool's edges (summed over the checked CL points) are moves "
            "OpenCASCADE has no reliable solids for (a bull-nose mill's moves within 5.74° of the plane across its "
            "axis, whose solids have nearly degenerate faces its booleans misjudge; oblique moves of a tool shorter "
            "than its corner radius): the reference decides where the edges lie in those with an exact inside test "
            "of its own (the tool's distance function minimised along the move, every crossing isolated to "
            "10⁻¹⁰ mm), independent of the engine (column <code>gauged</code> of <code>depth.csv</code>).",
            count=int(np.nansum(gauged))) + "</p>"
    inside = _table(head, rows, css="wide")
    picture = ""
    if views:
        picture = _image(figures.inprocess_figure(validation, views, job.toolpath, job.tool))
    changed_rows = check.changed & (comparison.l_abm > 0.0).any(axis=1)
    return "\n".join([
        _heading(translate("In-process stock")),
        "<p>" + translate(
            "Both the engine and the boolean reference work on the <b>in-process stock</b>: at each CL point, the "
            "stock minus the volumes swept by the cutting moves that end before it. The boolean reference sections "
            "each cutting-edge line with the stock solid and with exact solids of the volumes swept by the earlier "
            "moves that can reach the tool, and keeps what lies in the stock and in none of them. The pictures show "
            "the top of that in-process stock around the tool, found the same way along vertical lines. Earlier "
            "moves changed {changed} of {count} CL points ({instants} instants by more than {tiny} mm; {engaged} of "
            "the changed CL points still engage). Per instant, <code>comparison.csv</code> has the length in the "
            "stock as given (<code>l_initial</code>) beside both in-process lengths; <code>depth.csv</code> says "
            "which CL points changed.", changed=int(check.changed.sum()), count=m, instants=int(differs.sum()),
            tiny=f"{TINY_LENGTH:g}", engaged=int(changed_rows.sum())) + "</p>",
        exact_test, inside, picture,
    ])


def _error_definition(tool=None):
    """How the error is defined (and, for a tool with a corner, what l, LEP and UEP are on it)."""
    corner = ""
    if tool is not None and tool.corner_radius > 0.0:
        radius = f"{tool.corner_radius:g}"
        corner = " " + (translate(
            "For this ball mill the cutting edge is the corner arc (radius {radius} mm, sectioned by the boolean as a "
            "true circular arc) followed by the straight side: l is the arc length along both, LEP and UEP are "
            "heights along the tool axis above the tip (mm).", radius=radius) if tool.kind == "ball" else translate(
            "For this bull-nose mill the cutting edge is the corner arc (radius {radius} mm, sectioned by the boolean "
            "as a true circular arc) followed by the straight side: l is the arc length along both, LEP and UEP are "
            "heights along the tool axis above the tip (mm).", radius=radius))
    return "<p class='note'>" + translate(
        "Error of the length of cut as the paper defines it: relative, (l<sub>ABM</sub> − l<sub>ref</sub>)/"
        "l<sub>ref</sub>, with l<sub>ref</sub> from the OpenCASCADE boolean of the cutting edges with the stock "
        "solid. Where l<sub>ref</sub> &lt; {tiny} mm (the edge grazes the stock) the absolute difference "
        "l<sub>ABM</sub> − l<sub>ref</sub> in mm is used instead; those instants are counted apart. LEP/UEP: "
        "largest difference along the edge (mm). Mismatched: instants where only one method finds engagement. End "
        "edge: the largest |end<sub>ABM</sub> − end<sub>ref</sub>| of the end cutting edge's engaged length (tip to "
        "the corner, in the tip plane) over the instants where both give it, and the instants where only one finds "
        "it in the stock.", tiny=f"{TINY_LENGTH:g}") + f"{_e(corner)}</p>"


def _statistics_cells(row):
    """Table cells of the statistics of one summary row."""
    return [
        str(row["instants"]), str(row["relative_instants"]), _percent(row["max_rel_error"]),
        _percent(row["mean_rel_error"]), _mm(row["max_abs_difference"]), _mm(row["max_lep_difference"]),
        _mm(row["max_uep_difference"]), str(row["mismatched"]), _mm(row["max_end_difference"]),
        str(row["end_mismatched"]),
    ]


def _statistics_head():
    """The heads of the statistics' columns (:func:`_statistics_cells`)."""
    return (translate("instants"), translate("relative"), translate("max |rel. error|"), translate("mean |rel. error|"),
            translate("max |Δl| (mm)"), translate("max |ΔLEP| (mm)"), translate("max |ΔUEP| (mm)"),
            translate("mismatched"), translate("max |Δ end| (mm)"), translate("end mismatched"))


def _surface_table(validation):
    """Errors per kind of UEP surface, and over the whole pass."""
    rows = [[_e(translate(row["surface"].replace("_", " ")))] + _statistics_cells(row)
            for row in surface_summary(validation.engagement, validation.comparison)]
    rows.append([f"<b>{_e(translate('whole pass'))}</b>"] + _statistics_cells(overall(validation.comparison)))
    return _table((translate("UEP on"),) + _statistics_head(), rows, escape_first=False, css="wide")


def _segment_table(validation, cls):
    """Errors per engagement segment at the CL points shown."""
    rows = [
        [str(row["cl"]), row["segment"], _phi_span(row["phi_start"], row["phi_end"]),
         translate(row["surface"].replace("_", " ")), str(row["section"]), str(row["wall"])] + _statistics_cells(row)
        for row in segment_summary(validation.engagement, validation.comparison, cls)
    ]
    head = ("CL", translate("segment"), translate("φ (deg)"), translate("UEP on"), translate("section"),
            translate("wall")) + _statistics_head()
    return _table(head, rows, css="wide") + "<p class='note'>" + translate(
        "Every CL point: <code>segments.csv</code>.") + "</p>"


def _depth_text(validation, model):
    """The depth of cut of both methods beside the paper's ranges."""
    comparison = validation.comparison
    ours = translate("ABM {abm_low}–{abm_high} mm, boolean {low}–{high} mm",
                     abm_low=f"{np.nanmin(comparison.depth_abm):.2f}",
                     abm_high=f"{np.nanmax(comparison.depth_abm):.2f}",
                     low=f"{np.nanmin(comparison.depth_ref):.2f}", high=f"{np.nanmax(comparison.depth_ref):.2f}")
    papers = "; ".join(translate("model test {number} {low}–{high} mm", number=k, low=f"{low:g}", high=f"{high:g}")
                       for k, (low, high) in PAPER_DEPTH.items())
    which = " " + translate("This job is model test {number}.", number=model) if model else ""
    return "<p>" + translate("Depth of cut over the pass (highest UEP z − lowest LEP z per CL point): {ours}. The "
                             "paper's passes: {papers}.", ours=ours, papers=papers) + f"{_e(which)}</p>"


def _timings(validation, job):
    """Times of both methods, their ratio, and the paper's for scale."""
    seconds = validation.seconds
    m, p = validation.engagement.shape
    rows = [
        (translate("ABM engine, whole pass"), f"{seconds['abm']:.4g} s",
         translate("{time} µs per instant", time=f"{1e6 * seconds['abm'] / (m * p):.3g}")),
        (translate("boolean reference (OpenCASCADE)"), f"{seconds['boolean']:.4g} s",
         translate("{time} s per CL point", time=f"{seconds['boolean'] / m:.3g}")),
        (translate("boolean / ABM"), f"{validation.speed_ratio:.4g} ×", ""),
        (translate("stock solid and staircase (read, build or recognise)"), f"{job.stock_seconds:.3g} s", ""),
    ]
    rows += [(translate("paper, {name}, 53 CC points (MATLAB, i7 2.7 GHz)", name=name), f"{value:g} s",
              translate("angle step not stated")) for name, value in PAPER_SECONDS.items()]
    return _table(("", translate("time"), ""), rows)


def _force_section(forces, cls, png):
    """Cutting forces: peak over the pass, the force figure (PNG bytes `png`, made when None)."""
    if png is None:
        buffer = io.BytesIO()
        force_figure(forces, cls).savefig(buffer, format="png")
        png = buffer.getvalue()
    peak = forces.peak
    worst = int(np.argmax(peak))
    shown = sorted({cl for cl, _ in cls[:SHOWN_CL]})
    rows = [
        (translate("peak resultant force over the pass"),
         translate("{force} N at CL {cl}", force=f"{peak[worst]:.4g}", cl=worst)),
        (translate("mean resultant force, pass average"), f"{forces.mean.mean():.4g} N"),
        (translate("peak torque"), f"{forces.torque.max():.4g} N·mm"),
    ] + ([(translate("peak spindle power"), f"{forces.power.max():.4g} W")] if forces.power is not None else [])
    data = base64.b64encode(png).decode("ascii")
    return "\n".join([
        _heading(translate("Cutting forces")),
        "<p class='note'>" + translate(
            "Linear edge-force model (docs/FORCES.md) on the ABM engagement, global frame, summed over the flutes "
            "cutting at each angle of flute 1; over φ at CL {shown} (dotted in the first plot). Also "
            "<a href='forces.png'><code>forces.png</code></a>.", shown=_e(", ".join(map(str, shown)))) + "</p>",
        _table(("", ""), rows, header=False),
        f"<img alt='cutting forces' src='data:image/png;base64,{data}'>",
    ])


def _files():
    """The CSV files beside the page."""
    rows = [
        ("comparison.csv", translate(
            "one row per instant the boolean checked: cl, phi_deg, l_abm, l_ref, difference, error, error_kind, LEP "
            "and UEP of both, pieces of both, segment, uep_surface, end_abm, end_ref, end_difference (the end edge's "
            "engaged length; against the in-process stock also l_initial: ABM in the stock as given)")),
        ("segments.csv", translate("error per CL point and engagement segment")),
        ("surfaces.csv", translate("error per kind of UEP surface")),
        ("depth.csv", translate(
            "depth of cut per CL point, both methods, and checked (1 where the boolean checked it; against the "
            "in-process stock also changed: whether earlier moves changed the CL point, and swept: the swept pieces "
            "the boolean sectioned)")),
    ]
    body = "".join(f"<tr><td><a href='{name}'><code>{name}</code></a></td><td>{_e(text)}</td></tr>"
                   for name, text in rows)
    return f"<table>{body}</table>"


def _table(head, rows, *, header=True, escape_first=True, css=""):
    """An HTML table of class `css`; cells escaped (but the first column's when escape_first is False);
    numbers to the right."""
    lines = [f"<table class='{css}'>" if css else "<table>"]
    if header:
        lines.append("<tr>" + "".join(f"<th>{_e(h)}</th>" for h in head) + "</tr>")
    for row in rows:
        cells = []
        for k, cell in enumerate(row):
            text = cell if (k == 0 and not escape_first) else _e(cell)
            numeric = k > 0 and re.fullmatch(r"[-+0-9.e× %µs]+(mm)?", str(cell) or "x") is not None
            cells.append(f"<td class='n'>{text}</td>" if numeric else f"<td>{text}</td>")
        lines.append("<tr>" + "".join(cells) + "</tr>")
    lines.append("</table>")
    return "\n".join(lines)


def _image(figure):
    """An <img> of `figure` as an embedded PNG."""
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png")
    data = base64.b64encode(buffer.getvalue()).decode("ascii")
    return f"<img alt='' src='data:image/png;base64,{data}'>"


def _phi_span(start, end):
    """'30–42', or '59' for a segment of one angle."""
    return f"{start:g}" if start == end else f"{start:g}–{end:g}"


def _cl_list(cls):
    """'22 (deepest), 3 (shallowest)'."""
    return ", ".join(f"{cl} ({translate(why)})" for cl, why in cls)


def _percent(value):
    """A fraction as a percentage with 3 significant digits; '–' for NaN."""
    return "–" if np.isnan(value) else f"{100.0 * value:.3g} %"


def _mm(value):
    """A length (mm) with 3 significant digits; '–' for NaN."""
    return "–" if np.isnan(value) else f"{value:.3g}"


def _e(text):
    """HTML-escaped text."""
    return html.escape(str(text), quote=True)
