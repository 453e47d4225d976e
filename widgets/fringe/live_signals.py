"""The fringe workbench's *Live signals* tab: a read head's sin/cos signals watched while it
is mounted, as an encoder maker's test set shows them.

A stream (an ADC or oscilloscope on a serial port or TCP, ``u_sin,u_cos`` a line, or a
pattern with groups ``sin`` and ``cos``; or the demonstration head) is read by a worker
thread in blocks; a timer (:data:`REFRESH_MS`, the display's rate, never per sample)
takes in what arrived and redraws once from the sliding window of the last periods
(models/fringe/live_signals.py): a bar per quantity with its tolerance band, the value and
the lowest and highest since *Reset*; the Lissajous figure with the amplitude band as rings;
the interpolation error over the period. *Take* puts the window's samples in the readings
table (one undo step, as an import) and keeps the stream's lines behind them, refused lines
included, as the capture panel keeps an instrument's frames.

The window opens no port itself (widgets never reach app/): :meth:`LiveSignalsPanel.attach`
is given the opener of a stream, the demonstration head's, the workbench's list of capture
sessions and the lab defaults (app/main_window.py does this).
"""

from __future__ import annotations

import contextlib
import datetime as dt
import math
from collections import deque
from collections.abc import Callable

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QEvent, QObject, QPoint, Qt, QTimer, Signal
from PySide6.QtWidgets import (
    QBoxLayout,
    QComboBox,
    QDoubleSpinBox,
    QFormLayout,
    QFrame,
    QGridLayout,
    QGroupBox,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QScrollArea,
    QSizePolicy,
    QSpacerItem,
    QSpinBox,
    QVBoxLayout,
    QWidget,
)

from models.capture.raw_record import frame_text
from models.fringe.live_signals import Extremes, LiveFigures, SampleWindow, live_figures
from models.fringe.model import model_signal
from models.fringe.signal_tolerance import (
    BUILTIN_PRESETS,
    LAB_DEFAULTS_KEY,
    NOT_CONFORMITY,
    QUANTITIES,
    PresetError,
    TolerancePreset,
    load_presets,
    preset_from_dict,
)
from widgets.fringe.preset_editor import PresetEditorDialog
from widgets.fringe.signal_bar import SignalBar
from widgets.i18n import declared, explained, live, on_language_change, tr, translated
from widgets.lazy_menu_view_box import LazyMenuViewBox
from widgets.plot_grid import keep_axis_title_room, show_grid
from widgets.plot_title import set_fitting_title, wrap_title

__all__ = ["INSTRUMENT", "REFRESH_MS", "LiveSignalsPanel"]

#: the display's refresh: at most one redraw this often, whatever the stream's rate
REFRESH_MS = 50
#: the samples (and lines) kept for the window; a take holds at most this many
CAPACITY = 100_000
#: the instrument name of a take's raw session (app/capture/instruments.py reads it back)
INSTRUMENT = "signals"
#: the window's age limit by default (s): no sample older than this is judged
MAX_AGE_S = 2.0
#: the phase bins of the interpolation error's curve
ERROR_BINS = 90


def _quantity_titles() -> dict[str, str]:
    return {"amplitude_a": tr("Amplitude A (sin)"), "amplitude_b": tr("Amplitude B (cos)"),
            "amplitude_ratio": tr("Ratio B/A"), "phase_deviation": tr("Phase B − A − 90°"),
            "offset_a": tr("Offset A"), "offset_b": tr("Offset B"),
            "harmonic_content": tr("Harmonic content")}


def preset_name(preset: TolerancePreset) -> str:
    """A built-in preset's name in the window's language; a lab's own as the lab wrote it."""
    builtin = next((p for p in BUILTIN_PRESETS if p.key == preset.key), None)
    return declared(preset.name) if builtin == preset else preset.name


def _decimals(unit: str) -> int:
    return {"°": 2, "%": 2}.get(unit, 3)


def _plot() -> pg.PlotWidget:
    plot = pg.PlotWidget(background="w", viewBox=LazyMenuViewBox())
    show_grid(plot)
    for axis in ("left", "bottom"):
        plot.getAxis(axis).enableAutoSIPrefix(False)
    plot.setMenuEnabled(False)
    return plot


class LiveSignalsPanel(QWidget):
    #: a take: the window's (u_sin, u_cos) in V, for the readings table
    taken = Signal(object, object)

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.window = SampleWindow(CAPACITY)
        self.extremes = Extremes()
        #: the stream's newest lines: (index since the stream started, seconds, bytes, used)
        self.lines: deque[tuple[int, float, bytes, bool]] = deque(maxlen=CAPACITY)
        #: the blocks' first line and arrival time (s), for the window's age limit
        self.block_times: deque[tuple[int, float]] = deque(maxlen=CAPACITY)
        self.source = None
        self.demonstration = None
        self.figures: LiveFigures | None = None
        self.presets: list[TolerancePreset] = list(BUILTIN_PRESETS)
        #: redraws since the panel was made (the display's rate bounds it, not the stream's)
        self.redraws = 0
        self.refused = 0
        self.samples = 0
        self._new = False
        self._fault = ""
        self._opener: Callable | None = None
        self._demonstrator: Callable | None = None
        self._sessions: Callable[[], list] | None = None
        self._workbench = ""
        self._lab_defaults: Callable[[], dict] = dict
        self._setup_ui()
        self._layout()
        self.timer = QTimer(self)
        self.timer.setInterval(REFRESH_MS)
        self.timer.timeout.connect(self.tick)
        on_language_change(self, self._retitle)
        self._preset_chosen()

    # ------------------------------------------------------------------ the widgets
    def _setup_ui(self) -> None:
        self.port = QLineEdit()
        live(self.port.setPlaceholderText, tr("tcp://host:port or a serial port"))
        self.pattern = QLineEdit()
        live(self.pattern.setPlaceholderText, tr("u_sin,u_cos — or a pattern with (?P<sin>…) "
                                                 "and (?P<cos>…)"))
        self.baud = QSpinBox()
        self.baud.setRange(0, 4_000_000)
        self.baud.setSpecialValueText("115200")
        self.connect_button = QPushButton()
        live(self.connect_button.setText, tr("Connect"))
        self.disconnect_button = QPushButton()
        live(self.disconnect_button.setText, tr("Disconnect"))
        self.demo_button = QPushButton()
        live(self.demo_button.setText, tr("Demonstration head"))
        live(self.demo_button.setToolTip, tr("A simulated read head on this computer: set its "
                                             "gap, yaw and roll as if mounting it"))
        self.preset = QComboBox()
        self.preset.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToMinimumContentsLengthWithIcon)
        self.preset.setMinimumContentsLength(18)
        self.edit_presets_button = QPushButton()
        live(self.edit_presets_button.setText, tr("Edit presets…"))
        live(self.edit_presets_button.setToolTip, tr("Add the lab's own tolerance presets, copy "
                                                     "a built-in one to edit, rename, delete "
                                                     "(saved with the lab defaults)"))
        self.preset_editor = None
        self.periods = QSpinBox()
        self.periods.setRange(1, 1000)
        self.periods.setValue(16)
        live(self.periods.setToolTip, tr("The sliding window: the last N signal periods"))
        self.max_age = QDoubleSpinBox()
        self.max_age.setRange(0.1, 600.0)
        self.max_age.setDecimals(1)
        self.max_age.setValue(MAX_AGE_S)
        self.max_age.setSuffix(" s")
        live(self.max_age.setToolTip, tr("The window holds no sample older than this, so a head "
                                         "that loses its signal is judged on what it gives now "
                                         "(raise it for a shaft turned slowly by hand)"))
        self.scale = QDoubleSpinBox()
        self.scale.setRange(1e-6, 1e6)
        self.scale.setDecimals(4)
        self.scale.setValue(1.0)
        live(self.scale.setToolTip, tr("The preset's unit per volt of the stream (1 for a "
                                       "1 Vpp stream in volts; µA per V of the transimpedance "
                                       "for 11 µApp)"))
        self.reset_button = QPushButton()
        live(self.reset_button.setText, tr("Reset min/max"))
        self.take_button = QPushButton()
        live(self.take_button.setText, tr("Take"))
        live(self.take_button.setToolTip, tr("Put the window's samples in the readings table "
                                             "(replacing them; Undo brings them back), with the "
                                             "stream's lines behind them"))
        self.bars = {q: SignalBar(q) for q in QUANTITIES}
        self.note = QLabel()
        self.note.setWordWrap(True)
        self.note.setStyleSheet("QLabel { color: #5d4037; background: #fff8e1; padding: 3px; }")
        self.status = QLabel()
        self.status.setWordWrap(True)
        self.status.setTextFormat(Qt.TextFormat.PlainText)
        # the demonstration head's mounting (shown while it runs)
        self.mounting = QGroupBox()
        self.knobs: dict[str, QDoubleSpinBox] = {}
        for name, low, high, step, suffix in (("gap_mm", 0.2, 2.0, 0.02, " mm"),
                                              ("yaw_mrad", -20.0, 20.0, 0.5, " mrad"),
                                              ("roll_mrad", -50.0, 50.0, 2.0, " mrad"),
                                              ("dirt", 0.0, 0.9, 0.05, "")):
            box = QDoubleSpinBox()
            box.setRange(low, high)
            box.setSingleStep(step)
            box.setDecimals(2)
            box.setSuffix(suffix)
            box.valueChanged.connect(lambda v, n=name: self._knob(n, v))
            self.knobs[name] = box
        self.mounting.hide()
        # the plots: made once, their curves updated with setData
        self.lissajous = _plot()
        self.lissajous.setAspectLocked(True)
        self.liss_raw = self.lissajous.plot(pen=pg.mkPen("#90a4ae", width=1))
        self.liss_fit = self.lissajous.plot(pen=pg.mkPen("#1565c0", width=2))
        self.rings = [self.lissajous.plot(pen=pg.mkPen(colour, width=1.5, style=style))
                      for colour, style in (("#2e7d32", Qt.PenStyle.DashLine),) * 2
                      + (("#ef8f00", Qt.PenStyle.DotLine),) * 2]
        self.error_plot = _plot()
        self.error_low = self.error_plot.plot(pen=pg.mkPen("#90caf9", width=1))
        self.error_high = self.error_plot.plot(pen=pg.mkPen("#90caf9", width=1))
        self.error_band = pg.FillBetweenItem(self.error_low, self.error_high,
                                             brush=pg.mkBrush(21, 101, 192, 50))
        self.error_plot.addItem(self.error_band)
        self.error_mean = self.error_plot.plot(pen=pg.mkPen("#1565c0", width=2))
        self.error_plot.setXRange(0, 360, padding=0)

    def _layout(self) -> None:
        # the stream's fields and its buttons: one row, or two in a narrow window, where the
        # buttons left the port and the line a few characters ("057", "u…" at 572 px;
        # day review 67 F8): :meth:`_arrange`
        fields = QHBoxLayout()
        self.port_label, self.pattern_label, self.baud_label = QLabel(), QLabel(), QLabel()
        fields.addWidget(self.port_label)
        fields.addWidget(self.port, 3)
        fields.addWidget(self.pattern_label)
        fields.addWidget(self.pattern, 3)
        fields.addWidget(self.baud_label)
        fields.addWidget(self.baud)
        buttons = QHBoxLayout()
        buttons.addWidget(self.connect_button)
        buttons.addWidget(self.disconnect_button)
        buttons.addWidget(self.demo_button)
        buttons.addStretch(0)
        link = self.link_rows = QBoxLayout(QBoxLayout.Direction.LeftToRight)
        link.addLayout(fields, 1)
        link.addLayout(buttons)
        # the window's settings on two rows and Reset/Take on a row of their own below the
        # plots: on one row they made the window at least 1039 px wide, wider than a
        # 1280×720 screen at 150 % (853 px), and Take was off the screen
        view = QHBoxLayout()
        self.preset_label, self.periods_label, self.scale_label = QLabel(), QLabel(), QLabel()
        self.max_age_label = QLabel()
        view.addWidget(self.preset_label)
        view.addWidget(self.preset, 2)
        view.addWidget(self.edit_presets_button)
        view.addStretch(1)
        window = QHBoxLayout()
        window.addWidget(self.periods_label)
        window.addWidget(self.periods)
        window.addWidget(self.max_age_label)
        window.addWidget(self.max_age)
        window.addWidget(self.scale_label)
        window.addWidget(self.scale)
        window.addStretch(1)
        actions = QHBoxLayout()
        actions.addStretch(1)
        actions.addWidget(self.reset_button)
        actions.addWidget(self.take_button)
        bars = QVBoxLayout()
        bars.setSpacing(4)
        for bar in self.bars.values():
            bars.addWidget(bar)
        knobs = QFormLayout(self.mounting)
        knobs.setContentsMargins(6, 2, 6, 2)
        self.knob_labels = {name: QLabel() for name in self.knobs}
        for name, box in self.knobs.items():
            knobs.addRow(self.knob_labels[name], box)
        bars.addWidget(self.mounting)
        bars.addStretch(1)
        left = QWidget()
        left.setLayout(bars)
        left.setMinimumWidth(236)  # the bars' 220 px and the column's margins
        left.setMaximumWidth(420)
        plots = self.plots_grid = QGridLayout()
        # at the top, no taller than the body's view (:meth:`_fit_plots`); side by side, or
        # one above the other where two would not fit beside the bars (:meth:`_arrange`)
        plots.addWidget(self.lissajous, 0, 0)
        plots.addWidget(self.error_plot, 0, 1)
        plots.setColumnStretch(0, 1)
        plots.setColumnStretch(1, 1)
        # the plots' rows grow to the plots' greatest height, the room below goes to this
        # row (aligned to the top instead, a plot was as tall as its size hint, not as the
        # height fitted to the view: 160 px in a 261 px view under --screenshot at 200 %)
        plots.addItem(QSpacerItem(0, 0, QSizePolicy.Policy.Minimum,
                                  QSizePolicy.Policy.Expanding), 2, 0, 1, 2)
        plots.setRowStretch(0, 1)
        self.bars_column = left
        self.plots_beside: bool | None = True
        body = self.body_layout = QHBoxLayout()
        body.setContentsMargins(0, 0, 0, 0)
        body.addWidget(left, 2)
        body.addLayout(plots, 5)
        # one page that scrolls: the stream's and the window's rows, the bars and plots and
        # the note under them; Reset/Take and the status line stay in sight below it. At 200 %
        # on a 1280×720 screen (627×331 px of window) the rows were fixed above a body that
        # scrolled on its own, and that body had 105 px: the plots stood in a strip, their
        # x axes below the fold, the y title cut to "polation error" (day review 68 F10). Now
        # the page scrolls to the plots, each no taller than the page's view
        # (:meth:`_fit_plots`). Narrow margins: at 200 % the bars and plots at their least
        # width were wider than the view, and a sideways scroll bar took a line off the
        # plots' height (day review 67 F8)
        page = self.page_layout = QVBoxLayout()
        page.setContentsMargins(2, 2, 2, 2)
        page.addLayout(link)
        page.addLayout(view)
        page.addLayout(window)
        page.addLayout(body, 1)
        page.addWidget(self.note)
        self.body = QScrollArea()
        self.body.setWidgetResizable(True)
        self.body.setFrameShape(QFrame.Shape.NoFrame)
        inside = self.page = QWidget()
        inside.setLayout(page)
        self.body.setWidget(inside)
        # it scrolls down only: the window is at least as wide as the page (:meth:`_arrange`)
        self.body.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        # the plots follow the page's view, not only the window: the status line below
        # wrapping to two lines once figures come shortens the view with the window unchanged
        # (day review 67 F8: the x axis titles were cut on the first open at 150 %)
        self.body.viewport().installEventFilter(self)
        outer = self.outer_layout = QVBoxLayout(self)
        outer.setContentsMargins(4, 4, 4, 4)
        outer.addWidget(self.body, 1)
        outer.addLayout(actions)
        outer.addWidget(self.status)
        for plot in (self.lissajous, self.error_plot):
            plot.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Expanding)
            plot.setMinimumSize(self.PLOT_MIN_WIDTH, self.PLOT_MIN_HEIGHT)
            # as tall as its y axis' title needs, the body scrolling down instead: at 150 %
            # on a 1280×720 screen "interpolation error (° el.)" had less axis than its
            # length and was cut at both ends (day review 66)
            keep_axis_title_room(plot, self.PLOT_MIN_HEIGHT)
        wrap_title(self.lissajous)
        self.connect_button.clicked.connect(lambda: self.connect_stream())
        self.disconnect_button.clicked.connect(self.disconnect_stream)
        self.demo_button.clicked.connect(lambda: self.start_demonstration())
        self.reset_button.clicked.connect(self.reset)
        self.take_button.clicked.connect(lambda: self.take())
        self.preset.currentIndexChanged.connect(self._preset_chosen)
        self.edit_presets_button.clicked.connect(lambda: self.edit_presets())
        self.scale.valueChanged.connect(self._rescaled)
        self._retitle()
        self._show_connected()

    #: the least height of the Lissajous and the interpolation error's plot
    PLOT_MIN_HEIGHT = 160
    #: and their least width: both beside the bars in a 627 px window (200 % on 1280×720)
    PLOT_MIN_WIDTH = 160

    #: the characters the port field shows whole, at least, before the stream's buttons
    #: go to a row of their own, and the line field's
    PORT_SHOWN, LINE_SHOWN = "tcp://127.0.0.1:50000", "u_sin,u_cos"

    def resizeEvent(self, event) -> None:  # noqa: N802 - Qt's name
        super().resizeEvent(event)
        self._arrange()
        QTimer.singleShot(0, self, self._fit_plots)  # once the body is laid out anew

    def _arrange(self) -> None:
        """The stream's buttons beside its fields where the port and the line still show
        :data:`PORT_SHOWN` and :data:`LINE_SHOWN` whole, else on a row below them; the two
        plots side by side where both have their least width beside the bars' column, else
        one above the other (day review 67 F8: at 572 px the port showed "057" and the
        line "u…", and the bars and plots scrolled sideways)."""
        outer = self.outer_layout.contentsMargins()
        room = self.width() - outer.left() - outer.right()
        spacing = max(self.link_rows.spacing(), 0)

        def field(edit, shown: str) -> int:
            return edit.fontMetrics().horizontalAdvance(shown) + 16

        fields = sum(w.sizeHint().width() for w in (self.port_label, self.pattern_label,
                                                      self.baud_label, self.baud)) \
            + field(self.port, self.PORT_SHOWN) + field(self.pattern, self.LINE_SHOWN)
        buttons = sum(b.sizeHint().width() for b in (self.connect_button,
                                                     self.disconnect_button, self.demo_button))
        # the rows are on the page, beside its scroll bar
        page = self.page_layout.contentsMargins()
        page_room = room - page.left() - page.right() \
            - self.body.verticalScrollBar().sizeHint().width()
        one_row = fields + buttons + 9 * spacing <= page_room
        direction = QBoxLayout.Direction.LeftToRight if one_row else \
            QBoxLayout.Direction.TopToBottom
        if self.link_rows.direction() != direction:
            self.link_rows.setDirection(direction)
        inside = self.body_layout
        margins = self.page_layout.contentsMargins()
        scroll_bar = self.body.verticalScrollBar().sizeHint().width()
        beside = room - scroll_bar - margins.left() - margins.right() \
            - self.bars_column.minimumWidth() - 2 * max(inside.spacing(), 0) \
            >= 2 * self.PLOT_MIN_WIDTH + max(self.plots_grid.spacing(), 0)
        if self.plots_beside != beside:
            self.plots_beside = beside
            self.plots_grid.removeWidget(self.error_plot)
            row, column = (0, 1) if beside else (1, 0)
            self.plots_grid.addWidget(self.error_plot, row, column)
            self.plots_grid.setColumnStretch(1, 1 if beside else 0)
            # one above the other: both rows grow to the plots' height, the room the bars
            # leave below them to the row below, not between them
            self.plots_grid.setRowStretch(1, 0 if beside else 1)
        # no wider a window than its page (its rows in two, the plots one above the other
        # at least): the page never scrolls sideways
        least = self.page.minimumSizeHint().width() + scroll_bar
        if self.body.minimumWidth() != least:
            self.body.setMinimumWidth(least)

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:  # noqa: N802 - Qt's name
        if event.type() == QEvent.Type.Resize and watched is self.body.viewport():
            QTimer.singleShot(0, self, self._fit_plots)
        return super().eventFilter(watched, event)

    def _fit_plots(self) -> None:
        """The plots no taller than the page's view (their least height aside): below the
        rows above them where they fit there whole, so that they are seen whole without
        scrolling (at 100 % and 150 %); else a view's height each, the page scrolled down to
        them showing one whole, x axis and y title in view (200 % on a 1280×720 screen, day
        review 68 F10: 105 px of view for plots 176 and 193 px tall). As tall as the bars
        beside them, they scrolled with them, and the interpolation error's y title,
        centred on its axis, was partly out of view at 150 % (day review 66)."""
        margins = self.page_layout.contentsMargins()
        view = self.body.viewport().height() - margins.top() - margins.bottom()
        top = self.bars_column.mapTo(self.page, QPoint(0, 0)).y() - margins.top()
        least = max(plot.minimumHeight() for plot in (self.lissajous, self.error_plot))
        height = view - top if view - top >= least else view
        for plot in (self.lissajous, self.error_plot):
            plot.setMaximumHeight(max(height, plot.minimumHeight()))

    def _retitle(self) -> None:
        self.port_label.setText(tr("Port"))
        self.pattern_label.setText(tr("Line"))
        self.baud_label.setText(tr("Baud"))
        self.preset_label.setText(tr("Tolerances"))
        self.periods_label.setText(tr("Window (periods)"))
        self.max_age_label.setText(tr("at most"))
        self.scale_label.setText(tr("Scale"))
        self.mounting.setTitle(tr("Demonstration head: its mounting"))
        for name, text in (("gap_mm", tr("Gap")), ("yaw_mrad", tr("Yaw (moiré)")),
                           ("roll_mrad", tr("Roll")), ("dirt", tr("Dirt on the scale"))):
            self.knob_labels[name].setText(text)
        self.note.setText(translated(NOT_CONFORMITY))
        self._title_rings()
        self.lissajous.setLabel("left", tr("u sin (V)"))
        self.lissajous.setLabel("bottom", tr("u cos (V)"))
        self.error_plot.setLabel("left", tr("interpolation error (° el.)"))
        self.error_plot.setLabel("bottom", tr("phase (° el.)"))
        self._fill_presets()
        self._show_bands()
        self._show_status()

    # ------------------------------------------------------------------ wiring
    def attach(self, opener: Callable, demonstrator: Callable | None = None,
               sessions: Callable[[], list] | None = None,
               lab_defaults: Callable[[], dict] | None = None,
               save_lab_defaults_entry: Callable[[str, object], None] | None = None,
               workbench: str = "") -> None:
        """``opener(port, pattern, baud)``: a started stream worker (``drain()``, ``stop()``,
        ``port``, ``baud``, ``started_utc``; ValueError or OSError when it cannot be made);
        ``demonstrator()``: a running demonstration head (``port``, ``set(**mounting)``,
        ``close()``); ``sessions()``: the workbench's capture sessions, a list a take's
        session is added to; ``lab_defaults()``: the lab's defaults (its own presets);
        ``save_lab_defaults_entry(key, value)``: one entry of the lab defaults stored, the
        others kept (the presets edited, :meth:`edit_presets`); ``workbench``: the key its
        sessions are recorded under (each session names it: models/capture/raw_record.py)."""
        self._opener, self._demonstrator = opener, demonstrator
        self._sessions = sessions
        self._workbench = workbench
        if lab_defaults is not None:
            self._lab_defaults = lab_defaults
        if save_lab_defaults_entry is not None:
            self._save_entry = save_lab_defaults_entry
        self._fill_presets()
        self._show_connected()

    def reload_presets(self) -> None:
        """The built-in presets and the lab's own as its defaults hold them now."""
        self._fill_presets()
        self._show_bands()

    _save_entry: Callable[[str, object], None] | None = None

    def edit_presets(self) -> PresetEditorDialog | None:
        """The presets' editor, opened (window-modal, not blocking): on Save the lab's own
        are stored with the lab defaults and chosen from here; on Cancel nothing changes."""
        if self._save_entry is None:
            return None
        self._fill_presets()  # as the lab defaults hold them now
        dialog = PresetEditorDialog(self.presets, self)
        current = self.preset.currentData()
        row = next((i for i, p in enumerate(self.presets) if p.key == current), 0)
        dialog.list.setCurrentRow(row)
        dialog.accepted.connect(lambda: self._presets_saved(dialog))
        dialog.finished.connect(lambda _r: setattr(self, "preset_editor", None))
        dialog.setWindowModality(Qt.WindowModality.WindowModal)
        self.preset_editor = dialog
        dialog.open()
        return dialog

    def _presets_saved(self, dialog: PresetEditorDialog) -> None:
        """The lab's own presets stored; a stored one that no longer reads is kept as it was
        (never lost by an edit of the others)."""
        stored = (self._lab_defaults() or {}).get(LAB_DEFAULTS_KEY)
        unread = []
        for data in stored if isinstance(stored, list) else []:
            try:
                preset_from_dict(data)
            except PresetError:
                unread.append(data)
        chosen = dialog.list.currentRow()
        saved = dialog.presets() or []
        self._save_entry(LAB_DEFAULTS_KEY, dialog.stored() + unread)
        self._fill_presets()
        if 0 <= chosen < len(saved):
            index = self.preset.findData(saved[chosen].key)
            if index >= 0:
                self.preset.setCurrentIndex(index)
        self._preset_chosen()

    def _fill_presets(self) -> None:
        presets, problems = load_presets(self._lab_defaults() or {})
        self.presets = presets
        key = self.preset.currentData()
        self.preset.blockSignals(True)
        self.preset.clear()
        for preset in presets:
            self.preset.addItem(preset_name(preset), preset.key)
            self.preset.setItemData(self.preset.count() - 1, preset.source,
                                    Qt.ItemDataRole.ToolTipRole)
        self.preset.setCurrentIndex(max(0, self.preset.findData(key)) if key else 0)
        self.preset.blockSignals(False)
        if problems:
            self._fault = "; ".join(translated(p) for p in problems)

    @property
    def current_preset(self) -> TolerancePreset | None:
        key = self.preset.currentData()
        return next((p for p in self.presets if p.key == key), None)

    def _preset_chosen(self, *_args) -> None:
        self.extremes.reset()  # the figures' units may change with the preset
        self._show_bands()
        self.refresh()

    def _rescaled(self, *_args) -> None:
        self.extremes.reset()
        self.refresh()

    def _title_rings(self) -> None:
        """The Lissajous figure's title naming only the rings drawn: the amber outer ring
        only where the preset has an outer amplitude band (day review 69 F6: "amber outer"
        over a HEIDENHAIN 1 Vpp preset, which has none); wrapped to the plot's width (day
        review 67), the shorter wording where the whole one takes more than two lines (day
        review 68 F10: four lines at 200 %)."""
        preset = self.current_preset
        band = preset.band("amplitude_a") if preset is not None else None
        texts: list[str]
        if band is None:
            texts = [tr("No amplitude band in this preset: no rings"), tr("No rings")]
        elif band.outer is None:
            texts = [tr("Rings: amplitude band (green)"), tr("Band: green")]
        else:
            texts = [tr("Rings: amplitude band (green inside, amber outer)"),
                     tr("Band: green inside, amber outer")]
        set_fitting_title(self.lissajous, texts, size="9pt", color="#455a64")

    def _show_bands(self) -> None:
        self._title_rings()
        preset = self.current_preset
        titles = _quantity_titles()
        for quantity, bar in self.bars.items():
            band = preset.band(quantity) if preset is not None else None
            unit = band.unit if band is not None else ("V" if quantity.startswith("offset")
                                                       else "%" if quantity == "harmonic_content"
                                                       else "")
            bar.set_band(titles[quantity], band, unit, _decimals(unit))
            # a quantity the preset has no band for is shown only when there is a value
            bar.setVisible(band is not None or quantity == "harmonic_content")

    # ------------------------------------------------------------------ the stream
    def connect_stream(self, port: str | None = None, pattern: str | None = None) -> bool:
        """Open the stream (the port and line typed unless given); a fault is shown."""
        if self._opener is None:
            return False
        port = (self.port.text() if port is None else port).strip()
        pattern = (self.pattern.text() if pattern is None else pattern).strip() or None
        if not port:
            self._fault = tr("Type the port of the stream first (e.g. tcp://127.0.0.1:5025)")
            self._show_status()
            return False
        self.disconnect_stream(keep_demonstration=True)
        try:
            source = self._opener(port, pattern, self.baud.value() or None)
        except (ValueError, OSError) as exc:
            self._fault = explained(exc)
            self._show_status()
            return False
        self.port.setText(port)
        self.set_source(source)
        return True

    def set_source(self, source) -> None:
        """Read ``source`` from now on (the window afresh, the min/max too)."""
        self.source = source
        self.window.clear()
        self.lines.clear()
        self.block_times.clear()
        self.extremes.reset()
        self.refused = self.samples = 0
        self._fault = ""
        self.figures = None
        self._figures_unseen = True  # the page brought to them with the first figures
        self.timer.start()
        self._show_connected()
        self._show_status()

    def disconnect_stream(self, keep_demonstration: bool = False) -> None:
        if self.source is not None:
            self.source.stop()
            self.source = None
        if not keep_demonstration and self.demonstration is not None:
            self.demonstration.close()
            self.demonstration = None
            self.mounting.hide()
        self.timer.stop()
        self._show_connected()
        self._show_status()

    def start_demonstration(self) -> bool:
        """Start the demonstration head and read it."""
        if self._demonstrator is None:
            return False
        self.disconnect_stream()
        try:
            self.demonstration = self._demonstrator()
        except OSError as exc:
            self._fault = explained(exc)
            self._show_status()
            return False
        for name, box in self.knobs.items():
            box.blockSignals(True)
            box.setValue(float(getattr(self.demonstration, name, box.value())))
            box.blockSignals(False)
        self.mounting.show()
        self.pattern.clear()
        return self.connect_stream(self.demonstration.port, "")

    def _knob(self, name: str, value: float) -> None:
        if self.demonstration is not None:
            self.demonstration.set(**{name: value})

    def _show_connected(self) -> None:
        on = self.source is not None
        self.connect_button.setEnabled(self._opener is not None)
        self.disconnect_button.setEnabled(on)
        self.demo_button.setEnabled(self._demonstrator is not None)
        self.edit_presets_button.setEnabled(self._save_entry is not None)
        self.take_button.setEnabled(on or len(self.window) > 0)

    def closeEvent(self, event) -> None:  # noqa: N802 - Qt's name
        self.disconnect_stream()
        super().closeEvent(event)

    # ------------------------------------------------------------------ the display
    def tick(self) -> None:
        """Take in what the stream sent since the last tick; redraw once if anything came."""
        if self.source is None:
            return
        for event in self.source.drain():
            if hasattr(event, "lines"):
                self._add_block(event)
            else:  # a fault of the link
                self._fault = translated(event.message)
                if event.final:
                    self.source = None
                    self.timer.stop()
                    self._show_connected()
        if self._new:
            self.refresh()
        self._show_status()

    def _add_block(self, block) -> None:
        index = block.first + np.arange(len(block.lines))
        self.block_times.append((int(block.first), float(block.time_s)))
        for i, line, used in zip(index.tolist(), block.lines, block.used.tolist(), strict=True):
            self.lines.append((i, block.time_s, line, used))
        self.window.add(block.u_sin, block.u_cos, index[block.used])
        self.samples += block.u_sin.size
        self.refused += block.refused
        if block.reasons:
            self._last_refusal = block.reasons[-1]
        self._new = self._new or block.u_sin.size > 0

    _last_refusal = ""

    def window_samples(self):
        """The window's (u_sin, u_cos, line index, periods covered): the last periods, none
        of a line that came more than the age limit before the newest."""
        since = None
        if self.block_times:
            newest = self.block_times[-1][1]
            for first, time_s in reversed(self.block_times):
                if time_s < newest - self.max_age.value():
                    break
                since = first
        return self.window.last_periods(self.periods.value(), since)

    def refresh(self) -> None:
        """The figures of the window, drawn: bars, Lissajous, interpolation error."""
        self._new = False
        if len(self.window) == 0:
            return
        u_sin, u_cos, _, periods = self.window_samples()
        preset = self.current_preset
        self.figures = live_figures(u_sin, u_cos, preset, periods, self.scale.value())
        self.extremes.add(self.figures.figures)
        states = {j.quantity: j.state for j in self.figures.judgements}
        for quantity, bar in self.bars.items():
            value = self.figures.figures.get(quantity, math.nan)
            bar.set_value(value, states.get(quantity, ""))
            bar.set_extremes(self.extremes.low.get(quantity, math.nan),
                             self.extremes.high.get(quantity, math.nan))
        self._draw(u_sin, u_cos)
        self.redraws += 1
        if self._figures_unseen:
            self._figures_unseen = False
            QTimer.singleShot(0, self, self._bring_figures_into_view)  # once laid out

    _figures_unseen = False

    def _bring_figures_into_view(self) -> None:
        """The page scrolled down to the bars and plots when the first figures of a stream
        come and a plot is cut at the bottom of the view (a short window: 200 % on a
        1280×720 screen, where they cannot be whole below the rows; day review 68 F10):
        they are what is watched while a head is mounted. Never scrolled back up, nor when
        they are whole where they are."""
        inside = self.page
        bar = self.body.verticalScrollBar()
        view = self.body.viewport().height()
        top = self.bars_column.mapTo(inside, QPoint(0, 0)).y()
        first = self.lissajous
        bottom = first.mapTo(inside, QPoint(0, first.height())).y()
        if bottom - bar.value() > view and top > bar.value():
            bar.setValue(min(top - self.page_layout.contentsMargins().top(), bar.maximum()))

    def _draw(self, u_sin, u_cos) -> None:
        step = max(1, u_sin.size // 2000)
        self.liss_raw.setData(u_cos[::step], u_sin[::step])
        figures = self.figures
        if figures is None or figures.fits is None:
            for curve in (self.liss_fit, self.error_mean, self.error_low, self.error_high,
                          *self.rings):
                curve.setData([], [])
            self.error_band.setVisible(False)
            return
        grid = np.linspace(0.0, 2.0 * math.pi, 361)
        self.liss_fit.setData(model_signal(grid, figures.fits[1]),
                              model_signal(grid, figures.fits[0]))
        # the amplitude band as rings about the fitted centre: radius = half the peak-to-peak
        preset = self.current_preset
        band = preset.band("amplitude_a") if preset is not None else None
        cx, cy = figures.fits[1].offset, figures.fits[0].offset
        circle = np.exp(1j * grid)
        radii = []
        if band is not None:
            radii += [band.inside[0], band.inside[1]]
            radii += list(band.outer) if band.outer is not None else [math.nan, math.nan]
        for curve, radius in zip(self.rings, radii + [math.nan] * (4 - len(radii)), strict=True):
            if math.isfinite(radius):
                r = 0.5 * radius / self.scale.value()
                curve.setData(cx + r * circle.real, cy + r * circle.imag)
            else:
                curve.setData([], [])
        # the interpolation error over the period: mean and spread per phase bin (none
        # drawn when the window gives none: a head without signal)
        self.error_band.setVisible(figures.error_deg.size > 0)
        phase = np.degrees(figures.phase_rad) % 360.0
        bins = np.minimum((phase / (360.0 / ERROR_BINS)).astype(int), ERROR_BINS - 1)
        counts = np.bincount(bins, minlength=ERROR_BINS)
        sums = np.bincount(bins, weights=figures.error_deg, minlength=ERROR_BINS)
        low = np.full(ERROR_BINS, np.inf)
        high = np.full(ERROR_BINS, -np.inf)
        np.minimum.at(low, bins, figures.error_deg)
        np.maximum.at(high, bins, figures.error_deg)
        filled = counts > 0
        centres = (np.arange(ERROR_BINS) + 0.5) * (360.0 / ERROR_BINS)
        self.error_mean.setData(centres[filled], sums[filled] / counts[filled])
        self.error_low.setData(centres[filled], low[filled])
        self.error_high.setData(centres[filled], high[filled])

    def reset(self) -> None:
        """The lowest and highest start again from the next refresh."""
        self.extremes.reset()
        for bar in self.bars.values():
            bar.set_extremes(math.nan, math.nan)
        if self.figures is not None:
            self.extremes.add(self.figures.figures)
            for quantity, bar in self.bars.items():
                bar.set_extremes(self.extremes.low.get(quantity, math.nan),
                                 self.extremes.high.get(quantity, math.nan))

    def _show_status(self) -> None:
        parts = []
        if self.source is not None:
            parts.append(tr("{port}: {samples} samples, {refused} line(s) refused").format(
                port=self.source.port, samples=self.samples, refused=self.refused))
            if self._last_refusal and self.refused:
                parts.append(tr("last refused: {reason}").format(reason=self._last_refusal))
        else:
            parts.append(tr("Not connected"))
        figures = self.figures
        if figures is not None:
            if figures.problem:
                parts.append(translated(figures.problem))
            elif figures.error_deg.size:
                parts.append(tr("window: {periods} periods, {samples} samples; interpolation "
                                "error {pp}° el. peak to peak").format(
                    periods=f"{figures.periods:.1f}", samples=figures.samples,
                    pp=f"{figures.error_peak_to_peak_deg:.2f}"))
        if self._fault:
            parts.append(self._fault)
        self.status.setText(" — ".join(parts))

    # ------------------------------------------------------------------ the take
    def take(self) -> bool:
        """The window's samples to the readings table, their lines to the workbench's
        capture sessions; False (and said) when the window is empty."""
        u_sin, u_cos, index, _ = self.window_samples()
        if u_sin.size == 0:
            self._fault = tr("Nothing to take: no samples in the window")
            self._show_status()
            return False
        session = None
        if self._sessions is not None:
            sessions = self._sessions()
            session = self._session(index)
        # the readings replaced (one undo step), the earlier takes of the stream marked
        # replaced in that same step (FringePresenter.take_live_signals): marked here, outside
        # it, the undo of a retake left the earlier take's readings unclaimed
        self.taken.emit(np.array(u_sin), np.array(u_cos))
        # added once the readings are replaced: the replacement detaches the takes that
        # named the rows it replaced (models/capture/take_rows.py), not this one's
        if session is not None:
            sessions.append(session)
        return True

    def _session(self, index: np.ndarray) -> dict:
        """The take's raw session: the stream's lines from the window's first sample to its
        last (refused ones too), and where each sample went (row i: the i-th sample)."""
        first, last = int(index[0]), int(index[-1])
        kept = [entry for entry in self.lines if first <= entry[0] <= last]
        where = {entry[0]: i for i, entry in enumerate(kept)}
        source = self.source
        # the session starts with the take's first line (its frames' times count from it):
        # each take a session of its own, told apart from an earlier one of the same stream
        started = getattr(source, "started_utc", "") or ""
        t0 = kept[0][1] if kept else 0.0
        with contextlib.suppress(ValueError):
            started = (dt.datetime.fromisoformat(started)
                       + dt.timedelta(seconds=t0)).isoformat() if started else ""
        return {"instrument": INSTRUMENT,
                "port": getattr(source, "port", "") or self.port.text(),
                "baud": int(getattr(source, "baud", 0) or 0),
                "started_utc": started,
                "frames": [[round(float(t - t0), 6), frame_text(line), int(bool(used))]
                           for _, t, line, used in kept],
                "takes": [[row, where[i], where[i]] for row, i in enumerate(index.tolist())
                          if i in where],
                **({"workbench": self._workbench} if self._workbench else {})}
