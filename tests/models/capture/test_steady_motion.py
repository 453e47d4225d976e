"""The capture panel's reason an auto-take waits: the output moving (the axis turning to the
next point, a drift) is told from a window too tight for the noise. Frames are simulated as
an instrument sends them: a true position sampled at the instrument's rate, plus its noise
(models.capture.stability.steady_motion; app/capture/panel.py says "moving" or "widen")."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.capture.stability import steady_motion


def _frames(rate_hz: float, seconds: float, position, noise: float, seed: int = 0):
    rng = np.random.default_rng(seed)
    t = np.arange(0.0, seconds, 1.0 / rate_hz)
    return t, np.array([position(x) for x in t]) + rng.normal(0.0, noise, t.size)


@pytest.mark.parametrize("rate_hz", [10.0, 50.0, 250.0])
def test_an_axis_turning_is_moving_at_its_rate(rate_hz):
    """A rotary table turning at 1°/s read by a readout (degrees, 0.0001° noise)."""
    t, y = _frames(rate_hz, 1.0, lambda x: 30.0 + 1.0 * x, 1e-4)
    assert steady_motion(t, y) == pytest.approx(1.0, rel=1e-3)


def test_a_slow_drift_beyond_the_noise_is_moving():
    """An autocollimator drifting 2″/s with 0.05″ noise (the window 0.5″ never holds)."""
    t, y = _frames(50.0, 1.0, lambda x: 12.0 - 2.0 * x, 0.05, seed=3)
    assert steady_motion(t, y) == pytest.approx(-2.0, rel=0.05)


def test_the_axis_that_moves_is_found_among_two():
    """Hz turning, V still (a theodolite's two angles as frames × axes)."""
    t, hz = _frames(20.0, 1.0, lambda x: 0.5 * x, 1e-5, seed=1)
    _, v = _frames(20.0, 1.0, lambda x: 90.0, 1e-5, seed=2)
    assert steady_motion(t, np.column_stack([v, hz])) == pytest.approx(0.5, rel=1e-3)


@settings(max_examples=200, deadline=None, derandomize=True)
@given(seed=st.integers(0, 10_000), frames=st.integers(5, 250),
       noise=st.floats(1e-6, 10.0))
def test_noise_alone_is_never_called_moving(seed, frames, noise):
    """A still instrument, whatever its noise and rate: the window is what is too tight."""
    t, y = _frames(float(frames), 1.0, lambda x: 5.0, noise, seed=seed)
    assert steady_motion(t, y) is None


@pytest.mark.parametrize("frames", [5, 8, 16, 64])
def test_noise_is_not_called_moving_in_two_thousand_looks(frames):
    """What the panel looks at four times a second: many stills of one noisy instrument
    (the twice-the-scatter rule alone called 0.27 % of them moving at 8 frames: ~5 here)."""
    rng = np.random.default_rng(frames)
    t = np.arange(frames) / frames
    calls = sum(steady_motion(t, rng.normal(0.0, 1.0, frames)) is not None
                for _ in range(2_000))
    assert calls == 0


def test_a_readout_at_ten_frames_a_second_turning_is_moving():
    """A readout polled ten times a second: ten frames are enough to tell a turn."""
    t, y = _frames(10.0, 1.0, lambda x: 30.0 + 0.01 * x, 1e-4)
    assert steady_motion(t, y) == pytest.approx(0.01, rel=0.05)


def test_too_few_frames_tell_nothing():
    t = np.arange(4) * 0.25
    assert steady_motion(t, 3.0 * t) is None
    assert steady_motion([0.0] * 10, np.arange(10.0)) is None  # no time span
