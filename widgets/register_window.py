"""The certificate register window: where the register is, the issued certificates with a
search, the actions on one (open its project, amend, replace, save its PDF), verifying a
PDF, and an instrument's history of headline figures with its due date. Widgets only;
the presenter is app/register_presenter.py."""

from __future__ import annotations

import datetime as dt
import html
import threading

import pyqtgraph as pg
from PySide6.QtCore import QLocale, QObject, Qt, Signal
from PySide6.QtWidgets import (
    QAbstractItemView,
    QComboBox,
    QDialog,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QLineEdit,
    QMessageBox,
    QPushButton,
    QSizePolicy,
    QSpinBox,
    QSplitter,
    QTableWidget,
    QVBoxLayout,
    QWidget,
)

from widgets.flow_layout import FlowLayout
from widgets.i18n import application_language, declared, live, on_language_change, tr
from widgets.lazy_menu_view_box import LazyMenuViewBox
from widgets.open_file import ask_open_file
from widgets.plot_grid import show_grid
from widgets.plot_image import localise_plot_menus
from widgets.save_file import ask_save_file
from widgets.screen_fit import fit_to_screen
from widgets.text_table import show_text_table
from widgets.workers import emit_if_alive

EPOCH = dt.date(1970, 1, 1).toordinal()
_MONTHS = ("Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec")


class LocalDateAxis(pg.DateAxisItem):
    """pyqtgraph's date axis, its month names in the window's language (it writes them
    with the C locale's strftime: "Feb, Mar" in a Chinese window)."""

    def tickStrings(self, values, scale, spacing):  # noqa: N802 - pyqtgraph's name
        strings = super().tickStrings(values, scale, spacing)
        language = application_language().code
        if language == "en":
            return strings
        locale = QLocale(language)
        names = {english: locale.monthName(number, QLocale.FormatType.ShortFormat)
                 for number, english in enumerate(_MONTHS, start=1)}
        out = []
        for text in strings:
            for english, local in names.items():
                text = text.replace(english, local)
            out.append(text)
        return out

    def picture_again(self) -> None:
        """Written again (the window's language changed)."""
        self.picture = None
        self.update()


COLOURS = ("#1f5fbf", "#c0392b", "#27ae60", "#8e44ad", "#e67e22", "#16a085", "#7f8c8d")


class _Delivery(QObject):
    """Carries a worker thread's result to the GUI thread (a queued signal)."""

    finished = Signal(object, object)  # done, its result


#: the characters of the selected certificate's links shown below the list (about four
#: lines at 1280x720 and 200 %): the rest on hover and in 'register show'
LINKS_SHOWN = 400


def _plain_tip(text: str) -> str:
    """``text`` as a tooltip shown as typed (a tooltip that looks like HTML is rendered as
    HTML: a reason typed <h1>VALID</h1>), wrapped."""
    return f"<p>{html.escape(text)}</p>" if text else ""


class RegisterWindow(QDialog):
    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self._delivery = _Delivery(self)
        self._delivery.finished.connect(lambda done, result: done(result))
        self.background: list[threading.Thread] = []  # the checks started (a test joins them)
        # the stored PDFs' check, run in the background on opening: a mismatch stays in sight
        self.pdf_check = QLabel()
        self.pdf_check.setObjectName("pdf_check")
        self.pdf_check.setWordWrap(True)
        self.pdf_check.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.pdf_check_warning = False
        live(self.setWindowTitle, tr("Certificate register"))
        fit_to_screen(self, 1100, 720)
        self.location = QLabel()
        self.location.setObjectName("location")  # where the register is: a path or URL
        self.location.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        # a long path or URL does not set the window's width (day74 #11: a register in a
        # deep folder made it wider than a 200 % screen): cut at the window's edge, whole
        # in its tooltip and when selected
        self.location.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        self.location_edit = QLineEdit()
        live(self.location_edit.setPlaceholderText, tr("empty: the file in your data folder; "
                                                       "or postgresql://user@host/database"))
        self.location_button = QPushButton()
        live(self.location_button.setText, tr("Use"))
        self.search = QLineEdit()
        live(self.search.setPlaceholderText, tr("Search number, serial or customer"))
        self.table = QTableWidget()
        self.table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.table.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        self.table.verticalHeader().hide()
        self.table.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
        self.table.horizontalHeader().setStretchLastSection(True)
        #: the selected certificate's links to others (the list's last column) in full,
        #: wrapped: at 200 % the column is off the screen or cut short
        self.links = QLabel()
        # plain text: a withdrawal reason typed as <h1>VALID</h1> showed as a heading
        # (hostile79 #4)
        self.links.setTextFormat(Qt.TextFormat.PlainText)
        self.links.setWordWrap(True)
        self.links.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.links.hide()
        self._rows: list = []
        self.table.itemSelectionChanged.connect(self._show_links)
        self.buttons = {}
        for name, text in (("open", tr("Open project")), ("amend", tr("Amend…")),
                           ("replace", tr("Replace…")), ("save", tr("Save PDF…")),
                           ("print", tr("Print…")), ("verify", tr("Verify a PDF…")),
                           ("history", tr("History"))):
            self.buttons[name] = QPushButton()
            live(self.buttons[name].setText, text)
        live(self.buttons["amend"].setToolTip, tr(
            "Open the certificate's readings and details; the next export issues Amendment n "
            "to it, saying what changed"))
        live(self.buttons["replace"].setToolTip, tr(
            "As Amend, but the new certificate gets a new number and replaces the original"))
        live(self.buttons["verify"].setToolTip, tr(
            "Is a PDF, byte for byte, one this register issued?"))
        # the register's recoveries, as its commands record them (acknowledge-loss,
        # clock-correction: each dialog names its command): beside the line that says the
        # register's state
        self.recovery_buttons = {}
        for name, text, tip in (
                ("loss", tr("Acknowledge a loss…"), tr(
                    "Record that records were lost (an older copy restored or put back), so "
                    "that issuing resumes past the numbers lost")),
                ("clock", tr("Clock correction…"), tr(
                    "Record that the register's last record was dated by a clock set ahead, "
                    "so that a right clock issues again"))):
            self.recovery_buttons[name] = QPushButton()
            live(self.recovery_buttons[name].setText, text)
            live(self.recovery_buttons[name].setToolTip, tip)
        #: the recovery dialog open (a test types into it)
        self.recovery_dialog: QDialog | None = None
        self.history_title = QLabel()
        # before any history, a sentence in its place (not an empty plot with a 0–1 axis, nor
        # a second box of words taking the list's room: at 200 % on a 1280×720 laptop the
        # list showed one row)
        live(self.history_title.setText, tr(
            "Select a certificate and press History (or double-click it)"))
        live(self.history_title.setToolTip, tr(
            "The history: the instrument's figures over its calibrations, and its due date"))
        self.history_plot = pg.PlotWidget(background="w", viewBox=LazyMenuViewBox(), axisItems={
            "bottom": LocalDateAxis(orientation="bottom")})
        on_language_change(self, self.history_plot.getAxis("bottom").picture_again)
        show_grid(self.history_plot)
        self.history_plot.getAxis("left").enableAutoSIPrefix(False)
        self.history_legend = self.history_plot.addLegend(offset=(10, 10))
        self.history_curves: list[pg.PlotDataItem] = []
        self.due_line = pg.InfiniteLine(angle=90, pen=pg.mkPen("#c0392b", width=1.5,
                                                               style=Qt.PenStyle.DashLine),
                                        label="due", labelOpts={"position": 0.9})
        self.due_line.hide()
        self.history_plot.addItem(self.due_line)
        today = dt.date.today().toordinal() - EPOCH  # empty: the year up to today, in dates
        self.history_plot.setXRange((today - 365) * 86400.0, (today + 30) * 86400.0, padding=0)
        localise_plot_menus(self.history_plot)
        self.history_plot.hide()
        self.figure_caption = QLabel()  # the figure's drop-down, labelled
        live(self.figure_caption.setText, tr("figure"))
        self.figure = QComboBox()  # which headline figure the history plots
        self.figure.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToContents)
        live(self.figure.setToolTip, tr("The figure of the certificates to follow over time"))
        self.figure.currentIndexChanged.connect(
            lambda _i: self._draw_history(self.figure.currentData() or ""))
        self._series: dict = {}
        #: the days (ordinal) of the shown history's certificates that name no manufacturer
        self._makerless: set[float] = set()
        self.interval = QSpinBox()
        self.interval.setRange(0, 3650)
        live(self.interval.setSuffix, tr(" days"))
        live(self.interval.setSpecialValueText, tr("no interval set"))
        self.interval_button = QPushButton()
        live(self.interval_button.setText, tr("Set interval"))
        self.serial = ""
        self._layout()

    def _layout(self) -> None:
        top = QHBoxLayout()
        caption = QLabel()
        live(caption.setText, tr("Register:"))
        top.addWidget(caption)
        top.addWidget(self.location, 1)
        top.addWidget(self.location_edit, 1)
        top.addWidget(self.location_button)
        # the buttons wrap onto a second row on a narrow screen (day74 #11: at 200 % on a
        # 1280×720 laptop they made the window 652 px wide, 640 px free)
        actions = FlowLayout()
        for button in self.buttons.values():
            actions.addWidget(button)
        upper = QWidget()
        upper_layout = QVBoxLayout(upper)
        upper_layout.setContentsMargins(0, 0, 0, 0)
        upper_layout.addWidget(self.search)
        upper_layout.addWidget(self.table, 1)
        upper_layout.addWidget(self.links)
        upper_layout.addLayout(actions)
        lower = QWidget()
        lower_layout = QVBoxLayout(lower)
        lower_layout.setContentsMargins(0, 0, 0, 0)
        # the history's title on a line of its own, wrapped; its controls below, wrapping
        self.history_title.setWordWrap(True)
        # two lines kept for it, wrapped or not (a splitter shrinks a wrapped label to less)
        self.history_title.setMinimumHeight(2 * self.history_title.fontMetrics().lineSpacing())
        lower_layout.addWidget(self.history_title)
        row = FlowLayout()
        row.addWidget(self.figure_caption)
        row.addWidget(self.figure)
        self.figure_caption.hide()
        self.figure.hide()  # shown with a history (empty, it was a blank drop-down)
        interval_caption = QLabel()
        live(interval_caption.setText, tr("calibration interval"))
        #: the interval is set for the instrument whose history is shown: shown with it
        self.interval_row = (interval_caption, self.interval, self.interval_button)
        for widget in self.interval_row:
            row.addWidget(widget)
            widget.hide()
        lower_layout.addLayout(row)
        lower_layout.addWidget(self.history_plot, 1)
        lower_layout.addStretch(0)
        # the list takes the room until a history is asked for (show_history gives it half)
        self.splitter = splitter = QSplitter(Qt.Orientation.Vertical)
        splitter.addWidget(upper)
        splitter.addWidget(lower)
        splitter.setStretchFactor(0, 1)
        splitter.setStretchFactor(1, 0)
        splitter.setCollapsible(1, False)  # the history's title stays in sight
        splitter.setSizes([10_000, 1])
        layout = QVBoxLayout(self)
        layout.addLayout(top)
        state_row = QHBoxLayout()
        state_row.addWidget(self.pdf_check, 1)
        for button in self.recovery_buttons.values():
            state_row.addWidget(button)
        layout.addLayout(state_row)
        layout.addWidget(splitter, 1)

    # -- wiring ------------------------------------------------------------------------
    def subscribe(self, presenter) -> None:
        self.search.textChanged.connect(lambda text: presenter.refresh(text))
        self.location_button.clicked.connect(
            lambda: presenter.set_location(self.location_edit.text()))
        self.buttons["open"].clicked.connect(presenter.open_project)
        self.buttons["amend"].clicked.connect(lambda: presenter.revise(False))
        self.buttons["replace"].clicked.connect(lambda: presenter.revise(True))
        self.buttons["save"].clicked.connect(presenter.save_pdf)
        self.buttons["print"].clicked.connect(presenter.print_pdf)
        self.buttons["verify"].clicked.connect(presenter.verify_pdf)
        self.buttons["history"].clicked.connect(presenter.show_history)
        self.recovery_buttons["loss"].clicked.connect(presenter.acknowledge_loss)
        self.recovery_buttons["clock"].clicked.connect(presenter.correct_clock)
        self.table.doubleClicked.connect(lambda _index: presenter.show_history())
        self.interval_button.clicked.connect(
            lambda: self.serial and presenter.set_interval(self.serial, self.interval.value()))

    # -- the presenter's calls ---------------------------------------------------------------
    def show_location(self, url: str) -> None:
        self.location.setText(url)
        self.location.setToolTip(url)

    def show_records(self, header, rows) -> None:
        self._rows = list(rows)
        show_text_table(self.table, [tr(h) for h in header], rows)
        for r, row in enumerate(rows):  # the links in full where the column is narrow
            item = self.table.item(r, len(row) - 1) if row and row[-1] else None
            if item is not None:
                item.setToolTip(_plain_tip(row[-1]))
        # the links' column as wide as its text up to about 30 characters, not squeezed to
        # what the other columns leave (the selected one's in full below the list)
        last = self.table.columnCount() - 1
        if last > 0:
            widest = 30 * self.table.fontMetrics().averageCharWidth()
            header_view = self.table.horizontalHeader()
            header_view.setStretchLastSection(False)
            header_view.setSectionResizeMode(last, QHeaderView.ResizeMode.Interactive)
            self.table.setColumnWidth(last, min(max(self.table.sizeHintForColumn(last),
                                                    header_view.sectionSizeHint(last)),
                                                widest))
        self._show_links()
        if rows:
            self.table.selectRow(0)

    def _show_links(self) -> None:
        """The selected certificate's links (the list's last column) below the list."""
        row = self.selected_row()
        text = self._rows[row][-1] if 0 <= row < len(self._rows) and self._rows[row] else ""
        shown = text if len(text) <= LINKS_SHOWN else text[:LINKS_SHOWN - 1].rstrip() + "…"
        self.links.setText(tr("Links: {links}").format(links=shown) if text else "")
        # cut short (a reason of 10,000 characters took the list's room): in full on hover
        self.links.setToolTip(_plain_tip(text) if shown != text else "")
        self.links.setVisible(bool(text))

    def selected_row(self) -> int:
        rows = self.table.selectionModel().selectedRows()
        return rows[0].row() if rows else -1

    def show_history(self, serial, series, dates, due, interval_days, makers=(),
                     manufacturer="", makerless=()) -> None:
        """``makers``: the item names no maker, and the serial's certificates name these:
        no due date without the maker (rev65 F4). ``manufacturer``: whose item it is, named
        in the title (the schedule is per serial and maker since schema 7); ``makerless``:
        the dates of its certificates that name no manufacturer, drawn hollow and said."""
        self.serial = serial
        self._series = dict(series)
        self._makerless = {float(dt.date.fromisoformat(d).toordinal()) for d in makerless if d}
        chosen = self.figure.currentData()
        self.figure.blockSignals(True)
        self.figure.clear()
        for name in series:
            self.figure.addItem(declared(name), name)
        if chosen in series:
            self.figure.setCurrentIndex(self.figure.findData(chosen))
        self.figure.blockSignals(False)
        for widget in (self.figure_caption, self.figure):
            widget.setVisible(bool(series))
        self.history_plot.show()
        for widget in self.interval_row:
            widget.show()
        upper, lower = self.splitter.sizes()
        if lower < 0.45 * (upper + lower):  # the history asked for: half the room at least
            self.splitter.setSizes([(upper + lower) // 2, (upper + lower + 1) // 2])
        self._draw_history(self.figure.currentData() or "")
        ends = [x for xs, _ in series.values() for x in xs]
        if due:
            self.due_line.setValue((dt.date.fromisoformat(due).toordinal() - EPOCH) * 86400.0)
            self.due_line.show()
            ends.append(dt.date.fromisoformat(due).toordinal())
        else:
            self.due_line.hide()
        if ends:  # whole days at least a year wide: one calibration is a point in time
            lo, hi = min(ends), max(ends)
            pad = max(30.0, (365.0 - (hi - lo)) / 2)
            self.history_plot.setXRange((lo - pad - EPOCH) * 86400.0,
                                        (hi + pad - EPOCH) * 86400.0, padding=0)
        self.interval.setValue(interval_days)
        self.history_title.setText(
            (tr("Instrument {serial} of {maker}: {count} calibration(s)").format(
                serial=serial, maker=manufacturer, count=len(dates)) if manufacturer else
             tr("Instrument {serial}, no manufacturer named: {count} calibration(s)").format(
                serial=serial, count=len(dates)))
            + (tr(" ({n} on certificates naming no manufacturer, drawn hollow: {dates})").format(
                n=len(makerless), dates=", ".join(makerless)) if makerless else "")
            + (tr(", next due {date}").format(date=due) if due
               else tr(", no due date: the certificate names no manufacturer, and this "
                       "serial's name {makers} (the due date is per maker's item)").format(
                   makers=", ".join(makers)) if makers
               else tr(", no due date (set an interval)")))

    def _draw_history(self, name: str) -> None:
        """One figure at a time: the figures of a certificate differ by orders of magnitude."""
        self.history_legend.clear()
        for curve in self.history_curves:
            self.history_plot.removeItem(curve)
        self.history_curves = []
        if name not in self._series:
            return
        xs, ys = self._series[name]
        seconds = [(x - EPOCH) * 86400.0 for x in xs]
        self.history_curves.append(self.history_plot.plot(
            seconds, ys, name=declared(name), pen=pg.mkPen(COLOURS[0], width=2), symbol="o",
            symbolBrush=COLOURS[0], symbolPen=None))
        unnamed = [(s, y) for s, x, y in zip(seconds, xs, ys, strict=True)
                   if x in self._makerless]
        if unnamed:  # a maker's history: the certificates naming none drawn hollow, named
            self.history_curves.append(self.history_plot.plot(
                [s for s, _y in unnamed], [y for _s, y in unnamed], pen=None,
                name=tr("certificate naming no manufacturer"), symbol="o", symbolSize=12,
                symbolBrush="w", symbolPen=pg.mkPen(COLOURS[1], width=2)))
        self.history_plot.setLabel("left", declared(name))

    def ask_pdf_to_verify(self) -> str:
        return ask_open_file(self, tr("Verify a certificate PDF"), "", "PDF (*.pdf)")

    def ask_pdf_path(self, suggested: str) -> str:
        return ask_save_file(self, tr("Save the certificate's PDF"), suggested, "PDF (*.pdf)")

    def ask_loss(self, last_number_needed: bool, record) -> None:
        """The loss dialog (widgets/register_recoveries.py), open beside the window until
        ``record`` accepts what was typed or the user cancels."""
        from widgets.register_recoveries import LossDialog

        self._open_recovery(LossDialog(self, last_number_needed, record))

    def ask_clock_correction(self, record) -> None:
        """The clock-correction dialog, open until ``record`` accepts it or it is cancelled."""
        from widgets.register_recoveries import ClockCorrectionDialog

        self._open_recovery(ClockCorrectionDialog(self, record))

    def _open_recovery(self, dialog: QDialog) -> None:
        if self.recovery_dialog is not None:
            self.recovery_dialog.close()
        self.recovery_dialog = dialog
        dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
        dialog.finished.connect(lambda _result: self._recovery_closed(dialog))
        dialog.open()  # modal to this window; the window's event loop goes on

    def _recovery_closed(self, dialog: QDialog) -> None:
        if self.recovery_dialog is dialog:
            self.recovery_dialog = None

    def tell(self, title: str, text: str) -> None:
        QMessageBox.information(self, title, text)

    def in_background(self, work, done) -> None:
        """``work()`` on a thread of its own; ``done(result or exception)`` on the GUI
        thread (dropped when the window is gone)."""
        def run() -> None:
            try:
                result = work()
            except Exception as exc:  # noqa: BLE001 - said in the window, not lost
                result = exc
            emit_if_alive(self._delivery.finished, done, result)

        thread = threading.Thread(target=run, name="register-pdf-check", daemon=True)
        self.background = [t for t in self.background if t.is_alive()] + [thread]
        thread.start()

    def show_pdf_check(self, text: str, warning: bool, detail: str = "") -> None:
        self.pdf_check_warning = warning
        self.pdf_check.setToolTip(detail)
        self.pdf_check.setStyleSheet("color: #b00020; font-weight: bold;" if warning
                                     else "color: #555555;")
        self.pdf_check.setText(("⚠ " if warning else "") + text)

    def print_certificate(self, pdf: bytes, number: str) -> int:
        """The print dialog, then the certificate's pages as issued; 0 when cancelled."""
        from PySide6.QtPrintSupport import QPrintDialog, QPrinter

        from widgets.print_view import print_pdf

        printer = QPrinter(QPrinter.PrinterMode.HighResolution)
        printer.setDocName(tr("Certificate {number}").format(number=number))
        if QPrintDialog(printer, self).exec() != QDialog.DialogCode.Accepted:
            return 0
        return print_pdf(pdf, printer)
