"""One calibration, one current certificate (ISO/IEC 17025 7.8.8), per maker's item: a
serial number is unique only within its maker, so two makers' serial "001" calibrated the
same day are two calibrations (stop 63's note: the second was refused as the first's,
compared by the serial alone); the same maker however it prints is one, and a maker
corrected by an amendment never lands on another current certificate's calibration."""

from __future__ import annotations

import datetime as dt

import pytest

from models.certificate.metadata import CertificateMetadata
from models.register.store import (
    AnotherMakersItem,
    IssueRequest,
    NotTheSameCalibration,
    Register,
    SameCalibrationIssued,
)

PROJECT = '{"format": "anglebench-project", "schema_version": 1, "workbenches": {}}'
ISSUED = dt.datetime(2026, 11, 25, 10, 0, tzinfo=dt.timezone.utc)


def render(meta: CertificateMetadata, head: str = "") -> bytes:
    return f"%PDF {meta.certificate_number} {meta.revision} head {head}".encode()


def meta(maker: str, day: str = "2026-11-20", serial: str = "001") -> CertificateMetadata:
    return CertificateMetadata(item_serial=serial, item_manufacturer=maker,
                               item_description="24-face polygon", customer_name="Acme Optics",
                               calibration_date=day, number_scheme="AB-{year}-{seq:04d}",
                               approver="Dr. Li")


@pytest.fixture
def register(register_url):
    with Register(register_url, timezone="UTC") as reg:
        reg.clock = lambda: ISSUED
        yield reg


def issue(register: Register, maker: str, day: str = "2026-11-20", **options):
    return register.issue(IssueRequest("polygon", meta(maker, day), PROJECT), render,
                          **{"separate_calibration": "", **options})[0]


def test_two_makers_serial_001_calibrated_the_same_day_are_two_calibrations(register):
    acme = issue(register, "Acme Optics")
    # refused as Acme's calibration before; asked now (rev65 F1: a maker spelt otherwise is
    # no other maker), and issued when confirmed another maker's item
    with pytest.raises(AnotherMakersItem):
        issue(register, "Zeta Instruments")
    zeta = issue(register, "Zeta Instruments", another_makers_item=True)
    assert zeta.revision == "original" and zeta.supersedes is None
    assert register.reports_calibration("polygon", meta("Zeta Instruments")) == (zeta.number,)
    # the same maker however it prints, or a certificate naming none, is the same item
    for maker in ("ACME optics", "\u0410cme Optics", ""):
        with pytest.raises(SameCalibrationIssued) as refused:
            issue(register, maker)
        assert acme.number in refused.value.numbers
    assert len(register.list()) == 2


def test_a_maker_corrected_onto_another_current_calibration_is_refused(register):
    """Laundering by amendment: Zeta's "001" amended to Acme's maker (confirmed) would be a
    second current certificate of Acme's "001" calibrated that day."""
    acme = issue(register, "Acme Optics")
    zeta = issue(register, "Zeta Instruments", another_makers_item=True)
    with pytest.raises(NotTheSameCalibration, match=f"{acme.number} already reports serial "
                       f"number 001, calibrated 2026-11-20: a correction of {zeta.number}"):
        register.issue(IssueRequest("polygon", meta("\u0410cme optics"), PROJECT), render,
                       supersedes=zeta.number, change_note="maker",
                       correction_confirmed=True)
    amended = register.issue(IssueRequest("polygon", meta("Zeta Instruments GmbH"), PROJECT),
                             render, supersedes=zeta.number, change_note="maker's name",
                             correction_confirmed=True)[0]
    assert amended.change_note.startswith("manufacturer corrected from Zeta Instruments")
    assert register.audit() == []
