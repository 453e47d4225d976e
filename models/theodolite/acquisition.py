"""The theodolite workbench's guidance while readings come from the theodolite: the
angle θ to turn the axis under test to, and the n readings of each θ
(models/capture/guidance.py). θ is the current row's when it is filled in (the table's
nominal step fills it), else the last point's plus the step; without a step the
technician sets θ and types it."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from models.messages import QT_TR_NOOP, message
from models.readings.angles import parse_angle_deg

if TYPE_CHECKING:  # the guide's module is loaded when a guide is asked for (the window's)
    from models.capture.guidance import NextReading

__all__ = ["theodolite_guide"]

KEYS = ("theta_deg", "run", "direction")


def _angle(text: str) -> float | None:
    try:
        return parse_angle_deg(str(text))
    except ValueError:
        return None


def theodolite_guide(rows: Sequence[Mapping[str, str]], current: Mapping[str, str],
                     settings: Mapping[str, Any], step: float = 0.0) -> NextReading:
    from models.capture.guidance import NextReading, point_groups, used_rows

    n = max(1, int(settings.get("readings_per_point", 1) or 1))
    groups = point_groups(used_rows(rows), KEYS)
    theta = str(current.get("theta_deg", "")).strip()
    reading = 1
    if groups:
        (last_theta, *_), last = groups[-1]
        if len(last) < n and (not theta or theta == last_theta):
            theta, reading = last_theta, len(last) + 1
        elif not theta and step and (last_deg := _angle(last_theta)) is not None:
            theta = f"{last_deg + step:.10g}"
    if not theta or _angle(theta) is None:
        return NextReading(message(QT_TR_NOOP("turn the axis to the next θ and type it in the θ "
                                              "column")), {}, reading, n)
    text = message(QT_TR_NOOP("θ = {theta}"), theta=theta if "°" in theta else f"{theta}°")
    if n > 1:
        text = message(QT_TR_NOOP("{what} — reading {k} of {n}"), what=text, k=reading, n=n)
    return NextReading(text, {"theta_deg": theta}, reading, n)
