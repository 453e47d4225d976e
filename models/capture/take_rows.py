"""The captured readings follow their rows: each take of a capture session names the sheet
row its reading is in (models/capture/raw_record.py), so a row inserted, deleted or
replaced above or over it moves or detaches the take — in one place, for every operation
that moves rows and its undo and redo (widgets/table_commands.py calls :class:`TakeRows`).

A take's row is, in the stored ``takes``:

* ``r >= 0``: the reading is in row ``r`` (0-based) now;
* ``-1``: not behind a row, not an edit: a later take replaced its reading (the fringe's
  live signals), or the take was undone (Edit › Undo of the take, or of the replacement of
  the sheet it went into: review 62 F4). The frames stay in the raw record: they were
  read, but no cell claims to hold them;
* ``-1`` with a fourth item, the key of a newer take (:func:`take_key`, as a list):
  *superseded* — a newer take of the same instrument went into its row (its cells cleared
  and the reading taken again, review 62 F1; or the take undone and the reading taken again
  into the row it was in). The row holds the newer take's reading; the older one's frames
  stay, and the certificate says the row was captured again, never that it was edited
  (models/capture/edits.py). The undo of the newer take gives the row back to the older
  one (an undone one: undone again, of that row);
* ``r <= -2``: its row was deleted (or the sheet replaced) — at row ``-2 - r`` then. The
  frames stay in the raw record; the certificate says the captured reading was deleted
  (models/capture/edits.py). A file of 0.8.10 reads such a row as ``-1``.

A take is known by its session's instrument, port and start and its first and last frame
(:func:`take_key`: two sessions never share a start), so an undo puts back exactly the
takes its operation detached, whatever copies of the sessions were made in between.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any, cast

__all__ = ["CHOSEN_CELL", "REPLACED", "UNDONE", "TakeRows", "deleted_at", "deleted_row", "session_takes",
           "superseded_by", "take_key"]

#: the row of a take whose reading a later take replaced
REPLACED = -1
#: the row of a take undone (its cells put back as they were): no cell claims it
UNDONE = REPLACED

#: instruments whose reading goes to a cell chosen when it is taken (a readout's "the
#: current cell"): two takes of one in a row may be two readings in two columns
CHOSEN_CELL = frozenset({"readout"})

#: a take's key and the row it was detached from
Detached = list[tuple[tuple, int]]


def deleted_row(row: int) -> int:
    """The stored row of a take whose row ``row`` was deleted."""
    return -2 - row


def deleted_at(stored: int) -> int | None:
    """The row (0-based) a take's reading was deleted from, None when it was not deleted."""
    return -2 - stored if stored <= -2 else None


def take_key(instrument: str, port: str, started_utc: str, take) -> tuple:
    return (instrument, port, started_utc, int(take[1]), int(take[2]))


def superseded_by(take) -> tuple | None:
    """The key of the newer take that superseded ``take`` (a stored ``[row, first, last]``
    or ``[-1, first, last, key]``), None when it was not superseded."""
    return tuple(take[3]) if len(take) > 3 and take[0] == REPLACED else None


class TakeRows:
    """The takes of one workbench's sessions moved with its rows. ``takes()``: every take of
    the workbench as ``(key, take)``, ``take`` the live ``[row, first, last]`` list the
    sessions hold (changed in place).

    The row each take undone in this window was in (:attr:`undone_rows`) moves with the
    rows too, though the take claims none: the next take of its instrument into that row
    supersedes it, as it supersedes a take whose cells were cleared — both are a position
    taken again after its first take was thrown away, said "captured again" (the raw record
    holds both takes; it was said only of the cleared one). The row deleted, or the sheet
    replaced, and the undone take is of no row any more."""

    def __init__(self, takes: Callable[[], Iterable[tuple[tuple, list[int]]]]) -> None:
        self._takes = takes
        #: the columns (keys) each take made in this window wrote (:meth:`taken`)
        self.columns: dict[tuple, frozenset[str]] = {}
        #: the row each take undone was in, by its key (moved with the rows since)
        self.undone_rows: dict[tuple, int] = {}
        #: the undone takes a newer take superseded: its undo undoes them again
        self._superseded_undone: set[tuple] = set()

    def inserted(self, at: int, count: int) -> None:
        """``count`` rows inserted at ``at``: the takes at or below it move down."""
        for _, take in self._takes():
            if take[0] >= at:
                take[0] += count
        for key, row in self.undone_rows.items():
            if row >= at:
                self.undone_rows[key] = row + count

    def removed(self, at: int, count: int) -> Detached:
        """Rows ``at`` … ``at + count - 1`` deleted: their takes detached (returned, for
        the undo), the takes below move up."""
        detached: Detached = []
        for key, take in self._takes():
            if at <= take[0] < at + count:
                detached.append((key, take[0]))
                take[0] = deleted_row(take[0])
            elif take[0] >= at + count:
                take[0] -= count
        self.undone_rows = {key: row - count if row >= at + count else row
                            for key, row in self.undone_rows.items()
                            if not at <= row < at + count}
        return detached

    def replaced(self) -> Detached:
        """Every row replaced (an import, a paste replacing the sheet): every take that
        names a row detached (returned, for the undo)."""
        detached: Detached = []
        for key, take in self._takes():
            if take[0] >= 0:
                detached.append((key, take[0]))
                take[0] = deleted_row(take[0])
        self.undone_rows.clear()
        return detached

    def detach(self, detached: Detached) -> None:
        """These takes detached again (the redo of a replacement)."""
        rows = dict(detached)
        for key, take in self._takes():
            if key in rows and take[0] == rows[key]:
                take[0] = deleted_row(take[0])
        self.undone_rows.clear()

    def undone(self, taken: Detached) -> None:
        """These takes undone (``(key, row)``: each take's key and the row it went into):
        they no longer claim a row (the undo of the take's own cells, review 62 F4); the
        row is remembered (:attr:`undone_rows`)."""
        before = {key: take[0] for key, take in self._takes()}
        self._move(taken, lambda row: row, UNDONE)
        for key, row in taken:
            if before.get(key) == row:
                self.undone_rows[key] = row

    def redone(self, taken: Detached) -> None:
        """These undone takes back in their rows (the redo of what :meth:`undone` undid)."""
        self._move(taken, lambda row: UNDONE, None)
        for key, _ in taken:
            self.undone_rows.pop(key, None)

    def taken(self, taken: Detached, columns: dict[tuple, frozenset[str]] | None = None) -> None:
        """These takes in their rows (made, or redone; ``(key, row)`` each, the take at -1
        until then; ``columns``: the keys of the columns each wrote). An older take of the
        same instrument that claims one of those rows is superseded by it (``[-1, first,
        last, newer key]``, review 62 F1: a take whose cells were cleared and taken again
        kept its row, and the row was said "edited after capture" with the older take's
        values) — when it wrote no column the newer did not: a reading written into a cell
        chosen at the time (:data:`CHOSEN_CELL`, a readout's "the current cell") may be in
        another column of the row, and stays checked. The same frames taken twice are one
        reading, never superseded by themselves. A take undone whose row
        (:attr:`undone_rows`) is one of those rows is superseded the same way."""
        self.columns.update(columns or {})
        self.redone(taken)
        # the newer take of each instrument in each row
        rows = {(row, key[0]): key for key, row in taken}
        newer = {key for key, _ in taken}
        for key, take in self._takes():
            undone = take[0] == UNDONE and len(take) <= 3 and key in self.undone_rows
            by = rows.get((self.undone_rows[key] if undone else take[0], key[0]))
            if by is None or key in newer:
                continue
            mine, theirs = self.columns.get(by), self.columns.get(key)
            if theirs is None and key[0] in CHOSEN_CELL or \
                    theirs is not None and mine is not None and not theirs <= mine:
                continue
            if undone:
                self._superseded_undone.add(key)
                del self.undone_rows[key]
            take[0] = REPLACED
            cast(list, take)[3:] = [list(by)]  # the newer take's key beside it

    def untaken(self, taken: Detached) -> None:
        """The undo of :meth:`taken`: these takes undone, and the takes they superseded back
        in their rows."""
        self.undone(taken)
        rows = {tuple(key): row for key, row in taken}
        for key, take in self._takes():
            by = superseded_by(take)
            if by is not None and by in rows:
                if key in self._superseded_undone:  # undone before: undone again, of the row
                    self._superseded_undone.discard(key)
                    take[0] = UNDONE
                    self.undone_rows[key] = rows[by]
                else:
                    take[0] = rows[by]
                del take[3:]

    def replaced_by_later_take(self, instrument: str) -> Detached:
        """Every take of ``instrument`` not replaced yet (in a row, or at a row deleted) is
        replaced (row -1): a later take of it replaced the whole record (the fringe's live
        signals: a retake). Returned, ``(key, stored row)`` each, for the undo
        (:meth:`unreplaced`) and the redo (:meth:`undone`)."""
        replaced: Detached = []
        for key, take in self._takes():
            if key[0] == instrument and take[0] != REPLACED:
                replaced.append((key, take[0]))
                take[0] = REPLACED
        return replaced

    def unreplaced(self, replaced: Detached) -> None:
        """The undo of :meth:`replaced_by_later_take`: these takes back at the rows they stood
        at (a deleted row's as deleted)."""
        self._move(replaced, lambda row: REPLACED, None)

    def undo_replacement(self) -> Detached:
        """The replacement of the sheet undone: every take that names a row went into the
        replacement (those of the rows replaced were detached by it) and is undone with it
        (returned, for the redo). The fringe's live take adds its own takes after replacing
        the readings, outside any command."""
        taken: Detached = []
        for key, take in self._takes():
            if take[0] >= 0:
                taken.append((key, take[0]))
                take[0] = UNDONE
        self.undone_rows.clear()  # rows of the replacement, gone with it
        return taken

    def _move(self, taken: Detached, was: Callable[[int], int], to: int | None) -> None:
        """Each ``(key, row)`` moves one take of that key standing at ``was(row)`` to
        ``to`` (None: to ``row``): two takes of one key (the same frames taken twice) are
        each moved once."""
        wanted: dict[tuple, list[int]] = {}
        for key, row in taken:
            wanted.setdefault(key, []).append(row)
        if not wanted:
            return
        for key, take in self._takes():
            rows = wanted.get(key)
            if not rows:
                continue
            for i, row in enumerate(rows):
                if take[0] == was(row):
                    take[0] = row if to is None else to
                    del rows[i]
                    break

    def reattach(self, detached: Detached) -> None:
        """These takes back in their rows (the undo of a deletion or replacement)."""
        rows = dict(detached)
        for key, take in self._takes():
            if key in rows and take[0] == deleted_row(rows[key]):
                take[0] = rows[key]


def session_takes(sessions: Iterable[dict[str, Any]]) -> Iterable[tuple[tuple, list[int]]]:
    """``(key, take)`` of every take of stored sessions (for :class:`TakeRows`)."""
    for session in sessions:
        for take in session["takes"]:
            yield take_key(session["instrument"], session["port"], session["started_utc"],
                           take), take
