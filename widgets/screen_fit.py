"""Windows that fit the screen they open on: a window asks for the size it would like and
gets at most what the screen has free (a 1280×720 laptop, 200 % scale on 2560×1600),
with room left for the window's title bar and the desktop's panels."""

from __future__ import annotations

from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QWidget

__all__ = ["available_size", "fit_to_screen"]

#: the share of the screen's free height a window may take: its title bar (drawn by the
#: window manager, outside the geometry Qt sets) must stay on the screen too
HEIGHT_SHARE = 0.92
WIDTH_SHARE = 0.98


def available_size(widget: QWidget) -> tuple[int, int]:
    """The free width and height of the screen ``widget`` is (or will be) on."""
    screen = widget.screen() or QGuiApplication.primaryScreen()
    free = screen.availableGeometry()
    return int(free.width() * WIDTH_SHARE), int(free.height() * HEIGHT_SHARE)


def fit_to_screen(widget: QWidget, width: int, height: int) -> None:
    """Resize ``widget`` to ``width`` × ``height``, or less where its screen has less."""
    free_width, free_height = available_size(widget)
    widget.resize(min(width, free_width), min(height, free_height))
