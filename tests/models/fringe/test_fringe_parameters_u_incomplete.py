"""A signal parameter's U without an ADC figure that acts on it is said incomplete beside the
parameters table and in the JSON (assessment 70, M7: the bundled record printed the
offsets' U, 5.5 times less than with the ADC's figures stated, with no word of it there).

The ADC offset acts on the offsets, the gain ratio on the offsets, the amplitudes and the
amplitude ratio, the phase reference u (with N equal steps, the sampling's timing) on the
harmonics' phases, the ADC linearity (its integral nonlinearity) on every parameter (audit
71, finding 1: in none of them before; models.fringe.parameter_uncertainty). The
record comes from tests/fringe_adc_rig.py (first principles: the read head, an ADC offset
and gain ratio drawn once a run, noise, rounding)."""

from __future__ import annotations

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata
from models.fringe.analysis import FRINGE
from models.readings.sheet import ParsedReadings
from tests.fringe_adc_rig import Adc, Head, equal_steps

ADC = Adc(offset_u_v=0.001, gain_u=0.002, noise_v=0.0003, lsb_v=0.00025)
INCOMPLETE = "is incomplete"


def _outputs(stated: dict) -> tuple[str, dict]:
    theta = equal_steps(256, 64)
    u_sin, u_cos = ADC.digitise(*Head().clean(theta), np.random.default_rng(70))
    parsed = ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                             "theta_deg": np.full(u_sin.size, np.nan)}, np.arange(u_sin.size))
    settings = {"lines_per_rev": 16384, "samples_per_period": 64,
                "adc_lsb_mv": ADC.lsb_v * 1e3, "phase_reference_u": 0.02,
                "adc_linearity_mv": 0.5, **stated}
    result = FRINGE.analyze(parsed, {k: v for k, v in settings.items() if v is not None})
    metadata = CertificateMetadata.from_dict({})
    note = str(FRINGE.certificate(result, metadata).parameters.note)
    return note, FRINGE.certified_json(result, metadata)


@pytest.mark.parametrize(("stated", "named", "parameters"), [
    ({"adc_offset_u_mv": 1.0, "adc_gain_u_pct": 0.2, "phase_reference_u": None},
     ["Phase reference"], ["the harmonics' phases c"]),
    ({}, ["ADC offset", "ADC gain ratio"],
     ["the offsets A₀", "the amplitudes A", "the amplitude ratio"]),
    ({"adc_offset_u_mv": 1.0}, ["ADC gain ratio"],
     ["the offsets A₀", "the amplitudes A", "the amplitude ratio"]),
    ({"adc_gain_u_pct": 0.2}, ["ADC offset"], ["the offsets A₀"]),
    ({"adc_offset_u_mv": 1.0, "adc_gain_u_pct": 0.2, "adc_linearity_mv": None},
     ["ADC linearity"], ["the offsets A₀", "the amplitudes A", "the harmonics' phases c",
                         "the amplitude ratio", "the quadrature error"]),
])
def test_the_u_without_an_adc_figure_is_said_incomplete(stated, named, parameters):
    note, data = _outputs(stated)
    said = data["parameters_uncertainty_incomplete"]
    assert data["sin_params"]["expanded_uncertainty_A0"] is not None  # the U is given
    for text in (note, said):
        assert INCOMPLETE in text, text
        assert all(name in text.split(" not stated")[0] for name in named), text
        assert all(p in text.split(" is incomplete")[0] for p in parameters), text
    if "adc_offset_u_mv" in stated:
        assert "ADC offset," not in note and "ADC offset not" not in note
    if stated == {"adc_gain_u_pct": 0.2}:
        assert "amplitude" not in note.split(" is incomplete")[0]
    if stated.get("phase_reference_u", 0.02) and stated.get("adc_linearity_mv", 0.5):
        assert "phases" not in note.split(" is incomplete")[0]


def test_every_figure_stated_leaves_the_u_unqualified():
    note, data = _outputs({"adc_offset_u_mv": 1.0, "adc_gain_u_pct": 0.2})
    assert INCOMPLETE not in note
    assert "parameters_uncertainty_incomplete" in data
    assert data["parameters_uncertainty_incomplete"] is None
