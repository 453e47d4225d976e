"""The shared certificate shape (models/certificate/builder.py, #44): a minimal workbench
gives its columns, statistics rows, decided curve and statements; the builder makes the
document — each figure to the decimal of its own U, the decision rows in the statistics,
the conformity decided against the details' tolerance, the budget at its worst point."""

from __future__ import annotations

import math

import numpy as np
import pytest

from models.certificate.builder import (
    Decision,
    PointTable,
    Statistics,
    build_certificate,
    figure_column,
    text_column,
    uncertainty_column,
)
from models.certificate.document import Table
from models.certificate.metadata import CertificateMetadata
from models.uncertainty.budget import BudgetComponent, UncertaintyBudget

# three points: a reference point (u = 0) and two whose standard uncertainties are 0.23″ and
# 0.6″; one Type B input with ν = ∞, so k = 2.00 and U = 0, 0.46″, 1.2″ (two significant
# digits; k at p = 95.45 % differs from 2 by 2e-5, far from any rounding edge)
U_STANDARD = np.array([0.0, 0.23, 0.6])
ERRORS = np.array([0.0, 1.2345, -2.5])
CORRECTION = np.array([0.004, -0.5, 0.25])


def _budget() -> UncertaintyBudget:
    return UncertaintyBudget((BudgetComponent("Reference", "B", "normal", U_STANDARD, 1.0, 1.0,
                                              math.inf, "stated"),), 3)


def _metadata(**changes) -> CertificateMetadata:
    return CertificateMetadata(**{"tolerance": 5.0, "decision_quantity": "points", **changes})


def _document(metadata=None, statistics=None, plots=(), **more):
    budget = _budget()
    u = budget.expanded
    results = PointTable("Results per point", (
        text_column("Point", ["A", "B", "C"]),
        figure_column("Error (\")", ERRORS, u),
        figure_column("Correction (\")", CORRECTION, u),
        uncertainty_column("U (\")", u)), "a note")
    return build_certificate(
        kind_key="fake", kind_title="Fake bench", method="Compare with the reference.",
        metadata=metadata or _metadata(), source_name="run.csv", method_reference="ref",
        budget=budget, parameters=Table("Parameters", ("Parameter", "Value", ""), []),
        results=results,
        statistics=statistics or Statistics([("Points", "3", "")], "points",
                                             [("After", "x", "")]),
        decision=Decision(ERRORS, point_names=["A", "B", "C"]),
        budget_point=lambda worst: f"point {'ABC'[worst]}", plots=plots,
        warnings=["a warning"], statements=["own statement"],
        point_columns=(("error_arcsec", ERRORS),), **more)


def test_the_expanded_uncertainties_of_the_fake_budget_are_as_planned():
    assert _budget().expanded == pytest.approx([0.0, 0.46, 1.2], abs=1e-4)


def test_each_figure_is_printed_to_the_decimal_of_its_own_u():
    doc = _document()
    assert doc.results.title == "Results per point" and doc.results.note == "a note"
    assert doc.results.header == ("Point", "Error (\")", "Correction (\")", "U (\")")
    # U = 0: the figures to the decimal of the median positive U (0.83″ → 2 decimals)
    assert doc.results.rows == [
        # a zero unsigned, as a figure that rounds to zero elsewhere (assessment 76 L6)
        ("A", "0.00", "0.00", "reference point, by definition"),
        ("B", "+1.23", "-0.50", "0.46"),
        ("C", "-2.5", "+0.2", "1.2"),  # 0.25 to one decimal: round half to even
    ]


def test_the_statistics_get_the_decision_rows_between_the_workbenchs_rows():
    doc = _document()
    names = [row[0] for row in doc.statistics.rows]
    assert names[0] == "Points" and names[-1] == "After"
    assert names[1] == "Decided quantity (p = 95.45 %)"  # its own interval's probability
    assert names[2] == "Expanded uncertainty U (p = 95.45 %)"
    assert doc.statistics.rows[2][1] == "1.2\""
    assert "k = 2.00" in doc.statistics.rows[2][2]
    assert doc.statistics.header == ("Quantity", "Value", "")


def test_a_wider_statistics_table_gets_the_decision_note_in_its_last_column():
    wide = Statistics([("R", "1", "a … b", "95 %", "ISO")], "targets", title="Figures",
                      header=("Quantity", "Value", "Interval", "Probability", "Standard"))
    doc = _document(statistics=wide)
    assert doc.statistics.title == "Figures"
    assert all(len(row) == 5 for row in doc.statistics.rows)
    assert doc.statistics.rows[-1][2:4] == ("", "")
    # the decided quantity's interval and its own probability in their columns (audit 68)
    decided = doc.statistics.rows[1]
    assert decided[0] == "Decided quantity" and " … " in decided[2] and decided[3] == "95.45 %"
    assert "largest over the targets" in doc.statistics.rows[-1][4]


def test_conformity_is_decided_against_the_details_tolerance_in_the_budgets_unit():
    # points: every |e| + U within T → pass; worst |−2.5| + 1.2 = 3.7″
    assert _document().conformity.verdict == "pass"
    assert _document().tolerance == 5.0
    # 1 mdeg = 3.6″: the worst point's interval straddles the limit (1.3″ … 3.7″)
    doc = _document(_metadata(tolerance=1.0, tolerance_unit="mdeg"))
    assert doc.tolerance == pytest.approx(3.6)
    assert doc.conformity.verdict not in ("pass", "not assessed")
    assert _document(_metadata(tolerance=None)).conformity.verdict == "not assessed"


def test_a_withheld_decision_makes_no_statement():
    budget = _budget()
    doc = build_certificate(
        kind_key="fake", kind_title="Fake", method="m", metadata=_metadata(), source_name="",
        method_reference="", budget=budget, parameters=Table("P", ("", "", ""), []),
        results=PointTable("R", (figure_column("e", ERRORS, budget.expanded),)),
        statistics=Statistics([], "points"),
        decision=Decision(ERRORS, withheld="the run is invalid"), budget_point=str,
        plots=(), warnings=(), statements=(), point_columns=())
    assert doc.conformity.verdict == "not assessed"
    assert "the run is invalid" in doc.conformity.reason


def test_the_budget_is_shown_at_its_worst_point_and_the_rest_is_passed_through():
    doc = _document(plots=(None,), standard="ISO 230-2", unit=" nm")
    assert doc.budget_point == "point C"
    assert doc.plots == () and doc.warnings == ("a warning",)
    assert doc.statements == ("own statement",)
    assert doc.standard == "ISO 230-2" and doc.unit == " nm"
    assert doc.statistics.rows[2][1] == "1.2 nm"  # the decision rows in the document's unit
    assert doc.kind_key == "fake" and doc.source_name == "run.csv"
    assert doc.point_columns[0][0] == "error_arcsec"


def test_a_column_with_a_cell_too_few_is_refused_not_misaligned():
    budget = _budget()
    with pytest.raises(ValueError):
        PointTable("R", (text_column("Point", ["A", "B"]),
                         uncertainty_column("U", budget.expanded))).table(budget.expanded)
