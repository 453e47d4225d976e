"""ISG kernel (TwinCAT CNC): leadscrew error compensation in the axis compensation list
(kw.ssfk.*).

Rules, from ISG / Beckhoff Information System, TwinCAT CNC "Axis compensation",
Leadscrew error compensation (FCT-C5) and its parameters P-COMP-00017…00025, 00059:

* I/list: the compensation list holds the header kopf.log_achs_nr / kopf.log_achs_name and
  kw.ssfk.unit (1: metric, 0.1 µm, or 0.0001° for a rotary axis), kw.ssfk.interval
  (equidistant points; 0: each point's kw.ssfk.table[i].setpoint given),
  kw.ssfk.kw_startpos, kw.ssfk.kw_nr_max (number of entries), kw.ssfk.bilateral and
  kw.ssfk.modulo.
* I/values: the values are absolute position errors Δs = actual − set point (the list's
  own example: programmed 19866.7 µm, measured 19856.5 µm, value −102 × 0.1 µm):
  kw.ssfk.table[i].pos for the positive direction, .neg for the negative one (bilateral);
  the controller subtracts them.
* I/interpolation: between points the value is interpolated linearly.
* I/max: kw_nr_max must be smaller than P-COMP-00059 (default 1500).
* I/range: the type of ``pos``/``neg`` is SGN16 in older pages of the TwinCAT CNC
  documentation and SGN32 in newer ones: option ``value_type`` (default ``sgn16``, which every
  version takes). The range is "MIN(SGN16) < pos < MAX(SGN16)", both bounds excluded
  (TwinCAT CNC axis compensation, kw.ssfk.table[i].pos): −32767…+32766 × 0.1 µm, i.e.
  −3.2767…+3.2766 mm (SGN32: −2147483647…+2147483646); a value beyond it is refused, never
  wrapped or clipped.

Not verified (see docs/user-guide/positioning.md): what is applied beyond the table (held here). The ISG "CSV
format" belongs to the volumetric compensation (TF5280), not to an axis table; it is not
written.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from models.messages import QT_TR_NOOP, message
from models.positioning.controllers.common import (
    ControllerRuleError,
    Option,
    close_turn,
    equidistant_step,
    header_notes,
    in_target_unit,
    parse_options,
    refuse,
)

NAME = "ISG kernel"
SOURCE = "ISG/TwinCAT CNC axis compensation, leadscrew error compensation (P-COMP-00017…00025)"
UNIT = 1e-4  # 0.1 µm in mm, 0.0001° in degrees (kw.ssfk.unit = 1)
OPTIONS = (
    Option("axis_number", "int", 1, QT_TR_NOOP("logical axis number (kopf.log_achs_nr)"), minimum=1),
    Option("axis_name", "text", "X", QT_TR_NOOP("axis name (kopf.log_achs_name)")),
    Option("max_points", "int", 1500, QT_TR_NOOP("P-COMP-00059 of the axis (default 1500)"), minimum=2),
    Option("modulo", "float", 0.0, QT_TR_NOOP("a modulo axis's turn, 360 (0: linear)"), minimum=0),
    Option("value_type", "text", "sgn16", QT_TR_NOOP("type of pos/neg in the kernel's "
                                                     "documentation: sgn16 (older) or sgn32")),
)
#: I/range: MIN and MAX of each type; a pos/neg value lies strictly between them
VALUE_LIMITS = {"sgn16": (-2 ** 15, 2 ** 15 - 1), "sgn32": (-2 ** 31, 2 ** 31 - 1)}


@dataclass(frozen=True)
class Plan:
    number: int
    name: str
    start: float  # list units
    interval: float  # list units
    pos: np.ndarray  # int, list units
    neg: np.ndarray | None
    modulo: bool
    max_points: int
    value_type: str = "sgn16"


def build(table, options) -> Plan:
    o = parse_options(NAME, OPTIONS, options)
    if o["value_type"].lower() not in VALUE_LIMITS:
        raise ControllerRuleError(message(QT_TR_NOOP(
            "{controller} options: value_type={value}; it takes {known}"), controller=NAME,
            value=o["value_type"], known=", ".join(VALUE_LIMITS)))
    positions = np.asarray(table.positions, dtype=float)
    columns = [-in_target_unit(table.forward, table.deviation_unit)]  # I/values: the error
    if table.backward is not None:
        columns.append(-in_target_unit(table.backward, table.deviation_unit))
    step = equidistant_step(NAME, positions, SOURCE)
    if o["modulo"] > 0:
        positions, columns, _ = close_turn(NAME, positions, columns, o["modulo"], SOURCE)
    values = [np.round(c / UNIT).astype(np.int64) for c in columns]
    return Plan(o["axis_number"], o["axis_name"], positions[0] / UNIT, step / UNIT, values[0],
                values[1] if len(values) > 1 else None, o["modulo"] > 0, o["max_points"],
                o["value_type"].lower())


def lint(plan: Plan) -> Plan:
    for key, value in (("kw_startpos", plan.start), ("interval", plan.interval)):
        if abs(value - round(value)) > 1e-6:
            raise refuse(NAME, message(QT_TR_NOOP("{key} in whole units of 0.1 µm / 0.0001° ({source})"),
                                       key=key, source=SOURCE),
                         message(QT_TR_NOOP("{value} units"), value=f"{value:.6g}"))
    if plan.interval <= 0:
        raise refuse(NAME, "interval", message(QT_TR_NOOP("the positions must ascend")))
    if plan.pos.size >= plan.max_points:
        raise refuse(NAME, message(QT_TR_NOOP("kw_nr_max < P-COMP-00059 = {max_points}"),
                                   max_points=plan.max_points),
                     message(QT_TR_NOOP("{n} points: choose a larger step"), n=plan.pos.size))
    low, high = VALUE_LIMITS[plan.value_type]
    for values in (plan.pos, plan.neg):
        if values is None:
            continue
        outside = np.nonzero((values <= low) | (values >= high))[0]
        if outside.size:
            worst = outside[np.argmax(np.abs(values[outside]))]
            raise refuse(NAME, message(QT_TR_NOOP("pos/neg are {kind}: MIN({kind}) < value < "
                                                  "MAX({kind}), {low}…{high} units of 0.1 µm / "
                                                  "0.0001°"), kind=plan.value_type.upper(),
                                       low=low + 1, high=f"+{high - 1}"),
                         message(QT_TR_NOOP("a value of {value} units{hint}"),
                                 value=int(values[worst]),
                                 hint=message(QT_TR_NOOP(" (value_type=sgn32 if the kernel's "
                                                         "documentation types them so)"))
                                 if plan.value_type == "sgn16" else ""))
    if plan.modulo:
        for values in (plan.pos, plan.neg):
            if values is not None and values[0] != values[-1]:
                raise refuse(NAME, message(QT_TR_NOOP("modulo table closed ({source})"), source=SOURCE),
                             message(QT_TR_NOOP("the first and last values differ by {gap}"),
                                     gap=int(values[-1] - values[0])))
    return plan


def render(plan: Plan, notes: list[str] | tuple[str, ...] = ()) -> str:
    """The list; ``notes``: comment lines for its header ("#" lines)."""
    out = ["# AngleBench: leadscrew error compensation (kw.ssfk); values = actual - set point "
           "in 0.1 um (0.0001 deg)", *notes,
           f"kopf.log_achs_nr                 {plan.number}",
           f"kopf.log_achs_name               {plan.name}",
           "kw.ssfk.unit                     1",
           f"kw.ssfk.interval                 {int(round(plan.interval))}",
           f"kw.ssfk.kw_startpos              {int(round(plan.start))}",
           f"kw.ssfk.kw_nr_max                {plan.pos.size}",
           f"kw.ssfk.bilateral                {int(plan.neg is not None)}",
           f"kw.ssfk.modulo                   {int(plan.modulo)}"]
    out += [f"kw.ssfk.table[{i}].pos {' ' * (14 - len(str(i)))}{v}" for i, v in enumerate(plan.pos)]
    if plan.neg is not None:
        out += [f"kw.ssfk.table[{i}].neg {' ' * (14 - len(str(i)))}{v}"
                for i, v in enumerate(plan.neg)]
    return "\n".join(out) + "\n"


def write(table, options) -> tuple[list[tuple[str, str]], str]:
    plan = lint(build(table, options))
    what = message(QT_TR_NOOP("ISG leadscrew error compensation list, axis {axis}, {n} points{sides}"),
                   axis=plan.name, n=plan.pos.size,
                   sides=message(QT_TR_NOOP(", bilateral")) if plan.neg is not None else "")
    return [("", render(plan, header_notes(table, "# ")))], what
