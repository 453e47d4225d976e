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
    # another item (the same one issued again would be refused as issued, #61)
    view.edit_certificate_details.return_value = dataclasses.replace(COMPLETE, item_serial="T-2")
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


def test_the_dcc_settings_are_kept_with_the_lab_defaults_paths_only(parts, tmp_path):
    """The schema folder and the signing key, certificate and trusted certificate are lab
    settings: kept in the lab defaults (as paths; a key's content is never stored), kept
    when the details' lab defaults are saved again; a schema folder kept before in the
    window setting is still read."""
    import json

    from app.certificate_presenter import DCC_SCHEMA_KEY, LAB_DEFAULTS_KEY

    presenter, _ = parts
    presenter.store.setValue(DCC_SCHEMA_KEY, "/old/dcc")  # where it was kept before
    assert presenter.dcc_options() == (False, "/old/dcc")
    key = tmp_path / "lab.key"
    key.write_text("-----BEGIN PRIVATE KEY-----\nSECRET\n-----END PRIVATE KEY-----\n")
    presenter.set_dcc_options(True, "/labs/dcc")
    presenter.set_dcc_signing_paths(str(key), "/labs/lab.pem", "/labs/ca.pem")
    assert presenter.dcc_options() == (True, "/labs/dcc")
    assert presenter.dcc_signing_paths() == (str(key), "/labs/lab.pem", "/labs/ca.pem")
    stored = presenter.store.value(LAB_DEFAULTS_KEY)
    assert json.loads(stored)["dcc_schema_dir"] == "/labs/dcc" and "SECRET" not in stored
    presenter.save_lab_defaults({"lab_name": "Lab"}, "theodolite")  # the details' own save
    assert presenter.dcc_options()[1] == "/labs/dcc"
    assert presenter.dcc_signing_paths()[0] == str(key)
    assert presenter.lab_defaults()["lab_name"] == "Lab"


@pytest.mark.slow
def test_a_dcc_issued_in_the_window_is_signed_with_the_lab_defaults_key(parts, samples_dir,
                                                                         tmp_path, monkeypatch):
    from models.dcc import signature
    from tests.dcc_documents import self_signed

    monkeypatch.delenv(signature.KEY_ENV_VAR, raising=False)
    monkeypatch.delenv(signature.CERT_ENV_VAR, raising=False)
    presenter, view = parts
    key, cert = self_signed(tmp_path)
    (tmp_path / "lab.key").write_bytes(key)
    (tmp_path / "lab.pem").write_bytes(cert)
    presenter.set_dcc_options(True, str(SCHEMA) if SCHEMA else "")
    presenter.set_dcc_signing_paths(str(tmp_path / "lab.key"), str(tmp_path / "lab.pem"), "")
    kind, result = _theodolite(samples_dir)
    view.edit_certificate_details.return_value = DETAILS
    view.choose_save_path.return_value = str(tmp_path / "s.pdf")
    assert presenter.export_certificate(kind, result, {}, "run.csv", [])
    xml = (tmp_path / "s.xml").read_bytes()
    assert signature.has_signature(xml)
    check = signature.verify(xml, cert)
    assert check.problems == () and check.trusted


def test_the_details_dialog_has_the_signing_paths(qtbot):
    from models.certificate.metadata import CertificateMetadata
    from widgets.certificate_dialog import CertificateDialog

    dialog = CertificateDialog(CertificateMetadata(lab_country="CN"))
    qtbot.addWidget(dialog)
    assert dialog.dcc_signing_paths() == ("", "", "")
    dialog.set_dcc_signing_paths("/k.pem", "/c.pem", "/t.pem")
    assert dialog.dcc_signing_paths() == ("/k.pem", "/c.pem", "/t.pem")
    assert dialog.findChild(type(dialog.dcc_schema), "dcc_signing_key").text() == "/k.pem"
