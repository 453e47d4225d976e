"""The fewest samples a fringe record needs (cov76 F9): the unknowns of a channel and one
degree of freedom for the noise, not four times the unknowns; and with N samples a period,
orders that alias at N named before the count. Records from tests/fringe_jitter_rig.py."""

from __future__ import annotations

import numpy as np
import pytest

from models.fringe.analysis import FRINGE
from models.fringe.report import model_error_curve
from models.readings.sheet import ParsedReadings
from tests.fringe_jitter_rig import JitteredHead

#: the audit's head with its 3rd harmonics only (a 5th folds into the 3rd at N = 8 and
#: into the 2nd at N = 7: the curve between the samples would be the two together)
THIRD_ONLY = dict(sin_harmonics=((3, 0.02, 0.3),), cos_harmonics=((3, 0.018, 1.9),),
                  start_rad=0.4)


def _analyze(head: JitteredHead, seed: int, **settings):
    u_sin, u_cos, _ = head.record(np.random.default_rng(seed))
    parsed = ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                             "theta_deg": np.full(u_sin.size, np.nan)}, np.arange(u_sin.size))
    return FRINGE.analyze(parsed, {"lines_per_rev": 16384,
                                   "samples_per_period": head.per_period, **settings})


def _right_against_the_rig(result, head: JitteredHead) -> None:
    """The fitted model's half range over the period within 0.03″ of the rig's (1 mV of
    noise: 0.013″ a sample), and each sample's error within 0.05″ of the rig's there (both
    with their mean taken off: the phase origin is the first sample's)."""
    half = 0.5 * float(np.ptp(model_error_curve(result)[1]))
    assert half == pytest.approx(head.true_half_range_arcsec(), abs=0.03)
    phi = head.start_rad + result.theta_rad
    truth = head.error_arcsec(phi)
    measured = result.raw_error - np.mean(result.raw_error)
    assert np.max(np.abs(measured - (truth - np.mean(truth)))) < 0.05


def test_the_least_is_the_unknowns_and_one_degree_of_freedom():
    from models.fringe.analysis import least_samples

    assert least_samples((1,)) == 4
    assert least_samples((1, 3)) == 6
    assert least_samples((1, 3, 5)) == 8
    assert least_samples((1, 2, 3)) == 8


def test_two_periods_of_8_steps_with_orders_1_and_3_are_analysed():
    """16 samples, orders 1 and 3 determined at N = 8: refused before ("16 samples; at least
    20 are needed"); analysed, and right against the rig."""
    head = JitteredHead(8, 2, 0.001, **THIRD_ONLY)
    result = _analyze(head, 3, max_order=3)
    assert result.raw_error.size == 16
    _right_against_the_rig(result, head)


def test_a_record_at_the_least_is_analysed_right():
    """N = 7, orders 1, 2, 3 (7 unknowns a channel): 8 samples, the least, one period and
    one sample; refused before (at least 28); right against the rig."""
    head = JitteredHead(7, 8 / 7, 0.001, **THIRD_ONLY)
    assert head.samples == 8
    result = _analyze(head, 3, harmonics="all", max_order=3)
    _right_against_the_rig(result, head)


def test_one_fewer_is_refused_naming_what_is_needed():
    head = JitteredHead(7, 1, 0.001, **THIRD_ONLY)  # 7 samples, 7 unknowns
    with pytest.raises(ValueError, match=r"7 samples; at least 8 are needed: 7 unknowns for "
                                         r"each channel \(the offset and harmonics 1, 2, 3\)"):
        _analyze(head, 3, harmonics="all", max_order=3)


@pytest.mark.parametrize("periods", [3, 0.875])
def test_orders_that_alias_at_n_are_named_before_the_count(periods):
    """N = 8 with orders 1, 3, 5 (the audit's fr_126: 3 periods, 24 samples, refused as "24
    samples; at least 28"; and 7 samples, below the least of 8): the aliasing is the reason."""
    head = JitteredHead(8, periods, 0.002)
    with pytest.raises(ValueError, match="harmonic orders 3 and 5 alias at N = 8"):
        _analyze(head, 1)
