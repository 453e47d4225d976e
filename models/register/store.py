"""The certificate register behind one small interface, on SQLite or PostgreSQL.

Why SQLAlchemy Core (with psycopg 3 for PostgreSQL): one set of tables and queries for
both back ends, transactions and parameter styles handled the same way, and the
dialect's own DDL for the few types that differ (BLOB / BYTEA, autoincrement); the
ORM is not used. It is imported only when a register is opened.

Issuing is one transaction: the number is allocated (``INSERT … ON CONFLICT DO UPDATE …
RETURNING`` on a counter row, which both databases run atomically and serialise across
processes), the PDF is rendered with that number, and the record — number, dates, item,
customer, the full project state, software versions, headline figures, the PDF and its
SHA-256 — is inserted. Anything that fails before the commit (the PDF, the disk, the
process killed) leaves no record and no number used. SQLite transactions begin
IMMEDIATE (the write lock at once, so two writers queue instead of failing); on
PostgreSQL the counter row's lock does the same.
"""

from __future__ import annotations

import dataclasses
import datetime as dt
import hashlib
import importlib.metadata
import json
import platform
import re
import socket
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from models import __version__
from models.certificate.metadata import CertificateMetadata, format_certificate_number
from models.messages import QT_TR_NOOP, message, reason_of
from models.register.chain import CHAINED, GENESIS, link

__all__ = ["CertificateRecord", "IssueRequest", "Register", "RegisterError", "software_versions"]

LIBRARIES = ("numpy", "scipy", "fpdf2", "PySide6-Essentials", "pyqtgraph", "SQLAlchemy",
             "psycopg")
_SEQ = re.compile(r"\{seq(?::0?\d+d)?\}")
_ADVISORY_LOCK = 0x414E4742  # "ANGB": serialises migrations on PostgreSQL
_CHAIN_LOCK = 0x414E4743  # serialises the hash chain's growth on PostgreSQL


class RegisterError(ValueError):
    """The register refused (a number issued before, an unknown certificate, a register of a
    newer version) or cannot be reached; the message says which."""


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


class Register:
    """Open (creating or migrating) the register at ``url``: ``sqlite:///path`` or
    ``postgresql://user@host/db``."""

    def __init__(self, url: str) -> None:
        import sqlalchemy as sa

        from models.register import schema

        self._sa, self._schema = sa, schema
        self.url = _normalise_url(url)
        self.is_sqlite = self.url.startswith("sqlite")
        try:
            if self.is_sqlite:
                path = self.url.split("///", 1)[1] if "///" in self.url else ""
                if path and path != ":memory:":
                    Path(path).parent.mkdir(parents=True, exist_ok=True)
                self.engine = sa.create_engine(self.url, connect_args={"timeout": 60})
                sa.event.listen(self.engine, "connect", _sqlite_connect)
                sa.event.listen(self.engine, "begin", _sqlite_begin)
            else:
                self.engine = sa.create_engine(self.url, pool_pre_ping=True)
            try:
                self._migrate()
                #: what the hash chain found changed since issue (checked on opening)
                self.problems = self.audit()
            except BaseException:
                self.engine.dispose()
                raise
        except sa.exc.SQLAlchemyError as exc:
            raise RegisterError(message(
                QT_TR_NOOP("register {display_url}: {reason}"),
                display_url=self.display_url, reason=_reason(exc))) from None
        except OSError as exc:
            raise RegisterError(message(
                QT_TR_NOOP("register {display_url}: {exc}"),
                display_url=self.display_url, exc=reason_of(exc))) from None

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

    # -- schema ---------------------------------------------------------------------------
    def _migrate(self) -> None:
        sa, schema = self._sa, self._schema
        with self.engine.begin() as conn:
            if not self.is_sqlite:
                conn.execute(sa.text("SELECT pg_advisory_xact_lock(:k)"), {"k": _ADVISORY_LOCK})
            if not sa.inspect(conn).has_table("schema_version"):
                schema.SCHEMA_VERSION.create(conn)
                conn.execute(schema.SCHEMA_VERSION.insert().values(version=0))
            version = conn.execute(sa.select(schema.SCHEMA_VERSION.c.version)).scalar_one()
            if version > schema.LATEST:
                raise RegisterError(message(
                    QT_TR_NOOP("register {display_url} is at schema version {version}, made by a newer "
                               "AngleBench than {version__} (knows {latest}): open it with that version"),
                    display_url=self.display_url, version=version, version__=__version__,
                    latest=schema.LATEST))
            for step in range(version + 1, schema.LATEST + 1):
                schema.MIGRATIONS[step](conn)
            if version < schema.LATEST:
                conn.execute(schema.SCHEMA_VERSION.update().values(version=schema.LATEST))

    @property
    def version(self) -> int:
        with self._read() as conn:
            return conn.execute(self._sa.select(self._schema.SCHEMA_VERSION.c.version)).scalar_one()

    @contextmanager
    def _read(self) -> Iterator[Any]:
        try:
            with self.engine.connect() as conn:
                yield conn
        except self._sa.exc.SQLAlchemyError as exc:
            raise RegisterError(message(
                QT_TR_NOOP("register {display_url}: {reason}"),
                display_url=self.display_url, reason=_reason(exc))) from None

    @contextmanager
    def _write(self) -> Iterator[Any]:
        """One transaction: committed when the block ends, rolled back on any exception."""
        try:
            with self.engine.begin() as conn:
                yield conn
        except self._sa.exc.SQLAlchemyError as exc:  # a unique number taken meanwhile too
            raise RegisterError(message(
                QT_TR_NOOP("register {display_url}: {reason}"),
                display_url=self.display_url, reason=_reason(exc))) from None

    # -- issuing --------------------------------------------------------------------------
    def _allocate(self, conn, scheme: str, date: dt.date) -> str:
        sa, certificates = self._sa, self._schema.CERTIFICATES
        name = _counter_name(scheme, date)
        statement = sa.text(
            "INSERT INTO counters (name, last_value) VALUES (:name, 1) "
            "ON CONFLICT (name) DO UPDATE SET last_value = counters.last_value + 1 "
            "RETURNING last_value")
        for _ in range(10_000):  # skip numbers typed by hand before the register numbered
            seq = conn.execute(statement, {"name": name}).scalar_one()
            number = format_certificate_number(scheme, seq, date)
            taken = conn.execute(sa.select(certificates.c.id).where(
                certificates.c.number == number)).first()
            if taken is None:
                return number
        raise RegisterError(message(
            QT_TR_NOOP("no free number in scheme '{scheme}'"),
            scheme=scheme))

    def continue_numbering(self, scheme: str, date: dt.date, next_sequence: int) -> str:
        """A lab moving to the register from numbers issued by hand: the next number the
        scheme allocates (for ``date``'s year, month …) is ``next_sequence``. Never moves the
        counter back. Returns that next number."""
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
        return format_certificate_number(scheme, next_sequence, date)

    def _check_free(self, conn, number: str) -> None:
        row = conn.execute(self._sa.select(
            self._schema.CERTIFICATES.c.issued_at, self._schema.CERTIFICATES.c.workbench,
            self._schema.CERTIFICATES.c.item_serial).where(
            self._schema.CERTIFICATES.c.number == number)).first()
        if row is not None:
            raise RegisterError(
                message(
                QT_TR_NOOP("certificate number {number} was issued on {issued_at} ({workbench}, serial "
                           "{value}): a number is issued once; leave the number empty and the register "
                           "allocates the next"),
                number=number, issued_at=row.issued_at[:10], workbench=row.workbench,
                value=row.item_serial or '—'))

    def issue(self, request: IssueRequest, render: Callable[[CertificateMetadata], bytes],
              *, supersedes: str = "", change_note: str = "", replacement: bool = False
              ) -> tuple[CertificateRecord, bytes]:
        """Allocate the number (or check the one given), render the PDF with it, record it:
        one transaction. ``supersedes`` issues an amendment (number ``<original>-A<n>``) or,
        with ``replacement``, a new certificate replacing the original; the original is
        kept unchanged and marked superseded. Returns the record and the PDF."""
        meta = request.metadata
        now = self.clock().astimezone(dt.timezone.utc).replace(microsecond=0)
        issue_date = now.date()  # the date of issue is the day the register issues it
        _check_issuable(meta, issue_date)
        certificates = self._schema.CERTIFICATES
        with self._write() as conn:
            revision, original = "original", None
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
                    number = self._allocate(conn, meta.number_scheme, issue_date)
                else:
                    n = _amendment_count(conn, self, original) + 1
                    revision, number = f"amendment {n}", f"{_root(original)}-A{n}"
                    self._check_free(conn, number)
            elif meta.certificate_number:
                number = meta.certificate_number
                self._check_free(conn, number)
            else:
                number = self._allocate(conn, meta.number_scheme, issue_date)
            final = dataclasses.replace(
                meta, certificate_number=number, issue_date=issue_date.isoformat(),
                created=now.isoformat(),
                supersedes=original.number if original else "",
                revision="" if revision == "original" else revision, change_note=change_note)
            pdf = render(final)
            record = CertificateRecord(
                number=number,
                issued_at=now.isoformat(),
                issue_date=issue_date.isoformat(), calibration_date=meta.calibration_date,
                workbench=request.workbench, item_description=meta.item_description,
                item_manufacturer=meta.item_manufacturer, item_serial=meta.item_serial,
                customer=meta.customer_name, operator=meta.operator,
                workstation=socket.gethostname(), status="issued",
                supersedes=original.number if original else None, superseded_by=None,
                revision=revision, change_note=change_note,
                project_json=_with_metadata(request.project_json, request.workbench, final),
                software_json=json.dumps(software_versions(), sort_keys=True),
                headline_json=json.dumps(request.headline, sort_keys=True),
                pdf_sha256=hashlib.sha256(pdf).hexdigest())
            if not self.is_sqlite:  # SQLite's BEGIN IMMEDIATE already serialises writers
                conn.execute(self._sa.text("SELECT pg_advisory_xact_lock(:k)"),
                             {"k": _CHAIN_LOCK})
            previous = conn.execute(self._sa.select(certificates.c.chain_sha256).order_by(
                certificates.c.id.desc()).limit(1)).scalar_one_or_none() or GENESIS
            conn.execute(certificates.insert().values(
                **dataclasses.asdict(record), pdf=pdf,
                chain_sha256=link(previous, dataclasses.asdict(record))))
            if original is not None:
                conn.execute(certificates.update().where(
                    certificates.c.number == original.number).values(
                    status="superseded", superseded_by=number))
        return record, pdf

    @staticmethod
    def clock() -> dt.datetime:
        """The time of issue (a test sets its own)."""
        return dt.datetime.now(dt.timezone.utc)

    def _current(self, conn, number: str) -> CertificateRecord:
        record = self._get(conn, number)
        if record.status != "issued":
            raise RegisterError(message(
                QT_TR_NOOP("{number} was superseded by {superseded_by}: amend or replace that one"),
                number=number, superseded_by=record.superseded_by))
        return record

    # -- reading --------------------------------------------------------------------------
    def _get(self, conn, number: str) -> CertificateRecord:
        certificates = self._schema.CERTIFICATES
        row = conn.execute(self._sa.select(*(certificates.c[c] for c in _RECORD_COLUMNS)).where(
            certificates.c.number == number)).first()
        if row is None:
            raise RegisterError(message(
                QT_TR_NOOP("no certificate {number} in the register"),
                number=number))
        return CertificateRecord(**row._asdict())

    def get(self, number: str) -> CertificateRecord:
        with self._read() as conn:
            return self._get(conn, number)

    def pdf(self, number: str, checked: bool = True) -> bytes:
        """Return the PDF as issued. With ``checked``, raise RegisterError when it no longer
        matches the SHA-256 recorded at issue, so that a PDF changed in the database is never
        handed out as the issued one."""
        certificates = self._schema.CERTIFICATES
        with self._read() as conn:
            row = conn.execute(self._sa.select(certificates.c.pdf, certificates.c.pdf_sha256)
                               .where(certificates.c.number == number)).first()
        if row is None:
            raise RegisterError(message(
                QT_TR_NOOP("no certificate {number} in the register"),
                number=number))
        data = bytes(row.pdf)
        if checked and hashlib.sha256(data).hexdigest() != row.pdf_sha256:
            raise RegisterError(message(QT_TR_NOOP(
                "the stored PDF of {number} no longer matches the SHA-256 recorded when it was "
                "issued: it was changed in the database; it is not exported"), number=number))
        return data

    def audit(self, pdfs: bool = False) -> list:
        """List what was changed in the database after issue, one message per finding (an
        empty list when nothing was found). The hash chain is recomputed over every record,
        each record's status is checked against the record that supersedes it, and with
        ``pdfs`` each stored PDF is checked against its SHA-256."""
        sa, certificates = self._sa, self._schema.CERTIFICATES
        columns = ("id", *CHAINED, "status", "superseded_by", "chain_sha256")
        problems: list = []
        previous = GENESIS
        superseders: dict[str, str] = {}
        with self._read() as conn:
            rows = conn.execute(sa.select(*(certificates.c[c] for c in columns))
                                .order_by(certificates.c.id)).all()
            for row in rows:
                previous = link(previous, row._asdict())
                if row.chain_sha256 != previous:
                    problems.append(message(QT_TR_NOOP(
                        "record {number}: the hash chain is broken here (this record, or one "
                        "before it, was changed, inserted or deleted after issue)"),
                        number=row.number))
                    previous = row.chain_sha256 or previous  # report each break once
                if row.supersedes:
                    superseders[row.supersedes] = row.number
                if pdfs:
                    data = conn.execute(sa.select(certificates.c.pdf).where(
                        certificates.c.id == row.id)).scalar_one()
                    if hashlib.sha256(bytes(data)).hexdigest() != row.pdf_sha256:
                        problems.append(message(QT_TR_NOOP(
                            "record {number}: the stored PDF does not match the SHA-256 "
                            "recorded at issue"), number=row.number))
        for row in rows:
            by = superseders.get(row.number)
            if (row.status, row.superseded_by) != (("superseded", by) if by else ("issued", None)):
                problems.append(message(QT_TR_NOOP(
                    "record {number}: marked \"{status}\" (superseded by {marked}), but the "
                    "register's records say {by}"), number=row.number, status=row.status,
                    marked=row.superseded_by or "—",
                    by=by and message(QT_TR_NOOP("superseded by {number}"), number=by)
                    or message(QT_TR_NOOP("issued, superseded by none"))))
        return problems

    def chain_head(self) -> str:
        """The chain after the last record (GENESIS for an empty register): noted outside the
        database, it anchors every record issued before."""
        certificates = self._schema.CERTIFICATES
        with self._read() as conn:
            return conn.execute(self._sa.select(certificates.c.chain_sha256).order_by(
                certificates.c.id.desc()).limit(1)).scalar_one_or_none() or GENESIS

    def list(self, search: str = "", limit: int = 10_000) -> list[CertificateRecord]:
        """Newest first; ``search`` matches the number, the serial or the customer (any case)."""
        sa, certificates = self._sa, self._schema.CERTIFICATES
        query = sa.select(*(certificates.c[c] for c in _RECORD_COLUMNS))
        if search.strip():
            pattern = f"%{search.strip().lower()}%"
            query = query.where(sa.or_(*(sa.func.lower(certificates.c[c]).like(pattern)
                                         for c in ("number", "item_serial", "customer"))))
        query = query.order_by(certificates.c.id.desc()).limit(limit)
        with self._read() as conn:
            return [CertificateRecord(**row._asdict()) for row in conn.execute(query)]

    def verify(self, pdf: bytes) -> CertificateRecord | None:
        """The record whose PDF is byte for byte this one (by SHA-256), or None."""
        certificates = self._schema.CERTIFICATES
        digest = hashlib.sha256(pdf).hexdigest()
        with self._read() as conn:
            number = conn.execute(self._sa.select(certificates.c.number).where(
                certificates.c.pdf_sha256 == digest)).scalar_one_or_none()
            return None if number is None else self._get(conn, number)

    def history(self, serial: str) -> list[CertificateRecord]:
        """Every certificate of an instrument, oldest calibration first."""
        certificates = self._schema.CERTIFICATES
        with self._read() as conn:
            rows = conn.execute(self._sa.select(*(certificates.c[c] for c in _RECORD_COLUMNS))
                                .where(certificates.c.item_serial == serial)
                                .order_by(certificates.c.calibration_date, certificates.c.id))
            return [CertificateRecord(**row._asdict()) for row in rows]

    # -- calibration intervals -------------------------------------------------------------
    def set_interval(self, serial: str, days: int | None) -> None:
        instruments = self._schema.INSTRUMENTS
        with self._write() as conn:
            conn.execute(instruments.delete().where(instruments.c.serial == serial))
            if days:
                if days < 1:
                    raise RegisterError(message(
                        QT_TR_NOOP("a calibration interval is a positive number of days")))
                conn.execute(instruments.insert().values(serial=serial, interval_days=int(days)))

    def interval(self, serial: str) -> int | None:
        instruments = self._schema.INSTRUMENTS
        with self._read() as conn:
            return conn.execute(self._sa.select(instruments.c.interval_days).where(
                instruments.c.serial == serial)).scalar_one_or_none()

    def due_date(self, serial: str) -> dt.date | None:
        """The last calibration of the serial plus its interval (None without either)."""
        days = self.interval(serial)
        dates = [r.calibration_date for r in self.history(serial) if r.calibration_date]
        if not days or not dates:
            return None
        return dt.date.fromisoformat(max(dates)) + dt.timedelta(days=days)


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


def _amendment_count(conn, register: Register, record: CertificateRecord) -> int:
    certificates = register._schema.CERTIFICATES
    root = _root(record)
    return conn.execute(register._sa.select(register._sa.func.count()).where(
        certificates.c.number.like(f"{root}-A%"))).scalar_one()


def _with_metadata(project_json: str, workbench: str, meta: CertificateMetadata) -> str:
    """The project state with the certificate's final details (its number) in it."""
    data = json.loads(project_json)
    certificates = dict(data.get("metadata", {}).get("certificates", {}))
    certificates[workbench] = meta.to_dict()
    data.setdefault("metadata", {})["certificates"] = certificates
    return json.dumps(data, ensure_ascii=False)


def _reason(exc: Exception) -> str:
    text = str(getattr(exc, "orig", None) or exc).strip().splitlines()
    return text[0] if text else type(exc).__name__


def _sqlite_connect(dbapi_connection, _record) -> None:
    dbapi_connection.isolation_level = None  # the driver's own transactions off: ours below
    cursor = dbapi_connection.cursor()
    cursor.execute("PRAGMA journal_mode=WAL")
    cursor.execute("PRAGMA busy_timeout=60000")
    cursor.close()


def _sqlite_begin(conn) -> None:
    conn.exec_driver_sql("BEGIN IMMEDIATE")
