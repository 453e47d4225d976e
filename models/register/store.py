"""The certificate register behind one small interface, on SQLite or PostgreSQL.

Why SQLAlchemy Core (with psycopg 3 for PostgreSQL): one set of tables and queries for
both back ends, transactions and parameter styles handled the same way, and the
dialect's own DDL for the few types that differ (BLOB / BYTEA, autoincrement); the
ORM is not used. It is imported only when a register is opened.

Issuing holds the write lock for milliseconds: the number the register expects next
and the chain's head are read without a lock, the PDF is rendered with them, and one short
transaction checks that counter and head are still those (else the PDF is rendered again,
the issuer then waiting its turn) and commits the counter, the record — number, dates,
item, customer, issuing user and approver, the full project state, software versions,
headline figures, the PDF and its SHA-256 — and the register's state (record count and
head). Anything that fails before the commit (the PDF, the disk, the process killed) leaves
no record and no number used. SQLite writes begin IMMEDIATE (the write lock at once, so
two writers queue instead of failing), reads take no lock; on PostgreSQL an advisory lock
serialises the chain's growth and every statement has a lock timeout.
"""

from __future__ import annotations

import builtins
import contextlib
import dataclasses
import datetime as dt
import errno
import hashlib
import hmac
import importlib.metadata
import json
import platform
import re
import socket
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, BinaryIO

from models import __version__
from models.certificate.metadata import CertificateMetadata, format_certificate_number
from models.messages import QT_TR_NOOP, Message, listed, message, reason_of, separated
from models.project.output_guard import TURN_FILE_SUFFIX
from models.register.basis_changes import basis_changes, same_readings
from models.register.chain import (
    CHAINED,
    CHAINED_V2,
    CHAINED_V3,
    CHAINED_V4,
    GENESIS,
    link,
)
from models.register.high_water import BEHIND, COUNTER_BEHIND, NOT_SIGNED, REPLACED
from models.register.readings_identity import (
    INDEX_BOUND,
    NO_READINGS,
    ReadingsIdentity,
    near,
    readings_identity,
    readings_key,
    same_readings_values,
)
from models.register.register_error import RegisterError
from models.register.wording import DOCUMENT_KINDS, kind_words
from models.register.writer_note import holder as writer_holder
from models.register.writer_note import remove_note, write_note

if TYPE_CHECKING:
    from sqlalchemy.engine import Connection

__all__ = ["AnotherMakersItem", "CertificateRecord", "IssueRequest", "LookalikeSerial",
           "NotTheSameCalibration", "PrintedHead", "Register", "RegisterError",
           "ReadingsOfAnotherItem", "RegisterTampered", "SameCalibrationIssued",
           "SameReadingsIssued", "SerialLeftOut", "lab_timezone", "software_versions"]

LIBRARIES = ("numpy", "scipy", "fpdf2", "PySide6-Essentials", "pyqtgraph", "SQLAlchemy",
             "psycopg")
_SEQ = re.compile(r"\{seq(?::0?\d+d)?\}")
_ADVISORY_LOCK = 0x414E4742  # "ANGB": serialises migrations on PostgreSQL
_CHAIN_LOCK = 0x414E4743  # serialises the hash chain's growth on PostgreSQL
_TURN_LOCK = 0x414E4744  # an issuer's turn to render after a lost race (PostgreSQL)


def _not_in_register(number: str) -> RegisterError:
    """No record numbered ``number``: its kind unknown, so named as either (a test report's
    number was said to be "no certificate")."""
    return RegisterError(message(
        QT_TR_NOOP("no certificate or test report {number} in the register"), number=number))


def _item_said(meta: CertificateMetadata) -> dict:
    """The item and date of calibration a chained entry of the user's word names (serial,
    maker, date: the keys in the order the entries have always held them)."""
    return {"serial": meta.item_serial, "manufacturer": meta.item_manufacturer,
            "calibration_date": meta.calibration_date}


class SameCalibrationIssued(RegisterError):
    """An original for an item and date of calibration that a current certificate already
    reports (``numbers``): a corrected one is its amendment or replacement, a calibration of
    its own is issued as separate, saying why (ISO/IEC 17025 7.8.8: no second original of one
    calibration — a reading changed and issued again gave two, neither naming the other)."""

    def __init__(self, text, numbers: tuple[str, ...]) -> None:
        super().__init__(text)
        self.numbers = numbers


class NotASeparateCalibration(RegisterError):
    """An original issued as a calibration of its own beside current certificates of the
    same item and date (``numbers``) whose readings are its own: the same readings with
    other details are a correction, its amendment or replacement (hostile78 F2)."""

    def __init__(self, text, numbers: tuple[str, ...]) -> None:
        super().__init__(text)
        self.numbers = numbers


class SameReadingsIssued(NotASeparateCalibration):
    """An original issued as a calibration of its own beside current certificates of the
    same item and date (``numbers``) whose readings, by their values, and whose details are
    its own: no two calibrations repeat every reading to the last digit, so it is their
    calibration issued again, a second original of one calibration (ISO/IEC 17025 7.8.8).
    Its copy is their PDF; a correction is their amendment or replacement; issued only when
    the user says why, naming one of them (``same_readings_as``: on the command line
    --same-readings-as N:REASON), which is stated on it and recorded in the chain.
    ``facts``: what the register found, without the command line's option."""

    def __init__(self, text, numbers: tuple[str, ...], facts: str = "") -> None:
        super().__init__(text, numbers)
        self.facts = facts or text


class ReadingsOfAnotherItem(RegisterError):
    """A certificate whose readings, by their values (readings_identity.readings_key: a
    re-typed, re-saved or re-ordered file of the same values is the same readings), are
    those of certificates ``numbers`` of another item in the register (hostile78 F7: one
    item's 41 readings, to 0.1″, issued as another item's certificate, each an original,
    nothing said). No two calibrations repeat every reading to the last digit, so it is
    issued only when the user says why, naming one of them (``readings_of_another_item``:
    on the command line --readings-of-another-item N:REASON); the reason is printed on it
    with their numbers, items and dates of calibration, and recorded in the chain.
    ``facts``: what the register found (those certificates, each with its item and date of
    calibration), without the command line's option: the window asks from it."""

    def __init__(self, text, numbers: tuple[str, ...], facts: str = "") -> None:
        super().__init__(text)
        self.numbers = numbers
        self.facts = facts or text


class AnotherMakersItem(RegisterError):
    """An original for the serial (or, with none, the description) and date of calibration of
    a current certificate (``numbers``) naming another manufacturer, whose name is not one
    maker's by its maker key (maker_names; rev65 F1: "Moeller-Wedel" for "Möller-Wedel"
    issued a second current certificate of one calibration, unasked and unrecorded). Two
    makers' serial "001" are two items, so it is issued when the user confirms that it is
    another maker's item; the confirmation is a chained entry of the register ("another
    maker's item"), which `register show` lists."""

    def __init__(self, text, numbers: tuple[str, ...]) -> None:
        super().__init__(text)
        self.numbers = numbers


class LookalikeSerial(RegisterError):
    """An original (or an amendment or replacement whose item is corrected: stop 67) whose
    serial number is no serial in the register of its maker (a maker named on only one side
    is any) but looks like the serial of certificates ``numbers``, letters or digits that
    print alike, case aside (identifiers.serial_lookalike; rev65 F7: "1ra-0815", a digit for
    a letter and the case at once, issued as another item than LRA-0815, its history and
    due date split). The keys are not widened ("SN-1A" and "SN-LA" are two items), so it is
    issued when the user confirms it is another item; the confirmation is a chained entry
    of the register ("lookalike_serial"), which `register show` lists.

    ``text``: the refusal (the command line's, naming --another-lookalike-item); the window
    asks from its parts (day review 67 F6: its question repeated the command line's hint,
    and its "No" the advice for "Yes"): ``facts`` (what the register found: the serials,
    each once with its certificates, their differing characters marked and named),
    ``question`` (the question whose Yes issues it) and ``advice`` (what to do instead,
    after a No)."""

    def __init__(self, text, numbers: tuple[str, ...], facts: str = "", question: str = "",
                 advice: str = "", serial: str = "",
                 lookalikes: tuple[tuple[str, tuple[str, ...]], ...] = ()) -> None:
        super().__init__(text)
        self.numbers = numbers
        self.facts, self.question, self.advice = facts or text, question, advice
        #: the serial asked about and the serials it looks like, each once with the
        #: certificates of it, in the register's order: a window lists them one a line
        #: (day review 68 F11); () where the question is not about a serial's characters
        self.serial, self.lookalikes = serial, lookalikes


class SerialLeftOut(LookalikeSerial):
    """An item of no serial number (identifiers.no_serial) where a current certificate of
    the workbench and date of calibration (``numbers``) reports an item of its description
    and maker (printing alike; a maker named on only one side is any) with a serial, or the
    other way round (stop 67: LRA-0815's calibration issued a second time with the serial
    left blank, unasked, as if another item). Asked as a look-alike serial is, with the same
    word (``another_lookalike_item``, recorded as a "lookalike_serial" entry)."""


class NotTheSameCalibration(RegisterError):
    """An amendment or replacement whose details are not those of the calibration of the
    certificate it supersedes (ISO/IEC 17025 7.8.8: it corrects that report; rev62 F1: the
    window's pending Amend… issued another item's certificate as "AB-2026-0001-A1").
    ``corrections``: the sentences a confirmed correction states on it (the serial number or
    the date of calibration corrected); () when no confirmation makes it one (the
    workbench differs)."""

    def __init__(self, text, corrections: tuple[str, ...] = ()) -> None:
        super().__init__(text)
        self.corrections = corrections


def software_versions() -> dict[str, str]:
    """AngleBench (its version and source: the commit, or the source's digest), Python and
    every library that takes part in a result or its record."""
    from models.software import software_identity

    identity = software_identity()
    out = {"anglebench": __version__, "python": platform.python_version()}
    if identity.commit:
        out["anglebench_commit"] = identity.commit + ("+" if identity.modified else "")
    else:
        out["anglebench_source_sha256"] = identity.source_sha256
    for name in LIBRARIES:
        try:
            out[name] = importlib.metadata.version(name)
        except importlib.metadata.PackageNotFoundError:
            continue
    return out


@dataclass(frozen=True)
class IssueRequest:
    """What an export hands the register: the certificate's details (an empty number asks
    the register to allocate one), the project state behind the certificate as project-file
    JSON, and the headline figures."""

    workbench: str
    metadata: CertificateMetadata
    project_json: str
    headline: dict[str, float] = dataclasses.field(default_factory=dict)


@dataclass(frozen=True)
class CertificateRecord:
    number: str
    issued_at: str
    issue_date: str
    calibration_date: str
    workbench: str
    item_description: str
    item_manufacturer: str
    item_serial: str
    customer: str
    operator: str
    workstation: str
    status: str
    supersedes: str | None
    superseded_by: str | None
    revision: str
    change_note: str
    project_json: str
    software_json: str
    headline_json: str
    pdf_sha256: str
    # schema version 4 (None on older records): the place in the chain, the counter and
    # value the number came from, who issued (the operating-system user) and approved it,
    # why it was withdrawn, the chain's format and value after it
    seq: int | None = None
    counter: str | None = None
    counter_value: int | None = None
    os_user: str | None = None
    approver: str | None = None
    withdrawn_reason: str | None = None
    chain_format: int | None = None
    chain_sha256: str | None = None
    signature: str | None = None  # with the lab's key (models/register/signing.py)
    # schema version 5: the SHA-256 of the digital calibration certificate (DCC XML) issued
    # with the PDF (chain format 3); None when it was issued without one
    dcc_sha256: str | None = None
    # schema version 6: what the document is, "calibration" (a calibration certificate) or
    # "test" (a test report), in the chain (format 4); None: issued before it, not recorded
    document_kind: str | None = None
    # schema version 8: the identity of its readings by their values (readings_identity:
    # "" for none), made at issue, in the chain from chain format 7 (filled in by migration
    # 8 for older records: not in their chain, made again from project_json by verify);
    # None: not stored (a register read as it is at version 6 or 7, a record issued by an
    # AngleBench of schema 7 after the migration)
    readings_key: str | None = None
    # schema version 9: the identity of its readings by their physical values
    # (readings_identity.readings_identity: "", 0, 0 for none), made at issue, in the chain
    # from chain format 8 (filled in by migration 9 for older records: not in their chain,
    # made again from project_json by verify); None: not stored (a register read as it is
    # at version 6 to 8, a record issued by an AngleBench of schema 8 after the migration)
    readings_layout: str | None = None
    readings_anchor: int | None = None
    readings_reach: int | None = None

    @property
    def headline(self) -> dict[str, float]:
        return json.loads(self.headline_json)

    @property
    def software(self) -> dict[str, str]:
        return json.loads(self.software_json)

    @property
    def raw_sha256(self) -> str:
        """SHA-256 of the instrument's raw frames behind the readings, as the project state
        (in the hash chain) holds it; "" for typed readings and older records."""
        entry = json.loads(self.project_json).get("raw_capture", {}).get(self.workbench)
        return entry.get("sha256", "") if isinstance(entry, dict) else ""


_RECORD_COLUMNS = tuple(f.name for f in dataclasses.fields(CertificateRecord))
#: the record's columns a register of schema version 8 holds (read as it is)
_RECORD_COLUMNS_V8 = tuple(c for c in _RECORD_COLUMNS if c not in (
    "readings_layout", "readings_anchor", "readings_reach"))
#: the record's columns a register of schema version 6 or 7 holds (read as it is)
_RECORD_COLUMNS_V7 = tuple(c for c in _RECORD_COLUMNS_V8 if c != "readings_key")


@dataclass(frozen=True)
class PrintedHead:
    """A certificate's PDF against the place in the chain its printed head gives it (the
    head *before* it: its own record is the next one, :meth:`Register.printed_head`)."""

    head: str  # the head the PDF prints
    sha256: str  # the PDF's SHA-256
    number: str  # the number its title names ("" when it has none that can be read)
    place: int | None  # where the chain passed through the head; None: not in the chain
    record: CertificateRecord | None = None  # the certificate at place + 1, if one is there
    after: str = ""  # what else is at place + 1 ("entry withdrawal AB-…"); "": nothing
    #: the register already recorded that this PDF's record is missing (the "missing"
    #: entry at place + 1)
    recorded_missing: bool = False
    #: a record elsewhere in the chain has this PDF's SHA-256 (the head printed is not its)
    elsewhere: str = ""

    @property
    def there(self) -> bool:
        """The certificate's own record is at its place: number and SHA-256."""
        return self.record is not None and self.record.pdf_sha256 == self.sha256

    @property
    def missing(self) -> bool:
        """The chain ends at the head this PDF prints and no record has its SHA-256: its own
        record, which followed that head, was deleted (the tail truncated; rev64 F8)."""
        return (self.place is not None and self.record is None and not self.after
                and not self.recorded_missing and not self.elsewhere)


def _normalise_url(url: str) -> str:
    if url.startswith(("postgresql://", "postgres://")):
        return "postgresql+psycopg://" + url.split("://", 1)[1]
    return url


def _counter_name(scheme: str, date: dt.date) -> str:
    """Name the counter of ``scheme`` on ``date``: the scheme with its date fields filled in
    and the sequence left as '#'. All numbers of one year (or month, or day) thus share one
    counter."""
    if not _SEQ.search(scheme):
        raise RegisterError(message(
            QT_TR_NOOP("the number scheme '{scheme}' has no {{seq}}: the register cannot number "
                       "certificates with it"),
            scheme=scheme))
    return format_certificate_number(_SEQ.sub("#", scheme), 0, date)


#: the chained entry that records a loss acknowledged by a person (reg73 #2, #5): the
#: findings before it of certificates lost ("missing") or numbers issued twice
#: ("number_reissued") no longer stop issuing, and the counters it moved are reached
LOSS_ACKNOWLEDGED = "loss_acknowledged"
#: what an audit finds of a certificate shown to verify whose record was gone
MISSING_FOUND = QT_TR_NOOP(
    "certificate {number}: its PDF (SHA-256 {sha}…), shown to 'register verify' on {date}, "
    "was issued as record {place} of the chain (it prints the head before it), but the "
    "register no longer held its record: deleted after issue, or lost with a restore; nothing "
    "is issued until the loss is recorded with 'anglebench register acknowledge-loss --by "
    "NAME --reason TEXT'")
#: what an audit finds of a number found issued twice
REISSUED_FOUND = QT_TR_NOOP(
    "certificate {number}: its PDF (SHA-256 {sha}…), shown to 'register verify' on {date}, "
    "was issued as record {place} of the chain, but that record is now another certificate "
    "of the same number: the number was issued twice (the register restored from an older "
    "copy, or an older state copied back); nothing is issued until the loss is recorded with "
    "'anglebench register acknowledge-loss --by NAME --reason TEXT'")
#: the findings a recorded loss answers (:meth:`Register.acknowledge_loss`): a certificate
#: found missing, a number found issued twice, the register behind its high-water mark or the
#: mark not the key's; any other finding still refuses it
LOSS_FINDINGS = (MISSING_FOUND, REISSUED_FOUND, BEHIND, REPLACED, COUNTER_BEHIND, NOT_SIGNED)


class RegisterTampered(RegisterError):
    """The register's own records show a change made behind AngleBench's back that makes
    it unsafe to open (a schema version set back): refused, and reported by verify."""


#: how often an issue is rendered again when another issue took the number or head first
ISSUE_ATTEMPTS = 200
#: how long a PostgreSQL statement waits for a lock before saying who holds it
LOCK_TIMEOUT_S = 20
#: how long a connection to a PostgreSQL register waits for the server's answer (libpq's
#: connect_timeout; a URL that sets its own keeps it)
CONNECT_TIMEOUT_S = 30
#: how long an issuer that lost a race waits for its turn to render again (:class:`_Turn`)
TURN_TIMEOUT_S = 120
#: how long a write to a SQLite register waits for its write lock before giving up
BUSY_TIMEOUT_S = 60
#: how long a write waits for that lock in silence before it says it is waiting, and for
#: whom (reg72 #8: a minute of silence, then "database is locked")
WAIT_NOTICE_S = 1.5


@dataclass(frozen=True)
class _Plan:
    """What the register expects the next record to be, read without a write lock."""

    number: str
    seq: int
    head: str
    counter: str | None
    counter_before: int | None
    counter_value: int | None
    original: CertificateRecord | None
    revision: str
    #: today's date confirmed for an issue far after the last record (clock_rules), recorded
    date_confirmed: dict | None = None


def _os_user() -> str:
    import getpass

    try:
        return getpass.getuser()
    except (KeyError, OSError):
        return ""


def lab_timezone(name: str = "") -> dt.tzinfo:
    """The lab's time zone: ``name`` (an IANA name such as Asia/Shanghai), else the
    ``ANGLEBENCH_TIMEZONE`` environment variable, else the system's."""
    import os

    name = name.strip() or os.environ.get("ANGLEBENCH_TIMEZONE", "").strip()
    if name:
        from zoneinfo import ZoneInfo, ZoneInfoNotFoundError

        try:
            return ZoneInfo(name)
        except (ZoneInfoNotFoundError, ValueError):
            raise RegisterError(message(QT_TR_NOOP(
                "the lab's time zone '{name}' is not known (an IANA name such as "
                "Asia/Shanghai or Europe/Berlin)"), name=name)) from None
    return dt.datetime.now().astimezone().tzinfo or dt.timezone.utc


class Register:
    """Open (creating or migrating) the register at ``url``: ``sqlite:///path`` or
    ``postgresql://user@host/db``. Opening takes no write lock unless the schema version
    asks for a migration; it checks the hash chain, the state and the counters (not the
    stored PDFs: :meth:`audit` with ``pdfs``; :meth:`issue` re-hashes them before it issues).
    A SQLite file that cannot be written is opened read-only (listed and verified, never
    issued into)."""

    def __init__(self, url: str, *, timezone: str = "", key_file: str = "") -> None:
        import os

        import sqlalchemy as sa

        from models.register import schema
        from models.register.signing import KEY_ENV_VAR, KeyError_, load_key

        try:
            #: the laboratory's key (ANGLEBENCH_REGISTER_KEY): new records are signed with
            #: it and every signature is checked; None: nothing is signed or checked
            self._key = load_key(key_file)
        except KeyError_ as exc:
            raise RegisterError(reason_of(exc)) from None
        #: the key's file, beside which the register's high-water mark is kept (reg73 #2)
        self._key_path = (key_file.strip() or os.environ.get(KEY_ENV_VAR, "").strip()
                          if self._key else "")
        #: the state a write transaction leaves, noted in the mark once it is committed
        self._mark_due: dict | None = None

        self._sa, self._schema = sa, schema
        #: the numbers :meth:`issue` issued through this object whose results file is not
        #: recorded yet: the only ones :meth:`record_results` records for (stop 63)
        self._results_due: set[str] = set()
        #: each record's readings by their physical values, by its number: made once
        self._identities: dict[str, ReadingsIdentity | None] = {}
        #: the key given is not the one the register was signed with (:meth:`_key_problem`)
        self.key_problem: Message | None = None
        self.url = _normalise_url(url)
        self.is_sqlite = self.url.startswith("sqlite")
        self.read_only = False
        #: a read-only register at schema version 6, read without migrating: its intervals
        #: are per serial (every maker's item's)
        self._intervals_per_serial = False
        #: the records carry their readings' identity (schema version 8; a read-only
        #: register read as it is at 6 or 7 does not: made when compared)
        self._stored_keys = True
        #: the records carry their readings' identity by their physical values (schema
        #: version 9; a read-only register read as it is at 6 to 8 does not)
        self._stored_identities = True
        self.timezone = lab_timezone(timezone)
        self._sqlite_path = ""
        #: told, at once, when a write waits for the SQLite register's write lock held by
        #: another process (what it waits for, and for how long at most): the command line
        #: says it on stderr, the window in its status line. None: nobody is told
        self.on_wait: Callable[[Message], None] | None = None
        #: this process noted itself as the writer beside the database (writer_note.py)
        self._noted = False
        try:
            if self.is_sqlite:
                path = self.url.split("///", 1)[1] if "///" in self.url else ""
                if path and path != ":memory:":
                    self._sqlite_path = path
                    file = Path(path)
                    if _emptied(file):
                        raise RegisterTampered(self._emptied())
                    if file.exists() and not (os.access(file, os.W_OK)
                                              and os.access(file.parent, os.W_OK)):
                        self.read_only = True
                    else:
                        file.parent.mkdir(parents=True, exist_ok=True)
                if self.read_only:
                    self.engine = sa.create_engine(self._read_only_uri(file),
                                                   connect_args={"timeout": BUSY_TIMEOUT_S})
                    sa.event.listen(self.engine, "connect", _sqlite_connect_read_only)
                    sa.event.listen(self.engine, "begin", _sqlite_begin)
                else:
                    self.engine = sa.create_engine(self.url,
                                                   connect_args={"timeout": BUSY_TIMEOUT_S})
                    sa.event.listen(self.engine, "connect", _sqlite_connect)
                    sa.event.listen(self.engine, "begin", self._sqlite_begin)
                    sa.event.listen(self.engine, "commit", self._write_ended)
                    sa.event.listen(self.engine, "rollback", self._write_ended)
            else:
                args: dict[str, Any] = {
                    "application_name": f"anglebench {_os_user()}@{socket.gethostname()} "
                                        f"pid {os.getpid()}"[:63]}
                if "connect_timeout" not in sa.engine.make_url(self.url).query:
                    # a server that accepts and never answers held the window for ever
                    args["connect_timeout"] = CONNECT_TIMEOUT_S
                self.engine = sa.create_engine(self.url, pool_pre_ping=True, connect_args=args)
            try:
                self._migrate()
                #: what the chain, the state and the counters found changed since issue
                #: (checked on opening; the stored PDFs on demand: audit(pdfs=True))
                self.problems = self.audit()
            except BaseException:
                self.engine.dispose()
                raise
        except sa.exc.SQLAlchemyError as exc:
            journal = Path(f"{self._sqlite_path}-wal")
            if self.read_only and journal.exists() and journal.stat().st_size > 0:
                raise RegisterError(self._unread_journal()) from None
            if self._full(exc):  # reg72 #7: on opening, its WAL index could not be made
                raise RegisterError(self._disk_full(reading=True)) from None
            damaged = self._damaged(exc)
            if damaged is not None:
                raise RegisterError(damaged) from None
            raise RegisterError(message(
                QT_TR_NOOP("register {display_url}: {reason}"),
                display_url=self.display_url, reason=_reason(exc))) from None
        except OSError as exc:
            raise RegisterError(message(
                QT_TR_NOOP("register {display_url}: {exc}"),
                display_url=self.display_url, exc=reason_of(exc))) from None

    def _damaged(self, exc: Exception) -> Message | None:
        """What to do with a SQLite register file that is a folder, or that SQLite finds
        damaged or no database at all (hostile77 M1: only SQLite's words were said, "database
        disk image is malformed", "unable to open database file"); None for any other
        failure."""
        import os

        code = getattr(getattr(exc, "orig", None), "sqlite_errorcode", None)
        if not self.is_sqlite or not self._sqlite_path:
            return None
        if os.path.isdir(self._sqlite_path):
            return message(QT_TR_NOOP(
                "register {display_url} is a folder, not a register file: nothing was read "
                "or recorded; name the register's file (--register or ANGLEBENCH_REGISTER)"),
                display_url=self.display_url)
        if code not in (_SQLITE_CORRUPT, _SQLITE_NOTADB):
            return None
        return message(QT_TR_NOOP(
            "register {display_url}: the file is damaged or is not a register ({reason}); "
            "nothing is read from it or issued into it: keep it as it is, restore the "
            "register from a backup, then record the loss with 'anglebench register "
            "acknowledge-loss'"), display_url=self.display_url, reason=_reason(exc))

    def _emptied(self) -> Message:
        return message(QT_TR_NOOP(
            "register {display_url}: the file is empty (0 bytes), but a register holds its "
            "tables from the moment it is made: its records were lost (the file emptied or "
            "truncated: a crash, a disk fault, a command that wrote over it); nothing is read "
            "from it or issued into it, as numbers already issued would be issued again: "
            "restore the register from a backup, then record the loss with 'anglebench "
            "register acknowledge-loss'; if no certificate was ever issued into it, delete "
            "the file"), display_url=self.display_url)

    def _read_only_uri(self, file: Path) -> str:
        """The URI a register this user cannot write is opened by (rev65 F2). SQLite keeps
        the latest commits in the "-wal" journal beside the file until a writer copies them
        into it (a writer that stays open does so every ~1000 pages; one that crashed, never):
        ``mode=ro`` reads the journal through its "-shm" index, which the writer left or the
        reader creates. ``immutable=1`` reads the main file only: it is used only where
        nothing is in the journal and the index cannot be made (a read-only folder), where
        ``mode=ro`` cannot open the file at all. Where the journal holds commits and there
        is no index to read them by, the register is not opened: what the main file alone
        says (an issued certificate "NOT in the register", an old chain head) would be
        wrong."""
        import os
        from urllib.parse import quote

        journal, index = Path(f"{file}-wal"), Path(f"{file}-shm")
        written = journal.exists() and journal.stat().st_size > 0
        can_index = index.exists() or os.access(file.parent, os.W_OK)
        if written and not can_index:
            raise RegisterError(self._unread_journal())
        flags = "mode=ro" if can_index else "mode=ro&immutable=1"
        return f"sqlite:///file:{quote(str(file))}?{flags}&uri=true"

    def _unread_journal(self) -> str:
        return message(QT_TR_NOOP(
            "register {display_url}: it has writes in its journal ({journal}) that a "
            "read-only opening cannot read (its index {index} is missing and the folder "
            "cannot be written); nothing is said from the main file alone, which lacks "
            "them: open the register once by someone who can write its folder, or copy the "
            "register with its -wal file into a folder you can write"),
            display_url=self.display_url, journal=f"{Path(self._sqlite_path).name}-wal",
            index=f"{Path(self._sqlite_path).name}-shm")

    @property
    def display_url(self) -> str:
        """The URL without a password."""
        return re.sub(r"://([^:/@]+):[^@]*@", r"://\1:***@", self.url)

    def close(self) -> None:
        self.engine.dispose()

    def __enter__(self) -> Register:
        return self

    def __exit__(self, *_exc) -> None:
        self.close()

    @property
    def _record_columns(self) -> tuple[str, ...]:
        """The columns a record is read from (:class:`CertificateRecord`'s fields that the
        register holds)."""
        return _RECORD_COLUMNS if self._stored_identities else \
            _RECORD_COLUMNS_V8 if self._stored_keys else _RECORD_COLUMNS_V7

    # -- schema ---------------------------------------------------------------------------
    def _version_in(self, conn) -> int | None:
        sa, schema = self._sa, self._schema
        if not sa.inspect(conn).has_table("schema_version"):
            return None
        versions = conn.execute(sa.select(schema.SCHEMA_VERSION.c.version)).scalars().all()
        if len(versions) != 1:
            raise RegisterTampered(message(QT_TR_NOOP(
                "register {display_url}: the table schema_version holds {n} rows instead of "
                "one: it was changed outside AngleBench; the register is not opened"),
                display_url=self.display_url, n=len(versions)))
        return versions[0]

    def _check_version(self, conn, version: int) -> None:
        schema = self._schema
        if version > schema.LATEST:
            raise RegisterError(message(
                QT_TR_NOOP("register {display_url} is at schema version {version}, made by a newer "
                           "AngleBench than {version__} (knows {latest}): open it with that version"),
                display_url=self.display_url, version=version, version__=__version__,
                latest=schema.LATEST))
        if version < 1:
            raise RegisterTampered(message(QT_TR_NOOP(
                "register {display_url}: schema version {version} is no version AngleBench "
                "ever made: it was changed outside AngleBench; the register is not opened"),
                display_url=self.display_url, version=version))
        if version == schema.LATEST:
            # a table of the register gone (dropped outside AngleBench): said as a change
            # after issue, not as a register that cannot be read ("no such table: entries")
            held = set(self._sa.inspect(conn).get_table_names())
            missing = sorted(name for name in schema.METADATA.tables if name not in held)
            if missing:
                raise RegisterTampered(message(QT_TR_NOOP(
                    "register {display_url}: its table(s) {tables} are gone: deleted outside "
                    "AngleBench; the register is not opened; restore it from a backup"),
                    display_url=self.display_url, tables=", ".join(missing)))
            # a column of its version dropped (ident80b: ALTER TABLE … DROP COLUMN
            # readings_anchor gave a raw "no such column" at opening): said as the tables
            # are, never read as a register of another version
            for name, table in schema.METADATA.tables.items():
                held_columns = {c["name"] for c in self._sa.inspect(conn).get_columns(name)}
                lacking = [c.name for c in table.columns if c.name not in held_columns]
                if lacking:
                    raise RegisterTampered(message(QT_TR_NOOP(
                        "register {display_url}: its table {table} lacks the column(s) "
                        "{columns} of schema version {version}: it has been altered outside "
                        "AngleBench; the register is not opened; restore it from a backup"),
                        display_url=self.display_url, table=name, columns=", ".join(lacking),
                        version=version))
        evidence = schema.downgrade_evidence(conn, version)
        if evidence:
            raise RegisterTampered(message(QT_TR_NOOP(
                "register {display_url}: schema version {version} was set back ({evidence}): "
                "a migration would rewrite the records' hash chain, so the register is not "
                "opened; restore the version or the register from a backup"),
                display_url=self.display_url, version=version, evidence=evidence))

    def _migrate(self) -> None:
        sa, schema = self._sa, self._schema
        with self._read() as conn:
            version = self._version_in(conn)
            if version is not None:
                self._check_version(conn, version)
        if version == schema.LATEST:
            return  # nothing to do: no write lock taken
        if self.read_only and version is not None and version in schema.READ_AS_IS:
            # read as it is: its tables are this version's but for the intervals' key
            # (version 6) and the readings' stored identities (versions 6 to 8)
            self._intervals_per_serial = version < 7
            self._stored_keys = version >= schema.READINGS_KEY_VERSION
            self._stored_identities = version >= schema.READINGS_IDENTITY_VERSION
            return
        if self.read_only:
            raise RegisterError(message(QT_TR_NOOP(
                "register {display_url} is read-only and at schema version {version}: it must "
                "be migrated to {latest} by an AngleBench that can write it"),
                display_url=self.display_url, version=version or 0, latest=schema.LATEST))
        try:
            self._migrate_in_one_transaction()
        except OSError as exc:
            if exc.errno in _DISK_FULL:
                raise RegisterError(self._migration_full(version)) from None
            raise
        except sa.exc.SQLAlchemyError as exc:
            if self._full(exc):
                raise RegisterError(self._migration_full(version)) from None
            raise

    def _migration_full(self, version: int | None) -> Message:
        """What a migration that found the disk full says (hostile79 #1: "the register cannot
        be opened there (SQLite needs room beside it for its journal's index)", so the
        user freed a few kilobytes for nothing): it needs room for its journal, up to the
        register's own size (migration 8 rewrites every record's row); rolled back."""
        size = ""
        if self._sqlite_path:
            with contextlib.suppress(OSError):
                size = f"{Path(self._sqlite_path).stat().st_size / 1e6:.1f} MB"
        return message(QT_TR_NOOP(
            "the disk is full at {path}: migrating the register from schema version "
            "{version} to {latest} needs room for its journal (up to the register's own size, "
            "{size}); nothing was changed, the register is still at version {version} (free "
            "some space and try again)"),
            path=str(self._sqlite_path or self.display_url), version=version or 0,
            latest=self._schema.LATEST, size=size or "?")

    def _migrate_in_one_transaction(self) -> None:
        """The migrations from the register's version to the latest, in one transaction
        (rolled back whole: a register is at its old version or at the latest)."""
        sa, schema = self._sa, self._schema
        with self.engine.begin() as conn:
            if not self.is_sqlite:
                conn.execute(sa.text("SELECT pg_advisory_xact_lock(:k)"), {"k": _ADVISORY_LOCK})
            version = self._version_in(conn)
            if version is None:
                schema.SCHEMA_VERSION.create(conn)
                conn.execute(schema.SCHEMA_VERSION.insert().values(version=0))
                version = 0
            else:
                self._check_version(conn, version)
            for step in range(version + 1, schema.LATEST + 1):
                try:
                    schema.MIGRATIONS[step](conn)
                except ValueError as exc:
                    raise RegisterTampered(message(QT_TR_NOOP(
                        "register {display_url}: migration to schema version {step} refused: "
                        "{reason}; the records' hash chain is never recomputed"),
                        display_url=self.display_url, step=step, reason=str(exc))) from None
            if version < schema.LATEST:
                conn.execute(schema.SCHEMA_VERSION.update().values(version=schema.LATEST))
                conn.execute(schema.STATE.update().where(
                    schema.STATE.c.name == "schema_version").values(value=str(schema.LATEST)))

    @property
    def version(self) -> int:
        with self._read() as conn:
            return conn.execute(self._sa.select(self._schema.SCHEMA_VERSION.c.version)).scalar_one()

    @contextmanager
    def _read(self) -> Iterator[Any]:
        """A connection that reads: no write lock (SQLite: a deferred transaction, which
        reads one snapshot). On PostgreSQL a REPEATABLE READ, read-only transaction: every
        statement in it sees the same snapshot, so the state row and the records it counts
        are read as of one moment even while another issuer commits (READ COMMITTED took a
        new snapshot per statement, and a concurrent issue then looked like a broken
        chain)."""
        try:
            with self.engine.connect() as conn:
                conn.execution_options(anglebench_read=True)
                if not self.is_sqlite:
                    conn.execution_options(isolation_level="REPEATABLE READ",
                                           postgresql_readonly=True)
                yield conn
        except self._sa.exc.SQLAlchemyError as exc:
            if self._full(exc):  # a new connection's WAL index could not be made (reg72 #7)
                raise RegisterError(self._disk_full(reading=True)) from None
            raise RegisterError(self._damaged(exc) or message(
                QT_TR_NOOP("register {display_url}: {reason}"),
                display_url=self.display_url, reason=_reason(exc))) from None

    @contextmanager
    def _write(self) -> Iterator[Any]:
        """One transaction: committed when the block ends, rolled back on any exception.
        On PostgreSQL its statements wait at most LOCK_TIMEOUT_S for a lock, then the
        refusal names who holds it."""
        if self.read_only:
            raise RegisterError(message(QT_TR_NOOP(
                "register {display_url} is read-only: it can be listed and verified, not "
                "written"), display_url=self.display_url))
        if self.key_problem is not None:  # a wrong key writes nothing (reg73 #7)
            raise RegisterError(self.key_problem)
        self._mark_due = None
        try:
            with self.engine.begin() as conn:
                if not self.is_sqlite:
                    conn.execute(self._sa.text(
                        f"SET LOCAL lock_timeout = '{LOCK_TIMEOUT_S}s'"))
                yield conn
            self._raise_high_water()  # committed: the mark outside follows
        except OSError as exc:
            if exc.errno in _DISK_FULL:  # rolled back: said in words, not "[Errno 28] …"
                raise RegisterError(self._disk_full(exc.filename)) from None
            raise
        except self._sa.exc.SQLAlchemyError as exc:  # a unique number taken meanwhile too
            if self._full(exc):
                raise RegisterError(self._disk_full()) from None
            reason = _reason(exc)
            if getattr(getattr(exc, "orig", None), "sqlstate", "") == "55P03":
                reason = message(QT_TR_NOOP(
                    "waited {s} s for the register's lock, held by {holder}"),
                    s=LOCK_TIMEOUT_S, holder=self._lock_holders() or "?")
            elif self._sqlite_path and _is_busy(getattr(exc, "orig", None)):
                holder = writer_holder(self._sqlite_path)
                reason = message(QT_TR_NOOP(
                    "waited {s} s for the register's lock, held by {holder}"),
                    s=BUSY_TIMEOUT_S, holder=holder.text()) if holder else message(
                    QT_TR_NOOP("waited {s} s for the register's lock, held by another "
                               "program, which left no note of who it is"), s=BUSY_TIMEOUT_S)
            raise RegisterError(message(
                QT_TR_NOOP("register {display_url}: {reason}"),
                display_url=self.display_url, reason=reason)) from None

    def _sqlite_begin(self, conn) -> None:
        """A write takes the lock at once (writers queue instead of failing); a read takes
        none (a deferred transaction). A write that finds the lock held waits
        :data:`WAIT_NOTICE_S` in silence, then tells :attr:`on_wait` that it is waiting,
        for whom (the holder's note beside the database, writer_note.py) and for how long
        at most, and waits the rest of :data:`BUSY_TIMEOUT_S` as before (reg72 #8: a minute
        of silence, then "database is locked"). With the lock, it notes itself as the
        writer until its transaction ends."""
        import sqlite3

        if conn.get_execution_options().get("anglebench_read") or not self._sqlite_path:
            _sqlite_begin(conn)
            return
        raw = conn.connection.dbapi_connection
        start = time.monotonic()
        raw.execute(f"PRAGMA busy_timeout={int(WAIT_NOTICE_S * 1000)}")
        try:
            try:
                raw.execute("BEGIN IMMEDIATE")
            except sqlite3.Error as exc:  # waited (said, then waited on), or failed: tried
                if _is_busy(exc):  # again through SQLAlchemy, whose error is said as before
                    self._tell_waiting()
                rest = max(BUSY_TIMEOUT_S - (time.monotonic() - start), 0.0)
                raw.execute(f"PRAGMA busy_timeout={int(rest * 1000)}")
                conn.exec_driver_sql("BEGIN IMMEDIATE")
        finally:
            raw.execute(f"PRAGMA busy_timeout={BUSY_TIMEOUT_S * 1000}")
        write_note(self._sqlite_path)
        self._noted = True

    def _write_ended(self, _conn) -> None:
        """A transaction committed or rolled back: this process's writer note removed."""
        if self._noted:
            self._noted = False
            remove_note(self._sqlite_path)

    def _tell_waiting(self) -> None:
        """:attr:`on_wait` told that a write waits for the lock: the register, who holds
        the lock (since when), how long it will wait at most."""
        if self.on_wait is None:
            return
        holder = writer_holder(self._sqlite_path)
        if holder is not None:
            said = message(QT_TR_NOOP(
                "waiting for the register at {path}: its write lock is held by {holder} "
                "since {since}; giving up after {s} s unless it is released"),
                path=self._sqlite_path, holder=holder.text(), since=holder.since,
                s=BUSY_TIMEOUT_S)
        else:
            said = message(QT_TR_NOOP(
                "waiting for the register at {path}: its write lock is held by another "
                "program, which left no note of who it is; giving up after {s} s unless it "
                "is released"), path=self._sqlite_path, s=BUSY_TIMEOUT_S)
        with contextlib.suppress(Exception):  # a view that cannot show it stops no issue
            self.on_wait(said)

    def _disk_full(self, path: str | None = None, reading: bool = False) -> Message:
        """What a write that found the disk full says: where (the file the system named, or
        the register's file; a server's register by its URL), and that the transaction was
        rolled back: nothing recorded, the register as it was (it said "[Errno 28] No space
        left on device", stop 63). ``reading``: the register was being opened or read (a
        connection whose journal index could not be made), which any command does, `list`
        and `verify` too: said without a recording that none of them attempted (hostile77
        L1: "nothing was recorded" for a command that only reads)."""
        where = str(path or self._sqlite_path or self.display_url)
        if reading:
            return message(QT_TR_NOOP(
                "the disk is full at {path}: the register cannot be opened there (SQLite needs "
                "room beside it for its journal's index); it was not changed (free some space "
                "and try again)"), path=where)
        return message(QT_TR_NOOP(
            "the disk is full at {path}: nothing was recorded; the register is unchanged "
            "(free some space and try again)"), path=where)

    def _full(self, exc: Exception) -> bool:
        """A database error that is a full disk: said so (SQLITE_FULL, PostgreSQL's
        disk_full, ENOSPC), or SQLite's I/O error with no room left in the register's folder
        (:meth:`_no_room`) — on a full tmpfs SQLite fails already on connecting, when its
        "PRAGMA journal_mode=WAL" cannot map the WAL index (reg72 #7: the register was opened
        before any write, and its "disk I/O error" was said as it was)."""
        return _is_disk_full(exc) or (_is_io_error(exc) and self._no_room())

    def _no_room(self) -> bool:
        """The SQLite register's folder has (next to) no free space: SQLite says "disk I/O
        error" (SQLITE_IOERR), not SQLITE_FULL, when its journal cannot grow on some file
        systems (tmpfs; reg72 #7), which sent a technician to look for a failing drive."""
        import shutil

        if not self._sqlite_path:
            return False
        try:
            return shutil.disk_usage(Path(self._sqlite_path).parent).free < _NO_ROOM_BYTES
        except OSError:
            return False

    def _lock_holders(self) -> str:
        """PostgreSQL: the sessions holding the register's locks (user, program, client,
        since when)."""
        try:
            with self.engine.connect() as conn:
                rows = conn.execute(self._sa.text(
                    "SELECT DISTINCT a.pid, a.usename, a.application_name, a.client_addr, "
                    "a.xact_start FROM pg_locks l JOIN pg_stat_activity a ON a.pid = l.pid "
                    "WHERE l.granted AND a.pid <> pg_backend_pid() AND a.datname = "
                    "current_database() AND (l.locktype = 'advisory' OR l.relation IS NOT "
                    "NULL) ORDER BY a.xact_start")).all()
        except self._sa.exc.SQLAlchemyError:
            return ""
        return "; ".join(f"pid {r.pid} ({r.usename}, {r.application_name or '—'}, "
                         f"{r.client_addr or 'local'}, in a transaction since {r.xact_start})"
                         for r in rows)

    # -- the chain's state -------------------------------------------------------------
    def _tail(self, conn) -> tuple[int, str]:
        """The records in the chain and its head, as the records themselves give them (the
        highest place and its chain value)."""
        sa, schema = self._sa, self._schema
        best = (0, GENESIS)
        for table in (schema.CERTIFICATES, schema.ENTRIES):
            row = conn.execute(sa.select(table.c.seq, table.c.chain_sha256)
                               .where(table.c.seq.is_not(None))
                               .order_by(table.c.seq.desc()).limit(1)).first()
            if row is not None and row.seq > best[0]:
                best = (row.seq, row.chain_sha256 or GENESIS)
        return best

    def _state(self, conn) -> tuple[int, str]:
        """The record count and head the register wrote with its last record; refuses
        (RegisterError) when the records no longer end there, and when this process has no
        key and the register holds signed records (every write reads it first)."""
        sa, schema = self._sa, self._schema
        self._refuse_without_key(conn)
        state = dict(conn.execute(sa.select(schema.STATE.c.name, schema.STATE.c.value)).all())
        try:
            records, head = int(state["records"]), state["head"]
        except (KeyError, ValueError):
            raise RegisterError(message(QT_TR_NOOP(
                "the register's state row was changed or deleted: nothing is recorded into "
                "it until 'anglebench register verify' is clean"))) from None
        if (records, head) != self._tail(conn) or self.problems:
            raise RegisterError(message(QT_TR_NOOP(
                "the register's records were changed after issue ({problem}): nothing is "
                "recorded into a broken chain; see 'anglebench register verify'"),
                problem=self.problems[0] if self.problems else message(QT_TR_NOOP(
                    "its last record is not the one it recorded last"))))
        return records, head

    def _append_entry(self, conn, kind: str, subject: str, body: dict) -> str:
        """A chained entry after the current head; returns its chain value."""
        from models.register.chain import link_entry

        schema = self._schema
        records, head = self._state(conn)
        entry = {"seq": records + 1, "kind": kind, "subject": subject,
                 "body_json": json.dumps(body, sort_keys=True, ensure_ascii=False),
                 "recorded_at": self.clock().astimezone(dt.timezone.utc).replace(
                     microsecond=0).isoformat(),
                 "os_user": _os_user(), "workstation": socket.gethostname()}
        chain = link_entry(head, entry)
        conn.execute(schema.ENTRIES.insert().values(**entry, chain_sha256=chain,
                                                    signature=self._sign(chain)))
        self._set_state(conn, records + 1, chain)
        return chain

    def _sign(self, chain: str) -> str | None:
        from models.register.signing import sign

        return sign(self._key, chain) if self._key else None

    def _set_state(self, conn, records: int, head: str) -> None:
        """The state row after a record; with the lab's key its signature too, over the
        count, the head and the counters as this transaction leaves them (reg72 #1)."""
        from models.register.signing import STATE_SIGNATURE, sign, state_text

        state = self._schema.STATE
        conn.execute(state.update().where(state.c.name == "records").values(value=str(records)))
        conn.execute(state.update().where(state.c.name == "head").values(value=head))
        if not self._key:
            return
        from models.register.signing import FINGERPRINT, fingerprint

        if conn.execute(self._sa.select(state.c.value).where(
                state.c.name == FINGERPRINT)).first() is None:
            # the key this register is signed with, told from another (reg73 #7)
            conn.execute(state.insert().values(name=FINGERPRINT, value=fingerprint(self._key)))
        counters, entries = self._schema.COUNTERS, self._schema.ENTRIES
        values = dict(conn.execute(self._sa.select(counters.c.name, counters.c.last_value)).all())
        signature = sign(self._key, state_text(records, head, values))
        self._mark_due = {"records": records, "head": head, "counters": values,
                          "acknowledged": conn.execute(self._sa.select(self._sa.func.count())
                                                       .select_from(entries).where(
                              entries.c.kind == LOSS_ACKNOWLEDGED)).scalar_one()}
        if conn.execute(state.update().where(state.c.name == STATE_SIGNATURE).values(
                value=signature)).rowcount == 0:
            conn.execute(state.insert().values(name=STATE_SIGNATURE, value=signature))

    # -- the high-water mark outside the database (reg73 #2) ---------------------------------
    def _location(self) -> str:
        """The register's location, naming its high-water mark."""
        if self._sqlite_path:
            return "sqlite:///" + str(Path(self._sqlite_path).expanduser().resolve())
        return self.display_url

    def _mark_path(self) -> Path | None:
        from models.register.high_water import mark_path

        return mark_path(self._key_path, self._location()) if self._key_path else None

    def _raise_high_water(self) -> None:
        """After a commit: the state it left noted in the mark beside the key (never
        lowered). A mark that cannot be written is not kept: the register is written all the
        same (the docs say what the mark cannot find)."""
        from models.register.high_water import raise_mark

        due, self._mark_due = self._mark_due, None
        path = self._mark_path()
        if due is None or path is None or self._key is None:
            return
        with contextlib.suppress(OSError):
            raise_mark(path, self._key, self._location(), **due)

    def high_water_mark(self) -> dict | None:
        """The register's high-water mark beside the lab's key, signed with it
        (models/register/high_water.read_mark): None without the key or without a mark; {}
        when it cannot be read or is not the key's. Without a readable mark a loss is
        acknowledged only with the last number known issued (:meth:`acknowledge_loss`)."""
        from models.register.high_water import read_mark

        path = self._mark_path()
        return read_mark(path, self._key) if path is not None and self._key else None

    def _high_water_problems(self, links: list, counters: dict, notes) -> list:
        """With the key: what the register lacks against its high-water mark."""
        from models.register.high_water import mark_problems

        path = self._mark_path()
        if path is None or self._key is None:
            return []
        return mark_problems(path, self._key, {seq: item.chain_sha256 for seq, _e, item in links},
                             counters, sum(1 for n in notes if n.kind == LOSS_ACKNOWLEDGED))

    def _signed_records(self, conn) -> int:
        """How many records and entries carry a signature (the lab's key)."""
        sa, schema = self._sa, self._schema
        return sum(conn.execute(sa.select(sa.func.count()).select_from(table).where(
            table.c.signature.is_not(None))).scalar_one()
            for table in (schema.CERTIFICATES, schema.ENTRIES))

    def _refuse_without_key(self, conn) -> None:
        """A process without the lab's key writes nothing into a register that holds
        signed records (reg72 #3: one unsigned record blocked every keyed workstation for
        good, and a keyless verify called the chain intact)."""
        from models.register.signing import KEY_ENV_VAR

        if self._key or not self._signed_records(conn):
            return
        raise RegisterError(message(QT_TR_NOOP(
            "this register holds records signed with the laboratory's key, and this "
            "AngleBench has no key ({setting} is not set): nothing is recorded unsigned into "
            "a signed register; set {setting} to the key file and try again"),
            setting=KEY_ENV_VAR))

    # -- issuing --------------------------------------------------------------------------
    def _next_value(self, conn, scheme: str, date: dt.date) -> tuple[str, str, int | None, int]:
        """The counter of ``scheme`` on ``date``, its value now (None: no row yet), the value
        the next number takes and that number. A number issued before that is the next one
        by any key the commit's check refuses by (:meth:`_check_free`: "AB-2026-2" typed by
        hand is AB-2026-0002, so is "ab/2026/0002") is skipped, to the next free one (#64
        review F3: only the same text was skipped, and the commit then refused the number
        allocated, for every issue of the scheme). So is a number that a number in the
        register reads as an amendment of (:meth:`_check_amendment_form`: with
        "AB-2026-0009-A1" typed, AB-2026-0009 is skipped). And so is a number that prints
        the fields of one issued with other separators or none (scheme_identity.py: reg72
        #11, ``AB{year}{seq:04d}`` issued AB20260001 beside AB-2026-0001)."""
        from models.register.identifiers import amendment_form_keys, amendment_stems, identifier_keys
        from models.register.scheme_identity import fields_issued, number_pattern

        sa, schema = self._sa, self._schema
        name = _counter_name(scheme, date)
        before = conn.execute(sa.select(schema.COUNTERS.c.last_value).where(
            schema.COUNTERS.c.name == name)).scalar_one_or_none()
        issued = conn.execute(sa.select(schema.CERTIFICATES.c.number)).scalars().all()
        # each key of every number issued, by the key's place (a key meets its own kind)
        taken = [set(keys) for keys in zip(*(identifier_keys(n) for n in issued), strict=True)]
        # the numbers the register's numbers read as amendments of, by the key's place
        stems: list[set[str]] = [set() for _ in range(5)]
        for n in issued:
            for place, found in enumerate(amendment_stems(n)):
                stems[place] |= found
        exact = set(issued)
        value = (before or 0) + 1
        for _ in range(10_000):
            number = format_certificate_number(scheme, value, date)
            if number not in exact and not any(
                    key in keys for key, keys in zip(identifier_keys(number), taken,
                                                     strict=False)) and not any(
                    key in found for key, found in zip(amendment_form_keys(number), stems,
                                                       strict=True)) and fields_issued(
                    number_pattern(scheme, value, date.year, date.month, date.day),
                    issued) is None:
                return name, number, before, value
            value += 1
        raise RegisterError(message(
            QT_TR_NOOP("no free number in scheme '{scheme}'"),
            scheme=scheme))

    def continue_numbering(self, scheme: str, date: dt.date, next_sequence: int) -> str:
        """A lab moving to the register from numbers issued by hand: the next number the
        scheme allocates (for ``date``'s year, month …) is ``next_sequence``. Never moves the
        counter back. Recorded as a chained entry. Returns that next number."""
        if next_sequence < 1:
            raise RegisterError(message(
                QT_TR_NOOP("the next sequence number must be 1 or more")))
        name = _counter_name(scheme, date)
        counters = self._schema.COUNTERS
        with self._write() as conn:
            current = conn.execute(self._sa.select(counters.c.last_value).where(
                counters.c.name == name)).scalar_one_or_none()
            if current is not None and current >= next_sequence:
                raise RegisterError(
                    message(
                    QT_TR_NOOP("the register has already allocated up to {format_certificate_number}: it "
                               "never numbers back"),
                    format_certificate_number=format_certificate_number(scheme, current, date)))
            if current is None:
                conn.execute(counters.insert().values(name=name, last_value=next_sequence - 1))
            else:
                conn.execute(counters.update().where(counters.c.name == name).values(
                    last_value=next_sequence - 1))
            self._append_entry(conn, "numbering", name, {"last_value": next_sequence - 1})
        return format_certificate_number(scheme, next_sequence, date)

    def _check_free(self, conn, number: str, typed: bool = True) -> None:
        """Raise RegisterError if ``number``, or one that prints alike (same_identifier) or
        has its letters and digits with other separators or none (folded_serial_key; reg72
        #11), was issued. ``typed``: the number was typed (the message says to leave it
        empty); else the register allocated it (the message names ``register continue``)."""
        from models.register.identifiers import folded_serial_key, same_identifier

        c = self._schema.CERTIFICATES.c
        joined = folded_serial_key(number)  # letters and digits, separators aside
        row = next((r for r in conn.execute(self._sa.select(
            c.number, c.issued_at, c.workbench, c.item_serial).order_by(c.id))
            if r.number == number or same_identifier(r.number, number)
            or folded_serial_key(r.number) == joined), None)
        if row is None:
            return
        said = {"number": row.number if row.number == number else f"{number} ({row.number})",
                "issued_at": row.issued_at[:10], "workbench": row.workbench,
                "value": row.item_serial or "—"}
        if typed:
            raise RegisterError(message(QT_TR_NOOP(
                "certificate number {number} was issued on {issued_at} ({workbench}, serial "
                "{value}): a number is issued once; leave the number empty and the register "
                "allocates the next"), **said))
        raise RegisterError(message(QT_TR_NOOP(
            "certificate number {number} was issued on {issued_at} ({workbench}, serial "
            "{value}): a number is issued once; move the numbering past it with 'anglebench "
            "register continue SCHEME NEXT'"), **said))

    def _taken(self, conn, number: str) -> bool:
        try:
            self._check_free(conn, number)
        except RegisterError:
            return True
        return False

    def _check_amendment_form(self, conn, number: str, scheme: str = "") -> None:
        """RegisterError when ``number``, typed or (``scheme``) allocated by a number scheme
        for an original or a replacement, and a certificate of the register (issued,
        withdrawn, any) read as an amendment and what it amends (reads_as_amendment_of, by
        the commit check's keys, marks and dashes aside): ``number`` reads as an amendment
        of one ("AB-2026-0001A1", "AB-2026-0001-Amendment 1" with AB-2026-0001 issued;
        rev65 F5), or one, not a real amendment of ``number``, reads as an amendment of it
        ("AB-2026-0009-A1" typed before AB-2026-0009). A customer would take the two for a
        certificate and its amendment. A number of the form alone is issued: "KAL-2026-A17"
        unless KAL-2026 is a certificate's number (rev65 F6: every number ending in "A" and
        digits was refused, so were labs' schemes). The register's own amendments are
        numbered "<number>-A<n>" by Amend…, not checked here."""
        from models.register.identifiers import reads_as_amendment, reads_as_amendment_of

        c = self._schema.CERTIFICATES.c
        rows = conn.execute(self._sa.select(c.number, c.issued_at, c.revision)
                            .order_by(c.id)).all()
        if reads_as_amendment(number):
            row = next((r for r in rows if reads_as_amendment_of(number, r.number)), None)
            if row is not None and scheme:
                raise RegisterError(message(QT_TR_NOOP(
                    "the number scheme '{scheme}' gives {number}, which reads as an amendment's "
                    "number of {other} (issued on {issued_at}): a number, then -A, -Amd, "
                    "-Amendment or -Rev and a count is an amendment of that number, whatever the "
                    "separators, case, marks or look-alike letters; amendments are numbered by "
                    "the register itself; change the scheme"),
                    scheme=scheme, number=number, other=row.number,
                    issued_at=row.issued_at[:10]))
            if row is not None:
                raise RegisterError(message(QT_TR_NOOP(
                    "certificate number {number} reads as an amendment's number of {other} "
                    "(issued on {issued_at}): a number, then -A, -Amd, -Amendment or -Rev and a "
                    "count is an amendment of that number, whatever the separators, case, marks "
                    "or look-alike letters; amendments are numbered by the register itself when "
                    "a certificate is amended; type another number, or leave it empty and the "
                    "register allocates the next"),
                    number=number, other=row.number, issued_at=row.issued_at[:10]))
        row = next((r for r in rows if reads_as_amendment_of(r.number, number) and not (
            r.revision.startswith("amendment") and re.sub(r"-A\d+$", "", r.number) == number)),
            None)
        if row is not None:
            raise RegisterError(message(QT_TR_NOOP(
                "certificate number {number}: {other}, issued on {issued_at}, reads as an "
                "amendment's number of it (a number, then -A and a count, whatever the "
                "separators, case, marks or look-alike letters): a customer would take them "
                "for a certificate and its amendment; type another number, or leave it empty "
                "and the register allocates the next"),
                number=number, other=row.number, issued_at=row.issued_at[:10]))

    def _plan(self, conn, meta: CertificateMetadata, supersedes: str, replacement: bool,
              issue_date: dt.date, now: dt.datetime,
              confirmed_date: dt.date | None = None) -> _Plan:
        sa = self._sa
        records, head = self._state(conn)
        # the clock rules (reg73 #6, #8): against the last chained record of any kind
        from models.register.clock_rules import (
            clock_checked,
            date_backwards,
            last_certificate_since_correction,
            last_chained,
        )

        confirmed = clock_checked(last_chained(conn, sa, self._schema), now, issue_date,
                                  confirmed_date)
        # dates of issue never go backwards against the numbers (reg72 #10), since the last
        # clock correction (the record dated by a clock set ahead stands before it)
        last = last_certificate_since_correction(conn, sa, self._schema)
        if last is not None and last.issue_date > issue_date.isoformat():
            raise RegisterError(date_backwards(last, issue_date, now, self.timezone))
        revision, original = "original", None
        counter = before = value = None
        if supersedes:
            original = self._current(conn, supersedes)
            if original.issue_date > issue_date.isoformat():
                raise RegisterError(message(QT_TR_NOOP(
                    "{number} was issued on {original}: an amendment or replacement cannot "
                    "be dated {today}, before it (check the computer's clock)"),
                    number=original.number, original=original.issue_date,
                    today=issue_date.isoformat()))
            if replacement:
                revision = "replacement"
                counter, number, before, value = self._next_value(conn, meta.number_scheme,
                                                                  issue_date)
                self._check_amendment_form(conn, number, meta.number_scheme)
            else:
                n = _amendment_count(conn, self, original) + 1
                while self._taken(conn, f"{_root(original)}-A{n}"):  # typed in older registers
                    n += 1
                revision, number = f"amendment {n}", f"{_root(original)}-A{n}"
        elif meta.certificate_number:
            number = meta.certificate_number
            self._check_free(conn, number)
            self._check_amendment_form(conn, number)
        else:
            counter, number, before, value = self._next_value(conn, meta.number_scheme,
                                                              issue_date)
            self._check_amendment_form(conn, number, meta.number_scheme)
        return _Plan(number, records + 1, head, counter, before, value, original, revision,
                     confirmed)

    def _unchanged(self, conn, plan: _Plan) -> bool:
        """Whether the register is still as ``plan`` read it (in the write transaction)."""
        counters = self._schema.COUNTERS
        if self._state(conn) != (plan.seq - 1, plan.head):
            return False
        if plan.counter is None:
            return True
        now = conn.execute(self._sa.select(counters.c.last_value).where(
            counters.c.name == plan.counter)).scalar_one_or_none()
        return now == plan.counter_before

    def issue(self, request: IssueRequest, render: Callable[..., bytes],
              *, render_dcc: Callable[[CertificateMetadata, bytes], bytes] | None = None,
              supersedes: str = "", change_note: str = "", replacement: bool = False,
              separate_calibration: str | None = None,
              document_kind: str | Callable[[], str] | None = None,
              correction_confirmed: bool = False, another_makers_item: bool = False,
              another_lookalike_item: bool = False,
              readings_of_another_item: tuple[str, str] | None = None,
              same_readings_as: tuple[str, str] | None = None,
              confirmed_date: dt.date | None = None,
              prepare: Callable[[CertificateMetadata], tuple[str | None, bytes | None]]
              | None = None) -> tuple[CertificateRecord, bytes]:
        """Allocate the number (or check the one given), render the PDF with it and with
        the chain's head before it, record it. The PDF is rendered outside any lock with
        the number and head the register expects next; one short transaction then checks
        that they still are (else renders again) and commits number, record and PDF — no
        gaps, no duplicates. ``render(meta)`` or ``render(meta, head=…)``. ``supersedes``
        issues an amendment (number ``<original>-A<n>``) or, with ``replacement``, a new
        certificate replacing the original; the original is kept unchanged and marked
        superseded. ``render_dcc(meta, pdf)``, when given, makes the digital calibration
        certificate (DCC XML) from the final details and the PDF just rendered, in the same
        attempt (the same number, the PDF embedded in it): it is stored beside the PDF and
        its SHA-256 enters the chain (chain format 3); :meth:`dcc` hands it out. Anything it
        raises leaves no record, as a failing ``render`` does. Returns the record and the
        PDF.

        ``separate_calibration`` ("" or a reason; app/certificate_issue.py, which every
        certificate of the window and the command line goes through, always gives one): an
        original for the workbench, item and date of calibration of a current certificate
        raises :class:`SameCalibrationIssued` unless it says why this is a calibration of its
        own (printed on it, with the other certificates' numbers). None: not checked (the
        register's own tests of numbering and of the chain issue one detail many times).
        Where it finds a current certificate of that serial and date naming another
        manufacturer (one that is not this maker by the maker key, maker_names), it raises
        :class:`AnotherMakersItem` unless ``another_makers_item`` confirms it is another
        maker's item; the confirmation is then a chained entry ("another_maker", the new
        number, the makers and the certificates: :meth:`another_maker_confirmations`).
        Where the serial is none of its maker's in the register but one look-alike
        substitution, case aside, from one that is (identifiers.serial_lookalike: "1ra-0815"
        for LRA-0815), it raises :class:`LookalikeSerial` unless ``another_lookalike_item``
        confirms it is another item; the confirmation is then a chained entry
        ("lookalike_serial": :meth:`lookalike_serial_confirmations`), committed in the one
        transaction with the certificate. :meth:`confirmations_needed` tells both before.
        Where its readings, by their values (readings_identity.readings_key), are those of
        certificates of another item in the register (any status; an amendment's only when
        it changes its original's readings), it raises :class:`ReadingsOfAnotherItem` unless
        ``readings_of_another_item`` is (one of those certificates' numbers, why): then the
        statement naming each of them, its item and date of calibration, and why, is
        printed on it (``readings_note``) and is a chained entry ("readings_of_another_item":
        :meth:`readings_of_another_item_confirmations`). Stated where its readings are not
        that certificate's, it is refused too (the statement would be false). Not checked
        with ``separate_calibration`` None.
        A calibration of its own whose readings, by their values, and details are those of
        a current certificate of its item and date raises :class:`SameReadingsIssued` (no
        two calibrations repeat every reading to the last digit: it is that calibration
        issued again) unless ``same_readings_as`` is (that certificate's number, why): then
        it is stated in its change note and is a chained entry ("same_readings":
        :meth:`same_readings_confirmations`).

        ``document_kind``: what the document rendered is, "calibration" (a calibration
        certificate) or "test" (a test report), or a callable that says so after each
        ``render`` (the document of the attempt recorded; app/certificate_issue.py gives
        one, so every certificate of the window and the command line records it). It
        enters the record's chain (chain format 4: every record issued since schema version
        6). An amendment or replacement records its own document's kind, which is the
        original's unless the corrected document is of the other kind. None: not recorded
        (the register's own tests).
        ``prepare(final)``: the document's kind and its DCC made with an empty PDF, before
        the PDF is rendered (a guess that saves a rendering: the digest the PDF carries covers
        both, content form 2; when the rendering gives others, it is rendered again).

        An amendment or replacement is of the calibration it corrects: issued on the
        original's workbench, for its item (the serial compared as printed, never by its
        look-alike key, which only asks or refuses: rev63 F2; an item of no serial by its
        description and maker too: rev63 F1) and date of calibration, else
        :class:`NotTheSameCalibration`. What else it changes (the customer's address,
        readings, results) is what the change note says. A corrected serial number, date of
        calibration, manufacturer, customer's name, or description of an item of no serial
        is issued only with ``correction_confirmed`` and is then stated on it, before the
        change note ("serial number corrected from LRA-0815 (on AB-2026-0001) to LRA-0816",
        "customer corrected from …"; #64 review F5); a changed description of an item with a
        serial is stated unasked ("item description changed from …"); never
        onto the item and date of another current certificate. The workbench is never
        corrected: a calibration on another workbench is an original.

        The clock (models/register/clock_rules): an issue timed before the register's last
        chained record is refused; one dated more than CONFIRM_AFTER_DAYS days after it raises
        :class:`~models.register.clock_rules.DateToConfirm` unless ``confirmed_date`` is the
        date of issue (today's date confirmed by the person: a chained ``date_confirmed``
        entry committed with the certificate)."""
        from models.register.identifiers import IdentifierError, normalise_identifier, refuse_unprinted

        meta = request.metadata
        try:
            number = normalise_identifier(meta.certificate_number, message(
                QT_TR_NOOP("certificate number")))
            serial = normalise_identifier(meta.item_serial, message(QT_TR_NOOP("serial number")))
            # printed and stored as typed: what prints as nothing is refused, as in a number
            # (#63 regkeys: "ACME\u200b Ltd" printed as "ACME Ltd", another text in the register)
            for text, what in ((meta.item_description, QT_TR_NOOP("item description")),
                               (meta.item_manufacturer, QT_TR_NOOP("manufacturer")),
                               (meta.customer_name, QT_TR_NOOP("customer"))):
                refuse_unprinted(text, message(what))
        except IdentifierError as exc:
            raise RegisterError(reason_of(exc)) from None
        if number.upper().startswith("SPECIMEN"):
            raise RegisterError(message(QT_TR_NOOP(
                "certificate number {number}: numbers beginning SPECIMEN are kept for specimen "
                "certificates, which are never recorded"), number=number))
        meta = dataclasses.replace(meta, certificate_number=number, item_serial=serial)
        # the stored PDFs and DCCs too, which opening does not re-hash: what verify reports,
        # issuing refuses (rev64 F12: a PDF replaced in the database did not stop issuing)
        refused = self.issue_refusal()
        if refused is not None:
            raise RegisterError(refused)
        self._check_approval(meta)
        certificates = self._schema.CERTIFICATES
        user = _os_user()
        # the readings' identities, stored with the record: by their values to 10 digits
        # (schema version 8, chain format 7) and by their physical values (schema version
        # 9, chain format 8), which the register compares readings by (ident80)
        key = readings_key(request.project_json, request.workbench)
        ident = readings_identity(request.project_json, request.workbench)
        stored = NO_READINGS if ident is None else ident.stored
        with self._issuing_turn() as turn:
            for _attempt in range(ISSUE_ATTEMPTS):
                # the time of issue is taken for each attempt: a record committed by another
                # issuer meanwhile is then always before it
                now = self.clock().astimezone(dt.timezone.utc).replace(microsecond=0)
                issue_date = now.astimezone(self.timezone).date()  # the lab's local date
                _check_issuable(meta, issue_date)
                with self._read() as conn:
                    plan = self._plan(conn, meta, supersedes, replacement, issue_date, now,
                                      confirmed_date)
                    same = () if supersedes or separate_calibration is None else \
                        self._same_calibration(conn, request.workbench, meta)
                    # a calibration of its own has readings of its own: the same readings
                    # judged otherwise are a correction (hostile78 F2: the same readings,
                    # ±3″ for ±1″, issued "separate" read "pass")
                    repeated = self._judged_again(conn, same, request, meta, ident)
                    # and one judged alike is that calibration issued again
                    identical = self._issued_again(conn, same, ident, repeated)
                    # a standard whose certificate is one of this register's, withdrawn or
                    # superseded, calibrates nothing (hostile78 F6)
                    void = self._void_standards(conn, meta)
                    # and what one with readings of its own changes against them is said
                    # beside why it is separate (one reading of 41 edited, "as left")
                    against = tuple(
                        c for n in same for c in basis_changes(
                            self._get(conn, n).project_json,
                            _with_metadata(request.project_json, request.workbench, meta),
                            request.workbench, n)) if separate_calibration else ()
                    # an original of the calibration of a withdrawn certificate names it, and
                    # what it changes (hostile78 F3: a fail withdrawn, then a pass issued)
                    withdrawn = () if supersedes or separate_calibration is None else \
                        self._in_place_of_withdrawn(conn, request, meta)
                    # a current certificate of the item whose readings these are (each
                    # within the last digit it was typed to), with another date of
                    # calibration: that calibration issued again, re-dated (hostile79 #3: a
                    # day later it issued as an original, unsaid)
                    redated = () if supersedes or separate_calibration is None else \
                        self._readings_redated(conn, request, meta, ident, same)
                    # an amendment's corrected maker is confirmed and stated on it
                    # (_corrections); an original naming another maker is asked (rev65 F1)
                    others = () if supersedes or separate_calibration is None else \
                        self._another_makers(conn, request.workbench, meta)
                    # a serial that looks like an item's, new to the register (rev65 F7),
                    # and an item of no serial beside one of its description with one: asked
                    lookalikes = () if supersedes or separate_calibration is None else \
                        self._lookalike_serials(conn, meta)
                    left_out = () if supersedes or separate_calibration is None else \
                        self._serial_left_out(conn, request.workbench, meta)
                    # another item's readings (hostile78 F7: one item's readings issued, byte
                    # for byte, as the certificates of nine others)
                    elsewhere = () if separate_calibration is None else \
                        self._readings_elsewhere(conn, request, meta, plan.original, ident)
                    corrected = () if plan.original is None else self._corrections(
                        conn, plan.original, request.workbench, meta, correction_confirmed)
                    if plan.original is not None:
                        # what decides the result, changed, is said too: the tolerance, the
                        # rule, the readings … (hostile78 F1: a "conditional pass" amended to
                        # "pass" read "Changed: typo in the address")
                        corrected = (*corrected, *basis_changes(
                            plan.original.project_json,
                            _with_metadata(request.project_json, request.workbench, meta),
                            request.workbench, plan.original.number))
                    # an amendment or replacement that corrects the item is asked as an
                    # original is, its own certificates aside (stop 67: one corrected to
                    # "1ra-0815" made a second current certificate of LRA-0815's calibration)
                    if plan.original is not None and separate_calibration is not None \
                            and _item_corrected(plan.original, meta):
                        own = self._revisions_of(conn, plan.original)
                        lookalikes = self._lookalike_serials(conn, meta, own)
                        left_out = self._serial_left_out(conn, request.workbench, meta, own)
                separate = " ".join((separate_calibration or "").split())
                if same and not separate:
                    raise SameCalibrationIssued(message(QT_TR_NOOP(
                        "{numbers} already reports this calibration (serial {serial}, calibrated "
                        "{date}): a corrected certificate is its amendment or replacement (Amend… "
                        "or Replace… in File › Certificate register); a calibration of its own "
                        "(e.g. as left after an adjustment) is issued as separate, saying why "
                        "(on the command line: --separate-calibration REASON)"),
                        numbers=", ".join(same), serial=meta.item_serial or "—",
                        date=meta.calibration_date or "—"),
                        same)
                if void:
                    raise RegisterError(separated(void, " "))
                if same and separate and repeated:
                    numbers = ", ".join(n for n, _ in repeated)
                    raise NotASeparateCalibration(message(QT_TR_NOOP(
                        "the readings are those of {numbers} (serial {serial}, calibrated "
                        "{date}), judged otherwise: {changes}. That is no calibration of its "
                        "own, which has readings of its own (e.g. as left after an "
                        "adjustment): it is a correction of {numbers}, its amendment or "
                        "replacement (File › Certificate register, Amend… or Replace…), which "
                        "states what changed (ISO/IEC 17025 7.8.8)"),
                        numbers=numbers, serial=meta.item_serial or "—",
                        date=meta.calibration_date or "—",
                        changes=separated([c for _, said in repeated for c in said])),
                        tuple(n for n, _ in repeated))
                identical = identical if same and separate else ()
                same_said = _same_readings_said(meta, identical or redated, same_readings_as,
                                                redated=not identical and bool(redated))
                identical = identical or redated
                if others and not another_makers_item:
                    raise _another_makers_item(meta, others)
                if lookalikes and not another_lookalike_item:
                    raise _lookalike_serial(meta, lookalikes)
                if left_out and not another_lookalike_item:
                    raise _serial_left_out(meta, left_out)
                # asked once the item is told (another maker's, another serial's)
                readings_said = _readings_said(meta, elsewhere, readings_of_another_item)
                original = plan.original
                final = dataclasses.replace(
                    meta, certificate_number=plan.number, issue_date=issue_date.isoformat(),
                    created=now.isoformat(),
                    supersedes=original.number if original else "",
                    revision="" if plan.revision == "original" else plan.revision,
                    change_note=_bounded(separated([separate, *filter(None, [same_said]),
                                                    *against])) if same else
                    _bounded(separated([*corrected, change_note])) if corrected else
                    _bounded(separated([same_said, change_note])) if same_said else change_note,
                    separate_from=", ".join(same),
                    replaces_withdrawn=", ".join(n for n, _ in withdrawn),
                    withdrawn_note=_bounded(separated([said for _, said in withdrawn])),
                    readings_of_another_item=", ".join(e[0] for e in elsewhere)
                    if readings_said else "",
                    readings_note=_bounded(readings_said))
                record = CertificateRecord(
                    number=plan.number,
                    issued_at=now.isoformat(),
                    issue_date=issue_date.isoformat(), calibration_date=meta.calibration_date,
                    workbench=request.workbench, item_description=meta.item_description,
                    item_manufacturer=meta.item_manufacturer, item_serial=meta.item_serial,
                    customer=meta.customer_name, operator=meta.operator,
                    workstation=socket.gethostname(), status="issued",
                    supersedes=original.number if original else None, superseded_by=None,
                    revision=plan.revision, change_note=str(final.change_note),
                    project_json=_with_metadata(request.project_json, request.workbench, final),
                    software_json=json.dumps(software_versions(), sort_keys=True),
                    headline_json=json.dumps(request.headline, sort_keys=True),
                    pdf_sha256="",
                    seq=plan.seq, counter=plan.counter, counter_value=plan.counter_value,
                    os_user=user, approver=meta.approver,
                    chain_format=8, readings_key=key, readings_layout=stored[0],
                    readings_anchor=stored[1], readings_reach=stored[2])
                # the record's content first, carried by the PDF (so by the DCC that embeds
                # it); then the files' hashes (reg72 #2: the newest record rewritten with its
                # chain recomputed is found from the customer's copy). Content form 2 also
                # covers the document's kind and its DCC but for the PDF inside (reg73 #1),
                # which are told by the rendering: rendered again when they were not the
                # ones the digest was taken with (a kind given as text and no DCC: once)
                pdf, kind, dcc = self._render_with_content(
                    render, render_dcc, document_kind, final, plan.head, record, prepare)
                record = dataclasses.replace(
                    record, pdf_sha256=hashlib.sha256(pdf).hexdigest(),
                    dcc_sha256=None if dcc is None else hashlib.sha256(dcc).hexdigest(),
                    document_kind=kind)
                chain = link(plan.head, dataclasses.asdict(record))
                record = dataclasses.replace(record, chain_sha256=chain,
                                             signature=self._sign(chain))
                with self._write() as conn:
                    if not self.is_sqlite:  # SQLite's BEGIN IMMEDIATE already serialises
                        conn.execute(self._sa.text("SELECT pg_advisory_xact_lock(:k)"),
                                     {"k": _CHAIN_LOCK})
                    if self._unchanged(conn, plan):
                        if original is not None:
                            current = self._current(conn, original.number)
                            if current.status != "issued":
                                continue
                        self._check_free(conn, plan.number, typed=plan.counter is None
                                         and not supersedes)
                        conn.execute(certificates.insert().values(
                            **dataclasses.asdict(record), pdf=pdf,
                            dcc=None if dcc is None else bytes(dcc)))
                        if plan.counter is not None:
                            counters = self._schema.COUNTERS
                            if plan.counter_before is None:
                                conn.execute(counters.insert().values(
                                    name=plan.counter, last_value=plan.counter_value))
                            else:
                                conn.execute(counters.update().where(
                                    counters.c.name == plan.counter).values(
                                    last_value=plan.counter_value))
                        self._set_state(conn, plan.seq, chain)
                        if original is not None:
                            conn.execute(certificates.update().where(
                                certificates.c.number == original.number).values(
                                status="superseded", superseded_by=plan.number))
                        if others:  # said by the user: recorded, so that it can be audited
                            self._append_entry(conn, "another_maker", plan.number, {
                                "serial": meta.item_serial,
                                "description": meta.item_description,
                                "manufacturer": meta.item_manufacturer,
                                "calibration_date": meta.calibration_date,
                                "others": [{"number": n, "manufacturer": m}
                                           for n, m in others]})
                        if lookalikes or left_out:  # said by the user: recorded
                            self._append_entry(conn, "lookalike_serial", plan.number, {
                                **_item_said(meta),
                                "others": [{"number": n, "serial": k, "manufacturer": m}
                                           for n, k, m in (*lookalikes, *left_out)]})
                        if readings_said:  # said by the user: recorded
                            self._append_entry(conn, "readings_of_another_item", plan.number, {
                                **_item_said(meta),
                                "reason": " ".join(readings_of_another_item[1].split())
                                if readings_of_another_item else "",
                                "others": [{"number": n, "serial": k, "item": i,
                                            "calibration_date": d}
                                           for n, k, i, d in elsewhere]})
                        if same_said:  # said by the user: recorded
                            self._append_entry(conn, "same_readings", plan.number, {
                                **_item_said(meta),
                                "reason": " ".join(same_readings_as[1].split())
                                if same_readings_as else "",
                                "others": [{"number": n} for n in identical]})
                        if plan.date_confirmed is not None:  # said by the user: recorded
                            self._append_entry(conn, "date_confirmed", plan.number,
                                               plan.date_confirmed)
                        # its results file may now be recorded, by this issuer only
                        self._results_due.add(plan.number)
                        return record, pdf
                turn.take()  # another issue came first: render again, in turn
        raise RegisterError(message(QT_TR_NOOP(
            "the register was busy: {n} other certificates were issued while this one was "
            "being made; try again"), n=ISSUE_ATTEMPTS))

    def _render_with_content(self, render: Callable[..., bytes],
                             render_dcc: Callable[[CertificateMetadata, bytes], bytes] | None,
                             document_kind: str | Callable[[], str] | None,
                             final: CertificateMetadata, head: str,
                             record: CertificateRecord,
                             prepare: Callable[[CertificateMetadata],
                                               tuple[str | None, bytes | None]] | None = None,
                             ) -> tuple[bytes, str | None, bytes | None]:
        """The PDF rendered with the digest of its record's content in form 2 (chain format
        6), the document's kind and its DCC: the digest is taken with the kind and the DCC's
        body (:func:`models.register.chain.dcc_body_digest`) of the rendering before, until
        a rendering gives the ones its digest was taken with (the second, unless the
        document changes as it is rendered: then nothing is issued)."""
        from models.register.chain import content_digest_v2, dcc_body_digest
        from models.register.signing import proof

        kind = None if callable(document_kind) else document_kind
        body: str | None = None
        if prepare is not None:  # the guess of the caller, checked by the rendering
            guessed_kind, guessed_dcc = prepare(final)
            kind = guessed_kind if callable(document_kind) else kind
            body = None if guessed_dcc is None else dcc_body_digest(bytes(guessed_dcc))
        fields = dataclasses.asdict(record)
        for _rendering in range(3):
            guess = (kind, body)
            content = content_digest_v2({**fields, "document_kind": kind}, body)
            # with the lab's key, the proof that this register issued it (reg73 #3)
            made = proof(self._key, record.number, head, content if _takes(
                render, "content") else "") if self._key else ""
            pdf = _call_render(render, final, head, content, made)
            kind = document_kind() if callable(document_kind) else document_kind
            if kind is not None and kind not in DOCUMENT_KINDS:
                raise ValueError(f"document_kind {kind!r}: one of {DOCUMENT_KINDS}")
            dcc = render_dcc(final, pdf) if render_dcc is not None else None
            if dcc is not None and not isinstance(dcc, bytes | bytearray):
                raise TypeError("render_dcc returns the DCC's bytes")
            body = None if dcc is None else dcc_body_digest(bytes(dcc))
            if (kind, body) == guess:
                return pdf, kind, None if dcc is None else bytes(dcc)
        raise RegisterError(message(QT_TR_NOOP(
            "the document changed each time it was rendered (its kind or its DCC), so the "
            "digest its PDF carries cannot be its record's: nothing was issued")))

    @contextmanager
    def _issuing_turn(self) -> Iterator[Any]:
        """After a lost race an issuer waits for its turn (an advisory lock: a file lock
        beside a SQLite register, a session lock on PostgreSQL) so that it renders at most
        twice; the database's own lock is held only for the commit."""
        turn = _Turn(self)
        try:
            yield turn
        finally:
            turn.release()

    @staticmethod
    def clock() -> dt.datetime:
        """The time of issue (a test sets its own)."""
        return dt.datetime.now(dt.timezone.utc)

    def reports_calibration(self, workbench: str, meta: CertificateMetadata
                            ) -> tuple[str, ...]:
        """The current certificates of ``workbench`` that already report the item and date
        of calibration of ``meta`` (as :meth:`issue` finds them for an original): the window
        asks about a second original before it asks for a file name (rev62 F10)."""
        with self._read() as conn:
            return self._same_calibration(conn, workbench, meta)

    def _current_of_the_day(self, workbench: str, meta: CertificateMetadata,
                            status: str = "issued"):
        """The query of the current certificates (issued, not superseded or withdrawn) of
        ``workbench`` and the date of calibration of ``meta``: their number and item (the
        one-calibration check and its another-maker and serial-left-out questions)."""
        c = self._schema.CERTIFICATES.c
        return self._sa.select(c.number, c.item_serial, c.item_description,
                               c.item_manufacturer).where(
            c.workbench == workbench, c.status == status,
            c.calibration_date == meta.calibration_date)

    def _void_standards(self, conn, meta: CertificateMetadata) -> builtins.list[Any]:
        """Why each reference standard of ``meta`` whose certificate is one of this
        register's — its number, for that certificate's item (the standard's serial, where
        it lists one) — cannot be cited: that certificate was withdrawn or superseded
        (hostile78 F6: a polygon's withdrawn certificate typed as its calibration)."""
        from models.register.identifiers import same_serial

        out = []
        for standard in meta.standards:
            number = (standard.certificate_no or "").strip()
            if not number:
                continue
            try:
                record = self._get(conn, number)
            except RegisterError:
                continue
            if standard.serial and not same_serial(standard.serial, record.item_serial):
                continue  # another laboratory's certificate numbered alike
            name = standard.description or standard.serial or number
            if record.status == "withdrawn":
                out.append(message(QT_TR_NOOP(
                    "the reference standard {standard} cites certificate {number}, which this "
                    "register withdrew ({reason}): a withdrawn certificate calibrates nothing; "
                    "cite the standard's valid certificate"), standard=name,
                    number=record.number, reason=record.withdrawn_reason or "—"))
            elif record.status == "superseded":
                out.append(message(QT_TR_NOOP(
                    "the reference standard {standard} cites certificate {number}, which was "
                    "superseded by {by}: cite {by}, with its figures"), standard=name,
                    number=record.number, by=record.superseded_by or "—"))
        return out

    def _judged_again(self, conn, same: tuple[str, ...], request: IssueRequest,
                      meta: CertificateMetadata, ident: ReadingsIdentity | None = None
                      ) -> tuple[tuple[str, tuple], ...]:
        """Of the current certificates ``same`` of this calibration, those whose readings
        ``request`` holds too, as typed or by their values (``ident``: the request's
        readings_identity), and judges otherwise (another tolerance, rule, standard or
        setting): each with what it changes (hostile78 F2)."""
        project = _with_metadata(request.project_json, request.workbench, meta)
        out = []
        for number in same:
            record = self._get(conn, number)
            judged = project
            if not same_readings(record.project_json, project, request.workbench):
                if not self._same_values(record, ident):
                    continue
                # the same values typed otherwise: compared with the record's rows as typed
                judged = _with_rows_of(project, record.project_json, request.workbench)
            changes = basis_changes(record.project_json, judged, request.workbench, number)
            if changes:
                out.append((number, changes))
        return tuple(out)

    def _issued_again(self, conn, same: tuple[str, ...], ident: ReadingsIdentity | None,
                      repeated: tuple[tuple[str, tuple], ...]) -> tuple[str, ...]:
        """Of the current certificates ``same`` of this calibration, those whose readings
        are the request's by their values (``ident``) and that it judges alike (not among
        ``repeated``, :meth:`_judged_again`'s): that calibration issued again."""
        if ident is None:
            return ()
        judged = {n for n, _ in repeated}
        return tuple(n for n in same if n not in judged
                     and self._same_values(self._get(conn, n), ident))

    def _identity_of(self, number: str, workbench: str, project_json: str
                     ) -> ReadingsIdentity | None:
        """Record ``number``'s readings by their physical values, made from its project
        state (in the chain) once per register object."""
        if number not in self._identities:
            self._identities[number] = readings_identity(project_json, workbench)
        return self._identities[number]

    def _same_values(self, record: CertificateRecord, ident: ReadingsIdentity | None) -> bool:
        """Whether ``record``'s readings are ``ident``'s by their physical values
        (readings_identity.same_readings_values)."""
        if ident is None:
            return False
        # the anchor only: the stored layout is of the cells as typed, compared as the
        # analysis reads them (ReadingsIdentity.shape, made again)
        if record.readings_layout is not None and not near(
                ident.anchor, ident.reach, record.readings_anchor or 0,
                record.readings_reach or 0):
            return False
        return same_readings_values(ident, self._identity_of(
            record.number, record.workbench, record.project_json))

    def _numbers_of_readings(self, conn, workbench: str, ident: ReadingsIdentity | None,
                             *where: Any) -> builtins.list[str]:
        """The numbers of the records of ``workbench`` (and ``where``) whose readings are
        ``ident``'s by their physical values, in the register's order: the candidates looked
        up by the stored identity (its anchor, of any layout: the stored layout is of the
        cells as typed, "up" or a run given where the analysis derives it; their indexes:
        schema version 9), then compared; a record without one (issued by an AngleBench of schema 8 after the
        migration, or a register read as it is) by its readings, made once per register
        object."""
        if ident is None:
            return []
        sa, c = self._sa, self._schema.CERTIFICATES.c
        if not self._stored_identities:
            rows = conn.execute(sa.select(c.number, c.project_json).where(
                c.workbench == workbench, *where).order_by(c.id)).all()
        else:
            # the anchors within the larger reach: the request's, or a record's, which is at
            # most the largest of the workbench's below the index's bound (one look-up);
            # a record beyond it (values of 10⁶ rad) is every value's, compared always
            # — without widening every look-up to the whole workbench
            widest = conn.execute(sa.select(sa.func.max(c.readings_reach)).where(
                c.workbench == workbench, c.readings_reach < INDEX_BOUND)).scalar() or 0
            span = max(ident.reach, int(widest))
            rows = conn.execute(sa.select(c.number, c.project_json).where(
                c.workbench == workbench, *where, sa.or_(
                    sa.and_(c.readings_layout != NO_READINGS[0], sa.or_(
                        c.readings_anchor.between(ident.anchor - span, ident.anchor + span),
                        c.readings_reach >= INDEX_BOUND)),
                    c.readings_layout.is_(None))).order_by(c.id)).all()
        return [row.number for row in rows if same_readings_values(
            ident, self._identity_of(row.number, workbench, row.project_json))]

    def _request_identity(self, request: IssueRequest) -> ReadingsIdentity | None:
        """``request``'s readings by their physical values (the last request's kept)."""
        made = getattr(self, "_last_request_identity", None)
        if made is None or made[0] != (request.project_json, request.workbench):
            made = self._last_request_identity = (
                (request.project_json, request.workbench),
                readings_identity(request.project_json, request.workbench))
        return made[1]

    def _readings_elsewhere(self, conn, request: IssueRequest, meta: CertificateMetadata,
                            original: CertificateRecord | None,
                            ident: ReadingsIdentity | None = None
                            ) -> tuple[tuple[str, str, str, str], ...]:
        """The certificates (number, serial, item as printed, date of calibration) of any
        status, on ``request``'s workbench, of another item than ``meta``'s (not its serial
        as printed alike, of its maker: _same_calibration's rule; for an item of no serial,
        its description and maker) whose readings are ``request``'s by their physical values
        (``ident``, made when not given: :func:`models.register.readings_identity.
        readings_identity`), in the register's order.
        ``original``: the certificate an amendment or replacement corrects; () when it holds
        these readings already (the amendment does not change them), else its own revisions
        are not counted."""
        from models.register.identifiers import no_serial

        ident = ident if ident is not None else self._request_identity(request)
        if ident is None:
            return ()
        own: frozenset[str] = frozenset()
        if original is not None:
            if self._same_values(original, ident):
                return ()
            own = self._revisions_of(conn, original)
        out = []
        for number in self._numbers_of_readings(conn, request.workbench, ident):
            if number in own:
                continue
            record = self._get(conn, number)
            if not _one_item(record, meta):
                serial = _printed(record.item_serial)
                maker = _printed(record.item_manufacturer)
                out.append((number, serial, (f"{serial}, {maker}" if maker else serial)
                            if not no_serial(serial) else
                            _item_text(_printed(record.item_description), maker),
                            record.calibration_date or ""))
        return tuple(out)

    def readings_of_another_item(self, workbench: str, meta: CertificateMetadata,
                                 rows: builtins.list[builtins.list[str]],
                                 settings: dict | None = None
                                 ) -> ReadingsOfAnotherItem | None:
        """What :meth:`issue` would raise, unasked, for an original of ``meta`` on
        ``workbench`` whose readings are ``rows`` (the sheet's, as typed) because they are
        those of certificates of another item (:class:`ReadingsOfAnotherItem`); None when
        they are not: the window asks before it asks for a file name. ``settings``: the
        workbench's, which give its columns' units (readings_identity; None: the defaults).
        The issue checks again."""
        from models.register.identifiers import IdentifierError, normalise_identifier

        try:
            meta = dataclasses.replace(meta, item_serial=normalise_identifier(meta.item_serial))
        except IdentifierError:
            return None  # the issue refuses it, saying why
        project = json.dumps({"workbenches": {workbench: {"rows": rows,
                                                          "settings": settings or {}}}})
        request = IssueRequest(workbench, meta, project)
        with self._read() as conn:
            elsewhere = self._readings_elsewhere(conn, request, meta, None)
        try:
            _readings_said(meta, elsewhere, None)
        except ReadingsOfAnotherItem as exc:
            return exc
        return None

    def readings_of_another_item_confirmations(self, number: str = "") -> builtins.list[dict]:
        """The certificates issued after the user said why their readings are those of
        certificates of another item (:class:`ReadingsOfAnotherItem`), from the chained
        entries: ``number``, ``serial``, ``manufacturer``, ``reason``, ``others``
        ([{number, serial, item, calibration_date}]), ``recorded_at``, ``os_user``; every
        one, or ``number``'s."""
        return self._confirmations("readings_of_another_item", number)

    def same_readings_confirmations(self, number: str = "") -> builtins.list[dict]:
        """The calibrations of their own issued after the user said why their readings and
        details are those of a current certificate of their item and date
        (:class:`SameReadingsIssued`), from the chained entries: ``number``, ``serial``,
        ``manufacturer``, ``reason``, ``others`` ([{number}]), ``recorded_at``,
        ``os_user``; every one, or ``number``'s."""
        return self._confirmations("same_readings", number)

    def _readings_redated(self, conn, request: IssueRequest, meta: CertificateMetadata,
                          ident: ReadingsIdentity | None, same: tuple[str, ...]
                          ) -> tuple[str, ...]:
        """The current certificates of ``meta``'s item on ``request``'s workbench with
        another date of calibration than ``meta``'s whose readings are ``request``'s by their
        values (``ident``): no two calibrations repeat every reading to the last digit, so an
        original of them is that calibration issued again with its date moved (hostile79
        #3). ``same``: this date's certificates, told apart already."""
        c = self._schema.CERTIFICATES.c
        return tuple(n for n in self._numbers_of_readings(
            conn, request.workbench, ident, c.status == "issued",
            c.calibration_date != meta.calibration_date)
            if n not in same and _one_item(self._get(conn, n), meta))

    def _in_place_of_withdrawn(self, conn, request: IssueRequest, meta: CertificateMetadata
                               ) -> tuple[tuple[str, Any], ...]:
        """The withdrawn certificates of the item and date of calibration of ``meta`` on
        ``request``'s workbench, each with what to say of it: when and why it was withdrawn,
        and what this certificate changes of what decides the result against it
        (:func:`models.register.basis_changes.basis_changes`). Also those of the item of
        another date of calibration whose readings are ``request``'s, by their values
        (readings_identity.readings_key): the date moved by a day is the same calibration
        (hostile78 F3/F7: withdrawn, then issued again dated a day later, unlinked); the
        date's change is said first."""
        out = []
        project = _with_metadata(request.project_json, request.workbench, meta)
        numbers = self._same_calibration(conn, request.workbench, meta, "withdrawn")
        moved = self._withdrawn_readings(conn, request, meta, numbers)
        for number in (*numbers, *moved):
            record = self._get(conn, number)
            when = self._withdrawn_on(conn, number)
            changes = basis_changes(record.project_json, project, request.workbench, number)
            if number in moved:
                changes = (message(QT_TR_NOOP(
                    "date of calibration changed from {old} (on {number}) to {new}"),
                    old=record.calibration_date or "—", number=number,
                    new=meta.calibration_date or "—"), *changes)
            if _printed(record.customer) != _printed(meta.customer_name):  # whose it is
                changes = (message(QT_TR_NOOP(
                    "customer changed from {old} (on {number}) to {new}"),
                    old=_printed(record.customer) or "—", number=number,
                    new=_printed(meta.customer_name) or "—"), *changes)
            said = message(QT_TR_NOOP("{number} withdrawn {date} ({reason})"), number=number,
                           date=when or "—", reason=record.withdrawn_reason or "—")
            if changes:
                said = message(QT_TR_NOOP("{withdrawn}; changed: {changes}"), withdrawn=said,
                               changes=separated(changes))
            out.append((number, said))
        return tuple(out)

    def _withdrawn_readings(self, conn, request: IssueRequest, meta: CertificateMetadata,
                            besides: tuple[str, ...]) -> tuple[str, ...]:
        """The withdrawn certificates of ``request``'s workbench and ``meta``'s item (as
        :meth:`_same_calibration` tells an item), of another date of calibration, whose
        readings are ``request``'s by their values; ``besides`` (those of its date) not
        counted."""
        c = self._schema.CERTIFICATES.c
        out = []
        for number in self._numbers_of_readings(
                conn, request.workbench, self._request_identity(request), c.status == "withdrawn",
                c.calibration_date != meta.calibration_date):
            if number not in besides and _one_item(self._get(conn, number), meta):
                out.append(number)
        return tuple(out)

    def _withdrawn_on(self, conn, number: str) -> str:
        """The date (UTC, as recorded) of ``number``'s withdrawal entry; "" when the register
        holds none (a withdrawal of an older register)."""
        entries = self._schema.ENTRIES
        row = conn.execute(self._sa.select(entries.c.recorded_at).where(
            entries.c.kind == "withdrawal", entries.c.subject == number).order_by(
            entries.c.seq.desc())).first()
        return str(row.recorded_at)[:10] if row is not None and row.recorded_at else ""

    def _same_calibration(self, conn, workbench: str, meta: CertificateMetadata,
                          status: str = "issued") -> tuple[str, ...]:
        """The current certificates (issued, not superseded or withdrawn) of ``workbench``
        reporting the item and date of calibration of ``meta``: a serial number that prints
        alike or differs by case, separators aside (same_serial), of a manufacturer that
        does too (same_identifier; a record or ``meta`` naming none is any: a serial is
        unique only within its maker, so Acme's "001" and Zeta's "001" are two items, as in
        :meth:`history`; stop 63: compared by the serial alone). Where there is none
        (no_serial: empty, "-", "n/a" …), an item of no serial whose description and
        manufacturer print alike (same_identifier; #62 review: "rotary table" was another
        item than "Rotary table", and a serial "-" was every item without one)."""
        from models.register.identifiers import no_serial, same_identifier, same_serial

        c = self._schema.CERTIFICATES.c
        query = self._current_of_the_day(workbench, meta, status)
        if no_serial(meta.item_serial):
            return tuple(row.number for row in conn.execute(query.order_by(c.id))
                         if no_serial(row.item_serial) and same_identifier(
                             row.item_description or "", meta.item_description or "")
                         and _same_maker(row.item_manufacturer, meta.item_manufacturer))
        return tuple(row.number for row in conn.execute(query.order_by(c.id))
                     if same_serial(row.item_serial, meta.item_serial)
                     and _same_maker(row.item_manufacturer, meta.item_manufacturer))

    def _another_makers(self, conn, workbench: str, meta: CertificateMetadata,
                        original: CertificateRecord | None = None
                        ) -> tuple[tuple[str, str], ...]:
        """The current certificates (number, manufacturer) of ``workbench`` for the serial
        (with none, the description) and date of calibration of ``meta`` that name another
        manufacturer than ``meta``'s, both named and not one maker (maker_names): another
        maker's item, or the same one with its maker spelt otherwise — asked, never passed
        silently (rev65 F1). ``original``: the certificate an amendment corrects (not
        counted)."""
        from models.register.identifiers import no_serial, same_identifier, same_serial

        if not (meta.item_manufacturer or "").strip():
            return ()
        c = self._schema.CERTIFICATES.c
        query = self._current_of_the_day(workbench, meta)
        unnamed = no_serial(meta.item_serial)
        return tuple(
            (row.number, _printed(row.item_manufacturer))
            for row in conn.execute(query.order_by(c.id))
            if (original is None or row.number != original.number)
            and (row.item_manufacturer or "").strip()
            and not _same_maker(row.item_manufacturer, meta.item_manufacturer)
            and (same_identifier(row.item_description or "", meta.item_description or "")
                 and no_serial(row.item_serial) if unnamed else
                 not no_serial(row.item_serial)
                 and same_serial(row.item_serial, meta.item_serial)))

    def confirmations_needed(self, workbench: str, meta: CertificateMetadata
                             ) -> tuple[RegisterError, ...]:
        """What :meth:`issue` would ask the user to confirm for an original of ``meta`` on
        ``workbench``, as the errors it would raise unconfirmed (:class:`AnotherMakersItem`,
        :class:`LookalikeSerial`), worded as it words them: the window asks before it asks
        for a file name (rev65: a No after the file dialog left a file chosen for
        nothing). The issue checks again (the register may change meanwhile)."""
        from models.register.identifiers import IdentifierError, normalise_identifier

        try:
            meta = dataclasses.replace(meta, item_serial=normalise_identifier(meta.item_serial))
        except IdentifierError:
            return ()  # the issue refuses it, saying why
        with self._read() as conn:
            others = self._another_makers(conn, workbench, meta)
            lookalikes = self._lookalike_serials(conn, meta)
            left_out = self._serial_left_out(conn, workbench, meta)
        return ((_another_makers_item(meta, others),) if others else ()) + \
            ((_lookalike_serial(meta, lookalikes),) if lookalikes else ()) + \
            ((_serial_left_out(meta, left_out),) if left_out else ())

    def _lookalike_serials(self, conn, meta: CertificateMetadata,
                           own: frozenset[str] = frozenset()
                           ) -> tuple[tuple[str, str, str], ...]:
        """The certificates (number, serial, manufacturer) of every status whose serial
        looks like ``meta``'s, case aside (identifiers.serial_lookalike), of its maker (a
        certificate or ``meta`` naming none is any: _same_maker), when no certificate of its
        maker has its serial (then it is that item's, asked nothing: rev65 F7). () for an
        item of no serial. ``own``: the numbers of the certificate an amendment corrects and
        of its earlier revisions (not counted)."""
        from models.register.identifiers import no_serial, serial_lookalike

        if no_serial(meta.item_serial):
            return ()
        c = self._schema.CERTIFICATES.c
        rows = [row for row in conn.execute(self._sa.select(
                    c.number, c.item_serial, c.item_manufacturer).order_by(c.id))
                if row.number not in own and not no_serial(row.item_serial or "")
                and _same_maker(row.item_manufacturer, meta.item_manufacturer)]
        if any(_same_instrument(row.item_serial, meta.item_serial) for row in rows):
            return ()
        return tuple((row.number, row.item_serial, _printed(row.item_manufacturer))
                     for row in rows if serial_lookalike(meta.item_serial, row.item_serial))

    def _serial_left_out(self, conn, workbench: str, meta: CertificateMetadata,
                         own: frozenset[str] = frozenset()
                         ) -> tuple[tuple[str, str, str], ...]:
        """The current certificates (number, serial, manufacturer) of ``workbench`` and the
        date of calibration of ``meta`` whose item has a serial where ``meta``'s has none
        (no_serial), or none where it has one, of a description printing alike
        (same_identifier, as an item of no serial is told) and of its maker (_same_maker: a
        side naming none is any): that calibration's item, perhaps, its serial left out or
        typed only now (stop 67: a blank serial got past the one-calibration check).
        ``own``: as in :meth:`_lookalike_serials`."""
        from models.register.identifiers import no_serial, same_identifier

        c = self._schema.CERTIFICATES.c
        query = self._current_of_the_day(workbench, meta)
        unnamed = no_serial(meta.item_serial)
        return tuple(
            (row.number, row.item_serial or "", _printed(row.item_manufacturer))
            for row in conn.execute(query.order_by(c.id))
            if row.number not in own and no_serial(row.item_serial or "") != unnamed
            and same_identifier(row.item_description or "", meta.item_description or "")
            and _same_maker(row.item_manufacturer, meta.item_manufacturer))

    def _revisions_of(self, conn, record: CertificateRecord) -> frozenset[str]:
        """``record``'s number and those of the certificates it supersedes, back to the
        original: the one calibration an amendment corrects."""
        c = self._schema.CERTIFICATES.c
        numbers, number = {record.number}, record.supersedes
        while number and number not in numbers:
            numbers.add(number)
            number = conn.execute(self._sa.select(c.supersedes).where(
                c.number == number)).scalar_one_or_none()
        return frozenset(numbers)

    def _confirmations(self, kind: str, number: str) -> builtins.list[dict]:
        """The chained entries of ``kind`` (a confirmation the user gave at issue), every
        one or ``number``'s: ``number``, ``manufacturer``, ``serial``, ``others``,
        ``recorded_at``, ``os_user``."""
        entries = self._schema.ENTRIES
        query = self._sa.select(entries.c.subject, entries.c.body_json, entries.c.recorded_at,
                                entries.c.os_user).where(entries.c.kind == kind)
        if number:
            query = query.where(entries.c.subject == number)
        with self._read() as conn:
            rows = conn.execute(query.order_by(entries.c.seq)).all()
        out = []
        for row in rows:
            body = json.loads(row.body_json or "{}")
            out.append({"number": row.subject, "manufacturer": body.get("manufacturer", ""),
                        "serial": body.get("serial", ""), "reason": body.get("reason", ""),
                        "others": body.get("others", []), "recorded_at": row.recorded_at,
                        "os_user": row.os_user})
        return out

    def another_maker_confirmations(self, number: str = "") -> builtins.list[dict]:
        """The certificates issued after the user confirmed that the item is another
        maker's than that of a current certificate of the same serial and date
        (:class:`AnotherMakersItem`), from the chained entries: ``number``,
        ``manufacturer``, ``others`` ([{number, manufacturer}]), ``recorded_at``,
        ``os_user``; every one, or ``number``'s."""
        return self._confirmations("another_maker", number)

    def lookalike_serial_confirmations(self, number: str = "") -> builtins.list[dict]:
        """The certificates issued after the user confirmed that their serial, one
        look-alike from another certificate's, is another item's (:class:`LookalikeSerial`),
        from the chained entries: ``number``, ``serial``, ``manufacturer``, ``others``
        ([{number, serial, manufacturer}]), ``recorded_at``, ``os_user``."""
        return self._confirmations("lookalike_serial", number)

    def _corrections(self, conn, original: CertificateRecord, workbench: str,
                     meta: CertificateMetadata, confirmed: bool) -> tuple[Any, ...]:
        """What an amendment or replacement of ``original`` with ``meta`` on ``workbench``
        corrects of the calibration's identity, as stated on it (() when nothing);
        NotTheSameCalibration when it is not a correction of that calibration, or not
        confirmed (see :meth:`issue`)."""
        from models.register.identifiers import as_printed, no_serial

        if original.workbench != workbench:
            raise NotTheSameCalibration(message(QT_TR_NOOP(
                "{number} was issued on the {original} workbench: its amendment or replacement "
                "corrects that calibration and is issued on that workbench, not on {workbench} "
                "(ISO/IEC 17025 7.8.8); a calibration on another workbench is an original"),
                number=original.number, original=original.workbench, workbench=workbench))
        changes = []
        # compared as printed, never by the look-alike key, which only asks or refuses: a
        # serial that prints otherwise is a corrected one (rev63 F2: "XL-100" → "XI-100")
        if as_printed(original.item_serial) != as_printed(meta.item_serial):
            changes.append(message(QT_TR_NOOP(
                "serial number corrected from {old} (on {number}) to {new}"),
                old=original.item_serial or "—", number=original.number,
                new=meta.item_serial or "—"))
        if original.calibration_date != meta.calibration_date:
            changes.append(message(QT_TR_NOOP(
                "date of calibration corrected from {old} (on {number}) to {new}"),
                old=original.calibration_date or "—", number=original.number,
                new=meta.calibration_date or "—"))
        # an item of no serial is told from another by its description and maker, as the
        # one-calibration check tells it (rev63 F1: A's certificate amended with B's details)
        unnamed = no_serial(original.item_serial) and no_serial(meta.item_serial)
        if unnamed and not _same_item(original.item_description, original.item_manufacturer,
                                      meta):
            changes.append(message(QT_TR_NOOP(
                "item (no serial number) corrected from {old} (on {number}) to {new}"),
                old=_item_text(original.item_description, original.item_manufacturer),
                number=original.number,
                new=_item_text(meta.item_description, meta.item_manufacturer)))
        # the maker and the customer are the calibration's as the serial is: a serial is
        # unique only within its maker, and the customer is whose calibration it is (#64
        # review F5: an amendment moved LRA-0815's calibration onto another maker's item
        # and another customer's name, unasked and unsaid); compared as printed, spaces
        # collapsed. A changed description of an item with a serial is said, not asked.
        owned = []
        maker_changed = not unnamed and _printed(original.item_manufacturer) \
            != _printed(meta.item_manufacturer)
        if maker_changed:
            owned.append(message(QT_TR_NOOP(
                "manufacturer corrected from {old} (on {number}) to {new}"),
                old=_printed(original.item_manufacturer) or "—", number=original.number,
                new=_printed(meta.item_manufacturer) or "—"))
        if _printed(original.customer) != _printed(meta.customer_name):
            owned.append(message(QT_TR_NOOP(
                "customer corrected from {old} (on {number}) to {new}"),
                old=_printed(original.customer) or "—", number=original.number,
                new=_printed(meta.customer_name) or "—"))
        said = []
        if not unnamed and _printed(original.item_description) \
                != _printed(meta.item_description):
            said.append(message(QT_TR_NOOP(
                "item description changed from {old} (on {number}) to {new}"),
                old=_printed(original.item_description) or "—", number=original.number,
                new=_printed(meta.item_description) or "—"))
        if not changes and not owned:
            return tuple(said)
        if not confirmed and not changes:
            raise NotTheSameCalibration(message(QT_TR_NOOP(
                "{number}: these details change what it reports: {changes}. An amendment or "
                "replacement corrects the same calibration (ISO/IEC 17025 7.8.8): another "
                "manufacturer's item or another customer's calibration is an original; a "
                "corrected manufacturer or customer is issued only when confirmed, and is then "
                "stated on it"), number=original.number, changes=separated(owned)),
                tuple(owned))
        # said after the question about the serial, the item or the date, when asked
        also = message(QT_TR_NOOP("It also corrects: {changes}."),
                       changes=separated(owned)) if owned else ""
        refused = None
        if not confirmed and unnamed:
            refused = (message(QT_TR_NOOP(
                "{number} reports {item}, which has no serial number, calibrated {date}; these "
                "details give {new_item}, calibrated {new_date}. An amendment or replacement "
                "corrects the same calibration (ISO/IEC 17025 7.8.8): another item's or another "
                "day's calibration is an original; a corrected description, manufacturer or "
                "date of calibration is issued only when confirmed, and is then stated on it"),
                number=original.number,
                item=_item_text(original.item_description, original.item_manufacturer),
                date=original.calibration_date or "—",
                new_item=_item_text(meta.item_description, meta.item_manufacturer),
                new_date=meta.calibration_date or "—"))
        elif not confirmed:
            refused = (message(QT_TR_NOOP(
                "{number} reports serial number {serial}, calibrated {date}; these details give "
                "serial number {new_serial}, calibrated {new_date}. An amendment or replacement "
                "corrects the same calibration (ISO/IEC 17025 7.8.8): another item's or another "
                "day's calibration is an original; a corrected serial number or date of "
                "calibration is issued only when confirmed, and is then stated on it"),
                number=original.number, serial=original.item_serial or "—",
                date=original.calibration_date or "—", new_serial=meta.item_serial or "—",
                new_date=meta.calibration_date or "—"))
        # the maker is the item's as the serial is (a serial is unique only within its
        # maker, and the one-calibration check compares both): a corrected maker is a
        # corrected item too (stop 65: Zeta's "001" amended to Acme's maker made a second
        # current certificate of Acme's "001" calibrated that day)
        identity, changes = bool(changes) or maker_changed, [*changes, *owned]
        if refused is not None:
            raise NotTheSameCalibration(separated([refused, also], " "), tuple(changes))
        # the item or the date corrected: never onto another current certificate's
        others = () if not identity else tuple(
            n for n in self._same_calibration(conn, workbench, meta) if n != original.number)
        if others:
            raise NotTheSameCalibration(message(QT_TR_NOOP(
                "{numbers} already reports serial number {serial}, calibrated {date}: a "
                "correction of {number} cannot make a second certificate of that calibration; "
                "amend or replace {numbers} instead"),
                numbers=", ".join(others), serial=meta.item_serial or "—",
                date=meta.calibration_date or "—", number=original.number))
        return (*changes, *said)

    def _current(self, conn, number: str) -> CertificateRecord:
        record = self._get(conn, number)
        if record.status == "withdrawn":
            raise RegisterError(message(
                QT_TR_NOOP("{number} was withdrawn ({reason}): it cannot be amended or replaced"),
                number=number, reason=record.withdrawn_reason or "—"))
        if record.status != "issued":
            raise RegisterError(message(
                QT_TR_NOOP("{number} was superseded by {superseded_by}: amend or replace that one"),
                number=number, superseded_by=record.superseded_by))
        return record

    def withdraw(self, number: str, reason: str) -> str:
        """Withdraw (void) certificate ``number`` with ``reason``: a new chained record; the
        certificate is kept unchanged and marked withdrawn. Returns the entry's chain value."""
        reason = " ".join((reason or "").split())
        if not reason:
            raise RegisterError(message(QT_TR_NOOP(
                "a certificate is withdrawn with a reason (--reason)")))
        certificates = self._schema.CERTIFICATES
        with self._write() as conn:
            if not self.is_sqlite:
                conn.execute(self._sa.text("SELECT pg_advisory_xact_lock(:k)"),
                             {"k": _CHAIN_LOCK})
            record = self._get(conn, number)
            if record.status == "withdrawn":  # reg72 #11: it said "cannot be amended"
                raise RegisterError(message(QT_TR_NOOP(
                    "{number} was withdrawn already ({reason}): a certificate is withdrawn "
                    "once"), number=number, reason=record.withdrawn_reason or "—"))
            self._current(conn, number)
            chain = self._append_entry(conn, "withdrawal", number, {"reason": reason})
            conn.execute(certificates.update().where(certificates.c.number == number).values(
                status="withdrawn", withdrawn_reason=reason))
        return chain

    # -- results files ------------------------------------------------------------------------
    def record_results(self, number: str, data: bytes, name: str) -> str:
        """Record a results file (CSV or XLSX) written with certificate ``number`` when it was
        issued: a chained entry ("results") holding the file's SHA-256 and name, so that
        ``register verify`` finds it as it finds the PDF and the DCC. The certificate must be
        the current one (issued, not superseded or withdrawn) and have no results file yet:
        one per certificate, recorded at its issue (a corrected results file comes with the
        certificate's amendment, under the amendment's number; rev62 F7: a later call made
        any file "identical to the record"). Only the issuer records it: ``number`` must have
        been issued by :meth:`issue` of this object (stop 63: any caller could give a
        certificate issued earlier without one any file, which ``verify`` then called "the
        results file of certificate N, identical to the record"). Returns the entry's chain
        value."""
        if number not in self._results_due:
            raise RegisterError(message(QT_TR_NOOP(
                "no results file is recorded for {number}: a results file is recorded by the "
                "issue of its certificate, right after it, and {number} was not issued by "
                "this issue (a certificate without one gets one with its amendment)"),
                number=number))
        entry = {"sha256": hashlib.sha256(data).hexdigest(), "file": name}
        entries = self._schema.ENTRIES
        with self._write() as conn:
            if not self.is_sqlite:
                conn.execute(self._sa.text("SELECT pg_advisory_xact_lock(:k)"),
                             {"k": _CHAIN_LOCK})
            self._current(conn, number)
            earlier = conn.execute(self._sa.select(entries.c.recorded_at).where(
                entries.c.kind == "results", entries.c.subject == number)).first()
            if earlier is not None:
                raise RegisterError(message(QT_TR_NOOP(
                    "certificate {number} already has its results file, recorded "
                    "{recorded_at}: a certificate has one, recorded when it is issued (a "
                    "corrected one comes with its amendment)"), number=number,
                    recorded_at=earlier.recorded_at))
            chain = self._append_entry(conn, "results", number, entry)
        self._results_due.discard(number)
        return chain

    def results_records(self, number: str = "") -> builtins.list[dict]:
        """The results files recorded (every certificate's, or ``number``'s), in the chain's
        order: ``number``, ``file``, ``sha256``, ``recorded_at``, ``seq`` and ``first`` (False
        for a second one of the same certificate, which only a register written before 0.8.12
        or outside AngleBench holds)."""
        entries = self._schema.ENTRIES
        query = self._sa.select(entries.c.seq, entries.c.subject, entries.c.body_json,
                                entries.c.recorded_at).where(entries.c.kind == "results")
        with self._read() as conn:
            rows = conn.execute(query.order_by(entries.c.seq)).all()
        out, seen = [], set()
        for row in rows:
            body = json.loads(row.body_json or "{}")
            out.append({"number": row.subject, "file": body.get("file", ""),
                        "sha256": body.get("sha256", ""), "recorded_at": row.recorded_at,
                        "seq": row.seq, "first": row.subject not in seen})
            seen.add(row.subject)
        return [r for r in out if not number or r["number"] == number]

    def verify_results(self, data: bytes) -> builtins.list[tuple[CertificateRecord, str]]:
        """Every certificate a results file byte for byte this one (by SHA-256) was recorded
        with (:meth:`record_results`), with the time it was recorded."""
        digest = hashlib.sha256(data).hexdigest()
        found = [r for r in self.results_records() if r["sha256"] == digest]
        with self._read() as conn:
            return [(self._get(conn, r["number"]), r["recorded_at"]) for r in found]

    def issued_file(self, digest: str) -> builtins.list[tuple[str, str]]:
        """Which certificates issued a file of SHA-256 ``digest``, and as what ("pdf", "dcc"
        or "results"): an issued file is never overwritten by a later output (rev62 F8)."""
        certificates = self._schema.CERTIFICATES
        with self._read() as conn:
            found = [(number, "pdf") for number in conn.execute(self._sa.select(
                certificates.c.number).where(certificates.c.pdf_sha256 == digest)).scalars()]
            found += [(number, "dcc") for number in conn.execute(self._sa.select(
                certificates.c.number).where(certificates.c.dcc_sha256 == digest)).scalars()]
        return found + [(r["number"], "results") for r in self.results_records()
                        if r["sha256"] == digest]

    # -- approval ---------------------------------------------------------------------------
    def signatories(self) -> tuple[list[str], bool]:
        """The lab's authorised signatories (empty: none configured, any named approver is
        accepted) and whether the approver must differ from the operator: the last
        ``signatories`` entry of the chain."""
        entries = self._schema.ENTRIES
        with self._read() as conn:
            body = conn.execute(self._sa.select(entries.c.body_json).where(
                entries.c.kind == "signatories").order_by(entries.c.seq.desc()).limit(1)
            ).scalar_one_or_none()
        data = json.loads(body) if body else {}
        return list(data.get("names", [])), bool(data.get("distinct", False))

    def set_signatories(self, names: list[str], distinct: bool) -> None:
        """Configure the authorised signatories (an empty list: none, any named approver is
        accepted, as before) and whether approver and operator must differ: a chained entry."""
        cleaned = sorted({" ".join(n.split()) for n in names if n.strip()})
        with self._write() as conn:
            if not self.is_sqlite:
                conn.execute(self._sa.text("SELECT pg_advisory_xact_lock(:k)"),
                             {"k": _CHAIN_LOCK})
            self._append_entry(conn, "signatories", "lab",
                               {"names": cleaned, "distinct": bool(distinct)})

    def _check_approval(self, meta: CertificateMetadata) -> None:
        from models.register.identifiers import same_name

        names, distinct = self.signatories()
        approver = " ".join(meta.approver.split())
        if names and approver.casefold() not in {n.casefold() for n in names}:
            raise RegisterError(message(QT_TR_NOOP(
                "\"{approver}\" is not one of the lab's authorised signatories ({names}): "
                "the certificate is approved by one of them"),
                approver=approver, names=", ".join(names)))
        # by the look-alike keys, spaces collapsed (#64 review F10: an operator "Dr. Lі",
        # a Cyrillic "і", printed "Dr. Li" twice and passed as another person)
        if distinct and same_name(approver, meta.operator):
            raise RegisterError(message(QT_TR_NOOP(
                "the lab requires the approver to differ from the operator: {name} cannot "
                "approve a calibration they made"), name=approver))

    # -- reading --------------------------------------------------------------------------
    def _get(self, conn, number: str) -> CertificateRecord:
        certificates = self._schema.CERTIFICATES
        row = conn.execute(self._sa.select(*(certificates.c[c] for c in self._record_columns)).where(
            certificates.c.number == number)).first()
        if row is None:
            raise _not_in_register(number)
        return CertificateRecord(**row._asdict())

    def next_amendment_number(self, number: str) -> str:
        """The number an amendment of certificate ``number`` issued now would get (as
        :meth:`issue` allocates it: ``<original>-A<n>``), for the file name a window suggests
        (day review 65 F6: the original's name was suggested, and the amendment issued into
        it). RegisterError when ``number`` is not in the register."""
        with self._read() as conn:
            original = self._get(conn, number)
            n = _amendment_count(conn, self, original) + 1
            while self._taken(conn, f"{_root(original)}-A{n}"):
                n += 1
            return f"{_root(original)}-A{n}"

    def get(self, number: str) -> CertificateRecord:
        from models.register.identifiers import IdentifierError, normalise_identifier

        with self._read() as conn:
            try:
                return self._get(conn, number)
            except RegisterError:
                try:
                    alike = normalise_identifier(number)
                except IdentifierError:
                    raise _not_in_register(number) from None
                return self._get(conn, alike)

    def chain_before(self, number: str) -> str:
        """The chain's head before certificate ``number`` (what its PDF prints)."""
        record = self.get(number)
        sa, schema = self._sa, self._schema
        with self._read() as conn:
            if record.seq is None:
                row = conn.execute(sa.select(schema.CERTIFICATES.c.chain_sha256).where(
                    schema.CERTIFICATES.c.id < sa.select(schema.CERTIFICATES.c.id).where(
                        schema.CERTIFICATES.c.number == number).scalar_subquery())
                    .order_by(schema.CERTIFICATES.c.id.desc()).limit(1)).scalar_one_or_none()
                return row or GENESIS
            for table in (schema.CERTIFICATES, schema.ENTRIES):
                value = conn.execute(sa.select(table.c.chain_sha256).where(
                    table.c.seq == record.seq - 1)).scalar_one_or_none()
                if value:
                    return value
        return GENESIS

    def pdf(self, number: str, checked: bool = True) -> bytes:
        """Return the PDF as issued. With ``checked``, raise RegisterError when it no longer
        matches the SHA-256 recorded at issue, so that a PDF changed in the database is never
        handed out as the issued one."""
        certificates = self._schema.CERTIFICATES
        with self._read() as conn:
            row = conn.execute(self._sa.select(certificates.c.pdf, certificates.c.pdf_sha256)
                               .where(certificates.c.number == number)).first()
        if row is None:
            raise _not_in_register(number)
        data = bytes(row.pdf)
        if checked and hashlib.sha256(data).hexdigest() != row.pdf_sha256:
            raise RegisterError(message(QT_TR_NOOP(
                "the stored PDF of {number} no longer matches the SHA-256 recorded when it was "
                "issued: it was changed in the database; it is not exported"), number=number))
        return data

    def dcc(self, number: str, checked: bool = True) -> bytes:
        """The digital calibration certificate (DCC XML) issued with certificate ``number``.
        RegisterError when it was issued without one; with ``checked``, also when the stored
        DCC no longer matches the SHA-256 recorded at issue (it is never handed out as the
        issued one)."""
        certificates = self._schema.CERTIFICATES
        with self._read() as conn:
            row = conn.execute(self._sa.select(certificates.c.dcc, certificates.c.dcc_sha256)
                               .where(certificates.c.number == number)).first()
        if row is None:
            raise _not_in_register(number)
        if row.dcc is None and row.dcc_sha256 is None:
            raise RegisterError(message(QT_TR_NOOP(
                "certificate {number} was issued without a digital calibration certificate "
                "(DCC)"), number=number))
        data = b"" if row.dcc is None else bytes(row.dcc)
        if checked and (row.dcc is None or hashlib.sha256(data).hexdigest() != row.dcc_sha256):
            raise RegisterError(message(QT_TR_NOOP(
                "the stored DCC of {number} no longer matches the SHA-256 recorded when it was "
                "issued: it was changed or removed in the database; it is not exported"),
                number=number))
        return data

    def audit(self, pdfs: bool = False) -> list:
        """List what was changed in the database after issue, one message per finding (an
        empty list when nothing was found): the hash chain recomputed over every record
        and entry in their order, their places counted against the state row, the counters
        against the records numbered from them, the intervals and each record's status
        against the entries and records that set them; with ``pdfs`` each stored PDF against
        its SHA-256."""
        from models.register.chain import link_entry
        from models.register.wording import entry_words

        sa, schema = self._sa, self._schema
        certificates, entries = schema.CERTIFICATES, schema.ENTRIES
        columns = ("id", *CHAINED, *CHAINED_V2, *CHAINED_V3, *CHAINED_V4, "chain_format", "status",
                   "superseded_by", "withdrawn_reason", "chain_sha256", "signature",
                   *(("readings_key",) if self._stored_keys else ()),
                   *(schema.READINGS_IDENTITY_COLUMNS if self._stored_identities else ()))
        problems: list = []
        with self._read() as conn:
            rows = conn.execute(sa.select(*(certificates.c[c] for c in columns),
                                          certificates.c.dcc.is_not(None).label("has_dcc"))
                                .order_by(certificates.c.seq, certificates.c.id)).all()
            notes = conn.execute(sa.select(entries).order_by(entries.c.seq)).all()
            state = dict(conn.execute(sa.select(schema.STATE.c.name, schema.STATE.c.value)).all())
            counters = dict(conn.execute(sa.select(schema.COUNTERS.c.name,
                                                   schema.COUNTERS.c.last_value)).all())
            intervals = {(row.serial, row.manufacturer): row.interval_days
                         for row in self._intervals(conn)}
            links = sorted([(r.seq, 0, r) for r in rows if r.seq is not None]
                           + [(e.seq, 1, e) for e in notes], key=lambda t: (t[0], t[1]))
            for row in rows:
                if row.seq is None:
                    problems.append(message(QT_TR_NOOP(
                        "record {number}: it has no place in the hash chain (inserted after "
                        "issue)"), number=row.number))
            previous, expected = GENESIS, 1
            for seq, is_entry, item in links:
                name = entry_words(item.kind, item.subject) if is_entry else item.number
                if seq != expected:
                    problems.append(message(QT_TR_NOOP(
                        "record {number}: it is at place {seq} of the chain, where {expected} "
                        "was expected (records deleted or inserted before it)"),
                        number=name, seq=seq, expected=expected))
                expected = seq + 1
                fields = item._asdict()
                value = link_entry(previous, fields) if is_entry else link(previous, fields)
                if item.chain_sha256 != value:
                    problems.append(message(QT_TR_NOOP(
                        "record {number}: the hash chain is broken here (this record, or one "
                        "before it, was changed, inserted or deleted after issue)"),
                        number=name))
                previous = item.chain_sha256 or value  # report each break once
                if pdfs and not is_entry:
                    data = conn.execute(sa.select(certificates.c.pdf).where(
                        certificates.c.id == item.id)).scalar_one()
                    if hashlib.sha256(bytes(data)).hexdigest() != item.pdf_sha256:
                        problems.append(message(QT_TR_NOOP(
                            "record {number}: the stored PDF does not match the SHA-256 "
                            "recorded at issue"), number=item.number))
                    elif (item.chain_format or 1) >= 5:  # its PDF carries its content digest
                        dcc = conn.execute(sa.select(certificates.c.dcc).where(
                            certificates.c.id == item.id)).scalar_one() if item.has_dcc else None
                        problems += _content_problems(fields, bytes(data), dcc)
                    problems += _readings_key_problems(fields)
                if not is_entry:
                    problems += _dcc_problems(conn, certificates, item, pdfs)
                    if item.document_kind is not None and (item.chain_format or 1) < 4:
                        problems.append(message(QT_TR_NOOP(
                            "record {number}: its document kind ({kind}) was set after issue: "
                            "it was issued before the register recorded what a document is, and "
                            "its chain does not cover it"), number=item.number,
                            kind=kind_words(item.document_kind)))
        self.key_problem = self._key_problem(state, links, counters)
        if self.key_problem is None:  # a wrong key calls nothing forged (reg73 #7)
            problems += self._fingerprint_problems(state)
            problems += self._signature_problems(links)
            problems += self._state_signature_problems(rows, state, counters)
        count = len(links)
        if state.get("records") != str(count) or state.get("head") != previous:
            problems.append(message(QT_TR_NOOP(
                "the register recorded {recorded} record(s) ending at chain head {head}, but "
                "holds {count} ending at {actual}: records were deleted (the tail truncated) "
                "or added after issue"), recorded=state.get("records", "?"),
                head=(state.get("head") or "?")[:16], count=count, actual=previous[:16]))
        problems += self._high_water_problems(links, counters, notes)
        problems += _cross_checks(rows, notes, counters, intervals)
        return problems

    def issue_refusal(self, stored_files: bool = True) -> Message | None:
        """Why the register, as it stands, issues nothing whatever the document (None when
        it would issue): a wrong key (reg73 #7), or its records, state or (``stored_files``)
        stored PDFs and DCCs found changed after issue. :meth:`issue` refuses with it; the
        window asks it before any question about the document (day74 #7 b: "Issue it as a
        test report?", then the refusal) without ``stored_files``: what opening found, not
        every stored file read and hashed on the window's thread a second time — the issue
        itself still reads them."""
        if self.key_problem is not None:  # a wrong key issues nothing (reg73 #7)
            return self.key_problem
        problems = self.problems or (self._stored_file_problems() if stored_files else [])
        if problems:
            return message(QT_TR_NOOP(
                "the register's records were changed after issue ({problem}): nothing is "
                "recorded into a broken chain; see 'anglebench register verify'"),
                problem=problems[0])
        return None

    def _stored_file_problems(self) -> list:
        """Each stored PDF and DCC against the SHA-256 recorded at issue (in the chain): what
        :meth:`audit` with ``pdfs`` finds of the files themselves, read one record at a time
        (a server-side cursor on PostgreSQL), for :meth:`issue` to refuse as it refuses every
        other change made after issue."""
        sa, certificates = self._sa, self._schema.CERTIFICATES
        c = certificates.c
        problems: list = []
        with self._read() as conn:
            rows = conn.execution_options(stream_results=True, yield_per=20).execute(
                sa.select(c.number, c.pdf, c.pdf_sha256, c.dcc, c.dcc_sha256)
                .order_by(c.seq, c.id))
            for row in rows:
                if hashlib.sha256(bytes(row.pdf)).hexdigest() != row.pdf_sha256:
                    problems.append(message(QT_TR_NOOP(
                        "record {number}: the stored PDF does not match the SHA-256 "
                        "recorded at issue"), number=row.number))
                if row.dcc is not None and row.dcc_sha256 is not None and hashlib.sha256(
                        bytes(row.dcc)).hexdigest() != row.dcc_sha256:
                    problems.append(message(QT_TR_NOOP(
                        "record {number}: the stored DCC does not match the SHA-256 recorded "
                        "at issue"), number=row.number))
        return problems

    def _state_signature_problems(self, rows, state: dict, counters: dict) -> list:
        """With the lab's key: the state (count, head, counters) must carry the key's
        signature once any certificate of chain format 5 (issued by AngleBench 0.8.21 or
        later, which signs the state) is signed, or once a state signature was written. A
        register all of whose signed records are older is read as it was (its state is
        signed with its next record)."""
        from models.register.signing import STATE_SIGNATURE, signature_ok, state_text

        if not self._key:
            return []
        signature = state.get(STATE_SIGNATURE)
        expected = signature is not None or any(
            (row.chain_format or 1) >= 5 and row.signature for row in rows)
        if not expected:
            return []
        text = state_text(state.get("records", "?"), state.get("head", ""), counters)
        if signature_ok(self._key, text, signature):
            return []
        return [message(QT_TR_NOOP(
            "the register's state (its record count {records}, head {head} and number "
            "counters) does not carry the laboratory key's signature: the last record(s) "
            "were deleted with the state set back, or a counter was set back, outside "
            "AngleBench; restore the register from a backup"),
            records=state.get("records", "?"), head=(state.get("head") or "?")[:16])]

    def _key_problem(self, state: dict, links: list, counters: dict) -> Message | None:
        """With a key: the key is not the one the register was signed with — its
        fingerprint is not the one the register holds (written with its first signed record
        since 0.8.22), or, in a register signed before, not one of its signed records'
        signatures is this key's — and nothing the key signed proves it the register's
        (:meth:`_signed_with_this_key`). Then no signature is called forged and nothing is
        written (reg73 #7: a key file with a newline added read as every record forged, with
        the advice to restore a backup). The fingerprint row is not trusted against the
        key's own signatures: a row changed outside AngleBench made the right key "not the
        register's", which switched every signature check off and hid a record forged
        (:meth:`_fingerprint_problems` reports the row)."""
        from models.register.signing import FINGERPRINT, KEY_ENV_VAR, fingerprint, key_slip

        if not self._key:
            return None
        stored = state.get(FINGERPRINT)
        mine = fingerprint(self._key)
        if stored is not None and hmac.compare_digest(stored, mine):
            return None
        if stored is None and not any(item.signature is not None for _s, _e, item in links):
            return None  # nothing signed yet: this key signs from now on
        if self._signed_with_this_key(state, links, counters):
            return None
        slip = stored is not None and key_slip(self._key, stored)
        return message(QT_TR_NOOP(
            "the key named by {setting} is not the key this register was signed with (its "
            "fingerprint {mine}…; the register's: {theirs}){slip}: no signature is checked "
            "against it, no record is called changed for it, and nothing is written with it; "
            "name the laboratory's key file and try again"), setting=KEY_ENV_VAR,
            mine=mine[:16], theirs=f"{stored[:16]}…" if stored else message(QT_TR_NOOP(
                "not recorded, and none of its signed records is this key's")),
            slip=message(QT_TR_NOOP(
                " — it is the register's key with a line end added or removed at its end (the "
                "file was edited or pasted as text): restore the key file as it was"))
            if slip else "")

    def _signed_with_this_key(self, state: dict, links: list, counters: dict) -> bool:
        """Something in or beside the register carries this key's signature: the state's
        signature over the state as it stands, a record's or entry's signature, or the
        register's high-water mark. Only the key's holder can make one (HMAC-SHA256), so
        the key is the register's whatever its fingerprint row says."""
        from models.register.signing import STATE_SIGNATURE, signature_ok, state_text

        assert self._key is not None
        text = state_text(state.get("records", "?"), state.get("head", ""), counters)
        return (signature_ok(self._key, text, state.get(STATE_SIGNATURE))
                or any(item.signature is not None
                       and signature_ok(self._key, item.chain_sha256 or "", item.signature)
                       for _seq, _is_entry, item in links)
                or bool(self.high_water_mark()))

    def _fingerprint_problems(self, state: dict) -> list:
        """With the register's key (:meth:`_key_problem` found none): the fingerprint row, if
        there is one, must be this key's; one that is not was changed outside AngleBench —
        it would have made this key read as another (every signature then unchecked)."""
        from models.register.signing import FINGERPRINT, fingerprint

        stored = state.get(FINGERPRINT)
        if not self._key or stored is None or hmac.compare_digest(stored, fingerprint(self._key)):
            return []
        return [message(QT_TR_NOOP(
            "the register's key fingerprint ({theirs}…) is not the fingerprint of the key its "
            "records are signed with ({mine}…): it was changed outside AngleBench, which "
            "would have called this key another and left every signature unchecked"),
            theirs=stored[:16], mine=fingerprint(self._key)[:16])]

    @property
    def signed(self) -> bool:
        """This process signs with the lab's key."""
        return self._key is not None

    def signed_unchecked(self) -> int:
        """Without the lab's key: how many records and entries carry a signature, which
        this process cannot check (0 with the key)."""
        if self._key:
            return 0
        with self._read() as conn:
            return self._signed_records(conn)

    def _signature_problems(self, links: list) -> list:
        """With the lab's key: every signature must be the key's; from the first signed
        record on every record must be signed, the last one always (a record forged and
        appended after the last genuine one carries no valid signature)."""
        from models.register.signing import signature_ok
        from models.register.wording import entry_words

        if not self._key or not links:
            return []
        problems: list = []
        signed_since = None
        for _seq, is_entry, item in links:
            name = entry_words(item.kind, item.subject) if is_entry else item.number
            if item.signature is not None:
                if not signature_ok(self._key, item.chain_sha256 or "", item.signature):
                    problems.append(message(QT_TR_NOOP(
                        "record {number}: its signature is not the laboratory key's: it was "
                        "changed, or forged, outside AngleBench"), number=name))
                signed_since = signed_since or name
            elif signed_since is not None or item is links[-1][2]:
                problems.append(message(QT_TR_NOOP(
                    "record {number}: not signed with the laboratory's key (the last record "
                    "and every one since the first signed are): added outside AngleBench, or "
                    "issued without the key"), number=name))
        return problems

    def chain_head(self) -> str:
        """The chain after the last record (GENESIS for an empty register): noted outside the
        database, it anchors every record issued before."""
        with self._read() as conn:
            return self._tail(conn)[1]

    def chain_records(self) -> int:
        """How many records the hash chain holds: the certificates and every chained entry
        (results files, withdrawals, intervals, …)."""
        with self._read() as conn:
            return self._tail(conn)[0]

    def find_head(self, value: str) -> tuple[int, str] | None:
        """Where the chain passed through ``value`` (a head noted from an earlier day or
        printed on a certificate; 12 or more leading hex digits do): its place and the
        full value; None when no record's chain is that (the history up to it rewritten, or
        another register's). RegisterError when the digits fit several."""
        value = value.strip().lower()
        if not re.fullmatch(r"[0-9a-f]{12,64}", value):
            raise RegisterError(message(QT_TR_NOOP(
                "head '{value}': a chain head is 12 to 64 hexadecimal digits"), value=value))
        if GENESIS.startswith(value):
            return 0, GENESIS
        sa, schema = self._sa, self._schema
        found = []
        with self._read() as conn:
            for table in (schema.CERTIFICATES, schema.ENTRIES):
                found += conn.execute(sa.select(table.c.seq, table.c.chain_sha256).where(
                    table.c.chain_sha256.like(f"{value}%"))).all()
        if len(found) > 1:
            raise RegisterError(message(QT_TR_NOOP(
                "head '{value}' fits {n} records: give more of its digits"), value=value,
                n=len(found)))
        return (found[0].seq or 0, found[0].chain_sha256) if found else None

    def printed_head(self, pdf: bytes) -> PrintedHead | None:
        """Where a certificate's PDF belongs in the chain: the head it prints is the chain
        before it, so its own record — its number and its SHA-256 — is the next one. None
        when it prints no head (a draft, a specimen, issued before heads were printed)."""
        from models.register.chain import head_in_pdf, number_in_pdf

        head = head_in_pdf(pdf)
        if not head:
            return None
        found = self.find_head(head)
        check = PrintedHead(head=head, sha256=hashlib.sha256(pdf).hexdigest(),
                            number=number_in_pdf(pdf), place=found[0] if found else None)
        if found is None:
            return check
        with self._read() as conn:
            return self._at_place(conn, check)

    def _at_place(self, conn, check: PrintedHead) -> PrintedHead:
        """``check`` with what the register holds right after its head."""
        from models.register.wording import entry_words

        sa, certificates, entries = self._sa, self._schema.CERTIFICATES, self._schema.ENTRIES
        assert check.place is not None
        place = check.place + 1
        row = conn.execute(sa.select(*(certificates.c[c] for c in self._record_columns)).where(
            certificates.c.seq == place)).first()
        record = CertificateRecord(**row._asdict()) if row is not None else None
        entry = conn.execute(sa.select(entries.c.kind, entries.c.subject, entries.c.body_json)
                             .where(entries.c.seq == place)).first()
        after, recorded = "", False
        if entry is not None:
            body = json.loads(entry.body_json or "{}")
            recorded = entry.kind == "missing" and body.get("pdf_sha256") == check.sha256
            after = entry_words(entry.kind, entry.subject)
        elsewhere = ", ".join(conn.execute(sa.select(certificates.c.number).where(
            certificates.c.pdf_sha256 == check.sha256, sa.or_(
                certificates.c.seq.is_(None), certificates.c.seq != place))).scalars())
        return dataclasses.replace(check, record=record, after=after,
                                   recorded_missing=recorded, elsewhere=elsewhere)

    def record_content_digest(self, record: CertificateRecord) -> str:
        """The digest of ``record``'s content as it is now, in the form its PDF carries
        (models/register/chain.content_form; form 2 with its stored DCC)."""
        from models.register.chain import content_digest, content_form

        dcc = None
        if content_form(dataclasses.asdict(record)) >= 2 and record.dcc_sha256 is not None:
            certificates = self._schema.CERTIFICATES
            with self._read() as conn:
                stored = conn.execute(self._sa.select(certificates.c.dcc).where(
                    certificates.c.number == record.number)).scalar()
            dcc = None if stored is None else bytes(stored)
        return content_digest(dataclasses.asdict(record), dcc)

    def issued_here(self, pdf: bytes) -> str:
        """Whether a certificate's PDF proves that this register issued it: "proven" (it
        carries the proof made with the lab's key over its number, printed head and record
        digest: models/register/signing.proof), "refuted" (it carries a proof that is not
        this key's), "unknown" (no key, or it carries no proof: issued before 0.8.22 or
        without the key)."""
        from models.register.chain import content_in_pdf, head_in_pdf, number_in_pdf, proof_in_pdf
        from models.register.signing import proof_ok

        carried = proof_in_pdf(pdf)
        if not self._key or not carried or self.key_problem is not None:
            return "unknown"
        return "proven" if proof_ok(self._key, number_in_pdf(pdf), head_in_pdf(pdf),
                                    content_in_pdf(pdf), carried) else "refuted"

    def record_missing(self, check: PrintedHead) -> str:
        """Record, as a chained entry, that the certificate ``check`` was presented (its PDF
        printing the head before it) while the register no longer held its record
        (:attr:`PrintedHead.missing`): from then on the audit reports it, so nothing is issued
        — its number not again — until a person records the loss (:meth:`acknowledge_loss`;
        reg73 #5: a restore could not end it) (rev64 F8: a
        tail deleted with its state row set back agreed with itself). Checked again under the
        write lock; returns the entry's chain value, or "" when it is not missing."""
        with self._write() as conn:
            if not self.is_sqlite:
                conn.execute(self._sa.text("SELECT pg_advisory_xact_lock(:k)"),
                             {"k": _CHAIN_LOCK})
            if check.place is None or not self._at_place(conn, check).missing:
                return ""
            return self._append_entry(conn, "missing", check.number or check.sha256[:16], {
                "pdf_sha256": check.sha256, "place": check.place + 1,
                "head_before": check.head, "number": check.number})

    def record_reissued(self, check: PrintedHead) -> str:
        """Record, as a chained entry ("number_reissued"), that the certificate ``check`` was
        presented while the record at its place is another certificate of its number: the
        number was issued twice (reg73 #2: said and forgotten, and issuing went on). From
        then on the audit reports it and nothing is issued until a person acknowledges the
        loss (:meth:`acknowledge_loss`). Checked again under the write lock; recorded once
        per PDF; returns the entry's chain value, or "" when nothing was recorded."""
        with self._write() as conn:
            if not self.is_sqlite:
                conn.execute(self._sa.text("SELECT pg_advisory_xact_lock(:k)"),
                             {"k": _CHAIN_LOCK})
            if check.place is None:
                return ""
            now = self._at_place(conn, check)
            if now.record is None or now.record.number != check.number or now.there:
                return ""
            entries = self._schema.ENTRIES
            for body_json in conn.execute(self._sa.select(entries.c.body_json).where(
                    entries.c.kind == "number_reissued")).scalars():
                if json.loads(body_json or "{}").get("pdf_sha256") == check.sha256:
                    return ""
            return self._append_entry(conn, "number_reissued", check.number, {
                "pdf_sha256": check.sha256, "place": check.place + 1,
                "head_before": check.head, "number": check.number,
                "other_pdf_sha256": now.record.pdf_sha256})

    def acknowledge_loss(self, by: str, reason: str, last_number: str = "",
                         scheme: str = "") -> dict:
        """A person records a loss (reg73 #2, #5): the register restored from an older copy
        (or an older state copied back), its records since lost. A chained entry
        (``loss_acknowledged``: who, why, the last number known issued) after which the
        findings it answers — certificates found missing, numbers found issued twice, the
        register behind its high-water mark — no longer stop issuing. Every counter moves
        past the numbers known issued (``last_number``; those of the findings; the mark's
        counters), so no number is issued again; a later verify of a lost certificate says
        it was lost and acknowledged (:meth:`lost_acknowledged`). Any other finding (a
        broken chain, a record rewritten) still refuses. ``scheme``: the number scheme of
        ``last_number`` when the register has no counter of it (the copy restored predates
        its first number). Returns the entry's body."""
        by, reason = " ".join((by or "").split()), " ".join((reason or "").split())
        if not by or not reason:
            raise RegisterError(message(QT_TR_NOOP(
                "a loss is acknowledged by a named person with the reason (--by, --reason)")))
        found = self.audit(pdfs=True)
        others = [p for p in found if getattr(p, "template", "") not in LOSS_FINDINGS]
        if others:
            raise RegisterError(message(QT_TR_NOOP(
                "the register's records were changed after issue ({problem}): a loss is "
                "acknowledged in a register whose own records are intact; see 'anglebench "
                "register verify'"), problem=others[0]))
        mark = self.high_water_mark()
        if not last_number.strip() and not mark:
            # no signed mark tells how far the numbers went: the person must (a restore
            # acknowledged without it issued the lost numbers again)
            raise RegisterError(message(QT_TR_NOOP(
                "give the last certificate number known issued (--last-number: from the lab's "
                "log, the customers' copies): without the laboratory's key and its high-water "
                "mark the register cannot tell how far its numbers went before the loss")))
        counters_t, entries = self._schema.COUNTERS, self._schema.ENTRIES
        sa = self._sa
        with self._write() as conn:
            if not self.is_sqlite:
                conn.execute(sa.text("SELECT pg_advisory_xact_lock(:k)"), {"k": _CHAIN_LOCK})
            counters = dict(conn.execute(sa.select(counters_t.c.name,
                                                   counters_t.c.last_value)).all())
            named = [json.loads(b or "{}").get("number") or "" for b in conn.execute(
                sa.select(entries.c.body_json).where(entries.c.kind.in_(
                    ("missing", "number_reissued")))).scalars()]
            wanted: dict[str, int] = {}
            for name, value in dict((mark or {}).get("counters") or {}).items():
                wanted[name] = max(wanted.get(name, 0), int(value))
            for number in [*named, last_number.strip()]:
                if not number:
                    continue
                found_counter = _counter_of(number, [*counters, *wanted])
                if found_counter is None and scheme and number == last_number.strip():
                    found_counter = _counter_of(number, [_counter_name(
                        scheme, self.clock().astimezone(self.timezone).date())])
                if found_counter is None:
                    if number == last_number.strip():
                        raise RegisterError(message(QT_TR_NOOP(
                            "{number} is a number of none of the register's counters ({names}): "
                            "give the last number known issued as the register numbered it, "
                            "with its number scheme (--scheme) when the register has no "
                            "counter of it yet"), number=number,
                            names=", ".join(sorted(counters)) or "—"))
                    continue
                name, value = found_counter
                wanted[name] = max(wanted.get(name, 0), value)
            moved = {name: [counters.get(name, 0), value] for name, value in sorted(
                wanted.items()) if value > counters.get(name, 0)}
            for name, (_before, after) in moved.items():
                if name in counters:
                    conn.execute(counters_t.update().where(counters_t.c.name == name).values(
                        last_value=after))
                else:
                    conn.execute(counters_t.insert().values(name=name, last_value=after))
            self.problems = []  # answered by this entry (the others refused above)
            records, head = self._state(conn)
            body = {"by": by, "reason": reason, "last_issued": last_number.strip(),
                    "counters": moved, "records_held": records, "head_held": head,
                    "answered": [str(p) for p in found]}
            self._append_entry(conn, LOSS_ACKNOWLEDGED, last_number.strip() or "—", body)
        self.problems = self.audit()
        return body

    def lost_acknowledged(self, number: str) -> dict | None:
        """The acknowledged loss (:meth:`acknowledge_loss`) that covers certificate
        ``number``: a number between a counter's value before and after it moved, or one a
        finding it answered named; its body with the date it was recorded; None when none
        does."""
        if not number:
            return None
        entries = self._schema.ENTRIES
        with self._read() as conn:
            rows = conn.execute(self._sa.select(entries.c.seq, entries.c.kind,
                                                entries.c.body_json, entries.c.recorded_at)
                                .where(entries.c.kind.in_((LOSS_ACKNOWLEDGED, "missing",
                                                           "number_reissued")))
                                .order_by(entries.c.seq)).all()
        named: set[str] = set()
        for row in rows:
            body = json.loads(row.body_json or "{}")
            if row.kind != LOSS_ACKNOWLEDGED:
                named.add(body.get("number") or "")
                continue
            counters = dict(body.get("counters") or {})
            found = _counter_of(number, list(counters))
            if number in named or number == body.get("last_issued") or (
                    found is not None and counters[found[0]][0] < found[1]
                    <= counters[found[0]][1]):
                return {**body, "recorded_at": row.recorded_at}
            named.clear()
        return None

    def recoveries_recorded(self) -> list[dict]:
        """The losses acknowledged and the clock corrections recorded, oldest first: each
        its ``kind`` (:data:`LOSS_ACKNOWLEDGED` or "clock_correction"), ``seq``,
        ``recorded_at``, ``subject`` and ``body`` (day74 #7 d: the register window lists
        them among the certificates, so the gap a loss leaves is seen explained)."""
        entries = self._schema.ENTRIES
        with self._read() as conn:
            rows = conn.execute(self._sa.select(
                entries.c.seq, entries.c.kind, entries.c.subject, entries.c.body_json,
                entries.c.recorded_at).where(entries.c.kind.in_(
                    (LOSS_ACKNOWLEDGED, "clock_correction"))).order_by(entries.c.seq)).all()
        return [{"kind": row.kind, "seq": row.seq, "recorded_at": row.recorded_at,
                 "subject": row.subject, "body": json.loads(row.body_json or "{}")}
                for row in rows]

    def correct_clock(self, by: str, reason: str, confirmed_date: dt.date | None) -> dict:
        """A person records that the register's last record was dated by a clock set ahead
        (reg73 #6): a chained ``clock_correction`` entry timed by this (right) clock, with
        today's date confirmed; issues on a right clock are then compared with it. The
        record dated ahead stays as issued. Returns the entry's body."""
        from models.register.clock_rules import correction_refusal, last_chained

        by, reason = " ".join((by or "").split()), " ".join((reason or "").split())
        if not by or not reason:
            raise RegisterError(message(QT_TR_NOOP(
                "a clock correction is recorded by a named person with the reason (--by, "
                "--reason)")))
        with self._write() as conn:
            if not self.is_sqlite:
                conn.execute(self._sa.text("SELECT pg_advisory_xact_lock(:k)"),
                             {"k": _CHAIN_LOCK})
            now = self.clock().astimezone(dt.timezone.utc).replace(microsecond=0)
            today = now.astimezone(self.timezone).date()
            last = last_chained(conn, self._sa, self._schema)
            refused = correction_refusal(last, now, today, confirmed_date)
            if refused is not None:
                raise RegisterError(refused)
            assert last is not None
            body = {"by": by, "reason": reason, "ahead": last.recorded,
                    "ahead_at": last.at.isoformat(), "ahead_workstation": last.workstation,
                    "ahead_os_user": last.os_user, "confirmed_date": today.isoformat()}
            self._append_entry(conn, "clock_correction", last.recorded, body)
        return body

    def list(self, search: str = "", limit: int = 10_000) -> list[CertificateRecord]:
        """Newest first; ``search`` matches the number, the serial or the customer (any case),
        as typed or as it prints: a customer "Аcme Optics" with a Cyrillic "А", or a serial
        LRA-0980 searched as "LRA-098O", is found (hostile78 S1: the register takes serials
        that print alike as one item, its search did not, and a look-alike letter hid a
        customer's certificates from it)."""
        from models.register.identifiers import printed_search_keys

        sa, certificates = self._sa, self._schema.CERTIFICATES
        query = sa.select(*(certificates.c[c] for c in self._record_columns))
        query = query.order_by(certificates.c.id.desc())
        wanted = search.strip()
        if not wanted:
            with self._read() as conn:
                return [CertificateRecord(**row._asdict())
                        for row in conn.execute(query.limit(limit))]
        typed = wanted.lower()
        keys = printed_search_keys(wanted)
        out = []
        with self._read() as conn:
            for row in conn.execute(query):
                fields = [row.number or "", row.item_serial or "", row.customer or ""]
                if any(typed in f.lower() for f in fields) or any(
                        key in field_key for f in fields
                        for field_key in printed_search_keys(f) for key in keys):
                    out.append(CertificateRecord(**row._asdict()))
                    if len(out) >= limit:
                        break
        return out

    # (``builtins.list``: in this class ``list`` is the method above)
    def verify_all(self, pdf: bytes) -> builtins.list[CertificateRecord]:
        """Every record whose PDF is byte for byte this one (by SHA-256): one for a genuine
        PDF; more than one when a record was copied into the register."""
        certificates = self._schema.CERTIFICATES
        digest = hashlib.sha256(pdf).hexdigest()
        with self._read() as conn:
            numbers = conn.execute(self._sa.select(certificates.c.number).where(
                certificates.c.pdf_sha256 == digest).order_by(certificates.c.id)).scalars().all()
            return [self._get(conn, number) for number in numbers]

    def verify_dcc(self, dcc: bytes) -> builtins.list[CertificateRecord]:
        """Every record whose digital calibration certificate is byte for byte this one (by
        SHA-256)."""
        certificates = self._schema.CERTIFICATES
        digest = hashlib.sha256(dcc).hexdigest()
        with self._read() as conn:
            numbers = conn.execute(self._sa.select(certificates.c.number).where(
                certificates.c.dcc_sha256 == digest).order_by(certificates.c.id)).scalars().all()
            return [self._get(conn, number) for number in numbers]

    def verify(self, pdf: bytes) -> CertificateRecord | None:
        """The record whose PDF is byte for byte this one (by SHA-256), or None; the first
        when several are (see :meth:`verify_all`)."""
        found = self.verify_all(pdf)
        return found[0] if found else None

    def history(self, serial: str, manufacturer: str = "") -> builtins.list[CertificateRecord]:
        """Every certificate of an instrument, oldest calibration first: of every serial
        number the one-calibration check takes for this item's (same_serial: "AB-10 5" and
        "ab105" are one item at issue, so one history), or, for a serial that says there is
        none ("", "n/a": no_serial), of that serial as kept; with ``manufacturer``, of that
        manufacturer's item (printing alike, case aside: same_identifier) where a record
        names one — a serial is unique only within its maker (#64 review F6: Acme's "001"
        and Zeta's "001" were one history, the older one's due date from the other's later
        calibration); a record or a call naming none matches by the serial alone."""
        certificates = self._schema.CERTIFICATES
        c = certificates.c
        serial = _alike(serial)
        with self._read() as conn:
            ids = [row.id for row in conn.execute(self._sa.select(
                c.id, c.item_serial, c.item_manufacturer))
                   if _same_instrument(row.item_serial, serial)
                   and _same_maker(row.item_manufacturer, manufacturer)]
            if not ids:
                return []
            rows = conn.execute(self._sa.select(*(c[name] for name in self._record_columns))
                                .where(c.id.in_(ids))
                                .order_by(c.calibration_date, c.id))
            return [CertificateRecord(**row._asdict()) for row in rows]

    # -- calibration intervals -------------------------------------------------------------
    def set_interval(self, serial: str, days: int | None, manufacturer: str = "") -> None:
        """Set (or with None or 0 clear) the interval of ``manufacturer``'s item of ``serial``
        (schema version 7; stop 63: two makers' "001" shared one interval): a chained entry
        (its body names the maker; none for "", every maker's item of the serial that has
        no interval of its own, as every interval set before version 7)."""
        from models.register.identifiers import IdentifierError, normalise_identifier, refuse_unprinted

        try:
            serial = normalise_identifier(serial, message(QT_TR_NOOP("serial number")))
            refuse_unprinted(manufacturer, message(QT_TR_NOOP("manufacturer")))
        except IdentifierError as exc:
            raise RegisterError(reason_of(exc)) from None
        maker = " ".join((manufacturer or "").split())
        if days is not None and days < 0:
            raise RegisterError(message(
                QT_TR_NOOP("a calibration interval is a positive number of days")))
        instruments = self._schema.INSTRUMENTS
        c = instruments.c
        with self._write() as conn:
            if not self.is_sqlite:
                conn.execute(self._sa.text("SELECT pg_advisory_xact_lock(:k)"),
                             {"k": _CHAIN_LOCK})
            # one item, one interval: one set under a serial that is this item's by the
            # one-calibration check ("AB-10 5" for "ab105"), of a maker that prints alike
            # ("ACME optics" for Acme Optics), is cleared, each in the chain
            for other in conn.execute(self._sa.select(c.serial, c.manufacturer)).all():
                if (other.serial, other.manufacturer) != (serial, maker) \
                        and _same_instrument(other.serial, serial) \
                        and _one_maker(other.manufacturer, maker):
                    conn.execute(instruments.delete().where(
                        c.serial == other.serial, c.manufacturer == other.manufacturer))
                    self._append_entry(conn, "interval", other.serial,
                                       _interval_body(None, other.manufacturer))
            conn.execute(instruments.delete().where(c.serial == serial,
                                                    c.manufacturer == maker))
            if days:
                conn.execute(instruments.insert().values(serial=serial, manufacturer=maker,
                                                         interval_days=int(days)))
            self._append_entry(conn, "interval", serial,
                               _interval_body(int(days) if days else None, maker))

    def interval(self, serial: str, manufacturer: str = "") -> int | None:
        """The interval of ``manufacturer``'s item of ``serial``: set for it (its serial, or
        one that is this item's by the one-calibration check, same_serial; its maker
        printing alike, case aside, same_identifier), else the one set for every maker's
        item of the serial (manufacturer ""); never another maker's. Without
        ``manufacturer`` (an item whose certificate names none), the one set for every
        maker's item only (rev65 F4: it took any maker's, so a makerless "001" was due by
        Acme's interval). Of several, the one set last."""
        entries = self._schema.ENTRIES
        serial, maker = _alike(serial), " ".join((manufacturer or "").split())
        with self._read() as conn:
            found = {(row.serial, row.manufacturer): row.interval_days
                     for row in self._intervals(conn)
                     if _same_instrument(row.serial, serial)}
            own = {k: v for k, v in found.items() if maker and k[1]
                   and _one_maker(k[1], maker)}
            every = {k: v for k, v in found.items() if not k[1]}
            chosen = own or every
            if len(chosen) < 2:
                return next(iter(chosen.values()), None)
            notes = conn.execute(self._sa.select(entries.c.subject, entries.c.body_json).where(
                entries.c.kind == "interval",
                entries.c.subject.in_(sorted({k[0] for k in chosen})))
                .order_by(entries.c.seq.desc())).all()
        for note in notes:
            key = (note.subject, _interval_maker(note.body_json))
            if key in chosen:
                return chosen[key]
        return chosen.get((serial, maker), next(iter(chosen.values())))

    def _intervals(self, conn) -> builtins.list[Any]:
        """Every interval set: serial, manufacturer ("" in a register read at schema version
        6, whose intervals are per serial: :attr:`_intervals_per_serial`), interval_days."""
        sa = self._sa
        if self._intervals_per_serial:
            c = self._schema.intervals_per_serial().c
            return conn.execute(sa.select(c.serial, sa.literal("").label("manufacturer"),
                                          c.interval_days)).all()
        c = self._schema.INSTRUMENTS.c
        return conn.execute(sa.select(c.serial, c.manufacturer, c.interval_days)).all()

    def makers_of(self, serial: str) -> tuple[str, ...]:
        """The manufacturers the certificates of ``serial`` (as :meth:`history` tells the
        serial) name, one name a maker (maker_names), in the order issued; none named: ()."""
        from models.register.maker_names import same_maker_name

        makers: builtins.list[str] = []
        for record in sorted(self.history(serial), key=lambda r: r.issued_at or ""):
            name = _printed(record.item_manufacturer)
            if name and not any(same_maker_name(name, kept) for kept in makers):
                makers.append(name)
        return tuple(makers)

    def maker_needed(self, serial: str, manufacturer: str = "") -> tuple[str, ...]:
        """For an item named without its maker (``manufacturer`` blank): the makers the
        serial's certificates name (:meth:`makers_of`); then its due date cannot be told
        without the maker (rev65 F4: a makerless "001" last calibrated 2025-01-10 was due
        2027-11-20, from Acme's "001"). () when a maker is given or none is named."""
        if (manufacturer or "").strip():
            return ()
        return self.makers_of(serial)

    def due_date(self, serial: str, manufacturer: str = "") -> dt.date | None:
        """The last calibration of the serial (of ``manufacturer``'s item, as
        :meth:`history` tells it) plus that item's interval (:meth:`interval`; None without
        either). None too for an item named without its maker where the serial's
        certificates name one (:meth:`maker_needed`): whose calibrations and interval would
        count is not known, and another maker's are never borrowed (rev65 F4)."""
        if self.maker_needed(serial, manufacturer):
            return None
        days = self.interval(serial, manufacturer)
        dates = [r.calibration_date for r in self.history(serial, manufacturer)
                 if r.calibration_date]
        if not days or not dates:
            return None
        return dt.date.fromisoformat(max(dates)) + dt.timedelta(days=days)


def _counter_of(number: str, names) -> tuple[str, int] | None:
    """The counter (by name: the scheme with its date fields filled in, "#" for the
    sequence) whose numbers ``number`` is one of, and its value there; None when none."""
    for name in names:
        if name.count("#") != 1:
            continue
        before, after = name.split("#")
        found = re.fullmatch(re.escape(before) + r"(\d+)" + re.escape(after), number)
        if found:
            return name, int(found.group(1))
    return None


def _interval_body(days: int | None, manufacturer: str) -> dict:
    """An interval entry's body: the days, and the maker when it is one maker's item's."""
    return {"days": days, "manufacturer": manufacturer} if manufacturer else {"days": days}


def _interval_maker(body_json: str | None) -> str:
    """The maker an interval entry was set for ("" : every maker's item, as every entry
    recorded before schema version 7)."""
    maker = json.loads(body_json or "{}").get("manufacturer")
    return maker if isinstance(maker, str) else ""


def _one_maker(kept: str, manufacturer: str) -> bool:
    """Whether an interval's maker is ``manufacturer``: both none (every maker's item), or
    both named and one maker (maker_names.same_maker_name: its key, or printing alike)."""
    from models.register.maker_names import same_maker_name

    if not kept.strip() or not manufacturer.strip():
        return not kept.strip() and not manufacturer.strip()
    return kept == manufacturer or same_maker_name(kept, manufacturer)


class _Turn:
    """An issuer's turn after a lost race (see Register._issuing_turn)."""

    def __init__(self, register: Register) -> None:
        self.register = register
        self._handle: BinaryIO | None = None
        self._conn: Connection | None = None

    def take(self) -> None:
        if self._handle is not None or self._conn is not None:
            return
        register = self.register
        if register.is_sqlite and register._sqlite_path:
            try:
                import fcntl
            except ImportError:  # Windows: retries without a turn
                return
            try:
                handle = open(register._sqlite_path + TURN_FILE_SUFFIX, "a+b")  # noqa: SIM115
            except OSError:
                return
            # waited for as long as PostgreSQL's turn (lock_timeout below), then the issue
            # goes on without it, as on Windows: the turn only spares a render, the commit is
            # serialised by the database (a blocking flock waited for ever on an issuer that
            # hung holding it)
            deadline = time.monotonic() + TURN_TIMEOUT_S
            while True:
                try:
                    fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
                    break
                except BlockingIOError:
                    if time.monotonic() > deadline:
                        handle.close()
                        return
                    time.sleep(0.02)
            self._handle = handle
        elif not register.is_sqlite:
            conn = register.engine.connect()
            conn.execute(register._sa.text(f"SET lock_timeout = '{TURN_TIMEOUT_S}s'"))
            try:
                conn.execute(register._sa.text("SELECT pg_advisory_lock(:k)"), {"k": _TURN_LOCK})
                conn.commit()
            except register._sa.exc.SQLAlchemyError:
                conn.close()
                return
            self._conn = conn

    def release(self) -> None:
        if self._handle is not None:
            self._handle.close()  # the lock goes with the descriptor
            self._handle = None
        if self._conn is not None:
            try:
                self._conn.execute(self.register._sa.text("SELECT pg_advisory_unlock(:k)"),
                                   {"k": _TURN_LOCK})
                self._conn.commit()
            finally:
                self._conn.close()
                self._conn = None


def _alike(identifier: str) -> str:
    """An identifier as the register keeps it (as typed when it cannot be)."""
    from models.register.identifiers import IdentifierError, normalise_identifier

    try:
        return normalise_identifier(identifier)
    except IdentifierError:
        return identifier


def _same_instrument(kept: str, serial: str) -> bool:
    """Whether a serial kept in the register is ``serial``'s instrument, as the
    one-calibration check at issue tells it (same_serial); a serial that says there is none
    (no_serial) only as kept, the item being then told by its description and maker."""
    from models.register.identifiers import no_serial, same_serial

    if kept == serial:
        return True
    return not no_serial(serial) and not no_serial(kept) and same_serial(kept, serial)


def _same_maker(kept: str | None, manufacturer: str) -> bool:
    """Whether a record's manufacturer is ``manufacturer``'s: one maker by its maker key or
    printing alike, case aside (maker_names.same_maker_name; rev65 F1: "Moeller-Wedel" was
    another maker than "Möller-Wedel"); a record or a call naming none is any."""
    from models.register.maker_names import same_maker_name

    if not (kept or "").strip() or not (manufacturer or "").strip():
        return True
    return same_maker_name(kept or "", manufacturer)


def _another_makers_item(meta: CertificateMetadata, others) -> AnotherMakersItem:
    """The question of another maker's item (:meth:`Register.issue`), as raised."""
    return AnotherMakersItem(message(QT_TR_NOOP(
        "{numbers} reports serial {serial}, calibrated {date}, of {makers}, not "
        "of {maker}: a maker's name spelt otherwise is the same maker, and this "
        "would be a second certificate of that calibration. Issue it only if it "
        "is another maker's item with the same serial (it is then recorded in "
        "the register that you said so; on the command line: "
        "--another-makers-item)"),
        numbers=", ".join(n for n, _m in others),
        serial=meta.item_serial or meta.item_description or "—",
        date=meta.calibration_date or "—",
        makers=", ".join(sorted({m for _n, m in others})),
        maker=_printed(meta.item_manufacturer) or "—"),
        tuple(n for n, _m in others))


def _lookalike_serial(meta: CertificateMetadata, lookalikes) -> LookalikeSerial:
    """The question of a look-alike serial (:meth:`Register.issue`; rev65 F7), as raised:
    each serial it looks like once, with its certificates and maker, and the characters that
    differ marked and named (day review 67 F6: the serial was listed once a certificate, and
    which character differed was not said)."""
    from models.register.serial_differences import differences_sentence

    serials: dict[str, tuple[list[str], list[str]]] = {}
    for number, serial, maker in lookalikes:
        numbers, makers = serials.setdefault(serial, ([], []))
        numbers.append(number)
        if maker and maker not in makers:
            makers.append(maker)
    others = listed([
        message(QT_TR_NOOP("{serial} of {maker} ({numbers})"), serial=serial,
                maker=listed(makers), numbers=listed(numbers)) if makers else
        message(QT_TR_NOOP("{serial} ({numbers})"), serial=serial, numbers=listed(numbers))
        for serial, (numbers, makers) in serials.items()])
    facts = message(QT_TR_NOOP(
        "serial {serial} is in no certificate of the register, but looks like {others}. "
        "{differences}. If it is that item with its serial mistyped, a certificate under this "
        "serial would split its history and due date") if len(serials) == 1 else QT_TR_NOOP(
        "serial {serial} is in no certificate of the register, but looks like {others}. "
        "{differences}. If it is one of those items with its serial mistyped, a certificate "
        "under this serial would split its history and due date"),
        serial=meta.item_serial, others=others,
        differences=separated([differences_sentence(meta.item_serial, kept)
                               for kept in serials]))
    return LookalikeSerial(
        message(QT_TR_NOOP("{facts}. Issue it only if it is another item, with "
                           "--another-lookalike-item (the register records that you said so)"),
                facts=facts),
        tuple(n for n, _k, _m in lookalikes), facts,
        message(QT_TR_NOOP("Is {serial} a different item from {kept}?"), serial=meta.item_serial,
                kept=_either(list(serials))),
        message(QT_TR_NOOP("If it is the same item, correct the serial number in the "
                           "certificate details, then issue the certificate again.")),
        meta.item_serial, tuple((serial, tuple(numbers))
                                for serial, (numbers, _makers) in serials.items()))


def _either(items: list[str]) -> Any:
    """"A", "A or B", "A, B or C" (each a translatable join)."""
    if len(items) < 2:
        return "".join(items)
    return message(QT_TR_NOOP("{items} or {item}"), items=listed(items[:-1]), item=items[-1])


def _one_item(record: CertificateRecord, meta: CertificateMetadata) -> bool:
    """Whether ``record`` reports ``meta``'s item, as :meth:`Register._same_calibration`
    tells one: a serial that prints alike (same_serial) of its maker (_same_maker: a side
    naming none is any); with no serial (no_serial), none on the record either and a
    description that prints alike (same_identifier)."""
    from models.register.identifiers import no_serial, same_identifier, same_serial

    if not _same_maker(record.item_manufacturer, meta.item_manufacturer):
        return False
    if no_serial(meta.item_serial):
        return no_serial(record.item_serial or "") and same_identifier(
            record.item_description or "", meta.item_description or "")
    return not no_serial(record.item_serial or "") and same_serial(record.item_serial,
                                                                   meta.item_serial)


def _readings_said(meta: CertificateMetadata, elsewhere: tuple[tuple[str, str, str, str], ...],
                   stated: tuple[str, str] | None) -> Any:
    """The statement printed on a certificate whose readings are those of the certificates
    ``elsewhere`` of another item (:meth:`Register._readings_elsewhere`), ``stated`` (one of
    their numbers, why) by the user; "" when there are none and none is stated.
    :class:`ReadingsOfAnotherItem` when there are some and none is stated, or the reason is
    empty; RegisterError when the number stated is none of them (the statement would be
    false)."""
    from models.register.identifiers import as_printed

    def same(a: str, b: str) -> bool:
        return as_printed(a).upper() == as_printed(b).upper()

    if stated and not any(same(stated[0].strip(), n) for n, *_ in elsewhere):
        # "N:REASON" split at its first colon, where N holds one (a typed number may)
        whole = f"{stated[0].strip()}:{stated[1]}"
        for n in sorted((e[0] for e in elsewhere), key=len, reverse=True):
            if same(whole[:len(n)], n) and whole[len(n):len(n) + 1] == ":":
                stated = (n, whole[len(n) + 1:])
                break
    number, reason = (stated[0].strip(), " ".join(stated[1].split())) if stated else ("", "")
    each = [message(QT_TR_NOOP("{number} (item {item}, calibrated {date})"), number=n,
                    item=item or "—", date=date or "—") for n, _serial, item, date in elsewhere]
    facts = separated(each, ", ")
    if stated and not elsewhere:
        raise RegisterError(message(QT_TR_NOOP(
            "--readings-of-another-item {number}: the readings are not those of any "
            "certificate of another item in the register (compared by their values), so "
            "nothing is to be stated; leave it out"), number=number or "—"))
    if not elsewhere:
        return ""
    if stated and not any(same(number, n) for n, *_ in elsewhere):
        raise RegisterError(message(QT_TR_NOOP(
            "--readings-of-another-item {number}: the readings are not those of {number} but "
            "those of {facts}; name the certificate whose readings they are"),
            number=number or "—", facts=facts))
    if not reason:
        found = message(QT_TR_NOOP(
            "the readings are those of {facts}, another item than {serial}: no two "
            "calibrations repeat every reading to the last digit"), facts=facts,
            serial=_printed(meta.item_serial) or _printed(meta.item_description) or "—")
        raise ReadingsOfAnotherItem(message(QT_TR_NOOP(
            "{found}. A calibration of this item has readings of its own; if these are "
            "indeed its readings, say why (printed on the certificate and recorded in the "
            "register; on the command line: --readings-of-another-item {number}:REASON)"),
            found=found, number=elsewhere[0][0]), tuple(e[0] for e in elsewhere), found)
    if len(elsewhere) == 1:
        return message(QT_TR_NOOP("The readings are those of certificate {facts}: {reason}"),
                       facts=facts, reason=reason)
    return message(QT_TR_NOOP("The readings are those of certificates {facts}: {reason}"),
                   facts=facts, reason=reason)


def _with_rows_of(project_json: str, other_json: str, workbench: str) -> str:
    """``project_json`` with the readings of ``workbench`` as ``other_json`` holds them
    (typed otherwise, the same values: readings_identity.readings_key)."""
    project, other = json.loads(project_json), json.loads(other_json)
    project["workbenches"][workbench]["rows"] = other["workbenches"][workbench]["rows"]
    return json.dumps(project)


def _same_readings_said(meta: CertificateMetadata, identical: tuple[str, ...],
                        stated: tuple[str, str] | None, redated: bool = False) -> Any:
    """What a calibration of its own states whose readings and details are those of the
    current certificates ``identical`` of its item and date, ``stated`` (one of their
    numbers, why) by the user; "" when there are none and none is stated.
    :class:`SameReadingsIssued` when there are some and no reason is given;
    RegisterError when the number stated is none of them."""
    from models.register.identifiers import as_printed

    def same(a: str, b: str) -> bool:
        return as_printed(a).upper() == as_printed(b).upper()

    if stated and not any(same(stated[0].strip(), n) for n in identical):
        # "N:REASON" split at its first colon, where N holds one (a typed number may)
        whole = f"{stated[0].strip()}:{stated[1]}"
        for n in sorted(identical, key=len, reverse=True):
            if same(whole[:len(n)], n) and whole[len(n):len(n) + 1] == ":":
                stated = (n, whole[len(n) + 1:])
                break
    number, reason = (stated[0].strip(), " ".join(stated[1].split())) if stated else ("", "")
    numbers = ", ".join(identical)
    if stated and not identical:
        raise RegisterError(message(QT_TR_NOOP(
            "--same-readings-as {number}: the readings and details are not those of a "
            "current certificate of this item and date of calibration (the readings compared "
            "by their values), so nothing is to be stated; leave it out"),
            number=number or "—"))
    if not identical:
        return ""
    if stated and not any(same(number, n) for n in identical):
        raise RegisterError(message(QT_TR_NOOP(
            "--same-readings-as {number}: the readings and details are not those of {number} "
            "but those of {numbers}; name the certificate whose readings they are"),
            number=number or "—", numbers=numbers))
    if not reason:
        found = message(QT_TR_NOOP(
            "the readings are the same as those of {numbers} (serial {serial}, calibrated "
            "{date}), each within the last digit it was typed to, and so are its details: no "
            "two calibrations repeat every reading to the last digit, so this is the "
            "calibration {numbers} already reports, issued again"),
            numbers=numbers, serial=_printed(meta.item_serial) or "—",
            date=meta.calibration_date or "—") if not redated else message(QT_TR_NOOP(
            "the readings are the same as those of {numbers} (serial {serial}), each within "
            "the last digit it was typed to, with another date of calibration than {date}: no "
            "two calibrations repeat every "
            "reading to the last digit, so this is the calibration {numbers} already reports, "
            "issued again with its date of calibration moved"),
            numbers=numbers, serial=_printed(meta.item_serial) or "—",
            date=meta.calibration_date or "—")
        raise SameReadingsIssued(message(QT_TR_NOOP(
            "{found}. Its copy is the PDF of {number} (anglebench register show {number} "
            "--pdf OUT.pdf); a correction is its amendment or replacement (File › "
            "Certificate register, Amend… or Replace…); if these are indeed the readings of "
            "a calibration of its own, say why (stated on the certificate and recorded in "
            "the register; on the command line: --same-readings-as {number}:REASON)"),
            found=found, number=identical[0]), identical, found)
    return message(QT_TR_NOOP("The readings are the same as those of {number}, each within "
                              "the last digit it was typed to, and so are the details: "
                              "{reason}"), number=number, reason=reason)


def _serial_left_out(meta: CertificateMetadata, rows) -> SerialLeftOut:
    """The question of an item of no serial beside one of its description with a serial, or
    the other way round (:meth:`Register.issue`; stop 67), as raised: each serial once
    with its certificates, the verb agreeing with them (day review 67 F6: "AB-2026-0001
    (…), …, AB-2026-0005 (…) reports an item")."""
    from models.register.identifiers import no_serial

    numbers = tuple(n for n, _k, _m in rows)
    item = _item_text(meta.item_description, _printed(meta.item_manufacturer))
    date = meta.calibration_date or "—"
    if no_serial(meta.item_serial):
        serials: dict[str, list[str]] = {}
        for number, serial, _maker in rows:
            serials.setdefault(serial, []).append(number)
        listed_serials = listed([message(QT_TR_NOOP("{serial} ({numbers})"), serial=serial,
                                         numbers=listed(certificates))
                                 for serial, certificates in serials.items()])
        facts = message(QT_TR_NOOP(
            "{item} has no serial number, but an item of that description and maker calibrated "
            "{date} has one in the register: {serials}. A serial left out does not make another "
            "item: this may be a second certificate of that calibration") if len(serials) == 1
            else QT_TR_NOOP(
            "{item} has no serial number, but {count} items of that description and maker "
            "calibrated {date} have one in the register: {serials}. A serial left out does not "
            "make another item: this may be a second certificate of one of those calibrations"),
            item=item, date=date, serials=listed_serials, count=len(serials))
        return SerialLeftOut(
            message(QT_TR_NOOP("{facts}. Issue it only if it is another item, which has no "
                               "serial number, with --another-lookalike-item (the register "
                               "records that you said so)"), facts=facts),
            numbers, facts,
            message(QT_TR_NOOP("Is this a different item, one with no serial number?")),
            message(QT_TR_NOOP("If it is the same item, type its serial number in the "
                               "certificate details; a certificate is corrected by its "
                               "amendment or replacement (File › Certificate register).")))
    facts = message(QT_TR_NOOP(
        "{numbers} reports {item}, which has no serial number, calibrated {date}: this may be "
        "that item with its serial {serial} typed now, and a second certificate of that "
        "calibration") if len(numbers) == 1 else QT_TR_NOOP(
        "{numbers} report {item}, which has no serial number, calibrated {date}: this may be "
        "that item with its serial {serial} typed now, and a second certificate of that "
        "calibration"),
        numbers=listed(list(numbers)), serial=meta.item_serial, item=item, date=date)
    return SerialLeftOut(
        message(QT_TR_NOOP("{facts}. Issue it only if it is another item, with "
                           "--another-lookalike-item (the register records that you said so)"),
                facts=facts),
        numbers, facts,
        message(QT_TR_NOOP("Is {serial} a different item from the one of {numbers}?"),
                serial=meta.item_serial, numbers=listed(list(numbers))),
        message(QT_TR_NOOP("If it is the same item, its serial number is added by amending "
                           "or replacing {numbers} (File › Certificate register)."),
                numbers=listed(list(numbers))))


def _item_corrected(original: CertificateRecord, meta: CertificateMetadata) -> bool:
    """Whether an amendment or replacement of ``original`` with ``meta`` corrects its item:
    the serial or the manufacturer as printed, or for an item of no serial the
    description (the item an amendment's look-alike questions are asked of)."""
    from models.register.identifiers import as_printed, no_serial

    return as_printed(original.item_serial) != as_printed(meta.item_serial) \
        or _printed(original.item_manufacturer) != _printed(meta.item_manufacturer) \
        or no_serial(meta.item_serial) \
        and _printed(original.item_description) != _printed(meta.item_description)


def _takes(render: Callable[..., bytes], name: str) -> bool:
    """``render`` takes the keyword ``name`` (so the PDF carries what it is given)."""
    import inspect

    try:
        return name in inspect.signature(render).parameters
    except (TypeError, ValueError):
        return False


def _call_render(render: Callable[..., bytes], final: CertificateMetadata, head: str,
                 content: str = "", proof: str = "") -> bytes:
    import inspect

    try:
        parameters = inspect.signature(render).parameters
    except (TypeError, ValueError):
        parameters = {}  # type: ignore[assignment]
    given = {name: value for name, value in (("head", head), ("content", content),
                                             ("proof", proof))
             if name in parameters}
    return render(final, **given)


def _cross_checks(rows, notes, counters: dict, intervals: dict) -> list:
    """The counters, intervals and statuses against the chained records that set them."""
    problems: list = []
    reached: dict[str, int] = {}
    for note in notes:
        body = json.loads(note.body_json or "{}")
        if note.kind == "numbering" and isinstance(body.get("last_value"), int):
            reached[note.subject] = max(reached.get(note.subject, 0), body["last_value"])
        if note.kind == LOSS_ACKNOWLEDGED:  # moved past the numbers lost (reg73 #5)
            for name, (_before, after) in dict(body.get("counters") or {}).items():
                reached[name] = max(reached.get(name, 0), int(after))
    for row in rows:
        if row.counter and row.counter_value:
            reached[row.counter] = max(reached.get(row.counter, 0), row.counter_value)
    for name in sorted(set(reached) | set(counters)):
        value, recorded = counters.get(name), reached.get(name, 0)
        if value is None or value < recorded:
            problems.append(message(QT_TR_NOOP(
                "counter {name}: it stands at {value}, but the records reach {recorded}: it "
                "was set back after issue (a number would be issued twice)"),
                name=name, value="—" if value is None else value, recorded=recorded))
        elif value > recorded:
            problems.append(message(QT_TR_NOOP(
                "counter {name}: it stands at {value}, but no record was numbered {value}: "
                "the record was deleted after issue"), name=name, value=value))
    # per (serial, maker) since schema version 7: an entry recorded before names no maker,
    # as the rows migration 7 copied (every maker's item of the serial)
    last_interval: dict[tuple[str, str], int | None] = {}
    withdrawn: dict[str, str] = {}
    for note in notes:
        body = json.loads(note.body_json or "{}")
        if note.kind == "interval":
            last_interval[(note.subject, _interval_maker(note.body_json))] = body.get("days")
        elif note.kind == "withdrawal":
            withdrawn[note.subject] = body.get("reason", "")
    for serial, maker in sorted(set(last_interval) | set(intervals)):
        if intervals.get((serial, maker)) != last_interval.get((serial, maker)):
            problems.append(message(QT_TR_NOOP(
                "instrument {serial}: calibration interval {days} day(s), but the register's "
                "records set {recorded}: changed after it was recorded"),
                serial=f"{serial} ({maker})" if maker else serial,
                days=intervals.get((serial, maker)) or "—",
                recorded=last_interval.get((serial, maker)) or "—"))
    results: dict[str, int] = {}
    for note in notes:  # one results file per certificate, recorded at its issue (rev62 F7)
        if note.kind == "results":
            results[note.subject] = results.get(note.subject, 0) + 1
    # a certificate shown to verify whose record was gone (rev64 F8), or whose number was
    # issued again (reg73 #2): stops issuing until a loss acknowledged after it
    acknowledged = max((n.seq for n in notes if n.kind == LOSS_ACKNOWLEDGED), default=0)
    for note in notes:
        if note.kind in ("missing", "number_reissued") and note.seq > acknowledged:
            body = json.loads(note.body_json or "{}")
            problems.append(message(
                MISSING_FOUND if note.kind == "missing" else REISSUED_FOUND,
                number=body.get("number") or "—", sha=str(body.get("pdf_sha256", ""))[:16],
                date=note.recorded_at[:10], place=body.get("place", "?")))
    for number, count in sorted(results.items()):
        if count > 1:
            problems.append(message(QT_TR_NOOP(
                "certificate {number}: {count} results files recorded, where a certificate "
                "has one (recorded at its issue): all but the first were added after issue"),
                number=number, count=count))
    superseders = {row.supersedes: row.number for row in rows if row.supersedes}
    for row in rows:
        by = superseders.get(row.number)
        expected = (("superseded", by) if by else ("withdrawn", None) if row.number in withdrawn
                    else ("issued", None))
        if (row.status, row.superseded_by) != expected:
            problems.append(message(QT_TR_NOOP(
                "record {number}: marked \"{status}\" (superseded by {marked}), but the "
                "register's records say {by}"), number=row.number, status=row.status,
                marked=row.superseded_by or "—",
                by=by and message(QT_TR_NOOP("superseded by {number}"), number=by)
                or (message(QT_TR_NOOP("withdrawn")) if row.number in withdrawn else
                    message(QT_TR_NOOP("issued, superseded by none")))))
        # the reason is the withdrawal entry's, which the chain covers; the record's copy of
        # it (shown by show and verify) must read the same (rev64 F9: rewritten unnoticed);
        # a withdrawal undone with its reason is said once, by its status above
        if row.withdrawn_reason != withdrawn.get(row.number) and not (
                row.withdrawn_reason is None and row.status != "withdrawn"):
            problems.append(message(QT_TR_NOOP(
                "record {number}: its reason for withdrawal reads \"{reason}\", but the "
                "register's withdrawal record says {recorded}: changed after it was recorded"),
                number=row.number, reason=row.withdrawn_reason or "—",
                recorded=f"\"{withdrawn[row.number]}\"" if row.number in withdrawn
                else message(QT_TR_NOOP("it was never withdrawn"))))
    return problems


def _readings_key_problems(fields: dict) -> list:
    """A record's stored readings identities (readings_key, schema version 8: in the chain
    from chain format 7; readings_layout, _anchor and _reach, schema version 9: in the chain
    from chain format 8; outside it for the records migrations 8 and 9 filled them in for)
    against the ones its readings give (its project state, in the chain): set otherwise
    after issue, they would hide its readings from the check of one item's readings issued
    as another's, or name it for readings it does not hold. [] when they agree or none is
    stored; one finding for either or both."""
    stored = fields.get("readings_key")
    kept = stored is None or stored == readings_key(fields["project_json"], fields["workbench"])
    layout = fields.get("readings_layout")
    if kept and layout is not None:
        identity = readings_identity(fields["project_json"], fields["workbench"])
        kept = (layout, fields.get("readings_anchor"), fields.get("readings_reach")) == (
            NO_READINGS if identity is None else identity.stored)
    if kept:
        return []
    return [message(QT_TR_NOOP(
        "record {number}: the identity of its readings stored with it is not that of its "
        "readings (set otherwise after issue): the check of readings issued again would "
        "not find them"), number=fields["number"])]


def _content_problems(fields: dict, pdf: bytes, dcc: bytes | None) -> list:
    """A record of chain format 5 or later against the digest of its content its stored PDF
    carries (in the record's form: models/register/chain.content_form): a record rewritten
    after issue with its chain recomputed — in form 2 its DCC or document kind too (reg73
    #1). A stored PDF that carries no digest is not judged here (the register's own tests
    render without one); ``register verify FILE`` remarks on it (printed_place.digest_missing)."""
    from models.register.chain import content_digest, content_form, content_in_pdf

    carried = content_in_pdf(pdf)
    if not carried:
        return []
    actual = content_digest(fields, None if dcc is None else bytes(dcc))
    if actual == carried:
        return []
    return [message(QT_TR_NOOP(
        "record {number}: it is not the record its stored PDF was issued from: the PDF "
        "carries the digest {carried}… of its record's content (form {form}), the record now "
        "gives {actual}…: the record was rewritten after issue"), number=fields["number"],
        carried=carried[:16], form=content_form(fields), actual=actual[:16])]


def _dcc_problems(conn, certificates, row, content: bool) -> list:
    """A record's digital calibration certificate against what was recorded at issue: its
    SHA-256 only in a record of chain format 3 (which chains it), the DCC stored when the
    hash says one was issued, none stored when none was; with ``content`` the stored DCC
    against its SHA-256 and the PDF embedded in it against the stored PDF."""
    import sqlalchemy as sa

    problems: list = []
    chained = (row.chain_format or 1) >= 3
    if row.dcc_sha256 is not None and not chained:
        problems.append(message(QT_TR_NOOP(
            "record {number}: it carries a DCC SHA-256, but it was issued without a DCC "
            "(its chain does not cover one): added after issue"), number=row.number))
    if row.dcc_sha256 is not None and not row.has_dcc:
        problems.append(message(QT_TR_NOOP(
            "record {number}: its DCC was issued and recorded (SHA-256 {sha}…) but is no "
            "longer stored: deleted after issue"), number=row.number, sha=row.dcc_sha256[:16]))
    if row.has_dcc and row.dcc_sha256 is None:
        problems.append(message(QT_TR_NOOP(
            "record {number}: a DCC is stored, but none was recorded at issue: added after "
            "issue"), number=row.number))
    if not (content and row.has_dcc and row.dcc_sha256 is not None):
        return problems
    data = bytes(conn.execute(sa.select(certificates.c.dcc).where(
        certificates.c.id == row.id)).scalar_one())
    if hashlib.sha256(data).hexdigest() != row.dcc_sha256:
        problems.append(message(QT_TR_NOOP(
            "record {number}: the stored DCC does not match the SHA-256 recorded at issue"),
            number=row.number))
        return problems
    from models.dcc.reader import DccError, embedded_pdfs

    pdf = bytes(conn.execute(sa.select(certificates.c.pdf).where(
        certificates.c.id == row.id)).scalar_one())
    try:
        inside = embedded_pdfs(data)
    except DccError as exc:
        problems.append(message(QT_TR_NOOP("record {number}: its DCC cannot be read: "
                                           "{reason}"), number=row.number, reason=reason_of(exc)))
        return problems
    if pdf not in inside:
        problems.append(message(QT_TR_NOOP(
            "record {number}: the PDF embedded in its DCC is not the stored PDF ({n} PDF(s) "
            "embedded): the two forms of the certificate differ"),
            number=row.number, n=len(inside)))
    from models.dcc.signature import SigningError, has_signature, trusted_certificate, verify

    try:
        signed = has_signature(data)
        trusted = trusted_certificate() if signed else None
    except (SigningError, ValueError) as exc:
        problems.append(message(QT_TR_NOOP("record {number}: its DCC's signature cannot be "
                                           "checked: {reason}"), number=row.number,
                                reason=reason_of(exc)))
        return problems
    if signed:
        check = verify(data, trusted)
        if check.problems:
            problems.append(message(QT_TR_NOOP("record {number}: its DCC's signature: "
                                               "{reason}"), number=row.number,
                                    reason=check.problems[0]))
    return problems


def _check_issuable(meta: CertificateMetadata, issue_date: dt.date) -> None:
    """Raise RegisterError unless the certificate has an approver and its calibration date is
    not after ``issue_date``. (A draft needs neither, and the register never records one.)"""
    if not meta.approver.strip():
        raise RegisterError(message(QT_TR_NOOP(
            "an issued certificate needs the name of the person who approves it ("
            "\"Approved by\"); without one it can only be written as a draft")))
    if meta.calibration_date and meta.calibration_date > issue_date.isoformat():
        raise RegisterError(message(QT_TR_NOOP(
            "the date of calibration {calibration} is after the date of issue {today} (the day "
            "the register issues it): a certificate reports a calibration already made"),
            calibration=meta.calibration_date, today=issue_date.isoformat()))


def _root(record: CertificateRecord) -> str:
    """The number amendments count from: the original's, not an amendment's."""
    return re.sub(r"-A\d+$", "", record.number) if record.revision.startswith("amendment") \
        else record.number


def _same_item(description: str, manufacturer: str, meta: CertificateMetadata) -> bool:
    """Whether an item of no serial number is ``meta``'s: its description and manufacturer
    print alike (same_identifier)."""
    from models.register.identifiers import same_identifier

    return same_identifier(description or "", meta.item_description or "") \
        and same_identifier(manufacturer or "", meta.item_manufacturer or "")


def _printed(text: str | None) -> str:
    """``text`` as a certificate prints it (as_printed), spaces collapsed: a name or a
    description typed otherwise is a changed one."""
    from models.register.identifiers import as_printed

    return " ".join(as_printed(text or "").split())


def _item_text(description: str, manufacturer: str) -> str:
    """An item of no serial number as a sentence names it: "Rotary table RT-1 (Acme)"."""
    description = description or "—"
    return f"{description} ({manufacturer})" if manufacturer else description


def _amendment_count(conn, register: Register, record: CertificateRecord) -> int:
    """The highest n of the amendments ``<root>-A<n>`` the register made of ``record``'s
    original: amendments only (a number typed in that form before such numbers were refused
    made the first amendment "Amendment 2", or, taken, blocked every one)."""
    certificates = register._schema.CERTIFICATES
    root = _root(record)
    form = re.compile(rf"{re.escape(root)}-A(\d+)")
    rows = conn.execute(register._sa.select(certificates.c.number).where(
        certificates.c.number.like(f"{root}-A%"),
        certificates.c.revision.like("amendment%"))).all()
    return max((int(m.group(1)) for row in rows if (m := form.fullmatch(row.number))),
               default=0)


def _bounded(note: Any) -> Any:
    """A note stated on a certificate, within what its details hold (MAX_NOTES_CHARS: the
    project recorded with it must read again); longer, the changes are named, not listed
    (the register's record of each certificate holds its readings and details)."""
    from models.certificate.metadata import MAX_NOTES_CHARS

    if len(str(note)) <= MAX_NOTES_CHARS:
        return note
    return str(note)[:MAX_NOTES_CHARS - 80].rsplit(";", 1)[0] + "; " + str(message(QT_TR_NOOP(
        "and more: see the register's records")))


def _with_metadata(project_json: str, workbench: str, meta: CertificateMetadata) -> str:
    """The project state with the certificate's final details (its number) in it."""
    data = json.loads(project_json)
    certificates = dict(data.get("metadata", {}).get("certificates", {}))
    certificates[workbench] = meta.to_dict()
    data.setdefault("metadata", {})["certificates"] = certificates
    return json.dumps(data, ensure_ascii=False)


#: the errors of a write that found no room: the disk full, the user's quota used up
_DISK_FULL = frozenset(code for code in (errno.ENOSPC, getattr(errno, "EDQUOT", None))
                       if code is not None)


def _is_disk_full(exc: Exception) -> bool:
    """A database error that is a full disk: SQLite's SQLITE_FULL ("database or disk is
    full"), PostgreSQL's disk_full (53100), or an OSError of :data:`_DISK_FULL` under it."""
    orig = getattr(exc, "orig", None)
    if isinstance(orig, OSError) and orig.errno in _DISK_FULL:
        return True
    if getattr(orig, "sqlstate", "") == "53100" or getattr(orig, "pgcode", "") == "53100":
        return True
    return getattr(orig, "sqlite_errorname", "") == "SQLITE_FULL" or (
        "database or disk is full" in str(orig or ""))


#: free bytes under which a SQLite I/O error is taken for a full disk (a few pages and a
#: journal's header)
_NO_ROOM_BYTES = 1 << 20


def _is_io_error(exc: Exception) -> bool:
    """SQLite's SQLITE_IOERR (any of its kinds): "disk I/O error"."""
    orig = getattr(exc, "orig", None)
    return getattr(orig, "sqlite_errorname", "").startswith("SQLITE_IOERR") or (
        "disk I/O error" in str(orig or ""))


def _is_busy(error: object) -> bool:
    """SQLite's SQLITE_BUSY ("database is locked"): another connection holds the lock."""
    return getattr(error, "sqlite_errorname", "").startswith("SQLITE_BUSY") or (
        "database is locked" in str(error or ""))


#: SQLite's result codes of a file it finds damaged, or that is no database
_SQLITE_CORRUPT, _SQLITE_NOTADB = 11, 26


def _reason(exc: Exception) -> str:
    text = str(getattr(exc, "orig", None) or exc).strip().splitlines()
    return text[0] if text else type(exc).__name__


def _emptied(file: Path) -> bool:
    """Whether the SQLite register ``file`` exists and is empty (0 bytes), with nothing in
    its ``-wal`` journal either: records lost, never a register AngleBench made, which has
    its header (4096 bytes) as soon as it is opened (``PRAGMA journal_mode=WAL`` writes it)
    and its tables in the transaction that made it. SQLite reads such a file as a new,
    empty database: "hash chain intact over 0 record(s)", and the next certificate numbered
    1 again (hostile77 F3)."""
    import os
    import stat

    try:
        st = os.stat(file)
    except (OSError, ValueError):
        return False  # not there: made by the first certificate (or refused as missing)
    if not stat.S_ISREG(st.st_mode) or st.st_size:
        return False
    try:
        return os.stat(f"{file}-wal").st_size == 0
    except (OSError, ValueError):
        return True


def _sqlite_connect(dbapi_connection, _record) -> None:
    dbapi_connection.isolation_level = None  # the driver's own transactions off: ours below
    cursor = dbapi_connection.cursor()
    cursor.execute("PRAGMA journal_mode=WAL")
    cursor.execute(f"PRAGMA busy_timeout={BUSY_TIMEOUT_S * 1000}")
    cursor.close()


def _sqlite_connect_read_only(dbapi_connection, _record) -> None:
    dbapi_connection.isolation_level = None


def _sqlite_begin(conn) -> None:
    """A write takes the lock at once (writers queue instead of failing); a read takes
    none (a deferred transaction)."""
    read = conn.get_execution_options().get("anglebench_read")
    conn.exec_driver_sql("BEGIN" if read else "BEGIN IMMEDIATE")
