"""The window's capture panel: *Connect…* to an instrument, its live readout (the value,
how settled it is, the Allan deviation) and *Take reading*, which fills the current
row's cells as one undo step.

The connection is a :class:`app.capture.worker.CaptureWorker` (its own thread); a timer
empties its queue every 20 ms, so the window never waits for the instrument. Take
reading fills the columns of the current row whose keys are the reading's
(``ac_x_arcsec``/``ac_y_arcsec`` on the polygon workbench, ``azimuth_deg`` on the
theodolite workbench, and ``zenith_deg`` into its vertical column when that column is
set to read the zenith angle); a readout's single value goes to the current cell.
"""

from __future__ import annotations

import queue
from collections import deque

import numpy as np
from PySide6.QtCore import QTimer
from PySide6.QtGui import QKeySequence
from PySide6.QtWidgets import (
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QDockWidget,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QSpinBox,
    QVBoxLayout,
    QWidget,
)

from app.capture.instruments import INSTRUMENTS
from app.capture.worker import CaptureWorker, Fault, Reading
from models.capture.allan import allan_deviation
from widgets.i18n import live, tr, translated

__all__ = ["CapturePanel", "ConnectDialog", "TAKE_READING_KEY"]

#: the key of Take reading (a foot switch is set to send it)
TAKE_READING_KEY = "F9"
#: the stability shown is the spread of the frames of the last second
SPREAD_SECONDS = 1.0


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


class CapturePanel(QDockWidget):
    def __init__(self, window) -> None:
        super().__init__(window)
        self.window_ = window
        live(self.setWindowTitle, tr("Instrument"))
        self.setObjectName("capture_panel")
        self.worker: CaptureWorker | None = None
        self.kind = ""
        self.frames: deque[tuple[float, tuple[float, ...]]] = deque(maxlen=8192)
        self.latest: Reading | None = None
        body = QWidget()
        layout = QVBoxLayout(body)
        self.status = QLabel()
        live(self.status.setText, tr("Not connected"))
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
        self.take_button.clicked.connect(self.take_reading)
        self.take_button.setEnabled(False)
        buttons.addWidget(self.connect_button)
        buttons.addWidget(self.take_button)
        for widget in (self.status, self.value, self.stability, self.allan):
            widget.setWordWrap(True)
            layout.addWidget(widget)
        layout.addLayout(buttons)
        layout.addStretch(1)
        self.setWidget(body)
        self.timer = QTimer(self)
        self.timer.setInterval(20)
        self.timer.timeout.connect(self.drain)
        self._allan_due = 0.0

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
        self.worker = CaptureWorker(port, INSTRUMENTS[kind](), baud, **worker_options).start()
        self.status.setText(tr("Connecting to {port}…").format(port=port))
        self.timer.start()

    def disconnect_instrument(self) -> None:
        if self.worker is not None:
            self.worker.stop()
            self.worker = None
        self.timer.stop()
        self.take_button.setEnabled(False)

    def closeEvent(self, event) -> None:  # noqa: N802
        self.disconnect_instrument()
        super().closeEvent(event)

    # ------------------------------------------------------------ the live readout
    def drain(self) -> None:
        """Everything the worker has queued, without waiting."""
        worker = self.worker
        if worker is None:
            return
        fresh = False
        while True:
            try:
                event = worker.events.get_nowait()
            except queue.Empty:
                break
            if isinstance(event, Fault):
                reason = translated(event.message)
                self.status.setText(reason if event.final
                                    else tr("{reason} (reconnecting)").format(reason=reason))
                self.status.setStyleSheet("color: #b00020;")
                if event.final:
                    self.disconnect_instrument()
                continue
            self.frames.append((event.time_s, event.values))
            self.latest = event
            fresh = True
        if fresh:
            self.status.setStyleSheet("")
            self.status.setText(tr("Connected: {port}").format(port=worker.port))
            self.take_button.setEnabled(True)
            self._show()

    def _show(self) -> None:
        reading = self.latest
        unit = {"arcsec": '"', "deg": "°"}.get(reading.unit, f" {reading.unit}")
        self.value.setText("   ".join(f"{v:.6f}{unit}" if reading.unit == "deg" else f"{v:.3f}{unit}"
                                      for v in reading.values))
        now = reading.time_s
        recent = np.array([v for t, v in self.frames if t >= now - SPREAD_SECONDS])
        if len(recent) > 1:
            spread = recent.max(axis=0) - recent.min(axis=0)
            scale = 3600.0 if reading.unit == "deg" else 1.0
            shown = "   ".join(f"{s * scale:.3f}" for s in spread)
            self.stability.setText(tr("Spread over the last second: {spread}{unit}").format(
                spread=shown, unit='"' if scale != 1.0 or reading.unit == "arcsec" else ""))
        if now >= self._allan_due and len(self.frames) >= 16:
            self._allan_due = now + 1.0
            times = np.array([t for t, _ in self.frames])
            tau0 = float(np.median(np.diff(times)))
            first = np.array([v[0] for _, v in self.frames])
            if tau0 > 0:
                taus, adev = allan_deviation(first, tau0)
                scale = 3600.0 if reading.unit == "deg" else 1.0
                self.allan.setText(tr("Allan deviation (first axis): {figures}").format(
                    figures=", ".join(f"{a * scale:.3g} ({t:.3g} s)"
                                      for t, a in list(zip(taus, adev, strict=True))[::2])))

    # ------------------------------------------------------------ take reading
    def take_reading(self) -> str:
        """Fill the current row with the latest reading (one undo step); what it did."""
        reading = self.latest
        if reading is None:
            return ""
        presenter = self.window_.current
        table = presenter.view.table
        model = presenter.table_model
        index = table.currentIndex()
        row = index.row() if index.isValid() else model.sheet.row_count
        keys = [c.key for c in model.sheet.columns]
        changes = []
        columns = INSTRUMENTS[self.kind]().columns
        if self.kind == "readout":
            column = index.column() if index.isValid() else -1
            if column >= 0:
                changes.append((row, column, f"{reading.values[0]:.12g}"))
        else:
            vertical_zenith = presenter.settings.get("vertical_reading") == "zenith"
            for key, value in zip(columns, reading.values, strict=False):
                target = key
                if key == "zenith_deg" and vertical_zenith and "elevation_deg" in keys:
                    target = "elevation_deg"
                if target in keys:
                    changes.append((row, keys.index(target), f"{value:.12g}"))
        if not changes:
            self.status.setText(tr("This workbench has no column for this instrument's "
                                   "reading: choose a cell first (readout) or another "
                                   "workbench"))
            return ""
        model.set_cells(changes, tr("Take reading (row {row})").format(row=row + 1))
        table.next_row(row)
        return f"row {row + 1}"
