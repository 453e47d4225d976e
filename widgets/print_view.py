"""Printing: a workbench for the lab notebook (its verdict, warnings, the result text and
the plot on screen, scaled to the page), and an issued certificate, its PDF's pages as
they are (rendered by PDFium, which PySide6-Essentials lacks a Qt module for)."""

from __future__ import annotations

from PySide6.QtCore import QMarginsF, QRectF, Qt
from PySide6.QtGui import QFont, QImage, QPageLayout, QPainter, QTextDocument

__all__ = ["pdf_page_images", "print_pdf", "print_workbench"]

MAX_PRINT_DPI = 300  # a certificate's text and plots are sharp at 300 dpi; more only costs memory


def pdf_page_images(pdf: bytes, dpi: float):
    """Each page of ``pdf`` as a QImage at ``dpi`` (one at a time: a long certificate is
    never held whole as pixels)."""
    import pypdfium2  # imported here: only printing a certificate needs it

    document = pypdfium2.PdfDocument(pdf)
    try:
        for index in range(len(document)):
            page = document[index]
            bitmap = page.render(scale=dpi / 72.0, rev_byteorder=True)
            pixels = bitmap.to_numpy()
            height, width = pixels.shape[:2]
            fmt = (QImage.Format.Format_RGBA8888 if pixels.shape[2] == 4
                   else QImage.Format.Format_RGB888)
            yield QImage(pixels.tobytes(), width, height, pixels.strides[0], fmt).copy()
            bitmap.close()
            page.close()
    finally:
        document.close()


def print_pdf(pdf: bytes, printer) -> int:
    """Print every page of ``pdf`` full size (its own margins kept); returns the pages."""
    printer.setFullPage(True)
    dpi = min(printer.resolution(), MAX_PRINT_DPI)
    painter = QPainter()
    pages = 0
    try:
        for image in pdf_page_images(pdf, dpi):
            if pages == 0:
                if not painter.begin(printer):
                    raise OSError("the printer cannot be opened")
            elif not printer.newPage():
                raise OSError("the printer refused a new page")
            room = QRectF(printer.pageLayout().fullRectPixels(printer.resolution()))
            size = image.size().scaled(int(room.width()), int(room.height()),
                                       Qt.AspectRatioMode.KeepAspectRatio)
            painter.drawImage(QRectF(0, 0, size.width(), size.height()), image,
                              QRectF(image.rect()))
            pages += 1
    finally:
        if painter.isActive():
            painter.end()
    return pages


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
        from widgets.plot_range import show_data_if_hidden

        show_data_if_hidden(plot)  # a printout never shows an empty frame
        image = plot.grab()
        room = QRectF(0, top, width, max(page.height() - top, 10))
        target = image.size().scaled(int(room.width()), int(room.height()),
                                     Qt.AspectRatioMode.KeepAspectRatio)
        painter.drawPixmap(QRectF(0, top, target.width(), target.height()), image,
                           QRectF(image.rect()))
    finally:
        painter.end()
