"""The take button's key (F9, a foot switch) after a change of language: Qt's setText puts the
new text's mnemonic (none) in place of the button's shortcut, so after View › Language F9
took nothing and said nothing, in the new language and back in the old (day review 64)."""

from __future__ import annotations

import pytest
from PySide6.QtGui import QKeySequence

from app.capture.panel import TAKE_READING_KEY


def choose_language(window, key: str) -> None:
    """View › Language › ``key``, as the user picks it."""
    next(a for a in window.menus.language_actions.actions() if a.data() == key).trigger()


@pytest.mark.parametrize("path", [("zh_CN",), ("zh_CN", "en")])
def test_f9_takes_after_a_change_of_language(window, path):
    button = window.capture_panel.take_button
    assert button.shortcut() == QKeySequence(TAKE_READING_KEY)
    try:
        for key in path:
            choose_language(window, key)
            assert button.shortcut() == QKeySequence(TAKE_READING_KEY), (key, button.text())
    finally:
        choose_language(window, "en")
    assert "F9" in button.text()
