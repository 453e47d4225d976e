"""A printed PDF's text as the certificate tests read it: every page's, whitespace runs as one
space, a unit wrapped onto the next line joined to its figure (1.2 ″ → 1.2″)."""

from __future__ import annotations

import re

import pypdfium2 as pdfium

__all__ = ["pdf_text"]


def pdf_text(pdf: bytes) -> str:
    """The text of the PDF ``pdf`` (its bytes), pages joined."""
    document = pdfium.PdfDocument(pdf)
    try:
        text = re.sub(r"\s+", " ", " ".join(document[i].get_textpage().get_text_range()
                                            for i in range(len(document))))
        return re.sub(r"(\d) (\"|°)", r"\1\2", text)
    finally:
        document.close()
