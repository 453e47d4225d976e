"""The certificate dialog shows, before issue, what the certificate will say of where its
readings came from (day review 67 F7: the "Readings:" line was seen only in the issued PDF,
after the register had recorded it), read-only, in the certificate's language."""

from __future__ import annotations

import hashlib

from PySide6.QtWidgets import QDialog, QLabel

from widgets.certificate_dialog import CertificateDialog


def test_the_dialog_shows_the_readings_line_before_issue(window, qtbot, tmp_path, samples_dir,
                                                         monkeypatch):
    polygon = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    csv = tmp_path / "bench_run_0512.csv"
    csv.write_bytes((samples_dir / polygon.kind.sample_file).read_bytes())
    digest = hashlib.sha256(csv.read_bytes()).hexdigest()
    polygon.import_file(csv)
    column = polygon.sheet.column_index("ac_x_arcsec")
    polygon.table_model.set_cells([(3, column, "20.00")])
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    seen = {}

    def look(dialog):
        label = dialog.findChild(QLabel, "readings_line")
        language = dialog.choices["language"]
        for value in ("en", "zh", "zh+en"):
            language.setCurrentIndex(language.findData(value))
            seen[value] = (label.text(), label.isHidden(), bool(label.textInteractionFlags()))
        return QDialog.DialogCode.Rejected

    monkeypatch.setattr(CertificateDialog, "exec", look)
    assert not window.export_certificate()  # cancelled: nothing written
    english = (f"imported from bench_run_0512.csv (SHA-256 {digest}), edited in AngleBench")
    assert seen["en"] == (english, False, True)
    assert seen["zh+en"] == seen["en"]  # a bilingual certificate's body is English
    chinese, hidden, _ = seen["zh"]
    assert not hidden and digest in chinese and "bench_run_0512.csv" in chinese
    assert "imported from" not in chinese and "edited in" not in chinese
