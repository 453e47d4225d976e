"""Accuracy against the physical limit: on simulated runs with known noise, how far our
corrected curves lie from the truth, against the Cramér–Rao bound (CRB) — the smallest
spread any unbiased method can reach with the same readings.

* Theodolite: unknowns ψ, α, β, the theodolite's azimuth zero and the axis error at
  every point but the reference (where it is zero by definition); observations the
  azimuth and elevation readings with σ noise. CRB = σ² (JᵀJ)⁻¹ with J the forward
  model's Jacobian (numerical, independent of our fitting code).
* Fringe: unknowns the 14 signal parameters; the quantity the interpolation error
  Δ(θ) = atan2(u_s, u_c) − θ that the correction table removes; CRB through Δ's
  numerical gradient.
"""

from __future__ import annotations

import numpy as np

from models.fringe.model import fit_channels, model_signal, phase_of_samples
from models.theodolite.model import SetupParameters, analyze_run, forward_readings, simulate_readings

TRIALS = 400
# every corrected point shares the reference reading's noise, so the spread converges
# slowly (400 runs leave ±3 %): the theodolite gets more runs
THEODOLITE_TRIALS = 2500


def _theodolite_crb(theta, setup, truth, sigma):
    """CRB (arcsec) of the axis error at each non-reference point."""
    ref = int(np.argmin(np.abs(theta)))
    others = np.array([i for i in range(theta.size) if i != ref])
    x0 = np.concatenate([setup.as_array(), [0.0], truth[others] / 3600.0])  # degrees

    def observe(x):
        e = np.zeros(theta.size)
        e[others] = x[4:]
        az, el = forward_readings(theta + e, *x[:3])
        return np.concatenate([az + x[3], el]) * 3600.0  # arcsec

    base = observe(x0)
    jac = np.empty((base.size, x0.size))
    for k in range(x0.size):
        step = 1e-7
        hi, lo = x0.copy(), x0.copy()
        hi[k] += step
        lo[k] -= step
        jac[:, k] = (observe(hi) - observe(lo)) / (2 * step) / 3600.0  # per arcsec
    cov = sigma**2 * np.linalg.inv(jac.T @ jac)
    crb = np.zeros(theta.size)
    crb[others] = np.sqrt(np.diag(cov)[4:])
    return crb, others


def test_theodolite_against_cramer_rao(report):
    rng = np.random.default_rng(31)
    theta = np.arange(-40.0, 40.1, 2.0)
    setup = SetupParameters(2.5, 60.0, 4.0)
    truth = 2.0 * np.sin(np.radians(3 * theta)) + 0.5 * np.sin(np.radians(7 * theta))
    sigma = 0.5
    crb, others = _theodolite_crb(theta, setup, truth, sigma)
    dev = []
    for _ in range(THEODOLITE_TRIALS):
        az, el = simulate_readings(theta, setup, truth, sigma, rng)
        dev.append(analyze_run(theta, az, el).corrected_error_arcsec - truth)
    dev = np.array(dev)[:, others]
    ours = float(np.sqrt(np.mean(dev**2)))
    bound = float(np.sqrt(np.mean(crb[others] ** 2)))
    oracle = sigma * np.sqrt(2)  # the two azimuth readings alone, set-up known exactly
    ratio = ours / bound
    report("5-accuracy-a", [
        "## Accuracy against the physical limit",
        "",
        f"{THEODOLITE_TRIALS} (theodolite) and {TRIALS} (fringe) simulated runs. RMS "
        "deviation of our corrected curve from the truth, against the Cramér–Rao bound (RMS "
        "over the points).",
        "",
        "| run | ours | CRB | ours / CRB | note |",
        "|---|---|---|---|---|",
        f"| theodolite, {theta.size} points, σ = {sigma}\" on A and E | {ours:.4f}\" | "
        f"{bound:.4f}\" | **{ratio:.3f}** | set-up known exactly would give √2σ = "
        f"{oracle:.4f}\" |",
    ], headline=(
        f"Accuracy: the theodolite's corrected curve deviates from the truth by {ratio:.3f}× "
        f"the Cramér–Rao bound ({THEODOLITE_TRIALS} simulated runs)."))
    assert abs(ratio - 1.0) < 0.10


def _delta(theta, params_s, params_c):
    s = params_s[0] + sum(params_s[1 + 2 * i] * np.sin(k * theta) + params_s[2 + 2 * i]
                          * np.cos(k * theta) for i, k in enumerate((1, 3, 5)))
    c = params_c[0] + sum(params_c[1 + 2 * i] * np.sin(k * theta) + params_c[2 + 2 * i]
                          * np.cos(k * theta) for i, k in enumerate((1, 3, 5)))
    d = np.angle(np.exp(1j * (np.arctan2(s, c) - theta)))
    return d - d.mean()


def test_fringe_against_cramer_rao(report):
    rng = np.random.default_rng(8)
    per, periods, sigma = 64, 8, 0.003
    theta = phase_of_samples(per * periods, per)
    p_s = np.array([0.02, 1.0, 0.01, 0.012, 0.004, 0.004, 0.0])
    p_c = np.array([-0.015, 0.003, 0.97, 0.005, 0.007, 0.0, 0.002])
    grid = np.linspace(0, 2 * np.pi, 256, endpoint=False)
    true_delta = _delta(grid, p_s, p_c)
    # CRB of Δ on the grid: Fisher information of the 14 linear parameters is XᵀX/σ²
    x = np.column_stack([np.ones_like(theta)] + [f(k * theta) for k in (1, 3, 5)
                                                  for f in (np.sin, np.cos)])
    info_inv = sigma**2 * np.linalg.inv(x.T @ x)
    grad = np.empty((grid.size, 14))
    base = np.concatenate([p_s, p_c])
    for k in range(14):
        hi, lo = base.copy(), base.copy()
        hi[k] += 1e-7
        lo[k] -= 1e-7
        grad[:, k] = (_delta(grid, hi[:7], hi[7:]) - _delta(grid, lo[:7], lo[7:])) / 2e-7
    crb = np.sqrt(np.einsum("ij,jk,ik->i", grad[:, :7], info_inv, grad[:, :7])
                  + np.einsum("ij,jk,ik->i", grad[:, 7:], info_inv, grad[:, 7:]))
    clean_s = x @ p_s
    clean_c = x @ p_c
    dev = []
    for _ in range(TRIALS):
        fs, fc = fit_channels(theta, [clean_s + rng.normal(0, sigma, theta.size),
                                      clean_c + rng.normal(0, sigma, theta.size)])
        est = np.angle(np.exp(1j * (np.arctan2(model_signal(grid, fs), model_signal(grid, fc))
                                    - grid)))
        dev.append((est - est.mean()) - true_delta)
    to_arcsec = 1_296_000 / 16384 / (2 * np.pi)
    ours = float(np.sqrt(np.mean(np.square(dev)))) * to_arcsec
    bound = float(np.sqrt(np.mean(crb**2))) * to_arcsec
    ratio = ours / bound
    report("5-accuracy-b", [
        f"| fringe, modelled interpolation error Δ(θ), {periods} periods × {per} samples, "
        f"σ = {sigma * 1e3:g} mV, L = 16384 | {ours:.5f}\" | {bound:.5f}\" | **{ratio:.3f}** | "
        "the correction table's own error |",
    ], headline=(
        f"Accuracy: the fringe correction table's error is {ratio:.3f}× the Cramér–Rao "
        f"bound ({TRIALS} simulated runs)."))
    assert abs(ratio - 1.0) < 0.10


