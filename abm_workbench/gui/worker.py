"""Long work off the GUI thread: a worker thread, progress and Cancel.

FreeCAD's document is not thread-safe, so recomputes and everything that touches document objects
stay on the GUI thread; the long pure calls they make run in a worker thread (:func:`work`), while
the GUI thread waits in an event loop of its own and stays drawn:

- the engagement's engine calls (``features.engagement.engine_call``: flute 1's engagement, the
  in-process engine and the forces);
- reading and recognising a stock (``features.stock.recognise_call``);
- the in-process stock's OpenCASCADE booleans (``features.inprocess_stock.boolean_call``), not in a thread
  (there they crashed FreeCAD) but in a worker **process** of their own (:func:`in_process`): the stock
  goes to it as a binary BREP file, the swept pieces near the CL point as numpy arrays, the cut stock
  comes back as a BREP file read on the GUI thread; Cancel kills the process;
- validation (``gui.validate``: the engine and the boolean reference, the report written);
- reading a toolpath file to ask which operation to compute (``gui.commands``).

For the first SILENT_MS the wait shows only a wait cursor and holds user input back (Qt delivers
it afterwards); a longer one shows a modal progress dialog (``ABM_Engine``; validation its own
``ABM_Progress``) with the steps done of all, from the call's own ``progress(done, total)`` when it
takes one, and **Cancel**. Cancel ends the wait at once (within POLL_MS): the call is asked to stop
(its next ``progress`` raises in the worker; worker processes it waits for, validation's, are killed
within ``worker_processes.STOP_POLL`` seconds, not after their current CL point:
``worker_processes.stop_when``), its result is thrown away whenever it ends, and the caller gets
:class:`Cancelled` (an InputError: a recompute fails with ``recompute cancelled: nothing computed``).
A call without steps (the forces, one boolean) cannot stop half-way: it ends on its own in the
background, its result unused; a call that ends within GRACE_MS of Cancel is waited for, so what it
started (validation's worker processes) is ended before the caller goes on.

:func:`install` puts :func:`run` in place of the plain calls (InitGui does it through
``view_providers.install_observer``).
"""

import inspect
import threading
import time

from PySide import QtCore, QtGui

from .cancel import Cancelled  # also worker.Cancelled, as callers name it
from .i18n import noop

#: Milliseconds a wait stays silent (wait cursor, user input held back) before the progress dialog shows.
SILENT_MS = 400
#: Milliseconds between two looks at the worker's progress.
POLL_MS = 50
#: Milliseconds a cancelled call is waited for (the GUI drawn) before it is left to end in the background.
GRACE_MS = 3000
#: The engine's words (the default of :func:`work`).
ENGINE_TEXT = noop("Computing the engagement…")
#: The line under the dialog's words once steps are done: the engine's steps are CL points.
ENGINE_STEPS = noop("{done} of {total} CL points, about {left} left")
#: The in-process stock's boolean steps: each swept solid, their fuse, the cut.
BOOLEAN_STEPS = noop("{done} of {total} steps, about {left} left")
CANCELLED = "recompute cancelled: nothing computed"
#: Worker threads given up by Cancel that still run (kept alive until they end).
_ABANDONED = set()


def install():
    """Run the engagements' engine calls and the stocks' recognition in worker threads, the in-process
    stock's booleans in a worker process."""
    from ..features import engagement, inprocess_stock, stock

    engagement.engine_call = run
    stock.recognise_call = lambda function, *args, **keywords: work(
        function, *args, text=noop("Reading and recognising the stock…"), **keywords)
    inprocess_stock.boolean_call = lambda function, *args: in_process(
        function, *args, text=noop("Computing the in-process stock…"))


def run(function, *args):
    """The engine's function(*args) in a worker thread (:func:`work` with the engine's words)."""
    return work(function, *args)


def work(function, *args, text=ENGINE_TEXT, cancelled=CANCELLED, sink=None, steps=ENGINE_STEPS, **keywords):
    """function(*args, **keywords) in a worker thread, the GUI kept drawn meanwhile (see the module
    docstring); its value, or its exception raised here; when the user cancels, `cancelled` if it is an
    exception, else Cancelled(`cancelled`).

    text: the progress dialog's words (translated); steps: the line under them (:func:`steps_left`).
    sink: a progress(done, total) callback of the GUI thread with a ``dialog`` (QProgressDialog) it shows
    at once (gui.progress.ProgressDialog): it gets every step of the call, in order, and raising from it
    cancels; None: the worker's own dialog after SILENT_MS.
    """
    if QtGui.QApplication.instance() is None or threading.current_thread() is not threading.main_thread():
        return function(*args, **keywords)  # no GUI, or not its thread: nothing to keep drawn
    job = _Job(function, args, keywords, cancelled)
    return _wait(job, _Thread(job), (text, steps), sink)


def in_process(function, *args, text=ENGINE_TEXT, cancelled=CANCELLED, steps=BOOLEAN_STEPS):
    """function(*args) in a worker process of its own (``worker_processes.ChildTask``), waited for as
    :func:`work` waits for a thread: the GUI drawn, the progress dialog after SILENT_MS with the steps
    of the call's own progress(done, total), Cancel killing the process at once. function: module-level;
    args: Part.Shape (passed as binary BREP files) and picklable values; a Part.Shape value (or in a
    tuple value) is read back here. Without a GUI, or off its thread, a plain call."""
    if QtGui.QApplication.instance() is None or threading.current_thread() is not threading.main_thread():
        return function(*args)
    job = _ProcessJob(function, args, cancelled)
    try:
        return _wait(job, _Process(job), (text, steps), None)
    finally:
        job.close()


def _wait(job, thread, words, sink):
    """Start `thread` (a _Thread or _Process running `job`) and wait for it as :func:`work` says (`words`:
    its text and steps); the job's outcome."""
    loop = QtCore.QEventLoop()
    thread.finished.connect(loop.quit)
    thread.start()
    if sink is None:
        silent = QtCore.QTimer()
        silent.setSingleShot(True)
        silent.timeout.connect(loop.quit)
        silent.start(SILENT_MS)
        QtGui.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)
        try:
            loop.exec_(QtCore.QEventLoop.ExcludeUserInputEvents)
        finally:
            QtGui.QApplication.restoreOverrideCursor()
        silent.stop()
        if thread.isRunning():
            _wait_with_dialog(job, thread, loop, *words)
    else:
        _wait_with_sink(job, thread, loop, sink)
    if thread.isRunning() and job.cancel.is_set():  # give it a moment to stop and clean up
        grace = QtCore.QTimer()
        grace.setSingleShot(True)
        grace.timeout.connect(loop.quit)
        grace.start(GRACE_MS)
        loop.exec_(QtCore.QEventLoop.ExcludeUserInputEvents)
        grace.stop()
    if thread.isRunning():  # cancelled during a call without steps: let it end on its own
        _ABANDONED.add(thread)
        thread.finished.connect(lambda: _ABANDONED.discard(thread))
    return job.outcome()


def _wait_with_dialog(job, thread, loop, text, steps):
    """Wait for `thread` in `loop` with the progress dialog (`text`, and `steps` under it once steps are
    done: :func:`steps_left`); Cancel asks `job` to stop and ends the wait."""
    import FreeCADGui

    from .i18n import translate

    dialog = QtGui.QProgressDialog(translate(text), translate("Cancel"), 0, 0, FreeCADGui.getMainWindow())
    dialog.setObjectName("ABM_Engine")
    dialog.setWindowTitle("ABM")
    dialog.setWindowModality(QtCore.Qt.ApplicationModal)
    dialog.setMinimumDuration(0)
    dialog.setAutoClose(False)
    dialog.setAutoReset(False)
    timer = QtCore.QTimer()
    started = time.perf_counter()

    def look():
        done, total = job.done
        if total:
            dialog.setMaximum(total)
            dialog.setValue(done)
            line = steps_left(steps, done, total, time.perf_counter() - started)
            dialog.setLabelText(f"{translate(text)}\n{line}" if line else translate(text))

    def cancel():
        job.stop()
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


def steps_left(steps, done, total, elapsed):
    """The progress dialog's line under its text: `steps` (a text with {done}, {total} and {left}) in the
    user's language with `done` of `total` steps and the time left estimated from `elapsed` (s) at the
    pace so far; empty before the first step."""
    from .i18n import translate

    if done <= 0:
        return ""
    minutes, seconds = divmod(round(elapsed / done * (total - done)), 60)
    left = (translate("{minutes} min {seconds} s", minutes=minutes, seconds=seconds) if minutes
            else translate("{seconds} s", seconds=seconds))
    return translate(steps, done=f"{done:,}", total=f"{total:,}", left=left)


def _wait_with_sink(job, thread, loop, sink):
    """Wait for `thread` in `loop`, handing each step of `job` to `sink` on this thread; Cancel on its
    dialog, or `sink` raising, stops `job` and ends the wait."""
    timer = QtCore.QTimer()

    def cancel():
        job.stop()
        loop.quit()

    def look():
        for done, total in job.take_steps():
            try:
                sink(done, total)
            except Exception as error:  # noqa: BLE001 (the sink's way to cancel, e.g. validate.Cancelled)
                job.stop(error)
                loop.quit()
                return

    timer.timeout.connect(look)
    dialog = getattr(sink, "dialog", None)
    if dialog is not None:
        dialog.canceled.connect(cancel)
    timer.start(POLL_MS)
    loop.exec_()
    timer.stop()
    if not job.cancel.is_set():
        look()  # the steps of the last moments


class _Job:
    """function(*args, **keywords) run once, with the progress callback when it takes one."""

    def __init__(self, function, args, keywords, cancelled):
        self.function, self.args, self.keywords, self.cancelled = function, args, keywords, cancelled
        self.done = (0, 0)  # (steps done, all), written by the worker
        self.steps = []  # every (done, all) not yet handed to a sink
        self.lock = threading.Lock()
        self.cancel = threading.Event()
        self.reason = None  # the exception a sink cancelled with
        self.value, self.error = None, None
        self.seconds = None

    def stop(self, reason=None):
        if not self.cancel.is_set():
            self.reason = reason
            self.cancel.set()

    def progress(self, done, total):
        self.done = (done, total)
        with self.lock:
            self.steps.append((done, total))
        if self.cancel.is_set():
            raise self.cancelled_error()

    def cancelled_error(self):
        """The exception a cancelled call ends with: `cancelled` itself when it is one, else Cancelled(it)."""
        return self.cancelled if isinstance(self.cancelled, BaseException) else Cancelled(self.cancelled)

    def take_steps(self):
        with self.lock:
            steps, self.steps = self.steps, []
        return steps

    def _takes_progress(self):
        if "progress" in self.keywords:
            return False
        try:
            return "progress" in inspect.signature(self.function).parameters
        except (TypeError, ValueError):
            return False

    def __call__(self):
        from ..worker_processes import stop_when

        started = time.perf_counter()
        try:
            with stop_when(self.cancel):  # Cancel ends the worker processes the call waits for at once
                self._call()
        except BaseException as error:  # noqa: BLE001 (handed to the GUI thread, raised there)
            self.error = error
        self.seconds = time.perf_counter() - started

    def _call(self):
        if self._takes_progress():
            self.value = self.function(*self.args, progress=self.progress, **self.keywords)
        else:
            self.value = self.function(*self.args, **self.keywords)

    def outcome(self):
        """The value; the worker's exception; Cancelled (or the sink's reason) once cancelled."""
        if self.cancel.is_set():
            if self.reason is not None:
                raise self.reason
            raise self.cancelled_error()
        if self.error is not None:
            raise self.error
        return self.value


#: The worker threads' name (threading.Thread.name).
THREAD_NAME = "abm-worker"
#: Milliseconds between two looks, from the GUI thread, at whether a worker thread has ended.
THREAD_POLL_MS = 10


class _Thread(QtCore.QObject):
    """A _Job in a Python thread (threading.Thread, named THREAD_NAME), with what :func:`_wait` uses of a
    QThread: start, isRunning and the finished signal, emitted on the GUI thread by a timer that looks
    every THREAD_POLL_MS whether the thread has ended.

    Not a QThread: Qt calls a QThread's metaObject() from the new thread itself, as it starts (to name the
    thread) and as it ends (to queue its finished signal to the GUI thread), and PySide2 (5.15) answers
    that by looking the Python object up in its table of wrappers without holding the GIL, while the GUI
    thread may be changing that table: FreeCAD crashed there (SIGSEGV in BindingManager::retrieveWrapper
    under QThreadPrivate::start). The Python thread touches no Qt object, nor do the jobs (numpy,
    OpenCASCADE, files; the report's figures drawn with matplotlib's Agg canvas).
    """

    finished = QtCore.Signal()

    def __init__(self, job):
        super().__init__()
        self.job = job
        self.thread = threading.Thread(target=job, name=THREAD_NAME, daemon=True)
        self.timer = QtCore.QTimer(self)
        self.timer.setInterval(THREAD_POLL_MS)
        self.timer.timeout.connect(self._look)

    def start(self):
        self.thread.start()
        self.timer.start()

    def isRunning(self):  # noqa: N802 (QThread's name)
        return self.thread.is_alive()

    def _look(self):
        if not self.thread.is_alive():
            self.timer.stop()
            self.finished.emit()


class _ProcessJob(_Job):
    """function(*args) in a worker process: _Job's steps, Cancel and outcome, the call's inputs written
    into a folder of its own (worker_processes.write_arguments), its Part.Shape value read back."""

    def __init__(self, function, args, cancelled):
        import shutil
        import tempfile

        from .. import worker_processes

        super().__init__(function, args, {}, cancelled)
        self.folder = tempfile.mkdtemp(prefix="abm-worker-")
        self.running = False
        try:
            worker_processes.write_arguments(self.folder, args)
        except BaseException:
            shutil.rmtree(self.folder, ignore_errors=True)
            raise
        self.task = worker_processes.ChildTask(worker_processes.call_with_shapes, (function, self.folder))

    def start(self):
        self.running = True
        self.started = time.perf_counter()
        try:
            self.task.start()
        except BaseException as error:  # noqa: BLE001 (handed to the caller by outcome)
            self.error, self.running = error, False

    def look(self):
        """Take what the process said; True once it has ended."""
        for message in self.task.messages():
            if message[0] == "progress":
                self.done = message[1:]
                with self.lock:
                    self.steps.append(self.done)
            elif message[0] == "value":
                self.value = message[1]
            else:
                self.error = message[1]
        if self.task.ended:
            self.running = False
            self.seconds = time.perf_counter() - self.started
        return not self.running

    def stop(self, reason=None):
        super().stop(reason)
        self.task.stop(wait=False)
        self.running = False

    def outcome(self):
        from ..worker_processes import shapes_read

        return shapes_read(super().outcome())

    def close(self):
        """Kill the process if it still runs (reaped by a thread of its own); remove the folder."""
        import shutil

        self.task.stop(wait=False)
        shutil.rmtree(self.folder, ignore_errors=True)


class _Process(QtCore.QObject):
    """A _ProcessJob looked at every POLL_MS by a timer of the GUI thread, with what :func:`_wait` uses of a
    QThread: start, isRunning and the finished signal."""

    finished = QtCore.Signal()

    def __init__(self, job):
        super().__init__()
        self.job = job
        self.timer = QtCore.QTimer(self)
        self.timer.setInterval(POLL_MS // 2)
        self.timer.timeout.connect(self._look)

    def start(self):
        self.job.start()
        if self.job.running:
            self.timer.start()
        else:
            QtCore.QTimer.singleShot(0, self.finished.emit)

    def isRunning(self):  # noqa: N802 (QThread's name)
        return self.job.running

    def _look(self):
        if self.job.look():
            self.timer.stop()
            self.finished.emit()
