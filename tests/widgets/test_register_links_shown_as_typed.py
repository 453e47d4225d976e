"""hostile79 #4: the register window's links (a withdrawal's reason among them) shown as
typed: a reason typed as HTML was rendered below the list ("withdrawn:" and then a green
heading "VALID — NOT WITHDRAWN" with a link), and one of 10,000 characters took the
list's room; the list's cell tooltip rendered it too."""

from __future__ import annotations

from app.register_presenter import COLUMNS


def _rows(links: str) -> list[tuple[str, ...]]:
    row = ["AB-2026-0001", "withdrawn", "original", "Calibration certificate",
           "2026-11-20", "2026-11-20", "Theodolite", "LRA-0815", "Example Instruments",
           "ACME", links]
    assert len(row) == len(COLUMNS)
    return [tuple(row)]


def test_a_reason_typed_as_html_is_shown_as_typed(qtbot):
    from PySide6.QtCore import Qt

    from widgets.register_window import RegisterWindow

    view = RegisterWindow()
    qtbot.addWidget(view)
    links = "withdrawn: <h1 style='color:green'>VALID — NOT WITHDRAWN</h1><a href='x'>click</a>"
    view.show_records(COLUMNS, _rows(links))
    view.table.selectRow(0)
    assert view.links.textFormat() == Qt.TextFormat.PlainText
    assert view.links.text() == f"Links: {links}"
    tip = view.table.item(0, len(COLUMNS) - 1).toolTip()
    assert tip == ("<p>withdrawn: &lt;h1 style=&#x27;color:green&#x27;&gt;VALID — NOT "
                   "WITHDRAWN&lt;/h1&gt;&lt;a href=&#x27;x&#x27;&gt;click&lt;/a&gt;</p>")


def test_a_reason_of_10000_characters_is_cut_short_below_the_list(qtbot):
    from widgets.register_window import LINKS_SHOWN, RegisterWindow

    view = RegisterWindow()
    qtbot.addWidget(view)
    links = "withdrawn: " + "long reason " * 850
    view.show_records(COLUMNS, _rows(links))
    view.table.selectRow(0)
    shown = view.links.text()
    assert shown.startswith("Links: withdrawn: long reason") and shown.endswith("…")
    assert shown == "Links: " + links[:LINKS_SHOWN - 1].rstrip() + "…"
    assert LINKS_SHOWN == 400 and len(shown) <= len("Links: ") + 400
    assert view.links.toolTip() == f"<p>{links}</p>"
