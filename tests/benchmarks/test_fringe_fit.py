"""Fringe: our linear least squares against what a user would otherwise reach for —
numpy.linalg.lstsq on the 7-column design, scipy.optimize.least_squares — and
against particle swarms — the seed's (our code of eqs 12–15) and pyswarms'
global-best PSO with the standard constriction settings — on one 64-sample period; then a whole
1M-sample revolution analysed by our method (per-period drift included).

Cost is the seed's (11): the sum of squared residuals of one channel (V²).
"""

from __future__ import annotations

import math
import warnings

import numpy as np
from bench_util import fmt_time, timings

from models.fringe.analysis import FRINGE
from models.fringe.model import (
    _small_solver,
    channel_cost,
    fit_channel,
    fit_channel_pso,
    fit_periods,
    phase_of_samples,
)
from models.readings.sheet import ParsedReadings

PERIOD = 64
PERIODS_TRIED = 12
LINES = 16384


def _signals(theta, rng, noise=0.002):
    """Sine channel of Table 1 shape with drifting offset/amplitude, and its cosine."""
    drift = 1.0 + 0.002 * np.sin(theta / (LINES * 0.5))
    u_s = (0.05 + 3.68 * drift * np.sin(theta + 0.026) + 0.079 * np.sin(3 * theta + 0.084)
           + 0.011 * np.sin(5 * theta + 0.47) + rng.normal(0, noise, theta.size))
    u_c = (-0.06 + 3.73 * drift * np.sin(theta + 1.59) + 0.079 * np.sin(3 * theta + 1.79)
           + 0.010 * np.sin(5 * theta - 1.08) + rng.normal(0, noise, theta.size))
    return u_s, u_c


def _design(theta):
    cols = [np.ones_like(theta)]
    for k in (1, 3, 5):
        cols += [np.sin(k * theta), np.cos(k * theta)]
    return np.column_stack(cols)


def _numpy_lstsq_fit(theta, u) -> float:
    """numpy.linalg.lstsq on the design built for the call; the cost Σ r²."""
    coef = np.linalg.lstsq(_design(theta), u, rcond=None)[0]
    r = u - _design(theta) @ coef
    return float(r @ r)


def _scipy_least_squares_fit(theta, u) -> float:
    """scipy.optimize.least_squares (trf, default tolerances) from zero; the cost Σ r²."""
    from scipy.optimize import least_squares

    design = _design(theta)
    fit = least_squares(lambda x: design @ x - u, np.zeros(design.shape[1]), method="trf")
    return float(fit.fun @ fit.fun)


def _pyswarms_fit(theta, u, iterations=2000, particles=40, seed=0):
    try:
        import pyswarms as ps
    except ImportError:
        return None
    scale = float(np.max(np.abs(u)))
    lo = np.array([-0.2 * scale, 0.0, -math.pi, -0.1 * scale, -math.pi, -0.1 * scale, -math.pi])
    hi = np.array([0.2 * scale, 1.5 * scale, math.pi, 0.1 * scale, math.pi, 0.1 * scale, math.pi])
    s = [np.sin(k * theta) for k in (1, 3, 5)]
    c = [np.cos(k * theta) for k in (1, 3, 5)]

    def costs(p):
        model = p[:, [0]]
        for i in range(3):
            a, ph = p[:, [1 + 2 * i]], p[:, [2 + 2 * i]]
            model = model + a * np.cos(ph) * s[i] + a * np.sin(ph) * c[i]
        r = u[None, :] - model
        return np.einsum("ij,ij->i", r, r)

    np.random.seed(seed)  # pyswarms draws from numpy's global generator
    optimizer = ps.single.GlobalBestPSO(n_particles=particles, dimensions=7,
                                        options={"c1": 1.49618, "c2": 1.49618, "w": 0.7298},
                                        bounds=(lo, hi))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        cost, _ = optimizer.optimize(costs, iters=iterations, verbose=False)
    return float(cost)


def test_fringe_fit_against_particle_swarms(report):
    rng = np.random.default_rng(13)
    theta = phase_of_samples(PERIOD, PERIOD)
    rows = {"lsq": ([], []), "numpy": ([], []), "scipy": ([], []), "pso": ([], []),
            "pyswarms": ([], [])}
    for trial in range(PERIODS_TRIED):
        u, _ = _signals(theta + rng.uniform(0, 2 * np.pi), rng)
        lsq_cost = fit_channel(theta, u).cost
        rows["lsq"][0].append(lsq_cost)
        rows["lsq"][1].append(np.median(timings(lambda u=u: fit_channel(theta, u), 50)))
        for key, fit in (("numpy", _numpy_lstsq_fit), ("scipy", _scipy_least_squares_fit)):
            rows[key][0].append(fit(theta, u))
            rows[key][1].append(np.median(timings(lambda u=u, fit=fit: fit(theta, u), 20)))
        pso = fit_channel_pso(theta, u, seed=trial)
        rows["pso"][0].append(channel_cost(theta, u, pso.fit))
        rows["pso"][1].append(pso.seconds)
        ps_times = []
        ps_cost = None

        def run_pyswarms(u=u, trial=trial, times=ps_times):
            nonlocal ps_cost
            import time
            t0 = time.perf_counter()
            ps_cost = _pyswarms_fit(theta, u, seed=trial)
            times.append(time.perf_counter() - t0)

        run_pyswarms()
        if ps_cost is not None:
            rows["pyswarms"][0].append(ps_cost)
            rows["pyswarms"][1].append(ps_times[0])
    lsq_costs = np.array(rows["lsq"][0])
    lines = [
        "## Fringe: fitting one period's signal (64 samples, 7 parameters)",
        "",
        f"{PERIODS_TRIED} periods of a sine channel shaped like Table 1 (2 mV noise). Cost: the "
        "seed's (11), Σ residual² (V²); \"× LSQ\" is the cost over the least-squares cost of the "
        "same period.",
        "",
        "| method | cost × LSQ (median, worst) | time per period | LSQ speed ratio |",
        "|---|---|---|---|",
    ]
    lsq_time = float(np.median(rows["lsq"][1]))
    for key, label in (("lsq", "ours: linear least squares"),
                       ("numpy", "numpy.linalg.lstsq, design built per call"),
                       ("scipy", "scipy.optimize.least_squares (trf) from zero"),
                       ("pso", "seed's PSO, eqs 12–15 (40 particles, ≤ 2000 iterations)"),
                       ("pyswarms", "pyswarms GlobalBestPSO (40 particles, 2000 iterations, "
                                    "c1 = c2 = 1.49618, w = 0.7298)")):
        costs, times = np.array(rows[key][0]), np.array(rows[key][1])
        if costs.size == 0:
            lines.append(f"| {label} | not installed | | |")
            continue
        rel = costs / lsq_costs
        slower = np.median(times) / lsq_time
        ratio = "1×" if key == "lsq" else f"{slower:,.{0 if slower >= 10 else 1}f}×"
        lines.append(f"| {label} | {np.median(rel):.3g}, {rel.max():.3g} | {fmt_time(times)} | "
                     f"{ratio} |")
    pso_ratio = float(np.median(rows["pso"][1]) / lsq_time)

    def cold():
        _small_solver.cache_clear()
        fit_channel(theta, u)

    cold_t = timings(cold, 50)
    block = np.concatenate([_signals(theta, rng)[0] for _ in range(1024)])
    batched = timings(lambda: fit_periods(block, PERIOD), 20) / 1024
    lines.append(f"| ours, first call on a new phase grid (design and factorisation built) | "
                 f"1, 1 | {fmt_time(cold_t)} | {np.median(rows['pso'][1]) / np.median(cold_t):,.0f}× "
                 "faster than PSO |")
    lines.append(f"| ours, 1024 periods in one solve (`fit_periods`), per period | 1, 1 | "
                 f"{fmt_time(batched)} | {np.median(rows['pso'][1]) / np.median(batched):,.0f}× "
                 "faster than PSO |")

    # a whole revolution: 16384 periods × 64 samples
    n = LINES * PERIOD
    theta_rev = phase_of_samples(n, PERIOD)
    u_s, u_c = _signals(theta_rev, rng)
    parsed = ParsedReadings({"u_sin": u_s, "u_cos": u_c, "theta_deg": np.full(n, np.nan)},
                            np.arange(n))
    settings = FRINGE.settings_with_defaults({"samples_per_period": PERIOD, "lines_per_rev": LINES})
    revolution = timings(lambda: FRINGE.analyze(parsed, settings), 5)
    result = FRINGE.analyze(parsed, settings)
    pso_revolution = np.median(rows["pso"][1]) * 2 * LINES
    lines += [
        "",
        f"LSQ is **{pso_ratio:,.0f}×** faster than the seed's PSO per period (target ≥ 1000×) and "
        "its cost is never higher (it is the exact minimum).",
        "",
        f"Whole revolution ({n:,} samples, both channels, global fit, {LINES} per-period fits for "
        f"the drift, correction table, compensation): **{fmt_time(revolution)}** of compute "
        f"(target < 1 s); drift of A1 found: {np.ptp(result.sin_periods[:, 1]) * 1e3:.1f} mV. "
        f"The seed's PSO period by period would take about {pso_revolution / 3600:.1f} h.",
    ]
    ps = np.array(rows["pyswarms"][0]) / lsq_costs if rows["pyswarms"][0] else None
    pyswarms_note = ("" if ps is None else
                     f"; pyswarms' PSO reaches that cost (within 0.1 %) in {int(np.sum(ps <= 1.001))} "
                     f"of {ps.size} periods")
    numpy_ratio = float(np.median(rows["numpy"][1]) / lsq_time)
    scipy_ratio = float(np.median(rows["scipy"][1]) / lsq_time)
    report("2-fringe", lines, headline=(
        f"Fringe: linear least squares gives a period's exact minimum cost in "
        f"{fmt_time(rows['lsq'][1]).split(' (')[0]}; numpy.linalg.lstsq takes "
        f"{numpy_ratio:.1f}× as long, scipy.optimize.least_squares {scipy_ratio:.0f}×, the paper's "
        f"PSO (Gao et al. 2013) {pso_ratio:,.0f}×{pyswarms_note}. A whole revolution ({n:,} samples, "
        "drift included) takes "
        f"{fmt_time(revolution).split(' (')[0]} of compute once the readings are in memory "
        "(reading the file is not included)."))
    assert np.all(np.array(rows["pso"][0]) >= lsq_costs * (1 - 1e-9))
    assert np.allclose(rows["numpy"][0], lsq_costs, rtol=1e-9)  # the same exact minimum
    if rows["pyswarms"][0]:
        assert np.all(np.array(rows["pyswarms"][0]) >= lsq_costs * (1 - 1e-9))
    assert pso_ratio >= 1000
    assert np.median(revolution) < 1.0


def test_fringe_fit_of_a_revolution_by_per_phase_sums(report):
    """N equal steps a period: the fit from N per-phase sums against the general design
    (what the general path, and numpy.linalg.lstsq, build: a million rows), on one 1M-sample
    revolution with 1000 samples missing; both give the same fit."""
    from models.fringe.model import fit_channels, fit_channels_by_phase

    rng = np.random.default_rng(17)
    place = np.delete(np.arange(LINES * PERIOD), rng.choice(LINES * PERIOD, 1000, replace=False))
    theta = place * (2 * math.pi / PERIOD)
    u_s, u_c = _signals(theta, rng)
    index = place % PERIOD
    general = fit_channels(theta, [u_s, u_c])
    by_phase = fit_channels_by_phase(index, PERIOD, [u_s, u_c])
    for a, b in zip(general, by_phase, strict=True):
        assert math.isclose(a.cost, b.cost, rel_tol=1e-9)
        assert all(math.isclose(a.amplitude[k], b.amplitude[k], rel_tol=1e-9) for k in a.orders)
    t_general = timings(lambda: fit_channels(theta, [u_s, u_c]), 5)
    t_phase = timings(lambda: fit_channels_by_phase(index, PERIOD, [u_s, u_c]), 5)
    ratio = float(np.median(t_general) / np.median(t_phase))
    report("2b-fringe-revolution-fit", [
        "## Fringe: a 1M-sample revolution fitted from per-phase sums", "",
        f"{theta.size} samples, N = {PERIOD} equal steps a period, 1000 missing; both channels.",
        "", "| method | median time | ratio to per-phase sums |", "|---|---|---|",
        f"| per-phase sums (N sums, 7×7 solve; used for N equal steps) | "
        f"{fmt_time(np.median(t_phase))} | 1.0 |",
        f"| general design (1M×7, as for a θ column) | {fmt_time(np.median(t_general))} | "
        f"{ratio:.1f}× |", "",
        "Same fit: costs and amplitudes agree to 1e-9 (relative).", ""])
