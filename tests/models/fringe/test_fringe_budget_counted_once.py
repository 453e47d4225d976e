"""The fringe budget's inputs that are in the readings counted once, and the ADC's certificate
kept out of the phase reference's inputs (fringe76b's note; issue 39: every input once).

(a) A sample's U added the phase reference's u to a "Signal noise" row that is the readings'
    scatter about the fit, which holds the reference's independent per-sample errors (u²·m
    of each channel's variance): at a reference dominating the noise the U was √1.5 times
    what the deviations need (per sample 98.5 % covered, U/(2·sd) 1.23 over 200 records).
(b) Every listed standard with a U entered as the phase reference: the ADC's certificate
    (role "adc") with 0.05″ added 0.05″ to every sample's u and went through the fit as
    independent phase errors of each sample.
(c) The ADC's LSB/√12 had its own row and was in the "Signal noise" row too (a sample's U
    1.31 times what it needs at an LSB of 5 mV over 0.5 mV of noise); in the decided half
    range its whole ±LSB/2 was a pattern of the record even where the noise dithers it.

The records come from tests/fringe_budget_rig.py (the head, its reference and its ADC from
first principles; nothing from models/); the truth is the head's own error at each stated
phase and its own half range over the whole period.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata
from models.fringe.analysis import FRINGE
from models.fringe.report import (
    fringe_budget,
    fringe_certificate,
    model_error_budget,
    model_error_curve,
)
from models.readings.sheet import ParsedReadings
from tests.fringe_budget_rig import Bench, Head, Record, record


def _details(reference_u: float | None = None, adc_u: float | None = None,
             tolerance: float = 10.0) -> CertificateMetadata:
    standards = []
    if reference_u is not None:
        standards.append({"description": "Phase reference (encoder)", "certificate_no": "R-1",
                          "uncertainty": reference_u, "uncertainty_unit": "arcsec",
                          "basis": "u", "role": "reference"})
    standards.append({"description": "Data acquisition (16-bit ADC)", "certificate_no": "CAL-33",
                      "uncertainty": adc_u, "uncertainty_unit": "arcsec", "basis": "U95",
                      "role": "adc"})
    return CertificateMetadata.from_dict({"tolerance": tolerance, "tolerance_unit": "arcsec",
                                          "decision_rule": "guarded", "standards": standards})


def _analysed(r: Record, stated: dict):
    parsed = ParsedReadings({"u_sin": r.u_sin, "u_cos": r.u_cos,
                             "theta_deg": np.degrees(r.theta_rad)}, np.arange(r.theta_rad.size))
    return FRINGE.analyze(parsed, {"lines_per_rev": Head().lines_per_rev, **stated})


def _per_sample(bench: Bench, stated: dict, details: CertificateMetadata, runs: int,
                seed: int) -> tuple[float, float]:
    """(share of the samples whose deviation from the truth is within their U, the RMS of
    U/2 over the RMS deviation), over ``runs`` records of the rig."""
    rng, head = np.random.default_rng(seed), Head()
    deviations, expanded = [], []
    for _ in range(runs):
        r = record(head, bench, rng)
        result = _analysed(r, stated)
        deviations.append(result.raw_error - r.truth_arcsec)
        expanded.append(fringe_budget(result, details, as_found=True).expanded)
    d, big_u = np.concatenate(deviations), np.concatenate(expanded)
    return float(np.mean(np.abs(d) <= big_u)), float(np.sqrt(np.mean(big_u ** 2) / 4.0
                                                            / np.mean(d ** 2)))


def test_a_samples_u_counts_the_phase_reference_once_with_the_readings_scatter():
    """0.2″ per sample in the readings (the noise 0.007″): before, 98.7 % and 1.23 here."""
    covered, ratio = _per_sample(Bench(reference_u_arcsec=0.2), {}, _details(0.2), 60, 771)
    assert 0.935 <= covered <= 0.965, covered
    assert 0.95 < ratio < 1.06, ratio


def test_a_reference_better_than_stated_keeps_the_stated_u_per_sample():
    """The stated u is an envelope: 0.2″ stated over errors of 0.02″, every sample's U is
    still at least twice the stated u (the larger of scatter and stated, not less)."""
    rng = np.random.default_rng(772)
    result = _analysed(record(Head(), Bench(reference_u_arcsec=0.02), rng), {})
    budget = fringe_budget(result, _details(0.2), as_found=True)
    assert np.all(budget.expanded >= 2 * 0.2)
    names = [str(c.name) for c in budget.components]
    noise = budget.components[names.index("Signal noise")]
    assert "counted once" in str(noise.note)


def test_a_samples_u_counts_the_adc_lsb_once():
    """An LSB of 5 mV over 0.5 mV of noise: each reading's rounding is in its residual, so
    in the scatter: before, its own row and the scatter summed it twice (1.31 here, 99.3 %)."""
    bench = Bench(reference_u_arcsec=0.005, lsb_v=0.005, noise_v=0.0005)
    covered, ratio = _per_sample(bench, {"adc_lsb_mv": 5.0}, _details(0.005), 40, 773)
    assert 0.935 <= covered <= 0.97, covered
    assert 0.95 < ratio < 1.08, ratio


ADC_TYPED = {"adc_lsb_mv": 0.3, "adc_offset_u_mv": 2.0, "adc_gain_u_pct": 0.1}


@pytest.fixture(scope="module")
def adc_record():
    bench = Bench(reference_u_arcsec=0.005, offset_u_v=0.002, gain_u=0.001, lsb_v=0.0003)
    return _analysed(record(Head(), bench, np.random.default_rng(774)), ADC_TYPED)


def test_the_adcs_certificate_u_is_no_phase_reference(adc_record):
    """The ADC listed with its certificate's U (role "adc") beside its figures typed in the
    settings: the samples' U, the decided curve's budget and its interval are those
    without it (before: 0.05″ more at every sample, and 14 directions "through the fit")."""
    result = adc_record
    with_u, without = _details(0.005, adc_u=0.05), _details(0.005)
    assert fringe_budget(result, with_u, as_found=True, settings=ADC_TYPED).expanded == \
        pytest.approx(fringe_budget(result, without, as_found=True, settings=ADC_TYPED).expanded)
    theta, _ = model_error_curve(result)
    names = [str(c.name) for c in model_error_budget(result, with_u, theta, ADC_TYPED).components]
    assert not [n for n in names if "ADC" in n and "through the fit" in n], names
    assert sum("Phase reference (encoder), through the fit" in n for n in names) == 14
    assert sum(n.startswith(("ADC offset", "ADC gain ratio")) for n in names) == 3
    low, high = (fringe_certificate(result, d, settings=ADC_TYPED).conformity
                 for d in (with_u, without))
    assert (low.interval_low, low.interval_high) == (high.interval_low, high.interval_high)


def test_the_adcs_certificate_u_is_said_not_entered(adc_record):
    document = fringe_certificate(adc_record, _details(0.005, adc_u=0.05), settings=ADC_TYPED)
    said = [str(w) for w in document.warnings if "is the ADC" in str(w)]
    assert len(said) == 1
    assert "0.05\" is not entered as an error of each sample's phase" in said[0]
    assert "(stated here: ADC quantisation, ADC offset, ADC gain ratio)." in said[0]
    assert said[0] in FRINGE.certified_json(adc_record, _details(0.005, adc_u=0.05))["warnings"]
    quiet = fringe_certificate(adc_record, _details(0.005), settings=ADC_TYPED)
    assert not [w for w in quiet.warnings if "is the ADC" in str(w)]


def test_a_dithered_lsb_is_no_pattern_of_the_decided_curve():
    """An LSB of 2 mV under 2 mV of noise: the noise dithers it, each reading's rounding is
    in the scatter the fit's directions are drawn with; no "ADC quantisation" row of one
    pattern for the record (before: ±1 mV in each channel, the interval 1.6 times as wide).
    Coarse against the noise (5 mV over 0.5 mV) the pattern stays, within the bound the
    noise leaves repeated."""
    rng = np.random.default_rng(775)
    dithered = _analysed(record(Head(), Bench(lsb_v=0.002), rng), {"adc_lsb_mv": 2.0})
    theta, _ = model_error_curve(dithered)
    names = [str(c.name) for c in model_error_budget(dithered, _details(0.005), theta,
                                                     {"adc_lsb_mv": 2.0}).components]
    assert not [n for n in names if n.startswith("ADC quantisation")], names
    coarse = _analysed(record(Head(), Bench(lsb_v=0.005, noise_v=0.0005), rng),
                       {"adc_lsb_mv": 5.0})
    rows = [c for c in model_error_budget(coarse, _details(0.005), theta,
                                          {"adc_lsb_mv": 5.0}).components
            if str(c.name).startswith("ADC quantisation")]
    assert len(rows) == 2
    for row in rows:  # σ = LSB/10 leaves most of the half LSB (2.5 mV) repeated
        half_mv = float(re.search(r"within ±([0-9.]+) mV", str(row.note)).group(1))
        assert 1.0 < half_mv <= 2.5, row.note


def test_the_adcs_certificate_u_does_not_state_the_phase_reference(adc_record):
    """A θ column with only the ADC listed with a U and no phase reference u set: the phase
    reference's u is stated nowhere, so it is named not in U and the error not traceable
    (before: the ADC's U was taken for the θ reference's, through the fit)."""
    from models.fringe.report import not_stated, untraceable_inputs

    only_adc = CertificateMetadata.from_dict({
        "tolerance": 10.0, "tolerance_unit": "arcsec", "decision_rule": "guarded",
        "standards": [{"description": "Data acquisition (16-bit ADC)", "certificate_no": "CAL-33",
                       "uncertainty": 0.05, "uncertainty_unit": "arcsec", "role": "adc"}]})
    assert "Phase reference" in not_stated(adc_record, only_adc)
    assert any("phase reference" in str(w) for w in untraceable_inputs(adc_record, only_adc))
    document = fringe_certificate(adc_record, only_adc, settings=ADC_TYPED)
    from models.fringe.report import REFERENCE_IN_HALF_RANGE

    assert REFERENCE_IN_HALF_RANGE not in [str(s) for s in document.statements]
    # the phase reference listed: stated, and said how it enters
    listed = _details(0.005, adc_u=0.05)
    assert "Phase reference" not in not_stated(adc_record, listed)
    assert REFERENCE_IN_HALF_RANGE in [str(s) for s in fringe_certificate(
        adc_record, listed, settings=ADC_TYPED).statements]
