"""The live view's figures of a sliding window, checked against signals made here with known
amplitudes, ratio, phase and offsets (sampled at a true phase that the code never sees),
judged exactly at the band edges; the window of the last periods; min/max since reset."""

from __future__ import annotations

import math

import numpy as np
import pytest

from models.fringe.live_signals import Extremes, SampleWindow, live_figures
from models.fringe.signal_tolerance import BUILTIN_PRESETS

ONE_VPP = next(p for p in BUILTIN_PRESETS if p.key == "heidenhain_1vpp")


def signals(a=0.5, b=0.5, offset_a=0.0, offset_b=0.0, phase_deg=0.0, periods=12.0,
            per_period=400, speed_wobble=0.3, noise=0.0, seed=3):
    """u_sin = oa + a·sin θ, u_cos = ob + b·cos(θ + φ): a peak-to-peak of 2a and 2b, the
    cos channel's phase φ past the 90° of a quadrature pair. θ advances unevenly (a hand
    turning the shaft)."""
    n = int(periods * per_period)
    k = np.arange(n)
    step = 2 * math.pi / per_period * (1 + speed_wobble * np.sin(2 * math.pi * k / (2.7 * per_period)))
    theta = np.cumsum(step)
    theta *= 2 * math.pi * periods / theta[-1]
    rng = np.random.default_rng(seed)
    u_sin = offset_a + a * np.sin(theta) + rng.normal(0, noise, n)
    u_cos = offset_b + b * np.cos(theta + math.radians(phase_deg)) + rng.normal(0, noise, n)
    return u_sin, u_cos


def test_the_figures_are_those_the_signals_were_made_with():
    u_sin, u_cos = signals(a=0.45, b=0.52, offset_a=0.02, offset_b=-0.015, phase_deg=4.0)
    got = live_figures(u_sin, u_cos, ONE_VPP, 12.0)
    assert got.problem == ""
    f = got.figures
    assert f["amplitude_a"] == pytest.approx(0.9, abs=1e-9)
    assert f["amplitude_b"] == pytest.approx(1.04, abs=1e-9)
    assert f["amplitude_ratio"] == pytest.approx(0.52 / 0.45, rel=1e-9)
    assert f["phase_deviation"] == pytest.approx(4.0, abs=1e-7)
    # the asymmetry (P − N)/2M in %: P = o + a, N = a − o, M = 2a
    assert f["offset_a"] == pytest.approx(100 * 0.02 / 0.9, abs=1e-7)
    assert f["offset_b"] == pytest.approx(100 * -0.015 / 1.04, abs=1e-7)
    assert {j.quantity: j.state for j in got.judgements} == dict.fromkeys(
        ("amplitude_a", "amplitude_b", "amplitude_ratio", "phase_deviation", "offset_a",
         "offset_b"), "inside")


def test_the_interpolation_error_is_what_an_arctangent_makes_of_the_signals():
    # a phase error φ between the channels: atan2(sin θ, cos(θ + φ)) − θ, worked out here
    u_sin, u_cos = signals(phase_deg=6.0, periods=8)
    got = live_figures(u_sin, u_cos, ONE_VPP, 8.0)
    theta = np.linspace(0, 2 * math.pi, 20001)
    error = np.arctan2(np.sin(theta), np.cos(theta + math.radians(6.0))) - theta
    error = (error + math.pi) % (2 * math.pi) - math.pi
    assert got.error_peak_to_peak_deg == pytest.approx(math.degrees(np.ptp(error)), abs=0.01)


@pytest.mark.parametrize("amplitude_vpp, state", [(0.6, "inside"), (1.2, "inside"),
                                                  (0.6 * (1 - 1e-6), "outside"),
                                                  (1.2 * (1 + 1e-6), "outside")])
def test_an_amplitude_on_the_edge_is_inside_and_just_beyond_it_is_not(amplitude_vpp, state):
    u_sin, u_cos = signals(a=amplitude_vpp / 2, b=0.45)
    got = live_figures(u_sin, u_cos, ONE_VPP, 12.0)
    judged = {j.quantity: j for j in got.judgements}
    assert judged["amplitude_a"].state == state


@pytest.mark.parametrize("phase_deg, state", [(10.0, "inside"), (-10.0, "inside"),
                                              (10.0 + 1e-5, "outside"), (-10.0 - 1e-5, "outside")])
def test_a_phase_on_the_edge_is_inside(phase_deg, state):
    u_sin, u_cos = signals(phase_deg=phase_deg)
    judged = {j.quantity: j for j in live_figures(u_sin, u_cos, ONE_VPP, 12.0).judgements}
    assert judged["phase_deviation"].state == state


def test_a_standing_scale_gives_no_figures_and_says_why():
    u_sin, u_cos = signals(periods=0.4)
    got = live_figures(u_sin, u_cos, ONE_VPP, 0.4)
    assert got.figures == {} and got.judgements == []
    assert "0.40 periods" in got.problem


def test_the_window_holds_the_last_periods_and_the_lines_they_came_from():
    u_sin, u_cos = signals(periods=30, per_period=200, speed_wobble=0.0)
    window = SampleWindow(capacity=4000)  # 20 periods' worth
    for start in range(0, u_sin.size, 700):  # blocks of any size
        stop = min(start + 700, u_sin.size)
        window.add(u_sin[start:stop], u_cos[start:stop], np.arange(start, stop) * 2)
    assert len(window) == 4000 and window.total == 6000
    s, c, index, periods = window.last_periods(10)
    assert periods == pytest.approx(10, abs=0.01)
    assert s.size == pytest.approx(2000, abs=2)
    assert np.array_equal(s, u_sin[-s.size:]) and np.array_equal(index, np.arange(6000 - s.size, 6000) * 2)
    # fewer periods held than asked: all of them, and how many they are
    s, _, _, periods = window.last_periods(50)
    assert s.size == 4000 and periods == pytest.approx(20, abs=0.01)


def test_min_and_max_since_the_reset():
    extremes = Extremes()
    extremes.add({"amplitude_a": 1.0, "phase_deviation": -2.0})
    extremes.add({"amplitude_a": 0.8, "phase_deviation": 3.0, "offset_a": math.nan})
    assert extremes.low == {"amplitude_a": 0.8, "phase_deviation": -2.0}
    assert extremes.high == {"amplitude_a": 1.0, "phase_deviation": 3.0}
    extremes.reset()
    extremes.add({"amplitude_a": 0.9})
    assert extremes.low == extremes.high == {"amplitude_a": 0.9}
