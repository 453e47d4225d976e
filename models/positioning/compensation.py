"""Compensation tables for the axis controller, from a positioning result.

The compensation at a position is the negative of the mean positional deviation
there (compensation = −x̄; the controller adds it to the commanded position so that
the axis reaches the target). Tables are given at the targets, or at a uniform
spacing by linear interpolation between targets (never beyond the first and last
target: no extrapolation). Two forms:

* separate forward and backward tables (−x̄↑, −x̄↓): the reversal is compensated too;
* one bidirectional table, −(x̄↑ + x̄↓)/2 (the reversal is left to the controller's
  backlash setting).

Formats: CSV always. LinuxCNC's joint compensation file, ``COMP_FILE_TYPE = 0``, as
documented in the LinuxCNC manual (INI configuration, section [JOINT_n], COMP_FILE
and COMP_FILE_TYPE): one line per point, "nominal actual-forward actual-reverse" in
machine units (mm, or degrees for an angular joint), nominal ascending, at most 256
lines; the controller reads the actual positions and compensates itself, so the
file holds measured positions, not corrections. LinuxCNC does not wrap a rotary joint's
table: beyond its first and last lines it applies their values (checked against
LinuxCNC's own loading and look-up code), so at 370° it applies the value at the end of
the table, not at 10°. For a rotary joint the options ``modulo=360, travel_min=…,
travel_max=…`` write the closed turn repeated over the whole travel of the joint (at most
256 lines); without them the table is written as measured and the message warns that it
is not wrapped. The other controllers' formats
(SINUMERIK 840D, FANUC, HEIDENHAIN TNC, TwinCAT, ISG, Mach4) are in
models/positioning/controllers/, one module each, every rule citing its manual.
"""

from __future__ import annotations

import io
import os
from dataclasses import dataclass

import numpy as np

from models.messages import QT_TR_NOOP, joined, lines, message
from models.positioning.controllers.common import (
    ControllerRuleError,
    Option,
    close_turn,
    equidistant_step,
    header_notes,
    parse_options,
    refuse,
    table_notes,
)
from models.positioning.model import DEVIATION_UNITS, PositioningResult
from models.project.atomic_write import write_text_atomic

__all__ = ["LINUXCNC_MAX_POINTS", "LINUXCNC_NAME", "LINUXCNC_OPTIONS", "CompensationTable",
           "compensation_table", "compensation_csv", "linuxcnc_comp_file", "write_compensation"]

LINUXCNC_MAX_POINTS = 256
LINUXCNC_NAME = "LinuxCNC"
LINUXCNC_SOURCE = "LinuxCNC INI configuration, [JOINT_n] COMP_FILE_TYPE = 0"
FORMS = {"separate": QT_TR_NOOP("separate tables for the forward and the backward approach"),
         "bidirectional": QT_TR_NOOP("one table from the bidirectional mean (x_up + x_down)/2"),
         "forward only": QT_TR_NOOP("forward approach only (the backward was not measured)"),
         "backward only": QT_TR_NOOP("backward approach only (the forward was not measured)")}
MAX_POINTS = 100_000


@dataclass(frozen=True)
class CompensationTable:
    """Positions (target unit) and compensations (deviation unit); ``backward`` is None for
    one bidirectional table."""

    positions: np.ndarray
    forward: np.ndarray
    backward: np.ndarray | None
    target_unit: str
    deviation_unit: str
    spacing: str  # "at the targets" or "uniform step …"
    form: str  # "separate", "bidirectional", "forward only" or "backward only"
    last_target: float = float("nan")  # the log's last target (the table may end before it)


def _resample(positions: np.ndarray, values: np.ndarray, grid: np.ndarray,
              refusal: str) -> np.ndarray:
    """``values`` on ``grid``; ``refusal`` (a template naming the missing targets) when a
    target has none."""
    ok = np.isfinite(values)
    if not ok.all():
        raise ValueError(message(refusal, missing=", ".join(f"{p:g}" for p in positions[~ok])))
    return np.interp(grid, positions, values)


def compensation_table(result: PositioningResult, step: float = 0.0,
                       tables: str = "separate") -> CompensationTable:
    """The table: at the targets (``step`` 0) or every ``step`` from the first target."""
    positions = result.positions
    if step > 0:
        span = float(positions[-1] - positions[0])
        count = int(np.floor(span / step + 1e-9)) + 1
        if count < 2:
            raise ValueError(message(
                QT_TR_NOOP("a step of {step} leaves fewer than two points over the targets "
                           "{positions}…{positions2}"),
                step=f"{step:g}", positions=f"{positions[0]:g}", positions2=f"{positions[-1]:g}"))
        if count > MAX_POINTS:
            raise ValueError(message(
                QT_TR_NOOP("a step of {step} gives {count} points; at most {max_points}"),
                step=f"{step:g}", count=count, max_points=MAX_POINTS))
        grid = positions[0] + step * np.arange(count)
        spacing = message(QT_TR_NOOP("uniform step {step}"), step=f"{step:g}")
    else:
        grid, spacing = positions.copy(), message(QT_TR_NOOP("at the targets"))
    iso = result.iso
    if tables == "bidirectional":
        if not result.bidirectional:
            raise ValueError(message(
                QT_TR_NOOP("a bidirectional table needs both approach directions; this run has one: "
                           "export separate tables")))
        forward = -_resample(positions, iso.bidirectional_mean, grid,
                              QT_TR_NOOP("no bidirectional mean deviation at target(s) {missing}: a "
                                         "compensation table needs every target"))
        backward, form = None, "bidirectional"
    else:
        form = "separate"
        forward = backward = None
        if iso.forward is not None:
            forward = -_resample(positions, iso.forward.mean, grid,
                                  QT_TR_NOOP("no forward mean deviation at target(s) {missing}: a "
                                             "compensation table needs every target"))
        if iso.backward is not None:
            backward = -_resample(positions, iso.backward.mean, grid,
                                   QT_TR_NOOP("no backward mean deviation at target(s) {missing}: a "
                                              "compensation table needs every target"))
        if forward is None:  # backward only: it is the table
            forward, backward, form = backward, None, "backward only"
        elif backward is None:
            form = "forward only"
    return CompensationTable(grid, forward, backward, result.target_unit, result.deviation_unit,
                             spacing, form, float(positions[-1]))


def compensation_csv(table: CompensationTable) -> str:
    unit, tu = table.deviation_unit, table.target_unit
    out = io.StringIO()
    out.write("# AngleBench compensation table: compensation = -mean positional deviation "
              "(deviation = actual - target, ISO 230-2); commanded = target + compensation\n")
    out.write(f"# spacing: {table.spacing}\n")
    out.write(f"# {FORMS[table.form]}\n")
    for line in header_notes(table, "# "):
        out.write(f"{line}\n")
    if table.backward is None:
        out.write(f"position_{tu},compensation_{unit}\n")
        for p, c in zip(table.positions, table.forward, strict=True):
            out.write(f"{p:.9g},{c:.6f}\n")
    else:
        out.write(f"position_{tu},forward_compensation_{unit},backward_compensation_{unit}\n")
        for p, f, b in zip(table.positions, table.forward, table.backward, strict=True):
            out.write(f"{p:.9g},{f:.6f},{b:.6f}\n")
    return out.getvalue()


def _linuxcnc_options():
    return (
        Option("modulo", "float", 0.0, QT_TR_NOOP("a rotary joint's turn, 360 (0: linear): the table "
                                                  "is repeated over the joint's travel")),
        Option("travel_min", "float", float("nan"), QT_TR_NOOP("a rotary joint's travel, lowest "
                                                               "position (MIN_LIMIT)")),
        Option("travel_max", "float", float("nan"), QT_TR_NOOP("a rotary joint's travel, highest "
                                                               "position (MAX_LIMIT)")),
    )


LINUXCNC_OPTIONS = _linuxcnc_options()


def _over_travel(table: CompensationTable, modulo: float, low: float, high: float):
    """The closed turn repeated over ``low``…``high``: positions and the two compensations."""
    positions = np.asarray(table.positions, dtype=float)
    equidistant_step(LINUXCNC_NAME, positions, LINUXCNC_SOURCE)
    grid, (forward, backward), _ = close_turn(LINUXCNC_NAME, positions,
                                              [np.asarray(table.forward, dtype=float),
                                               np.asarray(table.backward, dtype=float)],
                                              modulo, LINUXCNC_SOURCE)
    start, step = float(grid[0]), float(grid[1] - grid[0])
    first = int(np.ceil((low - start) / step - 1e-9))
    last = int(np.floor((high - start) / step + 1e-9))
    points = start + step * np.arange(first, last + 1)
    points = np.unique(np.concatenate(([low], points[(points > low) & (points < high)], [high])))

    def periodic(values):
        return np.interp(start + np.mod(points - start, modulo), grid, values)

    return points, periodic(forward), periodic(backward)


def linuxcnc_comp_file(table: CompensationTable, options="") -> tuple[str, str]:
    """LinuxCNC COMP_FILE_TYPE 0: "nominal actual_forward actual_reverse" in machine units; with
    the text of what was written (and, for a rotary joint written as measured, the warning
    that LinuxCNC does not wrap it)."""
    if table.backward is None:
        raise ValueError(message(
            QT_TR_NOOP("LinuxCNC's compensation file lists the forward and the reverse positions: export "
                       "separate tables (both directions measured)")))
    o = parse_options(LINUXCNC_NAME, LINUXCNC_OPTIONS, options)
    positions, forward, backward = table.positions, table.forward, table.backward
    note = ""
    if o["modulo"] > 0:
        low = o["travel_min"] if np.isfinite(o["travel_min"]) else float(positions[0])
        high = (o["travel_max"] if np.isfinite(o["travel_max"])
                else float(positions[0]) + o["modulo"])
        if not high > low:
            raise ControllerRuleError(message(QT_TR_NOOP(
                "{controller} options: travel_max must be above travel_min"), controller=LINUXCNC_NAME))
        positions, forward, backward = _over_travel(table, o["modulo"], low, high)
        note = message(QT_TR_NOOP("LinuxCNC does not wrap a rotary joint's table: the closed turn is "
                                  "written over the joint's travel {low}…{high}; beyond it the end "
                                  "values apply"), low=f"{low:g}", high=f"{high:g}")
    elif table.target_unit == "deg":
        note = message(QT_TR_NOOP("warning: LinuxCNC does not wrap a rotary joint's table: beyond "
                                  "{first}…{last} it applies the end values (at {beyond} the value at "
                                  "{last}, not at {wrapped}); give modulo=360, travel_min and "
                                  "travel_max to write it over the joint's travel"),
                       first=f"{positions[0]:g}", last=f"{positions[-1]:g}",
                       beyond=f"{positions[-1] + 10:g}", wrapped=f"{positions[0] + 10:g}")
    if np.asarray(positions).size > LINUXCNC_MAX_POINTS:
        raise refuse(LINUXCNC_NAME, message(QT_TR_NOOP("at most {n} lines per joint ({source})"),
                                            n=LINUXCNC_MAX_POINTS, source=LINUXCNC_SOURCE),
                     message(QT_TR_NOOP("{size} points: choose a larger step or a shorter travel"),
                             size=np.asarray(positions).size))
    scale = DEVIATION_UNITS[table.deviation_unit][1]
    lines = []
    for p, f, b in zip(positions, forward, backward, strict=True):
        # actual position = nominal + mean deviation = nominal − compensation
        lines.append(f"{p:.9f} {p - f / scale:.9f} {p - b / scale:.9f}")
    return "\n".join(lines) + "\n", note


def check_compensation(result: PositioningResult, step: float = 0.0, tables: str = "separate",
                       fmt: str = "csv", options: str = "") -> None:
    """Make the table in memory, nothing written: ValueError naming the rule when the
    controller would reject or misapply it (the window asks this before its file dialog)."""
    from models.positioning.controllers import CONTROLLERS

    table = compensation_table(result, step, tables)
    if fmt in CONTROLLERS:
        if fmt == "heidenhain":
            CONTROLLERS[fmt].write(table, options, name="COMP.COM")
        else:
            CONTROLLERS[fmt].write(table, options)


def write_compensation(path: str, result: PositioningResult, step: float = 0.0,
                       tables: str = "separate", fmt: str = "csv", options: str = "") -> str:
    """Write the table (atomically); returns what was written, on its first line, and on the
    next ones what the user must know of the table (:func:`table_notes`). ``options``
    (``key=value, …``) are the controller's (models/positioning/controllers); a table the
    controller would reject or misapply is refused naming the rule, and nothing is written."""
    from models.positioning.controllers import CONTROLLERS

    table = compensation_table(result, step, tables)
    notes = table_notes(table)  # said with every format: machine coordinates, one direction, end
    if fmt in CONTROLLERS:
        module = CONTROLLERS[fmt]
        stem = os.path.splitext(path)[0]
        if fmt == "heidenhain":  # the .CMA beside the .COM: its path is said
            files, what = module.write(table, options, name=os.path.basename(path),
                                       cma_path=stem + ".CMA")
        else:
            files, what = module.write(table, options)
        for suffix, text in files:  # every file made before any is written
            write_text_atomic(stem + suffix if suffix else path, text)
        return _with_notes(what, notes)
    if fmt == "linuxcnc":
        text, note = linuxcnc_comp_file(table, options)
        what = message(QT_TR_NOOP("LinuxCNC compensation file (COMP_FILE_TYPE = 0), {n} points "
                                  "in {unit}"), n=text.count("\n"), unit=table.target_unit)
        if note:
            what = joined((what, "; ", note))
    else:
        text = compensation_csv(table)
        what = message(QT_TR_NOOP("Compensation table, {n} points ({form}, {spacing})"),
                       n=table.positions.size, form=message(FORMS[table.form]),
                       spacing=table.spacing)
    write_text_atomic(path, text)
    return _with_notes(what, notes)


def _with_notes(what: str, notes: list[str]) -> str:
    """What was written, on its first line; what the user must know of it on the next ones
    (the command line prints "… written to PATH" after the first)."""
    return lines((what, *notes))
