import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.fringe.analysis import FRINGE
from models.fringe.export import correction_table_c_header, correction_table_csv
from models.fringe.model import (
    ChannelFit,
    build_correction_table,
    channel_cost,
    fit_channel,
    fit_channel_pso,
    fit_periods,
    interpolation_error_arcsec,
    model_signal,
    period_arcsec,
    phase_of_samples,
)
from models.readings.sheet import ReadingsSheet

# Table 1 of the seed, cosine B1 read as +3.7346 (../shared/SPEC.md erratum)
SIN = ChannelFit.from_parameters(-0.0179, {1: (3.7763, 0.026), 3: (-0.0796, 3.2261),
                                           5: (0.0109, 0.4688)})
COS = ChannelFit.from_parameters(-0.0642, {1: (3.7346, 1.5902), 3: (0.079, 8.0719),
                                           5: (-0.01, 2.0662)})


def test_period_is_79_1_arcsec():
    assert period_arcsec(16384) == pytest.approx(79.1, abs=0.01)


def test_check_figure_table1_modelled_error():
    theta = phase_of_samples(4096, 4096)
    e = interpolation_error_arcsec(model_signal(theta, SIN), model_signal(theta, COS), theta, 16384)
    assert e.max() == pytest.approx(0.449, abs=0.001)
    assert e.min() == pytest.approx(-0.524, abs=0.001)
    assert np.ptp(e) == pytest.approx(0.97, abs=0.005)


def test_canonical_form():
    assert SIN.amplitude[3] == pytest.approx(0.0796) and SIN.phase[3] == pytest.approx(3.2261 - math.pi)
    assert -math.pi < COS.phase[3] <= math.pi
    assert COS.amplitude[5] == pytest.approx(0.01)


def test_least_squares_recovers_parameters_with_honest_uncertainty():
    theta = phase_of_samples(64 * 20, 64)
    rng = np.random.default_rng(4)
    estimates, reported = [], []
    for _ in range(200):
        u = model_signal(theta, SIN) + rng.normal(0, 0.003, theta.size)
        fit = fit_channel(theta, u)
        estimates.append([fit.amplitude[3], fit.phase[3]])
        reported.append([fit.u_amplitude[3], fit.u_phase[3]])
    estimates = np.array(estimates)
    np.testing.assert_allclose(estimates.mean(axis=0), [SIN.amplitude[3], SIN.phase[3]], atol=3e-4)
    np.testing.assert_allclose(estimates.std(axis=0, ddof=1), np.mean(reported, axis=0), rtol=0.2)


def test_noise_free_fit_is_exact():
    theta = phase_of_samples(64, 64)
    fit = fit_channel(theta, model_signal(theta, COS))
    for k in (1, 3, 5):
        assert fit.amplitude[k] == pytest.approx(COS.amplitude[k], abs=1e-12)
        assert fit.phase[k] == pytest.approx(COS.phase[k], abs=1e-10)


def test_compensated_error_reaches_the_noise_floor():
    theta = phase_of_samples(64 * 50, 64)
    rng = np.random.default_rng(7)
    noise = 0.002
    u_sin = model_signal(theta, SIN) + rng.normal(0, noise, theta.size)
    u_cos = model_signal(theta, COS) + rng.normal(0, noise, theta.size)
    table = build_correction_table(fit_channel(theta, u_sin), fit_channel(theta, u_cos), 1024)
    phase = table.compensate(np.arctan2(u_sin, u_cos))
    comp = interpolation_error_arcsec(np.sin(phase), np.cos(phase), theta, 16384)
    # noise floor: phase noise of a circle of radius A1 with σ per channel = σ/A1 rad
    floor = noise / 3.755 / (2 * math.pi) * period_arcsec(16384)
    assert np.std(comp) == pytest.approx(floor, rel=0.1)
    raw = interpolation_error_arcsec(u_sin, u_cos, theta, 16384)
    assert np.ptp(raw) > 20 * np.std(comp)


@pytest.mark.slow
def test_least_squares_cost_never_above_pso():
    theta = phase_of_samples(64, 64)
    rng = np.random.default_rng(0)
    for seed in range(5):
        u = model_signal(theta, SIN) + rng.normal(0, 0.002, 64)
        lsq = fit_channel(theta, u)
        pso = fit_channel_pso(theta, u, seed=seed, max_iterations=300)
        assert lsq.cost <= pso.cost * (1 + 1e-12)
        assert channel_cost(theta, u, pso.fit) == pytest.approx(pso.cost, rel=1e-9)


def test_per_period_drift():
    theta = phase_of_samples(64 * 10, 64)
    drift = np.repeat(np.linspace(3.7, 3.8, 10), 64)
    u = drift * np.sin(theta + 0.1) + 0.05 * np.sin(3 * theta)
    periods = fit_periods(u, 64)
    np.testing.assert_allclose(periods[:, 1], np.linspace(3.7, 3.8, 10), atol=1e-12)
    np.testing.assert_allclose(periods[:, 3], 0.05, atol=1e-12)


def test_sheet_analysis_and_exports():
    theta = phase_of_samples(256, 64)
    rows = [[f"{s:.6f}", f"{c:.6f}"] for s, c in zip(model_signal(theta, SIN),
                                                     model_signal(theta, COS), strict=True)]
    result = FRINGE.analyze(ReadingsSheet(FRINGE.columns, rows).parse(), {"samples_per_period": 64})
    data = FRINGE.to_json(result)
    assert set(data["sin_params"]) == {"A0", "A1", "c1", "A3", "c3", "A5", "c5"}
    assert data["raw_peak_to_peak_arcsec"] == pytest.approx(0.97, abs=0.01)
    assert data["compensated_peak_to_peak_arcsec"] < 0.01
    csv_text = correction_table_csv(result)
    assert csv_text.count("\n") == 1024 + 7  # six comment lines and the header
    assert f"# table sha256: {result.table.sha256}" in csv_text
    header = correction_table_c_header(result)
    assert "static const float anglebench_fringe_lut[1024]" in header and header.count("f,") == 1024


def test_explicit_theta_column():
    theta = phase_of_samples(100, 64) + 0.01
    rows = [[f"{s:.8f}", f"{c:.8f}", f"{math.degrees(t):.8f}"]
            for s, c, t in zip(model_signal(theta, SIN), model_signal(theta, COS), theta, strict=True)]
    result = FRINGE.analyze(ReadingsSheet(FRINGE.columns, rows).parse(), {})
    assert result.sin_fit.amplitude[1] == pytest.approx(3.7763, abs=1e-6)


@settings(max_examples=40, deadline=None)
@given(st.integers(8, 96), st.integers(2, 20), st.integers(0, 2**32 - 1),
       st.sampled_from([(1,), (1, 3, 5), (1, 2, 3, 4, 5)]))
def test_per_phase_sums_give_the_fit_of_the_whole_design(per, periods, seed, orders):
    """Samples at N equal steps with gaps: the fit from N per-phase sums is the general
    least-squares fit (parameters, uncertainties, cost, R²)."""
    from models.fringe.model import TWO_PI, fit_channels, fit_channels_by_phase

    rng = np.random.default_rng(seed)
    place = np.arange(per * periods)
    keep = rng.random(place.size) > 0.1
    keep[: 2 * len(orders) + 3] = True
    place = place[keep]
    theta = place * (TWO_PI / per)
    u = 1.3 * np.sin(theta + 0.3) + 0.05 * np.sin(3 * theta) + rng.normal(0, 0.01, theta.size)
    (a,) = fit_channels(theta, [u], orders)
    (b,) = fit_channels_by_phase(place % per, per, [u], orders)
    assert b.offset == pytest.approx(a.offset, abs=1e-10)
    for k in orders:
        assert b.amplitude[k] == pytest.approx(a.amplitude[k], abs=1e-10)
        assert b.u_amplitude[k] == pytest.approx(a.u_amplitude[k], rel=1e-6, abs=1e-12)
    assert b.cost == pytest.approx(a.cost, rel=1e-8, abs=1e-14)
    assert b.r_squared == pytest.approx(a.r_squared, abs=1e-10)


def test_the_tables_checksum_does_not_follow_the_last_bits_of_a_fit():
    """The bundled sample's table had another checksum on another processor (its values'
    last bits): an as-left checksum typed at the bench was refused where the certificate
    was issued. Values within a grid step of 1e-9 rad give one checksum; a step more does
    not."""
    from models.fringe.model import CHECKSUM_GRID_RAD, CorrectionTable

    rng = np.random.default_rng(4)
    values = 0.03 * np.sin(np.arange(1024) * 2 * np.pi / 1024 * 3) + rng.normal(0, 1e-4, 1024)
    wobble = values * (1.0 + 1e-13 * rng.standard_normal(1024))
    assert CorrectionTable(wobble).sha256 == CorrectionTable(values).sha256
    moved = values.copy()
    moved[100] += 2 * CHECKSUM_GRID_RAD
    assert CorrectionTable(moved).sha256 != CorrectionTable(values).sha256
