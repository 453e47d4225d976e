"""Mach4: screw mapping (the Machine Calibration plugin's linear compensation).

Rules, from MachMotion's support documentation "Mach 4 Screw Mapping":

* M/map: a map is given by its start point (the most negative position), its length (the
  positive travel from the start) and its number of points, evenly spaced, including
  both ends: intervals + 1.
* M/value: "the error at each point is the difference between the expected position and
  the actual one". The words allow either order, so the sign is an option without a
  default, as HEIDENHAIN's: ``values=correction`` writes expected − actual = −x̄ (the
  compensation; the reading under which the page's example comes out right), ``values=error``
  writes actual − expected = x̄. The file's header says which was written.
* M/direction: builds after 2107 apply one map to both directions; builds after 4780 take
  separate maps for positive and negative travel.

Not verified (docs/user-guide/positioning.md): the sign (hence the required option), what is applied beyond
the map, the limit on the number of points, and how Mach4 stores the map: the file written
is a list of the values to enter in the plugin, not a Mach4 file.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from models.messages import QT_TR_NOOP, message
from models.positioning.controllers.common import (
    ControllerRuleError,
    Option,
    equidistant_step,
    in_target_unit,
    parse_options,
    refuse,
    table_notes,
)

NAME = "Mach4"
SOURCE = "MachMotion, Mach 4 Screw Mapping"
OPTIONS = (
    Option("axis", "text", "X", QT_TR_NOOP("axis or motor name")),
    Option("values", "text", None, QT_TR_NOOP("correction (expected − actual) or error (actual − "
                                              "expected): as the machine's Mach4 build takes it")),
)


@dataclass(frozen=True)
class Plan:
    axis: str
    start: float
    length: float
    points: int
    positive: np.ndarray
    negative: np.ndarray | None
    sense: str = "correction"


def build(table, options) -> Plan:
    o = parse_options(NAME, OPTIONS, options)
    if o["values"] not in ("error", "correction"):
        raise ControllerRuleError(message(QT_TR_NOOP(
            "{controller} options: values=correction or values=error must be given (the sign of a "
            "screw map's value is not stated unambiguously: see the user guide, "
            "docs/user-guide/positioning.md, Compensation tables)"), controller=NAME))
    sign = 1.0 if o["values"] == "correction" else -1.0
    positions = np.asarray(table.positions, dtype=float)
    equidistant_step(NAME, positions, SOURCE)
    positive = sign * in_target_unit(table.forward, table.deviation_unit)  # M/value
    negative = (None if table.backward is None else
                sign * in_target_unit(table.backward, table.deviation_unit))
    return Plan(o["axis"], float(positions[0]), float(positions[-1] - positions[0]),
                positions.size, positive, negative, o["values"])


def lint(plan: Plan) -> Plan:
    if plan.points < 2 or plan.length <= 0 or plan.positive.size != plan.points or \
            (plan.negative is not None and plan.negative.size != plan.points):
        raise refuse(NAME, message(QT_TR_NOOP("points = intervals + 1, evenly spaced over the "
                                              "length ({source})"), source=SOURCE),
                     message(QT_TR_NOOP("{n} values for {points} points over {length}"),
                             n=plan.positive.size, points=plan.points, length=f"{plan.length:g}"))
    return plan


def render(plan: Plan, notes: list[str] | tuple[str, ...] = ()) -> str:
    """The list; ``notes``: said in its first, comment line (the lines after it keep their
    places: Axis, Start, Length, Points, the head, the values)."""
    sense = ("expected - actual (values=correction)" if plan.sense == "correction" else
             "actual - expected (values=error)")
    out = [f"; AngleBench: Mach4 screw map for {plan.axis} (Configure / Plugins / Machine "
           f"Calibration, Linear Compensation); error = {sense}"
           + "".join(f"; {note}" for note in notes),
           f"Axis={plan.axis}", f"Start={plan.start:.9g}", f"Length={plan.length:.9g}",
           f"Points={plan.points}"]
    step = plan.length / (plan.points - 1)
    head = "Point,Position,Error" if plan.negative is None else "Point,Position,PositiveError,NegativeError"
    out.append(head)
    for i in range(plan.points):
        row = f"{i},{plan.start + i * step:.9g},{plan.positive[i]:.9f}"
        if plan.negative is not None:
            row += f",{plan.negative[i]:.9f}"
        out.append(row)
    return "\n".join(out) + "\n"


def write(table, options) -> tuple[list[tuple[str, str]], str]:
    plan = lint(build(table, options))
    what = message(QT_TR_NOOP("Mach4 screw map for {axis}: start {start}, length {length}, {n} points "
                              "({sense})"),
                   axis=plan.axis, start=f"{plan.start:g}", length=f"{plan.length:g}", n=plan.points,
                   sense=plan.sense)
    return [("", render(plan, [str(n) for n in table_notes(table)]))], what
