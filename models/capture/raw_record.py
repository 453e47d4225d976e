"""The instrument's own output, kept with the project: every line it sent, time-stamped,
and which of them became the readings in the table.

A capture *session* is one connection of the window's instrument panel::

    {"instrument": "autocollimator", "port": "/dev/ttyUSB0", "baud": 9600,
     "started_utc": "2026-12-02T01:02:03.456789+00:00",
     "frames": [[0.004012, "3 003 12.500 -3.250", 1], …],
     "takes": [[7, 118, 242], …]}

``frames`` holds, per line the instrument sent (noise and refused lines included), the
seconds since ``started_utc`` when its last byte arrived, the line as sent (its bytes as
Latin-1 code points, so any byte survives JSON exactly: ``line.encode("latin-1")`` gives
them back) and 1 when it became a reading, 0 when it was refused or was not a
measurement. ``takes`` says where the readings went: the sheet row (0-based, as it was
when taken) and the first and last index into ``frames`` of the frames averaged into it
(one frame for *Take reading*, the dwell's frames for an auto-take). The fringe workbench's
live signals (#45) keep each *Take* as a session of its own (``instrument`` ``signals``, one
take a sample, from the take's first line); when a later take replaces the readings, the
earlier one's rows become -1 (its frames stay: they are no longer behind a row).

The digest is the SHA-256 of the sessions as stored: their JSON text with compact
separators, keys in the order above and non-ASCII characters as UTF-8 — the same text
the project file holds (``json.dumps(sessions, ensure_ascii=False,
separators=(",", ":"))``), so anyone can check it from the file alone.
"""

from __future__ import annotations

import hashlib
import json
import math
from typing import Any

from models.messages import QT_TR_NOOP, message

__all__ = ["KEYS", "frame_text", "raw_digest", "raw_sessions_from_json", "session_json"]

#: a session's keys, in the order they are stored
KEYS = ("instrument", "port", "baud", "started_utc", "frames", "takes")
#: the keys a session may have after them: ``steps``, per take, the step its cells were
#: rounded to (the instrument's resolution in the reading's unit; 0: every digit), since
#: #41 — a session without it wrote every digit
OPTIONAL_KEYS = ("steps",)


def frame_text(line: bytes) -> str:
    """The line's bytes as Latin-1 text (every byte one code point: reversible)."""
    return line.decode("latin-1")


def session_json(instrument: str, port: str, baud: int, started_utc: str,
                 frames, takes, steps=None) -> dict[str, Any]:
    """One session in its stored form, from the worker's frames ``(seconds, bytes,
    reading)``, the takes ``(row, first, last)`` and, optionally, each take's ``steps``."""
    session = {"instrument": instrument, "port": port, "baud": int(baud),
               "started_utc": started_utc,
               "frames": [[round(float(t), 6), frame_text(line), int(bool(used))]
                          for t, line, used in frames],
               "takes": [[int(r), int(a), int(b)] for r, a, b in takes]}
    if steps is not None:
        session["steps"] = [float(s) for s in steps]
    return session


def raw_digest(sessions: list[dict[str, Any]]) -> str:
    """SHA-256 (hex) of the sessions as stored."""
    text = json.dumps(sessions, ensure_ascii=False, separators=(",", ":"))
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def _latin1(text: str) -> bool:
    try:
        text.encode("latin-1")
    except UnicodeEncodeError:
        return False
    return True


def raw_sessions_from_json(data: Any, where: str) -> list[dict[str, Any]]:
    """The stored sessions checked (ValueError naming ``where`` and what is wrong), with
    their keys in the stored order."""
    if not isinstance(data, list):
        raise ValueError(message(QT_TR_NOOP("{where}: the raw frames must be a list of "
                                            "sessions"), where=where))
    sessions = []
    for i, session in enumerate(data, 1):
        if not isinstance(session, dict) or not set(KEYS) <= set(session) <= \
                set(KEYS) | set(OPTIONAL_KEYS):
            raise ValueError(message(QT_TR_NOOP("{where}, session {i}: not a capture session "
                                                "({keys} expected)"),
                                     where=where, i=i, keys=", ".join(KEYS)))
        ok = (isinstance(session["instrument"], str) and isinstance(session["port"], str)
              and isinstance(session["baud"], int) and isinstance(session["started_utc"], str)
              and isinstance(session["frames"], list) and isinstance(session["takes"], list))
        frames = session["frames"] if ok else []
        ok = ok and all(isinstance(f, list) and len(f) == 3 and isinstance(f[0], int | float)
                        and not isinstance(f[0], bool) and math.isfinite(f[0])
                        and isinstance(f[1], str) and _latin1(f[1]) and f[2] in (0, 1)
                        for f in frames)
        ok = ok and all(isinstance(t, list) and len(t) == 3
                        and all(isinstance(v, int) and not isinstance(v, bool) for v in t)
                        and 0 <= t[1] <= t[2] < len(frames) for t in session["takes"])
        steps = session.get("steps", [])
        ok = ok and isinstance(steps, list) and len(steps) == len(session["takes"]) \
            and all(isinstance(s, int | float) and not isinstance(s, bool) and math.isfinite(s)
                    and s >= 0 for s in steps) if "steps" in session else ok
        if not ok:
            raise ValueError(message(QT_TR_NOOP("{where}, session {i}: a frame or a take is "
                                                "not as stored by AngleBench"),
                                     where=where, i=i))
        sessions.append({k: session[k] for k in KEYS + OPTIONAL_KEYS if k in session})
    return sessions
