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
        return {r[0]: (r[1] if len(r) > 1 else None) for r in book["Certificate"].iter_rows(values_only=True)
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
    said = (f"readings typed in AngleBench, except rows 3–5, {rows} (4 of {rows}), captured "
            "from the instruments")
    assert said in text, text
    assert TYPED + " " not in text.replace(said, "")
    assert sheet["Readings"] == said
    # the instrument output's SHA-256 as the PDF gives it
    digest = raw_digest([session])
    assert sheet["Instrument output SHA-256"] == digest
    assert digest in text.replace(" ", "")


def test_typed_readings_are_said_typed(window, polygon, tmp_path):
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
