"""Every run of text on a certificate has its font (#29): every workbench's sample
certificate printed in en, zh+en and zh, with a laboratory name in Latin letters only, in
Chinese only and mixed, read back by poppler's pdftotext. fpdf2 once set the font inside
the "q … Q" around a cell, so the next run had none: poppler said "No font in show" and
printed nothing there (a Latin-only lab name in the head of every page after the first;
the seed's digits and "w" between Chinese words). Fails on any such complaint, on a page
without the lab's name, and on any figure or name of the source missing from the text.

The suite prints 15 of the 45 (workbench, language, lab name) certificates: every workbench
in every language and with every lab name, and every language with every lab name (a Latin
square: ``COVERING``); tests/benchmarks/test_certificate_fonts_full.py prints all 45 (`make
bench`)."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from app.writers.certificate_pdf import certificate_pdf_bytes
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

pytestmark = pytest.mark.slow  # every test prints a certificate and reads it back

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
LAB_NAMES = {"latin": "Shenzhen Angle Metrology Lab", "chinese": "深圳角度计量实验室",
             "mixed": "深圳 Angle 计量实验室 Lab"}
FIGURE = re.compile(r"[+\-−]?\d+(?:\.\d+)?")


@pytest.fixture(scope="module")
def analysed():
    out = {}
    for key, kind in KINDS.items():
        rows = map_columns(read_table(SAMPLES / kind.sample_file), kind.columns)
        settings = kind.settings_with_defaults(None)
        out[key] = (kind, kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings),
                    settings, json.loads((SAMPLES / f"certificate_{key}.json").read_text("utf-8")))
    return out


def _pdftotext(pdf: bytes, tmp_path: Path) -> tuple[str, str]:
    """(text, poppler's complaints)."""
    if shutil.which("pdftotext") is None:
        pytest.fail("pdftotext is missing: apt-get install poppler-utils (.ci/run does)")
    path = tmp_path / "certificate.pdf"
    path.write_bytes(pdf)
    run = subprocess.run(["pdftotext", "-enc", "UTF-8", str(path), "-"], capture_output=True,
                         text=True, encoding="utf-8", check=True)
    return run.stdout, run.stderr


LANGUAGES = ("en", "zh+en", "zh")
#: (workbench, language, lab name): each workbench in each language, with the lab names in
#: turn (workbench i, language j: lab name (i + j) mod 3), so every workbench meets every
#: lab name and every language every lab name (5 workbenches ≥ 3)
COVERING = [(key, language, list(LAB_NAMES)[(i + j) % len(LAB_NAMES)])
            for i, key in enumerate(sorted(KINDS)) for j, language in enumerate(LANGUAGES)]


@pytest.mark.parametrize(("key", "language", "lab"), COVERING)
def test_every_run_has_a_font_and_every_page_the_lab(analysed, key, language, lab, tmp_path):
    check_fonts_and_lab(analysed, key, language, lab, tmp_path)


def check_fonts_and_lab(analysed, key: str, language: str, lab: str, tmp_path: Path) -> None:
    """The certificate of ``key``'s sample in ``language`` for the lab named ``lab``: every run
    of text has its font, every page the lab's name, every figure and name its text."""
    kind, result, settings, details = analysed[key]
    metadata = CertificateMetadata.from_dict({**details, "lab_name": LAB_NAMES[lab],
                                              "language": language})
    document = kind.certificate_document(result, metadata, kind.sample_file, settings)
    text, complaints = _pdftotext(certificate_pdf_bytes(document), tmp_path)
    assert "No font" not in complaints, complaints[:300]
    assert complaints.strip() == "", complaints[:300]
    pages = [page for page in text.split("\f") if page.strip()]
    assert len(pages) >= 3
    without = [n for n, page in enumerate(pages, 1) if LAB_NAMES[lab] not in page]
    assert without == [], f"pages without the laboratory's name: {without}"
    flat = re.sub(r"\s+", "", text)  # a cell may wrap a long name or figure
    meta = metadata
    names = [meta.lab_name, meta.customer_name, meta.item_description, meta.item_manufacturer,
             meta.item_serial, meta.item_model, meta.operator, meta.approver,
             document.source_name,
             *(s.certificate_no for s in meta.standards), *(s.serial for s in meta.standards)]
    missing = [n for n in names if n and re.sub(r"\s+", "", n) not in flat]
    assert missing == []
    tables = (document.parameters, document.results, document.statistics)
    figures = {f.lstrip("+-−") if float(f.replace("−", "-")) == 0 else f  # "0.00", not "−0.00"
               for t in tables for row in t.rows for cell in row
               for f in FIGURE.findall(str(cell))}
    assert len(figures) > 50
    lost = sorted(f for f in figures if f not in flat)
    assert lost == []
    starts = [line for line in text.splitlines() if line.strip()[:1] in set("。，、；：）")]
    assert starts == []  # a line never starts with a closing mark
    report = document.is_test_report  # a test report ends as a report (review 61, F8)
    end = (f"—{'检测报告' if report else '证书'}{metadata.certificate_number}结束—"
           if language == "zh" else
           f"—Endof{'testreport' if report else 'certificate'}{metadata.certificate_number}—")
    assert end in re.sub(r"\s+", "", pages[-1])  # the end-of-document marker


def test_figures_and_formulas_are_never_broken_across_lines(analysed, tmp_path):
    """Chinese prose broke between any two characters: "随机种子 2026 / 1127", "T + / w"."""
    kind, result, settings, details = analysed["polygon"]
    metadata = CertificateMetadata.from_dict({**details, "language": "zh"})
    document = kind.certificate_document(result, metadata, kind.sample_file, settings)
    text, _ = _pdftotext(certificate_pdf_bytes(document), tmp_path)
    lines = [line.strip() for line in text.splitlines()]
    # the seed whole on its line (seeded from the readings since #39, 4a98ec3: no fixed 20261127)
    seeds = re.findall(r"随机种子(\d+)", re.sub(r"\s+", "", text))
    assert seeds
    assert all(any(seed in line for line in lines) for seed in seeds)
    assert not [line for line in lines if line.endswith(("T +", "T −", "="))]
    assert "在实验室内" in text  # the place of calibration


def test_a_lab_name_that_ends_in_chinese_keeps_its_latin_letters(analysed, tmp_path):
    """"Shenzhen Angle 计量实验室": measuring the head's width left the CJK font (its last
    run's) in use, and the cell then set "Shenzhen Angle" in it — glyphs the font lacks, so
    every page's head read "计量实验室" (until 0.8.22; the mixed name above ends in Latin)."""
    lab = "Shenzhen Angle 计量实验室"
    kind, result, settings, details = analysed["theodolite"]
    metadata = CertificateMetadata.from_dict({**details, "lab_name": lab, "language": "en"})
    document = kind.certificate_document(result, metadata, kind.sample_file, settings)
    text, complaints = _pdftotext(certificate_pdf_bytes(document), tmp_path)
    pages = [page for page in text.split("\f") if page.strip()]
    assert [n for n, page in enumerate(pages, 1) if lab not in page] == [], text[:400]


def test_the_chinese_validation_report_names_the_software_in_its_head(tmp_path):
    """The Chinese validation record's running head is "AngleBench 方法确认" on every page (it
    printed "方法确认": the Latin name set in the CJK font, which lacks it)."""
    import datetime as dt

    from app.validation_report import validation_pdf_bytes
    from models.validation.cases import uncertainty_cases

    pdf = validation_pdf_bytes(uncertainty_cases()[:1], dt.datetime(2026, 12, 7, 3, 0), 10,
                               language="zh")
    text, _ = _pdftotext(pdf, tmp_path)
    pages = [page for page in text.split("\f") if page.strip()]
    assert all("AngleBench 方法确认" in page for page in pages), text[:300]
