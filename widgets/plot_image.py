"""Right-click on any plot: "Copy image" and "Save image…", named after the plot's tab
(pyqtgraph's own export dialog lists its items as "Plot", "Plot", "Plot")."""

from __future__ import annotations

import re

import pyqtgraph as pg
from PySide6.QtWidgets import QApplication, QFileDialog, QWidget

from widgets.i18n import live, tr

__all__ = ["add_image_actions", "copy_image", "image_file_name", "plot_panels"]


def plot_panels(widget: QWidget) -> int:
    """How many plot panels (view boxes with axes) a widget holds."""
    return sum(1 for view in widget.findChildren(pg.GraphicsView) for item in view.scene().items()
               if isinstance(item, pg.PlotItem))


def image_file_name(title: str) -> str:
    return (re.sub(r"[^\w\-]+", "-", title, flags=re.UNICODE).strip("-").lower() or "plot") \
        + ".png"


def copy_image(widget: QWidget) -> None:
    QApplication.clipboard().setImage(widget.grab().toImage())


def _save_image(widget: QWidget, title: str) -> None:
    path, _ = QFileDialog.getSaveFileName(widget, tr("Save image"), image_file_name(title),
                                          tr("PNG image (*.png)"))
    if path:
        if not path.lower().endswith(".png"):
            path += ".png"
        widget.grab().save(path)


def add_image_actions(widget: QWidget, title: str) -> int:
    """Add the two actions to the right-click menu of every plot inside ``widget``; the
    image is the whole widget (all its panels). Returns how many menus got them."""
    count = 0
    for view in widget.findChildren(pg.GraphicsView):
        for item in view.scene().items():
            if isinstance(item, pg.ViewBox) and getattr(item, "menu", None) is not None:
                item.menu.addSeparator()
                copy = item.menu.addAction(tr("Copy image"))
                live(copy.setText, tr("Copy image"))
                copy.triggered.connect(lambda _=False, w=widget: copy_image(w))
                save = item.menu.addAction(tr("Save image…"))
                live(save.setText, tr("Save image…"))
                save.triggered.connect(lambda _=False, w=widget, t=title: _save_image(w, t))
                count += 1
    return count
