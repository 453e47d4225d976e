"""#39 (trust): ``ReadingsSheet.snapshot`` is the sheet as it was when taken — the readings
an analysis parses and a certificate records with its figures. No later edit of the sheet
(a cell typed, blanked or made unreadable, rows inserted or removed, all replaced) reaches
it, on a sheet of text rows and on a record of numbers alike; and it shares the rows instead
of copying them."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.readings.sheet import NumericRows, ReadingsSheet
from models.registry import KINDS
from tests.models.readings.test_numeric_rows import edits, same

COLUMNS = KINDS["fringe"].columns  # u_sin, u_cos (required), theta_deg (optional)


def _sheets(n: int, seed: int) -> tuple[ReadingsSheet, ReadingsSheet]:
    """The same readings as a record of numbers and as text rows."""
    rng = np.random.default_rng(seed)
    values = {"u_sin": rng.normal(0, 2, n).round(3), "u_cos": rng.normal(0, 2, n),
              "theta_deg": np.full(n, np.nan)}
    numeric = ReadingsSheet(COLUMNS)
    numeric.adopt_rows(NumericRows(COLUMNS, values, n))
    return numeric, ReadingsSheet(COLUMNS, [list(r) for r in NumericRows(COLUMNS, values, n)])


def _apply(sheet: ReadingsSheet, changes) -> None:
    for what, row, arg, cell in changes:
        if what == "set" and row <= sheet.row_count:
            sheet.set_text(row, arg, cell)
        elif what == "insert" and row <= sheet.row_count:
            sheet.insert_rows(row, [["0.5", "0.5", ""]] * arg)
        elif what == "remove" and row < sheet.row_count:
            sheet.remove_rows(row, arg)


@pytest.mark.slow
@settings(max_examples=120, deadline=None)
@given(st.integers(1, 25), st.integers(0, 2**31 - 1), edits, edits)
def test_no_edit_after_a_snapshot_reaches_it(n, seed, before, after):
    for sheet in _sheets(n, seed):
        _apply(sheet, before)  # a sheet already edited (a record of numbers: edited rows)
        rows = sheet.copy_rows()
        parsed = ReadingsSheet(COLUMNS, rows).parse()
        taken = sheet.snapshot()
        _apply(sheet, after)
        _apply(sheet, [("set", 0, 0, "99.5"), ("set", 0, 1, "x")])  # always one edit
        assert taken.copy_rows() == rows
        assert [taken.text(r, c) for r in range(taken.row_count)
                for c in range(len(COLUMNS))] == [cell for row in rows for cell in row]
        same(taken.parse(), parsed)
        assert sheet.text(0, 0) == "99.5"
        if rows:  # every row removed before the snapshot: it holds none, as it should
            assert taken.text(0, 0) == rows[0][0]


def test_a_cell_typed_replaces_its_row_so_the_snapshot_keeps_the_old_one():
    sheet = ReadingsSheet(COLUMNS, [["1.5", "2.5", ""], ["3", "4", ""]])
    taken = sheet.snapshot()
    first = sheet.rows[0]
    assert taken.rows[0] is first  # shared, not copied
    sheet.set_text(0, 1, "7")
    assert sheet.rows[0] == ["1.5", "7", ""] and sheet.rows[0] is not first
    assert taken.rows[0] == ["1.5", "2.5", ""] and taken.parse()["u_cos"].tolist() == [2.5, 4.0]
    sheet.replace_all([["0", "0", ""]])
    assert taken.row_count == 2


def test_a_record_of_numbers_shares_its_columns_and_copies_only_its_edited_rows():
    numeric, _ = _sheets(1000, 3)
    numeric.set_text(10, 0, "0.125")
    taken = numeric.snapshot()
    assert isinstance(taken.rows, NumericRows) and isinstance(numeric.rows, NumericRows)
    assert taken.rows.values is numeric.rows.values  # a million numbers are not copied
    assert taken.rows.edited == numeric.rows.edited
    assert taken.rows.edited[10] is not numeric.rows.edited[10]
    numeric.set_text(10, 1, "0.25")
    numeric.set_text(20, 0, "5")
    assert taken.text(10, 1) != "0.25" and taken.text(20, 0) != "5"
    assert taken.parse()["u_sin"][10] == 0.125
