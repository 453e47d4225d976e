"""Summary statistics of an error curve (all in arcsec)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["ErrorStats", "error_stats"]


@dataclass(frozen=True)
class ErrorStats:
    """min, max, peak-to-peak, mean and RMS of an error curve, in arcsec.

    ``rms`` is the root mean square about zero; ``std`` the sample standard
    deviation about the mean (n − 1).
    """

    n: int
    min: float
    max: float
    peak_to_peak: float
    mean: float
    rms: float
    std: float

    def as_dict(self) -> dict[str, float]:
        return {
            "n": self.n, "min": self.min, "max": self.max, "peak_to_peak": self.peak_to_peak,
            "mean": self.mean, "rms": self.rms, "std": self.std,
        }


def error_stats(error_arcsec: np.ndarray) -> ErrorStats:
    e = np.asarray(error_arcsec, dtype=float)
    e = e[np.isfinite(e)]
    if e.size == 0:
        nan = float("nan")
        return ErrorStats(0, nan, nan, nan, nan, nan, nan)
    std = float(np.std(e, ddof=1)) if e.size > 1 else 0.0
    return ErrorStats(
        int(e.size), float(e.min()), float(e.max()), float(np.ptp(e)), float(e.mean()),
        float(np.sqrt(np.mean(e**2))), std,
    )
