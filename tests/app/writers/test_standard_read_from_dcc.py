"""A standard read from its DCC is printed as read (review 61, F7.3): U with its k, two
significant digits (GUM 7.2.6), not the U/k the budget takes to six digits
("0.0248127″ (standard uncertainty u)")."""

from __future__ import annotations

import math

import pytest

from app.writers.certificate_pdf.traceability import _standards_table
from models.certificate.metadata import CertificateMetadata
from models.dcc.reader import PolygonReference, polygon_standard
from tests.models.certificate.test_certificate_statements import _sample
from tests.models.certificate.test_printed_rounding import _bundled, two_digits

#: the review's: crosscal certificate AB-2026-0008, its largest U from face 1 and its k
U, K = 0.0501957088144, 2.02298253284


def _reference(k: float = K, u: float = U) -> PolygonReference:
    faces = {i: 0.01 * i for i in range(1, 13)}
    return PolygonReference(faces, {i: u for i in faces}, k, 0.9545, "AB-2026-0008",
                            "2026-11-20", "")


@pytest.mark.parametrize("k, basis", [(K, "u"), (2.0, "U95")])
def test_a_standard_from_its_dcc_is_printed_as_u_with_its_k(k, basis):
    standard = polygon_standard(_reference(k))
    assert standard["basis"] == basis and standard["coverage_factor"] == k
    assert standard["uncertainty"] == pytest.approx(U / k if basis == "u" else U)  # exact
    kind, result = _sample("polygon")
    meta = _bundled("polygon", standards=[{**standard, "description": "Polygon P12"}])
    document = kind.certificate_document(result, meta)
    row = _standards_table(document).rows[0]
    d = two_digits(U)
    assert d == 3
    # and what it is stated per (day review 69 F2): the polygon's, each face's reading; U
    # rounded up as every printed U, the figure its own certificate prints (issue 39)
    up = math.ceil(U * 10**d) / 10**d
    assert str(row[3]) == f"{up:.{d}f}\" (expanded uncertainty U (k = {k:.2f}) per reading)"
    assert str(row[3]) in ("0.051\" (expanded uncertainty U (k = 2.02) per reading)",
                           "0.051\" (expanded uncertainty U (k = 2.00) per reading)")
    # the budget still takes u = U/k exactly
    rows = {r["name"]: r for r in document.budget.table()}
    assert rows["Polygon P12"]["u"] == pytest.approx(U / k)


def test_a_standard_typed_is_printed_as_typed():
    kind, result = _sample("polygon")
    document = kind.certificate_document(result, _bundled("polygon"))
    row = _standards_table(document).rows[-1]
    assert str(row[3]) == "0.1\" (expanded uncertainty U (k = 2) per reading)"


def test_a_metadata_standard_keeps_a_k_read_only_where_one_was():
    typed = CertificateMetadata.from_dict({"standards": [{"description": "AC",
                                                           "uncertainty": 0.1}]})
    assert "coverage_factor" not in typed.to_dict()["standards"][0]
    read = CertificateMetadata.from_dict({"standards": [
        {"description": "P12", "uncertainty": 0.0248127, "basis": "u",
         "coverage_factor": 2.02298253284}]})
    assert read.standards[0].coverage_factor == pytest.approx(2.02298253284)
    again = CertificateMetadata.from_dict(read.to_dict())
    assert again.standards[0] == read.standards[0]
