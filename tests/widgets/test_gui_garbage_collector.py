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


def _generations_collected(check) -> list[int]:
    """The generations the collector passed over while ``check()`` ran."""
    seen: list[int] = []

    def record(phase: str, info: dict) -> None:
        if phase == "start":
            seen.append(info["generation"])

    gc.callbacks.append(record)
    try:
        check()
    finally:
        gc.callbacks.remove(record)
    return seen


def _every_count_past_its_threshold() -> list:
    """The collector's counts as after a long busy spell: each generation's count past its
    threshold (a pass over a generation adds one to the next one's count and zeroes its own
    and the younger ones'); the youngest's allocations returned (kept, they stay counted)."""
    threshold = gc.get_threshold()
    for _ in range(threshold[2] + 1):
        gc.collect(1)
    for _ in range(threshold[1] + 1):
        gc.collect(0)
    young = [[i] for i in range(threshold[0] + 100)]
    counts = gc.get_count()
    assert all(counts[g] > threshold[g] for g in range(3)), (counts, threshold)
    return young


def test_a_full_pass_waits_until_the_oldest_generation_grew_by_a_quarter(qapp):
    """A full pass walks every object of the process (0.2–0.6 s in a window or a test
    worker): as CPython's own collector, the GUI thread's makes one only when the objects
    that reached the oldest generation since its last full pass are a quarter of those that
    pass left, and collects the middle generation otherwise; the counts alone made one every
    few seconds of a busy window."""
    collector = GuiThreadGarbageCollector(qapp, youngest_at_least_s=3600.0)
    kept: list[list] = []
    try:
        collector.start()
        collector.stop()  # a full pass
        left = len(gc.get_objects(generation=2))

        # a tenth of what it left joins the oldest generation: not yet
        kept.append([[i] for i in range(left // 10)])
        gc.collect(1)
        kept.append(_every_count_past_its_threshold())
        assert _generations_collected(collector.check) == [1]
        assert gc.get_count()[2] > gc.get_threshold()[2]  # the oldest still due by its count

        # more than a quarter of it has joined since the full pass: now
        kept.append([[i] for i in range(left // 5)])
        gc.collect(1)
        kept.append(_every_count_past_its_threshold())
        assert _generations_collected(collector.check) == [2]
    finally:
        collector.deleteLater()
