"""The worker threads of the window, and the one process-wide setting they need.

Imports and analyses of large sheets run on :func:`worker_pool`. While any of
them runs Python code, :func:`gui_thread_first` shortens the interpreter's
switch interval so the GUI thread gets the GIL back every 0.1 ms; this module
is the only place that changes it, and it restores the value when the last
worker ends.
"""

from __future__ import annotations

import contextlib
import gc
import sys
import threading

from PySide6.QtCore import QThreadPool

__all__ = ["analysis_running", "cyclic_gc_paused", "emit_if_alive", "gui_thread_first",
           "wait_while_analysing", "worker_pool"]


def emit_if_alive(signal, *args) -> None:
    """Deliver a worker's result; if its workbench was closed meanwhile, drop it."""
    with contextlib.suppress(RuntimeError):
        signal.emit(*args)


_WORKERS_RUNNING = 0
_WORKERS_LOCK = threading.Lock()
_SWITCH_INTERVAL_WORKING = 0.0001  # s
_switch_interval_default = sys.getswitchinterval()


@contextlib.contextmanager
def gui_thread_first():
    """While a worker runs Python code, hand the GIL back to the GUI thread every 0.1 ms
    instead of 5 ms. Painting calls Python (pyqtgraph) hundreds of times per frame and
    waits for the GIL at each call: with the default interval a frame took seconds."""
    global _WORKERS_RUNNING, _switch_interval_default
    with _WORKERS_LOCK:
        if _WORKERS_RUNNING == 0:
            _switch_interval_default = sys.getswitchinterval()
            sys.setswitchinterval(_SWITCH_INTERVAL_WORKING)
        _WORKERS_RUNNING += 1
    try:
        yield
    finally:
        with _WORKERS_LOCK:
            _WORKERS_RUNNING -= 1
            if _WORKERS_RUNNING == 0:
                sys.setswitchinterval(_switch_interval_default)


@contextlib.contextmanager
def cyclic_gc_paused():
    """No full cyclic-GC passes while the block runs (an import or an autosave building a
    million strings, which hold no cycles); counted, so that two such threads at once
    leave the collector as it was only when the last one ends."""
    global _GC_PAUSES, _gc_was_enabled
    with _WORKERS_LOCK:
        if _GC_PAUSES == 0:
            _gc_was_enabled = gc.isenabled()
            gc.disable()
        _GC_PAUSES += 1
    try:
        yield
    finally:
        with _WORKERS_LOCK:
            _GC_PAUSES -= 1
            if _GC_PAUSES == 0 and _gc_was_enabled:
                gc.enable()


_GC_PAUSES = 0
_gc_was_enabled = True


_WORKER_POOL: QThreadPool | None = None


def worker_pool() -> QThreadPool:
    """Our own thread pool for imports and analyses. Not Qt's global pool: Qt's painting
    uses that one for parallel image work, and waits for it on the GUI thread, so a
    long import queued there froze the window for up to a second."""
    global _WORKER_POOL
    if _WORKER_POOL is None:
        _WORKER_POOL = QThreadPool()
        _WORKER_POOL.setMaxThreadCount(2)
    return _WORKER_POOL




_ANALYSES = 0
_ANALYSES_CHANGED = threading.Condition()


@contextlib.contextmanager
def analysis_running():
    """Mark an analysis as running (see :func:`wait_while_analysing`)."""
    global _ANALYSES
    with _ANALYSES_CHANGED:
        _ANALYSES += 1
    try:
        yield
    finally:
        with _ANALYSES_CHANGED:
            _ANALYSES -= 1
            _ANALYSES_CHANGED.notify_all()


def wait_while_analysing(limit_s: float = 5.0) -> None:
    """Background work that can wait (an autosave) steps aside while an analysis runs:
    the analysis and the window share one interpreter, and a million-row autosave beside
    an analysis made an edit's result 0.1 s later and the window pause 0.26 s. Waits at
    most ``limit_s`` (typing that never stops still gets autosaved)."""
    with _ANALYSES_CHANGED:
        _ANALYSES_CHANGED.wait_for(lambda: _ANALYSES == 0, timeout=limit_s)
