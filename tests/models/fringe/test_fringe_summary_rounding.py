"""The fringe window's (and ``anglebench analyze fringe``'s) parameter lines print each
fitted amplitude with its uncertainty to two significant digits and the value to the same
decimal (GUM 7.2.6), as the certificate rounds its U (day review 68 F12: "A1 = 0.5000 ±
0.0000 V", the uncertainty rounded to nothing, where the certificate printed 0.000038 V).

The channels come from tests/fringe_channels.py (first principles, nothing from models/);
the standard uncertainty a least-squares amplitude has is worked out here from the noise:
over whole periods at equal steps each of a harmonic's sin and cos coefficients has
variance 2σ²/n, and so has the amplitude they make.
"""

from __future__ import annotations

import functools
import math
import re

import numpy as np
import pytest

from models.fringe.analysis import FRINGE
from models.readings.sheet import ParsedReadings
from tests.fringe_channels import Channels, equal_steps

LINES = 16384
PER_PERIOD, PERIODS = 64, 8
NOISE_V = 0.0003
HEAD = Channels(offsets_v=(0.003, -0.004), amplitudes_v=(0.5, 0.49), quadrature_deg=0.5,
                sin_harmonics={3: (0.006, 0.4)}, cos_harmonics={3: (0.003, -0.3)},
                noise_v=NOISE_V)
NUMBER = r"([+-]?\d+(?:\.\d+)?)"


@functools.lru_cache(maxsize=2)  # one analysis a noise for all the checks
def _summary(noise_v: float = NOISE_V, per_period: int = PER_PERIOD,
             periods: int = PERIODS) -> str:
    theta = equal_steps(per_period * periods, per_period)
    head = Channels(**{**HEAD.__dict__, "noise_v": noise_v})
    u_sin, u_cos = head.sample(theta, np.random.default_rng(11))
    parsed = ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                             "theta_deg": np.full(theta.size, np.nan)}, np.arange(theta.size))
    result = FRINGE.analyze(parsed, {"max_order": 3, "lines_per_rev": LINES,
                                     "samples_per_period": per_period})
    return FRINGE.summary(result)


def _significant(text: str) -> str:
    return text.replace(".", "").lstrip("0")


@pytest.mark.parametrize(("name", "true_v"), [("A1", 0.5), ("B1", 0.49), ("A3", 0.006)])
def test_each_amplitude_is_printed_to_its_uncertainty_with_two_significant_digits(name, true_v):
    text = _summary()
    found = re.search(rf"{name} = {NUMBER} ± {NUMBER} V", text)
    assert found, text
    value, u = found.group(1), found.group(2)
    # u never rounded to nothing, two significant digits of it, the value to its decimal
    assert float(u) > 0, text
    assert len(_significant(u)) == 2, u
    assert len(value.split(".")[1]) == len(u.split(".")[1]), (value, u)
    # the u of a least-squares amplitude from the noise (2σ²/n): what the line states
    expected_u = NOISE_V * math.sqrt(2.0 / (PER_PERIOD * PERIODS))
    assert 0.8 * expected_u < float(u) < 1.25 * expected_u, (u, expected_u)
    assert abs(float(value) - true_v) < 4 * expected_u, (value, true_v)


def test_the_offsets_are_printed_to_their_uncertainty_and_the_uncertainty_named():
    text = _summary()
    for name, true_v in (("A0", 0.003), ("B0", -0.004)):
        found = re.search(rf"{name} = {NUMBER} ± {NUMBER} V", text)
        assert found, text
        value, u = found.group(1), found.group(2)
        assert float(u) > 0 and len(_significant(u)) == 2, u
        assert len(value.split(".")[1]) == len(u.split(".")[1]), (value, u)
        # the offset's u from the noise: σ/√n
        expected_u = NOISE_V / math.sqrt(PER_PERIOD * PERIODS)
        assert 0.8 * expected_u < float(u) < 1.25 * expected_u, (u, expected_u)
        assert abs(float(value) - true_v) < 4 * expected_u
    # which uncertainty it is (a standard one, not the certificate's U = k·u)
    assert text.count("(± u, k = 1)") == 2, text


def test_a_larger_noise_gives_fewer_decimals_never_a_third_significant_digit():
    # 32 samples with 50 mV of noise: u(A1) ≈ 0.0125 V, printed to 0.001 V, not "0.0125"
    text = _summary(noise_v=0.05, per_period=16, periods=2)
    found = re.search(rf"A1 = {NUMBER} ± {NUMBER} V", text)
    assert found, text
    value, u = found.group(1), found.group(2)
    assert len(_significant(u)) == 2 and len(value.split(".")[1]) == 3, (value, u)
    expected_u = 0.05 * math.sqrt(2.0 / 32)
    assert 0.8 * expected_u < float(u) < 1.25 * expected_u, (u, expected_u)


def test_offsets_that_round_to_zero_are_printed_unsigned():
    """live78 F7: a centred head's result read "Offsets -0.00 / +0.00 mV" in the window and
    on the command line, where the window prints zero unsigned (gui78)."""
    theta = equal_steps(PER_PERIOD * PERIODS, PER_PERIOD)
    head = Channels(**{**HEAD.__dict__, "offsets_v": (-0.000001, 0.000001), "noise_v": 0.0,
                       "quadrature_deg": 0.0})
    u_sin, u_cos = head.sample(theta, np.random.default_rng(11))
    parsed = ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                             "theta_deg": np.full(theta.size, np.nan)}, np.arange(theta.size))
    result = FRINGE.analyze(parsed, {"max_order": 3, "lines_per_rev": LINES,
                                     "samples_per_period": PER_PERIOD})
    assert -5e-3 < 1e3 * result.sin_fit.offset < 0 < 1e3 * result.cos_fit.offset < 5e-3
    text = FRINGE.summary(result)
    assert "Offsets 0.00 / 0.00 mV" in text, text
    assert "quadrature error 0.000°" in text, text  # nor "+0.000°"
    assert "zero at its mean): 0.000\" … 0.000\" (peak-to-peak 0.000\"" in text, text
