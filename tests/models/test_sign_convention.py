"""One sign convention on every workbench: error = indicated − reference (VIM).

An instrument that indicates 1e-5 too much (a scale error) reads +1.44" at 40°
on the theodolite and +1.08" at 30° on the polygon; before, the theodolite
printed −1.440" (the seed's A − θ is a correction, not an error).
"""

import json

import numpy as np
import pytest

from app.main import main
from models.polygon.analysis import POLYGON
from models.readings.sheet import ReadingsSheet
from models.registry import KINDS
from models.theodolite.model import analyze_run
from models.validation.polygon_rig import PolygonRig
from models.validation.theodolite_rig import theodolite_readings
from models.workbench import SIGN_CONVENTION

SCALE = 1e-5


def test_theodolite_scale_error_is_positive():
    theta = np.arange(-40.0, 40.1, 2.0)  # indicated
    azimuth, elevation = theodolite_readings(theta / (1 + SCALE), 3.0, 45.0, 2.0)
    result = analyze_run(theta, azimuth, elevation)
    i = int(np.argmax(theta))
    assert result.corrected_error_arcsec[i] == pytest.approx(SCALE * 40 * 3600, abs=0.01)  # +1.44"
    np.testing.assert_allclose(result.corrected_error_arcsec, SCALE * theta * 3600, atol=0.01)
    # the raw error is the set-up's share plus the axis' own
    np.testing.assert_allclose(result.raw_error_arcsec - result.model_error_arcsec,
                               result.corrected_error_arcsec, atol=1e-9)


def test_polygon_scale_error_is_positive():
    faces = 12
    nominal = np.arange(faces) * 30.0
    rig = PolygonRig(faces, SCALE * nominal * 3600, psi_arcsec=200.0, omega_deg=30.0)
    result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rig.set_rows()).parse(), {"grade": 7})
    assert result.mean_corrected_arcsec[1] == pytest.approx(1.08, abs=1e-3)


@pytest.mark.parametrize("key", sorted(KINDS))
@pytest.mark.slow
def test_every_json_states_the_convention(key, capsys, samples_dir):
    kind = KINDS[key]
    extra = ["--samples-per-period", "64"] if key == "fringe" else []
    assert main(["analyze", key, str(samples_dir / kind.sample_file), "--json", *extra]) == 0
    expected = "actual_minus_target" if key == "positioning" else SIGN_CONVENTION
    assert json.loads(capsys.readouterr().out)["sign_convention"] == expected
    assert SIGN_CONVENTION == "indicated_minus_reference"


def test_positioning_takes_the_encoder_error_with_iso_sign():
    """ISO 230-2's deviation is actual − target = reference − indicated: an encoder that
    indicates 1e-5 too much (+1.08" at 30°) stops 1.08" short of its target."""
    faces = 12
    nominal = np.arange(faces) * 30.0
    rig = PolygonRig(faces, SCALE * nominal * 3600, psi_arcsec=200.0, omega_deg=30.0)
    result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rig.set_rows()).parse(), {"grade": 7})
    rows = POLYGON.run_rows(result)
    positioning = KINDS["positioning"]
    sent = positioning.analyze(ReadingsSheet(positioning.columns, rows).parse(), {})
    assert sent.iso.forward.mean[1] == pytest.approx(-1.08, abs=1e-3)
    assert positioning.to_json(sent)["sign_convention"] == "actual_minus_target"
