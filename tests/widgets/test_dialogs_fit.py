"""Every dialog of the window fits the screen (#31): a 1280×720 laptop, 200 % scale on
a 2560×1600 screen (1280×800 logical) and 200 % on the 1280×720 laptop (640×360 logical,
fit74). Each screen is an offscreen screen of that size in a process of its own
(tests/dialog_fit_probe.py opens every dialog as the user does); a dialog whose frame
leaves the screen's free area, whose least size is larger than it, or whose OK, Cancel or
Open is not all on it fails here, named, with its size. Before #31 the certificate dialog
was 868 px tall (Export… and Cancel off a 720 px screen), the register 724 and the manual
764.

The register's test reads the probe's runs of the 640×360 screen in English and in Chinese,
which the test of every dialog makes: each screen is probed once a run, in one process for
all the languages asked of it (``probed``: a probe process is ~3.5 s of CPU, ~1.5 s of it
starting; a window in each language after another, the Chinese one's records were the same
as those of a process of its own, compared 2026-12-07)."""

from __future__ import annotations

import pytest

from tests.screen_process import screen_probed

pytestmark = pytest.mark.slow  # every test here takes more than 0.4 s (a window, a certificate, a program)

SCREENS = {  # name: (width, height, QT_SCALE_FACTOR, the window's language)
    "1280x720": (1280, 720, "1", "en"),
    "200% on 2560x1600": (2560, 1600, "2", "zh_CN"),
    # fit74: 640×360 logical; before, the column mapping dialog was 403 px tall, the quick
    # guide 380, "what changed" 705 wide, the open-project and import file dialogs 634×410
    "200% on 1280x720": (1280, 720, "2", "en"),
    "200% on 1280x720, Chinese": (1280, 720, "2", "zh_CN"),
}


@pytest.fixture(scope="module")
def probed(tmp_path_factory):
    """``probed(width, height, scale, language)``: what tests/dialog_fit_probe.py found on that
    screen in that language, each screen probed once a run in every language asked of it
    (tests.screen_process.screen_probed: the workers and tests/widgets/test_small_screens.py
    share it); the tests only read it."""

    def found(width: int, height: int, scale: str, language: str) -> dict:
        return screen_probed(tmp_path_factory, width, height, scale)[language]["dialogs"]

    return found


@pytest.mark.parametrize("screen", SCREENS)
def test_every_dialog_fits_the_screen(screen, probed):
    width, height, scale, language = SCREENS[screen]
    found = probed(width, height, scale, language)
    expected = {"main window", "certificate details", "certificate details (Export certificate…)",
                "which column is which", "certificate register",
                "acknowledge a loss", "clock correction", "manual", "quick guide", "about",
                "a message (tell)", "a question (ask)", "paste question", "draft question",
                "what changed", "print", "open project", "import readings",
                "verify a certificate PDF", "save project", "export results",
                "polygon certificate"}
    assert set(found) == expected  # every dialog was opened (and answered)
    too_big = []
    for name, seen in found.items():
        x, y, w, h = seen["frame"]
        ax, ay, aw, ah = seen["available"]
        assert (aw, ah) == (width // int(scale), height // int(scale))
        if w > aw or h > ah or x < ax or y < ay or x + w > ax + aw or y + h > ay + ah:
            too_big.append(f"{name}: {w}×{h} at ({x}, {y}) on {aw}×{ah}")
        least_w, least_h = seen["minimum"]
        if least_w > aw or least_h > ah:  # the user could not make it fit either
            too_big.append(f"{name}: at least {least_w}×{least_h} on {aw}×{ah}")
        # the answers (OK, Cancel, Open…) do not scroll: each whole, in the window, on the screen
        too_big += [f"{name}: its button {text!r}" for text, whole in seen["buttons"] if not whole]
    assert not too_big, "off the screen: " + "; ".join(too_big)


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_the_register_window_fits_200_percent_on_a_1280x720_laptop(language, probed):
    """day74 #11: at QT_SCALE_FACTOR=2 on 1280×720 (640×360 logical) the register window was
    652 px wide, its row of seven buttons and its interval row wider than the screen (the
    right edges of Use, History and Set interval off it); its buttons now wrap. (Every
    dialog of that screen is checked by test_every_dialog_fits_the_screen since fit74.)"""
    found = probed(1280, 720, "2", language)
    for name in ("certificate register", "acknowledge a loss", "clock correction"):
        x, y, w, h = found[name]["frame"]
        ax, ay, aw, ah = found[name]["available"]
        assert (aw, ah) == (640, 360)
        assert ax <= x and ay <= y and x + w <= ax + aw and y + h <= ay + ah, (name, w, h)
        assert found[name]["minimum"][0] <= aw, (name, found[name]["minimum"])
