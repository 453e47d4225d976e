"""A plot's right-click menu built when it is first opened.

pyqtgraph builds every ViewBox's menu (two axis forms, their widget groups, ~40 widgets)
when the plot is made: a main window's 31 plots spent ~0.1 s of its ~0.6 s on menus that
a user opens on a plot or two, if at all, and each window of the test suite paid it again.
:class:`LazyMenuViewBox` builds its menu on the first right-click (or the first caller of
:meth:`~LazyMenuViewBox.getMenu`), then runs what was to be done to it
(:meth:`~LazyMenuViewBox.when_menu_made`: the window's image actions and its language);
the user sees the same menu.
"""

from __future__ import annotations

from collections.abc import Callable

import pyqtgraph as pg
from pyqtgraph.graphicsItems.ViewBox.ViewBoxMenu import ViewBoxMenu

__all__ = ["LazyMenuViewBox", "on_plot_menu"]


class LazyMenuViewBox(pg.ViewBox):
    """pyqtgraph's ViewBox, its menu (``menu``) None until first asked for."""

    menu: ViewBoxMenu | None

    def __init__(self, *args, enableMenu: bool = True, **kwargs) -> None:  # noqa: N803 (pyqtgraph's)
        super().__init__(*args, enableMenu=False, **kwargs)
        self.state["enableMenu"] = enableMenu
        self._menu_made: list[Callable[[ViewBoxMenu], None]] = []

    def when_menu_made(self, made: Callable[[ViewBoxMenu], None]) -> None:
        """``made(menu)`` on the menu when it is built (at once if it is already)."""
        self._menu_made.append(made)
        if self.menu is not None:
            made(self.menu)

    def getMenu(self, ev=None) -> ViewBoxMenu | None:  # noqa: N802 (pyqtgraph's)
        """The menu, built now if this is the first time and the menu is enabled."""
        if self.menu is None and self.menuEnabled():
            self.menu = ViewBoxMenu(self)
            self.updateViewLists()
            for made in self._menu_made:
                made(self.menu)
        return self.menu

    def getContextMenus(self, event) -> list:  # noqa: N802 (pyqtgraph's)
        menu = self.getMenu(event)
        return menu.actions() if menu is not None else []

    def setMenuEnabled(self, enableMenu: bool = True) -> None:  # noqa: N802, N803 (pyqtgraph's)
        """As pyqtgraph's, the menu built only when asked for."""
        self.state["enableMenu"] = enableMenu
        if not enableMenu and self.menu is not None:
            self.menu.setParent(None)
            self.menu = None
        self.sigStateChanged.emit(self)


def on_plot_menu(vb: pg.ViewBox, made: Callable[[ViewBoxMenu], None]) -> bool:
    """``made(menu)`` on ``vb``'s right-click menu: when it is built for a
    :class:`LazyMenuViewBox`, at once for another ViewBox with a menu. False when ``vb``
    has no menu to come."""
    if isinstance(vb, LazyMenuViewBox):
        if not vb.menuEnabled():
            return False
        vb.when_menu_made(made)
        return True
    if getattr(vb, "menu", None) is None:
        return False
    made(vb.menu)
    return True
