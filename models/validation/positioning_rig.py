"""An axis positioned to targets and read by a reference, from first principles.

This helper imports nothing from ``models`` but numpy: it knows what a driven axis does
(it reaches its commanded position plus its own systematic error, lags by half its lost
motion behind the direction it moves in, drifts from run to run and scatters) and how
the ISO 230-2 standard test cycle runs (each run goes up through every target and back
down, overtravelling at the ends). Nothing of the standards' formulas is here.

Positions and errors are in the axis unit (degrees or millimetres).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

Controller = Callable[[float, int], float]  # (target, direction) -> commanded position


@dataclass
class AxisRig:
    """``error(position)``: the systematic error of the axis at a commanded position;
    ``lost_motion``: the backlash (the axis stops lost_motion/2 short in the direction it
    moves); ``drift_per_run``: a thermal drift added run after run; ``noise``: the axis's
    scatter (1σ) on each approach; ``reference_noise``: the reference's reading noise."""

    error: Callable[[np.ndarray], np.ndarray]
    lost_motion: float = 0.0
    drift_per_run: float = 0.0
    noise: float = 0.0
    reference_noise: float = 0.0
    rng: np.random.Generator | None = None
    controller: Controller | None = None

    def _normal(self) -> float:
        return float(self.rng.normal()) if self.rng is not None else 0.0

    def reach(self, target: float, direction: int, run: int) -> float:
        """The actual position the axis stops at."""
        commanded = target if self.controller is None else self.controller(target, direction)
        return (commanded + float(self.error(np.asarray(commanded)))
                - direction * self.lost_motion / 2.0 + self.drift_per_run * (run - 1)
                + self.noise * self._normal())

    def read(self, actual: float) -> float:
        """The reference's reading of an actual position (zeroed at the axis's zero)."""
        return actual + self.reference_noise * self._normal()

    def true_mean_deviation(self, target: float, direction: int, runs: int) -> float:
        """What the mean deviation over ``runs`` runs would be without scatter."""
        commanded = target if self.controller is None else self.controller(target, direction)
        return (commanded - target + float(self.error(np.asarray(commanded)))
                - direction * self.lost_motion / 2.0
                + self.drift_per_run * (runs - 1) / 2.0)

    def standard_cycle(self, targets, runs: int = 5, directions: tuple[int, ...] = (1, -1)
                       ) -> list[tuple[float, int, int, float]]:
        """(target, run, direction, reference reading) in the order measured: each run goes
        up through the targets, then down (ISO 230-2 standard test cycle)."""
        targets = sorted(float(t) for t in targets)
        out = []
        for run in range(1, runs + 1):
            for direction in directions:
                order = targets if direction > 0 else targets[::-1]
                for t in order:
                    out.append((t, run, direction, self.read(self.reach(t, direction, run))))
        return out
