"""gui.worker's thread in the FreeCAD GUI: the job runs in a Python thread, not a QThread (Qt calls a
QThread's metaObject() from the thread itself, which PySide2 answers without holding the GIL: FreeCAD
crashed there), and work() still gives back its value, its error, and its steps to a sink."""

BODY = """
import threading
from abm_workbench.gui import worker
ran_in = []
def job(x, progress=None):
    ran_in.append([threading.current_thread().name, type(threading.current_thread()).__name__])
    for i in range(3):
        progress(i + 1, 3)
    if x < 0:
        raise ValueError("negative")
    return 2 * x
steps = []
def sink(done, total):
    steps.append([done, total])
verdict["value"] = worker.work(job, 21, sink=sink)
try:
    worker.work(job, -1)
except ValueError as error:
    verdict["error"] = str(error)
verdict["ran_in"], verdict["steps"], verdict["expected"] = ran_in, steps, worker.THREAD_NAME
verdict["left"] = [thread.name for thread in threading.enumerate() if thread.name == worker.THREAD_NAME]
"""


def test_work_runs_in_a_python_thread_and_gives_back_value_error_and_steps(run_gui):
    verdict = run_gui(BODY)
    # "Dummy-…" / _DummyThread: a thread Python did not start (a QThread running Python code)
    assert verdict["ran_in"] == [[verdict["expected"], "Thread"]] * 2, str(verdict)
    assert verdict["value"] == 42 and verdict["error"] == "negative" and verdict["left"] == [], str(verdict)
    assert verdict["steps"] == [[1, 3], [2, 3], [3, 3]], str(verdict)
