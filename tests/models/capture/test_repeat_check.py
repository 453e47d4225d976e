"""The limit a repeat of a face may read from the face's first reading on the table's
encoder (models/capture/repeat_check.py): half the pitch 360°/N."""

from __future__ import annotations

import pytest

from models.capture.repeat_check import repeat_limit_deg, turned_away


def test_a_repeat_within_half_the_pitch_is_the_same_face():
    assert turned_away(40.0 + 2 / 3600, 40.0, 30.0) is None  # noise: 2″
    assert turned_away(40.2, 40.0, 30.0) is None  # a nudge to null the autocollimator
    assert turned_away(54.99, 40.0, 30.0) is None


def test_the_next_face_is_another_face_either_side_of_zero():
    away = turned_away(70.0, 40.0, 30.0)
    assert away is not None and away.off_deg == pytest.approx(30.0) and away.limit_deg == 15.0
    assert turned_away(55.0, 40.0, 30.0) is not None  # half the pitch: nearer neither
    back = turned_away(340.0, 10.0, 30.0)  # face 12 from face 1, across 0°/360°
    assert back is not None and back.off_deg == pytest.approx(-30.0)
    assert turned_away(359.9, 0.1, 30.0) is None


def test_the_pitch_not_known_is_the_finest_a_guide_knows():
    assert repeat_limit_deg(0.0) == 0.5
    assert turned_away(40.6, 40.0, 0.0) is not None and turned_away(40.4, 40.0, 0.0) is None


def test_the_polygon_guide_gives_the_pitch_with_a_repeat():
    """The guide's pitch at reading 2 of a face (it was 0: the limit fell back to 0.5°, and
    the refusal spoke of "the 1° between faces" of a 12-face polygon)."""
    from models.polygon.acquisition import polygon_guide

    rows = [{"position": "1", "encoder_deg": "10", "ac_x_arcsec": "0.1", "set": "",
             "direction": ""}]
    again = polygon_guide(rows, {}, {"faces": 12, "readings_per_point": 2})
    assert again.text == "stay at face 1 — reading 2 of 2"
    assert again.pitch_deg == pytest.approx(30.0)
    assert polygon_guide(rows, {}, {"faces": 0, "readings_per_point": 2}).pitch_deg == 0.0
