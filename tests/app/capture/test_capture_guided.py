"""The instrument panel's auto-take, n readings per point and guidance, through the
protocol simulators on a pseudo-terminal (the real serial code path): what the table
receives is traced back frame by frame to what the simulated instrument sent, and the
n readings of a point give the budget's Type A input.

The simulator's ``sent`` list is the instrument's own record (nothing from the code under
test): with no line noise, raw frame i is sent frame i.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from PySide6.QtCore import Qt, QTimer

from models.certificate.metadata import CertificateMetadata
from models.readings.angles import parse_angle_deg
from models.readings.sheet import ReadingsSheet
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import AutocollimatorSimulator, TheodoliteSimulator

pytestmark = pytest.mark.slow  # every test here takes more than 0.4 s (a window, a certificate, a program)

FAST = {"silence_s": 0.2, "retries": 1, "retry_pause_s": 0.05}
META = CertificateMetadata.from_dict({"standards": [
    {"description": "Reference AC", "uncertainty_arcsec": 0.4}]})
TYPE_A = "Repeated readings (s/√n)"
#: an 8-face polygon read once round and closed: AC x at each face (arcsec)
AC_X = [3.0, -2.0, 5.0, 1.0, -4.0, 2.5, 0.5, -1.5, 3.0]


def _auto_take_on_an_empty_polygon(window, dwell_s: float):
    """The polygon's sheet emptied, its first AC x cell current, auto-take on (window 0.3",
    the dwell given): its model, column keys and the panel."""
    presenter = _show(window, "polygon")
    model = presenter.table_model
    model.replace_all([], "empty")
    keys = [c.key for c in model.sheet.columns]
    presenter.view.table.setCurrentIndex(model.index(0, keys.index("ac_x_arcsec")))
    panel = window.capture_panel
    panel.auto.setChecked(True)
    panel.window_box.setValue(0.3)
    panel.dwell_box.setValue(dwell_s)
    return model, keys, panel


def _phases(panel, seen: set) -> QTimer:
    probe = QTimer()
    probe.setInterval(5)
    probe.timeout.connect(lambda: seen.add(panel.auto_phase))
    probe.start()
    return probe


def _polygon_rows(n: int) -> list[list[str]]:
    """The faces and encoder readings typed beforehand, AC cells left for the instrument."""
    return [[str(i % 8 + 1), f"{45 * (i % 8)}", "0", "", "", "", ""]
            for i in range(len(AC_X)) for _ in range(n)]


def test_auto_take_two_readings_per_face_traced_to_the_frames_and_in_the_budget(window, qtbot):
    n = 2
    presenter = _show(window, "polygon")
    # one set: the σ of a reading stated (one set cannot evaluate it: 0.8.17); the n readings'
    # own s/√n is still the Type A input checked below
    presenter.set_settings({**presenter.settings, "readings_per_point": n, "faces": 8,
                            "reading_noise_arcsec": 0.04})
    model = presenter.table_model
    model.replace_all(_polygon_rows(n), "faces typed")
    keys = [c.key for c in model.sheet.columns]
    presenter.view.table.setCurrentIndex(model.index(0, keys.index("ac_x_arcsec")))
    panel = window.capture_panel
    # the resolution "as sent": the cells hold the mean to every digit (the default 0.01"
    # rounding is tested in test_capture_panel.py)
    window.qsettings.setValue("capture/resolution/autocollimator", 0.0)
    panel.auto.setChecked(True)
    panel.window_box.setValue(0.3)
    panel.dwell_box.setValue(0.1)
    seen: set[str] = set()
    # each face held until its n readings are taken, then the next: a face held a fixed 2 s
    # by the simulator's clock can pass with one take when a loaded machine starves this
    # process across it, and the 18 takes never come (flake79: the 60 s wait timed out in 3
    # of 3 runs of tests/app/capture on one core beside two CPU burners, in two orders;
    # never alone; at 0.6 s and 1.2 s holds in runs under load on 2026-12-05 and -07)
    with AutocollimatorSimulator("pty", positions=[(AC_X[0], 0.0)], sigma=0.04) as sim:
        probe = _phases(panel, seen)
        # the simulator answers throughout: given 2 s of silence, as a loaded machine can
        # starve its thread (in this process) past 0.2 s ("no answer for 0.2 s
        # (reconnecting)" in 1 of 3 runs there), and one retry gave the link up
        panel.connect_to("autocollimator", sim.port, **{**FAST, "silence_s": 2.0})
        for face, x in enumerate(AC_X):
            sim.positions[0] = (x, 0.0)
            qtbot.waitUntil(lambda face=face: len(panel.taken) >= n * (face + 1),
                            timeout=60000)
        qtbot.wait(300)  # the last face is held: no reading more is taken there
        probe.stop()
        panel.disconnect_instrument()
    assert len(panel.taken) == n * len(AC_X) and {"settling", "taken"} <= seen
    session = panel.raw_sessions("polygon")[-1]
    assert [t[0] for t in session["takes"]] == list(range(n * len(AC_X)))
    sent = np.array([(round(x, 3), round(y, 3)) for x, y in sim.sent])
    means = []
    previous_last, previous_at = -1, -1
    for row, first, last in session["takes"]:
        assert first > previous_last  # each reading from frames of its own
        previous_last = last
        stored = np.array([[float(v) for v in f[1].split()[2:]] for f in
                           session["frames"][first:last + 1]])
        # as the instrument said: a run of frames it sent, in order, later than the last
        # take's (found, not assumed at the session's index: the simulator may send frames
        # before the link reads its first, or while a link is retried under load)
        at = [k for k in range(previous_at + 1, len(sent) - len(stored) + 1)
              if np.array_equal(sent[k:k + len(stored)], stored)]
        # (it failed 2 of 3 whole-suite fresh runs at row 14 on 2026-12-05, never alone: say
        # what was stored and what was sent about there, so that a failing run shows why)
        assert at, (f"take of row {row}: its frames are not a run of the frames sent; stored "
                    f"{stored.tolist()} (frames {first}…{last} of {len(session['frames'])}), "
                    f"sent after the last take's run {sent[previous_at + 1:previous_at + 13].tolist()}"
                    f" ({len(sent)} sent)")
        previous_at = at[0]
        mean = stored.mean(axis=0)
        means.append(mean)
        cell = float(model.sheet.text(row, keys.index("ac_x_arcsec")))
        assert cell == pytest.approx(mean[0], abs=1e-9)
        truth = AC_X[row // n]
        assert abs(cell - truth) < 0.1  # 25 frames of σ = 0.04"
    # the workbench averages the n readings of each face; their s/√n is the Type A input
    kind = presenter.kind
    result = kind.analyze(ReadingsSheet(kind.columns, presenter.state().rows).parse(),
                          presenter.settings)
    component = next(c for c in kind.certificate_document(result, META).budget.components
                     if c.name == TYPE_A)
    x = np.array(means)[:, 0].reshape(len(AC_X), n)
    expected = x.std(axis=1, ddof=1) / math.sqrt(n)
    np.testing.assert_allclose(component.value, expected[:8], atol=1e-7)
    assert component.dof == n - 1 and component.evaluation == "A"
    # the guidance for a face's first reading, the encoder at 45° a face from face 1's
    presenter.view.table.setCurrentIndex(model.index(12, 0))
    panel.update_guide()
    assert panel.guide.text() == "Next: go to face 7 (encoder ≈ 270°) — reading 1 of 2"
    presenter.view.table.setCurrentIndex(model.index(13, 0))
    panel.update_guide()
    assert panel.guide.text() == "Next: stay at face 7 — reading 2 of 2"


def test_guided_polygon_fills_the_face_and_says_the_next_one(window, qtbot):
    presenter = _show(window, "polygon")
    model = presenter.table_model
    rows = [[str(f), f"{15 * f + 90}", "0", "", "", "1", "+"] for f in range(1, 7)]
    model.replace_all(rows + [["", "", "", "", "", "", ""]], "six faces")
    keys = [c.key for c in model.sheet.columns]
    presenter.view.table.setCurrentIndex(model.index(6, keys.index("ac_x_arcsec")))
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(1.25, -0.5)]) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        qtbot.waitUntil(lambda: panel.guide.text() != "", timeout=3000)
        assert panel.guide.text() == "Next: go to face 7 (encoder ≈ 195°)"
        panel.take_button.click()
        panel.disconnect_instrument()
    assert [model.sheet.text(6, keys.index(k)) for k in ("position", "set", "ac_x_arcsec")] == \
        ["7", "1", "1.25"]
    assert panel.guide.text() == "Next: go to face 8 (encoder ≈ 210°)"


def test_guided_theodolite_says_theta_and_fills_it(window, qtbot):
    presenter = _show(window, "theodolite")
    model = presenter.table_model
    presenter.view.step.setValue(2.0)
    model.replace_all([["10", "", "", "", ""]], "first θ")
    presenter.view.table.setCurrentIndex(model.index(0, 1))
    panel = window.capture_panel
    with TheodoliteSimulator("pty", positions=[(33.5, 90.25)]) as sim:
        panel.connect_to("theodolite", sim.port, **FAST)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        qtbot.waitUntil(lambda: panel.guide.text() != "", timeout=3000)
        assert panel.guide.text() == "Next: θ = 10°"
        for _ in range(3):
            # a frame fills one row (#60 review): each take waits for a new one
            qtbot.waitUntil(lambda: not panel.used_again(), timeout=3000)
            panel.take_button.click()
        panel.disconnect_instrument()
    assert [model.sheet.text(r, 0) for r in range(4)] == ["10", "12", "14", "16"]
    assert [float(model.sheet.text(r, 1)) for r in range(3)] == pytest.approx([33.5] * 3, abs=1e-8)
    assert panel.guide.text() == "Next: θ = 16°"


def test_auto_take_settles_in_face_two_of_the_first_target(window, qtbot):
    """Face I of a target (Hz 10°), then face II (Hz 190°, V 270°) with 0.3" noise: 180° from
    the first frame, where offsets from a fixed origin jumped between ±180° and the panel
    said "settling, 0 % of the dwell" for ever."""
    presenter = _show(window, "theodolite")
    model = presenter.table_model
    model.replace_all([["10", "", "", "", ""], ["190", "", "", "", ""]], "two faces")
    presenter.view.table.setCurrentIndex(model.index(0, 1))
    panel = window.capture_panel
    panel.auto.setChecked(True)
    panel.window_box.setValue(5.0)
    panel.dwell_box.setValue(0.3)
    with TheodoliteSimulator("pty", positions=[(10.0, 90.0), (190.0, 270.0)], hold_s=1.5,
                             sigma=0.3) as sim:
        panel.connect_to("theodolite", sim.port, **FAST)
        qtbot.waitUntil(lambda: len(panel.taken) >= 2, timeout=15000)
        panel.disconnect_instrument()
    session = panel.raw_sessions("theodolite")[-1]
    hz = [float(model.sheet.text(r, 1)) for r in range(2)]
    assert hz == pytest.approx([10.0, 190.0], abs=1 / 3600)
    (_, first, last) = session["takes"][1]
    frames = [[float(v) for v in f[1].split(":")[1].split(",")[1:3]] for f in
              session["frames"][first:last + 1]]
    # the cell is the frames' mean, to the capture's rounding (a theodolite's 0.1" by default)
    assert np.degrees([f[0] for f in frames]).mean() == pytest.approx(hz[1], abs=0.05 / 3600)


# ---------------------------------------------------------------- faults during a set

@pytest.mark.parametrize("transport", ["pty", "tcp"])
def test_a_disconnect_mid_set_names_the_port_and_the_set_goes_on(window, qtbot, transport):
    """The link drops while the set is read (a pulled cable: nothing either way for 0.4 s
    on the pty; the socket cut on TCP): the panel says so naming the port, reconnects, and
    every face is still taken once, with its own value."""
    model, keys, panel = _auto_take_on_an_empty_polygon(window, dwell_s=0.1)
    statuses: list[str] = []
    positions = [(10.0 * i, 1.0) for i in range(1, 6)]
    with AutocollimatorSimulator(transport, faults=("disconnect",), disconnect_after=200,
                                 gap_s=0.4, positions=positions, hold_s=0.8) as sim:
        panel.connect_to("autocollimator", sim.port, silence_s=0.2, retries=4,
                         retry_pause_s=0.05)
        probe = QTimer()
        probe.setInterval(5)
        probe.timeout.connect(lambda: statuses.append(panel.status.text()))
        probe.start()
        qtbot.waitUntil(lambda: len(panel.taken) >= len(positions), timeout=20000)
        probe.stop()
        panel.disconnect_instrument()
    # said while it reconnects (the pty's gap is long enough to see it), and after (the
    # reason without the port said before it: #62 review, the status grew 3-4 lines)
    head = f"Connected: {sim.port} (reconnected after: "
    assert any(s.startswith(head) and sim.port not in s[len(head):] for s in statuses)
    if transport == "pty":
        assert any(s.startswith(sim.port) and s.endswith("(reconnecting)") for s in statuses)
    got = [float(model.sheet.text(r, keys.index("ac_x_arcsec"))) for r in range(len(positions))]
    assert got == pytest.approx([p[0] for p in positions], abs=1e-9)
    assert [model.sheet.text(r, 0) for r in range(len(positions))] == ["1", "2", "3", "4", "5"]


def test_a_take_never_bridges_a_lost_link(window, qtbot):
    """The link is lost 0.2 s into a dwell of 0.5 s (the instrument silent for 0.4 s): the
    reading taken is the mean of frames after the reconnection only (it was the mean of
    the frames before the gap and the first one after it)."""
    model, keys, panel = _auto_take_on_an_empty_polygon(window, dwell_s=0.5)
    with AutocollimatorSimulator("pty", faults=("disconnect",), disconnect_after=50,
                                 gap_s=0.4, positions=[(4.0, 1.0)]) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        qtbot.waitUntil(lambda: len(panel.taken) >= 1, timeout=20000)
        panel.disconnect_instrument()
    assert sim.cuts == 1 and panel.links[0].last_fault  # the link was lost, and said so
    session = panel.raw_sessions("polygon")[-1]
    (row, first, last), = session["takes"]
    times = np.array([f[0] for f in session["frames"]])
    gap = int(np.argmax(np.diff(times)))  # the last frame before the silence
    assert times[gap + 1] - times[gap] > FAST["silence_s"]
    assert first > gap, (first, gap, last)  # every frame of the take after the gap
    assert times[last] - times[first] >= 0.5 - 1e-6  # and they cover the dwell


def test_line_noise_never_reaches_a_cell(window, qtbot):
    model, keys, panel = _auto_take_on_an_empty_polygon(window, dwell_s=0.1)
    positions = [(-5.0, 2.0), (7.5, 2.0), (0.25, 2.0)]
    with AutocollimatorSimulator("pty", faults=("noise",), positions=positions, hold_s=0.6) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        qtbot.waitUntil(lambda: len(panel.taken) >= 3, timeout=15000)
        panel.disconnect_instrument()
    assert [float(model.sheet.text(r, keys.index("ac_x_arcsec"))) for r in range(3)] == \
        pytest.approx([-5.0, 7.5, 0.25], abs=1e-9)
    frames = panel.raw_sessions("polygon")[-1]["frames"]
    assert any(f[2] == 0 for f in frames)  # the garbage is kept with the frames, refused


@pytest.mark.parametrize("port, words", [("/dev/nonexistent-anglebench", "cannot open"),
                                         ("tcp://127.0.0.1:9", "cannot open")])
def test_a_wrong_port_is_named(window, qtbot, port, words):
    _show(window, "polygon")
    panel = window.capture_panel
    panel.connect_to("autocollimator", port, silence_s=0.2, retries=0)
    qtbot.waitUntil(lambda: panel.worker is None, timeout=5000)
    assert panel.status.text().startswith(f"{port}: {words}")
    assert not panel.take_button.isEnabled()


def test_a_wrong_baud_rate_is_named(window, qtbot):
    _show(window, "theodolite")
    panel = window.capture_panel
    with TheodoliteSimulator("pty", faults=("wrong_baud",)) as sim:
        panel.connect_to("theodolite", sim.port, baud=4800, **FAST)
        qtbot.waitUntil(lambda: panel.worker is None, timeout=5000)
    text = panel.status.text()
    assert text.startswith(sim.port) and "baud" in text and "4800" in text


def test_theta_typed_and_return_with_a_step_the_take_fills_the_row_waiting(window, qtbot):
    """#41 review: θ typed and Return before a take (a nominal step set) left row 1 without a
    reading, the take filling row 2, while the guidance said row 1's θ and the caption
    "next: row 2". The row still waiting for its reading is the next one, for all three."""
    from PySide6.QtWidgets import QLineEdit

    presenter = _show(window, "theodolite")
    model = presenter.table_model
    table = presenter.view.table
    presenter.view.step.setValue(2.0)
    window.show()
    qtbot.waitExposed(window)
    table.setCurrentIndex(model.index(0, 0))
    table.edit(model.index(0, 0))
    editor = next(w for w in table.viewport().findChildren(QLineEdit) if w.isVisible())
    qtbot.keyClicks(editor, "-20")
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: model.sheet.row_count >= 2, timeout=3000)
    assert [model.sheet.text(r, 0) for r in range(2)] == ["-20", "-18"]
    assert table.currentIndex().row() == 1  # Return went on to the next row
    presenter.refresh()
    assert presenter.view.next_label.text() == "next: row 1"
    panel = window.capture_panel
    with TheodoliteSimulator("pty", positions=[(33.5, 90.25)]) as sim:
        panel.connect_to("theodolite", sim.port, **FAST)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        qtbot.waitUntil(lambda: panel.guide.text() != "", timeout=3000)
        assert panel.guide.text() == "Next: θ = -20°"
        assert panel.target_row() == 0
        panel.take_button.click()
        assert float(model.sheet.text(0, 1)) == pytest.approx(33.5, abs=1e-8)
        assert model.sheet.text(1, 1) == ""
        assert panel.guide.text() == "Next: θ = -18°"
        assert panel.target_row() == 1
        presenter.refresh()  # (on a worker while capturing)
        qtbot.waitUntil(lambda: presenter.view.next_label.text() == "next: row 2", timeout=3000)
        qtbot.waitUntil(lambda: not panel.used_again(), timeout=3000)  # a new frame (#60)
        panel.take_button.click()
        panel.disconnect_instrument()
    assert [model.sheet.text(r, 0) for r in range(3)] == ["-20", "-18", "-16"]
    assert float(model.sheet.text(1, 1)) == pytest.approx(33.5, abs=1e-8)
    assert model.sheet.text(2, 1) == ""


def test_the_live_value_reads_as_the_cells_it_fills(window, qtbot):
    """#41 review: the live value was decimal degrees to 6 places ("33.500000°") beside an
    azimuth column in D°M′S″; it is shown as the take writes the cell (format, resolution,
    the elevation from the zenith angle where the column reads elevation)."""
    presenter = _show(window, "theodolite")
    model = presenter.table_model
    model.replace_all([["-20", "12°30'00.00\"", "1°00'00.00\"", "", ""], ["-18", "", "", "", ""]],
                      "typed in D°M′S″")
    presenter.view.table.setCurrentIndex(model.index(1, 1))
    panel = window.capture_panel
    with TheodoliteSimulator("pty", positions=[(33.5, 90.25)]) as sim:
        panel.connect_to("theodolite", sim.port, **FAST)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        qtbot.waitUntil(lambda: "°" in panel.value.text(), timeout=3000)
        shown = panel.value.text().split("   ")
        panel.take_button.click()
        panel.disconnect_instrument()
    assert shown == [model.sheet.text(1, 1), model.sheet.text(1, 2)]
    assert parse_angle_deg(shown[0]) == pytest.approx(33.5, abs=1e-6)
    assert parse_angle_deg(shown[1]) == pytest.approx(-0.25, abs=1e-6)  # 90° − V
    assert shown[0].startswith("33°30'") and "33.500000" not in panel.value.text()
