"""reg72 #10: the lab's time zone set per call (ANGLEBENCH_TIMEZONE, the window's setting):
an issue in UTC+14 and one a minute later in UTC−12 got AB-2026-0001 dated 2026-12-07 and
AB-2026-0002 dated 2026-12-06, dates of issue going backwards against the numbers. Such an
issue is refused (nothing recorded, no number used), naming both dates and this call's zone;
it is issued in the zone the lab dated its last certificate in, or in this zone once the
lab's date there reaches the last one. The UTC clock rule is unchanged."""

from __future__ import annotations

import datetime as dt
from zoneinfo import ZoneInfo

import pytest

from models.certificate.metadata import CertificateMetadata
from models.register.store import IssueRequest, Register, RegisterError

PROJECT = '{"workbenches": {}}'
AHEAD, BEHIND = "Pacific/Kiritimati", "Etc/GMT+12"  # UTC+14, UTC−12
NOON = dt.datetime(2026, 12, 6, 12, 0, tzinfo=dt.timezone.utc)


def _meta(serial: str) -> CertificateMetadata:
    return CertificateMetadata(approver="Dr. Li", calibration_date="2026-12-01",
                               item_serial=serial)


def _issue(url: str, zone: str, when: dt.datetime, serial: str):
    with Register(url, timezone=zone) as register:
        register.clock = lambda: when
        return register.issue(IssueRequest("polygon", _meta(serial), PROJECT),
                              lambda m, head="": f"%PDF {m.certificate_number}".encode())[0]


def _local_date(when: dt.datetime, zone: str) -> str:
    return when.astimezone(ZoneInfo(zone)).date().isoformat()


def test_an_issue_dated_before_the_last_certificate_in_another_zone_is_refused(tmp_path):
    url = f"sqlite:///{tmp_path / 'r.sqlite'}"
    first = _issue(url, AHEAD, NOON, "Z-1")
    assert first.issue_date == _local_date(NOON, AHEAD) == "2026-12-07"
    later = NOON + dt.timedelta(minutes=1)
    assert _local_date(later, BEHIND) == "2026-12-06"  # what the second issue would print
    with pytest.raises(RegisterError) as refused:
        _issue(url, BEHIND, later, "Z-2")
    said = str(refused.value)
    assert said.startswith(
        "this certificate would be dated 2026-12-06 in the lab's time zone of this issue, "
        f"Etc/GMT+12 (UTC-12:00), before the register's last certificate, {first.number}, "
        f"dated 2026-12-07 (issued {first.issued_at};")
    assert "the dates of issue would go backwards against the numbers" in said
    assert said.endswith("in this zone from 2026-12-07T00:00:00-12:00 on")
    with Register(url) as register:
        assert [r.number for r in register.list()] == [first.number]
    # in the lab's zone the number that was not used is the next; then in UTC−12 once the
    # lab's date there is the last one's
    second = _issue(url, AHEAD, later, "Z-2")
    assert second.issue_date == "2026-12-07"
    midnight_behind = dt.datetime(2026, 12, 7, 12, 0, tzinfo=dt.timezone.utc)
    assert _local_date(midnight_behind, BEHIND) == "2026-12-07"
    third = _issue(url, BEHIND, midnight_behind, "Z-3")
    assert third.issue_date == "2026-12-07"
    numbers = [first.number, second.number, third.number]
    assert numbers == sorted(numbers) and len(set(numbers)) == 3
    assert int(second.number[-4:]) == int(first.number[-4:]) + 1


def test_a_later_date_in_another_zone_is_issued(tmp_path):
    """The zone alone is no reason to refuse: dates that do not go backwards are issued."""
    url = f"sqlite:///{tmp_path / 'r.sqlite'}"
    first = _issue(url, BEHIND, NOON, "Z-1")
    second = _issue(url, AHEAD, NOON + dt.timedelta(minutes=1), "Z-2")
    assert (first.issue_date, second.issue_date) == ("2026-12-06", "2026-12-07")
