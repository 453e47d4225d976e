"""Mach4: screw mapping (the Machine Calibration plugin's linear compensation).

Rules, from MachMotion's support documentation "Mach 4 Screw Mapping":

* M/map: a map is given by its start point (the most negative position), its length (the
  positive travel from the start) and its number of points, evenly spaced, including
  both ends: intervals + 1.
* M/value: the error at each point is the difference between the expected position and
  the actual one (read here as expected − actual = −x̄, the compensation).
* M/direction: builds after 2107 apply one map to both directions; builds after 4780 take
  separate maps for positive and negative travel.

Not verified (see README): the sign reading above (the page's words allow either order),
what is applied beyond the map, the limit on the number of points, and how Mach4 stores
the map: the file written is a list of the values to enter in the plugin, not a Mach4
file.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from models.messages import QT_TR_NOOP, message
from models.positioning.controllers.common import (
    Option,
    equidistant_step,
    in_target_unit,
    parse_options,
    refuse,
)

NAME = "Mach4"
SOURCE = "MachMotion, Mach 4 Screw Mapping"
OPTIONS = (
    Option("axis", "text", "X", QT_TR_NOOP("axis or motor name")),
)


@dataclass(frozen=True)
class Plan:
    axis: str
    start: float
    length: float
    points: int
    positive: np.ndarray
    negative: np.ndarray | None


def build(table, options) -> Plan:
    o = parse_options(NAME, OPTIONS, options)
    positions = np.asarray(table.positions, dtype=float)
    equidistant_step(NAME, positions, SOURCE)
    positive = in_target_unit(table.forward, table.deviation_unit)  # M/value
    negative = (None if table.backward is None else
                in_target_unit(table.backward, table.deviation_unit))
    return Plan(o["axis"], float(positions[0]), float(positions[-1] - positions[0]),
                positions.size, positive, negative)


def lint(plan: Plan) -> Plan:
    if plan.points < 2 or plan.length <= 0 or plan.positive.size != plan.points or \
            (plan.negative is not None and plan.negative.size != plan.points):
        raise refuse(NAME, message(QT_TR_NOOP("points = intervals + 1, evenly spaced over the "
                                              "length ({source})"), source=SOURCE),
                     message(QT_TR_NOOP("{n} values for {points} points over {length}"),
                             n=plan.positive.size, points=plan.points, length=f"{plan.length:g}"))
    return plan


def render(plan: Plan) -> str:
    out = [f"; AngleBench: Mach4 screw map for {plan.axis} (Configure / Plugins / Machine "
           "Calibration, Linear Compensation); error = expected - actual",
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
    what = message(QT_TR_NOOP("Mach4 screw map for {axis}: start {start}, length {length}, {n} points"),
                   axis=plan.axis, start=f"{plan.start:g}", length=f"{plan.length:g}", n=plan.points)
    return [("", render(plan))], what
