"""Figures and a small HTML report of cutting forces and of a feed schedule (matplotlib, Agg; no FreeCAD).

- :func:`force_over_phi_figure`: force components and resultant over φ at chosen CL points
  (and the peak force along the pass; ``engage --forces --plot R.png`` writes it as R.forces.png).
- :func:`schedule_figure`: peak force (or cut area) and feed along the pass, before and after.
- :func:`write_schedule_report`: ``index.html`` (the figures embedded), the figures as PNG and
  ``schedule.csv`` (one row per CL point) into a folder.

Forces in N, areas in mm², feeds in mm per tooth, angles in degrees, CL points by 0-based index.
"""

import base64
import html
import io
import os

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from ..scheduling import peak

#: Colours of the components fx, fy, fz and of the resultant.
_COMPONENT_COLOURS = ("tab:red", "tab:green", "tab:blue", "black")
#: At most this many CL points are shown over φ.
SHOWN_CL = 3


def chosen_cl(forces, count=SHOWN_CL):
    """Up to `count` CL indices worth showing over φ: the highest peak force, the lowest
    non-zero one, and the middle of the pass, in pass order without repeats."""
    cut = np.flatnonzero(forces.peak > 0.0)
    if cut.size == 0:
        return [0]
    picks = [int(cut[np.argmax(forces.peak[cut])]), int(cut[np.argmin(forces.peak[cut])]), int(cut[cut.size // 2])]
    return sorted(dict.fromkeys(picks))[:count]


def force_over_phi_figure(forces, cls, *, after=None, along=False):
    """Figure: one row per CL index of `cls`; F_x, F_y, F_z (global frame) and |F| over φ (N).

    after: Forces of the same pass at scheduled feeds, drawn dashed beside the solid `forces`.
    along: add a first row with the peak and mean resultant per CL point along the pass.
    """
    rows = len(cls) + bool(along)
    figure = Figure(figsize=(11, 3.2 * rows + 0.6), dpi=100, layout="constrained")
    FigureCanvasAgg(figure)
    if along:
        axes = figure.add_subplot(rows, 1, 1)
        draw_force_along(axes, forces, cls)
        axes.set_xlabel("CL point index (dotted: shown below)")
        axes.legend(loc="lower right", fontsize=9)
    for row, cl in enumerate(cls, start=int(bool(along))):
        axes = figure.add_subplot(rows, 1, row + 1)
        draw_force_over_phi(axes, forces, cl, after=after)
        axes.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=9)
    return figure


def draw_force_along(axes, forces, cls):
    """Draw on `axes` the peak and mean resultant force (N) per CL point along the pass, a dotted
    line at each CL index of `cls` (no legend)."""
    index = np.arange(forces.shape[0])
    axes.plot(index, forces.peak, ".-", color="black", label="peak |F| over φ")
    axes.plot(index, forces.mean, ".-", color="0.55", label="mean |F| over φ")
    for cl in cls:
        axes.axvline(cl, color="tab:purple", linestyle=":", linewidth=1.0)
    axes.set(xlabel="CL point index", ylabel="force on the tool (N)",
             title="Peak and mean resultant force along the pass")
    axes.set_xlim(-0.5, index.size - 0.5)
    axes.xaxis.set_major_locator(MaxNLocator(integer=True))
    axes.set_ylim(0.0, 1.15 * max(forces.peak.max(), 1e-9))
    axes.grid(alpha=0.3)


def draw_force_over_phi(axes, forces, cl, *, after=None):
    """Draw on `axes` F_x, F_y, F_z (global frame) and |F| (N) over φ at CL index `cl`, labelled
    $F_x$, …, $|F|$ (no legend); `after` (Forces at scheduled feeds) dashed, labelled "… after"."""
    for label, values, style in (("", forces, "-"), (" after", after, "--")):
        if values is None:
            continue
        xyz, resultant = values.xyz[cl], values.resultant[cl]
        for k, name in enumerate(("F_x", "F_y", "F_z")):
            axes.plot(values.phi, xyz[:, k], style, color=_COMPONENT_COLOURS[k], label=f"${name}${label}")
        axes.plot(values.phi, resultant, style, color=_COMPONENT_COLOURS[3], linewidth=1.8, label=f"$|F|${label}")
    axes.axhline(0.0, color="0.6", linewidth=0.8)
    feed = f", f = {forces.feed[cl]:.4g}" + ("" if after is None else f" → {after.feed[cl]:.4g}") + " mm/tooth"
    axes.set(xlabel="rotation angle of flute 1, φ (deg)", ylabel="force on the tool (N)",
             title=f"CL {cl}: peak |F| {forces.peak[cl]:.4g} N" + feed)
    axes.set_xlim(forces.phi[0], forces.phi[-1])
    axes.grid(alpha=0.3)


def schedule_figure(forces, plan):
    """Figure of a Schedule over the pass: the peak (force in N or area in mm²) per CL point
    before and after with the limit, and the feed per tooth programmed and scheduled."""
    figure = Figure(figsize=(11, 7.5), dpi=100, layout="constrained")
    FigureCanvasAgg(figure)
    top = figure.add_subplot(2, 1, 1)
    bottom = figure.add_subplot(2, 1, 2, sharex=top)
    index = np.arange(plan.feed.size)
    unit, what = ("N", "peak resultant force") if plan.kind == "force" else ("mm²", "peak total cut area")
    top.plot(index, plan.before, ".-", color="tab:red", label="programmed feed")
    top.plot(index, plan.after, ".-", color="tab:blue", label="scheduled feed")
    top.axhline(plan.limit, color="black", linestyle="--", linewidth=1.0, label=f"limit {plan.limit:g} {unit}")
    bottom.plot(index, plan.programmed, ".-", color="tab:red", label="programmed")
    bottom.plot(index, plan.feed, ".-", color="tab:blue", label="scheduled")
    if plan.infeasible.any():
        bad = np.flatnonzero(plan.infeasible)
        top.plot(bad, plan.after[bad], "x", color="black", markersize=9, label="limit not met at the minimum feed")
        bottom.plot(bad, plan.feed[bad], "x", color="black", markersize=9, label="minimum feed")
    top.set(ylabel=f"{what} ({unit})", title=f"{what.capitalize()} per CL point, before and after scheduling")
    bottom.set(xlabel="CL point index", ylabel="feed per tooth (mm)", title="Feed per tooth along the pass")
    bottom.set_ylim(0.0, 1.1 * max(plan.programmed.max(), plan.feed.max()))
    top.set_ylim(0.0, 1.15 * max(plan.before.max(), plan.limit))
    for axes in (top, bottom):
        axes.set_xlim(-0.5, index.size - 0.5)
        axes.legend(loc="lower right", fontsize=9)
        axes.grid(alpha=0.3)
    return figure


def schedule_csv_text(plan):
    """CSV text of a Schedule: cl, programmed_feed, feed (mm/tooth), peak_before, peak_after (N or mm²), infeasible."""
    lines = ["cl,programmed_feed,feed,peak_before,peak_after,infeasible"]
    for i in range(plan.feed.size):
        lines.append(f"{i},{plan.programmed[i]!r},{plan.feed[i]!r},{plan.before[i]!r},{plan.after[i]!r},"
                     f"{int(plan.infeasible[i])}")
    return "\n".join(lines) + "\n"


def write_schedule_report(folder, forces, plan, *, title, parameters=""):
    """Write index.html, forces.png, schedule.png and schedule.csv of a Schedule into `folder`.

    forces: the Forces at the programmed feed. Returns the path of index.html.
    """
    after = forces.with_feed(plan.feed)
    cls = chosen_cl(forces)
    images = {"schedule.png": schedule_figure(forces, plan),
              "forces.png": force_over_phi_figure(forces, cls, after=after)}
    embedded = {}
    for name, figure in images.items():
        buffer = io.BytesIO()
        figure.savefig(buffer, format="png")
        with open(os.path.join(folder, name), "wb") as file:
            file.write(buffer.getvalue())
        embedded[name] = base64.b64encode(buffer.getvalue()).decode("ascii")
    with open(os.path.join(folder, "schedule.csv"), "w", encoding="utf-8", newline="") as file:
        file.write(schedule_csv_text(plan))
    unit = "N" if plan.kind == "force" else "mm²"
    before_force, after_force = peak(forces), peak(after)
    rows = [
        ("limit", f"peak {plan.kind} ≤ {plan.limit:g} {unit}"),
        ("peak before → after", f"{plan.before.max():.4g} → {plan.after.max():.4g} {unit}"),
        ("peak force before → after", f"{before_force.max():.4g} → {after_force.max():.4g} N"),
        ("CL points with a lower feed", f"{int(plan.reduced.sum())} of {plan.feed.size}"),
        ("CL points that cannot meet the limit", f"{int(plan.infeasible.sum())} (given the minimum feed)"),
        ("feed per tooth", f"{plan.programmed.min():.4g}..{plan.programmed.max():.4g} → "
                           f"{plan.feed.min():.4g}..{plan.feed.max():.4g} mm"),
        ("parameters", parameters),
    ]
    table = "\n".join(f"<tr><th>{html.escape(k)}</th><td>{html.escape(v)}</td></tr>" for k, v in rows)
    page = f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>
<style>body {{ font: 15px/1.45 system-ui, sans-serif; max-width: 1100px; margin: 24px auto; color: #222; }}
th, td {{ text-align: left; padding: 3px 10px; border-bottom: 1px solid #e3e6ea; }} img {{ width: 100%; }}</style>
</head><body>
<h1>{html.escape(title)}</h1>
<table>{table}</table>
<h2>Along the pass</h2>
<img alt="peak and feed along the pass" src="data:image/png;base64,{embedded['schedule.png']}">
<h2>Force over φ at CL {', '.join(str(cl) for cl in cls)}</h2>
<p>Global frame, summed over the flutes cutting at each angle of flute 1; solid: programmed feed,
dashed: scheduled feed.</p>
<img alt="force over the rotation angle" src="data:image/png;base64,{embedded['forces.png']}">
<p>Per CL point: <a href="schedule.csv">schedule.csv</a>.</p>
</body></html>
"""
    path = os.path.join(folder, "index.html")
    with open(path, "w", encoding="utf-8") as file:
        file.write(page)
    return path
