"""Passes split into chunks of CL points, run in this process, on local processes or on a Dask cluster.

Every CL point of a pass is independent of the others: the engine solves each instant from the
CL point, the tool axis and φ alone, and the per-CL-point results (depth of cut, engagement
segments) only look along φ. So a pass cut into chunks of consecutive CL points, each engaged
on its own (``engine.engage`` on the toolpath slice), gives chunk Engagements whose rows
concatenate exactly into the Engagement of the whole pass, bit for bit. Chunk boundaries are
multiples of the engine's own chunk of CL points, so each worker even runs the same array
operations on the same lines as a single process would.

A job is a tuple (Staircase, Tool, Toolpath, CutSettings); many jobs (passes) are cut into
chunks together and share the workers. Chunks are handed out as workers become free, at most
a few per worker in flight, and their results are given back in pass order, so memory stays
bounded by the chunks in flight however long the pass is.

Where the work runs: ``workers=1`` (default) in this process; ``workers=N`` on N local
processes (``0``: one per core); ``scheduler="tcp://host:port"`` on the Dask cluster behind that
scheduler (its workers must be able to import ``abm_workbench``).
"""

import contextlib
import dataclasses
import os

import numpy as np

from .engine import Engagement, engage
from .engine.arguments import check_arguments
from .errors import InputError, ParameterError, note
from .limits import usable_cores

#: Instants per chunk (CL points × angles): the engine's default chunk, about 3 MiB of results.
CHUNK_INSTANTS = 1 << 15
#: Chunks in flight (computing or waiting to be given back in order) per worker.
IN_FLIGHT_PER_WORKER = 3
#: Seconds to wait for a Dask scheduler to answer.
SCHEDULER_TIMEOUT = 3.0
#: Engagement fields over the angles (p,), the same for every chunk; all others are over CL points first.
ANGLE_FIELDS = ("phi",)


class SchedulerError(InputError):
    """A Dask scheduler address that is malformed or does not answer."""


class ChunkError(RuntimeError):
    """A chunk of CL points failed on a worker: its job index, CL range [start, stop) and the cause."""

    def __init__(self, job, start, stop, cause, jobs=1):
        last, name = stop - 1, type(cause).__name__
        super().__init__(note(f"job {job}, CL points {start}..{last}: {name}: {cause}" if jobs > 1 else
                              f"CL points {start}..{last}: {name}: {cause}"))
        self.job, self.start, self.stop = job, start, stop


def worker_count(workers):
    """Number of local processes for `workers` (int ≥ 0; 0 = one per core), at most one per core this
    process may run on (more would only share the cores: the results are the same, no sooner); ValueError
    for anything but a whole number ≥ 0."""
    if isinstance(workers, bool) or not isinstance(workers, (int, np.integer)) or workers < 0:
        raise ValueError(f"workers must be a whole number >= 0 (0 = all cores), got {workers!r}")
    return min(int(workers), usable_cores()) or usable_cores()


def cl_ranges(m, p, chunk_instants=None):
    """[(start, stop), …] CL ranges covering m CL points of p angles, about `chunk_instants` each.

    Each range holds a whole number of the engine's chunks of max(1, chunk_instants // p) CL points.
    chunk_instants None: CHUNK_INSTANTS (as in every function here).
    """
    chunk_instants = CHUNK_INSTANTS if chunk_instants is None else chunk_instants
    step = max(1, int(chunk_instants) // max(int(p), 1))
    return [(start, min(int(m), start + step)) for start in range(0, int(m), step)]


def toolpath_part(toolpath, start, stop):
    """The Toolpath of CL points start:stop (the CC points too, when given)."""
    return toolpath.rows(slice(start, stop))


def engage_chunk(job, start, stop, chunk_instants=None):
    """Engagement of CL points start:stop of `job` (stock, tool, toolpath, settings), rows 0.. = CL start.."""
    stock, tool, toolpath, settings = job
    chunk_instants = CHUNK_INSTANTS if chunk_instants is None else chunk_instants
    return engage(stock, tool, toolpath_part(toolpath, start, stop), settings, chunk_instants=chunk_instants)


def engage_parallel(stock, tool, toolpath, settings, *, workers=1, scheduler=None, chunk_instants=None,
                    progress=None):
    """Engagement of one pass, computed chunk by chunk where `workers` / `scheduler` say.

    Identical (bit for bit, NaNs in the same places) to ``engine.engage`` of the whole pass.
    progress(done, total): CL points done, called as chunks complete.
    """
    check_arguments(stock=stock, tool=tool, toolpath=toolpath, settings=settings)
    return engage_jobs([(stock, tool, toolpath, settings)], workers=workers, scheduler=scheduler,
                       chunk_instants=chunk_instants, progress=progress)[0]


def engage_jobs(jobs, *, workers=1, scheduler=None, chunk_instants=None, progress=None):
    """Engagements of many jobs (stock, tool, toolpath, settings), one per job, computed together.

    Chunks of every job share the workers. progress(done, total): CL points done over all jobs.
    """
    jobs = list(jobs)
    chunk_instants = CHUNK_INSTANTS if chunk_instants is None else int(chunk_instants)
    passes = [PassAssembly(len(job[2])) for job in jobs]
    for j, start, stop, chunk in map_chunks(_EngageTask(chunk_instants), jobs, workers=workers,
                                            scheduler=scheduler, chunk_instants=chunk_instants, progress=progress):
        passes[j].add(chunk, start)
    return [assembly.engagement() for assembly in passes]


@dataclasses.dataclass(frozen=True)
class _EngageTask:
    """engage_chunk with a chunk size: a picklable task for map_chunks."""

    chunk_instants: int

    def __call__(self, job, start, stop):
        return engage_chunk(job, start, stop, self.chunk_instants)


class PassAssembly:
    """The Engagement of a pass of m CL points, put together from chunk Engagements.

    add(chunk, start) copies a chunk's rows to CL points start, …; engagement() gives the
    whole once every CL point is filled. The arrays are allocated once, at the first chunk.
    """

    def __init__(self, m):
        self.m, self.fields, self.filled = int(m), None, 0

    def add(self, chunk, start):
        """Copy the rows of Engagement `chunk` (CL points start, … of the pass) into the pass."""
        n = chunk.shape[0]
        if self.fields is None:
            self.fields = {f.name: (getattr(chunk, f.name) if f.name in ANGLE_FIELDS else
                                    np.empty((self.m,) + getattr(chunk, f.name).shape[1:],
                                             getattr(chunk, f.name).dtype))
                           for f in dataclasses.fields(Engagement)}
        for name, array in self.fields.items():
            if name not in ANGLE_FIELDS:
                array[start:start + n] = getattr(chunk, name)
            elif not np.array_equal(array, getattr(chunk, name)):
                raise ValueError(f"chunk of CL points {start}..{start + n - 1}: {name} differs from the first chunk's")
        self.filled += n

    def engagement(self):
        """The Engagement of the whole pass; ValueError unless all m CL points were added."""
        if self.fields is None or self.filled != self.m:
            raise ValueError(f"{self.filled} of {self.m} CL points added")
        return Engagement(**self.fields)


def map_chunks(task, jobs, *, workers=1, scheduler=None, chunk_instants=None, progress=None):
    """Run task(job, start, stop) on every chunk of CL points of every job; yield results in order.

    jobs: sequence of (stock, tool, toolpath, settings). `task` must be picklable (a module-level
    function, or a picklable callable object) unless everything runs in this process.
    Yields (job index, start, stop, task result), jobs in order and CL ranges in pass order.
    A failing chunk raises ChunkError naming its CL range (the original error as its cause);
    a scheduler that is malformed or does not answer raises SchedulerError.
    """
    jobs = list(jobs)
    chunks = [(j, start, stop) for j, job in enumerate(jobs)
              for start, stop in cl_ranges(len(job[2]), job[3].phi.size, chunk_instants)]
    total = sum(len(job[2]) for job in jobs)
    if scheduler is not None:
        pool = _DaskPool(scheduler, jobs)
    elif worker_count(workers) > 1:
        pool = _ProcessPool(worker_count(workers), jobs)
    else:
        pool = _InlinePool(jobs)
    with pool:
        yield from _in_order(pool, task, chunks, total, len(jobs), progress)


def _in_order(pool, task, chunks, total, n_jobs, progress):
    """Submit `chunks` to `pool` a few per worker at a time; yield their results in chunk order."""
    window = pool.in_flight
    pending, finished, done = {}, {}, 0
    following = 0  # index of the next chunk to submit
    for index, (j, start, stop) in enumerate(chunks):
        while following < len(chunks) and following - index < window:
            pending[pool.submit(task, *chunks[following])] = following
            following += 1
        while index not in finished:
            for future in pool.wait_first(list(pending)):
                key = pending.pop(future)
                finished[key] = _result(future, chunks[key], n_jobs)
                done += chunks[key][2] - chunks[key][1]
                if progress is not None:
                    progress(done, total)
        yield j, start, stop, finished.pop(index)


def _result(future, chunk, n_jobs):
    """The future's result; its error re-raised as ChunkError naming the chunk's job and CL range."""
    try:
        return future.result()
    except (KeyboardInterrupt, SystemExit):
        raise
    except BaseException as error:
        raise ChunkError(*chunk, error, jobs=n_jobs) from error


class _Done:
    """A task already run in this process: result() gives its value or raises its error, as a future's does."""

    __slots__ = ("value", "error")

    def __init__(self, value=None, error=None):
        self.value, self.error = value, error

    def result(self):
        if self.error is not None:
            raise self.error
        return self.value


class _InlinePool:
    """Runs each task at once, in this process (results already there), one chunk at a time; no
    concurrent.futures machinery (nor its import)."""

    in_flight = 1

    def __init__(self, jobs):
        self.jobs = jobs

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def submit(self, task, j, start, stop):
        try:
            return _Done(task(self.jobs[j], start, stop))
        except (KeyboardInterrupt, SystemExit):
            raise
        except BaseException as error:
            return _Done(error=error)

    @staticmethod
    def wait_first(futures):
        return futures


_JOBS = None  # the jobs of a local worker process, set once by _ProcessPool's initializer


def _set_jobs(parent, jobs):
    """A local worker's start: it dies with its parent (worker_processes.die_with_parent) and keeps the jobs."""
    from .worker_processes import die_with_parent

    global _JOBS
    die_with_parent(parent)
    _JOBS = jobs


def _run_local(task, j, start, stop):
    return task(_JOBS[j], start, stop)


class _ProcessPool:
    """Local worker processes; the jobs are sent to each once, tasks name them by index."""

    def __init__(self, workers, jobs):
        import concurrent.futures  # here: a run in this process needs none of it

        from .worker_processes import held_signals

        self.in_flight = workers * IN_FLIGHT_PER_WORKER
        self.futures = concurrent.futures
        self.executor = concurrent.futures.ProcessPoolExecutor(workers, initializer=_set_jobs,
                                                               initargs=(os.getpid(), jobs))
        try:
            # The first task forks every worker now, not halfway through the pass. Stop signals are held
            # meanwhile: one arriving during a fork would run the command line's handler inside fork's own
            # callbacks (logging's lock release), where its exception is printed and lost, and the run would
            # go on; held, it is delivered when the block ends, here. The workers let them through once they
            # ignore SIGINT and SIGHUP (worker_processes.die_with_parent).
            with held_signals():
                self.executor.submit(int)
        except BaseException as error:
            self._kill()
            if isinstance(error, OSError):
                raise ParameterError("workers", f"could not start {workers} worker processes ({error.strerror or error}"
                                                "; a limit on processes?)") from None
            raise

    def __enter__(self):
        return self

    def __exit__(self, kind, error, trace):
        if kind is not None and not issubclass(kind, Exception):  # stopped (Ctrl-C, SIGTERM): no waiting
            self._kill()
        self.executor.shutdown(wait=True, cancel_futures=True)
        return False

    def _kill(self):
        """Kill and reap the workers started, and let the executor go without waiting for them."""
        processes = list((getattr(self.executor, "_processes", None) or {}).values())
        for process in processes:
            with contextlib.suppress(OSError, AttributeError, ValueError):
                process.kill()
        for process in processes:
            with contextlib.suppress(OSError, AttributeError, ValueError, AssertionError):
                process.join()
        with contextlib.suppress(Exception):
            self.executor.shutdown(wait=False, cancel_futures=True)

    def submit(self, task, j, start, stop):
        return self.executor.submit(_run_local, task, j, start, stop)

    def wait_first(self, futures):
        return self.futures.wait(futures, return_when=self.futures.FIRST_COMPLETED).done


def map_cl_points(task, shared, m, scheduler):
    """Run task(shared, i, i + 1) for every CL point i < m on the Dask cluster behind `scheduler`; yield
    (i, result) in the order they finish.

    shared (picklable, e.g. a solid's BREP text) is scattered to every Dask worker once. Leaving the
    generator early (an error, KeyboardInterrupt, a cancelling progress callback) closes the client,
    which cancels the tasks not yet started; a task already running on a Dask worker runs to its end
    there, its result dropped. SchedulerError as map_chunks.
    """
    with _DaskPool(scheduler, [shared]) as pool:
        futures = {pool.submit(task, 0, i, i + 1): i for i in range(m)}
        for _ in range(m):
            future = pool.wait_first(None)[0]
            yield futures[future], future.result()


class _DaskPool:
    """A Dask cluster behind a scheduler address; the jobs are scattered to every worker once."""

    def __init__(self, address, jobs):
        import distributed  # here: importing it takes a second, and only this needs it

        if not isinstance(address, str) or "://" not in address:
            raise SchedulerError(f"Dask scheduler address must look like tcp://host:port, got {address!r}")
        try:
            self.client = distributed.Client(address, timeout=SCHEDULER_TIMEOUT, set_as_default=False)
        except (OSError, ValueError, TypeError) as error:
            raise SchedulerError(f"Dask scheduler {address}: no answer within {SCHEDULER_TIMEOUT:g} s "
                                 f"({type(error).__name__}: {error})") from None
        try:
            threads = sum(w.get("nthreads", 1) for w in self.client.scheduler_info()["workers"].values())
            self.in_flight = max(1, threads) * IN_FLIGHT_PER_WORKER
            self.jobs = self.client.scatter(jobs, broadcast=True)
            self.completed = distributed.as_completed(loop=self.client.loop)
        except BaseException:
            self.client.close()
            raise

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.client.close()
        return False

    def submit(self, task, j, start, stop):
        future = self.client.submit(task, self.jobs[j], start, stop, pure=False)
        self.completed.add(future)
        return future

    def wait_first(self, futures):
        return [next(self.completed)]
