"""Reading the instruments (#34): a 250 Hz autocollimator stream shown live in the window
with auto-take filling the table, and the link dropped 100 times; through the protocol
simulators on a pseudo-terminal and on TCP (the real serial code path).

The issue's targets: no frame dropped over 10 minutes of a 250 Hz stream; reading-to-cell
≤ 50 ms; the window's longest pause while capturing ≤ 50 ms; 0 readings lost over 100
disconnects. The stream runs ``ANGLEBENCH_STREAM_SECONDS`` seconds (default 60, a scaled
run; 600 for the target's 10 minutes).

Reading-to-cell is the time from the arrival of the frame that completes an auto-take's
dwell (the worker's time stamp, when its last byte was read) to the cell being set in
the table's model. The pauses are the gaps of a 5 ms QTimer heartbeat. "Dropped" compares
the frames the window took in, in order, with every frame the simulator wrote whole.
"""

from __future__ import annotations

import os
import queue
import time

import numpy as np
from PySide6.QtCore import QSettings, QTimer

from app.capture.instruments import Autocollimator, Theodolite
from app.capture.worker import CaptureWorker, Fault, Reading
from app.main_window import MainWindow
from models.project.recovery import RecoveryStore
from tests.instrument_simulators import AutocollimatorSimulator, TheodoliteSimulator

STREAM_S = float(os.environ.get("ANGLEBENCH_STREAM_SECONDS", "60"))
DISCONNECTS = 100
HOLD_S = 0.5  # each position of the stream's script


def _window(qtbot, tmp_path) -> MainWindow:
    settings = QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)
    window = MainWindow(settings=settings, recovery=RecoveryStore(tmp_path / "recovery"))
    window.tell = lambda *a: None
    window.ask = lambda *a: None
    window.resize(1400, 900)
    qtbot.addWidget(window)
    window.show()
    return window


def _stream(qtbot, window) -> dict:
    presenter = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    model = presenter.table_model
    model.replace_all([], "bench")
    keys = [c.key for c in model.sheet.columns]
    column = keys.index("ac_x_arcsec")
    presenter.view.table.setCurrentIndex(model.index(0, column))
    panel = window.capture_panel
    panel.show()
    panel.auto.setChecked(True)
    panel.window_box.setValue(0.5)
    panel.dwell_box.setValue(0.1)
    cell_set: dict[int, float] = {}

    def changed(top, bottom, _roles=()):
        if top.column() <= column <= bottom.column():
            now = time.monotonic()
            for row in range(top.row(), bottom.row() + 1):
                cell_set.setdefault(row, now)

    model.dataChanged.connect(changed)
    beats: list[float] = []
    heart = QTimer()
    heart.setInterval(5)
    heart.timeout.connect(lambda: beats.append(time.perf_counter()))
    # the machine's own floor: the same window idle, heartbeat only, for a few seconds
    heart.start()
    idle_from = time.perf_counter()
    qtbot.wait(int(min(STREAM_S, 10.0) * 1000))
    heart.stop()
    idle_gaps = np.diff(np.array([b for b in beats if b >= idle_from]))
    beats.clear()
    count = int(STREAM_S / HOLD_S) + 2
    positions = [(5.0 * (i % 9) - 20.0, 2.0 * (i % 5)) for i in range(count)]
    with AutocollimatorSimulator("pty", positions=positions, hold_s=HOLD_S, sigma=0.05,
                                 rate_hz=250.0) as sim:
        panel.connect_to("autocollimator", sim.port, silence_s=1.0, retries=3)
        worker = panel.worker
        heart.start()
        qtbot.waitUntil(lambda: panel.received > 0, timeout=5000)
        started = time.perf_counter()
        cpu = time.thread_time()
        beats.append(started)
        qtbot.wait(int(STREAM_S * 1000))
        cpu = (time.thread_time() - cpu) / (time.perf_counter() - started)
        heart.stop()
        t0 = worker.t0
        panel.disconnect_instrument()
        sent = [(round(x, 3), round(y, 3)) for x, y in sim.sent]
    model.dataChanged.disconnect(changed)
    session = panel.raw_sessions("polygon")[-1]
    used = [f for f in session["frames"] if f[2] == 1]
    got = [tuple(float(v) for v in f[1].split()[2:]) for f in used]
    in_order = sum(1 for a, b in zip(got, sent, strict=False) if a == b)
    latencies = np.array([cell_set[row] - (t0 + session["frames"][last][0])
                          for row, _, last in session["takes"] if row in cell_set])
    gaps = np.diff(np.array([b for b in beats if b >= started]))
    return {"seconds": STREAM_S, "sent": len(sent), "received": panel.received,
            "stored": len(used), "in_order": in_order, "refused": worker.refused,
            "takes": len(session["takes"]), "positions": int(STREAM_S / HOLD_S),
            "latency": latencies, "gaps": gaps, "idle_gaps": idle_gaps, "cpu": cpu}


def _disconnects(simulator, instrument, every: int) -> dict:
    """Readings through ``DISCONNECTS`` cuts of a TCP link: every frame the simulator wrote
    whole must arrive once, in order."""
    readings: list[Reading] = []
    faults: list[Fault] = []
    with simulator as sim:
        worker = CaptureWorker(sim.port, instrument, silence_s=0.5, retries=3,
                               retry_pause_s=0.02).start()
        started = time.perf_counter()
        end = started + 600
        while (sim.cuts < DISCONNECTS or len(faults) < DISCONNECTS) and time.perf_counter() < end:
            try:
                event = worker.events.get(timeout=0.05)
            except queue.Empty:
                continue
            (faults if isinstance(event, Fault) else readings).append(event)
        sim.faults.discard("disconnect")
        sim.faults.add("silence")  # the instrument stops: what it wrote whole arrives, then none
        idle = time.perf_counter()
        while time.perf_counter() - idle < 1.0:
            try:
                event = worker.events.get(timeout=0.05)
            except queue.Empty:
                continue
            if isinstance(event, Reading):
                readings.append(event)
                idle = time.perf_counter()
        elapsed = time.perf_counter() - started
        worker.stop()
        sent = list(sim.sent)
    values = [r.values for r in readings]
    if isinstance(instrument, Theodolite):
        matched = sum(1 for v, s in zip(values, sent, strict=False)
                      if s is not None and np.allclose(v, s, rtol=0, atol=1e-7))
        whole = sum(1 for s in sent if s is not None)
    else:
        matched = sum(1 for v, s in zip(values, sent, strict=False)
                      if v == (round(s[0], 3), round(s[1], 3)))
        whole = len(sent)
    return {"cuts": sim.cuts, "faults": len(faults), "final": sum(f.final for f in faults),
            "sent": whole, "received": len(readings), "matched": matched, "seconds": elapsed}


def test_capture_stream_latency_and_disconnects(qtbot, tmp_path, report):
    window = _window(qtbot, tmp_path)
    stream = _stream(qtbot, window)
    ac = _disconnects(AutocollimatorSimulator("tcp", faults=("disconnect",), disconnect_every=60,
                                              disconnect_after=60, positions=[(1.0, 2.0)],
                                              sigma=0.3), Autocollimator(), 60)
    theo = _disconnects(TheodoliteSimulator("tcp", faults=("disconnect",), disconnect_every=15,
                                            disconnect_after=15, positions=[(12.0, 91.0)],
                                            sigma=0.5), Theodolite(), 15)

    def mark(ok: bool) -> str:
        return "met" if ok else "**missed**"

    dropped = stream["sent"] - stream["in_order"]
    in_flight = stream["sent"] - stream["stored"]
    lat, gaps = stream["latency"], stream["gaps"]
    minutes = f"{stream['seconds'] / 60:g} min"
    lost = [d["sent"] - d["matched"] for d in (ac, theo)]
    lines = [
        "## Reading the instruments (pty and TCP simulators, offscreen window)",
        "",
        f"Stream: {minutes} of a 250 Hz autocollimator stream over a pseudo-terminal into the "
        f"window (polygon workbench, auto-take 0.5\" / 0.1 s, a new position every {HOLD_S} s). "
        "`ANGLEBENCH_STREAM_SECONDS=600` runs the target's 10 minutes (default 60 s).",
        "",
        "| measure | result | target | |",
        "|---|---|---|---|",
        f"| frames the simulator wrote whole / taken in by the window, in order | "
        f"{stream['sent']} / {stream['in_order']} ({dropped} not taken in: {in_flight} written "
        f"as the link closed) | none dropped | {mark(stream['in_order'] == stream['stored'])} |",
        f"| readings queued by the worker / taken in by the window | {stream['stored']} / "
        f"{stream['received']} | equal | {mark(stream['stored'] == stream['received'])} |",
        f"| auto-takes / positions held | {stream['takes']} / {stream['positions']} | | |",
        f"| reading-to-cell (frame completing the dwell → cell set), {lat.size} takes | "
        f"median {np.median(lat) * 1e3:.1f} ms, max {lat.max() * 1e3:.1f} ms | ≤ 50 ms | "
        f"{mark(lat.max() <= 0.05)} |",
        f"| window's longest pause while capturing (5 ms heartbeat; median gap "
        f"{np.median(gaps) * 1e3:.1f} ms, p99 {np.percentile(gaps, 99) * 1e3:.1f} ms) | "
        f"{gaps.max() * 1e3:.1f} ms | ≤ 50 ms above the idle window's own (#41) | "
        f"{mark(gaps.max() <= stream['idle_gaps'].max() + 0.05)} |",
        f"| … the same window idle just before (the machine's floor; p99 "
        f"{np.percentile(stream['idle_gaps'], 99) * 1e3:.1f} ms) | "
        f"{stream['idle_gaps'].max() * 1e3:.1f} ms | | |",
        f"| the window's thread busy while capturing (its CPU time per second) | "
        f"{stream['cpu'] * 100:.0f} % ({os.getloadavg()[0]:.1f} load average on "
        f"{os.cpu_count()} CPUs) | | |",
    ]
    for name, d, n_lost in (("autocollimator stream, TCP", ac, lost[0]),
                            ("theodolite (GeoCOM requests), TCP", theo, lost[1])):
        lines.append(
            f"| {name}: link cut {d['cuts']} times ({d['faults']} faults said, {d['final']} "
            f"final), {d['seconds']:.0f} s | {d['sent']} readings sent whole, {d['received']} "
            f"received, {d['matched']} identical and in order: {n_lost} lost | 0 lost | "
            f"{mark(n_lost == 0 and d['received'] == d['sent'])} |")
    report("7-capture", lines, headline=(
        f"Capture: a 250 Hz autocollimator stream for {minutes} into the window: "
        f"{dropped - in_flight} frames dropped ({in_flight} in flight at the close), "
        f"reading-to-cell max {lat.max() * 1e3:.0f} ms (target 50 ms, {mark(lat.max() <= 0.05)}), "
        f"longest pause {gaps.max() * 1e3:.0f} ms (idle {stream['idle_gaps'].max() * 1e3:.0f} ms; "
        f"target idle + 50 ms, {mark(gaps.max() <= stream['idle_gaps'].max() + 0.05)}); "
        f"{sum(lost)} readings lost over {ac['cuts']} + {theo['cuts']} disconnects "
        f"(target 0, {mark(sum(lost) == 0)})."))
    assert stream["in_order"] == stream["stored"] == stream["received"]
    assert sum(lost) == 0
    assert ac["cuts"] >= DISCONNECTS and theo["cuts"] >= DISCONNECTS
