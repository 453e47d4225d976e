"""The window's capture panel: a dock (left, right or bottom; where it was is remembered
with the window's state) with up to two instruments at once — e.g. an autocollimator for
AC x/y and a readout for the encoder column — each with its own link, status, fault
handling, *Connect…* and *Disconnect*; the live readout of each (the value, how settled
it is, the Allan deviation of the first instrument), *Take reading*, which fills one row
from both at the same moment as one undo step, auto-take, the workbench's guidance and
the raw frames.

Each connection is a :class:`app.capture.worker.CaptureWorker` (its own thread); a timer
empties their queues every 20 ms, so the window never waits for an instrument. A value
after which the worker has seen no reading for ``STALE_S`` of its own clock (or after a
fault) is greyed and marked "link lost" — never on the window's clock: a worker starved of
CPU is no lost link (capture80); the
statistics and the guidance start afresh on a new connection and when the workbench in
front changes. The panel's body scrolls rather than widening the window: the window never
grows past its screen.

**Where a take goes** (models/capture/take_cells.py): the row the cursor is on when the
cells the take fills are blank there, else the next empty point below (a row the plan has
pre-filled with its face or target counts as empty), else a new row; a take never writes
over a filled reading, and the table scrolls to the row it filled. Auto-take goes to the
point the guidance names, worked out for that same row.

**What a cell shows**: the value rounded to the instrument's resolution (a setting per
instrument: 0.001″ … 1″, 1 µrad, or as sent), in the column's angle format (D°M′S″ where
the column's cells are written so, else decimal degrees); the elevation is 90° − the
zenith angle where the vertical column reads elevation. The raw frames (and
``capture --out``) keep the instrument's full precision. A polygon face's deviation is
filled from the rows of the same face that have one (the polygon's certificate, sent or
typed once per face).

Columns: ``ac_x_arcsec``/``ac_y_arcsec`` from an autocollimator, ``azimuth_deg`` and the
vertical column from a theodolite; a readout's single value goes to the column chosen for
it (by default the workbench's encoder, reference or θ column: ``READOUT_COLUMNS``; or
the current cell's). A connected instrument whose reading a take cannot place (no column of
its own) is said in the panel, never dropped without a word; a reading far from the one the
plan expects (more than half the pitch between faces; positioning: nearer another target
of the plan than its row's, models/capture/wrong_target.py) is warned of and kept. A
position in degrees (positioning's measured) is written in the turn of its row's target
(models/capture/take_cells.py in_turn_of).

*Auto-take* feeds every reading of the first instrument to a stability gate
(models/capture/stability.py): when the output has stayed within the window for the
dwell, the mean of those frames is taken as if *Take reading* was pressed (the second
instrument's latest reading with it). A workbench that guides (``GuidesAcquisition`` of
models/workbench.py; models/capture/guidance.py) says what to do next; its cells saying
which point a reading is of are filled with it, and with *readings per point* n > 1 the
gate takes the n readings of a point one after another from fresh frames.

Every line an instrument sends is kept (models/capture/raw_record.py): a session per
connection and workbench in front (another workbench in front starts a session of its
own), filed under that workbench, with the rows its readings
went to (``takes``: row, first and last frame; the frames carry their times); the window
saves them with the project and the register records them with a certificate.
"""

from __future__ import annotations

import contextlib
import math
import queue
import re
import select
import subprocess
import sys
import time
from collections import deque
from collections.abc import Callable, Mapping
from datetime import datetime, timedelta
from pathlib import Path

import numpy as np
from PySide6.QtCore import QSettings, Qt, QTimer
from PySide6.QtGui import QKeySequence, QShortcut
from PySide6.QtWidgets import (
    QBoxLayout,
    QCheckBox,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QDockWidget,
    QDoubleSpinBox,
    QFormLayout,
    QGridLayout,
    QGroupBox,
    QHeaderView,
    QLabel,
    QLineEdit,
    QPushButton,
    QScrollArea,
    QSizePolicy,
    QSpinBox,
    QVBoxLayout,
    QWidget,
)

from app.capture.instruments import INSTRUMENTS
from app.capture.worker import CaptureWorker, Fault, NoTarget, Reading, Stale
from models.capture.allan import allan_deviation, last_even_run
from models.capture.guidance import degrees_text
from models.capture.raw_record import FRAMES_PER_BLOCK, FrameBlocks, frame_text
from models.capture.repeat_check import turned_away
from models.capture.stability import (
    ANGLE_UNITS,
    OUT_OF_VIEW_GAP_S,
    StabilityGate,
    UnwrappedAngles,
    gate_scale,
    steady_motion,
)
from models.capture.take_cells import (
    MICRORADIAN_ARCSEC,
    cell_step,
    cell_text,
    cleared_row,
    column_is_dms,
    elevation_from_zenith_deg,
    fixed_text,
    in_turn_of,
    next_empty_point,
)
from models.capture.take_rows import UNDONE, session_takes, take_key
from models.capture.wrong_target import off_target
from models.readings.angles import parse_angle_deg
from models.workbench import GuidesAcquisition
from widgets.i18n import declared, live, on_language_change, said_again, tr, translated
from widgets.settings_form import ignore_unfocused_wheel

__all__ = ["TAKE_READING_KEY", "CapturePanel", "ConnectDialog", "InstrumentLink"]

#: the key of Take reading (a foot switch is set to send it)
TAKE_READING_KEY = "F9"
def _unit_symbol(unit: str) -> str:
    """What follows a figure in the window's unit for a reading in ``unit``: ″ for an angle
    (arcseconds), else the readout's own unit after a space ("" for none)."""
    return '"' if unit in ANGLE_UNITS else (f" {unit}" if unit else "")


def _significant(value: float, digits: int = 3) -> str:
    """``value`` with ``digits`` significant digits, never in scientific notation."""
    return np.format_float_positional(float(value), precision=digits, unique=False,
                                      fractional=False, trim="-")


def last_still_run(values: np.ndarray, window: float) -> int:
    """Where the frames since the reading last moved begin: a move is a step from one frame
    to the next larger than the stability window (in the same unit as ``values``) and than
    five times the frames' own noise (a noisy instrument is not moving)."""
    if len(values) < 2:
        return 0
    steps = np.abs(np.diff(values))
    noise = 1.4826 * float(np.median(steps)) / np.sqrt(2.0)
    moved = np.flatnonzero(steps > max(window, 5.0 * noise))
    return int(moved[-1]) + 1 if len(moved) else 0


#: the stability shown is the spread of the frames of the last second
SPREAD_SECONDS = 1.0
#: how often the guidance is worked out again while connected (seconds of frames)
GUIDE_EVERY_S = 0.25
#: the longest a timer tick spends taking in readings (the window stays responsive)
DRAIN_BUDGET_S = 0.010
#: the live readout's texts are redrawn at most this often (a 250 Hz stream would
#: otherwise repaint the panel at every 20 ms tick); the newest reading is always shown
SHOW_EVERY_S = 0.1
#: a value after which the worker has read no reading for this long (its clock, from a read
#: begun after it: app/capture/worker.py Stale) is greyed and marked "link lost"
STALE_S = 1.0
#: the panel's narrowest: it scrolls rather than widening the window
PANEL_MIN_WIDTH = 240
#: the panel's highest when docked at the bottom (its parts side by side fit in it)
BOTTOM_PANEL_MAX_HEIGHT = 200
#: the plot tabs' lowest (their tab bar and ~200 px of plot) while the panel is at the bottom
PLOT_TABS_MIN_HEIGHT = 232
#: the readings' rows in sight while the panel is open, the set-up giving way (24 faces read:
#: the rows being filled seen)
READINGS_ROWS_IN_SIGHT = 6
#: the window's least height (px) for the panel at the bottom: a shorter window gets it at the
#: right. At the bottom it made the window at least ~557 px tall (the plots' 232 px, the
#: set-up's 100, the panel's own): on a 1280×720 screen at 150 % (853×480) the window grew
#: past the screen and the readings table kept 1–4 rows in sight, the guidance cut in
#: Chinese; a 662 px window (1280×720 at 100 %) keeps 9 rows (7 in Chinese), 6 at ~620 (gui81)
BOTTOM_DOCK_LEAST_WINDOW_HEIGHT = 620
#: Qt's "no maximum" of a widget's size
QWIDGETSIZE_MAX = (1 << 24) - 1
#: the columns a readout goes to unless another is chosen, the first the workbench has: the
#: encoder's (polygon, cross-calibration), the reference's (positioning), θ (theodolite,
#: fringe). "The current cell" by default took nothing when the cursor was on another
#: instrument's column (#62 review F5: a blank encoder cell, no take in the raw record)
READOUT_COLUMNS = ("encoder_deg", "measured", "theta_deg")
#: the columns of the table's own position (the polygon's and the cross-calibration's
#: encoder): a second instrument read into one shows the table's move to the next face
TABLE_COLUMNS = ("encoder_deg",)
#: with the pitch between faces not known yet (no *faces* set, too few faces read), the
#: table's move is half of 1°, the finest pitch the polygon's guide knows (360 faces)
TABLE_PITCH_UNKNOWN_DEG = 1.0
#: the instruments' names for their values, where the workbench has no column for them
_VALUE_NAMES = {"ac_x_arcsec": "x", "ac_y_arcsec": "y", "azimuth_deg": "Hz", "zenith_deg": "V"}
#: a nominal the plan writes (the encoder at the face) is written to this (″)
NOMINAL_RESOLUTION_ARCSEC = 0.01
#: settings keys (per instrument kind)
PORT_SETTING = "capture/port/{kind}"
BAUD_SETTING = "capture/baud/{kind}"
RESOLUTION_SETTING = "capture/resolution/{kind}"
#: the resolution an instrument is given until one is chosen (arcseconds; 0: as sent)
DEFAULT_RESOLUTION_ARCSEC = {"autocollimator": 0.01, "theodolite": 0.1, "readout": 0.0}
#: the choices of resolution (arcseconds), with their names
RESOLUTION_CHOICES = ((0.0, None), (0.001, '0.001"'), (0.01, '0.01"'), (0.1, '0.1"'),
                      (1.0, '1"'), (MICRORADIAN_ARCSEC, "1 µrad"))

_STALE_STYLE = "font-size: 16pt; font-family: monospace; color: #9e9e9e;"
_VALUE_STYLE = "font-size: 16pt; font-family: monospace;"


def _instrument_names() -> tuple[tuple[str, str], ...]:
    return (("autocollimator", tr("Autocollimator (ELCOMAT kind)")),
            ("theodolite", tr("Theodolite (Leica GeoCOM)")),
            ("readout", tr("Readout (one line per reading)")))


def _unwrapped_deg(values, origin):
    """Angles in degrees as ``origin`` plus their difference from it wrapped to ±180°: a
    direction near 0°/360° is not 360° apart from itself."""
    values = np.asarray(values, dtype=float)
    return origin + (values - origin + 180.0) % 360.0 - 180.0


def _without_port(reason: str, port: str) -> str:
    """A fault's reason less the port it starts with, said once already beside it
    ("Connected: tcp://…:47001 (reconnected after: no answer for 1 s)"): the port twice
    made the status 3–4 lines longer at a side of a 1280×720 screen (#62 review)."""
    for colon in (": ", "：", ":"):
        if reason.startswith(port + colon):
            return reason[len(port) + len(colon):].lstrip()
    return reason


#: reconnections the window tries in a row before it says the link is lost for good
WINDOW_RETRIES = 12
#: the most requests a second the window sends an instrument that is asked (a readout, a
#: theodolite, a polled autocollimator), as ``capture --poll-rate``'s default: a take uses
#: the latest reading, at most 50 ms old at 20 Hz (a hand on the foot switch is slower), and
#: auto-take's dwell (1 s by default) sees 20 readings. Unlimited, a readout that answers at
#: once was asked ~8.7 kHz: 2 M frames a morning in the raw record, a 66 MB project, and
#: the window held at every autosave (#62 review F6)
WINDOW_POLL_RATE_HZ = 20.0


class ConnectDialog(QDialog):
    """Instrument, port and baud rate; the port and baud last used for each instrument are
    filled in (``settings``)."""

    def __init__(self, parent=None, settings: QSettings | None = None, kind: str = "") -> None:
        super().__init__(parent)
        self.settings = settings
        self.setWindowTitle(tr("Connect to an instrument"))
        form = QFormLayout()
        self.instrument = QComboBox()
        for key, text in _instrument_names():
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
        self.instrument.currentIndexChanged.connect(self._remembered)
        if kind:
            self.instrument.setCurrentIndex(max(0, self.instrument.findData(kind)))
        self._remembered()

    def _remembered(self, *_args) -> None:
        """The port and baud rate last used with the instrument chosen."""
        if self.settings is None:
            return
        kind = self.instrument.currentData()
        self.port.setText(str(self.settings.value(PORT_SETTING.format(kind=kind), "") or ""))
        with contextlib.suppress(TypeError, ValueError):
            self.baud.setValue(int(self.settings.value(BAUD_SETTING.format(kind=kind), 0) or 0))

    def choice(self) -> tuple[str, str, int | None]:
        return (self.instrument.currentData(), self.port.text().strip(), self.baud.value() or None)


class DemonstrationDialog(QDialog):
    """A demonstration instrument: which, its noise, drift and faults."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.setWindowTitle(tr("Demonstration instrument"))
        form = QFormLayout()
        self.instrument = QComboBox()
        for key, text in _instrument_names():
            self.instrument.addItem(text, key)
        self.noise = QDoubleSpinBox()
        self.noise.setRange(0.0, 100.0)
        self.noise.setDecimals(3)
        self.noise.setValue(0.05)
        self.noise.setSuffix(' "')
        self.drift = QDoubleSpinBox()
        self.drift.setRange(-100.0, 100.0)
        self.drift.setDecimals(3)
        self.drift.setSuffix(' "/s')
        form.addRow(tr("Instrument"), self.instrument)
        form.addRow(tr("Noise (σ)"), self.noise)
        form.addRow(tr("Drift"), self.drift)
        self.faults: dict[str, QCheckBox] = {}
        for key, text in (("noise", tr("garbage between frames")),
                          ("invalid_axes", tr("invalid readings")),
                          ("disconnect", tr("the link drops now and then"))):
            box = QCheckBox(text)
            self.faults[key] = box
            form.addRow("", box)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok
                                   | QDialogButtonBox.StandardButton.Cancel)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        layout = QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(buttons)

    def choice(self) -> tuple[str, float, float, tuple[str, ...]]:
        return (self.instrument.currentData(), self.noise.value(), self.drift.value(),
                tuple(k for k, box in self.faults.items() if box.isChecked()))


class DemonstrationProcess:
    """``anglebench simulate KIND 0`` in a process of its own: the port it answers on, and
    ``close()`` (also as a context manager's exit) to stop it.

    ``noise`` (σ) and ``drift`` (a second) are in arcseconds, as the dialog says, for every
    instrument: a readout's, which sends degrees, are converted to them (day review 74 F5:
    the dialog's 0.05 ″ gave a readout σ = 0.05° = 180″).

    The readout is an axis the operator moves through a positioning plan's targets: run
    after run (``READOUT_RUNS`` of them), the targets rising and, ``bidirectional``,
    falling again — read from above a few arcseconds off (``READOUT_REVERSAL_DEG``, the
    axis's reversal error), so a take at the end target going down is a new reading (day
    review 74 F14: it held its last position for ever, a plan's second run could not be
    practised)."""

    #: where the demonstration instrument points in turn (8 s each)
    POSITIONS = {"autocollimator": ("12.5,4.1,-6.3,0.4", "12.5,-3.2"),
                 "theodolite": ("0,5,10,15", "0,89.998"),
                 "readout": ("0,15.00012,30.00007,44.99991", "0")}
    #: the readout's runs through its targets (more than any plan has: ISO 230-2 asks 5)
    READOUT_RUNS = 50
    #: the demonstration axis's reversal error: where it stops coming down (2.9″)
    READOUT_REVERSAL_DEG = 0.0008

    @classmethod
    def readout_script(cls, bidirectional: bool) -> str:
        """The readout's positions for :attr:`READOUT_RUNS` runs of its targets."""
        rising = [float(v) for v in cls.POSITIONS["readout"][0].split(",")]
        run = rising + ([v + cls.READOUT_REVERSAL_DEG for v in reversed(rising)]
                        if bidirectional else [])
        return ",".join(f"{v:.5f}".rstrip("0").rstrip(".") for v in run * cls.READOUT_RUNS)

    def __init__(self, kind: str, noise: float = 0.05, drift: float = 0.0,
                 faults: tuple[str, ...] = (), start_s: float = 30.0,
                 bidirectional: bool = True, hold_s: float = 8.0) -> None:
        positions, position = self.POSITIONS[kind]
        if kind == "readout":  # its unit is the degree: the arcseconds converted
            positions = self.readout_script(bidirectional)
            noise, drift = noise / 3600.0, drift / 3600.0
        command = [sys.executable, "-m", "app.main", "simulate", kind, "0",
                   "--positions", positions, "--position", position, "--hold", f"{hold_s:g}",
                   "--noise", f"{noise:.12g}", "--drift", f"{drift:.12g}"]
        for fault in faults:
            command += ["--fault", fault]
        self.process = subprocess.Popen(command, stdout=subprocess.PIPE,
                                        stderr=subprocess.DEVNULL, text=True,
                                        cwd=str(Path(__file__).resolve().parents[2]))
        ready, _, _ = select.select([self.process.stdout], [], [], start_s)
        line = self.process.stdout.readline() if ready else ""
        found = re.search(r"tcp://127\.0\.0\.1:\d+", line)
        if found is None:
            self.close()
            raise OSError(f"the demonstration {kind} did not start")
        self.port = found.group(0)

    def close(self) -> None:
        if self.process.poll() is None:
            self.process.terminate()
        with contextlib.suppress(subprocess.TimeoutExpired):
            self.process.communicate(timeout=5)

    def __enter__(self) -> DemonstrationProcess:
        return self

    def __exit__(self, *_exc) -> None:
        self.close()


class _ShownWhenSaid(QLabel):
    """A label that takes no room while it says nothing (an empty one left a blank band at
    the top of a panel docked at a side); ``said()`` after each new text."""

    def __init__(self, text: str = "", said: Callable[[], None] | None = None) -> None:
        super().__init__(text)
        self._said = said

    def setText(self, text: str) -> None:  # noqa: N802 (Qt's name)
        changed = text != self.text()
        super().setText(text)
        self.setVisible(bool(text))
        if changed and self._said is not None:
            self._said()


class _Session:
    """One connection's raw frames on one workbench as they will be stored, converted as
    they arrive (a project saved during a long stream converts only the frames since the
    last save).

    A connection that goes on while another workbench comes in front is cut in two
    sessions (#60 review: the polygon's raw record held the cross-calibration's takes): this
    one holds the worker's raw lines ``first`` … ``end`` (``end`` None while it is open), its
    frames indexed from 0 at ``first`` — the takes' indices are into the session's own
    ``frames``, as models/capture/raw_record.py and the edit check read them. Its
    ``started_utc`` is when the line before ``first`` arrived and its frames' times count
    from it (two sessions of one connection never share a start: the edit check knows a
    take by its session's port, start and frames).

    The worker's lines are read by their indices since its start (``CaptureWorker.lines``):
    the lines a session has converted are dropped from the worker's memory as the stream
    goes (:meth:`InstrumentLink.release_raw`), which never changes what is stored."""

    def __init__(self, workbench: str, kind: str, worker: CaptureWorker, first: int = 0) -> None:
        self.workbench, self.kind, self.worker = workbench, kind, worker
        self.first = first
        self.end: int | None = None
        #: seconds from the worker's start to this session's
        self.t0 = float(worker.lines(first - 1, first)[0][0]) if first > 0 else 0.0
        self.started_utc = worker.started_utc
        if self.t0 > 0.0:
            self.started_utc = (datetime.fromisoformat(worker.started_utc)
                                + timedelta(seconds=self.t0)).isoformat()
        #: the frames in their stored form, encoded a block at a time once full (a day's
        #: stream held as lists took ~215 bytes a frame and every save encoded them all
        #: again, twice: seconds in the window's thread at every autosave)
        self.frames = FrameBlocks()
        self.takes: list[list[int]] = []
        #: per take, the step its cells were rounded to (raw_record.OPTIONAL_KEYS)
        self.steps: list[float] = []
        #: a readout's: per take, the key of the column its value went to (raw_record's
        #: OPTIONAL_KEYS; the cell is chosen at the time, so the record says which)
        self.columns: list[str] = []

    def _end(self) -> int:
        """The raw index after this session's last line (the worker's newest while open)."""
        return self.worker.raw_end if self.end is None else self.end

    @property
    def converted(self) -> int:
        """The raw index of the first line this session has not converted yet."""
        return self.first + len(self.frames)

    def catch_up(self) -> None:
        """The worker's new lines converted to their stored form (a block at a time as the
        stream goes, so no save or take converts hours of them at once)."""
        self.frames.extend([round(float(t) - self.t0, 6), frame_text(line), int(bool(used))]
                           for t, line, used in self.worker.lines(self.converted, self._end()))

    def behind(self) -> int:
        """Lines the worker holds that are not converted yet."""
        return self._end() - self.converted

    def stored(self) -> dict:
        self.catch_up()
        return {"instrument": self.kind, "port": self.worker.port, "baud": int(self.worker.baud),
                "started_utc": self.started_utc, "frames": self.frames.snapshot(),
                "takes": [list(t) for t in self.takes], "steps": list(self.steps),
                "workbench": self.workbench,
                **({"columns": list(self.columns)} if self.kind == "readout" else {})}


class InstrumentLink:
    """One instrument of the panel: its connection, readings, status and raw session, and
    the widgets that show them (a box of the panel)."""

    def __init__(self, panel: CapturePanel, slot: int) -> None:
        self.panel, self.slot = panel, slot
        self.worker: CaptureWorker | None = None
        self.kind = ""
        self.frames: deque[tuple[float, tuple[float, ...], int]] = deque(maxlen=8192)
        self.latest: Reading | None = None
        #: when :attr:`latest` came (``time.monotonic()``)
        self.latest_at: float | None = None
        self.received = 0  # readings taken in from the worker since connecting
        #: the raw frame index of the last frame a take of this link used (-1: none): a
        #: take needs a newer one, one frame never fills two rows
        self.taken_frame = -1
        self.session: _Session | None = None
        self.last_fault = ""  # the fault the link recovered from, said while connected
        #: the time of the last frame before the link's last fault: the Allan deviation is of
        #: the frames after it (a reconnection is a gap in the series, however short)
        self.gap_before = -math.inf
        self.lost = False  # the value shown is stale (greyed, "link lost")
        #: frames arrive with no measurement since this one (a mirror out of view); None:
        #: readings come. Not a fault of the link: said as what it is (live76 F3)
        self.no_target: NoTarget | None = None
        #: the table's position (degrees) this link read at its last take, where it reads
        #: the table's encoder (:data:`TABLE_COLUMNS`); None: no take of it yet
        self.taken_position: float | None = None
        self.simulator = None  # a demonstration instrument this link started
        self.box = QGroupBox()
        live(self.box.setTitle, tr("Instrument") if slot == 0 else tr("Second instrument"))
        grid = QGridLayout(self.box)
        grid.setContentsMargins(4, 4, 4, 4)
        self.status = QLabel()
        live(self.status.setText, tr("Not connected"))
        self.value = QLabel("—")
        self.value.setStyleSheet(_VALUE_STYLE)
        # room for two lines: a stale value's "(link lost)" wraps below it, never clipped
        self.value.setMinimumHeight(2 * self.value.fontMetrics().lineSpacing() * 16 //
                                    max(1, self.value.font().pointSize()) + 8)
        for label in (self.status, self.value):
            label.setWordWrap(True)
            # a longer text wraps, never widens the panel: the plots beside it are not
            # resized (and redrawn) while a stream updates the texts 50 times a second
            label.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        self.connect_button = QPushButton()
        live(self.connect_button.setText, tr("Connect…"))
        self.connect_button.clicked.connect(lambda: panel.connect_dialog(slot))
        self.disconnect_button = QPushButton()
        live(self.disconnect_button.setText, tr("Disconnect"))
        # through the panel: the last one disconnected takes the take note with it
        self.disconnect_button.clicked.connect(
            lambda: self.panel.disconnect_instrument(self.slot))
        self.disconnect_button.setEnabled(False)
        self.resolution = QComboBox()
        for value, name in RESOLUTION_CHOICES:
            self.resolution.addItem(name or tr("as sent"), value)
        ignore_unfocused_wheel(self.resolution)
        live(self.resolution.setToolTip, tr("The instrument's resolution: captured values are "
                                            "rounded to it in the table (the raw frames keep "
                                            "every digit)"))
        self.resolution.currentIndexChanged.connect(self._resolution_chosen)
        self.resolution_label = QLabel()
        live(self.resolution_label.setText, tr("Resolution"))
        grid.addWidget(self.status, 0, 0, 1, 2)
        grid.addWidget(self.value, 1, 0, 1, 2)
        grid.addWidget(self.connect_button, 2, 0)
        grid.addWidget(self.disconnect_button, 2, 1)
        grid.addWidget(self.resolution_label, 3, 0)
        grid.addWidget(self.resolution, 3, 1)
        #: a readout's value goes to this column ("": the current cell's)
        self.column = QComboBox()
        ignore_unfocused_wheel(self.column)
        self.column_label = QLabel()
        live(self.column_label.setText, tr("Readout into"))
        grid.addWidget(self.column_label, 4, 0)
        grid.addWidget(self.column, 4, 1)
        self._show_kind()

    # ------------------------------------------------------------ settings
    def _show_kind(self) -> None:
        readout = self.kind == "readout"
        self.column.setVisible(readout)
        self.column_label.setVisible(readout)
        # no instrument yet: no resolution of its own to show ("as sent" until an
        # autocollimator was connected: day review live76 F11)
        self.resolution.setEnabled(bool(self.kind))
        self.resolution_label.setEnabled(bool(self.kind))
        self.resolution.blockSignals(True)
        try:
            value = self.resolution_arcsec
            index = min(range(self.resolution.count()),
                        key=lambda i: abs(float(self.resolution.itemData(i)) - value))
            self.resolution.setCurrentIndex(index)
        finally:
            self.resolution.blockSignals(False)

    @property
    def resolution_arcsec(self) -> float:
        """The instrument's resolution (arcseconds; 0: as sent), a setting per instrument."""
        if not self.kind:
            return 0.0
        default = DEFAULT_RESOLUTION_ARCSEC.get(self.kind, 0.0)
        try:
            return float(self.panel.qsettings.value(RESOLUTION_SETTING.format(kind=self.kind),
                                                    default))
        except (TypeError, ValueError):
            return default

    def _resolution_chosen(self, _index: int) -> None:
        if self.kind:
            self.panel.qsettings.setValue(RESOLUTION_SETTING.format(kind=self.kind),
                                          float(self.resolution.currentData()))

    def fill_columns(self, columns) -> None:
        """The workbench's columns a readout can go to; the one chosen stays (the current
        cell too), else the workbench's readout column (:data:`READOUT_COLUMNS`)."""
        chosen = self.column.currentData()
        self.column.blockSignals(True)
        try:
            self.column.clear()
            self.column.addItem(tr("the current cell"), "")
            for column in columns:
                self.column.addItem(declared(column.header), column.key)
            self.resolution.setItemText(0, tr("as sent"))  # in the language chosen now
            index = self.column.findData(chosen) if chosen is not None else -1
            if index < 0:
                keys = [column.key for column in columns]
                index = next((self.column.findData(k) for k in READOUT_COLUMNS if k in keys), 0)
            self.column.setCurrentIndex(index)
        finally:
            self.column.blockSignals(False)

    # ------------------------------------------------------------ connecting
    @property
    def connected(self) -> bool:
        return self.worker is not None

    def connect(self, kind: str, port: str, baud: int | None = None, simulator=None,
                **worker_options) -> None:
        self.disconnect()
        self.simulator = simulator
        self.kind = kind
        self.frames.clear()
        self.gap_before = -math.inf
        self.latest = None
        self.received = 0
        self.taken_frame = -1
        self.lost = False
        self.no_target = None
        self.taken_position = None
        self.value.setText("—")
        self.value.setStyleSheet(_VALUE_STYLE)
        # the window rides out a link down ~15 s (0.2 s, 0.4 s, … between 12 tries): an
        # instrument restarted or a cable re-seated; 3 tries gave up after 1.2 s (#41)
        worker_options.setdefault("retries", WINDOW_RETRIES)
        worker_options.setdefault("poll_interval_s", 1.0 / WINDOW_POLL_RATE_HZ)
        worker_options.setdefault("request_interval_s", 1.0 / WINDOW_POLL_RATE_HZ)
        # the value is stale when the worker says so, on its clock (never the window's)
        worker_options.setdefault("stale_s", STALE_S)
        self.worker = CaptureWorker(port, INSTRUMENTS[kind](), baud, **worker_options).start()
        self.session = _Session(self.panel.window_.current.kind.key, kind, self.worker)
        self.last_fault = ""
        self.status.setStyleSheet("")
        self.status.setText(tr("Connecting to {port}…").format(port=port))
        self.disconnect_button.setEnabled(True)
        self._show_kind()
        settings = self.panel.qsettings
        if simulator is None:  # a demonstration's port is its own, never remembered
            settings.setValue(PORT_SETTING.format(kind=kind), port)
            if baud:
                settings.setValue(BAUD_SETTING.format(kind=kind), int(baud))

    def disconnect(self) -> None:
        if self.worker is not None:
            self.panel.claim_columns(self)
        worker, self.worker = self.worker, None
        if worker is not None:
            worker.stop()
            self.panel._drain_link(self, worker)  # what is queued is taken in, never dropped
            if not self.status.styleSheet():
                self.status.setText(tr("Disconnected from {port}").format(port=worker.port))
        session, self.session = self.session, None
        if session is not None and (stored := session.stored())["frames"]:
            self.panel.sessions.setdefault(session.workbench, []).append(stored)
        simulator, self.simulator = self.simulator, None
        if simulator is not None:
            simulator.__exit__(None, None, None)
        self.latest = None
        self.lost = False
        self.no_target = None
        self.value.setText("—")
        self.value.setStyleSheet(_VALUE_STYLE)
        self.disconnect_button.setEnabled(False)
        # its spread and Allan deviation go with it (#41: they stayed on screen)
        if self.slot == 0 and hasattr(self.panel, "stability"):
            self.panel.clear_statistics()
        self.panel._links_changed()

    def next_session_start(self) -> int:
        """The raw index a session split off this link's session now would start at (the
        frame after the latest reading taken in: :meth:`CapturePanel._next_session`)."""
        session = self.session
        assert session is not None
        start = session.first
        if self.latest is not None:
            start = max(start, self.latest.frame + 1)
        return start

    def release_raw(self) -> None:
        """The worker's lines no session needs any more dropped from its memory (a day's
        stream held every line twice: ~700 MB at 100 Hz for 8 h beside the session's
        frames). Kept: what the session has not converted yet, and the line before the one
        a session split off it would start at (its start's time); the session's open, the
        only one of its connection that is (a session split off or ended is converted to its
        end first), so nothing stored ever needs a line dropped."""
        session = self.session
        if session is None or session.end is not None:
            return
        session.worker.release(min(session.converted, self.next_session_start() - 1))

    # ------------------------------------------------------------ readings
    def mark_lost(self, lost: bool) -> None:
        """The value greyed and marked "link lost" (stale), or shown as live again."""
        if lost == self.lost:
            return
        self.lost = lost
        self.value.setStyleSheet(_STALE_STYLE if lost else _VALUE_STYLE)
        if lost and self.latest is not None:
            self.show_value()
        self.panel._links_changed()

    def show_value(self) -> None:
        reading = self.latest
        if reading is None:
            self.value.setText("—")
            return
        unit = {"arcsec": '"', "deg": "°"}.get(reading.unit, f" {reading.unit}")
        # as the cell a take fills would read (its angle format, unit and the instrument's
        # resolution: #41 review, the live value was decimal degrees to 6 places beside a
        # D°M′S″ column); a value no column of the workbench in front takes, as sent
        cells = self.panel.cell_texts(self, reading.values, reading.unit)
        shown = []
        for i, v in enumerate(reading.values):
            cell = cells.get(i)
            if cell is None:
                shown.append(fixed_text(v, 6 if reading.unit == "deg" else 3) + unit)
            else:
                shown.append(f"{cell[0]}{cell[1]}")
        if self.kind == "autocollimator" and len(shown) == 2:
            # which axis is which, one a line (day review live76 F11: "9.56″ −3.19″"; beside
            # each other, with their names, they wrapped in the middle of the panel)
            text = f"x {shown[0]}\ny {shown[1]}"
        else:
            text = "   ".join(shown)
        if not self.lost:
            self.value.setText(text)
        elif self.no_target is not None:
            self.value.setText(tr("{value} ({why})").format(value=text, why=self.no_reading_why))
        else:
            self.value.setText(tr("{value} (link lost)").format(value=text))

    @property
    def no_target_words(self) -> str:
        """What frames with no measurement mean for this instrument, in words."""
        return tr("no mirror in view") if self.kind == "autocollimator" else \
            tr("no target in view")

    @property
    def no_reading_why(self) -> str:
        """Why there is no reading to take: no target in view (frames come, none holds a
        measurement), or the link lost."""
        if self.no_target is not None:
            return self.no_target_words
        if self.latest is None and not self.last_fault:
            return tr("no reading yet")
        return tr("link lost")

    def say_no_target(self) -> None:
        """The status while frames with no measurement come: what it means, with the value
        beyond the range under the column's name (never its key), and that the link is
        fine — no reconnection, nothing given up (live76 F3)."""
        event = self.no_target
        if event is None:
            return
        names = [self.panel.column_name(key) for key in event.columns]
        detail: str
        if event.value is not None and event.limits is not None and names:
            unit = '"' if self.kind == "autocollimator" else ("°" if self.kind == "theodolite"
                                                             else "")
            detail = tr("{column} {value}{unit} is beyond the range {low} … {high}{unit}").format(
                column=names[0], value=f"{event.value:g}", unit=unit,
                low=f"{event.limits[0]:g}", high=f"{event.limits[1]:g}")
        elif names:
            detail = tr("it marks {columns} not valid").format(columns=", ".join(names))
        else:
            detail = tr("none holds a measurement")
        self.status.setStyleSheet("color: #8a5a00;")
        what = tr("No mirror in view") if self.kind == "autocollimator" else \
            tr("No target in view")
        self.status.setText(tr("{what}: frames arrive from {port}, but {detail}. Not a fault "
                               "of the link: the readings come back with the target").format(
            what=what, port=self.worker.port if self.worker is not None else "",
            detail=detail))

    @property
    def usable(self) -> bool:
        """A fresh reading is there to take."""
        return self.worker is not None and self.latest is not None and not self.lost

    @property
    def name(self) -> str:
        """The instrument and its port, as the panel names it in a message."""
        kind = dict(_instrument_names()).get(self.kind, self.kind)
        port = self.worker.port if self.worker is not None else ""
        return tr("{instrument} on {port}").format(instrument=kind, port=port) if port else kind


#: the workbenches (keys, comma-separated) the panel was open on when last left: restored
#: open on those only, never on every tab with nothing connected (day 65, F10)
OPEN_ON_SETTING = "capture/panel_open_on"


class CapturePanel(QDockWidget):
    def __init__(self, window) -> None:
        super().__init__(window)
        self.window_ = window
        self.qsettings: QSettings = getattr(window, "qsettings", None) or QSettings()
        live(self.setWindowTitle, tr("Instrument"))
        self.setObjectName("capture_panel")
        self.setAllowedAreas(Qt.DockWidgetArea.LeftDockWidgetArea
                             | Qt.DockWidgetArea.RightDockWidgetArea
                             | Qt.DockWidgetArea.BottomDockWidgetArea)
        self.links = [InstrumentLink(self, 0), InstrumentLink(self, 1)]
        #: finished sessions per workbench (stored form)
        self.sessions: dict[str, list[dict]] = {}
        self.gate: StabilityGate | None = None
        self._origin: UnwrappedAngles | None = None
        self.next_reading = None  # the workbench's NextReading for the row a take goes to
        self._guide_due = 0.0
        #: rows filled by Take reading or auto-take: (workbench, row, values of the first
        #: instrument at full precision)
        self.taken: list[tuple[str, int, tuple[float, ...]]] = []
        #: the table seen turning since the last take: the seconds the first instrument's
        #: mirror was out of view (None: not seen); a repeat of a point after it is refused
        #: (:meth:`_not_this_points`), and — once that was said (``_turn_said``) — taken by hand
        self._turn_seen: float | None = None
        self._turn_said = False
        #: per workbench, the columns an instrument has filled or was set to fill: the
        #: plan's nominal is never written there (#60: a readout's link gave up and the
        #: plan's expected encoder value went into its column as if read)
        self.measured_columns: dict[str, set[str]] = {}
        body = QWidget()
        # five parts side by side when docked at the bottom (the guidance, the instrument,
        # its statistics, the take, the second instrument: a low panel, the plots keep their
        # height), one above the other beside
        self.body_layout = QBoxLayout(QBoxLayout.Direction.TopToBottom, body)
        self.body_layout.setContentsMargins(4, 4, 4, 4)
        sections = [QWidget() for _ in range(5)]
        columns = []
        for section in sections:
            column = QVBoxLayout(section)
            column.setContentsMargins(0, 0, 0, 0)
            columns.append(column)
            # the guidance and the statistics take the width left at the bottom (their texts
            # wrap); at a side no part takes height it does not need (_docked)
            self.body_layout.addWidget(section, 0)
        self._sections = sections
        self.body_layout.addStretch(1)
        self.guide = _ShownWhenSaid("", said=self._show_whole_note)
        self.guide.setVisible(False)
        self.guide.setStyleSheet("font-size: 12pt; font-weight: bold; color: #0b5394;")
        self.stability = QLabel("")
        self.allan = QLabel("")
        self.take_button = QPushButton()
        live(self._set_take_text, tr("Take reading (F9)"))
        self.take_button.clicked.connect(lambda: self.take_reading())
        self.take_button.setEnabled(False)
        # F9 (a foot switch) while the button is disabled with an instrument connected (its
        # link lost, no mirror in view): the take is refused with why, beside the guidance —
        # a disabled button's key did nothing and said nothing (live76 F8)
        self.refused_key = QShortcut(QKeySequence(TAKE_READING_KEY), self)
        self.refused_key.activated.connect(lambda: self.take_reading())
        self.refused_key.setEnabled(False)
        # auto-take: the stability gate's window and dwell
        self.auto = QCheckBox()
        live(self.auto.setText, tr("Auto-take when stable"))
        self.auto.toggled.connect(self._gate_changed)
        self.window_box = QDoubleSpinBox()
        self.window_box.setRange(0.001, 3600.0)
        self.window_box.setDecimals(3)
        self.window_box.setValue(0.5)
        self.window_box.setSuffix(' "')
        self._gate_unit = "arcsec"  # what the window is applied in (_window_in)
        self._say_window_unit()
        on_language_change(self.window_box, self._say_window_unit)
        self.dwell_box = QDoubleSpinBox()
        self.dwell_box.setRange(0.01, 600.0)
        self.dwell_box.setDecimals(2)
        self.dwell_box.setValue(1.0)
        self.dwell_box.setSuffix(" s")
        for box in (self.window_box, self.dwell_box):
            box.valueChanged.connect(self._gate_changed)
            ignore_unfocused_wheel(box)
        auto_form = QFormLayout()
        self.window_label, self.dwell_label = QLabel(), QLabel()
        live(self.window_label.setText, tr("Window"))
        live(self.dwell_label.setText, tr("Dwell"))
        auto_form.addRow(self.window_label, self.window_box)
        auto_form.addRow(self.dwell_label, self.dwell_box)
        self.auto_state = QLabel("")
        #: why a take was refused, or auto-take switched off (until the next take)
        self.take_note = _ShownWhenSaid("", said=self._show_whole_note)
        self.take_note_of: str | None = None  # the workbench whose take it is of
        #: the undo stack and its index just after the take the note speaks of (None: the
        #: note is of no take): the take undone (Edit › Undo), its note goes with it
        self.take_note_step: tuple[object, int] | None = None
        self._watched_stacks: set[int] = set()
        self.take_note.setStyleSheet("color: #b00020;")
        self.take_note.setVisible(False)
        # wide enough to wrap by words (a bottom-docked panel at 200 % squeezed it to a few
        # letters a line)
        self.take_note.setMinimumWidth(16 * self.take_note.fontMetrics().averageCharWidth())
        for widget in (self.guide, self.stability, self.allan, self.auto_state, self.take_note):
            widget.setWordWrap(True)
            widget.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        # the guidance and why a take was refused (or what it could not place), above the
        # part that scrolls when docked at a side: scrolled down to reach "Readout into", the
        # panel cut "Next: go to face 8" for the rest of a morning (#62 review). At the bottom
        # they are the first of the parts side by side (_docked). Beside the guidance, not
        # under the Take button: there it pushed the auto-take's window and dwell out of a
        # bottom-docked panel's sight
        self._guide_column = columns[0]
        self.header = QWidget()
        self.header_layout = QVBoxLayout(self.header)
        self.header_layout.setContentsMargins(4, 4, 4, 0)
        self.header_layout.addWidget(self.guide)
        self.header_layout.addWidget(self.take_note)
        columns[1].addWidget(self.links[0].box)
        columns[2].addWidget(self.stability)
        columns[2].addWidget(self.allan)
        columns[3].addWidget(self.take_button)
        columns[3].addWidget(self.auto)
        columns[3].addLayout(auto_form)
        columns[3].addWidget(self.auto_state)
        columns[4].addWidget(self.links[1].box)
        for column in columns:
            column.addStretch(1)
        self.dockLocationChanged.connect(self._docked)
        self.visibilityChanged.connect(self._keep_plots)
        # the body scrolls (vertically) rather than making the window wider or taller
        scroll = QScrollArea()
        scroll.setWidget(body)
        scroll.setWidgetResizable(True)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        scroll.setFrameShape(QScrollArea.Shape.NoFrame)
        body.setMinimumWidth(PANEL_MIN_WIDTH - 20)
        scroll.setMinimumWidth(PANEL_MIN_WIDTH)
        self.body = body
        self.scroll = scroll
        outer = QWidget()
        outer_layout = QVBoxLayout(outer)
        outer_layout.setContentsMargins(0, 0, 0, 0)
        outer_layout.setSpacing(0)
        outer_layout.addWidget(self.header)
        outer_layout.addWidget(scroll, 1)
        self.setWidget(outer)
        self.timer = QTimer(self)
        self.timer.setInterval(20)
        self.timer.timeout.connect(self.drain)
        self._allan_due = 0.0
        self._show_due = 0.0  # perf_counter time the readout's texts may be redrawn
        self._show_pending = False
        #: the workbench in front as the panel last saw it, and those it was open on
        self._front: str | None = None
        self._open_on: set[str] = set()
        tabs = getattr(window, "tabs", None)
        if tabs is not None:
            tabs.currentChanged.connect(self.workbench_changed)
        on_language_change(self, self._refill_columns)
        # the guidance in the new language, connected or not (day review live76 F4: with no
        # instrument connected it stayed in the old one until the next take)
        on_language_change(self, self._guide_again)

    def _docked(self, area) -> None:
        """At the bottom the panel's parts stand side by side; at a side, one above the other.
        A window too short for it at the bottom (:data:`BOTTOM_DOCK_LEAST_WINDOW_HEIGHT`) has
        it at the right: the readings keep their rows being filled."""
        bottom = area == Qt.DockWidgetArea.BottomDockWidgetArea
        if bottom and self._too_short_for_bottom():
            self.window_.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, self)
            return
        self.body_layout.setDirection(QBoxLayout.Direction.LeftToRight if bottom
                                      else QBoxLayout.Direction.TopToBottom)
        # stretched one above the other, the empty guidance left ~60 px blank at the top
        # before connecting (#41 review)
        for index, section in enumerate(self._sections):
            self.body_layout.setStretchFactor(section, 2 if bottom and index in (0, 2) else 0)
        # at the bottom the panel is low (its parts side by side fit): the readings table
        # and the plot above it keep their height on a 720 px screen
        self.setMaximumHeight(BOTTOM_PANEL_MAX_HEIGHT if bottom else QWIDGETSIZE_MAX)
        # the guidance: the first part at the bottom (a row above the parts would take
        # height from a low panel), fixed above the scrolling parts at a side
        home = self._guide_column if bottom else self.header_layout
        for index, widget in enumerate((self.guide, self.take_note)):
            home.insertWidget(index, widget)
        self.header.setVisible(not bottom)
        self._keep_plots()
        if bottom:  # a note said before, whole at the bottom too (once the parts are laid out)
            QTimer.singleShot(0, self._show_whole_note)

    def _too_short_for_bottom(self) -> bool:
        """The window is lower than the panel at the bottom needs to leave the readings
        table its rows (its height before the panel's least height made it grow)."""
        window = self.window_
        return hasattr(window, "addDockWidget") and not self.isFloating() \
            and window.height() < BOTTOM_DOCK_LEAST_WINDOW_HEIGHT

    def _show_whole_note(self) -> None:
        """Docked at the bottom, the panel grows (up to :data:`BOTTOM_PANEL_MAX_HEIGHT`, as the
        window has room) to show the guidance and the take note whole: they are the first of
        its parts side by side, in the part that scrolls, and an 88 px high panel on a
        1280×720 screen showed two lines of a refused take's note (capture80: "Not taken:
        face 6's reading 2 of 2 is due, but the table is at another face: encoder a" — the
        rest, and what to do, out of sight). Never shrinks it: the technician's height
        stays."""
        window = self.window_
        viewport = self.body.parentWidget() if hasattr(self, "body") else None
        if viewport is None or not hasattr(window, "resizeDocks") \
                or self.isHidden() or self.isFloating() \
                or window.dockWidgetArea(self) != Qt.DockWidgetArea.BottomDockWidgetArea:
            return
        column = self._sections[0]
        layout = column.layout()
        width = column.width()
        if layout is None or width <= 0:
            return
        layout.activate()
        needed = layout.heightForWidth(width) if layout.hasHeightForWidth() \
            else layout.sizeHint().height()
        # the dock's title and the body's margins around its parts
        around = self.height() - viewport.height() \
            + self.body_layout.contentsMargins().top() + self.body_layout.contentsMargins().bottom()
        wanted = min(BOTTOM_PANEL_MAX_HEIGHT, needed + around)
        if wanted > self.height():
            window.resizeDocks([self], [wanted], Qt.Orientation.Vertical)

    def _keep_plots(self, *_args) -> None:
        """While the panel is in sight at the bottom, every workbench's plot keeps ~200 px of
        height (its result box gives way first); elsewhere, or closed, no minimum. While it
        is open (docked), every readings table keeps :data:`READINGS_ROWS_IN_SIGHT` rows, the
        set-up giving way."""
        area = self.window_.dockWidgetArea(self) if hasattr(self.window_, "dockWidgetArea") \
            else None
        bottom = area == Qt.DockWidgetArea.BottomDockWidgetArea and not self.isHidden()
        shown = not self.isHidden() and not self.isFloating()
        for presenter in getattr(self.window_, "presenters", ()):
            keep = getattr(presenter.view, "keep_plot_height", None)
            if keep is not None:
                keep(PLOT_TABS_MIN_HEIGHT if bottom else 0)
            rows = getattr(presenter.view, "keep_readings_rows", None)
            if rows is not None:
                rows(READINGS_ROWS_IN_SIGHT if shown else 0)

    # ------------------------------------------------------------ the first link's state
    @property
    def worker(self) -> CaptureWorker | None:
        return self.links[0].worker

    @property
    def kind(self) -> str:
        return self.links[0].kind

    @property
    def latest(self) -> Reading | None:
        return self.links[0].latest

    @property
    def frames(self):
        return self.links[0].frames

    @property
    def received(self) -> int:
        return self.links[0].received

    @property
    def status(self) -> QLabel:
        return self.links[0].status

    @property
    def value(self) -> QLabel:
        return self.links[0].value

    @property
    def session(self) -> _Session | None:
        return self.links[0].session

    # ------------------------------------------------------------ connecting
    def connect_dialog(self, slot: int = 0) -> None:
        dialog = ConnectDialog(self, self.qsettings, self.suggested_kind(slot))
        if dialog.exec() == QDialog.DialogCode.Accepted:
            kind, port, baud = dialog.choice()
            if port:
                self.connect_to(kind, port, baud, slot=slot)

    def suggested_kind(self, slot: int = 0) -> str:
        """The instrument *Connect…* proposes: the one last connected in ``slot``, else the
        one the workbench in front reads (a theodolite on the theodolite's, an
        autocollimator elsewhere; a readout second) — it proposed an autocollimator on the
        theodolite's tab (#41)."""
        if self.links[slot].kind:
            return self.links[slot].kind
        if slot:
            return "readout"
        current = getattr(self.window_, "current", None)
        key = getattr(getattr(current, "kind", None), "key", "")
        return "theodolite" if key == "theodolite" else "autocollimator"

    def connect_to(self, kind: str, port: str, baud: int | None = None, slot: int = 0,
                   simulator=None, **worker_options) -> None:
        """Connect instrument ``slot`` (0: the first, which auto-take follows; 1: the
        second) to ``port`` (``simulator``: the demonstration instrument serving it, stopped
        with the link); its statistics and the guidance start afresh."""
        link = self.links[slot]
        link.connect(kind, port, baud, simulator, **worker_options)
        presenter = getattr(self.window_, "current", None)
        if presenter is not None:  # open on this workbench from now on (until closed here)
            self._remember(presenter.kind.key, True)
        self._reset_statistics()
        self._refill_columns()
        self._capturing()
        self.timer.start()

    def disconnect_instrument(self, slot: int | None = None) -> None:
        """Disconnect one instrument (``slot``) or both; with none left connected, the take
        note goes (day review 64 P7: "Row 50: encoder a … is −75.0° from …" stayed in red
        after both were disconnected)."""
        for link in (self.links if slot is None else [self.links[slot]]):
            link.disconnect()
        if not any(link.connected for link in self.links):
            self.clear_take_note()

    def clear_take_note(self) -> None:
        """No take note (what the last take could not place, or took off the plan)."""
        self.take_note.setText("")
        self.take_note_of = None
        self.take_note_step = None

    def _note_with_take(self, stack) -> None:
        """The take note (set by the take just pushed onto ``stack``) goes when that take
        is undone. live78: after Edit › Undo of a take at face 4's place (or at the next
        target), "Row 3: encoder a 190.0000° is +60.0° from … The reading is kept; undo the
        take if it is wrong" stayed in red over the emptied row until the next take."""
        self.take_note_step = (stack, stack.index())
        if id(stack) not in self._watched_stacks:
            self._watched_stacks.add(id(stack))
            stack.indexChanged.connect(lambda index, s=stack: self._stack_moved(s, index))

    def _stack_moved(self, stack, index: int) -> None:
        step = self.take_note_step
        if step is not None and step[0] is stack and index < step[1]:
            self.clear_take_note()

    def sheet_replaced(self, workbench: str) -> None:
        """``workbench``'s sheet was replaced (an import, a sample, a project opened or
        new): a take note of its rows is of rows that are gone."""
        if self.take_note_of == workbench:
            self.clear_take_note()

    def start_demonstration(self, kind: str, noise: float = 0.05, drift: float = 0.0,
                            faults: tuple[str, ...] = (), slot: int | None = None) -> str:
        """A demonstration instrument (``anglebench simulate``, a process of its own so it
        never competes with the window for time) on a free TCP port of 127.0.0.1,
        connected to the first free instrument (or ``slot``); its port."""
        if slot is None:
            slot = 0 if not self.links[0].connected or self.links[1].connected else 1
        self.links[slot].disconnect()
        # the readout goes back down the targets where the plan in front does (positioning)
        settings = getattr(self.window_.current, "settings", {}) or {}
        demonstration = DemonstrationProcess(
            kind, noise, drift, faults,
            bidirectional=settings.get("plan_directions", "both") == "both")
        self.connect_to(kind, demonstration.port, slot=slot, simulator=demonstration)
        return demonstration.port

    def demonstration_dialog(self) -> None:
        dialog = DemonstrationDialog(self)
        if dialog.exec() == QDialog.DialogCode.Accepted:
            kind, noise, drift, faults = dialog.choice()
            try:
                self.start_demonstration(kind, noise, drift, faults)
            except OSError as exc:
                self.status.setText(tr("The demonstration instrument did not start: {reason}")
                                    .format(reason=str(exc)))

    def closeEvent(self, event) -> None:  # noqa: N802
        self.disconnect_instrument()
        super().closeEvent(event)

    def _links_changed(self) -> None:
        usable = any(link.usable for link in self.links)
        self.take_button.setEnabled(usable)
        self.refused_key.setEnabled(not usable and any(link.connected for link in self.links))
        if hasattr(self, "auto_state"):  # what auto-take waits for, said when a link changes
            self._show_gate()
        if not any(link.connected for link in self.links):
            self.timer.stop()
        self._capturing()

    def _capturing(self) -> None:
        """The workbench in front analyses takes off the GUI thread while an instrument is
        connected; the others as usual."""
        connected = any(link.connected for link in self.links)
        current = getattr(self.window_, "current", None)
        for presenter in getattr(self.window_, "presenters", []):
            if hasattr(presenter, "set_capturing"):
                presenter.set_capturing(connected and presenter is current)
            if hasattr(presenter, "take_row"):
                # the row the next take goes to waits for its reading, plan or none
                # (day review 64 P4); the guidance follows the cursor
                taking = connected and presenter is current
                if taking == (presenter.take_row is not None):
                    continue
                presenter.take_row = (lambda p=presenter: self.target_row(p)) if taking \
                    else None
                self._follow_cursor(presenter)
                presenter.table_model.forget_waiting()
                presenter.schedule_refresh()

    def _follow_cursor(self, presenter) -> None:
        """The guidance, and the row waiting for the take, worked out again when the cursor
        moves (it may choose another row the take goes to): never a guidance that names a
        row the take does not go to (day review 64 P4)."""
        selection = presenter.view.table.selectionModel()
        if selection is None or getattr(selection, "_follows_capture", False):
            return
        selection._follows_capture = True
        selection.currentChanged.connect(lambda *_: self._cursor_moved(presenter))

    def _cursor_moved(self, presenter) -> None:
        if presenter is not getattr(self.window_, "current", None) \
                or not any(link.connected for link in self.links):
            return
        self.update_guide()
        seen = (presenter, presenter.planned_row())
        if seen != getattr(self, "_take_row_seen", None):
            self._take_row_seen = seen  # the row waiting changed: repainted, analysed again
            presenter.table_model.forget_waiting()
            presenter.schedule_refresh()

    def clear_statistics(self) -> None:
        """The first instrument's spread and Allan deviation off the screen (its link ended:
        they described readings no longer coming)."""
        self.stability.setText("")
        self.allan.setText("")
        self._spread: float | None = None
        self._motion: float | None = None  # the rate the output moves at, when it does
        self._allan_due = 0.0

    def _reset_statistics(self) -> None:
        """A new connection or another workbench: no figure of before stays on screen."""
        self.clear_statistics()
        self._show_due, self._show_pending = 0.0, False
        self._guide_due = 0.0
        self.next_reading = None
        self.guide.setText("")
        self._turn_seen, self._turn_said = None, False
        self._gate_changed()

    # ------------------------------------------------------------ where it is open
    def _remember(self, key: str, shown: bool) -> None:
        before = set(self._open_on)
        (self._open_on.add if shown else self._open_on.discard)(key)
        if self._open_on != before:
            self.qsettings.setValue(OPEN_ON_SETTING, ",".join(sorted(self._open_on)))

    def remember_open(self) -> None:
        """The panel's state on the workbench in front kept (the window closes)."""
        presenter = getattr(self.window_, "current", None)
        if presenter is not None:
            self._remember(presenter.kind.key, self.isVisible())

    def restore_open(self) -> None:
        """At start: open on the workbench in front only if it was open there when last
        left (the window's saved state opened it on every tab, where it took ~240 px, 370 of
        853 at 150 %, from the readings with nothing connected: day 65, F10)."""
        saved = str(self.qsettings.value(OPEN_ON_SETTING, "") or "")
        self._open_on = {key for key in saved.split(",") if key}
        self._restored = True
        presenter = getattr(self.window_, "current", None)
        self._front = presenter.kind.key if presenter is not None else None
        self._show_for(self._front)

    def _show_for(self, key: str | None) -> None:
        """Open where an instrument is connected or it was open on workbench ``key``;
        closed elsewhere (the Instrument menu opens it)."""
        if any(link.connected for link in self.links):
            return  # its readings go to the sheet in front: it stays
        self.setVisible(key in self._open_on)

    def _follow_front(self) -> None:
        presenter = getattr(self.window_, "current", None)
        key = presenter.kind.key if presenter is not None else None
        if key == self._front or not self._restored:
            return  # before restore_open: the window's saved state is still being put back
        if self._front is not None and not any(link.connected for link in self.links):
            self._remember(self._front, self.isVisible())
        self._front = key
        self._show_for(key)

    #: restore_open has run (the window's saved state is back)
    _restored = False

    def workbench_changed(self, _index: int = 0) -> None:
        """Another workbench in front: its guidance, not the last one's, and its own raw
        sessions (:meth:`_split_sessions`); the panel open there if it was when last left
        there, or an instrument is connected."""
        self._follow_front()
        self._split_sessions()
        self._reset_statistics()
        self._refill_columns()
        self._capturing()
        if any(link.connected for link in self.links):
            self.update_guide()

    def _split_sessions(self) -> None:
        """Each open link's session closed into :attr:`sessions` of its workbench and a new
        one started for the workbench in front: a take goes to the sheet in front, so its
        frames must be in that workbench's raw record. The frames the panel has taken in
        stay with the old session; the new one starts after them, and a take needs a frame
        of its own session (the latest one before the change counts as used)."""
        presenter = getattr(self.window_, "current", None)
        if presenter is None:
            return
        key = presenter.kind.key
        for link in self.links:
            session = link.session
            if session is None or session.workbench == key:
                continue
            if not session.takes:
                # nothing taken on the last workbench: the session goes on with the one in
                # front (a glance at another tab left a session of frames behind none of its
                # readings there, under its certificate's raw digest)
                session.workbench = key
                continue
            start = self._next_session(link, key)
            session.end = start
            del session.frames[start - session.first:]  # converted ahead, not taken in yet
            if (stored := session.stored())["frames"]:
                self.sessions.setdefault(session.workbench, []).append(stored)

    @staticmethod
    def _next_session(link: InstrumentLink, workbench: str) -> int:
        """A new session of ``link``'s connection for ``workbench`` from the frame after the
        last one read (which counts as used: a take needs a frame of the new session); the
        raw index it starts at."""
        session = link.session
        assert session is not None
        start = link.next_session_start()
        link.session = _Session(workbench, session.kind, session.worker, start)
        link.taken_frame = max(link.taken_frame, start - 1)
        return start

    def _refill_columns(self) -> None:
        presenter = getattr(self.window_, "current", None)
        if presenter is None:
            return
        for link in self.links:
            link.fill_columns(presenter.kind.columns)

    def _guide_again(self) -> None:
        if getattr(self.window_, "current", None) is not None:
            self.update_guide()

    # ------------------------------------------------------------ the raw frames
    def raw_sessions(self, workbench: str) -> list[dict]:
        """The sessions of a workbench in their stored form, the open connections' included."""
        # copies (their takes and steps too): the fringe's live take rewrites an earlier
        # session's takes in place, in the window's thread, while an autosave thread may be
        # writing these sessions (its digest then did not match the text it wrote)
        out = [{**s, "takes": [list(t) for t in s["takes"]],
                **({"steps": list(s["steps"])} if "steps" in s else {}),
                **({"columns": list(s["columns"])} if "columns" in s else {})}
               for s in self.sessions.get(workbench, [])]
        for link in self.links:
            if link.session is not None and link.session.workbench == workbench \
                    and (stored := link.session.stored())["frames"]:
                out.append(stored)
        return out

    def takes_of(self, workbench: str):
        """``(key, take)`` of every take of a workbench's sessions, the open connections'
        included, ``take`` the live ``[row, first, last]`` (models/capture/take_rows.py:
        the sheet's rows inserted, deleted or replaced move them in place)."""
        yield from session_takes(self.sessions.get(workbench, []))
        for link in self.links:
            session = link.session
            if session is not None and session.workbench == workbench:
                for take in session.takes:
                    yield take_key(session.kind, session.worker.port, session.started_utc,
                                   take), take

    def raw_capture(self) -> dict[str, list[dict]]:
        """Every workbench's sessions, for the project file."""
        keys = set(self.sessions) | {link.session.workbench for link in self.links
                                     if link.session is not None}
        return {k: v for k in sorted(keys) if (v := self.raw_sessions(k))}

    def load_raw_capture(self, raw: dict[str, list[dict]]) -> None:
        """The sessions of a project opened (or none for a new one); a connection open now
        goes on in a session of its own."""
        # the frames of a project opened held as their blocks' text too (encoded again at
        # every save they froze the window as a live session's did)
        # their takes copied: the sheet's rows move them in place (take_rows.py), not the
        # project's they were read from
        self.sessions = {k: [{**session, "frames": FrameBlocks(session["frames"]),
                              "takes": [list(t) for t in session["takes"]]}
                             for session in v] for k, v in raw.items()}
        # an instrument still connected goes on in a session of its own, from its next
        # frame: the last project's frames and takes (rows of its sheet) are not this one's
        # (they were saved into it, with a false "edited after capture" on its certificate)
        self.taken = []
        for link in self.links:
            if link.session is not None:
                self._next_session(link, link.session.workbench)
        self.measured_columns = {}  # another project's rows
        self.clear_take_note()  # of another project's rows (day review 64 P7)

    # ------------------------------------------------------------ auto-take
    def _gate_changed(self, *_args) -> None:
        self.gate = (StabilityGate(self.window_box.value(), self.dwell_box.value())
                     if self.auto.isChecked() else None)
        self._origin = None
        self.auto_state.setText("")

    def _window_in(self, unit: str) -> None:
        """The window's field says the unit it is applied in: arcseconds for an angle (a
        readout's degrees are converted to them, as a theodolite's), else the readout's own
        unit (day review 74 F1: a readout's degrees were gated against a window labelled ″,
        0.5 ″ applied as 0.5° = 1800″: a readout drifting 36″/s was taken as stable).
        Another unit than the gate was fed in starts its dwell again."""
        if unit == self._gate_unit:
            return
        self._gate_unit = unit
        self._say_window_unit()
        if self.gate is not None:
            self._gate_changed()  # a dwell or a take in the other unit is not this one's

    def _say_window_unit(self) -> None:
        """The window's suffix and tooltip for the unit it is applied in."""
        unit = self._gate_unit
        angle = unit in ANGLE_UNITS
        self.window_box.setSuffix(" " + _unit_symbol(unit).lstrip() if unit else "")
        self.window_box.setToolTip(
            tr("The spread allowed over the dwell, in arcseconds (a readout in degrees is "
               "converted to them)") if angle else
            tr("The spread allowed over the dwell, in the readout's own unit ({unit}): it "
               "sends no angle unit").format(unit=unit or tr("none")))

    def _feed_gate(self, reading: Reading) -> None:
        self._window_in(reading.unit)
        gate, scale = self.gate, gate_scale(reading.unit)
        if gate is None:
            return
        # the first link's frame fed here is live (it is marked so after the batch; a fault
        # of it restarts the gate itself): the others are asked
        if any(link is not self.links[0] for link in self.waiting_for() + self.used_again()):
            # a take now would leave a lost instrument's cells blank, or repeat another's
            # reading of the last take: the dwell starts again once every link is back with
            # a new reading (_show_gate says which one it waits for)
            gate.restart()
            return
        # angles in degrees go to the gate as continuous offsets from the first frame's
        # (models.capture.stability.UnwrappedAngles: 0°/360° and the first frame's ±180°
        # settle where they are)
        angles = scale != 1.0
        if angles:
            if self._origin is None:
                self._origin = UnwrappedAngles()
            offsets = self._origin.offsets(reading.values)
        else:
            offsets = np.asarray(reading.values, dtype=float)
        step = self.next_reading
        gate.retake = bool(step is not None and step.reading < step.of)
        # with the table's encoder read beside, the move to the next face is seen on it; the
        # autocollimator's reading (nulled at each face) says nothing of it (live76 F1)
        table = self._table_link()
        gate.moves_seen_elsewhere = table is not None
        if gate.waiting_for_move and self._next_point_here(table):
            gate.moved()  # a new set starting where its last closed: read again, no move
        elif table is not None and gate.waiting_for_move:
            link = table[0]
            latest, taken_at = link.latest, link.taken_position
            if latest is not None and taken_at is not None and abs(
                    (float(latest.values[0]) - taken_at + 180.0) % 360.0 - 180.0) \
                    >= self.table_move_deg():
                gate.moved()
        taken = gate.feed(reading.time_s, offsets * scale, tag=reading.frame,
                          others_since=self._others_since())
        if taken is None:
            return
        means = (self._origin.angles(np.asarray(taken.mean) / scale) if angles
                 else tuple(float(m) for m in taken.mean))
        # the reading's frames from its first to this one (the gate keeps the first's index:
        # counting back through the frames kept named one frame for a dwell longer than they
        # hold)
        first = taken.first_tag if taken.first_tag is not None else reading.frame
        self.take_reading(means, (first, reading.frame))

    def _others_since(self) -> float | None:
        """When the oldest of the other links' newest readings came, in the first link's
        time (its worker's seconds), or None with no other link usable: auto-take takes
        only when it came during the first's steady dwell (a readout read before it may be
        of the move: the encoder half-way between two faces beside the second's null)."""
        first = self.links[0]
        times = [link.latest_at for link in self.links
                 if link is not first and link.usable and link.latest_at is not None]
        if not times or first.worker is None:
            return None
        return min(times) - first.worker.t0

    def _behind_the_dwell(self) -> list[InstrumentLink]:
        """The other links whose newest reading came before the dwell in progress began."""
        if self.gate is None or self.links[0].worker is None:
            return []
        since = self.gate.dwell_since
        if since is None:
            return []
        t0 = self.links[0].worker.t0
        return [link for link in self.links if link is not self.links[0] and link.usable
                and link.latest_at is not None and link.latest_at - t0 < since]

    def _show_gate(self) -> None:
        if self.gate is None or self.latest is None:
            self.auto_state.setText("")
            return
        waiting = self.waiting_for()
        if waiting:
            self.auto_state.setText(tr("Auto-take: waiting for {instrument} ({why})").format(
                instrument=waiting[0].name, why=waiting[0].no_reading_why))
            return
        phase, part = self.gate.progress(self.latest.time_s)
        again = [link for link in self.used_again() if link is not self.links[0]]
        if phase == "settling" and part >= 1.0:
            again = again or self._behind_the_dwell()
        table = self._table_link() if phase == "taken" else None
        if table is not None:
            self.auto_state.setText(tr("Auto-take: taken; turn the table to the next face "
                                       "({column} ≥ {move}° from the take)").format(
                column=self.column_name(table[1]), move=f"{self.table_move_deg():g}"))
        elif phase == "taken":
            self.auto_state.setText(tr("Auto-take: taken; move to the next point"))
        elif again:
            self.auto_state.setText(tr("Auto-take: waiting for a new reading from {instrument}")
                                    .format(instrument=again[0].name))
        else:
            text = tr("Auto-take: settling, {percent} % of the dwell").format(
                percent=f"{100 * part:.0f}")
            spread = getattr(self, "_spread", None)
            motion = getattr(self, "_motion", None)
            if spread is not None and spread > self.window_box.value() and motion is not None:
                # moving to the next point, or drifting: the window is not what is wrong,
                # and widening it would take a moving reading as stable (stop 72's leftover:
                # "spreads 5.4e+04″ … widen the window" while the axis turned)
                text += tr(" — the output is moving ({rate} a second): it is taken once it "
                           "stays within the window").format(
                    rate=f"{motion:+.2g}" + _unit_symbol(self._gate_unit))
            elif spread is not None and spread > self.window_box.value():
                # why it waits (#41: a theodolite's 0.3" of noise spread 1.4" over a second:
                # with the 0.5" window it never took, saying only "2 % of the dwell")
                text += tr(" — the output spreads {spread} over a second, more than the "
                           "window: widen the window").format(
                    spread=f"{spread:.2g}" + _unit_symbol(self._gate_unit))
            self.auto_state.setText(text)

    @property
    def auto_phase(self) -> str:
        """"off", "settling" or "taken" (waiting for the instrument to move)."""
        if self.gate is None:
            return "off"
        return self.gate.progress(self.latest.time_s if self.latest else 0.0)[0]

    # ------------------------------------------------------------ where a take goes
    def _targets(self, presenter) -> list[tuple[InstrumentLink, int, str]]:
        """(link, value index, column key) of every value a take writes, for the links
        connected; a readout into "the current cell" gives the current column's key."""
        keys = [c.key for c in presenter.table_model.sheet.columns]
        index = presenter.view.table.currentIndex()
        out = []
        for link in self.links:
            if link.worker is None or not link.kind:
                continue
            if link.kind == "readout":
                key = link.column.currentData() or (
                    keys[index.column()] if index.isValid() else "")
                if key in keys:
                    out.append((link, 0, key))
                continue
            for i, key in enumerate(INSTRUMENTS[link.kind]().columns):
                if key == "zenith_deg" and "elevation_deg" in keys:
                    key = "elevation_deg"
                if key in keys:
                    out.append((link, i, key))
        # a value goes to one column once (the first instrument wins)
        seen: set[str] = set()
        return [t for t in out if not (t[2] in seen or seen.add(t[2]))]

    @staticmethod
    def _placement(presenter):
        """The entry plan's next point (models/readings/entry_plan.py Placement), None when
        the workbench has no plan or it is complete."""
        placement = getattr(presenter, "plan_placement", None)
        return placement() if placement is not None else None

    def target_row(self, presenter=None, placement=None) -> int:
        """The row the next take goes to: with an entry plan, the row of the plan's next point
        (``placement``, else the presenter's); without one, the current row when the cells
        it fills are blank; else a row above it whose reading was cleared (a take thrown
        away: :func:`~models.capture.take_cells.cleared_row`), else the next empty point
        below it, else a new row. Never a row whose cells the take fills are filled. The
        guidance names this row, and it waits for its reading (not a bad row): a click on
        a filled row does not move the take away from a cleared one (day review 64 P4)."""
        presenter = presenter or self.window_.current
        sheet = presenter.table_model.sheet
        index = presenter.view.table.currentIndex()
        row = index.row() if index.isValid() else sheet.row_count
        place = placement or self._placement(presenter)
        if place is not None:
            row = place.row
        else:
            # a row above the cursor still waiting for its reading is the next point (θ typed
            # and Return with a nominal step: the cursor went on to the next row) — the row
            # the caption and the guidance name (#41 review)
            waiting = getattr(presenter, "waiting_row", lambda: None)()
            if waiting is not None and waiting < row:
                row = waiting
        keys = [c.key for c in sheet.columns]
        columns = [keys.index(key) for _, _, key in self._targets(presenter)]
        if not columns:
            return row
        if place is None and (row >= sheet.row_count
                              or any(sheet.text(row, c).strip() for c in columns)):
            cleared = cleared_row(min(row, sheet.row_count), sheet.column_count, columns,
                                  presenter.table_model.reading_columns, sheet.text)
            if cleared is not None:
                return cleared
        return next_empty_point(sheet.row_count, row, columns, sheet.text)

    def _cell(self, presenter, link: InstrumentLink, i: int, key: str, value: float,
              unit: str, row: int) -> tuple[str, str, float]:
        """(the text value ``i`` of ``link`` is written as in column ``key`` of ``row``, the
        column's unit symbol, the step it was rounded to): the elevation from a zenith angle
        where the column reads elevation, D°M′S″ where the column is written so, rounded to
        the instrument's resolution."""
        sheet = presenter.table_model.sheet
        keys = [c.key for c in sheet.columns]
        if link.kind == "theodolite" and i == 1 and key == "elevation_deg" \
                and presenter.settings.get("vertical_reading") != "zenith":
            value = elevation_from_zenith_deg(value)
        column = keys.index(key)
        column_def = sheet.columns[column]
        dms = unit == "deg" and column_is_dms(
            [sheet.text(r, column) for r in range(max(0, row - 50), min(row, sheet.row_count))]
            or [sheet.text(r, column) for r in range(min(sheet.row_count, 50))])
        if dms:
            symbol = ""  # D°M′S″ carries its units
        elif column_def.unit in ('"', "arcsec") or unit == "arcsec":
            symbol = '"'
        elif unit == "deg":
            symbol = "°"
        else:
            symbol = f" {unit}" if unit else ""
        return (cell_text(value, unit, link.resolution_arcsec, dms, column_def.unit), symbol,
                cell_step(unit, link.resolution_arcsec, dms, column_def.unit))

    def column_name(self, key: str) -> str:
        """The name the user sees for an instrument's value ``key``: its column's header on
        the workbench in front, else the instrument's own name for it (never the key)."""
        presenter = getattr(self.window_, "current", None)
        columns = presenter.table_model.sheet.columns if presenter is not None else ()
        header = next((c.header for c in columns if c.key == key), None)
        if header is None:
            return _VALUE_NAMES.get(key, key)
        # the header less its unit ("AC x [″]"): the figure beside it carries the unit
        return re.sub(r"\s*\[[^\]]*\]$", "", str(declared(header))) or str(declared(header))

    def cell_texts(self, link: InstrumentLink, values: tuple[float, ...],
                   unit: str) -> dict[int, tuple[str, str]]:
        """{value index: (cell text, unit symbol)} for the values of ``link`` a take would
        write on the workbench in front, as it would write them."""
        presenter = getattr(self.window_, "current", None)
        if presenter is None:
            return {}
        targets = [(i, key) for t_link, i, key in self._targets(presenter) if t_link is link]
        if not targets:
            return {}
        # the column's format from its last rows (the plan's placement is not worked out at
        # every value shown: the live value follows the stream)
        row = presenter.table_model.sheet.row_count
        return {i: self._cell(presenter, link, i, key, values[i], unit, row)[:2]
                for i, key in targets if i < len(values)}

    # ------------------------------------------------------------ guidance
    def update_guide(self) -> None:
        """What the workbench says to do next, for the row the next reading goes to."""
        presenter = self.window_.current
        kind = presenter.kind
        if not isinstance(kind, GuidesAcquisition):
            self.next_reading = None
            self.guide.setText("")
            return
        sheet = presenter.table_model.sheet
        place = self._placement(presenter)
        row = self.target_row(presenter, place)
        keys = [c.key for c in sheet.columns]

        def cells(r: int) -> dict[str, str]:
            if r >= sheet.row_count:
                return dict.fromkeys(keys, "")
            return {k: sheet.text(r, c) for c, k in enumerate(keys)}

        current = cells(row)
        if place is not None and place.row == row:
            # the entry plan's next point, where its cells are still blank (the row is
            # pre-filled only at Return or a take): the guidance said "type θ" while the
            # table's caption said "next: θ = −14°" (day 65, F9)
            current.update({k: v for k, v in place.cells.items()
                            if k in current and not current[k].strip()})
        step = presenter.view.table.nominal_step or 0.0
        self.next_reading = kind.acquisition_guide(
            [cells(r) for r in range(min(row, sheet.row_count))], current, presenter.settings,
            step)
        complete = 0 if place is not None else getattr(presenter, "plan_complete", int)()
        if complete:
            # the plan's end said, not a point after it ("go to face 3" under "plan
            # complete (26/26)"): a take now adds a reading the plan does not have
            self.guide.setText(tr("Entry plan complete ({n} points): a further take is added "
                                  "after it").format(n=complete))
            return
        self.guide.setText(tr("Next: {what}").format(what=translated(self.next_reading.text)))

    # ------------------------------------------------------------ the live readout
    def drain(self) -> None:
        """What the workers have queued, without waiting: for at most ``DRAIN_BUDGET_S`` a
        tick, so a stream faster than the window can follow makes a backlog (worked off in
        the next ticks), never a frozen window."""
        active = [link for link in self.links if link.worker is not None]
        for link in active:  # each its share: a fast stream never starves the other link
            self._drain_link(link, link.worker, time.perf_counter() + DRAIN_BUDGET_S / len(active))
        for link in self.links:
            # a worker whose thread ended without a word (ending by itself it says a final
            # fault; a crash would not): its value is no longer refreshed. Silence is the
            # worker's own to judge (Stale, its faults), never this timer's
            if link.worker is not None and link.latest is not None and not link.lost \
                    and not link.worker.running and link.worker.events.empty():
                link.mark_lost(True)

    def _drain_link(self, link: InstrumentLink, worker: CaptureWorker,
                    until: float = math.inf) -> None:
        fresh = ended = False
        first = link is self.links[0]
        while time.perf_counter() < until:
            try:
                event = worker.events.get_nowait()
            except queue.Empty:
                break
            if isinstance(event, Fault):
                reason = translated(event.message)
                link.last_fault = reason
                link.no_target = None  # silence, not a target out of view
                link.status.setText(reason if event.final
                                    else tr("{reason} (reconnecting)").format(reason=reason))
                link.status.setStyleSheet("color: #b00020;")
                link.mark_lost(True)
                if link.frames:
                    link.gap_before = link.frames[-1][0]
                if first and self.gate is not None:
                    self.gate.restart()  # a take never bridges the frames the link lost
                ended = ended or event.final
                continue
            if isinstance(event, NoTarget):
                if link.no_target is None:
                    link.no_target = event
                continue
            if isinstance(event, Stale):
                # no reading for STALE_S, as the worker saw it itself
                if link.latest is not None:
                    if link.no_target is not None:  # frames come, no measurement: said so
                        link.say_no_target()
                    link.mark_lost(True)
                continue
            if link.no_target is not None:
                self._target_back(link, event)
            link.received += 1
            link.frames.append((event.time_s, event.values, event.frame))
            link.latest = event
            # when it came, on the monotonic clock every link's worker counts from: auto-take
            # pairs the first link's steady dwell only with the others' readings since
            link.latest_at = worker.t0 + event.time_s
            if link.session is not None and link.received % 1000 == 0:
                if link.session.behind() >= FRAMES_PER_BLOCK:
                    link.session.catch_up()  # a block's worth converted, not hours at a save
                link.release_raw()  # and the worker's memory holds only what is not
            fresh = True
            if first:
                if event.time_s >= self._guide_due:
                    self._guide_due = event.time_s + GUIDE_EVERY_S
                    self.update_guide()
                self._feed_gate(event)
        if fresh and link.worker is worker and not ended:
            if link.status.styleSheet():  # a style set anew repolishes the label
                link.status.setStyleSheet("")
            link.status.setText(tr("Connected: {port}").format(port=worker.port)
                                if not link.last_fault else
                                tr("Connected: {port} (reconnected after: {reason})").format(
                                    port=worker.port,
                                    # in the language now (live78: "cannot open (timed
                                    # out)" stayed English in the Chinese window)
                                    reason=_without_port(str(said_again(link.last_fault)),
                                                         worker.port)))
            if link.lost:
                link.mark_lost(False)
            self._links_changed()
        if fresh or (first and self._show_pending):
            now = time.perf_counter()
            pending = now < self._show_due and link.worker is worker and not ended
            if first:
                self._show_pending = pending
            if not pending or not first:
                if first:
                    self._show_due = now + SHOW_EVERY_S
                    self._show_statistics()
                    self._show_gate()
                link.show_value()
        if ended and link.worker is worker:
            if self.auto.isChecked():
                # no auto-take goes on without an instrument it fills cells from: the
                # rows after it would lack that instrument's reading
                name = link.name
                self.auto.setChecked(False)
                self.take_note.setText(tr("Auto-take switched off: the link to {instrument} "
                                          "ended ({reason})").format(
                    instrument=name, reason=link.last_fault))
            link.disconnect()

    def _target_back(self, link: InstrumentLink, reading: Reading) -> None:
        """A reading after frames with no measurement: out of view for
        :data:`~models.capture.stability.OUT_OF_VIEW_GAP_S` or more, that is a gap (the dwell
        starts afresh, the Allan deviation is of the frames after it) and, for the first
        instrument with no table encoder beside it, the move to the next face (live76 F1:
        an autocollimator nulled at each face reads within the window of the last take at
        every face, and auto-take waited for ever)."""
        gone = link.no_target
        link.no_target = None
        if gone is None or reading.time_s - gone.time_s < OUT_OF_VIEW_GAP_S:
            return  # a frame marked not valid among good ones: no gap
        if link.frames:
            link.gap_before = link.frames[-1][0]
        if link is self.links[0]:
            # the table seen turning (a repeat of the point after it is not its reading)
            self._turn_seen = max(self._turn_seen or 0.0, reading.time_s - gone.time_s)
        if link is self.links[0] and self.gate is not None:
            self.gate.restart()
            if self._table_link() is None:
                self.gate.moved()

    def _table_link(self) -> tuple[InstrumentLink, str] | None:
        """The second instrument that reads the table's encoder (:data:`TABLE_COLUMNS`) in
        degrees, with the column, once it has a take to count from: the table's move to the
        next face is seen on it."""
        presenter = getattr(self.window_, "current", None)
        if presenter is None:
            return None
        for link, _, key in self._targets(presenter):
            if link is not self.links[0] and key in TABLE_COLUMNS and link.connected \
                    and link.taken_position is not None \
                    and (link.latest is None or link.latest.unit == "deg"):
                return link, key
        return None

    def _next_point_here(self, table: tuple[InstrumentLink, str] | None) -> bool:
        """The entry plan's next point is where the last take was, so there is no move to
        wait for: the next set starting at the face its last closed on (the polygon's set 2 at
        face 1, read right after set 1's closure there). With the table's encoder: the
        reading the guide expects (or each it would take) within half the pitch of the
        encoder at the last take; else the face the guide names is the last take's row's."""
        step = self.next_reading
        presenter = getattr(self.window_, "current", None)
        if step is None or presenter is None or step.reading > 1:
            return False
        if self._placement(presenter) is None:
            # only the entry plan says a next point is read where the last was: with none,
            # or done, the guide's next set is open-ended (a take then, by itself, read the
            # last face over and over), and the move is waited for
            return False
        if table is not None:
            link, key = table
            if link.taken_position is None:
                return False
            nominal = step.nominal.get(key)
            candidates = (nominal,) if nominal is not None else step.near.get(key, ())
            return any(abs((c - link.taken_position + 180.0) % 360.0 - 180.0)
                       < self.table_move_deg() for c in candidates)
        face = step.fill.get("position", "").strip()
        last = next((row for key, row, _ in reversed(self.taken)
                     if key == presenter.kind.key), None)
        sheet = presenter.table_model.sheet
        keys = [c.key for c in sheet.columns]
        if not face or last is None or "position" not in keys or last >= sheet.row_count:
            return False
        return sheet.text(last, keys.index("position")).strip() == face

    def table_move_deg(self) -> float:
        """How far the table's encoder must turn from the last take for the next face: half
        the pitch between faces (360°/N), the same half the off-plan check counts a reading
        nearer another face by. A table nudged to null the autocollimator (seconds to
        minutes of arc) is no move; half of 1° while the pitch is not known."""
        step = self.next_reading
        pitch = step.pitch_deg if step is not None and step.pitch_deg > 0.0 \
            else TABLE_PITCH_UNKNOWN_DEG
        return pitch / 2.0

    def _show_statistics(self) -> None:
        reading = self.latest
        if reading is None:
            return
        now = reading.time_s
        recent, times = [], []
        for t, v, _ in reversed(self.frames):
            if t < now - SPREAD_SECONDS:
                break
            recent.append(v)
            times.append(t)
        degrees = reading.unit == "deg"
        scale = gate_scale(reading.unit)
        recent = np.array(recent)
        if degrees and len(recent):  # an angle near 0°/360° spreads by its noise, not 360°
            recent = _unwrapped_deg(recent, recent[0])
        if len(recent) > 1:
            spread = recent.max(axis=0) - recent.min(axis=0)
            self._spread = float(np.max(spread)) * scale  # in the gate's unit
            # a spread that is the axis moving (or drifting) is not a window too tight
            rate = steady_motion(times, recent)
            self._motion = None if rate is None else rate * scale
            # in the window's unit (arcseconds for an angle, else the readout's own), after
            # each axis's figure (live78: "0.097   0.097\"" left the first without one)
            unit = _unit_symbol(reading.unit)
            shown = "   ".join(f"{s * scale:.3f}{unit}" for s in spread)
            self.stability.setText(tr("Spread over the last second: {spread}{unit}").format(
                spread=shown, unit=""))
        if now >= self._allan_due and len(self.frames) >= 16:
            self._allan_due = now + 1.0
            self._show_allan(degrees, scale)

    def _show_allan(self, degrees: bool, scale: float) -> None:
        """The first instrument's Allan deviation over its frames since the last gap (a link
        lost, a pause, a rate set anew): the formula takes frames as evenly spaced, and
        frames from both sides of a gap as neighbours showed a step across it as noise.
        Only over the frames since the reading last moved, in the window's unit with three
        significant digits (day review live76 F9: "5.1e+03 (0.0753 s)" of a readout moved
        from target to target, the moves read as noise)."""
        link = self.links[0]
        kept = [frame for frame in self.frames if frame[0] > link.gap_before]
        times = np.array([t for t, _, _ in kept])
        start = last_even_run(times)
        if len(kept) - start < 16:
            if not self.frames:
                self.allan.setText("")
            elif link.gap_before > -math.inf:  # the link lost, a pause, the target gone
                self.allan.setText(tr("Allan deviation: waiting for frames after the gap"))
            else:  # no gap: frames that came unevenly (gui78, live78: "after the gap" said
                # right after a fresh connection)
                self.allan.setText(tr("Allan deviation: waiting for 16 frames at an even pace "
                                      "({count} so far)").format(count=len(kept) - start))
            return
        first = np.array([v[0] for _, v, _ in kept[start:]])
        if degrees:
            first = _unwrapped_deg(first, first[0])
        still = last_still_run(first * scale, self.window_box.value())
        if len(first) - still < 16:
            self.allan.setText(tr("Allan deviation: the reading is moving (waiting for it to "
                                  "stay still)"))
            return
        after_gap = len(kept) != len(self.frames)  # the frames after a gap of the link
        uneven = start > 0  # the frames since their spacing last broke
        times, first = times[start + still:], first[still:]
        tau0 = float(np.median(np.diff(times)))
        taus, adev = allan_deviation(first, tau0)
        # three of them (the shortest, a middle and the longest τ): the text stays short
        picked = sorted({0, len(taus) // 2, len(taus) - 1}) if len(taus) else []
        unit = _unit_symbol(self.latest.unit if self.latest is not None else "")
        figures = ", ".join(f"{_significant(adev[i] * scale)}{unit} ({_significant(taus[i])} s)"
                            for i in picked)
        if still:
            said = tr("Allan deviation (first axis, since the reading last moved): {figures}")
        elif after_gap:
            said = tr("Allan deviation (first axis, since the last gap): {figures}")
        elif uneven:
            said = tr("Allan deviation (first axis, since the frames' pace last broke): "
                      "{figures}")
        else:
            said = tr("Allan deviation (first axis): {figures}")
        self.allan.setText(said.format(figures=figures))

    # ------------------------------------------------------------ take reading
    def waiting_for(self) -> list[InstrumentLink]:
        """The links connected with no reading to take now (lost, reconnecting, or none
        yet): no take is made while there is one, or its cells would stay blank."""
        return [link for link in self.links if link.connected and not link.usable]

    def used_again(self) -> list[InstrumentLink]:
        """The links usable whose latest reading a take has used already: a second take from
        it would fill another row with the same frame, a reading repeated as if it were
        another (#60 review: F9 twice between two replies of a slow theodolite)."""
        return [link for link in self.links if link.usable
                and link.latest.frame <= link.taken_frame]

    def claim_columns(self, link: InstrumentLink) -> None:
        """The columns ``link`` fills on the workbench in front are measured columns there
        from now on (:attr:`measured_columns`)."""
        presenter = getattr(self.window_, "current", None)
        if presenter is None:
            return
        self.measured_columns.setdefault(presenter.kind.key, set()).update(
            key for t_link, _, key in self._targets(presenter) if t_link is link)

    def _set_take_text(self, text: str) -> None:
        """The take button's text in the language now, and its key again: Qt's setText puts
        the text's mnemonic (none) in place of the shortcut, so after View › Language F9 — a
        foot switch — took nothing and said nothing (day review 64)."""
        self.take_button.setText(text)
        self.take_button.setShortcut(QKeySequence(TAKE_READING_KEY))

    def take_reading(self, values: tuple[float, ...] | None = None,
                     frames: tuple[int, int] | None = None) -> str:
        """Fill the row a take goes to (:meth:`target_row`) from every instrument connected
        — the first's latest reading, or ``values`` (an auto-take's mean of its raw
        ``frames`` first…last), with the second's latest — and the cells the guidance says,
        as one undo step; what it did ("" when nothing was taken). No take while a link
        connected has no reading to give (:meth:`waiting_for`)."""
        first = self.links[0]
        presenter = self.window_.current
        # the take note (set below) is of this workbench's sheet: it goes when that sheet
        # is replaced (sheet_replaced)
        self.take_note_of = presenter.kind.key
        # an auto-take's frames are the first link's, live (it is marked so only after the
        # batch that brought it back: asked, a take at the end of that batch was refused
        # while the gate counted it taken)
        waiting = [link for link in self.waiting_for() if values is None or link is not first]
        if waiting:
            self.take_note.setText(tr("Not taken: no reading from {instrument} ({why})")
                                   .format(instrument=waiting[0].name,
                                           why=waiting[0].no_reading_why))
            return ""
        # a take by hand uses every link's latest frame: each must be new since its last
        # take (auto-take's own frames are new; the gate waits for the others': _feed_gate)
        again = [link for link in self.used_again() if values is None or link is not first]
        if again:
            self.take_note.setText(tr("Not taken: no new reading from {instrument} since the "
                                      "last take").format(instrument=again[0].name))
            return ""
        table = presenter.view.table
        model = presenter.table_model
        sheet = model.sheet
        keys = [c.key for c in sheet.columns]
        targets = self._targets(presenter)
        taking: dict[int, tuple[tuple[float, ...], str, tuple[int, int]]] = {}
        for link in self.links:
            if link is first and values is not None and first.latest is not None:
                taking[0] = (tuple(values), first.latest.unit,
                             frames or (first.latest.frame, first.latest.frame))
            elif link.usable:
                reading = link.latest
                taking[link.slot] = (reading.values, reading.unit, (reading.frame, reading.frame))
        # the columns an instrument fills: connected now, or filled or set to fill on this
        # workbench before (a link that gave up, or was disconnected). Only the instrument
        # writes there: the plan's cells and its nominal (the encoder expected at the face)
        # never do — a nominal pre-filled is a set-point for a workbench read without the
        # encoder's readout, never a value in a column a readout measures
        measured = self.measured_columns.setdefault(presenter.kind.key, set())
        measured.update(key for _, _, key in targets)
        instrument_columns = {keys.index(key) for key in measured if key in keys}
        targets = [t for t in targets if t[0].slot in taking]
        if not targets:
            if taking:
                # in the panel, beside the guidance (the status line it was written to was
                # rewritten by the next reading)
                self.take_note.setText(tr("Not taken: this workbench has no column for this "
                                          "instrument's reading: choose a column in “Readout "
                                          "into” (readout) or another workbench"))
            return ""
        placed = {link.slot for link, _, _ in targets}
        notes = [self._not_placed(link) for link in self.links
                 if link.slot in taking and link.slot not in placed]
        place = self._placement(presenter)
        row = self.target_row(presenter, place)
        # a take after the entry plan's end: said beside the guidance, the reading kept
        beyond = getattr(presenter, "after_plan_end", lambda _row: "")(row) \
            if place is None else ""
        notes += [beyond] if beyond else []
        # a position in degrees in its target's turn (positioning's measured: a readout's
        # 359.5 at target 0° is −0.5); the raw trace keeps it as sent
        taking = self._in_target_turn(presenter, row, place, targets, taking)
        self.update_guide()
        # a repeat of a point that cannot be this point's (the table at another face): never
        # filed under it (capture80: face 3's reading went in as face 2's reading 2)
        refused = self._not_this_points(presenter, row, targets, taking, by_hand=values is None)
        if refused:
            self._turn_said = True
            self.take_note.setText(refused)
            return ""
        changes = []
        steps: dict[int, float] = {}
        for link, i, key in targets:
            got, unit, _ = taking[link.slot]
            if i >= len(got):
                continue
            column = keys.index(key)
            text, _, step = self._cell(presenter, link, i, key, got[i], unit, row)
            changes.append((row, column, text))
            # the step the cell was rounded to: within half of it the cell is as captured
            steps[link.slot] = max(steps.get(link.slot, 0.0), step)
        # a reading that does not match its row's point (another face, another target): said
        # beside the guidance and its cell marked in the table (live76 F1: later takes went
        # into another face's row without a word)
        mismatched = self._off_the_plan(sheet, row, targets, taking) \
            + self._off_the_target(presenter, row, place, targets, taking)
        notes += [text for _, text in mismatched]
        filled = {c for _, c, _ in changes}
        if place is not None and place.row == row:  # the plan's cells, where blank
            for key, text in place.cells.items():
                if key not in keys or keys.index(key) in filled \
                        or keys.index(key) in instrument_columns:
                    continue
                if row >= sheet.row_count or not sheet.text(row, keys.index(key)).strip():
                    changes.append((row, keys.index(key), text))
                    filled.add(keys.index(key))
        if self.next_reading is not None:
            for key, text in self.next_reading.fill.items():
                if key not in keys or keys.index(key) in filled \
                        or keys.index(key) in instrument_columns:
                    continue
                blank = row >= sheet.row_count or not sheet.text(row, keys.index(key)).strip()
                if blank:
                    changes.append((row, keys.index(key), text))
                    filled.add(keys.index(key))
            # the reading the plan expects (the encoder at the face), where no instrument
            # fills that column and the cell is blank
            for key, value in self.next_reading.nominal.items():
                if key not in keys:
                    continue
                column = keys.index(key)
                if column in filled or column in instrument_columns:
                    continue
                if row < sheet.row_count and sheet.text(row, column).strip():
                    continue
                dms = column_is_dms([sheet.text(r, column) for r in range(
                    max(0, row - 50), min(row, sheet.row_count))])
                changes.append((row, column, cell_text(value, "deg", NOMINAL_RESOLUTION_ARCSEC,
                                                       dms, sheet.columns[column].unit)))
                filled.add(column)
        changes += self._from_reference(sheet, keys, row, changes, filled,
                                         getattr(presenter, "face_deviations", {}))
        new_takes = []
        for link in self.links:
            got = taking.get(link.slot)
            session = link.session
            if got is not None and session is not None and got[2][0] >= session.first \
                    and any(t[0] is link for t in targets):
                # indices into the session's own frames (it may start mid-connection)
                new_takes.append((link, session, [UNDONE, got[2][0] - session.first,
                                                  got[2][1] - session.first]))
        # the take and its cells one undo step: Edit › Undo undoes the take too (review 62
        # F4: an undone take kept its row, and a reading typed there later was printed as
        # "edited after capture", with the undone take's values). In its session before
        # (undone), so that the cells come with it in its row, superseding an older take
        # there (review 62 F1: marked edited until the next change)
        for link, i, key in targets:  # where the table was at this take
            got, unit, _ = taking[link.slot]
            if key in TABLE_COLUMNS and unit == "deg" and i < len(got):
                link.taken_position = float(got[i])
        for link, session, take in new_takes:
            session.takes.append(take)
            session.steps.append(steps.get(link.slot, 0.0))
            if link.kind == "readout":  # the cell it wrote, for the check after (P3)
                session.columns.append(next((key for t_link, _, key in targets
                                             if t_link is link), ""))
            link.taken_frame = max(link.taken_frame, take[2] + session.first)
        keyed = [(link, take_key(session.kind, session.worker.port, session.started_utc, take))
                 for link, session, take in new_takes]
        label = tr("Take reading (row {row})").format(row=row + 1)
        # the take and the plan's pre-fill of the next row (or the next nominal) that it
        # makes are one undo step: one Edit › Undo takes the reading back (rev62day F15: the
        # first undid the pre-fill, only the second the take)
        model.undo_stack.beginMacro(label)
        try:
            model.set_cells(changes, label, takes=[(key, row) for _, key in keyed],
                            columns={key: frozenset(k for t, _, k in targets if t is link)
                                     for link, key in keyed})
            self._widen(table, changes)
            for key, text in mismatched:
                model.warn_take(row, keys.index(key), text)
            if 0 in taking:
                self.taken.append((presenter.kind.key, row, tuple(taking[0][0])))
            # what the take could not place, or took far from where the plan expects it:
            # said until the next take (the reading is kept)
            self.take_note.setText("\n".join(notes))
            self._turn_seen, self._turn_said = None, False  # a turn is of the takes after
            table.next_row(row)
        finally:
            model.undo_stack.endMacro()
        self._note_with_take(model.undo_stack)
        self.update_guide()
        # a take is on disk at once, as `anglebench capture` syncs each reading to its
        # journal: it cannot be typed again, the instrument has moved on (hostile77 M2: a
        # window killed within the autosave's few seconds lost it)
        projects = getattr(self.window_, "projects", None)
        if projects is not None and hasattr(projects, "autosave_now"):
            projects.autosave_now()
        return f"row {row + 1}"

    def _not_this_points(self, presenter, row: int, targets, taking, by_hand: bool) -> str:
        """Why a take cannot be the repeat of its point the guidance names (reading k > 1 of
        a face, :attr:`next_reading`), or "" when it can be: the table's encoder more than
        half the pitch from the face's first reading, or — with no encoder in the take — the
        table seen turning since the last take (:attr:`_turn_seen`: the mirror out of view).
        models/capture/repeat_check.py says why those limits. The autocollimator alone cannot
        tell whether the table came back to the face: after the refusal is said, a take by
        hand (F9) is the technician's word that it did."""
        step = self.next_reading
        if step is None or step.reading <= 1:
            return ""
        sheet = presenter.table_model.sheet
        keys = [c.key for c in sheet.columns]
        # the point's earlier readings: the used rows just above the take's (the guide's);
        # the first of them is its reading 1
        earlier = 0
        first = min(row, sheet.row_count) - 1
        while first >= 0:
            if any(sheet.text(first, c).strip() for c in range(sheet.column_count)):
                earlier += 1
                if earlier == step.reading - 1:
                    break
            first -= 1
        if first < 0:
            return ""
        face = step.fill.get("position", "").strip()
        if not face and "position" in keys:
            face = sheet.text(first, keys.index("position")).strip()
        for link, i, key in targets:
            got, unit, _ = taking[link.slot]
            if key not in TABLE_COLUMNS or unit != "deg" or i >= len(got):
                continue
            try:
                was = float(parse_angle_deg(sheet.text(first, keys.index(key))))
            except (ValueError, TypeError, OverflowError):
                continue
            if not math.isfinite(was):
                continue
            # the encoder is in the take: it says where the table is, whatever the mirror did
            away = turned_away(float(got[i]), was, step.pitch_deg)
            if away is None:
                return ""
            return tr("Not taken: face {face}'s reading {k} of {n} is due, but the table is at "
                      "another face: {column} {value}° is {off}° from the {first}° of its "
                      "reading 1 (a repeat reads within half the {pitch}° between faces). Turn "
                      "back to face {face} and take reading {k} there; the readings taken are "
                      "kept").format(
                face=face, k=step.reading, n=step.of, column=self.column_name(key),
                value=f"{round(away.value_deg, 4) % 360.0:.4f}", off=f"{away.off_deg:+.1f}",
                first=f"{round(away.first_deg, 4) % 360.0:.4f}",
                pitch=degrees_text(2.0 * away.limit_deg))
        if self._turn_seen is None or (by_hand and self._turn_said):
            return ""
        return tr("Not taken: face {face}'s reading {k} of {n} is due, but the table was seen "
                  "turning since its reading {last} (the mirror out of view for {seconds} s). "
                  "Turn back to face {face}, null the autocollimator and press F9 (Take "
                  "reading): without the table's encoder the faces cannot be told apart. The "
                  "readings taken are kept").format(
            face=face, k=step.reading, n=step.of, last=step.reading - 1,
            seconds=f"{self._turn_seen:.1f}")

    def _not_placed(self, link: InstrumentLink) -> str:
        """Why a take holds no reading of ``link`` (connected, with a reading to give)."""
        if link.kind == "readout":
            return tr("{instrument}: its reading was not taken: no column of its own to go to "
                      "(the current cell's is another instrument's, or there is none) — "
                      "choose one in “Readout into”").format(instrument=link.name)
        return tr("{instrument}: its reading was not taken: this workbench has no column for "
                  "it").format(instrument=link.name)

    def _off_the_plan(self, sheet, row: int, targets, taking) -> list[tuple[str, str]]:
        """A warning per angle a take reads more than half the pitch between the plan's
        points away from the one the plan expects there (:attr:`next_reading`'s nominal:
        the encoder at the face) — the table at another face (#62 review F9: 300° taken
        where 270° was expected, without a word). The reading is kept; with the key of the
        column it is in (the take marks that cell)."""
        step = self.next_reading
        if step is None or step.pitch_deg <= 0.0 or not (step.nominal or step.near):
            return []
        keys = [c.key for c in sheet.columns]
        out = []
        for link, i, key in targets:
            # the reading the plan expects, or those it would take when it cannot say which
            # (the polygon's second face: either way round from the first)
            nominal = step.nominal.get(key)
            candidates = (nominal,) if nominal is not None else step.near.get(key, ())
            got, unit, _ = taking[link.slot]
            if not candidates or unit != "deg" or i >= len(got):
                continue
            expected, off = min((
                (c, (float(got[i]) - c + 180.0) % 360.0 - 180.0) for c in candidates),
                key=lambda pair: abs(pair[1]))
            if abs(off) <= step.pitch_deg / 2.0:
                continue
            out.append((key, tr("Row {row}: {column} {value}° is {off}° from the ≈ {expected}° the "
                          "plan expects at face {face} (more than half the {pitch}° between "
                          "faces): check the table's position. The reading is kept; undo the "
                          "take if it is wrong").format(
                row=row + 1, column=declared(sheet.columns[keys.index(key)].header),
                face=step.fill.get("position", "?"),
                # rounded before the turn is taken: −0.00001 is 0.0000°, not 360.0000° beside
                # the cell's "-0.00001" (day review live76 F11)
                value=f"{round(float(got[i]), 4) % 360.0:.4f}", off=f"{off:+.1f}",
                expected=degrees_text(expected), pitch=degrees_text(step.pitch_deg))))
        return out

    @staticmethod
    def _row_angle(presenter, row: int, place, key: str) -> float | None:
        """The number in column ``key`` of ``row`` once the take has filled it: its text, or
        the plan's cell for it where it is blank (None: neither is a number)."""
        sheet = presenter.table_model.sheet
        keys = [c.key for c in sheet.columns]
        text = sheet.text(row, keys.index(key)) if key in keys and row < sheet.row_count else ""
        if not text.strip() and place is not None and place.row == row:
            text = str(place.cells.get(key, ""))
        try:
            value = float(parse_angle_deg(text))
        except (ValueError, TypeError, OverflowError):
            return None
        return value if math.isfinite(value) else None

    def _in_target_turn(self, presenter, row: int, place, targets, taking):
        """``taking`` with each reading in degrees (or with no unit, into a column in degrees)
        that goes to a column of positions (``Workbench.reading_positions``) in the turn of its
        row's target (models/capture/take_cells.py in_turn_of)."""
        positions = presenter.kind.reading_positions(presenter.settings)
        out = dict(taking)
        for link, i, key in targets:
            got, unit, frames = out[link.slot]
            position = positions.get(key)
            if position is None or position[1] != "deg" or unit not in ("deg", "") \
                    or i >= len(got):
                continue
            near = self._row_angle(presenter, row, place, position[0])
            if near is not None:
                values = list(got)
                values[i] = in_turn_of(float(values[i]), near)
                out[link.slot] = (tuple(values), unit, frames)
        return out

    def _off_the_target(self, presenter, row: int, place, targets,
                        taking) -> list[tuple[str, str]]:
        """A warning per reading of a position (``Workbench.reading_positions``: positioning's
        measured) nearer another target of the plan than its row's: more than half the
        distance to the neighbouring target from it (models/capture/wrong_target.py) — the
        axis at another target. The reading is kept."""
        positions = presenter.kind.reading_positions(presenter.settings)
        if not positions:
            return []
        plan = getattr(presenter, "entry_plan", lambda: None)()
        planned = plan.spec.get("targets") if plan is not None else None
        if not planned:
            return []
        sheet = presenter.table_model.sheet
        keys = [c.key for c in sheet.columns]
        out = []
        for link, i, key in targets:
            position = positions.get(key)
            got, unit, _ = taking[link.slot]
            if position is None or unit not in (position[1], "") or i >= len(got):
                continue
            target = self._row_angle(presenter, row, place, position[0])
            off = None if target is None else off_target(float(got[i]), target, planned)
            if off is None:
                continue
            symbol = "°" if position[1] == "deg" else f" {position[1]}"
            out.append((key, tr("Row {row}: {column} {value}{unit} is {off}{unit} from target "
                          "{target}{unit}, the plan's for this row (more than half the "
                          "{gap}{unit} to the neighbouring target {neighbour}{unit}): check the "
                          "axis's position. The reading is kept; undo the take if it is "
                          "wrong").format(
                row=row + 1, column=declared(sheet.columns[keys.index(key)].header),
                value=f"{off.reading:.4f}", off=f"{off.off:+.4f}", unit=symbol,
                target=f"{off.target:g}", gap=f"{off.gap:g}", neighbour=f"{off.neighbour:g}")))
        return out

    @staticmethod
    def _widen(table, changes) -> None:
        """The columns a take filled widened to their new text when it needs more room (an
        increment, not a re-measure of every cell: the window never pauses for it)."""
        header = table.horizontalHeader()
        if header.sectionResizeMode(0) == QHeaderView.ResizeMode.ResizeToContents:
            return  # Qt fits them itself
        metrics = table.fontMetrics()
        for _, column, text in changes:
            needed = metrics.horizontalAdvance(text) + 16
            if needed > header.sectionSize(column):
                header.resizeSection(column, needed)

    @staticmethod
    def _from_reference(sheet, keys, row, changes, filled,
                        loaded: Mapping[int, str] | None = None) -> list[tuple[int, int, str]]:
        """A polygon face's deviation (its certificate's, as sent or typed for that face in
        another row, else as the certificate ``loaded`` before the face had a row gives
        it: PolygonPresenter.face_deviations) into the row the take fills, when its cell
        is blank."""
        if "polygon_dev_arcsec" not in keys or "position" not in keys:
            return []
        dev, position = keys.index("polygon_dev_arcsec"), keys.index("position")
        if dev in filled or (row < sheet.row_count and sheet.text(row, dev).strip()):
            return []
        face = next((t for r, c, t in changes if c == position), None)
        if face is None and row < sheet.row_count:
            face = sheet.text(row, position)
        face = (face or "").strip()
        if not face:
            return []
        known = {sheet.text(r, dev).strip() for r in range(sheet.row_count)
                 if r != row and sheet.text(r, position).strip() == face
                 and sheet.text(r, dev).strip()}
        # one deviation per face; two different ones are the technician's to settle
        if not known and loaded and face.isdigit() and int(face) in loaded:
            known = {loaded[int(face)]}
        return [(row, dev, known.pop())] if len(known) == 1 else []
