"""The window's "also write the digital certificate (XML)": the presenter writes the DCC
beside the PDF (issued, or a specimen), its number and embedded PDF the issued ones; an
invalid one (against the schema folder set) issues nothing."""

from __future__ import annotations

import base64
import dataclasses
from pathlib import Path
from unittest import mock

import pytest
from lxml import etree

from app.certificate_presenter import CertificatePresenter, CertificateView
from models.dcc import vocabulary as v
from models.dcc.schema import validate
from tests.app.test_certificate_presenter import COMPLETE, Store, _theodolite
from tests.app.test_dcc_out import SCHEMA, needs_schema

NS = {"dcc": v.DCC_NAMESPACE}
DETAILS = dataclasses.replace(COMPLETE, lab_country="CN")


@pytest.fixture
def parts():
    view = mock.create_autospec(CertificateView, instance=True)
    presenter = CertificatePresenter(view, Store(), lambda: {}, mock.Mock())
    return presenter, view


@needs_schema
@pytest.mark.slow
def test_an_issued_certificate_gets_its_dcc_beside_it(parts, samples_dir, tmp_path):
    presenter, view = parts
    presenter.set_dcc_options(True, str(SCHEMA))
    assert presenter.dcc_options() == (True, str(SCHEMA))
    kind, result = _theodolite(samples_dir)
    view.edit_certificate_details.return_value = DETAILS
    view.choose_save_path.return_value = str(tmp_path / "c.pdf")
    assert presenter.export_certificate(kind, result, {}, "run.csv", [])
    xml = (tmp_path / "c.xml").read_bytes()
    assert validate(xml, SCHEMA) == []
    tree = etree.fromstring(xml)
    with presenter.open_register() as register:
        record = register.list()[0]
    assert tree.findtext(".//dcc:uniqueIdentifier", namespaces=NS) == record.number
    assert base64.b64decode(tree.findtext("dcc:document/dcc:dataBase64", namespaces=NS)) == \
        (tmp_path / "c.pdf").read_bytes()
    assert "its DCC (validated) written to" in view.show_status.call_args.args[0]


@pytest.mark.slow
def test_no_dcc_unless_asked_and_a_refused_one_issues_nothing(parts, samples_dir, tmp_path):
    presenter, view = parts
    kind, result = _theodolite(samples_dir)
    view.edit_certificate_details.return_value = DETAILS
    view.choose_save_path.return_value = str(tmp_path / "a.pdf")
    assert presenter.export_certificate(kind, result, {}, "run.csv", [])
    assert (tmp_path / "a.pdf").exists() and not (tmp_path / "a.xml").exists()
    # asked for, but the details lack the country the DCC must state: nothing issued
    presenter.set_dcc_options(True, "")
    view.edit_certificate_details.return_value = COMPLETE
    view.choose_save_path.return_value = str(tmp_path / "b.pdf")
    assert not presenter.export_certificate(kind, result, {}, "run.csv", [])
    assert "lab_country" in view.tell.call_args.args[1]
    assert not Path(tmp_path / "b.pdf").exists() and not (tmp_path / "b.xml").exists()
    with presenter.open_register() as register:
        assert len(register.list()) == 1


def test_the_details_dialog_has_the_dcc_switch_its_schema_folder_and_the_country(qtbot):
    from models.certificate.metadata import CertificateMetadata
    from widgets.certificate_dialog import CertificateDialog

    dialog = CertificateDialog(CertificateMetadata(lab_country="CN"))
    qtbot.addWidget(dialog)
    assert dialog.dcc_options() == (False, "")
    dialog.set_dcc_options(True, "/labs/dcc-3.3.0")
    assert dialog.dcc_options() == (True, "/labs/dcc-3.3.0")
    assert dialog.fields["lab_country"].text() == "CN"
    dialog.fields["lab_country"].setText("DE")
    assert dialog.metadata().lab_country == "DE"
