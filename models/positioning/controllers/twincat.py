"""Beckhoff TwinCAT NC: table-based position compensation (Tc2_MC2
MC_TableBasedPositionCompensation), as a PLC declaration of the table and its parameters.

Rules, from Beckhoff Information System, TwinCAT 3 PLC library Tc2_MC2:
MC_TableBasedPositionCompensation, ST_PositionCompensationTableElement and
ST_PositionCompensationTableParameter:

* B/equidistant: the correction values are stored in an equidistant, monotonically
  increasing table of elements (Position, Compensation).
* B/additive: Compensation is an additive compensation value to the uncorrected position
  (e.g. the set position): compensation = −x̄.
* B/parameters: MinPosition, MaxPosition, NoOfTableElements; Direction (WorkDirectionBoth,
  or one table per direction: WorkDirectionPositive / WorkDirectionNegative); Modulo
  (TRUE: a modulo axis with a cyclic period).

Not verified (see docs/user-guide/positioning.md): what is applied beyond MinPosition…MaxPosition (held here),
a limit on the number of elements, and how a modulo table's ends are joined (the ends
are made equal here).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from models.messages import QT_TR_NOOP, message
from models.positioning.controllers.common import (
    Option,
    close_turn,
    equidistant_step,
    header_notes,
    in_target_unit,
    parse_options,
    refuse,
)

NAME = "TwinCAT (Tc2_MC2)"
SOURCE = "Beckhoff Tc2_MC2 MC_TableBasedPositionCompensation"
OPTIONS = (
    Option("name", "text", "Axis1", QT_TR_NOOP("prefix of the PLC variables, e.g. Axis1")),
    Option("modulo", "float", 0.0, QT_TR_NOOP("a modulo axis's period, e.g. 360 (0: linear)"), minimum=0),
)


@dataclass(frozen=True)
class Plan:
    name: str
    positions: np.ndarray
    tables: dict[str, np.ndarray]  # direction → compensation (axis unit)
    modulo: bool


def build(table, options) -> Plan:
    o = parse_options(NAME, OPTIONS, options)
    if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", o["name"]):
        raise refuse(NAME, "name", message(QT_TR_NOOP("'{name}' is not a PLC identifier"),
                                           name=o["name"]))
    positions = np.asarray(table.positions, dtype=float)
    columns = [in_target_unit(table.forward, table.deviation_unit)]  # B/additive
    if table.backward is not None:
        columns.append(in_target_unit(table.backward, table.deviation_unit))
    equidistant_step(NAME, positions, SOURCE)
    if o["modulo"] > 0:
        positions, columns, _ = close_turn(NAME, positions, columns, o["modulo"], SOURCE)
    tables = ({"WorkDirectionBoth": columns[0]} if len(columns) == 1 else
              {"WorkDirectionPositive": columns[0], "WorkDirectionNegative": columns[1]})
    return Plan(o["name"], positions, tables, o["modulo"] > 0)


def lint(plan: Plan) -> Plan:
    steps = np.diff(plan.positions)
    if plan.positions.size < 2 or np.any(steps <= 0) or \
            np.max(np.abs(steps - steps.mean())) > 1e-9 * max(1.0, abs(steps.mean())):
        raise refuse(NAME, message(QT_TR_NOOP("equidistant, monotonically increasing table ({source})"),
                                   source=SOURCE),
                     message(QT_TR_NOOP("the positions are not equally spaced and ascending")))
    if plan.modulo:
        for values in plan.tables.values():
            if values[0] != values[-1]:
                raise refuse(NAME, message(QT_TR_NOOP("modulo table closed ({source})"), source=SOURCE),
                             message(QT_TR_NOOP("the values at {minimum} and {maximum} differ by {gap}"),
                                     minimum=f"{plan.positions[0]:g}", maximum=f"{plan.positions[-1]:g}",
                                     gap=f"{values[-1] - values[0]:.6g}"))
    return plan


def render(plan: Plan, notes: list[str] | tuple[str, ...] = ()) -> str:
    """The declaration; ``notes``: comment lines for its header."""
    n = plan.positions.size
    out = ["(* AngleBench: table for Tc2_MC2 MC_TableBasedPositionCompensation; Compensation = "
           "-mean deviation, added to the set position *)",
           *(f"(* {line} *)" for line in notes), "VAR_GLOBAL"]
    for direction, values in plan.tables.items():
        tag = {"WorkDirectionBoth": "", "WorkDirectionPositive": "Pos",
               "WorkDirectionNegative": "Neg"}[direction]
        out.append(f"    {plan.name}_CompParam{tag} : ST_PositionCompensationTableParameter := ("
                   f"MinPosition := {plan.positions[0]:.9g}, MaxPosition := {plan.positions[-1]:.9g}, "
                   f"NoOfTableElements := {n}, Direction := {direction}, "
                   f"Modulo := {'TRUE' if plan.modulo else 'FALSE'});")
        out.append(f"    {plan.name}_CompTable{tag} : ARRAY[0..{n - 1}] OF "
                   "ST_PositionCompensationTableElement := [")
        rows = [f"        (Position := {p:.9g}, Compensation := {v:.9f})"
                for p, v in zip(plan.positions, values, strict=True)]
        out.append(",\n".join(rows))
        out.append("    ];")
    out.append("END_VAR")
    return "\n".join(out) + "\n"


def write(table, options) -> tuple[list[tuple[str, str]], str]:
    plan = lint(build(table, options))
    what = message(QT_TR_NOOP("TwinCAT Tc2_MC2 position compensation table(s) {name}, {n} elements"),
                   name=plan.name, n=plan.positions.size)
    return [("", render(plan, header_notes(table, "")))], what
