"""CSV cells a spreadsheet shows and never runs; numbers and angles stay the data they are."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from models.spreadsheet_cell import FORMULA_STARTS, is_number_or_angle, spreadsheet_safe

ATTACKS = ["=HYPERLINK(\"http://x\",\"click\")", "+cmd|' /C calc'!A0", "@SUM(1+1)*cmd|'/C calc'!A0",
           "-2+3+cmd|' /C calc'!A0", "\t=1+1", "\r=1+1", "\n=1", "  =1+1", "＝1+1", "-", "+",
           "=", "@", "-1+1", "-A1", "-19°52'57.0\"+cmd|'/C calc'!A0", "-1e5e5", "-0x1A",
           "-SUM(A1)", "+1 2 3 4"]
DATA = ["-0.5", "+3", "-1.2e-5", "-19°52'57.0\"", "-0°00'12.5\"", "-12 34 56.7", "-0.12\"",
        "-3 arcsec", "+12.5°", "-19°52′57.0″", "-7", "AB-2026-0001", "Dr. Li", "", "12:30",
        "RX-26-0815", "-.5"]


@pytest.mark.parametrize("text", ATTACKS)
def test_a_formula_is_shown_as_text(text):
    assert spreadsheet_safe(text) == "'" + text


@pytest.mark.parametrize("text", DATA)
def test_numbers_angles_and_plain_text_stay_as_they_are(text):
    assert spreadsheet_safe(text) == text


@given(st.floats(allow_nan=False, allow_infinity=False))
def test_any_number_stays_a_number(x):
    for text in (repr(x), f"{x:.6g}", f"{x:+.3f}", f"{x:.2f}\""):
        assert spreadsheet_safe(text) == text and is_number_or_angle(text)


@given(st.integers(-359, 359), st.integers(0, 59), st.floats(0, 59.99, allow_nan=False),
       st.sampled_from(["-", "+", ""]))
def test_any_angle_stays_as_it_is(d, m, s, sign):
    text = f"{sign}{abs(d)}°{m:02d}'{s:04.1f}\""
    assert spreadsheet_safe(text) == text and is_number_or_angle(text)


@given(st.text(max_size=30))
def test_nothing_left_unmarked_starts_like_a_formula_unless_it_is_data(text):
    safe = spreadsheet_safe(text)
    assert safe in (text, "'" + text)
    if safe == text and text.lstrip(" ").startswith(FORMULA_STARTS):
        assert is_number_or_angle(text)
        assert not any(c in text for c in "=(|!@&")  # nothing a spreadsheet could call
