"""A small form of typed settings fields, read and written as a dict."""

from __future__ import annotations

from typing import Any

from PySide6.QtCore import QEvent, QObject, Qt, Signal
from PySide6.QtWidgets import (
    QAbstractScrollArea,
    QApplication,
    QComboBox,
    QDoubleSpinBox,
    QFormLayout,
    QLabel,
    QLineEdit,
    QSpinBox,
    QWidget,
)

from models.parameters import Parameter
from widgets.i18n import Tr, declared, live, on_language_change, tr

#: a form whose widest label and widest field are wider than this (px) wraps its rows
WRAP_WIDTH = 600
#: a caption wider than this (px) goes above its field, the field the form's full width: one
#: long caption set the label column and left every field ~110 px (#41: the polygon's faces
#: field showed "rom the readings" at 1280×720 with the capture panel docked)
LONG_CAPTION = 150
#: a field whose value the readings refuse (a tilt bound of 0 where they do not identify the
#: tilt): the certificate dialog's colour of a field to correct
REFUSED_STYLE = "background: #ffd7d7;"


class _UnfocusedWheel(QObject):
    """Hands the wheel of a field without focus to the area that scrolls around it: scrolling
    a set-up past a field never changes it (#41: "not stated" became 0.3000)."""

    def eventFilter(self, watched, event) -> bool:  # noqa: N802 - Qt's name
        if event.type() == QEvent.Type.Wheel and isinstance(watched, QWidget) \
                and not watched.hasFocus():
            parent = watched.parentWidget()
            while parent is not None and not isinstance(parent, QAbstractScrollArea):
                parent = parent.parentWidget()
            if parent is not None:
                QApplication.sendEvent(parent.verticalScrollBar(), event)
            return True
        return False


_WHEEL_FILTER: _UnfocusedWheel | None = None


def ignore_unfocused_wheel(widget: QWidget) -> None:
    """The mouse wheel changes ``widget`` (a spin box, a list) only when it has focus (a
    click or Tab gives it); otherwise the wheel scrolls what is around it."""
    global _WHEEL_FILTER  # noqa: PLW0603 - one filter for the application
    if _WHEEL_FILTER is None:
        _WHEEL_FILTER = _UnfocusedWheel(QApplication.instance())
    widget.setFocusPolicy(Qt.FocusPolicy.StrongFocus)
    widget.installEventFilter(_WHEEL_FILTER)


def _suffix(unit: str) -> str:
    """A number field's suffix for ``unit``: "°", "″", "′" close up to the figure, any other
    unit after a space (" mV", " µm")."""
    return f" {unit}" if unit and unit not in ("°", "\"", "′") else unit


def _shown(text: str) -> Tr:
    """A text of the window (``tr``) as it is; a text the models declare, translated."""
    return text if isinstance(text, Tr) else declared(text)


class SettingsForm(QWidget):
    """Fields keyed by setting name; ``changed`` fires when the user edits one."""

    changed = Signal()

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self._fields: dict[str, QWidget] = {}
        self._form = QFormLayout(self)
        self._form.setContentsMargins(4, 4, 4, 4)
        self._choices: list[tuple[QComboBox, list[Tr]]] = []
        self._widest = (0, 0)  # the widest label and field so far (px)
        on_language_change(self, self._retranslate_choices)

    def add_float(self, key: str, label: str, minimum: float, maximum: float, decimals: int = 3,
                  suffix: str = "", step: float = 1.0, tooltip: str = "") -> QDoubleSpinBox:
        box = QDoubleSpinBox()
        box.setRange(minimum, maximum)
        box.setDecimals(decimals)
        box.setSingleStep(step)
        box.setSuffix(suffix)
        box.setKeyboardTracking(False)
        box.valueChanged.connect(self.changed)
        return self._add(key, label, box, tooltip)

    def add_int(self, key: str, label: str, minimum: int, maximum: int, suffix: str = "",
                special: str = "", tooltip: str = "") -> QSpinBox:
        box = QSpinBox()
        box.setRange(minimum, maximum)
        box.setSuffix(suffix)
        box.setKeyboardTracking(False)
        if special:
            live(box.setSpecialValueText, _shown(special))
        box.valueChanged.connect(self.changed)
        return self._add(key, label, box, tooltip)

    def add_choice(self, key: str, label: str, choices: list[tuple[Any, str]],
                   tooltip: str = "") -> QComboBox:
        box = QComboBox()
        texts = [_shown(text) for _, text in choices]
        for (value, _), text in zip(choices, texts, strict=True):
            box.addItem(text, value)
        self._choices.append((box, texts))
        box.currentIndexChanged.connect(self.changed)
        return self._add(key, label, box, tooltip)

    def add_text(self, key: str, label: str, tooltip: str = "") -> QLineEdit:
        edit = QLineEdit()
        edit.editingFinished.connect(self.changed)
        return self._add(key, label, edit, tooltip)

    def add_parameter(self, p: Parameter) -> QWidget:
        """The field a declared setting asks for: its type, range, unit and help."""
        tip = p.help
        if p.kind == "choice":
            return self.add_choice(p.key, p.label, list(p.choices), tip)
        if p.kind == "text":
            return self.add_text(p.key, p.label, tip)
        low = 0 if p.zero else (p.minimum if p.minimum is not None else -1e12)
        high = p.maximum if p.maximum is not None else 1e12
        suffix = _suffix(p.unit)
        if p.kind == "int":
            box = self.add_int(p.key, p.label, int(low), int(min(high, 2**31 - 1)), suffix,
                               p.zero, tip)
        else:
            box = self.add_float(p.key, p.label, low, high, p.decimals, suffix, p.step, tip)
            if p.zero:
                live(box.setSpecialValueText, _shown(p.zero))
        return box

    def set_units(self, units: dict[str, str]) -> None:
        """Each number field of ``units``' keys shows its unit, as a declared unit is shown
        (a unit another setting gives: :meth:`models.workbench.Workbench.setting_units`);
        keys with no such field are passed over."""
        for key, unit in units.items():
            box = self._fields.get(key)
            if isinstance(box, (QSpinBox, QDoubleSpinBox)) and box.suffix() != _suffix(unit):
                box.setSuffix(_suffix(unit))

    def _retranslate_choices(self) -> None:
        for box, texts in self._choices:
            for index, text in enumerate(texts):
                box.setItemText(index, declared(text.source) if text.is_declared
                                else tr(text.source))

    def _add(self, key: str, label: str, widget, tooltip: str):
        widget.setObjectName(key)
        if isinstance(widget, (QComboBox, QSpinBox, QDoubleSpinBox)):
            ignore_unfocused_wheel(widget)
        if tooltip:
            live(widget.setToolTip, _shown(tooltip))
        caption = QLabel()
        live(caption.setText, _shown(label))
        caption.setBuddy(widget)
        if tooltip:
            live(caption.setToolTip, _shown(tooltip))
        if caption.sizeHint().width() > LONG_CAPTION or isinstance(widget, QLineEdit):
            # a long caption (and a free text, as long as the list typed into it) above
            # its field; the field the form's whole width
            caption.setWordWrap(True)
            self._form.addRow(caption)
            self._form.addRow(widget)
            self._fields[key] = widget
            return widget
        self._form.addRow(caption, widget)
        # a form whose widest label and widest field together are wider than WRAP_WIDTH
        # puts fields below their labels when the pane is narrow: with the capture panel
        # docked beside it the window stays within a 1280 px screen (#41: the
        # cross-calibration set-up made it 1484 px)
        self._widest = (max(self._widest[0], caption.sizeHint().width()),
                        max(self._widest[1], widget.minimumSizeHint().width()))
        if sum(self._widest) > WRAP_WIDTH:
            self._form.setRowWrapPolicy(QFormLayout.RowWrapPolicy.WrapLongRows)
        self._fields[key] = widget
        return widget

    def field(self, key: str) -> QWidget:
        return self._fields[key]

    def mark(self, key: str) -> None:
        """Mark the field of ``key`` as the one the readings refuse (its value as typed,
        nothing else touched), every other field unmarked; "" unmarks them all."""
        for name, widget in self._fields.items():
            marked = name == key
            if bool(widget.property("refused")) != marked:
                widget.setProperty("refused", marked)
                widget.setStyleSheet(REFUSED_STYLE if marked else "")

    def marked(self) -> str:
        """The key of the field marked (:meth:`mark`), "" when none is."""
        return next((k for k, w in self._fields.items() if w.property("refused")), "")

    def values(self) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for key, widget in self._fields.items():
            if isinstance(widget, QComboBox):
                out[key] = widget.currentData()
            elif isinstance(widget, (QSpinBox, QDoubleSpinBox)):
                out[key] = widget.value()
            elif isinstance(widget, QLineEdit):
                out[key] = widget.text()
        return out

    def set_values(self, values: dict[str, Any]) -> None:
        """Show ``values`` without emitting ``changed``."""
        self.blockSignals(True)
        try:
            for key, value in values.items():
                widget = self._fields.get(key)
                if isinstance(widget, QComboBox):
                    index = widget.findData(value)
                    if index >= 0:
                        widget.setCurrentIndex(index)
                elif isinstance(widget, QSpinBox):
                    widget.setValue(int(value))
                elif isinstance(widget, QDoubleSpinBox):
                    widget.setValue(float(value))
                elif isinstance(widget, QLineEdit):
                    widget.setText(str(value))
        finally:
            self.blockSignals(False)
