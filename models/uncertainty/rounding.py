"""How many decimals an expanded uncertainty U is printed with (GUM 7.2.6: two significant
digits at most). In a module of its own, without the budgets and the decision rules of
:mod:`models.uncertainty.conformity` (which names both as its own too): a summary on the
command line rounds its U and needs no more (tests/app/test_cli_imports.py)."""

from __future__ import annotations

import functools
import math

__all__ = ["StatedNumber", "e29_rounded", "fixed_places", "interval_decimals", "interval_ends",
           "printed_range", "significant_decimals", "stated_decimals", "stated_interval",
           "stated_pair", "uncertainty_decimals", "without_interval_decimals", "written_places"]


def significant_decimals(expanded: float) -> int | None:
    """Decimals that show U with at most two significant digits (GUM 7.2.6, JJF 1059.1),
    after rounding up, as every U is printed (0.0996 is "0.10", not "0.100"; 0.994 is "1.0",
    not "1.00"); None if U is not a positive number. Negative for a U of 100 or more: to the
    tens, hundreds … (assessment 76 M1: 168 nm is "170 nm")."""
    return _significant_decimals(float(expanded))


@functools.lru_cache(maxsize=4096)
def _significant_decimals(expanded: float) -> int | None:
    """:func:`significant_decimals` of a float, kept for the U last asked about: a results
    table asks for each point's U in every column (a fringe certificate's 1,300 asks)."""
    if not math.isfinite(expanded) or expanded <= 0:
        return None
    decimals = 1 - int(math.floor(math.log10(expanded)))
    units = expanded * 10.0 ** decimals
    up = round(units) if abs(units - round(units)) < 1e-9 else math.ceil(units)
    if up >= 100:
        decimals -= 1  # rounding up carried into a third digit
    return decimals


def written_places(decimals: int) -> int:
    """The places after the point a figure rounded to ``decimals`` is written with: none
    where ``decimals`` is negative (a figure rounded to the tens, "170")."""
    return max(0, int(decimals))


def fixed_places(value: float, decimals: int, sign: str = "") -> str:
    """``value`` rounded to ``decimals`` (to the nearest; negative: to the tens, hundreds …,
    :func:`significant_decimals`) and written in fixed notation with
    :func:`written_places` places ("170" for 168.3 at −1, "+0.40" for 0.397 at 2), ``sign``
    "+" to sign it. A figure that rounds to zero has no sign, "0.0" (never "-0.0", nor
    "+0.0" with ``sign``): zero is neither positive nor negative, and one convention holds
    in every column (assessment 76 L6: a results table printed "0.0" at θ = −2° and "+0.0"
    at the reference point). A value that is not finite is written as Python writes it
    ("nan")."""
    if not math.isfinite(value):
        return f"{value:{sign}}"
    shown = round(float(value), int(decimals)) + 0.0
    return f"{shown:{'' if shown == 0.0 else sign}.{written_places(decimals)}f}"


def uncertainty_decimals(expanded: float) -> int:
    """:func:`significant_decimals` (two significant digits of U at most); two decimals
    where U is not a positive number (nothing to round to)."""
    decimals = significant_decimals(expanded)
    return 2 if decimals is None else decimals


def interval_decimals(low: float, high: float) -> int:
    """The decimal a figure and the ends of its coverage interval [``low``, ``high``] are
    printed to: that which shows the interval's half-width, (high − low)/2, its U, with at
    most two significant digits (GUM 7.2.6, JJF 1059.1): a figure with an interval 4″ wide
    to 0.1″, not 0.001″. Two decimals where the interval has no width."""
    return uncertainty_decimals((high - low) / 2.0)


def without_interval_decimals(scatter: float, step: float | None) -> int:
    """The decimal a figure with no coverage interval at all is printed to (a target
    approached once, readings alike or entered coarser than they scatter): that which shows
    the readings' own scatter ``scatter`` (their pooled s) to its first significant digit
    — a figure made of the readings is known no better than one reading, and how much
    worse no interval says, so its last digit stands where s's first does — and never
    finer than the readings' ``step`` as
    entered (models.readings.resolution.readings_step); the step's alone where the readings
    show no scatter; three decimals where neither is known. Day review 68 F5: such a figure
    was printed to 0.001″ beside figures with intervals printed to 1″."""
    first = significant_decimals(scatter) if math.isfinite(scatter) else None
    shown = [d for d in (None if first is None else first - 1, _step_decimals(step))
             if d is not None]
    return min(shown) if shown else 3


def _step_decimals(step: float | None) -> int | None:
    """The decimals of readings entered on a grid of ``step`` (0.01 → 2, 0.5 → 1, 2 → 0)."""
    if step is None or not math.isfinite(step) or step <= 0:
        return None
    for decimals in range(7):
        if abs(step * 10.0 ** decimals - round(step * 10.0 ** decimals)) < 1e-6:
            return decimals
    return 6


def interval_ends(low: float, high: float, decimals: int) -> tuple[float, float]:
    """A coverage interval's ends as printed, to ``decimals``: each rounded from the
    computed end, away from the inside (the lower end down, the upper up), so that the
    printed interval holds the computed one. The interval is a statement at a coverage
    probability: an end rounded inwards would state a narrower interval than the one that
    reached it, which is why GUM 7.2.6 rounds U up rather than to the nearest digit; and a
    printed upper end at or below T (on the printed grid) then says what the guarded
    decision says, where one rounded to the nearest could show 3.0″ for a computed 3.04″
    that fails ±3″. Ends already on the grid (to 1e-9 of a digit) are kept."""
    step = 10.0 ** -decimals

    def rounded(end: float, towards) -> float:
        if not math.isfinite(end):
            return end
        units = end / step
        near = round(units)
        whole = near if abs(units - near) < 1e-9 else towards(units)
        return round(whole * step, decimals) + 0.0  # never "-0.0"

    return rounded(low, math.floor), rounded(high, math.ceil)


def printed_range(low: float, high: float, decimals: int) -> tuple[str, str, str]:
    """A range as it is printed ("-1.08", "-0.10", "0.98"), the window's and the
    certificate's alike: its ends signed, to ``decimals``, and the peak-to-peak the
    difference of the ends as printed, so that it adds up as printed (2.65 for the ends
    -2.12 and +0.53, whatever the unrounded 2.64…). A zero has no sign, "0.00"
    (:func:`fixed_places`; until 0.8.24 "+0.00")."""
    a, b = (fixed_places(v, decimals, "+") for v in (low, high))
    ptp = round(float(b) - float(a), decimals) + 0.0
    return a, b, fixed_places(ptp, decimals)


def _on_grid(value: float, decimals: int, towards) -> float:
    units = value * 10.0 ** decimals
    near = round(units)
    whole = near if abs(units - near) < 1e-9 else towards(units)
    return round(whole / 10.0 ** decimals, decimals) + 0.0


def stated_interval(value: float, lower: float, upper: float, decimals: int,
                    clip_at_zero: bool = False) -> dict[str, float]:
    """A value with its coverage interval [value − ``lower``, value + ``upper``] as printed
    to ``decimals`` (assessment 70 M1), so that the printed value ± the printed U₋, U₊ *is*
    the printed interval: the value rounded to the nearest; each U the computed U rounded up
    (GUM 7.2.6), the same figure as the largest U, the CMC statement, the budget and the
    machine-readable outputs give for it (assessment 72 H1: until 0.8.20 a U was re-measured
    from the rounded value to the computed end, one digit above the U stated everywhere
    else, and a CMC-held ±0.050″ printed −0.050″/+0.051″); the ends the printed value ∓ the
    printed U. ``clip_at_zero``: a half range, whose lower end is held at 0 (U₋ then the
    printed value where the interval reaches below 0).
    Returns {"value", "lower", "upper", "low", "high"}."""
    shown = round(value, decimals) + 0.0
    if not all(math.isfinite(x) for x in (value, lower, upper)):
        return {"value": shown, "lower": lower, "upper": upper, "low": value - lower,
                "high": value + upper}
    minus = _on_grid(lower, decimals, math.ceil)
    plus = _on_grid(upper, decimals, math.ceil)
    if clip_at_zero and (value - lower <= 0.0 or shown - minus < 0.0):
        minus = shown  # held at 0: U₋ the printed value less it
    return {"value": shown, "lower": round(minus, decimals) + 0.0,
            "upper": round(plus, decimals) + 0.0, "low": round(shown - minus, decimals) + 0.0,
            "high": round(shown + plus, decimals) + 0.0}


def stated_pair(value: float, expanded: float) -> tuple[float, float, int]:
    """A figure and its symmetric U as printed side by side ("+10.3″", "3.1″": a results
    table's point and its U column, a deciding point's "|e| = …, U = …"): (the value to
    the nearest, U rounded up, decimals): U two significant digits at most rounded up
    (GUM 7.2.6), the value to the same decimal (:func:`stated_interval`), one U per point in
    every document (assessment 72 H1), the one its decision is taken on (issue 39). The sign
    of ``value`` does not change U. A U that is zero or not a number is returned as it is (a
    reference point, U withheld), the value then unrounded."""
    if not (math.isfinite(expanded) and expanded > 0):
        return value, expanded, uncertainty_decimals(expanded)
    decimals = uncertainty_decimals(expanded)
    # stated_interval(value, expanded, expanded, decimals)'s value and upper U, worked out
    # alone (a results table asks for one a cell: a fringe certificate's 1,800): the value
    # to the nearest; U rounded up, or as it is beside a value that is not a number
    shown = round(value, decimals) + 0.0
    if not math.isfinite(value):
        return shown, expanded, decimals
    return shown, round(_on_grid(expanded, decimals, math.ceil), decimals) + 0.0, decimals


def stated_decimals(number: float) -> int:
    """The decimal of the last significant place of a limit as it was stated: its
    ``decimals`` where it carries them (a number typed with trailing zeros, "1.50": 2, kept
    by :class:`StatedNumber`), else its shortest digits (1.626: 3, 1.5: 1, 20: 0). Never
    negative: a limit of 20 or 300 is taken to its units place."""
    given = getattr(number, "decimals", None)
    if isinstance(given, int) and given >= 0:
        return given
    if not math.isfinite(number):
        return 0
    import numpy as np

    text = np.format_float_positional(abs(float(number)), unique=True, trim="-")
    return len(text.partition(".")[2])


class StatedNumber(float):
    """A number that keeps the decimals it was typed with ("1.50" is 1.5 to 2 decimals):
    a specification limit's last significant place, which ASTM E29 §6.4 rounds an observed
    value to, and which a float drops with its trailing zeros."""

    decimals: int

    def __new__(cls, value: float, decimals: int) -> StatedNumber:
        made = super().__new__(cls, value)
        made.decimals = int(decimals)
        return made

    def __getnewargs__(self):  # copied, pickled
        return float(self), self.decimals

    @classmethod
    def from_text(cls, text: str) -> StatedNumber:
        """The number typed in ``text`` ("1.50", "1,50", "2e-3") with its decimals."""
        from decimal import Decimal, InvalidOperation

        cleaned = text.strip().replace(",", ".")
        try:
            exponent = Decimal(cleaned).as_tuple().exponent
        except InvalidOperation:
            raise ValueError(f"not a number: {text!r}") from None
        decimals = max(0, -exponent) if isinstance(exponent, int) else 0
        return cls(float(cleaned), decimals)


#: a value within this share of a place's step from a tie on that place (…5 followed by
#: nothing but zeros) is the tie: the decided values are computed in binary from readings
#: typed to a few decimals, so an exact 5.075 (E/2 of means of readings typed to 0.001)
#: comes out 5.074999999999999, a few ulps (here 1e-13 of the 0.01 step) off. The float
#: error is some ulps of the figures summed (values of at most ~1e4, steps of at least
#: 1e-6: under 1e-11 of the step). A value that is not a tie but is a mean's difference of
#: readings typed to d decimals lies at least 10^-d / (2 n) from one (n readings in a
#: mean): for d ≤ 6, n ≤ 100 and steps of at most 1, at least 5e-9 of the step. 1e-9 of
#: the step lies between the two; a value fitted (not a decimal) falls within it of a tie
#: with a chance of 2e-9, where either rounding is as good as the data.
E29_TIE_SHARE = 1e-9


def e29_rounded(value: float, decimals: int) -> float:
    """``value`` rounded to ``decimals`` decimals as ASTM E29 §6.4 rounds an observed value
    (its rounding method, §4.2–4.4: to the nearest, a 5 followed by nothing but zeros
    rounding the last place kept to even), from the value's shortest digits (1.6275 is
    1.628, 1.6265 is 1.626) and never "-0.0". A value within :data:`E29_TIE_SHARE` of the
    step from a tie is that tie (5.074999999999999, an exact 5.075 computed in binary, is
    5.08 at two decimals; until 0.8.21 it was 5.07)."""
    from decimal import ROUND_FLOOR, ROUND_HALF_EVEN, Decimal

    if not math.isfinite(value):
        return value
    exact = Decimal(repr(float(value)))
    step = Decimal(1).scaleb(-decimals)
    tie = exact.quantize(step, rounding=ROUND_FLOOR) + step / 2
    if abs(exact - tie) <= step * Decimal(E29_TIE_SHARE):
        exact = tie
    return float(exact.quantize(step, rounding=ROUND_HALF_EVEN)) + 0.0
