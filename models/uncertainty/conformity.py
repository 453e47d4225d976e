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
    "REFERENCE_POINT_TEXT",
    "decide_conformity",
    "expanded_text",
    "gum_rounded",
    "half_range_monte_carlo",
    "probability_conforming",
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
    """Decimals that show U with at most two significant digits (GUM 7.2.6, JJF 1059.1),
    after rounding (0.0996 is "0.10", not "0.100"); None if U is not a positive number.
    Never negative: a U of 100 or more is printed to the unit."""
    if not math.isfinite(expanded) or expanded <= 0:
        return None
    decimals = 1 - int(math.floor(math.log10(expanded)))
    if round(expanded, decimals) >= 10.0 ** (2 - decimals) * (1 - 1e-12):
        decimals -= 1  # rounding carried into a third digit
    return max(0, decimals)


def uncertainty_decimals(expanded: float) -> int:
    """:func:`significant_decimals` (two significant digits of U at most); two decimals
    where U is not a positive number (nothing to round to)."""
    decimals = significant_decimals(expanded)
    return 2 if decimals is None else decimals


#: what a U of zero at a reference point is printed as (never "0.00")
REFERENCE_POINT_TEXT = QT_TR_NOOP("reference point, by definition")


def gum_rounded(value: float, expanded: float) -> tuple[str, str]:
    """(value, U) as GUM 7.2.6 asks: U to at most two significant digits, the value to the
    same decimal; U of zero gives the value to two decimals and U as "0"."""
    decimals = uncertainty_decimals(expanded)
    u = "0" if expanded == 0 else f"{expanded:.{decimals}f}"
    return f"{value:.{decimals}f}", u


def expanded_text(expanded: float, unit: str = "\"", reference: bool | None = None) -> str:
    """U as printed: two significant digits at most with its unit; at a reference point
    (``reference``, or U exactly zero when not told) "reference point, by definition"."""
    if reference or (reference is None and expanded == 0):
        return message(REFERENCE_POINT_TEXT)
    if not math.isfinite(expanded):
        return "—"
    return f"{expanded:.{uncertainty_decimals(expanded)}f}{unit}"


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
    expanded: float = float("nan")  # its U (the upper half-width of its interval), in ``unit``
    zones: str = ""
    monte_carlo: HalfRangeEstimate | None = None
    expanded_lower: float = float("nan")  # an asymmetric interval's lower half-width (else U)
    unit: str = "arcsec"  # the unit of value, expanded and expanded_lower (models.quantity)
    # why no statement of conformity is made ("" when one is): U incomplete, U ≥ T, the
    # figure withheld, the run invalid, no tolerance
    reason: str = ""
    rule_key: str = ""  # "simple", "guarded_binary" or "guarded"
    probability: float = float("nan")  # the coverage probability of the interval
    # the probability that the item conforms (true value within ±T), from the decided
    # value's interval (see :func:`probability_conforming`)
    conforming_probability: float = float("nan")
    # the probability of a wrong decision at the decision stated: false acceptance after a
    # pass or conditional pass, false rejection after a fail or conditional fail (JCGM
    # 106:2012 9.5, specific risk); nan when no statement is made
    decision_risk: float = float("nan")

    @property
    def conforms(self) -> bool | None:
        if self.verdict == "not assessed":
            return None
        return self.verdict in ("pass", "conditional pass")

    @property
    def lower_half_width(self) -> float:
        lower = self.expanded_lower
        return lower if math.isfinite(lower) else self.expanded

    @property
    def interval_low(self) -> float:
        """The interval's lower end; a half range is never negative, so its interval ends
        at zero at the lowest (the coverage is not lowered by it)."""
        low = self.value - self.lower_half_width
        return max(low, 0.0) if self.monte_carlo is not None else low

    @property
    def interval_high(self) -> float:
        return self.value + self.expanded

    @property
    def stated(self) -> bool:
        """A statement of conformity was made."""
        return self.verdict != "not assessed"


# how the probabilities of conformity and of a wrong decision are computed (stated on
# the certificate and checked in tests/models/uncertainty/test_conformity_decision.py)
RISK_METHOD = QT_TR_NOOP(
    "probability of conformity from the decided value's own interval (JCGM 106:2012, 9.5: "
    "specific risk): the value's distribution taken as normal on each side of it, each side's "
    "standard deviation that half-width divided by the normal factor of the stated coverage "
    "probability, so that the interval holds it; with every point deciding, at most the sum "
    "over the points of each one's probability of lying outside ±T (Boole's inequality)")


def _z(probability: float) -> float:
    from scipy.special import ndtri

    return float(ndtri(0.5 * (1.0 + probability)))


def probability_conforming(value: float, lower: float, upper: float, tolerance: float,
                           probability: float, two_sided: bool = False) -> float:
    """P(Y ≤ T) (or P(|Y| ≤ T) when ``two_sided``) for a value with the interval
    [value − lower, value + upper] at ``probability``: each side of the value a half of a
    normal distribution whose quantile (1 ± p)/2 falls at that side's end (a split normal
    about the median ``value``; a symmetric interval gives the normal distribution)."""
    from scipy.special import ndtr

    z = _z(probability)
    s_lo, s_hi = max(lower, 0.0) / z, max(upper, 0.0) / z

    def cdf(y: float) -> float:  # P(Y ≤ y)
        if y >= value:
            return 1.0 if s_hi == 0 else 0.5 + (float(ndtr((y - value) / s_hi)) - 0.5)
        return 0.0 if s_lo == 0 else float(ndtr((y - value) / s_lo))

    inside = cdf(tolerance)
    if two_sided:
        inside -= cdf(-tolerance)
    return min(1.0, max(0.0, inside))


def _zones(t: float, w_accept: float, w_reject: float, rule: str, d: int,
           q: str = "\"") -> str:
    if rule == "simple":
        return message(QT_TR_NOOP("pass ≤ {t} < fail"), t=f"{t:g}{q}")
    if rule == "guarded_binary":
        return message(QT_TR_NOOP("pass ≤ {low} (T − w) < fail"), low=f"{t - w_accept:.{d}f}{q}")
    return message(QT_TR_NOOP("pass ≤ {low} (T − w) < conditional pass ≤ {t} (T) < conditional "
                              "fail ≤ {high} (T + w) < fail"),
                   low=f"{t - w_accept:.{d}f}{q}", t=f"{t:g}{q}",
                   high=f"{t + w_reject:.{d}f}{q}")


def _verdict(x: float, t: float, w_accept: float, rule: str,
             w_reject: float | None = None) -> str:
    """The decision on a result ``x`` against T with the guard band of acceptance
    ``w_accept`` (the interval's upper half-width: what the true value may exceed x by) and
    of rejection ``w_reject`` (its lower half-width; ``w_accept`` when not given)."""
    w_reject = w_accept if w_reject is None else w_reject
    if rule == "simple":
        return "pass" if x <= t else "fail"
    if rule == "guarded_binary":
        return "pass" if x <= t - w_accept else "fail"
    if x <= t - w_accept:
        return "pass"
    if x <= t:
        return "conditional pass"
    if x <= t + w_reject:
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


def _incomplete_reason(inputs) -> str:
    return message(QT_TR_NOOP("U is incomplete: inputs not stated, so not in U: {inputs}"),
                   inputs=joined(part for i, name in enumerate(inputs)
                                 for part in ((", " if i else ""), message(name))))


def _risk_sentence(verdict: str, risk: float) -> str:
    figure = "< 0.01" if risk < 1e-4 else f"{100 * risk:.2f}"
    if verdict in ("pass", "conditional pass"):
        return message(QT_TR_NOOP("Probability of a false acceptance at this decision: {p} % "
                                  "(specific risk, JCGM 106)."), p=figure)
    return message(QT_TR_NOOP("Probability of a false rejection at this decision: {p} % "
                              "(specific risk, JCGM 106)."), p=figure)


def _with_risk(conformity: Conformity) -> Conformity:
    """The statement followed by the probability of a wrong decision, when one is made."""
    if not conformity.stated or not math.isfinite(conformity.decision_risk):
        return conformity
    import dataclasses

    return dataclasses.replace(conformity, statement=joined(
        [conformity.statement, " ", _risk_sentence(conformity.verdict,
                                                   conformity.decision_risk)]),
        quantity=joined([conformity.quantity, "; ", message(RISK_METHOD)]))


def _risk(verdict: str, conforming: float) -> float:
    if verdict in ("pass", "conditional pass"):
        return 1.0 - conforming
    if verdict in ("fail", "conditional fail"):
        return conforming
    return float("nan")


def decide_conformity(errors, budget: UncertaintyBudget, tolerance: Quantity | float | None,
                      rule: str = "guarded", quantity: str = "half_range",
                      invalid_reason: str = "", what: str = QT_TR_NOOP("corrected error"),
                      point_names=None, not_stated=(),
                      estimate: HalfRangeEstimate | None = None) -> Conformity:
    """The verdict on an error curve against ±``tolerance`` (ILAC-G8:09/2019).

    ``errors`` are in the budget's unit (arcsec, or nm for an interferometer); a
    ``tolerance`` Quantity is converted to it (an angle against a length is refused with
    :class:`~models.quantity.UnitError`), a bare number is taken in it. Figures are
    written with that unit. No statement is made (verdict "not assessed", the ``reason``
    said) when ``invalid_reason`` is given (a failed closure, an untraceable error), when
    U is incomplete (``not_stated``: the inputs the certificate names as not stated, so
    not in U), when U ≥ T, or when the decided figure is withheld (not a finite number);
    the decided value and its interval are still given whenever they can be computed.
    The guard band is the decided value's own interval: its upper half-width guards
    acceptance, its lower half-width rejection. ``point_names`` name the points as the
    results table does (the deciding point is named so). ``estimate``: the half range and
    its interval as the workbench itself evaluates them (positioning: E/2 with E's own
    interval), in place of :func:`half_range_monte_carlo`; its ``method`` text, when it has
    one, describes the decided quantity instead.
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
    common = {"rule_key": rule, "probability": budget.probability, "unit": budget.unit.key}
    if tolerance is None:
        reason = message(QT_TR_NOOP("no specification (tolerance) was given"))
        return Conformity("not assessed", message(QT_TR_NOOP(
            "No statement of conformity: no specification (tolerance) was given.")), rule_text,
            reason=reason, **common)
    withheld = []
    if invalid_reason:
        withheld.append(invalid_reason)
    if not_stated:
        withheld.append(_incomplete_reason(not_stated))
    e = np.asarray(errors, dtype=float)
    t = float(tolerance)
    if not e.size or not np.all(np.isfinite(e)):
        reason = joined([*(part for i, w in enumerate(withheld) for part in (("; " if i else ""), w)),
                         "; " if withheld else "",
                         message(QT_TR_NOOP("the decided quantity is withheld (the errors are "
                                            "not all determined)"))])
        return Conformity("not assessed", message(
            QT_TR_NOOP("No statement of conformity: {reason}."), reason=reason), rule_text,
            reason=reason, **common)
    if quantity == "points":
        return _with_risk(_decide_points(e, budget, t, rule, rule_text, what, point_names,
                                         withheld, sentence, q, common))
    return _with_risk(_decide_half_range(e, budget, t, rule, rule_text, what, withheld,
                                         sentence, q, common, estimate))


def _withheld_text(withheld: list) -> str:
    return joined(part for i, w in enumerate(withheld) for part in (("; " if i else ""), w))


def _decide_points(e, budget, t, rule, rule_text, what, point_names, withheld, sentence, q,
                   common) -> Conformity:
    u = budget.expanded
    verdicts = [_verdict(abs(x), t, w if rule != "simple" else 0.0, rule)
                for x, w in zip(e, u, strict=True)]
    worst = max(range(e.size), key=lambda i: (_ORDER.index(verdicts[i]), abs(e[i]) + u[i]))
    x, w = abs(float(e[worst])), float(u[worst])
    d = uncertainty_decimals(w)
    verdict = verdicts[worst]
    point = (point_names[worst] if point_names is not None else
             message(QT_TR_NOOP("point {n}"), n=worst + 1))
    quantity_text = message(DECISION_QUANTITIES["points"])
    # P(every point within ±T) ≥ 1 − Σ P(point i outside) (Boole); ≤ P(the worst point within)
    inside = np.array([probability_conforming(float(xi), float(wi), float(wi), t,
                                              budget.probability, two_sided=True)
                       for xi, wi in zip(e, u, strict=True)])
    conforming = (max(0.0, 1.0 - float(np.sum(1.0 - inside)))
                  if verdict in ("pass", "conditional pass") else float(np.min(inside)))
    values = {"value": x, "expanded": w, "expanded_lower": w, "conforming_probability": conforming}
    largest = int(np.argmax(u))
    if float(u[largest]) >= t:
        w_max = float(u[largest])
        d = uncertainty_decimals(w_max)
        name = (point_names[largest] if point_names is not None else
                message(QT_TR_NOOP("point {n}"), n=largest + 1))
        text = joined([_too_uncertain(w_max, t, q, d), " ",
                       message(QT_TR_NOOP("(at {point})"), point=name)])
        reason = _withheld_text([*withheld, message(
            QT_TR_NOOP("U = {u} is not smaller than T = {t}"), u=f"{w_max:.{d}f}{q}",
            t=f"{t:g}{q}")])
        if withheld:
            text = message(QT_TR_NOOP("No statement of conformity: {reason}."), reason=reason)
        return Conformity("not assessed", text, rule_text, quantity_text, reason=reason,
                          **values, **common)
    if withheld:
        reason = _withheld_text(withheld)
        return Conformity("not assessed", message(QT_TR_NOOP(
            "No statement of conformity: {reason}."), reason=reason), rule_text, quantity_text,
            reason=reason, **values, **common)
    text = message(QT_TR_NOOP("Every point's {what} was judged against ±{t} with its own U; "
                              "the deciding point is {point}: |e| = {e}, U = {u}. "
                              "{sentence}"),
                   what=what, t=f"{t:g}{q}", point=point, e=f"{x:.{d}f}{q}",
                   u=f"{w:.{d}f}{q}", sentence=sentence[verdict])
    zones = message(QT_TR_NOOP("per point, with w = U of that point: {zones}"),
                    zones=_zones(t, w, w, rule, d, q))
    return Conformity(verdict, text, rule_text, quantity_text, zones=zones,
                      decision_risk=_risk(verdict, conforming), **values, **common)


def _decide_half_range(e, budget, t, rule, rule_text, what, withheld, sentence, q,
                       common, estimate=None) -> Conformity:
    mc = estimate if estimate is not None else half_range_monte_carlo(e, budget)
    x, upper, lower = float(mc.value), float(mc.u_upper), float(mc.u_lower)
    if not (math.isfinite(x) and math.isfinite(upper) and math.isfinite(lower)):
        reason = _withheld_text([*withheld, message(QT_TR_NOOP(
            "the decided quantity is withheld (the data do not determine it)"))])
        return Conformity("not assessed", message(QT_TR_NOOP(
            "No statement of conformity: {reason}."), reason=reason), rule_text,
            monte_carlo=mc, reason=reason, **common)
    d = uncertainty_decimals(max(upper, lower))  # two significant digits at most on each side
    verdict = _verdict(x, t, 0.0 if rule == "simple" else upper, rule,
                       0.0 if rule == "simple" else lower)
    interval = asymmetric_text(lower, upper, q, d)
    conforming = probability_conforming(x, lower, upper, t, mc.probability)
    reasons = list(withheld)
    if max(upper, lower) >= t:
        reasons.append(message(QT_TR_NOOP("U = {u} is not smaller than T = {t}"),
                               u=f"{max(upper, lower):.{d}f}{q}", t=f"{t:g}{q}"))
    if reasons:
        verdict = "not assessed"
        sentence[verdict] = (_too_uncertain(max(upper, lower), t, q, d)
                             if not withheld else
                             message(QT_TR_NOOP("No statement of conformity: {reason}."),
                                     reason=_withheld_text(reasons)))
    text = message(QT_TR_NOOP("Half the peak-to-peak {what}: {value} as measured, coverage "
                              "interval {low} … {high} (U = {u}, coverage probability {p} %; "
                              "noise can only widen a measured range, so the interval reaches "
                              "further below the value than above it). {sentence}"),
                   what=what, value=f"{x:.{d}f}{q}", low=f"{max(0.0, x - lower):.{d}f}{q}",
                   high=f"{x + upper:.{d}f}{q}", u=interval,
                   p=f"{100 * mc.probability:.2f}", sentence=sentence[verdict])
    trials, seed = getattr(mc, "trials", 0), getattr(mc, "seed", MONTE_CARLO_SEED)
    stride = getattr(mc, "stride", 1)
    quantity_text = (message(QT_TR_NOOP("{quantity}: {trials} trials, seed {seed}, on every "
                                        "{stride}-th of the {points} points"),
                             quantity=message(DECISION_QUANTITIES["half_range"]),
                             trials=trials, seed=seed, stride=stride, points=e.size)
                     if stride > 1 else
                     message(QT_TR_NOOP("{quantity}: {trials} trials, seed {seed}"),
                             quantity=message(DECISION_QUANTITIES["half_range"]),
                             trials=trials, seed=seed))
    achieved = HALF_RANGE_COVERAGE
    method = getattr(mc, "method", "")
    quantity_text = method or joined([quantity_text, "; ", message(QT_TR_NOOP(
        "the interval's coverage achieved in validation (noise 0.1 to 2 times the half range, "
        "12 to 72 points, the lowest of each shape): {smooth} % on a smooth curve, {rough} % on "
        "a rough one, {spike} % on a single spike, {sample} % on real curves, against the {p} % "
        "stated"),
        smooth=f"{100 * achieved['smooth']:.1f}", rough=f"{100 * achieved['rough']:.1f}",
        spike=f"{100 * achieved['spike']:.1f}", sample=f"{100 * achieved['sample']:.1f}",
        p=f"{100 * mc.probability:.2f}")])
    common = {**common, "probability": float(mc.probability)}
    return Conformity(verdict, text, rule_text, quantity_text, x, upper,
                      "" if verdict == "not assessed" else
                      _zones(t, 0.0 if rule == "simple" else upper,
                             0.0 if rule == "simple" else lower, rule, d, q), mc, lower,
                      reason=_withheld_text(reasons) if reasons else "",
                      conforming_probability=conforming,
                      decision_risk=_risk(verdict, conforming), **common)


def asymmetric_text(lower: float, upper: float, q: str, d: int) -> str:
    """An interval's half-widths: "±U" when they agree to the digits shown, else "−a/+b"."""
    if f"{lower:.{d}f}" == f"{upper:.{d}f}":
        return f"±{upper:.{d}f}{q}"
    # an interval wholly below the value (a range biased high by noise): its upper end signed
    upper_text = f"+{upper:.{d}f}" if upper >= 0 else f"−{-upper:.{d}f}"
    return f"−{lower:.{d}f}{q}/{upper_text}{q}"
