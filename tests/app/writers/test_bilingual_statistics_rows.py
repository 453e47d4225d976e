"""zh81: a bilingual ("zh+en") certificate printed its statistics table's rows and notes in
English only under the two-language heading "统计结果 Statistics" — the rows' names
("Points", "Raw error", "Decided quantity"), their notes ("peak-to-peak …", "largest over the
points …") and the note on figures printed without any coverage interval (a theodolite run of
one pass each way: models.uncertainty.without_interval_note). Each cell is now printed in
Chinese above its English, as the header is, and a cell too tall for a page (the decided
quantity's) below the table in Chinese, then in English. Read back from the printed PDF; the
Chinese is the catalogue's (resources/translations/anglebench_zh_CN.ts)."""

from __future__ import annotations

import json
import re
from dataclasses import replace
from pathlib import Path

import numpy as np
import pypdfium2 as pdfium
import pytest

from app.writers.certificate_pdf import certificate_pdf_bytes
from models.certificate.metadata import CertificateMetadata
from models.certificate.report_terms import report_translator
from models.messages import in_language, translator
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS
from models.uncertainty.without_interval_note import FIGURES_WITHOUT_INTERVAL_NOTE
from tests.theodolite_passes_simulator import passes_record

pytestmark = pytest.mark.slow  # prints certificates

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
ZH = translator("zh_CN")
_CJK = re.compile(r"[\u3000-\u9fff\uff00-\uffef]")


def _document(key: str, readings: Path, language: str):
    kind = KINDS[key]
    rows = map_columns(read_table(readings), kind.columns)
    settings = kind.settings_with_defaults(None)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings)
    details = json.loads((SAMPLES / f"certificate_{key}.json").read_text("utf-8"))
    document = kind.certificate_document(result, CertificateMetadata.from_dict(details),
                                         readings.name, settings)
    return replace(document, metadata=replace(document.metadata, language=language))


#: a page's foot (its notice in Chinese above the English) and the next page's head,
#: between which a paragraph may break
_NOTICES = "|".join(re.escape(ZH(f"This {what} shall not be reproduced except in full without "
                                 "the laboratory's written approval."))
                    for what in ("certificate", "report"))
_FOOT_AND_HEAD = re.compile(rf"(?:(?:{_NOTICES}).*?)?This (?:certificate|report) shall not.*?"
                            r"(?:Certificate|Test report) AB-\d+-\d+\s*$", re.S | re.M)


def _text(document) -> str:
    """The printed PDF's text, without each page's foot and head and without white space (a
    line breaks anywhere in Chinese)."""
    pdf = pdfium.PdfDocument(certificate_pdf_bytes(document))
    try:
        pages = "".join(pdf[i].get_textpage().get_text_range() for i in range(len(pdf)))
    finally:
        pdf.close()
    return re.sub(r"\s+", "", _FOOT_AND_HEAD.sub("", pages))


def _flat(text) -> str:
    return re.sub(r"\s+", "", str(text))


def _cells_with_chinese(document) -> list[tuple[str, str]]:
    """(Chinese, English) of every text cell of the statistics table the catalogue
    translates (a test report's in its own terms: 被检测对象)."""
    return _translated(document, [cell for row in document.statistics.rows for cell in row])


@pytest.fixture(scope="module")
def one_pass(tmp_path_factory):
    """A theodolite run of one pass each way: its figures get no coverage interval."""
    readings = tmp_path_factory.mktemp("zh81") / "one_pass.csv"
    passes_record(readings, np.random.default_rng(3), 1, 0.3, 0.5)
    return readings


def test_the_note_on_figures_without_an_interval_is_in_chinese_and_english(one_pass):
    """Fails before zh81: the one-pass theodolite's bilingual certificate printed the note
    in English only."""
    document = _document("theodolite", one_pass, "zh+en")
    notes = [cell for row in document.statistics.rows for cell in row
             if FIGURES_WITHOUT_INTERVAL_NOTE[:20] in str(cell)]
    assert len(notes) == 1, "the run's figures should have no coverage interval"
    chinese = _flat(in_language(notes[0], ZH))
    assert _CJK.search(chinese) and chinese.startswith("各项指标不给出包含区间"), chinese
    printed = _text(document)
    assert printed.count(chinese) == 1, chinese
    assert printed.count(_flat(notes[0])) == 1
    # the Chinese first, then the English of the same note
    assert printed.index(chinese) < printed.index(_flat(notes[0]))
    # with the same place and scatter as the English: 0.1″ and 0.23″
    assert '0.1"' in chinese and '0.23"' in chinese


@pytest.mark.parametrize("key", ["theodolite", "polygon", "fringe", "positioning", "crosscal"])
def test_every_statistics_row_of_a_bilingual_certificate_is_in_both(key):
    """Fails before zh81: "Points", "Raw error", "Decided quantity", "largest over the
    points; k = 2.00 there" … English only; every workbench's sample."""
    kind = KINDS[key]
    document = _document(key, SAMPLES / kind.sample_file, "zh+en")
    cells = _cells_with_chinese(document)
    assert len(cells) >= 3, cells  # rows' names and notes the catalogue translates
    printed = _text(document)
    for chinese, english in cells:
        assert _flat(chinese) in printed, (key, chinese)
        assert _flat(english) in printed, (key, english)


def test_a_decided_quantity_moved_below_the_table_is_in_both(one_pass):
    """The decided quantity's note, too tall for its cell, is printed below the table
    once in Chinese ("[1] 判定的量：…") and once in English ("[1] Decided quantity: …")."""
    document = _document("theodolite", SAMPLES / KINDS["theodolite"].sample_file, "zh+en")
    printed = _text(document)
    assert printed.count("[1]判定的量：") == 1
    assert printed.count("[1]Decidedquantity:") == 1
    assert printed.index("[1]判定的量：") < printed.index("[1]Decidedquantity:")


def test_the_english_and_chinese_certificates_print_the_statistics_once(one_pass):
    """The English certificate keeps its statistics in English alone (the sample lab's
    name is its own, in both); the Chinese one gives the note in Chinese alone."""
    english = _text(_document("theodolite", one_pass, "en"))
    statistics = english[english.index("Statistics"):english.index("Measurementuncertainty")]
    assert "Nocoverageintervalisgivenforthefigures" in statistics
    assert not _CJK.search(statistics.replace("精密角度计量实验室", ""))
    assert "Nocoverageintervalisgivenforthefigures" in english
    chinese = _text(_document("theodolite", one_pass, "zh"))
    assert chinese.count("各项指标不给出包含区间") == 1
    assert "Nocoverageinterval" not in chinese


def _translated(document, texts) -> list[tuple[str, str]]:
    """(Chinese, English) of each of ``texts`` the catalogue translates."""
    words = report_translator(ZH) if document.is_test_report else ZH
    out = []
    for text in texts:
        if isinstance(text, str) and text:
            chinese = in_language(text, words)
            if chinese != str(text):
                out.append((chinese, str(text)))
    return out


@pytest.mark.parametrize("key", ["theodolite", "polygon", "fringe", "positioning", "crosscal"])
def test_every_label_and_row_the_assessor_reads_is_in_both(key):
    """Fails before zh81: under their two-language headings a bilingual certificate printed
    the analysis settings, the parameters' table (its title too: "Set-up parameters
    identified"), the budget's inputs and notes, the results' note, the plots' titles, axes
    and legends, the place of calibration, the environment and the signatures' "Signature
    and date" in English only."""
    kind = KINDS[key]
    document = _document(key, SAMPLES / kind.sample_file, "zh+en")
    texts = [
        *(text for row in document.settings for text in row),
        document.parameters.title,
        *(cell for row in document.parameters.rows for cell in row),
        *(component.name for component in document.budget.components),
        document.results.note,
        *(text for figure in document.plots
          for text in (figure.title, figure.x_label, figure.y_label,
                       *(series.label for series in figure.series if series.label))),
        "Signature and date",
    ]
    pairs = _translated(document, texts)
    assert len(pairs) >= 10, pairs
    printed = _text(document)
    for chinese, english in pairs:
        assert _flat(chinese) in printed, (key, chinese)
        assert _flat(english) in printed, (key, english)
    for chinese, english in (("在实验室内", "atthelaboratory"), ("温度", "temperature")):
        assert chinese in printed and english in printed, (key, chinese)
