"""What a file is by its first bytes, not its name: the register's ``verify`` looks a file up
among the documents of its kind (reg72 #6: the same bytes named .tmp or .xlsx were "NOT in
the register"), and an output is not written over a file of another kind (a certificate
named over a lab's details JSON)."""

from __future__ import annotations

__all__ = ["file_kind"]

_BOM_AND_SPACE = b"\xef\xbb\xbf \t\r\n"


def file_kind(data: bytes) -> str:
    """"pdf" (``%PDF`` in the first KiB, as readers accept), "zip" (an XLSX workbook or any
    ZIP archive), "xml" (a document that starts with ``<`` after a byte-order mark and white
    space), "text" (other UTF-8 text) or "" (empty, or none of them)."""
    head = data[:4096].lstrip(_BOM_AND_SPACE)
    if b"%PDF" in data[:1024]:
        return "pdf"
    if head.startswith((b"PK\x03\x04", b"PK\x05\x06")):
        return "zip"
    if head.startswith(b"<"):
        return "xml"
    try:
        data[:4096].decode("utf-8")
    except UnicodeDecodeError:
        return ""
    return "text" if data.strip() else ""
