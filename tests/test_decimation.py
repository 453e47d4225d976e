"""Thinning a long curve for drawing keeps every excursion."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from models.decimation import envelope


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
