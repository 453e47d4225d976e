import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from models.readings.sheet import Column, ColumnKind, ReadingsSheet

COLUMNS = [
    Column("theta_deg", "θ", "deg", ColumnKind.ANGLE_DEG),
    Column("value", "value", "arcsec", ColumnKind.NUMBER),
    Column("run", "run", "", ColumnKind.INTEGER, required=False),
    Column("dir", "dir", "", ColumnKind.TEXT, required=False, choices=("+", "-")),
]


def test_bad_cells_are_reported_and_rows_left_out_but_text_kept():
    sheet = ReadingsSheet(COLUMNS, [["1", "2"], ["1°61'", "3"], ["", ""], ["2", "x", "1.5"]])
    parsed = sheet.parse()
    assert parsed.row_index.tolist() == [0]
    assert [(e.row, e.column_key) for e in parsed.errors] == [(1, "theta_deg"), (3, "value"),
                                                              (3, "run")]
    assert "minutes 61" in parsed.errors[0].reason
    line = parsed.errors[0].describe("f.csv")
    assert line.startswith("f.csv: row 2, column 'theta_deg': ") and "minutes 61" in line
    assert sheet.text(1, 0) == "1°61'"  # nothing lost
    assert sheet.cell_error(2, 0) is None  # blank row is fine
    assert np.isnan(parsed["run"][0])


def test_choices_and_optional():
    sheet = ReadingsSheet(COLUMNS, [["1", "2", "3", "+"], ["2", "1", "", "?"]])
    parsed = sheet.parse()
    assert parsed["dir"].tolist() == ["+"]
    assert "not one of" in parsed.errors[0].reason


@pytest.mark.slow
@given(st.lists(st.floats(-1e6, 1e6, allow_nan=False), min_size=1, max_size=30))
def test_number_columns_round_trip(values):
    sheet = ReadingsSheet(COLUMNS, [[repr(v), repr(v)] for v in values])
    parsed = sheet.parse()
    assert parsed.errors == []
    np.testing.assert_array_equal(parsed["value"], values)
    np.testing.assert_allclose(parsed["theta_deg"], values)
