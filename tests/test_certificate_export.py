"""Certificates and results exports from each bundled sample, parsed back."""

from __future__ import annotations

import io
import json
import re
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from openpyxl import load_workbook
from pypdf import PdfReader

from app.writers.certificate_pdf import certificate_pdf_bytes, font_files
from app.writers.results_export import neutralise, results_csv_bytes, results_xlsx_bytes
from models.certificate.metadata import CertificateMetadata, MetadataError
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS
from models.uncertainty.conformity import uncertainty_decimals

SAMPLES = Path(__file__).resolve().parents[1] / "resources" / "samples"

META = CertificateMetadata.from_dict({
    "certificate_number": "AB-2026-0042", "lab_name": "精密角度计量实验室 Precision Angle Lab",
    "customer_name": "长春光机所 CIOMP", "item_description": "Encoder RX-26", "item_serial": "SN-1",
    "calibration_date": "2026-11-20", "issue_date": "2026-11-24", "created": "2026-11-24T10:00:00",
    "operator": "王工", "approver": "Dr. Li", "tolerance_arcsec": 3,
    "standards": [{"description": "Reference AC", "certificate_no": "NIM-1", "uncertainty_arcsec": 0.4}],
    "notes": "=cmd|' /C calc'!A0 <b>x</b> 备注"})


def _meta(key):
    """The example details; the polygon takes its tolerance from its grade alone."""
    return replace(META, tolerance_arcsec=None) if key == "polygon" else META


def _analysed(key):
    kind = KINDS[key]
    table = read_table(SAMPLES / kind.sample_file)
    parsed = ReadingsSheet(kind.columns, map_columns(table, kind.columns)).parse()
    return kind, kind.analyze(parsed, kind.settings_with_defaults({}))


def _text(pdf: bytes) -> tuple[str, int]:
    reader = PdfReader(io.BytesIO(pdf))
    return "\n".join(page.extract_text() for page in reader.pages), len(reader.pages)


@pytest.mark.parametrize("key", sorted(KINDS))
def test_certificate_of_each_sample_carries_its_figures(key):
    kind, result = _analysed(key)
    document = kind.certificate_document(result, _meta(key), kind.sample_file)
    pdf = certificate_pdf_bytes(document)
    text, pages = _text(pdf)
    flat = re.sub(r"\s+", " ", text)
    assert f"Page {pages} of {pages}" in flat and "Page 1 of" in flat
    assert "AB-2026-0042" in flat and "长春光机所" in flat and "王工" in flat
    big_u = document.expanded_uncertainty_arcsec
    assert f"U = {big_u:.{uncertainty_decimals(big_u)}f}\"" in flat
    assert "Decision rule" in flat and "DRAFT" not in flat
    for row in document.parameters.rows[:3]:  # the identified parameters, as printed
        assert row[1] in flat
    for row in document.statistics.rows:
        assert row[1] in flat
    json_out = kind.to_json(result)
    if key == "theodolite":
        assert f"{json_out['psi_deg']:.5f}°" in flat
    if key == "polygon":
        assert f"{json_out['pyramidal_tilt_arcsec']:.1f}\"" in flat
    if key == "fringe":
        assert f"{json_out['compensated_peak_to_peak_arcsec']:.3f}\"" in flat
    # U on the certificate is the budget's: k from each point's ν_eff
    budget = document.budget
    assert document.expanded_uncertainty_arcsec == pytest.approx(
        float(np.max(budget.coverage_factors * budget.combined_arcsec)))
    assert f"k = {budget.coverage_factor:.2f}" in flat


def test_certificate_is_deterministic_and_marks_drafts():
    kind, result = _analysed("polygon")
    doc = kind.certificate_document(result, _meta("polygon"), "p.csv")
    assert certificate_pdf_bytes(doc) == certificate_pdf_bytes(doc)
    draft = kind.certificate_document(result, CertificateMetadata(created="2026-01-01T00:00:00"))
    text, _ = _text(certificate_pdf_bytes(draft))
    assert "DRAFT" in text and "customer" in text


def test_polygon_certificate_prints_every_warning_of_the_window():
    kind, result = _analysed("polygon")
    text, _ = _text(certificate_pdf_bytes(kind.certificate_document(result, _meta("polygon"))))
    flat = re.sub(r"\s+", " ", text)
    assert "exceeds the 270\" allowed for grade 3" in flat  # the sample's 480" tilt, levelled
    assert "239\" worst case over the tilt direction, 250\" at ω = 90°" in flat
    assert "Common zero face 1 of set 1" in flat
    for w in result.warnings:
        assert re.sub(r"\s+", " ", w)[:60] in flat


@pytest.mark.parametrize("details, message", [
    ({"tolerance_arcsec": 5}, "tolerance of ±5\" but the workbench is set to grade 3"),
    ({"item_grade": "grade 5 (±5\")"}, "say 'grade 5 \\(±5\"\\)' but the workbench is set to grade 3"),
])
def test_polygon_grade_has_one_source(details, message):
    kind, result = _analysed("polygon")
    with pytest.raises(MetadataError, match=message):
        kind.certificate_document(result, replace(_meta("polygon"), **details))
    same = replace(_meta("polygon"), tolerance_arcsec=1.0, item_grade="grade 3")
    assert kind.certificate_document(result, same).tolerance_arcsec == 1.0


def test_hostile_text_neither_breaks_the_page_nor_becomes_markup():
    kind, result = _analysed("theodolite")
    long_word = "W" * 400
    meta = CertificateMetadata.from_dict({
        **META.to_dict(), "customer_name": long_word, "item_description": "<b>bold</b> **x** {nb}",
        "notes": "\n".join(["第一行 line"] * 60)})
    text, pages = _text(certificate_pdf_bytes(kind.certificate_document(result, meta)))
    flat = re.sub(r"\s+", "", text)
    assert "W" * 150 in flat  # wrapped, not cut
    assert "<b>bold</b>**x**{nb}" in flat  # printed as typed
    assert pages >= 4


def test_bundled_fonts_exist_and_cover_chinese():
    from fontTools.ttLib import TTFont

    files = font_files()
    with TTFont(files["cjk"]) as cjk, TTFont(files["regular"]) as latin:
        assert all(ord(ch) in cjk.getBestCmap() for ch in "精密角度计量实验室备注")
        assert all(ord(ch) in latin.getBestCmap() for ch in "ψαβω±°″")


@pytest.mark.parametrize("text, safe", [("=1+2", "'=1+2"), ("+A1", "'+A1"), ("-2", "'-2"),
                                        ("@SUM(A1)", "'@SUM(A1)"), ("\t=x", "'\t=x"), ("ok", "ok")])
def test_neutralise(text, safe):
    assert neutralise(text) == safe


def test_results_csv_and_xlsx():
    kind, result = _analysed("theodolite")
    doc = kind.certificate_document(result, META, "t.csv")
    csv_text = results_csv_bytes(doc).decode("utf-8-sig").splitlines()
    assert csv_text[0].split(",")[:3] == ["theta_deg", "raw_error_arcsec", "correction_arcsec"]
    assert len(csv_text) == result.theta_deg.size + 1
    first = [float(v) for v in csv_text[1].split(",")]
    assert first[3] == pytest.approx(result.corrected_error_arcsec[0])
    book = load_workbook(io.BytesIO(results_xlsx_bytes(doc)))
    assert book.sheetnames == ["Results", "Parameters", "Statistics", "Uncertainty budget",
                               "Certificate"]
    assert book["Results"].cell(2, 4).value == pytest.approx(result.corrected_error_arcsec[0])
    values = [row[1] for row in book["Certificate"].iter_rows(values_only=True)]
    notes = next(v for v in values if isinstance(v, str) and "calc" in v)
    assert notes.startswith("'=")
    for ws in book.worksheets:  # no cell anywhere is a formula
        for row in ws.iter_rows():
            for cell in row:
                assert cell.data_type != "f"


def test_cli_writes_certificate_and_results(tmp_path):
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps(META.to_dict(), ensure_ascii=False), encoding="utf-8")
    pdf, xlsx = tmp_path / "c.pdf", tmp_path / "r.xlsx"
    done = subprocess.run([sys.executable, "-m", "app", "analyze", "fringe",
                           str(SAMPLES / "fringe_sample.csv"), "--certificate", str(pdf),
                           "--metadata", str(meta), "--results", str(xlsx)],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    assert pdf.read_bytes().startswith(b"%PDF") and xlsx.stat().st_size > 0
    bad = tmp_path / "bad.json"
    bad.write_text('{"humidity_pct": "wet"}', encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "app", "analyze", "fringe",
                           str(SAMPLES / "fringe_sample.csv"), "--certificate", str(pdf),
                           "--metadata", str(bad)], capture_output=True, text=True, check=False)
    assert done.returncode == 2
    assert "bad.json" in done.stderr and "humidity_pct" in done.stderr
    assert "Traceback" not in done.stderr


def test_text_no_bundled_font_can_print_is_refused_not_dropped(samples_dir):
    import pytest as _pytest

    from app.writers.certificate_pdf import certificate_pdf_bytes
    from models.certificate.metadata import CertificateMetadata
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.registry import KINDS

    kind = KINDS["theodolite"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))
    korean = kind.certificate_document(result, CertificateMetadata(customer_name="한국광학 Ltd"))
    with _pytest.raises(ValueError, match="no bundled font can print: '한국광학'"):
        certificate_pdf_bytes(korean)
    chinese = kind.certificate_document(result, CertificateMetadata(customer_name="长春光电"))
    assert certificate_pdf_bytes(chinese).startswith(b"%PDF")


def test_a_bilingual_certificate_has_chinese_headings_beside_the_english(samples_dir):
    import io
    import re

    from pypdf import PdfReader

    from app.writers.certificate_pdf import certificate_pdf_bytes
    from models.certificate.metadata import CertificateMetadata, MetadataError
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.registry import KINDS

    kind = KINDS["polygon"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))

    def text(language):
        document = kind.certificate_document(result, CertificateMetadata(
            language=language, certificate_number="AB-1", customer_name="长春光电"))
        pages = PdfReader(io.BytesIO(certificate_pdf_bytes(document))).pages
        return re.sub(r"\s+", " ", " ".join(p.extract_text() for p in pages))

    both, english = text("zh+en"), text("en")
    for words in ("校准证书 Calibration certificate", "证书编号 Certificate number",
                  "测量不确定度 Measurement uncertainty", "符合性声明 Statement of conformity"):
        assert words in both
    assert "校准证书" not in english and "Calibration certificate" in english
    with pytest.raises(MetadataError, match="'language' must be one of en, zh, zh\\+en"):
        CertificateMetadata.from_dict({"language": "fr"})
