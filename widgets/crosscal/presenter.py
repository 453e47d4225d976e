"""Cross-calibration (polygon + encoder) workbench: the presenter (no widgets: it asks
its view)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from models.crosscal import plots
from models.crosscal.analysis import CROSSCAL, CrossCalResult
from widgets.crosscal.view import CrossCalView
from widgets.i18n import explained, tr, translated
from widgets.workbench_presenter import WorkbenchPresenter


class CrossCalPresenter(WorkbenchPresenter):
    """Encoder errors and face deviations, with their U, on every edit."""

    view_class = CrossCalView

    def __init__(self, view: CrossCalView | None = None, parent=None) -> None:
        super().__init__(CROSSCAL, view, parent)
        #: the details this workbench's certificate would be issued with now (the main
        #: window sets it: app/certificate_presenter.py issue_details): the face-deviation
        #: file states the U from face 1 that certificate states
        self.issue_details: Callable[[], Any] = lambda: self.certificate_details()

    def certified_u(self, result: CrossCalResult) -> tuple[Any, Any]:
        """(U of E, U of d) per point as each item's certificate states them with the details
        it would be issued with now (:attr:`issue_details`: the workbench's details, the lab
        defaults filled in — the comparators' U, the resolution, the coverage probability):
        the plots' ±U bands are drawn with them. (None, None) where the details give no
        budget (the bands then the readings' own U)."""
        details = self.issue_details()
        if details is None:
            return None, None
        try:
            budgets = self.kind.uncertainty_budgets(result, details, self.result_settings)
        except (ValueError, ArithmeticError, IndexError):
            return None, None
        return tuple(getattr(budgets.get(name), "expanded", None)  # type: ignore[return-value]
                     for name in ("encoder_error_arcsec", "polygon_deviation_arcsec"))

    def printed_details(self) -> Any:
        """As the certificate rounds, with the details it would be issued with now (the lab
        defaults in: :meth:`certified_u`), so the summary's U is the bands'."""
        return self.issue_details()

    def show_result(self, result: CrossCalResult) -> None:
        self.table_model.set_highlight_rows({int(i) for i in result.readings.sheet_rows[
            result.readings.closure] - 1})
        u_encoder, u_polygon = self.certified_u(result)
        self.view.show_figures(*self.in_unit(
            plots.encoder_figure(result, self.parsed, u_encoder),
            plots.polygon_figure(result, u_polygon),
            plots.residual_figure(result), plots.closure_figure(result)))
        self.view.set_reference_enabled(result.solution.polygon_deviation_arcsec is not None)

    def clear_result(self) -> None:
        self.table_model.set_highlight_rows(set())
        self.view.clear_result()
        self.view.set_reference_enabled(False)

    def save_polygon_reference_dialog(self) -> str:
        if self.result is None:
            return ""
        path = self.view.ask_reference_path()
        return self.save_polygon_reference(path) if path else ""

    def save_polygon_reference(self, path: str) -> str:
        """The face deviations (from face 1, with the U the certificate states with its
        details) as the polygon workbench loads a certificate; a design that does not
        determine them is told, not written."""
        if self.output_refused(path, tr("Cannot save the face deviations")):
            return ""
        try:
            what = self.kind.correction_table(self.result, self._settings, path,
                                              self.issue_details())
        except (ValueError, OSError) as exc:
            self.view.tell(tr("Cannot save the face deviations"), explained(exc))
            return ""
        self.view.show_status(tr("{what} written: load them in the polygon workbench with "
                                 "'Load polygon certificate…'").format(what=translated(what)))
        return what
