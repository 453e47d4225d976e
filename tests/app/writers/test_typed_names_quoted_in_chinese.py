"""Assessment 78 L5: a Chinese sentence ran straight into a standard's name as the user typed
it, "未说明Data acquisition (16-bit ADC)的角色". A name the user typed is quoted inside a
Chinese sentence, “…”, as the catalogue's other quoted names (设置“{name}”); the English is as
it was."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import pytest

from models.certificate.metadata import CertificateMetadata
from models.certificate.traceability import standards_not_stated, traceability_gaps
from models.messages import in_language, translator

ADC_NO_ROLE = {"description": "Data acquisition (16-bit ADC)", "serial": "DAQ-5",
               "certificate_no": "CAL-2026-33", "uncertainty": 0.05}


def test_a_typed_name_is_itself_in_english_and_quoted_in_chinese():
    from models.messages import typed_name

    name = typed_name("Data acquisition (16-bit ADC)")
    assert name == "Data acquisition (16-bit ADC)"
    assert typed_name("") == "" and typed_name(None) is None
    assert in_language(name, translator("zh_CN")) == "“Data acquisition (16-bit ADC)”"


def test_the_role_not_stated_quotes_the_standard_in_chinese():
    from models.fringe import MEASURAND_STANDARDS
    from models.fringe.analysis import ROLES_STATED_ONLY

    meta = CertificateMetadata.from_dict({"standards": [ADC_NO_ROLE]})
    gaps = traceability_gaps(meta, MEASURAND_STANDARDS, (), ROLES_STATED_ONLY)
    assert gaps and "no role is stated for Data acquisition (16-bit ADC) and" in gaps[0]
    zh = in_language(gaps[0], translator("zh_CN"))
    assert "未说明“Data acquisition (16-bit ADC)”的角色" in zh, zh
    # its translation quotes {unnamed} itself: the name is not quoted twice
    assert "未说明Data" not in zh and "““" not in zh and "””" not in zh


def test_a_standard_with_no_u_is_quoted_too():
    meta = CertificateMetadata.from_dict({"standards": [{"description": "Autocollimator AC-9",
                                                         "certificate_no": "C-1"}]})
    names = standards_not_stated(meta)
    assert names == ["Autocollimator AC-9"]
    gaps = traceability_gaps(meta, (), ())
    assert any("Autocollimator AC-9 has no stated uncertainty" in g for g in gaps), gaps
    zh = [in_language(g, translator("zh_CN")) for g in gaps]
    assert any(z.startswith("“Autocollimator AC-9”") for z in zh), zh


@pytest.mark.slow
def test_the_chinese_certificate_quotes_it():
    from app.writers.certificate_pdf import certificate_pdf_bytes
    from models.registry import KINDS
    from tests.models.certificate.test_certificate_statements import _sample
    from tests.pdf_text import pdf_text

    settings = {"samples_per_period": 64, "adc_lsb_mv": 0.3, "adc_offset_u_mv": 0.5,
                "adc_gain_u_pct": 0.05, "adc_linearity_mv": 0.5}
    kind, result = _sample("fringe", settings)
    details = json.loads((Path("resources/samples/certificate_fringe.json")).read_text("utf-8"))
    meta = CertificateMetadata.from_dict({**details, "standards": [ADC_NO_ROLE],
                                          "tolerance": 0.6, "language": "zh"})
    assert kind is KINDS["fringe"]
    document = kind.certificate_document(result, meta,
                                         settings=kind.settings_with_defaults(settings))
    zh = pdf_text(certificate_pdf_bytes(document))
    both = pdf_text(certificate_pdf_bytes(replace(
        document, metadata=replace(document.metadata, language="zh+en"))))
    quoted = "未说明“Dataacquisition(16-bitADC)”的角色"  # the text without its line breaks
    assert quoted in "".join(zh.split()) and quoted in "".join(both.split())
    assert "未说明Data" not in "".join(zh.split())
    assert "no role is stated for Data acquisition (16-bit ADC) and" in both  # English as it was


def test_a_translation_that_quotes_the_name_keeps_its_quotes_before_the_catalogue_has_ours():
    """Until the catalogue holds “{typed_name}”, a translation's own quotes stay (no name left
    bare where the catalogue already quoted it); with it, the name is quoted once."""
    from models.fringe import MEASURAND_STANDARDS
    from models.fringe.analysis import ROLES_STATED_ONLY

    meta = CertificateMetadata.from_dict({"standards": [ADC_NO_ROLE]})
    gaps = traceability_gaps(meta, MEASURAND_STANDARDS, (), ROLES_STATED_ONLY)
    zh = in_language(gaps[0], translator("zh_CN"))  # the catalogue as it is
    if translator("zh_CN")("{typed_name}") == "{typed_name}":
        assert "未说明“Data acquisition (16-bit ADC)”的角色" in zh, zh
    assert "未说明Data" not in zh and "““" not in zh, zh
