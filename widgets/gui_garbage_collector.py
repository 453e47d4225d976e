"""Cyclic garbage collected in the GUI thread only.

Python's cyclic collector runs in whichever thread happens to allocate when its counts pass
the threshold: a capture worker, an autosave, an analysis. A cycle that holds a Qt object
(a closed dialog, a panel's slot) is then destroyed in that thread: ~QObject takes Qt's
connection lock and calls back into Python for the GIL, while the GUI thread holds the GIL
and waits for that lock in a connect. Both wait for ever. It happened (a CI run of the
capture tests, 2026-12-04: the window frozen, every thread of the worker in the GIL's
wait or Qt's mutex, no timeout able to fire), and at the bench it is a frozen window in
the middle of a run.

So automatic collection is switched off while the window lives, and a timer in the GUI
thread collects each generation when its count passes the threshold the collector had
(the scheme of calibre's GarbageCollector), and the youngest at least once a second. A pause asked by a worker
(widgets.workers.Workers.cyclic_gc_paused: an import building a million strings that hold
no cycles) holds the timer's full passes too.
"""

from __future__ import annotations

import gc
import time
from collections.abc import Callable

from PySide6.QtCore import QObject, QTimer

__all__ = ["GuiThreadGarbageCollector", "collect_in_gui_thread"]

#: how often the GUI thread looks at the collector's counts (ms)
INTERVAL_MS = 200
#: the youngest generation is collected at least this often (s): the counts are allocations
#: less deallocations, and a worker that builds and drops big lists passes the threshold
#: only between two looks, so a cycle could wait for ever (a test saw it)
YOUNGEST_AT_LEAST_S = 1.0


class GuiThreadGarbageCollector(QObject):
    """While it runs, cyclic garbage is collected here, in the thread that owns it (the GUI
    thread), and nowhere else. ``paused``: True while a worker asks for no full passes."""

    def __init__(self, parent: QObject | None = None, interval_ms: int = INTERVAL_MS,
                 paused: Callable[[], bool] = lambda: False,
                 youngest_at_least_s: float = YOUNGEST_AT_LEAST_S) -> None:
        super().__init__(parent)
        self.threshold = gc.get_threshold()
        self.youngest_at_least_s = youngest_at_least_s
        self.last = time.monotonic()
        self.paused = paused
        self.was_enabled = gc.isenabled()
        self.collections = 0
        self.timer = QTimer(self)
        self.timer.setInterval(interval_ms)
        self.timer.timeout.connect(self.check)

    def start(self) -> GuiThreadGarbageCollector:
        gc.disable()
        self.timer.start()
        return self

    def stop(self, full: bool = True) -> None:
        """Stop, collect what is left here (``full`` False: the two younger generations
        only, what a test just made; a full pass over a big heap takes 0.1–0.3 s), and
        leave the collector as it was found."""
        self.timer.stop()
        gc.collect() if full else gc.collect(1)
        if self.was_enabled:
            gc.enable()

    def check(self) -> None:
        """Collect the generations whose counts passed the threshold, as the automatic
        collector would have (generation 0 first; an older one when its count passed too)."""
        if self.paused():
            return
        counts = gc.get_count()
        due = time.monotonic() - self.last >= self.youngest_at_least_s
        if counts[0] <= self.threshold[0] and not (due and counts[0] > 0):
            return
        generation = 0
        if counts[1] > self.threshold[1]:
            generation = 1
            if counts[2] > self.threshold[2]:
                generation = 2
        gc.collect(generation)
        self.collections += 1
        self.last = time.monotonic()


def collect_in_gui_thread(app: QObject) -> GuiThreadGarbageCollector:
    """Start the application's collector (a child of ``app``, made once), holding its passes
    while a worker asks for none."""
    from widgets.workers import application_workers

    found = app.findChild(GuiThreadGarbageCollector)
    if found is not None:
        return found
    return GuiThreadGarbageCollector(app, paused=application_workers().gc_paused).start()
