"""A number that reads as an amendment's is the register's own: an original or a
replacement numbered "<number>-A<n>" in any writing the commit's check takes as one
(separators, case, look-alikes, zeros, a separator between "A" and the count) is refused,
typed or given by a number scheme, for any number, issued or not (stop 63's note: a new
certificate "AB-2026-0001-A 1" read to the customer as an amendment of AB-2026-0001 that
never happened); the register's own amendments are still numbered so."""

from __future__ import annotations

import datetime as dt

import pytest

from models.certificate.metadata import CertificateMetadata
from models.register.store import IssueRequest, Register, RegisterError

META = CertificateMetadata(item_serial="RX-1", item_description="Rotary encoder",
                           item_manufacturer="Acme Optics", customer_name="Acme Optics",
                           calibration_date="2026-11-20", number_scheme="AB-{year}-{seq:04d}",
                           approver="Dr. Li")
PROJECT = '{"format": "anglebench-project", "schema_version": 1, "workbenches": {}}'
ISSUED = dt.datetime(2026, 11, 24, 10, 0, tzinfo=dt.timezone.utc)


def render(meta: CertificateMetadata) -> bytes:
    return f"%PDF {meta.certificate_number} {meta.revision} {meta.supersedes}".encode()


def issue(register: Register, **changes):
    meta = CertificateMetadata(**{**META.to_dict(), "standards": (), **changes})
    return register.issue(IssueRequest("polygon", meta, PROJECT), render)[0]


@pytest.fixture
def register(tmp_path):
    with Register(f"sqlite:///{tmp_path / 'register.sqlite'}", timezone="UTC") as reg:
        reg.clock = lambda: ISSUED
        yield reg


#: each issued as a new original by the version before (its check read "-A" and digits
#: at the end of the number, its skeleton key or its folded key only)
IMITATIONS = ["AB-2026-0001-A 1", "AB-2026-0001-a-1", "AB-2026-0001-A-1", "AB-2026-0001 A-01",
              "AB-2026-0001-\u0410 1",  # a Cyrillic "А", a space
              "AB-2026-0001\uff0d\u0430\uff0d1",  # full-width dashes, a Cyrillic "а"
              "AB-2026-0001-\u0251-1",  # Latin alpha
              "AB-2026-0001-a-l",  # "l" for 1
              "AB-2026-0009-a 2"]  # the form of a number never issued


@pytest.mark.parametrize("typed", IMITATIONS)
def test_a_typed_number_that_reads_as_an_amendment_is_refused_saying_why(register, typed):
    first = issue(register)
    with pytest.raises(RegisterError, match="reads as an amendment's number .*kept for "
                       "amendments, which the register numbers itself"):
        issue(register, certificate_number=typed, item_serial="OTHER")
    assert [r.number for r in register.list()] == [first.number]
    # the register's own amendment is numbered as before, the first one "A1"
    amended = register.issue(IssueRequest("polygon", META, PROJECT), render,
                             supersedes=first.number, change_note="address")[0]
    assert (amended.number, amended.revision) == ("AB-2026-0001-A1", "amendment 1")
    assert register.audit(pdfs=True) == []


def test_a_scheme_that_gives_an_amendments_number_is_refused(register):
    """Re-numbering past the check: a scheme "AB-2026-0001-A{seq}" allocated "AB-2026-0001-A1"
    for a new original (and for a replacement) without a word."""
    first = issue(register)
    with pytest.raises(RegisterError, match="the number scheme 'AB-2026-0001-A \\{seq\\}' "
                       "gives AB-2026-0001-A 1, which reads as an amendment's number"):
        issue(register, number_scheme="AB-2026-0001-A {seq}", item_serial="OTHER")
    with pytest.raises(RegisterError, match="reads as an amendment's number"):
        register.issue(IssueRequest("polygon", CertificateMetadata(**{
            **META.to_dict(), "standards": (), "number_scheme": "AB-2026-0001-a{seq:02d}"}),
            PROJECT), render, supersedes=first.number, replacement=True, change_note="x")
    assert [r.number for r in register.list()] == [first.number]


@pytest.mark.parametrize("number", ["AB-2026-0001", "AB-2026-0001-B1", "AB-2026-0001-A",
                                    "AB-2026-0001-AX1", "AB-2026-A", "A-0001", "AB-2026-0001A1x",
                                    "CAL-2026-0001"])
def test_numbers_of_other_forms_are_not_taken_for_amendments(number):
    from models.register.identifiers import reads_as_amendment

    assert not reads_as_amendment(number)
    assert reads_as_amendment(number + "-A1") and reads_as_amendment(number + "-a 2")
