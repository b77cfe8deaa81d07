"""The engine off the GUI thread during a recompute: a worker thread, progress and Cancel.

FreeCAD's document is not thread-safe, so an engagement's recompute stays on the GUI thread;
only its pure-numpy engine calls (``features.engagement.engine_call``: flute 1's engagement
and the forces) run in a worker thread (:func:`run`), while the GUI thread waits in an event
loop of its own and stays drawn. For the first SILENT_MS the wait shows only a wait cursor and
holds user input back (Qt delivers it afterwards); a longer one shows the modal progress
dialog ``ABM_Engine`` (CL points done of all, from the engine's own ``progress(done, total)``
after each chunk of CL points) with Cancel. Cancel stops the engine at its next chunk (the
callback raises in the worker) and fails the recompute with :class:`Cancelled`, an
InputError: the task panel says so and stays open, its Cancel then goes back as after any
failed OK. An engine call without steps (the forces) cannot stop half-way: Cancel stops the
wait at once and the call's result is thrown away when it ends.

:func:`install` puts :func:`run` in place of the plain call (InitGui does it through
``view_providers.install_observer``).
"""

import inspect
import threading

from PySide import QtCore, QtGui

from ..errors import InputError

#: Milliseconds a wait stays silent (wait cursor, user input held back) before the progress dialog shows.
SILENT_MS = 400
#: Milliseconds between two looks at the worker's progress.
POLL_MS = 50
#: Worker threads given up by Cancel that still run (kept alive until they end).
_ABANDONED = set()


class Cancelled(InputError):
    """The engine was stopped by Cancel: the recompute made nothing."""


def install():
    """Run the engagements' engine calls through :func:`run` (the GUI's worker thread)."""
    from ..features import engagement

    engagement.engine_call = run


def run(function, *args):
    """function(*args) in a worker thread, the GUI kept drawn meanwhile (see the module docstring);
    its value, or its exception raised here; Cancelled when the user cancels."""
    if QtGui.QApplication.instance() is None or threading.current_thread() is not threading.main_thread():
        return function(*args)  # no GUI, or not its thread: nothing to keep drawn
    job = _Job(function, args)
    thread, loop, silent = _Thread(job), QtCore.QEventLoop(), QtCore.QTimer()
    thread.finished.connect(loop.quit)
    silent.setSingleShot(True)
    silent.timeout.connect(loop.quit)
    thread.start()
    silent.start(SILENT_MS)
    loop.exec_(QtCore.QEventLoop.ExcludeUserInputEvents)
    silent.stop()
    if thread.isRunning():
        _wait_with_dialog(job, thread, loop)
    if thread.isRunning():  # cancelled during a call without steps: let it end on its own
        _ABANDONED.add(thread)
        thread.finished.connect(lambda: _ABANDONED.discard(thread))
    return job.outcome()


def _wait_with_dialog(job, thread, loop):
    """Wait for `thread` in `loop` with the progress dialog; Cancel asks `job` to stop and ends the wait."""
    import FreeCADGui

    from .i18n import translate

    dialog = QtGui.QProgressDialog(translate("Computing the engagement…"), translate("Cancel"), 0, 0,
                                   FreeCADGui.getMainWindow())
    dialog.setObjectName("ABM_Engine")
    dialog.setWindowTitle("ABM")
    dialog.setWindowModality(QtCore.Qt.ApplicationModal)
    dialog.setMinimumDuration(0)
    dialog.setAutoClose(False)
    dialog.setAutoReset(False)
    timer = QtCore.QTimer()

    def look():
        done, total = job.done
        if total:
            dialog.setMaximum(total)
            dialog.setValue(done)

    def cancel():
        job.cancel.set()
        loop.quit()

    timer.timeout.connect(look)
    dialog.canceled.connect(cancel)
    timer.start(POLL_MS)
    dialog.show()
    loop.exec_()
    timer.stop()
    dialog.reset()
    dialog.setParent(None)
    dialog.deleteLater()


class _Job:
    """function(*args) run once, with the engine's progress callback when it takes one."""

    def __init__(self, function, args):
        self.function, self.args = function, args
        self.done = (0, 0)  # (CL points done, all), written by the worker
        self.cancel = threading.Event()
        self.value, self.error = None, None

    def progress(self, done, total):
        self.done = (done, total)
        if self.cancel.is_set():
            raise Cancelled("recompute cancelled: nothing computed")

    def __call__(self):
        try:
            steps = "progress" in inspect.signature(self.function).parameters
            self.value = self.function(*self.args, progress=self.progress) if steps else self.function(*self.args)
        except BaseException as error:  # noqa: BLE001 (handed to the GUI thread, raised there)
            self.error = error

    def outcome(self):
        """The value; the worker's exception; Cancelled once cancelled."""
        if self.cancel.is_set():
            raise Cancelled("recompute cancelled: nothing computed")
        if self.error is not None:
            raise self.error
        return self.value


class _Thread(QtCore.QThread):
    """A QThread running a _Job."""

    def __init__(self, job):
        super().__init__()
        self.job = job

    def run(self):
        self.job()
