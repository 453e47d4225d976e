"""rev63 F1, F2, F3, F10: the register's "same item" and "same calibration" checks, by the
register API (the call the window's Amend…/Replace… and the command line make).

- F1: an item of no serial is told from another by its description and maker, in an
  amendment's check as in the one-calibration check;
- F2: an amendment's serial is compared as printed: a serial that prints otherwise, though it
  shares a look-alike key, is a correction, asked and stated;
- F3: the skeleton works on NFD: Latin "Ö" and Cyrillic "Ӧ" are one;
- F10: the skeleton is case-sensitive and never chained with case folding: "SN-L5" and
  "SN-I5" are two items."""

from __future__ import annotations

import datetime as dt

import pytest

from models.certificate.metadata import CertificateMetadata
from models.register.identifiers import same_identifier, same_serial, serial_lookalike
from models.register.store import (
    IssueRequest,
    LookalikeSerial,
    NotTheSameCalibration,
    Register,
    RegisterError,
    SameCalibrationIssued,
)

BASE = dict(item_manufacturer="Example", customer_name="Acme", issue_date="2026-11-24",
            number_scheme="AB-{year}-{seq:04d}", approver="Dr. Li",
            calibration_date="2026-11-20", item_description="Rotary table")
PROJECT = '{"format": "anglebench-project", "schema_version": 1, "workbenches": {}}'


def _render(meta) -> bytes:
    return f"%PDF {meta.certificate_number} {meta.item_serial} {meta.change_note}".encode()


def _meta(**changes) -> CertificateMetadata:
    return CertificateMetadata(**{**BASE, **changes})


@pytest.fixture
def register(tmp_path):
    with Register(f"sqlite:///{tmp_path}/register.sqlite") as reg:
        reg.clock = lambda: dt.datetime(2026, 11, 24, 10, 0, tzinfo=dt.timezone.utc)
        yield reg


def _original(register, another_lookalike_item=False, **changes):
    record, _pdf = register.issue(IssueRequest("theodolite", _meta(**changes), PROJECT, {}),
                                  _render, separate_calibration="",
                                  document_kind="calibration",
                                  another_lookalike_item=another_lookalike_item)
    return record


def _amend(register, number, confirmed=False, **changes):
    record, _pdf = register.issue(
        IssueRequest("theodolite", _meta(**changes), PROJECT, {}), _render, supersedes=number,
        change_note="typo in customer", separate_calibration="", document_kind="calibration",
        correction_confirmed=confirmed)
    return record


def test_f1_an_item_without_serial_is_not_amended_with_another_items_details(register):
    a = _original(register, item_serial="", item_description="Rotary table RT-1",
                  item_manufacturer="Acme Rotary")
    b = _original(register, item_serial="", item_description="Autocollimator AC-9",
                  item_manufacturer="Other Optics", customer_name="Other Customer")
    b_details = dict(item_serial="", item_description="Autocollimator AC-9",
                     item_manufacturer="Other Optics", customer_name="Other Customer")
    with pytest.raises(NotTheSameCalibration) as refused:
        _amend(register, a.number, **b_details)
    assert str(refused.value).startswith(
        f"{a.number} reports Rotary table RT-1 (Acme Rotary), which has no serial number, "
        "calibrated 2026-11-20; these details give Autocollimator AC-9 (Other Optics), "
        "calibrated 2026-11-20.")
    assert refused.value.corrections == (
        f"item (no serial number) corrected from Rotary table RT-1 (Acme Rotary) (on "
        f"{a.number}) to Autocollimator AC-9 (Other Optics)",
        f"customer corrected from Acme (on {a.number}) to Other Customer")  # #64 review F5
    assert str(refused.value).endswith(
        f"It also corrects: customer corrected from Acme (on {a.number}) to Other Customer.")
    # confirmed: still refused, that is B's calibration
    with pytest.raises(NotTheSameCalibration, match=f"{b.number} already reports"):
        _amend(register, a.number, confirmed=True, **b_details)
    assert [(r.number, r.item_description) for r in register.list() if r.status == "issued"] \
        == [(b.number, "Autocollimator AC-9"), (a.number, "Rotary table RT-1")]
    # a corrected description, confirmed, is issued and stated
    amended = _amend(register, a.number, confirmed=True, item_serial="",
                     item_description="Rotary table RT-2", item_manufacturer="Acme Rotary")
    assert amended.change_note == (
        f"item (no serial number) corrected from Rotary table RT-1 (Acme Rotary) (on "
        f"{a.number}) to Rotary table RT-2 (Acme Rotary); typo in customer")
    # the same item, its description in another case: no question
    assert _amend(register, amended.number, item_serial="", item_description="ROTARY TABLE RT-2",
                  item_manufacturer="Acme Rotary").change_note == "typo in customer"


@pytest.mark.parametrize(("old", "new"), [("XL-100", "XI-100"), ("AB-10-5", "AB-1-05"),
                                          ("SN 12-345", "SN 123-45"), ("K0L7", "KOI7"),
                                          ("Ai55", "A155"), ("LRA-0815", "LRA-O815")])
def test_f2_a_serial_printed_otherwise_is_asked_and_stated(register, old, new):
    original = _original(register, item_serial=old)
    with pytest.raises(NotTheSameCalibration) as refused:
        _amend(register, original.number, item_serial=new)
    assert str(refused.value).startswith(
        f"{original.number} reports serial number {old}, calibrated 2026-11-20; these details "
        f"give serial number {new}, calibrated 2026-11-20.")
    amended = _amend(register, original.number, confirmed=True, item_serial=new)
    assert amended.item_serial == new
    assert amended.change_note == (f"serial number corrected from {old} (on "
                                   f"{original.number}) to {new}; typo in customer")


def test_f2_the_serial_as_printed_amends_unasked(register):
    original = _original(register, item_serial="LRA-0815")
    assert _amend(register, original.number, item_serial="LRA-0815").change_note \
        == "typo in customer"


@pytest.mark.parametrize(("latin", "other"), [
    ("MÖ-0815", "M\u04e6-0815"), ("KÄ-7", "K\u04d2-7"), ("LË-5", "L\u0401-5"),
    ("AÉ-5", "A\u0388-5"), ("Aé-5", "A\u0435\u0301-5")])
def test_f3_a_letter_with_a_mark_meets_its_look_alike_of_another_script(register, latin, other):
    assert same_serial(latin, other) and same_identifier(latin, other)
    _original(register, item_serial=latin)
    with pytest.raises(SameCalibrationIssued):
        _original(register, item_serial=other)
    assert not same_serial("MO-0815", "MÖ-0815")


def test_f3_a_number_with_a_mark_is_issued_once(register):
    _original(register, certificate_number="KÄ-2026-0001", item_serial="A-1")
    with pytest.raises(RegisterError, match="KÄ-2026-0001"):
        _original(register, certificate_number="K\u04d2-2026-0001", item_serial="A-2")
    assert _original(register, certificate_number="KA-2026-0001",
                     item_serial="A-3").number == "KA-2026-0001"


@pytest.mark.parametrize(("one", "other"), [("SN-L5", "SN-I5"), ("SN-L5", "SN-15"),
                                            ("Ai55", "A155"), ("XL-100", "XI-100"),
                                            ("K0L7", "KOI7")])
def test_f10_serials_that_print_otherwise_are_two_items(register, one, other):
    """Two items, never one; one look-alike substitution apart, case aside ("SN-L5" and
    "SN-15"), the second is issued only with the user's word that it is another item
    (rev65 F7), still as an item of its own."""
    assert not same_serial(one, other)
    _original(register, item_serial=one, calibration_date="2026-11-04")
    confirm = {}
    if serial_lookalike(one, other):
        with pytest.raises(LookalikeSerial):
            _original(register, item_serial=other, calibration_date="2026-11-04")
        confirm = {"another_lookalike_item": True}
    second = _original(register, item_serial=other, calibration_date="2026-11-04", **confirm)
    assert second.change_note == "" and second.item_serial == other


@pytest.mark.parametrize(("one", "other"), [("SN-I5", "SN-l5"), ("SN-I5", "SN-15"),
                                            ("lra-0815", "LRA-0815"), ("LRA-0815", "LRA-O815")])
def test_f10_serials_that_print_alike_or_differ_by_case_are_one_item(register, one, other):
    assert same_serial(one, other)
    _original(register, item_serial=one, calibration_date="2026-11-04")
    with pytest.raises(SameCalibrationIssued):
        _original(register, item_serial=other, calibration_date="2026-11-04")


def test_m4_a_long_identifier_has_a_key():
    assert same_serial("1" * 5000, "0" + "1" * 5000)
