"""The GUM budget, the metadata and the decision rules."""

from __future__ import annotations

import datetime as dt
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.certificate_metadata import (
    CertificateMetadata,
    MetadataError,
    ReferenceStandard,
    clean_text,
    format_certificate_number,
)
from models.conformity import decide_conformity
from models.uncertainty_budget import BudgetComponent, UncertaintyBudget, divisor_for_basis

GTC = pytest.importorskip("GTC")


def test_budget_hand_figures():
    budget = UncertaintyBudget((
        BudgetComponent("std", "B", "normal", 0.6, 2.0, math.sqrt(2), math.inf),
        BudgetComponent("mpe", "B", "rectangular", 0.3 * math.sqrt(3), math.sqrt(3), 1.0, math.inf),
        BudgetComponent("noise", "A", "normal", np.array([0.0, 0.4]), 1.0, 1.0, 9),
    ), points=2)
    # point 1: (0.3·√2)² + 0.3² = 0.27; point 2: + 0.16
    assert budget.combined_arcsec == pytest.approx([math.sqrt(0.27), math.sqrt(0.43)])
    assert budget.expanded_arcsec[1] == pytest.approx(2 * math.sqrt(0.43))
    assert budget.worst_index == 1
    # Welch–Satterthwaite: 0.43² / (0.4⁴ / 9)
    assert budget.effective_dof() == pytest.approx(0.43**2 / (0.4**4 / 9))
    rows = budget.table()
    assert [r["name"] for r in rows] == ["std", "mpe", "noise"]
    assert sum(r["share"] for r in rows) == pytest.approx(1.0)
    assert budget.coverage_probability(0) == pytest.approx(0.9545, abs=1e-4)


def test_divisors():
    assert divisor_for_basis("U95") == (2.0, "normal")
    assert divisor_for_basis("MPE")[0] == pytest.approx(math.sqrt(3))
    with pytest.raises(ValueError, match="basis"):
        divisor_for_basis("k3")


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(0.01, 5.0), st.floats(-3.0, 3.0).filter(lambda c: abs(c) > 0.01),
                          st.sampled_from([math.inf, 2, 5, 30])), min_size=1, max_size=6))
def test_budget_agrees_with_gtc(inputs):
    """The root sum of squares and ν_eff agree with the GUM Tree Calculator."""
    components = tuple(BudgetComponent(f"x{i}", "A", "normal", u, 1.0, c, nu)
                       for i, (u, c, nu) in enumerate(inputs))
    ours = UncertaintyBudget(components, 1)
    y = sum(c * GTC.ureal(1.0, u, nu) for u, c, nu in inputs)
    assert ours.combined_arcsec[0] == pytest.approx(GTC.uncertainty(y), rel=1e-9)
    nu_gtc = GTC.dof(y)
    if math.isinf(nu_gtc):
        assert math.isinf(ours.effective_dof())
    else:
        assert ours.effective_dof() == pytest.approx(nu_gtc, rel=1e-9)


def test_metadata_round_trip_and_errors():
    meta = CertificateMetadata.from_dict({
        "certificate_number": "AB-2026-0007", "customer_name": "北京精密机械 & Co <b>",
        "standards": [{"description": "Polygon 24", "uncertainty_arcsec": "0,25", "basis": "U95"}],
        "temperature_c": 20.1, "calibration_date": "2026-11-24", "unknown": 1})
    assert meta.standards[0].uncertainty_arcsec == 0.25
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
    out = clean_text(text, "x")
    assert len(out) <= 200
    assert not any(ord(ch) < 32 or 0x7F <= ord(ch) <= 0x9F for ch in out)
    assert "\u202e" not in out


def test_certificate_number_scheme():
    day = dt.date(2026, 3, 5)
    assert format_certificate_number("AB-{year}-{seq:04d}", 7, day) == "AB-2026-0007"
    assert format_certificate_number("{year}{month}{day}/{seq}", 12, day) == "20260305/12"
    assert format_certificate_number("X-{other}", 1, day) == "X-{other}"


@pytest.mark.parametrize("x, u, rule, verdict", [
    (0.5, 0.3, "guarded", "conforms"),
    (0.8, 0.3, "guarded", "no statement"),
    (1.2, 0.3, "guarded", "no statement"),
    (1.4, 0.3, "guarded", "does not conform"),
    (0.8, 0.3, "simple", "conforms"),
    (1.2, 0.3, "simple", "does not conform"),
])
def test_decision_rules(x, u, rule, verdict):
    c = decide_conformity(x, u, 1.0, rule)
    assert c.verdict == verdict
    assert "ILAC-G8" in c.rule


def test_no_tolerance_or_invalid_run_gives_no_statement():
    assert decide_conformity(0.1, 0.1, None).verdict == "not assessed"
    assert "closure" in decide_conformity(0.1, 0.1, 1.0, valid=False).statement
