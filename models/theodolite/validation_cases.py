"""The theodolite run workbench's reference cases for the method validation report
(``anglebench validate``): moved here from models/validation/cases.py, which keeps the
shared machinery (models.validation.run gathers every workbench's)."""

from __future__ import annotations

import math

import numpy as np

from models.certificate.metadata import CertificateMetadata, ReferenceStandard
from models.messages import QT_TR_NOOP, message
from models.theodolite.analysis import THEODOLITE
from models.theodolite.model import analyze_run, induced_error_arcsec
from models.theodolite.report import theodolite_budget
from models.validation.cases import (
    CHECK_FIGURE,
    EXACT_SIMULATION,
    ValidationCase,
    agreement_case,
    at_most_case,
    close_case,
)
from models.validation.theodolite_rig import theodolite_readings

__all__ = ["validation_cases"]


THEODOLITE_SETUP = (2.0, 40.0, 3.0)  # ψ, α, β in degrees


def theodolite_budget_trials(trials: int, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Corrected error − truth and the budget's u, per trial and point (arcsec). Each
    reading (azimuth and elevation) has one error, σ = 0.5″, and the theodolite is stated
    consistently with it, u = σ per reading (U = 1.0″, k = 2): the budget's one reading
    input, max(s, u), is checked against the spread (issue 39: before, the rig drew the
    standard as a second, azimuth-only error beside the noise, the budget's double count)."""
    theta = np.arange(-60.0, 60.1, 5.0)
    truth = 3.0 * np.sin(np.radians(3.0 * theta))  # error of indication, 0 at θ = 0
    noise = 0.5
    meta = CertificateMetadata(standards=(ReferenceStandard("theodolite", uncertainty=2 * noise,
                                                            basis="U95"),))
    clean_az, clean_el = theodolite_readings(theta - truth / 3600.0, *THEODOLITE_SETUP)
    deviations, budgets = [], []
    for _ in range(trials):
        az = clean_az + rng.normal(0.0, noise, theta.size) / 3600.0
        el = clean_el + rng.normal(0.0, noise, theta.size) / 3600.0
        result = analyze_run(theta, az, el)
        deviations.append(result.corrected_error_arcsec - truth)
        budgets.append(theodolite_budget(result, meta).combined)
    return np.array(deviations), np.array(budgets)


def theodolite_cases(trials: int) -> list[ValidationCase]:
    w = THEODOLITE.title
    theta = np.arange(-20.0, 21.0, 1.0)
    zeta = induced_error_arcsec(theta, 3.0, 45.0, 2.0)
    alphas = np.arange(0.0, 360.0, 1.0)
    spread = max(float(np.ptp([induced_error_arcsec(np.array([t]), 3.0, a, 2.0)[0]
                               for a in alphas])) for t in theta)
    experiment = induced_error_arcsec(theta, 5.8249, 43.4965, -0.0395)
    cases = [
        close_case(w, QT_TR_NOOP("ζ spans ±187.9\" (ψ = 3°, α = 45°, β = 2°, θ = −20…20°)"), CHECK_FIGURE,
               187.9, float(np.max(zeta)), 0.05, digits=2),
        close_case(w, QT_TR_NOOP("largest spread of ζ over α at one θ"), CHECK_FIGURE, 270.1, spread, 0.05,
               digits=2),
        close_case(w, QT_TR_NOOP("the published experiment (Tian et al. 2017): ζ from −301\""),
                   CHECK_FIGURE, -301.1,
               float(np.min(experiment)), 0.5, digits=1),
        close_case(w, QT_TR_NOOP("the published experiment (Tian et al. 2017): ζ to +423\""),
                   CHECK_FIGURE, 422.6,
               float(np.max(experiment)), 0.5, digits=1),
    ]
    truth = 0.05 * theta + 0.8 * np.sin(np.radians(theta) * 9)  # error of indication
    az, el = theodolite_readings(theta - truth / 3600.0, 5.8249, 43.4965, -0.0395)
    result = analyze_run(theta, az, el)
    s = result.identification.setup
    cases += [
        at_most_case(w, QT_TR_NOOP("3-D simulation, no noise: |corrected − true error|"), EXACT_SIMULATION,
                 1e-4, float(np.max(np.abs(result.corrected_error_arcsec - truth)))),
        at_most_case(w, QT_TR_NOOP("3-D simulation, no noise: |ψ, α, β − set-up| (°)"),
                     EXACT_SIMULATION, 1e-6,
                 float(max(abs(s.psi_deg - 5.8249), abs(s.alpha_deg - 43.4965),
                           abs(s.beta_deg + 0.0395))), unit="°"),
    ]
    scale = theodolite_readings(theta / (1 + 1e-5), 3.0, 45.0, 2.0)
    scaled = analyze_run(theta, *scale)
    cases.append(close_case(w, QT_TR_NOOP("sign: an axis indicating 1e-5 too much reads + at +20°"),
                        EXACT_SIMULATION, 0.72, float(scaled.corrected_error_arcsec[-1]), 0.005))
    cases.append(agreement_case(w, theodolite_budget_trials, trials, 11))
    return cases


#: the figures the passes' study states a case of, and their truth on the true distribution
FIGURE_TRUTHS = {
    "E": QT_TR_NOOP("range of d ± b/2"), "M": QT_TR_NOOP("range of d"),
    "B": QT_TR_NOOP("|b|"), "B_mean": QT_TR_NOOP("b"), "R": QT_TR_NOOP("4σ + |b|"),
    "A": QT_TR_NOOP("range of d ± b/2, + 4σ"),
    "decided": QT_TR_NOOP("half the range of d ± b/2"),
}


def _passes_tests(tests: int, runs: int, sigma: float, circle: float,
                  rng: np.random.Generator):
    """(truth, intervals) of ``tests`` runs of ``runs`` × (forward, backward) passes over 21
    θ: the axis' error d (a smooth curve of 2″ peak-to-peak, new in every test) with a
    reversal b = 0.6″ (d ± b/2 forward and backward), the pointing noise σ new in every
    reading, and the circle's error at each θ (standard deviation ``circle``, the same in
    every pass); the theodolite stated at u = √(σ² + circle²) per reading."""
    from models.theodolite.figures import theodolite_figure_intervals
    from models.theodolite.pass_means import means_half_range, pass_means_budget
    from models.uncertainty.figure_intervals import FigureInterval

    theta = np.arange(-20.0, 20.1, 2.0)
    b = 0.6
    stated = float(np.hypot(sigma, circle))
    meta = CertificateMetadata(standards=(ReferenceStandard("theodolite", uncertainty=stated,
                                                            basis="u"),))
    order = np.concatenate([theta, theta[::-1]] * runs)
    sign = np.concatenate([np.ones(theta.size), -np.ones(theta.size)] * runs)
    at = np.searchsorted(theta, order)
    for _ in range(tests):
        t = np.radians(theta)
        d = np.sin(4.0 * t + rng.uniform(0, 2 * np.pi)) + 0.4 * np.cos(
            9.0 * t + rng.uniform(0, 2 * np.pi))
        d *= 2.0 / float(np.ptp(d))
        c = rng.normal(0.0, circle, theta.size)
        error = d[at] + 0.5 * b * sign
        az, el = theodolite_readings(order - error / 3600.0, *THEODOLITE_SETUP)
        az = az + (c[at] + rng.normal(0.0, sigma, order.size)) / 3600.0
        el = el + rng.normal(0.0, sigma, order.size) / 3600.0
        result = analyze_run(order, az, el, reference_index=int(np.argmin(np.abs(order))),
                             directions=sign)
        both = float(np.ptp(np.concatenate([d + 0.5 * b, d - 0.5 * b])))
        truth = {"E": both, "M": float(np.ptp(d)), "B": b, "B_mean": b,
                 "R": 4.0 * sigma + b, "A": both + 4.0 * sigma}
        run_budget = theodolite_budget(result, meta)
        intervals = dict(theodolite_figure_intervals(result, run_budget, stated))
        # the decided quantity: half the peak-to-peak of the means over the passes
        mc = means_half_range(result, pass_means_budget(result, meta, stated), run_budget, stated)
        intervals["decided"] = FigureInterval(mc.value, mc.interval_low, mc.interval_high,
                                              mc.probability)
        truth["decided"] = 0.5 * both
        yield truth, intervals


def figure_coverage_cases(trials: int) -> list[ValidationCase]:
    """One case per ISO 230-2 figure of a run with passes (models.theodolite.figures): its
    interval's coverage of its truth over ``trials``/10 tests (at least 10) of each of three
    worlds: 2 runs with pointing noise 0.3″, 4 runs with 0.6″, 3 runs with the circle's
    error 0.4″ repeating in every pass and pointing noise 0.15″. Passes when no more tests
    missed than the binomial test (one-sided, 1 %) allows at the probability printed."""
    from scipy.stats import binom

    tests = max(10, trials // 10)
    rng = np.random.default_rng(2026)
    hits = {k: 0 for k in FIGURE_TRUTHS}
    count = {k: 0 for k in FIGURE_TRUTHS}
    probability = {k: 1.0 for k in FIGURE_TRUTHS}
    widths: dict[str, list[float]] = {k: [] for k in FIGURE_TRUTHS}
    for runs, sigma, circle in ((2, 0.3, 0.0), (4, 0.6, 0.0), (3, 0.15, 0.4)):
        for truth, intervals in _passes_tests(tests, runs, sigma, circle, rng):
            for key in FIGURE_TRUTHS:
                iv = intervals.get(key)
                if iv is None:
                    continue
                count[key] += 1
                hits[key] += int(iv.low - 1e-12 <= truth[key] <= iv.high + 1e-12)
                probability[key] = min(probability[key], iv.probability)
                widths[key].append(iv.high - iv.low)
    out = []
    for key, what in FIGURE_TRUTHS.items():
        n, p = count[key], probability[key]
        allowed = int(binom.ppf(0.99, n, 1.0 - p)) if n else 0
        out.append(ValidationCase(
            THEODOLITE.title,
            message(QT_TR_NOOP("passes: interval of ISO 230-2 {figure} covers its truth ({truth}; "
                               "d the axis' error, b its reversal, σ the pointing noise)"),
                    figure=key, truth=message(what)) if key != "decided" else
            message(QT_TR_NOOP("passes: interval of the decided quantity (half the peak-to-peak "
                               "of the means over the passes at each θ and direction) covers "
                               "its truth ({truth})"), truth=message(what)),
            QT_TR_NOOP("coverage study"),
            message(QT_TR_NOOP("≥ {p} % (at most {allowed} of {tests} missed)"),
                    p=f"{100 * p:.2f}", allowed=allowed, tests=n),
            message(QT_TR_NOOP("{coverage} % ({missed} missed); mean width {width}"),
                    coverage=f"{100 * hits[key] / max(n, 1):.1f}", missed=n - hits[key],
                    width=f"{float(np.mean(widths[key])) if widths[key] else math.nan:.2f}\""),
            n > 0 and n - hits[key] <= allowed))
    return out


def validation_cases(trials: int) -> list[ValidationCase]:
    """Every reference case of this workbench (``trials`` Monte Carlo runs a comparison)."""
    return theodolite_cases(trials) + figure_coverage_cases(trials)
