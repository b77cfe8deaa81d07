"""The in-process stock in the 3D view, following the engagement dock's chosen CL point.

:func:`show_at` makes (or reuses) the in-process stock object of an engagement
(:mod:`abm_workbench.features.inprocess_stock`), sets it to a CL point and recomputes it, saying
"computing" in the status bar and on the object's label while the booleans run; the engagement's
stock is hidden so the cut stock shows. The booleans run in a worker process (``gui.worker.in_process``):
the GUI stays drawn, a progress dialog (``ABM_Engine``) shows the hull solids built, the fuse and the cut,
and its Cancel kills the process at once; the object then stays as it was (a new one is removed). While
that object exists, choosing another CL point in the dock recomputes it once the slider has rested for
:data:`SETTLE_MS` (:class:`Follower`), so dragging the slider does not run the booleans at every step
(nor while they run); its FollowDock off, only the command moves it (the booleans can take minutes near
a dense five-axis program).
"""

from PySide import QtCore

import FreeCADGui

from . import dock, view_providers
from .i18n import noop, translate
from .reporting import CommandError, recompute_checked, report_error
from .worker import CANCELLED

#: Milliseconds the dock's CL point must stay unchanged before the stock is recomputed.
SETTLE_MS = 400
#: Label of the in-process stock object, with its CL point (translated where it is set).
LABEL = noop("In-process stock at CL {cl}")
#: Its label while its booleans run.
LABEL_COMPUTING = noop("In-process stock (computing CL {cl}…)")
#: Colour of the in-process stock (RGB 0..1): the stock's grey would hide the cuts.
COLOUR = (0.85, 0.65, 0.35)
#: True while show_at recomputes (the GUI's event loop runs meanwhile: the Follower waits for it).
computing = False


def stock_of(engagement):
    """The in-process stock object of `engagement` in its document, or None."""
    for obj in engagement.Document.Objects:
        if getattr(getattr(obj, "Proxy", None), "KIND", None) == "ABM::InProcessStock" and obj.Engagement == engagement:
            return obj
    return None


def show_at(engagement, cl):
    """Make or reuse the in-process stock object of `engagement`, at CL point `cl`, recomputed; the object.

    CommandError when the engagement has no results or the booleans fail.
    """
    from ..features.inprocess_stock import create_inprocess_stock

    if engagement.Proxy.result(engagement) is None:
        raise CommandError(translate("{label}: compute it first (recompute the document)", label=engagement.Label))
    global computing
    doc = engagement.Document
    obj = stock_of(engagement)
    new = obj is None
    if new:
        obj = create_inprocess_stock(doc, engagement, cl)
        view_providers.ViewProvider(obj.ViewObject)  # a Python feature without a view proxy is not drawn
        obj.ViewObject.ShapeColor = COLOUR
    before = obj.CLPoint
    obj.CLPoint = int(cl)
    obj.Label = translate(LABEL_COMPUTING, cl=cl)
    status = FreeCADGui.getMainWindow().statusBar()
    status.showMessage(translate("Computing the in-process stock of {label} at CL {cl}…", label=engagement.Label, cl=cl))
    computing, removed = True, False
    try:
        recompute_checked(doc, (obj,))
    except CommandError:
        if CANCELLED not in obj.getStatusString():
            raise
        removed = _cancelled(obj, new, before)
        status.showMessage(translate("In-process stock at CL {cl}: cancelled", cl=cl), 10000)
        return None
    finally:
        computing = False
        if not removed:
            obj.Label = translate(LABEL, cl=obj.CLPoint)
    if engagement.Stock is not None and engagement.Stock.ViewObject is not None:
        engagement.Stock.ViewObject.Visibility = False
    obj.ViewObject.Visibility = True
    status.showMessage(translate("In-process stock at CL {cl} (program row {row}): {volume} mm³ removed by earlier moves "
                                 "near it, in {seconds} s", cl=obj.CLPoint, row=obj.ProgramRow,
                                 volume=f"{obj.RemovedVolume:.1f}", seconds=f"{obj.ComputeTime:.1f}"), 10000)
    return obj


def _cancelled(obj, new, before):
    """After Cancel: a new in-process stock object removed, an earlier one back at CL point `before` with the
    shape it had (the proxy keeps it: its recompute runs no booleans); True when the object was removed."""
    if new:
        obj.Document.removeObject(obj.Name)
        return True
    obj.CLPoint = before
    if obj.recompute():
        obj.purgeTouched()
    return False


class Follower(QtCore.QObject):
    """Recomputes the in-process stock of the dock's engagement when its chosen CL point has rested."""

    def __init__(self, shown):
        super().__init__(shown)
        self.dock = shown
        self.timer = QtCore.QTimer(self)
        self.timer.setSingleShot(True)
        self.timer.setInterval(SETTLE_MS)
        self.timer.timeout.connect(self.update)
        shown.spin.valueChanged.connect(self.timer.start)

    def update(self):
        """The in-process stock at the dock's CL point, if the dock's engagement has one and it is elsewhere."""
        engagement = self.dock.obj
        try:
            if dock._result(engagement) is None:
                return
            obj = stock_of(engagement)
            cl = self.dock.spin.value()
            if computing:  # the booleans of an earlier CL point still run: look again once they are done
                self.timer.start()
                return
            if obj is not None and obj.FollowDock and (obj.CLPoint != cl or "Touched" in obj.State):
                show_at(engagement, cl)
        except Exception as error:  # noqa: BLE001 (reported; the GUI goes on)
            report_error(error)


def follow(shown):
    """Make the dock `shown` update the in-process stock as its CL point changes (once per dock)."""
    if getattr(shown, "in_process_follower", None) is None:
        shown.in_process_follower = Follower(shown)


def show_for_dock():
    """The in-process stock at the dock's engagement and chosen CL point; CommandError without a dock."""
    shown = dock.find()
    if shown is None or dock._result(shown.obj) is None:
        raise CommandError(translate("Show in-process stock: inspect an engagement first (Inspect engagement), then "
                                     "choose its CL point in the dock"))
    follow(shown)
    return show_at(shown.obj, shown.spin.value())
