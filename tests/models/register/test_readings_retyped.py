"""The same readings re-typed are the same readings (ident80; hostile pass of stop 79, left
open): the angles in decimal degrees to 6, 8 or 10 places instead of D°M'S" (or the other
way), the deviations in another unit chosen in the settings (arcsec ↔ µrad, µm ↔ nm), the
vertical column as zenith angles V with the setting that says so, the positioning's
deviations as the measured positions they are taken from. Compared by their
physical values within the resolution they were typed to
(models/register/readings_identity.py), they are refused as one item's readings issued as
another's, or as a calibration of its own of the same item; one reading changed by one step
of its resolution is still a calibration of its own."""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import pytest

from models.certificate.metadata import CertificateMetadata
from models.readings.angles import format_dms, parse_angle_deg
from models.register.store import (
    IssueRequest,
    NotASeparateCalibration,
    ReadingsOfAnotherItem,
    Register,
    SameReadingsIssued,
)
from tests.own_readings import theodolite_sample_rows

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
URAD_PER_ARCSEC = math.pi / 180 / 3600 * 1e6


def _project(workbench: str, rows, settings: dict | None = None) -> str:
    return json.dumps({"format": "anglebench-project",
                       "workbenches": {workbench: {"rows": rows, "settings": settings or {}}}})


def _issue(register: Register, workbench: str, serial: str, rows, settings=None,
           date: str = "2026-11-20", separate: str = ""):
    meta = CertificateMetadata(approver="Dr. Li", item_serial=serial, calibration_date=date,
                               item_description="Rotary axis",
                               item_manufacturer="Example Instruments")
    return register.issue(IssueRequest(workbench, meta, _project(workbench, rows, settings)),
                          lambda m: f"%PDF {m.certificate_number}".encode(),
                          separate_calibration=separate)[0]


def _decimal(rows, places: int):
    """The theodolite rows with the azimuth and elevation in decimal degrees to ``places``."""
    return [[r[0], f"{parse_angle_deg(r[1]):.{places}f}", f"{parse_angle_deg(r[2]):.{places}f}"]
            for r in rows]


def _positioning_rows() -> list[list[str]]:
    with open(SAMPLES / "positioning_sample.csv", newline="", encoding="utf-8") as handle:
        return [list(r) for r in csv.reader(handle)][1:]


def _deviations_as(rows, scale: float, places: int):
    return [[t, run, d, f"{float(x) * scale:.{places}f}"] for t, run, d, x in rows]


def _routes():
    """(name, workbench, the original's rows and settings, the re-typed rows and settings)."""
    theodolite = theodolite_sample_rows()
    decimal6 = _decimal(theodolite, 6)
    zenith = [[r[0], r[1], format_dms(parse_angle_deg(r[2]) + 90.0, 1)] for r in theodolite]
    positioning = _positioning_rows()
    return [
        *((f"decimal degrees to {p} places", "theodolite", theodolite, {},
           _decimal(theodolite, p), {}) for p in (6, 8, 10)),
        # the other way: decimal degrees to 6 places re-typed in D°M'S" to 0.001″
        ("D°M'S\" of decimal degrees", "theodolite", decimal6, {},
         [[r[0], format_dms(float(r[1]), 3), format_dms(float(r[2]), 3)] for r in decimal6], {}),
        ("zenith angles V", "theodolite", theodolite, {}, zenith,
         {"vertical_reading": "zenith"}),
        ("deviations in µrad", "positioning", positioning, {},
         _deviations_as(positioning, URAD_PER_ARCSEC, 4), {"deviation_unit": "urad"}),
        # the positioning's deviation is measured − target where it is blank: the same
        # readings typed as measured positions (decimal degrees to 8 places)
        ("deviations as measured positions", "positioning", positioning, {},
         [[t, run, d, "", f"{float(t) + float(x) / 3600:.8f}"] for t, run, d, x in positioning],
         {}),
        ("deviations in nm of µm", "positioning", positioning,
         {"target_unit": "mm", "deviation_unit": "um"},
         _deviations_as(positioning, 1000.0, 1), {"target_unit": "mm", "deviation_unit": "nm"}),
    ]


ROUTES = _routes()


@pytest.mark.parametrize("route", ROUTES, ids=[r[0] for r in ROUTES])
def test_readings_retyped_for_another_item_are_refused(tmp_path, route):
    _, workbench, rows, settings, retyped, retyped_settings = route
    assert retyped != rows
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        first = _issue(register, workbench, "LRA-0815", rows, settings)
        with pytest.raises(ReadingsOfAnotherItem) as refused:
            _issue(register, workbench, "LRA-0900", retyped, retyped_settings)
        assert refused.value.numbers == (first.number,)
        assert [r.number for r in register.list()] == [first.number]


@pytest.mark.parametrize("route", ROUTES, ids=[r[0] for r in ROUTES])
def test_readings_retyped_as_a_calibration_of_its_own_are_refused(tmp_path, route):
    """The item's own certificate's readings re-typed, issued as a calibration of its own
    (the same date: "as left"; or dated a day later): that calibration issued again."""
    _, workbench, rows, settings, retyped, retyped_settings = route
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        first = _issue(register, workbench, "LRA-0815", rows, settings)
        with pytest.raises(NotASeparateCalibration) as refused:
            _issue(register, workbench, "LRA-0815", retyped, retyped_settings,
                   separate="as left after adjustment")
        assert refused.value.numbers == (first.number,)
        with pytest.raises(SameReadingsIssued) as redated:
            _issue(register, workbench, "LRA-0815", retyped, retyped_settings,
                   date="2026-11-21")
        assert redated.value.numbers == (first.number,)
        assert [r.number for r in register.list()] == [first.number]


def _one_step(rows, places: int):
    """The theodolite rows in decimal degrees to ``places`` with row 8's azimuth one step of
    the sample's resolution (0.1″) away."""
    moved = _decimal(rows, places)
    moved[7][1] = f"{parse_angle_deg(rows[7][1]) + 0.1 / 3600:.{places}f}"
    return moved


@pytest.mark.parametrize("places", [6, 8, 10])
def test_one_reading_one_step_away_is_a_calibration_of_its_own(tmp_path, places):
    rows = theodolite_sample_rows()
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        first = _issue(register, "theodolite", "LRA-0815", rows)
        other = _issue(register, "theodolite", "LRA-0900", _one_step(rows, places))
        assert other.number != first.number


def test_one_reading_one_step_of_0_001_arcsec_away_is_a_calibration_of_its_own(tmp_path):
    """Readings to 0.001″ (the finest autocollimators): one of them a step away is another
    calibration's, typed in D°M'S" or in decimal degrees to 8 places."""
    rows = [[r[0], format_dms(parse_angle_deg(r[1]) + 0.0123 / 3600, 3), r[2]]
            for r in theodolite_sample_rows()]
    moved = [list(r) for r in rows]
    moved[7][1] = format_dms(parse_angle_deg(rows[7][1]) + 0.001 / 3600, 3)
    assert moved[7][1] != rows[7][1]
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        _issue(register, "theodolite", "LRA-0815", rows)
        _issue(register, "theodolite", "LRA-0900", moved)
        with pytest.raises(ReadingsOfAnotherItem):
            _issue(register, "theodolite", "LRA-0901", _decimal(moved, 8))
