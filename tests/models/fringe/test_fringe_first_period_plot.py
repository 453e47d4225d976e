"""The certificate's "Compensated error in the first period" plot, where the first samples
span many periods: a θ column stepping 3/8 of a period a sample visits 8 phases of the
period, and its first 64 samples are 24 periods. Drawn in sample order against θ, the
line ran over 8500° of "the first period"; each sample is drawn at its phase within the
period, in phase order, as a point (the band a valid outline), and the axis says the
periods are folded into one. Where the first samples are one period in order (N equal
steps), the plot is as it was.

The records are written here from first principles (the true phase, each channel's offset,
amplitude and harmonics, noise), nothing from models/.
"""

from __future__ import annotations

import math

import numpy as np

from models.certificate.metadata import CertificateMetadata
from models.fringe.analysis import FRINGE
from models.fringe.report import fringe_certificate
from models.readings.sheet import ParsedReadings


def _record(theta_deg: np.ndarray, seed: int = 3) -> ParsedReadings:
    rng = np.random.default_rng(seed)
    phi = np.radians(theta_deg)
    u_sin = 0.01 + 0.5 * np.sin(phi) + 0.004 * np.sin(3 * phi + 0.7) + rng.normal(0, 3e-4, phi.size)
    u_cos = (-0.006 + 0.49 * np.cos(phi + 0.02) + 0.003 * np.cos(3 * phi + 1.9)
             + rng.normal(0, 3e-4, phi.size))
    return ParsedReadings({"u_sin": u_sin, "u_cos": u_cos, "theta_deg": theta_deg},
                          np.arange(phi.size))


def _first_period_plot(parsed: ParsedReadings, settings: dict):
    result = FRINGE.analyze(parsed, {"lines_per_rev": 16384, "max_order": 3, **settings})
    document = fringe_certificate(result, CertificateMetadata.from_dict({}))
    return result, next(p for p in document.plots if "first period" in str(p.title))


def test_samples_of_several_periods_are_drawn_at_their_phase_in_phase_order():
    theta_deg = np.arange(160) * 135.0  # 3/8 of a period a sample: 8 phases
    result, plot = _first_period_plot(_record(theta_deg), {})
    series = plot.series[0]
    assert series.x.size == 64
    assert np.all(series.x >= 0.0) and np.all(series.x < 360.0)  # (was up to 8505°)
    assert np.all(np.diff(series.x) >= 0.0)
    assert series.markers
    assert "folded" in str(plot.x_label)
    # each sample keeps its own error at its phase
    drawn = sorted(zip(np.round(series.x, 9).tolist(), series.y.tolist(), strict=True))
    own = sorted(zip(np.round(np.mod(theta_deg[:64], 360.0), 9).tolist(),
                     result.compensated_error[:64].tolist(), strict=True))
    assert drawn == own
    assert np.all(np.isfinite(series.band))


def test_one_period_in_order_is_drawn_as_it_was():
    per_period = 64
    theta_deg = np.arange(per_period * 4) * (360.0 / per_period)
    parsed = _record(theta_deg)
    parsed.values["theta_deg"] = np.full(theta_deg.size, math.nan)
    _, plot = _first_period_plot(parsed, {"samples_per_period": per_period})
    series = plot.series[0]
    assert np.allclose(series.x, theta_deg[:per_period])
    assert "folded" not in str(plot.x_label)
