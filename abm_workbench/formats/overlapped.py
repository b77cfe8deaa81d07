"""Writing chunks while the next ones are computed: a consumer in a second thread.

The chunks of a pass come from a generator that runs the engine in this thread; writing a chunk
(os.pwrite, zlib.crc32) spends its time in calls that release the GIL, so a second thread can write
chunk k while this one computes chunk k + 1, on a second core.
"""

import queue
import threading

#: Tells the consumer thread that no item follows.
_END = object()


def consume_overlapped(items, consume):
    """Call consume(item) for every item of the iterable `items`, in order, in a second thread, while
    this thread takes the next item from `items`; at most one item waits between them. Returns the
    number of items consumed.

    An error of consume is raised here (the items left are not consumed); an error or a
    KeyboardInterrupt while taking items stops the consumer after its current item and is raised once
    the consumer thread has ended, so that nothing is written after this function returns or raises.
    """
    handoff = queue.Queue(maxsize=1)
    stop = threading.Event()
    failures = []

    def run():
        while True:
            item = handoff.get()
            if item is _END:
                return
            if stop.is_set() or failures:
                continue
            try:
                consume(item)
            except BaseException as error:  # raised in the calling thread
                failures.append(error)

    worker = threading.Thread(target=run, name="abm-writer", daemon=True)
    worker.start()
    count = 0
    try:
        for item in items:
            if failures:
                break
            handoff.put(item)
            count += 1
    except BaseException:
        stop.set()
        raise
    finally:
        _end(handoff, worker)
    if failures:
        raise failures[0]
    return count


def _end(handoff, worker):
    """Tell `worker` to end and wait until it has; a KeyboardInterrupt meanwhile is raised only after."""
    interrupted, told = None, False
    while worker.is_alive():
        try:
            if not told:
                handoff.put(_END)
                told = True
            worker.join()
        except KeyboardInterrupt as interrupt:
            interrupted = interrupt
    if interrupted is not None:
        raise interrupted
