"""No statement of conformity rests on results whose traceability is not established
(assessment 70, H1 and H2).

* H1: a standard listed with no stated U (the document a test report, its PDF saying the
  standard "is no input of the budget") left ``uncertainty_inputs_not_stated`` empty and
  stated "pass" on the theodolite, polygon, positioning and cross-calibration workbenches:
  the readings' scatter stood in for the standard's calibration. It is an input not stated:
  named under the budget and in the JSON, and no statement is made (the verdict null with
  its reason), as the fringe workbench did for its own inputs.
* H2: a fringe record with every input stated but only the ADC listed (no phase or angle
  reference standard) was a test report saying "traceability: not established … 1 listed
  so", and stated "pass". No statement is made while traceability is not established, and
  the reason names the standard listed.

The readings are the bundled samples, the details the bundled ones with the standards
changed; each case is checked against its control with every standard stated, which does
make a statement."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import pytest

from models.certificate.metadata import CertificateMetadata, ReferenceStandard
from models.certificate.uncertainty_json import workbench_uncertainty_json
from tests.models.certificate.test_certificate_statements import FRINGE_INPUTS, _sample

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"

#: (settings every input of U stated with, the tolerance to add to the sample's details)
CASES = {"theodolite": ({}, None), "polygon": ({}, None),
         "positioning": ({"misalignment_u": 0.2, "reference_resolution": 0.1,
                          "temperature_u": 0.2}, None),
         "crosscal": ({}, 1.0)}


def _details(key: str, tolerance: float | None) -> dict:
    details = json.loads((SAMPLES / f"certificate_{key}.json").read_text(encoding="utf-8"))
    details.update(example=False)
    if tolerance is not None:
        details["tolerance"] = tolerance
    return details


def _without_u(details: dict, index: int) -> dict:
    standard = details["standards"][index]
    for key in ("uncertainty", "uncertainty_arcsec"):
        standard.pop(key, None)
    standard["uncertainty"] = None
    return details


@pytest.mark.parametrize("key", sorted(CASES))
def test_a_standard_with_no_stated_u_is_an_input_not_stated_and_no_statement_is_made(key):
    settings, tolerance = CASES[key]
    kind, result = _sample(key, settings)
    stated = CertificateMetadata.from_dict(_details(key, tolerance))
    # the control: every standard with its U, a statement of conformity is made
    control = kind.certificate_document(result, stated)
    assert control.conformity.verdict != "not assessed", control.conformity.reason
    assert workbench_uncertainty_json(kind, result, stated, None)[
        "uncertainty_inputs_not_stated"] == []
    details = _without_u(_details(key, tolerance), -1)
    name = details["standards"][-1]["description"]
    meta = CertificateMetadata.from_dict(details)
    document = kind.certificate_document(result, meta)
    assert document.conformity.verdict == "not assessed"
    assert name in str(document.conformity.reason)
    assert name in document.not_in_u and name in str(document.not_in_u_statement)
    assert document.is_test_report
    extra = workbench_uncertainty_json(kind, result, meta, None)
    assert name in extra["uncertainty_inputs_not_stated"]
    decided = extra["decided_quantity"]
    assert decided["verdict"] is None and decided["probability_conforming"] is None
    assert name in decided["reason"]
    assert decided["value"] is not None  # the figure is still stated, with its reason


def _fringe_meta(*standards: ReferenceStandard) -> CertificateMetadata:
    details = _details("fringe", 0.5)
    return replace(CertificateMetadata.from_dict(details), standards=standards)


#: the assessor's: the ADC listed with a U (taken as the budget's reference standard), no
#: phase reference; and the phase reference that completes it (its u stated in the settings)
ADC = ReferenceStandard("Data acquisition (16-bit ADC)", "DAQ-5", "CAL-2026-33", 0.3)
PHASE_REFERENCE = ReferenceStandard("Reference angle encoder (phase of each sample)", "RE-2",
                                    "NIM-2026-0999", role="reference")


def test_a_fringe_record_with_no_phase_reference_listed_makes_no_statement():
    kind, result = _sample("fringe", {"samples_per_period": 64, **FRINGE_INPUTS})
    complete = _fringe_meta(ADC, PHASE_REFERENCE)
    control = kind.certificate_document(result, complete)
    assert not control.is_test_report
    assert control.conformity.verdict != "not assessed", control.conformity.reason
    meta = _fringe_meta(ADC)
    document = kind.certificate_document(result, meta)
    assert document.is_test_report and document.untraceable == ()  # every input stated
    assert document.conformity.verdict == "not assessed"
    reason = str(document.conformity.reason)
    assert "traceability of the results is not established" in reason
    # "1 listed so" names the standard listed and what is not: with no role stated, not the
    # phase or angle reference, and the role to state (assessment 72 L2: "the standard for the
    # other one"; assessment 78 H1; tests/models/certificate/test_traceability_roles.py)
    assert ("1 listed so (Data acquisition (16-bit ADC)): none is listed for a phase or angle "
            "reference, as no role is stated for Data acquisition (16-bit ADC)") in reason
    assert 'state the role "reference"' in reason
    assert any("1 listed so (Data acquisition (16-bit ADC))" in str(g)
               for g in document.traceability_gaps)
    decided = workbench_uncertainty_json(kind, result, meta, None)["decided_quantity"]
    assert decided["verdict"] is None
    assert "traceability of the results is not established" in decided["reason"]
    assert workbench_uncertainty_json(kind, result, complete, None)[
        "decided_quantity"]["verdict"] is not None


def test_a_polygon_with_its_polygon_not_listed_makes_no_statement():
    kind, result = _sample("polygon")
    details = _details("polygon", None)
    details["standards"] = details["standards"][1:]  # the autocollimator alone
    document = kind.certificate_document(result, CertificateMetadata.from_dict(details))
    assert document.conformity.verdict == "not assessed"
    assert "1 listed so (Photoelectric autocollimator)" in str(document.conformity.reason)


# audit 71 finding 2: no standard listed at all ------------------------------------------
#: the standards that carry each workbench's measurand, as the certificate names them (the
#: cross-calibration names none: each item is the other's reference)
ROLES = {"positioning": ("the reference measuring system",),
         "theodolite": ("the autocollimating theodolite",),
         "fringe": ("a phase or angle reference",
                    "the ADC (its figures stated in the settings)"),
         "polygon": ("the polygon (its face deviations)", "the autocollimator")}

#: every input of U stated in the settings, as the audit typed them
NO_STANDARD_SETTINGS = {**{k: v for k, (v, _) in CASES.items()},
                        "fringe": {"samples_per_period": 64, **FRINGE_INPUTS}}


def _no_standard(key: str, tolerance: float | None = None) -> CertificateMetadata:
    details = _details(key, tolerance)
    details["standards"] = []
    return CertificateMetadata.from_dict(details)


@pytest.mark.parametrize("key", sorted(ROLES))
def test_no_statement_of_conformity_with_no_reference_standard_listed(key):
    """The audit's positioning, theodolite and fringe (every input's u typed, none of the
    standards listed) stated "pass" under a traceability statement "not established … no
    reference standard with a calibration certificate"; the polygon did the same. No
    statement is made: the reason names the standards that carry the measurand and that
    none is listed; the figure and its interval are still given; the document is a test
    report, the same reason its traceability gap (assessment 72 M3: until 0.8.20 titled a
    calibration certificate beside "traceability not established")."""
    kind, result = _sample(key, NO_STANDARD_SETTINGS[key])
    tolerance = _details(key, None).get("tolerance")
    # the control: every standard that carries the measurand listed with its U
    listed = (_fringe_meta(ADC, PHASE_REFERENCE) if key == "fringe"
              else CertificateMetadata.from_dict(_details(key, tolerance)))
    control = kind.certificate_document(result, listed)
    assert control.conformity.verdict != "not assessed", control.conformity.reason
    meta = _no_standard(key, tolerance)
    document = kind.certificate_document(result, meta)
    assert document.conformity.verdict == "not assessed"
    reason = str(document.conformity.reason)
    assert "traceability of the results is not established" in reason
    assert "none is listed, so the uncertainty holds no standard's calibration" in reason
    for role in ROLES[key]:
        assert role in reason
    assert document.is_test_report and len(document.traceability_gaps) == 1
    assert "none is listed, so the uncertainty holds no standard's calibration" in str(
        document.traceability_gaps[0])
    extra = workbench_uncertainty_json(kind, result, meta, None)
    decided = extra["decided_quantity"]
    assert decided["verdict"] is None and decided["probability_conforming"] is None
    assert decided["reason"] == reason
    # the numbers are still stated: the figure and its interval (the readings' U alone)
    assert decided["value"] is not None
    assert decided["interval_low"] is not None and decided["interval_high"] is not None
    assert decided["interval_low"] <= decided["value"] <= decided["interval_high"]
    assert decided["interval_low"] == pytest.approx(document.conformity.interval_low)


def test_the_cross_calibration_with_no_standard_listed_lacks_its_comparators_calibration():
    """Each item is the other's reference: no standard carries the measurand, so no
    traceability gap is named for one. But every reading is made with the autocollimator,
    whose calibration is an input of U (assessment 73 M2: 0.8.21 dropped that row and still
    stated a pass): with none listed U is incomplete, no statement of conformity is made, and
    the reason names the comparator's calibration, not a standard carrying the measurand."""
    kind, result = _sample("crosscal")
    meta = _no_standard("crosscal", 1.0)
    document = kind.certificate_document(result, meta)
    assert document.conformity.verdict == "not assessed" and document.is_test_report
    assert "Comparator calibration" in str(document.conformity.reason)
    assert "carry the measurand" not in str(document.conformity.reason)
    decided = workbench_uncertainty_json(kind, result, meta, None)["decided_quantity"]
    assert decided["verdict"] is None and "Comparator calibration" in decided["reason"]
