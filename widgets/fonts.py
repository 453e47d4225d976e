"""Fonts of the window: the bundled CJK font is registered with Qt when the system has no
font for Simplified Chinese, so Chinese readings, headers and names never show as boxes."""

from __future__ import annotations

import functools
from importlib import resources

from PySide6.QtGui import QFontDatabase

__all__ = ["ensure_cjk_font"]


@functools.cache
def ensure_cjk_font() -> str:
    """The family that draws Chinese: the system's, else the bundled one (registered now);
    "" when neither is available."""
    chinese = QFontDatabase.WritingSystem.SimplifiedChinese
    system = QFontDatabase.families(chinese)
    if system:
        return system[0]
    path = resources.files("resources") / "fonts" / "DroidSansFallbackFull.ttf"
    font_id = QFontDatabase.addApplicationFont(str(path))
    families = QFontDatabase.applicationFontFamilies(font_id) if font_id >= 0 else []
    return families[0] if families else ""
