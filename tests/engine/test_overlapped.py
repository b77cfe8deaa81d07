"""formats.overlapped: every item consumed once, in order, in another thread; errors on either side
raised in the caller, and the consumer thread always ended before the call returns or raises."""

import threading
import time

import pytest

from abm_workbench.formats.overlapped import consume_overlapped


def writers():
    return [thread for thread in threading.enumerate() if thread.name == "abm-writer"]


def test_items_are_consumed_in_order_in_another_thread():
    seen, threads = [], set()

    def consume(item):
        threads.add(threading.get_ident())
        time.sleep(0.001 * (item % 3))  # a consumer slower than the producer at times
        seen.append(item)

    assert consume_overlapped(iter(range(50)), consume) == 50
    assert seen == list(range(50)) and threads and threading.get_ident() not in threads
    assert writers() == []


def test_no_items():
    assert consume_overlapped([], lambda item: pytest.fail("nothing to consume")) == 0


def test_an_error_of_the_consumer_is_raised_and_stops_it():
    seen = []

    def consume(item):
        if item == 3:
            raise OSError(28, "No space left on device")
        seen.append(item)

    with pytest.raises(OSError, match="No space left"):
        consume_overlapped(iter(range(100)), consume)
    assert seen == [0, 1, 2] and writers() == []


@pytest.mark.parametrize("error", [ValueError("bad chunk"), KeyboardInterrupt()])
def test_an_error_while_producing_ends_the_consumer_first(error):
    seen = []

    def produce():
        yield from range(5)
        raise error

    def consume(item):
        time.sleep(0.01)
        seen.append(item)

    with pytest.raises(type(error)):
        consume_overlapped(produce(), consume)
    assert writers() == []
    done = list(seen)
    time.sleep(0.05)
    assert seen == done and done == list(range(len(done))) and len(done) <= 5
