"""A test report is called one where AngleBench says what it issued: the window's status
line, the register's list and show, the register window's list (the positioning sample's
result names inputs not stated, so it is a test report since 0.8.11; the polygon's, with
its standard's U stated, a calibration certificate)."""

from __future__ import annotations

import datetime as dt
import json
import re
from unittest import mock

import pytest

from app.certificate_presenter import CertificatePresenter, CertificateView
from app.main import main
from app.register_presenter import RegisterPresenter, RegisterView
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

pytestmark = pytest.mark.slow  # certificates are rendered
YEAR = dt.datetime.now(dt.timezone.utc).year  # the register's day of issue numbers them
REPORT, CERTIFICATE = f"AB-{YEAR}-0001", f"AB-{YEAR}-0002"  # issued in this order


class Store(dict):
    def value(self, key, default=None):
        return self.get(key, default)

    def setValue(self, key, value):  # noqa: N802 - QSettings' name
        self[key] = value


def _details(samples_dir, key: str, **changes) -> CertificateMetadata:
    data = json.loads((samples_dir / f"certificate_{key}.json").read_text(encoding="utf-8"))
    data.update({"example": False, "certificate_number": "", **changes})  # the lab's own
    return CertificateMetadata.from_dict(data)


def _sample(samples_dir, key: str):
    kind = KINDS[key]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    return kind, kind.analyze(ReadingsSheet(kind.columns, rows).parse(),
                              kind.checked_settings({})), rows


def test_the_window_says_test_report_issued_and_the_register_window_lists_it(samples_dir,
                                                                            tmp_path):
    view = mock.create_autospec(CertificateView, instance=True)
    presenter = CertificatePresenter(view, Store(), lambda: {}, mock.Mock())
    for key, name in (("positioning", "report.pdf"), ("polygon", "certificate.pdf")):
        kind, result, rows = _sample(samples_dir, key)
        view.edit_certificate_details.return_value = _details(samples_dir, key)
        view.choose_save_path.return_value = str(tmp_path / name)
        assert presenter.export_certificate(kind, result, {}, kind.sample_file, rows)
        said = view.show_status.call_args.args[0]
        if key == "positioning":
            assert kind.certificate_document(result, _details(samples_dir, key),
                                             kind.sample_file, {}).is_test_report
            assert said.startswith(f"Test report {REPORT} issued: written to "
                                   f"{tmp_path / name} and recorded in the register"), said
        else:
            assert said.startswith(f"Certificate {CERTIFICATE} issued: written to "
                                   f"{tmp_path / name} and recorded in the register"), said
    with presenter.open_register() as register:
        assert {r.number: r.document_kind for r in register.list()} == {
            REPORT: "test", CERTIFICATE: "calibration"}
    window_view = mock.create_autospec(RegisterView, instance=True)
    RegisterPresenter(window_view, presenter, mock.Mock(return_value=True)).refresh()
    header, rows = window_view.show_records.call_args.args
    assert header[:4] == ("Number", "Status", "Revision", "Document")
    assert [r[:4] for r in rows] == [(CERTIFICATE, "issued", "original",
                                      "Calibration certificate"),
                                     (REPORT, "issued", "original", "Test report")]


def test_register_list_and_show_say_which_is_a_test_report(samples_dir, tmp_path, capsys):
    for key in ("positioning", "polygon"):
        details = tmp_path / f"{key}.json"
        details.write_text(json.dumps(_details(samples_dir, key).to_dict()), encoding="utf-8")
        assert main(["analyze", key, str(samples_dir / KINDS[key].sample_file),
                     "--certificate", str(tmp_path / f"{key}.pdf"),
                     "--metadata", str(details)]) == 0
    err = capsys.readouterr().err
    assert f"Test report {REPORT} issued" in err and f"Certificate {CERTIFICATE} issued" in err
    assert main(["register", "list"]) == 0
    listed = [re.split(r"\s{2,}", line) for line in capsys.readouterr().out.splitlines()[1:]]
    assert [(row[0], row[2], row[-1]) for row in listed] == [
        (CERTIFICATE, "polygon / Calibration certificate", "issued"),
        (REPORT, "positioning / Test report", "issued")]
    assert main(["register", "show", REPORT]) == 0
    shown = capsys.readouterr().out.splitlines()
    assert shown[:2] == [f"{REPORT}  (issued)", "  Document: Test report"]
    assert main(["register", "show", CERTIFICATE]) == 0
    assert capsys.readouterr().out.splitlines()[1] == "  Document: Calibration certificate"
    assert main(["register", "export", str(tmp_path / "all.zip")]) == 0
    import csv
    import io
    import zipfile

    with zipfile.ZipFile(tmp_path / "all.zip") as archive:
        index = list(csv.DictReader(io.StringIO(archive.read("index.csv").decode("utf-8"))))
    assert {r["number"]: r["document_kind"] for r in index} == {CERTIFICATE: "calibration",
                                                                 REPORT: "test"}
