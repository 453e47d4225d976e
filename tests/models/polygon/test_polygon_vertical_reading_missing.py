"""Contract review 75 F9: one empty vertical-reading cell switched off the whole set's
pyramidal correction (ψ = 480″ no longer removed, errors moved by 0.5″) and the warning
named no row. The tilt is fitted from the faces that have a vertical reading (each face's
correction needs only ψ, ω and its angle), the faces and rows without one named; too few
left: not identified, as before.

Checked against an exact 3-D rig written here: a polygon seated on a levelled shaft with its
axis tilted by ψ towards ω, turned about the shaft to each face with a stopping error, read
by a levelled autocollimator (c = −atan2(n_y, n_x), v = asin n_z)."""

from __future__ import annotations

import numpy as np
import pytest

from models.polygon.analysis import POLYGON
from models.readings.sheet import ReadingsSheet

ARCSEC = 180.0 * 3600.0 / np.pi
FACES = 24


def _turn(v: np.ndarray, axis: np.ndarray, angle: float) -> np.ndarray:
    """Rodrigues' rotation of ``v`` about the unit ``axis`` by ``angle`` (rad)."""
    return (v * np.cos(angle) + np.cross(axis, v) * np.sin(angle)
            + axis * np.dot(axis, v) * (1.0 - np.cos(angle)))


def _rig_rows(psi_arcsec: float, omega_deg: float, seed: int = 9,
              sets: int = 1) -> tuple[list[list[str]], np.ndarray]:
    """Rows of ``sets`` forward sets of a tilted polygon and the encoder's true error at
    faces 1…n (″) that the corrected error must give back (against face 1)."""
    rng = np.random.default_rng(seed)
    phi = np.arange(FACES) * 2.0 * np.pi / FACES
    truth = 0.4 * np.sin(phi + 0.3) + 0.15 * np.cos(2.0 * phi)
    om = np.radians(omega_deg)
    tilt_axis = np.array([-np.sin(om), np.cos(om), 0.0])
    rows: list[list[str]] = []
    for s in range(1, sets + 1):
        for i in [*range(FACES), 0]:
            stop = rng.normal(0.0, 2.0)  # where the operator stopped the shaft (″)
            normal = _turn(np.array([np.cos(phi[i]), np.sin(phi[i]), 0.0]), tilt_axis,
                           psi_arcsec / ARCSEC)
            normal = _turn(normal, np.array([0.0, 0.0, 1.0]), -(phi[i] + stop / ARCSEC))
            c = -np.arctan2(normal[1], normal[0]) * ARCSEC
            v = np.arcsin(normal[2]) * ARCSEC
            encoder = np.degrees(phi[i]) + (stop + truth[i]) / 3600.0
            rows.append([str(i + 1), repr(float(encoder)), "0", repr(float(c)), repr(float(v)),
                         str(s), "+"])
    return rows, truth - truth[0]


def _analyse(rows):
    parsed = ReadingsSheet(POLYGON.columns, rows).parse()
    return POLYGON.analyze(parsed, POLYGON.settings_with_defaults({"grade": 3}))


def test_the_rig_is_read_right_with_every_vertical_reading():
    rows, truth = _rig_rows(480.0, 30.0)
    result = _analyse(rows)
    assert result.sets[0].tilt.psi_arcsec == pytest.approx(480.0, abs=1e-3)
    np.testing.assert_allclose(result.sets[0].corrected_error_arcsec, truth, atol=1e-5)


@pytest.mark.parametrize("blank_face", [1, 7, 13])
def test_one_empty_vertical_cell_still_corrects_the_tilt(blank_face):
    rows, truth = _rig_rows(480.0, 30.0)
    rows[blank_face - 1][4] = ""
    result = _analyse(rows)
    tilt = result.sets[0].tilt
    assert tilt is not None
    assert tilt.psi_arcsec == pytest.approx(480.0, abs=1e-3)
    # the correction at every face, the one without a vertical reading too: the truth
    np.testing.assert_allclose(result.sets[0].corrected_error_arcsec, truth, atol=1e-5)
    assert np.max(np.abs(result.sets[0].pyramidal_error_arcsec)) > 0.3  # a tilt removed
    said = [w for w in result.warnings if "no vertical reading" in w]
    assert said == [f"Set 1: no vertical reading on face(s) {blank_face} (row(s) {blank_face}): "
                    "the pyramidal tilt is fitted from the 23 faces that have one and "
                    "corrected at every face."]
    assert not any("not identified" in w for w in result.warnings)
    # the residual plot's face without a reading is a gap, the others the fit's residuals
    residuals = tilt.residuals_arcsec
    assert residuals.shape == (FACES,) and np.isnan(residuals[blank_face - 1])
    assert np.all(np.abs(np.delete(residuals, blank_face - 1)) < 1e-4)


def test_a_blank_in_one_of_two_sets_keeps_the_noise_between_the_sets():
    rows, truth = _rig_rows(480.0, 30.0, sets=2)
    rows[FACES + 1 + 4][4] = ""  # set 2, face 5
    result = _analyse(rows)
    assert all(s.tilt is not None for s in result.sets)
    for s in result.sets:
        np.testing.assert_allclose(s.corrected_error_arcsec, truth, atol=1e-5)
    from models.polygon.model import vertical_fits_noise

    # the rig reads without noise: the fits' residuals are the arithmetic's, no noise told
    # (gui80: 9.76e-17″ went into U as the reading noise)
    assert vertical_fits_noise(result.sets, FACES) is None
    # with a reading noise, it is told between the sets over the faces both read
    rng = np.random.default_rng(80)
    noisy = [r[:4] + [repr(float(r[4]) + rng.normal(0.0, 0.05)) if r[4] else ""] + r[5:]
             for r in rows]
    noise, dof, between = vertical_fits_noise(_analyse(noisy).sets, FACES)
    assert between and dof == (FACES - 1 - 3) and 0.01 < noise < 0.15


def test_too_few_vertical_readings_left_is_not_identified_naming_the_rows():
    rows, _ = _rig_rows(480.0, 30.0)
    for i in range(3, FACES):  # only faces 1–3 keep a vertical reading
        rows[i][4] = ""
    result = _analyse(rows)
    assert result.sets[0].tilt is None
    said = [w for w in result.warnings if "no vertical reading on face(s)" in w]
    assert said and "4, 5, 6, 7, 8, 9, 10, 11, 12, 13, …" in said[0]
    assert "the 3 faces that have one are too few to fit the pyramidal tilt" in said[0]
    assert any("vertical readings missing" in w for w in result.warnings)
