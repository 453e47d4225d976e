"""Assessment 78 L9: the zh+en certificate's title was in both languages, "校准证书
Calibration certificate", and under it the workbench's name in English alone ("Polygon
encoder test"). It is in both, Chinese first, as the title; a Chinese certificate has the
Chinese alone and an English one the English."""

from __future__ import annotations

from dataclasses import replace

import pytest

from app.writers.certificate_pdf import certificate_pdf_bytes
from models.messages import translator
from tests.models.certificate.test_certificate_statements import _sample
from tests.models.certificate.test_printed_rounding import _bundled
from tests.pdf_text import pdf_text


@pytest.fixture(scope="module")
def document():
    kind, result = _sample("polygon")
    return kind.certificate_document(result, _bundled("polygon"))


@pytest.mark.parametrize("language", ["zh+en", "zh", "en"])
def test_the_workbench_is_named_under_the_title_in_the_certificates_languages(document,
                                                                              language):
    chinese = translator("zh_CN")("Polygon encoder test")
    assert chinese == "多面棱体编码器检测"
    printed = replace(document, metadata=replace(document.metadata, language=language))
    head = pdf_text(certificate_pdf_bytes(printed))[:200]
    expected = {"zh+en": "校准证书 Calibration certificate 多面棱体编码器检测 Polygon encoder test",
                "zh": "校准证书 多面棱体编码器检测 证书编号",
                "en": "Calibration certificate Polygon encoder test Certificate number"}
    assert expected[language] in head, head
