"""The positioning workbench's guidance while readings come from an instrument (an
encoder's readout, a theodolite): the target to move the axis to, with the run and the
approach direction of the test plan (models/capture/guidance.py).

The target, run and direction are the current row's cells — the test plan's next point,
which the window puts there (day review 74 F6: with a plan the instrument panel said
nothing while the table's caption said "next: target 0°, run 2 ↑"). A target typed
without a plan is said alone; with no target the operator is asked for one. Each
approach of a target is one reading: the next take waits for the axis to move."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from models.messages import QT_TR_NOOP, message

if TYPE_CHECKING:  # the guide's module is loaded when a guide is asked for (the window's)
    from models.capture.guidance import NextReading

__all__ = ["positioning_guide"]

#: the target unit's symbol as the plan writes it (models/positioning/model.py TARGET_UNITS)
_SYMBOLS = {"deg": "°", "mm": " mm"}
#: a direction cell's words (models/positioning/analysis.py UP, DOWN) and its arrow
_ARROWS = {**dict.fromkeys(("+", "↑", "up"), "↑"), **dict.fromkeys(("-", "−", "↓", "down"), "↓")}


def _number(text: str) -> float | None:
    try:
        value = float(str(text).strip().replace(",", ".").rstrip("°").strip())
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def positioning_guide(rows: Sequence[Mapping[str, str]], current: Mapping[str, str],
                      settings: Mapping[str, Any], step: float = 0.0) -> NextReading:
    from models.capture.guidance import NextReading

    target = str(current.get("target", "")).strip()
    if _number(target) is None:
        return NextReading(message(QT_TR_NOOP("move the axis to the next target and type it "
                                              "in the target column")))
    unit = _SYMBOLS.get(str(settings.get("target_unit", "deg")), "°")
    shown = f"{target}{unit}" if not target.endswith(unit.strip()) else target
    run = str(current.get("run", "")).strip()
    arrow = _ARROWS.get(str(current.get("direction", "")).strip().lower())
    if run and arrow:  # the plan's words for its point (models/readings/entry_plan.py)
        return NextReading(message(QT_TR_NOOP("target {target}, run {run} {arrow}"),
                                   target=shown, run=run, arrow=arrow))
    return NextReading(message(QT_TR_NOOP("target {target}"), target=shown))
