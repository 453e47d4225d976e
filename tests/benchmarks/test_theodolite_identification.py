"""Our closed-form + polish identification against the seed's route: nonlinear least
squares from random starts in the seed's bounds (ψ, β ∈ [−10°, 10°], α ∈ [0°, 360°]),
keeping the best. Reports success rate and time per fit as ratios."""

from __future__ import annotations

import platform
import time
from pathlib import Path

import numpy as np
from scipy.optimize import least_squares

from models.theodolite import (
    SetupParameters,
    _elevation_model,
    identify_from_elevations,
    induced_error_arcsec,
    simulate_readings,
)

SETUPS = 200
SEED_STARTS = 100  # the seed used 1000 starts; 100 keeps `make bench` short
REPORT = Path(__file__).resolve().parents[2] / "BENCHMARKS.md"


def seed_route(theta, elevation, rng):
    th, e = np.radians(theta), np.radians(elevation)
    best = None
    for _ in range(SEED_STARTS):
        start = np.radians([rng.uniform(-10, 10), rng.uniform(0, 360), rng.uniform(-10, 10)])
        fit = least_squares(lambda x: _elevation_model(x, th) - e, start, method="trf")
        cost = float(fit.fun @ fit.fun)
        if best is None or cost < best[0]:
            best = (cost, np.degrees(fit.x))
    return best[1]


def test_identification_against_seed_route():
    rng = np.random.default_rng(2017)
    ours_ok = seed_ok = 0
    ours_t = seed_t = 0.0
    for _ in range(SETUPS):
        setup = SetupParameters(rng.uniform(-10, 10), rng.uniform(0, 360), rng.uniform(-10, 10))
        theta = np.arange(-20.0, 21.0, 1.0)
        _, elevation = simulate_readings(theta, setup, noise_arcsec=0.3, rng=rng)
        th, e = np.radians(theta), np.radians(elevation)
        reference = least_squares(lambda x, th=th, e=e: _elevation_model(x, th) - e,
                                  np.radians(setup.as_array()), method="lm", xtol=1e-15, ftol=1e-15)
        optimum = induced_error_arcsec(theta, *np.degrees(reference.x))
        t0 = time.perf_counter()
        ours = identify_from_elevations(theta, elevation).setup.as_array()
        t1 = time.perf_counter()
        seed = seed_route(theta, elevation, rng)
        t2 = time.perf_counter()
        ours_t += t1 - t0
        seed_t += t2 - t1
        ours_ok += np.max(np.abs(induced_error_arcsec(theta, *ours) - optimum)) < 0.01
        seed_ok += np.max(np.abs(induced_error_arcsec(theta, *seed) - optimum)) < 0.01
    lines = [
        f"## Theodolite identification ({platform.machine()}, {platform.python_version()})",
        "",
        "| method | success (global optimum within 0.01\") | time per fit |",
        "|---|---|---|",
        f"| ours: linear solve + closed form + polish | {ours_ok}/{SETUPS} | "
        f"{ours_t / SETUPS * 1e3:.2f} ms |",
        f"| seed: NLS from {SEED_STARTS} random starts | {seed_ok}/{SETUPS} | "
        f"{seed_t / SETUPS * 1e3:.1f} ms |",
        "",
        f"Speed ratio: {seed_t / ours_t:.0f}x (the seed's 1000 starts would be 10x more).",
        "",
    ]
    print("\n".join(lines))  # noqa: T201 - the benchmark's report
    REPORT.write_text("# Benchmarks\n\nWritten by `make bench`.\n\n" + "\n".join(lines))
    assert ours_ok == SETUPS
