"""Theodolite run workbench: the presenter (no widgets: it asks its view to draw)."""

from __future__ import annotations

from models.theodolite import plots
from models.theodolite.analysis import THEODOLITE
from models.theodolite.model import TheodoliteResult
from widgets.theodolite.view import TheodoliteView
from widgets.workbench_presenter import WorkbenchPresenter


class TheodolitePresenter(WorkbenchPresenter):
    """Runs the set-up identification on every edit and has its declared figures drawn."""

    view_class = TheodoliteView

    def __init__(self, view: TheodoliteView | None = None, parent=None) -> None:
        super().__init__(THEODOLITE, view, parent)

    def show_result(self, result: TheodoliteResult) -> None:
        passes = plots.passes_figure(result)
        extra = {} if passes is None else {"passes": self.in_unit(passes)[0]}
        self.view.show_figures(*self.in_unit(plots.error_figure(result),
                                             plots.residual_figure(result)), **extra)

    def clear_result(self) -> None:
        self.view.clear_result()
