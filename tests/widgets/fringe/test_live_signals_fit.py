"""The Live signals window on a 1280×720 laptop at 150 % (853×480 logical pixels), in
English and in Chinese: the window can be made as small as the screen and Take is on it.

Before, the window's settings, Reset min/max and Take were one row: the window was at
least 1039 px wide, Take drawn at x = 955, off the 853 px screen, and no take possible
(day 65, F5). Now the settings are two rows, Reset and Take a row of their own below the
bars and plots, which scroll when the screen has less room than they want."""

from __future__ import annotations

import pytest

from tests.screen_process import run_on_screen

pytestmark = pytest.mark.slow  # a program of its own per screen


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_the_live_signals_window_and_its_take_button_fit_a_small_screen(language, tmp_path):
    found = run_on_screen("tests.live_signals_fit_probe", tmp_path, 1280, 720, "1.5", language)
    ax, ay, aw, ah = found["available"]
    assert (aw, ah) == (853, 480)
    least_w, least_h = found["minimum"]
    assert least_w <= aw and least_h <= ah, found
    x, y, w, h = found["frame"]
    assert ax <= x and ay <= y and x + w <= ax + aw and y + h <= ay + ah, found
    tx, ty, tw, th = found["take"]
    assert x <= tx and tx + tw <= x + w and y <= ty and ty + th <= y + h, found
    assert found["take_shown"] == [tw, th]  # not clipped by a scroll area either
    assert found["rows"] > 1000  # the click took the demonstration head's window
