"""The live window's age limit (models/fringe/live_signals.py): no sample of an older line."""

from __future__ import annotations

import numpy as np

from models.fringe.live_signals import SampleWindow


def test_the_window_keeps_no_line_older_than_asked():
    window = SampleWindow(10_000)
    k = np.arange(3000)
    theta = 2 * np.pi * k / 100
    window.add(np.sin(theta), np.cos(theta), k)
    u_sin, _, index, periods = window.last_periods(16)
    assert index[0] == 3000 - 1601 and abs(periods - 16) < 0.02
    u_sin, _, index, periods = window.last_periods(16, since_index=2500)
    assert index[0] == 2500 and u_sin.size == 500 and abs(periods - 4.99) < 0.02
