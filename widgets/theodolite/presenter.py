"""Theodolite run workbench: the presenter (no widgets: it asks its view to draw)."""

from __future__ import annotations

import numpy as np

from models.theodolite.analysis import THEODOLITE
from models.theodolite.model import TheodoliteResult
from widgets.theodolite.view import TheodoliteView
from widgets.workbench_presenter import WorkbenchPresenter


class TheodolitePresenter(WorkbenchPresenter):
    """Runs the set-up identification on every edit and has the raw, model and corrected
    error drawn in θ order."""

    view_class = TheodoliteView

    def __init__(self, view: TheodoliteView | None = None, parent=None) -> None:
        super().__init__(THEODOLITE, view, parent)

    def show_result(self, result: TheodoliteResult) -> None:
        order = np.argsort(result.theta_deg, kind="stable")
        self.view.show_curves(result.theta_deg[order], result.raw_error_arcsec[order],
                              result.model_error_arcsec[order],
                              result.corrected_error_arcsec[order],
                              result.elevation_residuals_arcsec[order])

    def clear_result(self) -> None:
        self.view.clear_result()
