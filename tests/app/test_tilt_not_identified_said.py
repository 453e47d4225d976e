"""Day 74 findings 3 and 10: what the result says of a tilt the readings do not identify.

* Finding 3 (a false statement): the polygon's summary, in the window's result pane and on
  the command line, said "no tilt" for every set whose tilt was NOT identified (vertical
  readings all equal, or none), two lines below the warning "the pyramidal tilt is not
  identified (ψ = 0 is not a finding)". Each set's line now says the tilt is not identified,
  why, and the bound whose effect enters U in place of a correction, whose bound it is
  (stated, or the program's default), as the warning and the certificate say it. A set whose
  tilt is fitted keeps its ψ.
* Finding 10: with a tilt bound of 0 refused (theodolite, polygon, cross-calibration) the
  refusal began with the warning's own sentence "… the tilt bound enters the uncertainty"
  before it said 0 is refused. It leads with the refusal and what to do, then why.

The rigs simulate the set-ups from first principles (a polygon tilted on the shaft, turned
face by face before an autocollimator: its face normals rotated in 3-D; a mirror on a tilted
axis read by a theodolite with OZ plumb down; tests/crosscal_simulator.py's bench): nothing
is imported from models/."""

from __future__ import annotations

import contextlib
import io
import math
import re
from pathlib import Path

import numpy as np
import pytest

from app.main import main
from tests.crosscal_simulator import Bench

FACES = 12


def _rotation(axis, angle_rad: float) -> np.ndarray:
    """The right-handed rotation by ``angle_rad`` about the unit ``axis`` (Rodrigues)."""
    k = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    return np.eye(3) + math.sin(angle_rad) * k + (1.0 - math.cos(angle_rad)) * (k @ k)


def _polygon_rows(tilt: float | None, sets: int = 2) -> list[str]:
    """A 12-face polygon on a rotary table, tilted ``tilt``″ on the shaft towards 40° (None:
    the vertical readings not typed), face i turned to the autocollimator by the table: its
    normal, rotated in 3-D, read as horizontal atan(y/x) and vertical atan(z/x) (″, to
    0.01″). The table's own error 1.5″ sin t + 0.8″ cos 2t; the polygon's face deviations
    known (calibrated); forward then reverse sets."""
    rng = np.random.default_rng(7410)
    dev = np.round(rng.normal(0.0, 0.3, FACES), 2)
    dev -= dev[0]
    psi, omega = math.radians((tilt or 0.0) / 3600.0), math.radians(40.0)
    seat = _rotation(np.array([-math.sin(omega), math.cos(omega), 0.0]), psi)
    rows = []
    for s in range(1, sets + 1):
        order = range(FACES) if s % 2 else [0, *range(FACES - 1, 0, -1)]
        for i in order:
            nominal = i * 360.0 / FACES
            t = math.radians(nominal)
            table = (1.5 * math.sin(t) + 0.8 * math.cos(2.0 * t)) / 3600.0  # °
            face = math.radians(-nominal + dev[i] / 3600.0)  # face i's normal on the polygon
            normal = (_rotation(np.array([0.0, 0.0, 1.0]), math.radians(nominal + table))
                      @ seat @ np.array([math.cos(face), math.sin(face), 0.0]))
            x = math.degrees(math.atan2(normal[1], normal[0])) * 3600.0 + rng.normal(0.0, 0.03)
            y = math.degrees(math.atan2(normal[2], normal[0])) * 3600.0 + 8.35
            vertical = "" if tilt is None else f"{y:.2f}"
            rows.append(f"{i + 1},{nominal:.6f},{dev[i]:.2f},{x:.2f},{vertical},{s},"
                        f"{'+' if s % 2 else '-'}\n")
    return rows


def _theodolite_rows() -> list[str]:
    """θ indicated, A and E (°) of a mirror on an axis tilted 120″ towards 37°, E typed to
    0.1° (a 120″ tilt moves it by under half of that: every E equal)."""
    rng = np.random.default_rng(7411)
    psi, d = math.radians(120.0 / 3600.0), math.radians(37.0)
    axis = np.array([math.sin(psi) * math.cos(d), math.sin(psi) * math.sin(d), math.cos(psi)])
    normal = np.array([math.cos(math.radians(10.0)), 0.0, -math.sin(math.radians(10.0))])
    rows = []
    for theta in np.linspace(-20.0, 20.0, 9):
        x, y, z = _rotation(axis, math.radians(theta)) @ normal
        az = math.degrees(math.atan2(y, x)) + rng.normal(0.0, 0.3) / 3600.0
        el = round(math.degrees(math.asin(z)) / 0.1) * 0.1
        rows.append(f"{theta:.4f},{az:.7f},{el:.6f}\n")
    return rows


def _run(args: list[str]) -> tuple[int, str]:
    said, told = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(told):
        code = main(args)
    return code, " ".join((said.getvalue() + told.getvalue()).split())


def _polygon(tmp_path: Path, tilt: float | None, *options: str) -> tuple[int, str]:
    path = tmp_path / "polygon.csv"
    path.write_text("position,encoder_deg,polygon_dev_arcsec,ac_x_arcsec,ac_y_arcsec,set,"
                    "direction\n" + "".join(_polygon_rows(tilt)), encoding="utf-8")
    return _run(["analyze", "polygon", str(path), "--language", "en", *options])


def _set_lines(said: str) -> list[str]:
    """Each set's line of the summary."""
    return re.findall(r"set \d \([+−], from face \d+\):.*?(?= set \d \(|Corrected error)", said)


def test_the_rig_reads_equal_vertical_readings_without_a_tilt_and_varying_ones_with():
    assert len({row.split(",")[4] for row in _polygon_rows(0.0)}) == 1
    assert len({row.split(",")[4] for row in _polygon_rows(60.0)}) > FACES // 2


@pytest.mark.parametrize("tilt, why", [(0.0, 'every vertical reading is 8.35"'),
                                       (None, "no vertical readings")])
def test_a_set_whose_tilt_is_not_identified_says_so(tmp_path, tilt, why):
    code, said = _polygon(tmp_path, tilt)
    assert code == 0, said
    lines = _set_lines(said)
    assert len(lines) == 2, said
    for line in lines:
        assert "no tilt" not in line, line  # the false statement
        assert f"tilt not identified ({why})" in line, line
        assert "nothing removed" in line and "a tilt up to 300\"" in line, line
        assert "program's default" in line and "(stated)" not in line, line
    code, said = _polygon(tmp_path, tilt, "--tilt-bound-arcsec", "45")
    assert code == 0, said
    for line in _set_lines(said):
        assert 'a tilt up to 45" (stated) enters the uncertainty' in line, line


def test_a_set_whose_tilt_is_fitted_keeps_its_psi(tmp_path):
    code, said = _polygon(tmp_path, 60.0)
    assert code == 0, said
    lines = _set_lines(said)
    assert len(lines) == 2 and all("ψ = " in line and "not identified (" not in line
                                   for line in lines), lines


def _refusal(said: str) -> str:
    assert said.startswith("anglebench analyze: "), said
    return said[len("anglebench analyze: "):]


def _leads_with_the_refusal(said: str) -> None:
    refusal = _refusal(said)
    assert re.match(r"A tilt bound of 0\" is refused: state the largest", refusal, re.I), said
    # what to do comes before why, and why follows it
    assert refusal.index("--tilt-bound-arcsec") < refusal.index("no set-up achieves"), said


def test_the_polygons_refusal_of_0_leads_with_the_refusal(tmp_path):
    code, said = _polygon(tmp_path, 0.0, "--tilt-bound-arcsec", "0")
    assert code != 0, said
    _leads_with_the_refusal(said)
    assert _refusal(said).index("refused") < _refusal(said).index("enters the uncertainty")


def test_the_theodolites_refusal_of_0_leads_with_the_refusal(tmp_path):
    path = tmp_path / "theodolite.csv"
    path.write_text("theta_deg,azimuth_deg,elevation_deg\n" + "".join(_theodolite_rows()),
                    encoding="utf-8")
    assert len({row.split(",")[2] for row in _theodolite_rows()}) == 1
    code, said = _run(["analyze", "theodolite", str(path), "--accuracy-arcsec", "0.3",
                       "--tilt-bound-arcsec", "0", "--language", "en"])
    assert code != 0, said
    _leads_with_the_refusal(said)
    assert _refusal(said).index("refused") < _refusal(said).index("enters the uncertainty")


def test_the_cross_calibrations_refusal_of_0_leads_with_the_refusal(tmp_path):
    bench = Bench(FACES, {1: (2.0, 0.3), 2: (1.0, 1.1)},
                  np.random.default_rng(7412).normal(0.0, 1.5, FACES),
                  rng=np.random.default_rng(3), noise_arcsec=0.02, tilt_arcsec=120.0)
    lines = [f"{j},{i},{a:.9f},{x:.4f},\n" for j, i, a, x, _y in bench.rows((0, 1, 5), vertical=True)]
    path = tmp_path / "crosscal.csv"
    path.write_text("mounting,position,encoder_deg,ac_x_arcsec,ac_y_arcsec\n" + "".join(lines),
                    encoding="utf-8")
    code, said = _run(["analyze", "crosscal", str(path), "--tilt-bound-arcsec", "0",
                       "--language", "en"])
    assert code != 0, said
    _leads_with_the_refusal(said)
    assert "not identified in mounting(s) 0, 1, 5 (no vertical readings)" in said, said
