"""Thinning a long curve for drawing keeps every excursion."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from models.decimation import envelope, one_per_cell


@pytest.mark.slow
@settings(max_examples=80, deadline=None)
@given(arrays(float, st.integers(1, 5000), elements=st.floats(-1e6, 1e6)),
       st.integers(1, 400))
def test_envelope_keeps_extremes_order_and_size(y, bins):
    x = np.arange(y.size, dtype=float)
    ex, ey = envelope(x, y, bins)
    assert ex.size <= max(2 * bins, y.size)
    assert ey.max() == y.max() and ey.min() == y.min()
    assert np.all(np.diff(ex) >= 0)  # in the curve's order
    assert np.array_equal(y[ex.astype(int)], ey)  # points of the curve, not made up
    if y.size > 2 * bins:  # every run's own extremes are kept
        run = -(-y.size // bins)
        for start in range(0, y.size, run):
            part = y[start:start + run]
            inside = (ex >= start) & (ex < start + run)
            assert ey[inside].max() == part.max() and ey[inside].min() == part.min()


@settings(max_examples=60, deadline=None)
@given(st.integers(0, 20_000), st.integers(0, 2**31), st.integers(4, 300))
@pytest.mark.slow
def test_a_thinned_scatter_draws_every_cell_the_points_fill(n, seed, cells):
    """Each drawn point is a sample; every sample shares a grid cell with a drawn one (so an
    outlier is drawn); no two drawn points share a cell; the record's order is kept."""
    rng = np.random.default_rng(seed)
    t = rng.uniform(0, 2 * np.pi, n)
    x, y = 3.7 * np.cos(t) + rng.normal(0, 0.01, n), 3.7 * np.sin(t) + rng.normal(0, 0.01, n)
    if n:
        x[rng.integers(n)] = 9.0  # a spike typed over one sample
    shown = one_per_cell(x, y, cells)
    assert np.all(np.diff(shown) > 0)
    if n <= 2 * cells:
        assert shown.size == n
        return

    def cell(v):
        return np.minimum(((v - v.min()) / np.ptp(v) * cells).astype(int), cells - 1)

    every, drawn = set(zip(cell(x), cell(y), strict=True)), list(zip(cell(x)[shown],
                                                                     cell(y)[shown], strict=True))
    assert set(drawn) == every and len(drawn) == len(every)
    assert np.argmax(x) in shown  # the spike
