"""rev63 F4: a pending Amend…/Replace… is ended when the register's location changes: its
number is the old register's, and it amended the new register's certificate of that number
(another item, another customer) after a question that named only the number."""

from __future__ import annotations

import dataclasses
from unittest import mock

import pytest

from app.certificate_presenter import CertificatePresenter, CertificateView, PendingRevision
from tests.app.test_certificate_presenter import COMPLETE, Store, _theodolite


@pytest.mark.slow
@pytest.mark.usefixtures("pdf_stand_in")  # no PDF read: of the register's records
def test_a_register_change_ends_the_pending_amendment(samples_dir, tmp_path, monkeypatch):
    monkeypatch.delenv("ANGLEBENCH_REGISTER")  # the window's setting is the register
    view = mock.create_autospec(CertificateView, instance=True)
    presenter = CertificatePresenter(view, Store(), dict, mock.Mock())
    kind, result = _theodolite(samples_dir)
    first, second = tmp_path / "r1.sqlite", tmp_path / "r2.sqlite"
    other = dataclasses.replace(COMPLETE, item_serial="XY-99", customer_name="Other Ltd")
    for register, details in ((second, other), (first, COMPLETE)):  # each its AB-2026-0001
        presenter.set_register_url(str(register))
        view.edit_certificate_details.return_value = details
        view.choose_save_path.return_value = str(tmp_path / f"{register.stem}.pdf")
        assert presenter.export_certificate(kind, result, {}, "run.csv", [])
        assert "Certificate AB-2026-0001 issued" in view.show_status.call_args.args[0]
    presenter.start_revision(PendingRevision("theodolite", "AB-2026-0001"))  # R1's
    presenter.set_register_url(str(first))  # the same register: nothing ends
    assert presenter.pending == PendingRevision("theodolite", "AB-2026-0001")
    presenter.set_register_url(str(second))  # Settings › register location
    assert presenter.pending is None
    assert view.show_status.call_args.args[0] == (
        "The amendment or replacement of AB-2026-0001 is ended: the register's location "
        "changed.")
    view.edit_certificate_details.return_value = COMPLETE
    view.ask_change_note.return_value = "address corrected"
    view.choose_save_path.return_value = str(tmp_path / "after.pdf")
    presenter.export_certificate(kind, result, {}, "run.csv", [])
    with presenter.open_register() as register:  # R2's AB-2026-0001 (XY-99) untouched
        records = {r.number: (r.status, r.item_serial) for r in register.list()}
    assert records["AB-2026-0001"] == ("issued", "XY-99")
    assert records["AB-2026-0002"] == ("issued", "T-1")  # an original of its own
    assert not any(number.startswith("AB-2026-0001-") for number in records)
    view.ask_change_note.assert_not_called()
