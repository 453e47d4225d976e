"""Background work that can wait steps aside while an analysis runs."""

from __future__ import annotations

import threading
import time

from widgets.workers import analysis_running, wait_while_analysing


def test_an_autosave_waits_for_the_running_analysis_and_no_longer():
    done = threading.Event()
    waited = []

    def autosave():
        t0 = time.perf_counter()
        wait_while_analysing(limit_s=5.0)
        waited.append(time.perf_counter() - t0)
        done.set()

    with analysis_running():
        worker = threading.Thread(target=autosave)
        worker.start()
        time.sleep(0.2)
        assert not done.is_set()  # still waiting: the analysis has the interpreter
    assert done.wait(2.0) and 0.15 < waited[0] < 2.0
    worker.join()
    t0 = time.perf_counter()
    wait_while_analysing()  # nothing running: no wait at all
    assert time.perf_counter() - t0 < 0.05


def test_typing_that_never_stops_still_gets_autosaved():
    with analysis_running():
        t0 = time.perf_counter()
        wait_while_analysing(limit_s=0.2)
        assert 0.15 < time.perf_counter() - t0 < 1.0
