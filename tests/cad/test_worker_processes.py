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


def counted(n, progress=None):
    """n steps said, then n; a crash for n = 4, ValueError for n = 3, a long sleep for n = 100."""
    import time

    for i in range(min(n, 5)):
        progress(i + 1, n)
    if n == 3:
        raise ValueError("three is refused")
    if n == 4:
        os._exit(7)
    if n == 100:
        time.sleep(60)
    return n


def said(task, seconds=60.0):
    """Every message of a ChildTask until it ends (looked at every 20 ms)."""
    import time

    messages, deadline = [], time.monotonic() + seconds
    while not task.ended and time.monotonic() < deadline:
        messages += task.messages()
        time.sleep(0.02)
    return messages


def test_child_task_says_its_steps_then_its_value_or_error():
    from abm_workbench.worker_processes import ChildTask

    for n, last in ((2, ("value", 2)), (3, ("error", ValueError)), (4, ("error", WorkerError))):
        task = ChildTask(counted, (n,)).start()
        try:
            messages = said(task)
        finally:
            task.stop()
        assert messages[:-1] == [("progress", i + 1, n) for i in range(n)]
        kind, value = messages[-1]
        assert kind == last[0] and (value == last[1] if kind == "value" else isinstance(value, last[1]))
        assert task.process.exitcode is not None


def test_child_task_stop_kills_at_once():
    import time

    from abm_workbench.worker_processes import ChildTask

    task = ChildTask(counted, (100,)).start()
    deadline = time.monotonic() + 60
    while not task.messages() and time.monotonic() < deadline:  # its first step: it runs
        time.sleep(0.02)
    started = time.monotonic()
    task.stop()
    assert time.monotonic() - started < 0.5 and task.process.exitcode == -9 and task.ended


def test_shapes_pass_to_a_child_and_back_exactly(tmp_path):
    """call_with_shapes: a Part.Shape argument and value through binary BREP files, the doubles unchanged."""
    import numpy as np

    from abm_workbench.cad.freecad_env import FreeCAD, Part
    from abm_workbench.cad.inprocess_boolean import cut_by_hulls
    from abm_workbench.worker_processes import ChildTask, ShapeFile, call_with_shapes, write_arguments

    stock = Part.makeBox(40.0, 30.0, 20.0, FreeCAD.Vector(0.1, 0.2, 0.3))
    hulls = {"c0": np.array([[5.0, 15.0, 12.0], [5.0, 5.0, 14.5]]), "c1": np.array([[35.0, 15.3, 12.0],
                                                                                   [30.0, 25.0, 13.0]]),
             "axis": np.array([[0.0, 0.0, 1.0], [0.0, 0.6, 0.8]]), "radius": np.array([4.0, 3.0]),
             "height": np.array([20.0, 15.0])}
    write_arguments(str(tmp_path), [stock, hulls])
    task = ChildTask(call_with_shapes, (cut_by_hulls, str(tmp_path))).start()
    try:
        messages = said(task)
    finally:
        task.stop()
    assert [m[1:] for m in messages[:-1]] == [(i, 4) for i in range(1, 5)]
    kind, value = messages[-1]
    assert kind == "value" and isinstance(value, ShapeFile)
    here = cut_by_hulls(stock, hulls)
    there = value.read()
    assert there.isValid() and there.Volume == here.Volume and len(there.Faces) == len(here.Faces)
    assert there.Volume < stock.Volume


def nap(seconds):
    """`seconds` slept, then `seconds`."""
    import time

    time.sleep(seconds)
    return seconds


def test_a_stop_set_by_another_thread_kills_the_busy_workers_at_once():
    import threading
    import time

    from abm_workbench.worker_processes import Stopped, stop_when

    event = threading.Event()
    with stop_when(event):  # not set: the answers as usual
        with WorkerProcesses(2, abs, (0,)) as workers:
            assert sorted(workers.map_unordered(nap, [(0,), (0.1,)])) == [(0, 0), (1, 0.1)]
    answers, stopped = [], {}

    def stop():
        stopped["at"] = time.monotonic()
        event.set()

    with pytest.raises(Stopped, match="2 of 3 tasks unanswered"):
        with stop_when(event):
            with WorkerProcesses(2, abs, (0,)) as workers:
                for answer in workers.map_unordered(nap, [(0,), (60,), (60,)]):
                    answers.append(answer)
                    threading.Timer(0.5, stop).start()  # the workers are busy with 60 s tasks by then
    seconds = time.monotonic() - stopped["at"]
    assert answers == [(0, 0)] and seconds < 2.0, seconds  # not the 60 s of the tasks
    assert [process.exitcode for process in workers.processes] == [-9, -9]
