"""The certificate presenter with a mock view: no window, no dialog (Mantid's MVP tests
are the model)."""

from __future__ import annotations

from unittest import mock

import pytest

from app.certificate_presenter import CertificatePresenter, CertificateView
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS


class Store(dict):
    def value(self, key, default=None):
        return self.get(key, default)

    def setValue(self, key, value):  # noqa: N802 - QSettings' name
        self[key] = value


@pytest.fixture
def parts():
    view = mock.create_autospec(CertificateView, instance=True)
    metadata: dict = {}
    modified = mock.Mock()
    presenter = CertificatePresenter(view, Store(), lambda: metadata, modified)
    return presenter, view, metadata, modified


def _theodolite(samples_dir):
    kind = KINDS["theodolite"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    return kind, kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))


def test_export_asks_the_view_and_keeps_the_details(parts, samples_dir, tmp_path):
    presenter, view, metadata, modified = parts
    entered = CertificateMetadata(certificate_number="AB/7", lab_name="Lab")
    view.edit_certificate_details.return_value = (entered, True)
    view.choose_save_path.return_value = str(tmp_path / "out")
    kind, result = _theodolite(samples_dir)
    assert presenter.export_certificate(kind, result, {}, "run.csv")
    args = view.edit_certificate_details.call_args.args
    assert args[1] == 1  # the first number of the lab's sequence …
    assert presenter.store.value("certificate/next_sequence") == 2  # … counted on
    assert view.choose_save_path.call_args.args[1] == "AB-7.pdf"
    assert (tmp_path / "out.pdf").read_bytes().startswith(b"%PDF")
    assert metadata["certificates"]["theodolite"]["certificate_number"] == "AB/7"
    modified.assert_called_once()
    assert "DRAFT" in view.show_status.call_args.args[0]
    view.wait_cursor.assert_has_calls([mock.call(True), mock.call(False)])


def test_cancelled_details_write_nothing(parts, samples_dir):
    presenter, view, metadata, modified = parts
    view.edit_certificate_details.return_value = (None, False)
    kind, result = _theodolite(samples_dir)
    assert not presenter.export_certificate(kind, result, {}, "run.csv")
    view.choose_save_path.assert_not_called()
    assert metadata == {} and not modified.called


def test_a_stored_detail_gone_bad_reaches_the_view_marked(parts):
    presenter, view, metadata, _ = parts
    metadata["certificates"] = {"polygon": {"lab_name": "Lab", "humidity_pct": "45 %"}}
    presenter.save_lab_defaults({"operator": "Wang"})
    meta = presenter.details("polygon")
    assert meta.lab_name == "Lab" and meta.operator == "Wang"
    view.edit_certificate_details.return_value = (None, False)
    presenter.edit_details(meta)
    _, _, problems, raw = view.edit_certificate_details.call_args.args
    assert "humidity_pct" in problems and raw["humidity_pct"] == "45 %"


def test_export_errors_are_told_not_raised(parts, samples_dir, tmp_path):
    presenter, view, _, _ = parts
    view.choose_save_path.return_value = str(tmp_path / "no" / "such" / "dir" / "r.csv")
    kind, result = _theodolite(samples_dir)
    assert not presenter.export_results(kind, result, {}, "run.csv")
    assert "Cannot export" in view.tell.call_args.args[0]
