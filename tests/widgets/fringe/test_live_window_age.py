"""The live window's age limit: a head that loses its signal is judged on what it gives
now, not on the good periods it gave before (found trying the window with the simulator:
the bars stayed green for a head whose signal had gone)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.widgets.fringe.test_live_signals_gui import fringe, live, signal_lines  # noqa: F401


def test_a_head_whose_signal_goes_turns_red_within_the_age_limit(fringe):  # noqa: F811
    panel, stream, _ = live(fringe)
    panel.max_age.setValue(2.0)  # the fake stream's clock: 1 ms a line
    stream.send(signal_lines(a=0.5, b=0.5, periods=16))  # 4 s of a good head: 1 Vpp
    panel.tick()
    assert panel.figures.figures["amplitude_a"] == pytest.approx(1.0, rel=1e-6)
    assert panel.bars["amplitude_a"].state == "inside"
    # the signal drops to 5 mVpp (the head lifted): 2.5 s of it
    stream.send(signal_lines(a=0.0025, b=0.0025, periods=10, theta0=1.0), block=500)
    panel.tick()
    assert panel.bars["amplitude_a"].state == "outside"
    assert panel.figures.figures["amplitude_a"] < 0.01
    # without the limit the window reached back to the good periods
    panel.max_age.setValue(600.0)
    panel.refresh()
    assert panel.figures.figures["amplitude_a"] > 0.1


def test_without_signal_no_interpolation_error_is_drawn(fringe):  # noqa: F811
    panel, stream, _ = live(fringe)
    stream.send(signal_lines(a=0.5, b=0.5, periods=8))
    panel.tick()
    assert panel.error_band.isVisible() and len(panel.error_mean.xData) > 0
    rng = np.random.default_rng(5)  # then only noise: the head lifted off
    noise = rng.normal(0, 0.002, (3000, 2))
    stream.send([f"{s:.9f},{c:.9f}".encode() for s, c in noise])
    panel.tick()
    assert "no signal above the noise" in panel.status.text()
    assert not panel.error_band.isVisible()
    assert panel.error_mean.xData is None or len(panel.error_mean.xData) == 0
    assert panel.bars["amplitude_a"].state == "outside"
    assert math.isnan(panel.bars["phase_deviation"].value)
