"""ISO 230-2 evaluation of repeated runs (positional deviations of an axis).

For each target position i and approach direction (↑ forward, ↓ backward)
with j = 1…n runs: mean deviation x̄, standard uncertainty s (n − 1),
reversal value B_i = x̄↑ − x̄↓, repeatability R↑ = 4 s↑,
R_i = max(2s↑ + 2s↓ + |B_i|, R↑, R↓), bidirectional mean M_i = (x̄↑ + x̄↓)/2.
Axis figures: E↑/E↓/E (systematic deviation), M (mean bidirectional),
R, B, B̄ (mean reversal, ISO 230-2:2014) and A (accuracy, x̄ ± 2s envelope). All values in the input's unit.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["DirectionStats", "Iso230Result", "iso230_evaluate"]


@dataclass
class DirectionStats:
    """Per-position statistics for one approach direction."""

    mean: np.ndarray
    std: np.ndarray
    runs: np.ndarray

    @property
    def repeatability(self) -> np.ndarray:
        return 4.0 * self.std


@dataclass
class Iso230Result:
    positions: np.ndarray
    forward: DirectionStats | None
    backward: DirectionStats | None
    figures: dict[str, float] = field(default_factory=dict)
    reversal: np.ndarray | None = None
    bidirectional_repeatability: np.ndarray | None = None
    bidirectional_mean: np.ndarray | None = None


def _direction_stats(positions: np.ndarray, key: np.ndarray, dev: np.ndarray) -> DirectionStats:
    mean = np.full(positions.size, np.nan)
    std = np.full(positions.size, np.nan)
    runs = np.zeros(positions.size, dtype=int)
    for i, _ in enumerate(positions):
        values = dev[key == i]
        runs[i] = values.size
        if values.size:
            mean[i] = values.mean()
        if values.size > 1:
            std[i] = values.std(ddof=1)
    return DirectionStats(mean, std, runs)


def iso230_evaluate(
    target_positions: np.ndarray,
    deviations: np.ndarray,
    directions: np.ndarray | None = None,
    decimals: int = 6,
) -> Iso230Result:
    """Evaluate deviations measured at repeated target positions.

    Parameters
    ----------
    target_positions : array
        Target position of each reading (deg); readings at the same position
        (to ``decimals`` places) belong together.
    deviations : array
        Positional deviation of each reading (arcsec).
    directions : array of +1 / −1, optional
        Approach direction of each reading; all forward if omitted.
    """
    pos = np.round(np.asarray(target_positions, dtype=float), decimals)
    dev = np.asarray(deviations, dtype=float)
    dirs = np.ones_like(dev) if directions is None else np.sign(np.asarray(directions, float))
    positions, key = np.unique(pos, return_inverse=True)
    fwd = _direction_stats(positions, key[dirs > 0], dev[dirs > 0]) if np.any(dirs > 0) else None
    bwd = _direction_stats(positions, key[dirs < 0], dev[dirs < 0]) if np.any(dirs < 0) else None
    result = Iso230Result(positions, fwd, bwd)
    figures: dict[str, float] = {}
    for name, stats in (("up", fwd), ("down", bwd)):
        if stats is None:
            continue
        figures[f"E_{name}"] = float(np.nanmax(stats.mean) - np.nanmin(stats.mean))
        if np.any(np.isfinite(stats.std)):
            figures[f"R_{name}"] = float(np.nanmax(stats.repeatability))
            figures[f"A_{name}"] = float(
                np.nanmax(stats.mean + 2 * stats.std) - np.nanmin(stats.mean - 2 * stats.std)
            )
    if fwd is not None and bwd is not None:
        reversal = fwd.mean - bwd.mean
        result.reversal = reversal
        result.bidirectional_mean = 0.5 * (fwd.mean + bwd.mean)
        both = np.concatenate([fwd.mean, bwd.mean])
        figures["E"] = float(np.nanmax(both) - np.nanmin(both))
        if not np.any(np.isfinite(reversal)):  # no target approached both ways
            result.figures = figures
            return result
        figures["M"] = float(
            np.nanmax(result.bidirectional_mean) - np.nanmin(result.bidirectional_mean)
        )
        figures["B"] = float(np.nanmax(np.abs(reversal)))
        figures["B_mean"] = float(np.nanmean(reversal))
        # R_i needs both directions' s: a target with one of them unknown gives none
        rbi = np.maximum(np.maximum(2 * fwd.std + 2 * bwd.std + np.abs(reversal),
                                    fwd.repeatability), bwd.repeatability)
        if np.any(np.isfinite(rbi)):
            result.bidirectional_repeatability = rbi
            figures["R"] = float(np.nanmax(rbi))
            upper = np.concatenate([fwd.mean + 2 * fwd.std, bwd.mean + 2 * bwd.std])
            lower = np.concatenate([fwd.mean - 2 * fwd.std, bwd.mean - 2 * bwd.std])
            figures["A"] = float(np.nanmax(upper) - np.nanmin(lower))
    result.figures = figures
    return result
