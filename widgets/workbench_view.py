"""The passive view every workbench shares: readings table and set-up on the left,
fit summary, warnings and plot tabs on the right."""

from __future__ import annotations

import json

from PySide6.QtCore import QEvent, QEventLoop, QObject, QSettings, Qt, QTimer
from PySide6.QtGui import QFont
from PySide6.QtWidgets import (
    QAbstractItemView,
    QApplication,
    QDialog,
    QDoubleSpinBox,
    QFrame,
    QGridLayout,
    QGroupBox,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QMainWindow,
    QPlainTextEdit,
    QProgressBar,
    QScrollArea,
    QSizePolicy,
    QSplitter,
    QTableWidget,
    QTableWidgetItem,
    QTabWidget,
    QVBoxLayout,
    QWidget,
)

from models.readings.tabular_import import header_signature
from widgets.column_mapping_dialog import ColumnMappingDialog
from widgets.i18n import Tr, declared, live, on_language_change, tr
from widgets.plot_grid import keep_axis_title_room
from widgets.plot_image import ImageWrite, add_image_actions, plot_panels, write_png
from widgets.readings_table_view import ReadingsTableView
from widgets.settings_form import SettingsForm
from widgets.unbroken_last_word import unbroken_last_word
from widgets.wrapped_text_area import WrappedTextArea


class _Resized(QObject):
    """Calls ``callback(height)`` whenever ``widget`` is resized."""

    def __init__(self, widget: QWidget, callback) -> None:
        super().__init__(widget)
        self._callback = callback
        widget.installEventFilter(self)

    def eventFilter(self, watched, event) -> bool:  # noqa: N802 - Qt's name
        if event.type() == QEvent.Type.Resize:
            self._callback(event.size().height())
        return False


class _Splitter(QSplitter):
    """A splitter that calls ``resized()`` once it has laid out its panes anew."""

    def __init__(self, orientation, resized) -> None:
        super().__init__(orientation)
        self._resized = resized

    def resizeEvent(self, event) -> None:  # noqa: N802 - Qt's name
        super().resizeEvent(event)
        self._resized()


class WorkbenchView(QWidget):
    """Widgets only: the presenter fills them and reads the settings back."""

    def __init__(self, title: str, parent=None) -> None:
        super().__init__(parent)
        self.title = title
        self.last_status = ""
        #: writes a plot's image (path, PNG bytes): atomically; once subscribed, the
        #: presenter's write, which checks the name first as every export does
        self.write_image: ImageWrite = lambda path, data: write_png(self, path, data)
        self._setup_ui()
        self._layout()
        self._retranslate()

    def _setup_ui(self) -> None:
        self.table = ReadingsTableView()
        self.table.notice.connect(self.show_row_status)
        self.settings = SettingsForm()
        self.readings_label = QLabel()
        live(self.readings_label.setText, tr("Readings"))
        # the caption wraps instead of widening the left pane as it grows ("— 130 used, 3
        # bad cell(s) — fewer than 5 runs: flagged" pushed it from 540 to 663 px)
        self.readings_label.setWordWrap(True)
        self.readings_label.setSizePolicy(QSizePolicy.Policy.Ignored,
                                          QSizePolicy.Policy.Preferred)
        self.step_label = QLabel()
        self._nominal_title = ""
        self.step = QDoubleSpinBox()
        self.step.setRange(0.0, 1e6)
        self.step.setDecimals(4)
        live(self.step.setSpecialValueText, tr("off"))
        live(self.step.setToolTip, tr("Typing a row and pressing Return fills the next row's "
                                      "nominal value with this step (0: off) and moves to its "
                                      "first reading"))
        self.step.valueChanged.connect(lambda v: setattr(self.table, "nominal_step", v))
        self.next_label = QLabel()
        # both in two lines where the pane is narrow ("下一个 目标位置 +": the Chinese window was
        # 651 px at the least, wider than 640)
        self.next_label.setWordWrap(True)
        self.step_label.setWordWrap(True)
        self.summary = QPlainTextEdit()
        self.summary.setReadOnly(True)
        font = QFont("DejaVu Sans Mono")
        font.setStyleHint(QFont.StyleHint.Monospace)
        font.setPointSize(9)
        self.summary.setFont(font)
        self.verdict = QLabel()
        self.verdict.setWordWrap(True)
        self.verdict.setTextFormat(Qt.TextFormat.PlainText)
        self.verdict.setStyleSheet("QLabel { font-weight: bold; padding: 2px; }")
        self.figures = QTableWidget(0, 2)
        self._plot_titles: list[Tr] = []
        on_language_change(self, self._retranslate)
        self.figures.verticalHeader().hide()
        self.figures.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        header = self.figures.horizontalHeader()
        header.setSectionResizeMode(0, QHeaderView.ResizeMode.Stretch)
        header.setSectionResizeMode(1, QHeaderView.ResizeMode.ResizeToContents)
        self.figures.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        # narrow enough that the summary beside it keeps its lines at 1280×720 (#41: cramped);
        # narrower still where the window is (200 % on a 1280×720 screen: 640 px in all),
        # the summary keeping a few words a line (it was 70 px, a word broken every 5 letters)
        self.figures.setMaximumWidth(250)
        self.figures.setMinimumWidth(self.FIGURES_MIN_WIDTH)
        self.summary.setMinimumWidth(self.SUMMARY_MIN_WIDTH)
        self.warnings = QLabel()
        self.warnings.setWordWrap(True)
        self.warnings.setTextFormat(Qt.TextFormat.PlainText)
        self.warnings.setStyleSheet("QLabel { color: #8a4b00; background: #fff4dc; padding: 4px; }")
        self.warnings.hide()
        self.plot_tabs = QTabWidget()
        self.busy = QProgressBar()
        self.busy.setRange(0, 0)  # busy indicator: reading or analysing off the GUI thread
        self.busy.setMaximumHeight(10)
        self.busy.setTextVisible(False)
        self.busy.hide()

    def _layout(self) -> None:
        left = QWidget()
        left_layout = QVBoxLayout(left)
        left_layout.setContentsMargins(0, 0, 0, 0)
        # the caption beside the next row and the step, or above them where the pane is
        # narrow (at 200 % on a 1280×720 screen they left the caption no width: not shown)
        self._entry = QGridLayout()
        self._entry.setContentsMargins(0, 0, 0, 0)
        self._entry.setColumnStretch(0, 1)
        self._caption_above: bool | None = None
        self._place_caption(above=False)
        left_layout.addLayout(self._entry)
        left_layout.addWidget(self.table, 1)
        setup_box = self.setup_box = QGroupBox()
        live(setup_box.setTitle, tr("Set-up"))
        setup_layout = QVBoxLayout(setup_box)
        setup_layout.setContentsMargins(2, 2, 2, 2)
        # the set-up scrolls when the window is short: the readings keep their rows
        self.settings_area = QScrollArea()
        self.settings_area.setWidgetResizable(True)
        self.settings_area.setFrameShape(QFrame.Shape.NoFrame)
        # (sideways too, where the window has no room for its widest field: 640 px at 200 %)
        self.settings_area.setWidget(self.settings)
        setup_layout.addWidget(self.settings_area)
        left_layout.addWidget(setup_box)
        _Resized(left, self._share_left_pane)
        self._left = left
        self._columns_width = 0  # the width the readings' columns and the set-up ask for

        right = QWidget()
        right_layout = QVBoxLayout(right)
        right_layout.setContentsMargins(0, 0, 0, 0)
        fit_box = QGroupBox()
        live(fit_box.setTitle, tr("Result"))
        fit_layout = QVBoxLayout(fit_box)
        fit_layout.setContentsMargins(2, 2, 2, 2)
        fit_layout.addWidget(self.busy)
        # the bold line and every warning, above the text, each whole: as tall as their
        # text where there is room, scrolling where there is not (200 % on a 1280×720
        # screen cut both mid-line: day review 69 F5)
        self.messages_area = WrappedTextArea([self.verdict, self.warnings])
        fit_layout.addWidget(self.messages_area)
        self._fit_layout = fit_layout
        # the text and the figures' table side by side, scrolling sideways together where
        # the pane is narrower than their least widths: at 200 % on a 1280×720 screen
        # (640 px) with the capture panel open, their 280 px made the window 760 px wide
        # at the least, its right part off the screen (day review 66)
        details = QWidget()
        details_layout = QHBoxLayout(details)
        details_layout.setContentsMargins(0, 0, 0, 0)
        details_layout.addWidget(self.summary, 1)
        details_layout.addWidget(self.figures)
        self.details_area = QScrollArea()
        self.details_area.setWidgetResizable(True)
        self.details_area.setFrameShape(QFrame.Shape.NoFrame)
        self.details_area.setVerticalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.details_area.setWidget(details)
        self.details_area.setMinimumWidth(self.DETAILS_MIN_WIDTH)
        fit_layout.addWidget(self.details_area, 1)
        # the result and the plots share the height; the technician drags the line between
        self.result_splitter = QSplitter(Qt.Orientation.Vertical)
        self.result_splitter.addWidget(fit_box)
        self.result_splitter.addWidget(self.plot_tabs)
        self.result_splitter.setStretchFactor(1, 1)
        self.result_splitter.setSizes([270, 590])
        right_layout.addWidget(self.result_splitter, 1)

        splitter = self.splitter = _Splitter(Qt.Orientation.Horizontal, self._fit_left_pane)
        splitter.addWidget(left)
        splitter.addWidget(right)
        splitter.setStretchFactor(0, 2)
        splitter.setStretchFactor(1, 3)
        splitter.setSizes(list(self.SPLIT))
        # the panes share the width as SPLIT until the technician drags the line between
        self._split_dragged = False
        self._fitting = False
        splitter.splitterMoved.connect(lambda *_: setattr(self, "_split_dragged", True))
        layout = QVBoxLayout(self)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.addWidget(splitter)

    # rows the readings table keeps in sight before the set-up below it gets its full
    # height (at 1280×720 the set-up took it: 3 rows of positioning readings were left)
    READINGS_ROWS = 12
    # the least the set-up keeps (it scrolls below its full height; 120 px made the window
    # 351 px tall at the least, more than a 1280×720 screen at 200 % has below its title bar)
    SETUP_MIN_HEIGHT = 100
    #: the least the set-up keeps while the readings keep their rows (:meth:`keep_readings_rows`):
    #: a field's row, scrolling
    SETUP_LEAST_HEIGHT = 32
    #: the readings' rows kept in sight before the set-up's least height (0: none)
    _rows_kept = 0
    #: the width the result keeps before the readings pane gives up its columns' width (its
    #: text beside the figures' table; the least the result kept when the panes had least widths)
    RESULT_WIDTH = 340
    #: the readings pane's and the result's shares of the width
    SPLIT = (520, 880)
    #: the least width of the figures' table (a name and a value; 250 px where there is room)
    FIGURES_MIN_WIDTH = 150
    #: the least width of the result's text beside it
    SUMMARY_MIN_WIDTH = 130
    #: the least width the text and the figures keep in the window: narrower, they scroll
    #: sideways together (FIGURES_MIN_WIDTH + SUMMARY_MIN_WIDTH are their least inside)
    DETAILS_MIN_WIDTH = 120

    def _share_left_pane(self, height: int) -> None:
        """Share the left pane's height: the readings first (READINGS_ROWS rows), the
        set-up the rest up to its full height, scrolling when it has less."""
        header = self.table.horizontalHeader().sizeHint().height()
        rows = self.table.verticalHeader().defaultSectionSize() * self.READINGS_ROWS
        readings = header + rows + 2 * self.table.frameWidth() + \
            self.readings_label.sizeHint().height() + 12
        full = self.settings.sizeHint().height() + 2
        beside = sum(w.sizeHint().width() for w in (self.next_label, self.step_label, self.step)
                     if not w.isHidden()) + 3 * self._entry.horizontalSpacing()
        self._place_caption(above=self._left.width() < beside + self.CAPTION_MIN_WIDTH)
        setup = max(min(full, self.SETUP_MIN_HEIGHT), min(full, height - readings - 40))
        if self._rows_kept:  # the capture panel open: the readings' rows before the set-up's
            setup = max(self.SETUP_LEAST_HEIGHT,
                        min(setup, height - self._height_beside_setup(self._rows_kept)))
        self.settings_area.setFixedHeight(setup)

    def _height_beside_setup(self, rows: int) -> int:
        """The left pane's height less the set-up's scrolling part, with ``rows`` rows of
        readings in sight: the caption and the next row above the table (as tall as their
        lines at the pane's width), the table's header, rows and sideways scroll bar, the
        set-up's frame and title, the spacing between them."""
        width = self._left.width()
        entry = self._entry.heightForWidth(width) if self._entry.hasHeightForWidth() \
            else self._entry.sizeHint().height()
        table = (self.table.horizontalHeader().sizeHint().height()
                 + self.table.verticalHeader().defaultSectionSize() * rows
                 + 2 * self.table.frameWidth()
                 + self.table.horizontalScrollBar().sizeHint().height())
        inside = self.setup_box.layout()
        margins = inside.contentsMargins()
        frame = (self.setup_box.sizeHint().height() - inside.sizeHint().height()
                 + margins.top() + margins.bottom())
        return entry + table + max(0, frame) + 2 * self._left.layout().spacing()

    #: the least width the readings' caption keeps beside the next row and the step
    CAPTION_MIN_WIDTH = 160

    def _place_caption(self, above: bool) -> None:
        if above == self._caption_above:
            return
        for widget in (self.readings_label, self.next_label, self.step_label, self.step):
            self._entry.removeWidget(widget)
        self._entry.addWidget(self.readings_label, 0, 0, 1, 4 if above else 1)
        if above:
            # a narrow pane: the next reading across the pane, the step and its caption on a
            # row of their own below it. Side by side in the pane's last quarter each was
            # drawn a word (in Chinese a character) a line: "下一个 目标位置 +" six lines
            # tall beside the docked capture panel at 150 % (gui80, gui81)
            self._entry.addWidget(self.next_label, 1, 0, 1, 4)
            self._entry.addWidget(self.step_label, 2, 0, 1, 2)
            self._entry.addWidget(self.step, 2, 2, 1, 2)
        else:
            self._entry.addWidget(self.next_label, 0, 1)
            self._entry.addWidget(self.step_label, 0, 2)
            self._entry.addWidget(self.step, 0, 3)
        # beside the next reading, the caption keeps the width it was placed there for: the
        # plan's long next caption ("下一个：目标位置 270°，第 1 次测量 ↑，第 1 次读数（共 2 次）")
        # squeezed it to 57 px, narrower than its unbroken last words "测量：已标注" (72 px),
        # and "注" (flagged) was cut off (gui80)
        self._entry.setColumnMinimumWidth(0, 0 if above else self.CAPTION_MIN_WIDTH)
        self._caption_above = above

    def _left_width_wanted(self) -> int:
        """The readings pane's width with every column and the set-up's every field in sight."""
        box = self.setup_box
        frame = box.contentsMargins()
        inside = box.layout().contentsMargins()
        setup = (self.settings.minimumSizeHint().width()
                 + self.settings_area.verticalScrollBar().sizeHint().width()
                 + frame.left() + frame.right() + inside.left() + inside.right())
        return max(self._columns_width, setup)

    def _fit_left_pane(self) -> None:
        """The readings pane as wide as its columns and its set-up (the polygon's last column
        in sight at 1280 px) while the result beside it keeps RESULT_WIDTH; where the window
        has less (200 % on a 1280×720 screen: 640 px) the pane is narrower and the table and
        the set-up scroll sideways. These were the panes' least widths: the window could not
        be narrower than 780 px (the positioning workbench's 892)."""
        splitter = self.splitter
        sizes = splitter.sizes()
        total = sum(sizes)
        if total <= 0 or self._fitting:
            return
        result = max(self.RESULT_WIDTH, splitter.widget(1).minimumSizeHint().width())
        left = min(self._left_width_wanted(), total - result)
        if not self._split_dragged:  # the pane's share, if its columns have that much
            left = max(left, total * self.SPLIT[0] // sum(self.SPLIT))
        elif left <= sizes[0]:  # as the technician left it: they see the columns
            return
        if left != sizes[0]:
            self._fitting = True  # the panes resized by it call it again
            try:
                splitter.setSizes([left, total - left])
            finally:
                self._fitting = False

    # -- the calls the presenter makes (all it knows of the view) ----------------
    def subscribe(self, presenter) -> None:
        """Wire the user's actions to the presenter (a workbench's view adds its own)."""
        self.settings.changed.connect(presenter.settings_edited)
        self.write_image = presenter.save_image  # a plot's "Save image…"

    def attach_table_model(self, model) -> None:
        self.table.setModel(model)
        header = self.table.horizontalHeader()
        header.setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
        # Qt measures the first 1000 rows for every change: 64 give the same widths for
        # readings (one number format per column) and keep an edit cheap on long runs.
        header.setResizeContentsPrecision(64)
        header.setStretchLastSection(True)
        header.sectionResized.connect(self._keep_columns_in_sight)
        header.geometriesChanged.connect(self._keep_columns_in_sight)

    def _keep_columns_in_sight(self, *_args) -> None:
        """The readings pane as wide as every column where the window has room for it
        (_fit_left_pane; the polygon's set and direction columns put its last ones behind a
        horizontal scroll bar at 1280 px)."""
        table = self.table
        header = table.horizontalHeader()
        count = header.count()
        if not count:
            return
        # the columns' own widths: the stretched last one counts with its contents' width,
        # not the width it was stretched to (#41: counted stretched, the least width only
        # grew — 663 px for the theodolite's 303 px of columns — and, with the instrument
        # panel docked, the result's text was left 70 px)
        last = count - 1
        natural = sum(header.sectionSize(i) for i in range(last) if not header.isSectionHidden(i))
        if not header.isSectionHidden(last):
            # (a stretched section is never narrower than the header's default section)
            natural += max(header.sectionSizeHint(last), table.sizeHintForColumn(last),
                           header.defaultSectionSize())
        width = (natural + table.verticalHeader().width() + 2 * table.frameWidth()
                 + table.verticalScrollBar().sizeHint().width())
        if width != self._columns_width:
            self._columns_width = width
            self._fit_left_pane()

    def hold_columns(self) -> None:
        """The columns keep their widths (readings arrive from an instrument: the capture
        widens the ones it fills; no re-measure of every cell at each take)."""
        self.table.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.Interactive)

    def fit_columns(self, rows: int, live_rows: int, measure_rows: int) -> None:
        """Columns follow their contents up to ``live_rows`` rows. On long sheets Qt's
        re-measuring after every edit costs ~10 ms, so they are sized once (up to
        ``measure_rows`` rows; beyond, not measured at all: that scan stalls)."""
        header = self.table.horizontalHeader()
        if rows <= live_rows:
            if header.sectionResizeMode(0) != QHeaderView.ResizeMode.ResizeToContents:
                header.setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
            return
        if header.sectionResizeMode(0) == QHeaderView.ResizeMode.ResizeToContents:
            header.setSectionResizeMode(QHeaderView.ResizeMode.Interactive)
            if rows <= measure_rows:
                self.table.resizeColumnsToContents()
                self._measured_rows = rows
        elif rows <= measure_rows and rows != self._measured_rows:
            # other readings in the sheet (a take, an import, a paste): measured again, once;
            # sized for the first ones only, a fringe take's 12-digit u sin/u cos were cut
            # ("0.2659…") while the empty θ-phase column had the room (day 65, F10)
            self.table.resizeColumnsToContents()
            self._measured_rows = rows

    #: the rows the columns were last measured for (long sheets: not at every edit)
    _measured_rows = -1

    def _retranslate(self) -> None:
        """Texts made here from parts (the plot tabs, the step's label) set anew in the
        language now chosen."""
        self.figures.setHorizontalHeaderLabels([tr("figure"), tr("value")])
        for index, title in enumerate(self._plot_titles):
            self.plot_tabs.setTabText(index, tr(title.source))
        self.step_label.setText(tr("next {column} +").format(column=declared(
            self._nominal_title)) if self._nominal_title else "")
        self._fit_left_pane()  # the set-up's captions are as wide as the language makes them
        self._fit_headers()

    def _fit_headers(self) -> None:
        """Columns sized once (a long sheet, a live capture's) as wide as their headers in
        the language now chosen, no narrower (gui78, live78: "准直仪 x [" — the Chinese
        "自准直仪 x [\"]" cut to the English header's width); columns that follow their
        contents do so by themselves. Only widened: the contents are not measured again."""
        header = self.table.horizontalHeader()
        if header.count() == 0 or \
                header.sectionResizeMode(0) == QHeaderView.ResizeMode.ResizeToContents:
            return
        for column in range(header.count()):
            needed = header.sectionSizeFromContents(column).width()
            if header.sectionSize(column) < needed:
                header.resizeSection(column, needed)

    def set_entry_columns(self, nominal: int | None, entry: int, nominal_title: str) -> None:
        self.table.nominal_column, self.table.entry_column = nominal, entry
        self._nominal_title = nominal_title if nominal is not None else ""
        self._retranslate()
        self.step_label.setVisible(nominal is not None)
        self.step.setVisible(nominal is not None)

    def set_readings_per_point(self, n: int) -> None:
        """Typed entry fills a point's nominal value n times (n readings make a point)."""
        self.table.readings_per_point = n

    def show_status(self, text: str) -> None:
        """A passing message (a table written): the window's status bar for ten seconds, not
        the readings' caption (which the next analysis rewrites); ``last_status`` keeps it."""
        self.last_status = text
        top = self.window()
        if isinstance(top, QMainWindow):
            top.statusBar().showMessage(text, 10_000)

    def show_row_status(self, text: str) -> None:
        """A message about a row of this sheet (what was typed and not entered): as
        :meth:`show_status`, and taken away when the sheet is replaced (the window's
        ``StatusLine.forget``)."""
        self.last_status = text
        top = self.window()
        if isinstance(top, QMainWindow):
            bar = top.statusBar()
            if hasattr(bar, "show_about"):
                bar.show_about(text, 10_000, self)
            else:
                bar.showMessage(text, 10_000)

    def set_next_row(self, text: str) -> None:
        self.next_label.setText(text)

    def add_setting(self, parameter) -> None:
        self.settings.add_parameter(parameter)

    def set_settings(self, values: dict) -> None:
        self.settings.set_values(values)

    def settings_values(self) -> dict:
        return self.settings.values()

    def set_setting_units(self, units: dict[str, str]) -> None:
        """The units other settings give the fields of ``units``' keys."""
        self.settings.set_units(units)

    def mark_setting(self, key: str) -> None:
        """Mark the setting the readings refuse ("": none; a key no field has: none)."""
        self.settings.mark(key)

    #: the least height a plot panel keeps: below it the tab scrolls instead of squeezing
    #: the plots flat and overprinting their axis titles (high-DPI scale, small windows)
    PANEL_MIN_HEIGHT = 150

    def keep_readings_rows(self, rows: int) -> None:
        """The readings table keeps ``rows`` rows in sight, the set-up giving way first down to
        :attr:`SETUP_LEAST_HEIGHT` (0: the set-up its usual least): the capture panel open on
        a 1280×720 screen at 150 % left 3–5 rows being filled beside a 100 px set-up (gui81)."""
        self._rows_kept = max(0, int(rows))
        self._share_left_pane(self._left.height())

    def keep_plot_height(self, height: int) -> None:
        """The plot tabs keep at least ``height`` px when the window's room shrinks (0: no
        minimum): the capture panel docked at the bottom asks for ~200 px of plot (#41);
        the result box above gives way first."""
        self.plot_tabs.setMinimumHeight(max(0, int(height)))

    def add_plot_tab(self, widget: QWidget, title: Tr) -> None:
        panels = max(1, plot_panels(widget))
        widget.setMinimumHeight(self.PANEL_MIN_HEIGHT * panels)
        # and, one plot's panel, as tall as its y axis' title needs (shown whole)
        keep_axis_title_room(widget, self.PANEL_MIN_HEIGHT * panels)
        scroll = QScrollArea()
        scroll.setWidgetResizable(True)
        scroll.setFrameShape(QFrame.Shape.NoFrame)
        scroll.setWidget(widget)
        self.plot_tabs.addTab(scroll, title)
        self._plot_titles.append(title)
        # through the presenter's checked write once it is subscribed (rev64: in place, over
        # an issued file a .png link named)
        add_image_actions(widget, f"{self.title} {title.source}",
                          lambda path, data: self.write_image(path, data))

    def plot_widget(self, index: int) -> QWidget:
        """The plot of tab ``index`` (inside its scroll area)."""
        tab = self.plot_tabs.widget(index)
        return tab.widget() if isinstance(tab, QScrollArea) else tab

    def set_summary(self, text: str) -> None:
        self.summary.setPlainText(text)

    MAPPINGS_KEY = "import/column_mappings"

    def ask_column_mapping(self, columns, header: list[str], preview: list[list[str]],
                           reason: str) -> dict[str, str] | None:
        """The mapping remembered for these headers, else the user's (None: cancelled)."""
        store = QSettings()
        signature = header_signature(header)
        try:
            remembered = json.loads(store.value(self.MAPPINGS_KEY, "{}") or "{}")
        except (TypeError, ValueError):
            remembered = {}
        if isinstance(remembered, dict) and isinstance(remembered.get(signature), dict):
            return remembered[signature]
        dialog = ColumnMappingDialog(columns, header, preview, reason, self)
        if dialog.exec() != QDialog.DialogCode.Accepted:
            return None
        mapping = dialog.mapping()
        if dialog.remember.isChecked():
            remembered = remembered if isinstance(remembered, dict) else {}
            remembered[signature] = mapping
            store.setValue(self.MAPPINGS_KEY, json.dumps(remembered, ensure_ascii=False))
        return mapping

    def set_verdict(self, text: str, tooltip: str = "") -> None:
        """The verdict line, and its tooltip (the certificate's statement of conformity; none
        where there is no result)."""
        self.verdict.setText(text)
        self.verdict.setToolTip(tooltip)
        self.verdict.setVisible(bool(text))

    def set_figures(self, figures: dict[str, float],
                    printed: dict[str, str] | None = None) -> None:
        """The headline figures, each with its unit in its name: as the certificate prints
        those in ``printed`` (by name), the others to four significant digits."""
        printed = printed or {}
        self.figures.setRowCount(len(figures))
        for row, (name, value) in enumerate(figures.items()):
            self.figures.setItem(row, 0, QTableWidgetItem(declared(name)))
            item = QTableWidgetItem(printed.get(name, f"{value:.4g}"))
            item.setTextAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
            self.figures.setItem(row, 1, item)
        self.figures.setVisible(bool(figures))

    def add_result_notice(self, notice: QWidget) -> None:
        """``notice`` under the warnings, at the top of the result strip: in sight at any
        window size, never in the set-up's scrolled form (day review 64 P2: a stale
        reference's notice there sat at y = 936 in a 720-px window)."""
        layout = self._fit_layout
        layout.insertWidget(layout.indexOf(self.messages_area) + 1, notice)

    def set_warnings(self, warnings: list[str]) -> None:
        self.warnings.setText("\n".join(f"⚠ {w}" for w in warnings))
        self.warnings.setVisible(bool(warnings))

    def set_busy(self, busy: bool) -> None:
        """Show the busy bar. While a worker reads or analyses, the plots (about to be
        replaced) are not repainted: pyqtgraph paints in Python, which would wait for the
        worker's GIL and stall the window. The table stays live (it is what the user
        looks at, and holding back a million-row table's layout only moves it later)."""
        self.busy.setVisible(busy)
        if busy:
            self.plot_tabs.setUpdatesEnabled(False)
        else:  # the plots repaint in a later event than the table: two short pauses
            QTimer.singleShot(20, self._resume_plots)  # instead of one long one

    def show_reading(self, text: str) -> bool:
        """A file read on the GUI thread: the busy bar, a wait cursor and ``text`` painted
        before the read holds the thread; "" ends it (the result text set by then, or the
        one before put back when the file was refused). Returns whether it was shown."""
        if not text:
            self.busy.hide()
            QApplication.restoreOverrideCursor()
            if self.summary.toPlainText() == self._reading_text:
                self.summary.setPlainText(self._summary_before)
            return False
        if not self.isVisible():
            return False
        self._summary_before, self._reading_text = self.summary.toPlainText(), text
        self.busy.show()
        self.summary.setPlainText(text)
        QApplication.setOverrideCursor(Qt.CursorShape.WaitCursor)
        QApplication.processEvents(QEventLoop.ProcessEventsFlag.ExcludeUserInputEvents)
        return True

    def _resume_plots(self) -> None:
        if self.busy.isHidden():  # not busy again meanwhile
            self.plot_tabs.setUpdatesEnabled(True)

    def set_readings_caption(self, text: str) -> None:
        # wrapped, its last Chinese word kept whole (day 74 finding 13: "标注" alone)
        self.readings_label.setText(unbroken_last_word(text))

    def append_to_readings_caption(self, text: str) -> None:
        self.set_readings_caption(self.readings_label.text() + text)
