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


def test_the_guidance_is_said_in_the_language_chosen_with_nothing_connected(window):
    """View › Language with no instrument connected: the panel's guidance follows (day
    review live76 F4: it stayed English in the Chinese window, Chinese in the English one,
    as it was worked out again only while frames came in)."""
    import re

    from tests.app.capture.window_steps import show_workbench

    presenter = show_workbench(window, "positioning")
    presenter.table_model.replace_all([], "empty")
    presenter.set_settings({**presenter.settings, "plan_runs": 2, "plan_targets": "0:15:3",
                            "plan_directions": "both", "plan_order": "linear",
                            "target_unit": "deg", "deviation_unit": "arcsec"})
    panel = window.capture_panel
    assert not any(link.worker for link in panel.links)
    panel.update_guide()
    english = panel.guide.text()
    assert english == "Next: target 0°, run 1 ↑", english
    try:
        choose_language(window, "zh_CN")
        chinese = panel.guide.text()
        assert re.search(r"[\u4e00-\u9fff]", chinese) and "Next" not in chinese, chinese
        assert "0°" in chinese, chinese
    finally:
        choose_language(window, "en")
    assert panel.guide.text() == english
