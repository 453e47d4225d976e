"""The fringe's "Signals and fit" plot of a coarsely sampled record (review finding: N = 8
samples a period joined by straight lines, the fit too, which was evaluated at the samples
only, looked like a distorted signal). The samples are drawn as markers, each where it was
read, and the fit as a continuous curve: between the samples the drawn fit is the signal
(the read head's own, from first principles: tests/fringe_channels.py, nothing from
models/), where a line joining the samples is off by A·(1 − cos(π/N)), 38 mV here."""

from __future__ import annotations

import numpy as np
import pytest

from models.fringe.analysis import FRINGE
from models.fringe.plots import figures
from models.readings.sheet import ParsedReadings
from tests.fringe_channels import Channels, equal_steps

N, PERIODS = 8, 4
HEAD = Channels(offsets_v=(0.01, -0.02), amplitudes_v=(0.5, 0.49), quadrature_deg=0.6,
                sin_harmonics={3: (0.01, 0.4)}, cos_harmonics={3: (0.008, 1.9)},
                noise_v=0.0002)


def _signals():
    theta = equal_steps(N * PERIODS, N)
    u_sin, u_cos = HEAD.sample(theta, np.random.default_rng(11))
    parsed = ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                             "theta_deg": np.full(theta.size, np.nan)}, np.arange(theta.size))
    result = FRINGE.analyze(parsed, FRINGE.settings_with_defaults(
        {"samples_per_period": N, "max_order": 3, "lines_per_rev": 16384}))
    return figures(result)["signals"], u_sin, u_cos


def test_the_samples_are_markers_where_they_were_read():
    figure, u_sin, u_cos = _signals()
    for series, read in zip(figure.series[:2], (u_sin, u_cos), strict=True):
        assert series.markers and series.width == 0, series.label  # no line joins them
        assert series.x == pytest.approx(np.arange(N * PERIODS) / N)  # phase in periods
        assert series.y == pytest.approx(read)


def test_the_fit_is_a_curve_through_the_phases_between_the_samples():
    figure, _, _ = _signals()
    clean = Channels(**{**HEAD.__dict__, "noise_v": 0.0})
    for series, channel in zip(figure.series[2:], (0, 1), strict=True):
        assert not series.markers and series.width
        assert series.x.size >= 8 * N * PERIODS  # many points between two samples
        between = (np.arange(N * PERIODS - 1) + 0.5) / N  # half-way between the samples
        drawn = np.interp(between, series.x, series.y)  # the line as drawn
        true = clean.sample(2 * np.pi * between)[channel]
        assert np.max(np.abs(drawn - true)) < 0.002, series.label  # (a chord: 38 mV off)
