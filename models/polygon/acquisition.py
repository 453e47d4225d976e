"""The polygon workbench's guidance while readings come from the autocollimator: the
face to turn to, with the encoder reading it should roughly show, the closure of each
set, and the n readings of each face (models/capture/guidance.py).

The encoder reading expected is the set's first encoder reading plus the steps of
360°/N taken since, counted the way the encoder went between the set's first two faces
(the first set's while a later set has one face read; the *encoder counts* setting when
only one face is read at all). N is the *faces*
setting, or the faces of the first set when it has closed, or 360° over the encoder's
first step when that step is within a quarter of the gap to the next N's; without them
the face alone is said (no figure is guessed).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any, overload

from models.messages import QT_TR_NOOP, message
from models.readings.angles import parse_angle_deg

if TYPE_CHECKING:  # the guide's module is loaded when a guide is asked for (the window's)
    from models.capture.guidance import NextReading

__all__ = ["polygon_guide"]

KEYS = ("position", "set", "direction")


@overload
def _int(text: str) -> int | None: ...
@overload
def _int(text: str, default: int) -> int: ...
def _int(text: str, default: int | None = None) -> int | None:
    try:
        return int(str(text).strip())
    except ValueError:
        return default


def _angle(text: str) -> float | None:
    try:
        return parse_angle_deg(str(text))
    except ValueError:
        return None


def _wrap(d: float) -> float:
    return (d + 180.0) % 360.0 - 180.0


def polygon_guide(rows: Sequence[Mapping[str, str]], current: Mapping[str, str],
                  settings: Mapping[str, Any], step: float = 0.0) -> NextReading:
    from models.capture.guidance import NextReading, degrees_text, point_groups, used_rows

    n = max(1, int(settings.get("readings_per_point", 1) or 1))
    groups = point_groups(used_rows(rows), KEYS)
    uses_sets = any(g[0][1] for g in groups)
    count = 0  # N, once known (below): the pitch said with an encoder figure

    def said(text, face: int, set_no: int, reading: int,
             encoder: float | None = None, near: tuple[float, ...] = ()) -> NextReading:
        if n > 1:
            text = message(QT_TR_NOOP("{what} — reading {k} of {n}"), what=text, k=reading, n=n)
        fill = {"position": str(face)}
        if uses_sets or set_no > 1:
            fill["set"] = str(set_no)
        nominal = {} if encoder is None else {"encoder_deg": float(encoder) % 360.0}
        return NextReading(text, fill, reading, n, nominal, 360.0 / count if count else 0.0,
                           {"encoder_deg": near} if near else {})

    face = _int(groups[-1][0][0]) if groups else None
    if face is None:
        return said(message(QT_TR_NOOP("go to face {face}"), face=1), 1, 1, 1)
    (_, set_text, _), last = groups[-1]
    set_no = _int(set_text, 1)
    # the pitch with a repeat too (a repeat further than half of it from the face's first
    # reading is at another face: app/capture/panel.py refuses it)
    count = int(settings.get("faces", 0) or 0)
    if len(last) < n:
        return said(message(QT_TR_NOOP("stay at face {face}"), face=face), face, set_no,
                    len(last) + 1)
    in_set = [(k, g) for k, g in groups if _int(k[1], 1) == set_no and _int(k[0]) is not None]
    faces_read = [f for k, _ in in_set if (f := _int(k[0])) is not None]  # all of in_set
    first_face = faces_read[0]
    encoders = [_angle(g[0].get("encoder_deg", "")) for _, g in in_set]
    # N: the setting, else the first set's faces once it has closed, else the encoder's step
    count = int(settings.get("faces", 0) or 0)
    set_one = [_int(k[0]) for k, _ in groups if _int(k[1], 1) == _int(groups[0][0][1], 1)]
    if not count and len(set_one) > 2 and set_one[-1] == set_one[0] and set_no != _int(
            groups[0][0][1], 1):
        count = len(set(set_one))
    # which way faces and encoder go: this set's first two faces, else the first set's
    pattern = in_set if len(in_set) > 1 else [
        (k, g) for k, g in groups if _int(k[1], 1) == _int(groups[0][0][1], 1)
        and _int(k[0]) is not None]
    pattern_faces = [f for k, _ in pattern if (f := _int(k[0])) is not None]  # all of pattern
    pattern_encoders = [_angle(g[0].get("encoder_deg", "")) for _, g in pattern]
    first_step = None
    if len(pattern) > 1:
        start, turned = pattern_encoders[0], pattern_encoders[1]
        if start is not None and turned is not None:
            first_step = _wrap(turned - start)
    if not count and first_step:
        # N when the step is within a quarter of the gap between 360°/N and 360°/(N ± 1)
        guess = round(360.0 / abs(first_step))
        if 3 <= guess <= 360 and abs(abs(first_step) - 360.0 / guess) < 90.0 / guess ** 2:
            count = guess
    order = 1
    if len(pattern_faces) > 1:
        gap = pattern_faces[1] - pattern_faces[0]
        order = -1 if gap == -1 or (count and gap == count - 1) else 1
    per_face = None  # the encoder's step from a face to the next in the pattern's order
    if count and first_step is not None:
        per_face = math.copysign(360.0 / count, first_step)
    elif count and str(settings.get("counting", "auto")) in ("with", "against"):
        per_face = order * (360.0 / count) * (1 if settings["counting"] == "with" else -1)

    def encoder_at(at: int) -> float | None:
        """The encoder expected at face ``at``: the set's first reading plus the steps of
        360°/N between their faces (which way the set goes round does not change where a
        face is)."""
        if per_face is None or encoders[0] is None:
            return None
        return (encoders[0] + ((at - first_face) * order) % count * per_face) % 360.0

    # the face the row the reading goes to already names (the entry plan's, or one typed):
    # the guidance says that face, never another (live76 F2: a reversed set 2's first step
    # was guided by set 1's direction, "go to face 2" where the plan's row said face 4)
    planned = _int(current.get("position", ""))
    if planned is not None and (planned < 1 or (count and planned > count)):
        planned = None
    closed = len(in_set) > 1 and face == first_face
    if closed:  # the set is done: the next one starts where this one did
        start_face = first_face if planned is None else planned
        encoder = encoders[0] if start_face == first_face else encoder_at(start_face)
        text = message(QT_TR_NOOP("set {set}: go to face {face}"), set=set_no + 1, face=start_face)
        if encoder is not None:
            text = message(QT_TR_NOOP("set {set}: go to face {face} (encoder ≈ {encoder}°)"),
                           set=set_no + 1, face=start_face, encoder=degrees_text(encoder % 360))
        return said(text, start_face, set_no + 1, 1, encoder)
    following = face + order if planned is None else planned
    if count:
        following = (following - 1) % count + 1
    elif following < 1:
        return NextReading(message(QT_TR_NOOP("go to the next face (set the number of faces)")),
                           {}, 1, n)
    encoder = encoder_at(following) if count else None
    closure = bool(count) and following == first_face
    if closure:
        template = (QT_TR_NOOP("go back to face {face} (encoder ≈ {encoder}°): the closure of "
                               "set {set}") if encoder is not None else
                    QT_TR_NOOP("go back to face {face}: the closure of set {set}"))
    else:
        template = (QT_TR_NOOP("go to face {face} (encoder ≈ {encoder}°)") if encoder is not None
                    else QT_TR_NOOP("go to face {face}"))
    figures: dict[str, object] = {"face": following, "set": set_no}
    if encoder is not None:
        figures["encoder"] = degrees_text(encoder)
    near: tuple[float, ...] = ()
    if encoder is None and count and encoders[0] is not None:
        # the way the encoder counts not known yet: the face is that many steps of 360°/N
        # either way round from the set's first (a reading at neither is at another face)
        steps = ((following - first_face) * order) % count
        near = tuple(sorted({(encoders[0] + sign * steps * 360.0 / count) % 360.0
                             for sign in (1, -1)}))
    return said(message(template, **figures), following, set_no, 1, encoder, near)
