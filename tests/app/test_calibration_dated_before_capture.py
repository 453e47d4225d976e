"""A date of calibration typed before the captured readings were taken, across a standard's
due date, is refused (hostile78 F5): readings captured on 2026-12-02, the autocollimator's
calibration due 2026-11-25 (expired: a test report), the details dated 2026-11-20 — issued
as a calibration certificate with the standard in date. Dated within a day of the capture,
or with no due date between, it is issued as before."""

from __future__ import annotations

import json

import pytest

from app.certificate_issue import issue_certificate
from models.capture.raw_record import session_json
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.register.location import register_url
from models.register.store import Register
from models.registry import KINDS

START = "2026-12-02T01:02:03+00:00"


@pytest.fixture
def captured(samples_dir):
    kind = KINDS["polygon"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    keys = [c.key for c in kind.columns]
    x, y = keys.index("ac_x_arcsec"), keys.index("ac_y_arcsec")
    frames = [(0.1 * i, f"3 003 {float(rows[i][x]):.3f} {float(rows[i][y]):.3f}".encode(), True)
              for i in (2, 3)]
    session = session_json("autocollimator", "/dev/ttyUSB0", 9600, START, frames,
                           [[2, 0, 0], [3, 1, 1]], workbench="polygon")
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))
    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    data.pop("issue_date", None)
    data.update(certificate_number="", example=False)
    return kind, rows, result, session, data


def _issue(captured, tmp_path, calibration_date: str, due: str):
    kind, rows, result, session, data = captured
    data = {**data, "calibration_date": calibration_date}
    data["standards"] = [{**s, "due_date": due} for s in data["standards"]]
    with Register(register_url()) as register:
        return issue_certificate(register, kind, result, CertificateMetadata.from_dict(data),
                                 kind.checked_settings({}), rows, "captured.anglebench.json",
                                 str(tmp_path / f"{calibration_date}.pdf"),
                                 raw_capture=[session])


def test_a_calibration_dated_before_the_capture_past_a_due_date_is_refused(captured, tmp_path):
    with pytest.raises(ValueError) as refused:
        _issue(captured, tmp_path, "2026-11-20", "2026-11-25")
    assert str(refused.value).startswith(
        "the date of calibration 2026-11-20 is before the readings were taken: the "
        "instruments' sessions behind the captured readings started on 2026-12-02, after the "
        "calibration of ")
    assert "was due (2026-11-25)" in str(refused.value)
    assert not (tmp_path / "2026-11-20.pdf").exists()
    with Register(register_url()) as register:
        assert register.list() == []


@pytest.mark.parametrize(("dated", "due"), [("2026-12-01", "2026-11-25"),  # a day's grace
                                            ("2026-11-20", "2027-01-01"),  # in date then too
                                            ("2026-11-20", "")])  # no due date stated
def test_other_dates_are_issued_as_before(captured, tmp_path, dated, due):
    record = _issue(captured, tmp_path, dated, due)
    assert record.status == "issued" and (tmp_path / f"{dated}.pdf").exists()
    # the standard in date at the date typed: a calibration certificate (the refused case
    # above was one too, dated before its standard expired)
    assert record.document_kind == ("test" if due and due < dated else "calibration")
