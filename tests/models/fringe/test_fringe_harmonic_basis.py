"""The harmonic basis of a long record from each sample's phasor (models/fringe/harmonic_basis):
the rows against sines and cosines taken directly, the rotation of a phasor by a step
against the phasor of the moved phase, the unwrapping by whole turns, and the refined
phase of a long record without a phase reference against the true phase of a simulated
one (models/validation/fringe_rig: sampled signals, nothing from the analysis)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.fringe.harmonic_basis import BLOCK, BasisBlocks, blocks
from models.fringe.model import refine_phase
from models.fringe.phase import fit_ellipse, unwrapped
from models.validation.fringe_rig import FringeHead, wandering_motion


@settings(max_examples=60, deadline=None)
@given(orders=st.lists(st.integers(1, 9), min_size=1, max_size=6, unique=True).map(sorted),
       size=st.integers(1, 2 * BLOCK + 7), seed=st.integers(0, 2**32 - 1),
       span=st.sampled_from([1.0, math.pi, 60.0]))
def test_rows_are_the_sines_and_cosines_of_each_order(orders, size, seed, span):
    theta = np.random.default_rng(seed).uniform(-span, span, size)
    basis = BasisBlocks(tuple(orders))
    sin, cos = np.sin(theta), np.cos(theta)
    for start, stop in blocks(size):
        rows = basis.rows(sin[start:stop], cos[start:stop])
        part = theta[start:stop]
        want = [np.ones_like(part)]
        for k in orders:
            want += [np.sin(k * part), np.cos(k * part)]
        # the recurrence loses ~k² ulps of the phasor, and np.sin(kθ) is that of kθ rounded
        # (an ulp of k·60 rad is k·7e-15): a few of each
        k = max(orders)
        np.testing.assert_allclose(rows, np.array(want), rtol=0, atol=4.5e-16 * k * (span + k))


def test_rows_into_a_given_array_and_the_normal_sums():
    theta = np.random.default_rng(5).uniform(-4, 4, 3000)
    basis = BasisBlocks((1, 3, 5), channels=2)
    out = np.full((7, theta.size), np.nan)
    basis.rows(np.sin(theta), np.cos(theta), out=out)
    x = np.column_stack([np.ones_like(theta)] + [f(k * theta) for k in (1, 3, 5)
                                                 for f in (np.sin, np.cos)])
    np.testing.assert_allclose(out, x.T, atol=1e-14)
    ys = np.vstack([np.cos(2 * theta), theta])
    gram, rhs = basis.normal_sums(np.sin(theta), np.cos(theta), ys)
    np.testing.assert_allclose(gram, x.T @ x, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(rhs, x.T @ ys.T, rtol=1e-12, atol=1e-9)


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), size=st.integers(1, 3000),
       scale=st.sampled_from([0.0, 1e-9, 1e-4, 0.03, 0.3, 0.5, 0.7, 3.0]))
def test_a_rotated_phasor_is_that_of_the_moved_phase(seed, size, scale):
    """sin δ and cos δ by their series up to |δ| = 0.5, np.sin and np.cos beyond: either
    way the phasor of θ − δ to a few ulps (θ within a turn, where θ − δ rounds to ~1e-16)."""
    rng = np.random.default_rng(seed)
    theta = rng.uniform(-math.pi, math.pi, size)
    delta = rng.uniform(-scale, scale, size)
    sin, cos = np.sin(theta), np.cos(theta)
    BasisBlocks((1,), size=size).rotate(sin, cos, delta)
    np.testing.assert_allclose(sin, np.sin(theta - delta), rtol=0, atol=2e-15)
    np.testing.assert_allclose(cos, np.cos(theta - delta), rtol=0, atol=2e-15)


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), size=st.integers(1, 5000),
       largest_step=st.sampled_from([0.1, 1.0, 3.0]))
def test_unwrapping_adds_whole_turns_where_the_phase_wrapped(seed, size, largest_step):
    rng = np.random.default_rng(seed)
    truth = rng.uniform(-math.pi, math.pi) + np.concatenate(
        [[0.0], np.cumsum(rng.uniform(-largest_step, largest_step, size - 1))])
    wrapped = np.arctan2(np.sin(truth), np.cos(truth))
    out = unwrapped(wrapped)
    start = truth[0] - wrapped[0]  # a whole turn, or 0
    np.testing.assert_allclose(out, truth - start, rtol=0, atol=1e-12 * max(1.0, np.abs(truth).max()))
    turns = (out - wrapped) / (2 * math.pi)
    np.testing.assert_allclose(turns, np.rint(turns), rtol=0, atol=1e-12)


def _head_record(count: int, seed: int):
    rng = np.random.default_rng(seed)
    theta = wandering_motion(count, rng, min_samples=3.0, max_samples=12.0)
    head = FringeHead(offsets_v=(0.05, -0.03), amplitudes_v=(1.0, 1.03), quadrature_deg=3.0)
    u_sin, u_cos = head.channels(theta)
    return theta, u_sin, u_cos


def test_the_refined_phase_of_a_long_record_is_the_true_phase():
    """No harmonics and no noise: the ellipse gives the exact phase and the refinement must
    keep it over a record that runs ~30,000 periods out (~2e5 rad). np.unwrap adds each
    turn as a rounded difference and drifted by 1.1e-7 rad over this one; whole turns and
    the phasor of the corrected signals do not drift."""
    theta, u_sin, u_cos = _head_record(300_000, 4)
    ellipse = fit_ellipse(u_sin, u_cos)
    phase, sin, cos = ellipse.phase_and_phasor(u_sin, u_cos)
    refined, (sin_fit, cos_fit), design = refine_phase(unwrapped(phase), u_sin, u_cos,
                                                       phasor=(sin, cos))
    offset = np.median(refined - theta)
    assert np.abs(refined).max() > 1.5e5
    np.testing.assert_allclose(refined - theta, offset, rtol=0, atol=1e-10)
    assert sin_fit.amplitude[1] == pytest.approx(1.0, abs=1e-9)
    assert cos_fit.amplitude[1] == pytest.approx(1.03, abs=1e-9)
    assert max(sin_fit.amplitude[3], sin_fit.amplitude[5], cos_fit.amplitude[3]) < 1e-9
    np.testing.assert_array_equal(design[-2:], [u_sin, u_cos])


def test_a_phasor_given_or_taken_from_the_phase_refines_alike():
    theta, u_sin, u_cos = _head_record(40_000, 8)
    start = theta + 0.02 * np.sin(3 * theta)  # a start that needs the refinement
    given_phasor = refine_phase(start, u_sin, u_cos, phasor=(np.sin(start), np.cos(start)))
    own_phasor = refine_phase(start, u_sin, u_cos)
    np.testing.assert_array_equal(given_phasor[0], own_phasor[0])
    assert given_phasor[1][0].as_dict() == own_phasor[1][0].as_dict()
