"""Before and after compensation: two positioning logs of the same axis, the second
measured with the compensation table active, and what the table bought in A, B and E
(with M and R).

Both logs are evaluated over the same targets: where one log has targets the other has
not, those readings are left out of both and the figures re-evaluated (ISO 230-2, the
same code as the workbench), so an "improvement" is never a smaller range of targets.
Logs in other units, or without a common target, cannot be compared and are refused.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from models.messages import QT_TR_NOOP, joined, message, reason_of
from models.plots import PlotFigure, PlotSeries
from models.positioning.model import PositioningResult, evaluate, figure_text

__all__ = ["AFTER_COLOUR", "BIDIRECTIONAL_FIGURES", "BeforeAfter", "FigureChange", "after_figure",
           "before_after", "log_from_file"]

AFTER_COLOUR = (230, 126, 34)  # the overlaid run's orange (widgets/run_overlay.py)

#: the figures compared when both logs are bidirectional (A, B, E first: the issue's three)
BIDIRECTIONAL_FIGURES = ("A", "B", "E", "M", "R")
#: per direction otherwise
DIRECTIONAL_FIGURES = ("A", "E", "R")
DECIMALS = 9  # targets equal to this many places are the same target (as iso230_evaluate)


@dataclass(frozen=True)
class FigureChange:
    """One figure before and after; ``None`` where a log could not determine it."""

    key: str
    before: float | None
    after: float | None

    @property
    def improvement(self) -> float | None:
        """before − after (positive: the axis got better)."""
        if self.before is None or self.after is None:
            return None
        return self.before - self.after

    @property
    def percent(self) -> float | None:
        """The improvement as a percentage of ``before`` (None when before is 0)."""
        if self.improvement is None or self.before == 0:
            return None
        return 100.0 * self.improvement / self.before


@dataclass(frozen=True)
class BeforeAfter:
    figures: tuple[FigureChange, ...]
    deviation_unit: str
    symbol: str
    targets: np.ndarray  # the common targets both were evaluated over
    left_out: dict[str, int]  # "before"/"after" → readings at targets the other log lacks

    def __getitem__(self, key: str) -> FigureChange:
        for change in self.figures:
            if change.key == key:
                return change
        raise KeyError(key)

    def as_dict(self) -> dict[str, Any]:
        return {"deviation_unit": self.deviation_unit,
                "targets": [float(t) for t in self.targets],
                "left_out_readings": dict(self.left_out),
                "figures": {c.key: {"before": c.before, "after": c.after,
                                    "improvement": c.improvement, "improvement_percent": c.percent}
                            for c in self.figures}}

    def text(self, name: str = "") -> str:
        """One line: "Before → after compensation (name): A 12.3" → 3.1" (−75 %), …"."""
        parts: list = [message(QT_TR_NOOP("Before → after compensation ({name}, {count} common "
                                          "targets): "), name=name or "—", count=self.targets.size)]
        for i, c in enumerate(self.figures):
            change = ("" if c.percent is None else f" ({-c.percent:+.0f} %)")
            parts += [", " if i else "", f"{c.key} ", figure_text(c.before, self.symbol), " → ",
                      figure_text(c.after, self.symbol), change]
        left = sum(self.left_out.values())
        if left:
            parts.append(message(QT_TR_NOOP("; {count} reading(s) at targets only one log has "
                                            "left out"), count=left))
        return joined(parts)


def _refuse(template: str, **figures: Any) -> ValueError:
    return ValueError(message(template, **figures))


def _restricted(result: PositioningResult, keep: np.ndarray) -> PositioningResult:
    """``result`` evaluated again with the readings at ``keep`` targets only."""
    pick = np.isin(np.round(result.targets, DECIMALS), keep)
    if pick.all():
        return result
    return evaluate(result.targets[pick], result.runs[pick], result.directions[pick],
                    result.deviations[pick], result.rows[pick], result.target_unit,
                    result.deviation_unit, result.standard, [])


def _value(figures: dict[str, float], key: str) -> float | None:
    value = figures.get(key)
    return float(value) if value is not None and math.isfinite(value) else None


def before_after(before: PositioningResult, after: PositioningResult) -> BeforeAfter:
    """A, B, E (M, R) of ``before`` and ``after`` over their common targets; ValueError
    saying why the two logs cannot be compared."""
    if before.target_unit != after.target_unit:
        raise _refuse(QT_TR_NOOP("the log after compensation has targets in {after}, the log "
                                 "before in {before}: not the same axis set-up"),
                      after=after.target_unit, before=before.target_unit)
    if before.deviation_unit != after.deviation_unit:
        raise _refuse(QT_TR_NOOP("the log after compensation has deviations in {after}, the log "
                                 "before in {before}: analyse both in the same deviation unit"),
                      after=after.deviation_unit, before=before.deviation_unit)
    common = np.intersect1d(np.round(before.positions, DECIMALS),
                            np.round(after.positions, DECIMALS))
    if common.size == 0:
        raise _refuse(QT_TR_NOOP("the log after compensation has no target in common with the "
                                 "log before: they cannot be compared"))
    b, a = _restricted(before, common), _restricted(after, common)
    if b.bidirectional and a.bidirectional:
        keys = BIDIRECTIONAL_FIGURES
    else:
        dirs = [n for n, _, _ in b.directions_present() if n in {m for m, _, _ in
                                                                    a.directions_present()}]
        if not dirs:
            raise _refuse(QT_TR_NOOP("the two logs have no approach direction in common: they "
                                     "cannot be compared"))
        keys = tuple(f"{f}_{n}" for n in dirs for f in DIRECTIONAL_FIGURES)
    changes = tuple(FigureChange(k, _value(b.iso.figures, k), _value(a.iso.figures, k))
                    for k in keys)
    left = {"before": int(before.deviations.size - b.deviations.size),
            "after": int(after.deviations.size - a.deviations.size)}
    return BeforeAfter(changes, before.deviation_unit, before.symbol, common, left)


def after_figure(after: PositioningResult) -> PlotFigure:
    """The log after compensation as the deviation plot draws it over the log before: its
    mean deviation per target, one dashed series per direction (↑, ↓), in its units."""
    series = tuple(PlotSeries("↑" if name == "up" else "↓", after.positions, stats.mean,
                              AFTER_COLOUR, True, dashed=True)
                   for name, _, stats in after.directions_present())
    return PlotFigure(QT_TR_NOOP("Mean positional deviation with ±2s"),
                      f"target position ({after.target_symbol.strip()})",
                      f"deviation ({after.symbol.strip()})", series)


def log_from_file(path: str | Path, settings: Mapping[str, Any] | None,
                  workbench: Any) -> PositioningResult:
    """The positioning log in a readings file (CSV/XLSX/TXT, analysed with ``settings``:
    today's) or a project file (its positioning readings with their own settings);
    ValueError saying why it cannot be analysed. ``workbench``: the positioning workbench
    (models.positioning.analysis.workbench, which passes itself: this module does not
    import it)."""
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table

    path = Path(path)
    if path.suffix.lower() == ".json":
        from models.project.file import load_project

        state = load_project(path, {workbench.key: workbench}).workbenches.get(workbench.key)
        if state is None or not state.rows:
            raise _refuse(QT_TR_NOOP("{label} holds no readings of the {workbench} workbench"),
                          label=path.name, workbench=workbench.title)
        rows, settings = state.rows, state.settings
    else:
        rows = map_columns(read_table(path), workbench.columns)
    parsed = ReadingsSheet(workbench.columns, rows).parse()
    try:
        return workbench.analyze(parsed, workbench.settings_with_defaults(settings))
    except (ValueError, ArithmeticError) as exc:
        raise _refuse(QT_TR_NOOP("{label}: the run cannot be analysed: {reason}"),
                      label=path.name, reason=reason_of(exc)) from None
