"""A take read at another target than the one the plan expects in its row (positioning's
test cycle, ISO 230-2): the reading is nearer another target of the plan than its own.

The threshold is half the distance from the row's target to the neighbouring target on the
side the reading lies — the point where another target becomes the nearer one. At an end
target read beyond the end (no target there) it is half the distance to the one
neighbour: a reading that far out is as far from its target as the nearest other target
is. Targets unevenly spaced each have their own two halves. The polygon's check is the
same with the pitch 360°/N between faces (app/capture/panel.py). The reading is kept
(never dropped): the window warns, naming the row, the target and the reading.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass

__all__ = ["OffTarget", "off_target"]


@dataclass(frozen=True)
class OffTarget:
    """A reading further from its ``target`` than half the ``gap`` to ``neighbour``."""

    reading: float
    target: float
    #: the neighbouring target the threshold is half the distance to
    neighbour: float
    #: |neighbour − target|
    gap: float

    @property
    def off(self) -> float:
        """reading − target."""
        return self.reading - self.target


def off_target(reading: float, target: float, targets: Iterable[float]) -> OffTarget | None:
    """The reading's :class:`OffTarget` when it is more than half the distance to the
    neighbouring target from ``target`` (see the module); None when it is within it, or
    the plan has no other target, or a number is not finite."""
    if not (math.isfinite(reading) and math.isfinite(target)):
        return None
    same = 1e-9 * max(1.0, abs(target))
    others = sorted(t for t in {float(t) for t in targets}
                    if math.isfinite(t) and abs(t - target) > same)
    if not others:
        return None
    above = [t for t in others if t > target]
    below = [t for t in others if t < target]
    off = reading - target
    # the neighbour on the side the reading lies; at an end target read beyond the end
    # (no target there), the one neighbour it has
    side = above if off > 0 else below
    neighbour = (min(side) if off > 0 else max(side)) if side else \
        (min(above) if above else max(below))
    gap = abs(neighbour - target)
    if abs(off) <= gap / 2.0:
        return None
    return OffTarget(reading, target, neighbour, gap)
