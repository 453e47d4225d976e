"""Zenith angles read as elevations are refused naming --zenith (contract75 F13: a
``zenith_deg`` or ``V`` column, taken by its place as the elevation, was refused with
"no set-up … fits the elevations" and not a word of --zenith). The readings are simulated
from first principles (tests/theodolite_passes_simulator.py)."""

from __future__ import annotations

import numpy as np
import pytest

from app.main import main
from tests.theodolite_passes_simulator import ALPHA, BETA, PSI, THETA, mirror_readings

HINT = ("the vertical readings are all near 90°, as zenith angles V are: if the vertical "
        "circle reads V, set the vertical reading to zenith (--zenith; E = V − 90°)")


@pytest.mark.parametrize("header", ["zenith_deg", "V"])
def test_zenith_angles_without_zenith_are_refused_naming_it(tmp_path, capsys, header):
    azimuth, elevation = mirror_readings(THETA)
    path = tmp_path / "zenith.csv"
    path.write_text(f"theta_deg,azimuth_deg,{header}\n" + "".join(
        f"{float(t)!r},{float(a)!r},{float(e) + 90.0!r}\n" for t, a, e in zip(THETA, azimuth, elevation,
                                                          strict=True)), encoding="utf-8")
    assert main(["analyze", "theodolite", str(path), "--language", "en"]) == 2
    captured = capsys.readouterr()
    (line,) = captured.err.strip().splitlines()
    assert line.startswith(f"{path}: ") and line.endswith(HINT)
    assert captured.out == ""
    # as the hint says: the set-up the readings were made with
    assert main(["analyze", "theodolite", str(path), "--zenith", "--json"]) == 0
    import json

    found = json.loads(capsys.readouterr().out)
    assert found["psi_deg"] == pytest.approx(PSI, abs=1e-6)
    assert found["alpha_deg"] == pytest.approx(ALPHA, abs=1e-5)
    assert found["beta_deg"] == pytest.approx(BETA, abs=1e-6)


def test_elevations_that_fit_nothing_get_no_zenith_hint():
    from models.theodolite.model import identify_from_elevations

    theta = np.arange(-20.0, 21.0, 5.0)
    with pytest.raises(ValueError) as refused:
        identify_from_elevations(theta, 30.0 + 20.0 * np.cos(np.radians(7 * theta)))
    assert "--zenith" not in str(refused.value)


def test_the_fit_s_refusal_names_zenith_too():
    from models.theodolite.model import identify_from_elevations

    _, elevation = mirror_readings(THETA)
    with pytest.raises(ValueError) as refused:
        identify_from_elevations(THETA, elevation + 90.0)
    assert str(refused.value).endswith(HINT)
