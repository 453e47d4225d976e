"""The register's accidents as a user makes them, for the register window's tests
(tests/app/test_register_recoveries_in_window.py, test_register_window_day74.py): a polygon
certificate issued into the test's own register (tests/conftest.py), at a clock of the
test's choosing; the database file copied and put back (a restore). The laboratory's key
and what the register window tells: the fixtures ``lab_key`` and ``told`` of
tests/app/conftest.py."""

from __future__ import annotations

import datetime as dt
import json
import shutil

from models.certificate.metadata import CertificateMetadata
from models.register.location import register_url
from models.register.store import IssueRequest, Register
from tests.register_forgery import stand_in_pdf

META = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-01", item_serial="RX-1",
                           number_scheme="AB-{year}-{seq:04d}")
PROJECT = json.dumps({"workbenches": {"polygon": {"rows": [["0", "0.41"], ["30", "-0.22"]]}}})


def issue(at: dt.datetime | None = None, **kwargs) -> str:
    """The number of a polygon certificate issued now (or ``at``)."""
    with Register(register_url()) as register:
        if at is not None:
            register.clock = lambda: at  # type: ignore[method-assign]
        return register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf,
                              **kwargs)[0].number


def restored(tmp_path, issued: int = 1, lost: int = 2) -> tuple[list[str], list[str]]:
    """Certificates issued, the database copied, more issued, the copy put back (the disk
    died; last night's backup restored): the numbers kept and the numbers lost."""
    database = register_url().split("///", 1)[1]
    kept = [issue() for _ in range(issued)]
    shutil.copy(database, tmp_path / "backup.sqlite")
    gone = [issue() for _ in range(lost)]
    shutil.copy(tmp_path / "backup.sqlite", database)
    return kept, gone
