"""Assessment 70 L3: a results table whose printed correction is not the difference of the
printed raw and corrected figures beside it (each rounded on its own from its unrounded
value: the polygon's "−0.27 +0.10 → −0.16") says so under the table; a table whose rows all
add up as printed says nothing. The figures themselves are not changed: a correction printed
as the difference of the rounded figures would state a correction that is not the one
applied (+0.01″ for 0.00001″)."""

from __future__ import annotations

from decimal import Decimal

import numpy as np

from models.certificate.builder import PointTable, difference_column, figure_column


def _table(raw, corrected, u):
    return PointTable("Results", (
        figure_column("Raw error (\")", raw, u),
        difference_column("Correction (\")", corrected, raw, u),
        figure_column("Corrected error (\")", corrected, u))).table(u)


def _adds_up(rows) -> bool:
    return all(Decimal(raw) + Decimal(correction) == Decimal(corrected)
               for raw, correction, corrected in rows)


def test_a_table_that_does_not_add_up_as_printed_says_why():
    # raw −0.2651″, correction +0.1022″: corrected −0.1629″, printed −0.27, +0.10, −0.16
    raw, corrected = np.array([-0.1, -0.2651]), np.array([-0.1, -0.1629])
    table = _table(raw, corrected, np.array([0.13, 0.35]))
    assert table.rows[1] == ("-0.27", "+0.10", "-0.16") and not _adds_up(table.rows)
    assert "rounded on its own" in table.note


def test_a_table_that_adds_up_as_printed_has_no_such_note():
    raw, corrected = np.array([-0.1, -0.2649]), np.array([-0.1, -0.1629])
    table = _table(raw, corrected, np.array([0.13, 0.35]))
    assert _adds_up(table.rows) and "rounded on its own" not in str(table.note)
