"""live76: a polygon read with auto-take as a technician does it — the autocollimator nulled
at each face (its readings within the window of one another), the mirror out of its view
while the table turns (the instrument sends frames beyond its range), the table's encoder
read by a second instrument.

* F1: auto-take followed the autocollimator alone and waited for its reading to leave the
  window: 1 take of 4 faces, later takes in the wrong face's row. The move to the next face
  is seen on the encoder (half the pitch, 360°/N), and with the autocollimator alone the
  mirror leaving the view and coming back is one.
* F3: out of view was a link fault: reconnected every second, given up after ~15 s with
  auto-take switched off, "ac_x_arcsec" in the words. Frames that arrive out of range are
  "no mirror in view"; only silence is a fault.
* F8: F9 with one instrument whose link is lost did nothing (the button disabled).

Through the real window and the protocol simulators on pseudo-terminals, the instruments'
positions set as the table would put them."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest

from tests.app.capture.window_steps import captured_rows, polygon_bench
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import AutocollimatorSimulator, ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and instruments for seconds

#: a link given up after 1 s of silence and one retry: out of view for 3 s outlived it (0.5 s
#: of silence was outlived on a loaded machine by the simulator, a thread of the test's
#: process, starved: "no answer … (reconnecting)" where the instrument never fell silent)
FAST = {"silence_s": 1.0, "retries": 1, "retry_pause_s": 0.05}
#: where the mirror is out of view: beyond the autocollimator's ±3600″
OUT_OF_VIEW = (9999.0, -3.2)
#: 4 faces of a 12-face polygon: the encoder (°) and the autocollimator nulled (x ″)
FACES = [(10.0, 0.10), (40.0, 0.25), (70.0, 0.05), (100.0, 0.30)]


@pytest.fixture
def bench(window):
    yield from polygon_bench(window, faces=12, plan_sets=1)


def _rows(bench) -> list[tuple]:
    """(face, encoder, AC x) of the rows with an AC x."""
    return captured_rows(bench)


def _auto(panel) -> None:
    panel.window_box.setValue(0.5)
    panel.dwell_box.setValue(0.2)
    panel.auto.setChecked(True)


def _first_take(panel, bench, qtbot, ac, ro=None) -> None:
    """The autocollimator connected (and the encoder's readout ``ro`` into the encoder
    column), auto-take on, and the first face taken."""
    panel.connect_to("autocollimator", ac.port, **FAST)
    if ro is not None:
        # the readout answers throughout (only the autocollimator's mirror leaves the view):
        # given 2 s of silence, as a loaded machine can starve its simulator past 0.5 s (a
        # fresh-clone run: "readout … (link lost) (reconnecting)" during a turn, 2026-12-07)
        panel.connect_to("readout", ro.port, slot=1, **{**FAST, "silence_s": 2.0})
        readout = panel.links[1]
        readout.column.setCurrentIndex(readout.column.findData("encoder_deg"))
    qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=5000)
    _auto(panel)
    qtbot.waitUntil(lambda: len(_rows(bench)) == 1, timeout=5000)


def _turn(qtbot, ac, ro, encoder_from, encoder_to, x, out_s=0.8) -> None:
    """The table turned from one face to the next: the mirror out of view for ``out_s``,
    then the autocollimator nulled at ``x`` and the encoder at ``encoder_to``."""
    ac.positions[0] = OUT_OF_VIEW
    if ro is not None:
        ro.positions[0] = ((encoder_from + encoder_to) / 2,)
    qtbot.wait(int(out_s * 1000))
    if ro is not None:
        ro.positions[0] = (encoder_to,)
    ac.positions[0] = (x, -3.2)


def test_auto_take_takes_every_face_of_a_nulled_autocollimator_with_the_encoder(bench, window,
                                                                                qtbot):
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(FACES[0][1], -3.2)], rate_hz=50.0) as ac, \
            ReadoutSimulator("pty", positions=[(FACES[0][0],)]) as ro:
        _first_take(panel, bench, qtbot, ac, ro)
        statuses: list[str] = []
        for i in range(1, len(FACES)):
            # the second turn is slow (3 s out of view: three times the link's silence)
            out_s = 3.0 if i == 2 else 0.8
            ac.positions[0] = OUT_OF_VIEW
            ro.positions[0] = ((FACES[i - 1][0] + FACES[i][0]) / 2,)
            qtbot.wait(int(out_s * 1000))
            statuses.append(panel.status.text())
            statuses.append(panel.value.text())
            assert panel.auto.isChecked(), panel.take_note.text()
            ro.positions[0] = (FACES[i][0],)
            ac.positions[0] = (FACES[i][1], -3.2)
            qtbot.waitUntil(lambda i=i: len(_rows(bench)) == i + 1, timeout=5000)
        rows = _rows(bench)
        assert "reconnect" not in " ".join(statuses) and panel.auto.isChecked()
        panel.disconnect_instrument()
    assert [(f, float(e), float(x)) for f, e, x in rows] == [
        (str(i + 1), pytest.approx(enc, abs=1e-4), pytest.approx(x, abs=0.02))
        for i, (enc, x) in enumerate(FACES)]


def test_a_slow_readout_is_read_again_after_the_null_before_the_take(bench, window, qtbot):
    """The encoder's readout answers every 0.6 s (a slow one, or one starved on a loaded
    machine): the autocollimator is steady for the 0.2 s dwell before the readout has
    answered since the table stopped. The take waits for that answer; taking at once paired
    the face's null with the encoder read half-way through the turn (a fresh-clone run:
    face 4 at 85°, the turn's middle, for 100°)."""
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(FACES[0][1], -3.2)], rate_hz=50.0) as ac, \
            ReadoutSimulator("pty", positions=[(FACES[0][0],)], reply_delay_s=0.6) as ro:
        _first_take(panel, bench, qtbot, ac, ro)
        for i in range(1, len(FACES)):
            _turn(qtbot, ac, ro, FACES[i - 1][0], FACES[i][0], FACES[i][1], out_s=1.3)
            qtbot.waitUntil(lambda i=i: len(_rows(bench)) == i + 1, timeout=8000)
        rows = _rows(bench)
        panel.disconnect_instrument()
    assert [(f, float(e), float(x)) for f, e, x in rows] == [
        (str(i + 1), pytest.approx(enc, abs=1e-4), pytest.approx(x, abs=0.02))
        for i, (enc, x) in enumerate(FACES)]


def test_auto_take_with_the_autocollimator_alone_sees_the_mirror_leave_the_view(bench, window,
                                                                              qtbot):
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(FACES[0][1], -3.2)], rate_hz=50.0) as ac:
        panel.connect_to("autocollimator", ac.port, **FAST)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=5000)
        _auto(panel)
        qtbot.waitUntil(lambda: len(_rows(bench)) == 1, timeout=5000)
        for i in range(1, len(FACES)):
            _turn(qtbot, ac, None, 0.0, 0.0, FACES[i][1])
            qtbot.waitUntil(lambda i=i: len(_rows(bench)) == i + 1, timeout=5000)
        # at the last face, nothing more is taken while the mirror stays in view
        qtbot.wait(800)
        rows = _rows(bench)
        panel.disconnect_instrument()
    assert [(f, float(x)) for f, _, x in rows] == [
        (str(i + 1), pytest.approx(x, abs=0.02)) for i, (_, x) in enumerate(FACES)]


def test_the_mirror_out_of_view_is_said_and_never_a_link_fault(bench, window, qtbot):
    """F3: 3 s of frames beyond the range (three times the link's silence, which with one
    retry gave the link up and switched auto-take off): said as no mirror in view, under the
    column's name; no reconnection; the readings and auto-take go on when it is back."""
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(0.10, -3.2)], rate_hz=50.0) as ac:
        panel.connect_to("autocollimator", ac.port, **FAST)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=5000)
        _auto(panel)
        qtbot.waitUntil(lambda: len(_rows(bench)) == 1, timeout=5000)
        ac.positions[0] = OUT_OF_VIEW
        qtbot.wait(3000)
        status, value, state = panel.status.text(), panel.value.text(), panel.auto_state.text()
        worker = panel.worker
        assert status == (f'No mirror in view: frames arrive from {ac.port}, but AC x 9999" is '
                          f'beyond the range -3600 … 3600". Not a fault of the link: the '
                          f'readings come back with the target')
        assert value == 'x 0.10"\ny -3.20" (no mirror in view)'  # x and y on two lines (day76 F11)
        assert state.startswith("Auto-take: waiting for Autocollimator (ELCOMAT kind) on ") \
            and state.endswith("(no mirror in view)")
        assert not panel.take_button.isEnabled()
        assert worker is not None and panel.auto.isChecked() and panel.take_note.text() == ""
        ac.positions[0] = (0.20, -3.2)
        qtbot.waitUntil(lambda: len(_rows(bench)) == 2, timeout=5000)
        assert panel.status.text() == f"Connected: {ac.port}"
        assert panel.links[0].last_fault == "" and panel.worker is worker
        panel.disconnect_instrument()


def test_with_the_encoder_the_move_is_the_encoders_not_the_autocollimators(bench, window,
                                                                           qtbot):
    """The encoder turned 30° with the mirror in view all the way (nulled the same): taken.
    At one face, the autocollimator re-nulled by 2″ (beyond the 0.5″ window) and the table
    nudged 0.01°: no second take at that face, into the next face's row."""
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(0.10, -3.2)], rate_hz=50.0) as ac, \
            ReadoutSimulator("pty", positions=[(10.0,)]) as ro:
        _first_take(panel, bench, qtbot, ac, ro)
        ac.positions[0], ro.positions[0] = (2.10, -3.2), (10.01,)  # re-nulled, nudged
        qtbot.wait(1000)
        assert len(_rows(bench)) == 1, _rows(bench)
        assert panel.auto_state.text() == ("Auto-take: taken; turn the table to the next face "
                                           "(encoder a ≥ 15° from the take)")
        ac.positions[0], ro.positions[0] = (2.15, -3.2), (40.0,)  # the next face, in view
        qtbot.waitUntil(lambda: len(_rows(bench)) == 2, timeout=5000)
        rows = _rows(bench)
        panel.disconnect_instrument()
    assert rows[1][0] == "2" and float(rows[1][1]) == pytest.approx(40.0, abs=1e-4)


def test_f9_with_the_only_instrument_lost_says_why(window, qtbot):
    """F8: the take button is disabled while the link is lost; F9 (a foot switch) then
    said nothing. It says why beside the guidance, and a take is still never made."""
    presenter = _show(window, "polygon")
    rows_before = presenter.table_model.sheet.row_count
    panel = window.capture_panel
    window.show()
    panel.show()
    qtbot.waitExposed(window)
    window.activateWindow()
    qtbot.waitUntil(window.isActiveWindow, timeout=3000)
    with AutocollimatorSimulator("pty", positions=[(3.0, 1.0)]) as sim:
        panel.connect_to("autocollimator", sim.port, silence_s=30.0, retries=1)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        sim.faults.add("silence")
        qtbot.waitUntil(lambda: "link lost" in panel.value.text(), timeout=3000)
        assert not panel.take_button.isEnabled()
        QTest.keyClick(window, Qt.Key.Key_F9)
        assert panel.take_note.text() == (f"Not taken: no reading from Autocollimator (ELCOMAT "
                                          f"kind) on {sim.port} (link lost)")
        assert presenter.table_model.sheet.row_count == rows_before
        sim.faults.discard("silence")
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        QTest.keyClick(window, Qt.Key.Key_F9)  # back: F9 takes (once, by the button)
        qtbot.waitUntil(lambda: presenter.table_model.sheet.row_count == rows_before + 1,
                        timeout=3000)
        qtbot.wait(300)
        assert presenter.table_model.sheet.row_count == rows_before + 1
        panel.disconnect_instrument()


def test_a_take_at_another_face_than_its_rows_is_said_and_marked(bench, window, qtbot):
    """live76 run3: row 2 "face 2" got face 7's reading (190°) with no word: the guide could
    not say the encoder at face 2 (the way it counts not known after one face), so nothing
    was checked. Either way round from face 1 is 40° or 340°; 190° is neither: said beside
    the guidance, and the encoder's cell marked in the table with the same words."""
    from tests.app.capture.test_capture_marks import _connect, _take_at

    panel = window.capture_panel
    model = bench.table_model
    keys = [c.key for c in model.sheet.columns]
    encoder = keys.index("encoder_deg")
    with AutocollimatorSimulator("pty", positions=[(0.5, 0.25)]) as ac, \
            ReadoutSimulator("pty", positions=[(10.0,)]) as ro:
        _connect(panel, ac, ro)
        assert _take_at(qtbot, panel, ac, ro, 10.0, 0.5, 0.25) == "row 1"
        assert panel.take_note.text() == ""
        assert _take_at(qtbot, panel, ac, ro, 190.0, 0.75, 0.5) == "row 2"
        note = panel.take_note.text()
        panel.disconnect_instrument()
    assert model.sheet.text(1, keys.index("position")) == "2"
    assert note == ("Row 2: encoder a [deg] 190.0000° is +150.0° from the ≈ 40° the plan "
                    "expects at face 2 (more than half the 30° between faces): check the "
                    "table's position. The reading is kept; undo the take if it is wrong")
    assert model.take_warning(1, encoder) == note and model.take_warning(0, encoder) is None
    from widgets.readings_table_model import WARNED_BRUSH

    index = model.index(1, encoder)
    assert model.data(index, Qt.ItemDataRole.BackgroundRole) == WARNED_BRUSH
    assert model.data(index, Qt.ItemDataRole.ToolTipRole) == note
    bench.undo_stack.undo()  # the take undone: its mark goes with it
    assert model.take_warning(1, encoder) is None


@pytest.mark.parametrize("with_encoder", [True, False])
def test_the_next_set_starting_at_the_closure_face_is_read_there_without_a_move(
        window, qtbot, with_encoder):
    """Set 2 starts at face 1, where set 1's closure was just read (the guide: "set 2: go to
    face 1 (encoder ≈ 10°)"): the table does not move, and waiting for a move skipped it —
    set 2's face 4 then went into its face 1 row (the live76 repro, with the encoder rule).
    The plan's next point being where the table is, it is read after a fresh dwell."""
    bench = _show(window, "polygon")
    bench.table_model.replace_all([], "empty")
    bench.set_settings({**bench.settings, "faces": 4, "plan_sets": 2})
    panel = window.capture_panel
    # face, encoder, AC x nulled; set 1 round and closed, then set 2 the other way
    plan = [(1, 10.0, 0.10), (2, 100.0, 0.25), (3, 190.0, 0.05), (4, 280.0, 0.30),
            (1, 10.0, 0.20), (1, 10.0, 0.15), (4, 280.0, 0.35)]
    with AutocollimatorSimulator("pty", positions=[(0.10, -3.2)], rate_hz=50.0) as ac, \
            ReadoutSimulator("pty", positions=[(10.0,)]) as ro:
        _first_take(panel, bench, qtbot, ac, ro if with_encoder else None)
        for i in range(1, len(plan)):
            if plan[i][1] != plan[i - 1][1]:  # the table turns: the mirror out of view
                _turn(qtbot, ac, ro, plan[i - 1][1], plan[i][1], plan[i][2])
            else:  # set 2 at set 1's closure face: re-nulled at most, the table still
                ac.positions[0] = (plan[i][2], -3.2)
            qtbot.waitUntil(lambda i=i: len(_rows(bench)) == i + 1, timeout=5000)
        qtbot.wait(800)  # and nothing more while the table stays at face 4
        rows = _rows(bench)
        sheet = bench.table_model.sheet
        sets = [sheet.text(r, [c.key for c in sheet.columns].index("set"))
                for r in range(len(rows))]
        panel.disconnect_instrument()
    assert [int(f) for f, _, _ in rows] == [face for face, _, _ in plan]
    assert sets == ["1"] * 5 + ["2"] * 2
    # set 2's face 1, re-nulled 0.20″ → 0.15″ with the table still: a change within the 0.5″
    # spread auto-take allows over its dwell (_auto) is no move, so a dwell under way when it
    # came holds frames of both and its mean lies between them (0.17″ in 2 of 5 runs on
    # 2026-12-07); every other face as nulled
    expected = [pytest.approx(x, abs=0.02) for _, _, x in plan]
    expected[5] = pytest.approx(0.175, abs=0.025 + 0.02)
    assert [float(x) for _, _, x in rows] == expected
    if with_encoder:
        assert [float(e) for _, e, _ in rows] == [pytest.approx(e, abs=1e-4)
                                                  for _, e, _ in plan]
