"""The window: cold start to the first paint, a cell edit to the updated plots on a
1000-point theodolite run, and loading a 1M-sample fringe file while the event loop
is watched for stalls (offscreen platform, this machine); a cell edit on the positioning
and cross-calibration samples with their certificate details, whose figures the window
shows as the certificate prints them (``-k printed``)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
from bench_util import fmt_time
from PySide6.QtCore import QSettings, QTimer
from PySide6.QtWidgets import QApplication

from app.main_window import MainWindow
from models.certificate.metadata import CertificateMetadata
from models.fringe.model import phase_of_samples
from models.project.recovery import RecoveryStore
from models.theodolite.model import SetupParameters, simulate_readings

ROOT = Path(__file__).resolve().parents[2]
LOADS = 3
#: the workbenches whose window rounds its figures as their certificate prints them at a cost
#: (the positioning's intervals with the reference standards' U, the cross-calibration's
#: budgets), each with the column a technician corrects
PRINTED_EDITS = (("positioning", "deviation"), ("crosscal", "ac_x_arcsec"))

CHILD = textwrap.dedent("""
    import sys
    from PySide6.QtCore import QEvent, QObject
    from PySide6.QtWidgets import QApplication
    from app.main_window import MainWindow

    class FirstPaint(QObject):
        def eventFilter(self, obj, event):
            if event.type() == QEvent.Type.Paint:
                sys.stdout.write("painted\\n")
                sys.stdout.flush()
                QApplication.instance().exit(0)
            return False

    app = QApplication(["anglebench"])
    app.setOrganizationName("AngleBenchBench")
    window = MainWindow()
    if "--samples" in sys.argv:
        window.load_all_samples()
    watcher = FirstPaint()
    window.installEventFilter(watcher)
    window.show()
    app.exec()
    window.projects.recovery.discard()
""")


def _cold_start(tmp_path: Path, samples: bool) -> float:
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen", XDG_CONFIG_HOME=str(tmp_path / "cfg"),
               XDG_DATA_HOME=str(tmp_path / "data"), PYTHONDONTWRITEBYTECODE="1")
    args = [sys.executable, "-c", CHILD] + (["--samples"] if samples else [])
    t0 = time.perf_counter()
    with subprocess.Popen(args, cwd=ROOT, env=env, stdout=subprocess.PIPE, text=True) as proc:
        line = proc.stdout.readline()
        elapsed = time.perf_counter() - t0
        proc.wait(timeout=30)
    assert line.strip() == "painted", line
    return elapsed


def _window(qtbot, tmp_path) -> MainWindow:
    settings = QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)
    window = MainWindow(settings=settings, recovery=RecoveryStore(tmp_path / "recovery"))
    window.tell = lambda *a: None
    window.ask = lambda *a: None
    window.resize(1400, 900)
    qtbot.addWidget(window)
    window.show()
    return window


def _edit_to_plot(qtbot, window, edits: int = 40) -> np.ndarray:
    presenter = window.presenter("theodolite")
    window.tabs.setCurrentIndex(0)
    rng = np.random.default_rng(5)
    theta = np.linspace(-45.0, 45.0, 1000)
    az, el = simulate_readings(theta, SetupParameters(1.5, 30.0, 2.0),
                               1.5 * np.sin(np.radians(4 * theta)), 0.2, rng)
    rows = [[f"{t:.6f}", f"{a:.8f}", f"{e:.8f}", "", ""] for t, a, e in zip(theta, az, el,
                                                                          strict=True)]
    presenter.table_model.replace_all(rows, "bench")
    presenter.refresh()
    QApplication.processEvents()
    curve = presenter.view.error_plot.corrected_curve
    done = []
    presenter.analysed.connect(lambda: done.append(time.perf_counter()))
    out = np.empty(edits)
    for i in range(edits):
        row = 10 + 23 * i
        index = presenter.table_model.index(row, 1)
        new = f"{az[row] + (1 if i % 2 else -1) * 2e-4:.8f}"
        before = curve.getData()[1].copy()
        done.clear()
        t0 = time.perf_counter()
        presenter.table_model.setData(index, new)
        while not done:  # the event loop, as the window runs it
            QApplication.processEvents()
        QApplication.processEvents()  # and the paint of what changed
        out[i] = time.perf_counter() - t0
        assert not np.array_equal(curve.getData()[1], before)
    return out


def _edit_large(qtbot, window, edits: int = 5) -> np.ndarray:
    """Seconds from a typed cell to the new result on the 1M-sample sheet just loaded."""
    presenter = window.presenter("fringe")
    model = presenter.table_model
    out = np.empty(edits)
    for i in range(edits):
        before = presenter.result
        t0 = time.perf_counter()
        slip = float(presenter.sheet.text(10 + i, 0)) + 0.3  # a slip (a spike is refused, #30)
        model.setData(model.index(10 + i, 0), f"{slip:.6f}")
        qtbot.waitUntil(lambda b=before: presenter.result is not b and not presenter.busy,
                        timeout=120_000)
        QApplication.processEvents()
        out[i] = time.perf_counter() - t0
    return out


def _edit_burst(qtbot, window, edits: int = 4) -> tuple[float, int]:
    """Cells typed one after another faster than a 1M-sample analysis runs: seconds from
    the first to the result of the last, and how many superseded analyses were cancelled."""
    presenter = window.presenter("fringe")
    model = presenter.table_model
    cancelled = presenter.cancelled_analyses
    t0 = time.perf_counter()
    last = float(presenter.sheet.text(40 + edits - 1, 0)) + 0.3
    for i in range(edits):
        model.setData(model.index(40 + i, 0), f"{float(presenter.sheet.text(40 + i, 0)) + 0.3:.6f}")
        qtbot.wait(30)  # typing: a cell every 30 ms
    qtbot.waitUntil(lambda: not presenter.busy and presenter.result is not None
                    and abs(presenter.result.u_sin[40 + edits - 1] - last) < 1e-6,
                    timeout=120_000)
    return time.perf_counter() - t0, presenter.cancelled_analyses - cancelled


def _fringe_file(path: Path, samples: int = 16384 * 64) -> Path:
    rng = np.random.default_rng(9)
    theta = phase_of_samples(samples, 64)
    u_s = 0.05 + 3.68 * np.sin(theta + 0.026) + 0.079 * np.sin(3 * theta) + rng.normal(0, 2e-3,
                                                                                         samples)
    u_c = -0.06 + 3.73 * np.cos(theta) + 0.079 * np.cos(3 * theta) + rng.normal(0, 2e-3, samples)
    with path.open("w", encoding="utf-8") as handle:
        handle.write("u_sin,u_cos\n")
        np.savetxt(handle, np.column_stack([u_s, u_c]), fmt="%.6f", delimiter=",")
    return path


def _load_large(qtbot, window, path: Path) -> tuple[float, float, float, float]:
    """(seconds to the result, seconds from the file read to the result, longest event-loop
    stall, median heartbeat gap)."""
    presenter = window.presenter("fringe")
    window.tabs.setCurrentIndex(2)
    QApplication.processEvents()
    beats: list[float] = []
    read: list[float] = []
    heart = QTimer()
    heart.setInterval(5)
    heart.timeout.connect(lambda: beats.append(time.perf_counter()))

    def on_read(*_args) -> None:
        read.append(time.perf_counter())

    presenter.imported.connect(on_read)
    heart.start()
    qtbot.wait(50)
    t0 = time.perf_counter()
    beats.append(t0)
    presenter.start_import(path)
    qtbot.waitUntil(lambda: bool(read) and presenter.sheet.row_count > 1_000_000
                    and not presenter.busy and presenter.result is not None, timeout=120_000)
    t1 = time.perf_counter()
    qtbot.wait(300)  # the paints of the new result belong to the load
    heart.stop()
    presenter.imported.disconnect(on_read)
    gaps = np.diff(np.array([b for b in beats if b >= t0]))
    return t1 - t0, t1 - read[-1], float(gaps.max()), float(np.median(gaps))


def test_window_responsiveness(qtbot, tmp_path, report):
    cold = np.array([_cold_start(tmp_path, False) for _ in range(5)])
    cold_samples = np.array([_cold_start(tmp_path, True) for _ in range(3)])
    window = _window(qtbot, tmp_path)
    edit = _edit_to_plot(qtbot, window)
    path = _fringe_file(tmp_path / "revolution.csv")
    fringe = window.presenter("fringe")
    rows = {}
    for label, per_period in (("phase estimated from the signals", 0),
                              ("N = 64 samples per period given", 64)):
        fringe.set_settings({**fringe.settings, "samples_per_period": per_period})
        loads = [_load_large(qtbot, window, path) for _ in range(LOADS)]
        rows[label] = (loads, _edit_large(qtbot, window), _edit_burst(qtbot, window))

    def mark(ok: bool) -> str:
        return "met" if ok else "**missed**"

    lines = [
        "## The window (offscreen platform)",
        "",
        "| measure | result | target | |",
        "|---|---|---|---|",
        f"| cold start to the first painted window (new process) | {fmt_time(cold)} | < 2 s | "
        f"{mark(np.median(cold) < 2.0)} |",
        f"| … with the three samples loaded and analysed | {fmt_time(cold_samples)} | | |",
        f"| cell edit to updated plots, 1000-point theodolite run ({edit.size} edits) | "
        f"{fmt_time(edit)} | < 50 ms | {mark(np.median(edit) < 0.05)} |",
    ]
    headline = []
    for label, (loads, big_edit, (burst, cancelled)) in rows.items():
        total = np.median([t for t, _, _, _ in loads])
        after_read = np.array([a for _, a, _, _ in loads])
        stalls = np.array([s for _, _, s, _ in loads])
        stall = float(np.median(stalls))
        beat = float(np.median([b for *_, b in loads]))
        lines += [
            f"| **1M-sample fringe file ({path.stat().st_size / 1e6:.0f} MB), {label}**: "
            f"import to result (median of {LOADS} loads) | {total:.2f} s | | |",
            f"| … from the file read to the result | {fmt_time(after_read)} | ≤ 1 s | "
            f"{mark(np.median(after_read) <= 1.0)} |",
            f"| … longest event-loop stall meanwhile (5 ms heartbeat, median gap "
            f"{beat * 1e3:.1f} ms), the result's first paints included | {stall * 1e3:.0f} ms "
            f"({stalls.min() * 1e3:.0f}–{stalls.max() * 1e3:.0f}) | ≤ 50 ms | "
            f"{mark(stall <= 0.05)} |",
            f"| … a cell edited to the new result ({big_edit.size} edits) | "
            f"{fmt_time(big_edit)} | ≤ 200 ms | {mark(np.median(big_edit) <= 0.2)} |",
            f"| … 4 cells typed 30 ms apart, to the last one's result | {burst:.2f} s; "
            f"{cancelled} superseded analyses cancelled | | |",
        ]
        headline.append(f"{label}: {total:.1f} s from import to result, longest pause "
                        f"{stall * 1e3:.0f} ms (target 50 ms, {mark(stall <= 0.05)}), an edit "
                        f"{fmt_time(big_edit).split(' (')[0]} to its result (target 200 ms, "
                        f"{mark(np.median(big_edit) <= 0.2)})")
    lines += [
        "",
        "A file of plain numbers is read into columns of numbers (models/readings/sheet.py "
        "NumericRows; a cell becomes text only when shown or edited), its bytes checked and "
        "parsed ~400 lines at a time so the window gets the interpreter back within half a "
        "millisecond: a paint calls Python hundreds of times and waits that long at each "
        "call (with chunks of 6000 lines, the paint of a result arriving during an import "
        "took 0.2–0.7 s: the longer pause seen in one load of three before). A superseded "
        "analysis stops at its next checkpoint (models/cancellation.py). The process runs "
        "BLAS on one thread and keeps freed arrays for reuse (app/process_setup.py). With N "
        "given the fit is 64 per-phase sums and an edit meets its target. With the phase "
        "estimated from the signals every edit estimates the phase again (the ellipse and "
        "its checks, ~40 ms), refines it over all million samples (four sweeps a block at a "
        "time from each sample's phasor, ~110 ms: models/fringe/harmonic_basis.py) and fits "
        "the drift of 16384 periods (~45 ms); with the window's own ~40 ms that is ~250 ms at "
        "best on this machine, numpy's floor for the method: each sweep is ~25 elementwise "
        "passes and one product, two threads were slower (the interpreter's lock), and no "
        "incremental form gives the same result as a fresh analysis. The pauses left are "
        "the paints of a new result (pyqtgraph draws the three "
        "error panels in ~20–40 ms). An autosave of a new million-row record runs in the "
        "background 20 s after the first unsaved change and steps aside while an analysis "
        "or an import runs.",
    ]
    report("4-gui", lines, headline=(
        f"Window (offscreen): cold start to the first paint {fmt_time(cold).split(' (')[0]} "
        f"(target 2 s, {mark(np.median(cold) < 2.0)}); a cell edit on a 1000-point theodolite "
        f"run updates the plots in {fmt_time(edit).split(' (')[0]} (target 50 ms, "
        f"{mark(np.median(edit) < 0.05)}). A 1M-sample fringe file, "
        + "; ".join(headline) + "."))
    assert np.median(cold) < 2.0
    assert np.median(edit) < 0.1  # regression guard (264 ms before); the 50 ms target is
    #                               reported above: this VM gives 34–58 ms from run to run
    for loads, _, (_, cancelled) in rows.values():
        assert np.median([s for _, _, s, _ in loads]) < 1.0  # regression guard: it was 1.1 s
        assert cancelled >= 1  # typed over a running analysis: it stopped


def _printed_edit(qtbot, window, key: str, column: str, edits: int = 12
                  ) -> tuple[np.ndarray, np.ndarray]:
    """(seconds, seconds of the GUI thread's CPU) from a cell typed on ``key``'s bundled
    sample, with the sample's certificate details, to the window updated and painted: the
    whole analysis runs on the GUI thread (a small sheet), the figures as printed with it."""
    presenter = window.presenter(key)
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    details = CertificateMetadata.from_dict(json.loads(
        (ROOT / "resources" / "samples" / f"certificate_{key}.json").read_text("utf-8")))
    presenter.certificate_details = lambda: details
    presenter.load_sample()
    QApplication.processEvents()
    model = presenter.table_model
    col = [c.key for c in presenter.kind.columns].index(column)
    done = []
    presenter.analysed.connect(lambda: done.append(time.perf_counter()))
    wall, cpu = np.empty(edits), np.empty(edits)
    for i in range(edits):
        value = float(presenter.sheet.text(i, col)) + (0.1 if i % 2 else -0.1)
        done.clear()
        t0, c0 = time.perf_counter(), time.thread_time()
        model.setData(model.index(i, col), f"{value:.3f}")
        while not done:  # the event loop, as the window runs it
            QApplication.processEvents()
        QApplication.processEvents()  # and the paint of what changed
        wall[i], cpu[i] = time.perf_counter() - t0, time.thread_time() - c0
        assert presenter.analyse_if_due()
    return wall, cpu


def test_printed_figures_edit(qtbot, tmp_path, report):
    window = _window(qtbot, tmp_path)
    rows = {key: _printed_edit(qtbot, window, key, column) for key, column in PRINTED_EDITS}
    lines = [
        "## The window: an edit whose figures are shown as the certificate prints them",
        "",
        "| bundled sample, its certificate details | cell edit to the updated window | "
        "the GUI thread's CPU |",
        "|---|---|---|",
    ]
    for key, (wall, cpu) in rows.items():
        lines.append(f"| {key} ({wall.size} edits) | {fmt_time(wall)} | {fmt_time(cpu)} |")
    lines += [
        "",
        "The sheets are small, so each edit is analysed on the GUI thread, the figures as the "
        "certificate prints them with it (review 62 F2). The positioning's certificate "
        "intervals (its reference standard's U in) are a bootstrap, united with the readings' "
        "own that the summary states: drawn once and kept with the result "
        "(models/uncertainty/figure_intervals.py ``cache``), not four times an edit. The "
        "cross-calibration's tilt effect is worked out once for the five budgets an edit "
        "asks for (models/crosscal/uncertainty.py). A take while capturing, or a large "
        "sheet, is analysed on a worker, and its figures as printed are made there too.",
    ]
    report("4-gui-printed", lines)
    # regression guards on the GUI thread's CPU (the wall time follows the other processes on
    # this shared VM: 0.6–1.3 s before): 395–420 ms and 276–293 ms before, 225 and 90 ms now
    assert np.median(rows["positioning"][1]) < 0.32
    assert np.median(rows["crosscal"][1]) < 0.18
