"""A maker's name spelt otherwise is the same maker (rev65): a second current certificate of
one calibration is never issued by writing the maker another way (F1), nor for an item with
no serial by leaving the maker out or adding its legal form (F9); a maker that really differs
with the same serial and date is asked about, and the answer recorded in the register's chain;
an item named without its maker never borrows another maker's due date (F4)."""

from __future__ import annotations

import datetime as dt

import pytest

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.register.store import IssueRequest, Register, SameCalibrationIssued

PROJECT = '{"format": "anglebench-project", "schema_version": 1, "workbenches": {}}'
ISSUED = dt.datetime(2026, 11, 25, 10, 0, tzinfo=dt.timezone.utc)
FIRST = "Möller-Wedel Optical GmbH"


def render(meta: CertificateMetadata, head: str = "") -> bytes:
    return f"%PDF {meta.certificate_number} {meta.revision} head {head}".encode()


def meta(maker: str, serial: str = "LRA-0815", day: str = "2026-11-20",
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


def issue(register: Register, details: CertificateMetadata, **options):
    return register.issue(IssueRequest("polygon", details, PROJECT), render,
                          **{"separate_calibration": "", **options})[0]


def _refused(register: Register, details: CertificateMetadata, **options):
    """The error an original of ``details`` is refused with (None: it was issued)."""
    from models.register.store import RegisterError

    try:
        issue(register, details, **options)
    except RegisterError as exc:
        return exc
    return None


@pytest.mark.parametrize("one,other,same", [
    ("Möller-Wedel Optical GmbH", "Moeller-Wedel Optical", True),
    ("Möller-Wedel Optical GmbH", "Mo\u0308ller Wedel Optical GmbH & Co. KG", True),
    ("Müller & Co. KG", "Mueller", True), ("Straße AG", "Strasse", True),
    ("Acme S.p.A.", "ACME Inc.", True), ("\u0410cme Ltd", "Acme Limited", True),
    ("上海光学仪器有限公司", "上海光学仪器股份有限公司", True), ("株式会社ニコン", "ニコン", True),
    ("Möller-Wedel Optical GmbH", "Möller-Wedel", False),
    ("Acme Optics", "Zeta Instruments", False), ("AG", "KG", False)])
def test_a_maker_key_joins_the_spellings_people_use(one, other, same):
    from models.register.maker_names import maker_key, same_maker_name

    assert (maker_key(one) == maker_key(other)) is same
    assert same_maker_name(one, other) is same
    assert maker_key("AG") and not same_maker_name("", "Acme")  # never empty, blank is no name


# -- F1: the maker spelt otherwise ----------------------------------------------------------
@pytest.mark.parametrize("maker", [
    "Moller-Wedel Optical GmbH", "Moeller-Wedel Optical GmbH", "Möller-Wedel Optical",
    "MöllerWedel Optical GmbH", "Möller-Wedel Optical GmbH & Co. KG", "MOELLER WEDEL OPTICAL",
    "Möller-Wedel"])
def test_a_makers_name_spelt_otherwise_is_no_second_original_unasked(register, maker):
    """rev65 F1: each of these was issued as a second current certificate of LRA-0815's
    calibration of 2026-11-20, no question asked, nothing in the audit."""
    first = issue(register, meta(FIRST))
    refused = _refused(register, meta(maker))
    assert [r.number for r in register.list()] == [first.number]
    from models.register.store import AnotherMakersItem

    assert isinstance(refused, SameCalibrationIssued | AnotherMakersItem), refused
    assert refused.numbers == (first.number,)


@pytest.mark.parametrize("maker", [
    "Moller-Wedel Optical GmbH", "Moeller-Wedel Optical GmbH", "MöllerWedel Optical GmbH",
    "Möller-Wedel Optical GmbH & Co. KG", "Möller-Wedel Optical"])
def test_one_maker_by_its_key_cannot_be_confirmed_as_another(register, maker):
    """Equal maker keys are one maker: saying "another maker's item" does not issue a second
    original of the calibration; only a separate calibration, saying why, does."""
    first = issue(register, meta(FIRST))
    refused = _refused(register, meta(maker), another_makers_item=True)
    assert isinstance(refused, SameCalibrationIssued) and refused.numbers == (first.number,)
    # and the history of the item is one, however it is spelt
    assert [r.number for r in register.history("LRA-0815", maker)] == [first.number]


def test_another_makers_serial_is_issued_when_confirmed_and_the_answer_recorded(register,
                                                                                capsys):
    from models.register.store import AnotherMakersItem

    acme = issue(register, meta("Acme Optics GmbH", serial="001"))
    refused = _refused(register, meta("Zeta Instruments", serial="001"))
    assert isinstance(refused, AnotherMakersItem) and refused.numbers == (acme.number,)
    assert "--another-makers-item" in str(refused)
    assert len(register.list()) == 1
    zeta = issue(register, meta("Zeta Instruments", serial="001"), another_makers_item=True)
    assert zeta.revision == "original" and not zeta.change_note
    [said] = register.another_maker_confirmations(zeta.number)
    assert said["manufacturer"] == "Zeta Instruments"
    assert said["others"] == [{"number": acme.number, "manufacturer": "Acme Optics GmbH"}]
    assert register.another_maker_confirmations(acme.number) == []
    assert register.audit() == []
    # two histories, two due dates
    assert [r.number for r in register.history("001", "ACME optics")] == [acme.number]
    assert [r.number for r in register.history("001", "Zeta Instruments")] == [zeta.number]
    assert main(["register", "--register", register.url, "show", zeta.number]) == 0
    assert (f"another maker's item, as {said['os_user']} confirmed at issue "
            f"({said['recorded_at']}): Zeta Instruments, not the maker of {acme.number} "
            "(Acme Optics GmbH)") in capsys.readouterr().out
    # the confirmation is in the chain: changing it is found
    with register.engine.begin() as conn:
        conn.exec_driver_sql("UPDATE entries SET body_json = '{}' WHERE kind = 'another_maker'")
    assert any("hash chain is broken" in str(p) for p in register.audit())


def test_an_amendment_cannot_move_an_item_onto_one_maker_spelt_otherwise(register):
    """rev65 F1 (r3b): Zeta's LRA-0815 amended (confirmed) to the maker "Moeller-Wedel
    Optical" passed the corrected-maker check, a second current certificate of Möller-Wedel's
    calibration of that day."""
    from models.register.store import NotTheSameCalibration

    first = issue(register, meta(FIRST))
    zeta = issue(register, meta("Zeta Instruments"), separate_calibration=None)  # unchecked
    with pytest.raises(NotTheSameCalibration, match=f"{first.number} already reports serial "
                       "number LRA-0815, calibrated 2026-11-20"):
        issue(register, meta("Moeller-Wedel Optical"), supersedes=zeta.number,
              change_note="maker", correction_confirmed=True)
    assert {r.number for r in register.list() if r.status == "issued"} == {first.number,
                                                                            zeta.number}


# -- F9: an item with no serial ----------------------------------------------------------------
@pytest.mark.parametrize("maker,serial", [("", ""), ("", "n/a"), ("Acme GmbH", ""),
                                          ("ACME", "-")])
def test_an_item_without_a_serial_is_the_same_item_whatever_its_makers_spelling(
        register, maker, serial):
    """rev65 F9: a blank maker and "Acme GmbH" issued a second original of the rotary table
    of Acme calibrated that day."""
    first = issue(register, meta("Acme", serial="", description="Rotary table RT-1"))
    refused = _refused(register, meta(maker, serial=serial, description="Rotary table RT-1"))
    assert isinstance(refused, SameCalibrationIssued) and refused.numbers == (first.number,)


def test_an_item_without_a_serial_of_another_maker_is_asked_about(register):
    from models.register.store import AnotherMakersItem

    first = issue(register, meta("Acme", serial="", description="Rotary table RT-1"))
    refused = _refused(register, meta("Zeta", serial="", description="rotary table RT-1"))
    assert isinstance(refused, AnotherMakersItem) and refused.numbers == (first.number,)
    issue(register, meta("Zeta", serial="", description="rotary table RT-1"),
          another_makers_item=True)
    # another item altogether is no question
    issue(register, meta("Zeta", serial="", description="Dividing head DH-2"))
    assert len(register.list()) == 3 and register.audit() == []


# -- F4: an item named without its maker -------------------------------------------------------
def test_an_item_without_a_maker_never_takes_another_makers_due_date(register, capsys):
    """rev65 F4: the makerless "001" last calibrated 2025-01-10 was due 2027-11-20, from
    Acme's "001" calibrated 2026-11-20 and Acme's interval."""
    blank = issue(register, meta("", serial="001", day="2025-01-10"))
    acme = issue(register, meta("Acme Optics", serial="001", day="2026-11-20"))
    register.set_interval("001", 365, "Acme Optics")
    assert register.interval("001", "") is None  # not Acme's
    assert register.due_date("001", "") is None
    assert register.maker_needed("001", "") == ("Acme Optics",)
    assert register.due_date("001", "Acme Optics") == dt.date(2027, 11, 20)
    assert register.maker_needed("001", "Acme Optics") == ()
    assert main(["register", "--register", register.url, "show", blank.number]) == 0
    out = capsys.readouterr().out
    assert "due:" not in out
    assert ("next calibration of 001: not known — this certificate names no manufacturer, "
            "and the serial's certificates name Acme Optics") in out
    assert main(["register", "--register", register.url, "show", acme.number]) == 0
    assert "next calibration of 001 due: 2027-11-20" in capsys.readouterr().out


def test_an_item_whose_certificates_never_name_a_maker_keeps_its_due_date(register):
    issue(register, meta("", serial="PG-12", day="2026-01-10"))
    register.set_interval("PG-12", 180)
    assert register.due_date("PG-12", "") == dt.date(2026, 7, 9)
    assert register.maker_needed("PG-12", "") == ()
