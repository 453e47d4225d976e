"""The U of the identified signal parameters when the ADC's rounding is not dithered by the
noise: a record of whole periods at N equal steps repeats the rounding of each phase in
every period, so averaging the periods does not remove it (a study found cos c3 covered by
1883 of 2000 runs at 95.45 %; tests/benchmarks/fringe_rounding_study.py with no noise:
33–54 % of 1000 records). Each parameter's U covers its true value at its binomial floor with
no noise at all and with noise a tenth of the step, for offsets that put the readings half a
period apart on the same rounding (2·A₀ a whole number of steps: their roundings cancel in
the offset and add in every odd order) and near half-way between (the offsets' add half
again); and where the noise dithers the rounding (σ = δ) the U is no wider than that of
independent readings of σ² + δ²/12 each.

The records come from tests/fringe_rounding_rig.py (first principles: the true phase at N
exact equal steps, each channel's offset, amplitude, quadrature and harmonics, noise, then
rounding to the ADC's step), nothing from models/.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from scipy.stats import binom

from models.fringe.analysis import FRINGE
from models.fringe.report import parameters_json
from models.readings.sheet import ParsedReadings
from tests.fringe_rounding_rig import head, wrapped

P = 0.9545
RECORDS = 100


def _errors(design, records: int, seed: int) -> dict[str, list[tuple[float, float]]]:
    """{"sin_A1": [(estimate − truth, U), …], …} over ``records`` records."""
    rng = np.random.default_rng(seed)
    out: dict[str, list[tuple[float, float]]] = {}
    for _ in range(records):
        start, u_sin, u_cos = design.readings(rng)
        parsed = ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                                 "theta_deg": np.full(u_sin.size, np.nan)},
                                np.arange(u_sin.size))
        data = parameters_json(FRINGE.analyze(parsed, design.settings()), P)
        for label, truth in design.parameters(start).items():
            params = data[f"{label}_params"]
            for key, true in truth.items():
                error = params[key] - true
                big_u = params[f"expanded_uncertainty_{key}"]
                out.setdefault(f"{label}_{key}", []).append(
                    (wrapped(error) if key.startswith("c") else error,
                     math.nan if big_u is None else big_u))
    return out


def _floor(n: int) -> int:
    """The least count of n not significantly low at P (one-sided binomial, 1 %: many
    parameters are checked)."""
    return int(binom.ppf(0.01, n, P))


@pytest.mark.slow  # (100 records a case, ~3 s)
@pytest.mark.parametrize("per_period, noise_over_lsb, offsets_v", [
    (16, 0.0, (0.01037, -0.00623)),  # as they fall: 2A₀ 20.74 and −12.46 steps
    (16, 0.1, (0.01037, -0.00623)),
    (32, 0.0, (0.010, -0.006)),  # 2A₀ whole steps: the odd orders' rounding doubled
    (8, 0.0, (0.01023, -0.00623)),  # 2A₀ near half-way: the offsets' rounding 1.5 times
])
def test_undithered_rounding_is_covered_by_every_parameters_u(per_period, noise_over_lsb,
                                                               offsets_v):
    design = dataclasses.replace(head(per_period, 10, noise_over_lsb), offsets_v=offsets_v)
    for key, pairs in _errors(design, RECORDS, seed=per_period).items():
        a = np.array(pairs)
        assert np.all(np.isfinite(a[:, 1])), key
        covered = int(np.sum(np.abs(a[:, 0]) <= a[:, 1]))
        assert covered >= _floor(len(a)), (key, covered, len(a))


@pytest.mark.slow
def test_dithered_rounding_keeps_the_u_of_the_scatter():
    """σ = δ: the rounding is random from reading to reading (Sheppard: each reading's
    error σ² + δ²/12, independent), so an amplitude's coefficient of N·P readings at N equal
    steps has u² = 2(σ² + δ²/12)/(N·P), the offset's half of it: the U stated stays at that
    (median within 5 %, k = 2.0 of ν = N·P − 11 ≈ 150) and covers."""
    design = head(16, 10, 1.0)
    n = design.per_period * design.periods
    reading = design.noise_v ** 2 + design.lsb_v ** 2 / 12.0
    for key, pairs in _errors(design, 200, seed=5).items():
        a = np.array(pairs)
        covered = int(np.sum(np.abs(a[:, 0]) <= a[:, 1]))
        assert covered >= _floor(len(a)), (key, covered)
        if "_c" in key:  # (a phase: its U is not linear in u)
            continue
        independent = 2.0 * math.sqrt((1.0 if key.endswith("A0") else 2.0) * reading / n)
        assert float(np.median(a[:, 1])) <= 1.05 * independent, (key, np.median(a[:, 1]),
                                                                 independent)
