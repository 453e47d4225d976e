"""The positioning workbench's view: the shared readings and set-up, the mean deviation
per direction with its ±2s bands and the envelope of A, the reversal per target, every
run's readings, and the compensation table export. Widgets only."""

from __future__ import annotations

from PySide6.QtWidgets import (
    QAbstractItemView,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QLineEdit,
    QMessageBox,
    QPushButton,
    QTableWidget,
)

from models.positioning import TITLE
from widgets.figure_plot import FigurePlot
from widgets.i18n import declared, live, tr
from widgets.save_file import ask_save_file
from widgets.text_table import show_text_table
from widgets.workbench_view import WorkbenchView


class PositioningView(WorkbenchView):
    def __init__(self, parent=None) -> None:
        super().__init__(TITLE, parent)
        self.deviation_plot = FigurePlot()
        self.reversal_plot = FigurePlot()
        self.readings_plot = FigurePlot()
        self.compensation_button = QPushButton()
        live(self.compensation_button.setText, tr("Export compensation table…"))
        live(self.compensation_button.setToolTip, tr(
            "Compensation = −mean deviation, at the targets or a uniform step, as set above: "
            "CSV, LinuxCNC's COMP_FILE (type 0), or a controller's table (SINUMERIK, FANUC, "
            "HEIDENHAIN, TwinCAT, ISG, Mach4)"))
        self.compensation_button.setEnabled(False)
        self.add_plot_tab(self.deviation_plot, tr("Deviation per target"))
        self.add_plot_tab(self.reversal_plot, tr("Reversal per target"))
        self.add_plot_tab(self.readings_plot, tr("Runs"))
        self.per_target = QTableWidget()
        self.per_target.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.per_target.verticalHeader().hide()
        self.per_target.horizontalHeader().setSectionResizeMode(
            QHeaderView.ResizeMode.ResizeToContents)
        self.add_plot_tab(self.per_target, tr("Per target"))

    def subscribe(self, presenter) -> None:
        super().subscribe(presenter)
        self.settings.layout().addRow(self.compensation_button)
        self.compensation_button.clicked.connect(presenter.export_compensation_dialog)

    def show_figures(self, deviation, reversal, readings) -> None:
        """The declared figures (models/positioning/plots.py); ``None`` leaves a plot empty."""
        self.deviation_plot.show_figure(deviation)
        self.reversal_plot.show_figure(reversal)
        self.readings_plot.show_figure(readings)
        self.compensation_button.setEnabled(True)

    def show_per_target(self, header, rows) -> None:
        show_text_table(self.per_target, [declared(h) for h in header], rows, align_right=True)

    def clear_result(self) -> None:
        for plot in (self.deviation_plot, self.reversal_plot, self.readings_plot):
            plot.clear()
        self.per_target.setRowCount(0)
        self.compensation_button.setEnabled(False)

    def ask_compensation_path(self, suggested: str, fmt: str) -> str:
        filters = (tr("LinuxCNC compensation file (*.txt *.comp);;All files (*)") if fmt == "linuxcnc"
                   else tr("CSV (*.csv);;All files (*)") if fmt == "csv" else
                   tr("Controller compensation file (*.{ext});;All files (*)").format(
                       ext=suggested.rsplit(".", 1)[-1]))
        return ask_save_file(self, tr("Export compensation table"), suggested, filters)

    def ask_controller_options(self, controller: str, fields: list[tuple[str, str, str]]
                               ) -> dict[str, str] | None:
        """A small form: one line per option (key, its help as tooltip, current value);
        the values typed, or None when cancelled."""
        dialog = QDialog(self)
        dialog.setWindowTitle(tr("{controller}: controller options").format(controller=controller))
        form = QFormLayout(dialog)
        # what every controller assumes of the log, said where the table is decided (comp75 F2)
        datum = QLabel(tr("Targets must be machine coordinates: a log in a work offset gives a "
                          "shifted table."))
        datum.setObjectName("machine_coordinates")
        datum.setWordWrap(True)
        form.addRow(datum)
        edits = {}
        for key, help_text, value in fields:
            edit = QLineEdit(value)
            edit.setToolTip(declared(help_text))
            edit.setPlaceholderText(declared(help_text))
            edit.setMinimumWidth(140)
            note = QLabel(declared(help_text))
            note.setWordWrap(True)
            note.setEnabled(False)  # the help, greyed beside the value
            row = QHBoxLayout()
            row.addWidget(edit)
            row.addWidget(note, 1)
            form.addRow(key, row)
            edits[key] = edit
        dialog.setMinimumWidth(560)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok
                                   | QDialogButtonBox.StandardButton.Cancel)
        buttons.accepted.connect(dialog.accept)
        buttons.rejected.connect(dialog.reject)
        form.addRow(buttons)
        if dialog.exec() != QDialog.DialogCode.Accepted:
            return None
        return {key: edit.text() for key, edit in edits.items()}

    def tell(self, title: str, text: str) -> None:
        QMessageBox.warning(self, title, text)
