"""The register window's list and the register's export name what links a certificate to
others — the certificate it amends and what superseded it, a withdrawal, "issued in place of
withdrawn N", a separate calibration, readings of another item, the same readings said why —
as `register show` and the PDF/DCC did (the window and the export showed none of them)."""

from __future__ import annotations

import csv
import io
import zipfile
from types import SimpleNamespace
from unittest import mock

from app.main import main
from app.register_presenter import COLUMNS, RegisterPresenter, RegisterView
from models.certificate.metadata import CertificateMetadata
from models.register.record_links import record_links
from models.register.store import IssueRequest, Register
from tests.own_readings import one_reading_moved, theodolite_project, theodolite_sample_rows


def _issue(register: Register, serial: str, rows, **options):
    meta = CertificateMetadata(approver="Dr. Li", item_serial=serial,
                               calibration_date="2026-11-20",
                               item_description="Limited-rotation axis",
                               item_manufacturer="Example Instruments")
    options.setdefault("separate_calibration", "")
    return register.issue(IssueRequest("theodolite", meta, theodolite_project(rows)),
                          lambda m: f"%PDF {m.certificate_number}".encode(), **options)[0]


def _linked_register(url: str) -> dict[str, str]:
    """A withdrawn certificate (a), its calibration issued again in its place (b) and
    amended (c), another item's certificate of a's readings said why (d), c's readings and
    details issued as a calibration of its own said why (e): their numbers."""
    rows = theodolite_sample_rows()
    moved = one_reading_moved(rows)
    with Register(url) as register:
        a = _issue(register, "LRA-0815", rows)
        register.withdraw(a.number, "wrong tolerance")
        b = _issue(register, "LRA-0815", moved)
        c = _issue(register, "LRA-0815", moved, supersedes=b.number, change_note="typo")
        d = _issue(register, "LRA-0900", rows,
                   readings_of_another_item=(a.number, "the same axis, relabelled"))
        e = _issue(register, "LRA-0815", moved, separate_calibration="second mounting",
                   same_readings_as=(c.number, "re-run on the same day"))
    return {"a": a.number, "b": b.number, "c": c.number, "d": d.number, "e": e.number}


def _expected(n: dict[str, str]) -> dict[str, str]:
    return {
        n["a"]: "withdrawn: wrong tolerance",
        n["b"]: f"superseded by {n['c']}; issued in place of withdrawn {n['a']}",
        n["c"]: f"amends {n['b']}",
        n["d"]: f"readings of another item's {n['a']}",
        n["e"]: f"issued in place of withdrawn {n['a']}; separate calibration from {n['c']}; "
                f"readings and details of {n['c']}, said why"}


def test_the_window_lists_each_certificates_links(tmp_path):
    url = f"sqlite:///{tmp_path / 'r.sqlite'}"
    numbers = _linked_register(url)
    view = mock.create_autospec(RegisterView, instance=True)
    certificates = SimpleNamespace(open_register=lambda: Register(url),
                                   register_url=lambda: url, lab_timezone=lambda: "UTC")
    RegisterPresenter(view, certificates, mock.Mock()).refresh()
    header, rows = view.show_records.call_args.args
    assert header[-1] == "Links" and header == COLUMNS
    assert {row[0]: row[-1] for row in rows} == _expected(numbers)
    assert all(len(row) == len(header) for row in rows)


def test_the_export_index_has_a_links_column(tmp_path, capsys):
    url = f"sqlite:///{tmp_path / 'r.sqlite'}"
    numbers = _linked_register(url)
    out = tmp_path / "export.zip"
    assert main(["register", "--register", url, "export", str(out)]) == 0
    with zipfile.ZipFile(out) as archive:
        index = list(csv.DictReader(io.StringIO(archive.read("index.csv").decode())))
    assert {row["number"]: row["links"] for row in index} == _expected(numbers)


def test_the_links_are_translatable_messages(tmp_path):
    url = f"sqlite:///{tmp_path / 'r.sqlite'}"
    numbers = _linked_register(url)
    with Register(url) as register:
        links = record_links(register.get(numbers["b"]))
    # each a message the window translates (tr) and the command line renders in its
    # language: the English text kept as its key, the numbers as its fields
    assert [(link.template, dict(link.figures)) for link in links] == [
        ("superseded by {number}", {"number": numbers["c"]}),
        ("issued in place of withdrawn {numbers}", {"numbers": numbers["a"]})]
