"""Records signed with the laboratory's key, kept outside the database: each record's and
entry's chain value is signed (HMAC-SHA256), so a record forged and appended after the
last genuine one — with its chain and the state recomputed, which needs no secret — carries
no valid signature. Since AngleBench 0.8.21 the register's state — its record count, its
head and every number counter (:func:`state_text`) — is signed too, with every record, so
the last records deleted and the state and counters set back, or a counter set back alone,
are found (reg72 #1); an older signed state copied back with its records (a backup
replayed) is not: only a head noted outside finds that. The key is a file named by
``ANGLEBENCH_REGISTER_KEY`` (at least 32 bytes, e.g. ``head -c 32 /dev/urandom >
lab.key``; kept off the database server)."""

from __future__ import annotations

import hashlib
import hmac
import os
from pathlib import Path

from models.messages import QT_TR_NOOP, message

__all__ = ["FINGERPRINT", "KEY_ENV_VAR", "STATE_SIGNATURE", "fingerprint", "key_slip",
           "load_key", "proof", "proof_ok", "sign", "signature_ok", "state_text"]

KEY_ENV_VAR = "ANGLEBENCH_REGISTER_KEY"
#: the name of the register_state row that holds the state's signature
STATE_SIGNATURE = "state_signature"
#: the name of the register_state row that holds the fingerprint of the key the register is
#: signed with (:func:`fingerprint`; written with its first signed record since 0.8.22).
#: The row is not in the signed state (:func:`state_text`) and need not be: only the right
#: key could check a signature over it, and the right key computes its own fingerprint. What
#: the row must never do is decide alone: changed by someone who can write the database, it
#: made the right key read as another, which switched every signature check off and hid a
#: record they forged (regwin74). So a key whose fingerprint differs is still the register's
#: when anything it signed says so — the state's signature, a record's, the high-water mark
#: (store.Register._signed_with_this_key) — and the row is then reported as changed; only a
#: key that verifies nothing is "not the key this register was signed with". No format
#: change: registers and marks written before open as they were.
FINGERPRINT = "key_fingerprint"


class KeyError_(ValueError):
    """The key file named cannot be used."""


def load_key(path: str = "") -> bytes | None:
    """The lab's key from ``path`` or the file ``ANGLEBENCH_REGISTER_KEY`` names; None when
    neither is set. ValueError (the message names the file) when it cannot be read or is
    shorter than 32 bytes."""
    path = path.strip() or os.environ.get(KEY_ENV_VAR, "").strip()
    if not path:
        return None
    try:
        key = Path(path).expanduser().read_bytes()
    except OSError as exc:
        raise KeyError_(message(QT_TR_NOOP(
            "the laboratory's register key {path} cannot be read ({reason})"),
            path=path, reason=exc.strerror or str(exc))) from None
    if len(key) < 32:
        raise KeyError_(message(QT_TR_NOOP(
            "the laboratory's register key {path} holds {n} bytes: a key is at least 32 "
            "random bytes"), path=path, n=len(key)))
    return key


def sign(key: bytes, chain: str) -> str:
    return hmac.new(key, chain.encode(), hashlib.sha256).hexdigest()


def signature_ok(key: bytes, chain: str, signature: str | None) -> bool:
    if not signature:
        return False
    return hmac.compare_digest(sign(key, chain), signature)


def state_text(records: int | str, head: str, counters: dict[str, int]) -> str:
    """What the state's signature covers: the record count, the head and every counter's
    last value, in one canonical text."""
    import json

    return "anglebench-register-state\n" + json.dumps(
        {"records": str(records), "head": head,
         "counters": {name: int(value) for name, value in sorted(counters.items())}},
        sort_keys=True, separators=(",", ":"))


def fingerprint(key: bytes) -> str:
    """The key's fingerprint: an HMAC of a fixed label, which tells one key from another
    without revealing it (reg73 #7: a wrong key read every record as forged)."""
    return sign(key, "anglebench-register-key-fingerprint")


def key_slip(key: bytes, expected: str) -> bool:
    """The key with a line end added or removed at its end (a key file opened and saved in
    a text editor, or pasted) has the fingerprint ``expected``. Key files are read byte
    for byte and never stripped: a key is random bytes, and about one in forty ends in a
    byte that reads as white space (a newline, a space), which stripping would lose — every
    register signed with such a key would then read as forged."""
    variants = [key + b"\n", key + b"\r\n"]
    for end in (b"\r\n", b"\n", b"\r", b" "):
        if key.endswith(end):
            variants.append(key[:-len(end)])
    return any(len(v) >= 32 and hmac.compare_digest(fingerprint(v), expected)
               for v in variants)


def _proof_text(number: str, head: str, content: str) -> str:
    return f"anglebench-register-proof\n{number}\n{head}\n{content}"


def proof(key: bytes, number: str, head: str, content: str) -> str:
    """What a certificate's PDF carries (its keywords, since 0.8.22, when the register has
    the lab's key) to prove it was issued by this register: an HMAC over its number, the
    head printed on it and its record's content digest, which only the key's holder can
    make (reg73 #3: a file printing the public head recorded a "missing" certificate)."""
    return sign(key, _proof_text(number, head, content))


def proof_ok(key: bytes, number: str, head: str, content: str, carried: str) -> bool:
    return bool(carried) and signature_ok(key, _proof_text(number, head, content), carried)
