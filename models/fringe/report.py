"""Fringe signal analysis: uncertainty budget and certificate content.

The compensated interpolation error of a sample is its measured phase
``φ = atan2(u_s, u_c)`` minus the table's correction, minus the phase θ. Its
inputs, per sample, with ``S, C`` the modelled signals:

* the signal noise: u(φ) = √(C² σ_s² + S² σ_c²) / (S² + C²), σ from each
  channel's fit residuals (Type A, n − p degrees of freedom);
* the fitted model: u²(S) = σ_s² xᵀ(XᵀX)⁻¹x and the same for C, through
  the same sensitivities (the correction table is the model's phase error);
* each reference standard's figure, sensitivity 1 (for example the phase
  reference when θ comes from a reference encoder).

The as-found interpolation error (before compensation) is the measured phase
minus θ: its budget is the signal noise and the reference standards. The
certificate judges conformity on the as-found error; the compensated error is
printed as "as left" only when the lab states that the correction table,
named by its checksum, was loaded into the encoder.

Phases are converted to shaft angle by the grating period 1296000"/L.
"""

from __future__ import annotations

import math

import numpy as np

from models.certificate.document import (
    CertificateDocument,
    Table,
    decision_rows,
    reference_standard_components,
)
from models.certificate.metadata import CertificateMetadata, MetadataError
from models.fringe import plots as fringe_plots
from models.fringe.model import model_signal, model_signal_std
from models.messages import QT_TR_NOOP, message
from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.conformity import decide_conformity

__all__ = ["fringe_budget", "fringe_certificate"]

METHOD = QT_TR_NOOP(
    "The sine and cosine signals of the encoder's grating are sampled over whole periods. Each "
    "channel is modelled as an offset plus fundamental and odd harmonics (3rd, 5th) with their "
    "phases, u = A₀ + Σ A_k sin(kθ + c_k), and fitted by linear least squares (the paper fits "
    "the same model by particle swarm optimisation). The interpolation error is the phase "
    "atan2(u_sin, u_cos) minus θ; the modelled error, tabulated over the measured phase, is the "
    "correction, and the compensated error is what remains after applying it."
)


OBSERVABILITY_STATEMENT = QT_TR_NOOP(
    "The phase was estimated from the signals, with no phase reference: offsets, amplitude "
    "ratio and quadrature error are identified; a pure phase distortion of the grating is not "
    "observable this way and is not in the error stated.")


def _phase_sensitivities(result) -> tuple[np.ndarray, np.ndarray]:
    s = model_signal(result.theta_rad, result.sin_fit)
    c = model_signal(result.theta_rad, result.cos_fit)
    r2 = s**2 + c**2
    return c / r2, s / r2  # |∂φ/∂u_s|, |∂φ/∂u_c| (rad/V)


def fringe_budget(result, metadata: CertificateMetadata, as_found: bool = False) -> UncertaintyBudget:
    """The budget of the compensated error, or of the as-found error (no model input)."""
    n = result.theta_rad.size
    to_unit = result.period_length / (2.0 * math.pi)
    ds, dc = _phase_sensitivities(result)
    p = 1 + 2 * len(result.sin_fit.orders)
    dof = max(n - p, 1)
    sig_s = result.sin_fit.residual_rms * math.sqrt(n / dof)
    sig_c = result.cos_fit.residual_rms * math.sqrt(n / dof)
    noise = np.hypot(ds * sig_s, dc * sig_c) * to_unit
    us = model_signal_std(result.theta_rad, sig_s, result.sin_fit.orders, result.theta_rad)
    uc = model_signal_std(result.theta_rad, sig_c, result.cos_fit.orders, result.theta_rad)
    model = np.hypot(ds * us, dc * uc) * to_unit
    components = reference_standard_components(metadata, 1.0, QT_TR_NOOP("sample"))
    components.append(BudgetComponent(
        QT_TR_NOOP("Signal noise"), "A", "normal", noise, 1.0, 1.0, dof,
        message(QT_TR_NOOP("σ = {sin} mV (sin), {cos} mV (cos) from the fit residuals, "
                           "converted to phase"), sin=f"{sig_s * 1e3:.3g}",
                cos=f"{sig_c * 1e3:.3g}")))
    if not as_found:
        components.append(BudgetComponent(
            QT_TR_NOOP("Fitted model (correction table)"), "A", "normal", model, 1.0, 1.0, dof,
            QT_TR_NOOP("covariance of the fitted parameters propagated to the modelled phase "
                       "error")))
    return UncertaintyBudget(tuple(components), n, metadata.coverage_probability)


def _parameter_rows(result) -> list[tuple[str, str, str]]:
    rows = []
    for label, fit in (("sin", result.sin_fit), ("cos", result.cos_fit)):
        rows.append((message(QT_TR_NOOP("{channel}: offset A₀"), channel=label),
                     f"{fit.offset:+.5f} V", f"{2 * fit.u_offset:.5f} V"))
        for k in fit.orders:
            ua = fit.u_amplitude.get(k, float("nan"))
            up = fit.u_phase.get(k, float("nan"))
            rows.append((f"{label}: A{k}", f"{fit.amplitude[k]:.5f} V", f"{2 * ua:.5f} V"))
            if abs(fit.amplitude[k]) > 2 * ua and np.isfinite(up) and 2 * up < np.pi:
                rows.append((f"{label}: c{k}", f"{fit.phase[k]:+.5f} rad", f"{2 * up:.5f} rad"))
            else:  # the phase of a harmonic indistinguishable from zero means nothing
                rows.append((f"{label}: c{k}", message(QT_TR_NOOP("undefined")),
                             message(QT_TR_NOOP("amplitude not significant (A{k} ≤ U)"), k=k)))
        rows.append((message(QT_TR_NOOP("{channel}: R², residual RMS"), channel=label),
                     f"{fit.r_squared:.8f}", f"{fit.residual_rms * 1e3:.3g} mV"))
    return rows


def fringe_certificate(result, metadata: CertificateMetadata, source_name: str = "",
                       method_reference: str = "") -> CertificateDocument:
    as_left = bool(metadata.as_left_table_sha256) and \
        metadata.as_left_table_sha256.strip().lower() == result.table.sha256
    if metadata.as_left_table_sha256 and not as_left:
        raise MetadataError(
            message(
            QT_TR_NOOP("the certificate details say a correction table with checksum "
                       "{as_left_table_sha256}… was loaded into the encoder, but this analysis's table "
                       "is {sha256}…: export and load this table, or clear the checksum"),
            as_left_table_sha256=metadata.as_left_table_sha256[:16], sha256=result.table.sha256[:16]))
    budget = fringe_budget(result, metadata, as_found=not as_left)
    found_budget = budget if not as_left else fringe_budget(result, metadata, as_found=True)
    big_u = budget.expanded_arcsec
    raw, comp = result.raw_error, result.compensated_error
    correction = comp - raw
    period, sym, unit = result.period_length, result.unit_symbol, result.unit
    parameters = Table(QT_TR_NOOP("Signal parameters identified"),
                       (QT_TR_NOOP("Parameter"), QT_TR_NOOP("Value"), "U (k = 2)"),
                       _parameter_rows(result))
    per = min(result.samples_per_period or 64, raw.size)
    step = max(1, per // 64)
    idx = np.arange(0, per, step)
    phase_deg = np.degrees(result.theta_rad[idx])
    numeric = list(zip(idx + 1, phase_deg, raw[idx], correction[idx], comp[idx], big_u[idx],
                       strict=True))
    rows = [(f"{int(i)}", f"{p:.2f}", f"{r:+.3f}", f"{c:+.3f}", f"{e:+.3f}", f"{u:.3f}")
            for i, p, r, c, e, u in numeric]
    note = message(QT_TR_NOOP("The first {per} samples are shown (every {step}-th); all {n} "
                              "samples are in the CSV/XLSX results export.") if step > 1 else
                   QT_TR_NOOP("The first {per} samples are shown; all {n} samples are in the "
                              "CSV/XLSX results export."), per=per, step=step, n=raw.size)
    u_unit = sym.strip()
    results = Table(QT_TR_NOOP("Results per sample (first period; compensated = raw + "
                               "correction)"),
                    (QT_TR_NOOP("Sample"), QT_TR_NOOP("Phase θ (°)"),
                     message(QT_TR_NOOP("As found ({unit})"), unit=u_unit),
                     message(QT_TR_NOOP("Correction ({unit})"), unit=u_unit),
                     message(QT_TR_NOOP("Compensated ({unit})"), unit=u_unit),
                     message(QT_TR_NOOP("U as left ({unit})") if as_left else
                             QT_TR_NOOP("U as found ({unit})"), unit=u_unit)), rows, note)
    pp_raw, pp_comp = float(np.ptp(raw)), float(np.ptp(comp))
    scale = (message(QT_TR_NOOP("L = {lines} (period {period})"), lines=result.lines_per_rev,
                     period=f"{period:.3f}\"") if unit == "arcsec"
             else message(QT_TR_NOOP("period {period} nm"), period=f"{period:g}"))
    source = {"samples_per_period": message(QT_TR_NOOP("phase from {n} equal steps a period"),
                                            n=result.samples_per_period),
              "theta_column": message(QT_TR_NOOP("phase from the θ column")),
              "estimated": message(QT_TR_NOOP("phase estimated from the signals"))}
    share = QT_TR_NOOP("peak-to-peak {ptp} ({share} % of a period)")
    stat_rows = [
        (QT_TR_NOOP("Samples"), f"{raw.size}", message("{source}; {scale}",
                                                       source=source[result.phase_source],
                                                       scale=scale)),
        (QT_TR_NOOP("Interpolation error as found"),
         f"{raw.min():+.3f}{sym} … {raw.max():+.3f}{sym}",
         message(share, ptp=f"{pp_raw:.3f}{sym}", share=f"{pp_raw / period * 100:.2f}")),
        (QT_TR_NOOP("After compensation (as left)") if as_left else
         QT_TR_NOOP("After compensation (not applied to the item)"),
         f"{comp.min():+.3f}{sym} … {comp.max():+.3f}{sym}",
         message(share, ptp=f"{pp_comp:.3f}{sym}", share=f"{pp_comp / period * 100:.2f}")),
        (QT_TR_NOOP("Offsets, amplitude ratio, quadrature error"),
         f"{1e3 * result.sin_fit.offset:+.2f} / {1e3 * result.cos_fit.offset:+.2f} mV",
         message(QT_TR_NOOP("ratio {ratio}, quadrature {quadrature}"),
                 ratio=f"{result.amplitude_ratio:.4f}",
                 quadrature=f"{result.quadrature_error_deg:+.3f}°")),
    ]
    tol = metadata.tolerance_arcsec
    conformity = decide_conformity(raw, found_budget, tol, metadata.decision_rule,
                                   metadata.decision_quantity,
                                   what=QT_TR_NOOP("as-found interpolation error"), unit=sym)
    stat_rows += decision_rows(conformity, found_budget, QT_TR_NOOP("samples"), sym)
    stat_rows.append((QT_TR_NOOP("Correction table"),
                      message(QT_TR_NOOP("{n} entries"), n=result.table.size),
                      f"sha256 {result.table.sha256[:16]}…"))
    if result.sin_periods.shape[0] > 1:
        amp = result.sin_periods[:, 1]
        stat_rows.append((QT_TR_NOOP("Drift of sin A1 over the periods"),
                          f"{np.ptp(amp) * 1e3:.3g} mV",
                          message(QT_TR_NOOP("{n} periods fitted one by one"),
                                  n=result.sin_periods.shape[0])))
    statistics = Table(QT_TR_NOOP("Statistics"), (QT_TR_NOOP("Quantity"), QT_TR_NOOP("Value"), ""),
                       stat_rows)
    drawn = fringe_plots.figures(result)
    plots = (drawn["errors"], fringe_plots.first_period_with_uncertainty(result, big_u, per),
             drawn["residuals"])
    worst = budget.worst_index
    table_statement = message(
        QT_TR_NOOP("As left: the lab states that the correction table with sha256 {sha} was "
                   "loaded into the encoder; the compensated error and its U are the item as "
                   "left.") if as_left else
        QT_TR_NOOP("Conformity is judged on the interpolation error as found. The compensated "
                   "error is the error the correction table would leave; it is not the item's "
                   "unless the table is loaded into it (table sha256 {sha})."),
        sha=result.table.sha256)
    return CertificateDocument(
        "fringe", QT_TR_NOOP("Fringe signal analysis"), metadata, source_name, METHOD,
        method_reference, parameters, results, statistics, budget,
        message(QT_TR_NOOP("sample {sample}"), sample=worst + 1), conformity, tol, plots,
        tuple(result.warnings), unit=sym, statements=(table_statement,) + (
            (OBSERVABILITY_STATEMENT,) if result.phase_source == "estimated" else ()),
        point_columns=(("sample", np.arange(1, raw.size + 1, dtype=float)),
         ("phase_deg", np.degrees(result.theta_rad)), (f"raw_error_{unit}", raw),
         (f"correction_{unit}", correction), (f"compensated_error_{unit}", comp),
         (f"expanded_uncertainty_{unit}", big_u)))
