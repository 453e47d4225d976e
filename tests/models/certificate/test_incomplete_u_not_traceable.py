"""A result whose U is declared incomplete is not stated as traceable (review 61, F13).

Metrological traceability is a property of a result related to a reference "through a
documented unbroken chain of calibrations, each contributing to the measurement
uncertainty" (VIM 2.41; ILAC-P10). The positioning certificate said "U is incomplete:
inputs not stated, so not in U: misalignment, resolution, temperature" and, on the same
page, "the results are traceable to the SI", titled a calibration certificate, with the
DCC's traceable true. The fringe's rule (an input with no stated U: not traceable through
it, a test report naming it) is now the rule for every incomplete U.
"""

from __future__ import annotations

import io
import json
import re
from pathlib import Path

import pytest
from lxml import etree
from pypdf import PdfReader

from app.writers.certificate_pdf import certificate_pdf_bytes
from models.certificate.metadata import CertificateMetadata
from models.dcc import vocabulary as v
from models.dcc.writer import build_dcc
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
NS = {"dcc": v.DCC_NAMESPACE}
KIND = KINDS["positioning"]
MISSING = "Misalignment of the reference, Resolution of the reference, Temperature"
STATED = {"misalignment_u": 0.2, "reference_resolution": 0.1, "temperature_u": 0.3}


def _document(**settings):
    table = read_table(SAMPLES / KIND.sample_file)
    parsed = ReadingsSheet(KIND.columns, map_columns(table, KIND.columns)).parse()
    chosen = KIND.settings_with_defaults(settings)
    data = json.loads((SAMPLES / "certificate_positioning.json").read_text("utf-8"))
    meta = CertificateMetadata.from_dict({**data, "example": False})
    return KIND.certificate_document(KIND.analyze(parsed, chosen), meta, settings=chosen)


def _flat(document) -> str:
    pdf = certificate_pdf_bytes(document)
    return re.sub(r"\s+", " ", " ".join(p.extract_text() for p in PdfReader(io.BytesIO(pdf)).pages))


def _traceable_flags(document) -> list[str]:
    root = etree.fromstring(build_dcc(document, certificate_pdf_bytes(document), "p.pdf"))
    return [e.text for e in root.iterfind(".//dcc:statement/dcc:traceable", NS)]


@pytest.mark.slow
def test_an_incomplete_u_makes_a_test_report_saying_why():
    document = _document()
    assert document.not_in_u == ("Misalignment of the reference", "Resolution of the reference",
                                 "Temperature")
    assert document.is_test_report and document.title == "Test report"
    flat = _flat(document)
    assert "Test report" in flat and "Calibration certificate" not in flat
    assert "the results are traceable to the SI" not in flat
    assert ("Metrological traceability: not established for these results — U is incomplete: "
            f"inputs not stated, so not in U: {MISSING}; no statement of conformity rests on "
            "them.") in flat
    assert ("This document is a test report, not a calibration certificate: metrological "
            f"traceability of its results is not established (U is incomplete: inputs not "
            f"stated, so not in U: {MISSING}).") in flat
    flags = _traceable_flags(document)
    assert flags and set(flags) == {"false"}


@pytest.mark.slow
def test_with_every_input_stated_it_is_a_traceable_calibration_certificate():
    document = _document(**STATED)
    assert document.not_in_u == () and not document.untraceable
    assert not document.is_test_report and document.title == "Calibration certificate"
    flat = _flat(document)
    assert "Metrological traceability: the results are traceable to the SI unit of plane " \
           "angle through the reference standards listed" in flat
    assert "Inputs not stated" not in flat and "U is incomplete" not in flat
    assert set(_traceable_flags(document)) == {"true"}
