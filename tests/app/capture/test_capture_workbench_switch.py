"""#60 review: the workbench tab changed while connected. The raw session stayed with the
workbench it was opened on while the takes went to the sheet in front: the polygon's raw
record held the cross-calibration's takes (its certificate then said "reading of row 1
edited after capture"), and the cross-calibration had no raw session. Now each workbench
gets a session of its own from the change on, its takes indexing its own frames."""

from __future__ import annotations

import pytest

from app.capture.instruments import frame_values
from app.certificate_issue import readings_edited_after_capture
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import AutocollimatorSimulator

pytestmark = pytest.mark.slow  # a window and an instrument for seconds

FAST = {"silence_s": 0.3, "retries": 4, "retry_pause_s": 0.05}


def _start(presenter):
    model = presenter.table_model
    model.replace_all([], "empty")
    keys = [c.key for c in model.sheet.columns]
    presenter.view.table.setCurrentIndex(model.index(0, keys.index("ac_x_arcsec")))
    return model, keys


def test_each_workbench_keeps_the_raw_frames_of_its_own_takes(window, qtbot):
    panel = window.capture_panel
    polygon = _show(window, "polygon")
    _start(polygon)
    crosscal = _show(window, "crosscal")
    _start(crosscal)

    def take(expected: str) -> None:
        qtbot.waitUntil(lambda: panel.take_button.isEnabled() and not panel.used_again(),
                        timeout=5000)
        assert panel.take_reading() == expected

    with AutocollimatorSimulator("pty", positions=[(3.25, -1.5), (7.0, -1.5), (5.5, 0.25)],
                                 hold_s=0.6) as sim:
        _show(window, "polygon")
        panel.connect_to("autocollimator", sim.port, **FAST)
        take("row 1")
        qtbot.waitUntil(lambda: panel.latest.values[0] > 5, timeout=5000)
        _show(window, "crosscal")
        take("row 1")
        take("row 2")
        qtbot.waitUntil(lambda: panel.latest.values[1] > 0, timeout=5000)
        _show(window, "polygon")  # and back: a third session, the polygon's second
        take("row 2")
        panel.disconnect_instrument()
    rows = {"polygon": [0, 1], "crosscal": [0, 1]}
    sessions = {key: panel.raw_sessions(key) for key in rows}
    assert [len(s) for s in sessions.values()] == [2, 1]
    assert [t[0] for s in sessions["polygon"] for t in s["takes"]] == rows["polygon"]
    assert [t[0] for s in sessions["crosscal"] for t in s["takes"]] == rows["crosscal"]
    # two sessions of one connection: told apart by their start
    assert len({s["started_utc"] for s in sessions["polygon"]}) == 2
    for key, presenter in (("polygon", polygon), ("crosscal", crosscal)):
        model = presenter.table_model
        x = [c.key for c in model.sheet.columns].index("ac_x_arcsec")
        for session in sessions[key]:
            times = [f[0] for f in session["frames"]]
            assert times == sorted(times) and times[0] >= 0
            for row, first, last in session["takes"]:
                # a take's frame is in its own session's frames, and reads as its cell
                assert first == last and session["frames"][first][2] == 1
                got = frame_values("autocollimator", session["frames"][first][1].encode("latin-1"))
                assert float(model.sheet.text(row, x)) == pytest.approx(got[0], abs=0.005)
        assert readings_edited_after_capture(presenter.kind, presenter.settings,
                                             presenter.state().rows, sessions[key], {}) == []


def test_a_new_project_while_connected_keeps_none_of_the_last_ones_frames(window, qtbot):
    """File › New while the instrument stays connected: the last job's session (its frames
    and its take into row 1) went on into the new project, whose certificate then said
    "reading of row 1 edited after capture: 3.25 → 7.00"."""
    panel = window.capture_panel
    polygon = _show(window, "polygon")
    model, keys = _start(polygon)
    with AutocollimatorSimulator("pty", positions=[(3.25, -1.5)]) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled() and not panel.used_again(),
                        timeout=5000)
        assert panel.take_reading() == "row 1"
        window.projects.new_project()
        assert panel.raw_sessions("polygon") == [] or all(
            not s["takes"] for s in panel.raw_sessions("polygon"))
        polygon = _show(window, "polygon")
        model, keys = _start(polygon)
        model.set_cells([(0, keys.index("ac_x_arcsec"), "7.00")], "typed")  # the new job's
        qtbot.waitUntil(lambda: panel.take_button.isEnabled() and not panel.used_again(),
                        timeout=5000)
        assert panel.take_reading() == "row 2"
        panel.disconnect_instrument()
    sessions = panel.raw_sessions("polygon")
    assert [t[0] for s in sessions for t in s["takes"]] == [1]
    assert readings_edited_after_capture(polygon.kind, polygon.settings, polygon.state().rows,
                                         sessions, {}) == []


def test_a_glance_at_another_tab_files_no_session_there(window, qtbot):
    """Connected on the polygon, the cross-calibration's tab looked at and left, nothing
    taken there: it has no raw session (it had one of frames behind none of its readings)."""
    panel = window.capture_panel
    polygon = _show(window, "polygon")
    _start(polygon)
    with AutocollimatorSimulator("pty", positions=[(3.25, -1.5)]) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled() and not panel.used_again(),
                        timeout=5000)
        _show(window, "crosscal")
        qtbot.wait(100)
        _show(window, "polygon")
        qtbot.waitUntil(lambda: panel.take_button.isEnabled() and not panel.used_again(),
                        timeout=5000)
        assert panel.take_reading() == "row 1"
        panel.disconnect_instrument()
    assert panel.raw_sessions("crosscal") == []
    (session,) = panel.raw_sessions("polygon")
    assert [t[0] for t in session["takes"]] == [0]
    assert readings_edited_after_capture(polygon.kind, polygon.settings, polygon.state().rows,
                                         [session], {}) == []
