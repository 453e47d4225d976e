"""Timing helpers shared by the benchmarks."""

from __future__ import annotations

import time

import numpy as np


def timings(fn, repeats: int, warmup: int = 1) -> np.ndarray:
    """Seconds of ``repeats`` calls of ``fn`` after ``warmup`` untimed calls."""
    for _ in range(warmup):
        fn()
    out = np.empty(repeats)
    for i in range(repeats):
        t0 = time.perf_counter()
        fn()
        out[i] = time.perf_counter() - t0
    return out


def fmt_time(seconds: np.ndarray | float) -> str:
    """Median (p25–p75) with a unit that suits it."""
    s = np.atleast_1d(np.asarray(seconds, dtype=float))
    med, lo, hi = np.median(s), np.percentile(s, 25), np.percentile(s, 75)
    unit, scale = (("s", 1.0) if med >= 1 else ("ms", 1e3) if med >= 1e-3 else ("µs", 1e6))
    digits = 3 if med * scale < 10 else 1
    if s.size == 1:
        return f"{med * scale:.{digits}f} {unit}"
    return f"{med * scale:.{digits}f} {unit} ({lo * scale:.{digits}f}–{hi * scale:.{digits}f})"
