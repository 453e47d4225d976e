"""HEIDENHAIN TNC: nonlinear axis error compensation (a .COM table and its .CMA assignment).

Rules, from the HEIDENHAIN technical manuals (TNC 407/415/425 Technical Manual, 1 "Machine
axes", nonlinear axis error compensation, and module 9095; MANUALplus 620 Technical
Manual, "Entering compensation values" and "Assigning the compensation value tables to
the axes"):

* H/COM: the compensation points go in column AXISPOS, with respect to the machine datum;
  the compensation values in the column named after the compensated axis; the values
  measured in the negative direction of traverse, if wanted, in column BACKLASH.
* H/256: a .COM table has at most 256 entries (module 9095, error 3).
* H/CMA: a .CMA table assigns .COM tables to axes, a column per axis; several lines may be
  entered, only one is active (ACTIVE = *). It holds "the names of the compensation-value
  tables (*.com)" (MANUALplus 620 Technical Manual, "Assigning the compensation value
  tables to the axes"), and module 9095 answers error 2, "No such compensation table
  (.COM)", for a name it cannot load: a table file not named *.COM is refused (the name it
  needs is given), and the names inside both files are the files' names as written, in
  their case (the .COM's BEGIN line and the .CMA's active line name the .COM; the .CMA's
  BEGIN line names the .CMA).
* H/rotary: on a rotary axis only the entries 0…360 are recognised.
* H/equidistant: the compensation points are equally spaced ("Equidistant spacing
  between the measuring points is necessary", MANUALplus 620 Technical Manual, "Entering
  compensation values"), on linear axes as on rotary ones: a table measured at unequal
  steps is refused, naming a compensation step that resamples it (``--compensation-step``).
* H/407: on the TNC 407/415/425 (option ``control=tnc407``) the spacing of the points is a
  power of two in 0.1 µm (the manual's example: a wanted 7 mm becomes 2^16 × 0.1 µm =
  6.5536 mm; TNC 407/415/425 Technical Manual 01.98, 1.6.4 "Nonlinear axis error
  compensation", p. 4-28). Checked on linear axes; on a rotary axis the unit of that power
  of two is not stated there, so it is not checked.

Not verified (see docs/user-guide/positioning.md), hence options without a default or stated in the file: the
sign of a value (the option ``values`` must say whether the machine's manual wants the
error — actual − target — or the correction), the table file's header and end lines
(BEGIN …/[END], as TNC tables are written), and what is applied beyond the last entry.
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
    in_target_unit,
    parse_options,
    refuse,
)

NAME = "HEIDENHAIN TNC"
SOURCE = "HEIDENHAIN Technical Manual, nonlinear axis error compensation"
SOURCE_EQUIDISTANT = "MANUALplus 620 Technical Manual, Entering compensation values"
SOURCE_407 = "TNC 407/415/425 Technical Manual, 1.6.4, p. 4-28"
MAX_ENTRIES = 256
OPTIONS = (
    Option("axis", "text", "X", QT_TR_NOOP("axis key (column name), e.g. X or C")),
    Option("values", "text", None, QT_TR_NOOP("error (actual − target) or correction (−error): "
                                              "as the machine's manual states")),
    Option("modulo", "float", 0.0, QT_TR_NOOP("a rotary axis's turn, 360 (0: linear)"), minimum=0),
    Option("control", "text", "tnc", QT_TR_NOOP("tnc (iTNC, TNC 6xx, MANUALplus) or tnc407 (TNC "
                                                "407/415/425: a spacing of 2^n × 0.1 µm)")),
)
CONTROLS = ("tnc", "tnc407")
#: TNC 407/415/425: the spacing of the compensation points is 2^n of this (mm)
TNC407_QUANTUM_MM = 1e-4


@dataclass(frozen=True)
class Plan:
    axis: str
    sense: str
    positions: np.ndarray
    forward: np.ndarray
    backward: np.ndarray | None
    rotary: bool
    unit: str


def build(table, options) -> Plan:
    o = parse_options(NAME, OPTIONS, options)
    if o["values"] not in ("error", "correction"):
        raise ControllerRuleError(message(QT_TR_NOOP(
            "{controller} options: values=error or values=correction must be given (the sign "
            "of a .COM value could not be verified: take it from the machine's manual)"),
            controller=NAME))
    sign = -1.0 if o["values"] == "error" else 1.0
    positions = np.asarray(table.positions, dtype=float)
    columns = [sign * in_target_unit(table.forward, table.deviation_unit)]
    if table.backward is not None:
        columns.append(sign * in_target_unit(table.backward, table.deviation_unit))
    if o["control"].lower() not in CONTROLS:
        raise ControllerRuleError(message(QT_TR_NOOP(
            "{controller} options: control={control}; it takes {known}"), controller=NAME,
            control=o["control"], known=", ".join(CONTROLS)))
    rotary = o["modulo"] > 0
    step = _equidistant(positions)
    if rotary:
        positions, columns, _ = close_turn(NAME, positions, columns, o["modulo"], SOURCE)
    elif o["control"].lower() == "tnc407":
        _power_of_two(step, table.target_unit)
    return Plan(o["axis"].upper(), o["values"], positions, columns[0],
                columns[1] if len(columns) > 1 else None, rotary, table.target_unit)


def _equidistant(positions: np.ndarray) -> float:
    """H/equidistant: the step; refused with the step that would resample the table (the
    smallest spacing measured, or a larger one when that makes more than 256 points)."""
    try:
        return equidistant_step(NAME, positions, SOURCE_EQUIDISTANT)
    except ControllerRuleError:
        steps = np.diff(positions)
        smallest = float(np.min(steps[steps > 0])) if np.any(steps > 0) else 0.0
        span = float(positions[-1] - positions[0])
        suggested = max(smallest, span / (MAX_ENTRIES - 1)) if smallest > 0 else 0.0
        raise refuse(NAME, message(QT_TR_NOOP("equidistant points ({source})"),
                                   source=SOURCE_EQUIDISTANT),
                     message(QT_TR_NOOP("the points are spaced {low}…{high}: resample the table at "
                                        "one compensation step, e.g. {step} (compensation step)"),
                             low=f"{float(np.min(steps)):g}", high=f"{float(np.max(steps)):g}",
                             step=f"{suggested:g}")) from None


def _power_of_two(step: float, unit: str) -> None:
    """H/407: the spacing 2^n × 0.1 µm (a linear axis in mm)."""
    if unit != "mm":
        return
    units = step / TNC407_QUANTUM_MM
    exponent = round(np.log2(units)) if units > 0 else 0
    if units <= 0 or abs(units - 2.0 ** exponent) > 1e-6 * units:
        below = 2.0 ** np.floor(np.log2(max(units, 1.0))) * TNC407_QUANTUM_MM
        raise refuse(NAME, message(QT_TR_NOOP("TNC 407/415/425: a spacing of 2^n × 0.1 µm "
                                              "({source})"), source=SOURCE_407),
                     message(QT_TR_NOOP("a step of {step} mm is not one: choose {below} mm or "
                                        "{above} mm (compensation step)"),
                             step=f"{step:g}", below=f"{below:g}", above=f"{2 * below:g}"))


def lint(plan: Plan) -> Plan:
    if plan.positions.size > MAX_ENTRIES:
        raise refuse(NAME, message(QT_TR_NOOP("at most {n} entries per .COM table ({source})"),
                                   n=MAX_ENTRIES, source=SOURCE),
                     message(QT_TR_NOOP("{n} points: choose a larger step"), n=plan.positions.size))
    if np.any(np.diff(plan.positions) <= 0):
        raise refuse(NAME, "AXISPOS", message(QT_TR_NOOP("the positions must ascend")))
    if plan.rotary and (plan.positions[0] < 0 or plan.positions[-1] > 360 + 1e-9):
        raise refuse(NAME, message(QT_TR_NOOP("rotary axis: entries 0…360 only ({source})"),
                                   source=SOURCE),
                     message(QT_TR_NOOP("the table runs {first}…{last}"),
                             first=f"{plan.positions[0]:g}", last=f"{plan.positions[-1]:g}"))
    return plan


def table_name(name: str, axis: str) -> str:
    """H/CMA: the .COM file's name ("" → AXIS.COM); a name that is not *.COM is refused,
    naming the one the control loads."""
    if not name:
        return f"{axis}.COM"
    stem, dot, ext = name.rpartition(".")
    if not dot or not stem or ext.lower() != "com":
        raise refuse(NAME, message(QT_TR_NOOP("compensation tables are *.COM files, named in the "
                                              ".CMA ({source}, module 9095: \"No such compensation "
                                              "table (.COM)\")"), source=SOURCE),
                     message(QT_TR_NOOP("'{name}' would not be loaded: name it {wanted}"),
                             name=name, wanted=f"{stem or name}.COM"))
    return name


def cma_name(name: str) -> str:
    """The .CMA written beside the .COM ``name``: its stem and .CMA."""
    return f"{name.rpartition('.')[0]}.CMA"


def render(plan: Plan, name: str) -> tuple[str, str]:
    unit = " MM" if plan.unit == "mm" else ""
    head = f"{'NR':<6}{'AXISPOS':>14}{plan.axis:>14}" + (
        f"{'BACKLASH':>14}" if plan.backward is not None else "")
    com = [f"BEGIN {name}{unit}", head]
    for i, p in enumerate(plan.positions):
        row = f"{i:<6}{p:>+14.5f}{plan.forward[i]:>+14.6f}"
        if plan.backward is not None:
            row += f"{plan.backward[i]:>+14.6f}"
        com.append(row)
    com.append("[END]")
    cma = [f"BEGIN {cma_name(name)}", f"{'NR':<6}{'ACTIVE':<8}{plan.axis}",
           f"{0:<6}{'*':<8}{name}", "[END]"]
    return "\n".join(com) + "\n", "\n".join(cma) + "\n"


def write(table, options, name: str = "", cma_path: str = ""
          ) -> tuple[list[tuple[str, str]], str]:
    """The .COM (``name``: its file's name, *.COM) and the .CMA beside it (``cma_path``:
    where it is written, said in the message; its name when not given)."""
    plan = lint(build(table, options))
    name = table_name(name, plan.axis)
    com, cma = render(plan, name)
    what = message(QT_TR_NOOP("HEIDENHAIN .COM table {name} for axis {axis}, {n} entries ({sense}), "
                              "with its .CMA assignment in {cma}"),
                   name=name, axis=plan.axis, n=plan.positions.size, sense=plan.sense,
                   cma=cma_path or cma_name(name))
    return [("", com), (".CMA", cma)], what
