"""The engagement dock: pick a CL point, see it highlighted on the model and its plots.

One ``QDockWidget`` ("ABM engagement", object name ``ABM_EngagementDock``) on the right of
FreeCAD's main window, showing one engagement object at a time (:func:`show`):

- a slider and a spin box over the CL points (0-based, as in the results CSV): every CL point of
  the toolpath's operation, all its passes; for a program of several operations, a second slider
  over the whole program, kept in step (:mod:`.program`); the chosen CL point is drawn on top of the model
  (``EngagementViewProvider.highlight``) and a line says its depth of cut, engagement segments
  and whether earlier moves of the program changed it (:func:`in_process_words`) at once, and
  its plots follow once the events queued are handled (a timer of 0 ms: a dragged slider plots
  where it stops);
- "Colour by" (the view property ``ColourBy``) and the legend: for segments, the UEP surface
  kinds and their colours; for a quantity, the colour bar with its minimum and maximum and unit
  (force only for an engagement with forces: otherwise the segments are shown);
- tab "Engagement": matplotlib plots (``FigureCanvasQTAgg``) for the chosen CL point: length of cut, cut area
  and cut thickness h over φ, each engagement segment in the colour of its UEP surface (as on
  the model, ``report.colours.SURFACE_COLOURS``), and the pass progression: depth of cut and maximum
  length of cut over the CL points, a marker at the chosen one;
- tab "Forces" (enabled when the engagement has forces, ``Forces`` on): F_x, F_y, F_z and |F|
  over φ at the chosen CL point, and the peak and mean resultant force along the pass with a
  marker at the chosen CL point (drawn by ``report.forces.draw_force_over_phi`` and
  ``draw_force_along``, as in the reports).
"""

import numpy as np
from PySide import QtCore, QtGui

import FreeCAD
import FreeCADGui

from .colouring import COLOUR_BY, QUANTITIES
from . import state
from .colouring import HIGHLIGHT_COLOUR
from .i18n import noop, translate
from .program import ProgramRow

OBJECT_NAME = "ABM_EngagementDock"
#: The quantities' names of colouring.QUANTITIES, for the translation template.
QUANTITY_WORDS = (noop("length of cut"), noop("cut area"), noop("resultant cutting force"))
#: The UEP surface kinds of report.colours.SURFACE_COLOURS in words (underscores as blanks), for the template.
SURFACE_WORDS = (noop("none"), noop("top"), noop("straight wall"), noop("curved wall"), noop("flute end"),
                 noop("stock side"), noop("immersion end"), noop("bottom"), noop("flute start"), noop("machined"))
#: The curves' labels that report.forces.draw_force_along gives, for the template (translated in the dock).
FORCE_CURVES = (noop("peak |F| over φ"), noop("mean |F| over φ"))
#: Width (px) of the legend's colour bar.
BAR_WIDTH = 220
#: Height of the length plot × its largest value, so the segment legend sits above the curve.
LEGEND_HEADROOM = 1.7
#: Smallest height (px) of the plots: the dock fits beside FreeCAD's panels on a screen 768 pixels high
#: (the plots are laid out again for the height they get).
CANVAS_MIN_HEIGHT = 260
#: Index of the "Forces" tab.
FORCES_TAB = 1
#: Stacked plots of the "Engagement" tab: length of cut, cut area, h, pass progression.
PLOTS = 4


class EngagementDock(QtGui.QDockWidget):
    """The dock (see the module docstring); ``show_object(obj, cl)`` fills it."""

    def __init__(self, parent):
        super().__init__(translate("ABM engagement"), parent)
        self.setObjectName(OBJECT_NAME)
        self.obj = None
        body = QtGui.QWidget()
        layout = QtGui.QVBoxLayout(body)
        self.title = QtGui.QLabel()
        self.title.setWordWrap(True)
        layout.addWidget(self.title)

        row = QtGui.QHBoxLayout()
        row.addWidget(QtGui.QLabel(translate("CL point")))
        self.slider = QtGui.QSlider(QtCore.Qt.Horizontal)
        self.slider.setObjectName("ABM_CLSlider")
        self.spin = QtGui.QSpinBox()
        self.spin.setObjectName("ABM_CLSpin")
        row.addWidget(self.slider, 1)
        row.addWidget(self.spin)
        layout.addLayout(row)
        self.slider.valueChanged.connect(self.spin.setValue)
        self.spin.valueChanged.connect(self.slider.setValue)
        self.spin.valueChanged.connect(self.choose)
        self.program = ProgramRow(self)
        layout.addWidget(self.program)
        self.about = QtGui.QLabel()
        self.about.setWordWrap(True)
        layout.addWidget(self.about)

        row = QtGui.QHBoxLayout()
        row.addWidget(QtGui.QLabel(translate("Colour by")))
        self.colour_by = QtGui.QComboBox()
        self.colour_by.setObjectName("ABM_ColourBy")
        for value in COLOUR_BY:
            self.colour_by.addItem(translate(QUANTITIES[value][1]) if value in QUANTITIES
                                   else translate("engagement segment (UEP surface)"), value)
        self.colour_by.currentIndexChanged.connect(self._colour_by_changed)
        row.addWidget(self.colour_by, 1)
        layout.addLayout(row)
        self.legend = QtGui.QLabel()
        self.legend.setObjectName("ABM_Legend")
        layout.addWidget(self.legend)

        from matplotlib.backends.backend_qt5agg import FigureCanvasQTAgg
        from matplotlib.figure import Figure

        self.figure = Figure(figsize=(4.2, 7.0), dpi=80)
        self.canvas = FigureCanvasQTAgg(self.figure)
        self.canvas.mpl_connect("resize_event", lambda event: self.figure.axes and _lay_out(self.figure))
        self.canvas.setMinimumHeight(CANVAS_MIN_HEIGHT)
        self.force_figure = Figure(figsize=(4.2, 7.0), dpi=80, layout="constrained")
        self.force_canvas = FigureCanvasQTAgg(self.force_figure)
        self.force_canvas.setMinimumHeight(CANVAS_MIN_HEIGHT)
        self.tabs = QtGui.QTabWidget()
        self.tabs.setObjectName("ABM_PlotTabs")
        self.tabs.addTab(self.canvas, translate("Engagement"))
        self.tabs.addTab(self.force_canvas, translate("Forces"))
        layout.addWidget(self.tabs, 1)
        self.setWidget(body)
        self.chosen = None  # the CL point whose plots are due
        self.plots_due = QtCore.QTimer(self)  # plots drawn once the events queued are handled
        self.plots_due.setSingleShot(True)
        self.plots_due.setInterval(0)
        self.plots_due.timeout.connect(self.plot_chosen)

    # ---- filling --------------------------------------------------------------------------
    def show_object(self, obj, cl=None):
        """Show the engagement object `obj`, at CL point `cl` (default: the deepest engaged one)."""
        if self.obj is not None and self.obj is not obj:
            _highlight(self.obj, None)
        self.obj = obj
        self.refresh(cl)

    def refresh(self, cl=None):
        """Redraw for the object's current results (after a recompute), at `cl` or the current CL."""
        obj = self.obj
        result = _result(obj)
        if result is None:
            self.title.setText(translate("{label}: no results (recompute it)", label=obj.Label)
                               if _alive(obj) else translate("No engagement: select one and use Inspect engagement"))
            self.about.setText("")
            self.legend.clear()
            for figure, canvas in ((self.figure, self.canvas), (self.force_figure, self.force_canvas)):
                figure.clear()
                canvas.draw_idle()
            self.tabs.setTabEnabled(FORCES_TAB, False)
            self.program.show_for(None, 0)
            return
        m = result.shape[0]
        if cl is None:
            cl = self.spin.value() if self.spin.maximum() == m - 1 and self.spin.value() < m else _deepest(result)
        forces = _forces(obj)
        peak = "" if forces is None else translate("; peak force {force} N", force=f"{obj.PeakForce:.4g}")
        self.title.setText(translate("<b>{label}</b>: {m} CL points × {p} angles φ; depth of cut {low}–{high} mm",
                                     label=obj.Label, m=m, p=result.shape[1], low=f"{obj.DepthOfCutMin.Value:.2f}",
                                     high=f"{obj.DepthOfCutMax.Value:.2f}") + f"{peak}; {stock_model_words(obj)}")
        self.tabs.setTabEnabled(FORCES_TAB, forces is not None)
        self.colour_by.model().item(COLOUR_BY.index("force")).setEnabled(forces is not None)
        self.tabs.setTabToolTip(FORCES_TAB, "" if forces is not None else
                                translate("no forces: turn Cutting forces on in the engagement's task panel and "
                                          "recompute"))
        for widget in (self.slider, self.spin):
            widget.blockSignals(True)
            widget.setRange(0, m - 1)
            widget.setValue(int(cl))
            widget.blockSignals(False)
        self.program.show_for(obj, int(cl))
        vobj = obj.ViewObject
        if "ColourBy" in vobj.PropertiesList:
            self.colour_by.blockSignals(True)
            self.colour_by.setCurrentIndex(COLOUR_BY.index(vobj.ColourBy))
            self.colour_by.blockSignals(False)
        self.show_legend()
        self.figure.clear()  # new results (another object or operation, a recompute): axes made and laid out anew
        self.choose(int(cl))

    def choose(self, cl):
        """Make CL point `cl` the chosen one: highlight and text at once, the plots once the events queued
        are handled (a slider dragged over many CL points plots only where it stops)."""
        obj = self.obj
        result = _result(obj)
        if result is None or not 0 <= cl < result.shape[0]:
            return
        _highlight(obj, cl)
        segments = result.segments(cl)
        depth = result.depth_of_cut[cl]
        if segments:
            parts = ", ".join(f"{s['letter']} {s['phi_start']:g}–{s['phi_end']:g}° {surface_words(s['surface'])}"
                              for s in segments)
            self.about.setText(translate("CL {cl}: depth of cut {depth} mm, max length of cut {length} mm; segments",
                                         cl=cl, depth=f"{depth:.3f}", length=f"{result.length[cl].max():.3f}")
                               + f" {parts}{in_process_words(obj, result, cl)}")
        else:
            self.about.setText(translate("CL {cl}: the tool does not engage the stock here", cl=cl)
                               + in_process_words(obj, result, cl))
        self.chosen = cl
        self.plots_due.start()

    def plot_chosen(self):
        """Draw the plots of the chosen CL point (if the object still has results with it)."""
        obj, cl = self.obj, self.chosen
        result = _result(obj) if obj is not None else None
        if result is None or cl is None or not 0 <= cl < result.shape[0]:
            return
        self.plot(result, cl)
        forces = _forces(obj)
        if forces is not None:
            self.plot_forces(forces, cl)

    def plot(self, result, cl):
        """Length of cut, cut area, h (the same at every CL point) over φ at `cl`, and the pass progression
        with `cl` marked. The four axes are made once per results (laid out then, and when the dock is resized) and
        only their curves are drawn anew for another CL point: clearing and laying out axes is most of
        a redraw's cost."""
        from ..report.colours import SURFACE_COLOURS

        axes, new = _reused_axes(self.figure, PLOTS)
        phi = result.phi
        labels = (translate("length of\ncut (mm)"), translate("cut area\n(mm²)"), translate("h (mm)"))  # two lines
        for ax, values, label in zip(axes[:3], (result.length[cl], result.area[cl], result.h[cl]), labels):
            ax.plot(phi, np.where(result.engaged[cl], values, np.nan), color="0.6", linewidth=1.0)
            for index, segment in enumerate(result.segments(cl)):
                rows = result.segment[cl] == index
                ax.plot(phi[rows], values[rows], ".-", markersize=2, color=SURFACE_COLOURS[segment["surface"]],
                        label=f"{segment['letter']} {surface_words(segment['surface'])}")
            ax.set_ylabel(label, fontsize="small")
            ax.set_xlim(phi[0], phi[-1] if len(phi) > 1 else phi[0] + 1.0)
            ax.relim()
            ax.autoscale_view(scalex=False)
        axes[0].set_title(translate("CL {cl} over the tool rotation angle φ", cl=cl), fontsize="small")
        if result.segments(cl):  # room above the curves for the legend
            axes[0].set_ylim(0.0, LEGEND_HEADROOM * max(float(np.nanmax(result.length[cl])), 1e-9))
            axes[0].legend(fontsize="x-small", ncol=3, loc="upper center", title=translate("segment: UEP surface"),
                           title_fontsize="x-small")
        axes[2].set_xlabel(translate("φ (deg)"), fontsize="small")
        index = np.arange(result.shape[0])
        depth, longest = result.depth_of_cut, result.length.max(axis=1)
        axes[3].plot(index, depth, ".-", color="black", label=translate("depth of cut"))
        axes[3].plot(index, longest, ".-", color="tab:green", label=translate("max length of cut"))
        axes[3].axvline(cl, color=_hex(HIGHLIGHT_COLOUR), linewidth=2.0)
        for values in (depth, longest):
            if np.isfinite(values[cl]):
                axes[3].plot([cl], [values[cl]], "o", color="red")
        axes[3].relim()
        axes[3].autoscale_view()
        axes[3].set_xlabel(translate("CL point"), fontsize="small")
        axes[3].set_ylabel(translate("mm"), fontsize="small")
        axes[3].set_title(translate("Pass progression"), fontsize="small")
        axes[3].legend(fontsize="x-small")
        if new:
            _lay_out(self.figure)
        self.canvas.draw_idle()

    def plot_forces(self, forces, cl):
        """F_x, F_y, F_z, |F| over φ at `cl` (N), and the peak and mean resultant along the pass with `cl` marked."""
        from ..report.forces import draw_force_along, draw_force_over_phi

        figure = self.force_figure
        figure.clear()
        over_phi, along = figure.subplots(2, 1, height_ratios=(3, 2))
        draw_force_over_phi(over_phi, forces, cl)
        over_phi.set_xlabel(translate("φ (deg)"), fontsize="small")
        over_phi.set_ylabel(translate("force (N)"), fontsize="small")
        over_phi.set_title(translate("CL {cl}: peak |F| {peak} N, mean {mean} N", cl=cl, peak=f"{forces.peak[cl]:.4g}",
                                     mean=f"{forces.mean[cl]:.4g}"), fontsize="small")
        top = max(float(np.abs(forces.xyz[cl]).max()), float(forces.resultant[cl].max()), 1e-9)
        over_phi.set_ylim(-1.1 * top if (forces.xyz[cl] < 0).any() else 0.0, 1.6 * top)  # room for the legend
        over_phi.legend(fontsize="x-small", ncol=4, loc="upper center")
        draw_force_along(along, forces, [])
        along.axvline(cl, color=_hex(HIGHLIGHT_COLOUR), linewidth=2.0)
        along.plot([cl, cl], [forces.peak[cl], forces.mean[cl]], "o", color="red")
        for line in along.lines:  # the report's curve labels, in the user's language
            line.set_label(translate(line.get_label()) if line.get_label() in FORCE_CURVES else line.get_label())
        along.set_xlabel(translate("CL point"), fontsize="small")
        along.set_ylabel(translate("force (N)"), fontsize="small")
        along.set_title(translate("Resultant force along the pass"), fontsize="small")
        along.legend(fontsize="x-small", loc="lower right")
        for ax in (over_phi, along):
            ax.tick_params(labelsize="x-small")
        self.force_canvas.draw_idle()

    def show_legend(self):
        """The legend of the colours shown (the view provider's)."""
        legend = getattr(self.obj.ViewObject.Proxy, "legend", None)
        if legend is None:
            self.legend.setText("")
            self.legend.setPixmap(QtGui.QPixmap())
            return
        if legend.kind == "segment":
            rows = "".join(f"<tr><td style='background:{_hex(rgb)}'>&nbsp;&nbsp;&nbsp;&nbsp;</td>"
                           f"<td>&nbsp;{surface_words(name)}</td></tr>" for name, rgb in legend.entries)
            self.legend.setText(translate("UEP surface of the engagement segment:") + f"<table>{rows}</table>")
            return
        self.legend.setPixmap(colour_bar(legend))

    def _colour_by_changed(self, index):
        obj = self.obj
        if obj is None:
            return
        obj.ViewObject.ColourBy = COLOUR_BY[index]  # onChanged recolours
        self.show_legend()


def _reused_axes(figure, count):
    """(the `count` stacked axes of `figure`, emptied of their curves and legends; whether they were
    made now, the figure not holding them yet: then lay them out once filled, :func:`_lay_out`)."""
    if len(figure.axes) != count:
        figure.clear()
        axes = figure.subplots(count, 1)
        for ax in axes:
            ax.grid(True, alpha=0.3)
            ax.tick_params(labelsize="x-small")
        for ax in axes[:2]:  # the plots over φ share its axis, its numbers under the lowest only: room for the curves
            ax.sharex(axes[2])
            ax.tick_params(labelbottom=False)
        return list(axes), True
    for ax in figure.axes:
        for artist in [*ax.lines, *([ax.get_legend()] if ax.get_legend() else [])]:
            artist.remove()
        ax.set_ylim(auto=True)
    return list(figure.axes), False


def _lay_out(figure):
    """Place the axes of `figure` once by matplotlib's constrained layout, for its size and texts now;
    later draws keep the places (finding them is most of a draw's cost)."""
    figure.set_layout_engine("constrained")
    figure.canvas.draw()
    figure.set_layout_engine("none")


def surface_words(kind):
    """The UEP surface `kind` ("curved_wall") in the user's words ("curved wall", :data:`SURFACE_WORDS`)."""
    return translate(kind.replace("_", " "))


def stock_model_words(obj):
    """The stock the engagement `obj` was computed against, in plain words (with how many CL points
    earlier moves changed, against the in-process stock)."""
    used = getattr(obj, "StockModelUsed", "initial")
    if used == "in-process":
        return translate("in-process stock: {count} CL points changed by earlier moves of the program",
                         count=obj.ChangedCLPoints)
    return translate("stock as given") + used[len('initial'):]


def in_process_words(obj, result, cl):
    """Whether earlier moves of the program changed CL point `cl` of the engagement `obj` (its Engagement
    `result`), as '; changed by earlier moves: …' with the longest length of cut against the in-process
    and the initial stock; '' when it was computed against the stock as given."""
    in_process = obj.Proxy.in_process(obj)
    if in_process is None:
        return ""
    if not in_process.changed[cl]:
        return "; " + translate("not changed by earlier moves")
    return "; " + translate("changed by earlier moves: longest length of cut in-process {now} mm / initial {before} "
                            "mm", now=f"{result.length[cl].max():.2f}", before=f"{in_process.initial[cl].max():.2f}")


def colour_bar(legend):
    """A QPixmap of the colour bar of a quantity Legend, with its minimum, maximum and unit."""
    from matplotlib import colormaps

    height, text = 16, 18
    pixmap = QtGui.QPixmap(BAR_WIDTH + 2, height + text + 4)
    pixmap.fill(QtGui.QColor("white"))
    painter = QtGui.QPainter(pixmap)
    colours = colormaps[legend.colour_map](np.linspace(0.0, 1.0, BAR_WIDTH))
    for x, rgba in enumerate(colours):
        painter.setPen(QtGui.QColor.fromRgbF(*rgba[:3]))
        painter.drawLine(x + 1, 1, x + 1, height)
    painter.setPen(QtGui.QColor("black"))
    painter.drawRect(0, 0, BAR_WIDTH + 1, height + 1)
    painter.drawText(QtCore.QRect(0, height + 3, BAR_WIDTH, text), QtCore.Qt.AlignLeft, f"{legend.low:.3g}")
    painter.drawText(QtCore.QRect(0, height + 3, BAR_WIDTH, text), QtCore.Qt.AlignCenter,
                     f"{translate(legend.label)} ({legend.unit})")
    painter.drawText(QtCore.QRect(0, height + 3, BAR_WIDTH, text), QtCore.Qt.AlignRight, f"{legend.high:.3g}")
    painter.end()
    return pixmap


def _hex(rgb):
    return "#" + "".join(f"{int(round(255 * v)):02x}" for v in rgb[:3])


def _alive(obj):
    """True while the document object `obj` exists (not deleted, its document not closed)."""
    try:
        return obj is not None and obj.Document.getObject(obj.Name) is not None
    except Exception:  # noqa: BLE001 (FreeCAD refuses any access to a deleted object)
        return False


def _result(obj):
    return obj.Proxy.result(obj) if _alive(obj) else None


def _forces(obj):
    """The engagement's PassForces, or None (forces off, no results, or gone)."""
    return obj.Proxy.forces(obj) if _alive(obj) else None


def _deepest(result):
    depth = result.depth_of_cut
    return int(np.nanargmax(depth)) if np.isfinite(depth).any() else 0


def _highlight(obj, cl):
    provider = getattr(obj.ViewObject, "Proxy", None) if _alive(obj) else None
    if hasattr(provider, "highlight"):
        provider.highlight(cl)


def find():
    """The dock, or None when it was never opened."""
    return FreeCADGui.getMainWindow().findChild(QtGui.QDockWidget, OBJECT_NAME)


def show(obj, cl=None):
    """Open (or reuse) the dock on the right of the main window, showing engagement `obj`; the dock."""
    window = FreeCADGui.getMainWindow()
    dock = find()
    if dock is None:
        dock = EngagementDock(window)
        window.addDockWidget(QtCore.Qt.RightDockWidgetArea, dock)
    dock.show_object(obj, cl)
    dock.show()
    dock.raise_()
    return dock


def refresh(obj):
    """Redraw the dock if it shows `obj` (after its recompute)."""
    if not FreeCAD.GuiUp:
        return
    dock = find()
    if dock is not None and dock.obj is obj:
        dock.refresh()


def forget(doc):
    """Empty the dock if it shows an object of `doc` (being closed)."""
    dock = find() if FreeCAD.GuiUp else None
    if dock is not None and _alive(dock.obj) and dock.obj.Document.Name == doc.Name:
        dock.obj = None
        dock.refresh()


def forget_gone():
    """Empty the dock if the engagement it shows was deleted (or taken back by undo)."""
    dock = find() if FreeCAD.GuiUp else None
    if dock is not None and dock.obj is not None and not _alive(dock.obj):
        dock.obj = None
        dock.refresh()


state.listen("show", show)
state.listen("gone", forget_gone)
state.listen("refresh", refresh)
state.listen("forget", forget)
