"""The positioning workbench's headline (the bold line above the results) prints its figures
as the summary beside it and the certificate do: each to the decimal of its coverage
interval's half-width, two significant digits (GUM 7.2.6). It printed "A = 22.447″" beside
a summary's "A = 22.4″ … A 19.1 … 23.9″" (#61 left)."""

from __future__ import annotations

import math
import re

import pytest

from models.positioning.report import figure_uncertainties


def _decimals_of(half_width: float) -> int:
    """Two significant digits of the half-width, counted here by hand (not the app's helper)."""
    text = f"{half_width:.1e}"  # "2.4e+00": the half-width rounded to two significant digits
    return max(0, 1 - int(text.split("e")[1]))


@pytest.mark.slow
def test_the_headline_prints_each_figure_to_its_intervals_decimal(window):
    window.load_all_samples()
    presenter = window.presenter("positioning")
    result = presenter.result
    shown = presenter.view.verdict.text()
    intervals = figure_uncertainties(result)
    expected = []
    for key in ("A", "R", "B"):
        iv = intervals[key]
        d = _decimals_of((iv.high - iv.low) / 2)
        expected.append(f'{key} = {result.iso.figures[key]:.{d}f}"')
    assert shown.startswith("ISO 230-2:2014: " + ", ".join(expected)), shown
    # the sample: A to 0.1″ beside its interval 18.0 … 34.7″ (half-width 8.4″: each target's
    # bound at the whole tail, 0.8.18; "A = 22″" beside 17 … 44″ in 0.8.17), R to 0.1″ beside
    # 4.6 … 19.8″ (half-width 7.6″: the two-way bound at one level, 0.8.19; to 1″ beside 3 … 28″
    # before), never to 0.001″
    assert shown.startswith('ISO 230-2:2014: A = 22.4", R = 10.1", B = 6.1"'), shown
    # the same figure and decimal as the summary's line beside it
    summary = presenter.view.summary.toPlainText()
    a = re.search(r'ISO 230-2: A = ([-\d.]+)"', summary).group(1)
    assert f'A = {a}"' in shown and math.isclose(float(a), result.iso.figures["A"], abs_tol=0.5)
