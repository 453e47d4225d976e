"""SINUMERIK 840D: measuring system error compensation (the "EEC" table file).

Rules, from SINUMERIK 840D sl Function Manual Extended Functions, K3 "Compensations",
section "Interpolatory compensation — measuring system error compensation (MSEC)", with
the system variables and machine data it names:

* K3/MSEC-table: one table per machine axis and measuring system, in the file
  ``%_N_AX_EEC_INI`` as assignments ``$AA_ENC_COMP[n,N,AXi]`` (n = measuring system,
  0 for the first and 1 for the second; N = interpolation point 0…k), with
  ``$AA_ENC_COMP_STEP[n,AXi]`` (distance between points), ``$AA_ENC_COMP_MIN[n,AXi]`` and
  ``$AA_ENC_COMP_MAX[n,AXi]`` (first and last point) and ``$AA_ENC_COMP_IS_MODULO[n,AXi]``;
  the file ends with ``M17``.
* K3/MSEC-points: the number of points is (MAX − MIN)/STEP + 1 and must not exceed
  MD38000 MM_ENC_COMP_MAX_POINTS[n] of the axis (the step must divide the range).
* K3/MSEC-load: the table is loaded only while MD32700 ENC_COMP_ENABLE[n] = 0 (stated in
  the file's comment; the controller, not the file, holds that setting).
* K3/MSEC-sign: the value is the measured error; a positive value moves the axis in the
  negative direction. So $AA_ENC_COMP = mean deviation x̄ = −compensation.
* K3/MSEC-range: beyond MIN and MAX the first and last values hold.
* K3/MSEC-modulo: with IS_MODULO = 1 the table covers one turn and repeats cyclically, MAX
  followed by MIN; the values at both ends must both be entered and agree. The 808D manual
  calls MIN 0°, MAX 360° suitable: a turn measured from elsewhere (e.g. −180…180°) is
  written from 0° (the closed turn read on from 0°, the same value at every angle) when 0° is
  one of its points; when it is not (the first point not a multiple of the step), it is
  written from its first point and the message says so.
* K3/MSEC-system: n selects the measuring system; a table for a measuring system the axis
  does not have (MD30200 NUM_ENCS) is never applied.
* K3/MSEC-reference: the manual recommends that the compensation be zero at the reference
  point (the axis's error there belongs to the reference point's own setting, MD34080
  REFP_MOVE_DIST / MD34090 REFP_MOVE_DIST_CORR, not to the table). Option ``reference``: the
  reference point's position; the table is then shifted so its value there is 0 and the
  shift is stated, to be taken out with MD34090. Which sign MD34090 takes could not be
  verified: the file and the message say which way the axis is left off (actual − target =
  the shift, everywhere) and that a wrong sign doubles it. Without the option the table is
  written as measured and the file and the message say so.
* One table per measuring system: the reversal is MD32450 BACKLASH's, not the table's
  (so separate forward/backward tables are refused, stating the mean reversal over the
  targets, mean(x̄↑ − x̄↓), and MD32450's value for it: positive when the axis stops short on
  reversal, "the encoder leading the machine part (normal situation)", 808D Parameter Manual,
  MD32450).
* Units: positions and values in mm (degrees on a rotary axis); a control with MD10240
  SCALING_SYSTEM_IS_METRIC = 0 reads the table's position data in inches (808D manual,
  "Table parameters that contain position data are interpreted … in inches"): the file and
  the message say so, with what such a control needs (the positions, step and values ÷ 25.4).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from models.messages import QT_TR_NOOP, joined, message
from models.positioning.controllers.common import (
    Option,
    backlash_sense,
    close_turn,
    equidistant_step,
    header_notes,
    in_target_unit,
    parse_options,
    refuse,
    reversal_and_backlash,
)

NAME = "SINUMERIK 840D"
SOURCE = "SINUMERIK 840D sl Function Manual Extended Functions, K3, measuring system error compensation"
OPTIONS = (
    Option("axis", "text", "AX1", QT_TR_NOOP("machine axis name, e.g. AX1 or X1")),
    Option("system", "int", 1, QT_TR_NOOP("measuring system the table is for: 1 or 2"), minimum=1),
    Option("encoders", "int", 1, QT_TR_NOOP("measuring systems the axis has (MD30200 NUM_ENCS)"), minimum=1),
    Option("max_points", "int", 0, QT_TR_NOOP("MD38000 MM_ENC_COMP_MAX_POINTS of the axis (0: "
                                              "not checked, the file states what it needs)"), minimum=0),
    Option("modulo", "float", 0.0, QT_TR_NOOP("a rotary axis's turn, e.g. 360 (0: not modulo)"), minimum=0),
    Option("reference", "float", float("nan"), QT_TR_NOOP(
        "the reference point's position: the table is made zero there (K3's recommendation; "
        "the shift goes to MD34090)")),
)


@dataclass(frozen=True)
class Plan:
    axis: str
    system: int
    encoders: int
    max_points: int
    step: float
    minimum: float
    maximum: float
    modulo: bool
    values: np.ndarray  # measured error (axis unit), one per point
    note: str = ""
    reference: float = float("nan")  # the reference point's position (nan: not given)
    reference_shift: float = 0.0  # the error at the reference point taken out of the table
    unit: str = "mm"  # of the positions and values: "mm" or "deg"


def build(table, options) -> Plan:
    o = parse_options(NAME, OPTIONS, options)
    if table.backward is not None:
        raise refuse(NAME, message(QT_TR_NOOP("one table per measuring system ({source})"),
                                   source=SOURCE),
                     message(QT_TR_NOOP("export one table from the bidirectional mean; the "
                                        "reversal belongs in MD32450 BACKLASH: {reversal}"),
                             reversal=mean_reversal(table)))
    positions = np.asarray(table.positions, dtype=float)
    error = -in_target_unit(table.forward, table.deviation_unit)  # K3/MSEC-sign
    step = equidistant_step(NAME, positions, SOURCE)
    note = ""
    if o["modulo"] > 0:
        positions, (error,), note = close_turn(NAME, positions, [error], o["modulo"], SOURCE)
        positions, error, started = _from_zero(positions, error, o["modulo"])
        if started:
            note = message(QT_TR_NOOP("{note}; the turn is written from 0 (the 808D manual's "
                                      "suitable 0…360), the same value at every angle"), note=note)
        elif abs(positions[0]) > 1e-9:
            note = message(QT_TR_NOOP("{note}; the turn is written {first}…{last}: 0 is not one of "
                                      "its points (the 808D manual calls 0…360 suitable)"),
                           note=note, first=f"{positions[0]:g}", last=f"{positions[-1]:g}")
    shift = 0.0
    reference = o["reference"]
    if np.isfinite(reference):
        if o["modulo"] > 0:
            reference = positions[0] + (reference - positions[0]) % o["modulo"]
        if not positions[0] - 1e-9 <= reference <= positions[-1] + 1e-9:
            raise refuse(NAME, message(QT_TR_NOOP("zero compensation at the reference point "
                                                  "({source})"), source=SOURCE),
                         message(QT_TR_NOOP("the reference point {reference} lies outside the "
                                            "table {first}…{last}"),
                                 reference=f"{o['reference']:g}", first=f"{positions[0]:g}",
                                 last=f"{positions[-1]:g}"))
        shift = float(np.interp(reference, positions, error))
        error = error - shift
    return Plan(o["axis"], o["system"], o["encoders"], o["max_points"], step,
                float(positions[0]), float(positions[-1]), o["modulo"] > 0, error, note,
                reference, shift, "deg" if table.target_unit == "deg" else "mm")


def _from_zero(positions: np.ndarray, values: np.ndarray, period: float
               ) -> tuple[np.ndarray, np.ndarray, bool]:
    """K3/MSEC-modulo: the closed turn read on from 0 (0…period) when 0 is one of its points
    (mod the period); as it is, and False, otherwise or when it starts at 0 already."""
    step = float(positions[1] - positions[0])
    first = float(positions[0]) % period
    count = values.size - 1  # points of one turn (the last is the first again)
    shift = first / step
    if abs(positions[0]) <= 1e-9 * period or abs(shift - round(shift)) > 1e-9 * max(1.0, shift):
        return positions, values, False
    q = int(round(shift)) % count  # point i of the table lies at (q + i)·step mod the period
    turned = values[(np.arange(count + 1) - q) % count]
    return step * np.arange(count + 1), turned, True


def mean_reversal(table) -> str:
    """The mean reversal over the targets and MD32450's value for it (axis unit)."""
    reversal, backlash = reversal_and_backlash(table)
    unit = "°" if table.target_unit == "deg" else " mm"
    return message(QT_TR_NOOP("the mean reversal over the targets, mean(x̄↑ − x̄↓), is {reversal} "
                              "{deviation_unit}, so MD32450 = {backlash}{unit} ({sense})"),
                   reversal=f"{reversal:+.4g}", deviation_unit=table.deviation_unit,
                   backlash=f"{backlash:+.6g}", unit=unit, sense=backlash_sense(backlash))


def lint(plan: Plan) -> Plan:
    """Refuses what the controller would reject or misapply, naming the rule."""
    if plan.system not in (1, 2) or plan.system > plan.encoders:
        raise refuse(NAME, message(QT_TR_NOOP("measuring system (K3; MD30200 NUM_ENCS = {encoders})"),
                                   encoders=plan.encoders),
                     message(QT_TR_NOOP("a table for measuring system {system} is never applied "
                                        "on an axis with {encoders}"),
                             system=plan.system, encoders=plan.encoders))
    intervals = (plan.maximum - plan.minimum) / plan.step
    if plan.step <= 0 or abs(intervals - round(intervals)) > 1e-9 * max(1.0, intervals) or \
            int(round(intervals)) + 1 != plan.values.size:
        raise refuse(NAME, message(QT_TR_NOOP("STEP divides MAX − MIN ({source})"), source=SOURCE),
                     message(QT_TR_NOOP("step {step} over {minimum}…{maximum} with {n} values"),
                             step=f"{plan.step:g}", minimum=f"{plan.minimum:g}",
                             maximum=f"{plan.maximum:g}", n=plan.values.size))
    if plan.max_points and plan.values.size > plan.max_points:
        raise refuse(NAME, message(QT_TR_NOOP("MD38000 MM_ENC_COMP_MAX_POINTS = {max_points}"),
                                   max_points=plan.max_points),
                     message(QT_TR_NOOP("{n} points: choose a larger step"), n=plan.values.size))
    if plan.modulo and abs(plan.values[0] - plan.values[-1]) > 1e-12:
        raise refuse(NAME, message(QT_TR_NOOP("modulo table closed ({source})"), source=SOURCE),
                     message(QT_TR_NOOP("the values at {minimum} and {maximum} differ by {gap}"),
                             minimum=f"{plan.minimum:g}", maximum=f"{plan.maximum:g}",
                             gap=f"{plan.values[-1] - plan.values[0]:.6g}"))
    return plan


def reference_text(plan: Plan) -> str:
    """K3/MSEC-reference: the shift taken out of the table, which way it leaves the axis and
    that a wrong sign of MD34090 doubles it."""
    return message(QT_TR_NOOP("zero at the reference point {reference} (K3): the axis is then left "
                              "{shift} (axis unit) off at every position (actual − target), to be "
                              "taken out with MD34090 REFP_MOVE_DIST_CORR; its sign there is not "
                              "verified here: after re-referencing the deviation at {reference} "
                              "must be 0 — {double} means the sign was wrong"),
                   reference=f"{plan.reference:g}", shift=f"{plan.reference_shift:+.6g}",
                   double=f"{2 * plan.reference_shift:+.6g}")


def unit_text(plan: Plan) -> str:
    """Units: the table in mm (or degrees); what a control in inches needs."""
    if plan.unit == "deg":
        return message(QT_TR_NOOP("positions and values in degrees"))
    return message(QT_TR_NOOP("positions and values in mm: a control with MD10240 "
                              "SCALING_SYSTEM_IS_METRIC = 0 reads them in inches (25.4 times too "
                              "large): for it, divide the positions, the step and the values by "
                              "25.4"))


def render(plan: Plan, notes: list[str] | tuple[str, ...] = ()) -> str:
    """The file; ``notes``: comment lines for its header (";" lines)."""
    n, ax = plan.system - 1, plan.axis
    out = ["%_N_AX_EEC_INI",
           "; AngleBench: measuring system error compensation (K3); value = measured error "
           "(actual - target), a positive value moves the axis negative",
           f"; load with MD32700 ENC_COMP_ENABLE[{n}]=0 and MD38000 MM_ENC_COMP_MAX_POINTS[{n}]"
           f" >= {plan.values.size}; then set MD32700 to 1",
           (f"; {reference_text(plan)}" if np.isfinite(plan.reference) else
            "; written as measured: K3 recommends zero compensation at the reference point "
            "(option reference)"),
           f"; {unit_text(plan)}", *notes,
           "CHANDATA(1)"]
    out += [f"$AA_ENC_COMP[{n},{i},{ax}]={v:.7f}" for i, v in enumerate(plan.values)]
    out += [f"$AA_ENC_COMP_STEP[{n},{ax}]={plan.step:.7g}",
            f"$AA_ENC_COMP_MIN[{n},{ax}]={plan.minimum:.7g}",
            f"$AA_ENC_COMP_MAX[{n},{ax}]={plan.maximum:.7g}",
            f"$AA_ENC_COMP_IS_MODULO[{n},{ax}]={int(plan.modulo)}",
            "M17"]
    return "\n".join(out) + "\n"


def write(table, options) -> tuple[list[tuple[str, str]], str]:
    plan = lint(build(table, options))
    what = message(QT_TR_NOOP("SINUMERIK 840D measuring system error compensation, axis {axis}, "
                              "measuring system {system}, {n} points"),
                   axis=plan.axis, system=plan.system, n=plan.values.size)
    if np.isfinite(plan.reference):
        ref = reference_text(plan)
    else:
        ref = message(QT_TR_NOOP("written as measured: the manual (K3) recommends zero compensation "
                                 "at the reference point (option reference=POSITION)"))
    return ([("", render(plan, header_notes(table)))],
            joined((what, "; " if plan.note else "", plan.note, "; ", ref, "; ", unit_text(plan))))
