"""Where a take goes and what its cell says (#41): never over a filled reading; the value
rounded to the instrument's resolution, in the column's angle format."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from models.capture.take_cells import (
    MICRORADIAN_ARCSEC,
    cell_text,
    column_is_dms,
    decimals_for,
    elevation_from_zenith_deg,
    next_empty_point,
    waiting_row,
)
from models.readings.angles import parse_angle_deg


def _text(rows):
    return lambda r, c: rows[r][c]


def test_a_take_goes_to_the_cursor_row_only_when_its_cells_are_blank():
    rows = [["1", "0.0", "3.21", "0.40"],   # face 1, read
            ["2", "15.0", "2.10", "0.10"],  # face 2, read (the cursor is here: #41's row 3)
            ["3", "", "", ""],              # the plan's next face, not read
            ["4", "", "", ""]]
    cells = _text(rows)
    assert next_empty_point(len(rows), 1, [2, 3], cells) == 2  # the next empty point
    assert next_empty_point(len(rows), 3, [2, 3], cells) == 3  # its own row, blank
    assert next_empty_point(len(rows), 0, [2, 3], cells) == 2
    assert next_empty_point(len(rows), 4, [2, 3], cells) == 4  # a new row after the last
    rows[2][3] = "0.5"  # one of the take's cells filled: not an empty point
    assert next_empty_point(len(rows), 1, [2, 3], cells) == 3


@given(st.lists(st.lists(st.sampled_from(["", " ", "1.5", "x"]), min_size=3, max_size=3),
                max_size=12), st.integers(0, 14), st.sets(st.integers(0, 2), min_size=1))
def test_a_take_never_lands_on_a_filled_cell(rows, start, columns):
    row = next_empty_point(len(rows), start, sorted(columns), _text(rows))
    assert row >= start
    if row < len(rows):
        assert all(not rows[row][c].strip() for c in columns)
    # every row skipped had a filled cell among the take's
    for r in range(start, min(row, len(rows))):
        assert any(rows[r][c].strip() for c in columns)


def test_cells_rounded_to_the_instrument_resolution():
    # #41: 23.9468846154 was written with 12 digits
    assert cell_text(23.9468846154, "arcsec", 0.01) == "23.95"
    assert cell_text(23.9468846154, "arcsec", 0.1) == "23.9"
    assert cell_text(-0.004, "arcsec", 0.01) == "0.00"  # no "-0.00"
    # 1 µrad = 0.206265"; 1.0" is 4.848 µrad → 5 µrad = 1.031"
    assert pytest.approx(0.2062648, abs=1e-7) == MICRORADIAN_ARCSEC
    assert cell_text(1.0, "arcsec", MICRORADIAN_ARCSEC) == "1.03"
    assert cell_text(23.9468846154, "arcsec", 0.0) == "23.9468846154"  # as sent
    # a theodolite's azimuth in decimal degrees, to 0.1": 5 decimals of a degree do not
    # show 0.1" (0.036"), 6 do
    assert cell_text(123.4567, "deg", 0.1) == "123.456694"  # 444444.12" → 444444.1"
    # …and among D°M′S″ rows as D°M′S″
    assert cell_text(123.4567, "deg", 0.1, dms=True) == "123°27'24.1\""
    assert cell_text(359.99999, "deg", 1.0, dms=True) == "360°00'00\""  # carried, never 60"
    # degrees into a column in arcseconds
    assert cell_text(0.001, "deg", 0.01, column_unit='"') == "3.60"


def test_a_reading_as_sent_is_fixed_point_and_never_minus_zero():
    """Review 62, F12: a readout's 0.00004° was written "4e-05", its closure "-1e-05", and
    the live value showed "-0°" (resolution not known: the value as sent)."""
    assert cell_text(0.00004, "deg", 0.0) == "0.00004"
    assert cell_text(-0.00001, "deg", 0.0) == "-0.00001"
    assert cell_text(-0.0, "deg", 0.0) == "0"
    assert cell_text(300.00002, "deg", 0.0) == "300.00002"
    assert cell_text(2e-7, "arcsec", 0.0) == "0.0000002"
    assert cell_text(-1e-13, "arcsec", 0.0) == "-0.0000000000001"
    assert cell_text(1.5e15, "arcsec", 0.0) == "1500000000000000"


@given(st.floats(-720.0, 720.0, allow_nan=False),
       st.sampled_from([0.001, 0.01, 0.1, 1.0, MICRORADIAN_ARCSEC]), st.booleans())
def test_an_angle_cell_reads_back_within_half_the_resolution(value_deg, resolution, dms):
    text = cell_text(value_deg, "deg", resolution, dms=dms)
    back = parse_angle_deg(text)
    # rounding to the resolution, then the text's own decimals (a tenth of it at most)
    shown = 10.0 ** -decimals_for(resolution if dms else resolution / 3600.0)
    slack = resolution / 2 + (shown if dms else shown * 3600.0) / 2 + 1e-9
    assert abs(back - value_deg) * 3600.0 <= slack


def test_a_column_written_in_dms_is_recognised():
    assert column_is_dms(["12°30'00\"", "15°00'00.5\"", ""])
    assert column_is_dms(["12 30 00", "15 0 0.5"])
    assert not column_is_dms(["12.5", "15.0001", "12°30'00\""])
    assert not column_is_dms(["", " "])


def test_elevation_from_the_zenith_angle_in_both_faces():
    # a sight 2.3456° above the horizon: V = 87.6544° in face I, 272.3456° in face II
    assert elevation_from_zenith_deg(87.6544) == pytest.approx(2.3456, abs=1e-12)
    assert elevation_from_zenith_deg(272.3456) == pytest.approx(2.3456, abs=1e-12)
    # from the geometry: the zenith angle of a direction with elevation e is 90° − e
    for e in (-10.0, 0.0, 0.004, 45.0):
        v = math.degrees(math.acos(math.sin(math.radians(e))))
        assert elevation_from_zenith_deg(v) == pytest.approx(e, abs=1e-9)


def test_the_row_waiting_is_the_first_of_the_last_rows_without_a_reading():
    # θ, azimuth, elevation: row 1 taken, rows 2 and 3 with θ only (θ and Return with a step)
    rows = [["10", "33.5", "1.0"], ["12", "", ""], ["14", "", ""], ["", "", ""]]
    assert waiting_row(4, 3, [1, 2], _text(rows)) == 1
    rows[1][1] = "33.6"
    assert waiting_row(4, 3, [1, 2], _text(rows)) == 2
    rows[2][2] = "1.1"
    assert waiting_row(4, 3, [1, 2], _text(rows)) is None
    # a row left without a reading in the middle is not waiting: only the rows at the end
    assert waiting_row(3, 3, [1, 2], _text([["10", "", ""], ["12", "1", ""], ["14", "", ""]])) == 2
    assert waiting_row(0, 3, [1, 2], _text([])) is None
    assert waiting_row(1, 3, [], _text([["10", "", ""]])) is None


def test_cleared_row_is_the_first_used_row_without_its_reading():
    """A row in the middle whose reading was cleared (its face and set kept) is where the
    next take goes, without a plan (day review 64 P4); a blank row or one with a reading
    is not, nor a row at or below ``before``."""
    from models.capture.take_cells import cleared_row

    rows = [["1", "0.0", "0.5"], ["2", "", ""], ["", "", ""], ["3", "", ""], ["4", "90", "1"]]

    def text(r: int, c: int) -> str:
        return rows[r][c]

    assert cleared_row(5, 3, [2], [1, 2], text) == 1
    assert cleared_row(1, 3, [2], [1, 2], text) is None  # only rows above ``before``
    rows[1][1] = "30.0"  # its encoder typed again: it has a reading
    assert cleared_row(5, 3, [2], [1, 2], text) == 3
    assert cleared_row(5, 3, [], [1, 2], text) is None  # no column the take fills
