"""The register's high-water mark, kept outside the database beside the laboratory's key
(reg73 #2): after every write AngleBench notes there how far the register has grown — its
record count, its head and every number counter — signed with the key. An older signed
state copied back into the database (a replay: the last records deleted, the state row,
its signature and the counters restored from an earlier copy), or an old backup restored,
holds fewer records, another record at the mark's place, or a counter below the mark's:
found on opening, and nothing is issued until a person records the loss
(``anglebench register acknowledge-loss``), so no number is issued twice.

What it cannot find: a mark file deleted or never written (a register opened only by
workstations without the key, or the key's folder not writable); someone who can write both
the database and the mark and holds the key (they can sign anything). The customer's copies
(``register verify``) are then the evidence from outside.

One file per register (named by the SHA-256 of its location) in the folder
``<key file>.high-water`` beside the key. It only grows: a write that would lower it (a
lagging process) keeps the higher one; only an acknowledged loss (a count of
``loss_acknowledged`` entries higher than the mark's) starts it again from the register as
it is."""

from __future__ import annotations

import datetime as dt
import hashlib
import json
from pathlib import Path

from models.messages import QT_TR_NOOP, message
from models.project.atomic_write import write_text_atomic
from models.project.output_guard import HIGH_WATER_SUFFIX

__all__ = ["BEHIND", "COUNTER_BEHIND", "NOT_SIGNED", "REPLACED", "mark_path", "mark_problems",
           "raise_mark", "read_mark"]

#: what an opening finds when the register holds less than the mark
BEHIND = QT_TR_NOOP(
    "the register holds {count} record(s), but it held {records} ending at head {head} when "
    "AngleBench last wrote it on {when} (its high-water mark {path}, signed with the key): "
    "records were removed since — an older copy restored or replayed; a number issued since "
    "could be issued again: nothing is issued until the loss is recorded with 'anglebench "
    "register acknowledge-loss --by NAME --reason TEXT'")
#: what an opening finds when the register holds as many records as the mark or more, but
#: another chain at the mark's place: nothing was removed — a record there (or before it)
#: was rewritten or replaced (regwin74: it was said "records were removed")
REPLACED = QT_TR_NOOP(
    "the register holds {count} record(s), but record {records} is not the one it held "
    "there when AngleBench last wrote it on {when} (its high-water mark {path}, signed with "
    "the key: head {head} there, {now} now): a record up to it was rewritten or replaced "
    "since — an older copy restored and issued on, or the database changed; a number issued "
    "before could be issued again: nothing is issued until the loss is recorded with "
    "'anglebench register acknowledge-loss --by NAME --reason TEXT'")
#: a counter below the mark's
COUNTER_BEHIND = QT_TR_NOOP(
    "counter {name}: it stands at {value}, but it stood at {marked} when AngleBench last "
    "wrote the register on {when} (its high-water mark {path}): an older copy restored or "
    "replayed; nothing is issued until the loss is recorded with 'anglebench register "
    "acknowledge-loss --by NAME --reason TEXT'")
#: a mark that is not the key's
NOT_SIGNED = QT_TR_NOOP(
    "the register's high-water mark {path} cannot be read or does not carry the laboratory "
    "key's signature: changed outside AngleBench, or written with another key; nothing is "
    "issued until it is recorded with 'anglebench register acknowledge-loss --by NAME "
    "--reason TEXT' (which writes it anew)")


def mark_path(key_path: str, location: str) -> Path:
    """Where the mark of the register at ``location`` is kept beside the key file."""
    key = Path(key_path).expanduser()
    name = hashlib.sha256(location.encode()).hexdigest()[:16]
    return key.parent / f"{key.name}{HIGH_WATER_SUFFIX}" / f"{name}.json"


def _signed_text(mark: dict) -> str:
    return "anglebench-register-high-water\n" + json.dumps(
        {k: v for k, v in mark.items() if k != "signature"}, sort_keys=True,
        separators=(",", ":"))


def read_mark(path: Path, key: bytes) -> dict | None:
    """The mark at ``path``; None when there is none; {} when it cannot be read or is not
    signed with ``key``."""
    from models.register.signing import signature_ok

    try:
        mark = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        return None
    except (OSError, ValueError):
        return {}
    if not isinstance(mark, dict) or not signature_ok(key, _signed_text(mark),
                                                      str(mark.get("signature", ""))):
        return {}
    try:
        int(mark["records"]), str(mark["head"]), int(mark["acknowledged"])
        {str(k): int(v) for k, v in dict(mark["counters"]).items()}
    except (KeyError, TypeError, ValueError):
        return {}
    return mark


def raise_mark(path: Path, key: bytes, location: str, records: int, head: str,
               counters: dict[str, int], acknowledged: int) -> None:
    """Write the register's state as the mark (atomically), unless the mark there is higher
    and no loss was acknowledged since it. OSError when it cannot be written."""
    from models.register.signing import sign

    old = read_mark(path, key)
    if old and int(old["acknowledged"]) == acknowledged and (
            int(old["records"]) > records or any(
                int(v) > counters.get(k, 0) for k, v in old["counters"].items())):
        return  # a process that lagged behind another never lowers it
    mark = {"format": 1, "register": location, "records": records, "head": head,
            "counters": {k: int(v) for k, v in sorted(counters.items())},
            "acknowledged": acknowledged,
            "written_at": dt.datetime.now(dt.timezone.utc).replace(microsecond=0).isoformat()}
    mark["signature"] = sign(key, _signed_text(mark))
    path.parent.mkdir(parents=True, exist_ok=True)
    write_text_atomic(path, json.dumps(mark, sort_keys=True))


def mark_problems(path: Path, key: bytes, chain: dict[int, str], counters: dict[str, int],
                  acknowledged: int) -> list:
    """What the register (``chain``: each place's chain value; its counters; how many losses
    it acknowledged) lacks against its mark: a list of Messages, empty when it holds all of
    it, when there is no mark, or when a loss was acknowledged since the mark was written."""
    from models.register.chain import GENESIS

    mark = read_mark(path, key)
    if mark is None:
        return []
    if not mark:
        return [message(NOT_SIGNED, path=str(path))]
    if int(mark["acknowledged"]) < acknowledged:
        return []  # written before a loss acknowledged since: superseded
    records, head, when = int(mark["records"]), str(mark["head"]), str(mark.get("written_at", "?"))
    problems: list = []
    held = GENESIS if records == 0 else chain.get(records)
    if held != head and held is not None:  # as many records or more: one was replaced
        problems.append(message(REPLACED, count=len(chain), records=records, head=head[:16],
                                now=held[:16], when=when[:10], path=str(path)))
    elif held != head:
        problems.append(message(BEHIND, count=len(chain), records=records, head=head[:16],
                                when=when[:10], path=str(path)))
    for name, marked in sorted(mark["counters"].items()):
        if counters.get(name, 0) < int(marked):
            problems.append(message(COUNTER_BEHIND, name=name, value=counters.get(name, "—"),
                                    marked=marked, when=when[:10], path=str(path)))
    return problems
