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


def _signals(a_v, noise_v, n=4000, per_period=250, seed=3):
    rng = np.random.default_rng(seed)
    theta = 2 * np.pi * np.arange(n) / per_period
    return (a_v * np.sin(theta) + rng.normal(0, noise_v, n),
            a_v * np.cos(theta) + rng.normal(0, noise_v, n))


def test_a_head_without_signal_is_judged_on_its_amplitudes_only():
    from models.fringe.live_signals import live_figures
    from models.fringe.signal_tolerance import BUILTIN_PRESETS

    preset = BUILTIN_PRESETS[0]
    u_sin, u_cos = _signals(0.0005, 0.002)  # 1 mVpp under 2 mV of noise: the head lifted
    figures = live_figures(u_sin, u_cos, preset, 16.0)
    assert set(figures.figures) == {"amplitude_a", "amplitude_b"}
    assert {j.quantity: j.state for j in figures.judgements} == {
        "amplitude_a": "outside", "amplitude_b": "outside"}
    assert "no signal above the noise" in figures.problem
    u_sin, u_cos = _signals(0.5, 0.002)  # 1 Vpp: everything judged
    figures = live_figures(u_sin, u_cos, preset, 16.0)
    assert not figures.problem and len(figures.judgements) == 6
    assert abs(figures.figures["amplitude_a"] - 1.0) < 0.01
