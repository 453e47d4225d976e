"""Only the issue that issued a certificate records its results file (stop 63:
``record_results`` was public and checked only that the certificate was current and had
none, so any caller gave a certificate issued earlier without one any file, which
``register verify`` then called "the results file of certificate N, identical to the
record")."""

from __future__ import annotations

import pytest

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.register.location import register_url
from models.register.store import IssueRequest, Register, RegisterError

NOT_HERE = "no results file is recorded for {number}: a results file is recorded by the issue"


def _issue(register: Register, serial: str) -> str:
    meta = CertificateMetadata(approver="Dr. Li", calibration_date="2026-01-01",
                               item_serial=serial)
    return register.issue(IssueRequest("polygon", meta, '{"workbenches": {}}'),
                          lambda m, head="": f"%PDF {m.certificate_number}".encode()
                          )[0].number


def test_results_are_recorded_only_for_a_number_this_issue_issued(tmp_path, capsys):
    forged = tmp_path / "r.csv"
    forged.write_bytes(b"face,deviation\r\n1,0.0\r\n")
    with Register(register_url()) as register:
        earlier = _issue(register, "RX-1")  # issued without a results file
    with Register(register_url()) as register:
        head = register.chain_head()
        for number in (earlier, "AB-2026-9999"):  # issued before; never issued at all
            with pytest.raises(RegisterError, match=NOT_HERE.format(number=number)):
                register.record_results(number, forged.read_bytes(), forged.name)
        assert register.chain_head() == head and register.results_records() == []
        issued = _issue(register, "RX-2")  # the issue records its own, once
        register.record_results(issued, b"face,deviation\r\n1,0.1\r\n", "own.csv")
        with pytest.raises(RegisterError, match=NOT_HERE.format(number=issued)):
            register.record_results(issued, forged.read_bytes(), forged.name)
        assert [r["number"] for r in register.results_records()] == [issued]
    capsys.readouterr()
    assert main(["register", "verify", str(forged)]) == 1
    assert "NOT in the register" in capsys.readouterr().out
