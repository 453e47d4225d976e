"""Plots declared once, as data: curves, axes, labels, units.

Each workbench's ``plots`` module turns its result into :class:`PlotFigure`\\ s;
the window draws them with pyqtgraph and the certificate with the PDF writer,
so a curve, its name and its unit are written in one place. ``role`` tells the
window's error plot where a series goes (raw and model on the upper panel,
corrected on its own); the PDF draws every series of a figure on one chart.
``y_unit`` is the unit of every series' y values and bands, as data (a key of
models.quantity.UNITS; empty when they are not a quantity of ours, volts say): given,
or read once from the y title's unit when the figure is declared.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["PlotFigure", "PlotSeries"]


@dataclass(frozen=True)
class PlotSeries:
    label: str
    x: np.ndarray
    y: np.ndarray
    color: tuple[int, int, int] = (31, 119, 180)
    markers: bool = False
    band: np.ndarray | None = None  # ± half-width drawn as a shaded band around y
    role: str = ""  # "raw", "model", "corrected", "residual" for the window's error plot
    dashed: bool = False  # drawn with a dashed line (the positioning runs: the down direction)


@dataclass(frozen=True)
class PlotFigure:
    title: str
    x_label: str
    y_label: str
    series: tuple[PlotSeries, ...]
    y_unit: str = ""  # the unit of the y values (models.quantity), "" when not one of ours

    def __post_init__(self) -> None:
        if not self.y_unit:
            from models.quantity import unit_of_title

            object.__setattr__(self, "y_unit", unit_of_title(self.y_label))

    def by_role(self, role: str) -> PlotSeries | None:
        return next((s for s in self.series if s.role == role), None)
