"""A θ column worse than its stated u: the per-sample phase error the readings show along the
Lissajous figure beyond their scatter across it enters a sample's U in the stated u's place
(covf77 F1, fringer77).

Before, a reference stated at a tenth of its true per-sample error left that error in the
"Signal noise" row, each channel's residual scatter, which holds only about half of a phase
error's variance: the audit's rig covered 90.4 % of its samples at a printed 95.45 %, U/(2 ×
scatter) 0.83. The records come from tests/fringe_budget_rig.py (nothing from models/).
"""

from __future__ import annotations

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata
from models.fringe.analysis import FRINGE
from models.fringe.report import fringe_budget, not_stated
from models.readings.sheet import ParsedReadings
from tests.fringe_budget_rig import Bench, Head, Record, record

SHOWN = "Phase reference (shown by the readings)"


def _details(reference_u: float | None) -> CertificateMetadata:
    standards = [] if reference_u is None else [
        {"description": "Phase reference (encoder)", "certificate_no": "R-1",
         "uncertainty": reference_u, "uncertainty_unit": "arcsec", "basis": "u",
         "role": "reference"}]
    return CertificateMetadata.from_dict({"tolerance": 10.0, "tolerance_unit": "arcsec",
                                          "decision_rule": "guarded", "standards": standards})


def _analysed(r: Record, theta_column: bool = True):
    columns = {"u_sin": r.u_sin, "u_cos": r.u_cos, "theta_deg": np.degrees(r.theta_rad)
               if theta_column else np.full(r.u_sin.size, np.nan)}
    settings = {"lines_per_rev": Head().lines_per_rev}
    if not theta_column:
        settings["samples_per_period"] = 64
    return FRINGE.analyze(ParsedReadings(columns, np.arange(r.u_sin.size)), settings)


def _budget_row(budget, name: str):
    names = [str(c.name) for c in budget.components]
    return budget.components[names.index(name)]


def test_the_readings_show_the_theta_columns_error_per_sample():
    """0.2″ per sample over 2 mV of noise (0.007″): the excess along the figure gives it
    within 10 %; 0.02″ (the noise three times it) within 30 %; with N equal steps, none."""
    from models.fringe.phase_error_shown import phase_error_shown

    rng = np.random.default_rng(7701)
    for true, within in ((0.2, 0.1), (0.02, 0.3)):
        result = _analysed(record(Head(), Bench(reference_u_arcsec=true), rng))
        shown = phase_error_shown(result)
        assert shown is not None
        assert shown.u_rad * result.period_length / (2 * np.pi) == pytest.approx(true,
                                                                                 rel=within)
        assert shown.dof > 50
    steps = _analysed(record(Head(), Bench(reference_u_arcsec=0.0), rng), theta_column=False)
    assert steps.phase_source == "samples_per_period"
    assert phase_error_shown(steps) is None


def test_a_reference_ten_times_worse_than_stated_is_counted_whole_in_a_samples_u():
    """σθ 0.2″ stated as 0.02″ (one seeded record): the phase reference's row takes the
    0.2″ the readings show, Type A, and the samples' U covers the record's deviations from
    the truth as the true 0.2″ stated does. Before: the 0.02″ row, U/(2·rms) 0.71."""
    r = record(Head(), Bench(reference_u_arcsec=0.2), np.random.default_rng(7702))
    result = _analysed(r)
    budget = fringe_budget(result, _details(0.02), as_found=True)
    deviation = result.raw_error - r.truth_arcsec
    ratio = float(np.sqrt(np.mean(budget.expanded ** 2) / 4.0 / np.mean(deviation ** 2)))
    assert 0.9 < ratio < 1.15, ratio  # 1.00; before 0.71
    assert np.mean(np.abs(deviation) <= budget.expanded) >= 0.93  # 95.9 %; before 83.2 %
    true_u = fringe_budget(result, _details(0.2), as_found=True).expanded
    assert budget.expanded == pytest.approx(true_u, rel=0.1)
    row = _budget_row(budget, SHOWN)
    assert row.evaluation == "A" and np.isfinite(row.dof) and row.dof > 50
    assert float(np.max(row.standard_uncertainty(1))) == pytest.approx(0.2, rel=0.1)
    assert "Phase reference (encoder)" not in [str(c.name) for c in budget.components]
    assert "in its place" in str(row.note)


def test_no_reference_stated_the_readings_estimate_enters_and_is_said():
    """No phase reference u: the estimate is what enters (Type A, said in its note), and the
    reference is still named as not stated (the estimate is no certificate of it)."""
    r = record(Head(), Bench(reference_u_arcsec=0.2), np.random.default_rng(7703))
    result = _analysed(r)
    budget = fringe_budget(result, _details(None), as_found=True)
    deviation = result.raw_error - r.truth_arcsec
    assert np.mean(np.abs(deviation) <= budget.expanded) >= 0.93  # before 82.8 %
    row = _budget_row(budget, SHOWN)
    assert row.evaluation == "A"
    assert float(np.max(row.standard_uncertainty(1))) == pytest.approx(0.2, rel=0.1)
    assert "no u is stated for the phase reference" in str(row.note)
    assert "Phase reference" in not_stated(result, _details(None))


def test_a_samples_u_covers_with_the_reference_ten_times_worse_than_stated():
    """40 records, 0.2″ per sample stated as 0.02″: the samples' U covers as printed, 95.7 %
    and U/(2·rms) 1.01 (before: 84.5 % and 0.71, half of the phase error left in the noise
    row)."""
    rng, head, bench = np.random.default_rng(7704), Head(), Bench(reference_u_arcsec=0.2)
    deviations, expanded = [], []
    for _ in range(40):
        r = record(head, bench, rng)
        result = _analysed(r)
        deviations.append(result.raw_error - r.truth_arcsec)
        expanded.append(fringe_budget(result, _details(0.02), as_found=True).expanded)
    d, big_u = np.concatenate(deviations), np.concatenate(expanded)
    covered = float(np.mean(np.abs(d) <= big_u))
    ratio = float(np.sqrt(np.mean(big_u ** 2) / 4.0 / np.mean(d ** 2)))
    assert 0.935 <= covered <= 0.97, covered
    assert 0.95 < ratio < 1.08, ratio
