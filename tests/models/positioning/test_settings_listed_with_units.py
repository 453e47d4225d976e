"""Assessment 78 L8: the positioning certificate's settings listed the budget's inputs with
no unit — "misalignment u 0.3", "reference resolution 0.1", "temperature u 0.2" — where the
figures are in the deviations' unit (arcseconds on a rotary axis, µm on a linear one). Each
is listed with that unit; "not stated" stays as it is."""

from __future__ import annotations

import pytest

from models.certificate.metadata import CertificateMetadata
from tests.models.certificate.test_certificate_statements import _sample

INPUTS = {"misalignment_u": 0.3, "reference_resolution": 0.1, "temperature_u": 0.2}


def _listing(settings):
    kind, result = _sample("positioning", settings)
    checked = kind.settings_with_defaults(settings)
    document = kind.certificate_document(result, CertificateMetadata(language="en"),
                                         settings=checked)
    return dict((str(k), str(v)) for k, v in document.settings)


def test_the_inputs_are_listed_in_the_deviations_unit():
    listed = _listing(INPUTS)
    assert listed["misalignment u"] == "0.3\""
    assert listed["reference resolution"] == "0.1\""
    assert listed["temperature u"] == "0.2\""
    assert listed["deviation unit"] == "arcseconds (\")"


@pytest.mark.parametrize("unit, symbol", [("urad", " µrad")])
def test_another_deviation_unit_is_said(unit, symbol):
    listed = _listing({**INPUTS, "deviation_unit": unit})
    assert listed["misalignment u"] == f"0.3{symbol}"
    assert listed["temperature u"] == f"0.2{symbol}"


def test_an_input_not_stated_is_said_so_with_no_unit():
    listed = _listing({"misalignment_u": 0.3})
    assert listed["misalignment u"] == "0.3\""
    assert listed["reference resolution"] == "not stated"
    assert listed["temperature u"] == "not stated"
