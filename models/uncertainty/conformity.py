"""Statements of conformity with ±T under a stated decision rule (ILAC-G8:09/2019).

The decided quantity is explicit and chosen (metadata ``decision_quantity``):

* ``half_range`` — half the peak-to-peak of the error curve, the ± band the
  curve fits in after the best zero. The range of noisy points is biased
  upward, and its uncertainty is not one point's U, so both come from a
  Monte Carlo simulation of this statistic for this measurement (JCGM 101):
  a curve plus draws of every input of its budget (independent from point to
  point, or shared where the input is one reading common to all points),
  seeded so that the certificate is reproducible (see
  :func:`half_range_monte_carlo`).
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
    "half_range": QT_TR_NOOP("half the peak-to-peak error after the best zero, with its own U "
                             "and bias from a Monte Carlo simulation of this measurement "
                             "(JCGM 101)"),
    "points": QT_TR_NOOP("every point's error against ±T with that point's own U "
                         "(ISO 14253-1)"),
}

MONTE_CARLO_SEED = 20261127
MONTE_CARLO_TRIALS = 10_000
_MONTE_CARLO_DRAWS = 5_000_000  # trials × points at the most (40 MB of draws)
#: A longer curve is judged on every k-th point (its range over 16 384 points of a long,
#: repetitive record — a fringe revolution — is all but the same), and says so.
MAX_MONTE_CARLO_POINTS = 16_384


#: The coverage the half-range interval achieved in its validation, by curve shape
#: (tests/models/uncertainty/test_half_range_coverage.py: true half range 3σ, 36 points — 41 for the real
#: sample — 300 measurements each, seed 20261201): short of the stated 95.45 %, so the
#: certificate prints it.
HALF_RANGE_COVERAGE = {"smooth": 0.883, "rough": 0.917, "spike": 0.900, "sample": 0.893}


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
    """Half the peak-to-peak of an error curve, from a Monte Carlo simulation (in the unit of
    the curve and its budget)."""

    measured: float  # half the peak-to-peak of the measured curve
    bias: float  # measured − value: what the noise added to the range
    value: float  # the estimate stated
    u_upper: float  # upper half-width of the coverage interval about the simulated mean
    u_lower: float
    probability: float
    trials: int
    seed: int
    stride: int = 1  # judged on every stride-th point of a long curve


def _standard_draws(rng: np.random.Generator, distribution: str, shape) -> np.ndarray:
    if distribution == "rectangular":
        return rng.uniform(-math.sqrt(3.0), math.sqrt(3.0), shape)
    return rng.standard_normal(shape)


def _noise_draws(budget: UncertaintyBudget, points: np.ndarray, trials: int,
                 rng: np.random.Generator) -> np.ndarray:
    """(trials, len(points)) draws of the curve's error at ``points``: every budget input,
    ``common`` inputs one draw per trial, the others one per point."""
    n = points.size
    draws = np.zeros((trials, n))
    for comp, c_u in zip(budget.components, budget.contributions(), strict=True):
        shape = (trials, 1) if comp.common else (trials, n)
        draws += _standard_draws(rng, comp.distribution, shape) * c_u[points]
    return draws


def _denoised_half_range(curves: np.ndarray, noise_power: float) -> np.ndarray:
    """Half the peak-to-peak of each row of ``curves`` after Fourier shrinkage: every
    coefficient is scaled by max(0, 1 − P/|X_k|²), P the expected power of the
    point-to-point noise in one coefficient (positive-part James–Stein)."""
    spectrum = np.fft.rfft(curves - curves.mean(axis=1, keepdims=True), axis=1)
    power = np.abs(spectrum) ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        gain = np.where(power > noise_power, 1.0 - noise_power / power, 0.0)
    smooth = np.fft.irfft(spectrum * gain, n=curves.shape[1], axis=1)
    return 0.5 * (smooth.max(axis=1) - smooth.min(axis=1))


def half_range_monte_carlo(errors, budget: UncertaintyBudget,
                           trials: int = MONTE_CARLO_TRIALS,
                           seed: int = MONTE_CARLO_SEED) -> HalfRangeEstimate:
    """JCGM 101 for half the peak-to-peak of ``errors`` (in the budget's unit; points in
    their natural order: by angle, position or sample).

    The measured half range of a noisy curve runs high: noise widens any range.
    The estimator S takes the half range after Fourier shrinkage of the
    point-to-point noise that the budget states. Its mean over simulated
    measurements — a candidate true curve (the shrunk curve scaled by λ) plus
    draws of every budget input (``common`` inputs one draw per trial, the
    others one per point) — is matched to S of the measurement by choosing λ
    (the same draws for every λ); the estimate is the candidate's half range.
    U is the simulated spread of S at that λ divided by the slope of mean S
    against the true half range (so it widens where noise hides the curve),
    combined with the size of the bias removed (rectangular). ``trials`` is
    lowered on long curves (5·10⁶ draws at the most), and a curve of more than
    16 384 points is judged on every k-th point.
    """
    full = np.asarray(errors, dtype=float)
    stride = max(1, -(-full.size // MAX_MONTE_CARLO_POINTS))
    points = np.arange(0, full.size, stride)
    e = full[points]
    n = e.size
    trials = int(max(200, min(trials, _MONTE_CARLO_DRAWS // max(n, 1))))
    independent = [c_u[points] for comp, c_u in zip(budget.components, budget.contributions(),
                                                    strict=True) if not comp.common]
    noise_power = float(np.sum(np.square(independent))) if independent else 0.0
    spectrum = np.fft.rfft(e - e.mean())
    power = np.abs(spectrum) ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        gain = np.where(power > noise_power, 1.0 - noise_power / power, 0.0)
    shrunk = np.fft.irfft(spectrum * gain, n=n)
    observed = 0.5 * float(np.ptp(shrunk))
    draws = _noise_draws(budget, points, trials, np.random.default_rng(seed))

    def estimates(scale: float, count: int = trials) -> np.ndarray:
        out = np.empty(count)
        chunk = max(1, min(count, 2_000_000 // max(n, 1)))
        for start in range(0, count, chunk):
            stop = min(start + chunk, count)
            out[start:stop] = _denoised_half_range(scale * shrunk + draws[start:stop],
                                                   noise_power)
        return out

    def mean_estimate(scale: float) -> float:
        # λ is searched on the first 2000 trials (the same for every λ), then all are run
        return float(np.mean(estimates(scale, min(trials, 2000))))

    scale = 0.0
    if observed > 0 and mean_estimate(0.0) < observed:
        lo, hi = 0.0, 1.0
        while mean_estimate(hi) < observed and hi < 8.0:
            lo, hi = hi, 2.0 * hi
        for _ in range(40):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if mean_estimate(mid) < observed else (lo, mid)
            if hi - lo < 1e-4:
                break
        scale = 0.5 * (lo + hi)
    value = scale * observed
    at_value = estimates(scale)
    mean = float(np.mean(at_value))
    step = 0.05
    slope = 1.0
    if observed > 0:
        slope = (mean_estimate(scale + step) - mean_estimate(max(scale - step, 0.0))) / (
            (scale + step - max(scale - step, 0.0)) * observed)
    slope = max(slope, 0.2)  # a flat response would make U unbounded: cap its growth
    tail = 0.5 * (1.0 - budget.probability)
    q_lo, q_hi = np.quantile(at_value, [tail, 1.0 - tail])
    spread = float(np.std(at_value))
    k = (float(q_hi) - float(q_lo)) / (2.0 * spread) if spread > 0 else 2.0
    measured = 0.5 * float(np.ptp(e))
    u_bias = k * abs(observed - value) / math.sqrt(3.0)
    return HalfRangeEstimate(measured, measured - value, value,
                             math.hypot((float(q_hi) - mean) / slope, u_bias),
                             math.hypot((mean - float(q_lo)) / slope, u_bias),
                             budget.probability, trials, seed, stride)


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
                      point_names=None, not_stated=()) -> Conformity:
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
    results table does (the deciding point is named so).
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
                                         sentence, q, common))


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
                       common) -> Conformity:
    mc = half_range_monte_carlo(e, budget)
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
    measured = float(mc.measured)
    text = message(QT_TR_NOOP("Half the peak-to-peak {what}: {value} (measured {measured}, less "
                              "{bias} that the noise adds to a range), U = {u} (coverage "
                              "probability {p} %). {sentence}"),
                   what=what, value=f"{x:.{d}f}{q}", measured=f"{measured:.{d}f}{q}",
                   bias=f"{measured - x:.{d}f}{q}", u=interval,
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
    quantity_text = joined([quantity_text, "; ", message(QT_TR_NOOP(
        "the interval's coverage achieved in validation (true half range 3σ): {smooth} % on a "
        "smooth curve, {rough} % on a rough one, {spike} % on a single spike, {sample} % on a "
        "real axis' curve, against the {p} % stated"),
        smooth=f"{100 * achieved['smooth']:.0f}", rough=f"{100 * achieved['rough']:.0f}",
        spike=f"{100 * achieved['spike']:.0f}", sample=f"{100 * achieved['sample']:.0f}",
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
    return f"−{lower:.{d}f}{q}/+{upper:.{d}f}{q}"
