"""#41: scrolling the positioning set-up turned *misalignment u* and *reference resolution*
from "not stated" into 0.3000 and 0.2000, with no undo. The wheel now changes a field only
when it has focus (else it scrolls the set-up), and a setting changed is one Edit › Undo
step."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, QPointF, Qt
from PySide6.QtGui import QWheelEvent
from PySide6.QtWidgets import QApplication

pytestmark = pytest.mark.slow  # a window


def _wheel(widget, steps: int = 3) -> None:
    centre = QPointF(widget.rect().center())
    for _ in range(steps):
        event = QWheelEvent(centre, QPointF(widget.mapToGlobal(centre.toPoint())), QPoint(0, 0),
                            QPoint(0, 120), Qt.MouseButton.NoButton,
                            Qt.KeyboardModifier.NoModifier, Qt.ScrollPhase.NoScrollPhase, False)
        QApplication.sendEvent(widget, event)


def _positioning(window):
    presenter = window.presenter("positioning")
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    window.show()
    return presenter


def test_the_wheel_over_a_field_without_focus_changes_nothing(window, qtbot):
    presenter = _positioning(window)
    field = presenter.view.settings.field("misalignment_u")
    assert field.value() == 0.0 and field.text() == "not stated"
    steps = presenter.undo_stack.count()
    window.tabs.setFocus()
    assert not field.hasFocus()
    _wheel(field)
    assert field.value() == 0.0 and presenter.settings["misalignment_u"] == 0.0
    assert presenter.undo_stack.count() == steps
    # with focus (clicked or tabbed into) the wheel does change it, as one would expect
    field.setFocus()
    qtbot.waitUntil(field.hasFocus, timeout=2000)
    _wheel(field, 1)
    assert field.value() > 0.0
    assert presenter.settings["misalignment_u"] == field.value()


def test_a_setting_changed_is_undone_and_redone(window, qtbot):
    presenter = _positioning(window)
    field = presenter.view.settings.field("misalignment_u")
    before = presenter.settings
    steps = presenter.undo_stack.count()
    field.setValue(0.3)  # typed, Return
    assert presenter.settings["misalignment_u"] == pytest.approx(0.3)
    assert presenter.undo_stack.count() == steps + 1
    assert "misalignment u" in presenter.undo_stack.undoText()
    window.menus.undo_action.trigger()  # Edit › Undo
    assert presenter.settings == before
    assert field.value() == 0.0 and field.text() == "not stated"
    qtbot.waitUntil(lambda: not presenter._timer.isActive(), timeout=2000)
    window.menus.redo_action.trigger()
    assert presenter.settings["misalignment_u"] == pytest.approx(0.3)
    assert field.value() == pytest.approx(0.3)
    # the same value again is no step
    field.setValue(0.3)
    assert presenter.undo_stack.count() == steps + 1
