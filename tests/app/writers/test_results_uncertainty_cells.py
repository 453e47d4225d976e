"""--results as numbers (issue 39): a figure with a symmetric U ("25.01\", U = ±1.35\"", or its
U on a line of its own, "0.407\"\\n±0.094\"") is split into number cells like an asymmetric one,
and the Certificate sheet states the decided value's interval and the decision's risk."""

from __future__ import annotations

import io
from dataclasses import replace

import pytest
from openpyxl import load_workbook

from app.writers.results_export import results_xlsx_bytes, split_figures
from models.certificate.document import Table
from tests.app.writers.test_certificate_export import META, _analysed


@pytest.mark.parametrize(("text", "numbers"), [
    ("25.01\", U = ±1.35\"", (25.01, 1.35, 1.35)),
    ("0.407\"\n±0.094\"", (0.407, 0.094, 0.094)),
    ("0.41\"\n−0.12\"/+0.14\"", (0.41, 0.12, 0.14)),
    ("-3.2\", U = ±0.81\"", (-3.2, 0.81, 0.81)),
])
def test_a_figure_with_its_u_is_three_numbers(text, numbers):
    assert split_figures(text) == (numbers, "\"", "U−/U+")


def test_xlsx_holds_value_and_u_as_numbers_and_the_decision_figures():
    kind, result = _analysed("theodolite")
    doc = kind.certificate_document(result, META)
    table = Table("Statistics", ("Quantity", "Value", ""),
                  [("A", "25.01\", U = ±1.35\"", ""), ("Decided", "0.407\"\n±0.094\"", ""),
                   ("B", "0.41\"\n−0.12\"/+0.14\"", "")])
    book = load_workbook(io.BytesIO(results_xlsx_bytes(replace(doc, statistics=table))))
    rows = [list(r) for r in book["Statistics"].iter_rows(values_only=True)]
    assert rows[0][:4] == ["Quantity", "Value (\")", "Value (U−) (\")", "Value (U+) (\")"]
    assert rows[1][1:4] == [25.01, 1.35, 1.35]
    assert rows[2][1:4] == [0.407, 0.094, 0.094]
    assert rows[3][1:4] == [0.41, 0.12, 0.14]
    certificate = {r[0]: r[1] for r in book["Certificate"].iter_rows(values_only=True)}
    # U and the decided figures as the certificate prints them (assessment 76 M4: the sheet
    # gave U = 1.4773″ and the interval's end 1.4482″ beside the 1.5″ and 1.45″ printed)
    decided = next(row for row in doc.statistics.rows if row[0].startswith("Decided"))
    assert decided[1] == "0.94\"\n−0.94\"/+0.51\"" and decided[2].startswith(
        "interval 0.00\" … 1.45\";")
    assert certificate["Decided value (\")"] == 0.94
    assert certificate["U of the decided value, below it (U−) (\")"] == 0.94
    assert certificate["U of the decided value, above it (U+) (\")"] == 0.51
    assert certificate["Decided value: interval low (\")"] == 0.0
    assert certificate["Decided value: interval high (\")"] == 1.45
    assert doc.expanded_uncertainty == pytest.approx(1.4773, abs=1e-4)
    assert certificate["Expanded uncertainty U, largest (\")"] == 1.5
    assert certificate["Decided value: coverage probability (%)"] == pytest.approx(95.45, abs=0.01)
    risk = certificate["Probability of a wrong decision (%)"]  # "< 0.01" as the PDF's
    assert risk == "< 0.01" or 0.01 <= risk <= 100


def test_the_certificate_sheet_read_in_urad_rounds_there_as_the_certificate_does():
    """In µrad the sheet's U and decided figures are the certificate's read in µrad, rounded
    there from their values (1.4773″ = 7.162 µrad → U = 7.2 µrad; 0.9409″ = 4.562 µrad with
    U₋ 4.562, U₊ 2.459 µrad → 4.6, 4.6, 2.5 µrad, the interval 0 … 7.1 µrad), never the
    arcsecond figures converted (1.5″ = 7.27 µrad) nor unrounded (assessment 76 M4)."""
    from models.display_units import ANGLE_UNITS

    kind, result = _analysed("theodolite")
    doc = kind.certificate_document(result, META)
    book = load_workbook(io.BytesIO(results_xlsx_bytes(doc, unit=ANGLE_UNITS["urad"])))
    sheet = {r[0].value: r[1] for r in book["Certificate"].iter_rows()}
    figures = {name: (sheet[name].value, sheet[name].number_format) for name in (
        "Expanded uncertainty U, largest (µrad)", "Decided value (µrad)",
        "U of the decided value, below it (U−) (µrad)",
        "U of the decided value, above it (U+) (µrad)", "Decided value: interval low (µrad)",
        "Decided value: interval high (µrad)")}
    assert list(figures.values()) == [(7.2, "0.0"), (4.6, "0.0"), (4.6, "0.0"), (2.5, "0.0"),
                                      (0, "0.0"), (7.1, "0.0")]


@pytest.mark.parametrize("key", ["theodolite", "positioning"])
def test_the_certificate_sheet_gives_the_coverage_probability_the_certificate_prints(key):
    """The *Certificate* sheet's coverage probabilities are the figures the certificate
    prints ("95.45 %"), not the computed probability's every digit (0.8.25: 95.44997361036415
    twice on the sheet of the certificate it records, cert77)."""
    from models.uncertainty.probability_text import percent_text

    kind, result = _analysed(key)
    doc = kind.certificate_document(result, META)
    book = load_workbook(io.BytesIO(results_xlsx_bytes(doc)))
    sheet = book["Report" if doc.is_test_report else "Certificate"]  # (positioning's sample)
    certificate = {r[0]: r[1] for r in sheet.iter_rows(values_only=True)}
    assert doc.budget.probability != 0.9545  # the computed one, 2Φ(2) − 1
    assert certificate["Coverage probability (%)"] == 95.45
    assert certificate["Decided value: coverage probability (%)"] == float(
        percent_text(doc.conformity.probability))
    assert len(repr(certificate["Decided value: coverage probability (%)"])) <= 5  # 95.45, 92.5
