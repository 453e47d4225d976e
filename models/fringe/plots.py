"""The fringe signal analysis' plots, declared once for the window and the certificate.

A revolution has a million samples: every curve is thinned to its envelope (the
lowest and highest point of each run of samples), which keeps every excursion.
When the motion stood or turned back, the curves run over the phase within a
period, in phase order, instead of along the record.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from models.decimation import envelope, one_per_cell
from models.fringe.model import model_signal
from models.messages import QT_TR_NOOP
from models.plots import PlotFigure, PlotSeries

if TYPE_CHECKING:  # the analysis imports the report, which draws with this module
    from models.fringe.result import FringeResult

__all__ = ["figures", "first_period_with_uncertainty"]

BINS = 2000  # runs per curve
#: a record of at most this many samples has its signals drawn as markers, each sample
#: where it was read, and the fit as a continuous curve between them
MARKED_SAMPLES = 2048
ERROR = QT_TR_NOOP("error")  # an axis title, its unit after it
BLUE, GREEN, PURPLE, RED, ORANGE, TEAL = ((31, 119, 180), (44, 160, 44), (148, 103, 189),
                                          (214, 39, 40), (230, 126, 34), (22, 160, 133))
# the window's own plots (signals, Lissajous, spectrum, drift), as they have always looked
SIN_RED, COS_BLUE, ELLIPSE_GREEN = (192, 57, 43), (31, 95, 191), (39, 174, 96)


def _axis(result: FringeResult) -> tuple[np.ndarray, np.ndarray | None, str]:
    """(x of every sample in drawing order, the order (None: as recorded), the axis
    title)."""
    periods = result.theta_rad / (2 * np.pi)
    if periods.size < 2 or (result.reversals == 0 and periods[-1] > periods[0]):
        # one way along the record: a sample whose phase stepped back less than a turn
        # (a spike typed over it, noise while standing) is drawn where the record had got to
        return np.maximum.accumulate(periods, out=periods), None, \
            QT_TR_NOOP("electrical phase θ (periods)")
    x = np.degrees(np.mod(result.theta_rad, 2 * np.pi))
    order = np.argsort(x, kind="stable")
    return x[order], order, QT_TR_NOOP("phase within the period (°); the motion stood or turned back")


def _residuals(u: np.ndarray, theta_rad: np.ndarray, fit) -> np.ndarray:
    """Each sample's residual (V): kept by the fit when it was made from these samples."""
    if fit.residuals is not None and fit.residuals.shape == u.shape:
        return fit.residuals
    return u - model_signal(theta_rad, fit)


def _signals(result: FringeResult, x: np.ndarray, order: np.ndarray | None, drawn,
             along: str, bins: int) -> PlotFigure:
    """The signals and their fit. A record of up to :data:`MARKED_SAMPLES` samples: each
    sample a marker and the fit a continuous curve through the phases between them (straight
    lines joining N = 8 samples a period drew a distorted signal, the fit included, which was
    evaluated at the samples only); a longer one: the samples' envelope as lines, the fit at
    every few samples, dense enough to be a curve."""
    if x.size <= MARKED_SAMPLES:
        points = min(max(16 * x.size, 361), 8 * bins)
        if order is None:  # along the record: x is the phase in periods
            fine_x = np.linspace(x[0], x[-1], points) if x.size else x
            fine_theta = 2 * np.pi * fine_x
        else:  # the phase within the period, in degrees
            fine_x = np.linspace(0.0, 360.0, points)
            fine_theta = np.radians(fine_x)
        size = 6 if x.size <= 256 else 4  # (smaller where many: the fit seen between them)
        return PlotFigure(QT_TR_NOOP("Signals and their fit"), along, "signal (V)", (
            PlotSeries("u sin", x, drawn(result.u_sin), SIN_RED, True, width=0, marker_size=size),
            PlotSeries("u cos", x, drawn(result.u_cos), COS_BLUE, True, width=0,
                       marker_size=size),
            PlotSeries("fit", fine_x, model_signal(fine_theta, result.sin_fit), (123, 36, 28),
                       width=1.5),
            PlotSeries("", fine_x, model_signal(fine_theta, result.cos_fit), (21, 67, 96),
                       width=1.5)))
    step = max(1, x.size // (2 * bins))
    theta = drawn(result.theta_rad)[::step]
    return PlotFigure(QT_TR_NOOP("Signals and their fit"), along, "signal (V)", (
        PlotSeries("u sin", *envelope(x, drawn(result.u_sin), bins), (230, 176, 170), width=3),
        PlotSeries("u cos", *envelope(x, drawn(result.u_cos), bins), (169, 204, 227), width=3),
        PlotSeries("fit", x[::step], model_signal(theta, result.sin_fit), (123, 36, 28), width=1.5),
        PlotSeries("", x[::step], model_signal(theta, result.cos_fit), (21, 67, 96), width=1.5)))


def figures(result: FringeResult, bins: int = BINS) -> dict[str, PlotFigure]:
    """Every figure of a result: errors, residuals, signals, Lissajous, spectrum, drift."""
    x, order, along = _axis(result)

    def drawn(values: np.ndarray) -> np.ndarray:  # in drawing order (a record's own: no copy)
        return values if order is None else values[order]

    unit = result.unit_symbol.strip()
    raw, comp = drawn(result.raw_error), drawn(result.compensated_error)
    # raw and compensated on one sampling that keeps the extremes of both
    raw_x, _ = envelope(x, raw, bins)
    comp_x, _ = envelope(x, comp, bins)
    pick = np.clip(np.union1d(np.searchsorted(x, raw_x), np.searchsorted(x, comp_x)), 0,
                   max(x.size - 1, 0))
    label = (QT_TR_NOOP("error, est. phase") if result.phase_source == "estimated"
             else QT_TR_NOOP("interp. error"))
    # where orders fold into fitted ones, the compensated error holds at the sampled phases
    # only (models.fringe.compensation_at_samples): the legend says so, in the window and on
    # the certificate (day review 68 F8: "after compensation" drawn as a curve between them)
    # the error as found too: the readings' own at the samples, the whole period's not
    # determined (day review 69 F1: 0.497″ at the 8 phases, 0.671″ over the period, unsaid)
    folded = bool(getattr(result, "folded_orders", ()))
    after = (QT_TR_NOOP("after compensation, at the sampled phases only")
             if folded else QT_TR_NOOP("after compensation"))
    before = (QT_TR_NOOP("before compensation, at the sampled phases only")
              if folded else QT_TR_NOOP("before compensation"))
    out = {"errors": PlotFigure(QT_TR_NOOP("Interpolation error before and after compensation"), along,
                                f"{label} ({unit})", (
        PlotSeries(before, x[pick], raw[pick], BLUE, role="raw"),
        PlotSeries(after, x[pick], comp[pick], GREEN, role="corrected")))}
    res_s = drawn(_residuals(result.u_sin, result.theta_rad, result.sin_fit)) * 1e3
    res_c = drawn(_residuals(result.u_cos, result.theta_rad, result.cos_fit)) * 1e3
    out["residuals"] = PlotFigure(QT_TR_NOOP("Fit residuals"), along, QT_TR_NOOP("residual (mV)"), (
        PlotSeries("sin", *envelope(x, res_s, bins), PURPLE, role="residual"),
        PlotSeries("cos", *envelope(x, res_c, bins), RED)))
    out["signals"] = _signals(result, x, order, drawn, along, bins)
    shown = one_per_cell(result.u_cos, result.u_sin)  # every excursion, ~1000 points a ring
    t = np.linspace(0.0, 2 * np.pi, 361)
    e = result.ellipse
    ellipse = ((e.offset_cos + e.amplitude_cos * np.cos(t + e.quadrature_rad),
                e.offset_sin + e.amplitude_sin * np.sin(t)) if e is not None
               else (np.empty(0), np.empty(0)))
    radius = 0.5 * (result.sin_fit.amplitude[1] + result.cos_fit.amplitude[1])
    out["lissajous"] = PlotFigure(QT_TR_NOOP("Lissajous figure"), "u cos (V)", "u sin (V)", (
        PlotSeries("measured", result.u_cos[shown], result.u_sin[shown], SIN_RED, True, width=0,
                   marker_size=2),
        PlotSeries("fitted ellipse (Heydemann)", *ellipse, ELLIPSE_GREEN, dashed=True),
        PlotSeries("compensated (unit circle × A1)", radius * np.cos(t), radius * np.sin(t),
                   COS_BLUE, width=1.5)))
    orders = np.array(result.sin_fit.orders, dtype=float)
    out["spectrum"] = PlotFigure(QT_TR_NOOP("Harmonics of the two channels"), "harmonic order",
                                 "amplitude (V, log10)", tuple(
        PlotSeries(name, orders + shift, np.log10([max(fit.amplitude[k], 1e-9)
                                                   for k in fit.orders]), color)
        for name, shift, fit, color in (("sin", -0.18, result.sin_fit, SIN_RED),
                                        ("cos", 0.18, result.cos_fit, COS_BLUE))))
    periods = np.arange(result.sin_periods.shape[0], dtype=float)
    drift = [("A1 (sin)", result.sin_periods[:, 1], SIN_RED),
             ("B1 (cos)", result.cos_periods[:, 1], COS_BLUE)]
    if result.sin_periods.shape[1] > 3:
        drift += [("A3 × 10", result.sin_periods[:, 3] * 10, ORANGE),
                  ("B3 × 10", result.cos_periods[:, 3] * 10, TEAL)]
    out["drift"] = PlotFigure(QT_TR_NOOP("Drift per period"), "period", "amplitude (V)", tuple(
        PlotSeries(name, *envelope(periods, values, bins // 2), color, width=1.5)
        for name, values, color in drift))
    return out


#: the x axis of the first period's plot when its samples span more than one period
FOLDED_PHASE = QT_TR_NOOP("phase within the period (°): the samples of several periods "
                          "folded into one")


def first_period_with_uncertainty(result: FringeResult, expanded, samples: int) -> PlotFigure:
    """The compensated error of the first ``samples`` samples with their U as a band; with
    no U stated (every ``expanded`` not finite: the phase estimated from the signals), the
    curve alone. Where those samples span more than one period or run back (a θ column of
    few phases a period: 64 samples of 8 phases are 8 periods and more), each is drawn at
    its phase within the period, in phase order, as a point on the line: in sample order
    the line ran over thousands of degrees of "the first period" (or back and forth)."""
    unit = result.unit_symbol.strip()
    band = np.asarray(expanded, dtype=float)[:samples]
    with_u = bool(np.any(np.isfinite(band)))
    folded = bool(getattr(result, "folded_orders", ()))  # at the sampled phases only (F8)
    theta = np.asarray(result.theta_rad[:samples], dtype=float)
    error = np.asarray(result.compensated_error[:samples], dtype=float)
    x, x_label, markers = np.degrees(theta), QT_TR_NOOP("phase θ (°)"), samples <= 256
    if theta.size > 1 and (theta[-1] - theta[0] >= 2 * np.pi * (1 - 1e-9)
                           or np.any(np.diff(theta) < 0)):
        x = np.degrees(np.mod(theta, 2 * np.pi))
        order = np.argsort(x, kind="stable")
        x, error, band = x[order], error[order], band[order]
        x_label, markers = FOLDED_PHASE, True
    return PlotFigure(QT_TR_NOOP("Compensated error in the first period, with U") if with_u
                      else QT_TR_NOOP("Compensated error in the first period (no U stated)"),
                      x_label,
                      f"{ERROR} ({unit})", (
        PlotSeries((QT_TR_NOOP("compensated ± U, at the sampled phases only") if folded else
                    QT_TR_NOOP("compensated ± U")) if with_u else
                   (QT_TR_NOOP("compensated, at the sampled phases only") if folded else
                    QT_TR_NOOP("compensated")),
                   x, error, GREEN, markers,
                   band=band if with_u else None, role="corrected"),))
