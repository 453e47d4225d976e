"""The paths a long record takes: per-period fits solved together, reversals counted
from the turning points, the phase refined on one design a pass, and an analysis that
newer readings cancel. Each is held to what a direct computation of the same physics
gives (the signals come from a head written here, not from the model)."""

from __future__ import annotations

import math
import threading

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.cancellation import AnalysisCancelled, cancellable, checkpoint
from models.fringe.analysis import FRINGE, count_reversals
from models.fringe.model import fit_periods_along
from models.readings.sheet import ParsedReadings

TWO_PI = 2 * math.pi


def head(theta, a1_sin, a1_cos, a3=0.02, offset=(0.05, -0.04)):
    """A read head whose fundamental amplitude may change along the record (V)."""
    u_sin = offset[0] + a1_sin * np.sin(theta) + a3 * np.sin(3 * theta + 0.4)
    u_cos = offset[1] + a1_cos * np.cos(theta) + a3 * np.cos(3 * theta - 0.2)
    return u_sin, u_cos


def back_and_forth(turns_at, step=0.07):
    """A phase that runs forward to each turning point in turn, then back (rad)."""
    pieces, here = [], 0.0
    for target in turns_at:
        n = max(2, int(abs(target - here) / step))
        pieces.append(np.linspace(here, target, n, endpoint=False))
        here = target
    pieces.append(np.array([here]))
    return np.concatenate(pieces)


def direct_segment_fits(theta, u, width):
    """Each stretch of ``width`` rad of travel fitted on its own by SVD least squares."""
    travel = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(theta)))])
    segment = np.floor(travel / width).astype(int)
    rows = []
    for s in np.unique(segment):
        t, y = theta[segment == s], u[segment == s]
        if t.size < 14 or np.unique(np.floor(np.mod(t, TWO_PI) / TWO_PI * 8)).size < 6:
            continue
        x = np.column_stack([np.ones_like(t)] + [f(k * t) for k in (1, 3, 5)
                                                  for f in (np.sin, np.cos)])
        c = np.linalg.lstsq(x, y, rcond=None)[0]
        rows.append([c[0], math.hypot(c[1], c[2]), math.atan2(c[2], c[1])])
    return np.array(rows)


def test_per_period_fits_follow_a_drifting_amplitude_through_reversals():
    theta = back_and_forth([60 * TWO_PI, 25 * TWO_PI, 90 * TWO_PI])
    travel = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(theta)))])
    a1 = 1.0 + 0.05 * travel / travel[-1]  # the amplitude falls off as the lamp ages
    u_sin, u_cos = head(theta, a1, 0.98 * a1)
    sin_rows, cos_rows = fit_periods_along(theta, [u_sin, u_cos])
    direct = direct_segment_fits(theta, u_sin, TWO_PI)
    assert sin_rows.shape == (direct.shape[0], 7)
    np.testing.assert_allclose(sin_rows[:, :3], direct, atol=1e-9)
    # and the drift itself: each period's A1 is the head's amplitude at that period
    assert sin_rows[0, 1] == pytest.approx(1.0, abs=1e-3)
    assert sin_rows[-1, 1] == pytest.approx(1.05, abs=1e-3)
    np.testing.assert_allclose(cos_rows[:, 1] / sin_rows[:, 1], 0.98, atol=1e-3)


def test_blocks_of_periods_when_the_record_is_long():
    theta = np.arange(400_000) * (TWO_PI / 50.0)  # 8000 periods: blocks of two
    u_sin, _ = head(theta, 1.0, 1.0)
    (rows,) = fit_periods_along(theta, [u_sin], max_segments=4000)
    assert rows.shape[0] == 4000
    first_block = direct_segment_fits(theta[:100], u_sin[:100], 2 * TWO_PI)
    np.testing.assert_allclose(rows[:, :3], np.repeat(first_block, 4000, axis=0), atol=1e-9)


def test_a_segment_that_cannot_fix_every_harmonic_gets_the_least_squares_answer():
    # 40 samples on 6 distinct phases: the 5th harmonic cannot be told from the 1st
    theta = np.tile(np.arange(6) * (TWO_PI / 6), 7)[:40] + np.repeat(np.arange(7), 6)[:40] * TWO_PI
    u_sin, _ = head(theta, 1.0, 1.0)
    (rows,) = fit_periods_along(theta, [u_sin], max_segments=1)
    direct = direct_segment_fits(theta, u_sin, TWO_PI * 7)
    np.testing.assert_allclose(rows[:, :3], direct, atol=1e-9)


@pytest.mark.slow
@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(-40.0, 40.0), min_size=1, max_size=8),
       st.floats(0.0, 0.3), st.integers(0, 2**31))
def test_reversals_are_the_turns_of_the_motion(turns_at, noise, seed):
    """A motion that turns at given points, with jitter smaller than the hysteresis: the
    count is the number of turns that went back further than the hysteresis."""
    theta = back_and_forth(turns_at) + np.random.default_rng(seed).uniform(-noise / 2,
                                                                             noise / 2)
    stops = [0.0, *turns_at]
    expected, direction, extreme = 0, 0, 0.0
    for target in stops[1:]:  # the turns a technician counts on the chart
        step = target - extreme
        if direction == 0:
            if abs(step) > 0.5:
                direction, extreme = np.sign(step), target
            continue
        if direction * step > 0:
            extreme = target
        elif abs(step) > 0.5:
            expected += 1
            direction, extreme = -direction, target
    # near the hysteresis the jitter decides, and so may the sample at a sharp turn (a
    # lone extreme sample is taken for a spike: its neighbours' median is followed)
    margin = noise + 2 * 0.07  # either end of a leg
    ambiguous = any(0.5 - margin <= abs(b - a) <= 0.5 + margin for a, b in zip(
        stops, stops[1:], strict=False))
    if not ambiguous:
        assert count_reversals(theta) == expected


def test_checkpoints_do_nothing_outside_a_cancellable_analysis():
    checkpoint()
    with cancellable(lambda: False):
        checkpoint()
    with cancellable(lambda: True), pytest.raises(AnalysisCancelled):
        checkpoint()
    checkpoint()  # the question went with the block


def test_a_superseded_analysis_stops_early_and_only_on_its_thread():
    theta = np.arange(200_000) * (TWO_PI / 37.3)
    u_sin, u_cos = head(theta, 1.0, 1.02)
    parsed = ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                             "theta_deg": np.full(theta.size, np.nan)},
                            np.arange(theta.size), [])
    asked = []

    def superseded():
        asked.append(1)
        return len(asked) >= 3  # newer readings arrive during the analysis

    with cancellable(superseded), pytest.raises(AnalysisCancelled):
        FRINGE.analyze(parsed, {})
    assert len(asked) == 3
    # another thread's analysis is not touched by this thread's question
    out = {}
    with cancellable(lambda: True):
        worker = threading.Thread(target=lambda: out.setdefault("r", FRINGE.analyze(parsed, {})))
        worker.start()
        worker.join()
    assert out["r"].phase_source == "estimated"


def test_a_spike_on_a_forward_record_is_drawn_along_the_record():
    """A spike typed over one sample moves its estimated phase back a little: the record
    still ran one way, so it is drawn along the record, spike and all; a motion that turned
    back is drawn over the phase within a period."""
    from models.fringe.plots import figures

    theta = np.arange(64 * 300) * (TWO_PI / 64)
    u_sin, u_cos = head(theta, 3.7, 3.72)
    u_sin[1000] = 1.0  # the spike
    result = FRINGE.analyze(ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                                            "theta_deg": np.full(theta.size, np.nan)},
                                           np.arange(theta.size), []), {})
    assert np.any(np.diff(result.theta_rad) < 0) and result.reversals == 0
    errors = figures(result)["errors"]
    assert errors.x_label == "electrical phase θ (periods)"
    before = errors.series[0]
    assert np.all(np.diff(before.x) >= 0)
    assert np.max(np.abs(before.y)) == np.max(np.abs(result.raw_error))  # the spike is drawn

    back = back_and_forth([40 * TWO_PI, 10 * TWO_PI], step=TWO_PI / 64)
    u_sin, u_cos = head(back, 3.7, 3.72)
    turned = FRINGE.analyze(ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                                            "theta_deg": np.degrees(back)},
                                           np.arange(back.size), []), {})
    assert turned.reversals == 1
    assert figures(turned)["errors"].x_label.startswith("phase within the period")
