"""plan80: a polygon entry plan of sets with two readings per face: each take went to the
plan's next row, one row per face, so face 1's second take was filed in face 2's planned row
and every later take one face early. The plan now has a row per reading: the takes land on
their faces, the guidance and the table's caption name the reading of the face.

Through the real window and the protocol simulators on pseudo-terminals (the autocollimator,
and the table's encoder on a position readout)."""

from __future__ import annotations

import pytest

from tests.app.capture.test_auto_take_polygon_faces import FAST
from tests.app.capture.window_steps import captured_rows, polygon_bench
from tests.instrument_simulators import AutocollimatorSimulator, ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and two instruments for seconds

#: faces 1 … 3 of a 12-face polygon: the encoder (°) and the autocollimator's x (″)
FACES = [(10.0, 0.10), (40.0, 0.25), (70.0, 0.05)]


@pytest.fixture
def bench(window):
    yield from polygon_bench(window, faces=12, plan_sets=1, readings_per_point=2)


def _rows(bench) -> list[tuple]:
    """(face, set, encoder, AC x) of the rows with an AC x."""
    return captured_rows(bench, ("position", "set", "encoder_deg", "ac_x_arcsec"))


def test_two_takes_a_face_fill_the_faces_rows_in_the_plan(bench, window, qtbot):
    panel = window.capture_panel
    guides, captions, notes = [], [], []
    with AutocollimatorSimulator("pty", positions=[(FACES[0][1], -3.2)]) as ac, \
            ReadoutSimulator("pty", positions=[(FACES[0][0],)]) as ro:
        panel.connect_to("autocollimator", ac.port, **FAST)
        panel.connect_to("readout", ro.port, slot=1, **FAST)
        readout = panel.links[1]
        readout.column.setCurrentIndex(readout.column.findData("encoder_deg"))
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=5000)
        for encoder, x in FACES:
            ac.positions[0] = (x, -3.2)
            ro.positions[0] = (encoder,)
            for _ in (1, 2):
                qtbot.waitUntil(lambda: not panel.used_again(), timeout=3000)
                qtbot.waitUntil(lambda e=encoder, x=x: all(
                    link.latest is not None and abs(float(link.latest.values[0]) - v) < 1e-3
                    for link, v in zip(panel.links, (x, e), strict=False)), timeout=3000)
                panel.update_guide()
                guides.append(panel.guide.text())
                captions.append(bench._next_text())
                taken = len(_rows(bench))
                panel.take_button.click()
                # filed, or refused with a word in the panel's note
                qtbot.waitUntil(lambda t=taken: len(_rows(bench)) == t + 1
                                or panel.take_note.text() != "", timeout=3000)
                notes.append(panel.take_note.text())
        panel.disconnect_instrument()
    rows = _rows(bench)
    assert [(face, set_no) for face, set_no, _, _ in rows] == [
        ("1", "1"), ("1", "1"), ("2", "1"), ("2", "1"), ("3", "1"), ("3", "1")], (rows, notes)
    assert [float(e) for _, _, e, _ in rows] == pytest.approx(
        [FACES[k // 2][0] for k in range(6)], abs=1e-4)
    assert [float(x) for _, _, _, x in rows] == pytest.approx(
        [FACES[k // 2][1] for k in range(6)], abs=0.02)
    assert captions[1] == "next: set 1: face 1 of 12, reading 2 of 2 (1/26)"
    assert captions[2] == "next: set 1: face 2 of 12, reading 1 of 2 (2/26)"
    assert guides[1] == "Next: stay at face 1 — reading 2 of 2"
    assert guides[5] == "Next: stay at face 3 — reading 2 of 2"
    assert bench._next_text() == "next: set 1: face 4 of 12, reading 1 of 2 (6/26)"
    assert notes == [""] * 6  # no take refused or said to be at another face
