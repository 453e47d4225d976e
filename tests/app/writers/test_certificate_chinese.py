"""A certificate in Chinese (#18): every sample's certificate, passing, failing, judged
per point, a draft, an amendment and a replacement, printed with the language "zh" and
read back from the PDF. No English of ours is left (the lab's own details, the method's
published reference and symbols such as sin, cos, rad stay as written), and every figure
of the English certificate is on the Chinese one, unchanged.

The suite prints each workbench's certificate as issued and with two of the other five
variants, each variant for two workbenches (``COVERING``: 15 of the 30);
tests/benchmarks/test_certificate_chinese_full.py prints all 30 (`make bench`)."""

from __future__ import annotations

import collections
import json
import re
from collections.abc import Callable
from pathlib import Path
from typing import NamedTuple

import pytest

from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS
from tests.app.test_no_in_house_names import IN_HOUSE
from tests.pdf_text import pdf_text as _text

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
SYMBOLS = {"sin", "cos", "rad", "zero", "ISO", "IEC", "GUM", "JCGM", "ILAC", "VIM", "CSV", "ASTM",
           "XLSX", "VDI", "DGQ", "Welch", "Satterthwaite", "AngleBench", "anglebench",
           "validate", "CNAS", "atan", "dev", "asin", "ADC", "LSB", "git",
           "sha", "SHA", "CMC", "Beran", "Louis", "Shen", "Efron", "Tibshirani", "Berger", "Boos",
           "Romano", "Shaikh", "Wolf", "Owen", "Bonferroni", "max"}
#: git: the software's commit; CMC: as CNAS writes it; cited authors' names too (Owen,
#: Bonferroni: A's and P's tolerance bounds, 0.8.17); max: the operator of a formula (z · 2 max u)
WORD = re.compile(r"(?<![\w.])[A-Za-z]{3,}(?![\w])")  # "down" of A_down is a symbol's
FIGURE = re.compile(r"[+-]?\d+\.\d+(?:\"|°| mV| V| %| rad)")


class Samples(NamedTuple):
    """Every sample analysed (workbench → (kind, result, settings, its example's details)),
    and ``printed``: tests/conftest.py's ``sample_certificates``."""

    analysed: dict[str, tuple]
    printed: Callable[..., tuple[bytes, list[str]]]


@pytest.fixture(scope="module")
def analysed(sample_certificates):
    out = {}
    for key, kind in KINDS.items():
        rows = map_columns(read_table(SAMPLES / kind.sample_file), kind.columns)
        settings = kind.settings_with_defaults(None)
        out[key] = (kind, kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings),
                    settings, json.loads((SAMPLES / f"certificate_{key}.json").read_text("utf-8")))
    return Samples(out, sample_certificates)


def _document(analysed, key: str, change: dict):
    kind, result, settings, details = analysed.analysed[key]
    metadata = CertificateMetadata.from_dict({**details, **change})
    return kind.certificate_document(result, metadata, kind.sample_file, settings)


#: (workbench, variant, language) → the printed text and fpdf2's missing-glyph warnings: a
#: sample's certificate is printed once a run (tests/conftest.py's ``sample_certificates``:
#: each takes ~1–3 s; the glyph check reads the ones the figures check printed, and the
#: bilingual and manufacturer's term tests some of them) and read once a process
_PRINTS: dict[tuple[str, str, str], tuple[str, list[str]]] = {}


def _sample_printed(analysed, key: str, variant: str, language: str) -> tuple[str, list[str]]:
    """The sample certificate of ``key`` in ``variant``, printed in ``language`` (once)."""
    if (key, variant, language) not in _PRINTS:
        pdf, missing = analysed.printed(key, language, VARIANTS[variant])
        _PRINTS[key, variant, language] = (_text(pdf), missing)
    return _PRINTS[key, variant, language]


def _their_words(document) -> list[str]:
    """What the lab and the method's authors wrote: printed as given."""
    meta = document.metadata.to_dict()
    texts = [str(v) for v in meta.values() if isinstance(v, str)]
    texts += [str(v) for s in meta.get("standards", []) for v in s.values() if isinstance(v, str)]
    return [*texts, document.method_reference, document.source_name]


#: (workbench, variant): every workbench as issued, and workbench i with the other variants
#: 2i and 2i + 1 (mod 5), so each of those is printed for two workbenches
COVERING = [(key, variant) for i, key in enumerate(sorted(KINDS)) for variant in (
    "as issued", list(VARIANTS)[1 + (2 * i) % 5], list(VARIANTS)[1 + (2 * i + 1) % 5])]


@pytest.mark.parametrize(("key", "variant"), COVERING)
def test_a_chinese_certificate_has_every_figure_and_no_english_of_ours(analysed, key, variant):
    check_chinese_certificate(analysed, key, variant)


def check_chinese_certificate(analysed, key: str, variant: str) -> None:
    """``key``'s sample certificate in ``variant`` printed in Chinese: no English of ours, and
    every figure of the English one as many times."""
    document = _document(analysed, key, VARIANTS[variant])
    chinese = _sample_printed(analysed, key, variant, "zh")[0]
    theirs = " ".join(_their_words(document))
    # a word of the lab's may be broken across a line (a table cell wraps between letters)
    english = sorted(w for w in set(WORD.findall(chinese)) - SYMBOLS if w not in theirs)
    assert english == [], english
    assert "校准证书" in chinese and "测量不确定度" in chinese and "符合性声明" in chinese
    # every figure of the English certificate, as many times (none lost where a line breaks)
    english_text = _sample_printed(analysed, key, variant, "en")[0]
    assert collections.Counter(FIGURE.findall(chinese)) == collections.Counter(
        FIGURE.findall(english_text))
    assert len(FIGURE.findall(english_text)) > 20


def test_the_english_certificate_is_not_touched_by_the_chinese_one(analysed):
    english = _sample_printed(analysed, "theodolite", "as issued", "en")[0]
    assert not re.search("[\u4e00-\u9fff]", english.replace("精密角度计量实验室", "").replace(
        "长春光电有限公司", "").replace("王工", ""))


@pytest.mark.parametrize("language", ["en", "zh+en", "zh"])
def test_every_glyph_printed_and_no_word_broken_between_letters(analysed, language):
    """fpdf2 warns of a character no font has (a two-line heading printed its line break as
    a missing glyph, glued "分析设置Analysis settings" together); a Latin table cell is
    wrapped between words (a character wrap printed "t he seed's")."""
    for key in sorted(KINDS):
        document = _document(analysed, key, {})
        printed, missing = _sample_printed(analysed, key, "as issued", language)
        assert missing == [], key
        if language == "en":
            tables = (document.parameters, document.results, document.statistics)
            cells = [cell for t in tables for row in (t.header, *t.rows) for cell in row]
            words = {w for text in cells + [v for _, v in document.settings]
                     for w in re.findall(r"(?<![\w'])[A-Za-z]{5,}(?![\w'])", str(text))}
            broken = sorted(w for w in words if not re.search(rf"(?<![A-Za-z]){w}(?![A-Za-z])",
                                                               printed))
            assert broken == [], (key, broken)


@pytest.mark.parametrize("language", ["en", "zh+en", "zh"])
def test_no_sample_certificate_names_a_paper_by_our_in_house_name(analysed, language):
    """The method's paper is named ("Tian et al. 2017", its full reference under the
    method), never "the seed's …" (assessor: the theodolite's certificate printed "the
    negative of the seed's A − θ" and "taken as the seed's E", the polygon's "the seed's
    eqs 3–7"); the Monte Carlo's "seed 1234…" stays (tests/app/test_no_in_house_names.py)."""
    for key in sorted(KINDS):
        printed = _sample_printed(analysed, key, "as issued", language)[0]
        assert IN_HOUSE.findall(printed) == [], key
    if language == "en":  # each paper named where the reader meets it, in full once
        theodolite = _sample_printed(analysed, "theodolite", "as issued", "en")[0]
        assert "the negative of A − θ in the published method (Tian et al. 2017)" in theodolite
        assert "Acta Photonica Sinica 46(11):1112005 (2017)" in theodolite
        assert "eqs 3–7 of the published method, Tian et al. 2015," in _sample_printed(
            analysed, "polygon", "as issued", "en")[0]
