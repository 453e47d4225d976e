"""hostile78 F3 left a day open (F7's decision, b): a certificate withdrawn, then its
readings — the same values — issued again for its item with the date of calibration moved by
a day were an unrelated original; now it is issued in place of the withdrawn one, naming it
and the date's change. Readings of their own a day later are another calibration."""

from __future__ import annotations

import json

from models.certificate.metadata import CertificateMetadata
from models.register.store import IssueRequest, Register
from tests.own_readings import one_reading_moved, theodolite_sample_rows


def _issue(register: Register, serial: str, rows, date: str):
    """An original issued as the window and the command line issue one; the record and the
    details it was rendered with."""
    rendered = {}

    def render(meta):
        rendered["meta"] = meta
        return f"%PDF {meta.certificate_number}".encode()

    project = json.dumps({"format": "anglebench-project",
                          "workbenches": {"theodolite": {"rows": rows, "settings": {}}}})
    meta = CertificateMetadata(approver="Dr. Li", item_serial=serial, calibration_date=date,
                               item_description="Limited-rotation axis",
                               item_manufacturer="Example Instruments")
    record, _ = register.issue(IssueRequest("theodolite", meta, project), render,
                               separate_calibration="")
    return record, rendered["meta"]


def test_a_withdrawn_certificates_readings_dated_a_day_later_name_it(tmp_path):
    rows = theodolite_sample_rows()
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        first, _ = _issue(register, "LRA-0815", rows, "2026-11-20")
        register.withdraw(first.number, "tolerance typed wrong")
        second, meta = _issue(register, "LRA-0815", rows, "2026-11-21")
        assert meta.replaces_withdrawn == first.number
        assert str(meta.withdrawn_note).startswith(f"{first.number} withdrawn ")
        assert (f"(tolerance typed wrong); changed: date of calibration changed from "
                f"2026-11-20 (on {first.number}) to 2026-11-21") in str(meta.withdrawn_note)
        # readings of their own, a day later: another calibration, no link
        moved = one_reading_moved(rows)
        register.withdraw(second.number, "again")
        _, meta = _issue(register, "LRA-0815", moved, "2026-11-22")
        assert meta.replaces_withdrawn == ""
