"""The positioning certificate's decided quantity where every point decides (day 68, finding
4): the deciding point is named, its value is its mean deviation with its sign, and its
interval is that value ± the point's U — not a half range held at 0 ("6″ −6″/+18″, 0″ …
25″, … as a half range is not negative" for a point at −6″). The axis is simulated here
from first principles (this file's generator imports nothing from the code it checks).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.repeatability_rig import iso230_rows

TROUGH = 90.0  # the target whose forward approach lies far below the rest


def _axis(rng, runs: int, targets: int = 8, noise: float = 0.3):
    """An ISO 230-2 test of a rotary axis: x = f(P) ± b/2 + σ z at every approach, each run
    up through the targets and back down; f has one deep trough, −8″ forward, at TROUGH.
    Returns (rows for the readings sheet, the readings by (target, direction))."""
    angles = np.linspace(0.0, 360.0, targets, endpoint=False)
    f = 1.5 * np.sin(np.radians(angles))
    mu = {"+": f + 0.5, "-": f - 0.5}
    mu["+"][int(np.argmin(abs(angles - TROUGH)))] = -8.0
    return iso230_rows(angles, mu, runs, noise, rng)


def _certificate(rows):
    from models.certificate.metadata import CertificateMetadata
    from models.positioning.analysis import POSITIONING
    from models.positioning.report import positioning_certificate
    from models.readings.sheet import ReadingsSheet

    settings = POSITIONING.settings_with_defaults({})
    result = POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, rows).parse(), settings)
    meta = CertificateMetadata(tolerance=15.0, tolerance_unit="arcsec",
                               decision_rule="guarded", decision_quantity="points")
    return positioning_certificate(result, meta)


@pytest.mark.parametrize("runs", [2, 5])
def test_the_deciding_point_is_named_with_its_signed_error(runs):
    rows, readings = _axis(np.random.default_rng(6804 + runs), runs)
    document = _certificate(rows)
    c = document.conformity
    # the deciding point is the trough (|x̄| + U there is the largest by far): its mean
    # deviation as the readings give it, negative, and ±U about it
    mean = float(np.mean(readings[(TROUGH, "+")]))
    assert mean < -6.0
    assert c.value == pytest.approx(mean, abs=1e-9)
    assert "90" in str(c.point) and "↑" in str(c.point)
    u = c.expanded
    assert math.isfinite(u) and u > 0 and c.expanded_lower == pytest.approx(u)
    assert c.interval_low == pytest.approx(mean - u, abs=1e-9)
    assert c.interval_high == pytest.approx(mean + u, abs=1e-9)
    # the certificate's row: the signed value, the interval about it, the point named, and
    # no half range held at 0
    row = next(r for r in document.statistics.rows if str(r[0]) == "Decided quantity")
    value, interval, note = str(row[1]), str(row[2]), str(row[4])
    assert value.startswith("-") and "±" in value and "/" not in value
    low, high = (float(end.strip().rstrip('"')) for end in interval.split("…"))
    step = 10.0 ** -len(value.split("±")[1].strip().rstrip('"').partition(".")[2])
    # outward, and the printed value ± the printed U (rounded up: GUM 7.2.6) the printed ends
    # (assessment 70 M1): at most a digit and a half beyond the computed ends
    shown, shown_u = (float(x.strip().rstrip('"')) for x in value.split("±"))
    assert shown_u >= u - 1e-12
    assert low == pytest.approx(shown - shown_u, abs=1e-9)
    assert high == pytest.approx(shown + shown_u, abs=1e-9)
    assert mean - u - 1.5 * step - 1e-9 <= low <= mean - u
    assert mean + u <= high <= mean + u + 1.5 * step + 1e-9
    assert "half range" not in note and "held at 0" not in note
    assert "90°" in note and "↑" in note

