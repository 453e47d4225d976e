import numpy as np
import pytest
from scipy.optimize import least_squares

from models.theodolite.model import (
    SetupParameters,
    _elevation_jacobian,
    _elevation_model,
    analyze_run,
    elevation_coefficients,
    forward_readings,
    identify_from_elevations,
    induced_error_arcsec,
    rotated_normal,
    setups_from_coefficients,
    simulate_readings,
)

THETA = np.arange(-20.0, 21.0, 1.0)


# -- check figures of ../shared/SPEC.md section 1 -------------------------------------------
def test_check_figure_zeta_span_187_9():
    zeta = induced_error_arcsec(THETA, 3.0, 45.0, 2.0)
    assert zeta.min() == pytest.approx(-187.9, abs=0.05)
    assert zeta.max() == pytest.approx(187.9, abs=0.05)


def test_check_figure_alpha_sweep_spread_270_1():
    alphas = np.arange(0.0, 360.0, 0.25)
    curves = np.array([induced_error_arcsec(THETA, 3.0, a, 2.0) for a in alphas])
    assert np.ptp(curves, axis=0).max() == pytest.approx(270.1, abs=0.05)


def test_check_figure_experiment_span():
    zeta = induced_error_arcsec(THETA, 5.8249, 43.4965, -0.0395)
    assert zeta.min() == pytest.approx(-301.1, abs=0.5)
    assert zeta.max() == pytest.approx(422.6, abs=0.5)


# -- forward model ----------------------------------------------------------------
def test_rodrigues_matches_eqs_2_to_4_of_the_seed():
    psi, alpha, beta = np.radians([3.0, 45.0, 2.0])
    th = np.radians(THETA)
    sp, cp, sa, ca = np.sin(psi), np.cos(psi), np.sin(alpha), np.cos(alpha)
    sb, cb = np.sin(beta), np.cos(beta)
    one_c = 1 - np.cos(th)
    x = (np.cos(th) + sp**2 * ca**2 * one_c) * cb + (sp * cp * ca * one_c + sp * sa * np.sin(th)) * sb
    y = (sp**2 * ca * sa * one_c + cp * np.sin(th)) * cb + (sp * sa * cp * one_c - sp * ca * np.sin(th)) * sb
    z = (-sp * ca * cp * one_c + sp * sa * np.sin(th)) * cb - (np.cos(th) + cp**2 * one_c) * sb
    np.testing.assert_allclose(rotated_normal(THETA, 3.0, 45.0, 2.0), [x, y, z], atol=1e-15)


def test_no_tilt_means_no_induced_error_and_constant_elevation():
    assert np.max(np.abs(induced_error_arcsec(THETA, 0.0, 30.0, 4.0))) < 1e-9
    _, elevation = forward_readings(THETA, 0.0, 30.0, 4.0)
    np.testing.assert_allclose(elevation, -4.0, atol=1e-12)


def test_elevation_is_linear_in_cos_sin():
    a, b, c = elevation_coefficients(3.0, 45.0, 2.0)
    _, elevation = forward_readings(THETA, 3.0, 45.0, 2.0)
    th = np.radians(THETA)
    np.testing.assert_allclose(np.sin(np.radians(elevation)), a + b * np.cos(th) + c * np.sin(th),
                               atol=1e-15)


def test_closed_form_inversion_finds_both_roots():
    roots = setups_from_coefficients(*elevation_coefficients(3.0, 45.0, 2.0))
    assert len(roots) == 2
    assert roots[0].as_array() == pytest.approx([3.0, 45.0, 2.0], abs=1e-10)
    assert roots[1].psi_deg > 80.0
    # both produce the same elevations: the second root "fits equally well"
    _, e0 = forward_readings(THETA, *roots[0].as_array())
    _, e1 = forward_readings(THETA, *roots[1].as_array())
    np.testing.assert_allclose(e0, e1, atol=1e-10)


def test_analytic_jacobian_matches_finite_differences():
    x = np.radians([4.0, 130.0, -3.0])
    th = np.radians(THETA)
    numeric = np.empty((th.size, 3))
    for k in range(3):
        h = np.zeros(3)
        h[k] = 1e-7
        numeric[:, k] = (_elevation_model(x + h, th) - _elevation_model(x - h, th)) / 2e-7
    np.testing.assert_allclose(_elevation_jacobian(x, th), numeric, atol=1e-7)


# -- identification: convergence for every set-up ------------------------------------
def random_setups(count, seed):
    rng = np.random.default_rng(seed)
    for _ in range(count):
        yield (
            SetupParameters(rng.uniform(-10, 10), rng.uniform(0, 360), rng.uniform(-10, 10)),
            np.linspace(-(h := rng.uniform(5, 60)), h, int(rng.integers(5, 501))),
            rng,
        )


@pytest.mark.slow
def test_noise_free_recovery_to_1e_6_arcsec_for_every_setup():
    for setup, theta, _ in random_setups(300, seed=11):
        _, elevation = forward_readings(theta, *setup.as_array())
        found = identify_from_elevations(theta, elevation).setup
        truth = induced_error_arcsec(theta, *setup.as_array())
        assert np.max(np.abs(induced_error_arcsec(theta, *found.as_array()) - truth)) < 1e-6
        canonical = setup.canonical()
        assert found.psi_deg == pytest.approx(canonical.psi_deg, abs=1e-9)
        assert found.beta_deg == pytest.approx(canonical.beta_deg, abs=1e-9)


@pytest.mark.slow
def test_noisy_fit_always_reaches_the_global_optimum():
    """With 0.3" noise the fit matches one started at the true parameters (the optimum)."""
    for setup, theta, rng in random_setups(300, seed=12):
        _, elevation = simulate_readings(theta, setup, noise_arcsec=0.3, rng=rng)
        found = identify_from_elevations(theta, elevation)
        th, e = np.radians(theta), np.radians(elevation)
        at_truth = least_squares(lambda x, th=th, e=e: _elevation_model(x, th) - e,
                                 np.radians(setup.as_array()), method="lm", xtol=1e-15, ftol=1e-15)
        optimum = induced_error_arcsec(theta, *np.degrees(at_truth.x))
        assert np.max(np.abs(induced_error_arcsec(theta, *found.setup.as_array()) - optimum)) < 0.01


@pytest.mark.slow
def test_uncertainties_agree_with_monte_carlo():
    setup = SetupParameters(5.0, 200.0, -3.0)
    rng = np.random.default_rng(5)
    estimates, reported = [], None
    for _ in range(300):
        _, elevation = simulate_readings(THETA, setup, noise_arcsec=0.5, rng=rng)
        ident = identify_from_elevations(THETA, elevation)
        estimates.append(ident.setup.as_array())
        reported = ident.uncertainty_deg
    spread = np.std(estimates, axis=0, ddof=1)
    np.testing.assert_allclose(reported, spread, rtol=0.2)


def test_short_range_warns_which_parameters_cannot_be_separated():
    theta = np.linspace(-1.0, 1.0, 9)
    rng = np.random.default_rng(3)
    _, elevation = simulate_readings(theta, SetupParameters(3.0, 45.0, 2.0), noise_arcsec=0.3,
                                     rng=rng)
    ident = identify_from_elevations(theta, elevation)
    assert any(w.startswith("ψ and α cannot be separated") for w in ident.warnings)


def test_too_few_points():
    with pytest.raises(ValueError, match="at least 4"):
        identify_from_elevations([0, 1, 2], [0, 0, 0])


# -- the whole run -------------------------------------------------------------------
def true_axis_error(theta):
    """A true error with a linear (scale) part and a periodic part, arcsec."""
    return 0.05 * theta + 0.8 * np.sin(np.radians(theta) * 9)


def test_recovers_true_error_with_linear_part_from_noisy_readings():
    setup = SetupParameters(5.8249, 43.4965, -0.0395)
    rng = np.random.default_rng(8)
    truth = true_axis_error(THETA)
    azimuth, elevation = simulate_readings(THETA, setup, truth, noise_arcsec=0.3, rng=rng)
    result = analyze_run(THETA, azimuth, elevation, accuracy_arcsec=0.5)
    assert result.raw_stats.peak_to_peak > 700
    deviation = result.corrected_error_arcsec - truth
    assert np.sqrt(np.mean(deviation**2)) < 0.6  # 0.3" azimuth noise plus propagated fit noise
    slope = np.polyfit(THETA, result.corrected_error_arcsec, 1)[0]
    assert slope == pytest.approx(np.polyfit(THETA, truth, 1)[0], abs=0.01)
    assert result.warnings == []


def test_noise_free_run_recovers_true_error_exactly():
    """Elevations are read at the true rotation; the fit must use it, not the indicated θ."""
    setup = SetupParameters(5.8249, 43.4965, -0.0395)
    truth = true_axis_error(THETA)
    azimuth, elevation = simulate_readings(THETA, setup, truth)
    result = analyze_run(THETA, azimuth, elevation)
    assert np.max(np.abs(result.corrected_error_arcsec - truth)) < 1e-6
    assert result.identification.r_squared > 0.999999


@pytest.mark.slow
def test_azimuth_route_absorbs_the_linear_part_and_warns():
    setup = SetupParameters(5.8249, 43.4965, -0.0395)
    truth = true_axis_error(THETA)
    azimuth, elevation = simulate_readings(THETA, setup, truth)
    result = analyze_run(THETA, azimuth, elevation, method="azimuth")
    assert any("absorbed" in w for w in result.warnings)
    slope = np.polyfit(THETA, result.corrected_error_arcsec, 1)[0]
    true_slope = np.polyfit(THETA, truth, 1)[0]
    assert abs(slope) < 0.2 * true_slope  # most of the scale error vanished into the model


def test_reference_row_and_relative_angles():
    setup = SetupParameters(3.0, 45.0, 2.0)
    theta = np.arange(0.0, 41.0, 1.0)
    azimuth, elevation = forward_readings(theta - 20.0, *setup.as_array())
    result = analyze_run(theta, azimuth + 17.0, elevation, reference_index=20)
    assert result.reference_theta_deg == 20.0
    assert np.max(np.abs(result.corrected_error_arcsec)) < 1e-6


def test_residuals_far_above_accuracy_warn():
    rng = np.random.default_rng(2)
    azimuth, elevation = simulate_readings(THETA, SetupParameters(3, 45, 2), noise_arcsec=5.0,
                                           rng=rng)
    result = analyze_run(THETA, azimuth, elevation, accuracy_arcsec=0.5)
    assert any("three times the theodolite accuracy" in w for w in result.warnings)


def test_repeated_passes_give_iso230_figures():
    setup = SetupParameters(3.0, 45.0, 2.0)
    rng = np.random.default_rng(4)
    theta = np.tile(THETA, 4)
    directions = np.repeat([1, -1, 1, -1], THETA.size)
    truth = true_axis_error(theta) + 0.5 * directions  # a 1" reversal
    azimuth, elevation = simulate_readings(theta, setup, truth, noise_arcsec=0.1, rng=rng)
    result = analyze_run(theta, azimuth, elevation, directions=directions)
    figures = result.iso230.figures
    assert figures["B"] == pytest.approx(1.0, abs=0.4)
    assert result.iso230.reversal.mean() == pytest.approx(1.0, abs=0.1)
    assert figures["R"] >= figures["B"]


def test_one_theta_typed_twice_gives_no_accuracy_below_e():
    """#41 item 6: one θ typed twice made the other θ single readings; A↑ was the ±2s band of
    the one repeated θ (0.11″) below E↑ (2.56″). ISO 230-2 takes A and R over every target:
    with s unknown at the others they are not evaluated, and the summary says why."""
    from models.theodolite.analysis import THEODOLITE

    setup = SetupParameters(3.0, 45.0, 2.0)
    rng = np.random.default_rng(8)
    theta = np.append(THETA, THETA[7])  # θ = THETA[7] typed twice
    azimuth, elevation = simulate_readings(theta, setup, true_axis_error(theta),
                                           noise_arcsec=0.05, rng=rng)
    result = analyze_run(theta, azimuth, elevation)
    figures = result.iso230.figures
    assert figures["E_up"] == pytest.approx(np.ptp(true_axis_error(THETA)), abs=0.3)
    assert "A_up" not in figures and "R_up" not in figures
    assert result.iso230.approached_once["up"].size == THETA.size - 1
    text = THEODOLITE.summary(result)
    assert "A and R not evaluated" in text and "A_up" not in text
    # every θ read twice: A↑ is back, and never below E↑
    theta2 = np.tile(THETA, 2)
    azimuth, elevation = simulate_readings(theta2, setup, true_axis_error(theta2),
                                           noise_arcsec=0.05, rng=rng)
    figures = analyze_run(theta2, azimuth, elevation).iso230.figures
    assert figures["A_up"] >= figures["E_up"] > 0
