"""Fringe signal analysis as a workbench: columns, settings, result, JSON and summary."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from models.analysis_kind import SIGN_CONVENTION, AnalysisKind, SettingsError
from models.fringe import (
    ChannelFit,
    CorrectionTable,
    build_correction_table,
    fit_channel_pso,
    fit_channels,
    fit_periods,
    interpolation_error_arcsec,
    period_arcsec,
    phase_of_samples,
)
from models.fringe_report import fringe_certificate
from models.readings import Column, ColumnKind, ParsedReadings

__all__ = ["FRINGE", "FringeResult"]

COLUMNS = (
    Column("u_sin", "u sin", "V", ColumnKind.NUMBER, help="Sine channel voltage"),
    Column("u_cos", "u cos", "V", ColumnKind.NUMBER, help="Cosine channel voltage"),
    Column("theta_deg", "θ phase", "deg", ColumnKind.ANGLE_DEG, required=False,
           help="Electrical (fringe) phase of the sample, optional: without it the samples are "
                "taken as equally spaced, N per period"),
)

DEFAULT_SETTINGS: dict[str, Any] = {
    "lines_per_rev": 16384,
    "samples_per_period": 64,
    "max_order": 5,
    "harmonics": "odd",  # or "all"
    "method": "lsq",  # or "pso" (the seed's particle swarm, one period at most)
    "lut_size": 1024,
}


@dataclass
class FringeResult:
    theta_rad: np.ndarray
    u_sin: np.ndarray
    u_cos: np.ndarray
    sin_fit: ChannelFit
    cos_fit: ChannelFit
    raw_error_arcsec: np.ndarray
    compensated_error_arcsec: np.ndarray
    table: CorrectionTable
    lines_per_rev: int
    samples_per_period: int
    method: str
    sin_periods: np.ndarray
    cos_periods: np.ndarray
    pso_seconds: float | None = None
    warnings: list[str] = field(default_factory=list)

    @property
    def raw_peak_to_peak_arcsec(self) -> float:
        return float(np.ptp(self.raw_error_arcsec))

    @property
    def compensated_peak_to_peak_arcsec(self) -> float:
        return float(np.ptp(self.compensated_error_arcsec))


def harmonic_orders(max_order: int, harmonics: str) -> tuple[int, ...]:
    if max_order < 1:
        raise SettingsError("max_order must be at least 1")
    step = 2 if harmonics == "odd" else 1
    return tuple(range(1, max_order + 1, step))


def analyze(parsed: ParsedReadings, settings: Mapping[str, Any]) -> FringeResult:
    s = FRINGE.settings_with_defaults(settings)
    lines, per_period = int(s["lines_per_rev"]), int(s["samples_per_period"])
    if lines < 1 or per_period < 4:
        raise SettingsError("lines_per_rev must be ≥ 1 and samples_per_period ≥ 4")
    orders = harmonic_orders(int(s["max_order"]), str(s["harmonics"]))
    u_sin, u_cos = parsed["u_sin"], parsed["u_cos"]
    theta_col = parsed["theta_deg"]
    warnings: list[str] = []
    if np.all(np.isfinite(theta_col)) and theta_col.size:
        theta = np.radians(theta_col)
    else:
        if np.any(np.isfinite(theta_col)):
            warnings.append("The θ column is only partly filled; equal steps were used instead.")
        theta = phase_of_samples(u_sin.size, per_period)
    pso_seconds = None
    if s["method"] == "pso":
        if orders != (1, 3, 5):
            raise SettingsError("the particle swarm (the seed's method) fits orders 1, 3, 5 only")
        span = slice(0, min(u_sin.size, per_period))
        ps, pc = fit_channel_pso(theta[span], u_sin[span]), fit_channel_pso(theta[span], u_cos[span])
        sin_fit, cos_fit = ps.fit, pc.fit
        pso_seconds = ps.seconds + pc.seconds
        lsq_cost = sum(f.cost for f in fit_channels(theta[span], [u_sin[span], u_cos[span]]))
        warnings.append(f"Particle swarm on the first period: cost {ps.cost + pc.cost:.3g} V² "
                        f"against {lsq_cost:.3g} V² for least squares, {pso_seconds:.2f} s.")
    elif s["method"] == "lsq":
        sin_fit, cos_fit = fit_channels(theta, [u_sin, u_cos], orders)
    else:
        raise SettingsError(f"method must be 'lsq' or 'pso', not '{s['method']}'")
    table = build_correction_table(sin_fit, cos_fit, int(s["lut_size"]))
    measured = np.arctan2(u_sin, u_cos)
    raw = interpolation_error_arcsec(u_sin, u_cos, theta, lines)
    compensated_phase = table.compensate(measured)
    comp = interpolation_error_arcsec(np.sin(compensated_phase), np.cos(compensated_phase), theta,
                                      lines)
    return FringeResult(
        theta_rad=theta, u_sin=u_sin, u_cos=u_cos, sin_fit=sin_fit, cos_fit=cos_fit,
        raw_error_arcsec=raw, compensated_error_arcsec=comp, table=table, lines_per_rev=lines,
        samples_per_period=per_period, method=str(s["method"]),
        sin_periods=fit_periods(u_sin, per_period, orders),
        cos_periods=fit_periods(u_cos, per_period, orders),
        pso_seconds=pso_seconds, warnings=warnings,
    )


def to_json(result: FringeResult) -> dict[str, Any]:
    return {
        "sin_params": result.sin_fit.as_dict(),
        "cos_params": result.cos_fit.as_dict(),
        "raw_error_arcsec": result.raw_error_arcsec.tolist(),
        "compensated_error_arcsec": result.compensated_error_arcsec.tolist(),
        "raw_peak_to_peak_arcsec": result.raw_peak_to_peak_arcsec,
        "compensated_peak_to_peak_arcsec": result.compensated_peak_to_peak_arcsec,
        "period_arcsec": period_arcsec(result.lines_per_rev),
        "method": result.method,
        "sign_convention": SIGN_CONVENTION,
        "warnings": result.warnings,
    }


def _fit_line(name: str, fit: ChannelFit) -> str:
    parts = [f"{name}0 = {fit.offset:+.4f} V"]
    for k in fit.orders:
        ua = fit.u_amplitude.get(k)
        unc = f" ± {ua:.4f}" if ua is not None and math.isfinite(ua) else ""
        parts.append(f"{name}{k} = {fit.amplitude[k]:.4f}{unc} V ∠ {fit.phase[k]:+.4f} rad")
    return "  " + ", ".join(parts)


def summary(result: FringeResult) -> str:
    period = period_arcsec(result.lines_per_rev)
    raw, comp = result.raw_error_arcsec, result.compensated_error_arcsec
    return "\n".join([
        f"{raw.size} samples, {result.samples_per_period} per period, L = {result.lines_per_rev} "
        f"(period {period:.2f}\"), fitted by {'least squares' if result.method == 'lsq' else 'PSO'}",
        _fit_line("A", result.sin_fit) + f"; R² = {result.sin_fit.r_squared:.8f}",
        _fit_line("B", result.cos_fit) + f"; R² = {result.cos_fit.r_squared:.8f}",
        f"Interpolation error before: {raw.max():+.3f}\" … {raw.min():+.3f}\" "
        f"(peak-to-peak {np.ptp(raw):.3f}\", {np.ptp(raw) / period * 100:.2f} % of a period)",
        f"After compensation ({result.table.size}-entry table): {comp.max():+.3f}\" … "
        f"{comp.min():+.3f}\" (peak-to-peak {np.ptp(comp):.3f}\", "
        f"{np.ptp(comp) / period * 100:.2f} %)",
    ])


FRINGE = AnalysisKind(
    key="fringe",
    title="Fringe signal analysis",
    columns=COLUMNS,
    default_settings=DEFAULT_SETTINGS,
    analyze=analyze,
    to_json=to_json,
    summary=summary,
    sample_file="fringe_sample.csv",
    method_reference="Gao X. et al., Automatic compensation of sine deviation for grating fringe "
                     "photoelectric signal, Acta Optica Sinica 33(7):0712001 (2013)",
    certificate=fringe_certificate,
)
