"""The item's manufacturer is called one thing in Chinese: the certificate's label is the
register's column (day review 67 F9: `register list --language zh_CN` headed it 制造商,
the certificate printed 制造单位)."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import pytest

from app.register_listing import HEADERS
from app.writers.certificate_pdf import certificate_pdf_bytes
from models.certificate.metadata import CertificateMetadata
from models.messages import translator
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS
from tests.pdf_text import pdf_text

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"


def _register_manufacturer() -> str:
    """The Chinese heading of the register list's manufacturer column."""
    assert "Manufacturer" in HEADERS
    return translator("zh_CN")("Manufacturer")


@pytest.mark.parametrize("language", ["zh", "zh+en"])
def test_the_certificate_calls_the_manufacturer_as_the_register_does(language):
    heading = _register_manufacturer()
    assert heading != "Manufacturer"
    kind = KINDS["polygon"]
    rows = map_columns(read_table(SAMPLES / kind.sample_file), kind.columns)
    settings = kind.settings_with_defaults(None)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings)
    details = json.loads((SAMPLES / "certificate_polygon.json").read_text("utf-8"))
    document = kind.certificate_document(result, CertificateMetadata.from_dict(details),
                                         kind.sample_file, settings)
    text = pdf_text(certificate_pdf_bytes(replace(document, metadata=replace(
        document.metadata, language=language))))
    assert heading in text and "制造单位" not in text, (heading, text[:800])
