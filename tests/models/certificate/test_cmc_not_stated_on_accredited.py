"""An accredited calibration certificate with no CMC stated says that its U was not compared
with the CMC of the scope (assessment 76 L7; ILAC-P14:09/2020 5.4). 0.8.24 printed
"laboratory's CMC (smallest U): none stated" under an accreditation with no word. Without an
accreditation, on a test report, or with a CMC stated (its own statement then) nothing of
the kind is said."""

from __future__ import annotations

from dataclasses import replace

import pytest

from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

NOT_COMPARED = ("No calibration and measurement capability (CMC) of the laboratory is stated "
                "for this quantity in the analysis settings, so the U stated here has not been "
                "compared with the CMC of its scope of accreditation (ILAC-P14:09/2020 5.4: no "
                "U smaller than the CMC is stated under accreditation).")

META = CertificateMetadata.from_dict({
    "certificate_number": "AB-2026-0720", "lab_name": "Angle Lab",
    "lab_accreditation": "CNAS L0000 (example)", "customer_name": "Customer",
    "item_description": "Axis", "item_serial": "SN-7", "calibration_date": "2026-11-20",
    "issue_date": "2026-11-24", "operator": "Wang", "approver": "Dr. Li", "tolerance": 3,
    "standards": [{"description": "Autocollimating theodolite", "certificate_no": "NIM-1",
                   "uncertainty": 0.5, "basis": "u"}]})


@pytest.fixture(scope="module")
def theodolite():
    kind = KINDS["theodolite"]
    table = read_table(f"resources/samples/{kind.sample_file}")
    parsed = ReadingsSheet(kind.columns, map_columns(table, kind.columns)).parse()
    settings = kind.settings_with_defaults({})
    return kind, kind.analyze(parsed, settings), settings


def _statements(theodolite, meta, **settings):
    kind, result, defaults = theodolite
    document = kind.certificate_document(result, meta, "", {**defaults, **settings})
    return document, [str(s) for s in document.statements]


def test_an_accredited_certificate_without_a_cmc_says_its_u_was_not_compared(theodolite):
    document, said = _statements(theodolite, META)
    assert not document.is_test_report
    assert ("laboratory's CMC (smallest U)", "none stated") in document.settings
    assert said.count(NOT_COMPARED) == 1


def test_a_cmc_stated_gives_its_own_statement_instead(theodolite):
    _, said = _statements(theodolite, META, cmc_arcsec=2.0)
    assert NOT_COMPARED not in said
    assert any(s.startswith("The laboratory's calibration and measurement capability (CMC) for "
                            "this quantity is U = 2\"") for s in said)


def test_no_accreditation_no_word_of_it(theodolite):
    _, said = _statements(theodolite, replace(META, lab_accreditation=""))
    assert NOT_COMPARED not in said and not any("CMC" in s for s in said)


def test_a_test_report_claims_no_calibration_scope(theodolite):
    document, said = _statements(theodolite, replace(META, document_type="test"))
    assert document.is_test_report
    assert NOT_COMPARED not in said
