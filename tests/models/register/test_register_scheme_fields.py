"""reg72 #11: the register stepped over numbers issued under a scheme with other separators,
case or padding (AB-2026-005, AB-2026-6, ab-2026-0008, AB_2026_0009), but a scheme without
separators, ``AB{year}{seq:04d}``, issued AB20260001 beside AB-2026-0001: its digits run
together and no key met. A number is its scheme's fields (year, sequence, the letters of the
text), not its separators: such a number is skipped as issued."""

from __future__ import annotations

import datetime as dt

import pytest

from models.certificate.metadata import CertificateMetadata
from models.register.store import IssueRequest, Register, RegisterError

WHEN = dt.datetime(2026, 12, 6, 9, 0, tzinfo=dt.timezone.utc)


def _issue(register: Register, scheme: str, serial: str) -> str:
    meta = CertificateMetadata(approver="Dr. Li", calibration_date="2026-12-01",
                               item_serial=serial, number_scheme=scheme)
    return register.issue(IssueRequest("polygon", meta, '{"workbenches": {}}'),
                          lambda m, head="": f"%PDF {m.certificate_number}".encode()
                          )[0].number


def _fields(number: str) -> tuple[str, int, int]:
    """What the number prints, separators aside: its letters, its year (the first four
    digits of its digits) and its sequence (the rest), as a reader of it would take it."""
    letters = "".join(c for c in number if c.isalpha()).upper()
    digits = "".join(c for c in number if c.isdigit())
    return letters, int(digits[:4]), int(digits[4:])


@pytest.mark.parametrize(("first", "then"), [
    ("AB-{year}-{seq:04d}", "AB{year}{seq:04d}"),
    ("AB{year}{seq:04d}", "AB-{year}-{seq:04d}"),
    ("AB-{year}-{seq:04d}", "AB{year}{seq}"),
    ("AB/{year}/{seq:03d}", "ab{year}{seq:04d}"),
])
def test_a_scheme_without_separators_skips_the_fields_issued(tmp_path, first, then):
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}", timezone="UTC") as register:
        register.clock = lambda: WHEN
        issued = [_issue(register, first, f"S-{n}") for n in range(1, 4)]
        new = _issue(register, then, "S-9")
    assert [_fields(n) for n in issued] == [("AB", 2026, 1), ("AB", 2026, 2), ("AB", 2026, 3)]
    assert _fields(new) == ("AB", 2026, 4)  # the next sequence, none issued again


def test_other_letters_are_another_number(tmp_path):
    """The letters are fields too: CD20260001 is not AB-2026-0001."""
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}", timezone="UTC") as register:
        register.clock = lambda: WHEN
        _issue(register, "AB-{year}-{seq:04d}", "S-1")
        assert _issue(register, "CD{year}{seq:04d}", "S-2") == "CD20260001"


@pytest.mark.parametrize("typed", ["AB20260002", "ab2026/0002", "AB 2026 0002"])
def test_a_typed_number_of_an_issued_ones_letters_and_digits_is_refused(tmp_path, typed):
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}", timezone="UTC") as register:
        register.clock = lambda: WHEN
        issued = [_issue(register, "AB-{year}-{seq:04d}", f"S-{n}") for n in (1, 2)]
        meta = CertificateMetadata(approver="Dr. Li", calibration_date="2026-12-01",
                                   item_serial="S-9", certificate_number=typed)
        with pytest.raises(RegisterError) as refused:
            register.issue(IssueRequest("polygon", meta, '{"workbenches": {}}'),
                           lambda m, head="": b"%PDF")
        assert f"({issued[1]}) was issued on 2026-12-06" in str(refused.value)
        assert [r.number for r in register.list()] == issued[::-1]
