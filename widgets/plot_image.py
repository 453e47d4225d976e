"""Right-click on any plot: "Copy image" and "Save image…", named after the plot's tab
(pyqtgraph's own export dialog lists its items as "Plot", "Plot", "Plot"). The image is
written atomically, through the write its owner gives (a workbench's: the checks every
other output goes through, a file the register issued never replaced)."""

from __future__ import annotations

import functools
import re
from collections.abc import Callable

import pyqtgraph as pg
from pyqtgraph.graphicsItems.ViewBox.ViewBoxMenu import ViewBoxMenu
from PySide6.QtCore import QBuffer, QIODevice
from PySide6.QtWidgets import QApplication, QMessageBox, QWidget

from models.project.atomic_write import write_bytes_atomic
from widgets.i18n import explained, live, tr
from widgets.lazy_menu_view_box import on_plot_menu
from widgets.save_file import ask_save_file

__all__ = ["ImageWrite", "add_image_actions", "copy_image", "image_file_name",
           "localise_plot_menu", "localise_plot_menus", "plot_panels", "png_bytes", "write_png"]

#: writes a plot's image: ``(path, PNG bytes)``
ImageWrite = Callable[[str, bytes], object]


def plot_panels(widget: QWidget) -> int:
    """How many plot panels (view boxes with axes) a widget holds."""
    return sum(1 for view in _graphics_views(widget) for item in view.scene().items()
               if isinstance(item, pg.PlotItem))


def image_file_name(title: str) -> str:
    return (re.sub(r"[^\w\-]+", "-", title, flags=re.UNICODE).strip("-").lower() or "plot") \
        + ".png"


def copy_image(widget: QWidget) -> None:
    QApplication.clipboard().setImage(widget.grab().toImage())


def png_bytes(widget: QWidget) -> bytes:
    """The widget as it is drawn, a PNG image."""
    buffer = QBuffer()
    buffer.open(QIODevice.OpenModeFlag.WriteOnly)
    widget.grab().save(buffer, "PNG")
    return bytes(buffer.data().data())


def _save_image(widget: QWidget, title: str, write: ImageWrite | None = None) -> None:
    """The file dialog, then the image written by ``write(path, data)`` (a workbench's: it
    checks the name as every export does and writes atomically); without one, written
    atomically (rev64: it was written in place, through a ``.png`` link to an issued PDF)."""
    path = ask_save_file(widget, tr("Save image"), image_file_name(title),
                         tr("PNG image (*.png)"))
    if not path:
        return
    data = png_bytes(widget)
    if write is not None:
        write(path, data)
    else:
        write_png(widget, path, data)


def write_png(parent: QWidget, path: str, data: bytes) -> bool:
    """``data`` written to ``path`` atomically (readers see the old file or the new one);
    a failure told in a message box of ``parent``'s. False when nothing was written."""
    try:
        write_bytes_atomic(path, data)
    except OSError as exc:
        QMessageBox.warning(parent, tr("Cannot save the image"), explained(exc))
        return False
    return True


def _graphics_views(widget: QWidget) -> list[pg.GraphicsView]:
    """The plot views inside ``widget``, and ``widget`` itself when it is one."""
    return ([widget] if isinstance(widget, pg.GraphicsView) else []) + \
        widget.findChildren(pg.GraphicsView)


def localise_plot_menu(vb: pg.ViewBox, menu: ViewBoxMenu | None = None) -> None:
    """pyqtgraph's right-click menu (``menu``: ``vb``'s) in the window's language: "View All"
    and the axis submenus translated; its English-only "Mouse Mode", "Plot Options" and
    "Export…" (a dialog of its own, in English) left out: Copy image / Save image… do the
    export."""
    menu = vb.menu if menu is None else menu
    live(menu.viewAll.setText, tr("View All"))
    live(menu.setTitle, tr("Plot"))
    submenus = [a.menu() for a in menu.actions() if a.menu() is not None]
    for sub in submenus:
        if sub.actions() and sub.actions()[0] in menu.mouseModes:  # "Mouse Mode"
            menu.removeAction(sub.menuAction())
    axis_menus = [m for m in submenus if m.actions() and m.actions()[0] not in menu.mouseModes]
    for sub, title in zip(axis_menus, (tr("X axis"), tr("Y axis")), strict=False):
        live(sub.setTitle, title)
    for ui in menu.ctrl:
        for widget, text in ((ui.autoRadio, tr("Auto")), (ui.manualRadio, tr("Manual")),
                             (ui.invertCheck, tr("Invert axis")),
                             (ui.mouseCheck, tr("Mouse enabled")),
                             (ui.visibleOnlyCheck, tr("Visible data only")),
                             (ui.autoPanCheck, tr("Auto pan only")),
                             (ui.label, tr("Link axis:"))):
            live(widget.setText, text)
        for widget in (ui.autoRadio, ui.manualRadio, ui.invertCheck, ui.mouseCheck,
                       ui.visibleOnlyCheck, ui.autoPanCheck, ui.linkCombo, ui.autoPercentSpin,
                       ui.minText, ui.maxText):
            widget.setToolTip("")  # pyqtgraph's English help texts
    parent = vb.parentItem()
    while parent is not None and not isinstance(parent, pg.PlotItem):
        parent = parent.parentItem()
    if parent is not None:
        parent.setMenuEnabled(False, None)  # "Plot Options"; the view's own menu stays
    if vb.scene() is not None:
        vb.scene().contextMenu = []  # "Export…"
        # pyqtgraph's menu is a window of its own (no parent), held by the ViewBox, whose
        # reference cycle outlives the plot: every closed window's menus (29 in a main window,
        # ~580 texts) stayed alive, each change of language set their texts again, until the
        # cyclic collector ran. Deleted with the plot that shows them.
        for view in vb.scene().views():
            view.destroyed.connect(menu.deleteLater)


def localise_plot_menus(widget: QWidget) -> int:
    """``localise_plot_menu`` for every plot inside ``widget`` (a
    :class:`~widgets.lazy_menu_view_box.LazyMenuViewBox`'s when its menu is built); returns
    how many."""
    count = 0
    for view in _graphics_views(widget):
        for item in view.scene().items():
            if isinstance(item, pg.ViewBox) and on_plot_menu(
                    item, functools.partial(localise_plot_menu, item)):
                count += 1
    return count


def add_image_actions(widget: QWidget, title: str, write: ImageWrite | None = None) -> int:
    """Add the two actions to the right-click menu of every plot inside ``widget`` (a
    :class:`~widgets.lazy_menu_view_box.LazyMenuViewBox`'s when its menu is built); the
    image is the whole widget (all its panels), saved through ``write`` (see
    :func:`_save_image`). Returns how many menus get them."""

    def add(vb: pg.ViewBox, menu: ViewBoxMenu) -> None:
        menu.addSeparator()
        copy = menu.addAction(tr("Copy image"))
        live(copy.setText, tr("Copy image"))
        copy.triggered.connect(lambda _=False, w=widget: copy_image(w))
        save = menu.addAction(tr("Save image…"))
        live(save.setText, tr("Save image…"))
        save.triggered.connect(lambda _=False, w=widget, t=title: _save_image(w, t, write))
        localise_plot_menu(vb, menu)

    count = 0
    for view in _graphics_views(widget):  # the fringe's plots are tabs of their own
        for item in view.scene().items():
            if isinstance(item, pg.ViewBox) and on_plot_menu(item, functools.partial(add, item)):
                count += 1
    return count
