"""ISO 230-2 evaluation of repeated runs (positional deviations of an axis).

For each target position i and approach direction (↑ forward, ↓ backward)
with j = 1…n runs: mean deviation x̄, standard uncertainty s (n − 1),
reversal value B_i = x̄↑ − x̄↓, repeatability R↑ = 4 s↑,
R_i = max(2s↑ + 2s↓ + |B_i|, R↑, R↓), bidirectional mean M_i = (x̄↑ + x̄↓)/2.
Axis figures: E↑/E↓/E (systematic deviation), M (mean bidirectional),
R, B, B̄ (mean reversal, ISO 230-2:2014) and A (accuracy, x̄ ± 2s envelope). All values in the input's unit.

A and R are taken over every target (ISO 230-2, 3.22–3.25): where a target has a mean
deviation but was approached only once in a direction, its s is unknown and A, R of that
direction (and the bidirectional A, R) are not evaluated — never an envelope of the other
targets alone, which could fall below E (:attr:`Iso230Result.approached_once` names them).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from models.messages import QT_TR_NOOP, message, separated

__all__ = ["DirectionStats", "Iso230Result", "iso230_evaluate", "once_note"]


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
    #: direction ("up"/"down") → the targets approached exactly once that way (their s is
    #: unknown, so A and R are not evaluated)
    approached_once: dict[str, np.ndarray] = field(default_factory=dict)

    @staticmethod
    def complete(stats: DirectionStats) -> bool:
        """Whether every target with a mean has its s (A and R are determined)."""
        has_mean = stats.runs > 0
        return bool(np.any(has_mean)) and bool(np.all(np.isfinite(stats.std[has_mean])))


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
        if values.size and np.ptp(values) == 0.0:
            # readings alike: exactly their value and no scatter (numpy's sum left 2e-16 of
            # −1.66 read five times, and the checks for readings alike missed it)
            mean[i], std[i] = values[0], 0.0 if values.size > 1 else std[i]
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
        once = stats.runs == 1
        if np.any(once):
            result.approached_once[name] = positions[once]
        if Iso230Result.complete(stats):
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
        if np.any(np.isfinite(rbi)) and Iso230Result.complete(fwd) and \
                Iso230Result.complete(bwd):
            figures["R"] = float(np.nanmax(rbi))
            upper = np.concatenate([fwd.mean + 2 * fwd.std, bwd.mean + 2 * bwd.std])
            lower = np.concatenate([fwd.mean - 2 * fwd.std, bwd.mean - 2 * bwd.std])
            figures["A"] = float(np.nanmax(upper) - np.nanmin(lower))
    result.figures = figures
    return result


def once_note(result: Iso230Result, unit: str = ""):
    """Why A and R are not evaluated, naming the targets approached once; ``None`` when
    every target has its s."""
    parts = []
    for name, where in result.approached_once.items():
        targets = ", ".join(f"{t:g}{unit}" for t in where)
        parts.append(message(QT_TR_NOOP("forward at {targets}") if name == "up" else
                             QT_TR_NOOP("backward at {targets}"), targets=targets))
    if not parts:
        return None
    return message(QT_TR_NOOP("A and R not evaluated (ISO 230-2 takes them over every target): "
                              "approached only once, so no standard deviation, {where}"),
                   where=separated(parts, "; "))
