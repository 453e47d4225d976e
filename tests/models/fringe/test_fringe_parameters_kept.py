"""The parameters' uncertainties are worked out once a result and its stated inputs: the
summary, the JSON, the certificate's tables and its DCC each read them (with an ADC linearity
stated, a θ column of 10⁶ phases took about a second a pass, four or five passes a
certificate); a changed input is worked out again, never read from before. The record comes
from tests/fringe_adc_rig.py (first principles)."""

from __future__ import annotations

import numpy as np

from models.fringe.analysis import FRINGE
from models.fringe.parameter_uncertainty import parameter_uncertainty
from models.readings.sheet import ParsedReadings
from tests.fringe_adc_rig import Adc, Head, equal_steps


def _result():
    theta = equal_steps(64, 32)
    adc = Adc(offset_u_v=0.001, gain_u=0.002, noise_v=0.0003, lsb_v=0.00025)
    u_sin, u_cos = adc.digitise(*Head().clean(theta), np.random.default_rng(71))
    parsed = ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                             "theta_deg": np.full(u_sin.size, np.nan)}, np.arange(u_sin.size))
    return FRINGE.analyze(parsed, {"lines_per_rev": 16384, "samples_per_period": 32,
                                   "adc_lsb_mv": 0.25, "adc_offset_u_mv": 1.0,
                                   "adc_gain_u_pct": 0.2, "adc_linearity_mv": 0.5})


def test_the_same_inputs_read_the_uncertainties_worked_out_once():
    result = _result()
    assert parameter_uncertainty(result) is parameter_uncertainty(result)


def test_a_changed_input_is_worked_out_again():
    result = _result()
    first = parameter_uncertainty(result)
    result.inputs["adc_linearity_mv"] = 3.0
    wider = parameter_uncertainty(result)
    assert wider is not first
    assert wider.channels["cos"]["A3"] > 2 * first.channels["cos"]["A3"]
    result.inputs["adc_linearity_mv"] = 0.5
    again = parameter_uncertainty(result)
    assert again.channels["cos"]["A3"] == first.channels["cos"]["A3"]
