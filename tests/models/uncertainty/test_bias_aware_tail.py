"""The readings' interval under a bounded bias (#39's widths): the level at which an interval
moved out each way by the largest bias b misses at the tail asked for at the least favourable
bias, checked against a simulation of a normal error with every bias from 0 to b (numpy only;
the interval's ends from the normal quantile, as a figure's error's)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.special import ndtri

from models.uncertainty.figure_intervals import bias_aware_tail

TAIL = 0.5 * (1.0 - 0.9545)


def _miss(level: float, bias: float, spread: float, draws: np.ndarray) -> float:
    """The share of errors (bias + spread · z) outside ±(z_level · spread + b), b the largest
    bias the interval is moved out by (``draws`` the biases actually made)."""
    half = float(ndtri(1.0 - level)) * spread + bias
    return float(np.mean(np.abs(draws) > half))


@pytest.mark.parametrize("ratio", [0.25, 1.0, 3.0])
def test_the_interval_misses_at_the_tail_at_the_largest_bias_and_less_below_it(ratio):
    """σ = 1, b = ratio · σ: the interval x ± (z_t σ + b) with t = bias_aware_tail misses at
    twice the tail (both sides together) where the bias is b (10⁶ draws: within 0.0007), and
    not more where it is 0, b/2 or −b. With t = the tail itself (the readings' bound at the
    probability and the bias added, until 0.8.20) it misses at about half that at the largest
    bias: wider than asked for."""
    z = np.random.default_rng(39).standard_normal(1_000_000)
    bias = ratio
    level = bias_aware_tail(TAIL, bias, 1.0)
    assert TAIL < level <= 2.0 * TAIL
    assert _miss(level, bias, 1.0, z + bias) == pytest.approx(2.0 * TAIL, abs=7e-4)
    for made in (0.0, 0.5 * bias, -bias):
        assert _miss(level, bias, 1.0, z + made) <= 2.0 * TAIL + 7e-4, made
    assert _miss(TAIL, bias, 1.0, z + bias) < 0.8 * 2.0 * TAIL


def test_no_bias_is_the_tail_and_a_large_one_twice_it():
    assert bias_aware_tail(TAIL, 0.0, 1.0) == TAIL
    assert bias_aware_tail(TAIL, 10.0, 1.0) == pytest.approx(2.0 * TAIL, rel=1e-9)
    assert bias_aware_tail(TAIL, 1.0, 0.0) == 2.0 * TAIL
