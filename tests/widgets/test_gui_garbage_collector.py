"""Cyclic garbage is collected in the GUI thread only (widgets.gui_garbage_collector): a Qt
object in a cycle destroyed in a worker thread deadlocked a CI worker."""

from __future__ import annotations

import gc
import threading

from PySide6.QtCore import QObject

from widgets.gui_garbage_collector import GuiThreadGarbageCollector


class _Cycle:
    """A cycle that holds a QObject; says in which thread it was collected."""

    where: list[str] = []

    def __init__(self) -> None:
        self.me = self
        self.qt = QObject()

    def __del__(self) -> None:
        _Cycle.where.append(threading.current_thread().name)


def _garbage_then_allocations_in_a_thread() -> None:
    _Cycle()  # unreachable at once: only the cyclic collector can free it

    def allocate() -> None:  # what a capture worker does: many small objects
        for _ in range(20):
            _ = [[i] for i in range(20_000)]

    worker = threading.Thread(target=allocate, name="capture worker")
    worker.start()
    worker.join()


def test_without_it_a_worker_thread_collects_a_qt_cycle(qapp):
    """The hazard itself, with automatic collection on: the worker's allocations collect the
    cycle in the worker's thread (the test shows why the collector exists)."""
    collector = qapp.findChild(GuiThreadGarbageCollector)
    if collector is not None:  # the test set-up's: off for this test
        collector.stop()
    gc.collect()
    was = gc.isenabled()
    gc.enable()
    try:
        _Cycle.where.clear()
        _garbage_then_allocations_in_a_thread()
    finally:
        if not was:
            gc.disable()
    gc.collect()
    assert _Cycle.where == ["capture worker"]


def test_with_it_the_cycle_is_collected_in_the_gui_thread(qapp, qtbot):
    # the test set-up's own collectors off for this test: it runs on the GUI thread too, and
    # under load its timer collected the cycle first (this one then counted 0 collections)
    for running in qapp.findChildren(GuiThreadGarbageCollector):
        running.stop(full=False)
    gc.collect()
    collector = GuiThreadGarbageCollector(qapp, interval_ms=10, youngest_at_least_s=0.05).start()
    try:
        assert not gc.isenabled()
        _Cycle.where.clear()
        _garbage_then_allocations_in_a_thread()
        assert _Cycle.where == []  # nothing collected in the worker
        qtbot.waitUntil(lambda: bool(_Cycle.where), timeout=5000)
        assert _Cycle.where == [threading.main_thread().name]
        assert collector.collections >= 1
    finally:
        collector.stop()
        collector.deleteLater()


def test_a_worker_pause_holds_it_and_stop_leaves_the_collector_as_found(qapp):
    """(The test session itself runs with automatic collection off.)"""
    gc.collect()
    enabled = gc.isenabled()
    collector = GuiThreadGarbageCollector(qapp, paused=lambda: True,
                                          youngest_at_least_s=3600.0).start()
    _ = [[i] for i in range(5_000)]  # counts well past the threshold
    collector.check()
    assert collector.collections == 0
    collector.paused = lambda: False
    collector.check()
    assert collector.collections == 1
    collector.stop()
    collector.deleteLater()
    assert gc.isenabled() == enabled
