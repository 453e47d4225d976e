"""Fringe signal analysis workbench: the presenter (no widgets: it hands its view arrays
to draw and asks it for file names)."""

from __future__ import annotations

from models.fringe import plots
from models.fringe.analysis import FRINGE, FringeResult
from models.fringe.signal_quality import SignalQuality, default_window, signal_quality
from widgets.fringe.live_signals import INSTRUMENT as LIVE_INSTRUMENT
from widgets.fringe.view import FringeView
from widgets.i18n import explained, tr, translated
from widgets.workbench_presenter import WorkbenchPresenter


class FringePresenter(WorkbenchPresenter):
    """Fits both channels, builds the correction table and shows before/after errors."""

    view_class = FringeView

    def __init__(self, view: FringeView | None = None, parent=None) -> None:
        super().__init__(FRINGE, view, parent)

    def prepare_display(self, result: FringeResult) -> dict:
        """The declared figures, envelopes and all: pure numpy, run on the worker thread
        for a large run (a million samples draw in a few ms as envelopes)."""
        return plots.figures(result)

    def show_result(self, result: FringeResult) -> None:
        figures = self.display if isinstance(self.display, dict) else self.prepare_display(result)
        self.view.show_figures(dict(zip(figures, self.in_unit(*figures.values()), strict=True)))
        self.view.show_signal_quality(lambda preset: self.signal_quality(result, preset))

    def signal_quality(self, result: FringeResult, preset) -> SignalQuality | None:
        """The signals along the record, per window of periods, judged against ``preset``
        (None: in the record's units); None when the record has no per-period fits."""
        periods = getattr(result, "sin_periods", None)
        if result is None or periods is None or len(periods) == 0:
            return None
        try:
            return signal_quality(result, preset, periods_per_window=default_window(result, 400))
        except ValueError:
            return None

    def clear_result(self) -> None:
        self.view.clear_result()

    def take_live_signals(self, u_sin, u_cos) -> None:
        """The live view's window as the record: its samples replace the readings (one undo
        step, as an import does), each channel's voltage written with 12 significant digits
        (what the capture's raw lines say, so an edit after the take is seen); the phase is
        left to be estimated from the signals."""
        keys = [c.key for c in self.sheet.columns]
        rows = []
        for s, c in zip(u_sin.tolist(), u_cos.tolist(), strict=True):
            values = {"u_sin": f"{s:.12g}", "u_cos": f"{c:.12g}"}
            rows.append([values.get(k, "") for k in keys])
        # the earlier takes of the stream replaced in the same undo step as their readings
        self.table_model.replace_all(rows, tr("Take live signals ({n} samples)").format(
            n=len(rows)), checked=True, replaces=LIVE_INSTRUMENT)
        self._fit_columns()
        self.schedule_refresh()
        self.view.show_status(tr("{n} samples taken from the live signals").format(n=len(rows)))

    def export_table_dialog(self) -> None:
        if self.result is None:
            return
        path = self.view.ask_table_path()
        if path:
            self.export_table(path)

    def export_table(self, path: str) -> str:
        """Write the correction table through the kind (as the command line does); a table
        that cannot be written is told, naming the file, and nothing else changes."""
        if self.output_refused(path, tr("Cannot export the correction table")):
            return ""
        try:
            what = self.kind.correction_table(self.result, self._settings, path)
        except ValueError as exc:
            self.view.tell(tr("Cannot export the correction table"), explained(exc))
            return ""
        except OSError as exc:
            self.view.tell(tr("Cannot export the correction table"),
                           tr("{path}: {reason}. Nothing else was changed.").format(
                               path=path, reason=exc.strerror or exc))
            return ""
        self.view.show_status(tr("{what} written").format(what=translated(what)))
        return what
