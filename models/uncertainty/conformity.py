"""Statements of conformity with ±T under a stated decision rule (ILAC-G8:09/2019).

The decided quantity is explicit and chosen (metadata ``decision_quantity``):

* ``half_range`` — half the peak-to-peak of the error curve, the ± band the
  curve fits in after the best zero, as measured. The range of noisy points
  runs high, and its uncertainty is not one point's U: its coverage interval
  comes from bounds on the maximum and minimum of a curve measured with noise
  (Romano, Shaikh & Wolf 2014), the noise simulated from the budget with
  every input once and with its nature (JCGM 101: independent from point to
  point, or one value for the whole run), seeded from the readings so that
  the certificate is reproducible (see :func:`half_range_monte_carlo`). Its
  coverage is validated by simulation (models.validation.half_range).
* ``points`` — every point's error against ±T with that point's own U (the
  ISO 14253-1 way): the worst point decides.

Decision rules, as ILAC-G8:09/2019 defines them (section 4.2):

* ``simple`` — 4.2.1, binary statement for simple acceptance (w = 0):
  pass when the result is within the tolerance, fail otherwise.
* ``guarded_binary`` — 4.2.2, binary statement with a guard band w = U:
  pass when the result is within the tolerance reduced by w, fail otherwise.
* ``guarded`` — 4.2.3, non-binary statement with a guard band w = U: pass
  (within T − w), conditional pass (within T), conditional fail (within T + w),
  fail (beyond T + w).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from models.messages import QT_TR_NOOP, joined, message
from models.quantity import Quantity
from models.uncertainty.budget import UncertaintyBudget

__all__ = [
    "DECISION_QUANTITIES",
    "DECISION_RULES",
    "Conformity",
    "HalfRangeEstimate",
    "asymmetric_text",
    "decide_conformity",
    "half_range_monte_carlo",
    "significant_decimals",
    "uncertainty_decimals",
]

DECISION_RULES = {
    "guarded": QT_TR_NOOP("non-binary statement with a guard band w = U (ILAC-G8:09/2019, "
                          "4.2.3): pass when the result lies within T − w; conditional pass "
                          "within T; conditional fail within T + w; fail beyond T + w"),
    "guarded_binary": QT_TR_NOOP("binary statement with a guard band w = U (ILAC-G8:09/2019, "
                                 "4.2.2): pass when the result lies within T − w, fail "
                                 "otherwise"),
    "simple": QT_TR_NOOP("binary statement for simple acceptance, w = 0 (ILAC-G8:09/2019, "
                         "4.2.1): pass when the result lies within T, fail otherwise; the risk "
                         "of a false acceptance reaches 50 % at the limit"),
}

DECISION_QUANTITIES = {
    "half_range": QT_TR_NOOP("half the peak-to-peak error after the best zero, as measured, "
                             "with a coverage interval from bounds on the curve's maximum and "
                             "minimum (Romano, Shaikh & Wolf 2014), the noise simulated from "
                             "the budget (JCGM 101)"),
    "points": QT_TR_NOOP("every point's error against ±T with that point's own U "
                         "(ISO 14253-1)"),
}

MONTE_CARLO_SEED = 20261127
MONTE_CARLO_TRIALS = 5_000
_MONTE_CARLO_DRAWS = 1_500_000  # trials × points at the most (12 MB of draws)
#: A longer curve is judged on every k-th point (its range over 16 384 points of a long,
#: repetitive record — a fringe revolution — is all but the same), and says so.
MAX_MONTE_CARLO_POINTS = 16_384


#: The coverage the half-range interval achieved in its validation, by curve shape: the
#: lowest cell of each shape over noise 0.1, 0.5, 1 and 2 times the true half range and 12,
#: 36 and 72 points, 50 runs a cell (models.validation.half_range.coverage_study, seed
#: 20261202; pooled over a shape's 600 runs: smooth 99.8 %, rough 99.3 %, spike 99.5 %,
#: the samples' real curves 99.7 %). tests/benchmarks/test_half_range_coverage.py reruns it
#: with 100 runs a cell; `anglebench validate` with fewer.
HALF_RANGE_COVERAGE = {"smooth": 0.98, "rough": 0.96, "spike": 0.96, "sample": 0.96}


def significant_decimals(expanded: float) -> int | None:
    """Decimals that show U with two significant digits (GUM 7.2.6); None if U is not
    a positive number."""
    if not math.isfinite(expanded) or expanded <= 0:
        return None
    return max(0, 1 - int(math.floor(math.log10(expanded))))


def uncertainty_decimals(expanded: float) -> int:
    """:func:`significant_decimals`, but never fewer than two (arcsec are printed to 0.01")."""
    decimals = significant_decimals(expanded)
    return 2 if decimals is None else max(2, decimals)


@dataclass(frozen=True)
class HalfRangeEstimate:
    """Half the peak-to-peak of an error curve with its coverage interval
    [value − u_lower, value + u_upper] at ``probability`` (in the unit of the curve and its
    budget); see :func:`half_range_monte_carlo`."""

    measured: float  # half the peak-to-peak of the measured curve
    bias: float  # measured − value: 0, the value is the measured half range (what noise may
    # have added to it is the interval's lower side, u_lower)
    value: float  # the estimate stated
    u_upper: float  # upper half-width of the coverage interval about ``value``
    u_lower: float
    probability: float
    trials: int
    seed: int
    stride: int = 1  # judged on every stride-th point of a long curve

    @property
    def interval_low(self) -> float:
        """The coverage interval's lower end, value − u_lower (never below 0)."""
        return self.value - self.u_lower

    @property
    def interval_high(self) -> float:
        """The coverage interval's upper end, value + u_upper."""
        return self.value + self.u_upper


def _standard_draws(rng: np.random.Generator, distribution: str, shape) -> np.ndarray:
    if distribution == "rectangular":
        return rng.uniform(-math.sqrt(3.0), math.sqrt(3.0), shape)
    return rng.standard_normal(shape)


#: The share of the miss probability α spent on bounding the curve's gaps to its extremes
#: (the first step of Romano, Shaikh & Wolf's two-step test, β = α/10).
_GAP_SHARE = 0.1


def readings_seed(errors, budget: UncertaintyBudget) -> int:
    """A seed made from the readings (the curve and its budget's figures): the same
    readings give the same draws, on every run and machine."""
    import zlib

    curve = np.round(np.asarray(errors, dtype=float), 9)
    contributions = np.round(budget.contributions(), 9)
    crc = zlib.crc32(np.ascontiguousarray(curve).tobytes())
    crc = zlib.crc32(np.ascontiguousarray(contributions).tobytes(), crc)
    return int((MONTE_CARLO_SEED ^ crc) & 0x7FFFFFFF)


def _signed_draws(budget: UncertaintyBudget, points: np.ndarray, trials: int,
                  rng: np.random.Generator) -> np.ndarray:
    """(trials, len(points)) draws of the curve's error (JCGM 101): every budget input
    once; a ``common`` input (one unknown value for the whole run) one draw per trial
    carried to every point through its signed sensitivity, the others one draw per point;
    a Type A input with ν degrees of freedom as a t-distribution (JCGM 101 6.4.9), its
    scale s·√(ν/χ²_ν) one draw per trial for all the inputs of one estimate (``dof_group``)."""
    n = points.size
    draws = np.zeros((trials, n))
    scales: dict[object, np.ndarray] = {}
    for i, comp in enumerate(budget.components):
        sens = np.broadcast_to(np.asarray(comp.sensitivity, dtype=float), (budget.points,))
        c_u = (sens * comp.standard_uncertainty(budget.points))[points]
        if not np.any(c_u):
            continue
        shape = (trials, 1) if comp.common else (trials, n)
        term = _standard_draws(rng, comp.distribution, shape) * c_u
        if comp.evaluation == "A" and math.isfinite(comp.dof) and comp.dof > 0:
            key = comp.dof_group or i
            if key not in scales:
                scales[key] = np.sqrt(comp.dof / rng.chisquare(comp.dof, (trials, 1)))
            term = term * scales[key]
        draws += term
    return draws


def _gap_bounds(curve: np.ndarray, draws: np.ndarray, level: float) -> np.ndarray:
    """Lower confidence bounds, simultaneous at ``level``, of every point's gap to the
    curve's true maximum: f_max − f_i ≥ f_a − f_i ≥ y_a − y_i − c·sd(ε_a − ε_i), a the
    highest measured point (0 where the point may hold the maximum)."""
    a = int(np.argmax(curve))
    diff = draws - draws[:, [a]]
    sd = np.std(diff, axis=0)
    sd[a] = 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        scaled = np.where(sd > 0, np.abs(diff) / np.where(sd > 0, sd, 1.0), 0.0)
    c = float(np.quantile(np.max(scaled, axis=1), level))
    return np.maximum(0.0, curve[a] - curve - c * sd)


def half_range_monte_carlo(errors, budget: UncertaintyBudget,
                           trials: int = MONTE_CARLO_TRIALS,
                           seed: int | None = None) -> HalfRangeEstimate:
    """Half the peak-to-peak of ``errors`` (in the budget's unit; points in their natural
    order) with a coverage interval: bounds on a maximum of means by the two-step method
    of Romano, Shaikh & Wolf (*Econometrica* 82 (2014) 1979–2002), the noise's
    distribution simulated from the budget (JCGM 101, see :func:`_signed_draws`).

    With y = f + ε (f the true curve), the measured range r̂ = max y − min y, the true
    range r = max f − min f, α = 1 − p and β = α/10:

    * upper end: r̂ ≥ y_{i*} − y_{j*} = r + ε_{i*} − ε_{j*} for the true extremes i*, j*,
      so r ≤ r̂ + q, q the (1 − α/2 + β) quantile of ε_j − ε_i for the least favourable
      pair of the points that may hold the extremes;
    * lower end: r̂ − r = (ε_a − G_a) − (ε_b + H_b) for the measured extremes a, b, with
      G_i = f_max − f_i and H_j = f_j − f_min the true gaps, so r ≥ r̂ − Q, Q the
      (1 − α/2 + β) quantile of max_i(ε_i − G_i) − min_j(ε_j + H_j) with the gaps
      replaced by their lower confidence bounds at 1 − β (the least favourable curve the
      data allow: where noise hides the curve every point may be tied at its extremes).

    Each end misses with a probability of at most α/2, the two together at most α, on any
    curve (given the budget): the interval covers the true half range with at least the
    stated probability p (checked by simulation over the shapes that occur,
    models.validation.half_range). The value stated is the measured half range r̂/2: it is
    at least the true one with a probability of at least 50 % (P(ε_{i*} ≥ ε_{j*}) = ½), so
    simple acceptance keeps the risk of false acceptance at or below 50 % at the limit;
    what the noise may have added to it is the interval's lower side. ``seed`` None: made
    from the readings (:func:`readings_seed`); a curve of more than 16 384 points is
    judged on every k-th point.
    """
    full = np.asarray(errors, dtype=float)
    stride = max(1, -(-full.size // MAX_MONTE_CARLO_POINTS))
    points = np.arange(0, full.size, stride)
    e = full[points]
    n = e.size
    if seed is None:
        seed = readings_seed(full, budget)
    trials = int(max(2000, min(trials, _MONTE_CARLO_DRAWS // max(n, 1))))
    measured = 0.5 * float(np.ptp(e)) if n else 0.0
    if n < 2:
        return HalfRangeEstimate(measured, 0.0, measured, 0.0, 0.0, budget.probability, trials,
                                 seed, stride)
    draws = _signed_draws(budget, points, trials, np.random.default_rng(seed))
    if not np.any(draws):
        return HalfRangeEstimate(measured, 0.0, measured, 0.0, 0.0, budget.probability, trials,
                                 seed, stride)
    alpha = 1.0 - budget.probability
    beta = _GAP_SHARE * alpha
    level = 1.0 - 0.5 * alpha + beta
    gaps_top = _gap_bounds(e, draws, 1.0 - beta / 2.0)
    gaps_bottom = _gap_bounds(-e, -draws, 1.0 - beta / 2.0)
    spread = np.max(draws - gaps_top, axis=1) - np.min(draws + gaps_bottom, axis=1)
    q_low = float(np.quantile(spread, level))
    q_high = _pair_quantile(draws, np.flatnonzero(gaps_top == 0.0),
                            np.flatnonzero(gaps_bottom == 0.0), level)
    low = max(0.0, measured - 0.5 * q_low)
    high = measured + 0.5 * q_high
    return HalfRangeEstimate(measured, 0.0, measured, high - measured, measured - low,
                             budget.probability, trials, seed, stride)


_MAX_PAIRS = 4_000_000


def _pair_quantile(draws: np.ndarray, top: np.ndarray, bottom: np.ndarray,
                   level: float) -> float:
    """The ``level`` quantile of ε_j − ε_i for the pair (i in ``top``, j in ``bottom``)
    whose difference varies most: normal (a sum of several inputs; conservative for a
    single rectangular one)."""
    from scipy.special import ndtri

    rng = np.random.default_rng(0)
    if top.size * bottom.size > _MAX_PAIRS:  # a long flat curve: a sample of its points
        limit = int(math.sqrt(_MAX_PAIRS))
        top = np.sort(rng.choice(top, min(top.size, limit), replace=False))
        bottom = np.sort(rng.choice(bottom, min(bottom.size, limit), replace=False))
    centred = draws - draws.mean(axis=0)
    a, b = centred[:, top], centred[:, bottom]
    var_a = np.mean(a**2, axis=0)
    var_b = np.mean(b**2, axis=0)
    cov = a.T @ b / draws.shape[0]
    variance = var_a[:, None] + var_b[None, :] - 2.0 * cov
    return float(ndtri(level)) * math.sqrt(max(float(np.max(variance)), 0.0))


@dataclass(frozen=True)
class Conformity:
    verdict: str  # "pass", "conditional pass", "conditional fail", "fail", "not assessed"
    statement: str
    rule: str
    quantity: str = ""  # the decided quantity and how it was evaluated
    value: float = float("nan")  # the decided value, in ``unit``
    expanded: float = float("nan")  # its U, in ``unit``
    zones: str = ""
    monte_carlo: HalfRangeEstimate | None = None
    expanded_lower: float = float("nan")  # an asymmetric interval's lower half-width (else U)
    unit: str = "arcsec"  # the unit of value, expanded and expanded_lower (models.quantity)

    @property
    def conforms(self) -> bool | None:
        if self.verdict == "not assessed":
            return None
        return self.verdict in ("pass", "conditional pass")


def _zones(t: float, w: float, rule: str, d: int, q: str = "\"") -> str:
    if rule == "simple":
        return message(QT_TR_NOOP("pass ≤ {t} < fail"), t=f"{t:g}{q}")
    if rule == "guarded_binary":
        return message(QT_TR_NOOP("pass ≤ {low} (T − w) < fail"), low=f"{t - w:.{d}f}{q}")
    return message(QT_TR_NOOP("pass ≤ {low} (T − w) < conditional pass ≤ {t} (T) < conditional "
                              "fail ≤ {high} (T + w) < fail"),
                   low=f"{t - w:.{d}f}{q}", t=f"{t:g}{q}", high=f"{t + w:.{d}f}{q}")


def _verdict(x: float, t: float, w: float, rule: str) -> str:
    if rule == "simple":
        return "pass" if x <= t else "fail"
    if rule == "guarded_binary":
        return "pass" if x <= t - w else "fail"
    if x <= t - w:
        return "pass"
    if x <= t:
        return "conditional pass"
    if x <= t + w:
        return "conditional fail"
    return "fail"


_ORDER = ("pass", "conditional pass", "conditional fail", "fail")

_SENTENCE = {
    "pass": QT_TR_NOOP("The item conforms to the specification ±{t} (pass)."),
    "conditional pass": QT_TR_NOOP("Conditional pass: the result lies within ±{t} but closer "
                                   "to the limit than the guard band, so conformity is not "
                                   "proven at the stated coverage probability."),
    "conditional fail": QT_TR_NOOP("Conditional fail: the result lies beyond ±{t} by less "
                                   "than the guard band, so non-conformity is not proven at "
                                   "the stated coverage probability."),
    "fail": QT_TR_NOOP("The item does not conform to the specification ±{t} (fail)."),
}


def _too_uncertain(w: float, t: float, q: str, d: int) -> str:
    """The statement when U ≥ T: no result could be shown to conform (ILAC-G8)."""
    return message(QT_TR_NOOP("No statement of conformity is possible: the expanded uncertainty "
                              "U = {u} is not smaller than the tolerance T = {t}, so no result "
                              "could be shown to lie within it."), u=f"{w:.{d}f}{q}",
                   t=f"{t:g}{q}")


def decide_conformity(errors, budget: UncertaintyBudget, tolerance: Quantity | float | None,
                      rule: str = "guarded", quantity: str = "half_range",
                      invalid_reason: str = "", what: str = QT_TR_NOOP("corrected error"),
                      point_names=None) -> Conformity:
    """The verdict on an error curve against ±``tolerance``.

    ``errors`` are in the budget's unit (arcsec, or nm for an interferometer); a
    ``tolerance`` Quantity is converted to it (an angle against a length is refused with
    :class:`~models.quantity.UnitError`), a bare number is taken in it. Figures are
    written with that unit. ``invalid_reason`` (for example a failed closure) withholds
    the statement, and so does U ≥ T. ``point_names`` name the points as the results
    table does (the deciding point is named so).
    """
    q = budget.unit.written()
    if isinstance(tolerance, Quantity):
        tolerance = float(tolerance.in_unit(budget.unit))
    what = message(what) if not hasattr(what, "template") else what
    rule_text = message(DECISION_RULES[rule])
    sentence = {v: message(template, t=f"{float(tolerance or 0):g}{q}")
                for v, template in _SENTENCE.items()}
    if quantity not in DECISION_QUANTITIES:
        raise ValueError(f"decision quantity must be one of {', '.join(DECISION_QUANTITIES)}")
    if invalid_reason:
        return Conformity("not assessed", message(
            QT_TR_NOOP("No statement of conformity: {reason}."), reason=invalid_reason),
            rule_text, unit=budget.unit.key)
    if tolerance is None:
        return Conformity("not assessed", message(QT_TR_NOOP(
            "No statement of conformity: no specification (tolerance) was given.")), rule_text,
            unit=budget.unit.key)
    e = np.asarray(errors, dtype=float)
    t = float(tolerance)
    if quantity == "points":
        u = budget.expanded
        verdicts = [_verdict(abs(x), t, w if rule != "simple" else 0.0, rule) for x, w in zip(e, u,
                                                                                              strict=True)]
        worst = max(range(e.size), key=lambda i: (_ORDER.index(verdicts[i]), abs(e[i]) + u[i]))
        x, w = abs(float(e[worst])), float(u[worst])
        d = uncertainty_decimals(w)
        verdict = verdicts[worst]
        point = (point_names[worst] if point_names is not None else
                 message(QT_TR_NOOP("point {n}"), n=worst + 1))
        quantity_text = message(DECISION_QUANTITIES["points"])
        largest = int(np.argmax(u))
        if float(u[largest]) >= t:
            w_max = float(u[largest])
            d = uncertainty_decimals(w_max)
            name = (point_names[largest] if point_names is not None else
                    message(QT_TR_NOOP("point {n}"), n=largest + 1))
            return Conformity("not assessed", joined([_too_uncertain(w_max, t, q, d), " ",
                                                      message(QT_TR_NOOP("(at {point})"),
                                                              point=name)]),
                              rule_text, quantity_text, x, w, unit=budget.unit.key)
        text = message(QT_TR_NOOP("Every point's {what} was judged against ±{t} with its own U; "
                                  "the deciding point is {point}: |e| = {e}, U = {u}. "
                                  "{sentence}"),
                       what=what, t=f"{t:g}{q}", point=point, e=f"{x:.{d}f}{q}",
                       u=f"{w:.{d}f}{q}", sentence=sentence[verdict])
        zones = message(QT_TR_NOOP("per point, with w = U of that point: {zones}"),
                        zones=_zones(t, w, rule, d, q))
        return Conformity(verdict, text, rule_text, quantity_text, x, w, zones,
                          unit=budget.unit.key)
    mc = half_range_monte_carlo(e, budget)
    x, w = mc.value, mc.u_upper
    d = uncertainty_decimals(min(mc.u_upper, mc.u_lower))
    verdict = _verdict(x, t, 0.0 if rule == "simple" else w, rule)
    interval = asymmetric_text(mc.u_lower, mc.u_upper, q, d)
    if max(mc.u_upper, mc.u_lower) >= t:
        verdict = "not assessed"
        sentence[verdict] = _too_uncertain(max(mc.u_upper, mc.u_lower), t, q, d)
    text = message(QT_TR_NOOP("Half the peak-to-peak {what}: {value} as measured, coverage "
                              "interval {low} … {high} (U = {u}, coverage probability {p} %; "
                              "noise can only widen a measured range, so the interval reaches "
                              "further below the value than above it). {sentence}"),
                   what=what, value=f"{x:.{d}f}{q}", low=f"{mc.interval_low:.{d}f}{q}",
                   high=f"{mc.interval_high:.{d}f}{q}", u=interval,
                   p=f"{100 * mc.probability:.2f}", sentence=sentence[verdict])
    quantity_text = (message(QT_TR_NOOP("{quantity}: {trials} trials, seed {seed}, on every "
                                        "{stride}-th of the {points} points"),
                             quantity=message(DECISION_QUANTITIES["half_range"]),
                             trials=mc.trials, seed=mc.seed, stride=mc.stride, points=e.size)
                     if mc.stride > 1 else
                     message(QT_TR_NOOP("{quantity}: {trials} trials, seed {seed}"),
                             quantity=message(DECISION_QUANTITIES["half_range"]),
                             trials=mc.trials, seed=mc.seed))
    achieved = HALF_RANGE_COVERAGE
    quantity_text = joined([quantity_text, "; ", message(QT_TR_NOOP(
        "the interval's coverage achieved in validation (noise 0.1 to 2 times the half range, "
        "12 to 72 points, the lowest of each shape): {smooth} % on a smooth curve, {rough} % on "
        "a rough one, {spike} % on a single spike, {sample} % on real curves, against the {p} % "
        "stated"),
        smooth=f"{100 * achieved['smooth']:.1f}", rough=f"{100 * achieved['rough']:.1f}",
        spike=f"{100 * achieved['spike']:.1f}", sample=f"{100 * achieved['sample']:.1f}",
        p=f"{100 * mc.probability:.2f}")])
    return Conformity(verdict, text, rule_text, quantity_text, x, w,
                      "" if verdict == "not assessed" else _zones(t, w, rule, d, q), mc,
                      mc.u_lower, budget.unit.key)


def asymmetric_text(lower: float, upper: float, q: str, d: int) -> str:
    """An interval's half-widths: "±U" when they agree to the digits shown, else "−a/+b"."""
    if f"{lower:.{d}f}" == f"{upper:.{d}f}":
        return f"±{upper:.{d}f}{q}"
    return f"−{lower:.{d}f}{q}/+{upper:.{d}f}{q}"
