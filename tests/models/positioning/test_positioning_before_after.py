"""Before and after compensation (models/positioning/before_after.py): hand-checked logs,
the rig's axis measured again through an ideal controller applying our table, and the
refusals when two logs cannot be compared."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.positioning.analysis import POSITIONING
from models.positioning.before_after import before_after
from models.positioning.compensation import compensation_table
from models.readings.sheet import ReadingsSheet
from models.validation.positioning_rig import AxisRig

ARCSEC = 1 / 3600.0


def analyze(rows, **settings):
    return POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, rows).parse(), settings)


def log(up: dict[float, list[float]], down: dict[float, list[float]], **settings):
    """Readings (target, run, direction, deviation) from deviations per target and run."""
    rows = []
    runs = len(next(iter((up or down).values())))
    for run in range(runs):
        rows += [[f"{t:g}", str(run + 1), "+", f"{v[run]:g}", ""] for t, v in sorted(up.items())]
        rows += [[f"{t:g}", str(run + 1), "-", f"{v[run]:g}", ""]
                 for t, v in sorted(down.items(), reverse=True)]
    return analyze(rows, **settings)


# before: x̄↑ = 1, 3, 5 and x̄↓ = −1, 1, 3 (no scatter): E = 6, B = 2, M = 4 − 0 = 4, A = 6, R = 2
BEFORE = dict(up={0: [1, 1], 10: [3, 3], 20: [5, 5]}, down={0: [-1, -1], 10: [1, 1], 20: [3, 3]})
# after: x̄↑ = 1, 1, 1 (s↑ = √½ at 0), x̄↓ = 0: E = 1, B = 1, M = 0,
# A = (1 + 2√½) − (1 − 2√½) = 4√½ = 2.828, R = max(2√½ + 1, 4√½) = 2.828
AFTER = dict(up={0: [0.5, 1.5], 10: [1, 1], 20: [1, 1]}, down={0: [0, 0], 10: [0, 0], 20: [0, 0]})


def test_hand_checked_figures_before_after_and_improvement():
    ba = before_after(log(**BEFORE), log(**AFTER))
    s = math.sqrt(0.5)
    expect = {"A": (6, 4 * s), "B": (2, 1), "E": (6, 1), "M": (4, 0), "R": (2, 4 * s)}
    assert [c.key for c in ba.figures] == ["A", "B", "E", "M", "R"]
    for key, (b, a) in expect.items():
        assert ba[key].before == pytest.approx(b, abs=1e-9)
        assert ba[key].after == pytest.approx(a, abs=1e-9)
        assert ba[key].improvement == pytest.approx(b - a, abs=1e-9)
        assert ba[key].percent == pytest.approx(100 * (b - a) / b, abs=1e-7)
    # R got worse (the after log scatters): a negative improvement, said as it is
    assert ba["R"].percent < 0
    assert ba.left_out == {"before": 0, "after": 0}
    text = ba.text("after.csv")
    assert 'A 6.000" → 2.828" (-53 %)' in text
    assert 'B 2.000" → 1.000" (-50 %)' in text and 'E 6.000" → 1.000" (-83 %)' in text
    assert "after.csv, 3 common targets" in text
    data = ba.as_dict()
    assert data["figures"]["E"] == {"before": 6.0, "after": 1.0, "improvement": 5.0,
                                    "improvement_percent": pytest.approx(500 / 6)}


def test_only_the_common_targets_are_compared():
    after = {k: {t: v for t, v in d.items() if t != 20} for k, d in AFTER.items()}
    after["up"][30] = [9, 9]
    after["down"][30] = [9, 9]
    ba = before_after(log(**BEFORE), log(**after))
    # before over 0, 10: x̄↑ = 1, 3, x̄↓ = −1, 1: E = 4, B = 2, M = 2
    assert list(ba.targets) == [0, 10]
    assert (ba["E"].before, ba["B"].before, ba["M"].before) == pytest.approx((4, 2, 2))
    assert (ba["E"].after, ba["B"].after) == pytest.approx((1, 1))  # 30 (9") left out
    assert ba.left_out == {"before": 4, "after": 4}
    assert "8 reading(s) at targets only one log has left out" in ba.text()


def test_unidirectional_logs_compare_per_direction():
    before = log(up=BEFORE["up"], down={})
    after = log(**AFTER)
    ba = before_after(before, after)
    assert [c.key for c in ba.figures] == ["A_up", "E_up", "R_up"]
    assert ba["E_up"].before == pytest.approx(4) and ba["E_up"].after == pytest.approx(0)
    assert ba["E_up"].percent == pytest.approx(100)


def test_logs_that_cannot_be_compared_are_refused():
    with pytest.raises(ValueError, match="deviations in urad.*before in arcsec"):
        before_after(log(**BEFORE), log(**AFTER, deviation_unit="urad"))
    with pytest.raises(ValueError, match="targets in mm"):
        before_after(log(**BEFORE), log(**AFTER, target_unit="mm", deviation_unit="um"))
    far = {k: {t + 100: v for t, v in d.items()} for k, d in AFTER.items()}
    with pytest.raises(ValueError, match="no target in common"):
        before_after(log(**BEFORE), log(**far))
    with pytest.raises(ValueError, match="no approach direction in common"):
        before_after(log(up=BEFORE["up"], down={}), log(up={}, down=AFTER["down"]))


def rotary_error(p):
    """Eccentricity (1/rev) and a 4/rev periodic error, degrees (first principles)."""
    r = np.radians(p)
    return (8.0 * np.sin(r) + 3.0 * np.sin(4 * r + 0.3)) * ARCSEC


def measure(controller=None, noise=0.0, seed=1):
    rig = AxisRig(rotary_error, lost_motion=4.0 * ARCSEC, drift_per_run=0.6 * ARCSEC,
                  noise=noise, rng=np.random.default_rng(seed), controller=controller)
    cycle = rig.standard_cycle(np.arange(0.0, 360.0 + 1e-9, 15.0), 5)
    rows = [[f"{t:.9g}", str(run), "+" if d > 0 else "-", f"{(x - t) * 3600:.9f}", ""]
            for t, run, d, x in cycle]
    return analyze(rows)


def ideal_controller(table):
    """Commands target − (−compensation): the table's value at the target, per direction,
    moved in the target unit (what a controller applying our table does)."""
    def command(target, direction):
        values = table.forward if direction > 0 or table.backward is None else table.backward
        return target + float(np.interp(target, table.positions, values)) / 3600.0
    return command


@pytest.mark.parametrize("noise", [0.0, 0.3 * ARCSEC])
def test_the_rig_after_our_compensation_loses_its_systematic_error(noise):
    before = measure(noise=noise, seed=1)
    after = measure(ideal_controller(compensation_table(before)), noise=noise, seed=2)
    ba = before_after(before, after)
    # the axis' own error: eccentricity 8" and 4/rev 3" (±11" at most) and lost motion 4"
    assert ba["E"].before > 18 and ba["B"].before == pytest.approx(4, abs=0.1 + 10 * noise * 3600)
    # the table removes the systematic part (left: second order in the slope of the error,
    # and the noise's effect on the means)
    assert ba["E"].after < 0.05 * ba["E"].before + 4 * noise * 3600
    assert ba["B"].after < 0.05 + 4 * noise * 3600
    assert ba["M"].after < 0.05 + 4 * noise * 3600
    assert ba["E"].percent > 85 and ba["B"].percent > 75
    # the drift (0.6"/run over 5 runs) is no systematic error: A after is its ±2s band,
    # 4·s of 0, 0.6, …, 2.4 = 4·0.6·√2.5 = 3.79" (plus the noise)
    if noise == 0:
        assert ba["A"].after == pytest.approx(4 * 0.6 * math.sqrt(2.5), abs=0.05)
        assert ba["R"].after == pytest.approx(ba["R"].before - ba["B"].before, abs=0.1)
    assert ba["A"].after < 0.4 * ba["A"].before


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-50, 50), min_size=12, max_size=12),
       st.lists(st.floats(-50, 50), min_size=12, max_size=12))
@pytest.mark.slow
def test_a_log_against_itself_changes_nothing_and_swapping_negates(first, second):
    def of(values):
        v = iter(values)
        return log(up={t: [next(v), next(v)] for t in (0, 10, 20)},
                   down={t: [next(v), next(v)] for t in (0, 10, 20)})
    a, b = of(first), of(second)
    same = before_after(a, a)
    assert all(c.improvement == 0 for c in same.figures)
    there, back = before_after(a, b), before_after(b, a)
    for key in ("A", "B", "E", "M", "R"):
        assert there[key].before == a.iso.figures[key] and there[key].after == b.iso.figures[key]
        assert there[key].improvement == pytest.approx(-back[key].improvement, abs=1e-12)
