"""Fringe records the data cannot determine (issue 39): shorter than one period, or harmonic
orders that alias at the samples per period — refused, naming the share or the pair.

The channels are sampled sin/cos of a known true phase (tests/fringe_channels.py: first
principles, numpy only, nothing from models/), with harmonics, noise and an ADC's
quantisation.
"""

from __future__ import annotations

import numpy as np
import pytest

from app.main import main
from models.fringe.analysis import FRINGE
from models.readings.sheet import ParsedReadings
from tests.fringe_channels import Channels, equal_steps

HEAD = Channels(offsets_v=(0.01, -0.02), amplitudes_v=(1.0, 0.97), quadrature_deg=0.4,
                sin_harmonics={3: (0.012, 0.3), 5: (0.004, 1.0)},
                cos_harmonics={3: (0.009, -0.2)}, noise_v=0.001, adc_bits=16)


def _parsed(count: int, per_period: int, with_theta: bool = False) -> ParsedReadings:
    theta = equal_steps(count, per_period)
    u_sin, u_cos = HEAD.sample(theta, np.random.default_rng(count))
    column = np.degrees(theta) if with_theta else np.full(count, np.nan)
    return ParsedReadings({"u_sin": u_sin, "u_cos": u_cos, "theta_deg": column},
                          np.arange(count))


@pytest.mark.parametrize("with_theta", [False, True])
def test_a_record_shorter_than_one_period_is_refused_with_its_share(with_theta):
    settings = {"samples_per_period": 0 if with_theta else 64}
    with pytest.raises(ValueError, match=r"covers 62\.5 % of one period"):
        FRINGE.analyze(_parsed(40, 64, with_theta), settings)
    whole = FRINGE.analyze(_parsed(64, 64, with_theta), settings)  # one period is enough
    assert whole.sin_fit.amplitude[3] == pytest.approx(0.012, abs=0.002)


def test_orders_that_alias_at_the_samples_per_period_are_refused_naming_the_pair():
    # N = 8: sin 5θ = −sin 3θ and cos 5θ = cos 3θ at every sample
    with pytest.raises(ValueError, match=r"orders 3 and 5 alias at N = 8"):
        FRINGE.analyze(_parsed(80, 8), {"samples_per_period": 8})
    with pytest.raises(ValueError, match=r"order 3 is not determined at N = 6"):
        FRINGE.analyze(_parsed(60, 6), {"samples_per_period": 6, "max_order": 3})
    # the same samples with orders below N/2 are determined: the fit finds the truth
    result = FRINGE.analyze(_parsed(80, 8), {"samples_per_period": 8, "max_order": 3})
    assert result.sin_fit.orders == (1, 3)


def test_aliasing_is_found_in_a_theta_column_too():
    with pytest.raises(ValueError, match=r"orders 3 and 5 alias"):
        FRINGE.analyze(_parsed(80, 8, with_theta=True), {})


def test_the_command_line_refuses_with_one_line(tmp_path, capsys):
    parsed = _parsed(40, 64)
    path = tmp_path / "short.csv"
    path.write_text("u_sin,u_cos\n" + "".join(
        f"{s:.6f},{c:.6f}\n" for s, c in zip(parsed["u_sin"], parsed["u_cos"], strict=True)))
    assert main(["analyze", "fringe", str(path), "--samples-per-period", "64", "--json"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "covers 62.5 % of one period" in err[0]


def _one_period(count: int, jitter_deg: float, seed: int, with_theta: bool = True,
                noise_v: float = 0.001) -> ParsedReadings:
    """``count`` samples of a 64-step period whose true phases are jittered (the sampling's
    timing), the θ column the reference's reading of the true phase — or no θ at all."""
    rng = np.random.default_rng(seed)
    theta = equal_steps(count, 64) + np.radians(jitter_deg) * rng.standard_normal(count)
    head = Channels(offsets_v=HEAD.offsets_v, amplitudes_v=HEAD.amplitudes_v,
                    quadrature_deg=HEAD.quadrature_deg, sin_harmonics=HEAD.sin_harmonics,
                    cos_harmonics=HEAD.cos_harmonics, noise_v=noise_v, adc_bits=16)
    u_sin, u_cos = head.sample(theta, rng)
    column = np.degrees(theta) if with_theta else np.full(count, np.nan)
    return ParsedReadings({"u_sin": u_sin, "u_cos": u_cos, "theta_deg": column},
                          np.arange(count))


def test_one_period_with_jittered_or_estimated_phases_is_one_whole_period():
    """cov76 F1: one period of 64 samples (the seed's own design) with 0.5–2° of sampling
    jitter, its θ column the reference's, was refused as "99.8 % of one period" in 7 of 16
    records, and so were phases estimated from low-noise signals (no θ, no N): the step back
    from the last phase to the first is one more step of the record. Even steps a step short,
    and a jittered record a quarter of a period short, stay refused."""
    for seed in range(12):
        for jitter in (0.5, 1.0, 2.0):
            FRINGE.analyze(_one_period(64, jitter, seed), {})  # no refusal
        FRINGE.analyze(_one_period(64, 0.0, seed, with_theta=False), {})
    with pytest.raises(ValueError, match=r"covers 98\.4 % of one period"):
        FRINGE.analyze(_one_period(63, 0.0, 0), {})  # one step short
    for seed in range(4):
        with pytest.raises(ValueError, match=r"covers 7\d\.\d % of one period"):
            FRINGE.analyze(_one_period(48, 2.0, seed), {})


def _with_theta_and_n(jittered_signals: bool, seed: int) -> ParsedReadings:
    """Three periods of 64 steps, 2° of phase of timing jitter, and a θ column: either the
    signals sampled at the jittered phases and θ the reference's reading of them, or the
    signals at the equal steps and θ a noisy reference's reading of those."""
    rng = np.random.default_rng(seed)
    steps = equal_steps(192, 64)
    off_grid = steps + np.radians(2.0) * rng.standard_normal(steps.size)
    signal_at, theta = (off_grid, off_grid) if jittered_signals else (steps, off_grid)
    u_sin, u_cos = HEAD.sample(signal_at, rng)
    return ParsedReadings({"u_sin": u_sin, "u_cos": u_cos, "theta_deg": np.degrees(theta)},
                          np.arange(steps.size))


def test_a_theta_column_where_the_samples_were_is_used_in_place_of_n():
    """cov76 F4: with N and a θ column, the θ column was dropped (a warning) even when the
    sampling was jittered by 2°: the half range came out 1.3–1.8″ for a true 0.71″. The
    signals tell which phases they were taken at: fitted at the θ column's they leave far
    less residual, and then the θ column is the phase (the same figures as without N). A θ
    column that is only a noisier reading of equal steps fits worse and N stays."""
    settings = {"samples_per_period": 64, "lines_per_rev": 16384}
    for seed in range(3):
        parsed = _with_theta_and_n(True, seed)
        both = FRINGE.analyze(parsed, settings)
        theta_only = FRINGE.analyze(parsed, {**settings, "samples_per_period": 0})
        assert both.phase_source == "theta_column"
        assert np.array_equal(both.raw_error, theta_only.raw_error)
        assert any("N = 64 was not used: the samples are not at equal steps" in w
                   for w in both.warnings)
        noisy_theta = FRINGE.analyze(_with_theta_and_n(False, seed), settings)
        assert noisy_theta.phase_source == "samples_per_period"
        assert any("The θ column was not used" in w for w in noisy_theta.warnings)
