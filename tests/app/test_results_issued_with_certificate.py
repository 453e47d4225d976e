"""The results file written with an issued certificate carries the number and date of issue
the register gave, and the register records it; one written without issuing says it is not
issued (review 61, F1). The polygon sample's details are bilingual (zh+en): so are the
results file's labels (N6). The register of each test is its own (conftest.py)."""

from __future__ import annotations

import hashlib
import json

import pytest
from openpyxl import load_workbook

from app.main import main
from models.register.location import register_url
from models.register.store import Register

#: the results file and the register's records are read, never a PDF's pages (verify finds
#: a PDF by its SHA-256): each PDF a stand-in (tests/app/conftest.py, ~0.5 s of CPU a certificate)
pytestmark = pytest.mark.usefixtures("pdf_stand_in")

TYPED_DATE = "2026-11-24"  # a date of issue typed in the details, as the review's were


def _details(samples_dir, tmp_path, **changes):
    meta = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    meta.update({"example": False, "certificate_number": "", "issue_date": TYPED_DATE,
                 **changes})
    path = tmp_path / "details.json"
    path.write_text(json.dumps(meta), encoding="utf-8")
    return path


class _Labelled(dict):
    """A sheet's rows by label, looked up by the label's English (a bilingual label is the
    Chinese, then the English: 证书编号 Certificate number)."""

    def __getitem__(self, english):
        (value,) = [v for k, v in self.items() if k == english or k.endswith(" " + english)]
        return value


def _certificate_sheet(path):
    book = load_workbook(path)
    return _Labelled((row[0], row[1]) for row in book["Certificate"].iter_rows(values_only=True))


@pytest.mark.slow
def test_the_xlsx_issued_with_a_certificate_carries_its_number_and_date_and_is_recorded(
        samples_dir, tmp_path, capsys):
    pdf, xlsx = tmp_path / "c.pdf", tmp_path / "r.xlsx"
    code = main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"),
                 "--certificate", str(pdf), "--results", str(xlsx),
                 "--metadata", str(_details(samples_dir, tmp_path))])
    said = capsys.readouterr().err
    assert code == 0, said
    with Register(register_url()) as register:
        (record,) = register.list()
    sheet = _certificate_sheet(xlsx)
    # the register's number and date of issue (it was empty and the typed date, 2026-11-24)
    assert sheet["Certificate number"] == record.number and record.number
    assert sheet["Date of issue"] == record.issue_date
    assert record.issue_date != TYPED_DATE and TYPED_DATE not in sheet.values()
    assert sheet["Status"].startswith(f"已签发：证书 {record.number} 的结果")
    assert f"\nissued: the results of certificate {record.number}" in sheet["Status"]
    # tied to the certificate it accompanies: the PDF's SHA-256 as issued and recorded
    assert sheet["Certificate PDF SHA-256"] == hashlib.sha256(pdf.read_bytes()).hexdigest()
    assert sheet["Certificate PDF SHA-256"] == record.pdf_sha256
    assert f"Results of {record.number} written to {xlsx}" in said
    # the register checks the file as it checks the PDF
    assert main(["register", "verify", str(xlsx)]) == 0
    out = capsys.readouterr().out
    assert f"{xlsx}: the results file of certificate {record.number}" in out
    assert "identical to the record" in out and "CHANGED AFTER ISSUE" not in out
    altered = tmp_path / "altered.xlsx"
    altered.write_bytes(xlsx.read_bytes() + b"\0")
    assert main(["register", "verify", str(altered)]) == 1
    assert f"{altered}: NOT in the register" in capsys.readouterr().out
    # the certificate still verifies: its printed chain head is the one before it
    assert main(["register", "verify", str(pdf)]) == 0
    assert "CHANGED AFTER ISSUE" not in capsys.readouterr().out


@pytest.mark.slow
def test_results_written_without_issuing_say_so_and_are_not_recorded(samples_dir, tmp_path,
                                                                      capsys):
    xlsx = tmp_path / "r.xlsx"
    # a number and a date of issue typed in the details, no certificate issued
    details = _details(samples_dir, tmp_path, certificate_number="AB-2026-0042")
    code = main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"),
                 "--results", str(xlsx), "--metadata", str(details)])
    assert code == 0, capsys.readouterr().err
    sheet = _certificate_sheet(xlsx)
    assert sheet["Certificate number"] is None and sheet["Date of issue"] is None
    assert "AB-2026-0042" not in sheet.values() and TYPED_DATE not in sheet.values()
    assert sheet["Status"].startswith("未签发：")
    assert ("\nnot issued: these results were written apart from any certificate's issue"
            in sheet["Status"])
    assert sheet["Certificate PDF SHA-256"] is None
    capsys.readouterr()
    from models.register.store import Register

    with Register(register_url()):  # the lab's, empty (contract75 F10: none is refused)
        pass
    assert main(["register", "verify", str(xlsx)]) == 1
    assert f"{xlsx}: NOT in the register" in capsys.readouterr().out


@pytest.mark.slow
def test_a_csv_issued_with_a_certificate_is_recorded_too(samples_dir, tmp_path, capsys):
    pdf, csv = tmp_path / "c.pdf", tmp_path / "r.csv"
    assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"),
                 "--certificate", str(pdf), "--results", str(csv),
                 "--metadata", str(_details(samples_dir, tmp_path))]) == 0
    capsys.readouterr()
    assert main(["register", "verify", str(csv)]) == 0
    assert "the results file of certificate" in capsys.readouterr().out


@pytest.mark.slow
def test_a_results_record_changed_after_issue_breaks_the_chain(samples_dir, tmp_path, capsys):
    """The results file's SHA-256 is a chained entry: set to another file's afterwards (to
    pass an altered file off as issued), the register's chain no longer holds."""
    import sqlalchemy as sa

    from models.register.schema import ENTRIES

    xlsx = tmp_path / "r.xlsx"
    assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"),
                 "--certificate", str(tmp_path / "c.pdf"), "--results", str(xlsx),
                 "--metadata", str(_details(samples_dir, tmp_path))]) == 0
    altered = xlsx.read_bytes() + b"\0"
    engine = sa.create_engine(register_url())
    with engine.begin() as conn:
        body = json.dumps({"sha256": hashlib.sha256(altered).hexdigest(), "file": "r.xlsx"},
                          sort_keys=True)
        assert conn.execute(ENTRIES.update().where(ENTRIES.c.kind == "results").values(
            body_json=body)).rowcount == 1
    engine.dispose()
    (tmp_path / "altered.xlsx").write_bytes(altered)
    capsys.readouterr()
    assert main(["register", "verify", str(tmp_path / "altered.xlsx")]) == 3
    assert "CHANGED AFTER ISSUE" in capsys.readouterr().out
