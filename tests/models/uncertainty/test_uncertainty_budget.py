"""The GUM budget, the metadata and the decision rules."""

from __future__ import annotations

import datetime as dt
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.certificate.metadata import (
    CertificateMetadata,
    MetadataError,
    ReferenceStandard,
    clean_text,
    format_certificate_number,
)
from models.uncertainty.budget import (
    DEFAULT_COVERAGE_PROBABILITY,
    BudgetComponent,
    UncertaintyBudget,
    coverage_factor,
    divisor_for_basis,
)
from models.uncertainty.conformity import decide_conformity, half_range_monte_carlo

GTC = pytest.importorskip("GTC")


def test_budget_hand_figures():
    budget = UncertaintyBudget((
        BudgetComponent("std", "B", "normal", 0.6, 2.0, math.sqrt(2), math.inf),
        BudgetComponent("mpe", "B", "rectangular", 0.3 * math.sqrt(3), math.sqrt(3), 1.0, math.inf),
        BudgetComponent("noise", "A", "normal", np.array([0.0, 0.4]), 1.0, 1.0, 9),
    ), points=2)
    # point 1: (0.3·√2)² + 0.3² = 0.27; point 2: + 0.16
    assert budget.combined == pytest.approx([math.sqrt(0.27), math.sqrt(0.43)])
    assert budget.worst_index == 1
    # Welch–Satterthwaite: 0.43² / (0.4⁴ / 9) = 65.0; k from Student's t for 95.45 %
    nu = 0.43**2 / (0.4**4 / 9)
    assert budget.effective_dof() == pytest.approx(nu)
    assert budget.coverage_factor == pytest.approx(2.039, abs=1e-3)  # scipy.stats.t.ppf
    assert budget.expanded[1] == pytest.approx(budget.coverage_factor * math.sqrt(0.43))
    assert budget.coverage_factors[0] == pytest.approx(2.0, abs=1e-9)  # ν_eff = ∞: k = 2
    rows = budget.table()
    assert [r["name"] for r in rows] == ["std", "mpe", "noise"]
    assert sum(r["share"] for r in rows) == pytest.approx(1.0)


@pytest.mark.parametrize("dof, probability, k", [
    (5, 0.9545, 2.65), (5, 0.95, 2.57), (math.inf, DEFAULT_COVERAGE_PROBABILITY, 2.00),
    (math.inf, 0.95, 1.96), (20, 0.9545, 2.13)])
def test_coverage_factor_from_student_t(dof, probability, k):
    """GUM Table G.2: ν = 5 gives k = 2.65 for 95.45 % (2.57 for 95 %)."""
    assert coverage_factor(dof, probability) == pytest.approx(k, abs=0.005)


@pytest.mark.parametrize("value", [float("inf"), float("nan"), -0.1])
def test_budget_refuses_an_absurd_input(value):
    with pytest.raises(ValueError, match="finite, non-negative"):
        BudgetComponent("x", "B", "normal", value, 1.0, 1.0, math.inf)


def test_divisors():
    assert divisor_for_basis("U95") == (2.0, "normal")
    assert divisor_for_basis("MPE")[0] == pytest.approx(math.sqrt(3))
    with pytest.raises(ValueError, match="basis"):
        divisor_for_basis("k3")


@pytest.mark.slow
@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(0.01, 5.0), st.floats(-3.0, 3.0).filter(lambda c: abs(c) > 0.01),
                          st.sampled_from([math.inf, 2, 5, 30])), min_size=1, max_size=6))
def test_budget_agrees_with_gtc(inputs):
    """The root sum of squares and ν_eff agree with the GUM Tree Calculator."""
    components = tuple(BudgetComponent(f"x{i}", "A", "normal", u, 1.0, c, nu)
                       for i, (u, c, nu) in enumerate(inputs))
    ours = UncertaintyBudget(components, 1)
    y = sum(c * GTC.ureal(1.0, u, nu) for u, c, nu in inputs)
    assert ours.combined[0] == pytest.approx(GTC.uncertainty(y), rel=1e-9)
    nu_gtc = GTC.dof(y)
    if math.isinf(nu_gtc):
        assert math.isinf(ours.effective_dof())
    else:
        assert ours.effective_dof() == pytest.approx(nu_gtc, rel=1e-9)


def test_metadata_round_trip_and_errors():
    meta = CertificateMetadata.from_dict({
        "certificate_number": "AB-2026-0007", "customer_name": "北京精密机械 & Co <b>",
        "standards": [{"description": "Polygon 24", "uncertainty": "0,25", "basis": "U95"}],
        "temperature_c": 20.1, "calibration_date": "2026-11-24", "unknown": 1})
    assert meta.standards[0].uncertainty == 0.25
    assert CertificateMetadata.from_dict(meta.to_dict()) == meta
    assert "customer" not in meta.missing_fields() and "operator" in meta.missing_fields()
    with pytest.raises(MetadataError, match="calibration_date"):
        CertificateMetadata.from_dict({"calibration_date": "24.11.2026"})
    with pytest.raises(MetadataError, match=r"standards\[1\].basis"):
        CertificateMetadata.from_dict({"standards": [{"basis": "k=3"}]})
    with pytest.raises(MetadataError, match="humidity"):
        CertificateMetadata.from_dict({"humidity_pct": 130})


def test_lab_defaults_fill_only_empty_fields():
    lab = CertificateMetadata(lab_name="Lab", operator="Li", standards=(ReferenceStandard("AC"),))
    meta = CertificateMetadata(operator="Wang").with_lab_defaults(lab.lab_defaults())
    assert meta.lab_name == "Lab" and meta.operator == "Wang" and meta.standards[0].description == "AC"


@given(st.text(max_size=400))
def test_clean_text_never_keeps_control_characters(text):
    """A field is printed whole or refused naming it (#40: never cut or stripped silently)."""
    try:
        out = clean_text(text, "x")
    except MetadataError as exc:
        assert "'x'" in str(exc)
        return
    assert len(out) <= 200
    assert not any(ord(ch) < 32 or 0x7F <= ord(ch) <= 0x9F for ch in out)
    assert "\u202e" not in out


def test_certificate_number_scheme():
    day = dt.date(2026, 3, 5)
    assert format_certificate_number("AB-{year}-{seq:04d}", 7, day) == "AB-2026-0007"
    assert format_certificate_number("{year}{month}{day}/{seq}", 12, day) == "20260305/12"
    assert format_certificate_number("X-{other}", 1, day) == "X-{other}"


def _flat_budget(points: int, expanded: float) -> UncertaintyBudget:
    """A budget whose every point has U = ``expanded`` (k = 2, ν = ∞)."""
    return UncertaintyBudget((BudgetComponent("u", "B", "normal", expanded, 2.0, 1.0, math.inf),),
                             points)


@pytest.mark.parametrize("x, rule, verdict", [
    (0.5, "guarded", "pass"),
    (0.8, "guarded", "conditional pass"),
    (1.2, "guarded", "conditional fail"),
    (1.4, "guarded", "fail"),
    (0.6, "guarded_binary", "pass"),
    (0.8, "guarded_binary", "fail"),
    (0.8, "simple", "pass"),
    (1.2, "simple", "fail"),
])
def test_decision_rules_on_every_point(x, rule, verdict):
    """ILAC-G8:09/2019 4.2.1–4.2.3 with w = U = 0.3", the worst point deciding."""
    errors = np.array([0.0, -x, 0.2])
    c = decide_conformity(errors, _flat_budget(3, 0.3), 1.0, rule, "points")
    assert c.verdict == verdict
    assert "ILAC-G8:09/2019, 4.2." in c.rule
    assert c.value == pytest.approx(-x) and c.expanded == pytest.approx(0.3)  # signed
    assert "the deciding point is point 2:" in c.statement


def test_guarded_rule_prints_the_four_zones_of_4_2_3():
    c = decide_conformity(np.array([0.0, 0.5]), _flat_budget(2, 0.3), 1.0, "guarded", "points")
    assert c.zones.endswith("pass ≤ 0.70\" (T − w) < conditional pass ≤ 1\" (T) < conditional "
                            "fail ≤ 1.30\" (T + w) < fail")
    assert "4.2.3" in c.rule


def test_half_range_interval_reaches_down_to_what_noise_explains():
    """A perfect axis measured with 0.5" noise: the range of noisy points runs high.

    41 points of pure noise have a half range near 1.1" whatever the truth. The value is
    the measured half range less the median excess the noise gives it on the measured
    curve; the interval reaches down to 0, as noise explains all of it, and up by the
    lower tail of that excess — less than what one pair of readings can hide (2σ·√2/2 =
    0.71" for k = 2) above the measured half range, the range of 41 noisy points being
    above its true value nearly always — so the axis passes ±2"."""
    rng = np.random.default_rng(1)
    truth = np.zeros(41)
    noisy = truth + rng.normal(0.0, 0.5, 41)
    budget = UncertaintyBudget((BudgetComponent("noise", "A", "normal", 0.5, 1.0, 1.0, math.inf),),
                               41)
    c = decide_conformity(noisy, budget, 2.0, "guarded", "half_range")
    mc = c.monte_carlo
    assert mc.measured == pytest.approx(0.5 * np.ptp(noisy))
    assert c.value == mc.value == pytest.approx(mc.measured - mc.bias)
    assert 0.0 < mc.bias < mc.measured  # noise widens the range; the value is not zero
    assert mc.interval_low == 0.0  # noise explains it all
    assert mc.value <= mc.interval_high < mc.measured + 0.5 * 2.09 * 0.5 * math.sqrt(2.0)
    assert c.verdict == "pass"
    again = decide_conformity(noisy, budget, 2.0, "guarded", "half_range")
    assert again.value == c.value and again.monte_carlo == mc  # seeded from the readings


def test_half_range_well_above_the_noise_is_never_decided_near_zero():
    """The bundled theodolite sample's defect: a measured half range well above the noise
    was decided as 0.0". Now the value and the interval's lower end stay well above 0, the
    value within the noise's reach of the measured half range."""
    theta = np.linspace(0.0, 2.0 * np.pi, 36, endpoint=False)
    truth = 1.3 * np.sin(theta)
    budget = UncertaintyBudget((BudgetComponent("noise", "A", "normal", 0.2, 1.0, 1.0, 33),), 36)
    noisy = truth + np.random.default_rng(2).normal(0.0, 0.2, 36)
    mc = half_range_monte_carlo(noisy, budget)
    assert mc.measured == pytest.approx(0.5 * np.ptp(noisy))
    assert mc.measured - 2 * 0.2 < mc.value <= mc.measured
    assert 0.8 < mc.interval_low < 1.3 < mc.interval_high < 1.9


@pytest.mark.slow
def test_half_range_interval_covers_over_repeats():
    """The seed's theodolite experiment, 41 points, 0.5" noise, a curve of true half
    range 0.991": the measured half range averages 1.67" (biased high); the interval covers
    the truth at least as often as stated."""
    theta = np.arange(-20.0, 21.0, 1.0)
    truth = 0.991 * np.sin(np.radians(theta) * 9)
    budget = UncertaintyBudget((BudgetComponent("noise", "A", "normal", 0.5, 1.0, 1.0, math.inf),),
                               theta.size)
    rng = np.random.default_rng(7)
    measured, covered = [], 0
    for _ in range(60):
        mc = half_range_monte_carlo(truth + rng.normal(0, 0.5, theta.size), budget, trials=2000)
        measured.append(mc.measured)
        covered += mc.interval_low <= 0.5 * np.ptp(truth) <= mc.interval_high
    assert np.mean(measured) == pytest.approx(1.67, abs=0.12)
    assert covered >= 56  # of 60: binomial at 95.45 % gives fewer than 56 in 2.6 % of runs


def test_no_tolerance_or_invalid_run_gives_no_statement():
    budget = _flat_budget(2, 0.1)
    assert decide_conformity([0.0, 0.1], budget, None).verdict == "not assessed"
    c = decide_conformity([0.0, 0.1], budget, 1.0, invalid_reason="the closure failed")
    assert c.verdict == "not assessed" and "closure" in c.statement
