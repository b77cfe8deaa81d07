"""Plots of one pass's Engagement (matplotlib Figure on an Agg canvas; no pyplot, no FreeCAD).

Lengths in mm, areas in mm², angles in degrees, CL points by their 0-based index.
"""

import textwrap

import matplotlib
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from ..formats import replacing

#: Line colours of the representative CL points: deepest, shallowest, middle of the pass.
_COLOURS = ("tab:red", "tab:blue", "tab:green")
#: Colour map of the length-of-cut heat map; cells without engagement in light grey.
_HEAT_MAP = matplotlib.colormaps["viridis"].with_extremes(bad="0.92")
#: Title lines are wrapped at this many characters, and at most _TITLE_LINES of them shown.
_TITLE_WIDTH, _TITLE_LINES = 120, 3
#: Room above the curves for the legends (× the data limit, or × the data span for the depth).
_HEADROOM = 1.35


def plot_pass(engagement, path, *, title=""):
    """Write the pass figure (see pass_figure) to `path` as a PNG, atomically."""
    figure = pass_figure(engagement, title=title)
    with replacing(path) as (temporary,):
        figure.savefig(temporary, format="png")


def pass_figure(engagement, *, title=""):
    """Figure of a pass (m CL points × p angles φ), 12 × 12 in at 100 dpi; a long title is wrapped.

    Top: max length of cut over φ, and depth of cut, per CL index. Middle: heat map of the
    length of cut over (CL index, φ). Bottom: length of cut and cut area over φ at three
    representative CL points (deepest, shallowest, middle of the pass), marked above.
    """
    figure = Figure(figsize=(12, 12), dpi=100, layout="constrained")
    FigureCanvasAgg(figure)
    grid = figure.add_gridspec(3, 2, height_ratios=(1.0, 1.3, 1.0))
    along_length = figure.add_subplot(grid[0, 0])
    along_depth = figure.add_subplot(grid[0, 1], sharex=along_length)
    heat = figure.add_subplot(grid[1, :])
    over_length = figure.add_subplot(grid[2, 0])
    over_area = figure.add_subplot(grid[2, 1], sharex=over_length)
    m, p = engagement.shape
    index = np.arange(m)
    chosen = representative_cl(engagement.depth_of_cut)

    along_length.plot(index, engagement.length.max(axis=1), ".-", color="black")
    along_length.set(xlabel="CL point index", ylabel="max length of cut over φ (mm)",
                     title="Maximum length of cut along the pass")
    along_depth.plot(index, engagement.depth_of_cut, ".-", color="black")
    along_depth.set(xlabel="CL point index", ylabel="depth of cut (mm)", title="Depth of cut along the pass")
    for axes in (along_length, along_depth):
        axes.set_xlim(-0.5, m - 0.5)
        for (cl, label), colour in zip(chosen, _COLOURS):
            axes.axvline(cl, color=colour, linestyle="--", linewidth=1.0, label=f"CL {cl} ({label})")
    if chosen:
        low, high = along_depth.get_ylim()
        along_depth.set_ylim(low, high + (_HEADROOM - 1.0) * (high - low))
        along_depth.legend(loc="upper center", ncol=3, fontsize="small", title="CL points shown below",
                           title_fontsize="small")

    length = np.ma.masked_less_equal(engagement.length.T, 0.0)
    mesh = heat.pcolormesh(cell_edges(index), cell_edges(engagement.phi), length, cmap=_HEAT_MAP, shading="flat")
    figure.colorbar(mesh, ax=heat, label="length of cut (mm)", pad=0.01)
    heat.set(xlabel="CL point index", ylabel="tool rotation angle φ (deg)",
             title="Length of cut over the pass (grey: no engagement)")
    for axes in (along_length, along_depth, heat):
        axes.xaxis.set_major_locator(MaxNLocator(integer=True))

    for (cl, label), colour in zip(chosen, _COLOURS):
        legend = f"CL {cl}: {label}, depth {engagement.depth_of_cut[cl]:.2f} mm"
        over_length.plot(engagement.phi, engagement.length[cl], color=colour, label=legend)
        over_area.plot(engagement.phi, engagement.area[cl], color=colour, label=legend)
    over_length.set(xlabel="tool rotation angle φ (deg)", ylabel="length of cut (mm)",
                    title="Length of cut at representative CL points")
    over_area.set(xlabel="tool rotation angle φ (deg)", ylabel="cut area A = length · h (mm²)",
                  title="Cut area at representative CL points")
    for axes in (over_length, over_area):
        axes.set_xlim(engagement.phi[0], engagement.phi[-1] if p > 1 else engagement.phi[0] + 1.0)
        axes.set_ylim(0.0, _HEADROOM * max(axes.get_ylim()[1], 1e-9))
        if chosen:
            axes.legend(loc="upper center", fontsize="small", ncol=2)
        else:
            axes.text(0.5, 0.5, "the tool never engages the stock", transform=axes.transAxes, ha="center")
    for axes in (along_length, along_depth, over_length, over_area):
        axes.grid(True, alpha=0.3)
    title = textwrap.shorten(title or "Cut geometry along the pass", _TITLE_WIDTH * _TITLE_LINES - 10,
                             placeholder=" …")
    figure.suptitle(textwrap.fill(title, _TITLE_WIDTH), fontsize="large")
    return figure


def representative_cl(depth_of_cut):
    """Up to three engaged CL points as (index, label): deepest, shallowest, middle of the pass.

    depth_of_cut: (m,) mm, NaN where a CL point does not engage. The middle one is the engaged
    CL point nearest the pass's middle index that is neither of the others.
    """
    engaged = np.flatnonzero(~np.isnan(depth_of_cut))
    if engaged.size == 0:
        return []
    deepest = int(engaged[np.argmax(depth_of_cut[engaged])])
    shallowest = int(engaged[np.argmin(depth_of_cut[engaged])])
    chosen = [(deepest, "deepest")]
    if shallowest != deepest:
        chosen.append((shallowest, "shallowest"))
    rest = engaged[~np.isin(engaged, [deepest, shallowest])]
    if rest.size:
        middle = int(rest[np.argmin(np.abs(rest - 0.5 * (depth_of_cut.size - 1)))])
        chosen.append((middle, "middle"))
    return chosen


def cell_edges(centres):
    """Cell edges (n+1,) around sorted cell centres (n,): midpoints, ends mirrored (1 wide if n = 1)."""
    centres = np.asarray(centres, dtype=float)
    if centres.size == 1:
        return centres + np.array([-0.5, 0.5])
    middle = 0.5 * (centres[1:] + centres[:-1])
    return np.concatenate([[2 * centres[0] - middle[0]], middle, [2 * centres[-1] - middle[-1]]])
