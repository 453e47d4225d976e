"""Positioning workbench: the presenter (no widgets: it asks its view)."""

from __future__ import annotations

from models.display_units import table_in_unit
from models.positioning import plots
from models.positioning.analysis import POSITIONING
from models.positioning.model import PositioningResult
from widgets.i18n import explained, tr, translated
from widgets.positioning.view import PositioningView
from widgets.workbench_presenter import WorkbenchPresenter


class PositioningPresenter(WorkbenchPresenter):
    """ISO 230-2 and VDI/DGQ 3441 on every edit; exports the compensation table."""

    view_class = PositioningView

    def __init__(self, view: PositioningView | None = None, parent=None) -> None:
        super().__init__(POSITIONING, view, parent)

    def show_result(self, result: PositioningResult) -> None:
        self.view.show_figures(*self.in_unit(plots.deviation_figure(result),
                                             plots.reversal_figure(result),
                                             plots.readings_figure(result)))
        self.view.show_per_target(*table_in_unit(*result.per_target_table(), self.angle_unit))
        if not result.minimum_runs_met:
            self.view.append_to_readings_caption(tr(" — fewer than 5 runs: flagged"))

    def clear_result(self) -> None:
        self.view.clear_result()

    def export_compensation_dialog(self) -> None:
        if self.result is None:
            return
        linuxcnc = self._settings["compensation_format"] == "linuxcnc"
        path = self.view.ask_compensation_path(
            "compensation.txt" if linuxcnc else "compensation.csv", linuxcnc)
        if path:
            self.export_compensation(path)

    def export_compensation(self, path: str) -> str:
        """Write the table as set up; a table that cannot be made is told, not written."""
        try:
            what = self.kind.correction_table(self.result, self._settings, path)
        except (ValueError, OSError) as exc:
            self.view.tell(tr("Cannot export the compensation table"),
                           explained(exc))
            return ""
        self.view.show_status(tr("{what} written").format(what=translated(what)))
        return what
