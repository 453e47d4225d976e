"""The readings' identity by their physical values (models/register/readings_identity.py,
ident80) at its edges: no grid is cut through the values, so readings at 0.001″ anywhere —
next to any would-be boundary — re-typed in decimal degrees are the same readings, and the
anchors the register finds them by are near; one reading a step away is not; the tolerance
is the coarser value's half step, its end included."""

from __future__ import annotations

import json

import numpy as np
import pytest

from models.readings.angles import format_dms
from models.register.readings_identity import near, readings_identity, same_readings_values


def _identity(rows, settings=None):
    return readings_identity(json.dumps({"workbenches": {"theodolite": {
        "rows": rows, "settings": settings or {}}}}), "theodolite")


def _readings(seed: int, n: int = 200) -> np.ndarray:
    """n azimuths and elevations to 0.001″, whole thousandths of a second of arc."""
    rng = np.random.default_rng(seed)
    return np.round(rng.uniform(-40.0, 40.0, (n, 2)) * 3.6e6) / 3.6e6


def _found(one, other) -> bool:
    return same_readings_values(one, other) and near(one.anchor, one.reach, other.anchor,
                                                     other.reach)


@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize("places", [6, 7, 8, 10, 12])
def test_readings_to_0_001_arcsec_retyped_in_decimal_degrees_are_found(seed, places):
    values = _readings(seed)
    rows = [[str(i), format_dms(a, 3), format_dms(e, 3)] for i, (a, e) in enumerate(values)]
    retyped = [[str(i), f"{a:.{places}f}", f"{e:.{places}f}"] for i, (a, e) in enumerate(values)]
    original, copy = _identity(rows), _identity(retyped[::-1])
    assert original.layout == copy.layout and _found(original, copy) and _found(copy, original)
    # one of 400 readings a step (0.001″) away, typed as the original: other readings
    moved = [list(r) for r in rows]
    moved[17][2] = format_dms(values[17, 1] + 0.001 / 3600, 3)
    assert not same_readings_values(original, _identity(moved))


def test_the_tolerance_is_half_the_coarser_step_its_end_included():
    rows = [["0", "10°00'00.1\"", "1°00'00.0\""], ["1", "11°00'00.0\"", "1°00'00.0\""]]
    one = _identity(rows)
    # 0.05″ away typed to 0.01″: within half of the original's 0.1″
    half = [["0", "10°00'00.15\"", "1°00'00.0\""], rows[1]]
    assert same_readings_values(one, _identity(half))
    beyond = [["0", "10°00'00.16\"", "1°00'00.0\""], rows[1]]
    assert not same_readings_values(one, _identity(beyond))
    # and the other way: a row given twice is the same readings, a row left out is not
    assert same_readings_values(one, _identity([*rows, rows[0]]))
    assert not same_readings_values(one, _identity(rows[:1]))


def test_no_readings_are_no_ones():
    assert _identity([]) is None and _identity([["", "", ""]]) is None
    assert not same_readings_values(None, None)
