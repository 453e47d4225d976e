"""What an ISO/IEC 17025 assessor reads on every certificate (issue: six defects).

Each test names the defect it covers; the PDFs are read back with pdfium (tests/pdf_text.py:
the fringe sample's 15 pages in 0.03 s of CPU, pypdf's in ~0.5 s).
"""

from __future__ import annotations

import math
import re
from dataclasses import replace

import numpy as np
import pytest

from app.writers.certificate_pdf import certificate_pdf_bytes
from models.certificate.metadata import CertificateMetadata, MetadataError, ReferenceStandard
from models.polygon.analysis import POLYGON
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS
from models.theodolite.model import analyze_run
from models.theodolite.report import theodolite_budget
from models.uncertainty.budget import coverage_factor
from models.validation.polygon_rig import PolygonRig
from models.validation.theodolite_rig import theodolite_readings
from models.workbench import IssuesCertificates
from tests.pdf_text import pdf_text

META = CertificateMetadata.from_dict({
    "certificate_number": "AB-2026-0100", "lab_name": "Angle Lab", "customer_name": "Customer",
    "item_description": "Encoder", "item_serial": "SN-1", "calibration_date": "2026-11-20",
    "issue_date": "2026-11-24", "created": "2026-11-24T10:00:00", "operator": "Wang",
    "standards": [{"description": "Autocollimator", "certificate_no": "NIM-2026-0212",
                   "uncertainty": 0.1}]})


#: the fringe inputs the signals cannot show (a 16-bit ADC over ±10 V, its calibration)
FRINGE_INPUTS = {"phase_reference_u": 0.01, "adc_lsb_mv": 0.3, "adc_offset_u_mv": 0.5,
                 "adc_gain_u_pct": 0.02, "adc_linearity_mv": 0.6}


def _flat(document) -> str:
    return pdf_text(certificate_pdf_bytes(document))


def _sample(key, settings=None):
    kind = KINDS[key]
    table = read_table(f"resources/samples/{kind.sample_file}")
    parsed = ReadingsSheet(kind.columns, map_columns(table, kind.columns)).parse()
    return kind, kind.analyze(parsed, kind.settings_with_defaults(settings or {}))


# 1. k = 2 always -----------------------------------------------------------------------
@pytest.mark.slow
def test_coverage_factor_follows_the_effective_degrees_of_freedom():
    """An 8-face polygon measured twice forward: few degrees of freedom (the sets' scatter,
    ν = 8), so k is well above 2. (Measured once, it has no noise of its own to evaluate:
    its U is withheld unless the σ of a reading is stated, issue 39.)"""
    rig = PolygonRig(8, 0.3 * np.sin(np.radians(np.arange(8) * 45.0)), psi_arcsec=200.0,
                     omega_deg=40.0, noise_arcsec=0.1, rng=np.random.default_rng(8))
    rows = rig.set_rows(1) + rig.set_rows(2)
    result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(),
                             {"grade": 4, "ac_roll_arcmin": 0.0})
    document = POLYGON.certificate_document(result, replace(META, standards=()))
    budget = document.budget
    nu = budget.effective_dof()
    assert nu < 15
    k = coverage_factor(budget.truncated_dof())  # the integer ν below ν_eff (GUM G.6.4)
    assert budget.truncated_dof() == math.floor(nu)
    assert budget.coverage_factor == pytest.approx(k) and k > 2.2
    flat = _flat(document)
    assert f"k = {k:.2f}" in flat and "95.45 %" in flat
    assert document.expanded_uncertainty == pytest.approx(
        float(np.max(budget.coverage_factors * budget.combined)))


# 4. fringe conformity on the as-found error -----------------------------------------------
@pytest.mark.slow
def test_fringe_conformity_is_on_the_error_as_found():
    kind, result = _sample("fringe", {"samples_per_period": 64, **FRINGE_INPUTS})
    meta = replace(META, tolerance=0.5, decision_quantity="points")
    document = kind.certificate_document(result, meta)
    # the as-found error, not the compensated 0.02" (signed: the deciding point's, 0.8.17)
    assert abs(document.conformity.value) > 0.4
    flat = _flat(document)
    assert "as-found interpolation error" in flat or "as found" in flat
    assert "is not the item's unless the table is loaded" in flat
    assert "As left" not in flat


@pytest.mark.slow
def test_fringe_as_left_only_with_the_loaded_tables_checksum():
    kind, result = _sample("fringe", {"samples_per_period": 64})
    left = kind.certificate_document(result, replace(META, as_left_table_sha256=result.table.sha256))
    assert "As left: the lab states that the correction table" in _flat(left)
    with pytest.raises(MetadataError, match="was loaded into the encoder, but this analysis"):
        kind.certificate_document(result, replace(META, as_left_table_sha256="0" * 64))


# 5. the statements ------------------------------------------------------------------------
#: the inputs a workbench's sample needs for a traceable certificate with a conformity
#: statement, beside META (none for a workbench not listed)
STATEMENT_SETTINGS = {"fringe": {"samples_per_period": 64, **FRINGE_INPUTS},
                      # every input of its U stated: else U is incomplete, and a result
                      # whose U is incomplete is not traceable (review 61, F13)
                      "positioning": {"misalignment_u": 0.2, "reference_resolution": 0.1,
                                      "temperature_u": 0.3}}
STATEMENT_TOLERANCE = {"polygon": None}  # the grade's accuracy is the polygon's tolerance
#: issue 39: every standard that carries the measurand listed with its certificate and U,
#: beside META's autocollimator (the polygon's; the fringe's phase reference and ADC)
STATEMENT_STANDARDS = {
    "polygon": ({"description": "Polygon", "certificate_no": "NIM-2026-0871",
                 "uncertainty": 0.2, "applies_to": "from face 1"},),
    "fringe": ({"description": "Reference angle encoder", "certificate_no": "NIM-2026-0999",
                "uncertainty": 0.05, "role": "reference"},
               {"description": "Data acquisition", "certificate_no": "CAL-2026-33"})}
#: workbenches whose errors are taken from one of their own readings (zero there)
ZEROED_AT_ONE_OF_ITS_READINGS = ("theodolite", "polygon")


@pytest.mark.slow
@pytest.mark.parametrize("key", sorted(k for k in KINDS if isinstance(KINDS[k], IssuesCertificates)))
def test_17025_statements_on_every_certificate(key):
    kind, result = _sample(key, STATEMENT_SETTINGS.get(key, {}))
    meta = replace(META, tolerance=STATEMENT_TOLERANCE.get(key, 2.0), standards=(
        *META.standards, *(ReferenceStandard.from_dict(s, i)
                           for i, s in enumerate(STATEMENT_STANDARDS.get(key, ())))))
    document = kind.certificate_document(result, meta)
    flat = _flat(document)
    assert flat.count("Calibration certificate") >= 1 and "Test certificate" not in flat
    assert "traceable to the SI unit of plane angle" in flat and "NIM-2026-0212" in flat
    assert "The results relate only to the item calibrated" in flat
    if document.standard:  # a standard method, named as such
        assert f"follows {document.standard}" in flat and "non-standard method" not in flat
    else:
        assert "non-standard method" in flat
    assert "anglebench validate" in flat
    assert document.sign_convention in flat
    if key == "positioning":
        assert "follows ISO 230-2:2014" in flat
        assert "x = actual position − target (ISO 230-2), i.e. reference − indicated" in flat
    elif key == "crosscal":  # a polygon's face deviations (review 61, F3)
        assert "(actual − nominal), i.e. reference − indicated" in flat
        assert "error = indicated − reference" not in flat
    else:
        assert "error = indicated − reference" in flat
    assert "cross-checked by a Monte Carlo" not in flat
    assert "4.2.3" in flat and "conditional pass" in flat  # the rule's own zones
    if key in ZEROED_AT_ONE_OF_ITS_READINGS:  # says why the error there is zero by definition
        assert re.search(r"U is zero (only )?at", flat)
    if key == "polygon":
        assert "Table 1 of Tian et al. (2015)" in flat
    report = kind.certificate_document(result, replace(meta, document_type="test"))
    assert "Test report" in _flat(report)


@pytest.mark.slow
def test_no_traceability_claimed_without_a_certified_standard():
    kind, result = _sample("theodolite")
    flat = _flat(kind.certificate_document(result, replace(META, standards=())))
    assert "traceability: not established" in flat


# 6. budget gaps ----------------------------------------------------------------------------
def test_repeats_of_the_reference_angle_carry_their_uncertainty():
    theta = np.tile(np.arange(-20.0, 20.1, 5.0), 2)
    azimuth, elevation = theodolite_readings(theta, 3.0, 45.0, 2.0)
    rng = np.random.default_rng(1)
    azimuth = azimuth + rng.normal(0, 0.3, theta.size) / 3600
    elevation = elevation + rng.normal(0, 0.3, theta.size) / 3600
    result = analyze_run(theta, azimuth, elevation, reference_index=4)
    budget = theodolite_budget(result, META)
    at_zero = np.nonzero(theta == 0.0)[0]
    assert list(at_zero) == [4, 13]
    assert budget.expanded[4] == 0.0  # the zeroing reading itself
    assert budget.expanded[13] > 0.3  # a later reading at θ = 0 is a reading like any


@pytest.mark.parametrize("field, value, message", [
    ("standards", [{"description": "x", "uncertainty": 1e300}], "at most 3600"),
    # no calibration states 0: a run of exact readings then decided "pass" on ±0.0003″
    ("standards", [{"description": "x", "uncertainty": 0}], "must be more than 0"),
    ("item_resolution_arcsec", -5, "must be 0 to 3600"),
    ("coverage_probability_pct", 120, "50 to 99.9"),
    ("decision_quantity", "mean", "must be one of half_range, points"),
])
def test_absurd_details_are_refused(field, value, message):
    with pytest.raises(MetadataError, match=message):
        CertificateMetadata.from_dict({field: value})
