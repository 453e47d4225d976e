"""A number that reads as an amendment of a certificate in the register is the register's
own: an original or a replacement numbered "<number>-A<n>" (or "A<n>", "-Amendment <n>",
"-Amd<n>", "-Rev <n>" …) in any writing the commit's check takes as one (separators, case,
marks, look-alikes, zeros, any dash) is refused, typed or given by a number scheme, where
<number> is a certificate's (stop 63's note: a new certificate "AB-2026-0001-A 1" read to the
customer as an amendment of AB-2026-0001 that never happened; rev65 F5: "AB-2026-0001A1",
"-Amendment 1", "-Ạ1" were issued); and a number that a certificate's number reads as an
amendment of is refused too. The form alone is not (rev65 F6: "KAL-2026-A17", "2026-A-0001"
are labs' schemes). The register's own amendments are still numbered "-A<n>"."""

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
              # rev65 F5: each issued as a new original by the version before
              "AB-2026-0001-A\u03231",  # A with a combining dot below
              "AB-2026-0001-A\u03321",  # A with a combining low line
              "AB-2026-0001-A1\u0332",  # the count with a combining low line
              "AB-2026-0001A1",  # no separator
              "AB-2026-0001-Amendment 1", "AB-2026-0001-Amd1", "AB-2026-0001-A No.1",
              "AB-2026-0001-Rev 1",
              "AB-2026-0001\u1428A1",  # Canadian syllabics final short horizontal stroke
              "AB-2026-0001\u02c9A1",  # modifier letter macron as the dash
              "AB-2026-0001-\u00c21",  # Â
              "AB-2026-0001-\u1e001",  # Ḁ, precomposed
              "AB-2026-0001-\u01ce1",  # ǎ
              "AB-2026-0001-\u02011",  # ȁ
              "AB-2026-0001-\u023a1"]  # Ⱥ, no decomposition


@pytest.mark.parametrize("typed", IMITATIONS)
def test_a_typed_number_that_reads_as_an_amendment_is_refused_saying_why(register, typed):
    first = issue(register)
    with pytest.raises(RegisterError, match="reads as an amendment's number of AB-2026-0001 "
                       "\\(issued on 2026-11-24\\).*amendments are numbered by the register "
                       "itself"):
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


#: rev65 F6: labs' own numbering schemes, each refused by the version before, for originals
#: and replacements alike, though no certificate's number precedes the "A"
SCHEMES = [("{year}-A-{seq:04d}", "2026-A-0001"), ("KAL-{year}-A{seq:04d}", "KAL-2026-A0001"),
           ("D-K-15070-A-{seq}", "D-K-15070-A-1"), ("LAB-{year}-A-{seq}", "LAB-2026-A-1"),
           ("CAL-A{seq}", "CAL-A1")]


@pytest.mark.parametrize(("scheme", "number"), SCHEMES)
def test_a_scheme_ending_in_a_and_a_count_is_used_when_nothing_precedes_it(register, scheme,
                                                                         number):
    first = issue(register, number_scheme=scheme)
    assert (first.number, first.revision) == (number, "original")
    replacement = register.issue(IssueRequest("polygon", CertificateMetadata(**{
        **META.to_dict(), "standards": (), "number_scheme": scheme}), PROJECT), render,
        supersedes=first.number, replacement=True, change_note="x")[0]
    assert replacement.revision == "replacement" and replacement.number != number
    amended = register.issue(IssueRequest("polygon", CertificateMetadata(**{
        **META.to_dict(), "standards": (), "number_scheme": scheme}), PROJECT), render,
        supersedes=replacement.number, change_note="address")[0]
    assert amended.number == f"{replacement.number}-A1"
    assert register.audit(pdfs=True) == []


@pytest.mark.parametrize("typed", ["2026-A-0001", "KAL-2026-A17", "D-K-15070-A-17",
                                   "LAB-2026-A-4", "CAL-A1", "AB-2026-0009-a 2"])
def test_a_typed_number_of_the_form_is_issued_when_nothing_precedes_it(register, typed):
    issue(register)
    record = issue(register, certificate_number=typed, item_serial="OTHER")
    assert (record.number, record.revision) == (typed, "original")


def test_a_scheme_is_refused_when_a_certificate_number_precedes_its_a(register):
    issue(register, certificate_number="KAL-2026")
    with pytest.raises(RegisterError, match="the number scheme 'KAL-\\{year\\}-A\\{seq\\}' "
                       "gives KAL-2026-A1, which reads as an amendment's number of KAL-2026"):
        issue(register, number_scheme="KAL-{year}-A{seq}", item_serial="OTHER")


def test_a_number_a_certificate_reads_as_an_amendment_of_is_refused(register):
    """The other way: "KAL-2026-A17" issued, "KAL-2026" typed (in any writing) would be
    taken for the certificate that KAL-2026-A17 amends; a scheme skips such a number."""
    issue(register, certificate_number="KAL-2026-A17")
    for typed in ("KAL-2026", "kal 2026", "KAL\u00b72026"):
        with pytest.raises(RegisterError, match=f"certificate number {typed}: KAL-2026-A17, "
                           "issued on 2026-11-24, reads as an amendment's number of it"):
            issue(register, certificate_number=typed, item_serial="OTHER")
    issue(register, certificate_number="AB-2026-0002-Amendment 1", item_serial="OTHER")
    allocated = [issue(register, item_serial=f"S-{n}").number for n in range(3)]
    assert allocated == ["AB-2026-0001", "AB-2026-0003", "AB-2026-0004"]  # 0002 skipped
    assert register.audit(pdfs=True) == []
