"""A reference sent from the cross-calibration to the polygon workbench (File › Send as
reference) is a snapshot: when the cross-calibration changes afterwards (a reading typed, its
certificate details), the polygon workbench says its reference column is no longer what
would be sent and offers *Send again*; the digest of what was sent is saved with the project
and compared when it is opened. Before, nothing was said: the polygon workbench kept the old
figures silently."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from PySide6.QtCore import Qt

from app.reference_sender import SENT_REFERENCES, send_reference
from models.certificate.metadata import CertificateMetadata

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


def _sent(window, qtbot):
    window.show()
    crosscal, polygon = window.presenter("crosscal"), window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(crosscal))
    crosscal.load_sample()
    qtbot.waitUntil(lambda: crosscal.result is not None and not crosscal.analysis_pending)
    assert send_reference(window), window.told
    assert not polygon.view.reference_notice.stale
    return crosscal, polygon


def _column(polygon) -> np.ndarray:
    column = polygon.sheet.column_index("polygon_dev_arcsec")
    return np.array([float(polygon.sheet.text(r, column)) for r in range(polygon.sheet.row_count)])


def test_a_reading_typed_after_sending_is_said_and_sent_again(window, qtbot):
    crosscal, polygon = _sent(window, qtbot)
    notice = polygon.view.reference_notice
    before = _column(polygon)
    # a reading typed in the cross-calibration: another autocollimator reading
    column = crosscal.sheet.column_index("ac_x_arcsec")
    typed = crosscal.sheet.text(3, column)
    old = float(typed)
    window.tabs.setCurrentIndex(window.presenters.index(crosscal))
    _type_cell(qtbot, crosscal.view.table, 3, column, f"{old + 0.8:.3f}")
    qtbot.waitUntil(lambda: notice.stale, timeout=5000)
    assert "Cross-calibration" in notice.label.text() and "changed since" in notice.label.text()
    assert notice.button.isEnabled()
    np.testing.assert_allclose(_column(polygon), before)  # the snapshot, held and said
    # typed back: what was sent is current again, the notice goes
    _type_cell(qtbot, crosscal.view.table, 3, column, typed)
    qtbot.waitUntil(lambda: not notice.stale, timeout=5000)
    # changed again, then Send again clicked in the polygon workbench
    _type_cell(qtbot, crosscal.view.table, 3, column, f"{old + 0.8:.3f}")
    qtbot.waitUntil(lambda: notice.stale, timeout=5000)
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    qtbot.mouseClick(notice.button, Qt.MouseButton.LeftButton)
    assert not notice.stale and window.current is polygon
    d = crosscal.result.solution.polygon_deviation_arcsec
    np.testing.assert_allclose(_column(polygon), d - d[0], atol=1e-6)
    assert np.max(np.abs(_column(polygon) - before)) > 1e-3


def test_the_crosscals_details_changed_after_sending_are_said(window, qtbot):
    crosscal, polygon = _sent(window, qtbot)
    details = CertificateMetadata.from_dict(json.loads(
        (SAMPLES / "certificate_crosscal.json").read_text(encoding="utf-8")))
    assert details.standards  # the comparator's stated U: a larger U from face 1
    window.certificates.store_details("crosscal", details)
    qtbot.waitUntil(lambda: polygon.view.reference_notice.stale, timeout=5000)


def test_a_column_no_longer_the_sent_one_is_not_said_stale(window, qtbot):
    """The polygon's column typed over after sending (or undone, or a certificate loaded):
    it is not the sent reference, so a change of the cross-calibration says nothing there."""
    crosscal, polygon = _sent(window, qtbot)
    column = polygon.sheet.column_index("polygon_dev_arcsec")
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    _type_cell(qtbot, polygon.view.table, 2, column, "1.25")
    details = CertificateMetadata.from_dict(json.loads(
        (SAMPLES / "certificate_crosscal.json").read_text(encoding="utf-8")))
    window.certificates.store_details("crosscal", details)
    qtbot.waitUntil(lambda: not crosscal.analysis_pending and not polygon.analysis_pending)
    qtbot.wait(300)  # the redraw
    assert not polygon.view.reference_notice.stale
    polygon.table_model.undo_stack.undo()  # the sent column back: now said
    qtbot.waitUntil(lambda: polygon.view.reference_notice.stale, timeout=5000)


def test_the_digest_is_saved_with_the_project_and_compared_on_opening(window, qtbot,
                                                                       tmp_path):
    crosscal, polygon = _sent(window, qtbot)
    path = tmp_path / "sent.anglebench.json"
    assert window.projects.save_to(path)
    saved = json.loads(path.read_text(encoding="utf-8"))["metadata"][SENT_REFERENCES]
    assert saved["polygon"]["source"] == "crosscal" and len(saved["polygon"]["digest"]) == 64
    assert window.projects.open_project(path)
    qtbot.waitUntil(lambda: crosscal.result is not None and not crosscal.analysis_pending)
    qtbot.wait(100)
    assert not polygon.view.reference_notice.stale  # as sent
    # the project as saved after the cross-calibration's readings changed (by another
    # session, say): opened, the reference is said to be stale
    project = json.loads(path.read_text(encoding="utf-8"))
    rows = project["workbenches"]["crosscal"]["rows"]
    column = [c.key for c in crosscal.kind.columns].index("ac_x_arcsec")
    rows[3][column] = f"{float(rows[3][column]) + 0.8:.3f}"
    changed = tmp_path / "changed.anglebench.json"
    changed.write_text(json.dumps(project), encoding="utf-8")
    assert window.projects.open_project(changed)
    qtbot.waitUntil(lambda: polygon.view.reference_notice.stale, timeout=5000)
    assert "changed since" in polygon.view.reference_notice.label.text()
