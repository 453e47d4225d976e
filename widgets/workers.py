"""The window's background work, in one object owned by the application.

:class:`Workers` holds the thread pool that imports and analyses of large sheets run
on, and counts what runs on it. While any worker runs Python code,
:meth:`Workers.gui_thread_first` shortens the interpreter's switch interval so the
GUI thread gets the GIL back every 0.1 ms, and :meth:`Workers.cyclic_gc_paused`
rests the cyclic garbage collector while a million rows of strings are built. Both
settings belong to the whole process: this object is the only one that changes them,
and it restores each when the last worker that asked for it ends.

The application has one :class:`Workers`, a child of the ``QCoreApplication``
(:func:`application_workers`); a test may make its own.
"""

from __future__ import annotations

import contextlib
import gc
import sys
import threading

from PySide6.QtCore import QCoreApplication, QObject, QRunnable, QThreadPool

__all__ = ["Workers", "application_workers", "emit_if_alive"]

SWITCH_INTERVAL_WORKING = 0.0001  # s: the GUI thread gets the GIL back every 0.1 ms
WORKER_THREADS = 2


def emit_if_alive(signal, *args) -> None:
    """Deliver a worker's result; if its workbench was closed meanwhile, drop it."""
    with contextlib.suppress(RuntimeError):
        signal.emit(*args)


class Workers(QObject):
    """The thread pool of imports and analyses, and the process-wide settings they need."""

    def __init__(self, parent: QObject | None = None, threads: int = WORKER_THREADS) -> None:
        super().__init__(parent)
        # Our own pool, not Qt's global one: Qt's painting uses that one for parallel image
        # work and waits for it on the GUI thread, so a long import queued there froze the
        # window for up to a second.
        self.pool = QThreadPool(self)
        self.pool.setMaxThreadCount(threads)
        self._lock = threading.Lock()
        self._fast_switching = 0  # workers inside gui_thread_first
        self._switch_interval_before = sys.getswitchinterval()
        self._gc_pauses = 0  # workers inside cyclic_gc_paused
        self._gc_was_enabled = True
        self._analyses = 0  # workers inside analysis_running
        self._analyses_changed = threading.Condition()

    def start(self, task: QRunnable) -> None:
        """Run ``task`` on the pool."""
        self.pool.start(task)

    @contextlib.contextmanager
    def gui_thread_first(self):
        """While a worker runs Python code, hand the GIL back to the GUI thread every 0.1 ms
        instead of 5 ms. Painting calls Python (pyqtgraph) hundreds of times per frame and
        waits for the GIL at each call: with the default interval a frame took seconds."""
        with self._lock:
            if self._fast_switching == 0:
                self._switch_interval_before = sys.getswitchinterval()
                sys.setswitchinterval(SWITCH_INTERVAL_WORKING)
            self._fast_switching += 1
        try:
            yield
        finally:
            with self._lock:
                self._fast_switching -= 1
                if self._fast_switching == 0:
                    sys.setswitchinterval(self._switch_interval_before)

    @contextlib.contextmanager
    def cyclic_gc_paused(self):
        """No full cyclic-GC passes while the block runs (an import or an autosave building a
        million strings, which hold no cycles); counted, so that two such threads at once
        leave the collector as it was only when the last one ends."""
        with self._lock:
            if self._gc_pauses == 0:
                self._gc_was_enabled = gc.isenabled()
                gc.disable()
            self._gc_pauses += 1
        try:
            yield
        finally:
            with self._lock:
                self._gc_pauses -= 1
                if self._gc_pauses == 0 and self._gc_was_enabled:
                    gc.enable()

    def gc_paused(self) -> bool:
        """Whether a worker is inside :meth:`cyclic_gc_paused` (the GUI thread's collector,
        widgets.gui_garbage_collector, then holds its passes too)."""
        return self._gc_pauses > 0

    @contextlib.contextmanager
    def analysis_running(self):
        """Mark an analysis as running (see :meth:`wait_while_analysing`)."""
        with self._analyses_changed:
            self._analyses += 1
        try:
            yield
        finally:
            with self._analyses_changed:
                self._analyses -= 1
                self._analyses_changed.notify_all()

    def wait_while_analysing(self, limit_s: float = 5.0) -> None:
        """Background work that can wait (an autosave) steps aside while an analysis runs:
        the analysis and the window share one interpreter, and a million-row autosave beside
        an analysis made an edit's result 0.1 s later and the window pause 0.26 s. Waits at
        most ``limit_s`` (typing that never stops still gets autosaved)."""
        with self._analyses_changed:
            self._analyses_changed.wait_for(lambda: self._analyses == 0, timeout=limit_s)


def application_workers() -> Workers:
    """The application's workers: a child of the ``QCoreApplication``, made when first asked
    for, and gone with the application."""
    app = QCoreApplication.instance()
    if app is None:
        raise RuntimeError("the workers belong to the application: make a QApplication first")
    workers = app.findChild(Workers)
    if workers is None:
        workers = Workers(app)
    return workers
