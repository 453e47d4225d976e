"""What the workbenches say to do next while an instrument is read (guided acquisition):
the polygon's next face with the encoder reading it should roughly show, its closure and
the next set, the n readings of a point; the theodolite's θ. The rows are a bench turned
by hand: encoder readings 360°/N apart with the table's own small errors, either way
round, from any start."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.polygon.acquisition import polygon_guide
from models.registry import KINDS
from models.theodolite.acquisition import theodolite_guide


def _row(face, encoder, set_no="1"):
    return {"position": str(face), "encoder_deg": f"{encoder:.6f}", "polygon_dev_arcsec": "0",
            "ac_x_arcsec": "1.0", "ac_y_arcsec": "", "set": set_no, "direction": ""}


def _wrapped(a, b):
    return abs((a - b + 180.0) % 360.0 - 180.0)


@pytest.mark.slow
@settings(max_examples=150, deadline=None)
@given(faces=st.integers(3, 72), start=st.floats(0, 360, exclude_max=True),
       counts_up=st.booleans(), faces_up=st.booleans(), data=st.data())
def test_the_next_face_and_its_encoder_reading_from_any_start(faces, start, counts_up, faces_up,
                                                              data):
    read = data.draw(st.integers(2, faces - 1))
    first = data.draw(st.integers(1, faces))
    step = (360.0 / faces) * (1 if counts_up else -1)
    errors = data.draw(st.lists(st.floats(-20, 20), min_size=read, max_size=read))  # arcsec
    order = 1 if faces_up else -1
    rows = [_row((first - 1 + order * k) % faces + 1, (start + k * step + e / 3600) % 360)
            for k, e in enumerate(errors)]
    told = dict(faces=faces) if data.draw(st.booleans()) else dict(faces=0)
    step_out = polygon_guide(rows, {}, {**told, "readings_per_point": 1})
    face = (first - 1 + order * read) % faces + 1
    assert step_out.fill["position"] == str(face) and step_out.reading == step_out.of == 1
    expected = (start + read * step) % 360
    text = str(step_out.text)
    shown = float(text.split("≈ ")[1].split("°")[0])
    assert _wrapped(shown, expected) <= 0.05 + 20 / 3600
    assert text.startswith(f"go to face {face} (encoder ≈ ")
    # the nominal a take writes into a blank encoder cell: the set's first reading plus the
    # steps of 360°/N, exactly
    first_reading = float(rows[0]["encoder_deg"])
    assert _wrapped(step_out.nominal["encoder_deg"], first_reading + read * step) < 1e-9


def test_closure_then_the_next_set_then_the_readings_of_a_point():
    rows = [_row(f, 15.0 * f) for f in range(1, 25)]
    closure = polygon_guide(rows, {}, {"faces": 0, "readings_per_point": 1})
    assert closure.text == "go back to face 1 (encoder ≈ 15°): the closure of set 1"
    rows.append(_row(1, 15.0004))
    second = polygon_guide(rows, {}, {"faces": 0, "readings_per_point": 1})
    assert second.text == "set 2: go to face 1 (encoder ≈ 15°)"
    assert second.fill == {"position": "1", "set": "2"}
    rows.append(_row(1, 15.0, "2"))
    assert polygon_guide(rows, {}, {"faces": 0, "readings_per_point": 1}).text == \
        "go to face 2 (encoder ≈ 30°)"  # 24 faces: the first set's
    again = polygon_guide(rows, {}, {"faces": 0, "readings_per_point": 3})
    assert again.text == "stay at face 1 — reading 2 of 3" and again.reading == 2
    assert not again.new_point


def test_nothing_is_guessed_that_the_readings_cannot_say():
    # one face read, the face count not set: the face, no encoder figure
    assert polygon_guide([_row(1, 40.0)], {}, {"faces": 0, "readings_per_point": 1}).text == \
        "go to face 2"
    # the count set but not which way the encoder counts: still no figure …
    assert polygon_guide([_row(1, 40.0)], {}, {"faces": 8, "readings_per_point": 1,
                                               "counting": "auto"}).text == "go to face 2"
    # … until the setting says it
    assert polygon_guide([_row(1, 40.0)], {}, {"faces": 8, "readings_per_point": 1,
                                               "counting": "against"}).text == \
        "go to face 2 (encoder ≈ 355°)"
    assert polygon_guide([], {}, {"faces": 0, "readings_per_point": 2}).text == \
        "go to face 1 — reading 1 of 2"


@pytest.mark.parametrize("rows, current, n, step, text, fill", [
    ([], {"theta_deg": "12"}, 1, 0.0, "θ = 12°", {"theta_deg": "12"}),
    ([{"theta_deg": "-4", "azimuth_deg": "1"}], {"theta_deg": ""}, 2, 2.0,
     "θ = -4° — reading 2 of 2", {"theta_deg": "-4"}),
    ([{"theta_deg": "-4", "azimuth_deg": "1"}] * 2, {"theta_deg": ""}, 2, 2.0,
     "θ = -2° — reading 1 of 2", {"theta_deg": "-2"}),
    ([{"theta_deg": "10", "azimuth_deg": "1"}], {"theta_deg": "12°30'"}, 1, 0.0, "θ = 12°30'",
     {"theta_deg": "12°30'"}),
    ([{"theta_deg": "10", "azimuth_deg": "1"}], {"theta_deg": ""}, 1, 0.0,
     "turn the axis to the next θ and type it in the θ column", {}),
])
def test_theodolite_theta(rows, current, n, step, text, fill):
    said = theodolite_guide(rows, current, {"readings_per_point": n}, step)
    assert (said.text, said.fill) == (text, fill)


def test_the_guides_are_the_workbenches_own():
    from models.workbench import GuidesAcquisition

    assert KINDS["polygon"].acquisition_guide is polygon_guide
    assert KINDS["theodolite"].acquisition_guide is theodolite_guide
    assert not isinstance(KINDS["fringe"], GuidesAcquisition)
    assert {k for k, w in KINDS.items() if isinstance(w, GuidesAcquisition)} >= {"polygon",
                                                                                "theodolite"}


def test_the_polygon_nominal_encoder_is_said_only_where_the_guide_knows_it():
    rows = [_row(f, 15.0 * f + 0.0002) for f in range(1, 25)]
    closure = polygon_guide(rows, {}, {"faces": 0, "readings_per_point": 1})
    assert closure.nominal["encoder_deg"] == pytest.approx(15.0002, abs=1e-9)
    rows.append(_row(1, 15.0004))
    second = polygon_guide(rows, {}, {"faces": 0, "readings_per_point": 1})
    assert second.nominal["encoder_deg"] == pytest.approx(15.0002, abs=1e-9)  # set 1's start
    # one face read and no face count: no encoder figure is guessed, no nominal either
    assert polygon_guide([_row(1, 40.0)], {}, {"faces": 0, "readings_per_point": 1}).nominal == {}
    # the second reading of a point: it is taken where the table stands, no nominal
    rows.append(_row(1, 15.0, "2"))
    assert polygon_guide(rows, {}, {"faces": 0, "readings_per_point": 3}).nominal == {}


def _crosscal_row(mounting, face, encoder):
    return {"mounting": str(mounting), "position": str(face),
            "encoder_deg": "" if encoder is None else f"{encoder:.6f}", "ac_x_arcsec": "1.0",
            "ac_y_arcsec": ""}


@pytest.mark.parametrize("sense", [1, -1])
def test_the_crosscal_nominal_encoder_is_the_start_plus_the_steps(sense):
    """7 faces (a step of 51.428571…°), the encoder counting either way from 200.0003°:
    every mounting's face k at start + k·360°/7, its closure and the next mounting's first
    face at the start."""
    guide = KINDS["crosscal"].acquisition_guide
    start, n = 200.0003, 7
    rows = [_crosscal_row(0, k + 1, (start + sense * k * 360.0 / n) % 360) for k in range(3)]
    got = guide(rows, {}, {"faces": n})
    assert got.fill == {"mounting": "0", "position": "4"}
    assert _wrapped(got.nominal["encoder_deg"], start + sense * 3 * 360.0 / n) < 1e-6
    rows = [_crosscal_row(0, k % n + 1, (start + sense * k * 360.0 / n) % 360)
            for k in range(n + 1)]  # mounting 0 with its closure
    nxt = guide(rows, {}, {"faces": n})
    assert nxt.fill == {"mounting": "1", "position": "2"}
    assert _wrapped(nxt.nominal["encoder_deg"], start) < 1e-6
    rows += [_crosscal_row(1, (1 + k) % n + 1, (start + sense * k * 360.0 / n) % 360)
             for k in range(n)]
    closure = guide(rows, {}, {"faces": n})
    assert closure.fill == {"mounting": "1", "position": "2"}
    assert _wrapped(closure.nominal["encoder_deg"], start) < 1e-6
    # no encoder reading at the start, or no face count: nothing is guessed
    assert guide([_crosscal_row(0, 1, None)], {}, {"faces": n}).nominal == {}
    assert guide(rows[:2], {}, {"faces": 0}).nominal == {}


def test_a_reversed_mounting_is_guided_to_the_face_its_row_names_with_that_faces_encoder():
    """The polygon's rule (live76 F2) in the cross-calibration: 4 faces, mounting 0 read
    1→2→3→4 (encoder 10°, 100°, 190°, 280°), mounting 1 read the other way round from face
    2 at the start (2, 1, 4, 3). After its first face the guidance said "go to face 3
    (encoder ≈ 100°)" whatever the row named; the row's face is said, with the encoder at
    it (face 1 is 90° before face 2), and on, the mounting's own direction."""
    guide = KINDS["crosscal"].acquisition_guide
    settings_ = {"faces": 4}
    rows = [_crosscal_row(0, f, 10.0 + (f - 1) * 90.0) for f in (1, 2, 3, 4)]
    rows.append(_crosscal_row(1, 2, 10.0))
    got = guide(rows, {"mounting": "1", "position": "1"}, settings_)
    assert got.text == "mounting 1: go to face 1 (encoder ≈ 280°)"
    assert got.fill == {"mounting": "1", "position": "1"}
    assert got.nominal == {"encoder_deg": pytest.approx(280.0)}
    # no face named: the way this mounting goes round (2, 1, then 4 at 190°)
    got = guide(rows + [_crosscal_row(1, 1, 280.0)], {}, settings_)
    assert got.text == "mounting 1: go to face 4 (encoder ≈ 190°)"
    assert got.nominal == {"encoder_deg": pytest.approx(190.0)}
    # the plan's row after a mounting without closure is the next mounting's first face
    got = guide(rows[:4], {"mounting": "1", "position": "2"}, settings_)
    assert got.fill == {"mounting": "1", "position": "2"}
    assert got.text.startswith("turn the polygon on the shaft by one face: mounting 1, face 2")
    assert got.nominal == {"encoder_deg": pytest.approx(10.0)}


def test_a_first_mounting_read_the_other_way_round_counts_the_encoder_its_way():
    """6 faces, mounting 0 read 1, 6 (encoder 10°, 310°): face 5 is next, at 250°; the
    encoder's sense taken from the faces' order, not assumed forward."""
    guide = KINDS["crosscal"].acquisition_guide
    rows = [_crosscal_row(0, 1, 10.0), _crosscal_row(0, 6, 310.0)]
    got = guide(rows, {}, {"faces": 6})
    assert got.text == "mounting 0: go to face 5 (encoder ≈ 250°)"
    assert got.fill == {"mounting": "0", "position": "5"}
    # and face 2, named by its row, 60° on from face 1
    got = guide(rows, {"mounting": "0", "position": "2"}, {"faces": 6})
    assert got.nominal == {"encoder_deg": pytest.approx(70.0)}


def test_a_reversed_set_is_guided_to_the_face_its_row_names_with_that_faces_encoder():
    """live76 F2: 4 faces, set 1 read 1→2→3→4→1 (encoder 10°, 100°, 190°, 280°), set 2 goes
    the other way round (the plan pre-fills its next row with face 4). After set 2's first
    face the guidance said "go to face 2 (encoder ≈ 100°)" from set 1's direction, and the
    off-plan check expected 100°. The row's face is what is said, with the encoder at it."""
    rows = [_row(f, 10.0 + (f - 1) * 90.0) for f in (1, 2, 3, 4, 1)] + [_row(1, 10.0, "2")]
    settings_ = {"faces": 4, "readings_per_point": 1}
    guided = polygon_guide(rows, {"position": "4", "set": "2"}, settings_)
    assert guided.text == "go to face 4 (encoder ≈ 280°)"
    assert guided.fill == {"position": "4", "set": "2"}
    assert guided.nominal == {"encoder_deg": pytest.approx(280.0)}
    # and on round the other way: face 3 after 1, 4 (set 2's own direction now)
    guided = polygon_guide(rows + [_row(4, 280.0, "2")], {"position": "3", "set": "2"}, settings_)
    assert guided.text == "go to face 3 (encoder ≈ 190°)"
    assert guided.nominal == {"encoder_deg": pytest.approx(190.0)}
    # a row with no face yet: the direction of the readings, as before
    assert polygon_guide(rows[:2], {}, settings_).text == "go to face 3 (encoder ≈ 190°)"


def test_the_second_face_is_expected_either_way_round_from_the_first():
    """live76 run3: after one face the guide cannot say which way the encoder counts, so it
    gave no figure and a take at face 7 went into face 2's row unchecked. The readings it
    would take there are the first ± 360°/N (the off-plan check warns of any other)."""
    guided = polygon_guide([_row(1, 10.0)], {}, {"faces": 12, "readings_per_point": 1})
    assert guided.text == "go to face 2" and guided.nominal == {}
    assert guided.near == {"encoder_deg": (pytest.approx(40.0), pytest.approx(340.0))}
    assert guided.pitch_deg == pytest.approx(30.0)
    # known the way round: the one figure, nothing "either way"
    guided = polygon_guide([_row(1, 10.0), _row(2, 40.0)], {}, {"faces": 12})
    assert guided.nominal == {"encoder_deg": pytest.approx(70.0)} and guided.near == {}
