"""Steps the capture tests take in the main window, written once."""

from __future__ import annotations


def show_workbench(window, key):
    """Bring workbench ``key``'s tab to the front, as a click on its tab does; its presenter."""
    window.tabs.setCurrentIndex(window.presenters.index(window.presenter(key)))
    return window.presenter(key)
