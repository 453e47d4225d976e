"""The Live signals window as a technician opens it (Instrument › Live signals… from the
shown main window), for the qtbot tests of this folder."""

from __future__ import annotations

__all__ = ["open_live_signals"]


def open_live_signals(window, qtbot):
    """Show ``window``, open Live signals from its menu and wait until it is exposed; returns
    the fringe workbench's Live signals panel."""
    window.show()
    window.menus.live_signals_action.trigger()
    fringe = window.presenters[window.tabs.currentIndex()]
    panel = fringe.view.live_signals
    qtbot.waitExposed(panel)
    return panel
