"""The Allan deviation of an instrument's output: how its noise averages down.

For frames y_1 … y_N taken every τ0 seconds, at τ = m·τ0 the overlapping Allan variance
(IEEE Std 1139; Riley, NIST SP 1065, eq. 12, with the frames as the "fractional
frequency" samples) is

    σ²(τ) = 1 / (2 (N − 2m + 1)) · Σ_j (ȳ_{j+m} − ȳ_j)²,   j = 1 … N − 2m + 1

where ȳ_j is the mean of the m frames starting at j. White noise of standard
deviation σ gives σ(τ) = σ/√m; a steady drift D per second gives σ(τ) = D·τ/√2, so
the minimum shows how long averaging still helps.
"""

from __future__ import annotations

import numpy as np

__all__ = ["allan_deviation", "octave_factors"]


def octave_factors(n: int) -> np.ndarray:
    """m = 1, 2, 4, … while at least two averages of m frames fit (N ≥ 2m)."""
    if n < 2:
        return np.array([], dtype=int)
    return 2 ** np.arange(int(np.floor(np.log2(n // 2))) + 1)


def allan_deviation(values, tau0_s: float, factors=None) -> tuple[np.ndarray, np.ndarray]:
    """τ (s) and the overlapping Allan deviation at each averaging factor m (default:
    octaves). Factors with fewer than 2m frames are left out."""
    y = np.asarray(values, dtype=float)
    if y.ndim != 1 or not np.all(np.isfinite(y)):
        raise ValueError("the Allan deviation needs one finite series")
    if not tau0_s > 0:
        raise ValueError("the frame interval must be greater than 0")
    m = octave_factors(len(y)) if factors is None else np.asarray(factors, dtype=int)
    m = m[(m >= 1) & (2 * m <= len(y))]
    cumulative = np.concatenate(([0.0], np.cumsum(y - y.mean())))
    deviations = []
    for k in m:
        means = (cumulative[k:] - cumulative[:-k]) / k  # mean of frames j … j+k-1
        steps = means[k:] - means[:-k]
        deviations.append(np.sqrt(0.5 * np.mean(steps ** 2)))
    return m * tau0_s, np.array(deviations)
