"""Issue 39: traceability stated only where every standard that carries the measurand has a
certificate and a stated U (else a test report, saying why); the cross-calibration
comparator's stated U an input of the budget; the laboratory's CMC a floor on every U."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata, ReferenceStandard
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS
from models.validation.polygon_rig import PolygonRig

AUTOCOLLIMATOR = ReferenceStandard("Autocollimator", "AC-17", "NIM-2026-0212", 0.1)
POLYGON_STD = ReferenceStandard("24-face polygon", "P24-3", "NIM-2026-0871", 0.2,
                                applies_to="from face 1")
META = CertificateMetadata(certificate_number="AB-1", lab_name="Lab", customer_name="C",
                           item_description="Encoder", item_serial="1",
                           calibration_date="2026-11-20", operator="W", approver="Z",
                           standards=(POLYGON_STD, AUTOCOLLIMATOR))


def _sample(key, settings=None):
    kind = KINDS[key]
    table = read_table(f"resources/samples/{kind.sample_file}")
    parsed = ReadingsSheet(kind.columns, map_columns(table, kind.columns)).parse()
    return kind, kind.analyze(parsed, kind.settings_with_defaults(settings or {}))


def test_a_polygon_test_with_every_standard_listed_is_a_calibration_certificate():
    kind, result = _sample("polygon")
    document = kind.certificate_document(result, META)
    assert not document.is_test_report and document.title == "Calibration certificate"
    assert not any("test report" in s for s in document.statements)


@pytest.mark.parametrize("standards, why", [
    ((AUTOCOLLIMATOR,), "the polygon (its face deviations); the autocollimator, each to be "
                        "listed with a calibration certificate and a stated uncertainty; 1 "
                        "listed so"),
    ((POLYGON_STD, replace(AUTOCOLLIMATOR, uncertainty=None)), "Autocollimator has no stated "
                                                                "uncertainty"),
    ((POLYGON_STD, replace(AUTOCOLLIMATOR, certificate_no="")), "Autocollimator has no "
                                                                "calibration certificate")])
def test_a_standard_that_carries_the_measurand_without_certificate_and_u_makes_a_test_report(
        standards, why):
    kind, result = _sample("polygon")
    document = kind.certificate_document(result, replace(META, standards=standards))
    assert document.is_test_report and document.title == "Test report"
    said = document.statements[0]
    assert said.startswith("This document is a test report, not a calibration certificate")
    assert why in said


def test_a_theodolite_run_needs_its_theodolite_with_u():
    kind, result = _sample("theodolite")
    theodolite = ReferenceStandard("Theodolite", "T-1", "NIM-1", 0.5, basis="u")
    assert not kind.certificate_document(result, replace(META, standards=(theodolite,))
                                         ).is_test_report
    assert kind.certificate_document(result, replace(META, standards=(
        replace(theodolite, uncertainty=None),))).is_test_report


def test_asked_for_as_a_test_report_it_needs_no_reason():
    kind, result = _sample("polygon")
    document = kind.certificate_document(result, replace(META, document_type="test"))
    assert document.title == "Test report"
    assert not any("not a calibration certificate" in s for s in document.statements)


@pytest.mark.slow
def test_the_comparators_stated_u_is_an_input_through_the_design():
    kind, result = _sample("crosscal")
    without = kind.certificate_document(result, replace(META, standards=()))
    document = kind.certificate_document(result, replace(META, standards=(AUTOCOLLIMATOR,)))
    names = [c.name for c in document.budget.components]
    assert "Comparator calibration: Autocollimator" in names
    assert not any(n.startswith("Comparator") for n in (c.name for c in without.budget.components))
    comp = document.budget.components[names.index("Comparator calibration: Autocollimator")]
    # by hand: U95 0.1″ → u 0.05″ per reading, through the results' gain: u·√(Σ_j G_ij²)
    s = result.solution
    n = result.faces
    gain = np.asarray(s.gain)[n:2 * n] if result.certificate_of == "polygon" else \
        np.asarray(s.gain)[:n]
    expected = 0.05 * np.sqrt(np.sum(gain**2, axis=1))
    np.testing.assert_allclose(comp.standard_uncertainty(n), expected, rtol=1e-9)
    assert np.all(document.budget.expanded > without.budget.expanded)
    combined = np.hypot(without.budget.combined, expected)
    np.testing.assert_allclose(document.budget.combined, combined, rtol=1e-9)


@pytest.mark.slow
def test_the_laboratorys_cmc_is_a_floor_named_on_the_certificate():
    kind, result = _sample("crosscal")
    computed = kind.certificate_document(result, META).budget.expanded
    cmc = float(np.median(computed)) * 1.5
    kind, result = _sample("crosscal", {"cmc_arcsec": cmc})
    document = kind.certificate_document(result, META)
    big_u = document.budget.expanded
    assert np.all(big_u >= cmc - 1e-12)
    np.testing.assert_allclose(big_u, np.maximum(computed, cmc))
    below = int(np.count_nonzero(computed < cmc))
    said = [s for s in document.statements if "(CMC)" in s]
    assert len(said) == 1 and f"At {below} of the {result.faces} points" in said[0]
    # within the scope, their U raised to the CMC (ILAC-P14 5.4), not "outside the scope"
    assert "their U is stated as the CMC, with the same coverage factor k" in said[0]
    assert "outside" not in said[0]
    assert not any("(CMC)" in s for s in kind.certificate_document(
        _sample("crosscal")[1], META).statements)  # no CMC set: nothing said


def test_the_cmc_leaves_a_zero_by_definition_at_zero():
    """One set: every error is taken from face 1's reading, so its U is 0 by definition and
    stays 0; every other U is at least the CMC."""
    faces = 12
    th = np.radians(np.arange(faces) * 30.0)
    rig = PolygonRig(faces, 0.3 * np.cos(th), psi_arcsec=200.0, omega_deg=30.0,
                     noise_arcsec=0.03, rng=np.random.default_rng(5))
    kind = KINDS["polygon"]
    settings = {"grade": 3, "cmc_arcsec": 0.5, "reading_noise_arcsec": 0.03}  # one set: stated
    result = kind.analyze(ReadingsSheet(kind.columns, rig.set_rows()).parse(), settings)
    big_u = kind.certificate_document(result, META, settings=settings).budget.expanded
    assert big_u[0] == 0.0
    assert np.all(big_u[1:] >= 0.5)
