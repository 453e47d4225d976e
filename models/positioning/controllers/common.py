"""What the controller writers share: their options, the refusal that names a rule, and the
grid checks (equidistant points, a full turn closed).

A writer takes the :class:`~models.positioning.compensation.CompensationTable`
(compensation = −mean deviation, in the deviation unit) and the options the user gave as
text ("axis=X1, system=1, unit=0.001"), builds what the controller will hold, lints it
(a :class:`ControllerRuleError` names the rule broken), then renders the file.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from models.messages import QT_TR_NOOP, message
from models.positioning.model import DEVIATION_UNITS

__all__ = ["ControllerRuleError", "Option", "backlash_sense", "close_turn", "equidistant_step",
           "header_notes", "in_target_unit", "parse_options", "reversal_and_backlash", "table_notes"]


class ControllerRuleError(ValueError):
    """The table breaks a rule of the controller (the message names the controller, the rule
    and the manual it is from); nothing is written."""


def refuse(controller: str, rule: str, detail) -> ControllerRuleError:
    return ControllerRuleError(message(QT_TR_NOOP("{controller}: {rule} — {detail}"),
                                       controller=controller, rule=rule, detail=detail))


@dataclass(frozen=True)
class Option:
    """One controller option: ``kind`` "text", "int" or "float"; ``default`` None = required
    (the writer refuses without it)."""

    key: str
    kind: str
    default: Any
    help: str = ""
    minimum: float | None = None  # numbers only: the least value the controller takes


def parse_options(controller: str, declared: tuple[Option, ...],
                  text: str | Mapping[str, Any] | None) -> dict[str, Any]:
    """``key=value`` pairs separated by commas (or a mapping), each checked against the
    controller's declared options; an unknown key or a bad value is refused naming it."""
    given: dict[str, str] = {}
    if isinstance(text, Mapping):
        given = {str(k): str(v) for k, v in text.items()}
    elif text:
        for part in str(text).replace(";", ",").split(","):
            if not part.strip():
                continue
            key, sep, value = part.partition("=")
            if not sep or not key.strip():
                raise ControllerRuleError(message(
                    QT_TR_NOOP("{controller} options: '{part}' is not KEY=VALUE"),
                    controller=controller, part=part.strip()))
            given[key.strip().lower()] = value.strip()
    known = {o.key: o for o in declared}
    for key in given:
        if key not in known:
            raise ControllerRuleError(message(
                QT_TR_NOOP("{controller} options: unknown option '{key}'; it takes {known}"),
                controller=controller, key=key, known=", ".join(known)))
    out: dict[str, Any] = {}
    for option in declared:
        if option.key not in given:
            out[option.key] = option.default
            continue
        value = given[option.key]
        try:
            out[option.key] = (value if option.kind == "text" else
                               int(value) if option.kind == "int" else float(value))
        except ValueError:
            raise ControllerRuleError(message(
                QT_TR_NOOP("{controller} options: {key}={value} is not a number"),
                controller=controller, key=option.key, value=value)) from None
        if option.kind != "text" and not np.isfinite(out[option.key]):
            raise ControllerRuleError(message(
                QT_TR_NOOP("{controller} options: {key}={value} is not a number"),
                controller=controller, key=option.key, value=value))
        if option.minimum is not None and out[option.key] < option.minimum:
            raise ControllerRuleError(message(
                QT_TR_NOOP("{controller} options: {key}={value} is below {minimum}"),
                controller=controller, key=option.key, value=value,
                minimum=f"{option.minimum:g}"))
    return out


def in_target_unit(values: np.ndarray, deviation_unit: str) -> np.ndarray:
    """Compensation values from the deviation unit into the axis unit (mm or degrees)."""
    return np.asarray(values, dtype=float) / DEVIATION_UNITS[deviation_unit][1]


def equidistant_step(controller: str, positions: np.ndarray, source: str) -> float:
    """The step of an equidistant grid; refused (naming ``source``, the manual's rule)
    when the points are not equally spaced."""
    steps = np.diff(positions)
    step = float(np.mean(steps))
    if positions.size < 2 or np.max(np.abs(steps - step)) > 1e-9 * max(1.0, abs(step)):
        raise refuse(controller, message(QT_TR_NOOP("equidistant points ({source})"), source=source),
                     message(QT_TR_NOOP("the points are not equally spaced: choose a compensation "
                                        "step")))
    return step


def close_turn(controller: str, positions: np.ndarray, columns: list[np.ndarray], period: float,
               source: str) -> tuple[np.ndarray, list[np.ndarray], str]:
    """A full turn: the grid from its first point to first + ``period``; the last point is the
    first one again (the same position of the axis). Measured at both, the two means are
    averaged (their difference is the drift and scatter between the two ends, stated); not
    measured at the end, the first point's value is repeated there. A grid whose step does
    not divide the turn, or that runs past it, is refused."""
    step = float(positions[1] - positions[0])
    turns = period / step
    if abs(turns - round(turns)) > 1e-9 * max(1.0, turns):
        raise refuse(controller, message(QT_TR_NOOP("the step divides the turn ({source})"),
                                         source=source),
                     message(QT_TR_NOOP("a step of {step} does not divide {period}"),
                             step=f"{step:g}", period=f"{period:g}"))
    end = positions[0] + period
    if positions[-1] > end + 1e-9 * period:
        raise refuse(controller, message(QT_TR_NOOP("one turn ({source})"), source=source),
                     message(QT_TR_NOOP("the points {first}…{last} run past one turn of {period}"),
                             first=f"{positions[0]:g}", last=f"{positions[-1]:g}",
                             period=f"{period:g}"))
    count = int(round(turns)) + 1
    grid = positions[0] + step * np.arange(count)
    out = []
    note = ""
    for values in columns:
        full = np.interp(grid, positions, values)  # grid points are table points
        if abs(positions[-1] - end) <= 1e-9 * period:
            gap = values[-1] - values[0]
            full[0] = full[-1] = 0.5 * (values[0] + values[-1])
            note = message(QT_TR_NOOP("the two ends of the turn differed by {gap} (axis unit): "
                                      "both set to their mean"), gap=f"{gap:.3g}")
        else:
            if grid.size != positions.size + 1:
                raise refuse(controller, message(QT_TR_NOOP("one turn ({source})"), source=source),
                             message(QT_TR_NOOP("the points {first}…{last} do not reach one turn "
                                                "less one step"),
                                     first=f"{positions[0]:g}", last=f"{positions[-1]:g}"))
            full[-1] = full[0]
            note = message(QT_TR_NOOP("the end of the turn, {end}, takes the value at its start"),
                           end=f"{end:g}")
        out.append(full)
    return grid, out, note


def table_notes(table) -> list[str]:
    """What the user must know of any table before loading it (said in the export's message
    and, where the format has comments, in the file's header):

    * its positions are the log's targets, taken as machine coordinates: the controllers look
      the table up at the machine position (HEIDENHAIN: AXISPOS "with respect to the machine
      datum"; SINUMERIK: $AA_ENC_COMP_MIN "the axis position at which the table begins";
      TwinCAT: the uncorrected set position), so a log taken in a work offset gives a table
      shifted by that offset — nothing is assumed of an offset the log does not state;
    * one direction measured: the one table is applied to both directions (the other approach
      is left off by the reversal, which was not measured);
    * a step that does not divide the targets' span: the table ends before the last target,
      where the controller applies the table's end value."""
    notes: list[str] = [message(QT_TR_NOOP(
        "the positions are the log's targets, taken as machine coordinates (from the machine "
        "datum): a log taken in a work offset gives a table shifted by that offset"))]
    form = getattr(table, "form", "")
    if form in ("forward only", "backward only"):
        notes.append(message(
            QT_TR_NOOP("only the {measured} approach was measured: this one table is applied to both "
                       "directions, and approached {other} the axis is left off by the reversal "
                       "(not measured)"),
            measured=message(QT_TR_NOOP("forward (+)")) if form == "forward only" else
            message(QT_TR_NOOP("backward (−)")),
            other=message(QT_TR_NOOP("backward (−)")) if form == "forward only" else
            message(QT_TR_NOOP("forward (+)"))))
    last_target = float(getattr(table, "last_target", float("nan")))
    end = float(np.asarray(table.positions)[-1])
    if np.isfinite(last_target) and last_target - end > 1e-9 * max(1.0, abs(last_target)):
        notes.append(message(
            QT_TR_NOOP("the table ends at {end}, {gap} before the last target {last} (the step "
                       "does not divide the targets' span): beyond {end} the controller applies the "
                       "value at {end}; a step that divides the span ends the table at {last}"),
            end=f"{end:g}", gap=f"{last_target - end:g}", last=f"{last_target:g}"))
    return notes


def header_notes(table, comment: str = "; ", extra: tuple[str, ...] = ()) -> list[str]:
    """:func:`table_notes` (and ``extra``) as the file's comment lines, in English."""
    return [f"{comment}{str(n)}" for n in (*table_notes(table), *extra)]


def reversal_and_backlash(table) -> tuple[float, float]:
    """Of separate tables (compensation = −x̄): the mean reversal over the targets,
    mean(x̄↑ − x̄↓), in the deviation unit, and the backlash that takes it out, −that, in the
    axis unit: positive when the axis stops short on reversal (x̄↑ below x̄↓), "the encoder
    leading the machine part (normal situation)" (SINUMERIK 808D Parameter Manual, MD32450)."""
    reversal = float(np.mean(np.asarray(table.backward, dtype=float)
                             - np.asarray(table.forward, dtype=float)))
    return reversal, float(-in_target_unit(np.array([reversal]), table.deviation_unit)[0])


def backlash_sense(backlash: float) -> str:
    return (message(QT_TR_NOOP("positive: the axis stops short on reversal, the normal case"))
            if backlash >= 0 else message(QT_TR_NOOP("negative: the axis overshoots on reversal")))
