"""Polygon encoder test as a workbench: readings columns, sets and closure rows,
statistics, verdicts, JSON and summary."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from models.analysis_kind import AnalysisKind, SettingsError
from models.error_stats import error_stats
from models.iso230 import iso230_evaluate
from models.polygon import (
    GRADE_ACCURACY_ARCSEC,
    PolygonResult,
    PolygonSetResult,
    allowed_tilt_arcsec,
    analyze_set,
    harmonic_analysis,
)
from models.polygon_report import polygon_certificate
from models.readings import Column, ColumnKind, ParsedReadings

__all__ = ["POLYGON", "closure_limit_arcsec"]

COLUMNS = (
    Column("position", "pos", "", ColumnKind.INTEGER,
           help="Polygon face / measuring position 1…n; the row after position n that "
                "repeats position 1 is the closure reading"),
    Column("encoder_deg", "encoder a", "deg", ColumnKind.ANGLE_DEG,
           help="Encoder reading (decimal or D°M'S\")"),
    Column("polygon_dev_arcsec", "polygon dev", "\"", ColumnKind.NUMBER,
           help="Face deviation from nominal, from the polygon's calibration certificate"),
    Column("ac_x_arcsec", "AC x", "\"", ColumnKind.NUMBER,
           help="Autocollimator horizontal reading"),
    Column("ac_y_arcsec", "AC y", "\"", ColumnKind.NUMBER, required=False,
           help="Autocollimator vertical reading (gives the pyramidal tilt)"),
    Column("set", "set", "", ColumnKind.INTEGER, required=False,
           help="Set (round) number when the test was repeated (optional)"),
    Column("direction", "dir", "+/−", ColumnKind.TEXT, required=False, choices=("+", "-"),
           help="Turning direction of the set: + forward, − reverse (optional)"),
)

DEFAULT_SETTINGS: dict[str, Any] = {
    "faces": 0,  # 0: from the readings
    "grade": 3,
    # closure limit (") for grades 1–7; default half the grade's accuracy (see README)
    "closure_limits_arcsec": "0.125, 0.25, 0.5, 1, 2.5, 5, 15",
    "autocollimator_accuracy_arcsec": 0.1,
}


def closure_limit_arcsec(grade: int, table: str = "") -> float:
    """Closure limit for a grade from the comma-separated table of grades 1–7; a missing
    entry falls back to half the grade's accuracy (our default, see README)."""
    parts = [p.strip() for p in str(table or "").replace(";", ",").split(",") if p.strip()]
    if grade - 1 < len(parts):
        try:
            value = float(parts[grade - 1])
        except ValueError:
            raise SettingsError(f"closure limit table: '{parts[grade - 1]}' (grade {grade}) is "
                                "not a number") from None
        if value <= 0:
            raise SettingsError(f"closure limit for grade {grade} must be positive")
        return value
    return GRADE_ACCURACY_ARCSEC[grade] / 2.0


def split_sets(parsed: ParsedReadings) -> list[tuple[int, np.ndarray, int | None, int]]:
    """(set id, row indices of positions, closure row index or None, direction) per set."""
    set_ids = np.nan_to_num(parsed["set"], nan=1.0).astype(int)
    out = []
    for set_id in dict.fromkeys(set_ids.tolist()):
        rows = np.nonzero(set_ids == set_id)[0]
        positions = parsed["position"][rows]
        closure = None
        if rows.size > 1 and positions[-1] == positions[0]:
            closure = int(rows[-1])
            rows = rows[:-1]
        dirs = [d for d in parsed["direction"][rows] if d]
        direction = -1 if dirs and dirs[0] == "-" else 1
        out.append((set_id, rows, closure, direction))
    return out


def analyze(parsed: ParsedReadings, settings: Mapping[str, Any]) -> PolygonResult:
    s = POLYGON.settings_with_defaults(settings)
    grade = int(s["grade"])
    if grade not in GRADE_ACCURACY_ARCSEC:
        raise SettingsError(f"grade must be 1 to 7, not {grade}")
    if parsed.n < 3:
        raise ValueError(f"{parsed.n} usable readings; a polygon test needs at least 3 positions")
    limit = closure_limit_arcsec(grade, str(s["closure_limits_arcsec"]))
    sets = split_sets(parsed)
    faces = int(s["faces"]) or int(sets[0][1].size)
    results: list[PolygonSetResult] = []
    for set_id, rows, closure_row, direction in sets:
        positions = parsed["position"][rows].astype(int)
        expected = np.arange(1, faces + 1)
        if positions.size != faces or not np.array_equal(np.sort(positions), expected):
            sheet_row = int(parsed.row_index[rows[0]]) + 1
            raise ValueError(
                f"set {set_id} (from row {sheet_row}) has positions {positions.tolist()}; expected "
                f"1…{faces} once each, then position 1 again for the closure")
        order = rows[np.argsort(positions)]
        closure_x = None if closure_row is None else float(parsed["ac_x_arcsec"][closure_row])
        results.append(analyze_set(
            parsed["encoder_deg"][order], parsed["polygon_dev_arcsec"][order],
            parsed["ac_x_arcsec"][order], parsed["ac_y_arcsec"][order], faces,
            closure_x, limit, direction))
    theta = results[0].theta_deg
    errors = np.array([r.error_arcsec for r in results])
    corrected = np.array([r.corrected_error_arcsec for r in results])
    mean_error, mean_corrected = errors.mean(axis=0), corrected.mean(axis=0)
    repeat = corrected.std(axis=0, ddof=1) if len(results) > 1 else None
    fwd = [r.direction > 0 for r in results]
    reversal = None
    if any(fwd) and not all(fwd):
        reversal = corrected[np.array(fwd)].mean(axis=0) - corrected[~np.array(fwd)].mean(axis=0)
    stats = error_stats(mean_corrected)
    tol = GRADE_ACCURACY_ARCSEC[grade]
    allowed = allowed_tilt_arcsec(grade)
    warnings = [w for r in results for w in r.warnings]
    valid = all(r.closure_ok is not False for r in results)
    tilt = results[0].tilt
    if tilt is None:
        verdict = "Tilt not identified (no vertical readings)."
    elif tilt.psi_arcsec <= allowed:
        verdict = (f"Pyramidal tilt ψ = {tilt.psi_arcsec:.1f}\" is within the {allowed:.0f}\" "
                   f"allowed for grade {grade}: the fixture is fine.")
    else:
        face = tilt.omega_deg / (360.0 / faces) + 1.0
        verdict = (f"Pyramidal tilt ψ = {tilt.psi_arcsec:.1f}\" exceeds the {allowed:.0f}\" allowed "
                   f"for grade {grade}: the encoder axis leans towards ω = {tilt.omega_deg:.1f}° "
                   f"(near face {face:.1f}); shim the polygon by {tilt.psi_arcsec:.0f}\" the same "
                   "way, re-zero and measure again.")
    return PolygonResult(
        sets=results, faces=faces, grade=grade, theta_deg=theta,
        mean_error_arcsec=mean_error, mean_corrected_arcsec=mean_corrected,
        repeatability_arcsec=repeat, reversal_arcsec=reversal, stats=stats,
        raw_stats=error_stats(mean_error), harmonics=harmonic_analysis(mean_corrected),
        allowed_tilt_arcsec=allowed, accuracy_ok=stats.peak_to_peak / 2.0 <= tol,
        tilt_verdict=verdict, valid=valid, warnings=warnings,
        closure_rows={int(parsed.row_index[c]) for _, _, c, _ in sets if c is not None},
    )


def iso230_figures(result: PolygonResult) -> dict[str, float]:
    theta = np.concatenate([r.theta_deg for r in result.sets])
    dev = np.concatenate([r.corrected_error_arcsec for r in result.sets])
    dirs = np.concatenate([np.full(r.theta_deg.size, r.direction) for r in result.sets])
    return iso230_evaluate(theta, dev, dirs).figures


def to_json(result: PolygonResult) -> dict[str, Any]:
    first = result.sets[0]
    closures = [r.closure_arcsec for r in result.sets]
    out: dict[str, Any] = {
        "error_arcsec": np.concatenate([r.error_arcsec for r in result.sets]).tolist(),
        "closure_arcsec": closures[0] if len(closures) == 1 else closures,
        "closure_ok": result.valid,
        "pyramidal_tilt_arcsec": first.tilt.psi_arcsec if first.tilt else None,
        "pyramidal_direction_deg": first.tilt.omega_deg if first.tilt else None,
        "pyramidal_error_arcsec": np.concatenate(
            [r.pyramidal_error_arcsec for r in result.sets]).tolist(),
        "corrected_error_arcsec": np.concatenate(
            [r.corrected_error_arcsec for r in result.sets]).tolist(),
        "faces": result.faces,
        "grade": result.grade,
        "accuracy_arcsec": GRADE_ACCURACY_ARCSEC[result.grade],
        "accuracy_ok": result.accuracy_ok,
        "allowed_tilt_arcsec": result.allowed_tilt_arcsec,
        "stats_arcsec": result.stats.as_dict(),
        "harmonics": {"order": result.harmonics.order.tolist(),
                      "amplitude_arcsec": result.harmonics.amplitude.tolist(),
                      "phase_deg": result.harmonics.phase_deg.tolist()},
        "warnings": result.warnings,
    }
    if len(result.sets) > 1:
        out["mean_corrected_error_arcsec"] = result.mean_corrected_arcsec.tolist()
        out["repeatability_arcsec"] = float(np.max(result.repeatability_arcsec))
        out["iso230_arcsec"] = iso230_figures(result)
        if result.reversal_arcsec is not None:
            out["reversal_error_arcsec"] = float(np.max(np.abs(result.reversal_arcsec)))
    return out


def summary(result: PolygonResult) -> str:
    s, tol = result.stats, GRADE_ACCURACY_ARCSEC[result.grade]
    lines = [f"{result.faces}-face polygon, {len(result.sets)} set(s), grade {result.grade} "
             f"(±{tol:g}\")" + ("" if result.valid else "   *** RUN INVALID: closure failed ***")]
    for i, r in enumerate(result.sets, 1):
        closure = "not measured" if r.closure_arcsec is None else (
            f"{r.closure_arcsec:.2f}\" {'ok' if r.closure_ok else 'FAILED'}")
        tilt = (f"ψ = {r.tilt.psi_arcsec:.1f}\" ± {r.tilt.u_psi_arcsec:.2f}\", "
                f"ω = {r.tilt.omega_deg:.1f}° ± {r.tilt.u_omega_deg:.2f}°") if r.tilt else "no tilt"
        lines.append(f"  set {i} ({'+' if r.direction > 0 else '−'}): closure {closure}; {tilt}; "
                     f"pyramidal correction up to {np.max(np.abs(r.pyramidal_error_arcsec)):.3f}\"")
    lines.append(f"Corrected error {s.min:+.2f}\" … {s.max:+.2f}\" (peak-to-peak "
                 f"{s.peak_to_peak:.2f}\"): accuracy ±{tol:g}\" "
                 f"{'met' if result.accuracy_ok else 'NOT met'} (rule: half the peak-to-peak ≤ "
                 "accuracy)")
    h = result.harmonics
    if h.amplitude.size > 2:
        lines.append(f"Harmonics: 1st (eccentricity) {h.amplitude[1]:.3f}\", "
                     f"2nd (ellipticity) {h.amplitude[2]:.3f}\"")
    if result.repeatability_arcsec is not None:
        jjf = (f"JJF 1115: division error {np.ptp(result.mean_corrected_arcsec):.2f}\", "
               f"repeatability {np.max(result.repeatability_arcsec):.2f}\"")
        if result.reversal_arcsec is not None:
            jjf += f", reversal error {np.max(np.abs(result.reversal_arcsec)):.2f}\""
        lines.append(jjf)
        figs = iso230_figures(result)
        lines.append("ISO 230-2: " + ", ".join(
            f"{k} = {v:.2f}\"" for k, v in figs.items() if math.isfinite(v)))
    lines.append(result.tilt_verdict)
    return "\n".join(lines)


POLYGON = AnalysisKind(
    key="polygon",
    title="Polygon encoder test",
    columns=COLUMNS,
    default_settings=DEFAULT_SETTINGS,
    analyze=analyze,
    to_json=to_json,
    summary=summary,
    sample_file="polygon_sample.csv",
    method_reference="Tian L. et al., Analysis the influence of pyramidal error on the encoder "
                     "accuracy test by using coordinate transformation, Acta Optica Sinica "
                     "35(5):0512003 (2015)",
    certificate=polygon_certificate,
)
