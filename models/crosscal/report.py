"""Cross-calibration: uncertainty budget and certificate content, for the polygon (its
face deviations) or for the encoder (its error at its steps) — the setting
``certificate_of`` chooses.

Each result is a linear function of the readings (least squares under the closure
constraints), so its standard uncertainty is exact from the design: the diagonal of
σ²·(AᵀA)⁺ on the constraints, σ the scatter of one reading from the fit's residuals
(Type A, ν = readings − unknowns) or as stated. No reference standard enters: the
closure of the circle is the reference. The item's resolution, when stated, enters per
reading through the same design (its standard uncertainty scales σ's share).
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
    figure_column,
    text_column,
    uncertainty_column,
)
from models.certificate.document import CertificateDocument, Table, range_cells
from models.certificate.metadata import CertificateMetadata, MetadataError
from models.crosscal import (
    DEFAULT_TILT_BOUND_ARCSEC,
    KEY,
    POLYGON_SIGN_CONVENTION_TEXT,
    TITLE,
)
from models.crosscal.export import comparator_not_stated
from models.crosscal.figures import encoder_figures
from models.crosscal.plots import closure_figure, encoder_figure, polygon_figure, residual_figure
from models.messages import QT_TR_NOOP, message, separated
from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.printed_figure import printed
from models.uncertainty.tilt_bound_words import BOUND_UNCHECKED

__all__ = ["crosscal_budget", "crosscal_certificate"]

METHOD = QT_TR_NOOP(
    "Cross-calibration by the closure principle: a polygon is fixed on the shaft of the encoder "
    "in several mountings (turned by j faces on the shaft) and in each mounting the shaft is "
    "turned from the same encoder reading through the encoder's n steps of 360°/n, an "
    "autocollimator reading each face in turn. Each reading is the encoder's error at its step "
    "plus the polygon's deviation at the face plus the mounting's offset (and drift); the faces "
    "of the polygon and the steps of a full turn each close at 360°, so both error sets are "
    "found together by least squares, without a calibrated polygon. Harmonics that the "
    "mountings chosen cannot separate are named and not reported. Each mounting ends with a "
    "closure reading of its first face after the full turn: its change over the turn is the "
    "mounting's drift, fitted or spread linearly over the mounting and removed, or reported, as "
    "set. When vertical readings are given, the polygon's tilt on the shaft is fitted for each "
    "mounting from them and its effect on the horizontal readings removed, in the frame the "
    "autocollimator is set up in.")


#: :data:`METHOD` where a mounting has no closure reading of its own: the closure sentence
#: said of the mountings that have one, and what is done with the others' drift (assessment
#: 70 M8: "Each mounting ends with a closure reading" printed of a run with none)
METHOD_SOME_WITHOUT_CLOSURE = QT_TR_NOOP(
    "Cross-calibration by the closure principle: a polygon is fixed on the shaft of the encoder "
    "in several mountings (turned by j faces on the shaft) and in each mounting the shaft is "
    "turned from the same encoder reading through the encoder's n steps of 360°/n, an "
    "autocollimator reading each face in turn. Each reading is the encoder's error at its step "
    "plus the polygon's deviation at the face plus the mounting's offset (and drift); the faces "
    "of the polygon and the steps of a full turn each close at 360°, so both error sets are "
    "found together by least squares, without a calibrated polygon. Harmonics that the "
    "mountings chosen cannot separate are named and not reported. Where a mounting ends with a "
    "closure reading of its first face after the full turn, its change over the turn is the "
    "mounting's drift, fitted or spread linearly over the mounting and removed, or reported, as "
    "set; a mounting without one has its drift fitted through the other mountings' closure "
    "readings where the design determines it, and otherwise its drift is not measured (the "
    "set-up parameters name each). When vertical readings are given, the polygon's tilt on the "
    "shaft is fitted for each mounting from them and its effect on the horizontal readings "
    "removed, in the frame the autocollimator is set up in.")


DRIFT_WORDS = {"fit": QT_TR_NOOP("fitted linearly over each mounting by least squares and removed"),
               "spread": QT_TR_NOOP("spread linearly over each mounting and removed"),
               "report": QT_TR_NOOP("reported, not removed")}


def _tilt_rows(result) -> list[tuple[str, Any, Any]]:
    """The set-up parameters' tilt row where some mounting's tilt is not identified (none
    where every one is fitted): which mountings, and the bound whose effect enters U for
    them, stated or the program's default (audit 73 finding 3, the theodolite's set-up
    table's; a bound of 0 is refused there: models.crosscal.analysis), and that the readings
    cannot check it, as the theodolite's and the polygon's decisions say (left 74)."""
    unidentified = result.unidentified_tilt_mountings
    if not unidentified:
        return []
    return [(QT_TR_NOOP("Tilt of the polygon on the shaft (not measured)"),
             message(QT_TR_NOOP("not identified in mounting(s) {mountings}"),
                     mountings=", ".join(map(str, unidentified))),
             separated([message(QT_TR_NOOP("bound {bound} (stated) in U")
                                if result.tilt_bound_arcsec != DEFAULT_TILT_BOUND_ARCSEC else
                                QT_TR_NOOP("bound {bound} (the program's default) in U"),
                                bound=f"{result.tilt_bound_arcsec:g}\""),
                        message(BOUND_UNCHECKED)], "; "))]


def _drift_row(result) -> tuple[str, Any, Any]:
    """The set-up parameters' "Closure drift" row, said of each mounting as it was done: the
    mode's words for the mountings with a closure reading of their own; a mounting without
    one has its drift fitted through the others' closure readings (where the design
    determines it: models.crosscal.uncertainty.unchecked_drift_mountings) or not measured."""
    s = result.solution
    unchecked = set(result.unchecked_drift_mountings)
    own = [j for j, c in zip(s.mountings, result.closure_arcsec, strict=True) if math.isfinite(c)]
    fitted = [j for j in s.mountings if j not in own and j not in unchecked]
    value = DRIFT_WORDS[result.drift_mode] if own else QT_TR_NOOP("not measured (no closure "
                                                                  "readings)")
    notes = [message(QT_TR_NOOP("no closure reading in mounting(s) {mountings}: their drift "
                                "fitted through the other mountings' closure readings"),
                     mountings=", ".join(map(str, fitted))) if fitted else "",
             message(QT_TR_NOOP("no closure reading in mounting(s) {mountings}: their drift not "
                                "measured"),
                     mountings=", ".join(map(str, sorted(unchecked)))) if unchecked and own
             else ""]
    return QT_TR_NOOP("Closure drift"), value, separated(notes, "; ")


def _per_point(result) -> tuple[np.ndarray, np.ndarray, str]:
    """(values, u of one reading's scatter per point, what) of the certificate's item, each
    about its mean over the n faces or steps (the budget's and the conformity's quantity)."""
    s = result.solution
    if result.certificate_of == "encoder":
        return s.encoder_error_arcsec, s.encoder_error_u_arcsec, "encoder"
    return s.polygon_deviation_arcsec, s.polygon_deviation_u_arcsec, "polygon"


def crosscal_budget(result, metadata: CertificateMetadata) -> UncertaintyBudget:
    s = result.solution
    _, u, _ = _per_point(result)
    nu = s.dof
    components = [BudgetComponent(
        QT_TR_NOOP("Reading scatter through the design"), "A" if math.isfinite(nu) else "B",
        "normal", np.asarray(u, dtype=float), 1.0, 1.0, nu,
        message(QT_TR_NOOP("σ = {sigma} of one reading ({how}), propagated exactly through the "
                           "least-squares design of {mountings} mountings"),
                sigma=f"{s.sigma_arcsec:.4f}\"",
                how=message(QT_TR_NOOP("from the residuals, ν = {nu}"), nu=f"{nu:.0f}")
                if math.isfinite(nu) else message(QT_TR_NOOP("stated")),
                mountings=len(s.mountings)))]
    r = metadata.item_resolution_in("arcsec")
    if r and s.sigma_arcsec > 0:
        components.append(BudgetComponent(
            QT_TR_NOOP("Item resolution"), "B", "rectangular", np.asarray(u) / s.sigma_arcsec * r / 2,
            math.sqrt(3.0), 1.0, math.inf,
            message(QT_TR_NOOP("resolution {r} per reading, through the same design"),
                    r=f"{r:g}\"")))
    components += _comparator_components(result, metadata)
    components += _systematic_components(result, np.asarray(u, dtype=float))
    return UncertaintyBudget(tuple(components), result.faces, metadata.coverage_probability,
                             floor=result.cmc)


def _comparator_components(result, metadata: CertificateMetadata) -> list[BudgetComponent]:
    """Each comparator's stated uncertainty (the autocollimator's calibration), an input of
    every reading: the closure is the reference, but every reading is made with the
    comparator, and its indication error at a reading is known only within its certificate's
    U. Taken as independent from reading to reading and propagated exactly through the design,
    like the reading scatter: a constant part cancels in each mounting's offset (so this is on
    the safe side), a part that follows the reading's value is what its certificate bounds.
    A comparator listed without a stated uncertainty is no input: the certificate then says
    the results are not traceable through it."""
    from models.uncertainty.budget import divisor_for_basis

    s = result.solution
    through = np.sqrt(np.sum(np.asarray(s.gain, dtype=float)[_item_block(result)] ** 2, axis=1))
    out = []
    for std in metadata.standards:
        stated = std.uncertainty_in("arcsec")
        if stated is None or not stated > 0:
            continue
        divisor, distribution = divisor_for_basis(std.basis)
        out.append(BudgetComponent(
            message(QT_TR_NOOP("Comparator calibration: {standard}"),
                    standard=std.description or message(QT_TR_NOOP("comparator"))),
            "B", distribution, stated * through, divisor, 1.0, math.inf,
            message(QT_TR_NOOP("its stated uncertainty {u} per reading (certificate {certificate}), "
                               "through the least-squares design as the reading scatter is"),
                    u=f"{stated:g}\"", certificate=std.certificate_no or "—")))
    return out


def comparator_u_arcsec(result, metadata: CertificateMetadata, combine=None) -> np.ndarray:
    """Standard uncertainty that the comparators' stated U (each independent from reading to
    reading, as in :func:`_comparator_components`) adds to (E, d) — or to combine·(E, d),
    e.g. the values from face 1 — through the design (results = G·y)."""
    from models.uncertainty.budget import divisor_for_basis

    g = np.asarray(result.solution.gain, dtype=float)
    if combine is not None:
        g = np.asarray(combine, dtype=float) @ g
    through2 = np.sum(g**2, axis=1)
    var = np.zeros(g.shape[0])
    for std in metadata.standards:
        stated = std.uncertainty_in("arcsec")
        if stated is None or not stated > 0:
            continue
        var = var + (stated / divisor_for_basis(std.basis)[0]) ** 2 * through2
    return np.sqrt(var)


def _item_block(result) -> slice:
    n = result.faces
    return slice(0, n) if result.certificate_of == "encoder" else slice(n, 2 * n)


def _systematic_components(result, u_scatter: np.ndarray) -> list[BudgetComponent]:
    """The bench's systematic inputs, each through the design (results = G·y, so a pattern
    δy in the readings moves them by G·δy exactly): the autocollimator's scale error over the
    readings' span, and an unmeasured tilt of the polygon on the shaft (its fitted tilt's own
    uncertainty, when vertical readings were given, if it is not negligible)."""
    from models.crosscal.uncertainty import (
        drift_effect_arcsec,
        drift_pattern_arcsec,
        own_drift_effect_arcsec,
        reported_drift_bias_arcsec,
        roll_pattern_arcsec,
        scale_effect_arcsec,
        tilt_effect_arcsec,
        tilt_fit_effect_arcsec,
    )

    s, r, block = result.solution, result.readings, _item_block(result)
    out = []
    if result.ac_scale_pct > 0:
        c = np.asarray(r.ac_x_arcsec, dtype=float)
        # one scale error for the whole run: δ(E, d) = −s·G·c, its sign point by point
        pattern = -(s.gain @ c)[block]
        out.append(BudgetComponent(
            QT_TR_NOOP("Autocollimator scale error"), "B", "rectangular",
            result.ac_scale_pct / 100.0 * scale_effect_arcsec(s, c)[block], math.sqrt(3.0),
            np.where(pattern < 0, -1.0, 1.0), math.inf,
            message(QT_TR_NOOP("up to ±{scale} of the reading (scale and linearity, stated) over "
                               "the readings' span {low} … {high}, through the design"),
                    scale=f"{result.ac_scale_pct:g} %", low=f"{np.min(c):+.1f}\"",
                    high=f"{np.max(c):+.1f}\""), common=True))
    pattern = roll_pattern_arcsec(s, r.ac_y_arcsec)[block]
    roll = math.radians(result.ac_roll_arcmin / 60.0) * np.abs(pattern)
    if np.any(roll > 0):
        # one roll for the whole run: δ(E, d) = ρ·G·y, its sign point by point. An audit
        # (mountings seated with tilts of 100-300″, the autocollimator rolled up to 1′, low
        # noise) found the face deviations' U covering 92.7 % with no such input
        out.append(BudgetComponent(
            QT_TR_NOOP("Autocollimator roll ρ (cross-talk ρ·y)"), "B", "rectangular",
            roll, math.sqrt(3.0), np.where(pattern < 0, -1.0, 1.0), math.inf,
            message(QT_TR_NOOP("roll about the line of sight up to ±{roll} (stated, not "
                               "measured) times each vertical reading, through the design"),
                    roll=f"{result.ac_roll_arcmin:g}′"), common=True))
    unmeasured = [j for j, t in zip(s.mountings, s.tilts or (None,) * len(s.mountings),
                                    strict=True) if t is None]
    if unmeasured and result.tilt_bound_arcsec > 0:
        out.append(BudgetComponent(
            QT_TR_NOOP("Tilt of the polygon on the shaft (not measured)"), "B", "rectangular",
            tilt_effect_arcsec(s, r.mounting, r.position, result.tilt_bound_arcsec)[block],
            math.sqrt(3.0), 1.0, math.inf,
            message(QT_TR_NOOP("no vertical readings in {count} mounting(s): a tilt up to {psi} "
                               "(stated) in its worst direction, exact effect in the set-up's "
                               "frame, through the design")
                    if result.tilt_bound_arcsec != DEFAULT_TILT_BOUND_ARCSEC else
                    # none typed: the program's figure, not the laboratory's (audit 73
                    # finding 3, the theodolite's and the polygon's)
                    QT_TR_NOOP("no vertical readings in {count} mounting(s): a tilt up to {psi} "
                               "(the program's default: no bound was stated) in its worst "
                               "direction, exact effect in the set-up's frame, through the "
                               "design"),
                    count=len(unmeasured), psi=f"{result.tilt_bound_arcsec:g}\"")))
    unchecked = result.unchecked_drift_mountings
    drift_effect = result.drift_bound_arcsec * drift_effect_arcsec(s)[block]
    if unchecked and np.max(drift_effect, initial=0.0) > 1e-9:  # (none for the faces)
        out.append(BudgetComponent(
            QT_TR_NOOP("Autocollimator drift (no closure reading)"), "B", "rectangular",
            drift_effect, math.sqrt(3.0),
            np.where(drift_pattern_arcsec(s)[block] < 0, -1.0, 1.0), math.inf,
            message(QT_TR_NOOP("no closure reading in mounting(s) {mountings}: a linear drift "
                               "up to ±{drift} over each such mounting (stated, not measured), "
                               "the same in all of them, through the design"),
                    mountings=", ".join(map(str, unchecked)),
                    drift=f"{result.drift_bound_arcsec:g}\""), common=True))
    own = result.drift_bound_arcsec * own_drift_effect_arcsec(s)[block]
    if unchecked and np.max(own, initial=0.0) > 1e-9:  # σ stated, two such mountings or more
        out.append(BudgetComponent(
            QT_TR_NOOP("Autocollimator drift, each mounting its own (no closure reading)"), "B",
            "rectangular", own, math.sqrt(3.0), 1.0, math.inf,
            message(QT_TR_NOOP("σ stated, so the reading scatter holds no drift that differs "
                               "between mountings: each of mounting(s) {mountings} drifting its "
                               "own way up to ±{drift} (stated, not measured), what that adds "
                               "beyond the same drift in all of them, through the design"),
                    mountings=", ".join(map(str, unchecked)),
                    drift=f"{result.drift_bound_arcsec:g}\"")))
    bias = reported_drift_bias_arcsec(s)[block]
    if np.max(np.abs(bias), initial=0.0) > 1e-9:  # "report": the closure drifts left in
        closures = result.closure_arcsec[np.isfinite(result.closure_arcsec)]
        # a known bias not corrected, in quadrature (RSS_u, as the polygon workbench carries
        # its drift: U = k·√(u_c² + b²) covers at ≥ 95 % for k = 2 whatever b/u_c)
        out.append(BudgetComponent(
            QT_TR_NOOP("Autocollimator drift, reported, not removed"), "B", "normal",
            np.abs(bias), 1.0, np.where(bias < 0, -1.0, 1.0), math.inf,
            message(QT_TR_NOOP("the closure drifts {closures} (beyond their reading noise) left "
                               "in the readings, linear over each mounting: the bias they leave, "
                               "through the design, in quadrature"),
                    closures=", ".join(f"{c:+.3f}" for c in closures) + "\""), common=True))
    fitted = tilt_fit_effect_arcsec(s, r.mounting, r.position)[block]
    if np.any(fitted > 0) and np.max(fitted) > 0.1 * np.min(u_scatter):
        out.append(BudgetComponent(
            QT_TR_NOOP("Tilt correction (fitted ψ, ω)"), "A", "normal", fitted, 1.0, 1.0, math.inf,
            QT_TR_NOOP("u(ψ), u(ω) of each mounting's tilt fit through its removed correction "
                       "and the design")))
    return out


def budget_remarks(result) -> tuple[str, ...]:
    """Why the budget has no separate row for drift, temperature and (when negligible) the
    fitted tilt's own uncertainty: one line for the certificate."""
    from models.crosscal.uncertainty import tilt_fit_effect_arcsec

    s, r = result.solution, result.readings
    drift = {"fit": QT_TR_NOOP("each mounting's drift is fitted with the results, so what is "
                               "left of it is in the reading scatter"),
             "spread": QT_TR_NOOP("each mounting's closure drift is removed, so what is left of "
                                  "it is in the reading scatter"),
             "report": QT_TR_NOOP("each mounting's drift is reported, not removed: the bias "
                                  "its closure drift leaves is a row above")}[result.drift_mode]
    said = message(drift)
    if result.unchecked_drift_mountings:  # mountings with no closure reading
        from models.crosscal.uncertainty import drift_effect_arcsec, own_drift_effect_arcsec

        block = _item_block(result)
        moved = result.drift_bound_arcsec * np.hypot(drift_effect_arcsec(s)[block],
                                                     own_drift_effect_arcsec(s)[block])
        said = message(QT_TR_NOOP("where a mounting ends with a closure reading, {how}; where "
                                  "none does, its row above, from the drift bound stated")
                       if np.max(moved, initial=0.0) > 1e-9 else
                       QT_TR_NOOP("where a mounting ends with a closure reading, {how}; where "
                                  "none does, a drift the same in every mounting does not move "
                                  "the face deviations, and what differs between mountings is "
                                  "in the reading scatter"), how=said)
    parts = [message(QT_TR_NOOP("Not separate rows of the budget: drift ({drift}); temperature "
                                "(the angles between a polygon's faces, and an encoder's steps "
                                "over a full turn, are insensitive to a uniform temperature)"),
                     drift=said)]
    fitted = tilt_fit_effect_arcsec(s, r.mounting, r.position)[_item_block(result)]
    if np.any(fitted > 0) and np.max(fitted) <= 0.1 * np.min(_per_point(result)[1]):
        parts.append(message(QT_TR_NOOP("the fitted tilts' own uncertainty changes the "
                                        "results by at most {u} (u), negligible"),
                             u=f"{np.max(fitted):.2g}\""))
    # joined and ended in the certificate's language (Chinese: "；" and "。", not "; ", ".")
    return (message(QT_TR_NOOP("{remarks}."), remarks=separated(parts, "; ")),)


def _budget_point(point: str, k: int, big_u: np.ndarray, item: str) -> str:
    """Where the budget is shown: the point with the largest U, or any when U is the same at
    every point (a full rosette)."""
    if np.ptp(big_u) <= 1e-6 * max(float(np.max(big_u)), 1e-12):
        return message(QT_TR_NOOP("{point} (U is the same at every step)") if item == "encoder"
                       else QT_TR_NOOP("{point} (U is the same at every face)"),
                       point=message(point, k=k))
    return message(point, k=k)


def _correlation_statement(result, item: str, metadata: CertificateMetadata | None = None) -> str:
    """The correlations within the certificate's set, as the covariance gives them: about the
    mean and from the first point, and the largest U of a difference of two."""
    n, s = result.faces, result.solution
    block = s.covariance_arcsec2[:n, :n] if item == "encoder" else s.covariance_arcsec2[n:, n:]
    off = ~np.eye(n, dtype=bool)

    def mean_r(c: np.ndarray) -> float:
        sd = np.sqrt(np.clip(np.diag(c), 1e-300, None))
        return float(np.mean((c / np.outer(sd, sd))[~np.eye(len(c), dtype=bool)]))

    first = block - block[:, :1] - block[:1, :] + block[0, 0]  # cov of x_i − x_1
    pair = np.diag(block)[:, None] + np.diag(block)[None, :] - 2.0 * block
    u2_pair = float(np.max(pair[off])) + _pair_systematic_u2(result, item, metadata)
    # a difference of two is the quantity stated from the first point (x_j − x_1): its U is
    # held to the laboratory's CMC as theirs is (ILAC-P14 5.4)
    u_pair = max(s.coverage_factor * np.sqrt(u2_pair), _cmc_of_item(result, item))
    return message(QT_TR_NOOP("Within these results the values are correlated: about the mean "
                              "r = {r_mean} on average between two of them (−1/(n − 1) = "
                              "{r_full} for a full rosette); stated from {first} r = {r_first}. "
                              "The U of the difference of any two, U(x_j − x_i), is at most "
                              "{u_pair}."),
                   r_mean=f"{mean_r(block):+.3f}", r_full=f"{-1.0 / (n - 1):+.3f}",
                   first=message(QT_TR_NOOP("step 0") if item == "encoder"
                                 else QT_TR_NOOP("face 1")),
                   r_first=f"{mean_r(first[1:, 1:]):+.2f}",
                   u_pair=printed(u_pair, "\""))  # in any unit, rounded there (H3)


def _cmc_of_item(result, item: str) -> float:
    """The laboratory's CMC for the item's quantity (0: none set)."""
    return result.cmc_encoder_arcsec if item == "encoder" else result.cmc_polygon_arcsec


def _from_first_cmc_statement(result, item: str, metadata: CertificateMetadata) -> tuple[str, ...]:
    """Where the laboratory's CMC raised a U stated from the first point (face 1, step 0):
    one sentence naming it and how many points (none when no such U was raised; the
    certificate's scope statement names the CMC's hold on the U about the mean)."""
    held = result.u_from_first(item, metadata)
    if held.below_floor is None or not np.any(held.below_floor):
        return ()
    raised = np.asarray(held.below_floor, dtype=bool)
    k = float(result.solution.coverage_factor)
    computed = k * (result.polygon_u_from_face1_standard_arcsec(metadata) if item != "encoder"
                    else result.encoder_u_from_step0_standard_arcsec(metadata))
    return (message(QT_TR_NOOP(
        "The laboratory's CMC for this quantity, U = {cmc}, holds the U stated from {first} and "
        "the U of the difference of any two too: from {first}, at {count} of the {others} other "
        "points the U these readings give (down to {lowest}) is below it, so it is stated as the "
        "CMC, with the same coverage factor k (ILAC-P14 5.4)."),
        cmc=f"{held.floor:g}\"",
        first=message(QT_TR_NOOP("step 0") if item == "encoder" else QT_TR_NOOP("face 1")),
        count=int(np.count_nonzero(raised)), others=raised.size - 1,
        lowest=f"{float(np.min(computed[raised])):.2g}\""),)


def _pair_systematic_u2(result, item: str, metadata: CertificateMetadata | None = None) -> float:
    """A bound on the squared standard uncertainty that the bench's stated bounds (scale,
    unmeasured tilt; rectangular) add to the difference of two values of the set: the scale
    effect's largest difference within the set, and twice the largest tilt effect."""
    from models.crosscal.uncertainty import (
        drift_effect_arcsec,
        own_drift_effect_arcsec,
        reported_drift_bias_arcsec,
        tilt_effect_arcsec,
    )

    n, s, r = result.faces, result.solution, result.readings
    block = slice(0, n) if item == "encoder" else slice(n, 2 * n)
    signed = s.gain[block] @ np.asarray(r.ac_x_arcsec, dtype=float)
    scale = result.ac_scale_pct / 100.0 * float(np.ptp(signed))
    tilt = 2.0 * float(np.max(tilt_effect_arcsec(s, r.mounting, r.position,
                                                 result.tilt_bound_arcsec)[block]))
    comparators = 0.0  # each comparator's u per reading, independent: Σ_k (G_ik − G_jk)² u²
    if metadata is not None:
        g = np.asarray(s.gain, dtype=float)[block]
        gram = g @ g.T
        spread = float(np.max(np.diag(gram)[:, None] + np.diag(gram)[None, :] - 2.0 * gram))
        for std in metadata.standards:
            stated = std.uncertainty_in("arcsec")
            if stated is not None and stated > 0:
                from models.uncertainty.budget import divisor_for_basis

                comparators += (stated / divisor_for_basis(std.basis)[0]) ** 2 * spread
    # the drift bound's rows in quadrature (the same drift in every mounting; σ stated, each
    # its own), twice the largest; the drift reported and left in: its bias's largest
    # difference within the set (a known pattern, in quadrature)
    drift = 2.0 * result.drift_bound_arcsec * float(np.max(np.hypot(
        drift_effect_arcsec(s)[block], own_drift_effect_arcsec(s)[block])))
    bias = float(np.ptp(reported_drift_bias_arcsec(s)[block]))
    return (scale**2 + tilt**2 + drift**2) / 3.0 + comparators + bias**2


def crosscal_certificate(result, metadata: CertificateMetadata, source_name: str = "",
                         method_reference: str = "",
                         settings: Mapping[str, Any] | None = None) -> CertificateDocument:
    s = result.solution
    values, _, item = _per_point(result)
    if item == "encoder" and values is not None and result.encoder_u_withheld is not None:
        raise MetadataError(message(QT_TR_NOOP("no certificate of the encoder: {reason}"),
                                    reason=result.encoder_u_withheld))
    if item == "polygon" and values is not None and result.polygon_u_withheld is not None:
        raise MetadataError(message(QT_TR_NOOP("no certificate of the polygon: {reason}"),
                                    reason=result.polygon_u_withheld))
    if values is None:
        raise MetadataError(message(QT_TR_NOOP(
            "no certificate: this design does not determine the {what} (harmonic(s) {orders} "
            "unseen); add a mounting"),
            what=message(QT_TR_NOOP("encoder's error") if item == "encoder"
                         else QT_TR_NOOP("face deviations")),
            orders=", ".join(map(str, s.undetermined_encoder_harmonics if item == "encoder"
                                 else s.undetermined_polygon_harmonics))))
    budget = crosscal_budget(result, metadata)
    big_u = budget.expanded
    n = result.faces
    closures = result.closure_arcsec
    rows_p = [(QT_TR_NOOP("Faces / encoder steps"), f"{n}", ""),
              (QT_TR_NOOP("Mountings"), ", ".join(map(str, s.mountings)), ""),
              (QT_TR_NOOP("σ of one reading"), f"{s.sigma_arcsec:.4f}\"",
               "ν = ∞" if not math.isfinite(s.dof) else f"ν = {s.dof:.0f}"),
              _drift_row(result),
              *_tilt_rows(result),
              (QT_TR_NOOP("Encoder"),
               QT_TR_NOOP("set to its nominal steps") if result.readings.nominal_encoder
               else QT_TR_NOOP("read at each step"),
               message(QT_TR_NOOP("start {start}; step k at start + k·{step}"),
                       start=f"{result.encoder_start_deg:.4f}°", step=f"{360.0 / n:g}°")),
              (QT_TR_NOOP("Largest correlation encoder / polygon"),
               f"{result.cross_correlation():.2f}", "")]
    for q, j in enumerate(s.mountings):
        if math.isfinite(closures[q]):
            rows_p.append((message(QT_TR_NOOP("Mounting {mounting} closure"), mounting=j),
                           f"{closures[q]:+.3f}\"", ""))
    parameters = Table(QT_TR_NOOP("Set-up parameters identified"),
                       (QT_TR_NOOP("Parameter"), QT_TR_NOOP("Value"), ""), rows_p)
    if item == "encoder":
        first = result.step_deg
        start = result.encoder_start_deg
        reading = (start + first) % 360.0
        u0 = result.encoder_u_from_step0_arcsec(metadata)
        results = PointTable(QT_TR_NOOP("Encoder error at its steps"), (
            text_column(QT_TR_NOOP("Step"), [f"{k}" for k in range(n)]),
            text_column(QT_TR_NOOP("From the start (°)"), [f"{v:.4f}" for v in first]),
            text_column(QT_TR_NOOP("Encoder reading (°)"), [f"{v:.4f}" for v in reading]),
            figure_column(QT_TR_NOOP("Error (\")"), values, big_u),
            uncertainty_column("U (\")", big_u, values),
            figure_column(QT_TR_NOOP("From step 0 (\")"), values - values[0], u0),
            uncertainty_column(QT_TR_NOOP("U from step 0 (\")"), u0, values - values[0])),
            QT_TR_NOOP("Error = indicated − true angle at each of the n steps, stated "
                       "about its mean over the n steps (the steps of a full turn close "
                       "at 360°), with its U; harmonics of order n and above are not "
                       "resolved (aliased). The last two columns state it from step 0 "
                       "(zero there), with their own U from the full covariance."))
        point_columns = (("step", np.arange(n, dtype=float)), ("step_deg", first),
                         ("encoder_reading_deg", reading),
                         ("error_arcsec", values), ("expanded_uncertainty_arcsec", big_u),
                         ("error_from_step0_arcsec", values - values[0]),
                         ("expanded_uncertainty_from_step0_arcsec", u0))
        point = QT_TR_NOOP("step {k}")
        names = [message(point, k=k) for k in range(n)]
        what = QT_TR_NOOP("encoder error")
        figures = encoder_figures(result)
        span, ptp, _ = range_cells(np.min(values), np.max(values), budget.max_expanded, fallback=3)
        first_rows = [(QT_TR_NOOP("Error"), span, message(QT_TR_NOOP("peak-to-peak {ptp}"), ptp=ptp))]
        more_rows = [(QT_TR_NOOP("JJF 1115 division error"),
                      f"{figures['division_error_jjf1115']:.3f}\"", "")]
        if math.isfinite(figures["repeatability_jjf1115"]):
            more_rows.append((QT_TR_NOOP("JJF 1115 repeatability (largest s over the steps)"),
                              f"{figures['repeatability_jjf1115']:.3f}\"",
                              QT_TR_NOOP("indicative (mountings are remountings, not repeat "
                                         "runs)")))
        iso = [f"{k[7:]} = {v:.3f}\"" for k, v in figures.items()
               if k.startswith("iso230_") and math.isfinite(v)]
        if iso:
            more_rows.append((QT_TR_NOOP("ISO 230-2 (unidirectional)"), ", ".join(iso),
                              QT_TR_NOOP("indicative (mountings are remountings, not repeat "
                                         "runs); deviation = −error")))
        plots = [encoder_figure(result, u=big_u)]  # the table's U
    else:
        u1 = result.polygon_u_from_face1_arcsec(metadata)
        results = PointTable(QT_TR_NOOP("Face deviations"), (
            text_column(QT_TR_NOOP("Face"), [f"{i + 1}" for i in range(n)]),
            text_column(QT_TR_NOOP("Nominal (°)"), [f"{i * 360.0 / n:.4f}" for i in range(n)]),
            figure_column(QT_TR_NOOP("Deviation (\")"), values, big_u),
            uncertainty_column("U (\")", big_u, values),
            figure_column(QT_TR_NOOP("From face 1 (\")"), values - values[0], u1),
            uncertainty_column(QT_TR_NOOP("U from face 1 (\")"), u1, values - values[0])),
            QT_TR_NOOP("Deviation d_i = the face's angle minus its nominal, stated "
                       "about the mean over the n faces (Σ d_i = 0: the faces close at "
                       "360°), with its U. The last two columns state it from face 1, "
                       "d_i − d_1 (zero there), with their own U from the full "
                       "covariance."))
        point_columns = (("face", np.arange(1, n + 1, dtype=float)),
                         ("nominal_deg", np.arange(n) * 360.0 / n), ("deviation_arcsec", values),
                         ("expanded_uncertainty_arcsec", big_u),
                         ("deviation_from_face1_arcsec", values - values[0]),
                         ("expanded_uncertainty_from_face1_arcsec", u1))
        point = QT_TR_NOOP("face {k}")
        names = [message(point, k=k + 1) for k in range(n)]
        what = QT_TR_NOOP("face deviation")
        span, ptp, _ = range_cells(np.min(values), np.max(values), budget.max_expanded, fallback=3)
        first_rows = [(QT_TR_NOOP("Deviation"), span,
                       message(QT_TR_NOOP("peak-to-peak {ptp}"), ptp=ptp))]
        more_rows = []
        plots = [polygon_figure(result, u=big_u)]  # the table's U
    sign = {} if item == "encoder" else {"sign_convention": POLYGON_SIGN_CONVENTION_TEXT}
    statements = (
        # the autocollimator gives no reference value, but its calibration is an input of
        # U (its budget row, or named as not stated): "a comparator only" read as though it
        # were none (assessment 73 M2)
        message(QT_TR_NOOP("No calibrated reference value enters these results: the polygon and "
                           "the encoder are calibrated against each other by the closure of the "
                           "circle. The autocollimator serves as the comparator: its calibration "
                           "(the uncertainty its certificate states) is an input of the "
                           "uncertainty, as is its scale error over its readings' span {low} … "
                           "{high}."),
                low=f"{np.min(result.readings.ac_x_arcsec):+.1f}\"",
                high=f"{np.max(result.readings.ac_x_arcsec):+.1f}\""),
        _correlation_statement(result, item, metadata),
        # the encoder's error is solved with the face deviations, but with its U withheld it
        # is not calibrated (assessment 70 M8)
        message(QT_TR_NOOP("The encoder's error was solved in the same run, but the encoder is "
                           "not calibrated: its U is withheld (mounting(s) {mountings} have no "
                           "closure reading and no drift bound is stated); the largest "
                           "correlation between its results and these is {r}."),
                mountings=", ".join(map(str, result.unchecked_drift_mountings)),
                r=f"{result.cross_correlation():.2f}")
        if item == "polygon" and result.encoder_u_withheld is not None else
        message(QT_TR_NOOP("The {other} was calibrated in the same run; the largest correlation "
                           "between its results and these is {r}."),
                other=message(QT_TR_NOOP("polygon") if item == "encoder"
                              else QT_TR_NOOP("encoder")),
                r=f"{result.cross_correlation():.2f}"))
    return build_certificate(
        kind_key=KEY, kind_title=TITLE, metadata=metadata,
        method=METHOD if all(math.isfinite(c) for c in closures) else METHOD_SOME_WITHOUT_CLOSURE,
        source_name=source_name, method_reference=method_reference, budget=budget,
        parameters=parameters, results=results,
        statistics=Statistics(first_rows, QT_TR_NOOP("steps") if item == "encoder"
                              else QT_TR_NOOP("faces"), more_rows),
        decision=Decision(values, what, names, not_stated=tuple(comparator_not_stated(metadata))),
        budget_point=lambda worst: _budget_point(point, worst if item == "encoder" else worst + 1,
                                                 big_u, item),
        tolerance=metadata.tolerance_in("arcsec"),
        plots=[*plots, residual_figure(result), closure_figure(result)],
        warnings=result.warnings, point_columns=point_columns,
        statements=statements + _from_first_cmc_statement(result, item, metadata)
        + budget_remarks(result), **sign)
