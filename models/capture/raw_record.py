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
earlier one's rows become -1 (its frames stay: they are no longer behind a row). A take
undone (Edit › Undo of the take, or of the replacement of the sheet it went into) is -1
too, until its redo (review 62 F4: it kept its row, and a reading typed there afterwards
was said "edited after capture"). A take *superseded* by a newer take of the same
instrument into its row (its cells cleared and the reading taken again, review 62 F1; or
the take undone and the reading taken again into the row it was in) is
``[-1, first, last, key]``, ``key`` the newer take's ``[instrument, port, started_utc,
first, last]``: both takes stay, the certificate says the row was captured again.

A take's row follows its reading: a row inserted or deleted above it moves it, and a
deleted (or replaced) row leaves ``-2 - r``, ``r`` the row it was in then — the frames stay,
the certificate says the reading was deleted (models/capture/take_rows.py; before review 61
F5 the rows stayed as taken, and a row deleted above captured readings made them all look
edited). So the digest is of the sessions as they are now, takes' rows included: a
certificate prints the digest of the sessions the register records with it.

``workbench`` (since review 61 F7): the key of the workbench the session was recorded on;
a session under another workbench's key is refused on opening (a raw record moved to
other readings). Sessions written before (0.8.10) have none and are read as before.

The digest is the SHA-256 of the sessions as stored: their JSON text with compact
separators, keys in the order above and non-ASCII characters as UTF-8 — the same text
the project file holds (``json.dumps(sessions, ensure_ascii=False,
separators=(",", ":"))``), so anyone can check it from the file alone.
"""

from __future__ import annotations

import hashlib
import json
import math
from collections.abc import Iterator, Mapping, Sequence
from typing import Any

from models.messages import QT_TR_NOOP, message

__all__ = ["FRAMES_PER_BLOCK", "KEYS", "FrameBlocks", "frame_text", "raw_digest", "raw_sessions_from_json",
           "session_json", "sessions_json_pieces"]

#: a session's keys, in the order they are stored
KEYS = ("instrument", "port", "baud", "started_utc", "frames", "takes")
#: the keys a session may have after them: ``steps``, per take, the step its cells were
#: rounded to (the instrument's resolution in the reading's unit; 0: every digit), since
#: #41 — a session without it wrote every digit; ``workbench``, the key of the workbench it
#: was recorded on (review 61 F7) — a session without it (0.8.10) is read as before;
#: ``columns``, per take, the key of the column a readout's value was written into (the
#: cell chosen at the time: "Readout into", or the current cell's), since day review 64 P3 —
#: a session without it is checked as before, its reading searched for in the row's cells
OPTIONAL_KEYS = ("steps", "workbench", "columns")


def frame_text(line: bytes) -> str:
    """The line's bytes as Latin-1 text (every byte one code point: reversible)."""
    return line.decode("latin-1")


def session_json(instrument: str, port: str, baud: int, started_utc: str,
                 frames, takes, steps=None, workbench: str = "") -> dict[str, Any]:
    """One session in its stored form, from the worker's frames ``(seconds, bytes,
    reading)``, the takes ``(row, first, last)`` and, optionally, each take's ``steps`` and
    the ``workbench`` it was recorded on."""
    session = {"instrument": instrument, "port": port, "baud": int(baud),
               "started_utc": started_utc,
               "frames": [[round(float(t), 6), frame_text(line), int(bool(used))]
                          for t, line, used in frames],
               "takes": [[int(r), int(a), int(b)] for r, a, b in takes]}
    if steps is not None:
        session["steps"] = [float(s) for s in steps]
    if workbench:
        session["workbench"] = str(workbench)
    return session


def _dumps(value: Any) -> str:
    return json.dumps(value, ensure_ascii=False, separators=(",", ":"))


#: frames a block of :class:`FrameBlocks` holds once full (then encoded, never again)
FRAMES_PER_BLOCK = 20_000


class FrameBlocks(Sequence):
    """A session's frames as stored ([seconds, line, 0/1] each), held as JSON text in blocks
    of :data:`FRAMES_PER_BLOCK` that are encoded once, when full, and never again.

    A day's stream is millions of frames: held as lists they took ~215 bytes each and a
    save encoded every one of them again, twice (the digest and the file): 5 s in the
    window's thread after 8 h at 100 Hz, at every autosave. Blocks keep ~40 bytes a frame
    and a save joins text. :meth:`json_pieces` is exactly ``json.dumps(list(self),
    ensure_ascii=False, separators=(",", ":"))`` (a JSON array is its items' texts joined
    by commas), so the digest and the file are the same bytes as before. Indexing decodes
    the block that holds the frame (the last one decoded is kept)."""

    def __init__(self, frames: Sequence[list] = (), per_block: int = FRAMES_PER_BLOCK) -> None:
        self.per_block = per_block
        self._blocks: list[str] = []  # each the texts of per_block frames, comma-joined
        self._tail: list[list] = []
        self._decoded: tuple[int, list[list]] = (-1, [])
        self.extend(frames)

    def extend(self, frames) -> None:
        """Frames in their stored form appended (lists [seconds, text, 0/1])."""
        for frame in frames:
            self._tail.append(frame)
            if len(self._tail) == self.per_block:
                self._blocks.append(_dumps(self._tail)[1:-1])
                self._tail = []

    def __len__(self) -> int:
        return len(self._blocks) * self.per_block + len(self._tail)

    def _block(self, b: int) -> list[list]:
        if b == len(self._blocks):
            return self._tail
        if self._decoded[0] != b:
            self._decoded = (b, json.loads(f"[{self._blocks[b]}]"))
        return self._decoded[1]

    def __getitem__(self, index):
        if isinstance(index, slice):
            return [self[i] for i in range(*index.indices(len(self)))]
        n = len(self)
        if index < 0:
            index += n
        if not 0 <= index < n:
            raise IndexError("frame index out of range")
        return self._block(index // self.per_block)[index % self.per_block]

    def __delitem__(self, index) -> None:
        """Only the frames from ``index`` on, ``del frames[k:]`` (a session cut short)."""
        if not (isinstance(index, slice) and index.stop is None and index.step is None):
            raise TypeError("only the frames from an index on can be deleted")
        k = len(range(len(self))[:index.start])  # the frames kept
        # the full blocks before the cut stay as they are (a switch of workbench cut a day's
        # stream: rebuilding every block held the window 5.5 s at 2.9 M frames)
        b = k // self.per_block
        rest = self._block(b)[:k % self.per_block] if b <= len(self._blocks) else []
        self._blocks, self._tail, self._decoded = self._blocks[:b], [], (-1, [])
        self.extend(rest)

    def __iter__(self):
        for b in range(len(self._blocks) + 1):
            yield from self._block(b)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Sequence) and len(self) == len(other) and \
            all(a == b for a, b in zip(self, other, strict=True))

    __hash__ = None  # type: ignore[assignment]

    def snapshot(self) -> FrameBlocks:
        """The frames as they are now (the blocks shared: they never change)."""
        out = FrameBlocks(per_block=self.per_block)
        out._blocks, out._tail = list(self._blocks), list(self._tail)
        return out

    def json_pieces(self) -> Iterator[str]:
        """The JSON array's text, a block at a time."""
        yield "["
        first = True
        for block in self._blocks:
            yield block if first else "," + block
            first = False
        if self._tail:
            text = _dumps(self._tail)[1:-1]
            yield text if first else "," + text
        yield "]"


def sessions_json_pieces(sessions: Sequence[Mapping[str, Any]]) -> Iterator[str]:
    """The sessions' JSON text as stored (``json.dumps(sessions, ensure_ascii=False,
    separators=(",", ":"))``), in pieces: a session's frames block by block."""
    yield "["
    for i, session in enumerate(sessions):
        yield "," if i else ""
        yield "{"
        for j, (key, value) in enumerate(session.items()):
            yield ("," if j else "") + _dumps(key) + ":"
            if isinstance(value, FrameBlocks):
                yield from value.json_pieces()
            else:
                yield _dumps(value)
        yield "}"
    yield "]"


def raw_digest(sessions: Sequence[Mapping[str, Any]]) -> str:
    """SHA-256 (hex) of the sessions as stored."""
    digest = hashlib.sha256()
    for piece in sessions_json_pieces(sessions):
        digest.update(piece.encode("utf-8"))
    return digest.hexdigest()


def _latin1(text: str) -> bool:
    try:
        text.encode("latin-1")
    except UnicodeEncodeError:
        return False
    return True


def _superseded(take: list) -> bool:
    """``[-1, first, last, [instrument, port, started_utc, first, last]]``: a take superseded
    by the newer take of that key (models/capture/take_rows.py)."""
    key = take[3] if len(take) == 4 else None
    return take[0] == -1 and isinstance(key, list) and len(key) == 5 \
        and all(isinstance(v, str) for v in key[:3]) \
        and all(isinstance(v, int) and not isinstance(v, bool) for v in key[3:])


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
              and isinstance(session["frames"], list | FrameBlocks)
              and isinstance(session["takes"], list))
        frames = session["frames"] if ok else []
        ok = ok and all(isinstance(f, list) and len(f) == 3 and isinstance(f[0], int | float)
                        and not isinstance(f[0], bool) and math.isfinite(f[0])
                        and isinstance(f[1], str) and _latin1(f[1]) and f[2] in (0, 1)
                        for f in frames)
        ok = ok and all(isinstance(t, list) and (len(t) == 3 or _superseded(t))
                        and all(isinstance(v, int) and not isinstance(v, bool) for v in t[:3])
                        and 0 <= t[1] <= t[2] < len(frames) for t in session["takes"])
        steps = session.get("steps", [])
        ok = ok and isinstance(steps, list) and len(steps) == len(session["takes"]) \
            and all(isinstance(s, int | float) and not isinstance(s, bool) and math.isfinite(s)
                    and s >= 0 for s in steps) if "steps" in session else ok
        ok = ok and isinstance(session.get("workbench", ""), str)
        columns = session.get("columns", [])
        ok = ok and isinstance(columns, list) and len(columns) == len(session["takes"]) \
            and all(isinstance(c, str) for c in columns) if "columns" in session else ok
        if not ok:
            raise ValueError(message(QT_TR_NOOP("{where}, session {i}: a frame or a take is "
                                                "not as stored by AngleBench"),
                                     where=where, i=i))
        sessions.append({k: session[k] for k in KEYS + OPTIONAL_KEYS if k in session})
    return sessions
