"""A phase estimated from the signals whose phases cannot determine the harmonics asked for:
refused naming what the data cannot tell apart, not solved by a pseudo-inverse.

The fit at an estimated phase fell back to the pseudo-inverse when its normal equations
were (near) singular: 30 phases a period with orders 1 … 20 printed a minimum-norm answer
that was then refused as "the Lissajous figure loops near 0 V", a reason not the signals';
32 phases a period with orders up to 16 (order N/2, its sine nothing but noise) printed a
result. Channels from tests/fringe_channels.py (first principles, nothing from models/).
"""

from __future__ import annotations

import numpy as np
import pytest

from models.fringe.analysis import FRINGE
from models.readings.sheet import ParsedReadings
from tests.fringe_channels import Channels, equal_steps

HEAD = Channels(amplitudes_v=(0.5, 0.49), sin_harmonics={3: (0.004, 0.4)},
                cos_harmonics={3: (0.003, -0.3)})


def _parsed(per_period: int, noise_v: float) -> ParsedReadings:
    """12 periods at ``per_period`` equal steps, no θ column and no N: the phase is
    estimated from the signals."""
    theta = equal_steps(12 * per_period, per_period)
    head = Channels(**{**HEAD.__dict__, "noise_v": noise_v})
    u_sin, u_cos = head.sample(theta, np.random.default_rng(1))
    return ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                           "theta_deg": np.full(theta.size, np.nan)}, np.arange(theta.size))


def test_a_singular_design_is_refused_naming_the_orders_that_alias():
    # 30 phases a period (noise-free, the phases repeat exactly): 14 + 16 = 30, so orders 14
    # and 16 take the same values at every phase, and 41 parameters exceed 30 phases
    with pytest.raises(ValueError) as refused:
        FRINGE.analyze(_parsed(30, 0.0), {"max_order": 20, "harmonics": "all"})
    said = str(refused.value)
    assert "not determined at the phase estimated from the signals" in said
    assert "orders 14 and 16 take the same values" in said
    assert "Lissajous" not in said  # (the pseudo-inverse's answer was refused for this)


def test_a_near_singular_design_is_refused_naming_what_it_can_hardly_tell_apart():
    # 32 phases a period with noise, orders up to 16: order 16 is N/2
    with pytest.raises(ValueError, match=r"determined only poorly at the phase estimated.*"
                                         r"hardly tell orders \d+ and 16 apart"):
        FRINGE.analyze(_parsed(32, 0.0003), {"max_order": 16, "harmonics": "all"})


def test_a_design_that_determines_the_orders_is_fitted():
    result = FRINGE.analyze(_parsed(64, 0.0003), {"max_order": 5, "harmonics": "all"})
    assert result.phase_source == "estimated" and result.sin_fit.orders == (1, 2, 3, 4, 5)
