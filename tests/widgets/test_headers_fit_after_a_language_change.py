"""Columns sized once (a live capture sizes the columns it writes; a long sheet is measured
once) keep their widths when the language changes: live78's polygon headers read "准直仪 x ["
at 1280×720 and 200 % — "自准直仪 x [\\"]" cut to the English "AC x [\\"]"'s width, its unit
out of sight (gui78). After a change of language each column is at least as wide as its
header; none is narrowed."""

from __future__ import annotations

import pytest
from PySide6.QtWidgets import QHeaderView

pytestmark = pytest.mark.slow  # a window


def test_sized_columns_widen_to_their_headers_in_chinese(window, qtbot):
    window.set_language("en")
    presenter = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    presenter.table_model.replace_all([["1", "10", "", "0.09", "1.50", "1", "+"]], "typed")
    header = presenter.view.table.horizontalHeader()
    qtbot.waitUntil(lambda: header.sectionSize(3) > 0)
    header.setSectionResizeMode(QHeaderView.ResizeMode.Interactive)  # as a capture leaves it
    presenter.view.table.resizeColumnsToContents()
    english = [header.sectionSize(c) for c in range(header.count())]
    ac_x = presenter.sheet.column_index("ac_x_arcsec")
    try:
        window.set_language("zh_CN")
        title = presenter.table_model.headerData(ac_x, header.orientation())
        assert title == "自准直仪 x [\"]", title
        needed = header.sectionSizeFromContents(ac_x).width()
        assert needed > english[ac_x]  # the Chinese header is wider than the English one
        widths = [header.sectionSize(c) for c in range(header.count())]
        for column in range(header.count()):
            assert widths[column] >= header.sectionSizeFromContents(column).width(), column
            assert widths[column] >= english[column], column  # none narrowed
    finally:
        window.set_language("en")
