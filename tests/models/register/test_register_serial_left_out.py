"""Stop 67, a hostile user's view of the one-calibration check.

(b) An item of no serial: LRA-0815's calibration issued again with the serial left blank
("", "n/a", "-", "无") passed as another item, unasked — the check compared an item of no
serial only with items of no serial. Now, where a current certificate of the workbench and
date of calibration reports an item of the same description and maker with a serial (or,
the other way round, none where one is typed now), it is asked: issued only with the user's
word that it is another item, recorded in the register's chain.

(c) An amendment or replacement that corrects the item (its serial, its maker, an item of no
serial's description) onto a serial that looks like another item's, or onto no serial beside
an item of that description, was never asked: a correction confirmed to "1ra-0815" made a
second current certificate of LRA-0815's calibration. Now asked as an original is; its own
certificates (the one it corrects and those before) are not counted."""

from __future__ import annotations

import datetime as dt

import pytest

from models.certificate.metadata import CertificateMetadata
from models.register.store import (
    IssueRequest,
    LookalikeSerial,
    NotTheSameCalibration,
    Register,
    RegisterError,
    SameCalibrationIssued,
)

PROJECT = '{"format": "anglebench-project", "schema_version": 1, "workbenches": {}}'
ISSUED = dt.datetime(2028, 6, 1, 10, 0, tzinfo=dt.timezone.utc)
MAKER = "Möller-Wedel Optical GmbH"
DAY = "2026-11-20"


def render(meta: CertificateMetadata, head: str = "") -> bytes:
    return f"%PDF {meta.certificate_number} {meta.revision} head {head}".encode()


def meta(serial: str, maker: str = MAKER, day: str = DAY,
         description: str = "24-face polygon") -> CertificateMetadata:
    return CertificateMetadata(item_serial=serial, item_manufacturer=maker,
                               item_description=description, customer_name="Customer X",
                               calibration_date=day, number_scheme="AB-{year}-{seq:04d}",
                               approver="Dr. Li")


@pytest.fixture
def register(register_url):
    with Register(register_url, timezone="UTC") as reg:
        reg.clock = lambda: ISSUED
        yield reg


def issue(register: Register, details: CertificateMetadata, workbench: str = "polygon",
          **options):
    return register.issue(IssueRequest(workbench, details, PROJECT), render,
                          **{"separate_calibration": "", **options})[0]


def refused(register: Register, details: CertificateMetadata, **options):
    """The error ``details`` are refused with (None: issued)."""
    try:
        issue(register, details, **options)
    except RegisterError as exc:
        return exc
    return None


@pytest.mark.parametrize("blank", ["", "n/a", "-", "无", "None"])
def test_a_serial_left_out_does_not_pass_the_one_calibration_check(register, blank):
    first = issue(register, meta("LRA-0815"))
    exc = refused(register, meta(blank))
    assert isinstance(exc, LookalikeSerial), exc  # asked, as a look-alike serial is
    assert exc.numbers == (first.number,)
    assert str(exc).startswith(f"24-face polygon ({MAKER}) has no serial number, but an "
                               "item of that description and maker calibrated 2026-11-20 has "
                               f"one in the register: LRA-0815 ({first.number})"), exc
    assert "--another-lookalike-item" in str(exc)
    assert [r.number for r in register.list()] == [first.number]
    # the window asks it before the file name
    [question] = register.confirmations_needed("polygon", meta(blank))
    assert question.numbers == (first.number,)
    # the user's word: another item, which has none; recorded in the chain
    second = issue(register, meta(blank), another_lookalike_item=True)
    [said] = register.lookalike_serial_confirmations(second.number)
    assert said["others"] == [{"number": first.number, "serial": "LRA-0815",
                               "manufacturer": MAKER}]
    assert register.audit() == []


def test_a_serial_typed_after_the_item_was_issued_without_one_is_asked(register):
    first = issue(register, meta(""))
    exc = refused(register, meta("LRA-0815"))
    assert isinstance(exc, LookalikeSerial) and exc.numbers == (first.number,), exc
    assert str(exc).startswith(f"{first.number} reports 24-face polygon ({MAKER}), which has "
                               "no serial number, calibrated 2026-11-20: this may be that "
                               "item with its serial LRA-0815 typed now"), exc
    assert issue(register, meta("LRA-0815"), another_lookalike_item=True).number


def test_a_serial_left_out_is_asked_only_of_that_calibrations_item(register):
    """Another description, another maker, another date or workbench, a withdrawn
    certificate: another item, unasked. A side naming no maker is any maker's."""
    first = issue(register, meta("LRA-0815"))
    exc = refused(register, meta("", maker="", description="24-face  POLYGON"))
    assert isinstance(exc, LookalikeSerial) and exc.numbers == (first.number,), exc
    for other in (meta("", description="Autocollimator"), meta("", maker="Zeta Instruments"),
                  meta("", day="2026-11-21")):
        assert refused(register, other) is None, other
    assert refused(register, meta("", description="24-face  POLYGON"),
                   workbench="theodolite") is None
    gone = issue(register, meta("LRA-0816", day="2026-11-25", description="Encoder"))
    register.withdraw(gone.number, "wrong item")
    assert refused(register, meta("", day="2026-11-25", description="Encoder")) is None


def test_two_items_of_no_serial_are_still_the_one_calibration_check(register):
    issue(register, meta(""))
    assert isinstance(refused(register, meta("n/a")), SameCalibrationIssued)


def _amend(register, number, details, **options):
    return issue(register, details, supersedes=number, change_note="typo",
                 correction_confirmed=True, **options)


def test_an_amendment_onto_a_lookalike_serial_is_asked(register):
    other = issue(register, meta("SN-77"))
    lra = issue(register, meta("LRA-0815"))
    # the correction confirmed is not the word that the item is another than LRA-0815's
    for typed in ("1ra-0815", "LRA-o815", "1ra-o815"):
        exc = refused(register, meta(typed), supersedes=other.number, change_note="typo",
                      correction_confirmed=True)
        assert isinstance(exc, LookalikeSerial), (typed, exc)
        assert exc.numbers == (lra.number,), typed
        assert str(exc).startswith(f"serial {typed} is in no certificate of the register, "
                                   f"but looks like LRA-0815 of {MAKER} ({lra.number})"), exc
    # unconfirmed, the correction is asked first, as before
    assert isinstance(refused(register, meta("1ra-0815"), supersedes=other.number,
                              change_note="typo"), NotTheSameCalibration)
    assert register.get(other.number).status == "issued"
    amended = _amend(register, other.number, meta("1ra-0815"), another_lookalike_item=True)
    assert amended.number == f"{other.number}-A1"
    [said] = register.lookalike_serial_confirmations(amended.number)
    assert said["others"] == [{"number": lra.number, "serial": "LRA-0815",
                               "manufacturer": MAKER}]
    assert register.audit() == []


def test_an_amendment_onto_no_serial_beside_that_items_certificate_is_asked(register):
    lra = issue(register, meta("LRA-0815"))
    other = issue(register, meta("SN-77"))
    exc = refused(register, meta(""), supersedes=other.number, change_note="typo",
                  correction_confirmed=True)
    assert isinstance(exc, LookalikeSerial) and exc.numbers == (lra.number,), exc
    assert _amend(register, other.number, meta(""), another_lookalike_item=True).number


def test_an_amendment_is_not_asked_about_its_own_certificates_or_an_unchanged_item(register):
    """The certificate corrected and those it superseded are that calibration's: a serial
    corrected from LRA-0815 to "1ra-0815" is asked as a correction (and stated), not as a
    look-alike of itself; an amendment that keeps its item asks nothing more."""
    first = issue(register, meta("LRA-0815"))
    a1 = _amend(register, first.number, meta("LRA-0815"))
    a2 = _amend(register, a1.number, meta("1ra-0815"))
    assert a2.change_note.startswith("serial number corrected from LRA-0815")
    # another item confirmed as such keeps its look-alike: amended unasked
    lra = issue(register, meta("LRA-0815", day="2027-01-15"))
    assert lra.number
    lookalike = issue(register, meta("lRA-O8I5", day="2027-01-16"),
                      another_lookalike_item=True)
    assert _amend(register, lookalike.number, meta("lRA-O8I5", day="2027-01-16")).number
    assert register.audit() == []


def test_an_amendment_names_the_very_certificate_it_amends(register):
    """Guard (passes before stop 67 too): an amendment of a number that only looks like a
    certificate's ("AB-2028-OOO1", "ab-2028-0001") is refused, nothing issued or
    superseded: an amendment names the very certificate it amends."""
    first = issue(register, meta("LRA-0815"))
    for alike in (first.number.replace("0", "O"), first.number.lower(), first.number + " "):
        exc = refused(register, meta("LRA-0815"), supersedes=alike, change_note="typo")
        assert isinstance(exc, RegisterError) and "no certificate or test report" in str(exc), \
            (alike, exc)
    assert [(r.number, r.status) for r in register.list()] == [(first.number, "issued")]
