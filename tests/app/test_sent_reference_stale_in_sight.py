"""The polygon workbench's "reference is stale / Send again" notice is in sight at the
window's 1280×720 (day review 64 P2: it was the Set-up form's last row, at y = 936 in a
720-px window, seen only by scrolling the set-up down), and no certificate is issued from
the polygon workbench while the reference column it holds is stale."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import QPoint, QRect, Qt

from app.reference_sender import send_reference

pytestmark = pytest.mark.slow  # the window

SAMPLES = Path(__file__).resolve().parents[2] / "resources" / "samples"


def _type_cell(qtbot, view, row, column, text):
    index = view.model().index(row, column)
    view.setCurrentIndex(index)
    view.edit(index)
    qtbot.waitUntil(lambda: view._typing_delegate.editor is not None, timeout=3000)
    editor = view._typing_delegate.editor
    editor.selectAll()
    qtbot.keyClicks(editor, text)
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: view.model().data(view.model().index(row, column)) == text)


def _in_sight(widget, window) -> bool:
    """``widget`` shown, of some size, wholly inside the window and inside every scroll
    area's viewport it is in (the visible part of it is all of it)."""
    if not widget.isVisible() or widget.width() == 0 or widget.height() == 0:
        return False
    top_left = widget.mapTo(window, QPoint(0, 0))
    if not window.rect().contains(QRect(top_left, widget.size())):
        return False
    return widget.visibleRegion().boundingRect() == widget.rect()


def _twelve_faces(path: Path) -> Path:
    """A 12-face polygon's readings, two sets (the cross-calibration sends 12 faces)."""
    lines = ["position,encoder_deg,polygon_dev_arcsec,ac_x_arcsec,ac_y_arcsec,set,direction"]
    for number, direction in ((1, "+"), (2, "-")):
        faces = range(1, 13) if direction == "+" else [1, *range(12, 1, -1)]
        for face in faces:
            wobble = 0.3 * ((face * 7 + number) % 5) - 0.6
            lines.append(f"{face},{(123.4 + 30.0 * (face - 1)) % 360.0 + wobble / 3600.0:.7f},0,"
                         f"{10.0 + wobble:.2f},{-5.0 + face * 0.1:.2f},{number},{direction}")
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _stale_after_a_change(window, qtbot, polygon_readings: Path | None = None):
    window.resize(1280, 720)
    window.show()
    qtbot.waitExposed(window)
    crosscal, polygon = window.presenter("crosscal"), window.presenter("polygon")
    if polygon_readings is not None:
        polygon.import_file(polygon_readings)
        qtbot.waitUntil(lambda: polygon.result is not None and not polygon.analysis_pending,
                        timeout=10000)
    window.tabs.setCurrentIndex(window.presenters.index(crosscal))
    crosscal.load_sample()
    qtbot.waitUntil(lambda: crosscal.result is not None and not crosscal.analysis_pending)
    assert send_reference(window), window.told
    notice = polygon.view.reference_notice
    assert not notice.stale
    # another autocollimator reading typed in the cross-calibration
    column = crosscal.sheet.column_index("ac_x_arcsec")
    old = float(crosscal.sheet.text(3, column))
    window.tabs.setCurrentIndex(window.presenters.index(crosscal))
    _type_cell(qtbot, crosscal.view.table, 3, column, f"{old + 0.8:.3f}")
    qtbot.waitUntil(lambda: notice.stale, timeout=5000)
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    return crosscal, polygon, notice


def test_the_stale_notice_and_send_again_are_in_sight_at_1280x720(window, qtbot):
    _, polygon, notice = _stale_after_a_change(window, qtbot)
    assert window.size().width() <= 1280 and window.size().height() <= 720
    qtbot.waitUntil(lambda: _in_sight(notice.label, window), timeout=3000)
    assert "changed since" in notice.label.text()
    assert _in_sight(notice.button, window) and notice.button.isEnabled()
    # not in the set-up's scrolled form: in the result strip, under its warnings
    assert not polygon.view.settings_area.isAncestorOf(notice)
    # Send again, clicked where it is seen, sends it again
    qtbot.mouseClick(notice.button, Qt.MouseButton.LeftButton)
    assert not notice.stale


def test_no_certificate_is_issued_on_a_stale_reference(window, qtbot, monkeypatch,
                                                         tmp_path):
    _, polygon, notice = _stale_after_a_change(window, qtbot,
                                               _twelve_faces(tmp_path / "faces.csv"))
    issued = []
    monkeypatch.setattr(window.certificates, "export_certificate",
                        lambda *a, **k: issued.append(a) or True)
    qtbot.waitUntil(lambda: polygon.result is not None and not polygon.analysis_pending)
    window.told.clear()
    assert not window.export_certificate()
    assert issued == []  # refused before the certificate's dialogs
    assert any("no certificate is issued" in t and "changed since" in t for t in window.told)
    # sent again: issued
    qtbot.mouseClick(notice.button, Qt.MouseButton.LeftButton)
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    qtbot.waitUntil(lambda: polygon.result is not None and not polygon.analysis_pending)
    assert window.export_certificate()
    assert len(issued) == 1
