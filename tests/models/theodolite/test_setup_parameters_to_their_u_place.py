"""Assessment 78 L3: the theodolite's set-up parameters were printed in degrees to a place
coarser than their U's last digit, U in arcseconds: "Axis tilt ψ 5.8263° U 6.4″" (0.0001° =
0.36″ beside a U to 0.1″), "Tilt direction α 43.484° U 59″". Value and U are printed in one
unit, degrees, to the same place (GUM 7.2.6): "5.8263°" with "0.0018°"."""

from __future__ import annotations

import math
import re

import pytest

from tests.models.certificate.test_certificate_statements import _sample
from tests.models.certificate.test_certificate_uncertainty import META


def _decimals(text: str) -> int:
    found = re.fullmatch(r"-?\d+(?:\.(\d+))?°", text)
    assert found, text
    return len(found.group(1) or "")


@pytest.fixture(scope="module")
def rows():
    from models.theodolite.report import theodolite_certificate

    _, result = _sample("theodolite")
    document = theodolite_certificate(result, META)
    return result, {str(r[0]): (str(r[1]), str(r[2])) for r in document.parameters.rows}, \
        str(document.parameters.header[2])


@pytest.mark.parametrize("name, index", [("Axis tilt ψ", 0), ("Tilt direction α", 1),
                                         ("Mirror normal β", 2)])
def test_a_set_up_parameter_and_its_u_in_degrees_to_one_place(rows, name, index):
    result, shown, header = rows
    value, u = shown[name]
    assert _decimals(value) == _decimals(u), (value, u)  # the same place, the same unit
    k = float(re.search(r"k = ([\d.]+)", header).group(1))
    expanded_deg = k * result.identification.uncertainty_deg[index]
    # U to two significant digits, rounded up, in degrees
    d = _decimals(u)
    assert float(u.rstrip("°")) == pytest.approx(
        math.ceil(expanded_deg * 10**d - 1e-9) / 10**d, abs=1e-12), (u, expanded_deg)
    assert 10 <= float(u.rstrip("°")) * 10**d < 100  # two significant digits
    setup = result.identification.setup
    exact = (setup.psi_deg, setup.alpha_deg, setup.beta_deg)[index]
    assert float(value.rstrip("°")) == pytest.approx(round(exact, d), abs=10.0 ** -(d + 6))


def test_the_review_s_figures(rows):
    _, shown, _ = rows
    assert shown["Axis tilt ψ"] == ("5.8263°", "0.0018°")  # was 5.8263° beside 6.4″
    assert shown["Tilt direction α"] == ("43.484°", "0.017°")  # was 43.484° beside 59″
