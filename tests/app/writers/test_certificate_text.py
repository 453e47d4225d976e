"""Text on the certificate (issue 40 item 13): blank lines and long words in any script, a
long laboratory name that never prints over the certificate number, right-to-left script
refused (it would print reversed), invisible and control characters and fields over their
limit refused, never removed or cut unseen. Read back with poppler's pdftotext -bbox."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from app.main import main
from app.writers.certificate_pdf import certificate_pdf_bytes
from models.certificate.metadata import CertificateMetadata, MetadataError
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
PAGE_WIDTH_PT = 595.28
MARGIN_PT = 18 / 25.4 * 72


@pytest.fixture(scope="module")
def theodolite():
    kind = KINDS["theodolite"]
    rows = map_columns(read_table(SAMPLES / kind.sample_file), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))
    details = json.loads((SAMPLES / "certificate_theodolite.json").read_text("utf-8"))
    return kind, result, details


def _document(theodolite, **changes):
    kind, result, details = theodolite
    return kind.certificate_document(result, CertificateMetadata.from_dict({**details, **changes}),
                                     "run.csv", {})


def _words(pdf: bytes, tmp_path: Path) -> list[list[tuple[float, float, float, str]]]:
    """Per page, every word with its xMin, xMax, yMin (points) as poppler reads it."""
    if shutil.which("pdftotext") is None:
        pytest.fail("pdftotext is missing: apt-get install poppler-utils (.ci/run does)")
    path = tmp_path / "c.pdf"
    path.write_bytes(pdf)
    out = subprocess.run(["pdftotext", "-bbox", "-enc", "UTF-8", str(path), "-"],
                         capture_output=True, text=True, encoding="utf-8", check=True).stdout
    pages = []
    for page in out.split("<page ")[1:]:
        pages.append([(float(a), float(b), float(c), w) for a, c, b, w in re.findall(
            r'<word xMin="([\d.]+)" yMin="([\d.]+)" xMax="([\d.]+)" yMax="[\d.]+">([^<]*)</word>',
            page)])
    return pages


LONG_LAB = ("National Institute of Angle Metrology and Precision Rotary Instruments, "
            "Division of Optical Angles Xian")


@pytest.mark.slow
def test_a_long_lab_name_and_long_words_stay_in_their_place(theodolite, tmp_path):
    assert len(LONG_LAB) == 103
    notes = "First paragraph.\n\n" + "Ш" * 150 + " " + "W" * 120 + "\n\nlast"
    pdf = certificate_pdf_bytes(_document(theodolite, lab_name=LONG_LAB, notes=notes,
                                          customer_name="Щ" * 120))
    pages = _words(pdf, tmp_path)
    assert len(pages) >= 3
    head_words = LONG_LAB.split()
    for words in pages:
        top = [w for w in words if w[2] < 60]  # the running head
        number = next(w for w in top if w[3].startswith("AB-"))
        certificate = next(w for w in top if w[3] == "Certificate")
        name = [w for w in top if w[0] < certificate[0]]
        assert [w[3] for w in name] == head_words  # the whole name, on every page
        assert max(w[1] for w in name) < certificate[0] < number[0]  # never over the number
        for x_min, x_max, _, word in words:  # the long words within the margins
            if set(word) & set("ШЩW"):
                assert x_min >= MARGIN_PT - 1 and x_max <= PAGE_WIDTH_PT - MARGIN_PT + 1, word
    text = "".join(w[3] for page in pages for w in page)
    assert text.count("Ш") == 150 and text.count("Щ") == 120 and text.count("W") >= 120


@pytest.mark.slow
def test_chinese_notes_with_a_blank_line_and_a_long_chinese_lab_name(theodolite, tmp_path):
    lab = "国家角度计量与精密转台仪器研究院光学角度测量分部" * 3
    pdf = certificate_pdf_bytes(_document(theodolite, language="zh", lab_name=lab,
                                          notes="第一段说明。\n\n第二段说明。\n\n\n" + "测" * 300))
    pages = _words(pdf, tmp_path)
    for words in pages:
        top = [w for w in words if w[2] < 60]
        number = next(w for w in top if w[3].startswith("AB-"))
        name = [w for w in top if w[3] and w[3][0] in lab and w[1] <= number[0]]
        assert "".join(w[3] for w in name) == lab
        assert max(w[1] for w in top if w[3] and w[3][0] in lab) < number[0]
    text = "".join(w[3] for page in pages for w in page)
    assert "第一段说明。" in text and "第二段说明。" in text and text.count("测") >= 300


@pytest.mark.slow
def test_right_to_left_script_is_refused_not_printed_reversed(theodolite):
    for name in ("شركة القياس", "מעבדה לכיול"):
        with pytest.raises(ValueError, match="right-to-left script"):
            certificate_pdf_bytes(_document(theodolite, customer_name=name))


@pytest.mark.parametrize(("text", "code"), [("A\u061cB", "061C"), ("AB\u200b-1", "200B"),
                                            ("\ufeffLab", "FEFF"), ("a\u202eb", "202E"),
                                            ("a\x00b", "0000"), ("x\u2028y", "2028")])
def test_invisible_and_control_characters_are_refused_naming_the_field(text, code):
    with pytest.raises(MetadataError, match=f"'customer_name' holds the invisible or control "
                                            f"character U\\+{code}"):
        CertificateMetadata.from_dict({"customer_name": text})


def test_a_field_over_its_limit_is_refused_not_cut():
    assert CertificateMetadata.from_dict({"lab_name": "L" * 200}).lab_name == "L" * 200
    with pytest.raises(MetadataError, match="'lab_name' is 201 characters long; at most 200"):
        CertificateMetadata.from_dict({"lab_name": "L" * 201})
    assert len(CertificateMetadata.from_dict({"notes": "n" * 2000}).notes) == 2000
    with pytest.raises(MetadataError, match="'notes' is 2001 characters long; at most 2000"):
        CertificateMetadata.from_dict({"notes": "n" * 2001})
    # what was kept as typed: blank lines in notes, a tab as a space, a pasted line break
    meta = CertificateMetadata.from_dict({"notes": "a\r\n\r\nb\tc ", "customer_name": "x\ny"})
    assert meta.notes == "a\n\nb c" and meta.customer_name == "x y"


def test_the_command_line_refuses_such_details_with_exit_2(tmp_path, capsys):
    details = json.loads((SAMPLES / "certificate_polygon.json").read_text("utf-8"))
    details.update({"example": False, "lab_name": "L" * 250})
    (tmp_path / "m.json").write_text(json.dumps(details), encoding="utf-8")
    assert main(["analyze", "polygon", str(SAMPLES / "polygon_sample.csv"), "--metadata",
                 str(tmp_path / "m.json"), "--certificate", str(tmp_path / "c.pdf")]) == 2
    err = capsys.readouterr().err
    assert "'lab_name' is 250 characters long; at most 200" in err
    assert not (tmp_path / "c.pdf").exists()
