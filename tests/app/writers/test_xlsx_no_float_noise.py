"""The results workbook's *Uncertainty budget* ends on the U the certificate states, rounded
up to two significant digits (GUM 7.2.6), below its unrounded "Expanded U" (assessment 72
L6: 0.8.20 ended on 1.436 beside U = 1.5″)."""

from __future__ import annotations

import contextlib
import io
from decimal import ROUND_CEILING, Decimal
from pathlib import Path

import openpyxl

from app.main import main

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"


def _book(tmp_path: Path, workbench: str) -> openpyxl.Workbook:
    book = tmp_path / f"{workbench}.xlsx"
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        assert main(["analyze", workbench, str(SAMPLES / f"{workbench}_sample.csv"),
                     "--results", str(book)]) == 0
    return openpyxl.load_workbook(book)


def test_the_budget_ends_on_the_u_stated(tmp_path):
    book = _book(tmp_path, "theodolite")
    budget = [row for row in book["Uncertainty budget"].iter_rows(values_only=True) if row]
    names = [str(row[0]) for row in budget]
    expanded = next(row for row in budget if str(row[0]).startswith("Expanded uncertainty k·u_c"))
    stated = next(row for row in budget if str(row[0]).startswith("U stated (p ="))
    assert names.index(str(stated[0])) == names.index(str(expanded[0])) + 1
    u = Decimal(repr(float(expanded[7])))
    d = 1 - u.adjusted()  # two significant digits, rounded up
    assert Decimal(str(stated[7])) == u.quantize(Decimal(1).scaleb(-d), ROUND_CEILING)
    certificate = {row[0]: row[1] for row in _details_sheet(book).iter_rows(values_only=True)}
    largest = next(v for k, v in certificate.items() if str(k).startswith("Expanded uncertainty"))
    assert Decimal(str(stated[7])) == Decimal(repr(largest)).quantize(
        Decimal(1).scaleb(-d), ROUND_CEILING)


def _details_sheet(book):
    """The sheet of the document's details: *Report* on a test report's file (assessment 73
    L4), else *Certificate*."""
    return book["Report" if "Report" in book.sheetnames else "Certificate"]
