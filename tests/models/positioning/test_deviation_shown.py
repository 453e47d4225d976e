"""The deviation a positioning row shows from its measured position (gui77): measured −
target in the deviation unit, to the positions' resolution one digit finer, a zero
unsigned, nothing for a blank or unreadable position."""

from __future__ import annotations

import pytest

from models.positioning.deviation_shown import deviation_from_measured
from models.registry import KINDS


@pytest.mark.parametrize("target, measured, unit, shown", [
    ("15", "15.0003", "arcsec", "1.08"),         # 0.0001° = 0.36″: two decimals
    ("0", "0.000278", "arcsec", "1.0008"),
    ("0", "-0.0005", "arcsec", "-1.80"),
    ("10", "10.000000", "arcsec", "0.0000"),     # zero unsigned
    ("15", "15°00'01.0\"", "arcsec", "1.00"),    # D°M′S″: to 0.01
    ("15", "15.0003", "urad", "5.2"),
    ("100", "100.0012", "um", "1.20"),
    ("100", "100.0012", "nm", "1200"),
    ("15", "", "arcsec", None),
    ("", "15.1", "arcsec", None),
    ("15", "fifteen", "arcsec", None),
])
def test_measured_minus_target(target, measured, unit, shown):
    assert deviation_from_measured(target, measured, {"deviation_unit": unit}) == shown


def test_only_positioning_shows_a_figure_in_a_blank_cell():
    assert set(KINDS["positioning"].shown_in_blank({"deviation_unit": "arcsec"})) == {
        "deviation"}
    assert all(not KINDS[k].shown_in_blank({}) for k in KINDS if k != "positioning")
