"""Positioning workbench: the presenter (no widgets: it asks its view)."""

from __future__ import annotations

from types import SimpleNamespace

from models.certificate.metadata import CertificateMetadata
from models.display_units import table_in_unit
from models.positioning import plots
from models.positioning.analysis import POSITIONING
from models.positioning.compensation import LINUXCNC_NAME, LINUXCNC_OPTIONS, check_compensation
from models.positioning.controllers import CONTROLLERS
from models.positioning.controllers.common import parse_options
from models.positioning.model import PositioningResult
from models.positioning.report import positioning_budget, printed_per_target
from models.tolerance_band import with_tolerance
from widgets.i18n import Said, explained, tr, translated
from widgets.positioning.before_after import AfterCompensation
from widgets.positioning.view import PositioningView
from widgets.workbench_presenter import WorkbenchPresenter

# the file name offered for each format (the controller's own naming where it has one)
SUGGESTED_NAMES = {"csv": "compensation.csv", "linuxcnc": "compensation.txt",
                   "sinumerik": "AX_EEC.INI", "fanuc": "PITCH.TXT", "heidenhain": "AXIS.COM",
                   "twincat": "compensation_table.st", "isg": "achskw.lis",
                   "mach4": "screwmap.txt"}


class PositioningPresenter(WorkbenchPresenter):
    """ISO 230-2 and VDI/DGQ 3441 on every edit; exports the compensation table."""

    view_class = PositioningView

    def __init__(self, view: PositioningView | None = None, parent=None) -> None:
        super().__init__(POSITIONING, view, parent)
        # File › Overlay a run…: the log after compensation, compared (app/run_overlay_actions.py)
        self.after_compensation = AfterCompensation(self)

    def show_result(self, result: PositioningResult) -> None:
        # a reading left out for a deviation beyond the limit, drawn apart in the table (its
        # warning names it: day review live76 F7)
        self.table_model.set_left_out_rows(set(result.left_out))
        self.view.show_figures(*self.in_unit(self._with_tolerance(plots.deviation_figure(result),
                                                                  result),
                                             plots.reversal_figure(result),
                                             plots.readings_figure(result, self.parsed)))
        self.view.show_per_target(*table_in_unit(
            *result.per_target_table(self._printed_per_target(result)), self.angle_unit))
        if not result.minimum_runs_met:
            self.view.append_to_readings_caption(tr(" — fewer than 5 runs: flagged"))

    def _printed_per_target(self, result: PositioningResult) -> dict[str, list[str]] | None:
        """The certificate's results cells with the details it would be made with (none:
        the readings' own U): the per-target table shows what it prints (review 62, F2)."""
        meta = self.certificate_details()
        try:
            return printed_per_target(result, positioning_budget(
                result, meta if meta is not None else CertificateMetadata(),
                self.result_settings))
        except (ValueError, ArithmeticError, IndexError):
            return None  # no certificate of these readings: the figures to 0.001

    def _with_tolerance(self, figure, result: PositioningResult):
        """The mean deviations' plot with ±T and each direction's U band where the
        certificate details set a tolerance (models/tolerance_band.py)."""
        tolerance, expanded, quantity = self.tolerance_bands(result)
        if tolerance is None:
            return figure
        curves = [(f"x̄{plots.ARROWS[name]} ± U", result.positions, stats.mean,
                   expanded.get(f"per_target/mean_{name}"))
                  for name, _, stats in result.directions_present()]
        return with_tolerance(figure, tolerance, curves, quantity)

    def clear_result(self) -> None:
        self.table_model.set_left_out_rows(set())
        self.view.clear_result()

    def export_compensation_dialog(self) -> None:
        if self.result is None:
            return
        fmt = self._settings["compensation_format"]
        asks = fmt in CONTROLLERS or (fmt == "linuxcnc" and self.result.target_unit == "deg")
        if asks and not self.ask_controller_options(fmt):
            return
        s = self.kind.checked_settings(self._settings)
        try:  # a table the controller would refuse is told before the file dialog
            check_compensation(self.result, s["compensation_step"], s["compensation_tables"],
                               fmt, s["compensation_controller_options"])
        except ValueError as exc:
            self.view.tell(tr("Cannot export the compensation table"), explained(exc))
            return
        path = self.view.ask_compensation_path(SUGGESTED_NAMES.get(fmt, "compensation.csv"), fmt)
        if path:
            self.export_compensation(path)

    def ask_controller_options(self, fmt: str) -> bool:
        """The controller's options in a small form (filled from the set-up's text); the
        answer is kept in the set-up. False when cancelled or the text cannot be read."""
        module = CONTROLLERS.get(fmt) or SimpleNamespace(NAME=LINUXCNC_NAME, OPTIONS=LINUXCNC_OPTIONS)
        try:
            current = parse_options(module.NAME, module.OPTIONS,
                                    self._settings["compensation_controller_options"])
        except ValueError as exc:
            self.view.tell(tr("Cannot export the compensation table"), explained(exc))
            return False
        fields = [(o.key, o.help, "" if current[o.key] is None or current[o.key] != current[o.key]
                   else f"{current[o.key]:g}"
                   if isinstance(current[o.key], float) else str(current[o.key]))
                  for o in module.OPTIONS]
        answer = self.view.ask_controller_options(module.NAME, fields)
        if answer is None:
            return False
        text = ", ".join(f"{k}={v.strip()}" for k, v in answer.items() if v.strip())
        if text != self._settings["compensation_controller_options"]:
            self.set_settings({**self._settings, "compensation_controller_options": text})
        return True

    def export_compensation(self, path: str) -> str:
        """Write the table as set up; a table that cannot be made is told, not written."""
        if self.output_refused(path, tr("Cannot export the compensation table")):
            return ""
        try:
            what = self.kind.correction_table(self.result, self._settings, path)
        except ValueError as exc:
            self.view.tell(tr("Cannot export the compensation table"),
                           explained(exc))
            return ""
        except OSError as exc:  # named by the file asked for, not the temporary file beside it
            self.view.tell(tr("Cannot export the compensation table"),
                           tr("{path}: {reason}. Nothing else was changed.").format(
                               path=path, reason=exc.strerror or exc))
            return ""
        def status() -> Said:
            """Composed again in the language chosen later, each time (View › Language;
            gui77: the lines' plain join stayed in the language it was shown in)."""
            said, *notes = translated(what).split("\n")  # what was written, then what to know
            return Said("; ".join([tr("{what} written").format(what=said), *notes]), status)

        self.view.show_status(status())
        return what
