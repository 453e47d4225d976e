"""Signal tolerance presets (#45): the judgement at the band edges, the figures of a fit, the
presets' dict round trip."""

from __future__ import annotations

import math

import pytest

from models.fringe.signal_tolerance import (
    BUILTIN_PRESETS,
    LAB_DEFAULTS_KEY,
    Band,
    PresetError,
    TolerancePreset,
    judge,
    lab_defaults_with_presets,
    load_presets,
    preset_by_key,
    preset_from_dict,
    preset_to_dict,
)

TWO_BANDS = TolerancePreset("lab", "lab", "1Vpp",
                            (Band("amplitude_a", "Vpp", (0.8, 1.2), (0.6, 1.3)),), "lab")


@pytest.mark.parametrize(("value", "state"), [
    (0.8, "inside"), (1.2, "inside"), (1.0, "inside"),
    (0.79999, "outer"), (1.20001, "outer"), (0.6, "outer"), (1.3, "outer"),
    (0.59999, "outside"), (1.30001, "outside"),
])
def test_edges_of_two_bands(value, state):
    (j,) = judge({"amplitude_a": value}, TWO_BANDS)
    assert (j.state, j.value, j.unit) == (state, value, "Vpp")


def test_one_band_preset_has_no_outer_state():
    preset = preset_by_key("heidenhain_1vpp")
    states = {v: judge({"amplitude_ratio": v}, preset)[0].state
              for v in (0.8, 1.25, 0.7999, 1.2501)}
    assert states == {0.8: "inside", 1.25: "inside", 0.7999: "outside", 1.2501: "outside"}


def test_missing_or_nan_figure_is_not_judged():
    preset = preset_by_key("heidenhain_1vpp")
    got = judge({"amplitude_a": 1.0, "amplitude_b": math.nan}, preset)
    assert [j.quantity for j in got] == ["amplitude_a"]


def test_builtin_round_trip_and_lab_defaults():
    for p in BUILTIN_PRESETS:
        assert preset_from_dict(preset_to_dict(p)) == p
    edited = TolerancePreset("heidenhain_1vpp", "ours", "1Vpp",
                             (Band("amplitude_a", "Vpp", (0.9, 1.1), (0.6, 1.2)),), "our rule")
    stored = lab_defaults_with_presets({"lab_name": "X"}, [*BUILTIN_PRESETS, edited, TWO_BANDS])
    assert stored["lab_name"] == "X"
    assert [d["key"] for d in stored[LAB_DEFAULTS_KEY]] == ["heidenhain_1vpp", "lab"]
    presets, problems = load_presets(stored)
    assert problems == []
    assert preset_by_key("heidenhain_1vpp", presets) == edited
    assert preset_by_key("lab", presets) == TWO_BANDS
    assert len(presets) == len(BUILTIN_PRESETS) + 1


def test_bad_stored_preset_is_named_and_others_kept():
    bad = preset_to_dict(TWO_BANDS) | {"key": "bad"}
    bad["bands"][0]["outer"] = [0.9, 1.0]  # does not contain the inside band
    presets, problems = load_presets({LAB_DEFAULTS_KEY: [bad, preset_to_dict(TWO_BANDS)]})
    assert len(problems) == 1 and "bad" in problems[0] and "outer" in problems[0]
    assert preset_by_key("lab", presets) == TWO_BANDS
    with pytest.raises(PresetError, match="quantity"):
        preset_from_dict({"key": "k", "interface": "1Vpp",
                          "bands": [{"quantity": "colour", "inside": [0, 1]}]})
