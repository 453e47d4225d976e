"""Theodolite run: uncertainty budget and certificate content.

The corrected error at point i is the difference of two readings (at i and
at the reference point), minus the set-up model ζ(θ):
``e_i = (A_i − A_0) − (θ_i − θ_0) − ζ(θ_i; ψ, α, β)``. Its inputs:

* the reading error, ONE input (issue 39: the noise counted once). Every
  reading of the theodolite has one error; two figures describe it: the
  scatter s of the vertical readings about the identification's fit (Type A,
  ν = n − 3; the azimuth residuals hold the axis' own error, the measurand, and
  an autocollimating theodolite sets on the mirror as repeatably in azimuth as
  in elevation) and the stated standards' per-reading standard uncertainty
  u_std (Type B, the root sum of squares of the stated standards' figures).
  They describe the same error, so the budget takes the larger, u_read =
  max(s, u_std): a stated calibration figure above the observed scatter still
  governs (ν = ∞), and a set-up noisier than the instrument's figure is not
  hidden (ν = n − 3). Its note says which governed. It enters twice, as the
  error is the difference of two readings: the point's own reading (one value
  per point, independent; sensitivity 1, 0 at the reference reading) and the
  reference reading θ₀ (one value for the whole run, ``common``; sensitivity 1
  at every point but θ₀): √2·u_read at a point, 0 at θ₀. One estimate, so for
  Welch–Satterthwaite the two count as one input (``dof_group``). The
  standards stay in the certificate's table of standards and its traceability;
  only their budget line is this one. (Before, the standard entered a second
  time as one value per trial with sensitivity √2 beside s at the point and at
  θ₀: the noise counted twice, and the standard's share of the wrong nature —
  it only moved the reference point against the others.) A repeat of the
  reference angle later in the run is a reading like any other.
  With n readings a point (setting *readings per point*, averaged first), a
  point's reading is the mean of n, and its error has two parts: one that
  averages (the pointing noise, σ/√n, estimated by s_repeat/√n, the points' s/√n
  of the azimuth repeats pooled, ν = points · (n − 1)) and one that does not (the
  instrument's error at that circle position, the same in every repeat). The
  stated u_std is one reading's whole error, as with one reading a point (where
  it is the same noise the scatter shows, counted once): the part of it the
  repeats show to scatter averages, and the rest, u_c = √max(u_std² − s_repeat²,
  0), is the circle's (0.8.6; the same split as the passes' means,
  models.theodolite.pass_means). The mean's error is √(u_c² + (s_repeat/√n)²);
  the scatter s of the means about the fit estimates the same error where the fit
  sees it. So still ONE input, u_read = max(s, √(u_c² + (s_repeat/√n)²)), with
  the ν of the figure that governs (for the root sum of squares,
  Welch–Satterthwaite of its two parts, u_c's ν = ∞). Before 0.8.6 u_std was
  taken whole as the circle's error (not divided by √n) beside s_repeat/√n: with
  the theodolite stated at its pointing noise (u_std = σ, nothing fixed at a
  circle position) every point covered and U was twice and more what the mean's
  error needs (an audit: per-point coverage 100 %, the decided interval 2.1–2.9
  times the value's spread). Not s with s/√n on top: before (#39) s/√n entered
  again beside s at each point and at θ₀, the noise of the mean counted twice
  (U / (2 × actual scatter) 1.53 with 4 readings and no standard). Nor max(s,
  u_std/√n, s_repeat/√n): where the circle's error is the horizontal circle's
  alone (the elevations barely move over a run, so the vertical circle's error is
  one offset the fit takes up), s does not see it and the larger of the parts
  misses the other. Checked by simulation in
  tests/models/theodolite/test_theodolite_budget_once.py (a 3-D rig, the
  circle's error drawn once per circle position and run, pointing noise per
  reading, the theodolite stated at √(u_c² + σ²) per reading; and stated at σ
  with no circle error). With one reading a point the rule is max(s, u_std) as
  before (there is no s_repeat);
* the identified parameters' covariance propagated through ζ (first order);
* the item's resolution, if stated: rectangular, sensitivity √2.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from models.certificate.builder import (
    Decision,
    PointTable,
    Statistics,
    build_certificate,
    difference_column,
    figure_column,
    text_column,
    uncertainty_column,
)
from models.certificate.document import (
    CertificateDocument,
    Exact,
    Table,
    gum_pair,
    range_cells,
    resolution_component,
)
from models.certificate.interval_note import interval_note
from models.certificate.metadata import CertificateMetadata
from models.messages import QT_TR_NOOP, message, separated
from models.theodolite import KEY, MEASURAND_STANDARDS, TITLE
from models.theodolite.accuracy_check import certificate_warnings
from models.theodolite.figures import MODEL_INPUT, per_angle_note, pooled_repeats
from models.theodolite.model import (
    DEFAULT_TILT_BOUND_ARCSEC,
    SETUP_INPUTS,
    TILT_BOUND_INPUT,
    TheodoliteResult,
)
from models.theodolite.plots import corrected_with_uncertainty, error_figure, residual_figure
from models.uncertainty.budget import (
    BudgetComponent,
    UncertaintyBudget,
    coverage_factor,
    divisor_for_basis,
)
from models.uncertainty.lab_scope import cmc_of
from models.uncertainty.printed_figure import interval_range, printed
from models.uncertainty.probability_text import percent_text
from models.uncertainty.rounding import fixed_places
from models.uncertainty.tilt_direction import NOT_IDENTIFIED

__all__ = ["READING_INPUT", "REFERENCE_READING_INPUT", "reading_error_components",
           "theodolite_budget", "theodolite_certificate",
           "theodolite_json_budgets"]

METHOD = QT_TR_NOOP(
    "The axis under test carries a plane mirror. At each indicated angle θ the autocollimating "
    "theodolite is set on the mirror normal and its horizontal reading A and vertical reading E "
    "are taken. The set-up misalignment — the tilt ψ of the axis from the theodolite's vertical, "
    "its direction α and the elevation β of the mirror normal — makes A differ from the axis "
    "rotation by ζ(θ) = A(θ) − θ. ψ, α and β are identified by least squares from the readings "
    "(sin E is linear in 1, cos θ and sin θ; the nonlinear solution is then polished). The error "
    "of indication (indicated − reference) is (θ − θ₀) − (A − A₀), the negative of A − θ in the "
    "published method (Tian et al. 2017); the set-up's share of it, −ζ evaluated at the axis' "
    "true rotation, is removed: corrected error = (θ − θ₀) − (A − A₀) + ζ. Errors are relative "
    "to the reference point θ₀, where the theodolite was zeroed."
)


#: what ψ, α and β are (the frame of ../shared/SPEC.md §1, the seed's), checked against an independent rig
#: built in a frame with OZ up (tests/models/certificate/test_certificate_uncertainty.py)
SETUP_DEFINITIONS = QT_TR_NOOP(
    "Set-up parameters: azimuths are counted from the theodolite's azimuth zero in the sense its "
    "horizontal circle reads (clockwise seen from above), and the axis under test turns that way "
    "for increasing θ. ψ is the angle between the axis and the plumb line; α is the azimuth, so "
    "counted, toward which the axis' upper end leans (its lower end leans toward α + 180°); β is "
    "the elevation of the mirror normal above the horizontal at the reference reading θ₀, "
    "positive upward. The vertical readings are taken as E of the published method (Tian et al. "
    "2017; OZ plumb down, E = asin z): positive below the horizontal, E = V − 90° for a zenith "
    "angle V. Elevations entered positive upward give α + 180° and −β and the same corrected "
    "errors: the set-up mirrored in the horizontal plane shows the same azimuths.")

#: how the table names what the set-up was identified from (ident.method)
_IDENTIFIED_FROM = {"elevation": QT_TR_NOOP("elevation readings"),
                    "azimuth": QT_TR_NOOP("azimuth readings")}


def _not_reference(result: TheodoliteResult) -> np.ndarray:
    """1 at every reading, 0 at the reference reading (the zeroing one only)."""
    out = np.ones(result.theta_deg.size)
    out[result.reference_index] = 0.0
    return out


def _point_names(theta_deg: np.ndarray) -> list[str]:
    """Each point as the results table shows it: its θ, and its row where θ repeats."""
    shown = [f"{t:.4f}" for t in theta_deg]
    return [f"θ = {t}°" if shown.count(t) == 1 else
            message(QT_TR_NOOP("θ = {theta}° (row {row} of the results)"), theta=t, row=i + 1)
            for i, t in enumerate(shown)]


#: a standard stated for any angle between two readings (``applies_to`` "angle"): its u is
#: that of one angle, the difference of two readings, so each reading's share is u/√2 (#39:
#: it was taken whole per reading, and a point, the difference of its reading and θ₀'s,
#: got √2 u — an audit's per-point U 2.48 times what the errors needed, coverage 100 %)
PER_ANGLE_READING_SHARE = 1.0 / math.sqrt(2.0)


def _per_reading(std) -> float:
    """A stated standard's u as one reading's (arcsec): its own per reading, u/√2 for one
    stated for any angle between two readings (:data:`PER_ANGLE_READING_SHARE`)."""
    divisor, _ = divisor_for_basis(std.basis)
    u = std.uncertainty_in("arcsec") / divisor
    return u * PER_ANGLE_READING_SHARE if std.applies_to == "angle" else u


def stated_reading_uncertainty(metadata: CertificateMetadata) -> tuple[float, list]:
    """u_std, the root sum of squares of the stated standards' per-reading standard
    uncertainties (arcsec; one stated for any angle between two readings enters at u/√2,
    :func:`_per_reading`), and the standards that state one. A point's error is the
    difference of two readings (the point's and θ₀'s), so a standard stated per angle counts
    once at each point, √2 · u/√2 = u, and between two points (an angle it measured) u."""
    stated = [std for std in metadata.standards if std.uncertainty is not None]
    return math.sqrt(sum(_per_reading(std) ** 2 for std in stated)), stated


def stated_pair_factor(metadata: CertificateMetadata) -> float:
    """How many times the stated u per reading (:func:`stated_reading_uncertainty`) the
    difference of the stated standards' errors at two θ can have as its standard
    deviation, whatever their correlation from θ to θ: 2 for a standard stated for each
    reading (its errors at two θ may be opposite), √2 for one stated for any angle between
    two readings (ReferenceStandard.applies_to "angle": that difference is one more angle it
    measured, within its own u, √2 times its per-reading share u/√2), the standards in
    quadrature (independent of one another), as the positioning workbench's ``pair_u``
    (models.positioning.report); 2 with none. It sizes the figures' widening for a circle
    error shaped as the curve's worst (models.theodolite.figures
    .theodolite_figure_intervals)."""
    parts = [(_per_reading(std), math.sqrt(2.0) if std.applies_to == "angle" else 2.0)
             for std in metadata.standards if std.uncertainty is not None]
    u2 = sum(u**2 for u, _ in parts)
    if not u2 > 0.0:
        return 2.0
    return math.sqrt(sum((k * u) ** 2 for u, k in parts) / u2)


def _reading_error_notes(result: TheodoliteResult, s: float, dof: int, u_std: float,
                         stated: bool, governs: str, nu: float,
                         pooled: tuple[float, int, int] | None) -> str:
    """What the reading error's note says: its candidate figures and which governs
    (``governs``: standard, scatter, repeats or both, the standard with the repeats; ``nu``
    the input's ν; ``pooled``: :func:`models.theodolite.figures.pooled_repeats`)."""
    n = result.theta_deg.size
    if pooled is None:  # one reading a point: the texts as they were before repeats counted once
        scatter = message(QT_TR_NOOP("s = {s} (the vertical readings about the fit, {n} "
                                     "readings, ν = {dof}; taken for the azimuth too)"),
                          s=f"{s:.3f}\"", n=n, dof=dof)
        if governs == "standard":
            return message(QT_TR_NOOP(
                "one error per reading, counted once: the larger of the stated standards' "
                "u = {u} per reading and the scatter {scatter}; the standard governs (Type B, "
                "ν = ∞)"), u=f"{u_std:.3f}\"", scatter=scatter)
        if stated:
            return message(QT_TR_NOOP(
                "one error per reading, counted once: the larger of the stated standards' "
                "u = {u} per reading and the scatter {scatter}; the scatter governs (Type A, "
                "ν = {dof})"), u=f"{u_std:.3f}\"", scatter=scatter, dof=dof)
        return message(QT_TR_NOOP("one error per reading, counted once: no standard states a "
                                  "u per reading, so the scatter {scatter} (Type A, ν = {dof})"),
                       scatter=scatter, dof=dof)
    s_rep, dof_rep, readings = pooled
    scatter = message(QT_TR_NOOP("s = {s} (the means' vertical readings about the fit, {n} "
                                 "points, ν = {dof}; taken for the azimuth too: it holds the "
                                 "means' own noise)"), s=f"{s:.3f}\"", n=n, dof=dof)
    repeats = message(QT_TR_NOOP("the pooled s/√n = {s} of the {readings} azimuth readings "
                                 "at each point (ν = {dof})"),
                      s=f"{s_rep:.3f}\"", readings=readings, dof=dof_rep)
    verdict = {"standard": message(QT_TR_NOOP("the standard governs (Type B, ν = ∞)")),
               "scatter": message(QT_TR_NOOP("the scatter governs (Type A, ν = {dof})"),
                                  dof=dof),
               "repeats": message(QT_TR_NOOP("the repeated readings govern (Type A, "
                                             "ν = {dof})"), dof=dof_rep),
               "both": message(QT_TR_NOOP("the standard with the repeated readings governs "
                                          "(ν_eff = {dof})"), dof=f"{nu:.0f}")}[governs]
    if stated:
        circle = _circle_part(u_std, s_rep, readings)
        return message(QT_TR_NOOP(
            "one error per point's mean of {readings} readings, counted once: the larger of "
            "the scatter {scatter} and the stated standards' u = {u} per reading split in "
            "two, the part the repeats show to scatter, which averages ({repeats}), and the "
            "rest, √max(u² − s_repeat², 0) = {circle}, the instrument's error at that circle "
            "position, the same in every repeat: √(u_c² + (s/√n)²) = {both}; {verdict}"),
            readings=readings, u=f"{u_std:.3f}\"", scatter=scatter, repeats=repeats,
            circle=f"{circle:.3f}\"", both=f"{math.hypot(circle, s_rep):.3f}\"",
            verdict=verdict)
    return message(QT_TR_NOOP(
        "one error per point's mean of {readings} readings, counted once: no standard states "
        "a u per reading, so the larger of the scatter {scatter} and {repeats}; {verdict}"),
        readings=readings, scatter=scatter, repeats=repeats, verdict=verdict)


def _circle_part(u_std: float, s_mean: float, readings: int) -> float:
    """The part of the stated u per reading that a point's n repeats do not show to scatter,
    √max(u_std² − s_repeat², 0), s_repeat = s_mean·√n (``s_mean``: the pooled s/√n); u_std
    whole with one reading a point."""
    return math.sqrt(max(u_std**2 - readings * s_mean**2, 0.0))


def reading_error_components(result: TheodoliteResult,
                             metadata: CertificateMetadata) -> list[BudgetComponent]:
    """The theodolite's reading error, one input (see the module's note): u_read = max(s,
    u_std); with n readings a point max(s, √(u_c² + (s_repeat/√n)²)), u_c the stated u's
    part the repeats do not show (:func:`_circle_part`). At the point's own
    reading (independent per point) and at the reference reading θ₀ (one value for the run),
    sensitivity 1 at every point but θ₀; its ν that of the figure that governs."""
    n = result.theta_deg.size
    single = _not_reference(result)
    dof = max(n - 3, 1)
    res = result.elevation_residuals_arcsec
    s = float(np.sqrt(np.sum(res**2) / dof))
    u_std, stated = stated_reading_uncertainty(metadata)
    pooled = pooled_repeats(result)
    s_rep, dof_rep, readings = pooled if pooled is not None else (0.0, 0, 1)
    # a mean's error: the part the repeats show to scatter averages (s_rep = s_repeat/√n);
    # the rest of one reading's stated error is the circle's, the same in every repeat
    circle = _circle_part(u_std, s_rep, readings)
    u_mean = math.hypot(circle, s_rep)
    ident = result.identification
    if not ident.tilt_identified and pooled is None:  # no fit, no scatter: never a noise of 0
        value = max(u_std, ident.reading_noise_arcsec)
        note = per_angle_note(message(QT_TR_NOOP(
            "one error per reading, counted once: the elevations do not vary, so they show no "
            "scatter; the larger of the stated standards' u = {u} per reading and the "
            "theodolite accuracy {accuracy} (the setting), Type B, ν = ∞"),
            u=f"{u_std:.3f}\"", accuracy=f"{ident.reading_noise_arcsec:g}\""), stated)
        return [
            BudgetComponent(READING_INPUT, "B", "normal", value, 1.0, single, math.inf,
                            message(QT_TR_NOOP("{governs}; the point's own reading, one value "
                                               "per point"), governs=note),
                            dof_group="reading"),
            BudgetComponent(REFERENCE_READING_INPUT, "B", "normal", value, 1.0, single,
                            math.inf, QT_TR_NOOP(
                                "the zeroing reading at θ₀, shared by every point (one value "
                                "for the run): two readings enter each error, the point's and "
                                "the zero's, each with the same u (the figure chosen once, "
                                "above); one input for ν_eff"),
                            common=True, dof_group="reading")]
    if u_mean > s and s_rep == 0.0:  # one reading a point (or n equal ones): the standard
        governs, evaluation, nu = "standard", "B", math.inf
        if len(stated) == 1:  # its own figure and distribution (per reading: u/√2 of
            # one stated for any angle, an angle being two readings)
            value = stated[0].uncertainty_in("arcsec")
            divisor, distribution = divisor_for_basis(stated[0].basis)
            if stated[0].applies_to == "angle":
                value *= PER_ANGLE_READING_SHARE
        else:
            value, divisor, distribution = u_std, 1.0, "normal"
    elif u_mean > s and circle == 0.0:  # no standard, or one the repeats' scatter shows whole
        governs, evaluation, nu, value, divisor, distribution = (
            "repeats", "A", float(dof_rep), s_rep, 1.0, "normal")
    elif u_mean > s:  # Welch–Satterthwaite of the two parts (the circle's ν = ∞)
        governs, value, divisor, distribution = "both", u_mean, 1.0, "normal"
        evaluation = "B" if circle >= s_rep else "A"
        nu = float(math.floor(u_mean**4 / (s_rep**4 / dof_rep) + 1e-9))
    else:
        governs, evaluation, nu, value, divisor, distribution = (
            "scatter", "A", float(dof), s, 1.0, "normal")
    note = _reading_error_notes(result, s, dof, u_std, bool(stated), governs, nu, pooled)
    note = per_angle_note(note, stated)
    own = (QT_TR_NOOP("{governs}; the point's own reading, one value per point")
           if pooled is None else
           QT_TR_NOOP("{governs}; the point's own mean, one value per point"))
    return [
        BudgetComponent(READING_INPUT, evaluation, distribution, value, divisor, single, nu,
                        message(own, governs=note), dof_group="reading"),
        BudgetComponent(REFERENCE_READING_INPUT, evaluation, distribution, value, divisor,
                        single, nu,
                        QT_TR_NOOP("the zeroing reading at θ₀, shared by every point (one "
                                   "value for the run): two readings enter each error, the "
                                   "point's and the zero's, each with the same u (the figure "
                                   "chosen once, above); one input for ν_eff"),
                        common=True, dof_group="reading")]


#: the budget's names of the reading error at the point and at θ₀ (one input, two readings)
READING_INPUT = QT_TR_NOOP("Reading error (pointing)")
REFERENCE_READING_INPUT = QT_TR_NOOP("Reference reading (θ₀)")


def theodolite_budget(result: TheodoliteResult, metadata: CertificateMetadata,
                      settings: Mapping[str, Any] | None = None) -> UncertaintyBudget:
    """The budget of the corrected error, held to the laboratory's CMC of the ``settings``
    ``result`` was analysed with (None: none)."""
    n = result.theta_deg.size
    single = _not_reference(result)
    pair = math.sqrt(2.0) * single
    dof = max(n - 3, 1)
    components = reading_error_components(result, metadata)
    ident = result.identification
    if ident.tilt_identified:
        components.append(BudgetComponent(
            MODEL_INPUT, "A", "normal", result.model_uncertainty_arcsec,
            1.0, 1.0, dof, QT_TR_NOOP("covariance of the identified parameters propagated "
                                      "through ζ(θ)")))
    elif ident.tilt_bound_arcsec > 0:
        # the model's u is the bound's effect ÷ √3 (models.theodolite.model.model_error_modes)
        components.append(BudgetComponent(
            TILT_BOUND_INPUT, "B", "rectangular",
            result.model_uncertainty_arcsec * math.sqrt(3.0), math.sqrt(3.0), 1.0, math.inf,
            message(QT_TR_NOOP("a tilt up to {psi} (stated) in its worst direction, not "
                               "identified by the elevations and not removed: its exact "
                               "effect on ζ(θ) with β = {beta}")
                    if ident.tilt_bound_arcsec != DEFAULT_TILT_BOUND_ARCSEC else
                    QT_TR_NOOP("a tilt up to {psi} (the program's default: no bound was "
                               "stated) in its worst direction, not identified by the "
                               "elevations and not removed: its exact effect on ζ(θ) with "
                               "β = {beta}"),
                    psi=f"{ident.tilt_bound_arcsec:g}\"", beta=f"{ident.setup.beta_deg:.4f}°")))
    components += resolution_component(metadata, pair)
    return UncertaintyBudget(tuple(components), n, metadata.coverage_probability,
                             floor=cmc_of(settings, "cmc_arcsec"))




def _degrees_with_u(value_deg: float, expanded_arcsec: float, fallback: int
                    ) -> tuple[str, str]:
    """A set-up parameter in degrees and its U, given in arcseconds, both printed in degrees
    to the same place (:func:`gum_pair`, GUM 7.2.6): ψ = 5.82625° with U = 6.3″ is
    "5.8263°" and "0.0018°" — not "5.8263°" beside "6.4″", a U whose last digit (0.1″) is
    finer than the value's (0.0001° = 0.36″: assessment 78 L3); without a U, ``fallback``
    decimals and "—"."""
    return gum_pair(value_deg, expanded_arcsec / 3600.0, "°", fallback=fallback)


def theodolite_json_budgets(result: TheodoliteResult, metadata: CertificateMetadata,
                            settings: Mapping[str, Any] | None = None
                            ) -> dict[str, UncertaintyBudget]:
    """The budget of each error array of the JSON: the raw error (the readings and the
    standards: every input but the set-up model), the model error (the set-up model alone)
    and the corrected error (all, the certificate's)."""
    full = theodolite_budget(result, metadata, settings)

    def part(keep, floor: float) -> UncertaintyBudget:
        return UncertaintyBudget(tuple(c for c in full.components if keep(c.name in SETUP_INPUTS)),
                                 full.points, full.probability, full.unit, floor)

    # the laboratory's CMC is a floor on the axis error's U, as found (raw) or corrected,
    # not on the set-up model's own (a correction, as the polygon's pyramidal one)
    return {"raw_error_arcsec": part(lambda model: not model, full.floor),
            "model_error_arcsec": part(lambda model: model, 0.0),
            "corrected_error_arcsec": full}


def _iso230_rows(result: TheodoliteResult, budget: UncertaintyBudget,
                 metadata: CertificateMetadata) -> list[tuple[str, str, str]]:
    """The ISO 230-2 figures of a run with passes, each with its coverage interval (held to
    the laboratory's CMC, the ``budget``'s floor) and the probability it reached
    (models.theodolite.figures), or why it has none."""
    from models.readings.resolution import readings_step
    from models.theodolite.figures import (
        figure_intervals_withheld,
        figures_scatter,
        stated_theodolite_figure_intervals,
        theodolite_figure_decimals,
        withheld_theodolite_figure_reasons,
    )
    from models.uncertainty.without_interval_note import figures_without_interval_note

    if result.iso230 is None:
        return []
    stated_u, pair = stated_reading_uncertainty(metadata)[0], stated_pair_factor(metadata)
    intervals = stated_theodolite_figure_intervals(result, budget, stated_u, pair)
    # R, R↑, R↓ of two passes: the value as measured, its interval withheld, and why
    alone = withheld_theodolite_figure_reasons(result, budget, stated_u, pair)
    withheld = figure_intervals_withheld(result)
    decimals = theodolite_figure_decimals(result, budget, stated_u, pair)
    rows = []
    for key, v in result.iso230.figures.items():
        if not math.isfinite(v):
            continue
        iv = intervals.get(key)
        if iv is None and key in alone:
            # to the decimal of the interval its reason quotes, the figure's own scatter, as
            # positioning's (day 68 F5: "R_up 4.24″" beside an interval 0″ … 443″ withheld);
            # the DCC states it at full precision
            d = decimals[key]
            rows.append((f"ISO 230-2 {key}", Exact(f"{fixed_places(v, d)}\"", float(v)), message(
                QT_TR_NOOP("no coverage interval: {reason}"), reason=alone[key])))
            continue
        if iv is None:  # no interval at all: to the decimal its readings support (F5)
            said = withheld is None or any(r[2] for r in rows)  # the reason once
            rows.append((f"ISO 230-2 {key}", Exact(f"{fixed_places(v, decimals[key])}\"", float(v)),
                         message(QT_TR_NOOP("no coverage interval")) if said else
                         figures_without_interval_note(
                             message(withheld), figures_scatter(result)[0],
                             readings_step(result.raw_error_arcsec), '"',
                             figures_scatter(result)[1])))
            continue
        # the value and the interval's ends (rounded outwards, as every interval) to the
        # decimal of its half-width (GUM 7.2.6), at full precision for the DCC and the
        # results export, which state them as numbers, as positioning's (audit 69 finding 5),
        # and converted from their values where read in another unit (assessment 70 H3)
        ends = interval_range(iv.low, iv.high, "\"")
        rows.append((f"ISO 230-2 {key}", printed(v, "\"", u=(iv.high - iv.low) / 2.0,
                                                 stated_exactly=True), interval_note(
            iv.low, iv.high, ends.low, ends.high, percent_text(iv.probability))))
    return rows


def _iso230_raised_to_cmc(result: TheodoliteResult, budget: UncertaintyBudget,
                          metadata: CertificateMetadata) -> tuple[str, ...]:
    """The ISO 230-2 figures (keys, as the statistics print them) whose interval
    :func:`_iso230_rows` states raised to the laboratory's CMC."""
    from models.theodolite.figures import stated_theodolite_figure_intervals
    from models.uncertainty.figure_intervals import figures_raised_to_cmc

    if result.iso230 is None or not budget.floor > 0:
        return ()
    return tuple(figures_raised_to_cmc(stated_theodolite_figure_intervals(
        result, budget, stated_reading_uncertainty(metadata)[0], stated_pair_factor(metadata))))


#: how the ISO 230-2 figures of a run with passes get their intervals: which figure's from
#: which method, so that an assessor can reproduce each (models.theodolite.figures; it said
#: A's was the bootstrap's: day review 68 F1, F6)
FIGURES_STATEMENT = QT_TR_NOOP(
    "Coverage interval of each ISO 230-2 figure of the passes: a figure is a largest value "
    "or a range over the θ, biased high by the scatter, so its interval, that of the true "
    "figure (of the true means and standard deviations at each θ and direction as this "
    "theodolite reads them: R and A hold its pointing noise), may lie below the value "
    "stated. The interval of E, E↑, E↓, M, B and B̄ is a parametric bootstrap of the "
    "figure's error from a model "
    "of the axis fitted to the means and standard deviations over the passes (the "
    "positioning workbench's, models/uncertainty/figure_intervals.py), with the set-up "
    "model's error (one curve over θ, drawn as its fit's covariance correlates it) and the "
    "part of the stated theodolite u that the passes' scatter does not show (the circle's "
    "error where it reads that θ, drawn once per θ), the same in every pass and both "
    "directions. The intervals of R and A use no bootstrap: they are bounds from each θ's "
    "own readings over the passes, never pooled. The interval of R, R↑ and R↓ is the "
    "bounds from each θ's own standard deviation (chi-square, ν = passes − 1: the upper end "
    "the largest θ's upper bound, the lower end the largest lower bound taken at once over "
    "the θ), which hold however the repeatability changes from θ to θ. The interval of A, "
    "A↑ and A↓ is the bounds from each θ's own mean and standard deviation: each end of a "
    "θ's band x̄ ± 2s by its one-sided tolerance bound, from the noncentral t distribution "
    "with ν = passes − 1 (Owen 1968; ISO 16269-6); the upper end the largest bound of a "
    "band's top less the smallest bound of a band's bottom, each at the whole tail (the "
    "intersection–union bound, Berger 1982: the two bounds together hold at it whatever "
    "their σ, exactly where one σ is far the larger), the lower end from every θ's bounds "
    "taken at "
    "once (Šidák over the θ and directions, Bonferroni within each); the set-up "
    "model's error enters them at a tenth of the tail, as the "
    "largest difference of its errors at two θ. These intervals of R and A are wide at few "
    "passes, because each θ's σ is known only from its own readings (at 3 passes each σ has "
    "2 degrees of freedom), so a specification of R or A may not be decidable. The interval "
    "of E, M and A (and E↑, E↓, A↑, A↓) is also widened for a circle error shaped as the "
    "curve's worst, as large as the readings do not exclude (the stated u over the pointing "
    "noise's lower confidence bound, at a quarter of the tail, the widened interval at the "
    "rest). The probability stated is the one a simulation study reached where that is "
    "lower.")
#: how a run with passes is decided
MEANS_STATEMENT = QT_TR_NOOP(
    "The half range is decided on the means over the passes at each θ and direction (the "
    "reversal kept), each with its own budget: the passes' pooled scatter over √n, the "
    "set-up model's error and the part of the stated theodolite u that the scatter does not "
    "show, the same at a θ in every pass. Where the readings do not exclude such a part "
    "(the stated u over the pointing noise's lower confidence bound), its shape is not "
    "known: the interval also holds ISO 230-2 E's halved, which holds a circle error of any "
    "shape up to that part.")


def _passes_statements(result: TheodoliteResult, metadata: CertificateMetadata,
                       budget: UncertaintyBudget) -> tuple[str, ...]:
    """What the certificate says of a run with passes: how its figures' intervals and its
    decided half range are made, how far the circle error the readings do not exclude
    widens the figures' intervals, and how much of R and A is the theodolite's pointing
    noise (the latter wherever R is evaluated; the others nothing where the passes do not
    determine them)."""
    from models.theodolite.figures import (
        circle_widening_note,
        least_passes,
        pointing_in_figures_note,
        stated_theodolite_figure_intervals,
    )
    from models.theodolite.pass_means import decided_on_means
    from models.uncertainty.wide_intervals import wide_intervals_statement

    pointing = pointing_in_figures_note(result)
    said = () if pointing is None else (pointing,)
    if result.iso230 is not None:  # an upper end far above its figure: why (day 68 F6)
        wide = wide_intervals_statement(
            result.iso230.figures, stated_theodolite_figure_intervals(
                result, budget, stated_reading_uncertainty(metadata)[0],
                stated_pair_factor(metadata)), least_passes(result), "\"", passes=True)
        said += () if wide is None else (wide,)
    if not decided_on_means(result):
        return said
    widening = circle_widening_note(result, budget, stated_reading_uncertainty(metadata)[0],
                                    stated_pair_factor(metadata))
    return ((separated([message(FIGURES_STATEMENT), widening], " "),) + said
            + ((message(MEANS_STATEMENT),) if metadata.decision_quantity == "half_range"
               and metadata.tolerance is not None else ()))


def _decision(result: TheodoliteResult, metadata: CertificateMetadata,
              settings: Mapping[str, Any] | None, budget: UncertaintyBudget) -> Decision:
    """The curve the statement of conformity is made on: with passes that determine it and
    the half range decided, the means over the passes at each θ and direction with their
    own budget (models.theodolite.pass_means; ``budget``: the run's, whose figures' E the
    means' interval may be united with); else every reading's corrected error, its half
    range withheld where the passes show no random scatter (pass_means.withheld_half_range)."""
    from models.theodolite.pass_means import (
        MEANS_DECIDED,
        decided_on_means,
        means_half_range,
        pass_means,
        pass_means_budget,
        withheld_half_range,
    )
    from models.theodolite.unidentified_tilt_half_range import (
        TILT_INPUTS,
        tilt_not_removed,
        tilt_widened,
    )
    from models.uncertainty.bounded_systematic_half_range import without_inputs
    from models.uncertainty.conformity import half_range_monte_carlo

    # a tilt not identified: one unknown error for the run, not noise (audit 72 finding 1):
    # the half range decided on the other inputs, its interval widened by the tilt's largest
    # change to it (models.theodolite.unidentified_tilt_half_range)
    tilt = metadata.decision_quantity == "half_range" and tilt_not_removed(result)
    if metadata.decision_quantity == "half_range" and decided_on_means(result):
        means, names = pass_means(result)
        stated = stated_reading_uncertainty(metadata)[0]
        means_budget = pass_means_budget(result, metadata, stated, settings)
        if tilt:  # the set-up model's modes are the tilt's bound alone
            noise_budget = without_inputs(means_budget, {
                c.name for c in means_budget.components if c.dof_group == "set-up model"})
            return Decision(means, MEANS_DECIDED, names, budget=means_budget,
                            estimate=tilt_widened(result, means_half_range(
                                result, noise_budget, without_inputs(budget, TILT_INPUTS),
                                stated, stated_pair_factor(metadata))))
        return Decision(means, MEANS_DECIDED, names, budget=means_budget,
                        estimate=means_half_range(result, means_budget, budget, stated,
                                                  stated_pair_factor(metadata)))
    withheld = (withheld_half_range(result, budget.probability)
                if metadata.decision_quantity == "half_range" else None)
    if withheld is not None and result.directions is not None:  # the means' curve, named
        means, names = pass_means(result)
        return Decision(means, MEANS_DECIDED, names, estimate=withheld)
    if withheld is None and tilt:
        withheld = tilt_widened(result, half_range_monte_carlo(
            result.corrected_error_arcsec, without_inputs(budget, TILT_INPUTS)))
    return Decision(result.corrected_error_arcsec, point_names=_point_names(result.theta_deg),
                    estimate=withheld)


#: the parameters table's cell of ψ and α when the elevations do not identify the tilt
TILT_NOT_IDENTIFIED_CELL = QT_TR_NOOP("not identified by the elevations")


def theodolite_certificate(result: TheodoliteResult, metadata: CertificateMetadata,
                           source_name: str = "", method_reference: str = "",
                           settings: Mapping[str, Any] | None = None) -> CertificateDocument:
    budget = theodolite_budget(result, metadata, settings)
    big_u = budget.expanded
    ident = result.identification
    s = ident.setup
    # their own ν: the fit's n − 3 (three parameters from n elevations)
    nu = max(result.theta_deg.size - 3, 1)
    k = coverage_factor(nu, budget.probability)
    u2 = k * ident.uncertainty_deg * 3600.0  # expanded, arcsec
    parameters = Table(
        QT_TR_NOOP("Set-up parameters identified") if ident.tilt_identified else
        QT_TR_NOOP("Set-up parameters: the tilt not identified"),
        # k and ν are the fit's: where no fit was made (the tilt not identified) the column
        # holds the stated bound and β's origin, no k (assessment 72 L7)
        (QT_TR_NOOP("Parameter"), QT_TR_NOOP("Value"),
         f"U (k = {k:.2f}, ν = {nu})" if ident.tilt_identified else "U"),
        [(QT_TR_NOOP("Axis tilt ψ"), *_degrees_with_u(s.psi_deg, u2[0], 5))
         if ident.tilt_identified else
         (QT_TR_NOOP("Axis tilt ψ"), message(TILT_NOT_IDENTIFIED_CELL),
          message(QT_TR_NOOP("bound {bound} (stated) in U")
                  if ident.tilt_bound_arcsec != DEFAULT_TILT_BOUND_ARCSEC else
                  QT_TR_NOOP("bound {bound} (the program's default) in U"),
                  bound=f"{ident.tilt_bound_arcsec:g}\"")),
         (QT_TR_NOOP("Tilt direction α"), *_degrees_with_u(s.alpha_deg, u2[1], 4))
         if ident.alpha_determined else
         (QT_TR_NOOP("Tilt direction α"), message(NOT_IDENTIFIED if ident.tilt_identified
                                                  else TILT_NOT_IDENTIFIED_CELL), ""),
         (QT_TR_NOOP("Mirror normal β"), *_degrees_with_u(s.beta_deg, u2[2], 5))
         if ident.tilt_identified else
         (QT_TR_NOOP("Mirror normal β"), f"{s.beta_deg:.4f}°",
          message(QT_TR_NOOP("−E at the reference reading"))),
         (QT_TR_NOOP("Identified from"), message(_IDENTIFIED_FROM.get(
             ident.method, QT_TR_NOOP("{method} readings")), method=ident.method), ""),
         *(((QT_TR_NOOP("R² of the fit"), f"{ident.r_squared:.8f}", ""),
            (QT_TR_NOOP("Residual RMS"), f"{ident.residual_rms_arcsec:.3f}\"", ""))
           if ident.tilt_identified else
           ((QT_TR_NOOP("R² of the fit"), message(QT_TR_NOOP("no fit")), ""),)),
         (QT_TR_NOOP("Reference point θ₀"), f"{result.reference_theta_deg:g}°", "")])
    correction = -result.model_error_arcsec
    results = PointTable(QT_TR_NOOP("Results per point (corrected = raw + correction)"), (
        text_column("θ (°)", [f"{t:.4f}" for t in result.theta_deg]),
        figure_column(QT_TR_NOOP("Raw error (\")"), result.raw_error_arcsec, big_u),
        difference_column(QT_TR_NOOP("Correction (\")"), result.corrected_error_arcsec,
                          result.raw_error_arcsec, big_u),
        figure_column(QT_TR_NOOP("Corrected error (\")"), result.corrected_error_arcsec, big_u),
        uncertainty_column("U (\")", big_u, result.corrected_error_arcsec)))
    r, c = result.raw_stats, result.corrected_stats
    # to the decimal of the results table's U (GUM 7.2.6), the peak-to-peak as printed
    raw_range, raw_ptp, _ = range_cells(r.min, r.max, budget.max_expanded)
    corrected_range, corrected_ptp, d = range_cells(c.min, c.max, budget.max_expanded)
    statistics = Statistics([
        (QT_TR_NOOP("Points"), f"{c.n}", ""),
        (QT_TR_NOOP("Raw error"), raw_range,
         message(QT_TR_NOOP("peak-to-peak {ptp}"), ptp=raw_ptp)),
        (QT_TR_NOOP("Corrected error"), corrected_range,
         message(QT_TR_NOOP("peak-to-peak {ptp}, RMS {rms}"), ptp=corrected_ptp,
                 rms=printed(c.rms, "\"", u=budget.max_expanded)
                 if budget.max_expanded > 0 and math.isfinite(budget.max_expanded) else
                 printed(c.rms, "\"", decimals=d))),
    ], QT_TR_NOOP("points"), after=_iso230_rows(result, budget, metadata))
    return build_certificate(
        measurand_standards=MEASURAND_STANDARDS,
        kind_key=KEY, kind_title=TITLE, method=METHOD, metadata=metadata,
        source_name=source_name, method_reference=method_reference, budget=budget,
        parameters=parameters, results=results, statistics=statistics,
        decision=_decision(result, metadata, settings, budget),
        budget_point=lambda worst: f"θ = {result.theta_deg[worst]:g}°",
        plots=(error_figure(result), corrected_with_uncertainty(result, big_u),
               residual_figure(result)),
        # no fit, no residual to judge (the reason the tilt is not identified is a warning)
        warnings=certificate_warnings(result.warnings, ident.residual_rms_arcsec
                                      if ident.tilt_identified else 0.0,
                                      stated_reading_uncertainty(metadata)[0], settings),
        statements=(message(QT_TR_NOOP("U is zero at the reference reading (row {row}, θ₀ = "
                                       "{theta}): the theodolite was zeroed there, so its error "
                                       "is zero by definition."),
                            row=result.reference_index + 1,
                            theta=f"{result.reference_theta_deg:g}°"), SETUP_DEFINITIONS,
                    *_passes_statements(result, metadata, budget)),
        figures_raised_to_cmc=_iso230_raised_to_cmc(result, budget, metadata),
        point_columns=(("theta_deg", result.theta_deg), ("raw_error_arcsec", result.raw_error_arcsec),
         ("correction_arcsec", correction), ("corrected_error_arcsec", result.corrected_error_arcsec),
         ("expanded_uncertainty_arcsec", big_u)))
