"""Readings changed in the window after their project file was saved (or recovered from
its autosave) are not said to be that file's (day review 67 F4: AB-2026-0002, issued from
the recovered, unsaved job.anglebench.json, began "job.anglebench.json: imported from …"
while the file held 11.46 where the certificate's readings held 11.50)."""

from __future__ import annotations

import hashlib
import json
import os

import pytest

from models.certificate.metadata import CertificateMetadata
from tests.app.test_readings_origin_kept import _line, _polygon
from tests.pdf_text import pdf_lines

pytestmark = pytest.mark.slow  # windows, each analysing the polygon's readings

JOB = "job.anglebench.json"
CHANGED = f"changed in AngleBench after {JOB} was saved (not the readings in that file)"


def _killed(window) -> None:
    """The window dies (kill -9) after an autosave: its lock goes with the process."""
    window.projects.autosave()
    os.close(window.projects.recovery._lock_fd)
    window.projects.recovery._lock_fd = None
    window.projects.autosave_timer.stop()


def _set_up_changed(presenter) -> None:
    """A set-up field changed (one undo step that changes no reading)."""
    roll = float(presenter.settings["ac_roll_arcmin"])
    presenter.view.set_settings({**presenter.settings, "ac_roll_arcmin": roll + 1.0})
    presenter.settings_edited()
    assert presenter.is_modified and presenter.settings["ac_roll_arcmin"] == roll + 1.0


def _pdf_text(path) -> str:
    """The PDF's text as pdftotext -raw reads it, every space taken out."""
    return "".join("".join(pdf_lines(path)).split())


def test_readings_changed_after_the_save_are_not_the_files(recovering_window, qtbot, tmp_path,
                                                           samples_dir):
    window = recovering_window()
    polygon = _polygon(window, qtbot)
    csv = tmp_path / "bench_run_0512.csv"
    csv.write_bytes((samples_dir / polygon.kind.sample_file).read_bytes())
    digest = hashlib.sha256(csv.read_bytes()).hexdigest()
    polygon.import_file(csv)
    imported = f"imported from bench_run_0512.csv (SHA-256 {digest})"
    path = tmp_path / JOB
    assert window.projects.save_to(path), window.told
    assert _line(window, _polygon(window, qtbot)) == f"{JOB}: {imported}"
    _set_up_changed(polygon)  # the readings are still the file's
    assert _line(window, _polygon(window, qtbot)) == f"{JOB}: {imported}"
    column = polygon.sheet.column_index("ac_x_arcsec")
    saved = polygon.sheet.text(9, column)
    changed = f"{float(saved) + 0.04:.2f}"
    polygon.table_model.set_cells([(9, column, changed)])
    edited = f"{imported}, edited in AngleBench; {CHANGED}"
    assert _line(window, _polygon(window, qtbot)) == edited
    polygon.undo_stack.undo()  # the file's readings again
    assert _line(window, _polygon(window, qtbot)) == f"{JOB}: {imported}"
    polygon.undo_stack.redo()

    # recovered after a crash: still not the file's (which holds the value saved)
    _killed(window)
    survivor = recovering_window()
    assert survivor.projects.offer_recovery()
    recovered = _polygon(survivor, qtbot)
    assert survivor.projects.path == path
    assert recovered.sheet.text(9, column) == changed
    stored = json.loads(path.read_text(encoding="utf-8"))["workbenches"]["polygon"]["rows"]
    assert stored[9][column] == saved
    assert _line(survivor, recovered) == edited

    # the certificate says so
    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    data.update({"certificate_number": "", "language": "en", "example": True})
    survivor.certificates.edit_details = lambda shown: CertificateMetadata.from_dict(data)
    survivor.certificates.view.confirm_standards = lambda warnings: True
    survivor.certificates.view.confirm_test_report = lambda why: True
    survivor.certificates.view.choose_save_path = (
        lambda title, suggested, kinds: str(tmp_path / "cert.pdf"))
    assert survivor.export_certificate(), survivor.told
    text = _pdf_text(tmp_path / "cert.pdf")
    assert "".join(edited.split()) in text
    assert f"Readings:{JOB}" not in text

    # saved: the file's again; a set-up changed, then a crash: still the file's readings
    assert survivor.projects.save_to(path), survivor.told
    assert _line(survivor, recovered) == f"{JOB}: {imported}, edited in AngleBench"
    _set_up_changed(recovered)
    _killed(survivor)
    third = recovering_window()
    assert third.projects.offer_recovery()
    assert _line(third, _polygon(third, qtbot)) == f"{JOB}: {imported}, edited in AngleBench"
