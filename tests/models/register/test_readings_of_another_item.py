"""One item's readings issued as another item's certificate (hostile78 F7: the sample's 41
readings, to 0.1″, issued for LRA-0815, LRA-0900 … each an original, nothing said): the
readings compared by their values (models/register/readings_identity.readings_key), refused
unless the user says why, which is printed on it and recorded in the register's chain
(a withdrawn certificate's readings issued a day later: test_withdrawn_readings_moved.py)."""

from __future__ import annotations

import json

import pytest

from models.certificate.metadata import CertificateMetadata
from models.readings.angles import parse_angle_deg
from models.register.readings_identity import readings_key
from models.register.store import (
    IssueRequest,
    ReadingsOfAnotherItem,
    Register,
    RegisterError,
    SameReadingsIssued,
)
from tests.own_readings import one_reading_moved, theodolite_project, theodolite_sample_rows


def _meta(serial: str, date: str = "2026-11-20", **changes) -> CertificateMetadata:
    return CertificateMetadata(approver="Dr. Li", item_serial=serial, calibration_date=date,
                               item_description="Limited-rotation axis",
                               item_manufacturer="Example Instruments", **changes)


def _issue(register: Register, serial: str, rows, date: str = "2026-11-20",
           stated: tuple[str, str] | None = None):
    """An original issued as the window and the command line issue one
    (``separate_calibration`` given); the record and the details it was rendered with."""
    rendered = {}

    def render(meta):
        rendered["meta"] = meta
        return f"%PDF {meta.certificate_number}".encode()

    record, _ = register.issue(IssueRequest("theodolite", _meta(serial, date),
                                            theodolite_project(rows)), render,
                               separate_calibration="", readings_of_another_item=stated)
    return record, rendered["meta"]


def test_the_readings_are_their_values_however_typed_ordered_or_saved():
    rows = theodolite_sample_rows()
    key = readings_key(theodolite_project(rows), "theodolite")
    assert len(key) == 64
    # re-typed: the angles in decimal degrees, 12 digits; "+" and trailing zeros; the rows
    # in another order; a sheet's padding and a blank row
    decimal = [[f"{float(r[0]):+.1f}", f"{parse_angle_deg(r[1]):.12f}",
                f"{parse_angle_deg(r[2]):.12f}" if r[2].strip() else ""] for r in rows]
    assert decimal[1] != rows[1]
    assert readings_key(theodolite_project(decimal[::-1] + [["", "", ""]]), "theodolite") == key
    # one reading of 41 one tenth of a second of arc away: other readings
    moved = one_reading_moved(rows)
    assert readings_key(theodolite_project(moved), "theodolite") != key
    # nothing to compare: no rows, no project, a workbench this version does not have
    assert readings_key(theodolite_project([]), "theodolite") == ""
    assert readings_key("not json", "theodolite") == ""
    assert readings_key(theodolite_project(rows), "nonesuch") == ""


def test_another_items_readings_are_refused_naming_its_certificate(tmp_path):
    rows = theodolite_sample_rows()
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        first, _ = _issue(register, "LRA-0815", rows)
        # the same values re-typed and the rows reversed, for another item: refused
        retyped = [[r[0], f"{parse_angle_deg(r[1]):.12f}", r[2]] for r in rows][::-1]
        with pytest.raises(ReadingsOfAnotherItem) as refused:
            _issue(register, "LRA-0900", retyped, date="2026-11-21")
        said = str(refused.value)
        assert refused.value.numbers == (first.number,)
        assert said.startswith(
            f"the readings are those of {first.number} (item LRA-0815, Example Instruments, "
            "calibrated 2026-11-20), another item than LRA-0900: no two calibrations repeat "
            "every reading to the last digit.")
        assert f"--readings-of-another-item {first.number}:REASON" in said
        assert [r.number for r in register.list()] == [first.number]  # nothing issued
        # a number that is not the certificate whose readings they are: refused
        with pytest.raises(RegisterError, match="the readings are not those of AB-9"):
            _issue(register, "LRA-0900", retyped, stated=("AB-9", "a pair"))
        # said why: issued, the statement on it, the user's word in the chain
        record, meta = _issue(register, "LRA-0900", retyped, date="2026-11-21",
                              stated=(first.number, "the pair was read once, coupled"))
        assert meta.readings_of_another_item == first.number
        assert str(meta.readings_note) == (
            f"The readings are those of certificate {first.number} (item LRA-0815, Example "
            "Instruments, calibrated 2026-11-20): the pair was read once, coupled")
        recorded = json.loads(record.project_json)["metadata"]["certificates"]["theodolite"]
        assert recorded["readings_of_another_item"] == first.number
        [word] = register.readings_of_another_item_confirmations(record.number)
        assert word["reason"] == "the pair was read once, coupled"
        assert word["others"] == [{"number": first.number, "serial": "LRA-0815",
                                   "item": "LRA-0815, Example Instruments",
                                   "calibration_date": "2026-11-20"}]
        assert register.audit() == []
        # a third item: both are named
        with pytest.raises(ReadingsOfAnotherItem) as refused:
            _issue(register, "LRA-0910", rows)
        assert refused.value.numbers == (first.number, record.number)


def test_readings_of_their_own_and_the_items_own_are_issued_and_a_false_word_refused(tmp_path):
    rows = theodolite_sample_rows()
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        _issue(register, "LRA-0815", rows)
        moved = one_reading_moved(rows)  # one reading of its own
        _, meta = _issue(register, "LRA-0900", moved)
        assert meta.readings_of_another_item == "" and meta.readings_note == ""
        # the same item's readings, another day's calibration: not another item's (to every
        # digit they are its calibration of 2026-11-20 re-dated: hostile79 #3, refused as
        # that calibration issued again unless said why)
        with pytest.raises(SameReadingsIssued) as refused:
            _issue(register, "LRA-0815", rows, date="2026-11-25")
        assert not isinstance(refused.value, ReadingsOfAnotherItem)
        # said where nothing is another item's: the statement would be false
        with pytest.raises(RegisterError, match="not those of any certificate of another item"):
            _issue(register, "LRA-0999", [r[:1] + [r[1] + " "] + r[2:] for r in moved][:3],
                   stated=("AB-1", "why"))


def test_a_lookalike_serial_said_to_be_another_item_is_still_asked_for_its_readings(tmp_path):
    """hostile78 F7: with F2 closed the route stayed open through a look-alike serial and
    --another-lookalike-item: another item, by the user's word, so another item's readings."""
    rows = theodolite_sample_rows()
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        first, _ = _issue(register, "LRA-0815", rows)
        meta = _meta("1ra-0815")
        with pytest.raises(ReadingsOfAnotherItem) as refused:
            register.issue(IssueRequest("theodolite", meta, theodolite_project(rows)),
                           lambda m: b"%PDF", separate_calibration="",
                           another_lookalike_item=True)
        assert refused.value.numbers == (first.number,)
        assert [r.number for r in register.list()] == [first.number]


def test_an_amendment_is_asked_only_when_it_changes_its_readings_to_another_items(tmp_path):
    rows = theodolite_sample_rows()
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        first, _ = _issue(register, "LRA-0815", rows)
        second, _ = _issue(register, "LRA-0900", one_reading_moved(rows))
        # its own readings again: not asked
        amended, _ = register.issue(IssueRequest("theodolite", _meta("LRA-0900"),
                                                 theodolite_project(one_reading_moved(rows))),
                                    lambda m: b"%PDF A1", supersedes=second.number,
                                    change_note="typo", separate_calibration="")
        # LRA-0815's readings put in its place: asked
        with pytest.raises(ReadingsOfAnotherItem) as refused:
            register.issue(IssueRequest("theodolite", _meta("LRA-0900"), theodolite_project(rows)),
                           lambda m: b"%PDF A2", supersedes=amended.number,
                           change_note="readings", separate_calibration="")
        assert refused.value.numbers == (first.number,)


def test_a_typed_number_with_a_colon_is_named_whole(tmp_path):
    """--readings-of-another-item N:REASON is split at its first colon; a number typed with
    one (the register takes it) is found again whole."""
    rows = theodolite_sample_rows()
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        register.issue(IssueRequest("theodolite", _meta(
            "LRA-0815", certificate_number="LAB:2026-7"), theodolite_project(rows)),
            lambda m: b"%PDF", separate_calibration="")
        _, meta = _issue(register, "LRA-0900", rows, stated=("LAB", "2026-7:a pair: read once"))
        assert meta.readings_of_another_item == "LAB:2026-7"
        assert str(meta.readings_note).endswith("calibrated 2026-11-20): a pair: read once")
