"""Polygon encoder test: uncertainty budget and certificate content.

The error at position i (eq 1) is relative to position 1:
``e_i = (a_i − a_1) − nominal_i − (dev_i − dev_1) − (x_i − x_1)``, plus the
pyramidal correction ``ε_x(θ_i) − ε_x(0)``, averaged over the m sets. Its inputs:

* each reference standard's figure (polygon calibration, autocollimator), per
  face or reading: sensitivity √2, 0 at position 1. These are systematic and are
  not reduced by repeating sets;
* the repeatability: with m ≥ 2 sets the pooled standard deviation of the
  corrected errors over the sets divided by √m, (m − 1)(n − 1) degrees of
  freedom; with one set the autocollimator's reading noise from the tilt fit's
  residuals (n − 3 degrees of freedom), sensitivity √2;
* the pyramidal correction: u(ψ) and u(ω) of the tilt fit propagated through
  ε_x (first order), divided by √m;
* the item's resolution, if stated.
"""

from __future__ import annotations

import math

import numpy as np

from models.certificate_document import (
    CertificateDocument,
    PlotFigure,
    PlotSeries,
    Table,
    accuracy_rows,
    reference_standard_components,
    resolution_component,
)
from models.certificate_metadata import CertificateMetadata
from models.conformity import decide_conformity
from models.polygon import GRADE_ACCURACY_ARCSEC, PolygonResult, pyramidal_readings_arcsec
from models.uncertainty_budget import BudgetComponent, UncertaintyBudget

__all__ = ["polygon_budget", "polygon_certificate"]

METHOD = (
    "A polygon is fixed on the shaft of the encoder under test and an autocollimator is set on "
    "its faces. The shaft is turned to each face in turn; the encoder's reading a, the polygon's "
    "calibrated face deviation and the autocollimator's horizontal reading x give the encoder "
    "error at each position relative to the first, e = (a − a₁) − nominal − (dev − dev₁) − "
    "(x − x₁). Returning to the first face checks the closure. The vertical readings y identify "
    "the pyramidal tilt ψ and its direction ω of the polygon against the shaft by least squares, "
    "and the horizontal error ε_x it induces is removed from e (coordinate transformation)."
)


def _pyramidal_uncertainty(result: PolygonResult) -> np.ndarray | None:
    """u of the pyramidal correction per position, from u(ψ), u(ω) of each set, mean over sets."""
    variances = []
    theta = result.theta_deg
    for s in result.sets:
        t = s.tilt
        if t is None:
            return None

        def eps(psi: float, omega: float) -> np.ndarray:
            e = pyramidal_readings_arcsec(theta, psi, omega)[0]
            return e - e[0]

        d_psi = (eps(t.psi_arcsec + 0.01, t.omega_deg) - eps(t.psi_arcsec - 0.01, t.omega_deg)) / 0.02
        d_om = (eps(t.psi_arcsec, t.omega_deg + 1e-3) - eps(t.psi_arcsec, t.omega_deg - 1e-3)) / 2e-3
        variances.append((d_psi * t.u_psi_arcsec) ** 2 + (d_om * t.u_omega_deg) ** 2)
    return np.sqrt(np.sum(variances, axis=0)) / len(result.sets)


def polygon_budget(result: PolygonResult, metadata: CertificateMetadata) -> UncertaintyBudget:
    n, m = result.faces, len(result.sets)
    pair = np.full(n, math.sqrt(2.0))
    pair[0] = 0.0
    components = reference_standard_components(metadata, pair, "face or reading")
    if m >= 2:
        corrected = np.array([s.corrected_error_arcsec for s in result.sets])
        dev = corrected - corrected.mean(axis=0)
        dof = (m - 1) * (n - 1)
        pooled = float(np.sqrt(np.sum(dev[:, 1:] ** 2) / dof))
        components.append(BudgetComponent(
            "Repeatability (mean of sets)", "A", "normal", pooled / math.sqrt(m), 1.0,
            (pair > 0).astype(float), dof,
            f"pooled standard deviation {pooled:.3f}\" of {m} sets, divided by √{m}"))
    else:
        tilt = result.sets[0].tilt
        if tilt is not None:
            dof = max(n - 3, 1)
            noise = float(np.sqrt(np.sum(tilt.residuals_arcsec**2) / dof))
            components.append(BudgetComponent(
                "Autocollimator reading noise", "A", "normal", noise, 1.0, pair, dof,
                f"vertical readings about the tilt fit, {dof} degrees of freedom (one set)"))
    u_pyr = _pyramidal_uncertainty(result)
    if u_pyr is not None:
        components.append(BudgetComponent(
            "Pyramidal correction (ψ, ω)", "A", "normal", u_pyr, 1.0, 1.0, max(n - 3, 1),
            "u(ψ), u(ω) of the tilt fit propagated through ε_x"))
    components += resolution_component(metadata, pair)
    return UncertaintyBudget(tuple(components), n)


def polygon_certificate(result: PolygonResult, metadata: CertificateMetadata,
                        source_name: str = "", method_reference: str = "") -> CertificateDocument:
    budget = polygon_budget(result, metadata)
    big_u = budget.expanded_arcsec
    m = len(result.sets)
    rows_p = [("Faces", f"{result.faces}", ""), ("Sets", f"{m}", ""),
              ("Encoder grade", f"{result.grade} (±{GRADE_ACCURACY_ARCSEC[result.grade]:g}\")", "")]
    for i, s in enumerate(result.sets, 1):
        closure = "not measured" if s.closure_arcsec is None else (
            f"{s.closure_arcsec:.2f}\" ({'within' if s.closure_ok else 'OUTSIDE'} the limit)")
        rows_p.append((f"Set {i} closure", closure, ""))
        if s.tilt is not None:
            rows_p.append((f"Set {i} pyramidal tilt ψ", f"{s.tilt.psi_arcsec:.1f}\"",
                           f"{2 * s.tilt.u_psi_arcsec:.2f}\""))
            rows_p.append((f"Set {i} tilt direction ω", f"{s.tilt.omega_deg:.1f}°",
                           f"{2 * s.tilt.u_omega_deg:.2f}°"))
    parameters = Table("Set-up parameters identified (U with k = 2)",
                       ("Parameter", "Value", "U (k = 2)"), rows_p)
    correction = result.mean_corrected_arcsec - result.mean_error_arcsec
    numeric = list(zip(np.arange(1, result.faces + 1), result.theta_deg, result.mean_error_arcsec,
                       correction, result.mean_corrected_arcsec, big_u, strict=True))
    rows = [(f"{int(p)}", f"{t:.3f}", f"{r:+.2f}", f"{c:+.3f}", f"{e:+.2f}", f"{u:.2f}")
            for p, t, r, c, e, u in numeric]
    results = Table(f"Results per position (mean of {m} set{'s' if m > 1 else ''}; corrected = "
                    "raw + pyramidal correction)",
                    ("Position", "Nominal (°)", "Raw error (\")", "Correction (\")",
                     "Corrected error (\")", "U (k = 2) (\")"), rows)
    st, raw = result.stats, result.raw_stats
    stat_rows = [
        ("Raw error", f"{raw.min:+.2f}\" … {raw.max:+.2f}\"", f"peak-to-peak {raw.peak_to_peak:.2f}\""),
        ("Corrected error", f"{st.min:+.2f}\" … {st.max:+.2f}\"",
         f"peak-to-peak {st.peak_to_peak:.2f}\""),
        *accuracy_rows(st.peak_to_peak, budget, "corrected", "positions"),
    ]
    h = result.harmonics
    if h.amplitude.size > 2:
        stat_rows.append(("Harmonics 1st / 2nd", f"{h.amplitude[1]:.3f}\" / {h.amplitude[2]:.3f}\"",
                          "eccentricity / ellipticity"))
    if result.repeatability_arcsec is not None:
        stat_rows.append(("Repeatability (largest s over positions)",
                          f"{np.max(result.repeatability_arcsec):.2f}\"", ""))
    if result.reversal_arcsec is not None:
        stat_rows.append(("Reversal error", f"{np.max(np.abs(result.reversal_arcsec)):.2f}\"", ""))
    statistics = Table("Statistics", ("Quantity", "Value", ""), stat_rows)
    th = result.theta_deg
    plots = [PlotFigure("Raw and corrected error", "position angle (°)", "error (\")", (
        PlotSeries("raw (mean)", th, result.mean_error_arcsec, (31, 119, 180), True),
        PlotSeries("corrected (mean)", th, result.mean_corrected_arcsec, (44, 160, 44), True),
        PlotSeries("pyramidal correction", th, correction, (255, 127, 14)),
    ))]
    plots.append(PlotFigure("Corrected error with its expanded uncertainty U (k = 2)",
                            "position angle (°)", "error (\")", (
        PlotSeries("corrected ± U", th, result.mean_corrected_arcsec, (44, 160, 44), True,
                   band=big_u),)))
    tilt = result.sets[0].tilt
    if tilt is not None:
        plots.append(PlotFigure("Tilt fit residuals (vertical readings, set 1)",
                                "position angle (°)", "residual (\")", (
            PlotSeries("residual", th, tilt.residuals_arcsec, (148, 103, 189), True),)))
    tol = metadata.tolerance_arcsec or GRADE_ACCURACY_ARCSEC[result.grade]
    conformity = decide_conformity(st.peak_to_peak / 2.0, budget.max_expanded_arcsec, tol,
                                   metadata.decision_rule, valid=result.valid)
    warnings = list(result.warnings)
    if m == 1 and tilt is None:
        warnings.append("Repeatability was not evaluated: one set and no vertical readings.")
    worst = budget.worst_index
    return CertificateDocument(
        "polygon", "Polygon encoder test", metadata, source_name, METHOD, method_reference,
        parameters, results, statistics, budget, f"position {worst + 1}", conformity, tol,
        tuple(plots), tuple(warnings),
        point_columns=(("position", np.arange(1, result.faces + 1, dtype=float)),
         ("nominal_deg", result.theta_deg), ("raw_error_arcsec", result.mean_error_arcsec),
         ("correction_arcsec", correction), ("corrected_error_arcsec", result.mean_corrected_arcsec),
         ("expanded_uncertainty_arcsec", big_u)))
