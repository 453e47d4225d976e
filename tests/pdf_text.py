"""A printed PDF's text as the certificate tests read it: every page's, whitespace runs as one
space, a unit wrapped onto the next line joined to its figure (1.2 ″ → 1.2″)."""

from __future__ import annotations

import re
import shutil
import subprocess

import pypdfium2 as pdfium
import pytest

__all__ = ["CLOSING", "pdf_lines", "pdf_text"]

#: the marks a line break must not put first on a line (a Chinese line begins with none of them)
CLOSING = "。，、；：？！）》」』】”’)],;:"


def pdf_text(pdf: bytes) -> str:
    """The text of the PDF ``pdf`` (its bytes), pages joined."""
    document = pdfium.PdfDocument(pdf)
    try:
        text = re.sub(r"\s+", " ", " ".join(document[i].get_textpage().get_text_range()
                                            for i in range(len(document))))
        return re.sub(r"(\d) (\"|°)", r"\1\2", text)
    finally:
        document.close()


def pdf_lines(path) -> list[str]:
    """The lines of the PDF at ``path`` as pdftotext -raw reads them (in the order written, one
    printed line each), stripped, empty ones left out: where a line breaks, which pdfium's
    whole-page text does not show."""
    if shutil.which("pdftotext") is None:
        pytest.fail("pdftotext is missing: apt-get install poppler-utils (.ci/run does)")
    out = subprocess.run(["pdftotext", "-raw", "-enc", "UTF-8", str(path), "-"],
                         capture_output=True, text=True, check=True).stdout
    return [line.strip() for line in out.splitlines() if line.strip()]
