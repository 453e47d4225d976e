"""A verdict is not laundered through the register (hostile78): an amendment states what it
changes of what decides the result (F1: "conditional pass" at ±1″ amended to "pass" at ±3″
with the simple rule read "Changed: typo in the address"); a calibration "of its own" has
readings of its own (F2: the same readings at ±3″ issued "separate" read "pass"); an
original of the calibration of a withdrawn certificate names it and what it changes (F3: a
fail withdrawn "typo", the pass issued as an original, neither naming the other). Issued
with app.certificate_issue.issue_certificate, the call the window and the command line
make; the PDFs read back."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from pypdf import PdfReader

from app.certificate_issue import issue_certificate
from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.register.location import register_url
from models.register.register_error import RegisterError
from models.register.store import Register
from models.registry import KINDS


def _text(path: Path) -> str:
    return re.sub(r"\s+", " ", "".join(p.extract_text() for p in PdfReader(path).pages))


@pytest.fixture
def bench(samples_dir):
    """The theodolite sample analysed; its details (±1″, the guarded rule, no number)."""
    kind = KINDS["theodolite"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    settings = kind.checked_settings({})
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings)
    data = json.loads((samples_dir / "certificate_theodolite.json").read_text(encoding="utf-8"))
    data.pop("issue_date")
    data.update(certificate_number="", example=False, tolerance=1, decision_rule="guarded",
                calibration_date="2026-11-20")
    return kind, rows, settings, result, CertificateMetadata.from_dict(data)


def _issue(register, bench, path: Path, rows=None, **changes):
    kind, sample_rows, settings, result, meta = bench
    if rows is not None:
        result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings)
    meta = CertificateMetadata.from_dict({**meta.to_dict(), **changes.pop("details", {})})
    return issue_certificate(register, kind, result, meta, settings,
                             sample_rows if rows is None else rows, "theodolite_sample.csv",
                             str(path), **changes)


def test_an_amendment_states_the_tolerance_rule_and_readings_it_changes(tmp_path, bench):
    with Register(register_url()) as register:
        original = _issue(register, bench, tmp_path / "o.pdf")
        amended = _issue(register, bench, tmp_path / "a.pdf", supersedes=original.number,
                         change_note="typo in the address",
                         details={"tolerance": 3, "decision_rule": "simple"})
    assert "Conditional pass" in _text(tmp_path / "o.pdf")
    text = _text(tmp_path / "a.pdf")
    assert "(pass)" in text
    n = original.number
    assert amended.change_note == (
        f'tolerance changed from ±1" (on {n}) to ±3"; decision rule changed from guarded (on '
        f"{n}) to simple; typo in the address")
    assert ("Changed: tolerance changed from ±1\" (on " + n + ") to ±3\"; decision rule "
            "changed from guarded") in text


def test_an_amendment_states_readings_changed_and_nothing_when_nothing_changed(
        tmp_path, bench):
    kind, rows, *_ = bench
    edited = [list(r) for r in rows]
    edited[2][1] = edited[2][1].replace("42.8", "43.8")  # row 3's azimuth
    with Register(register_url()) as register:
        original = _issue(register, bench, tmp_path / "o.pdf")
        same = _issue(register, bench, tmp_path / "a1.pdf", supersedes=original.number,
                      change_note="the humidity was 45 %")
        again = _issue(register, bench, tmp_path / "a2.pdf", rows=edited,
                       supersedes=same.number, change_note="row 3 mistyped")
    assert same.change_note == "the humidity was 45 %"  # nothing else said
    assert again.change_note == (
        f"readings changed from those of {same.number}: row(s) 3 ({len(rows)} rows there, "
        f"{len(rows)} here); row 3 mistyped")


def test_a_separate_calibration_of_the_same_readings_is_refused(tmp_path, bench):
    kind, rows, *_ = bench
    with Register(register_url()) as register:
        first = _issue(register, bench, tmp_path / "o.pdf")
        with pytest.raises(RegisterError) as refused:
            _issue(register, bench, tmp_path / "s.pdf", details={"tolerance": 3},
                   separate_calibration="as left after adjustment")
        assert type(refused.value).__name__ == "NotASeparateCalibration"
        assert refused.value.numbers == (first.number,)
        assert str(refused.value).startswith(
            f"the readings are those of {first.number} (serial LRA-0815, calibrated "
            f'2026-11-20), judged otherwise: tolerance changed from ±1" (on {first.number}) '
            'to ±3". That is no calibration of its own')
        assert [r.number for r in register.list()] == [first.number]  # nothing issued
        # readings of its own: issued, separate, as before
        other = [list(r) for r in rows]
        other[0][1] = other[0][1].replace("57.0", "57.4")
        separate = _issue(register, bench, tmp_path / "s2.pdf", rows=other,
                          separate_calibration="as left after adjustment")
    assert separate.status == "issued"
    assert not (tmp_path / "s.pdf").exists()
    # what it changes against the other is said beside why it is separate: one reading of
    # 41 "as left after adjustment" is seen as such
    assert separate.change_note == (
        f"as left after adjustment; readings changed from those of {first.number}: row(s) 1 "
        f"({len(rows)} rows there, {len(rows)} here)")
    assert ("which stays valid: as left after adjustment; readings changed from those of "
            f"{first.number}: row(s) 1") in _text(tmp_path / "s2.pdf")


def test_the_command_line_refuses_a_separate_calibration_of_the_same_readings(
        tmp_path, samples_dir, capsys):
    meta = json.loads((samples_dir / "certificate_theodolite.json").read_text(encoding="utf-8"))
    meta.pop("issue_date")
    meta.update(certificate_number="", example=False, tolerance=1)
    (tmp_path / "m1.json").write_text(json.dumps(meta), encoding="utf-8")
    (tmp_path / "m3.json").write_text(json.dumps({**meta, "tolerance": 3}), encoding="utf-8")
    readings = str(samples_dir / "theodolite_sample.csv")
    assert main(["analyze", "theodolite", readings, "--certificate", str(tmp_path / "1.pdf"),
                 "--metadata", str(tmp_path / "m1.json")]) == 0
    capsys.readouterr()
    assert main(["analyze", "theodolite", readings, "--certificate", str(tmp_path / "3.pdf"),
                 "--metadata", str(tmp_path / "m3.json"),
                 "--separate-calibration", "as left after adjustment"]) == 2
    err = capsys.readouterr().err
    assert "the readings are those of AB-2026-0001" in err and "no certificate was written" in err
    assert not (tmp_path / "3.pdf").exists()


def test_an_original_after_a_withdrawal_names_the_withdrawn_one_and_its_changes(
        tmp_path, bench):
    with Register(register_url()) as register:
        failed = _issue(register, bench, tmp_path / "o.pdf")
        register.withdraw(failed.number, "typo")
        again = _issue(register, bench, tmp_path / "n.pdf", details={"tolerance": 3})
        stored = json.loads(register.get(again.number).project_json)
    details = stored["metadata"]["certificates"]["theodolite"]
    n = failed.number
    assert details["replaces_withdrawn"] == n
    assert re.fullmatch(rf'{n} withdrawn \d{{4}}-\d\d-\d\d \(typo\); changed: tolerance changed '
                        rf'from ±1" \(on {n}\) to ±3"', details["withdrawn_note"])
    text = _text(tmp_path / "n.pdf")
    assert (f"Issued in place of a withdrawn certificate of the same item and date of "
            f"calibration: {n} withdrawn") in text
    assert "(typo); changed: tolerance changed from ±1\"" in text
    assert "withdrawn" not in _text(tmp_path / "o.pdf").split("Certificate number")[0]


def test_an_original_after_a_withdrawal_for_another_customer_says_so(tmp_path, bench):
    with Register(register_url()) as register:
        first = _issue(register, bench, tmp_path / "o.pdf")
        register.withdraw(first.number, "wrong customer")
        again = _issue(register, bench, tmp_path / "n.pdf",
                       details={"customer_name": "Acme Optics GmbH"})
        details = json.loads(register.get(again.number).project_json)[
            "metadata"]["certificates"]["theodolite"]
    assert details["replaces_withdrawn"] == first.number
    assert details["withdrawn_note"].endswith(
        f"(wrong customer); changed: customer changed from 长春光电有限公司 Changchun Photonics "
        f"Ltd. (on {first.number}) to Acme Optics GmbH")
