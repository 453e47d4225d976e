"""models/tolerance_band.py: ±T about the decided curve's mid-range (half-range decision)
or about zero (every point judged), each curve's U as its band; no tolerance, no band."""

from __future__ import annotations

import math

import numpy as np

from models.plots import PlotFigure, PlotSeries
from models.tolerance_band import tolerance_limits, with_tolerance

X = np.array([0.0, 30.0, 60.0, 90.0])
Y = np.array([1.0, 3.5, -0.5, 2.0])
U = np.array([0.4, 0.5, 0.6, 0.4])
FIGURE = PlotFigure("errors", "θ (°)", "error (\")", (PlotSeries("mean", X, Y),))


def test_limits_about_the_mid_range_or_zero():
    # mid-range of 3.5 and −0.5 is 1.5
    assert tolerance_limits(2.0, [Y]) == (-0.5, 3.5)
    assert tolerance_limits(2.0, [Y, np.array([5.5, np.nan])]) == (0.5, 4.5)
    assert tolerance_limits(2.0, [Y], "points") == (-2.0, 2.0)


def test_the_bands_added_beside_the_figure():
    out = with_tolerance(FIGURE, 2.0, [("mean ± U", X, Y, U)])
    assert out.series[0] is FIGURE.series[0]
    band, upper, lower = out.series[1:]
    assert np.array_equal(band.y, Y) and np.array_equal(band.band, U) and band.width == 0
    assert list(upper.x) == [0.0, 90.0] and np.allclose(upper.y, 3.5)
    assert np.allclose(lower.y, -0.5) and lower.label == ""
    points = with_tolerance(FIGURE, 2.0, [("mean ± U", X, Y, None)], "points")
    assert len(points.series) == 3  # U not determined: the limits only
    assert np.allclose(points.series[1].y, 2.0) and np.allclose(points.series[2].y, -2.0)


def test_no_tolerance_no_band():
    for tolerance in (None, 0.0, -1.0, math.nan):
        assert with_tolerance(FIGURE, tolerance, [("mean ± U", X, Y, U)]) is FIGURE
    assert with_tolerance(FIGURE, 2.0, []) is FIGURE
