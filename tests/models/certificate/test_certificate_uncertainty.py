"""The uncertainty content of the certificates (issue 29, second review): ν_eff truncated,
the set-up parameters' k, one estimate counted once, the deciding point named, U ≥ T, the
asymmetric interval, and the theodolite set-up parameters defined against independent rigs.
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from models.certificate.document import budget_table, decision_rows
from models.certificate.metadata import CertificateMetadata, ReferenceStandard
from models.certificate.withheld import UncertaintyWithheld
from models.readings.sheet import ReadingsSheet
from models.theodolite.model import analyze_run
from models.theodolite.report import theodolite_budget, theodolite_certificate
from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.conformity import decide_conformity, significant_decimals
from models.validation.theodolite_rig import theodolite_readings
from tests.models.certificate.test_certificate_statements import FRINGE_INPUTS, _flat, _sample

GTC = pytest.importorskip("GTC")

POSITIONING_INPUTS = {"misalignment_u": 0.1, "reference_resolution": 0.1, "temperature_u": 0.1}

META = CertificateMetadata.from_dict({
    "certificate_number": "AB-2026-0100", "lab_name": "Angle Lab", "customer_name": "Customer",
    "item_description": "Axis", "item_serial": "SN-1", "calibration_date": "2026-11-20",
    "operator": "Wang",
    "standards": [{"description": "Theodolite", "certificate_no": "NIM-1",
                   "uncertainty": 0.5, "basis": "u"}]})
#: the fringe's phase reference: its certificate listed, its u stated in the settings
PHASE_REFERENCE = ReferenceStandard("Reference angle encoder (phase of each sample)", "RE-2",
                                    "NIM-2026-0999", role="reference")


def _line(table, label: str) -> list[str]:
    """The budget table's line whose first cell starts with ``label`` (the combined u, the
    expanded U, and since assessment 72 L6 the U stated, rounded up, below them)."""
    found = [[str(c) for c in row] for row in table.rows if str(row[0]).startswith(label)]
    assert len(found) == 1, [str(row[0]) for row in table.rows]
    return found[0]


# 10. ν_eff truncated to the lower integer before t is taken (GUM G.6.4) -------------------
def test_effective_dof_is_truncated_before_t():
    """ν_eff = 8·(1 + b²)² = 8.6 for u_A = 1 (ν = 8) and u_B = b: GUM G.6.4 takes ν = 8,
    k = 2.37 (Table G.2, 95.45 %), where the untruncated 8.6 gives 2.34 (printed "9")."""
    b = math.sqrt(math.sqrt(8.6 / 8.0) - 1.0)
    budget = UncertaintyBudget((BudgetComponent("a", "A", "normal", 1.0, 1.0, 1.0, 8),
                                BudgetComponent("b", "B", "normal", b, 1.0, 1.0, math.inf)), 1)
    # GTC: the same two inputs, its Welch–Satterthwaite, then its k for the integer below
    y = GTC.ureal(0, 1.0, 8) + GTC.ureal(0, b)
    assert budget.effective_dof() == pytest.approx(GTC.dof(y)) == pytest.approx(8.6)
    assert budget.truncated_dof() == 8
    k_gtc = GTC.reporting.k_factor(8, 100 * math.erf(math.sqrt(2)))
    assert budget.coverage_factor == pytest.approx(k_gtc) == pytest.approx(2.37, abs=0.005)
    assert GTC.reporting.k_factor(8.6, 100 * math.erf(math.sqrt(2))) < 2.35  # what it was
    table = budget_table(budget, "x")
    combined, expanded = _line(table, "Combined standard"), _line(table, "Expanded uncertainty k·u_c (k")
    assert combined[-1] == "8" and "k = 2.37" in expanded[0]
    assert "8.60" in str(table.note) and "G.6.4" in str(table.note)


def test_a_large_dof_is_said_alike_in_the_budgets_line_and_its_note():
    """ν = 10⁸ (a Type A input of 10⁸ degrees of freedom beside Type B inputs): the table's
    line says "≥ 10⁴", and so does the note (day review 66 F8: it said "ν = 1.0×10⁸ …
    (Welch–Satterthwaite: 1.0×10⁸)")."""
    budget = UncertaintyBudget((BudgetComponent("a", "A", "normal", 0.1, 1.0, 1.0, 1e8),
                                BudgetComponent("b", "B", "normal", 0.5, 1.0, 1.0, math.inf)), 1)
    table = budget_table(budget, "x")
    assert _line(table, "Combined standard")[-1] == "≥ 10⁴"
    note = str(table.note)
    assert "ν ≥ 10⁴" in note and "×10" not in note, note
    assert "k = 2.00" in note


def test_an_integer_dof_is_not_truncated_below_itself():
    budget = UncertaintyBudget((BudgetComponent("a", "A", "normal", 1.0, 1.0, 1.0, 9),), 1)
    assert budget.truncated_dof() == 9 and budget.coverage_factor == pytest.approx(2.32, abs=0.005)


# 12. one standard deviation, two readings ---------------------------------------------------
def test_one_estimate_entering_twice_counts_once_for_nu():
    """The point's reading and the reference reading are two readings (two independent
    errors, so u² adds 2s²) but one estimate s with ν: Welch–Satterthwaite by hand gives
    ν_eff = (2s² + b²)² / ((2s²)² / ν), not the (2s² + b²)² / (2 s⁴ / ν) of two estimates."""
    s, nu, b = 0.498, 20, 0.25
    grouped = UncertaintyBudget((
        BudgetComponent("repeat", "A", "normal", s, 1.0, 1.0, nu, dof_group="s"),
        BudgetComponent("reference", "A", "normal", s, 1.0, 1.0, nu, common=True, dof_group="s"),
        BudgetComponent("standard", "B", "normal", b, 1.0, 1.0, math.inf)), 1)
    apart = UncertaintyBudget(tuple(replace(c, dof_group="") for c in grouped.components), 1)
    u2 = 2 * s**2 + b**2
    assert grouped.combined[0] == pytest.approx(math.sqrt(u2))
    assert grouped.effective_dof() == pytest.approx(u2**2 / ((2 * s**2) ** 2 / nu))  # 25.9
    assert apart.effective_dof() == pytest.approx(u2**2 / (2 * s**4 / nu))  # 51.8: doubled
    # GTC: one input of u = √2·s with ν gives the same ν_eff
    y = GTC.ureal(0, math.sqrt(2) * s, nu) + GTC.ureal(0, b)
    assert grouped.effective_dof() == pytest.approx(GTC.dof(y))


def test_theodolite_budget_counts_its_reading_error_once():
    """The reading error at the point and at θ₀: one estimate (the larger of s and the
    standard's u), so one input for ν_eff; the standard has no line of its own (issue 39)."""
    _, result = _sample("theodolite")
    for u in (0.5, 0.05):  # the sample's standard governs (0.5″ > s); s governs (Type A)
        meta = replace(META, standards=(replace(META.standards[0], uncertainty=u),))
        budget = theodolite_budget(result, meta)
        rows = budget.table()
        names = [r["name"] for r in rows]
        assert "Theodolite" not in names
        repeat = [r for r in rows if r["name"] in ("Reading error (pointing)",
                                                   "Reference reading (θ₀)")]
        assert len(repeat) == 2 and repeat[0]["u"] == repeat[1]["u"]
        nu = repeat[0]["dof"]
        assert (nu == math.inf) == (u == 0.5)
        i = budget.worst_index
        contrib = budget.contributions()[:, i]
        model = contrib[names.index("Set-up model ζ (ψ, α, β)")]
        model_nu = rows[names.index("Set-up model ζ (ψ, α, β)")]["dof"]
        group = repeat[0]["contribution"] ** 2 + repeat[1]["contribution"] ** 2
        hand = float(np.sum(contrib**2)) ** 2 / (group**2 / nu + model**4 / model_nu)
        assert budget.effective_dof() == pytest.approx(hand)


# 11. set-up parameters: k from their own ν ----------------------------------------------------
def test_theodolite_setup_parameters_take_k_from_their_own_dof():
    _, result = _sample("theodolite")
    document = theodolite_certificate(result, META)
    nu = result.theta_deg.size - 3
    k = GTC.reporting.k_factor(nu, 100 * math.erf(math.sqrt(2)))
    assert document.parameters.header[2] == f"U (k = {k:.2f}, ν = {nu})"
    u_psi = result.identification.uncertainty_deg[0]
    # U to two significant digits (GUM 7.2.6; three were printed before issue 39), rounded
    # up as every printed U (issue 39, "conformity you can defend"), in the value's degrees
    # (assessment 78 L3: "5.8263°" beside "6.4″", a U finer than the value's place)
    printed = document.parameters.rows[0][2]
    decimals = significant_decimals(k * u_psi)
    assert printed == f"{math.ceil(k * u_psi * 10**decimals - 1e-9) / 10**decimals:.{decimals}f}°"


# 13. the deciding point named as the results table names it ----------------------------------
@pytest.mark.parametrize("key", ["theodolite", "polygon", "positioning", "fringe"])
def test_deciding_point_is_named_as_in_the_results_table(key):
    settings = {"samples_per_period": 64, **FRINGE_INPUTS} if key == "fringe" else None
    if key == "positioning":  # every input stated: an incomplete U makes no statement
        settings = POSITIONING_INPUTS
    kind, result = _sample(key, settings)
    tolerance = 1000.0 if key != "polygon" else None
    meta = replace(META, decision_quantity="points", tolerance=tolerance)
    # every standard that carries the measurand listed (a statement is made on traceable
    # results only, assessment 70 H2): the polygon and the autocollimator; the fringe's
    # phase reference, its u stated in the settings
    if key == "polygon":  # its tolerance is the grade's (±1")
        meta = replace(meta, tolerance=None,
                       standards=(replace(META.standards[0], uncertainty=0.1),
                                  replace(META.standards[0], description="Autocollimator",
                                          uncertainty=0.1)))
    if key == "fringe":
        meta = replace(meta, standards=(*meta.standards, PHASE_REFERENCE))
    document = kind.certificate_document(result, meta)
    statement = str(document.conformity.statement)
    assert "number " not in statement
    named = statement.split("the deciding point is ")[1].split(":")[0]
    first = {"theodolite": lambda r: f"θ = {r[0]}°", "polygon": lambda r: f"position {r[0]}",
             "positioning": lambda r: f"target {r[0]}", "fringe": lambda r: f"sample {r[0]}"}
    shown = [first[key](row) for row in document.results.rows]
    assert any(named.startswith(s) for s in shown), (named, shown[:3])


# 14. U ≥ T: no statement of conformity is possible -----------------------------------------
@pytest.mark.parametrize("quantity", ["points", "half_range"])
def test_u_not_below_t_gives_no_statement(quantity):
    budget = UncertaintyBudget((BudgetComponent("u", "B", "normal", 1.0, 1.0, 1.0, math.inf),), 12)
    # a flat curve read with the noise the budget states (σ = 1"): its half range may all be
    # noise, so the interval reaches down to 0 from about 1.5", and U ≥ 0.6" = T
    errors = 0.05 * np.sin(np.arange(12) * math.pi / 6) + np.random.default_rng(14).normal(
        0.0, 1.0, 12)
    c = decide_conformity(errors, budget, 0.6, "guarded", quantity)
    assert c.verdict == "not assessed" and c.conforms is None
    assert "No statement of conformity is possible" in c.statement
    assert "T = 0.6\"" in c.statement and not c.zones
    smaller = decide_conformity(errors, budget, 9.0, "guarded", quantity)
    assert smaller.verdict == "pass"


# 9. an asymmetric interval printed as such ---------------------------------------------------
def test_asymmetric_half_range_interval_is_printed_as_such():
    rng = np.random.default_rng(4)
    budget = UncertaintyBudget((BudgetComponent("noise", "A", "normal", 0.3, 1.0, 1.0, 30),), 36)
    errors = 0.5 * np.sin(np.radians(np.arange(36) * 10.0)) + rng.normal(0, 0.3, 36)
    c = decide_conformity(errors, budget, 3.0, "guarded", "half_range")
    mc = c.monte_carlo
    assert mc.u_upper != pytest.approx(mc.u_lower, rel=0.02)
    assert c.expanded_lower == mc.u_lower and c.expanded == mc.u_upper
    row = decision_rows(c, budget, "points")[0][1]
    d = 2 if min(mc.u_lower, mc.u_upper) >= 0.1 else 3
    # each U rounded up, and at least the printed value to its end rounded outward, so that
    # value ± U is the printed interval (assessment 70 M1)
    step = 10.0 ** -d
    value = round(mc.value, d)
    minus = max(math.ceil(mc.u_lower / step - 1e-9) * step,
                value - math.floor((mc.value - mc.u_lower) / step + 1e-9) * step)
    plus = max(math.ceil(mc.u_upper / step - 1e-9) * step,
               math.ceil((mc.value + mc.u_upper) / step - 1e-9) * step - value)
    assert f"−{minus:.{d}f}\"/+{plus:.{d}f}\"" in row and "±" not in row
    assert f"−{minus:.{d}f}\"/+{plus:.{d}f}\"" in c.statement
    assert f"{value - minus:.{d}f}\" … {value + plus:.{d}f}\"" in c.statement


# 17. α and β as the certificate defines them, against two independent rigs -------------------
def _rotate(v, axis, phi):
    k = axis / np.linalg.norm(axis)
    return v * math.cos(phi) + np.cross(k, v) * math.sin(phi) + k * (k @ v) * (1 - math.cos(phi))


def _rig_with_z_up(theta_deg, psi_deg, lean_azimuth_deg, normal_elevation_deg):
    """The set-up as the certificate words it, in a frame of its own (X the azimuth zero, Z
    up, Y = Z × X): the axis' upper end leans by ψ toward the azimuth counted clockwise seen
    from above; the axis turns clockwise seen from above for increasing θ; the mirror normal
    is elevated above the horizontal. Returns the azimuth (clockwise) and the elevation
    (positive up) of the normal."""
    psi, a, e = np.radians([psi_deg, lean_azimuth_deg, normal_elevation_deg])
    upper = np.array([math.sin(psi) * math.cos(a), -math.sin(psi) * math.sin(a), math.cos(psi)])
    normal = np.array([math.cos(e), 0.0, math.sin(e)])
    out = np.array([_rotate(normal, upper, -t) for t in np.radians(theta_deg)])
    return np.degrees(np.arctan2(-out[:, 1], out[:, 0])), np.degrees(np.arcsin(out[:, 2]))


@pytest.mark.parametrize("alpha", [30.0, 120.0, 210.0, 330.0])
@pytest.mark.parametrize("beta", [1.5, -1.5])
def test_alpha_and_beta_as_defined_on_the_certificate(alpha, beta):
    theta = np.arange(-30.0, 30.1, 2.0)
    # the rig of ../shared/SPEC.md (models/validation): its α and β are recovered as they were set
    azimuth, elevation = theodolite_readings(theta, 2.0, alpha, beta)
    s = analyze_run(theta, azimuth, elevation).identification.setup
    assert (s.psi_deg, s.alpha_deg, s.beta_deg) == pytest.approx((2.0, alpha, beta), abs=1e-7)
    # the rig of the certificate's words: E entered positive downward gives α and β as worded
    azimuth, up = _rig_with_z_up(theta, 2.0, alpha, beta)
    result = analyze_run(theta, azimuth, -up)
    s = result.identification.setup
    assert (s.psi_deg, s.alpha_deg, s.beta_deg) == pytest.approx((2.0, alpha, beta), abs=1e-7)
    assert np.max(np.abs(result.corrected_error_arcsec)) < 1e-6
    # elevations entered positive upward: α + 180°, −β, the same corrected errors (the
    # assessor's rig: a definition, not a bug)
    mirrored = analyze_run(theta, azimuth, up)
    m = mirrored.identification.setup
    assert m.alpha_deg == pytest.approx((alpha + 180.0) % 360.0, abs=1e-7)
    assert m.beta_deg == pytest.approx(-beta, abs=1e-7)
    np.testing.assert_allclose(mirrored.corrected_error_arcsec, result.corrected_error_arcsec,
                               atol=1e-6)


def test_the_certificate_defines_alpha_and_beta():
    _, result = _sample("theodolite")
    statements = " ".join(str(s) for s in theodolite_certificate(result, META).statements)
    for words in ("clockwise seen from above", "toward which the axis' upper end leans",
                  "elevation of the mirror normal above the horizontal",
                  "positive below the horizontal", "α + 180° and −β"):
        assert words in statements


# 1. the fringe certificate's traceability ----------------------------------------------------
@pytest.mark.slow
def test_fringe_without_stated_inputs_is_not_traceable_and_not_judged():
    kind, result = _sample("fringe", {"samples_per_period": 64})
    meta = replace(META, tolerance=0.5, standards=(
        replace(META.standards[0], description="Data acquisition (16-bit ADC)",
                uncertainty=None),))
    document = kind.certificate_document(result, meta)
    assert document.conformity.verdict == "not assessed"
    assert "not traceable" in document.conformity.statement
    flat = _flat(document)
    assert "traceable to the SI unit" not in flat
    assert "Metrological traceability: not established for these results" in flat
    assert "the phase reference (the sampling's uniformity (the timing of the samples)) has no " \
           "stated uncertainty" in flat
    assert "no stated uncertainty for the ADC's quantisation, offset, gain, linearity" in flat
    assert "Data acquisition (16-bit ADC): no uncertainty stated" in flat


@pytest.mark.slow
def test_fringe_stated_inputs_enter_the_budget_by_hand():
    """Per sample: the phase reference u·P/360; an offset u_o of either channel moves the
    phase by u_o/R (rad), a gain ratio u_g by |S C|/R² u_g, the LSB q by q/√12/R, a
    linearity limit a by a/√3/R; R from the measured signals about their mean."""
    kind, result = _sample("fringe", {"samples_per_period": 64, **FRINGE_INPUTS})
    # issue 39: traceable only with the phase reference listed too (its u in the settings)
    document = kind.certificate_document(result, replace(META, tolerance=0.5, standards=(
        replace(META.standards[0], description="Data acquisition (16-bit ADC)",
                uncertainty=0.005, basis="U95"), PHASE_REFERENCE)))
    assert not document.untraceable and document.conformity.verdict != "not assessed"
    budget = document.budget
    names = [c.name for c in budget.components]
    u = {name: budget.components[names.index(name)].standard_uncertainty(budget.points)
         for name in ("Phase reference", "ADC quantisation", "ADC offset", "ADC gain ratio",
                      "ADC linearity")}
    period = 1296000.0 / 16384  # "
    to_unit = period / (2 * math.pi)
    s = result.u_sin - result.u_sin.mean()
    c = result.u_cos - result.u_cos.mean()
    r = np.hypot(s, c)
    assert u["Phase reference"] == pytest.approx(0.01 / 360 * period)  # 0.0022"
    np.testing.assert_allclose(u["ADC offset"], 0.5e-3 / r * to_unit, rtol=0.02)
    np.testing.assert_allclose(u["ADC quantisation"], 0.3e-3 / math.sqrt(12) / r * to_unit,
                               rtol=0.02)
    np.testing.assert_allclose(u["ADC linearity"], 0.6e-3 / math.sqrt(3) / r * to_unit,
                               rtol=0.02)
    gain = np.abs(s * c) / r**2 * 2e-4 * to_unit  # peak 2e-4/2 · to_unit = 1.26e-3"
    assert float(np.max(gain)) == pytest.approx(1e-4 * to_unit, rel=0.03)
    np.testing.assert_allclose(u["ADC gain ratio"], gain, atol=0.05 * float(np.max(gain)))
    flat = _flat(document)
    assert "traceable to the SI unit of plane angle" in flat


def test_fringe_prints_every_sample_and_its_extreme():
    kind, result = _sample("fringe", {"samples_per_period": 64, **FRINGE_INPUTS})
    document = kind.certificate_document(result, META)
    rows = document.results.rows
    assert len(rows) == result.raw_error.size == 512
    lowest = int(np.argmin(result.raw_error))
    # printed to the decimal of its U (GUM 7.2.6; issue 39: three decimals whatever U was)
    d = significant_decimals(float(document.budget.expanded[lowest]))
    assert rows[lowest][0] == f"{lowest + 1}" and rows[lowest][2] == f"{result.raw_error[lowest]:+.{d}f}"
    # U beside its figure rounded up, the figure ± U holding the computed interval (issue 39:
    # the U a point is decided with), one digit above U rounded up at most
    big, shown, step = float(document.budget.expanded[lowest]), float(rows[lowest][5]), 10.0**-d
    value, low_digits = float(rows[lowest][2]), f"{shown:.{d}f}" == rows[lowest][5]
    assert low_digits and big <= shown < big + 2 * step
    assert value - shown <= result.raw_error[lowest] - big + 1e-12
    assert value + shown >= result.raw_error[lowest] + big - 1e-12


# 6. the positioning figures with their U ---------------------------------------------------
def test_axis_figures_of_the_measured_statistics_are_the_evaluated_ones():
    """The vectorised figures of the Monte Carlo, fed the measured means and s, give the
    ISO 230-2 and VDI/DGQ 3441 figures of the evaluation."""
    from models.positioning.report import axis_figures

    _, result = _sample("positioning")
    stats = {name: (st.mean[None, :], st.std[None, :])
             for name, _, st in result.directions_present()}
    figures = axis_figures(stats)
    for key, value in result.iso.figures.items():
        assert figures[key][0] == pytest.approx(value, abs=1e-12), key
    for key, value in result.vdi.as_dict().items():
        assert figures[key][0] == pytest.approx(value, abs=1e-12), key


def test_positioning_figures_carry_their_interval():
    """B̄ = mean of the reversals x̄↑ − x̄↓ over m targets: a reference's error at a target is
    the same both ways and cancels, so by hand U(B̄) = 2 √(Σ (s↑² + s↓²)/n) / m from the
    scatter alone (the earlier Monte Carlo drew the reference once per direction, a reversal
    the reference does not have — #39); the bootstrap's interval agrees, up to a third wider
    (each target's scatter the larger of its own s and the moderated σ: on the safe side).
    Every other figure has an interval, printed with its probability on the certificate."""
    from models.positioning.report import figure_uncertainties, positioning_budget

    _, result = _sample("positioning")
    budget = positioning_budget(result, META)
    intervals = figure_uncertainties(result, budget)
    m = result.positions.size
    up, down = result.iso.forward, result.iso.backward
    hand = 2.0 * math.sqrt(float(np.sum(up.std**2 / up.runs + down.std**2 / down.runs))) / m
    b_mean = intervals["B_mean"]
    assert 0.9 * hand < b_mean.value - b_mean.low < 1.35 * hand
    assert 0.9 * hand < b_mean.high - b_mean.value < 1.35 * hand
    for key in ("A", "R", "E", "M", "B", "B_mean", "P"):
        assert key in intervals and intervals[key].high > intervals[key].low
    # E is a range of means: its interval at least one mean's U wide
    assert intervals["E"].high - intervals["E"].low > 2.0 * float(np.min(budget.combined))
    kind, _ = _sample("positioning")
    document = kind.certificate_document(result, META)
    assert len(document.statistics.header) == 5
    rows = {row[0].split(":")[0]: row for row in document.statistics.rows}
    for key in ("A", "R", "E", "M", "B", "P"):
        assert " … " in rows[key][2] and rows[key][3].endswith(" %"), key
    ends = [v.rstrip('"') for v in rows["R"][2].split(" … ")]
    low, high = (float(v) for v in ends)
    # the ends to the decimal of the interval's half-width (GUM 7.2.6: two significant digits
    # of it; R's, some 12″ since its chi-square bounds (0.8.16), to 1″), each rounded
    # outwards (the printed interval holds the computed one)
    step = 10.0 ** -(len(ends[0].split(".")[1]) if "." in ends[0] else 0)
    half = 0.5 * (intervals["R"].high - intervals["R"].low)
    assert step == (1.0 if half >= 10 else 0.1 if half >= 1 else 0.01)
    assert intervals["R"].low - step < low <= intervals["R"].low + 1e-9
    assert intervals["R"].high - 1e-9 <= high < intervals["R"].high + step


def test_positioning_states_its_inputs_and_the_test_conditions():
    kind, result = _sample("positioning", {"misalignment_u": 0.3, "reference_resolution": 0.1,
                                          "temperature_u": 0.2, "axis_temperature_c": 20.3,
                                          "axis_setup": "calibrator on the table centre"})
    settings = {"misalignment_u": 0.3, "reference_resolution": 0.1, "temperature_u": 0.2,
                "axis_temperature_c": 20.3, "axis_setup": "calibrator on the table centre"}
    document = kind.certificate_document(result, META, settings=settings)
    rows = {r["name"]: r for r in document.budget.table()}
    assert rows["Misalignment of the reference"]["u"] == pytest.approx(0.3)
    assert rows["Resolution of the reference"]["u"] == pytest.approx(0.1 / math.sqrt(12))
    assert rows["Temperature"]["u"] == pytest.approx(0.2)
    listed = dict(document.settings)
    assert "calibrator on the table centre" in listed.values()
    assert any("20.3" in v for v in listed.values())
    statements = " ".join(str(s) for s in document.statements)
    assert "Inputs not stated" not in statements and "sensitivity 1" in statements
    bare = kind.certificate_document(_sample("positioning")[1], META)
    assert not document.not_in_u_statement
    # said once, under the budget (CertificateDocument.not_in_u), not among the statements
    assert "Inputs not stated, so not in U: Misalignment of the reference, Resolution of the " \
           "reference, Temperature" in str(bare.not_in_u_statement)
    assert "Inputs not stated" not in " ".join(str(s) for s in bare.statements)


# 20. advice marked as opinion ---------------------------------------------------------------
def test_advice_is_marked_as_opinion():
    kind, result = _sample("positioning")
    statements = [str(s) for s in kind.certificate_document(result, META).statements]
    advice = [s for s in statements if "controller" in s]
    assert advice and all(s.startswith("Opinion and interpretation (ISO/IEC 17025 7.8.7)")
                          for s in advice)


# 19. polygon: what covers the repeatability when it is not evaluated -------------------------
def test_polygon_says_what_covers_an_unevaluated_repeatability():
    from models.polygon.analysis import POLYGON
    from models.validation.polygon_rig import PolygonRig

    rig = PolygonRig(8, 0.3 * np.sin(np.radians(np.arange(8) * 45.0)), psi_arcsec=200.0,
                     omega_deg=40.0, noise_arcsec=0.1, rng=np.random.default_rng(8))
    result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rig.set_rows()).parse(),
                             {"grade": 4, "ac_roll_arcmin": 0.0})
    assert result.repeatability_arcsec is None  # one set
    # one set: the tilt fit gives the autocollimator's noise with the faces' own pyramidal
    # errors, never the encoder's (audit s67): no U unless the σ of a reading is stated
    # (issue 39, tests/models/polygon/test_polygon_one_set_withheld.py)
    with pytest.raises(UncertaintyWithheld, match="reading_noise_arcsec"):
        POLYGON.certificate_document(result, replace(META, tolerance=None))
    stated = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rig.set_rows()).parse(),
                             {"grade": 4, "ac_roll_arcmin": 0.0, "reading_noise_arcsec": 0.12})
    document = POLYGON.certificate_document(stated, replace(META, tolerance=None))
    rows = [r for r in document.statistics.rows if r[0] == "Repeatability"]
    assert rows and "the stated σ of a reading" in rows[0][2]
    assert any(c.name.startswith("Reading noise, stated") for c in document.budget.components)


@pytest.mark.slow
def test_fringe_adc_certificate_stands_behind_the_stated_inputs():
    kind, result = _sample("fringe", {"samples_per_period": 64, **FRINGE_INPUTS})
    meta = replace(META, tolerance=0.5, standards=(
        replace(META.standards[0], description="Data acquisition (16-bit ADC)",
                certificate_no="CAL-2026-33", uncertainty=None),))
    document = kind.certificate_document(result, meta)
    assert document.stated_inputs == ("Phase reference", "ADC quantisation", "ADC offset",
                                      "ADC gain ratio", "ADC linearity")
    # issue 39: the ADC alone, no phase reference standard listed — not traceable, a test
    # report that says why (it was stated "traceable to the SI" here before)
    flat = _flat(document)
    assert document.is_test_report and "Test report" in flat
    assert "traceable to the SI unit of plane angle" not in flat
    assert ("the standards that carry the measurand are a phase or angle reference; the ADC "
            "(its figures stated in the settings), each to be listed with a calibration "
            "certificate and a stated uncertainty; 1 listed so") in flat
    assert "This document is a test report, not a calibration certificate" in flat
    # the ADC's U is what the settings state, not "—"
    assert "as stated in the settings: Phase reference, ADC quantisation" in flat
    document = kind.certificate_document(result, replace(
        meta, standards=(*meta.standards, PHASE_REFERENCE)))
    flat = _flat(document)
    assert not document.is_test_report and "Calibration certificate" in flat
    assert ("traceable to the SI unit of plane angle through the reference standards listed, "
            "calibrated as stated in their certificates: Data acquisition (16-bit ADC) "
            "(certificate CAL-2026-33; its figures enter as the inputs stated in the settings: "
            "Phase reference, ADC quantisation, ADC offset, ADC gain ratio, ADC linearity)") in flat
    assert "no uncertainty stated" not in flat


def test_positioning_figures_in_their_own_unit_enter_the_budget_converted():
    """#32: a standard's uncertainty, the item's resolution and the tolerance carry their
    unit; on an axis evaluated in µrad a figure stated in arcseconds is converted (1" =
    4.8481368 µrad), one stated in µm is refused, and the verdict is in µrad."""
    from models.certificate.metadata import MetadataError, ReferenceStandard
    from models.positioning.report import positioning_budget
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.registry import KINDS
    from models.uncertainty.conformity import decide_conformity

    kind = KINDS["positioning"]
    sample = Path(__file__).parents[3] / "resources" / "samples" / "positioning_sample.csv"
    rows = map_columns(read_table(sample), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(),
                          kind.settings_with_defaults({"deviation_unit": "urad"}))
    in_arcsec = replace(META, standards=(ReferenceStandard("calibrator", uncertainty=1.0),),
                        item_resolution=0.2, tolerance=15.0, tolerance_unit="arcsec")
    budget = positioning_budget(result, in_arcsec)
    assert budget.unit.key == "urad"
    values = {str(c.name): c.value for c in budget.components}
    assert values["calibrator"] == pytest.approx(4.8481368, rel=1e-8)
    assert values["Item resolution"] == pytest.approx(0.1 * 4.8481368, rel=1e-8)
    conformity = decide_conformity(result.deviations[:1] * 0.0, type(budget)(
        budget.components[:1], 1, budget.probability, "urad"),
        in_arcsec.tolerance_quantity, "simple", "points")
    # judged in µrad, the specification quoted as stated (assessment 70 M4), the T decided
    # with beside it to six significant digits (72 M2): ±15″ (72.7221 µrad)
    assert conformity.unit == "urad" and "±15\" (72.7221 µrad)" in conformity.statement
    in_um = replace(META, standards=(ReferenceStandard("laser", uncertainty=0.5,
                                                       uncertainty_unit="um"),))
    with pytest.raises(MetadataError, match="laser.*in µm, but the errors are in µrad"):
        positioning_budget(result, in_um)
