"""A certificate in Chinese (#18): every sample's certificate, passing, failing, judged
per point, a draft, an amendment and a replacement, printed with the language "zh" and
read back from the PDF. No English of ours is left (the lab's own details, the method's
published reference and symbols such as sin, cos, rad stay as written), and every figure
of the English certificate is on the Chinese one, unchanged."""

from __future__ import annotations

import collections
import json
import re
from dataclasses import replace
from pathlib import Path

import pypdfium2 as pdfium
import pytest

from app.writers.certificate_pdf import certificate_pdf_bytes
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

pytestmark = pytest.mark.slow  # every test prints certificates (fringe: 512 rows)

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"

VARIANTS = {
    "as issued": {},
    "judged per point": {"decision_quantity": "points"},
    "simple acceptance": {"decision_rule": "simple"},
    "binary with guard band": {"decision_rule": "guarded_binary"},
    "draft of an amendment": {"certificate_number": "", "standards": [],
                              "revision": "amendment 2", "supersedes": "AB-2026-0001",
                              "change_note": "客户地址更正"},
    "replacement": {"revision": "replacement", "supersedes": "AB-2026-0001"},
}
#: what may stay in Latin letters: symbols, units and the names of standards and tools
SYMBOLS = {"sin", "cos", "rad", "zero", "ISO", "IEC", "GUM", "JCGM", "ILAC", "VIM", "CSV",
           "XLSX", "VDI", "DGQ", "Welch", "Satterthwaite", "AngleBench", "anglebench",
           "validate", "CNAS", "atan", "dev", "asin", "ADC", "LSB", "git",
           "sha", "CMC", "Beran", "Louis", "Efron", "Tibshirani",
           "Romano", "Shaikh", "Wolf"}  # git: the software's commit; CMC: as CNAS writes it;
#: cited authors' names too
WORD = re.compile(r"(?<![\w.])[A-Za-z]{3,}(?![\w])")  # "down" of A_down is a symbol's
FIGURE = re.compile(r"[+-]?\d+\.\d+(?:\"|°| mV| V| %| rad)")


def _text(pdf: bytes) -> str:
    document = pdfium.PdfDocument(pdf)
    try:
        text = re.sub(r"\s+", " ", " ".join(document[i].get_textpage().get_text_range()
                                            for i in range(len(document))))
        return re.sub(r"(\d) (\"|°)", r"\1\2", text)  # a unit wrapped onto the next line
    finally:
        document.close()


@pytest.fixture(scope="module")
def analysed():
    out = {}
    for key, kind in KINDS.items():
        rows = map_columns(read_table(SAMPLES / kind.sample_file), kind.columns)
        settings = kind.settings_with_defaults(None)
        out[key] = (kind, kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings),
                    settings, json.loads((SAMPLES / f"certificate_{key}.json").read_text("utf-8")))
    return out


def _document(analysed, key: str, change: dict):
    kind, result, settings, details = analysed[key]
    metadata = CertificateMetadata.from_dict({**details, **change})
    return kind.certificate_document(result, metadata, kind.sample_file, settings)


def _printed(document, language: str) -> str:
    """The same certificate printed in ``language``."""
    return _text(certificate_pdf_bytes(replace(document, metadata=replace(
        document.metadata, language=language))))


def _their_words(document) -> list[str]:
    """What the lab and the method's authors wrote: printed as given."""
    meta = document.metadata.to_dict()
    texts = [str(v) for v in meta.values() if isinstance(v, str)]
    texts += [str(v) for s in meta.get("standards", []) for v in s.values() if isinstance(v, str)]
    return [*texts, document.method_reference, document.source_name]


@pytest.mark.parametrize("key", sorted(KINDS))
@pytest.mark.parametrize("variant", list(VARIANTS))
def test_a_chinese_certificate_has_every_figure_and_no_english_of_ours(analysed, key, variant):
    document = _document(analysed, key, VARIANTS[variant])
    chinese = _printed(document, "zh")
    theirs = " ".join(_their_words(document))
    # a word of the lab's may be broken across a line (a table cell wraps between letters)
    english = sorted(w for w in set(WORD.findall(chinese)) - SYMBOLS if w not in theirs)
    assert english == [], english
    assert "校准证书" in chinese and "测量不确定度" in chinese and "符合性声明" in chinese
    # every figure of the English certificate, as many times (none lost where a line breaks)
    english_text = _printed(document, "en")
    assert collections.Counter(FIGURE.findall(chinese)) == collections.Counter(
        FIGURE.findall(english_text))
    assert len(FIGURE.findall(english_text)) > 20


def test_the_english_certificate_is_not_touched_by_the_chinese_one(analysed):
    english = _printed(_document(analysed, "theodolite", {}), "en")
    assert not re.search("[\u4e00-\u9fff]", english.replace("精密角度计量实验室", "").replace(
        "长春光电有限公司", "").replace("王工", ""))


@pytest.mark.parametrize("language", ["en", "zh+en", "zh"])
def test_every_glyph_printed_and_no_word_broken_between_letters(analysed, language, caplog):
    """fpdf2 warns of a character no font has (a two-line heading printed its line break as
    a missing glyph, glued "分析设置Analysis settings" together); a Latin table cell is
    wrapped between words (a character wrap printed "t he seed's")."""
    for key in sorted(KINDS):
        document = _document(analysed, key, {})
        with caplog.at_level("WARNING", logger="fpdf"):
            printed = _printed(document, language)
        assert not [r for r in caplog.records if "missing" in r.getMessage()], key
        if language == "en":
            tables = (document.parameters, document.results, document.statistics)
            cells = [cell for t in tables for row in (t.header, *t.rows) for cell in row]
            words = {w for text in cells + [v for _, v in document.settings]
                     for w in re.findall(r"(?<![\w'])[A-Za-z]{5,}(?![\w'])", str(text))}
            broken = sorted(w for w in words if not re.search(rf"(?<![A-Za-z]){w}(?![A-Za-z])",
                                                               printed))
            assert broken == [], (key, broken)
