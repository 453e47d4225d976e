"""Day 74 findings 12 and 13: what a certificate's labels say.

* Finding 12: the uncertainty budget printed "Expanded U (k = 2.01) 0.018" and below it
  "Expanded uncertainty U (p = 95.45 %) 0.019": two expanded U's with different figures, the
  labels not saying which was which (the second is the U stated: k·u_c rounded up to two
  significant digits, GUM 7.2.6). Every workbench's budget (one table builder for all) names
  the first k·u_c before rounding and the second the U stated, rounded up to two significant
  digits; the one stated is not below the one computed.
* Finding 13: a calibration certificate labelled the item "被校准对象 / Item under test": the
  Chinese said the item calibrated, the English the item of a test. A calibration
  certificate says "Item calibrated" (as its statement "The results relate only to the item
  calibrated"), a test report "Item under test" (被检测对象), in the PDF and the results
  workbook.

The samples are the shipped ones, analysed and issued as a user would from the command line;
the figures are read back from the workbook and the PDF's text."""

from __future__ import annotations

import contextlib
import io
import json
import re
import subprocess
from decimal import ROUND_CEILING, Decimal
from pathlib import Path

import openpyxl
import pytest

from app.main import main

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"


def _book(tmp_path: Path, workbench: str, details: bool = False) -> openpyxl.Workbook:
    """The sample's results workbook; with ``details`` the sample's certificate details (the
    standards of a calibration certificate where the workbench has them)."""
    book = tmp_path / f"{workbench}.xlsx"
    options = []
    if details:
        data = json.loads((SAMPLES / f"certificate_{workbench}.json").read_text("utf-8"))
        meta = tmp_path / f"{workbench}.json"
        meta.write_text(json.dumps({**data, "example": False}), "utf-8")
        options = ["--metadata", str(meta)]
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        assert main(["analyze", workbench, str(SAMPLES / f"{workbench}_sample.csv"),
                     "--results", str(book), *options]) == 0
    return openpyxl.load_workbook(book)


@pytest.mark.parametrize("workbench", ["theodolite", "polygon", "positioning", "fringe",
                                       "crosscal"])
def test_the_budgets_two_u_lines_say_which_is_which(tmp_path, workbench):
    budget = [row for row in _book(tmp_path, workbench)["Uncertainty budget"].iter_rows(
        values_only=True) if row and row[0]]
    names = [str(row[0]) for row in budget]
    combined = next(i for i, name in enumerate(names) if name.startswith("Combined standard"))
    computed, stated = budget[combined + 1], budget[combined + 2]
    # the line after u_c is k·u_c as computed, said to be before rounding
    assert "k·u_c" in str(computed[0]) and "before rounding" in str(computed[0]), names
    # the next is the U the certificate states, said to be rounded up (or raised to the CMC)
    assert str(stated[0]).startswith("U stated"), names
    assert ("rounded up to two significant digits" in str(stated[0])
            or "raised to the laboratory's CMC" in str(stated[0])), names
    # never two lines both named the expanded uncertainty U
    assert sum(bool(re.match(r"Expanded (uncertainty )?U\b", n)) for n in names) == 0, names
    # k·u_c is printed to 0.001 (the table's decimal): the U stated is it rounded up to two
    # significant digits, from its value within half a printed step
    u = Decimal(repr(float(computed[7])))
    half = Decimal("0.0005")
    assert Decimal(str(stated[7])) >= u - half
    if "rounded up" in str(stated[0]):
        d = 1 - u.adjusted()  # two significant digits, rounded up
        step = Decimal(1).scaleb(-d)
        assert ((u - half).quantize(step, ROUND_CEILING) <= Decimal(str(stated[7]))
                <= (u + half).quantize(step, ROUND_CEILING)), (computed, stated)


def _certificate_sheet(book: openpyxl.Workbook) -> dict:
    sheet = next(ws for ws in book.worksheets if ws.title not in (
        "Statistics", "Parameters", "Uncertainty budget") and ws.max_column == 2)
    return {row[0]: row[1] for row in sheet.iter_rows(values_only=True)}


def test_the_workbook_names_the_item_as_the_document_does(tmp_path):
    calibration = _certificate_sheet(_book(tmp_path, "theodolite", details=True))
    assert "Certificate number" in calibration, calibration  # a calibration certificate's
    assert calibration.get("Item calibrated") is not None, calibration
    assert "Item under test" not in calibration
    report = _certificate_sheet(_book(tmp_path, "fringe", details=True))
    assert "Report number" in report, report
    assert report.get("Item under test") is not None, report
    assert "Item calibrated" not in report


def _issued_text(tmp_path: Path, workbench: str, language: str) -> str:
    data = json.loads((SAMPLES / f"certificate_{workbench}.json").read_text("utf-8"))
    meta = tmp_path / f"{workbench}-{language}.json"
    meta.write_text(json.dumps({**data, "example": False, "language": language}), "utf-8")
    pdf = tmp_path / f"{workbench}-{language}.pdf"
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        assert main(["analyze", workbench, str(SAMPLES / f"{workbench}_sample.csv"),
                     "--metadata", str(meta), "--certificate", str(pdf)]) == 0
    text = subprocess.run(["pdftotext", "-f", "1", "-l", "1", str(pdf), "-"],
                          capture_output=True, check=True, text=True).stdout
    return re.sub(r"\s+", " ", text)


@pytest.mark.slow
def test_a_bilingual_calibration_certificate_names_the_item_calibrated_in_both(tmp_path):
    text = _issued_text(tmp_path, "polygon", "zh+en")
    assert "Calibration certificate" in text, text[:400]
    assert "被校准对象 Item calibrated" in text, text[:800]
    assert "Item under test" not in text


@pytest.mark.slow
def test_a_bilingual_test_report_names_the_item_under_test_in_both(tmp_path):
    text = _issued_text(tmp_path, "fringe", "zh+en")
    assert "Test report" in text, text[:400]
    assert "被检测对象 Item under test" in text, text[:800]
    assert "Item calibrated" not in text and "被校准对象" not in text
