"""The certificate's and the results' "Readings:" say which rows were captured from the
instruments (day review 64 P8: the PDF and the XLSX said "readings typed in AngleBench" of
rows taken from the instruments; the XLSX gave no instrument output at all)."""

from __future__ import annotations

import json
import shutil
import subprocess

import pytest
from openpyxl import load_workbook

from models.capture.raw_record import raw_digest, session_json
from models.certificate.metadata import CertificateMetadata

TYPED = "readings typed in AngleBench"


def _session(rows: list[int]) -> dict:
    """An autocollimator's session whose takes went into ``rows`` (0-based)."""
    frames = [(0.1 * i, b"1.00 2.00\r\n", 1) for i in range(len(rows))]
    return session_json("autocollimator", "pty", 9600, "2026-12-05T10:00:00Z", frames,
                        [(r, i, i) for i, r in enumerate(rows)], workbench="polygon")


@pytest.fixture(params=[True, False], ids=["specimen", "issued"])
def polygon(request, window, samples_dir, tmp_path):
    """The polygon sample analysed in front; the certificate's details (the example's: a
    specimen, or issued through the register) and files answered."""
    presenter = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    presenter.import_file(samples_dir / presenter.kind.sample_file)
    assert presenter.result is not None and not presenter.analysis_pending
    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    data.update({"certificate_number": "", "language": "en", "example": request.param})
    window.certificates.edit_details = lambda shown: CertificateMetadata.from_dict(data)
    window.certificates.view.confirm_standards = lambda warnings: True
    window.certificates.view.confirm_test_report = lambda why: True
    window.certificates.view.choose_save_path = (
        lambda title, suggested, kinds: str(tmp_path / ("cert.pdf" if suggested.endswith(".pdf")
                                                        else "results.xlsx")))
    yield presenter
    window.capture_panel.close()


def _pdf_text(path) -> str:
    if shutil.which("pdftotext") is None:
        pytest.fail("pdftotext is missing: apt-get install poppler-utils (.ci/run does)")
    out = subprocess.run(["pdftotext", "-raw", "-enc", "UTF-8", str(path), "-"], capture_output=True,
                         text=True, check=True).stdout
    return " ".join(out.split())


def _certificate_sheet(path) -> dict:
    book = load_workbook(path, read_only=True)
    try:
        return {r[0]: (r[1] if len(r) > 1 else None) for r in _details_sheet(book).iter_rows(values_only=True)
                if r}
    finally:
        book.close()


def _export_both(window, tmp_path) -> tuple[str, dict]:
    assert window.export_certificate()
    assert window.export_results()
    with window.certificates.open_register() as register:
        issued = register.list()
    # the example's details write a specimen (no record), the others are issued
    assert len(issued) == (0 if "SPECIMEN" in _pdf_text(tmp_path / "cert.pdf") else 1)
    return _pdf_text(tmp_path / "cert.pdf"), _certificate_sheet(tmp_path / "results.xlsx")


def test_captured_rows_are_named_on_the_certificate_and_the_results(window, polygon, tmp_path):
    rows = polygon.sheet.row_count
    session = _session([2, 3, 4, rows - 1])
    window._load_raw_capture({"polygon": [session]})
    text, sheet = _export_both(window, tmp_path)
    said = f"; rows 3–5, {rows} (4 of {rows}) captured from the instruments"
    imported = f"imported from polygon_sample.csv (SHA-256 {_sha256(polygon)})"
    assert said in text, text
    assert imported in text.replace(" )", ")"), text
    assert TYPED not in text
    assert sheet["Readings"] == imported + said
    # the instrument output's SHA-256 as the PDF gives it
    digest = raw_digest([session])
    assert sheet["Instrument output SHA-256"] == digest
    assert digest in text.replace(" ", "")


def _sha256(presenter) -> str:
    from models.project.file import file_sha256
    from widgets.workbench_presenter import SAMPLES_DIR

    return file_sha256(SAMPLES_DIR / presenter.kind.sample_file)


def test_typed_readings_are_said_typed(window, polygon, tmp_path, qtbot):
    # the sample's rows pasted over the sheet (as typed into it): no file's readings
    polygon.table_model.replace_all(polygon.state().rows, "Paste, replacing the sheet")
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    text, sheet = _export_both(window, tmp_path)
    assert "captured from the instruments" not in text
    assert "Readings " + TYPED in text, text
    assert sheet["Readings"] == TYPED
    assert sheet["Instrument output SHA-256"] is None


def test_every_row_captured_and_which_rows_count():
    from models.certificate.readings_origin import captured_rows, readings_origin, row_spans

    sheet = [["1", "2"], ["", ""], ["3", "4"], ["5", "6"]]
    # an undone (-1), superseded and deleted (-2 - r) take, and an empty row, are behind no row
    sessions = [{"takes": [[0, 0, 0], [-1, 1, 1], [-4, 2, 2], [1, 3, 3], [3, 4, 4]]},
                {"workbench": "other", "takes": [[2, 0, 0]]}]
    assert captured_rows(sessions, sheet, "polygon") == [0, 3]
    assert row_spans([0, 1, 2, 5, 7, 8]) == "1–3, 6, 8–9"
    assert readings_origin(TYPED, [0, 1, 2], 3) == "all 3 rows captured from the instruments"
    assert readings_origin("job.anglebench.json", [1], 3) == (
        "job.anglebench.json; rows 2 (1 of 3) captured from the instruments")
    assert readings_origin(TYPED, [], 3) == TYPED


def _type_cell(qtbot, presenter, row: int, column: int, text: str) -> None:
    """Type ``text`` into a cell of ``presenter``'s sheet as the user does, then Return."""
    from PySide6.QtCore import Qt
    from PySide6.QtWidgets import QLineEdit

    view = presenter.view.table
    view.window().show()
    qtbot.waitExposed(view.window())
    index = view.model().index(row, column)
    view.setCurrentIndex(index)
    view.edit(index)
    editor = next(w for w in view.viewport().findChildren(QLineEdit) if w.isVisible())
    editor.selectAll()
    qtbot.keyClicks(editor, text)
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: presenter.sheet.text(row, column) == text, timeout=3000)


def _readings_line(window, tmp_path, qtbot) -> tuple[str, str]:
    """The certificate's (PDF) and the results' (XLSX) "Readings:" of the workbench in front."""
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    text, sheet = _export_both(window, tmp_path)
    return text.replace(" )", ")"), sheet["Readings"]


def _results_readings(window, tmp_path, qtbot) -> str:
    """The results' (XLSX) "Readings:" of the workbench in front (nothing issued)."""
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    assert window.export_results()
    return _certificate_sheet(tmp_path / "results.xlsx")["Readings"]


def test_an_imported_file_is_named_with_its_digest(window, polygon, tmp_path, qtbot,
                                                   samples_dir, monkeypatch):
    """Day review 65 F4: readings imported (File › Import) into an unsaved project were
    "readings typed in AngleBench" on the certificate and in the results."""
    import app.main_window
    from models.project.file import file_sha256

    csv = tmp_path / "bench_run_0512.csv"
    csv.write_bytes((samples_dir / polygon.kind.sample_file).read_bytes())
    monkeypatch.setattr(app.main_window, "ask_open_file", lambda *a, **k: str(csv))
    window.menus.import_action.trigger()  # File › Import CSV/XLSX…, the file chosen
    qtbot.waitUntil(lambda: csv.name in window.statusBar().currentMessage(), timeout=10000)
    imported = f"imported from bench_run_0512.csv (SHA-256 {file_sha256(csv)})"
    text, sheet = _readings_line(window, tmp_path, qtbot)
    assert f"Readings {imported} " in text, text
    assert sheet == imported
    assert TYPED not in text

    # a reading typed over the import: the file's readings, edited
    _type_cell(qtbot, polygon, 2, polygon.sheet.column_index("polygon_dev_arcsec"), "0.25")
    assert _results_readings(window, tmp_path, qtbot) == f"{imported}, edited in AngleBench"
    # undone, the readings are the file's again; the import undone, the sample's
    window.undo_group.undo()
    assert _results_readings(window, tmp_path, qtbot) == imported
    window.undo_group.undo()
    assert _results_readings(window, tmp_path, qtbot) == (
        f"imported from polygon_sample.csv (SHA-256 {_sha256(polygon)})")


def test_the_bundled_sample_is_named(window, polygon, tmp_path, qtbot):
    """File › Load bundled sample: the certificate names the sample, not typed readings."""
    window.menus.sample_action.trigger()
    text, sheet = _readings_line(window, tmp_path, qtbot)
    assert sheet == "the bundled sample polygon_sample.csv"
    assert "Readings the bundled sample polygon_sample.csv " in text, text


def test_imported_source_wording():
    from models.certificate.readings_origin import ImportedFrom, imported_source

    assert imported_source(ImportedFrom("a.csv", "ab12"), False) == (
        "imported from a.csv (SHA-256 ab12)")
    assert imported_source(ImportedFrom("a.csv"), True) == "imported from a.csv, edited in AngleBench"
    assert imported_source(ImportedFrom("s.csv", "ff", sample=True), False) == "the bundled sample s.csv"


def _copied(presenter, rows: list[int]) -> str:
    """``rows`` of ``presenter``'s sheet as a spreadsheet copies them (tab-separated)."""
    sheet = presenter.sheet
    return "\n".join("\t".join(sheet.text(r, c) for c in range(sheet.column_count))
                     for r in rows)


def test_readings_pasted_over_the_sheet_are_said_pasted(window, polygon, tmp_path, qtbot):
    """Day review 66: readings pasted from the clipboard (their source unknown) were
    "readings typed in AngleBench" on the certificate; typing over one is an edit."""
    table = polygon.view.table
    rows = polygon.sheet.row_count
    table.setCurrentIndex(table.model().index(0, 0))
    table.selectAll()  # the whole sheet selected: the paste replaces it
    assert table.paste_text(_copied(polygon, list(range(rows)))) == "replace"
    text, sheet = _readings_line(window, tmp_path, qtbot)
    assert sheet == "readings pasted into AngleBench"
    assert "Readings readings pasted into AngleBench " in text, text
    assert TYPED not in text
    _type_cell(qtbot, polygon, 2, polygon.sheet.column_index("polygon_dev_arcsec"), "0.25")
    assert _results_readings(window, tmp_path, qtbot) == (
        "readings pasted into AngleBench, then edited in AngleBench")


def test_rows_pasted_into_a_sheet_are_named(window, polygon, tmp_path, qtbot):
    """Rows pasted over some of an imported sheet's: named as the captured rows are, and
    moved by a row inserted above them."""
    table = polygon.view.table
    rows = polygon.sheet.row_count
    table.setCurrentIndex(table.model().index(3, 0))
    assert table.paste_text(_copied(polygon, [3, 4])) == "cells"
    imported = f"imported from polygon_sample.csv (SHA-256 {_sha256(polygon)})"
    assert _results_readings(window, tmp_path, qtbot) == (
        f"{imported}; rows 4–5 (2 of {rows}) pasted into AngleBench")
    polygon.table_model.insert_rows(0)  # a blank row: no reading, but the rows below move
    assert _results_readings(window, tmp_path, qtbot) == (
        f"{imported}, edited in AngleBench; rows 5–6 (2 of {rows}) pasted into AngleBench")


def test_readings_sent_to_positioning_name_the_workbench_and_its_origin(window, tmp_path,
                                                                        qtbot, samples_dir):
    """Day review 66: a run sent to the positioning workbench was "readings typed in
    AngleBench" on its certificate."""
    polygon = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    polygon.import_file(samples_dir / polygon.kind.sample_file, sample=True)
    window.certificates.view.choose_save_path = (
        lambda title, suggested, kinds: str(tmp_path / "results.xlsx"))
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    assert window.send_to_positioning(), window.told
    assert window.current is window.presenter("positioning")
    # one forward approach per target: no certificate or results can be exported; the
    # source the certificate is given
    assert window._source_name() == (
        "sent from the Polygon encoder test workbench (its readings: the bundled sample "
        "polygon_sample.csv)")


def test_sheet_source_wording():
    from models.certificate.readings_origin import PastedIn, SentFrom, sheet_source

    assert sheet_source(None, False, [], 5) is None
    assert sheet_source(None, False, [0, 1, 2, 3, 4], 5) == "readings pasted into AngleBench"
    assert sheet_source(None, True, [1, 2], 5) == (
        "readings typed in AngleBench, except rows 2–3 (2 of 5), pasted, then edited in "
        "AngleBench")
    assert sheet_source(PastedIn(), False, [4], 5) == "readings pasted into AngleBench"
    assert sheet_source(SentFrom("Polygon encoder test"), False, [], 5) == (
        "sent from the Polygon encoder test workbench")
    assert sheet_source(SentFrom("Polygon encoder test", "job.anglebench.json"), True, [0],
                        5) == ("sent from the Polygon encoder test workbench (its readings: "
                               "job.anglebench.json), then edited in AngleBench; rows 1 (1 of "
                               "5) pasted into AngleBench")


def _details_sheet(book):
    """The sheet of the document's details: *Report* on a test report's file (assessment 73
    L4), else *Certificate*."""
    return book["Report" if "Report" in book.sheetnames else "Certificate"]


def test_a_row_the_analysis_cannot_read_is_named_not_counted():
    """A take after the plan's end made row 17 with no target, which the analysis leaves
    out: the report said "all 17 rows captured from the instruments" beside "Readings 16"
    (day review live76 F6). Now it counts the 16 rows read and names row 17 left out."""
    from app.certificate_issue import readings_stated
    from models.positioning.analysis import COLUMNS

    rows = [[str(15 * (i % 4)), str(1 + i // 8), "+" if i % 8 < 4 else "-", "", f"{15 * (i % 4)}.0002"]
            for i in range(16)]
    rows.append(["", "", "", "", "0.0001"])  # row 17: no target
    sessions = [{"workbench": "positioning", "takes": [[r, r, r] for r in range(17)]}]
    origin, _digest = readings_stated("positioning", TYPED, rows, sessions, COLUMNS)
    assert origin == ("all 16 rows captured from the instruments; row(s) 17 left out of the "
                      "analysis")
    # every row read: as before
    origin, _digest = readings_stated("positioning", TYPED, rows[:16], sessions, COLUMNS)
    assert origin == "all 16 rows captured from the instruments"


def test_a_reading_the_analysis_left_out_is_named_not_counted():
    """A positioning reading at another position than its target (left out, live76 F7) is
    named on the "Readings:" line as the rows that cannot be read are."""
    from types import SimpleNamespace

    from app.certificate_issue import readings_stated
    from models.positioning.analysis import COLUMNS

    rows = [[str(15 * (i % 4)), str(1 + i // 8), "+" if i % 8 < 4 else "-", "", "0.1"]
            for i in range(16)]
    sessions = [{"workbench": "positioning", "takes": [[r, r, r] for r in range(16)]}]
    origin, _digest = readings_stated("positioning", TYPED, rows, sessions, COLUMNS,
                                      SimpleNamespace(left_out=(6,)))
    assert origin == ("all 15 rows captured from the instruments; row(s) 7 left out of the "
                      "analysis")
