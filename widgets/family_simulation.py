"""A simulation panel: parameters in a form, one of them swept over a list of values,
a family of curves in two stacked plots (the seeds' Figs 3–6)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import Qt, QTimer
from PySide6.QtWidgets import (
    QBoxLayout,
    QComboBox,
    QFormLayout,
    QLabel,
    QLineEdit,
    QVBoxLayout,
    QWidget,
)

from widgets.i18n import live, on_language_change, tr
from widgets.lazy_menu_view_box import LazyMenuViewBox
from widgets.legend_placement import place_legend
from widgets.plot_grid import axis_title_height, show_grid
from widgets.settings_form import SettingsForm

# the swept curves' colours, told apart at a glance: the first five (a default sweep)
# at least ΔE*ab 67 apart (pyqtgraph's 9 hues gave ω = 90° and 135° two greens 32 apart)
PALETTE = ("#1f5fbf", "#e07000", "#1b9e3e", "#c2185b", "#000000", "#8c564b", "#17becf",
           "#7f7f7f", "#bcbd22", "#9467bd")

#: the width (px) the plots want beside the form; narrower, the form goes above them
PLOTS_BESIDE = 300
#: characters a choice shows at least (the whole text where there is room, and in its list)
CHOICE_CHARACTERS = 14

# (parameters) -> (x, top curve, bottom curve)
FamilyModel = Callable[[dict], tuple[np.ndarray, np.ndarray, np.ndarray]]


class FamilySimulation(QWidget):
    """``top_curves`` / ``bottom_curves`` hold one PlotDataItem per swept value (created once).

    ``sweeps`` maps a parameter key to its (symbol, unit) for the legend.
    """

    def __init__(self, form: SettingsForm, sweeps: dict[str, tuple[str, str]],
                 default_values: str, model: FamilyModel, labels: tuple[str, str, str],
                 parent=None) -> None:
        super().__init__(parent)
        self.form = form
        self.sweeps = sweeps
        self.model = model
        self._setup_ui(default_values, labels)
        self._layout()
        self._drawn = False  # the family is computed when the tab is first shown (start-up)

    def showEvent(self, event) -> None:  # noqa: N802
        if not self._drawn:
            self.update_curves()
        super().showEvent(event)

    def _setup_ui(self, default_values: str, labels: tuple[str, str, str]) -> None:
        self.sweep_values = QLineEdit(default_values)
        live(self.sweep_values.setToolTip, tr("Values of the swept parameter, separated by "
                                              "commas"))
        caption = QLabel()
        live(caption.setText, tr("sweep values"))
        self.form.layout().addRow(caption, self.sweep_values)
        self.form.changed.connect(self.update_curves)
        self.sweep_values.editingFinished.connect(self.update_curves)
        self._labels = labels
        self.top_plot = pg.PlotWidget(background="w", viewBox=LazyMenuViewBox())
        self.bottom_plot = pg.PlotWidget(background="w", viewBox=LazyMenuViewBox())
        self._relabel()
        on_language_change(self, self._relabel)
        for plot in (self.top_plot, self.bottom_plot):
            show_grid(plot)
            plot.getAxis("left").enableAutoSIPrefix(False)
            plot.addLegend(offset=(-10, 10))
            # the room around a plot's y axis changes with its legend's place (above the
            # view when cramped): its least height follows
            plot.getPlotItem().getViewBox().sigResized.connect(self._keep_height_later)
        self.top_curves: list[pg.PlotDataItem] = []
        self.bottom_curves: list[pg.PlotDataItem] = []

    def _relabel(self) -> None:
        x_label, top_label, bottom_label = (tr(label.source) for label in self._labels)
        self.top_plot.setLabel("left", top_label)
        self.bottom_plot.setLabel("left", bottom_label)
        for plot in (self.top_plot, self.bottom_plot):
            plot.setLabel("bottom", x_label)
        if hasattr(self, "_plots_layout"):
            self._keep_height()  # a title in another language: another length

    def _keep_height_later(self, *_) -> None:
        """:meth:`_keep_height` once the plots' layout is done (not inside it)."""
        if not getattr(self, "_keep_pending", False) and hasattr(self, "_plots_layout"):
            self._keep_pending = True
            QTimer.singleShot(0, self, self._keep_height_now)  # not after it is gone

    def _keep_height_now(self) -> None:
        self._keep_pending = False
        self._keep_height()

    def _plots_least_height(self) -> int:
        """The plots' least height: each as tall as its y axis' title needs to be shown
        whole (widgets/plot_grid.axis_title_height), the two with the space between them.
        Beside the docked instrument panel at 1280×720 each plot had 138 px, its y axis
        68 px, and the polygon's titles "ε_x induced error (\")" (126 px) and
        "ε_y vertical (\")" (91 px) were cut at both ends (day review 65)."""
        least = 0
        for plot in (self.top_plot, self.bottom_plot):
            need = axis_title_height(plot)
            if plot.minimumHeight() != need:
                plot.setMinimumHeight(need)
            least += need
        return least + max(0, self._plots_layout.spacing())

    def _layout(self) -> None:
        plots = self._plots_layout = QVBoxLayout()
        plots.addWidget(self.top_plot)
        plots.addWidget(self.bottom_plot)
        self._fit_form()
        self.body = QBoxLayout(QBoxLayout.Direction.LeftToRight, self)
        self.body.addWidget(self.form)
        self.body.addLayout(plots, 1)

    def _fit_form(self) -> None:
        """The form as narrow as its narrowest useful field: a choice shows
        :data:`CHOICE_CHARACTERS` characters at least (all of its text where there is
        room; its list is as wide as its longest); where the tab is narrower than its captions
        and fields side by side, each caption goes above its field (:meth:`resizeEvent`).
        Docked beside the instrument
        panel at 1280×720 the polygon's What-if tab needed a horizontal scroll bar (its
        set-up choice "vertical along the polygon's axis (rolled with the tilt)" held the
        form at 486 px of the tab's 494)."""
        self.form.layout().setFieldGrowthPolicy(
            QFormLayout.FieldGrowthPolicy.AllNonFixedFieldsGrow)
        for choice in self.form.findChildren(QComboBox):
            # as wide as its text where there is room (its size hint), never held wider
            # than CHOICE_CHARACTERS characters (its minimum), its list as wide as its
            # longest entry
            narrow = choice.fontMetrics().horizontalAdvance("x" * CHOICE_CHARACTERS)
            choice.setMinimumWidth(min(choice.minimumSizeHint().width(),
                                       narrow + choice.iconSize().width() + 24))
            view = choice.view()
            view.setMinimumWidth(view.sizeHintForColumn(0) + 2 * view.frameWidth())
        self.sweep_values.setMinimumWidth(0)

    def _form_width_beside(self) -> int:
        """The form's width with every caption beside its field, each shown whole."""
        form = self.form.layout()
        labels = fields = spans = 0
        for row in range(form.rowCount()):
            for role, in_column in ((QFormLayout.ItemRole.LabelRole, "label"),
                                    (QFormLayout.ItemRole.FieldRole, "field"),
                                    (QFormLayout.ItemRole.SpanningRole, "span")):
                item = form.itemAt(row, role)
                if item is None or item.widget() is not None and item.widget().isHidden():
                    continue
                width = item.sizeHint().width()
                if in_column == "label":
                    labels = max(labels, width)
                elif in_column == "field":
                    fields = max(fields, width)
                else:
                    spans = max(spans, width)
        margins = form.contentsMargins()
        spacing = max(0, form.horizontalSpacing())
        return max(labels + spacing + fields, spans) + margins.left() + margins.right()

    def resizeEvent(self, event) -> None:  # noqa: N802 - Qt's name
        """The form beside the plots where both have room, above them where not (a
        docked panel's narrow tab: the plots keep the width); where the form's captions
        and fields have no room side by side either, each caption above its field (every
        choice's text shown whole)."""
        width = event.size().width()
        form_width = self._form_width_beside()
        beside = width >= form_width + PLOTS_BESIDE
        direction = (QBoxLayout.Direction.LeftToRight if beside
                     else QBoxLayout.Direction.TopToBottom)
        if self.body.direction() != direction:
            self.body.setDirection(direction)
        margins = self.body.contentsMargins()
        wrap = (QFormLayout.RowWrapPolicy.WrapAllRows
                if not beside and width - margins.left() - margins.right() < form_width
                else QFormLayout.RowWrapPolicy.DontWrapRows)
        form = self.form.layout()
        if form.rowWrapPolicy() != wrap:
            form.setRowWrapPolicy(wrap)
        self._keep_height()
        super().resizeEvent(event)

    def setMinimumHeight(self, height: int) -> None:  # noqa: N802 - Qt's name
        """The least height of the plots (a plot tab keeps each panel's); the form above
        them, when it is, is added to it (a minimum set on the widget is the layout's
        floor: the stacked form and plots were squeezed flat into the plots' 300 px)."""
        self._plots_height = max(0, int(height))
        self._keep_height()

    def _keep_height(self) -> None:
        plots = max(getattr(self, "_plots_height", 0), self._plots_least_height())
        above = 0
        if self.body.direction() == QBoxLayout.Direction.TopToBottom:
            above = self.form.sizeHint().height() + max(0, self.body.spacing())
        # and the layout's margins: without them the plots had 18 px less than their least
        # height once they kept their titles whole (the lower one's legend over the upper
        # one's x axis title)
        margins = self.body.contentsMargins()
        super().setMinimumHeight(plots + above + margins.top() + margins.bottom())

    def swept_values(self) -> list[float]:
        out = []
        for part in self.sweep_values.text().replace(";", ",").split(","):
            try:
                out.append(float(part))
            except ValueError:
                continue
        return out[:12]

    def update_curves(self) -> None:
        self._drawn = True
        params = self.form.values()
        sweep = params["sweep"]
        values = self.swept_values() or [params[sweep]]
        while len(self.top_curves) < len(values):
            index = len(self.top_curves)  # a colour each (hues 9 apart: ω 90° and 135° both
            pen = pg.mkPen(PALETTE[index % len(PALETTE)], width=2,  # green), dashed past ten
                           style=Qt.PenStyle.DashLine if index >= len(PALETTE) else
                           Qt.PenStyle.SolidLine)
            self.top_curves.append(self.top_plot.plot(pen=pen, name=" "))
            self.bottom_curves.append(self.bottom_plot.plot(pen=pen, name=" "))
        symbol, unit = self.sweeps[sweep]
        for i, (top, bottom) in enumerate(zip(self.top_curves, self.bottom_curves, strict=True)):
            if i >= len(values):
                top.setData([], [])
                bottom.setData([], [])
                continue
            x, y_top, y_bottom = self.model({**params, sweep: values[i]})
            top.setData(x, y_top)
            bottom.setData(x, y_bottom)
            for plot, curve in ((self.top_plot, top), (self.bottom_plot, bottom)):
                legend = plot.getPlotItem().legend
                label = legend.getLabel(curve)
                if label is None:
                    legend.addItem(curve, " ")
                    label = legend.getLabel(curve)
                label.setText(f"{symbol} = {values[i]:g}{unit}")
        for plot, curves in ((self.top_plot, self.top_curves),
                             (self.bottom_plot, self.bottom_curves)):
            item = plot.getPlotItem()
            for curve in curves[len(values):]:  # an unused curve: out of the legend
                item.legend.removeItem(curve)
            # in a free corner, or above the plot when it is cramped (at 1280×720 the
            # legend covered the curves and lost its last entry)
            place_legend(item, item.legend)
        self._keep_height()  # the legends' rows above a plot take room from its y axis
