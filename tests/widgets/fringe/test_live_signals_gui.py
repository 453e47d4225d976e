"""The fringe workbench's live signals, driven as a technician would: samples arrive from a
stream (a fake one with signals made here, and the read head simulator over TCP), the bars
show the figures worked out here independently, coloured by their state at the band edges;
min/max pointers and their reset; a take puts the window in the readings with its raw
lines; the display redraws at its own rate, not per block."""

from __future__ import annotations

import math
import time

import numpy as np
import pytest

from app.capture.signal_live import open_signal_stream
from app.capture.signal_worker import SampleBlock
from models.fringe.signal_tolerance import LAB_DEFAULTS_KEY
from tests.instrument_simulators import SIMULATORS
from widgets.fringe.live_signals import REFRESH_MS
from widgets.fringe.presenter import FringePresenter
from widgets.fringe.signal_bar import STATE_COLOURS


def signal_lines(a=0.5, b=0.5, offset_a=0.0, offset_b=0.0, phase_deg=0.0, periods=20,
                 per_period=250, theta0=0.0):
    """Lines ``u_sin,u_cos`` of u_sin = oa + a·sin θ, u_cos = ob + b·cos(θ + φ), θ stepping
    unevenly (a hand turning the shaft), 12 digits a value."""
    n = periods * per_period
    k = np.arange(n)
    theta = theta0 + 2 * math.pi * (k / per_period + 0.05 * np.sin(2 * math.pi * k / 900))
    u_sin = offset_a + a * np.sin(theta)
    u_cos = offset_b + b * np.cos(theta + math.radians(phase_deg))
    return [f"{s:.12g},{c:.12g}".encode() for s, c in zip(u_sin, u_cos, strict=True)]


class FakeStream:
    """What the worker hands on: blocks of lines with their samples (read here with
    float(), not with the parser under test)."""

    port, baud, started_utc = "tcp://fake:1", 115200, "2026-12-02T09:00:00+00:00"

    def __init__(self) -> None:
        self.queued: list[SampleBlock] = []
        self.lines = 0
        self.stopped = False

    def send(self, lines: list[bytes], block: int = 500) -> None:
        for start in range(0, len(lines), block):
            chunk = lines[start:start + block]
            values, used = [], []
            for line in chunk:
                try:
                    s, c = (float(v) for v in line.split(b","))
                except ValueError:
                    used.append(False)
                    continue
                values.append((s, c))
                used.append(True)
            values = np.array(values).reshape(-1, 2)
            self.queued.append(SampleBlock(self.lines, 0.001 * self.lines, chunk,
                                           np.array(used), values[:, 0], values[:, 1],
                                           used.count(False)))
            self.lines += len(chunk)

    def drain(self):
        out, self.queued = self.queued, []
        return out

    def stop(self) -> None:
        self.stopped = True


@pytest.fixture
def fringe(qtbot):
    presenter = FringePresenter()
    qtbot.addWidget(presenter.view)
    panel = presenter.view.live_signals
    yield presenter
    panel.disconnect_stream()


def live(presenter, lab_defaults=None):
    from models.capture.take_rows import TakeRows, session_takes

    panel = presenter.view.live_signals
    sessions: list[dict] = []
    # the takes follow their rows, as the window has them (app/main_window.py)
    presenter.table_model.take_rows = TakeRows(lambda: session_takes(sessions))
    panel.attach(lambda *_a: None, sessions=lambda: sessions,
                 lab_defaults=(lambda: lab_defaults) if lab_defaults else None)
    stream = FakeStream()
    panel.set_source(stream)
    panel.timer.stop()  # ticks by hand
    return panel, stream, sessions


def test_the_bars_show_the_figures_the_signals_were_made_with(fringe):
    panel, stream, _ = live(fringe)
    stream.send(signal_lines(a=0.45, b=0.52, offset_a=0.02, offset_b=-0.015, phase_deg=4.0))
    panel.tick()
    bars = panel.bars
    assert bars["amplitude_a"].value == pytest.approx(0.90, abs=1e-6)
    assert bars["amplitude_b"].value == pytest.approx(1.04, abs=1e-6)
    assert bars["amplitude_ratio"].value == pytest.approx(0.52 / 0.45, rel=1e-6)
    assert bars["phase_deviation"].value == pytest.approx(4.0, abs=1e-5)
    assert bars["offset_a"].value == pytest.approx(100 * 0.02 / 0.90, abs=1e-5)  # (P − N)/2M
    assert bars["offset_b"].value == pytest.approx(100 * -0.015 / 1.04, abs=1e-5)
    for quantity in ("amplitude_a", "amplitude_b", "amplitude_ratio", "phase_deviation",
                     "offset_a", "offset_b"):
        assert bars[quantity].state == "inside"
        assert bars[quantity].colour() == STATE_COLOURS["inside"]
    assert bars["amplitude_a"].value_text() == "0.900 Vpp"
    # the Lissajous: the window's samples (u_cos across, u_sin up) and the fitted ellipse
    x, y = panel.liss_raw.getData()
    assert x.size > 1000 and np.max(y) == pytest.approx(0.47, abs=1e-3)
    fx, fy = panel.liss_fit.getData()
    assert np.ptp(fy) == pytest.approx(0.90, abs=1e-4) and np.ptp(fx) == pytest.approx(1.04, abs=1e-4)
    # the rings of the amplitude band: 0.6 and 1.2 Vpp as radii 0.3 V and 0.6 V
    rx, _ = panel.rings[0].getData()
    assert np.ptp(rx) == pytest.approx(0.6, abs=1e-3)
    rx, _ = panel.rings[1].getData()
    assert np.ptp(rx) == pytest.approx(1.2, abs=1e-3)
    assert "not a statement of conformity" in panel.note.text()


@pytest.mark.parametrize("amplitude_vpp, state", [(0.6, "inside"), (0.6 * (1 - 1e-5), "outside")])
def test_a_bar_is_green_on_the_edge_and_red_beyond_it(fringe, amplitude_vpp, state):
    panel, stream, _ = live(fringe)
    stream.send(signal_lines(a=amplitude_vpp / 2))
    panel.tick()
    assert panel.bars["amplitude_a"].state == state
    assert panel.bars["amplitude_a"].colour() == STATE_COLOURS[state]


def test_a_labs_own_preset_with_an_outer_band_shows_amber_between_the_bands(fringe):
    own = {"key": "lab_mounting", "name": "Lab mounting band", "interface": "1Vpp",
           "source": "our own work instruction WI-12",
           "bands": [{"quantity": "phase_deviation", "unit": "°", "inside": [-2, 2],
                      "outer": [-5, 5]}]}
    panel, stream, _ = live(fringe, lab_defaults={LAB_DEFAULTS_KEY: [own]})
    panel.preset.setCurrentIndex(panel.preset.findData("lab_mounting"))
    for phase, state in ((2.0, "inside"), (3.5, "outer"), (-5.0, "outer"), (5.5, "outside")):
        stream.send(signal_lines(phase_deg=phase, periods=20))
        panel.tick()
        assert panel.bars["phase_deviation"].state == state, phase
        assert panel.bars["phase_deviation"].colour() == STATE_COLOURS[state]
    assert not panel.bars["amplitude_a"].isVisibleTo(panel)  # no band for it in this preset


def test_min_and_max_pointers_follow_the_window_until_reset(fringe):
    panel, stream, _ = live(fringe)
    panel.periods.setValue(8)
    bar = panel.bars["amplitude_a"]
    stream.send(signal_lines(a=0.5, periods=10))
    panel.tick()
    stream.send(signal_lines(a=0.4, periods=10))
    panel.tick()
    assert bar.value == pytest.approx(0.8, abs=1e-6)
    assert bar.low == pytest.approx(0.8, abs=1e-6) and bar.high == pytest.approx(1.0, abs=1e-6)
    panel.reset_button.click()
    assert bar.low == bar.high == pytest.approx(0.8, abs=1e-6)
    stream.send(signal_lines(a=0.42, periods=10))
    panel.tick()
    assert bar.low == pytest.approx(0.8, abs=1e-6) and bar.high == pytest.approx(0.84, abs=1e-6)


def test_a_take_puts_the_window_in_the_readings_with_its_raw_lines(fringe):
    panel, stream, sessions = live(fringe)
    panel.periods.setValue(4)
    lines = signal_lines(a=0.45, periods=6, per_period=200)
    lines.insert(1000, b"\xff garbage")  # a line the stream sent that is no sample
    stream.send(lines)
    panel.tick()
    u_sin, u_cos, index, _ = panel.window_samples()
    panel.take_button.click()
    sheet = fringe.sheet
    assert sheet.row_count == u_sin.size == pytest.approx(800, abs=20)
    assert [float(v) for v in sheet.rows[0][:2]] == [u_sin[0], u_cos[0]]
    assert [float(v) for v in sheet.rows[-1][:2]] == [u_sin[-1], u_cos[-1]]
    (session,) = sessions
    assert session["instrument"] == "signals" and session["port"] == "tcp://fake:1"
    frames, takes = session["frames"], session["takes"]
    assert len(takes) == sheet.row_count and len(frames) == sheet.row_count + 1
    assert [f[1] for f in frames if not f[2]] == [b"\xff garbage".decode("latin-1")]
    for row, first, last in (takes[0], takes[500], takes[-1]):
        assert first == last
        s, c = (float(v) for v in frames[first][1].split(","))
        assert [float(v) for v in sheet.rows[row][:2]] == [s, c]
    # a second take replaces the rows: the first take's rows are marked gone, Undo restores
    stream.send(signal_lines(a=0.40, periods=6, per_period=200, theta0=1.0))
    panel.tick()
    panel.take()
    assert len(sessions) == 2 and all(t[0] == -1 for t in sessions[0]["takes"])
    assert float(sheet.rows[0][0]) != float(frames[takes[0][1]][1].split(",")[0])
    fringe.undo_stack.undo()
    assert [float(v) for v in fringe.sheet.rows[0][:2]] == [u_sin[0], u_cos[0]]


def test_undo_of_a_take_undoes_its_claim_on_the_rows_it_replaced(fringe):
    """Review 62 F4: the undo of a second take gave the first take's readings back, the
    second take still naming their rows: every row was printed "edited after capture" with
    the second take's voltages. The undo undoes the take; the redo puts it back."""
    from app.certificate_issue import readings_edited_after_capture
    from models.capture.take_rows import TakeRows, session_takes

    panel, stream, sessions = live(fringe)
    fringe.table_model.take_rows = TakeRows(lambda: session_takes(sessions))  # the window's

    def said():
        return list(readings_edited_after_capture(
            fringe.kind, fringe.settings, fringe.sheet.rows, sessions))

    panel.periods.setValue(4)
    stream.send(signal_lines(a=0.45, periods=6, per_period=200))
    panel.tick()
    panel.take()
    first = [list(r[:2]) for r in fringe.sheet.rows]
    stream.send(signal_lines(a=0.40, periods=6, per_period=200, theta0=1.0))
    panel.tick()
    panel.take()
    second = [list(r[:2]) for r in fringe.sheet.rows]
    assert len(sessions) == 2 and said() == []
    fringe.undo_stack.undo()  # the second take: the first's readings back
    assert [list(r[:2]) for r in fringe.sheet.rows] == first
    assert said() == []  # was: every row "edited after capture: <second's> → <first's>"
    assert {t[0] for t in sessions[1]["takes"]} == {-1}
    fringe.undo_stack.redo()
    assert [list(r[:2]) for r in fringe.sheet.rows] == second
    assert [t[0] for t in sessions[1]["takes"]] == list(range(len(second)))
    fringe.table_model.set_cells([(5, 0, "0.123456")])
    assert [(e.row, e.what) for e in said()] == [(5, "edited")]


def test_undo_of_a_retake_gives_the_earlier_take_its_rows_back_and_redo_replaces_them(fringe):
    """A retake marked the earlier take's readings replaced before, and outside, the undo
    step that replaced them: Undo gave the earlier readings back unclaimed (a cell of them
    edited since was no longer said edited, the record said no row held them). The marks
    are now in the retake's own step: Undo gives the earlier take its rows back, Redo
    replaces them again."""
    from app.certificate_issue import readings_edited_after_capture

    panel, stream, sessions = live(fringe)

    def said():
        return [(e.row, e.what) for e in readings_edited_after_capture(
            fringe.kind, fringe.settings, fringe.sheet.rows, sessions)]

    panel.periods.setValue(4)
    stream.send(signal_lines(a=0.45, periods=6, per_period=200))
    panel.tick()
    panel.take_button.click()
    fringe.table_model.set_cells([(5, 0, "0.123456")])  # a reading of the first take edited
    before_rows = [list(r) for r in fringe.sheet.rows]
    before_takes = [list(t) for t in sessions[0]["takes"]]
    assert [t[0] for t in before_takes] == list(range(len(before_rows)))
    assert said() == [(5, "edited")]
    stream.send(signal_lines(a=0.40, periods=6, per_period=200, theta0=1.0))
    panel.tick()
    panel.take_button.click()  # the retake
    second_rows = [list(r) for r in fringe.sheet.rows]
    assert len(sessions) == 2 and {t[0] for t in sessions[0]["takes"]} == {-1}
    assert said() == []
    fringe.undo_stack.undo()
    assert [list(r) for r in fringe.sheet.rows] == before_rows
    assert sessions[0]["takes"] == before_takes  # was: every take of it still at -1
    assert {t[0] for t in sessions[1]["takes"]} == {-1}
    assert said() == [(5, "edited")]  # was: [] (the first take no longer claimed its rows)
    fringe.undo_stack.redo()
    assert [list(r) for r in fringe.sheet.rows] == second_rows
    assert {t[0] for t in sessions[0]["takes"]} == {-1}
    assert [t[0] for t in sessions[1]["takes"]] == list(range(len(second_rows)))
    assert said() == []
    fringe.undo_stack.undo()  # and again: the same state as before the retake
    assert sessions[0]["takes"] == before_takes and said() == [(5, "edited")]


def test_a_take_with_nothing_in_the_window_is_refused_and_said(fringe):
    panel, _, sessions = live(fringe)
    assert panel.take() is False
    assert sessions == [] and fringe.sheet.row_count == 0
    assert "Nothing to take" in panel.status.text()


def test_many_blocks_between_two_ticks_are_one_redraw(fringe):
    panel, stream, _ = live(fringe)
    stream.send(signal_lines(periods=40), block=20)  # 500 blocks
    before = panel.redraws
    panel.tick()
    assert panel.redraws == before + 1
    panel.tick()  # nothing new: nothing redrawn
    assert panel.redraws == before + 1


def test_the_display_redraws_at_its_own_rate_however_fast_the_stream(fringe, qtbot):
    panel, stream, _ = live(fringe)
    lines = signal_lines(periods=400, per_period=100)
    sent = {"at": 0}

    def drain():  # a stream that always has new blocks, 10 000 samples a second
        start = sent["at"]
        sent["at"] = min(start + 400, len(lines))
        stream.send(lines[start:sent["at"]], block=10)
        return FakeStream.drain(stream)

    stream.drain = drain
    # until 2000 samples have come (a loaded machine ticks late: the bound is on the time
    # it took, not on one second of wall clock)
    start = time.monotonic()
    panel.timer.start()
    qtbot.waitUntil(lambda: panel.samples > 2000, timeout=30_000)
    panel.timer.stop()
    elapsed_ms = (time.monotonic() - start) * 1000
    assert 3 <= panel.redraws <= elapsed_ms / REFRESH_MS + 2


def test_the_read_head_simulator_live_over_tcp(fringe, qtbot):
    head = SIMULATORS["signals"]("tcp", sample_hz=10_000.0, signal_hz=40.0, noise_mv=1.0,
                                 gap_mm=0.9, yaw_mrad=2.0, roll_mrad=10.0, seed=11)
    with head:
        panel = fringe.view.live_signals
        panel.attach(open_signal_stream)
        assert panel.connect_stream(head.port, "")
        qtbot.waitUntil(lambda: panel.figures is not None and panel.figures.periods >= 15,
                        timeout=10_000)
        panel.disconnect_stream()
    # the head's figures from its own geometry, at the true phase (not the estimated one)
    theta = np.linspace(0, 2 * math.pi, 3600, endpoint=False)
    u_sin, u_cos = (np.asarray(u) for u in head.channels(theta))
    design = np.column_stack([np.ones_like(theta), np.sin(theta), np.cos(theta)])
    (_, ss, sc), *_ = np.linalg.lstsq(design, u_sin, rcond=None)
    (_, cs, cc), *_ = np.linalg.lstsq(design, u_cos, rcond=None)
    phase = math.degrees(math.atan2(cc, cs) - math.atan2(sc, ss)) - 90.0
    bars = panel.bars
    assert bars["amplitude_a"].value == pytest.approx(np.ptp(u_sin), rel=0.01)
    assert bars["amplitude_b"].value == pytest.approx(np.ptp(u_cos), rel=0.01)
    assert bars["phase_deviation"].value == pytest.approx(phase, abs=0.3)
    high, low = u_sin.max(), u_sin.min()
    assert bars["offset_a"].value == pytest.approx(100 * (high + low) / (2 * (high - low)), abs=0.3)
    assert panel.refused == 0 and panel.samples >= 15 * 250


@pytest.mark.slow
def test_in_the_window_a_demonstration_take_is_kept_with_the_project_and_edits_are_seen(window, qtbot):
    bench = next(p for p in window.presenters if getattr(p.view, "live_signals", None))
    panel = bench.view.live_signals
    bench.view.open_live_signals()
    assert panel.start_demonstration()
    try:
        panel.knobs["gap_mm"].setValue(0.8)  # the technician turns the gap to nominal
        assert panel.demonstration.gap_mm == 0.8
        qtbot.waitUntil(lambda: panel.figures is not None and panel.figures.periods >= 15,
                        timeout=15_000)
        panel.take_button.click()
        qtbot.wait(300)
        panel.take_button.click()  # a second take: its own session, nothing flagged
    finally:
        panel.disconnect_stream()
    key = bench.kind.key
    sessions = window.capture_panel.raw_sessions(key)
    assert len(sessions) == 2 and {s["instrument"] for s in sessions} == {"signals"}
    assert sessions[0]["started_utc"] != sessions[1]["started_utc"]
    # each bound to its workbench (review 61 F7)
    assert [s["workbench"] for s in sessions] == [key, key]
    assert key in window.capture_panel.raw_capture()  # saved with the project
    model = bench.table_model
    assert bench.sheet.row_count == len(sessions[1]["takes"]) > 1000
    assert model.edited_cells == {}
    model.set_cells([(5, 0, "0.123456")])
    assert set(model.edited_cells) == {(5, 0)}
    assert panel.demonstration is None and panel.source is None


def test_signal_quality_along_the_record_marks_where_the_head_leaves_its_band(fringe, qtbot):
    """200 periods of 64 equal steps; the sin channel's amplitude falls to 0.5 Vpp (below
    the 1 Vpp interface's 0.6) over periods 80 … 119, as a stain on the scale would."""
    n, periods = 64, 200
    k = np.arange(n * periods)
    theta = 2 * math.pi * k / n
    a = np.where((k // n >= 80) & (k // n < 120), 0.25, 0.5)
    rows = [[f"{s:.12g}", f"{c:.12g}", ""] for s, c in zip(a * np.sin(theta), 0.5 * np.cos(theta),
                                                             strict=True)]
    fringe.set_settings({**fringe.settings, "samples_per_period": n, "lines_per_rev": periods})
    fringe.table_model.replace_all(rows, "simulated", checked=True)
    fringe.schedule_refresh()
    qtbot.waitUntil(lambda: fringe.result is not None, timeout=20_000)
    plot = fringe.view.signal_quality
    plot.preset.setCurrentIndex(plot.preset.findData("heidenhain_1vpp"))
    plot.quantity.setCurrentIndex(plot.quantity.findData("amplitude_a"))
    x, y = plot.curve.getData()
    assert len(x) == len(plot.quality.windows) >= 50
    bx, by = plot.beyond.getData()
    # the windows beyond the band are those of the stain, along the revolution (360°/200 a period)
    assert by.size and np.allclose(by, 0.5, atol=1e-6)
    assert bx.min() > 80 * 1.8 - 1e-9 and bx.max() < 120 * 1.8
    assert plot.inside.isVisible() and plot.inside.getRegion() == (0.6, 1.2)
    assert "outside the band" in plot.note.text()


def test_a_preset_the_lab_saved_since_is_there_when_the_window_opens(fringe):
    defaults: dict = {}
    panel, _, _ = live(fringe, lab_defaults=None)
    panel.attach(lambda *_a: None, lab_defaults=lambda: defaults)
    assert panel.preset.findData("lab_gap") == -1
    defaults[LAB_DEFAULTS_KEY] = [{"key": "lab_gap", "name": "Our heads", "interface": "1Vpp",
                                   "bands": [{"quantity": "amplitude_a", "unit": "Vpp",
                                              "inside": [0.9, 1.1]}]}]
    fringe.view.open_live_signals()
    assert panel.isVisible() and panel.preset.findData("lab_gap") >= 0
    panel.close()


def test_a_bar_prints_a_zero_unsigned(qtbot):
    """live78: a centred offset read "Offset A -0.00 %" on the live bars; zero is printed
    unsigned, as the window's tables and the certificate print it."""
    from widgets.fringe.signal_bar import SignalBar

    bar = SignalBar("offset_a")
    qtbot.addWidget(bar)
    bar.set_band("Offset A", None, "%", 2)
    bar.set_value(-0.0004, "")
    assert bar.value_text() == "0.00 %"
    bar.set_value(-0.006, "")
    assert bar.value_text() == "-0.01 %"
