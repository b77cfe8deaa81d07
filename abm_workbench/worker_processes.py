"""Spawned worker processes that run tasks one at a time and are gone whenever the caller stops.

:class:`WorkerProcesses` starts `count` processes with the spawn method (a fresh interpreter each,
:func:`abm_workbench.cad.recognise.spawn_context`: FreeCAD's own Python even under the GUI), each
running ``initializer(*initargs)`` once and then the tasks it is sent, one at a time, over a pipe
of its own. :meth:`WorkerProcesses.map_unordered` hands the tasks out as workers become free and
yields (index, result) as they finish.

Leaving the ``with`` block ends every worker, whatever ended the block (the last result, an error,
KeyboardInterrupt, the command line's SIGTERM / SIGHUP, a progress callback that cancels):

- SIGINT, SIGTERM and SIGHUP are held back (``signal.pthread_sigmask``) while the workers are
  started and while they are stopped, so an interrupt arrives either before the first worker
  exists or after every started one is recorded, and never halfway through the clean-up: it is
  delivered when the block of held signals ends;
- the workers inherit that mask, so Ctrl-C on a terminal (sent to the whole process group) cannot
  stop a worker halfway through its start-up; each then ignores SIGINT and SIGHUP (the parent ends
  it) and lets SIGTERM end it as usual;
- on an error the workers are killed (SIGKILL: a boolean cannot be interrupted halfway, and a
  worker still starting has SIGTERM held) and reaped; after the last result they are told to end
  and given STOP_WAIT seconds before being killed;
- a thread that another thread must be able to stop at once (the GUI's Cancel) runs the block inside
  :func:`stop_when` (a threading.Event): waiting for answers, :meth:`WorkerProcesses.map_unordered` looks
  at the event every STOP_POLL seconds and raises :class:`Stopped` once it is set, so the workers are
  killed then, not after the next task ends;
- a worker holds only its own end of its pipe, so if the parent dies without any clean-up (SIGKILL)
  the worker reads the end of the pipe after its current task and ends too; on Linux it is killed at
  once (:func:`die_with_parent`: PR_SET_PDEATHSIG), even in the middle of a task.

:class:`ChildTask` is one task in one spawned process that the caller looks at without waiting (the
GUI's event loop polls it): its progress steps, then its value or error; :meth:`ChildTask.stop` kills it
at once. :func:`call_with_shapes` runs there a function of Part.Shape arguments and value, the shapes
passing through OpenCASCADE's binary BREP files (exact: the doubles as they are).
"""

import contextlib
import inspect
import multiprocessing.connection
import os
import pickle
import signal
import threading
from dataclasses import dataclass
from multiprocessing import resource_tracker

#: Signals held back while workers are started or stopped.
HELD = tuple(getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, name))
#: Seconds the workers get to end by themselves after the last task, before they are killed.
STOP_WAIT = 5.0
#: Seconds between two looks at the thread's stop event (stop_when) while waiting for the workers' answers.
STOP_POLL = 0.05

_stops = threading.local()  # .event: the stop event of stop_when's block in this thread (or none)


#: prctl's option that sends a signal when the parent ends (linux/prctl.h).
_PR_SET_PDEATHSIG = 1


def die_with_parent(parent):
    """In a worker process: be killed (SIGKILL) when the process that started it ends, however it ends
    (Linux's PR_SET_PDEATHSIG through ctypes; elsewhere nothing), and end now if `parent` (its pid) already
    has; SIGINT and SIGHUP ignored (Ctrl-C on a terminal reaches the whole process group: the parent ends
    the workers), SIGTERM left to end it; then the signals held while the parent started it
    (:func:`held_signals`) let through."""
    try:
        import ctypes

        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(_PR_SET_PDEATHSIG, int(signal.SIGKILL), 0, 0, 0)
    except (OSError, AttributeError, TypeError):
        pass
    for name, handler in (("SIGINT", signal.SIG_IGN), ("SIGHUP", signal.SIG_IGN), ("SIGTERM", signal.SIG_DFL)):
        if hasattr(signal, name):
            signal.signal(getattr(signal, name), handler)
    if os.getppid() != parent:
        os._exit(1)
    if hasattr(signal, "pthread_sigmask"):  # the signals held while the parent started it (held_signals)
        signal.pthread_sigmask(signal.SIG_UNBLOCK, HELD)


class WorkerError(RuntimeError):
    """A worker process ended without answering its task (it crashed or was killed)."""


class Stopped(Exception):
    """The stop event of :func:`stop_when` was set while workers computed: their tasks are given up."""


@contextlib.contextmanager
def stop_when(event):
    """Within the block, in this thread: :meth:`WorkerProcesses.map_unordered` looks at `event` (a
    threading.Event that another thread sets) at least every STOP_POLL seconds while it waits for answers,
    and raises :class:`Stopped` once it is set (leaving the ``with`` block of the workers then kills them).
    Blocks nest: the innermost event counts."""
    previous = getattr(_stops, "event", None)
    _stops.event = event
    try:
        yield
    finally:
        _stops.event = previous


@contextlib.contextmanager
def held_signals():
    """Hold back HELD signals during the block (this thread); a signal that came meanwhile is
    delivered, and its handler runs, when the block ends. Where the platform cannot, nothing is held."""
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, HELD)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)


class WorkerProcesses:
    """`count` spawned worker processes for the ``with`` block; see the module docstring.

    initializer: a module-level function run once in each worker with `initargs` (picklable); an
    error it raises is given back as the answer to every task of that worker.
    """

    def __init__(self, count, initializer, initargs=()):
        self.count, self.initializer, self.initargs = int(count), initializer, tuple(initargs)
        self.processes, self.connections = [], []

    def __enter__(self):
        from .cad.recognise import spawn_context

        context = spawn_context()
        resource_tracker.ensure_running()  # first: starting it lets SIGINT and SIGTERM through again
        with held_signals():
            try:
                for _ in range(self.count):
                    ours, theirs = context.Pipe()
                    process = context.Process(target=_serve, args=(theirs, self.initializer, self.initargs,
                                                                   os.getpid()), daemon=True)
                    self.connections.append(ours)
                    try:
                        process.start()
                    finally:
                        theirs.close()
                    self.processes.append(process)
            except BaseException:
                self._stop(clean=False)
                raise
        return self

    def __exit__(self, kind, error, trace):
        with held_signals():
            self._stop(clean=kind is None)
        return False

    def map_unordered(self, function, arguments):
        """Yield (index, function(*arguments[index])) for every index, run in the workers, in the order
        they finish. function: module-level (picklable), arguments: a sequence of tuples. An error raised
        by a task is raised here; a worker that ends without answering raises WorkerError; the stop event of
        :func:`stop_when`, once set, raises Stopped within STOP_POLL seconds."""
        waiting = list(range(len(arguments)))[::-1]
        busy = {}
        stop = getattr(_stops, "event", None)
        timeout = None if stop is None else STOP_POLL

        def hand_out(connection):
            if waiting:
                index = waiting.pop()
                connection.send((function, arguments[index]))
                busy[connection] = index

        for connection in self.connections:
            hand_out(connection)
        while busy:
            if stop is not None and stop.is_set():
                raise Stopped(f"stopped with {len(busy) + len(waiting)} of {len(arguments)} tasks unanswered")
            for connection in multiprocessing.connection.wait(list(busy), timeout=timeout):
                index = busy.pop(connection)
                try:
                    succeeded, value = connection.recv()
                except (EOFError, OSError):
                    process = self.processes[self.connections.index(connection)]
                    process.join(timeout=1.0)
                    raise WorkerError(f"a worker process ended without answering task {index} "
                                      f"(exit code {process.exitcode})") from None
                if not succeeded:
                    raise value
                hand_out(connection)
                yield index, value

    def _stop(self, clean):
        """End every worker started: asked to end first after a clean run, killed otherwise; all reaped."""
        if clean:
            for connection in self.connections:
                with contextlib.suppress(OSError):
                    connection.send(None)
            for process in self.processes:
                process.join(timeout=STOP_WAIT)
        for process in self.processes:
            if process.exitcode is None:
                process.kill()
        for process in self.processes:
            process.join()
        for connection in self.connections:
            connection.close()


def _serve(connection, initializer, initargs, parent):
    """A worker's life: SIGINT and SIGHUP ignored and killed with its parent (die_with_parent), the signals
    held back since the spawn let through, the initializer run, then tasks answered until None or the
    pipe's end."""
    die_with_parent(parent)
    failure = None
    try:
        initializer(*initargs)
    except Exception as error:
        failure = error
    while True:
        try:
            task = connection.recv()
        except EOFError:
            return
        if task is None:
            return
        function, arguments = task
        try:
            if failure is not None:
                raise failure
            answer = (True, function(*arguments))
        except Exception as error:
            answer = (False, error)
        try:
            connection.send(answer)
        except Exception as error:  # an answer that does not pickle: said in words
            connection.send((False, RuntimeError(f"{type(error).__name__}: {error}")))


class ChildTask:
    """function(*arguments) in one spawned process (with progress=, a callback, when it takes one), looked
    at without waiting: :meth:`messages` gives what it said since the last look. function: module-level,
    arguments: picklable and small (they pass through the spawn's pipe: put big data in files).

    The process ignores SIGINT and SIGHUP and, on Linux, is killed when its parent dies; :meth:`stop`
    kills it (SIGKILL: a boolean cannot be interrupted halfway) and reaps it.
    """

    def __init__(self, function, arguments=()):
        self.function, self.arguments = function, tuple(arguments)
        self.process = self.connection = None
        self.ended = False

    def start(self):
        from .cad.recognise import spawn_context

        context = spawn_context()
        resource_tracker.ensure_running()  # first: starting it lets SIGINT and SIGTERM through again
        with held_signals():
            ours, theirs = context.Pipe(duplex=False)
            self.connection = ours
            self.process = context.Process(target=_run_child,
                                           args=(theirs, os.getpid(), self.function, self.arguments), daemon=True)
            try:
                self.process.start()
            finally:
                theirs.close()
        return self

    def messages(self):
        """What the task said since the last look, without waiting: ("progress", done, total) steps, then
        ("value", value) or ("error", exception) once, as it ended (WorkerError when the process ended
        without answering)."""
        said = []
        if self.ended:
            return said
        try:
            while self.connection.poll():
                message = self.connection.recv()
                said.append(message)
                if message[0] != "progress":  # its last word (the process may still be ending: stop reaps it)
                    self.ended = True
                    break
        except (EOFError, OSError):
            self.process.join(timeout=1.0)
            self.ended = True
            said.append(("error", WorkerError(f"the worker process ended without answering "
                                              f"(exit code {self.process.exitcode})")))
        return said

    def stop(self, wait=True):
        """Kill the process if it still runs, and reap it (wait False: a thread of its own waits for it,
        so a caller that must not block, the GUI thread, does not wait for the kernel to free a big
        process's memory); close the pipe."""
        self.ended = True
        if self.process is None or self.connection.closed:
            return
        with held_signals():
            if self.process.exitcode is None:
                self.process.kill()
            self.connection.close()
        if wait:
            self.process.join()
        else:
            threading.Thread(target=self.process.join, name="abm-reaper", daemon=True).start()


def _run_child(connection, parent, function, arguments):
    """A ChildTask's process (started by the process `parent`, its pid): killed with its parent
    (:func:`die_with_parent`), its progress steps and then its value or error sent over `connection`."""
    die_with_parent(parent)

    def progress(done, total):
        connection.send(("progress", int(done), int(total)))

    try:
        takes = "progress" in inspect.signature(function).parameters
    except (TypeError, ValueError):
        takes = False
    try:
        answer = ("value", function(*arguments, progress=progress) if takes else function(*arguments))
    except Exception as error:
        answer = ("error", error)
    try:
        connection.send(answer)
    except Exception as error:  # an answer that does not pickle: said in words
        connection.send(("error", RuntimeError(f"{type(error).__name__}: {error}")))
    connection.close()


@dataclass(frozen=True)
class ShapeFile:
    """A Part.Shape passed to or from a worker process as a binary BREP file (Shape.exportBinary)."""

    path: str

    @classmethod
    def written(cls, shape, path):
        shape.exportBinary(path)
        return cls(path)

    def read(self):
        from .cad.freecad_env import Part

        shape = Part.Shape()
        shape.importBinary(self.path)
        return shape


def write_arguments(folder, arguments):
    """Write `arguments` into `folder` for :func:`call_with_shapes`: each Part.Shape as a ShapeFile, the
    rest pickled."""
    from .cad.freecad_env import Part

    passed = [ShapeFile.written(value, os.path.join(folder, f"argument_{i}.brep"))
              if isinstance(value, Part.Shape) else value for i, value in enumerate(arguments)]
    with open(os.path.join(folder, "arguments.pickle"), "wb") as handle:
        pickle.dump(passed, handle, protocol=pickle.HIGHEST_PROTOCOL)


def call_with_shapes(function, folder, progress=None):
    """In a worker process: function(*arguments, progress=progress) with the arguments write_arguments put
    in `folder` (the shapes read back); a Part.Shape value, or each Part.Shape of a tuple value, comes back
    as a ShapeFile in `folder` (:func:`shapes_read` reads them)."""
    from .cad.freecad_env import Part

    with open(os.path.join(folder, "arguments.pickle"), "rb") as handle:
        arguments = [value.read() if isinstance(value, ShapeFile) else value for value in pickle.load(handle)]
    try:
        takes = "progress" in inspect.signature(function).parameters
    except (TypeError, ValueError):
        takes = False
    value = function(*arguments, progress=progress) if takes else function(*arguments)

    def passed(item, i):
        return ShapeFile.written(item, os.path.join(folder, f"value_{i}.brep")) if isinstance(item, Part.Shape) else item

    return tuple(passed(item, i) for i, item in enumerate(value)) if isinstance(value, tuple) else passed(value, 0)


def shapes_read(value):
    """A value of :func:`call_with_shapes` with its ShapeFiles (itself, or in a tuple) read as Part.Shape."""
    if isinstance(value, tuple):
        return tuple(item.read() if isinstance(item, ShapeFile) else item for item in value)
    return value.read() if isinstance(value, ShapeFile) else value
