"""Opens the window on the screen Qt was started with, docks the capture panel (right, left,
bottom) on every workbench, and prints, as JSON, every set-up field whose text does not fit
in the field (tests/widgets/test_settings_fields_fit.py reads :func:`fields_at`'s records,
made in tests/capture_panel_probe.py's process on a 1280×720 screen at each of its steps)."""

from __future__ import annotations

import json

from PySide6.QtWidgets import (
    QAbstractSpinBox,
    QComboBox,
    QLineEdit,
    QStyle,
    QStyleOptionComboBox,
)

from tests.capture_panel_probe import each_docked_tab


def room(field) -> tuple[str, int, int]:
    """The text a field shows, its width and the width it has for it (px)."""
    if isinstance(field, QComboBox):
        option = QStyleOptionComboBox()
        field.initStyleOption(option)
        rect = field.style().subControlRect(QStyle.ComplexControl.CC_ComboBox, option,
                                            QStyle.SubControl.SC_ComboBoxEditField, field)
        text = field.currentText()
        return text, field.fontMetrics().horizontalAdvance(text), rect.width()
    edit = field.lineEdit() if isinstance(field, QAbstractSpinBox) else field
    assert isinstance(edit, QLineEdit)
    text = edit.text()
    # a line edit keeps 2 px of margin each side of its text (QLineEditPrivate::horizontalMargin)
    return text, edit.fontMetrics().horizontalAdvance(text), edit.contentsRect().width() - 4


def fields_at(window, area_name: str, presenter) -> list[dict]:
    """Every set-up field of ``presenter``'s tab in sight, its text, the width it needs and
    the width it has (px), the capture panel docked at ``area_name``."""
    found = []
    form = presenter.view.settings
    for key, field in form._fields.items():
        if not field.isVisibleTo(form):
            continue
        text, needs, has = room(field)
        found.append({"area": area_name, "workbench": presenter.kind.key,
                      "key": key, "text": text, "needs": needs, "has": has,
                      "window": window.frameGeometry().width()})
    return found


def main() -> None:
    """The probe on its own (tests/capture_panel_probe.py makes these records in its own
    process, at each of its steps)."""
    found = []
    for _app, window, _panel, area_name, presenter in each_docked_tab("anglebench-fields-"):
        found += fields_at(window, area_name, presenter)
    print(json.dumps(found))  # noqa: T201 - the probe's output


if __name__ == "__main__":
    main()
