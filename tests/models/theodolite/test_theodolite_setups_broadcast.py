"""The set-up model's ζ(θ) for many set-ups at once: ψ, α and β broadcast, each set-up's
curve bit for bit what it was.

``rotated_normal`` and ``induced_error_arcsec`` took scalar ψ, α, β; the tilt's largest
change to the half range (``tilt_half_range_change``) carried a vectorised copy of both over
every tilt direction α, which rounded P · n its own way (written out, not the BLAS dot of the
public one) and so gave another last bit in a few cases. The reference below is the two
functions of 0.8.21 (commit 00631536) as they were, the physics from first principles
(Rodrigues by scipy), and the search of 0.8.21 over the ζ of the public functions.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from models.theodolite.model import induced_error_arcsec, rotated_normal, tilt_half_range_change

D2R = math.pi / 180.0
ARCSEC_PER_RAD = 180.0 * 3600.0 / math.pi


# -- 0.8.21's functions, as they were (the reference of "bit for bit") ----------------------
def rotated_normal_0821(theta_deg, psi_deg, alpha_deg, beta_deg):
    th = np.asarray(theta_deg, dtype=float) * D2R
    psi, alpha, beta = psi_deg * D2R, alpha_deg * D2R, beta_deg * D2R
    p = np.array([-math.sin(psi) * math.cos(alpha), -math.sin(psi) * math.sin(alpha), math.cos(psi)])
    n = np.array([math.cos(beta), 0.0, -math.sin(beta)])
    cross = np.cross(p, n)
    dot = float(p @ n)
    c, s = np.cos(th), np.sin(th)
    return n[:, None] * c + cross[:, None] * s + (p * dot)[:, None] * (1.0 - c)


def induced_error_arcsec_0821(theta_deg, psi_deg, alpha_deg, beta_deg):
    theta = np.asarray(theta_deg, dtype=float)
    x, y, _ = rotated_normal_0821(theta, psi_deg, alpha_deg, beta_deg)
    th = theta * D2R
    diff = np.arctan2(y * np.cos(th) - x * np.sin(th), x * np.cos(th) + y * np.sin(th))
    return diff * ARCSEC_PER_RAD


def tilt_half_range_change_0821(rotation_deg, beta_deg, bound_arcsec, half_ranges_of):
    """0.8.21's search (a 1° grid of α at eight magnitudes, the best refined to 0.01°, at β
    and β ± twice the bound) over the half ranges ``half_ranges_of(rotation, β)(ψ″, α)``."""
    rotation = np.asarray(rotation_deg, dtype=float)
    if not bound_arcsec > 0 or rotation.size < 2:
        return 0.0

    def at(beta: float) -> float:
        half_ranges = half_ranges_of(rotation, beta)
        best, best_psi, best_alpha = 0.0, bound_arcsec, 0.0
        for psi in bound_arcsec * np.arange(1, 9) / 8.0:
            h = half_ranges(float(psi), np.arange(360.0))
            if float(h.max()) > best:
                best, best_psi, best_alpha = float(h.max()), float(psi), float(np.argmax(h))
        return max(best, float(half_ranges(best_psi, best_alpha + np.arange(-100, 101) / 100.0).max()))

    return max(at(beta_deg + k * 2.0 * bound_arcsec / 3600.0) for k in (-1, 0, 1))


def public_half_ranges_0821(rotation, beta_deg):
    """The half ranges of 0.8.21's public ζ, one α at a time (the loop the copy replaced)."""
    def half_ranges(psi_arcsec, alpha_deg):
        return np.array([0.5 * np.ptp(induced_error_arcsec_0821(rotation, psi_arcsec / 3600.0,
                                                                float(a), beta_deg))
                         for a in alpha_deg])
    return half_ranges


def copied_half_ranges_0821(rotation, beta_deg):
    """The half ranges of 0.8.21's private vectorised copy, as it was."""
    th = rotation * D2R
    c, s = np.cos(th)[None, :], np.sin(th)[None, :]
    n = np.array([math.cos(beta_deg * D2R), 0.0, -math.sin(beta_deg * D2R)])

    def half_ranges(psi_arcsec, alpha_deg):
        psi, alpha = psi_arcsec / 3600.0 * D2R, np.asarray(alpha_deg, dtype=float)[:, None] * D2R
        p = [-math.sin(psi) * np.cos(alpha), -math.sin(psi) * np.sin(alpha),
             math.cos(psi) + 0.0 * alpha]
        dot = p[0] * n[0] + p[2] * n[2]
        cross_x, cross_y = p[1] * n[2], p[2] * n[0] - p[0] * n[2]
        x = n[0] * c + cross_x * s + p[0] * dot * (1.0 - c)
        y = cross_y * s + p[1] * dot * (1.0 - c)
        zeta = np.arctan2(y * c - x * s, x * c + y * s) * ARCSEC_PER_RAD
        return 0.5 * np.ptp(zeta, axis=1)
    return half_ranges


# -- first principles ---------------------------------------------------------------------
def rodrigues_normal(theta_deg, psi_deg, alpha_deg, beta_deg):
    """The mirror normal n = (cos β, 0, −sin β) turned by θ about the axis
    P = (−sin ψ cos α, −sin ψ sin α, cos ψ), right-handed, by scipy's rotation: (3, N)."""
    psi, alpha, beta = np.radians([psi_deg, alpha_deg, beta_deg])
    axis = np.array([-np.sin(psi) * np.cos(alpha), -np.sin(psi) * np.sin(alpha), np.cos(psi)])
    normal = np.array([np.cos(beta), 0.0, -np.sin(beta)])
    return Rotation.from_rotvec(np.radians(theta_deg)[:, None] * axis).apply(normal).T


def rodrigues_error_arcsec(theta_deg, psi_deg, alpha_deg, beta_deg):
    """ζ = A − θ, A the azimuth the theodolite reads of that normal, within ±180° of θ."""
    x, y, _ = rodrigues_normal(theta_deg, psi_deg, alpha_deg, beta_deg)
    diff = np.degrees(np.arctan2(y, x)) - theta_deg
    return ((diff + 180.0) % 360.0 - 180.0) * 3600.0


def random_setup(rng):
    """θ a row of 1–40 angles; ψ from arcseconds to degrees, either sign; α any; β within
    ±89°; a third of them numpy scalars (``SetupParameters.as_array``'s)."""
    theta = (np.sort(rng.uniform(-60.0, 60.0, int(rng.integers(1, 41)))) if rng.random() < 0.5
             else rng.uniform(-400.0, 400.0, int(rng.integers(1, 41))))
    psi = float(rng.uniform(-0.1, 0.1) if rng.random() < 0.5 else rng.uniform(-10.0, 10.0))
    setup = [psi, float(rng.uniform(-720.0, 720.0)), float(rng.uniform(-89.0, 89.0))]
    if rng.random() < 1 / 3:
        return theta, list(np.array(setup))
    return theta, setup


# -- scalars: the arrays of before, bit for bit -------------------------------------------
def check_scalar_setups(count: int, seed: int) -> None:
    rng = np.random.default_rng(seed)
    for _ in range(count):
        theta, setup = random_setup(rng)
        before, now = rotated_normal_0821(theta, *setup), rotated_normal(theta, *setup)
        assert now.shape == before.shape == (3, theta.size)
        assert np.array_equal(now, before), setup
        before, now = induced_error_arcsec_0821(theta, *setup), induced_error_arcsec(theta, *setup)
        assert now.shape == before.shape == (theta.size,)
        assert np.array_equal(now, before), setup


def test_a_scalar_setup_gives_the_arrays_of_before_bit_for_bit():
    check_scalar_setups(500, seed=20261206)


@pytest.mark.slow
def test_many_scalar_setups_give_the_arrays_of_before_bit_for_bit():
    check_scalar_setups(10000, seed=73)


def test_a_scalar_rotation_gives_the_shape_of_before():
    """θ a scalar: (3, 1) and (1,), as before."""
    assert rotated_normal(12.5, 2.0, 30.0, 1.0).shape == rotated_normal_0821(12.5, 2.0, 30.0, 1.0).shape
    assert np.array_equal(induced_error_arcsec(12.5, 2.0, 30.0, 1.0),
                          induced_error_arcsec_0821(12.5, 2.0, 30.0, 1.0))


# -- arrays: (3,) + S + (N,) and S + (N,), each set-up its own curve ------------------------
def test_every_tilt_direction_at_once_is_each_directions_curve():
    rng = np.random.default_rng(7)
    theta = np.sort(rng.uniform(-50.0, 50.0, 17))
    alphas = rng.uniform(0.0, 360.0, 64)
    normals = rotated_normal(theta, 0.3, alphas, -4.0)
    errors = induced_error_arcsec(theta, 0.3, alphas, -4.0)
    assert normals.shape == (3, alphas.size, theta.size)
    assert errors.shape == (alphas.size, theta.size)
    for k, alpha in enumerate(alphas):
        assert np.array_equal(normals[:, k], rotated_normal_0821(theta, 0.3, float(alpha), -4.0))
        assert np.array_equal(errors[k], induced_error_arcsec_0821(theta, 0.3, float(alpha), -4.0))
        np.testing.assert_allclose(normals[:, k], rodrigues_normal(theta, 0.3, alpha, -4.0),
                                   rtol=0, atol=1e-14)
        np.testing.assert_allclose(errors[k], rodrigues_error_arcsec(theta, 0.3, alpha, -4.0),
                                   rtol=0, atol=1e-8)


def test_tilt_its_direction_and_the_mirror_broadcast_together():
    """ψ (m, 1), α (k,) and β (m, k) give S = (m, k); each element the scalar set-up's."""
    rng = np.random.default_rng(11)
    theta = rng.uniform(-180.0, 180.0, 9)
    psis = rng.uniform(-6.0, 6.0, (4, 1))
    alphas = rng.uniform(-360.0, 360.0, 5)
    betas = rng.uniform(-45.0, 45.0, (4, 5))
    normals = rotated_normal(theta, psis, alphas, betas)
    errors = induced_error_arcsec(theta, psis, alphas, betas)
    assert normals.shape == (3, 4, 5, theta.size)
    assert errors.shape == (4, 5, theta.size)
    for i in range(4):
        for k in range(5):
            setup = (float(psis[i, 0]), float(alphas[k]), float(betas[i, k]))
            assert np.array_equal(normals[:, i, k], rotated_normal_0821(theta, *setup))
            assert np.array_equal(errors[i, k], induced_error_arcsec_0821(theta, *setup))
            np.testing.assert_allclose(errors[i, k], rodrigues_error_arcsec(theta, *setup),
                                       rtol=0, atol=1e-8)


# -- the tilt's largest change to the half range: the search over the public ζ ------------
def random_tilt_case(rng):
    """Rotations from the reference (2–30 of them, a limited turn or a whole one), β within
    ±80°, a bound anywhere in the setting's 0.1–3600″."""
    rotation = (rng.uniform(-60.0, 60.0, int(rng.integers(2, 31))) if rng.random() < 0.5
                else rng.uniform(-180.0, 180.0, int(rng.integers(2, 31))))
    return rotation, float(rng.uniform(-80.0, 80.0)), float(rng.uniform(0.1, 3600.0))


#: seeds of random_tilt_case: 56 and 138 draw cases where 0.8.21's copy, rounding P · n its
#: own way, gave other last bits than the search over its public ζ (9e-13″ and 1.1e-11″
#: above it; 7 of seeds 0–599 do); 1, 2 and 3 draw any
TILT_SEEDS = (56, 138, 1, 2, 3)


@pytest.mark.slow
@pytest.mark.parametrize("seed", TILT_SEEDS)
def test_the_tilts_change_is_the_search_over_the_public_zeta_bit_for_bit(seed):
    """0.8.21's search over 0.8.21's public ζ one α at a time (~0.3 s a case)."""
    rotation, beta, bound = random_tilt_case(np.random.default_rng(seed))
    assert tilt_half_range_change(rotation, beta, bound) == tilt_half_range_change_0821(
        rotation, beta, bound, public_half_ranges_0821)


def test_the_tilts_change_is_the_copys_of_before_to_its_rounding():
    """Against 0.8.21's copy: the same to its rounding of ζ (1e-15 rad, 2e-10″), and the
    same no-tilt, one-rotation and no-bound answers."""
    rng = np.random.default_rng(5)
    for _ in range(10):
        rotation, beta, bound = random_tilt_case(rng)
        now = tilt_half_range_change(rotation, beta, bound)
        before = tilt_half_range_change_0821(rotation, beta, bound, copied_half_ranges_0821)
        assert abs(now - before) <= 2e-10
        assert now > 0
    assert tilt_half_range_change(np.array([0.0, 10.0]), 2.0, 0.0) == 0.0
    assert tilt_half_range_change(np.array([10.0]), 2.0, 300.0) == 0.0


# -- the tilt bound's effect at each rotation (the set-up model's error mode) ---------------
def tilt_bound_effect_one_direction_at_a_time(rotation, beta, bound):
    """tilt_bound_effect_arcsec as it was until stop 75: the public ζ one α at a time."""
    worst = np.zeros(np.shape(rotation))
    for psi in (0.5 * bound, bound):
        for alpha in np.arange(360.0):
            worst = np.maximum(worst, np.abs(induced_error_arcsec(rotation, psi / 3600.0,
                                                                  float(alpha), beta)))
    return worst


def test_the_tilt_bounds_effect_is_every_directions_largest_bit_for_bit():
    """Every tilt direction at once (one ζ of 360 directions) gives the largest |ζ| at each
    rotation that the directions one at a time give, bit for bit; a scalar rotation and no
    bound as before."""
    from models.theodolite.model import tilt_bound_effect_arcsec

    rng = np.random.default_rng(75)
    for _ in range(12):
        rotation, beta, bound = random_tilt_case(rng)
        effect = tilt_bound_effect_arcsec(rotation, beta, bound)
        assert effect.shape == rotation.shape and np.all(effect > 0)
        assert np.array_equal(effect, tilt_bound_effect_one_direction_at_a_time(
            rotation, beta, bound))
    for rotation in (np.array(12.5), np.array([0.0, 10.0])):
        assert np.array_equal(tilt_bound_effect_arcsec(rotation, 3.0, 40.0),
                              tilt_bound_effect_one_direction_at_a_time(rotation, 3.0, 40.0))
    assert not np.any(tilt_bound_effect_arcsec(np.array([0.0, 10.0]), 3.0, 0.0))
