"""The cross-calibration's guidance while readings come from the autocollimator: in each
mounting j the faces j + 1, j + 2, … from the common encoder start, with the encoder
reading each should roughly show (start + k·360°/n, counted the way the first mounting
went), its closure back at face j + 1, then the next mounting (models/capture/guidance.py).

n is the *faces* setting, or the faces of the first mounting once it has closed; without it
the face alone is said and no encoder figure is guessed. The encoder start is the first
mounting's first encoder reading; without one, none is said.

The face (and mounting) the row the reading goes to already names — the entry plan's, or
one typed — is the face said, with the encoder at it, as the polygon's guidance does
(models/polygon/acquisition.py, live76 F2): a mounting read the other way round (j + 1,
j, j − 1, …) is guided face by face, and where no row names a face, the mounting's own
first two faces say which way it goes round. A face's encoder reading does not depend on
the way it is read: start + k·360°/n, k its steps from face j + 1 the way the encoder
counts (the first mounting's first step, read either way round).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from models.capture.guidance import NextReading, degrees_text, used_rows
from models.messages import QT_TR_NOOP, message
from models.readings.angles import parse_angle_deg

__all__ = ["crosscal_guide"]


def _int(text: Any) -> int | None:
    try:
        return int(float(str(text).strip()))
    except ValueError:
        return None


def _angle(text: Any) -> float | None:
    try:
        return parse_angle_deg(str(text))
    except ValueError:
        return None


def _mountings(rows: Sequence[Mapping[str, str]]) -> list[tuple[int, list[int], list]]:
    """(mounting, faces read, encoder readings) of consecutive rows of one mounting."""
    out: list[tuple[int, list[int], list]] = []
    for row in rows:
        j, face = _int(row.get("mounting", "")), _int(row.get("position", ""))
        if j is None or face is None:
            continue
        if not out or out[-1][0] != j:
            out.append((j, [], []))
        out[-1][1].append(face)
        out[-1][2].append(_angle(row.get("encoder_deg", "")))
    return out


def crosscal_guide(rows: Sequence[Mapping[str, str]], current: Mapping[str, str],
                   settings: Mapping[str, Any], step: float = 0.0) -> NextReading:
    groups = _mountings(used_rows(rows))
    if not groups:
        return NextReading(message(QT_TR_NOOP("mounting {mounting}: go to face {face} (the "
                                              "encoder's start)"), mounting=0, face=1),
                           {"mounting": "0", "position": "1"})
    first_faces, first_enc = groups[0][1], groups[0][2]
    n = int(settings.get("faces", 0) or 0)
    if not n and len(groups) > 1 and len(first_faces) > 2 and first_faces[-1] == first_faces[0]:
        n = len(set(first_faces))  # the first mounting closed: its faces

    def order_of(faces: list[int]) -> int:
        """+1: a mounting read j + 1, j + 2, …; −1: read the other way round, j + 1, j, …
        (its first two faces)."""
        return -1 if n and len(faces) > 1 and (faces[1] - faces[0]) % n == n - 1 else 1

    start = first_enc[0]
    # which way the encoder counts from a face to the next (j + 1 to j + 2): the first
    # mounting's first step, read either way round
    sense = 1.0
    if len(first_enc) > 1 and start is not None and first_enc[1] is not None:
        sense = (1.0 if (first_enc[1] - start + 180.0) % 360.0 - 180.0 >= 0 else -1.0) \
            * order_of(first_faces)
    j, faces, _ = groups[-1]

    def said(text, mounting: int, face: int, k: int | None = None) -> NextReading:
        nominal = {} if k is None or start is None else {"encoder_deg": expected(k)}
        return NextReading(text, {"mounting": str(mounting), "position": str(face)},
                           nominal=nominal, pitch_deg=360.0 / n if n else 0.0)

    def expected(k: int) -> float:
        return (start + sense * k * 360.0 / n) % 360.0

    def encoder(k: int) -> str:
        return degrees_text(expected(k))

    if not n:  # the face count is not known yet: no face number is guessed
        return NextReading(message(QT_TR_NOOP("mounting {mounting}: go to the next face, or back "
                                              "to face {face} for its closure"),
                                   mounting=j, face=faces[0]), {"mounting": str(j)})
    # the face (and mounting) the row the reading goes to already names (the entry plan's,
    # or one typed): the guidance says that face, with the encoder at it, never another —
    # the polygon's rule (live76 F2: a reversed set was guided by the first set's direction)
    planned = _int(current.get("position", ""))
    if planned is not None and not 1 <= planned <= n:
        planned = None
    planned_mounting = _int(current.get("mounting", ""))
    if planned is None or planned_mounting is None or planned_mounting < 0:
        planned_mounting = None
    k = len(faces)
    home = j % n + 1
    order = order_of(faces)
    if planned_mounting is not None and planned_mounting != j:
        k = n + 1  # the row is another mounting's: the polygon turned on the shaft first
    if k < n or (k == n and planned is not None and planned != home):
        face = (home - 1 + order * k) % n + 1 if planned is None else planned
        at = (face - home) % n  # a face's place does not depend on the way it is read
        if face == home:
            return said(message(QT_TR_NOOP("mounting {mounting}: go back to face {face} for "
                                           "its closure"), mounting=j, face=home), j, home, n)
        if start is None:
            return said(message(QT_TR_NOOP("mounting {mounting}: go to face {face}"),
                                mounting=j, face=face), j, face)
        return said(message(QT_TR_NOOP("mounting {mounting}: go to face {face} (encoder ≈ "
                                       "{encoder}°)"), mounting=j, face=face, encoder=encoder(at)),
                    j, face, at)
    if k == n:
        return said(message(QT_TR_NOOP("mounting {mounting}: go back to face {face} for its "
                                       "closure"), mounting=j, face=home), j, home, n)  # a full turn on
    nxt = j + 1 if planned_mounting is None else planned_mounting
    first = nxt % n + 1  # the face the mounting brings to the encoder's start
    face = first if planned is None else planned
    if face != first:  # the row names another face of that mounting: that face, its encoder
        at = (face - first) % n
        if start is None:
            return said(message(QT_TR_NOOP("mounting {mounting}: go to face {face}"),
                                mounting=nxt, face=face), nxt, face)
        return said(message(QT_TR_NOOP("mounting {mounting}: go to face {face} (encoder ≈ "
                                       "{encoder}°)"), mounting=nxt, face=face,
                            encoder=encoder(at)), nxt, face, at)
    if start is None:
        return said(message(QT_TR_NOOP("turn the polygon on the shaft by one face: mounting "
                                       "{mounting}, face {face} at the encoder's start"),
                            mounting=nxt, face=face), nxt, face)
    return said(message(QT_TR_NOOP("turn the polygon on the shaft by one face: mounting "
                                   "{mounting}, face {face} at the encoder's start (encoder ≈ "
                                   "{encoder}°)"), mounting=nxt, face=face, encoder=encoder(0)),
                nxt, face, 0)
