"""Assessment 78 L4: the fringe's angle reference, its U stated per reading, was "0.02″
(expanded uncertainty U (k = 2) per reading)" in the standards table and "expanded
uncertainty U (k = 2) per sample" in the budget: one figure, two words. The fringe calls a
reading a sample (its results are per sample, its budget's notes say u per sample): the
standards table says "per sample" too; a workbench whose readings are readings keeps
"per reading"."""

from __future__ import annotations

from dataclasses import replace

import pytest

from app.writers.certificate_pdf.traceability import _standards_table
from models.certificate.metadata import CertificateMetadata
from tests.models.certificate.test_certificate_statements import _sample

REFERENCE = {"description": "Angle reference (rotary table with encoder)", "serial": "RT-9",
             "certificate_no": "NIM-2026-0555", "uncertainty": 0.02, "uncertainty_unit": "arcsec",
             "basis": "U95", "role": "reference"}
ADC = {"description": "Data acquisition (16-bit ADC)", "serial": "DAQ-5",
       "certificate_no": "CAL-2026-33", "uncertainty": 0.05, "uncertainty_unit": "arcsec",
       "basis": "U95", "role": "adc"}
ADC_FIGURES = {"adc_lsb_mv": 0.3, "adc_offset_u_mv": 0.5, "adc_gain_u_pct": 0.05,
               "adc_linearity_mv": 0.5}


@pytest.fixture(scope="module")
def fringe():
    settings = {"samples_per_period": 64, **ADC_FIGURES}
    kind, result = _sample("fringe", settings)
    meta = CertificateMetadata.from_dict({"standards": [REFERENCE, ADC], "tolerance": 0.45,
                                          "language": "en"})
    return kind.certificate_document(result, meta, settings=kind.settings_with_defaults(
        settings))


def test_the_standards_table_says_per_sample_as_the_budget(fringe):
    row = _standards_table(fringe).rows[0]
    assert str(row[0]) == REFERENCE["description"]
    assert str(row[3]) == "0.02\" (expanded uncertainty U (k = 2) per sample)", row
    notes = [str(c.note) for c in fringe.budget.components
             if c.name == REFERENCE["description"]]
    assert notes and all("expanded uncertainty U (k = 2) per sample" in n for n in notes), notes
    assert "per reading" not in " ".join(notes)


def test_in_chinese_one_word_too(fringe):
    from app.writers.certificate_pdf import certificate_pdf_bytes
    from models.messages import in_language, translator
    from tests.pdf_text import pdf_text

    zh = replace(fringe, metadata=replace(fringe.metadata, language="zh"))
    per_sample = in_language(_standards_table(zh).rows[0][3], translator("zh_CN"))
    reading = translator("zh_CN")("reading")
    sample = translator("zh_CN")("sample")
    assert sample != "sample" and sample in per_sample and reading not in per_sample, per_sample
    assert sample in pdf_text(certificate_pdf_bytes(zh))


def test_a_theodolites_standard_is_still_per_reading():
    kind, result = _sample("theodolite")
    meta = CertificateMetadata.from_dict({"standards": [{
        "description": "Autocollimating theodolite", "serial": "T-1", "certificate_no": "C-1",
        "uncertainty": 0.5, "basis": "u"}], "language": "en"})
    document = kind.certificate_document(result, meta)
    assert str(_standards_table(document).rows[0][3]).endswith("per reading)")
