"""Fringe signal analysis workbench: the presenter (no widgets: it hands its view arrays
to draw and asks it for file names)."""

from __future__ import annotations

import numpy as np

from models.decimation import envelope
from models.fringe.analysis import FRINGE, FringeResult
from models.fringe.export import write_correction_table
from models.fringe.model import model_signal
from widgets.fringe.view import FringeView
from widgets.workbench_presenter import WorkbenchPresenter

MAX_LISSAJOUS_POINTS = 5_000
PLOT_BINS = 2000  # runs per curve; each keeps its min and max


class FringePresenter(WorkbenchPresenter):
    """Fits both channels, builds the correction table and shows before/after errors."""

    view_class = FringeView

    def __init__(self, view: FringeView | None = None, parent=None) -> None:
        super().__init__(FRINGE, view, parent)

    def prepare_display(self, result: FringeResult) -> dict[str, tuple[np.ndarray, np.ndarray]]:
        """The curves thinned for drawing (worker thread for a large run). A revolution has
        a million samples: each curve keeps its envelope (every excursion, ~4000 points),
        which Qt draws in a few ms instead of ~100. When the motion stood or turned back
        the curves run over the phase within a period instead, in phase order."""
        x = result.theta_rad / (2 * np.pi)
        order = np.arange(x.size)
        if x.size > 1 and not np.all(np.diff(x) > 0):
            x = np.degrees(np.mod(result.theta_rad, 2 * np.pi))
            order = np.argsort(x, kind="stable")
            x = x[order]
        step = max(1, x.size // (2 * PLOT_BINS))
        theta = result.theta_rad[order][::step]
        raw, comp = result.raw_error[order], result.compensated_error[order]
        residual = (result.u_sin - model_signal(result.theta_rad, result.sin_fit))[order]
        raw_x, _ = envelope(x, raw, PLOT_BINS)
        comp_x, _ = envelope(x, comp, PLOT_BINS)
        # raw and compensated on one sampling that keeps the extremes of both
        pick = np.union1d(np.searchsorted(x, raw_x), np.searchsorted(x, comp_x))
        pick = np.clip(pick, 0, x.size - 1)
        return {
            "errors": (x[pick], order[pick]),
            "residual": envelope(x, residual * 1000.0, PLOT_BINS),
            "sin": envelope(x, result.u_sin[order], PLOT_BINS),
            "cos": envelope(x, result.u_cos[order], PLOT_BINS),
            "sin_fit": (x[::step], model_signal(theta, result.sin_fit)),
            "cos_fit": (x[::step], model_signal(theta, result.cos_fit)),
            "drift": [envelope(np.arange(result.sin_periods.shape[0]), values, PLOT_BINS // 2)
                      for values in (result.sin_periods[:, 1], result.cos_periods[:, 1],
                                     result.sin_periods[:, min(3, result.sin_periods.shape[1] - 1)]
                                     * 10, result.cos_periods[:, min(3, result.cos_periods.shape[1]
                                                                     - 1)] * 10)],
        }

    def show_result(self, result: FringeResult) -> None:
        d = dict(self.display) if isinstance(self.display, dict) else self.prepare_display(result)
        x, pick = d["errors"]
        unit = result.unit_symbol.strip()
        d["errors"] = (x, result.raw_error[pick], result.compensated_error[pick])
        d["along"] = ("electrical phase θ (periods)" if np.all(np.diff(result.theta_rad) > 0)
                      else "phase within the period (°); the motion stood or turned back")
        d["error_label"] = ("error, est. phase" if result.phase_source == "estimated"
                            else "interp. error") + f" ({unit})"
        d["compensated_label"] = f"compensated ({unit})"
        # a parametric curve cannot be peak-downsampled; a stride keeps its shape
        step = max(1, result.u_sin.size // MAX_LISSAJOUS_POINTS)
        d["lissajous"] = (result.u_cos[::step], result.u_sin[::step])
        t = np.linspace(0.0, 2 * np.pi, 361)
        e = result.ellipse
        d["ellipse"] = ((e.offset_cos + e.amplitude_cos * np.cos(t + e.quadrature_rad),
                         e.offset_sin + e.amplitude_sin * np.sin(t)) if e is not None
                        else ([], []))
        radius = 0.5 * (result.sin_fit.amplitude[1] + result.cos_fit.amplitude[1])
        d["circle"] = (radius * np.cos(t), radius * np.sin(t))
        orders = np.array(result.sin_fit.orders, dtype=float)
        d["bars"] = tuple((orders + shift, np.log10([max(fit.amplitude[k], 1e-9)
                                                     for k in fit.orders]))
                          for shift, fit in ((-0.18, result.sin_fit), (0.18, result.cos_fit)))
        if result.sin_periods.shape[1] <= 3:  # no 3rd harmonic fitted
            d["drift"] = [*d["drift"][:2], ([], []), ([], [])]
        self.view.show_drawing(d)

    def clear_result(self) -> None:
        self.view.clear_result()

    def export_table_dialog(self) -> None:
        if self.result is None:
            return
        path = self.view.ask_table_path()
        if path:
            write_correction_table(path, self.result)
