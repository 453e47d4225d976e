"""A read-only table of text: headers and rows shown as they are handed over."""

from __future__ import annotations

from collections.abc import Sequence

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QTableWidget, QTableWidgetItem


def show_text_table(table: QTableWidget, header: Sequence[str], rows: Sequence[Sequence[str]],
                    align_right: bool = False) -> None:
    """Replace ``table``'s contents with ``header`` and ``rows`` (numbers right-aligned when
    asked, as a column of figures reads)."""
    table.clear()
    table.setColumnCount(len(header))
    table.setHorizontalHeaderLabels(list(header))
    table.setRowCount(len(rows))
    for r, row in enumerate(rows):
        for c, text in enumerate(row):
            item = QTableWidgetItem(text)
            if align_right:
                item.setTextAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
            table.setItem(r, c, item)
