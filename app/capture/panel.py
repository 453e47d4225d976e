"""The window's capture panel: *Connect…* to an instrument, its live readout (the value,
how settled it is, the Allan deviation), *Take reading*, which fills the current row's
cells as one undo step, auto-take, the workbench's guidance and the raw frames.

The connection is a :class:`app.capture.worker.CaptureWorker` (its own thread); a timer
empties its queue every 20 ms, so the window never waits for the instrument. Take
reading fills the columns of the current row whose keys are the reading's
(``ac_x_arcsec``/``ac_y_arcsec`` on the polygon workbench, ``azimuth_deg`` on the
theodolite workbench, and ``zenith_deg`` into its vertical column when that column is
set to read the zenith angle); a readout's single value goes to the current cell.

*Auto-take* feeds every reading to a stability gate (models/capture/stability.py): when
the output has stayed within the window for the dwell, the mean of those frames is
taken as if *Take reading* was pressed. A workbench that guides (the capability
``GuidesAcquisition`` of models/workbench.py; models/capture/guidance.py) says what to
do next ("go to face 7 (encoder ≈ 105°)", "θ = 12°"); its cells saying which point a
reading is of are filled with it, and with *readings per point* n > 1 the gate takes
the n readings of a point one after another from fresh frames, then waits for the
instrument to move. The n rows of a point are
averaged by the workbench, and their s/√n is the budget's Type A input
(models/readings/repeats.py).

Every line the instrument sends is kept (models/capture/raw_record.py): a session per
connection, filed under the workbench shown when it was made, with the rows its readings
went to; the window saves them with the project and the register records them (and
their SHA-256) with a certificate.
"""

from __future__ import annotations

import math
import queue
import time
from collections import deque

import numpy as np
from PySide6.QtCore import QTimer
from PySide6.QtGui import QKeySequence
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QDockWidget,
    QDoubleSpinBox,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QSizePolicy,
    QSpinBox,
    QVBoxLayout,
    QWidget,
)

from app.capture.instruments import INSTRUMENTS, reading_columns
from app.capture.worker import CaptureWorker, Fault, Reading
from models.capture.allan import allan_deviation
from models.capture.raw_record import frame_text
from models.capture.stability import StabilityGate
from models.workbench import GuidesAcquisition
from widgets.i18n import live, tr, translated

__all__ = ["CapturePanel", "ConnectDialog", "TAKE_READING_KEY"]

#: the key of Take reading (a foot switch is set to send it)
TAKE_READING_KEY = "F9"
#: the stability shown is the spread of the frames of the last second
SPREAD_SECONDS = 1.0
#: how often the guidance is worked out again while connected (seconds of frames)
GUIDE_EVERY_S = 0.25
#: the longest a timer tick spends taking in readings (the window stays responsive)
DRAIN_BUDGET_S = 0.010
#: the live readout's texts are redrawn at most this often (a 250 Hz stream would
#: otherwise repaint the panel at every 20 ms tick); the newest reading is always shown
SHOW_EVERY_S = 0.1

class ConnectDialog(QDialog):
    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.setWindowTitle(tr("Connect to an instrument"))
        form = QFormLayout()
        self.instrument = QComboBox()
        for key, text in (("autocollimator", tr("Autocollimator (ELCOMAT kind)")),
                          ("theodolite", tr("Theodolite (Leica GeoCOM)")),
                          ("readout", tr("Readout (one line per reading)"))):
            self.instrument.addItem(text, key)
        self.port = QLineEdit()
        self.port.setPlaceholderText("/dev/ttyUSB0, COM3, tcp://host:port")
        self.baud = QSpinBox()
        self.baud.setRange(0, 4_000_000)
        self.baud.setSpecialValueText("9600")
        form.addRow(tr("Instrument"), self.instrument)
        form.addRow(tr("Port"), self.port)
        form.addRow(tr("Baud rate"), self.baud)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok
                                   | QDialogButtonBox.StandardButton.Cancel)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        layout = QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(buttons)

    def choice(self) -> tuple[str, str, int | None]:
        return (self.instrument.currentData(), self.port.text().strip(), self.baud.value() or None)


class _Session:
    """One connection's raw frames as they will be stored, converted as they arrive (a
    project saved during a long stream converts only the frames since the last save)."""

    def __init__(self, workbench: str, kind: str, worker: CaptureWorker) -> None:
        self.workbench, self.kind, self.worker = workbench, kind, worker
        self.frames: list[list] = []
        self.takes: list[list[int]] = []

    def stored(self) -> dict:
        raw = self.worker.raw
        for t, line, used in raw[len(self.frames):len(raw)]:
            self.frames.append([round(float(t), 6), frame_text(line), int(bool(used))])
        return {"instrument": self.kind, "port": self.worker.port, "baud": int(self.worker.baud),
                "started_utc": self.worker.started_utc, "frames": list(self.frames),
                "takes": [list(t) for t in self.takes]}


class CapturePanel(QDockWidget):
    def __init__(self, window) -> None:
        super().__init__(window)
        self.window_ = window
        live(self.setWindowTitle, tr("Instrument"))
        self.setObjectName("capture_panel")
        self.worker: CaptureWorker | None = None
        self.kind = ""
        self.frames: deque[tuple[float, tuple[float, ...], int]] = deque(maxlen=8192)
        self.latest: Reading | None = None
        self.received = 0  # readings taken in from the worker since connecting
        #: finished sessions per workbench (stored form), and the one of this connection
        self.sessions: dict[str, list[dict]] = {}
        self.session: _Session | None = None
        self.gate: StabilityGate | None = None
        self._origin: tuple[float, ...] | None = None
        self.next_reading = None  # the workbench's NextReading for the current row
        self._guide_due = 0.0
        self._last_fault = ""  # the fault the link recovered from, said while connected
        #: rows filled by Take reading or auto-take: (workbench, row, values)
        self.taken: list[tuple[str, int, tuple[float, ...]]] = []
        body = QWidget()
        layout = QVBoxLayout(body)
        self.status = QLabel()
        live(self.status.setText, tr("Not connected"))
        self.guide = QLabel("")
        self.guide.setStyleSheet("font-size: 12pt; font-weight: bold; color: #0b5394;")
        self.value = QLabel("—")
        self.value.setStyleSheet("font-size: 16pt; font-family: monospace;")
        self.stability = QLabel("")
        self.allan = QLabel("")
        buttons = QHBoxLayout()
        self.connect_button = QPushButton()
        live(self.connect_button.setText, tr("Connect…"))
        self.connect_button.clicked.connect(self.connect_dialog)
        self.take_button = QPushButton()
        live(self.take_button.setText, tr("Take reading (F9)"))
        self.take_button.setShortcut(QKeySequence(TAKE_READING_KEY))
        self.take_button.clicked.connect(lambda: self.take_reading())
        self.take_button.setEnabled(False)
        buttons.addWidget(self.connect_button)
        buttons.addWidget(self.take_button)
        # auto-take: the stability gate's window and dwell
        self.auto = QCheckBox()
        live(self.auto.setText, tr("Auto-take when stable"))
        self.auto.toggled.connect(self._gate_changed)
        self.window_box = QDoubleSpinBox()
        self.window_box.setRange(0.001, 3600.0)
        self.window_box.setDecimals(3)
        self.window_box.setValue(0.5)
        self.window_box.setSuffix(' "')
        live(self.window_box.setToolTip, tr("The spread allowed over the dwell (arcseconds; a "
                                            "readout's own unit)"))
        self.dwell_box = QDoubleSpinBox()
        self.dwell_box.setRange(0.01, 600.0)
        self.dwell_box.setDecimals(2)
        self.dwell_box.setValue(1.0)
        self.dwell_box.setSuffix(" s")
        for box in (self.window_box, self.dwell_box):
            box.valueChanged.connect(self._gate_changed)
        auto_form = QFormLayout()
        self.window_label, self.dwell_label = QLabel(), QLabel()
        live(self.window_label.setText, tr("Window"))
        live(self.dwell_label.setText, tr("Dwell"))
        auto_form.addRow(self.window_label, self.window_box)
        auto_form.addRow(self.dwell_label, self.dwell_box)
        self.auto_state = QLabel("")
        for widget in (self.status, self.guide, self.value, self.stability, self.allan,
                       self.auto_state):
            widget.setWordWrap(True)
            # a longer text wraps, never widens the panel: the plots beside it are not
            # resized (and redrawn) while a stream updates the texts 50 times a second
            widget.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        for widget in (self.status, self.guide, self.value, self.stability, self.allan):
            layout.addWidget(widget)
        layout.addLayout(buttons)
        layout.addWidget(self.auto)
        layout.addLayout(auto_form)
        layout.addWidget(self.auto_state)
        body.setMinimumWidth(320)
        layout.addStretch(1)
        self.setWidget(body)
        self.timer = QTimer(self)
        self.timer.setInterval(20)
        self.timer.timeout.connect(self.drain)
        self._allan_due = 0.0
        self._show_due = 0.0  # perf_counter time the readout's texts may be redrawn
        self._show_pending = False

    # ------------------------------------------------------------ connecting
    def connect_dialog(self) -> None:
        dialog = ConnectDialog(self)
        if dialog.exec() == QDialog.DialogCode.Accepted:
            kind, port, baud = dialog.choice()
            if port:
                self.connect_to(kind, port, baud)

    def connect_to(self, kind: str, port: str, baud: int | None = None, **worker_options) -> None:
        self.disconnect_instrument()
        self.kind = kind
        self.frames.clear()
        self.latest = None
        self.received = 0
        self._show_due, self._show_pending = 0.0, False
        self.worker = CaptureWorker(port, INSTRUMENTS[kind](), baud, **worker_options).start()
        self.session = _Session(self.window_.current.kind.key, kind, self.worker)
        self._last_fault = ""
        self._gate_changed()
        self.status.setText(tr("Connecting to {port}…").format(port=port))
        self.timer.start()

    def disconnect_instrument(self) -> None:
        worker, self.worker = self.worker, None
        if worker is not None:
            worker.stop()
            self._drain(worker)  # the readings already queued are taken in, never dropped
        self._close_session()
        self.timer.stop()
        self.take_button.setEnabled(False)

    def _close_session(self) -> None:
        session, self.session = self.session, None
        if session is not None and session.worker.raw:
            self.sessions.setdefault(session.workbench, []).append(session.stored())

    def closeEvent(self, event) -> None:  # noqa: N802
        self.disconnect_instrument()
        super().closeEvent(event)

    # ------------------------------------------------------------ the raw frames
    def raw_sessions(self, workbench: str) -> list[dict]:
        """The sessions of a workbench in their stored form, this connection's included."""
        out = list(self.sessions.get(workbench, []))
        if self.session is not None and self.session.workbench == workbench \
                and self.session.worker.raw:
            out.append(self.session.stored())
        return out

    def raw_capture(self) -> dict[str, list[dict]]:
        """Every workbench's sessions, for the project file."""
        keys = set(self.sessions) | ({self.session.workbench} if self.session else set())
        return {k: v for k in sorted(keys) if (v := self.raw_sessions(k))}

    def load_raw_capture(self, raw: dict[str, list[dict]]) -> None:
        """The sessions of a project opened (or none for a new one); a connection open now
        goes on in a session of its own."""
        self.sessions = {k: list(v) for k, v in raw.items()}

    # ------------------------------------------------------------ auto-take
    def _gate_changed(self, *_args) -> None:
        self.gate = (StabilityGate(self.window_box.value(), self.dwell_box.value())
                     if self.auto.isChecked() else None)
        self._origin = None
        self.auto_state.setText("")

    @property
    def _scale(self) -> float:
        """The gate's window is in arcseconds: a theodolite's degrees are scaled to them."""
        return 3600.0 if self.kind == "theodolite" else 1.0

    def _feed_gate(self, reading: Reading) -> None:
        gate, scale = self.gate, self._scale
        if gate is None:
            return
        # angles in degrees go to the gate as their difference from the first frame's,
        # wrapped to ±180°, so a position at 0°/360° settles (and averages) where it is
        if self._origin is None or len(self._origin) != len(reading.values):
            self._origin = reading.values if scale != 1.0 else (0.0,) * len(reading.values)
        offsets = [v - o for v, o in zip(reading.values, self._origin, strict=True)]
        if scale != 1.0:
            offsets = [(d + 180.0) % 360.0 - 180.0 for d in offsets]
        step = self.next_reading
        gate.retake = bool(step is not None and step.reading < step.of)
        taken = gate.feed(reading.time_s, [d * scale for d in offsets])
        if taken is None:
            return
        means = tuple(o + float(m) / scale for m, o in zip(taken.mean, self._origin, strict=True))
        if scale != 1.0:
            means = tuple(m % 360.0 for m in means)
        indices = [f for _, _, f in self.frames]
        first = indices[-taken.frames] if taken.frames <= len(indices) else reading.frame
        self.take_reading(means, (first, reading.frame))

    def _show_gate(self) -> None:
        if self.gate is None or self.latest is None:
            self.auto_state.setText("")
            return
        phase, part = self.gate.progress(self.latest.time_s)
        if phase == "taken":
            self.auto_state.setText(tr("Auto-take: taken; move to the next point"))
        else:
            self.auto_state.setText(tr("Auto-take: settling, {percent} % of the dwell").format(
                percent=f"{100 * part:.0f}"))

    @property
    def auto_phase(self) -> str:
        """"off", "settling" or "taken" (waiting for the instrument to move)."""
        if self.gate is None:
            return "off"
        return self.gate.progress(self.latest.time_s if self.latest else 0.0)[0]

    # ------------------------------------------------------------ guidance
    def update_guide(self) -> None:
        """What the workbench says to do next, for the row the next reading goes to."""
        presenter = self.window_.current
        kind = presenter.kind
        if not isinstance(kind, GuidesAcquisition):
            self.next_reading = None
            self.guide.setText("")
            return
        model = presenter.table_model
        sheet = model.sheet
        index = presenter.view.table.currentIndex()
        row = index.row() if index.isValid() else sheet.row_count
        keys = [c.key for c in sheet.columns]

        def cells(r: int) -> dict[str, str]:
            if r >= sheet.row_count:
                return dict.fromkeys(keys, "")
            return {k: sheet.text(r, c) for c, k in enumerate(keys)}

        step = presenter.view.table.nominal_step or 0.0
        self.next_reading = kind.acquisition_guide([cells(r) for r in range(min(row, sheet.row_count))],
                                  cells(row), presenter.settings, step)
        self.guide.setText(tr("Next: {what}").format(what=translated(self.next_reading.text)))

    # ------------------------------------------------------------ the live readout
    def drain(self) -> None:
        """What the worker has queued, without waiting: for at most ``DRAIN_BUDGET_S`` a
        tick, so a stream faster than the window can follow makes a backlog (worked off in
        the next ticks), never a frozen window."""
        if self.worker is not None:
            self._drain(self.worker, time.perf_counter() + DRAIN_BUDGET_S)

    def _drain(self, worker: CaptureWorker, until: float = math.inf) -> None:
        fresh = ended = False
        while time.perf_counter() < until:
            try:
                event = worker.events.get_nowait()
            except queue.Empty:
                break
            if isinstance(event, Fault):
                reason = translated(event.message)
                self._last_fault = reason
                self.status.setText(reason if event.final
                                    else tr("{reason} (reconnecting)").format(reason=reason))
                self.status.setStyleSheet("color: #b00020;")
                ended = ended or event.final
                continue
            self.received += 1
            self.frames.append((event.time_s, event.values, event.frame))
            self.latest = event
            fresh = True
            if event.time_s >= self._guide_due:
                self._guide_due = event.time_s + GUIDE_EVERY_S
                self.update_guide()
            self._feed_gate(event)
        if fresh and self.worker is worker and not ended:
            if self.status.styleSheet():  # a style set anew repolishes the label
                self.status.setStyleSheet("")
            self.status.setText(tr("Connected: {port}").format(port=worker.port)
                                if not self._last_fault else
                                tr("Connected: {port} (reconnected after: {reason})").format(
                                    port=worker.port, reason=self._last_fault))
            self.take_button.setEnabled(True)
        if fresh or self._show_pending:
            now = time.perf_counter()
            self._show_pending = now < self._show_due and self.worker is worker and not ended
            if not self._show_pending:
                self._show_due = now + SHOW_EVERY_S
                self._show()
                self._show_gate()
        if ended and self.worker is worker:
            self.disconnect_instrument()

    def _show(self) -> None:
        reading = self.latest
        unit = {"arcsec": '"', "deg": "°"}.get(reading.unit, f" {reading.unit}")
        self.value.setText("   ".join(f"{v:.6f}{unit}" if reading.unit == "deg" else f"{v:.3f}{unit}"
                                      for v in reading.values))
        now = reading.time_s
        recent = []
        for t, v, _ in reversed(self.frames):
            if t < now - SPREAD_SECONDS:
                break
            recent.append(v)
        recent = np.array(recent)
        if len(recent) > 1:
            spread = recent.max(axis=0) - recent.min(axis=0)
            scale = 3600.0 if reading.unit == "deg" else 1.0
            shown = "   ".join(f"{s * scale:.3f}" for s in spread)
            self.stability.setText(tr("Spread over the last second: {spread}{unit}").format(
                spread=shown, unit='"' if scale != 1.0 or reading.unit == "arcsec" else ""))
        if now >= self._allan_due and len(self.frames) >= 16:
            self._allan_due = now + 1.0
            times = np.array([t for t, _, _ in self.frames])
            tau0 = float(np.median(np.diff(times)))
            first = np.array([v[0] for _, v, _ in self.frames])
            if tau0 > 0:
                taus, adev = allan_deviation(first, tau0)
                scale = 3600.0 if reading.unit == "deg" else 1.0
                self.allan.setText(tr("Allan deviation (first axis): {figures}").format(
                    figures=", ".join(f"{a * scale:.3g} ({t:.3g} s)"
                                      for t, a in list(zip(taus, adev, strict=True))[::2])))

    # ------------------------------------------------------------ take reading
    def take_reading(self, values: tuple[float, ...] | None = None,
                     frames: tuple[int, int] | None = None) -> str:
        """Fill the current row with the latest reading, or with ``values`` (an auto-take's
        mean of the raw ``frames`` first…last), and the cells the guidance says (one undo
        step); what it did."""
        reading = self.latest
        if reading is None:
            return ""
        values = reading.values if values is None else values
        frames = (reading.frame, reading.frame) if frames is None else frames
        presenter = self.window_.current
        table = presenter.view.table
        model = presenter.table_model
        index = table.currentIndex()
        row = index.row() if index.isValid() else model.sheet.row_count
        keys = [c.key for c in model.sheet.columns]
        changes = []
        if self.kind == "readout":
            column = index.column() if index.isValid() else -1
            if column >= 0:
                changes.append((row, column, f"{values[0]:.12g}"))
        else:
            vertical_zenith = presenter.settings.get("vertical_reading") == "zenith"
            for (_, column), value in zip(reading_columns(self.kind, keys, vertical_zenith),
                                          values, strict=False):
                if column is not None and column >= 0:
                    changes.append((row, column, f"{value:.12g}"))
        if not changes:
            self.status.setText(tr("This workbench has no column for this instrument's "
                                   "reading: choose a cell first (readout) or another "
                                   "workbench"))
            return ""
        self.update_guide()
        if self.next_reading is not None:
            for key, text in self.next_reading.fill.items():
                blank = row >= model.sheet.row_count or not model.sheet.text(
                    row, keys.index(key)).strip()
                if key in keys and blank:
                    changes.append((row, keys.index(key), text))
        model.set_cells(changes, tr("Take reading (row {row})").format(row=row + 1))
        if self.session is not None and frames[0] >= 0:
            self.session.takes.append([row, frames[0], frames[1]])
        self.taken.append((presenter.kind.key, row, tuple(values)))
        table.next_row(row)
        self.update_guide()
        return f"row {row + 1}"
