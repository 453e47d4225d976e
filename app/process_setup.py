"""How the process runs numpy, set once at start-up, before numpy is imported.

* **One BLAS thread.** OpenBLAS starts a thread per core for a large product and
  its threads spin while they wait, holding the interpreter from the window's
  thread (the measurements: BENCHMARKS.md, Notes); the analyses here are small,
  for which one thread is as fast. ``OPENBLAS_NUM_THREADS`` (and its cousins) is
  read when the library loads, so this must run before the first ``import numpy``;
  a value the user set is kept.
* **Freed arrays reused, not returned to the system.** glibc returns every
  freed block above 128 KB to the kernel at once (``mmap``), so each temporary
  array of a million-sample analysis (8 MB) was faulted in again page by page.
  Blocks up to 32 MB come from the heap instead, and up to 256 MB of freed heap
  is kept for the next analysis (``mallopt``; glibc only, nothing elsewhere).
"""

from __future__ import annotations

import ctypes
import os
import sys

__all__ = ["BLAS_THREAD_VARIABLES", "tune_process"]

BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")
_M_TRIM_THRESHOLD, _M_MMAP_THRESHOLD = -1, -3  # glibc's mallopt parameters
MMAP_THRESHOLD_BYTES = 32 * 1024 * 1024  # the largest glibc accepts on 64-bit
TRIM_THRESHOLD_BYTES = 256 * 1024 * 1024


def tune_process() -> bool:
    """Set both; True when numpy was not yet imported (the BLAS setting takes effect)."""
    for name in BLAS_THREAD_VARIABLES:
        os.environ.setdefault(name, "1")
    _keep_freed_arrays()
    return "numpy" not in sys.modules


def _keep_freed_arrays() -> None:
    if not sys.platform.startswith("linux"):
        return
    try:
        mallopt = ctypes.CDLL(None).mallopt  # the C library the interpreter runs on
    except (OSError, AttributeError):  # not glibc (musl has no mallopt)
        return
    mallopt.argtypes, mallopt.restype = (ctypes.c_int, ctypes.c_int), ctypes.c_int
    mallopt(_M_MMAP_THRESHOLD, MMAP_THRESHOLD_BYTES)
    mallopt(_M_TRIM_THRESHOLD, TRIM_THRESHOLD_BYTES)
