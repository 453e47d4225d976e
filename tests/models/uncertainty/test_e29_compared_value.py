"""Audit 72 finding 5: where a rule compares the value itself with T (simple acceptance; a
conditional pass against a conditional fail), the value is rounded as ASTM E29 §6.4 rounds
an observed value against a limit — to the last significant place of T as stated (in T's
unit, trailing zeros as typed), or to U's digit where that is finer — and the statement
prints that figure, so that re-deciding from the printed figures gives the printed verdict.
Until 0.8.20 the value was compared at U's digit: 1.6275″ printed 1.6″ passed ±1.626″.

The checks are independent of the code: E29's rounding is done here with decimal.Decimal
(ROUND_HALF_EVEN from the value's own digits, E29 §4) and the verdict re-derived from the
printed text."""

from __future__ import annotations

import math
import re
from decimal import ROUND_FLOOR, ROUND_HALF_EVEN, Decimal
from types import SimpleNamespace

import numpy as np
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

from models.certificate.metadata import CertificateMetadata
from models.quantity import Quantity
from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.conformity import decide_conformity
from tests.ilac_verdict import ilac_verdict

P = 0.9544997361036416  # k = 2 for a normal distribution
NUMBER = r"([+-]?\d+(?:\.\d+)?)"
#: the size of each unit in arcseconds (from the definitions: 1 rad = 648000/π ″)
ARCSEC = {"arcsec": 1.0, "urad": 0.648 / math.pi, "mdeg": 3.6}
SYMBOL = {"arcsec": '"', "urad": " µrad", "mdeg": " mdeg"}


def _budget(expanded: np.ndarray, unit: str = "arcsec") -> UncertaintyBudget:
    return UncertaintyBudget((BudgetComponent("noise", "B", "normal", expanded / 2.0, 1.0, 1.0,
                                              math.inf),), expanded.size, P, unit)


def _half_range(value, lower, upper, t, rule):
    estimate = SimpleNamespace(value=value, u_lower=lower, u_upper=upper, probability=P,
                               measured=value, trials=1000, seed=1, stride=1)
    return decide_conformity(np.array([value, -value]), _budget(np.full(2, 1e-6)), t, rule,
                             "half_range", estimate=estimate)


def _e29(value: float, places: int) -> Decimal:
    """E29's rounding of the decimal the value stands for: its shortest digits, and a value
    within a billionth of the step from a 5 on the place kept taken as that 5 (binary
    arithmetic leaves a decimal tie such as 8.85 a few units of its last bit off:
    8.850000000000001; readings typed to six decimals or fewer cannot make a value that close
    to a tie that is not one — audit 73, finding 2)."""
    exact, step = Decimal(repr(float(value))), Decimal(1).scaleb(-places)
    tie = exact.quantize(step, rounding=ROUND_FLOOR) + step / 2
    if abs(exact - tie) <= step / 10**9:
        exact = tie
    return exact.quantize(step, rounding=ROUND_HALF_EVEN)


def _compared(statement: str, symbol: str = '"') -> Decimal | None:
    found = re.search(r"Compared with T: " + NUMBER + re.escape(symbol), statement)
    return Decimal(found.group(1)) if found else None


def test_the_audit_case_fails_as_e29_rounds_it():
    """1.6275″ (U −1.0″/+0.5″, printed 1.6″) against ±1.626″, simple acceptance: E29 rounds
    it to 1.628″ > 1.626″, a fail, and the statement prints the figure compared."""
    c = _half_range(1.6275, 1.0, 0.5, 1.626, "simple")
    assert c.verdict == "fail"
    assert "1.6\" as measured" in c.statement and "±1.626\" (fail)" in c.statement
    assert _compared(c.statement) == Decimal("1.628")


def test_a_tie_rounds_to_even_and_passes():
    """1.6265″ is 1.626″ in E29's rounding (a 5 alone rounds to the even digit): a pass."""
    c = _half_range(1.6265, 1.0, 0.5, 1.626, "simple")
    assert c.verdict == "pass" and _compared(c.statement) == Decimal("1.626")


def test_the_reverse_passes_at_the_limits_place():
    """Cross-calibration's case: 1.7695227″ against ±1.76952″ with U = 0.02″ (printed 1.77″,
    which 0.8.20 failed): E29 to T's fifth decimal gives 1.76952″, at T, a pass."""
    c = _half_range(1.7695227, 0.02, 0.02, 1.76952, "simple")
    assert c.verdict == "pass" and _compared(c.statement) == Decimal("1.76952")


#: how the statement says the figure compared was rounded: to the finer of the two places,
#: E29's (T's) and U's (assessment 73 M1: it said "to the last place of T as stated" alone)
FINER_RULE = "the result rounded to the finer of T's last place as stated and U's last digit"


def test_a_coarse_limit_compares_the_value_as_printed():
    """T stated to a coarser place than U's digit: the printed value is compared (U's digit
    is the finer), and the statement says so, as E29 alone would round to T's place: 2.96″
    against ±3″ (until 0.8.21 nothing was said of the place)."""
    c = _half_range(2.96, 0.2, 0.2, 3.0, "simple")
    assert c.verdict == "pass" and "2.96\"" in c.statement
    assert _compared(c.statement) == Decimal("2.96") and FINER_RULE in c.statement


def test_a_value_kept_finer_than_t_says_so_where_e29_at_t_would_pass():
    """Assessment 73 M1's cross-calibration case: 0.5448″ (U 0.026″/0.030″, printed 0.545″)
    against ±0.54″ under simple acceptance. E29 at T's place alone would give 0.54″, a pass;
    the stricter rule keeps U's digit, 0.545″ > 0.54″, a fail, and the statement prints the
    figure compared and the rule it was rounded by (0.8.21 printed no sentence)."""
    c = _half_range(0.5448, 0.026, 0.030, 0.54, "simple")
    assert c.verdict == "fail"
    figure = _compared(c.statement)
    assert figure is not None and figure > Decimal("0.54") and FINER_RULE in c.statement
    assert _e29(0.5448, 2) <= Decimal("0.54")  # the case is the one where the rules differ


def test_a_figure_finer_than_t_never_claims_t_s_place_alone():
    """Assessment 73 M1's fringe case: 2.3571 µrad against ±2.357 µrad (U's digit 0.0001):
    the figure compared keeps four decimals, so the statement may not say it was rounded to
    T's place as stated: it names the finer of the two."""
    value = 2.35712 * ARCSEC["urad"]
    c = _half_range(value, 0.0003, 0.0003, Quantity(2.357, "urad"), "simple")
    figure = _compared(c.statement, " µrad")
    assert figure is not None and -figure.as_tuple().exponent > 3  # T: 3 decimals
    assert FINER_RULE in c.statement and "rounded to the last place of T as stated" not in (
        c.statement)
    assert c.verdict == ("pass" if figure <= Decimal("2.357") else "fail")


def test_the_non_binary_rule_compares_so_between_its_conditional_verdicts():
    """guarded: 1.6275″ beyond T by E29 is a conditional fail, not a conditional pass."""
    c = _half_range(1.6275, 1.0, 0.5, 1.626, "guarded")
    assert c.verdict == "conditional fail" and _compared(c.statement) == Decimal("1.628")


def test_every_point_is_compared_so():
    """The points' rule: a point at −1.6275″ with U = 1.2″ (printed 1.6″) against ±1.626″."""
    errors, expanded = np.array([0.1, -1.6275]), np.array([1.2, 1.2])
    c = decide_conformity(errors, _budget(expanded), 1.626, "simple", "points")
    assert c.verdict == "fail" and "|e| = 1.6\"" in c.statement
    assert _compared(c.statement) == Decimal("1.628")


def test_a_limit_in_another_unit_is_compared_in_its_unit():
    """T = ±7.883 µrad for errors in arcseconds: the value in µrad rounded to 0.001 µrad."""
    value = 1.6275
    c = _half_range(value, 1.0, 0.5, Quantity(7.883, "urad"), "simple")
    in_urad = value / ARCSEC["urad"]
    expected = _e29(in_urad, 3)
    assert _compared(c.statement, " µrad") == expected
    assert c.verdict == ("pass" if expected <= Decimal("7.883") else "fail")


def test_a_limit_typed_with_trailing_zeros_keeps_its_place():
    """A tolerance typed "1.50" (a text, or a JSON number read with its digits) is stated to
    0.01: 1.54″ with U = 1.2″ (d 0.1″, printed 1.5″) fails ±1.50″ (0.8.20: "1.5″", passed)."""
    meta = CertificateMetadata.from_dict({"tolerance": "1.50", "tolerance_unit": "arcsec"})
    c = _half_range(1.54, 1.2, 1.2, meta.tolerance_quantity, "simple")
    assert c.verdict == "fail"
    assert "±1.50\" (fail)" in c.statement and _compared(c.statement) == Decimal("1.54")


def test_the_command_line_reads_a_limits_trailing_zeros(tmp_path):
    """The details' JSON number 1.50 is read with its two decimals."""
    from app.cli import _read_metadata

    path = tmp_path / "details.json"
    path.write_text('{"tolerance": 1.50, "tolerance_unit": "arcsec"}', "utf-8")
    meta = _read_metadata(str(path))
    assert meta.tolerance == 1.5 and getattr(meta.tolerance, "decimals", None) == 2


# --- the property -------------------------------------------------------------------------

def _printed_verdict(statement: str) -> str:
    for said, verdict in (("(pass)", "pass"), ("(fail)", "fail"),
                          ("Conditional pass:", "conditional pass"),
                          ("Conditional fail:", "conditional fail")):
        if said in statement:
            return verdict
    raise AssertionError(statement)


@st.composite
def _finer_limits(draw):
    """A value near T, T stated to 1–4 places finer than U's digit, in the errors' unit or
    another."""
    rule = draw(st.sampled_from(["simple", "guarded_binary", "guarded"]))
    t_unit = draw(st.sampled_from(["arcsec", "urad", "mdeg"]))
    scale = 10.0 ** draw(st.integers(-2, 1))
    upper = scale * draw(st.floats(1.0, 9.99))
    lower = upper * draw(st.floats(0.5, 2.0))
    u_places = 1 - math.floor(math.log10(max(upper, lower)))
    t_arcsec = max(upper, lower) * draw(st.floats(1.2, 6.0))
    t_places = max(0, u_places + draw(st.integers(-1, 4))
                   - round(math.log10(ARCSEC[t_unit])))
    t_number = Decimal(repr(t_arcsec / ARCSEC[t_unit])).quantize(Decimal(1).scaleb(-t_places))
    assume(t_number > 0)
    t_arcsec = float(t_number) * ARCSEC[t_unit]
    digit = 10.0 ** -u_places
    value = max(1e-9, t_arcsec + digit * draw(st.floats(-1.0, 1.0)))
    return value, lower, upper, t_number, t_unit, rule


@settings(max_examples=300, deadline=None)
@given(_finer_limits())
@example((1.6275, 1.0, 0.5, Decimal("1.626"), "arcsec", "simple"))
@example((1.6275, 1.0, 0.5, Decimal("1.626"), "arcsec", "guarded"))
def test_the_verdict_is_the_printed_figures_and_never_passes_beyond_e29(case):
    value, lower, upper, t_number, t_unit, rule = case
    # T as the details state it, typed with its digits (trailing zeros too)
    t = CertificateMetadata.from_dict({"tolerance": str(t_number),
                                       "tolerance_unit": t_unit}).tolerance_quantity
    c = _half_range(value, lower, upper, t, rule)
    if not c.stated:
        assert "is not smaller than" in c.reason
        return
    found = re.search(NUMBER + '" as measured, coverage interval ' + NUMBER + '" … ' + NUMBER
                      + r'" \(U = (?:±' + NUMBER + '"|−' + NUMBER + r'"/\+' + NUMBER + '")',
                      c.statement)
    assert found, c.statement
    x = Decimal(found.group(1))
    minus = Decimal(found.group(4) or found.group(5))
    plus = Decimal(found.group(4) or found.group(6))
    compared = _compared(c.statement, SYMBOL[t_unit])
    # T's number as printed (as stated, in its unit)
    said_t = re.search(r"(?:specification|within|beyond) ±" + NUMBER + re.escape(SYMBOL[t_unit]),
                       c.statement)
    assert said_t and Decimal(said_t.group(1)) == t_number, c.statement
    t_in_errors = t_number * Decimal(repr(ARCSEC[t_unit]))
    # the guard bands' ends in the errors' unit against T converted; the value itself
    # against T in T's unit, as the statement prints it compared (a value compared in
    # another unit is always printed)
    value_decides = rule == "simple" or (
        rule == "guarded" and x + plus > t_in_errors and x - minus <= t_in_errors)
    if t_unit != "arcsec" and value_decides:
        assert compared is not None, c.statement
    xc = (x if compared is None else compared)
    if rule == "simple":
        redone = "pass" if xc <= t_number else "fail"
    elif t_unit == "arcsec":
        redone = ilac_verdict(rule, x, minus, plus, t_number, xc)
    else:
        redone = ilac_verdict(rule, x, minus, plus, t_in_errors, x)
        if value_decides:
            redone = "conditional pass" if xc <= t_number else "conditional fail"
    assert _printed_verdict(c.statement) == c.verdict == redone, (c.statement, case)
    # never a pass of a value that ASTM E29 rounds beyond T (in T's unit, to T's place)
    if c.verdict in ("pass", "conditional pass"):
        in_t = value / ARCSEC[t_unit]
        assert _e29(in_t, -t_number.as_tuple().exponent) <= t_number, (c.statement, case)


def test_a_limits_trailing_zeros_survive_the_details_saved_and_read_back():
    """The details saved (a project file, the lab's defaults) and read again keep ±1.50″."""
    import json

    meta = CertificateMetadata.from_dict({"tolerance": "1.50", "tolerance_unit": "arcsec"})
    again = CertificateMetadata.from_dict(json.loads(json.dumps(meta.to_dict())))
    c = _half_range(1.54, 1.2, 1.2, again.tolerance_quantity, "simple")
    assert c.verdict == "fail" and "±1.50\" (fail)" in c.statement
    plain = CertificateMetadata.from_dict({"tolerance": 1.5})
    assert plain.to_dict()["tolerance"] == 1.5  # a number stays a number


def test_a_value_ending_in_a_five_on_the_printed_place_is_compared_as_e29_rounds_it():
    """Fresh CI's hypothesis draw: 3.55″ (U −2.0″/+1.0″) printed 3.5″ (the float is 3.5499…)
    passed ±3.5″ under simple acceptance; E29 rounds 3.55 to 3.6, beyond T."""
    c = _half_range(3.55, 2.0, 1.0, 3.5, "simple")
    assert "3.5\" as measured" in c.statement
    assert c.verdict == "fail", c.statement
    assert _compared(c.statement) == Decimal("3.6")


def test_a_tie_computed_just_above_rounds_to_even_as_the_tie_it_is():
    """8.85″ computed as 8.850000000000001 (fresh CI's hypothesis draw) is the tie 8.85,
    which E29 rounds to the even 8.8: a pass against ±8.8″ — as 8.85 typed would."""
    assert _e29(8.850000000000001, 1) == _e29(8.85, 1) == Decimal("8.8")
    c = _half_range(8.850000000000001, 3.5, 2.0, 8.8, "simple")
    assert c.verdict == "pass" and _compared(c.statement) == Decimal("8.8")
