"""repeat80: the polygon's window between the two readings of a face (readings per point 2).
Set 1 read twice a face and set 2's faces 1 and 24 pasted as a technician does (Ctrl+A,
Ctrl+V), then face 23's first reading typed: set 1's result stays, the summary says set 2
is in progress at face 23's reading 1 of 2, and a certificate is refused naming it. On main
the window showed no result and "2 readings per point, but the last point has 1 …"."""

from __future__ import annotations

import csv
from unittest import mock

import numpy as np
import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QLineEdit

from widgets.polygon.presenter import PolygonPresenter

pytestmark = pytest.mark.slow  # the polygon's exact 3-D analysis, a few times


def _type(qtbot, table, row: int, column: int, text: str) -> None:
    index = table.model().index(row, column)
    table.scrollTo(index)
    table.setCurrentIndex(index)
    table.setFocus()
    qtbot.keyClick(table, Qt.Key.Key_F2)
    editor = next(w for w in table.viewport().findChildren(QLineEdit) if w.isVisible())
    editor.selectAll()
    qtbot.keyClicks(editor, text)
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: table.model().data(table.model().index(row, column)) == text)


def test_face_23_at_its_first_reading_keeps_set_1s_result(qtbot, samples_dir):
    with open(samples_dir / "polygon_sample.csv", encoding="utf-8-sig", newline="") as handle:
        header, *rows = list(csv.reader(handle))
    presenter = PolygonPresenter()
    qtbot.addWidget(presenter.view)
    assert [c.key for c in presenter.kind.columns][:len(header)] == header
    presenter.set_settings({**presenter.settings, "readings_per_point": 2})
    presenter.view.show()
    presenter.view.activateWindow()
    qtbot.waitActive(presenter.view)
    presenter.load_sample()  # the sheet the readings are pasted over
    qtbot.waitUntil(lambda: presenter.sheet.row_count > 3)
    table = presenter.view.table
    set_1 = [r for r in rows if r[5] == "1"]
    set_2 = [r for r in rows if r[5] == "2"]
    twice = [r for row in set_1 + set_2[:2] for r in (row, row)]
    QGuiApplication.clipboard().setText("\n".join("\t".join(r) for r in twice))
    index = table.model().index(0, 0)
    qtbot.mouseClick(table.viewport(), Qt.MouseButton.LeftButton,
                     pos=table.visualRect(index).center())
    table.setFocus()  # the click's focus (the offscreen platform's click gives none)
    qtbot.waitUntil(table.hasFocus)
    qtbot.keyClick(table, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
    qtbot.keyClick(table, Qt.Key.Key_V, Qt.KeyboardModifier.ControlModifier)
    summary = presenter.view.summary
    qtbot.waitUntil(lambda: "In progress: set 2: 2 of 24 faces (rows" in summary.toPlainText(),
                    timeout=20000)
    before = presenter.result.mean_corrected_arcsec.copy()
    assert before.size == 24
    row = len(twice)  # face 23's first reading typed, cell by cell
    for column, text in enumerate(set_2[2]):
        _type(qtbot, table, row, column, text)
    qtbot.waitUntil(lambda: "face 23: reading 1 of 2" in summary.toPlainText(), timeout=20000)
    assert presenter.problem == ""
    assert summary.toPlainText().startswith(
        "In progress: set 2: 2 of 24 faces, face 23: reading 1 of 2 (rows 51–55)")
    np.testing.assert_array_equal(presenter.result.mean_corrected_arcsec, before)
    assert str(presenter.result.incomplete.text()) == \
        "set 2: 2 of 24 faces, face 23: reading 1 of 2"
    # a certificate is refused before the details dialog, naming the point in progress
    from app.certificate_presenter import CertificatePresenter, CertificateView

    dialogs = mock.create_autospec(CertificateView, instance=True)
    certificates = CertificatePresenter(dialogs, mock.MagicMock(), dict, lambda: None)
    assert not certificates.export_certificate(presenter.kind, presenter.result,
                                               presenter.settings, "x.csv")
    assert "face 23: reading 1 of 2" in dialogs.tell.call_args.args[1]
    dialogs.edit_certificate_details.assert_not_called()
