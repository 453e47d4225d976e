"""The certificate's "Readings" line as day review 68 (F12) found it wanting: on a zh+en
certificate it was in English only under "原始记录 Readings", where every other line of the
heading is in both languages; on a Chinese one the "），" after the imported file's SHA-256
began a line of its own making (the digest fills a line at 9 pt, and the marks cannot hang
after it) where a slightly smaller size holds them on the digest's line; and a certificate
exported over a PDF the register issued was refused naming the path twice ("/…/x.pdf:
/…/x.pdf is the PDF of certificate …"). Each on the real window and a printed certificate."""

from __future__ import annotations

import hashlib
import json

import pytest

from models.certificate.metadata import CertificateMetadata
from tests.pdf_text import CLOSING, pdf_lines

pytestmark = pytest.mark.slow  # certificates printed from the window



def _issue(window, qtbot, tmp_path, samples_dir, name: str, language: str, pdf: str,
           number: str = "") -> str:
    """The polygon sample imported as ``name``, one reading typed over, issued in
    ``language`` to ``pdf``; returns the file's SHA-256."""
    polygon = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    csv = tmp_path / name
    csv.write_bytes((samples_dir / polygon.kind.sample_file).read_bytes())
    polygon.import_file(csv)
    polygon.table_model.set_cells([(3, polygon.sheet.column_index("ac_x_arcsec"), "20.00")])
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    data.update({"certificate_number": number, "language": language,
                 "example": not number})
    window.certificates.edit_details = lambda shown: CertificateMetadata.from_dict(data)
    window.certificates.view.confirm_standards = lambda warnings: True
    window.certificates.view.confirm_test_report = lambda why: True
    window.certificates.view.choose_save_path = lambda title, suggested, kinds: pdf
    return hashlib.sha256(csv.read_bytes()).hexdigest()


def _readings(lines: list[str], name: str) -> list[str]:
    first = next(i for i, line in enumerate(lines) if name in line)
    last = next(i for i in range(len(lines) - 1, first - 1, -1)
                if "edited in AngleBench" in lines[i] or "编辑过" in lines[i])
    return lines[first:last + 1]


def test_a_bilingual_certificates_readings_line_is_in_chinese_and_in_english(
        window, qtbot, tmp_path, samples_dir):
    name = "bench_0512.csv"
    digest = _issue(window, qtbot, tmp_path, samples_dir, name, "zh+en",
                    str(tmp_path / "both.pdf"))
    assert window.export_certificate(), window.told
    said = " ".join(_readings(pdf_lines(tmp_path / "both.pdf"), name))
    # the Chinese (导入自 …，导入后在 AngleBench 中编辑过), then the English, each with the digest
    assert "导入自" in said and "imported from" in said, said
    assert said.index("导入自") < said.index("imported from"), said
    assert said.count(digest) == 2, said


@pytest.mark.parametrize("name", ["r.csv", "bench_run_0512.csv"])
def test_no_line_of_the_chinese_readings_line_begins_with_a_closing_mark(
        window, qtbot, tmp_path, samples_dir, name):
    digest = _issue(window, qtbot, tmp_path, samples_dir, name, "zh",
                    str(tmp_path / "zh.pdf"))
    assert window.export_certificate(), window.told
    said = _readings(pdf_lines(tmp_path / "zh.pdf"), name)
    assert any(digest in line for line in said), said  # whole, on one line
    assert not [line for line in said[1:] if line[:1] in CLOSING], said
    line = next(line for line in said if digest in line)
    assert line.endswith(digest + "），") or line.endswith(digest + "）"), said


@pytest.mark.usefixtures("pdf_stand_in")  # of the refusal's words: no page read
def test_the_refusal_of_an_issued_pdf_names_its_path_once(window, qtbot, tmp_path, samples_dir):
    pdf = str(tmp_path / "issued.pdf")
    _issue(window, qtbot, tmp_path, samples_dir, "r.csv", "en", pdf, number="AB-2026-0068")
    assert window.export_certificate(), window.told
    issued = (tmp_path / "issued.pdf").read_bytes()
    window.told.clear()
    _issue(window, qtbot, tmp_path, samples_dir, "r.csv", "en", pdf, number="AB-2026-0069")
    assert not window.export_certificate()
    refusal = next(text for text in window.told if "never replaced" in text)
    assert refusal.count(pdf) == 1, refusal
    assert refusal.startswith(pdf + " is the PDF of certificate AB-2026-0068"), refusal
    assert (tmp_path / "issued.pdf").read_bytes() == issued
