"""A bilingual ("zh+en") certificate gives the customer's key sentence, the statement of
conformity, in Chinese and then in English, with the same figures (assessor, item 13), and
its statements and remarks too; a Chinese ("zh") one joins the statement's Chinese parts
with full-width punctuation (item 14). Read back from the printed PDF."""

from __future__ import annotations

import json
import re
from dataclasses import replace
from pathlib import Path
from typing import Any

import pypdfium2 as pdfium
import pytest

from app.writers.certificate_pdf import certificate_pdf_bytes
from models.certificate.metadata import CertificateMetadata
from models.messages import in_language, translator
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

pytestmark = pytest.mark.slow  # prints certificates

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
ZH = translator("zh_CN")
_NOTICE_ZH = ZH("This certificate shall not be reproduced except in full without the "
                "laboratory's written approval.")


#: the module's sample document and tests/conftest.py's ``sample_certificates`` (set by
#: ``theodolite``): the sample's certificate is printed once a run in each language (the
#: Chinese certificate's tests print the same ones; this module printed zh+en twice)
_SAMPLE: dict[str, Any] = {}


@pytest.fixture(scope="module")
def theodolite(sample_certificates):
    kind = KINDS["theodolite"]
    rows = map_columns(read_table(SAMPLES / kind.sample_file), kind.columns)
    settings = kind.settings_with_defaults(None)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings)
    details = json.loads((SAMPLES / "certificate_theodolite.json").read_text("utf-8"))
    document = kind.certificate_document(result, CertificateMetadata.from_dict(details),
                                         kind.sample_file, settings)
    _SAMPLE.update(document=document, printed=sample_certificates)
    return document


def _printed(document, language: str) -> str:
    """The PDF's text in ``language``, without its line breaks and spaces (a line may
    break between two Chinese characters), and without each page's foot and head. The
    sample's document (``theodolite``) is the sample certificate printed once a run (the
    same document, :data:`_SAMPLE`); any other is printed here."""
    if document is _SAMPLE.get("document"):
        printed = _SAMPLE["printed"]("theodolite", language)[0]
    else:
        printed = certificate_pdf_bytes(replace(document, metadata=replace(
            document.metadata, language=language)))
    pdf = pdfium.PdfDocument(printed)
    try:
        pages = [pdf[i].get_textpage().get_text_range() for i in range(len(pdf))]
    finally:
        pdf.close()
    # a bilingual foot's notice in Chinese above the English (zh81)
    foot_and_head = re.compile(rf"(?:{re.escape(_NOTICE_ZH)}.*?)?This certificate shall not.*?"
                               r"Certificate AB-\d+-\d+\s*$|"
                               r"本证书未经.*?证书 AB-\d+-\d+\s*$", re.S | re.M)
    return re.sub(r"\s+", "", foot_and_head.sub("", "".join(pages)))


def _flat(text: str) -> str:
    return re.sub(r"\s+", "", text)


def _section(text: str, start: str, end: str) -> str:
    return text[text.index(start) + len(start):text.index(end, text.index(start) + len(start))]


def test_a_bilingual_certificate_states_conformity_in_chinese_then_english(theodolite):
    """Fails on the old code: the bilingual certificate printed the statement in English
    only."""
    c = theodolite.conformity
    section = _section(_printed(theodolite, "zh+en"), "符合性声明Statementofconformity",
                       "声明Statements")
    chinese, english = _flat(in_language(c.statement, ZH)), _flat(c.statement)
    assert chinese != english and chinese in section and english in section
    assert section.index(chinese) < section.index(english)
    # the same value, interval and U in both, each read from the printed text
    # U₋, U₊ the printed value to the printed ends (0.8.19: value ± U is the printed interval
    # 0.01″ … 1.45″; −0.93″/+0.49″ to the nearest before)
    value, u = f"{c.value:.2f}\"", "−0.94\"/+0.50\""
    assert f"：{value}" in chinese and f"U={u}" in chinese
    assert f":{value}" in english and f"U={u}" in english
    assert section.count(f"U={u}") == 2
    # the rule, the decided quantity and the zones in both languages too
    for text in (c.rule, c.quantity, c.zones):
        assert _flat(in_language(text, ZH)) in section and _flat(text) in section
    # the statements in both languages; the results table not doubled
    statements = _section(_printed(theodolite, "zh+en"), "声明Statements", "备注Remarks")
    fixed = "The results relate only to the item calibrated, as received, under the conditions stated."
    assert _flat(fixed) in statements and _flat(ZH(fixed)) in statements


def test_a_chinese_statement_of_conformity_has_no_ascii_separator_between_chinese_parts(
        theodolite):
    """Fails on the old code: "随机种子 928363538; 该区间…", "…（合格）。 本判定…"."""
    section = _section(_printed(theodolite, "zh"), "符合性声明", "声明•")
    assert "随机种子" in section and "；该区间在验证中达到的包含概率" in section
    assert not re.search(r"[\u4e00-\u9fff（）\d][;,][\u4e00-\u9fff（]", section), section
    english = _printed(theodolite, "en")
    # every figure of the English statement, unchanged
    figures = re.compile(r"\d+\.\d+\"")
    assert figures.findall(section) == figures.findall(
        _section(english, "Statementofconformity", "Statements"))


def test_traceability_method_and_uncertainty_in_chinese_then_english(theodolite):
    """The traceability statement, the method (and what validates it) and the measurement
    uncertainty's paragraph (U, k, p, the GUM) of a bilingual certificate in Chinese, then
    in English, from the one message with the same figures (assessment 76 L1: English only,
    where CNAS assessors read them in Chinese); the Chinese the catalogue's, as on a Chinese
    certificate."""
    from app.writers.certificate_pdf.traceability import _traceability

    printed = _printed(theodolite, "zh+en")
    chinese_only = _printed(theodolite, "zh")
    traced = _traceability(theodolite)
    sections = (
        ("计量标准及计量溯源性Referencestandardsandtraceability", "校准方法Method", [traced]),
        ("校准方法Method", "符号约定Signconvention", [theodolite.method]),
        ("测量不确定度Measurementuncertainty", "输入量Input", []),
    )
    for start, end, texts in sections:
        section = _section(printed, start, end)
        for text in texts:
            chinese, english = _flat(in_language(text, ZH)), _flat(text)
            assert chinese != english and chinese in section and english in section, text
            assert section.index(chinese) < section.index(english)
            assert chinese in chinese_only  # the Chinese certificate's own words
    uncertainty = _section(printed, "测量不确定度Measurementuncertainty", "输入量Input")
    english = re.search(r"TheexpandeduncertaintyoftheerrorisU=([\d.]+)\".*?k=([\d.]+)\..*?"
                        r"GUM\(JCGM100:2008\)\.", uncertainty)
    assert english, uncertainty
    chinese = uncertainty[:english.start()]
    assert "包含因子" in chinese and "包含概率" in chinese and "95.45%" in chinese, chinese
    # the same U and k in both
    assert f"U={english[1]}\"" in chinese and f"k={english[2]}" in chinese, chinese
    assert "按GUM（JCGM100:2008）评定" in chinese
