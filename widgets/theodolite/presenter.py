"""Theodolite run workbench: the presenter (no widgets: it asks its view to draw)."""

from __future__ import annotations

import numpy as np

from models.messages import QT_TR_NOOP
from models.theodolite import plots
from models.theodolite.analysis import THEODOLITE
from models.theodolite.model import TheodoliteResult
from models.tolerance_band import with_tolerance
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
        self.view.show_figures(*self.in_unit(self._with_tolerance(plots.error_figure(result),
                                                                  result),
                                             plots.residual_figure(result)), **extra)

    def _with_tolerance(self, figure, result: TheodoliteResult):
        """The corrected error with its U band and ±T where the certificate details set a
        tolerance (models/tolerance_band.py); drawn on the corrected error's panel."""
        tolerance, expanded, quantity = self.tolerance_bands(result)
        if tolerance is None:
            return figure
        order = np.argsort(result.theta_deg, kind="stable")
        u = expanded.get("corrected_error_arcsec")
        return with_tolerance(figure, tolerance, [(
            QT_TR_NOOP("corrected ± U"), result.theta_deg[order], result.corrected_error_arcsec[order],
            None if u is None else np.asarray(u, dtype=float)[order])], quantity)

    def clear_result(self) -> None:
        self.view.clear_result()
