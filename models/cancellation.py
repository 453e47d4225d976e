"""Cooperative cancellation of a long analysis.

The window analyses a large sheet on a worker thread; when the readings change
again, that analysis is superseded and its result would be thrown away. The
analysis calls :func:`checkpoint` between its stages, and the worker runs it
inside :func:`cancellable` with a question that says whether it is still
wanted: the first checkpoint after the answer turns to "superseded" raises
:class:`AnalysisCancelled`, and the thread is free for the analysis that is.

Outside :func:`cancellable` (the command line, the tests, the certificate)
a checkpoint does nothing.
"""

from __future__ import annotations

import contextlib
import threading
from collections.abc import Callable, Iterator

__all__ = ["AnalysisCancelled", "cancellable", "checkpoint"]


class AnalysisCancelled(Exception):  # noqa: N818 - what it says to the caller
    """The analysis was superseded by newer readings; its result is not wanted."""


_local = threading.local()


@contextlib.contextmanager
def cancellable(superseded: Callable[[], bool]) -> Iterator[None]:
    """Run the block as an analysis that ``superseded()`` may cancel (on this thread)."""
    previous = getattr(_local, "superseded", None)
    _local.superseded = superseded
    try:
        yield
    finally:
        _local.superseded = previous


def checkpoint() -> None:
    """Raise :class:`AnalysisCancelled` if the analysis on this thread is no longer wanted."""
    superseded = getattr(_local, "superseded", None)
    if superseded is not None and superseded():
        raise AnalysisCancelled
