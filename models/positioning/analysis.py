"""Positioning of an axis as a workbench: readings columns, settings, the checks a log
must pass, JSON and summary."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from models.messages import QT_TR_NOOP, joined, lines, message, separated
from models.parameters import Parameter, SettingsError
from models.positioning import KEY, MEASURAND_STANDARDS, TITLE
from models.positioning.acquisition import positioning_guide
from models.positioning.compensation import write_compensation
from models.positioning.model import (
    DEVIATION_UNITS,
    MIN_RUNS,
    SIGN_CONVENTION,
    STANDARDS,
    TARGET_UNITS,
    PositioningResult,
    evaluate,
    figure_text,
    infer_directions,
)
from models.positioning.per_target_reasons import per_target_reasons
from models.positioning.report import (
    axis_figure_values,
    figure_decimals,
    figures_withheld_notes,
    intervals_withheld,
    one_direction_reasons,
    positioning_budget,
    positioning_certificate,
    readings_figure_intervals,
    stated_figure_intervals,
    withheld_figure_notes,
    withheld_figure_reasons,
    without_interval,
)
from models.readings.copied_runs import COPIED_RUN, copied_run
from models.readings.entry_plan import positioning_plan, targets_from_text
from models.readings.incomplete import IncompleteUnit, short_last_unit, subset
from models.readings.repeats import REPEATS_PARAMETER, average_repeats
from models.readings.resolution import readings_step
from models.readings.sheet import Column, ColumnKind, ParsedReadings
from models.uncertainty.budget import DEFAULT_COVERAGE_PROBABILITY
from models.uncertainty.figure_intervals import FIGURE_VALUE_NOTE, figure_objects
from models.uncertainty.iso230 import once_note
from models.uncertainty.lab_scope import cmc_parameter
from models.uncertainty.probability_text import percent_text
from models.uncertainty.rounding import fixed_places
from models.uncertainty.wide_intervals import wide_intervals_statement
from models.workbench import (
    AcceptsRuns,
    ComparesAfterLog,
    GuidesAcquisition,
    IssuesCertificates,
    ShowsHeadline,
    Workbench,
    WritesCorrectionTable,
)

__all__ = ["POSITIONING"]

UP, DOWN = ("+", "↑", "up"), ("-", "−", "↓", "down")

COLUMNS = (
    Column("target", "target", "", ColumnKind.ANGLE_DEG,
           help="Target position P_j the axis was sent to, in the target unit of the set-up "
                "(degrees, decimal or D°M'S\"; or mm)",
           aliases=("target position", "目标位置", "目标", "指令位置", "P")),
    Column("run", "run", "", ColumnKind.INTEGER, required=False,
           help="Run number j (optional; without it the k-th approach to a target in a "
                "direction is run k)",
           aliases=("次数", "测量次数", "循环")),
    Column("direction", "dir", "+/−", ColumnKind.TEXT, required=False, choices=UP + DOWN,
           help="Approach direction: + (also ↑, up) or − (also ↓, down); when blank, taken "
                "from the order of the targets",
           aliases=("方向", "dir")),
    Column("deviation", "deviation", "", ColumnKind.NUMBER, required=False,
           help="Positional deviation x = actual position reached − target, in the deviation "
                "unit of the set-up (ISO 230-2 sense)",
           aliases=("位置偏差", "定位偏差", "偏差", "x")),
    Column("measured", "measured", "", ColumnKind.ANGLE_DEG, required=False,
           help="Actual position reached, as the reference read it, in the target unit "
                "(instead of the deviation)",
           aliases=("actual", "actual position", "实际位置", "测量值")),
)

PARAMETERS = (
    Parameter("target_unit", "target unit", "choice", "deg",
              choices=(("deg", "degrees (rotary axis)"), ("mm", "millimetres (linear axis)")),
              help="Unit of the target (and measured) positions"),
    Parameter("deviation_unit", "deviation unit", "choice", "arcsec",
              choices=(("arcsec", "arcseconds (\")"), ("urad", "microradians (µrad)"),
                       ("um", "micrometres (µm)"), ("nm", "nanometres (nm)")),
              help="Unit of the deviations and of every figure; arcsec or µrad for a rotary "
                   "axis, µm or nm for a linear one"),
    Parameter("standard", "standard applied", "choice", "iso230-2",
              choices=tuple(STANDARDS.items()),
              help="The standard the certificate states and judges by; the JSON always has "
                   "ISO 230-2 and VDI/DGQ 3441 both"),
    Parameter("compensation_step", "compensation step", "float", 0.0, "",
              1e-6, 1e6, zero="at the targets", decimals=4, step=1.0,
              help="Spacing of the compensation table in the target unit; 0: one entry at "
                   "each target"),
    Parameter("compensation_tables", "compensation tables", "choice", "separate",
              choices=(("separate", "forward and backward"),
                       ("bidirectional", "one, from the bidirectional mean")),
              help="Separate tables for the two approach directions, or one table from the "
                   "mean of the two (compensation = −mean deviation)"),
    Parameter("compensation_format", "compensation format", "choice", "csv",
              choices=(("csv", "CSV (position, compensation)"),
                       ("linuxcnc", "LinuxCNC COMP_FILE type 0"),
                       ("sinumerik", "SINUMERIK 840D measuring system error compensation"),
                       ("fanuc", "FANUC pitch error compensation (parameters 3620–3625)"),
                       ("heidenhain", "HEIDENHAIN TNC .COM table (and .CMA)"),
                       ("twincat", "Beckhoff TwinCAT Tc2_MC2 position compensation table"),
                       ("isg", "ISG kernel leadscrew error compensation list"),
                       ("mach4", "Mach4 screw map")),
              help="CSV always works; LinuxCNC's joint compensation file (COMP_FILE_TYPE = 0, "
                   "documented in the LinuxCNC INI configuration manual) lists nominal, "
                   "actual forward and actual reverse positions; the controllers' formats "
                   "follow their manuals, and a table the controller would reject or misapply "
                   "is refused naming the rule"),
    Parameter("compensation_controller_options", "controller options", "text", "",
              help="The controller's settings as KEY=VALUE, comma-separated, e.g. "
                   "axis=AX4, system=1, modulo=360, reference=0 (SINUMERIK); axis=4, "
                   "detection_unit=0.001, magnification=1, reference=0, modulo=360, series=30i "
                   "(FANUC); axis=C, values=error, modulo=360 (HEIDENHAIN); name=Axis1 (TwinCAT); "
                   "axis_name=C, max_points=1500, value_type=sgn32 (ISG); axis=X, "
                   "values=correction (Mach4); modulo=360, travel_min=-720, travel_max=720 "
                   "(LinuxCNC, a rotary joint)"),
    # inputs of the budget the readings cannot show, in the deviation unit (0: not stated, and
    # the certificate says it is not in U)
    Parameter("misalignment_u", "misalignment u", "float", 0.0, "", 0.0, 1e6, zero="not stated",
              decimals=4, step=0.1,
              help="Standard uncertainty at a target from the reference's alignment to the axis "
                   "(cosine error, eccentricity), in the deviation unit. 0: not stated"),
    Parameter("reference_resolution", "reference resolution", "float", 0.0, "", 0.0, 1e6,
              zero="not stated", decimals=4, step=0.1,
              help="Resolution of the reference's reading, in the deviation unit (rectangular, "
                   "half-width r/2). 0: not stated"),
    Parameter("temperature_u", "temperature u", "float", 0.0, "", 0.0, 1e6, zero="not stated",
              decimals=4, step=0.1,
              help="Standard uncertainty at a target from the temperatures (the axis' expansion "
                   "and its compensation, the reference's environment), in the deviation unit. "
                   "0: not stated"),
    # ISO 230-2 clause 8: the test conditions, printed as details
    Parameter("axis_temperature_c", "axis temperature", "float", 0.0, "°C", -50.0, 100.0,
              zero="not stated", decimals=1, step=0.1,
              help="Temperature of the axis (its scale or encoder) during the test (ISO 230-2, "
                   "clause 8). 0: not stated"),
    Parameter("expansion_ppm_k", "expansion coefficient", "float", 0.0, "µm/(m·K)", 0.0, 100.0,
              zero="not stated", decimals=2, step=0.1,
              help="The nominal expansion coefficient the compensation used (linear axes; ISO "
                   "230-2, clause 8). 0: not stated"),
    Parameter("axis_setup", "axis set-up", "text", "",
              help="The axis' set-up (ISO 230-2, clause 8): position of the reference, load, "
                   "feed, dwell at each target, other axes' positions"),
    cmc_parameter("cmc", "laboratory's CMC (smallest U), in the deviations' unit", "",
                  "the positioning deviation"),
    REPEATS_PARAMETER,
    # the test plan: entry follows the run (models/readings/entry_plan.py)
    Parameter("plan_runs", "test plan: runs", "int", 0, minimum=1, maximum=100, zero="no plan",
              cli=False,
              help="Runs of the test plan (ISO 230-2: 5); with the targets below, entry fills "
                   "target, run and direction as readings arrive and shows the next point. "
                   "0: no plan (the nominal step fills the target)",
              entry_aid=True),
    Parameter("plan_targets", "test plan: targets", "text", "0:30:12", cli=False,
              help="The plan's targets: start:step:count (0:30:12) or a list (0, 30, 60)",
              entry_aid=True),
    Parameter("plan_directions", "test plan: directions", "choice", "both", cli=False,
              choices=(("both", "bidirectional (↑ then ↓)"), ("up", "unidirectional (↑)")),
              help="Approach directions of the plan",
              entry_aid=True),
    Parameter("plan_order", "test plan: order", "choice", "linear", cli=False,
              choices=(("linear", "linear (ISO 230-2 standard cycle)"),
                       ("pilgrim", "pilgrim step (every approach of a target in turn)")),
              help="Linear: run 1 ↑ over every target, then ↓, then run 2; pilgrim step: "
                   "all of one target's approaches before the next target",
              entry_aid=True),
)

#: the settings that are inputs of the certificate's budget (PositioningResult.inputs)
BUDGET_INPUTS = ("misalignment_u", "reference_resolution", "temperature_u")

#: A deviation beyond this (in the target unit) is no positioning deviation: a wrong unit
#: or a measured position typed as a deviation.
DEVIATION_LIMIT = {"deg": 1.0, "mm": 10.0}
#: Targets beyond this are no axis positions (100 turns; 100 m).
TARGET_LIMIT = {"deg": 36_000.0, "mm": 100_000.0}


def _check_units(s: dict[str, Any]) -> None:
    belongs = DEVIATION_UNITS[s["deviation_unit"]][0]
    if belongs != s["target_unit"]:
        raise SettingsError(
            message(
            QT_TR_NOOP("deviation_unit {s} is for an axis in {belongs}, but target_unit is {s2}: choose "
                       "arcsec or urad for deg, um or nm for mm"),
            s=s['deviation_unit'], belongs=belongs, s2=s['target_unit']))


def _row(parsed: ParsedReadings, index: int) -> int:
    return int(parsed.row_index[index]) + 1


#: the columns a blank deviation is taken from, as measured − target (Workbench.derived_columns)
DEVIATION_FROM = ("measured", "target")


def _deviations(parsed: ParsedReadings, s: dict[str, Any]) -> np.ndarray:
    """Each reading's deviation in the deviation unit, from either column (where it is blank,
    :data:`DEVIATION_FROM`: measured − target); refuses a row with neither, or with both
    disagreeing, naming it."""
    scale = DEVIATION_UNITS[s["deviation_unit"]][1]
    deviation = parsed["deviation"].astype(float)
    source, other = DEVIATION_FROM
    measured = parsed[source].astype(float)
    from_measured = (measured - parsed[other]) * scale
    neither = np.nonzero(~np.isfinite(deviation) & ~np.isfinite(measured))[0]
    if neither.size:
        raise ValueError(message(
            QT_TR_NOOP("row {row}: neither a deviation nor a measured position; one of the two is needed"),
            row=_row(parsed, int(neither[0]))))
    both = np.isfinite(deviation) & np.isfinite(measured)
    disagree = np.nonzero(both & (np.abs(deviation - from_measured) > 1e-3))[0]
    if disagree.size:
        i = int(disagree[0])
        raise ValueError(
            message(
            QT_TR_NOOP("row {row}: deviation {deviation} but measured − target = {from_measured} ({s}): "
                       "give one of the two, or make them agree"),
            row=_row(parsed, i), deviation=f"{deviation[i]:g}", from_measured=f"{from_measured[i]:.4f}",
            s=s['deviation_unit']))
    return np.where(np.isfinite(deviation), deviation, from_measured)


def _beyond_limit(parsed: ParsedReadings, s: dict[str, Any], deviations: np.ndarray,
                  targets: np.ndarray) -> tuple[np.ndarray, list[str]]:
    """The readings whose deviation is beyond :data:`DEVIATION_LIMIT` (a mask) and what to
    say of each. A few of them are readings of another position (a take at a target the
    table was not at: a measured 0° in the row of target 15°), left out of the analysis and
    named, the rest of the test kept; most of them are a wrong unit, and refused (day
    review live76 F7: one take at the wrong target withheld the whole result, with "whether
    a position was typed as a deviation" of rows captured, in "arcsec" and "deg")."""
    sym, tsym = DEVIATION_UNITS[s["deviation_unit"]][2], TARGET_UNITS[s["target_unit"]]
    limit = DEVIATION_LIMIT[s["target_unit"]] * DEVIATION_UNITS[s["deviation_unit"]][1]
    beyond = np.abs(deviations) > limit
    if not beyond.any():
        return beyond, []
    measured = parsed["measured"].astype(float)
    given = np.isfinite(parsed["deviation"].astype(float))
    kept_targets = np.unique(np.round(targets[~beyond], 9)).size
    if beyond.sum() * 2 >= beyond.size or kept_targets < 2:
        i = int(np.nonzero(beyond)[0][0])
        raise ValueError(message(QT_TR_NOOP(
            "row {row}: a deviation of {out}{s} is beyond {limit}{s} ({deviation_limit}{s2}), "
            "as are {n} of the {count} readings: check the deviation unit"),
            row=_row(parsed, i), out=f"{deviations[i]:g}", s=sym, limit=f"{limit:g}",
            deviation_limit=f"{DEVIATION_LIMIT[s['target_unit']]:g}", s2=tsym,
            n=int(beyond.sum()), count=int(beyond.size)))
    said = []
    for i in np.nonzero(beyond)[0]:
        if given[i]:
            said.append(message(QT_TR_NOOP(
                "Row {row}: a deviation of {out}{s} is beyond {limit}{s} ({deviation_limit}{s2}): "
                "left out of the analysis; check its reading"),
                row=_row(parsed, int(i)), out=f"{deviations[i]:g}", s=sym, limit=f"{limit:g}",
                deviation_limit=f"{DEVIATION_LIMIT[s['target_unit']]:g}", s2=tsym))
        else:
            said.append(message(QT_TR_NOOP(
                "Row {row}: measured {measured}{s2} at target {target}{s2}, a deviation of "
                "{out}{s} beyond {limit}{s} ({deviation_limit}{s2}): left out of the analysis "
                "(a reading at another position than its target's?)"),
                row=_row(parsed, int(i)), measured=f"{measured[i]:g}", target=f"{targets[i]:g}",
                out=f"{deviations[i]:g}", s=sym, limit=f"{limit:g}",
                deviation_limit=f"{DEVIATION_LIMIT[s['target_unit']]:g}", s2=tsym))
    return beyond, said


#: readings that show neither a scatter nor a step (models.positioning.report refuses U)
IDENTICAL_READINGS = QT_TR_NOOP(
    "The readings of every target came out identical in each direction (s = 0 everywhere) "
    "and show no step of their display: their repeatability cannot be told. The figures of "
    "the axis get no coverage interval and no certificate is issued; enter the readings with "
    "the digits the reference shows.")


def _entered_step(parsed: ParsedReadings, s: dict[str, Any]) -> float | None:
    """The step of the deviations as entered (models.readings.resolution), in the deviation
    unit: of the deviation column where it is given, of measured − target elsewhere (the
    coarser of the two where both are used); None where either lies on no grid."""
    scale = DEVIATION_UNITS[s["deviation_unit"]][1]
    deviation = parsed["deviation"].astype(float)
    measured = parsed["measured"].astype(float)
    given = np.isfinite(deviation)
    steps = []
    if np.any(given):
        steps.append(readings_step(deviation[given]))
    others = ~given & np.isfinite(measured)
    if np.any(others):
        step = readings_step(measured[others] - parsed["target"].astype(float)[others])
        steps.append(None if step is None else step * scale)
    found = [step for step in steps if step is not None]
    return max(found) if found and len(found) == len(steps) else None


def approach_directions(targets: np.ndarray, stated: Any) -> np.ndarray:
    """Each reading's approach direction as the analysis takes it: +1 where its cell is one
    of :data:`UP` (+, ↑, up), −1 where one of :data:`DOWN`, and where it is blank from the
    order of the targets (:func:`models.positioning.model.infer_directions`)."""
    directions = infer_directions(targets)
    for i, d in enumerate(stated):
        if d:
            directions[i] = 1.0 if d in UP else -1.0
    return directions


def _directions(parsed: ParsedReadings, warnings: list[str]) -> np.ndarray:
    stated = parsed["direction"]
    given = np.array([bool(d) for d in stated], dtype=bool)
    directions = approach_directions(parsed["target"], stated)
    if not given.all():
        count = int(np.sum(~given))
        warnings.append(message(QT_TR_NOOP("Approach direction not stated for {count} "
                                           "reading(s): taken from the order of the targets (a "
                                           "repeated target is the turn of a run)."),
                                count=count))
    return directions


def _runs(parsed: ParsedReadings, targets: np.ndarray, directions: np.ndarray) -> np.ndarray:
    """The run of each reading; with the run column, a (target, run, direction) seen twice is
    refused naming both rows."""
    runs = parsed["run"]
    key_target = np.round(targets, 9)
    if np.all(np.isfinite(runs)):
        seen: dict[tuple[float, int, float], int] = {}
        for i, key in enumerate(zip(key_target.tolist(), runs.astype(int).tolist(),
                                    directions.tolist(), strict=True)):
            if key in seen:
                raise ValueError(
                    message(
                    QT_TR_NOOP("rows {row} and {row2}: target {key}, run {key2}, direction {value} twice"),
                    row=_row(parsed, seen[key]), row2=_row(parsed, i), key=f"{key[0]:g}", key2=key[1],
                    value='+' if key[2] > 0 else '−'))
            seen[key] = i
        return runs.astype(int)
    if np.any(np.isfinite(runs)):
        i = int(np.nonzero(~np.isfinite(runs))[0][0])
        raise ValueError(message(
            QT_TR_NOOP("row {row}: no run number, though other rows have one; give every row its run, or "
                       "none"),
            row=_row(parsed, i)))
    return _runs_counted(runs, targets, directions)


def _check_stray_targets(parsed: ParsedReadings, targets: np.ndarray, runs: np.ndarray,
                         directions: np.ndarray) -> None:
    """Refuse a target read in one run only where, in that direction, another target lacks
    a reading in a run that reads the others: a target mistyped in place of one of the
    test's. It was taken for a new target: the runs were planned anew, a complete last run
    became one in progress and its readings entered no figure (contract review 75 F8).

    A target read in one run with no reading missing elsewhere is a target approached once
    (its U is not determined, said so), and a target the run in progress has not reached
    (the linear cycle's last run, its readings the last rows and a part of the earlier
    runs' targets) is no hole: that run is left out of the count."""
    key = np.round(targets, 9).tolist()
    run_list = [int(r) for r in runs.tolist()]
    sense = directions.tolist()
    if len(set(run_list)) < 2:
        return
    members = list(zip(key, sense, strict=True))
    last = run_list[-1]
    earlier = {members[i] for i in range(len(members)) if run_list[i] != last}
    in_progress = last if short_last_unit(run_list, members, earlier) is not None else None
    runs_of: dict[tuple[float, float], set[int]] = {}
    for member, r in zip(members, run_list, strict=True):
        runs_of.setdefault(member, set()).add(r)
    targets_runs: dict[float, set[int]] = {}
    for t, r in zip(key, run_list, strict=True):
        targets_runs.setdefault(t, set()).add(r)
    for i, (t, r) in enumerate(zip(key, run_list, strict=True)):
        if len(targets_runs[t]) != 1 or r == in_progress:
            continue
        d = sense[i]
        runs_d = {q for (u, e), qs in runs_of.items() if e == d for q in qs} - {in_progress}
        holes = sorted((u, sorted(runs_d - qs)) for (u, e), qs in runs_of.items()
                       if e == d and u != t and runs_d - qs)
        if not holes:
            continue
        u, lacking = holes[0]
        raise ValueError(message(QT_TR_NOOP(
            "row {row}: target {target} is read in run {run} only, while target {missing} "
            "has no reading in that direction in run {lacking}, which the other runs read: "
            "a mistyped target? Check that row"),
            row=_row(parsed, i), target=f"{targets[i]:g}", run=r, missing=f"{u:g}",
            lacking=", ".join(str(q) for q in lacking[:5])))


def split_incomplete(parsed: ParsedReadings, settings: Mapping[str, Any]
                     ) -> tuple[ParsedReadings, IncompleteUnit | None]:
    """The complete runs, and the last unit when it is in progress: in the linear cycle the
    last run (its readings the last rows, fewer (target, direction) than the earlier runs
    have, each once); in the pilgrim-step cycle the last target (fewer (run, direction)
    than the other targets have)."""
    if parsed.n < 2 or not np.all(np.isfinite(parsed["target"])):
        return parsed, None
    runs_column = parsed["run"]
    if np.any(np.isfinite(runs_column)) and not np.all(np.isfinite(runs_column)):
        return parsed, None  # refused by the analysis, naming the row
    per_point = int(settings.get("readings_per_point", 1) or 1)
    if not np.all(np.isfinite(runs_column)) and per_point > 1:
        return parsed, None  # repeated readings: the runs are counted after averaging
    with np.errstate(all="ignore"):  # a target of 1e308: refused by the analysis, naming it
        targets = np.round(parsed["target"].astype(float), 9)
    directions = _directions(parsed, [])
    runs = _runs_counted(parsed["run"], targets, directions)
    if np.all(np.isfinite(targets)):  # before a run is taken for one in progress
        _check_stray_targets(parsed, targets, runs, directions)
    t, d, r = targets.tolist(), directions.tolist(), runs.tolist()
    # linear cycle: the last run short of the (target, direction) the runs before it have
    earlier = {(t[i], d[i]) for i in range(parsed.n) if r[i] != r[-1]}
    rows = short_last_unit(r, list(zip(t, d, strict=True)), earlier)
    unit = "run"
    if rows is None:  # pilgrim-step cycle: the last target short of the others' approaches
        others = {(r[i], d[i]) for i in range(parsed.n) if t[i] != t[-1]}
        rows = short_last_unit(t, list(zip(r, d, strict=True)), others)
        unit = "target"
        if rows is None:
            return parsed, None
        expected = len(others)
    else:
        expected = len(earlier)
    keep = np.ones(parsed.n, dtype=bool)
    keep[rows] = False
    number = float(r[-1]) if unit == "run" else float(t[-1])
    return subset(parsed, keep), IncompleteUnit(
        unit, number, int(rows.size) // per_point if per_point > 1 else int(rows.size),
        expected, _row(parsed, int(rows[0])), _row(parsed, int(rows[-1])),
        tuple(int(i) for i in rows))


def _runs_counted(runs: np.ndarray, targets: np.ndarray, directions: np.ndarray
                  ) -> np.ndarray:
    """The run of each reading: the run column (``runs``) where every row has one, else the
    k-th approach to a target (to 9 decimals) in a direction (no check: the analysis
    checks)."""
    if np.all(np.isfinite(runs)):
        return runs.astype(int)
    counts: dict[tuple[float, float], int] = {}
    out = np.empty(targets.size, dtype=int)
    with np.errstate(all="ignore"):  # a target of 1e308: refused by the analysis, naming it
        key_target = np.round(targets.astype(float), 9)
    for i, key in enumerate(zip(key_target.tolist(), directions.tolist(), strict=True)):
        counts[key] = counts.get(key, 0) + 1
        out[i] = counts[key]
    return out


def analyze(parsed: ParsedReadings, settings: Mapping[str, Any]) -> PositioningResult:
    s = POSITIONING.checked_settings(settings)
    step = _entered_step(parsed, s)
    parsed, repeats = average_repeats(parsed, s["readings_per_point"], Positioning.point_keys,
                                      ("deviation", "measured"))
    if parsed.n < 2:
        raise ValueError(message(
            QT_TR_NOOP("{n} usable readings; a positioning test needs at least two targets"),
            n=parsed.n))
    targets = parsed["target"].astype(float)
    limit = TARGET_LIMIT[s["target_unit"]]
    beyond = np.nonzero(np.abs(targets) > limit)[0]
    if beyond.size:
        i = int(beyond[0])
        raise ValueError(message(
            QT_TR_NOOP("row {row}: target {targets} {s} is beyond ±{limit} {s}: not a position of an axis"),
            row=_row(parsed, i), targets=f"{targets[i]:g}", s=s['target_unit'], limit=f"{limit:g}"))
    if np.unique(np.round(targets, 9)).size < 2:
        raise ValueError(message(
            QT_TR_NOOP("every reading is at target {targets}: a positioning test needs at least two "
                       "targets"),
            targets=f"{targets[0]:g}"))
    warnings: list[str] = []
    deviations = _deviations(parsed, s)
    beyond, said = _beyond_limit(parsed, s, deviations, targets)
    left_out = tuple(int(r) for r in parsed.row_index[beyond])
    if left_out:  # a few readings of another position: named, the rest of the test kept
        keep = ~beyond
        parsed, targets, deviations = subset(parsed, keep), targets[keep], deviations[keep]
        warnings.extend(said)
    directions = _directions(parsed, warnings)
    runs = _runs(parsed, targets, directions)
    _check_stray_targets(parsed, targets, runs, directions)
    result = evaluate(targets, runs, directions, deviations, parsed.row_index.copy(),
                      s["target_unit"], s["deviation_unit"], s["standard"], warnings)
    if repeats is not None:
        scale = DEVIATION_UNITS[s["deviation_unit"]][1]
        result.repeats = repeats
        result.repeat_s_mean = np.where(np.isfinite(parsed["deviation"].astype(float)),
                                        repeats.s_mean["deviation"],
                                        repeats.s_mean["measured"] * scale)
    result.inputs = {key: float(s[key]) for key in BUDGET_INPUTS}
    result.left_out = left_out
    result.readings_step = step
    copy = copied_run(runs, directions, targets, deviations, step, result.pooled_s())
    if copy is not None:
        raise ValueError(message(COPIED_RUN, later=copy[1], earlier=copy[0],
                                 direction="+" if copy[2] > 0 else "−"))
    if result.without_scatter and step is None:
        warnings.append(message(IDENTICAL_READINGS))
    elif result.coarse_readings:
        sym = result.symbol
        warnings.append(message(QT_TR_NOOP(
            "The readings were entered to {step}, coarser than they scatter (s pooled over the "
            "targets {s}): readings of one target come out alike and each mean carries a "
            "rounding error up to {half} that its s does not show. U counts the step "
            "(rectangular, half-width {half}); the figures of the axis get no coverage interval. "
            "Enter the readings with more digits."),
            step=f"{step:g}{sym}", s=f"{result.pooled_s():.3g}{sym}", half=f"{0.5 * step:g}{sym}"))
    for template, stats in (
            (QT_TR_NOOP("Every forward run read alike at target(s) {targets} while the other "
                        "targets scatter: a repeatability of 0 is not what these readings show "
                        "(copied, or rounded apart from the rest?); U there takes the s pooled "
                        "over the targets, {s}."), result.iso.forward),
            (QT_TR_NOOP("Every backward run read alike at target(s) {targets} while the other "
                        "targets scatter: a repeatability of 0 is not what these readings show "
                        "(copied, or rounded apart from the rest?); U there takes the s pooled "
                        "over the targets, {s}."), result.iso.backward)):
        if stats is None:
            continue
        alike = result.alike_unexplained(stats)
        if np.any(alike):
            warnings.append(message(template,
                                    targets=", ".join(f"{t:g}" for t in result.positions[alike]),
                                    s=f"{result.pooled_s():.3g}{result.symbol}"))
    for template, stats in (
            (QT_TR_NOOP("No forward reading at target(s) {targets}: the forward figures leave "
                        "them out."), result.iso.forward),
            (QT_TR_NOOP("No backward reading at target(s) {targets}: the backward figures leave "
                        "them out."), result.iso.backward)):
        if stats is None:
            continue
        missing = result.positions[stats.runs == 0]
        if missing.size:
            warnings.append(message(template, targets=", ".join(f"{t:g}" for t in missing)))
    once = once_note(result.iso, result.target_symbol.strip())
    if once is not None and (result.iso.forward is None or np.any(result.iso.forward.runs > 1)
                             or result.iso.backward is None
                             or np.any(result.iso.backward.runs > 1)):
        warnings.append(once)
    short = {k: n for k, n in result.least_runs.items() if n < MIN_RUNS}
    if short:
        words = {"up": QT_TR_NOOP("forward {runs}"), "down": QT_TR_NOOP("backward {runs}")}
        # joined in the language's own punctuation (Chinese "，": day review 69 F6)
        parts = separated([message(words[key], runs=n) for key, n in short.items()], ", ")
        warnings.append(message(
            QT_TR_NOOP("Fewer runs than ISO 230-2 asks (5 in each direction at every target): "
                       "{runs} at the least measured target. Evaluated, and flagged as the "
                       "standard requires."),
            runs=parts))
    if not result.bidirectional:
        warnings.append(message(QT_TR_NOOP(
            "One approach direction only: the unidirectional figures are given; B, M, the "
            "bidirectional R and A, and VDI/DGQ 3441 U and P need both directions and are not "
            "evaluated.")))
    if result.iso.forward is not None and not np.any(np.isfinite(result.iso.forward.std)) or \
            result.iso.backward is not None and not np.any(np.isfinite(result.iso.backward.std)):
        warnings.append(message(QT_TR_NOOP(
            "No target was approached twice in the same direction: repeatability (R), accuracy "
            "(A) and the position scatter Ps are not evaluated.")))
    return result


ISO_KEYS = ("A", "A_up", "A_down", "E", "E_up", "E_down", "M", "R", "R_up", "R_down", "B",
            "B_mean")


def _finite(value: Any) -> Any:
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def _array(values: np.ndarray | None) -> list[float | None] | None:
    if values is None:
        return None
    return [_finite(float(v)) for v in values]


VDI_KEYS = ("P", "Ps_max", "Pa", "U_max")





def figures_json(result: PositioningResult, budget=None) -> dict[str, Any]:
    """The figures as the JSON states them, each {value, interval_low, interval_high,
    coverage_probability}, with the intervals of :func:`figure_uncertainties` for
    ``budget`` (the certificate's, with its reference standards' U; without it the result's
    own stated inputs) — the same intervals the certificate prints, held to the laboratory's
    CMC where it is set (each object's ``raised_to_cmc``) — and the probability of that
    budget."""
    intervals = (readings_figure_intervals(result) if budget is None else
                 stated_figure_intervals(result, budget))
    # R, R↑, R↓, Ps_max of two runs: the value, no interval, and why (audit 68 finding 3)
    # and a figure of both directions where one was measured (assessment 72 M6)
    reasons = {**one_direction_reasons(result), **withheld_figure_reasons(result, budget)}
    cmc_set = budget is not None and float(budget.floor) > 0
    return {
        "iso230_2_figures": figure_objects(ISO_KEYS, result.iso.figures, intervals, cmc_set,
                                           reasons),
        "vdi3441_figures": figure_objects(VDI_KEYS, result.vdi.as_dict(), intervals, cmc_set,
                                          reasons),
        "figure_intervals_note": message(FIGURE_VALUE_NOTE),
        "coverage_probability": (DEFAULT_COVERAGE_PROBABILITY if budget is None
                                 else float(budget.probability)),
    }


def to_json(result: PositioningResult) -> dict[str, Any]:
    iso = result.iso
    per_target: dict[str, Any] = {"target": result.positions.tolist()}
    for name, _, stats in result.directions_present():
        per_target[f"mean_{name}"] = _array(stats.mean)
        per_target[f"s_{name}"] = _array(stats.std)
        per_target[f"band_2s_{name}"] = _array(2.0 * stats.std)
        per_target[f"runs_{name}"] = stats.runs.tolist()
    per_target["B_i"] = _array(iso.reversal)
    per_target["M_i"] = _array(iso.bidirectional_mean)
    per_target["R_i"] = _array(iso.bidirectional_repeatability)
    # why a list has nulls, beside it, null where every value is given (assessment 73 M3):
    # the run's reason where one direction was measured, else the targets named (a target
    # approached one way, or once in a direction, of a run in both: left 74)
    for key, reason in per_target_reasons(result).items():
        per_target[f"{key}_reason"] = reason
    return {
        "target_unit": result.target_unit,
        "deviation_unit": result.deviation_unit,
        "standard": result.standard,
        "standard_title": STANDARDS[result.standard],
        "iso230_2": {k: _finite(iso.figures.get(k, float("nan"))) for k in ISO_KEYS},
        "vdi3441": result.vdi.as_dict(),
        "per_target": per_target,
        "readings": int(result.deviations.size),
        "least_runs": result.least_runs,
        "minimum_runs_met": result.minimum_runs_met,
        "sign_convention": SIGN_CONVENTION,
        "warnings": result.warnings,
        **figures_json(result),
        "figure_intervals_reason": None if (withheld := intervals_withheld(result)) is None
        else message(withheld),
    }


def summary(result: PositioningResult, printed: dict[str, int] | None = None) -> str:
    """The result as text; ``printed``: each figure's decimal on the certificate
    (:meth:`Positioning.printed_rounding`, its intervals with the reference standards' U;
    None: those of the intervals from the readings)."""
    sym = result.symbol
    f = result.iso.figures
    present = [name for name, _, _ in result.directions_present()]
    dirs = (message(QT_TR_NOOP("forward and backward")) if present == ["up", "down"] else
            message(QT_TR_NOOP("forward")) if present == ["up"] else
            message(QT_TR_NOOP("backward")))
    runs: list = []
    for key, n in result.least_runs.items():
        runs += ([", "] if runs else []) + [message(
            QT_TR_NOOP("forward ≥ {runs}") if key == "up" else QT_TR_NOOP("backward ≥ {runs}"),
            runs=n)]
    n = int(getattr(result.repeats, "n", 1) or 1)  # readings per point
    out = [joined((
        message(QT_TR_NOOP("{targets} targets {first}…{last}, {readings} readings, {directions} "
                           "(runs per target: {runs})") if n == 1 else
                # the readings and the points they make (gui80: "3 readings" beside the
                # table's caption "6 used", the averaged points counted as readings)
                QT_TR_NOOP("{targets} targets {first}…{last}, {readings} readings ({points} "
                           "points of {n}), {directions} (runs per target: {runs})"),
                targets=result.positions.size, first=f"{result.positions.min():g}",
                last=f"{result.positions.max():g}{result.target_symbol}",
                readings=result.deviations.size * n, points=result.deviations.size, n=n,
                directions=dirs, runs=joined(runs)),
        "" if result.minimum_runs_met else
        message(QT_TR_NOOP("   *** fewer than 5 runs: flagged ***"))))]
    keys = ("A", "R", "B", "B_mean", "E", "M") if result.bidirectional else tuple(
        f"{figure}_{n}" for n in present for figure in ("A", "R", "E"))
    intervals = readings_figure_intervals(result)
    # each figure to the decimal of its interval's half-width (GUM 7.2.6), as the certificate;
    # one whose interval is withheld to that of the interval withheld (day 68 F5: "A =
    # 19.866″" here beside the window's "A = 20″")
    decimals = figure_decimals(result) | (printed or {})
    out.append(_figures_line("ISO 230-2: ", ((k, f.get(k)) for k in keys), sym, decimals))
    out.append(_figures_line("VDI/DGQ 3441: ", result.vdi.as_dict().items(), sym, decimals))
    if intervals:
        shown = [k for k in (*keys, *VDI_KEYS) if k in intervals]
        # without the certificate's details: the readings and their stated inputs only (a
        # certificate adds its reference standards' U, and its intervals are wider: #61)
        parts: list = [message(QT_TR_NOOP("Coverage intervals ({p} %, from the readings "
                                          "without the reference standards' U; a "
                                          "certificate's include it): "),
                               p=f"{100 * DEFAULT_COVERAGE_PROBABILITY:.2f}")]
        for i, key in enumerate(shown):
            iv = intervals[key]
            d = decimals[key]
            # each end with its unit: shown in µrad or mdeg, both ends are converted (the
            # low end, bare, stayed in arcseconds beside a converted high end)
            parts += [", " if i else "",
                      f"{key} {fixed_places(iv.low, d)}{sym} … {fixed_places(iv.high, d)}{sym}"]
            if iv.probability < DEFAULT_COVERAGE_PROBABILITY:
                parts.append(f" ({percent_text(iv.probability)} %)")
        out.append(joined(parts))
        # R, R↑, R↓, Ps_max of two runs: no interval, why, and the place the figure above is
        # printed to, in the certificate's words (audit 68 finding 3; leftovers 79: "R = 10″"
        # with nothing saying it was rounded to the interval withheld)
        out += withheld_figure_notes(result, decimals)
        # an upper end far above its figure (few runs): why, as the certificate says (F6)
        wide = wide_intervals_statement(axis_figure_values(result), intervals,
                                        min(result.least_runs.values()), sym, outwards=False)
        if wide is not None:
            out.append(wide)
    else:  # no figure has an interval: why, as the certificate says it
        out += figures_withheld_notes(result, decimals)
    out.append(message(QT_TR_NOOP("Standard applied: {standard}. Compensation = −mean deviation "
                                  "(Export compensation table… below the set-up)."),
                       standard=message(STANDARDS[result.standard])))
    return lines(out)


def _figures_line(prefix: str, figures, symbol: str, decimals: dict[str, int] | None = None):
    """``prefix`` then "A = 3.20", R = …" (each to its ``decimals``, else 0.001): a figure
    the readings could not determine says so in the reader's language."""
    parts: list = [prefix]
    for i, (key, value) in enumerate(figures):
        parts += [", " if i else "", f"{key} = ", figure_text(value, symbol,
                                                              (decimals or {}).get(key, 3))]
    return joined(parts)


#: the settings in the deviations' unit (the budget's inputs the readings cannot show)
DEVIATION_UNIT_SETTINGS = ("misalignment_u", "reference_resolution", "temperature_u")


class Positioning(Workbench[PositioningResult], IssuesCertificates[PositioningResult],
                  WritesCorrectionTable[PositioningResult], AcceptsRuns,
                  ComparesAfterLog[PositioningResult], ShowsHeadline[PositioningResult],
                  GuidesAcquisition):
    key = KEY
    title = TITLE
    columns = COLUMNS
    parameters = PARAMETERS
    sample_file = "positioning_sample.csv"
    point_keys = ("target", "run", "direction")

    def point_name(self, parsed: ParsedReadings, index: int) -> str:
        return message(QT_TR_NOOP("target {target}"), target=f"{parsed['target'][index]:g}")
    measurand_standards = MEASURAND_STANDARDS
    dcc_uncertainty_columns = {"mean_deviation": ""}  # the certificate's U column (DCC)
    method_reference = ("ISO 230-2:2014 Test code for machine tools — Part 2: Determination of "
                        "accuracy and repeatability of positioning of numerically controlled "
                        "axes; VDI/DGQ 3441:1977; GB/T 17421.2-2016")
    presenter = "widgets.positioning.presenter:PositioningPresenter"
    nominal_column = "target"
    entry_column = "deviation"
    analyze = staticmethod(analyze)
    to_json = staticmethod(to_json)
    summary = staticmethod(summary)
    acquisition_guide = staticmethod(positioning_guide)

    def check_settings(self, checked):
        _check_units(checked)

    def split_incomplete(self, parsed, settings):
        return split_incomplete(parsed, settings)

    plan_reading_keys = ("deviation", "measured")

    def reading_positions(self, settings):
        # the measured position is the target's, in the target unit: on a rotary axis in the
        # target's turn (measured − target is its deviation: a readout's −0.5 or 359.5 at
        # target 0° is written −0.5)
        unit = "mm" if settings.get("target_unit", "deg") == "mm" else "deg"
        return {"measured": ("target", unit)}

    def shown_in_blank(self, settings):
        # the deviation of a reading taken (or typed) as a measured position: measured −
        # target, shown in its blank deviation cell as the typed path shows the deviation
        from models.positioning.deviation_shown import DEVIATION_SHOWN_NOTE, shown_deviation

        return {"deviation": (shown_deviation(settings), DEVIATION_SHOWN_NOTE)}

    def derived_columns(self, settings):
        # where the deviation is blank the analysis takes measured − target (_deviations)
        return {"deviation": DEVIATION_FROM}

    def read_cells(self, parsed, settings):
        # the direction by its meaning, + or − (UP's and DOWN's first), blank ones from the
        # order of the targets; the run, where no row has one, counted: as the analysis takes
        # them (approach_directions, _runs_counted), of each point's first reading where a
        # point has several (readings_per_point: the analysis averages them first)
        n = int(settings.get("readings_per_point", 1) or 1)
        if parsed.n == 0 or parsed.n % n:
            return {}  # refused by the analysis (a point short of its readings)
        first = slice(None, None, n)
        targets = parsed["target"].astype(float)[first]
        directions = approach_directions(targets, parsed["direction"][first])
        runs = _runs_counted(parsed["run"][first], targets, directions)
        return {"direction": np.repeat([UP[0] if d > 0 else DOWN[0] for d in directions], n
                                       ).tolist(),
                "run": np.repeat(runs, n).tolist()}

    def column_units(self, settings):
        # live78: the live table's "deviation" and "measured" had no unit in their header
        # (arcseconds, µm … only in the set-up below it), unlike every other workbench's
        target = "mm" if settings.get("target_unit", "deg") == "mm" else "deg"
        deviation = DEVIATION_UNITS.get(str(settings.get("deviation_unit", "arcsec")),
                                        DEVIATION_UNITS["arcsec"])[2].strip()
        return {"target": target, "measured": target, "deviation": deviation}

    def setting_units(self, settings):
        # the budget's Type B inputs are in the deviations' unit: their fields showed no
        # unit beside the set-up's "°C" and "µm/(m·K)" (leftovers 79)
        # unit; the laboratory's CMC is in it too, the compensation table's step in the
        # targets' (leftovers 80: both fields bare)
        unit = DEVIATION_UNITS[self.error_unit(settings)][2].strip()
        target = TARGET_UNITS.get(str(settings.get("target_unit", "deg")), "°").strip()
        return dict.fromkeys((*DEVIATION_UNIT_SETTINGS, "cmc"), unit) | {
            "compensation_step": target}

    def entry_plan(self, settings):
        runs = int(settings.get("plan_runs", 0) or 0)
        if not runs:
            return None
        unit = TARGET_UNITS.get(str(settings.get("target_unit", "deg")), "°")
        return positioning_plan(targets_from_text(str(settings.get("plan_targets", ""))), runs,
                                settings.get("plan_directions", "both") == "both",
                                str(settings.get("plan_order", "linear")), unit,
                                int(settings.get("readings_per_point", 1) or 1))

    def error_unit(self, settings):
        """The deviation unit, every figure's."""
        unit = settings.get("deviation_unit", "arcsec")
        return unit if unit in DEVIATION_UNITS else "arcsec"

    def listed_setting(self, parameter, settings):
        # the budget's inputs are in the deviations' unit, which the certificate's settings
        # state with each (assessment 78 L8: "misalignment u 0.3", no unit)
        text = parameter.text(settings[parameter.key])
        if parameter.key in DEVIATION_UNIT_SETTINGS and settings[parameter.key]:
            return f"{text}{DEVIATION_UNITS[self.error_unit(settings)][2]}"
        return text

    def certificate(self, result, metadata, source_name="", settings=None):
        return positioning_certificate(result, metadata, source_name, self.method_reference,
                                       settings)

    def certificate_refusal(self, result):
        # no U whatever the details: a target approached once, readings that show no scatter
        from models.positioning.report import uncertainty_refusal

        return uncertainty_refusal(result) or ""

    def decided_errors(self, result, metadata):
        return np.concatenate([stats.mean for _, _, stats in result.directions_present()])

    def certified_json(self, result, metadata, settings=None):
        # the figures' intervals with the certificate's budget (its reference standards' U):
        # the intervals the certificate prints
        return figures_json(result, positioning_budget(result, metadata, settings))

    def uncertainty_array_names(self, result):
        return [f"per_target/mean_{name}" for name, _, _ in result.directions_present()]

    def inputs_not_stated(self, result, metadata):
        from models.positioning.report import not_stated

        return not_stated(result)

    def uncertainty_budgets(self, result, metadata, settings=None):
        # the budget's points: every target of each direction measured, direction after
        # direction (as the certificate's table); U of the mean deviation per_target.mean_*
        from models.certificate.uncertainty_json import PointUncertainty

        budget = positioning_budget(result, metadata, settings)
        out, start = {}, 0
        for name, _, _stats in result.directions_present():
            stop = start + result.positions.size
            out[f"per_target/mean_{name}"] = PointUncertainty.part(budget, slice(start, stop))
            start = stop
        return out

    def correction_table(self, result, settings, path, metadata=None):
        s = self.checked_settings(settings)
        return write_compensation(path, result, s["compensation_step"], s["compensation_tables"],
                                  s["compensation_format"], s["compensation_controller_options"])

    def settings_for_runs(self, settings):
        return {**settings, "target_unit": "deg", "deviation_unit": "arcsec"}

    def after_log(self, path, settings):
        return _before_after().log_from_file(path, settings, self)

    def compare_after(self, before, after):
        return _before_after().before_after(before, after)

    def printed_rounding(self, result, metadata, settings=None):
        """Each figure's decimal on the certificate: that of its interval with the budget's
        inputs (the reference standards' U) held to the laboratory's CMC, as
        models/positioning/report.py prints it."""
        from models.positioning.report import positioning_budget

        try:
            return figure_decimals(result, positioning_budget(result, metadata, settings))
        except (ValueError, ArithmeticError, IndexError):
            return None

    def printed_headline(self, result, printed=None):
        decimals = figure_decimals(result) | (printed or {})
        return {f"{k} ({result.deviation_unit})": figure_text(v, "", decimals[k])
                for k, v in result.iso.figures.items() if k in decimals and math.isfinite(v)}

    def verdict(self, r, printed=None):
        # each figure to its interval's decimal, as the summary and the certificate print it
        # (GUM 7.2.6; the window said "A 22.447″" beside a summary's "A = 22.4″"), with the
        # certificate's reference standards' U where ``printed`` gives them
        decimals = figure_decimals(r) | (printed or {})
        keys = (("A", "R", "B") if r.bidirectional else
                tuple(f"{f}_{n}" for n, _, _ in r.directions_present() for f in ("A", "R")))
        # a figure printed with no coverage interval says so, here as on the certificate,
        # where its row has none (day review 68 F5)
        none = without_interval(r, readings_figure_intervals(r))
        alone = [k for k in keys if k in none]
        return joined((
            _figures_line(f"{STANDARDS[r.standard].split(' (')[0]}: ",
                          ((k, r.iso.figures.get(k)) for k in keys), r.symbol, decimals),
            message(QT_TR_NOOP(" (no coverage interval: {figures})"), figures=separated(alone, ", "))
            if alone else "",
            "" if r.minimum_runs_met else message(QT_TR_NOOP(" — fewer than 5 runs: flagged"))))

    def headline(self, r):
        return {f"{k} ({r.deviation_unit})": r.iso.figures[k]
                for k in ("A", "R", "B", "A_up", "A_down", "R_up", "R_down")
                if k in r.iso.figures}


POSITIONING = Positioning()


def _before_after():
    from models.positioning import before_after  # imported when a log is first compared

    return before_after
