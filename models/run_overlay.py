"""A second run drawn against today's: before and after compensation, or this instrument's
earlier certificate from the register, on the same axes.

The other run is analysed again from its readings — a readings file (with today's
settings), a project file or a register record (each with the settings it was analysed
with) — by the same workbench, so both curves are the same quantity computed the same
way; its certified curve (the corrected error, or the compensated one of a fringe run)
is what is overlaid. Nothing of it is guessed: a file of another workbench, or readings
this workbench cannot analyse, is refused with the reason.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from models.messages import QT_TR_NOOP, message, reason_of
from models.plots import PlotFigure
from models.workbench import OverlaysRuns, Workbench

__all__ = ["PROJECT_SUFFIX", "OverlayRun", "overlay_from_file",
           "overlay_from_project_json", "overlay_run"]

PROJECT_SUFFIX = ".json"  # a project file (.anglebench.json); other files are readings


@dataclass(frozen=True)
class OverlayRun:
    """The other run: what the legend calls it, and its curve as a declared figure (the
    angles in arcseconds, converted like today's when drawn)."""

    label: str
    figure: PlotFigure

    @property
    def x(self):
        return self.figure.series[0].x

    @property
    def y(self):
        return self.figure.series[0].y


def _figure(kind: OverlaysRuns, result: Any) -> PlotFigure:
    figure = kind.overlay_figure(result)
    corrected = figure.by_role("corrected")
    if corrected is None:
        raise ValueError(message(QT_TR_NOOP("the other run has no corrected curve to draw")))
    return PlotFigure(figure.title, figure.x_label, figure.y_label, (corrected,))


def overlay_run(kind: Workbench, rows: Sequence[Sequence[str]], settings: Mapping[str, Any] | None,
                label: str) -> OverlayRun:
    """The run of ``rows`` analysed by ``kind`` with ``settings``; ValueError saying why it
    cannot be drawn."""
    from models.readings.sheet import ReadingsSheet

    if not isinstance(kind, OverlaysRuns):
        raise ValueError(message(QT_TR_NOOP("the {workbench} workbench has no error curve to "
                                            "overlay"), workbench=kind.title))
    parsed = ReadingsSheet(kind.columns, rows).parse()
    try:
        result = kind.analyze(parsed, kind.settings_with_defaults(settings))
    except (ValueError, ArithmeticError) as exc:
        raise ValueError(message(QT_TR_NOOP("{label}: the run cannot be analysed: {reason}"),
                                 label=label, reason=reason_of(exc))) from None
    return OverlayRun(label, _figure(kind, result))


def _from_project(kind: Workbench, project: Any, label: str) -> OverlayRun:
    state = project.workbenches.get(kind.key)
    if state is None or not state.rows:
        raise ValueError(message(QT_TR_NOOP("{label} holds no readings of the {workbench} "
                                            "workbench"), label=label, workbench=kind.title))
    return overlay_run(kind, state.rows, state.settings, label)


def overlay_from_project_json(kind: Workbench, text: str, label: str) -> OverlayRun:
    """The run this workbench holds in a project (a register record's JSON), with the
    settings it was analysed with."""
    from models.project.file import project_from_json

    return _from_project(kind, project_from_json(text, label, {kind.key: kind}), label)


def overlay_from_file(kind: Workbench, path: str | Path, settings: Mapping[str, Any] | None
                      ) -> OverlayRun:
    """The run in a readings file (CSV/XLSX/TXT, analysed with ``settings``: today's) or a
    project file (with its own)."""
    from models.readings.tabular_import import map_columns, read_table

    path = Path(path)
    label = path.name
    if path.suffix.lower() == PROJECT_SUFFIX:
        from models.project.file import load_project

        return _from_project(kind, load_project(path, {kind.key: kind}), label)
    rows = map_columns(read_table(path), kind.columns)
    return overlay_run(kind, rows, settings, label)
