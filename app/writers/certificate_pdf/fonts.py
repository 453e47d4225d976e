"""The bundled fonts (resources/fonts), the characters they cover, and a document's text
checked against them: what no font can print, and right-to-left script (printed reversed)."""

from __future__ import annotations

import functools
import json
import unicodedata
from importlib import resources
from pathlib import Path

from fpdf import FPDF

from models.certificate.document import CertificateDocument

FONT = "dejavu"
CJK_FONT = "droid"


def font_files() -> dict[str, Path]:
    """The bundled font files by role: regular, bold, cjk."""
    base = resources.files("resources") / "fonts"
    return {"regular": Path(str(base / "DejaVuSans.ttf")),
            "bold": Path(str(base / "DejaVuSans-Bold.ttf")),
            "cjk": Path(str(base / "DroidSansFallbackFull.ttf"))}


@functools.cache
def _latin_coverage() -> frozenset[int]:
    from fontTools.ttLib import TTFont

    with TTFont(font_files()["regular"], lazy=True) as font:
        return frozenset(font.getBestCmap())


@functools.cache
def _cjk_coverage() -> frozenset[int]:
    from fontTools.ttLib import TTFont

    with TTFont(font_files()["cjk"], lazy=True) as font:
        return frozenset(font.getBestCmap())


def _document_texts(document: CertificateDocument) -> list[str]:
    tables = (document.parameters, document.results, document.statistics)
    return [document.source_name, document.method, document.method_reference,
            *document.warnings, *document.statements, document.standard,
            *(cell for t in tables for row in (t.header, *t.rows) for cell in row),
            *(f"{k} {v}" for k, v in document.settings),
            json.dumps(document.metadata.to_dict(), ensure_ascii=False)]


def right_to_left(document: CertificateDocument) -> str:
    """The right-to-left letters of the document (Arabic, Hebrew…): the certificate sets text
    left to right, one character after another, so such a word would print reversed and
    unjoined."""
    seen = dict.fromkeys(ch for text in _document_texts(document) for ch in text
                         if unicodedata.bidirectional(ch) in ("R", "AL"))
    return "".join(seen)


def unprintable(document: CertificateDocument) -> str:
    """The characters of the document that no bundled font has (they would be dropped
    from the PDF without a word)."""
    covered = _latin_coverage() | _cjk_coverage()
    seen = dict.fromkeys(ch for text in _document_texts(document) for ch in text
                         if ord(ch) > 0x7F and ord(ch) not in covered and ch.isprintable())
    return "".join(seen)


def _needs_fallback(document: CertificateDocument) -> bool:
    """Whether any text of the document has a character DejaVu Sans lacks."""
    texts = _document_texts(document)
    covered = _latin_coverage()
    return any(ord(ch) not in covered for text in texts for ch in text if ord(ch) > 0x7F)



def close_fonts(pdf: FPDF) -> None:
    """fpdf2 opens the TrueType files lazily and leaves them open: close them."""
    for font in pdf.fonts.values():
        ttfont = getattr(font, "ttfont", None)
        if ttfont is not None:
            ttfont.close()
