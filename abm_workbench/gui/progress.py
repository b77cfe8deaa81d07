"""Progress in FreeCAD's GUI: a busy context for work without steps, a cancellable dialog for steps.

- :class:`busy`: a wait cursor and FreeCAD's own progress indicator (``Base.ProgressIndicator``,
  in the status bar) around work that cannot report steps (the engine's one vectorised call and
  the tessellation of the engaged surface).
- :class:`ProgressDialog`: a ``progress(done, total)`` callback as a modal ``QProgressDialog``
  with Cancel; Cancel raises :class:`~abm_workbench.gui.validate.Cancelled` at the next step,
  so the caller's atomic output (``report.staging.staged``) leaves nothing half-written.
"""

from PySide import QtCore, QtGui

import FreeCAD
import FreeCADGui


class busy:
    """Context: a wait cursor and FreeCAD's progress indicator (status bar) with `text`."""

    def __init__(self, text):
        self.text = text

    def __enter__(self):
        QtGui.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)
        self.progress = FreeCAD.Base.ProgressIndicator()
        self.progress.start(self.text, 0)
        QtGui.QApplication.processEvents()
        return self

    def __exit__(self, *exc):
        self.progress.stop()
        QtGui.QApplication.restoreOverrideCursor()
        return False


class ProgressDialog:
    """progress(done, total) as a modal QProgressDialog with Cancel; Cancel raises validate.Cancelled
    at the next CL point."""

    def __init__(self, text):
        from .i18n import translate

        self.dialog = QtGui.QProgressDialog(text, translate("Cancel"), 0, 1, FreeCADGui.getMainWindow())
        self.dialog.setObjectName("ABM_Progress")
        self.dialog.setWindowTitle("ABM")
        self.dialog.setWindowModality(QtCore.Qt.WindowModal)
        self.dialog.setMinimumDuration(0)
        self.dialog.setValue(0)
        QtGui.QApplication.processEvents()

    def __call__(self, done, total):
        from .i18n import translate
        from .validate import Cancelled

        self.dialog.setMaximum(total)
        self.dialog.setValue(done)
        QtGui.QApplication.processEvents()
        if self.dialog.wasCanceled():
            raise Cancelled(translate("validation cancelled: nothing written"))

    def close(self):
        """Hide the dialog and let it go (out of the main window at once: Qt deletes it later)."""
        self.dialog.reset()
        self.dialog.setParent(None)
        self.dialog.deleteLater()
