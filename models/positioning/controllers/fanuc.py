"""FANUC: stored pitch error compensation (parameters 3620–3625 and the compensation data).

Rules, from the FANUC parameter manuals, "Parameters of pitch error compensation"
(e.g. Series 0i-PB Parameter Manual B-63980EN/01, 4. Description of parameters, 3620–3625
and its examples 1 and 2; the bidirectional variant from Technical Report A-77810E,
Series 16i/18i "Bidirectional pitch error compensation"):

* F/3620: the number of the compensation point of the reference position.
* F/3621, F/3622: the numbers of the most negative and the most positive points.
* F/3623: the magnification; F/3624: the interval between points, in detection units.
* F/3625: a rotary axis's travel per revolution, in detection units.
* F/values: the value stored at point n is the increment output in the section that ends
  at point n's position (the section from point n−1 to point n), in detection units ×
  magnification; the absolute compensation is their sum from the reference position,
  where it is zero. So the deviation at the reference position itself is no pitch error
  (stated, not written). Sign: a positive value moves the axis further positive (the
  compensation = −x̄).
* F/rotary: the most negative point is the reference point; the most positive is
  reference + travel per revolution / interval; the values of points reference+1 …
  most positive must sum to zero (else the error accumulates every turn), and the
  reference point takes the same value as the most positive one.
* F/range: outside 3621…3622 no further compensation is output (the end sums hold).
* F/separate: bidirectional pitch error compensation (3605#0, 3626, 3627) is not written:
  one table, from the bidirectional mean (the reversal belongs in parameter 1851).

* F/series: the parameter tapes of the Series 30i/31i/32i write ``Q1`` in every block
  (``N03620Q1A1P…``, ``N10000Q1P…``), as that series' parameter manual shows its tape blocks;
  the older series (0i, 16i/18i/21i) write none. Option ``series``: ``0i`` (default, no Q) or
  ``30i``.

Not verified (docs/user-guide/positioning.md): the range of one stored value (±7 on older series, larger on
later ones: option value_limit), the number of points per axis (option max_points), the
data numbers N10000 + point of the parameter tape, and whether the increment is output
at the point or spread over the section.
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
    in_target_unit,
    parse_options,
    refuse,
    reversal_and_backlash,
)
from models.positioning.model import DEVIATION_UNITS

NAME = "FANUC"
SOURCE = "FANUC Parameter Manual, pitch error compensation 3620-3625"
OPTIONS = (
    Option("axis", "int", 1, QT_TR_NOOP("controlled axis number of the parameter tape (A1, A2 …)"),
           minimum=1),
    Option("detection_unit", "float", 0.001, QT_TR_NOOP("detection unit in mm or degrees, e.g. 0.001 "
                                                        "(an inch machine's in mm: 0.00254)"),
           minimum=1e-09),
    Option("magnification", "int", 1, QT_TR_NOOP("parameter 3623, pitch error compensation magnification"),
           minimum=1),
    Option("reference", "float", 0.0, QT_TR_NOOP("reference position (machine coordinate); it must be a "
                                                 "point of the table")),
    Option("reference_number", "int", -1, QT_TR_NOOP("parameter 3620 (−1: chosen so that the "
                                                      "numbers start at 0 or 1)"), minimum=-1),
    Option("value_limit", "int", 7, QT_TR_NOOP("largest stored value of one point, in detection units"),
           minimum=1),
    Option("max_points", "int", 128, QT_TR_NOOP("most compensation points of one axis"), minimum=2),
    Option("modulo", "float", 0.0, QT_TR_NOOP("a rotary axis's travel per revolution, e.g. 360 "
                                              "(parameter 3625; 0: linear)"), minimum=0),
    Option("series", "text", "0i", QT_TR_NOOP("control series of the tape: 0i (also 16i/18i/21i) or "
                                              "30i (also 31i/32i: Q1 in every block)")),
)
SERIES = ("0i", "30i")


@dataclass(frozen=True)
class Plan:
    axis: int
    detection_unit: float
    magnification: int
    reference_number: int  # 3620
    most_negative: int  # 3621
    most_positive: int  # 3622
    interval: float  # 3624, detection units
    per_revolution: float  # 3625, detection units; 0 for a linear axis
    values: dict[int, int]  # point number → stored value
    value_limit: int
    max_points: int
    reference_deviation: str = ""  # the compensation at the reference (text), not written
    series: str = "0i"


def build(table, options) -> Plan:
    o = parse_options(NAME, OPTIONS, options)
    if o["series"].lower() not in SERIES:
        raise refuse(NAME, message(QT_TR_NOOP("series ({source})"), source=SOURCE),
                     message(QT_TR_NOOP("series={series}; it takes {known}"),
                             series=o["series"], known=", ".join(SERIES)))
    if table.backward is not None:
        raise refuse(NAME, message(QT_TR_NOOP("one table ({source})"), source=SOURCE),
                     message(QT_TR_NOOP("export one table from the bidirectional mean; the "
                                        "reversal belongs in parameter 1851 (bidirectional pitch "
                                        "error compensation, 3605#0, is not written): {reversal}"),
                             reversal=_mean_reversal(table, o["detection_unit"])))
    if o["detection_unit"] <= 0 or o["magnification"] < 1:
        raise refuse(NAME, "3623", message(QT_TR_NOOP("detection unit and magnification must be "
                                                      "positive")))
    positions = np.asarray(table.positions, dtype=float)
    comp = in_target_unit(table.forward, table.deviation_unit)  # F/values: + moves positive
    step = equidistant_step(NAME, positions, SOURCE)
    rotary = o["modulo"] > 0
    if rotary:
        positions, (comp,), _ = close_turn(NAME, positions, [comp], o["modulo"], SOURCE)
    hit = np.nonzero(np.abs(positions - o["reference"]) <= 1e-9 * max(1.0, step))[0]
    if hit.size == 0 or (rotary and hit[0] != 0):
        raise refuse(NAME, message(QT_TR_NOOP("3620, the reference position is a compensation "
                                              "point ({source})"), source=SOURCE),
                     message(QT_TR_NOOP("the reference {reference} is not a point of {first}…"
                                        "{last} step {step}{rotary}"),
                             reference=f"{o['reference']:g}", first=f"{positions[0]:g}",
                             last=f"{positions[-1]:g}", step=f"{step:g}",
                             rotary=message(QT_TR_NOOP("; on a rotary axis it is the first point"))
                             if rotary else ""))
    r = int(hit[0])
    quantum = o["detection_unit"] * o["magnification"]
    absolute = np.round((comp - comp[r]) / quantum).astype(int)  # rounded once: no drift of sums
    increments = np.diff(absolute)
    ref_no = o["reference_number"] if o["reference_number"] >= 0 else (0 if rotary else r)
    k = increments.size
    if rotary:
        first, last = ref_no, ref_no + k
        values = {ref_no + i: int(increments[i - 1]) for i in range(1, k + 1)}
        values[ref_no] = values[last]
    else:
        first, last = ref_no + 1 - r, ref_no + k - r
        values = {first + i: int(increments[i]) for i in range(k)}
    return Plan(o["axis"], o["detection_unit"], o["magnification"], ref_no, first, last,
                step / o["detection_unit"], o["modulo"] / o["detection_unit"] if rotary else 0.0,
                values, o["value_limit"], o["max_points"],
                f"{comp[r] * DEVIATION_UNITS[table.deviation_unit][1]:.3g} {table.deviation_unit}",
                o["series"].lower())


def _mean_reversal(table, detection_unit: float) -> str:
    """The mean reversal over the targets and parameter 1851's value for it, in detection
    units (positive when the axis stops short on reversal)."""
    reversal, backlash = reversal_and_backlash(table)
    return message(QT_TR_NOOP("the mean reversal over the targets, mean(x̄↑ − x̄↓), is {reversal} "
                              "{deviation_unit}, {units} detection units of {detection_unit} "
                              "({sense})"),
                   reversal=f"{reversal:+.4g}", deviation_unit=table.deviation_unit,
                   units=f"{backlash / detection_unit:+.4g}", detection_unit=f"{detection_unit:g}",
                   sense=backlash_sense(backlash))


def units_text(plan: Plan, rotary_unit: bool) -> str:
    """The detection unit the values count, and what an inch machine needs."""
    if rotary_unit:
        return message(QT_TR_NOOP("values in detection units of {du}°"),
                       du=f"{plan.detection_unit:g}")
    return message(QT_TR_NOOP("values and 3624 in detection units of {du} mm (the table is "
                              "metric): on an inch machine give detection_unit in mm, e.g. "
                              "0.0001 in = 0.00254"), du=f"{plan.detection_unit:g}")


def lint(plan: Plan) -> Plan:
    for key, value in (("3624", plan.interval), ("3625", plan.per_revolution)):
        if abs(value - round(value)) > 1e-6:
            raise refuse(NAME, message(QT_TR_NOOP("{key} in whole detection units ({source})"),
                                       key=key, source=SOURCE),
                         message(QT_TR_NOOP("{value} detection units"), value=f"{value:.6g}"))
    if plan.most_negative < 0:
        raise refuse(NAME, message(QT_TR_NOOP("3621 ≥ 0 ({source})"), source=SOURCE),
                     message(QT_TR_NOOP("point numbers would start at {first}: raise "
                                        "reference_number"), first=plan.most_negative))
    count = plan.most_positive - plan.most_negative + 1
    if count > plan.max_points:
        raise refuse(NAME, message(QT_TR_NOOP("at most {max_points} points per axis"),
                                   max_points=plan.max_points),
                     message(QT_TR_NOOP("{n} points: choose a larger step"), n=count))
    worst = max(plan.values.values(), key=abs)
    if abs(worst) > plan.value_limit:
        raise refuse(NAME, message(QT_TR_NOOP("a stored value is at most ±{limit} × 3623 "
                                              "magnification"), limit=plan.value_limit),
                     message(QT_TR_NOOP("an increment of {worst} units of {quantum}: raise the "
                                        "magnification or choose a smaller step"),
                             worst=worst, quantum=f"{plan.detection_unit * plan.magnification:g}"))
    if plan.per_revolution:
        turn = sum(plan.values[n] for n in range(plan.reference_number + 1, plan.most_positive + 1))
        if plan.most_negative != plan.reference_number or turn != 0 or \
                plan.values[plan.reference_number] != plan.values[plan.most_positive]:
            raise refuse(NAME, message(QT_TR_NOOP("rotary axis: the values of one revolution "
                                                  "sum to zero ({source})"), source=SOURCE),
                         message(QT_TR_NOOP("they sum to {turn} (3620 = {ref}, 3621 = {first})"),
                                 turn=turn, ref=plan.reference_number, first=plan.most_negative))
    return plan


def render(plan: Plan) -> str:
    a = plan.axis
    q = "Q1" if plan.series == "30i" else ""  # F/series
    n = "05d" if plan.series == "30i" else "d"
    out = ["%", f"N{3620:{n}}{q}A{a}P{plan.reference_number}",
           f"N{3621:{n}}{q}A{a}P{plan.most_negative}",
           f"N{3622:{n}}{q}A{a}P{plan.most_positive}", f"N{3623:{n}}{q}A{a}P{plan.magnification}",
           f"N{3624:{n}}{q}A{a}P{int(round(plan.interval))}"]
    if plan.per_revolution:
        out.append(f"N{3625:{n}}{q}A{a}P{int(round(plan.per_revolution))}")
    out += [f"N{10000 + i}{q}P{plan.values[i]}" for i in sorted(plan.values)]
    out.append("%")
    return "\n".join(out) + "\n"


def write(table, options) -> tuple[list[tuple[str, str]], str]:
    plan = lint(build(table, options))
    what = message(QT_TR_NOOP("FANUC pitch error compensation, axis {axis}, points {first}…{last}, "
                              "reference point {ref}; the compensation at the reference position "
                              "({offset}) is not pitch error: it is left out of the table"),
                   axis=plan.axis, first=plan.most_negative, last=plan.most_positive,
                   ref=plan.reference_number, offset=plan.reference_deviation)
    return [("", render(plan))], joined((what, "; ", units_text(plan, table.target_unit == "deg")))
