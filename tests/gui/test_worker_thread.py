"""gui.worker's thread in the FreeCAD GUI: Qt names it from its object name as it starts, never through its
metaObject(), which PySide2 answers without holding the GIL (the SIGSEGV FreeCAD once had there)."""

BODY = """
from abm_workbench.gui import worker
names = []
def own_name():  # the OS's name of the thread running it
    with open("/proc/thread-self/comm") as handle:
        names.append(handle.read().strip())
thread = worker._Thread(worker._Job(own_name, (), {}, worker.CANCELLED))
thread.start()
verdict["ended"] = thread.wait(60000)
verdict["names"], verdict["expected"] = names, worker.THREAD_NAME
"""


def test_the_worker_thread_is_named_before_it_starts(run_gui):
    verdict = run_gui(BODY)
    assert verdict["ended"] and len(verdict["expected"]) <= 15, str(verdict)
    assert verdict["names"] == [verdict["expected"]], str(verdict)  # not "_Thread" (its class, by metaObject)
