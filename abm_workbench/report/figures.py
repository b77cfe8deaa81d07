"""Figures of a validation report (matplotlib Figure on an Agg canvas; no pyplot, no FreeCAD).

Each function takes a :class:`~abm_workbench.validation.Validation` of a pass (m CL points ×
p angles φ) and returns a Figure. Lengths in mm, areas in mm², angles in degrees, CL points by
their 0-based index, relative errors shown in %. The paper's figures they follow are named.
"""

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.colors import LogNorm
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from ..engine import edge_lines
from .colours import segment_colour
from .plots import cell_edges

#: Width of every figure (in) at DPI; heights vary.
WIDTH, DPI = 11.0, 100
#: Colours of the two methods.
ABM_COLOUR, REF_COLOUR = "tab:blue", "black"
#: Relative errors below this are drawn at it on log scales.
ERROR_FLOOR = 1e-16
#: At most this many edge lines per CL point in the 3D view.
SHAPE_LINES = 60
#: Direction of the light that shades the in-process stock (unit).
LIGHT = np.array([-0.4, -0.5, 0.77]) / np.linalg.norm([-0.4, -0.5, 0.77])
#: Lines drawn around the tool's cylinder in the in-process view.
TOOL_LINES = 24


def _figure(height, rows=1, cols=1, **grid):
    """A constrained-layout Figure WIDTH × height in with its Agg canvas and a rows × cols grid."""
    figure = Figure(figsize=(WIDTH, height), dpi=DPI, layout="constrained")
    FigureCanvasAgg(figure)
    return figure, figure.add_gridspec(rows, cols, **grid)


def pass_length_figure(validation):
    """Length of cut along the pass (Fig. 6(e)/(f)): max and mean over φ per CL point, ABM as lines
    and the boolean reference as markers; below, the ABM length of cut over (CL point, φ)."""
    engagement, comparison = validation.engagement, validation.comparison
    m, _ = engagement.shape
    figure, grid = _figure(7.5, 2, 1, height_ratios=(1.0, 1.1))
    along = figure.add_subplot(grid[0])
    index = np.arange(m)
    for name, reduce, style in (("max", np.max, "-"), ("mean", np.mean, "--")):
        along.plot(index, reduce(comparison.l_abm, axis=1), style, color=ABM_COLOUR, label=f"ABM, {name} over φ")
        along.plot(index, reduce(comparison.l_ref, axis=1), "o" if name == "max" else "s", markersize=4,
                   markerfacecolor="none", color=REF_COLOUR, label=f"boolean, {name} over φ")
    along.set(xlabel="CL point", ylabel="length of cut (mm)", title="Length of cut along the pass",
              xlim=(-0.5, m - 0.5))
    along.set_ylim(0.0, 1.3 * along.get_ylim()[1])
    along.legend(fontsize="small", ncol=4, loc="upper center")
    along.grid(True, alpha=0.3)
    heat = figure.add_subplot(grid[1], sharex=along)
    length = np.ma.masked_less_equal(comparison.l_abm.T, 0.0)
    mesh = heat.pcolormesh(cell_edges(index), cell_edges(engagement.phi), length, cmap="viridis", shading="flat")
    heat.set_facecolor("0.92")
    figure.colorbar(mesh, ax=heat, label="length of cut (mm)", pad=0.01)
    heat.set(xlabel="CL point", ylabel="φ (deg)", title="ABM length of cut over the pass (grey: no engagement)")
    along.xaxis.set_major_locator(MaxNLocator(integer=True))
    return figure


def depth_figure(validation, paper_range=None, paper_label=""):
    """Depth of cut along the pass, ABM and reference; the paper's range as dashed lines when given.

    paper_range: (low, high) mm, the range the paper reports for this model test, or None.
    """
    comparison = validation.comparison
    m = comparison.depth_abm.size
    figure, grid = _figure(3.8)
    axes = figure.add_subplot(grid[0])
    index = np.arange(m)
    axes.plot(index, comparison.depth_abm, "-", color=ABM_COLOUR, label="ABM")
    axes.plot(index, comparison.depth_ref, "o", markersize=4, markerfacecolor="none", color=REF_COLOUR,
              label="boolean")
    if paper_range is not None:
        for k, value in enumerate(paper_range):
            axes.axhline(value, color="tab:red", linestyle="--", linewidth=1.0,
                         label=f"{paper_label}: {paper_range[0]:g}–{paper_range[1]:g} mm" if k == 0 else None)
    axes.set(xlabel="CL point", ylabel="depth of cut (mm)", title="Depth of cut along the pass",
             xlim=(-0.5, m - 0.5))
    axes.xaxis.set_major_locator(MaxNLocator(integer=True))
    axes.legend(fontsize="small", loc="best")
    axes.grid(True, alpha=0.3)
    return figure


def phi_figure(validation, cls):
    """Length of cut and cut area over φ at CL points `cls` (Fig. 7(a)–(h)): a row per CL point.

    ABM as a line, the reference as markers (its area is l_ref·h); the engagement segments
    shaded and lettered.
    """
    engagement, comparison = validation.engagement, validation.comparison
    phi, h = engagement.phi, engagement.h
    figure, grid = _figure(2.6 * len(cls) + 0.4, len(cls), 2)
    every = max(1, phi.size // 45)
    for row, cl in enumerate(cls):
        length = figure.add_subplot(grid[row, 0])
        area = figure.add_subplot(grid[row, 1], sharex=length)
        for axes, abm, ref, label in ((length, comparison.l_abm[cl], comparison.l_ref[cl], "length of cut (mm)"),
                                      (area, engagement.area[cl], comparison.l_ref[cl] * h[cl], "cut area (mm²)")):
            _shade_segments(axes, engagement, cl)
            axes.plot(phi, abm, color=ABM_COLOUR, label="ABM")
            axes.plot(phi, ref, "o", markevery=every, markersize=3.5, markerfacecolor="none", color=REF_COLOUR,
                      label="boolean")
            axes.set(ylabel=label, xlim=(phi[0], phi[-1] if phi.size > 1 else phi[0] + 1.0))
            axes.set_ylim(0.0, 1.2 * max(axes.get_ylim()[1], 1e-9))
            axes.grid(True, alpha=0.3)
        length.set_title(f"CL {cl}: length of cut", loc="left", fontsize="medium")
        area.set_title(f"CL {cl}: cut area A = l·h", loc="left", fontsize="medium")
        if row == 0:
            length.legend(fontsize="small", loc="upper right")
        if row == len(cls) - 1:
            length.set_xlabel("φ (deg)")
            area.set_xlabel("φ (deg)")
    return figure


def shape_figure(validation, cls):
    """The shape of the cut in 3D (Fig. 6(c)/(d)): the engaged part of the cutting edge, LEP to
    UEP, over φ at CL points `cls` (up to four), coloured by engagement segment."""
    engagement = validation.engagement
    cols = min(2, len(cls))
    rows = -(-len(cls) // cols)
    figure, grid = _figure(5.0 * rows, rows, cols)
    for k, cl in enumerate(cls):
        axes = figure.add_subplot(grid[k // cols, k % cols], projection="3d")
        lep, uep = engagement.lep_xyz[cl], engagement.uep_xyz[cl]
        engaged = np.flatnonzero(engagement.segment[cl] >= 0)
        shown = engaged[:: max(1, -(-engaged.size // SHAPE_LINES))]
        for index in shown:
            colour = segment_colour(engagement.segment[cl, index])
            axes.plot(*np.stack([lep[index], uep[index]]).T, color=colour, linewidth=1.2)
        for points, name in ((lep, "LEP"), (uep, "UEP")):
            axes.plot(*points.T, color="0.2", linewidth=0.8, linestyle=":" if name == "LEP" else "-")
        handles = [
            axes.plot([], [], color=segment_colour(s), linewidth=3)[0] for s in range(len(engagement.segments(cl)))
        ]
        labels = [f"{s['letter']}: {s['surface'].replace('_', ' ')} {s['phi_start']:g}–{s['phi_end']:g}°"
                  for s in engagement.segments(cl)]
        axes.legend(handles, labels, fontsize="x-small", loc="upper left")
        if engaged.size:
            points = np.concatenate([lep[engaged], uep[engaged]])
            axes.set_box_aspect(np.maximum(np.ptp(points, axis=0), 1e-3))
        axes.set(xlabel="x (mm)", ylabel="y (mm)", zlabel="z (mm)")
        axes.set_title(f"CL {cl}: engaged edge LEP–UEP (solid line: UEP, dotted: LEP)", fontsize="medium")
        axes.tick_params(labelsize="x-small")
    return figure


def inprocess_figure(validation, views, toolpath, tool):
    """The in-process stock at the CL points of `views` ({cl: (x (c,), y (c,), z (c, c)) mm}, the top of
    the stock less what earlier moves removed, around the tool), a row per CL point. Left: that top
    surface shaded, the tool's cylinder (grey lines) and the engaged part of its cutting edge (ABM,
    LEP to UEP, blue). Right: the length of cut over φ in the stock as given (ABM, grey), in the
    in-process stock (ABM, blue) and by the boolean on the in-process stock (black rings)."""
    engagement, comparison, check = validation.engagement, validation.comparison, validation.in_process
    cls = sorted(views)
    figure, grid = _figure(4.6 * len(cls), len(cls), 2, width_ratios=(1.0, 1.2))
    base, direction = edge_lines(toolpath, tool, np.linspace(0.0, 360.0, TOOL_LINES, endpoint=False))
    for row, cl in enumerate(cls):
        x, y, z = views[cl]
        axes = figure.add_subplot(grid[row, 0], projection="3d")
        gx, gy = np.meshgrid(x, y)
        dz_dy, dz_dx = np.gradient(np.nan_to_num(z, nan=np.nanmin(z, initial=0.0)), y, x)
        normal = np.stack([-dz_dx, -dz_dy, np.ones_like(z)], axis=-1)
        shade = 0.35 + 0.6 * np.abs(normal @ LIGHT) / np.linalg.norm(normal, axis=-1)
        colours = np.stack([0.93 * shade, 0.8 * shade, 0.6 * shade, np.ones_like(shade)], axis=-1)
        axes.plot_surface(gx, gy, z, facecolors=colours, rstride=1, cstride=1, linewidth=0.0, antialiased=False,
                          shade=False)
        rim = np.stack([base[cl], base[cl] + tool.flute_length * direction[cl]])
        for k in range(TOOL_LINES):
            axes.plot(*rim[:, k].T, color="0.45", linewidth=0.5)
        for end in rim:
            axes.plot(*np.vstack([end, end[:1]]).T, color="0.45", linewidth=0.7)
        engaged = np.flatnonzero(engagement.segment[cl] >= 0)
        for index in engaged[:: max(1, -(-engaged.size // SHAPE_LINES))]:
            axes.plot(*np.stack([engagement.lep_xyz[cl, index], engagement.uep_xyz[cl, index]]).T, color=ABM_COLOUR,
                      linewidth=1.4)
        points = np.concatenate([np.column_stack([gx.ravel(), gy.ravel(), z.ravel()]), rim.reshape(-1, 3)])
        low, high = np.nanmin(points, axis=0), np.nanmax(points, axis=0)
        axes.set(xlim=(low[0], high[0]), ylim=(low[1], high[1]), zlim=(low[2], high[2]),
                 xlabel="x (mm)", ylabel="y (mm)", zlabel="z (mm)")
        axes.set_box_aspect(np.maximum(high - low, 1e-3))
        axes.view_init(elev=28.0, azim=-62.0)
        axes.tick_params(labelsize="x-small")
        changed = "changed by earlier moves" if check.changed[cl] else "not changed by earlier moves"
        axes.set_title(f"CL {cl}: top of the in-process stock around the tool\n({changed}; {check.swept[cl]:.0f} swept "
                       "pieces near)",
                       fontsize="small", loc="left")
        along = figure.add_subplot(grid[row, 1])
        phi = engagement.phi
        along.plot(phi, check.initial[cl], color="0.55", linestyle="--", label="ABM, stock as given")
        along.plot(phi, comparison.l_abm[cl], color=ABM_COLOUR, label="ABM, in-process stock")
        along.plot(phi, comparison.l_ref[cl], "o", markevery=max(1, phi.size // 45), markersize=3.5,
                   markerfacecolor="none", color=REF_COLOUR, label="boolean, in-process stock")
        along.set(xlabel="φ (deg)", ylabel="length of cut (mm)",
                  xlim=(phi[0], phi[-1] if phi.size > 1 else phi[0] + 1.0))
        along.set_ylim(0.0, 1.15 * max(along.get_ylim()[1], 1e-9))
        along.grid(True, alpha=0.3)
        along.set_title(f"CL {cl}: max |l_ABM − l_ref| {np.abs(comparison.difference[cl]).max():.3g} mm",
                        fontsize="small", loc="left")
        if row == 0:
            along.legend(fontsize="small", loc="upper right")
    return figure


def error_figure(validation, cls):
    """Error of the length of cut per engagement segment at CL points `cls` (Fig. 8(c), 8(e)).

    Left: the relative error (%) over φ with the segments shaded; instants judged by the
    absolute error (l_ref < 1e-3 mm) are left out. Right: max and mean |relative error| per
    segment, lettered with the UEP's surface.
    """
    engagement, comparison = validation.engagement, validation.comparison
    phi = engagement.phi
    figure, grid = _figure(2.6 * len(cls) + 0.4, len(cls), 2, width_ratios=(1.6, 1.0))
    for row, cl in enumerate(cls):
        over = figure.add_subplot(grid[row, 0])
        _shade_segments(over, engagement, cl)
        over.plot(phi, 100.0 * comparison.relative_error[cl], ".-", color=ABM_COLOUR, markersize=2.5,
                  linewidth=0.8)
        over.axhline(0.0, color="0.5", linewidth=0.8)
        over.set(ylabel="(l_ABM − l_ref)/l_ref (%)", xlim=(phi[0], phi[-1] if phi.size > 1 else phi[0] + 1.0))
        over.set_title(f"CL {cl}: relative error of the length of cut", loc="left", fontsize="medium")
        over.grid(True, alpha=0.3)
        bars = figure.add_subplot(grid[row, 1])
        segments = engagement.segments(cl)
        statistics = [_segment_errors(engagement, comparison, cl, s) for s in range(len(segments))]
        x = np.arange(len(segments))
        bars.bar(x - 0.2, [100.0 * s[0] for s in statistics], 0.4, color="tab:red", label="max |error|")
        bars.bar(x + 0.2, [100.0 * s[1] for s in statistics], 0.4, color="tab:gray", label="mean |error|")
        bars.set_xticks(x, [f"{s['letter']}\n{s['surface'].replace('_', ' ')}" for s in segments],
                        fontsize="x-small")
        bars.set(ylabel="|relative error| (%)")
        bars.set_title(f"CL {cl}: per segment", loc="left", fontsize="medium")
        bars.grid(True, axis="y", alpha=0.3)
        if row == 0:
            bars.legend(fontsize="x-small")
        if row == len(cls) - 1:
            over.set_xlabel("φ (deg)")
    return figure


def error_pass_figure(validation):
    """|Relative error| of the length of cut over (CL point, φ), log colour scale; grey where the
    error is absolute (l_ref < 1e-3 mm) and below the floor shown at ERROR_FLOOR."""
    engagement, comparison = validation.engagement, validation.comparison
    m, _ = engagement.shape
    figure, grid = _figure(4.2)
    axes = figure.add_subplot(grid[0])
    error = np.ma.masked_invalid(np.maximum(np.abs(comparison.relative_error), ERROR_FLOOR)).T
    top = max(float(error.max()) if error.count() else 1.0, 10 * ERROR_FLOOR)
    mesh = axes.pcolormesh(cell_edges(np.arange(m)), cell_edges(engagement.phi), error, shading="flat", cmap="magma_r",
                           norm=LogNorm(vmin=ERROR_FLOOR, vmax=top))
    axes.set_facecolor("0.92")
    figure.colorbar(mesh, ax=axes, label="|relative error|", pad=0.01)
    axes.set(xlabel="CL point", ylabel="φ (deg)",
             title="|relative error| of the length of cut over the pass (grey: l_ref < 1e-3 mm)")
    axes.xaxis.set_major_locator(MaxNLocator(integer=True))
    return figure


def _segment_errors(engagement, comparison, cl, index):
    """(max, mean) |relative error| over segment `index` of CL point `cl`; (0, 0) if none is relative."""
    mask = (engagement.segment[cl] == index) & comparison.relative[cl]
    values = np.abs(comparison.error[cl, mask])
    return (float(values.max()), float(values.mean())) if values.size else (0.0, 0.0)


def _shade_segments(axes, engagement, cl):
    """Shade each engagement segment of CL point `cl` over φ in its colour, its letter at the top."""
    half = 0.5 * (engagement.phi[1] - engagement.phi[0]) if engagement.phi.size > 1 else 0.5
    for index, segment in enumerate(engagement.segments(cl)):
        start, end = segment["phi_start"] - half, segment["phi_end"] + half
        axes.axvspan(start, end, color=segment_colour(index), alpha=0.12, linewidth=0)
        axes.text(0.5 * (start + end), 0.98, segment["letter"], transform=axes.get_xaxis_transform(),
                  ha="center", va="top", fontsize="small", color=segment_colour(index), fontweight="bold")

