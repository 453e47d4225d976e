"""A "calibration of its own" whose readings (each within the last digit it was typed to)
and details are those of a current certificate of its item and date was issued as a new
certificate, a second original of one calibration: no two calibrations repeat every reading
to the last digit. Refused, naming the certificate and the ways out (its PDF, its amendment
or replacement, or --same-readings-as N:REASON), as a laundered copy is; said why, it is
stated and chained."""

from __future__ import annotations

import dataclasses

import pytest

from app.register_cli import run_register
from models.certificate.metadata import CertificateMetadata
from models.readings.angles import parse_angle_deg
from models.register.store import (
    IssueRequest,
    NotASeparateCalibration,
    Register,
    RegisterError,
    SameReadingsIssued,
)
from tests.own_readings import one_reading_moved, theodolite_project, theodolite_sample_rows

META = CertificateMetadata(approver="Dr. Li", item_serial="LRA-0815",
                           calibration_date="2026-11-20",
                           item_description="Limited-rotation axis",
                           item_manufacturer="Example Instruments")


def _issue(register: Register, rows, separate: str = "", **options):
    return register.issue(IssueRequest("theodolite", META, theodolite_project(rows)),
                          lambda m: f"%PDF {m.certificate_number}".encode(),
                          separate_calibration=separate, **options)[0]


@pytest.fixture
def first(tmp_path):
    register = Register(f"sqlite:///{tmp_path / 'r.sqlite'}")
    yield register, _issue(register, theodolite_sample_rows())
    register.close()


def test_the_same_readings_and_details_as_separate_are_refused_naming_the_ways_out(first):
    register, original = first
    rows = theodolite_sample_rows()
    # the same values, re-typed in decimal degrees and the rows reversed: the same readings
    retyped = [[r[0], f"{parse_angle_deg(r[1]):.12f}", r[2]] for r in rows][::-1]
    for readings in (rows, retyped):
        with pytest.raises(SameReadingsIssued) as refused:
            _issue(register, readings, "as left after adjustment")
        said = str(refused.value)
        assert isinstance(refused.value, NotASeparateCalibration)
        assert refused.value.numbers == (original.number,)
        assert said.startswith(
            f"the readings are the same as those of {original.number} (serial LRA-0815, "
            "calibrated 2026-11-20), each within the last digit it was typed to, and so are "
            "its details: no two calibrations repeat every reading to the last digit")
        assert f"anglebench register show {original.number} --pdf OUT.pdf" in said
        assert "Amend… or Replace…" in said
        assert f"--same-readings-as {original.number}:REASON" in said
        assert "--same-readings-as" not in str(refused.value.facts)  # the window's words
    assert [r.number for r in register.list()] == [original.number]


def test_said_why_it_is_issued_stating_it_and_recorded_in_the_chain(first, capsys):
    register, original = first
    rows = theodolite_sample_rows()
    with pytest.raises(RegisterError, match="not those of XX-1 but those of"):
        _issue(register, rows, "as left", same_readings_as=("XX-1", "a reason"))
    with pytest.raises(SameReadingsIssued):  # a number and no reason
        _issue(register, rows, "as left", same_readings_as=(original.number, "  "))
    record = _issue(register, rows, "as left",
                    same_readings_as=(original.number, "second run of the  same mounting"))
    assert record.change_note == (f"as left; The readings are the same as those of "
                                  f"{original.number}, each within the last digit it was "
                                  "typed to, and so are the details: second run of the "
                                  "same mounting")
    [entry] = register.same_readings_confirmations(record.number)
    assert entry["reason"] == "second run of the same mounting"
    assert entry["others"] == [{"number": original.number}]
    assert register.audit(pdfs=True) == []
    # register show says what the user said, as true of a re-typed copy as of these
    assert run_register(["--register", register.url, "show", record.number]) == 0
    shown = " ".join(capsys.readouterr().out.split())
    assert (f"the same readings as {original.number}, each within the last digit it was "
            "typed to, and the same details, as ") in shown
    assert "said at issue" in shown and "): second run of the same mounting" in shown
    assert "to every digit" not in shown


def test_readings_of_their_own_are_a_calibration_of_its_own_and_the_option_is_refused(first):
    register, original = first
    moved = one_reading_moved(theodolite_sample_rows())
    with pytest.raises(RegisterError, match="--same-readings-as .*leave it out"):
        _issue(register, moved, "as left", same_readings_as=(original.number, "why"))
    record = _issue(register, moved, "as left after adjustment")
    assert record.change_note.startswith("as left after adjustment")
    assert register.same_readings_confirmations(record.number) == []


def test_the_same_values_typed_otherwise_and_judged_otherwise_are_no_separate_calibration(
        first):
    """hostile78 F2's refusal compared the readings as typed: re-typed in decimal degrees
    and judged against another tolerance they were issued as separate."""
    import dataclasses

    register, original = first
    retyped = [[r[0], f"{parse_angle_deg(r[1]):.12f}", r[2]]
               for r in theodolite_sample_rows()]
    meta = dataclasses.replace(META, tolerance=3.0, tolerance_unit="arcsec")
    with pytest.raises(NotASeparateCalibration) as refused:
        register.issue(IssueRequest("theodolite", meta, theodolite_project(retyped)),
                       lambda m: f"%PDF {m.certificate_number}".encode(),
                       separate_calibration="as left")
    assert not isinstance(refused.value, SameReadingsIssued)
    said = str(refused.value)
    assert f"judged otherwise: tolerance changed from — (on {original.number}) to ±3" in said
    assert "readings changed" not in said


def test_the_same_readings_with_the_date_of_calibration_moved_are_refused(first):
    """hostile79 #3: the same readings and details with the date of calibration a day later
    issued as an original, nothing said on it: a second current certificate of one
    calibration, re-dated. Refused as that calibration issued again; said why with
    --same-readings-as, stated on it and chained; a calibration of its own (readings of its
    own) on another date issues as before."""
    register, original = first
    later = dataclasses.replace(META, calibration_date="2026-11-21")

    def issue(rows, meta=later, **options):
        return register.issue(IssueRequest("theodolite", meta, theodolite_project(rows)),
                              lambda m: f"%PDF {m.certificate_number}".encode(),
                              separate_calibration="", **options)[0]

    with pytest.raises(SameReadingsIssued) as refused:
        issue(theodolite_sample_rows()[::-1])
    assert refused.value.numbers == (original.number,)
    assert str(refused.value).startswith(
        f"the readings are the same as those of {original.number} (serial LRA-0815), each "
        "within the last digit it was typed to, with another date of calibration than "
        "2026-11-21: no two calibrations repeat every reading "
        f"to the last digit, so this is the calibration {original.number} already reports, "
        "issued again with its date of calibration moved. Its copy is the PDF of "
        f"{original.number}")
    assert [r.number for r in register.list()] == [original.number]
    said = issue(theodolite_sample_rows(),
                 same_readings_as=(original.number, "the lab's date was wrong on the first"))
    assert said.change_note == (f"The readings are the same as those of {original.number}, "
                                "each within the last digit it was typed to, and so are the "
                                "details: the lab's date was wrong on the first")
    assert [e["others"] for e in register.same_readings_confirmations(said.number)] == [
        [{"number": original.number}]]
    own = issue(one_reading_moved(theodolite_sample_rows()),
                dataclasses.replace(META, calibration_date="2026-11-22"))
    assert own.change_note == "" and own.calibration_date == "2026-11-22"
