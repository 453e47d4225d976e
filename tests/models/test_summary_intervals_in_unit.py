"""The theodolite's and the positioning axis's summary (the window's Result pane, shown in
the unit the window reads in) converts both ends of each coverage interval: the low end,
written bare ("E_up 2.96 … 3.95″"), stayed in arcseconds beside a high end in µrad or mdeg
("E_up 2.96 … 19.15 µrad": a wrong number on the screen, found checking day 69's digits).

The runs come from first principles (tests/repeatability_rig.py), nothing from models/; the
units' factors are worked out here."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from models.display_units import ANGLE_UNITS, in_unit
from models.readings.sheet import ReadingsSheet
from models.registry import KINDS
from tests.repeatability_rig import iso230_rows, theodolite_passes_csv

pytestmark = pytest.mark.slow  # (a theodolite run of 3 passes analysed, ~0.7 s)

PER_ARCSEC = {"urad": math.pi / 648000 * 1e6, "mdeg": 1000 / 3600}
SYMBOL = {"urad": "µrad", "mdeg": "mdeg"}


def _theodolite():
    text, _ = theodolite_passes_csv("varying", 13, 3, 0.3, np.random.default_rng(6852))
    kind = KINDS["theodolite"]
    lines = [line.split(",") for line in text.splitlines()[1:]]
    rows = [row + [""] * (len(kind.columns) - len(row)) for row in lines]
    return kind, kind.analyze(ReadingsSheet(kind.columns, rows).parse(),
                              kind.settings_with_defaults({}))


def _positioning():
    angles = np.linspace(0.0, 360.0, 12, endpoint=False)
    f = 5.0 * np.sin(np.radians(angles)) + 2.0 * np.cos(np.radians(3 * angles))
    rows, _ = iso230_rows(angles, {"+": f + 2.5, "-": f - 2.5}, 3, 0.8,
                          np.random.default_rng(6851))
    kind = KINDS["positioning"]
    return kind, kind.analyze(ReadingsSheet(kind.columns, rows).parse(),
                              kind.settings_with_defaults({}))


def _intervals(summary: str, unit: str) -> dict[str, tuple[float, float]]:
    """{figure: (low, high)} of the summary's "Coverage intervals" line; both ends must be
    in ``unit`` (a bare end is taken as it is written)."""
    line = next(x for x in summary.splitlines() if x.startswith("Coverage intervals"))
    found = re.findall(rf"(\w+) (-?[\d.]+)(?:\s*{re.escape(unit)})? … (-?[\d.]+)\s*"
                       rf"{re.escape(unit)}", line.split("): ", 1)[1])
    return {key: (float(low), float(high)) for key, low, high in found}


@pytest.mark.parametrize("make", [_theodolite, _positioning], ids=["theodolite", "positioning"])
def test_both_ends_of_each_interval_are_shown_in_the_windows_unit(make):
    kind, result = make()
    summary = str(kind.summary(result))
    in_arcsec = _intervals(summary, '"')
    assert len(in_arcsec) >= 6, summary
    for key, per_arcsec in PER_ARCSEC.items():
        shown = _intervals(str(in_unit(summary, ANGLE_UNITS[key])), SYMBOL[key])
        assert shown.keys() == in_arcsec.keys()
        for figure, (low, high) in in_arcsec.items():
            # each end the arcsecond one times the factor, shown to three significant
            # digits or more (so within 0.5 % of it)
            for end, was in zip(shown[figure], (low, high), strict=True):
                assert end == pytest.approx(was * per_arcsec, rel=0.006, abs=1e-9), (
                    key, figure, shown[figure], (low, high))
