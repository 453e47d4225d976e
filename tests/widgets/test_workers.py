"""The application's workers: one object, owned by the application, that holds the thread
pool and is the only one to change the process-wide switch interval and cyclic GC (each
restored when the last worker that asked for it ends); background work that can wait steps
aside while an analysis runs."""

from __future__ import annotations

import gc
import sys
import threading
import time

import pytest
from PySide6.QtCore import QCoreApplication, QRunnable

from widgets.fringe.presenter import FringePresenter
from widgets.workers import SWITCH_INTERVAL_WORKING, Workers, application_workers


@pytest.mark.slow
def test_the_application_owns_one_workers_object_that_every_presenter_uses(qapp, qtbot):
    workers = application_workers()
    assert workers is application_workers()
    assert workers.parent() is QCoreApplication.instance()
    assert workers.pool.maxThreadCount() == 2
    presenter = FringePresenter()
    qtbot.addWidget(presenter.view)
    assert presenter.workers is workers


def test_a_task_runs_on_the_workers_pool(qapp):
    workers = Workers()
    ran = threading.Event()
    threads = []

    class Task(QRunnable):
        def run(self):
            threads.append(threading.current_thread())
            ran.set()

    workers.start(Task())
    assert ran.wait(5.0) and threads[0] is not threading.main_thread()
    assert workers.pool.waitForDone(5000)


def test_the_switch_interval_is_short_while_any_worker_runs_and_restored_after_the_last():
    workers = Workers()
    before = sys.getswitchinterval()
    with workers.gui_thread_first():
        assert sys.getswitchinterval() == pytest.approx(SWITCH_INTERVAL_WORKING)
        with workers.gui_thread_first():  # a second worker at once
            assert sys.getswitchinterval() == pytest.approx(SWITCH_INTERVAL_WORKING)
        assert sys.getswitchinterval() == pytest.approx(SWITCH_INTERVAL_WORKING)  # the first still runs
    assert sys.getswitchinterval() == before


def test_the_collector_rests_while_any_import_runs_and_is_left_as_it_was():
    workers = Workers()
    # the test session runs with automatic collection off (tests/conftest.py): on for this
    # test, off again after
    gc.enable()
    try:
        _collector_rests(workers)
    finally:
        gc.disable()


def _collector_rests(workers: Workers) -> None:
    assert gc.isenabled() and not workers.gc_paused()
    with workers.cyclic_gc_paused():
        assert not gc.isenabled() and workers.gc_paused()
        with workers.cyclic_gc_paused():
            assert not gc.isenabled()
        assert not gc.isenabled()
    assert gc.isenabled()
    gc.disable()  # someone else had it off: it stays off
    try:
        with workers.cyclic_gc_paused():
            assert not gc.isenabled()
        assert not gc.isenabled()
    finally:
        gc.enable()


def test_a_worker_that_fails_still_restores_the_process_settings():
    workers = Workers()
    before = sys.getswitchinterval()
    gc.enable()  # the test session runs with it off (tests/conftest.py)
    try:
        with workers.cyclic_gc_paused(), workers.gui_thread_first(), workers.analysis_running():
            raise KeyError("a bug in an analysis")
    except KeyError:
        pass
    finally:
        enabled = gc.isenabled()
        gc.disable()
    assert sys.getswitchinterval() == before and enabled
    t0 = time.perf_counter()
    workers.wait_while_analysing(limit_s=2.0)  # the failed analysis no longer counts
    assert time.perf_counter() - t0 < 0.05


def test_an_autosave_waits_for_the_running_analysis_and_no_longer():
    workers = Workers()
    done = threading.Event()
    waited = []

    def autosave():
        t0 = time.perf_counter()
        workers.wait_while_analysing(limit_s=5.0)
        waited.append(time.perf_counter() - t0)
        done.set()

    with workers.analysis_running():
        worker = threading.Thread(target=autosave)
        worker.start()
        time.sleep(0.2)
        assert not done.is_set()  # still waiting: the analysis has the interpreter
    assert done.wait(2.0) and 0.15 < waited[0] < 2.0
    worker.join()
    t0 = time.perf_counter()
    workers.wait_while_analysing()  # nothing running: no wait at all
    assert time.perf_counter() - t0 < 0.05


def test_typing_that_never_stops_still_gets_autosaved():
    workers = Workers()
    with workers.analysis_running():
        t0 = time.perf_counter()
        workers.wait_while_analysing(limit_s=0.2)
        assert 0.15 < time.perf_counter() - t0 < 1.0


@pytest.mark.slow
def test_one_workers_analysis_does_not_hold_up_anothers_autosave():
    """Each object counts its own analyses (a test's workers do not touch the window's)."""
    mine, theirs = Workers(), Workers()
    with theirs.analysis_running():
        t0 = time.perf_counter()
        mine.wait_while_analysing(limit_s=2.0)
        assert time.perf_counter() - t0 < 0.05
