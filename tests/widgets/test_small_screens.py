"""The window and the certificate dialog on a technician's screen: a 1280×720 laptop,
and the same screen at 200 % (640×360 logical pixels), in English and in Chinese. Each
screen is an offscreen screen of that size in a process of its own (tests/small_screen_probe.py
measures the window on every workbench and the dialog with the screenshot's details, in the
process tests/widgets/test_dialogs_fit.py's dialogs are opened in: one a screen, once a run,
tests.screen_process.screen_probed; three processes of ~2.7 s of CPU each before).

Before, the window could not be narrower than 780 px (the positioning workbench's 892:
the readings pane held every column and the set-up's widest field, the figures' table
250 px), off a 640 px screen; the dialog's groups, two a row, were 1198 px wide: at 640 px
(and in the 1100 px screenshot) the Laboratory column was behind a horizontal scroll bar,
and three of the DCC fields' hints were cut ("…TRUSTED_CERTIFICATE, else the…")."""

from __future__ import annotations

import pytest

from tests.screen_process import screen_probed

pytestmark = pytest.mark.slow  # a program of its own per screen (shared with the dialogs' test)

SCREENS = {  # name: (width, height, QT_SCALE_FACTOR, the window's language)
    "1280x720": (1280, 720, "1", "en"),
    "200% on 1280x720": (1280, 720, "2", "en"),
    "200% on 1280x720, Chinese": (1280, 720, "2", "zh_CN"),
}


@pytest.mark.parametrize("screen", SCREENS)
def test_the_window_and_the_certificate_dialog_fit_the_screen(screen, tmp_path_factory):
    width, height, scale, language = SCREENS[screen]
    found = screen_probed(tmp_path_factory, width, height, scale)[language][
        "window and certificate dialog"]
    # five workbenches, alone and with the instrument panel open, and the dialog
    assert len(found) == 11
    too_big = []
    for name, seen in found.items():
        x, y, w, h = seen["frame"]
        ax, ay, aw, ah = seen["available"]
        assert (aw, ah) == (width // int(scale), height // int(scale))
        least_w, least_h = seen["minimum"]
        if least_w > aw or least_h > ah:  # it could not be made small enough
            too_big.append(f"{name}: at least {least_w}×{least_h} on {aw}×{ah}")
        if w > aw or h > ah or x < ax or y < ay or x + w > ax + aw or y + h > ay + ah:
            too_big.append(f"{name}: {w}×{h} at ({x}, {y}) on {aw}×{ah}")
    assert not too_big, "; ".join(too_big)
    dialog = found["certificate details"]
    assert dialog["sideways"] == 0  # every group in sight without scrolling sideways
    assert dialog["cut"] == []
