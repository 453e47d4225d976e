"""Signal quality along the record (#45): a head whose amplitude and phase drift over the
revolution is found in tolerance at one place and out at another."""

from __future__ import annotations

import json

import numpy as np
import pytest

from models.fringe.analysis import FRINGE
from models.fringe.signal_quality import signal_quality, tolerance_json
from models.fringe.signal_tolerance import preset_by_key, signal_figures
from models.readings.sheet import ParsedReadings
from tests.fringe_signal_simulator import Head, equal_phase

PER, PERIODS = 64, 48
VPP = preset_by_key("heidenhain_1vpp")
#: peak-to-peak of sin θ + 0.01 sin(3θ + 0.2) over 2: the third harmonic's share of it
SHAPE = Head(peak_a=1.0, harmonics={3: (0.01, 0.2)}).peak_to_peak()[0] / 2.0


def _drifting(theta_column: bool = False, noise: float = 0.0):
    """Amplitude A rising 1.1 → 1.3 Vpp along the record, the quadrature error 0 → 14°."""
    theta = equal_phase(PERIODS, PER)
    along = theta / theta[-1]
    head = Head(peak_a=0.55 + 0.1 * along, peak_b=0.55, quadrature_deg=0.0,
                harmonics={3: (0.01, 0.2)}, noise=noise)
    u_a, u_b = head.signals(theta, np.random.default_rng(1))
    # the quadrature error drifting too: B's phase moved sample by sample
    u_b = 0.55 * np.cos(theta + np.radians(14.0) * along) + 0.0055 * np.cos(3 * theta + 0.2)
    if noise:
        u_b = u_b + np.random.default_rng(2).normal(0, noise, theta.size)
    column = np.degrees(theta) if theta_column else np.full(theta.size, np.nan)
    parsed = ParsedReadings({"u_sin": u_a, "u_cos": u_b, "theta_deg": column},
                            np.arange(theta.size))
    settings = {"max_order": 3, "harmonics": "all", "lines_per_rev": 48}
    if not theta_column:
        settings["samples_per_period"] = PER
    return FRINGE.analyze(parsed, settings), along


@pytest.mark.parametrize("theta_column", [False, True])
def test_a_head_in_tolerance_at_one_place_and_out_at_another(theta_column):
    result, along = _drifting(theta_column)
    quality = signal_quality(result, VPP)
    assert len(quality.windows) == PERIODS
    for w in quality.windows:
        middle = (w["first_period"] + 0.5) / PERIODS
        true_ptp, true_quad = (1.1 + 0.2 * middle) * SHAPE, 14.0 * middle
        assert w["amplitude_a"] == pytest.approx(true_ptp, abs=3e-3)
        assert w["phase_deviation"] == pytest.approx(true_quad, abs=0.2)
        if true_ptp < 1.195:
            assert w["states"]["amplitude_a"] == "inside"
        elif true_ptp > 1.205:
            assert w["states"]["amplitude_a"] == "outside"
        if true_quad < 9.8:
            assert w["states"]["phase_deviation"] == "inside"
        elif true_quad > 10.2:
            assert w["states"]["phase_deviation"] == "outside"
    counts = quality.out_of_band["amplitude_a"]
    below = sum((1.1 + 0.2 * (i + 0.5) / PERIODS) * SHAPE <= 1.2 for i in range(PERIODS))
    assert 10 < below < PERIODS - 10  # the head crosses the edge along the record
    assert counts["inside"] == pytest.approx(below, abs=1)
    assert counts["outside"] == pytest.approx(PERIODS - below, abs=1)
    assert any("amplitude_a" in line for line in quality.summary())
    if not theta_column:  # equal steps: the place on the revolution (L = 48: 7.5° a period)
        assert quality.windows[3]["revolution_deg"] == pytest.approx(3.5 * 7.5)


def test_windows_of_several_periods_and_the_json():
    result, _ = _drifting(noise=1e-3)
    quality = signal_quality(result, VPP, periods_per_window=8)
    assert [w["periods"] for w in quality.windows] == [8] * 6
    assert quality.windows[0]["amplitude_a"] == pytest.approx((1.1 + 0.2 * 4 / PERIODS) * SHAPE,
                                                              abs=3e-3)
    whole = signal_figures(result, VPP)
    data = json.loads(json.dumps(tolerance_json(whole, VPP, 1.0, quality)))
    assert data["preset"] == "heidenhain_1vpp" and data["guard_band"] is None
    assert "not a statement of conformity" in data["note"]
    assert data["quantities"]["amplitude_a"]["inside"] == [0.6, 1.2]
    assert data["windows_by_state"]["amplitude_a"]["outside"] >= 2
    with pytest.raises(ValueError, match="at least one period"):
        signal_quality(result, VPP, periods_per_window=0)


def test_without_a_preset_in_the_records_units():
    result, _ = _drifting()
    quality = signal_quality(result)
    assert "states" not in quality.windows[0] and quality.out_of_band == {}
    assert quality.units["offset_a"] == "V"
    assert quality.windows[0]["offset_a"] == pytest.approx(0.0, abs=1e-3)
