"""Printing a workbench for the lab notebook: its verdict, warnings, the result text and the
plot on screen, scaled to the page (the certificate itself is the PDF)."""

from __future__ import annotations

from PySide6.QtCore import QMarginsF, QRectF, Qt
from PySide6.QtGui import QFont, QPageLayout, QPainter, QTextDocument

__all__ = ["print_workbench"]


def print_workbench(view, printer, title: str) -> None:
    """Paint ``view``'s result and its current plot onto ``printer`` (one page)."""
    printer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout.Unit.Millimeter)
    painter = QPainter(printer)
    try:
        page = printer.pageLayout().paintRectPixels(printer.resolution())
        width = page.width()
        text = QTextDocument()
        text.setDefaultFont(QFont("DejaVu Sans", 9))
        warnings = view.warnings.text() if view.warnings.isVisible() else ""
        text.setPlainText("\n\n".join(p for p in (title, view.verdict.text(), warnings,
                                                  view.summary.toPlainText()) if p))
        text.setTextWidth(width)
        painter.save()
        scale = printer.resolution() / 96.0
        text.setTextWidth(width / scale)
        painter.scale(scale, scale)
        text.drawContents(painter)
        painter.restore()
        top = text.size().height() * scale + 20
        plot = view.plot_widget(view.plot_tabs.currentIndex())
        image = plot.grab()
        room = QRectF(0, top, width, max(page.height() - top, 10))
        target = image.size().scaled(int(room.width()), int(room.height()),
                                     Qt.AspectRatioMode.KeepAspectRatio)
        painter.drawPixmap(QRectF(0, top, target.width(), target.height()), image,
                           QRectF(image.rect()))
    finally:
        painter.end()
