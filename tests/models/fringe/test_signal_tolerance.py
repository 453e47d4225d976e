"""Signal tolerance presets (#45): the judgement at the band edges, the figures of a fit, the
presets' dict round trip."""

from __future__ import annotations

import math

import numpy as np
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


# -- simulated heads, fitted by the workbench, judged ----------------------------------------

from models.fringe.analysis import FRINGE  # noqa: E402
from models.fringe.signal_tolerance import signal_figures  # noqa: E402
from models.readings.sheet import ParsedReadings  # noqa: E402
from tests.fringe_signal_simulator import Head, equal_phase  # noqa: E402

PER = 64


def _fit(head: Head, periods: int = 8, seed: int = 0, scale: float = 1.0, max_order: int = 3):
    theta = equal_phase(periods, PER)
    u_a, u_b = head.signals(theta, np.random.default_rng(seed))
    parsed = ParsedReadings({"u_sin": u_a / scale, "u_cos": u_b / scale,
                             "theta_deg": np.full(theta.size, np.nan)}, np.arange(theta.size))
    return FRINGE.analyze(parsed, {"samples_per_period": PER, "max_order": max_order,
                                   "harmonics": "all"})


VPP = preset_by_key("heidenhain_1vpp")


def _states(head: Head, **kw) -> dict[str, str]:
    result = _fit(head, **kw)
    return {j.quantity: j.state for j in judge(signal_figures(result, VPP, kw.get("scale", 1.0)),
                                               VPP)}


def test_a_head_on_every_edge_is_inside():
    # 1.2 Vpp and 0.96 Vpp: ratio 0.8; quadrature +10°; offsets at the asymmetry's edges
    sym = VPP.band("offset_a").inside[1] / 100.0
    head = Head(peak_a=0.6, peak_b=0.48, quadrature_deg=10.0,
                offset_a=sym * 1.2, offset_b=-sym * 0.96)
    states = _states(head)
    assert states == dict.fromkeys(("amplitude_a", "amplitude_b", "amplitude_ratio",
                                    "phase_deviation", "offset_a", "offset_b"), "inside")
    figures = signal_figures(_fit(head), VPP)
    assert figures["amplitude_a"] == pytest.approx(1.2, rel=1e-12)
    assert figures["amplitude_ratio"] == pytest.approx(0.8, rel=1e-12)
    assert figures["phase_deviation"] == pytest.approx(10.0, abs=1e-9)
    assert figures["offset_a"] == pytest.approx(100 * sym, rel=1e-9)
    assert figures["harmonic_content"] == pytest.approx(0.0, abs=1e-9)


def test_just_beyond_each_edge_is_outside():
    sym = VPP.band("offset_a").inside[1] / 100.0
    head = Head(peak_a=0.6 * 1.0001, peak_b=0.48 * 0.9998, quadrature_deg=-10.001,
                offset_a=-sym * 1.2 * 1.001, offset_b=sym * 0.96 * 1.001)
    states = _states(head)
    assert states.pop("amplitude_b") == "inside"  # 0.96 Vpp: only its ratio to A is beyond
    assert set(states.values()) == {"outside"} and len(states) == 5


def test_noisy_head_near_edges_with_a_two_band_preset():
    # a lab's preset with an outer band; 1 mV noise; margins of 1 % beyond the edges
    lab = TolerancePreset("lab", "lab", "1Vpp", (
        Band("amplitude_a", "Vpp", (0.8, 1.2), (0.6, 1.3)),
        Band("phase_deviation", "°", (-2.0, 2.0), (-5.0, 5.0)),
        Band("harmonic_content", "%", (0.0, 1.0), (0.0, 3.0))), "test")
    for ptp, quad, h3, want in [
        (1.2 * 1.01, 2.05, 0.0101, ("outer", "outer", "outer")),
        (1.2 * 0.99, 1.95, 0.0099, ("inside", "inside", "inside")),
        (1.3 * 1.01, 5.05, 0.0303, ("outside", "outside", "outside")),
        (0.8 * 0.99, -5.05, 0.0297, ("outer", "outside", "outer")),
    ]:
        shape = Head(peak_a=1.0, harmonics={3: (h3, 0.3)})
        head = Head(peak_a=ptp / shape.peak_to_peak()[0], peak_b=0.5, quadrature_deg=quad,
                    harmonics={3: (h3, 0.3)}, noise=1e-3)
        assert head.peak_to_peak()[0] == pytest.approx(ptp, rel=1e-9)
        result = _fit(head, periods=32, seed=3)
        got = judge(signal_figures(result, lab), lab)
        assert tuple(j.state for j in got) == want, [(j.quantity, j.value) for j in got]


def test_record_in_adc_counts_with_a_scale():
    lsb = 0.002  # V per count (the workbench refuses values beyond ±1000: a coarse ADC here)
    head = Head(peak_a=0.5, peak_b=0.45, offset_a=0.01)
    result = _fit(head, scale=lsb)
    volts = signal_figures(result, None, scale=lsb)
    assert volts["amplitude_a"] == pytest.approx(1.0, rel=1e-9)
    assert volts["offset_a"] == pytest.approx(0.01, rel=1e-6)  # no preset: in V
    assert signal_figures(result, VPP, scale=lsb)["offset_a"] == pytest.approx(1.0, rel=1e-6)
    with pytest.raises(ValueError, match="scale"):
        signal_figures(result, VPP, scale=0.0)


# -- the dict round trip, for any preset a lab could type -------------------------------------

from hypothesis import given  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from models.fringe.signal_tolerance import INTERFACES, QUANTITIES  # noqa: E402

_finite = st.floats(-1e6, 1e6, allow_nan=False, allow_infinity=False)


@st.composite
def _bands(draw):
    quantities = draw(st.lists(st.sampled_from(QUANTITIES), min_size=1, unique=True))
    out = []
    for q in quantities:
        low, high = sorted(draw(st.tuples(_finite, _finite)))
        outer = None
        if draw(st.booleans()):
            outer = (low - draw(st.floats(0, 1e3)), high + draw(st.floats(0, 1e3)))
        out.append(Band(q, draw(st.sampled_from(("Vpp", "µApp", "%", "°", "", "V"))),
                        (low, high), outer))
    return tuple(out)


@given(key=st.text(min_size=1).filter(lambda s: s.strip() == s and s.strip()),
       name=st.text(), interface=st.sampled_from(INTERFACES), bands=_bands(), source=st.text())
def test_any_preset_round_trips_through_a_dict(key, name, interface, bands, source):
    preset = TolerancePreset(key, name, interface, bands, source)
    import json
    again = preset_from_dict(json.loads(json.dumps(preset_to_dict(preset))))
    assert again == preset
    presets, problems = load_presets(lab_defaults_with_presets({}, [preset]))
    assert problems == [] and preset_by_key(key, presets) == preset
