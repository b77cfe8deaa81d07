"""worker_processes.WorkerProcesses: every task answered once, errors raised in the caller, and the
workers gone after the block however it ends (a failing task, a crashed worker, a failing initializer)."""

import os

import pytest

from abm_workbench.worker_processes import WorkerError, WorkerProcesses


def square_or_fail(x):
    """x², ValueError for x = 3 (a task that fails), the worker dying for x = 4 (a crash)."""
    if x == 3:
        raise ValueError("three is refused")
    if x == 4:
        os._exit(7)
    return x * x


def gone(processes):
    return all(process.exitcode is not None for process in processes)


def test_every_task_answered_once():
    with WorkerProcesses(2, abs, (0,)) as workers:
        answers = sorted(workers.map_unordered(square_or_fail, [(x,) for x in (0, 1, 2, 5, 6, 7, 8)]))
    assert answers == [(0, 0), (1, 1), (2, 4), (3, 25), (4, 36), (5, 49), (6, 64)]
    assert gone(workers.processes) and [process.exitcode for process in workers.processes] == [0, 0]


def test_a_failing_task_raises_its_error_and_ends_the_workers():
    with pytest.raises(ValueError, match="three is refused"):
        with WorkerProcesses(2, abs, (0,)) as workers:
            list(workers.map_unordered(square_or_fail, [(x,) for x in (1, 2, 3, 5)]))
    assert gone(workers.processes)


def test_a_crashed_worker_raises_worker_error():
    with pytest.raises(WorkerError, match="exit code 7"):
        with WorkerProcesses(2, abs, (0,)) as workers:
            list(workers.map_unordered(square_or_fail, [(4,), (1,)]))
    assert gone(workers.processes)


def test_a_failing_initializer_answers_every_task_with_its_error():
    with pytest.raises(TypeError):
        with WorkerProcesses(1, abs, ("not a number",)) as workers:
            list(workers.map_unordered(square_or_fail, [(1,)]))
    assert gone(workers.processes)
