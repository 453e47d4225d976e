"""The register's tables and their numbered migrations.

``schema_version`` holds the version a register is at; opening it applies every later
migration in one transaction, so an old register opens in a newer AngleBench. A register
made by a newer AngleBench than this one is refused, not guessed at; so is a version set
back (the structures of a later version are there, or the copy of the version in
``register_state`` differs): a migration never recomputes a chain over records that have
one (migration 4 proves the existing chain first and keeps its values). The transaction
makes each opening's migrations all or nothing: one that fails or is killed half-way
(migration 7 makes a table anew) leaves the register at its old version, whole.
"""

from __future__ import annotations

from collections.abc import Callable

import sqlalchemy as sa

__all__ = ["CERTIFICATES", "COUNTERS", "ENTRIES", "INSTRUMENTS", "LATEST", "METADATA",
           "MIGRATIONS", "READINGS_IDENTITY_COLUMNS", "READINGS_IDENTITY_VERSION",
           "READINGS_KEY_VERSION", "READ_AS_IS", "SCHEMA_VERSION", "STATE",
           "downgrade_evidence", "intervals_per_serial"]

METADATA = sa.MetaData()

SCHEMA_VERSION = sa.Table("schema_version", METADATA, sa.Column("version", sa.Integer,
                                                                nullable=False))

#: the last number allocated per scheme (the scheme with its date fields filled in)
COUNTERS = sa.Table(
    "counters", METADATA,
    sa.Column("name", sa.String(200), primary_key=True),
    sa.Column("last_value", sa.Integer, nullable=False),
)

CERTIFICATES = sa.Table(
    "certificates", METADATA,
    sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
    sa.Column("number", sa.String(200), nullable=False, unique=True),
    sa.Column("issued_at", sa.String(40), nullable=False),  # UTC, ISO 8601
    sa.Column("issue_date", sa.String(10), nullable=False),
    sa.Column("calibration_date", sa.String(10), nullable=False),
    sa.Column("workbench", sa.String(40), nullable=False),
    sa.Column("item_description", sa.Text, nullable=False),
    sa.Column("item_manufacturer", sa.Text, nullable=False),
    sa.Column("item_serial", sa.String(200), nullable=False),
    sa.Column("customer", sa.Text, nullable=False),
    sa.Column("operator", sa.Text, nullable=False),
    sa.Column("workstation", sa.Text, nullable=False),
    sa.Column("status", sa.String(20), nullable=False),  # issued | superseded
    sa.Column("supersedes", sa.String(200), nullable=True),  # the original's number
    sa.Column("superseded_by", sa.String(200), nullable=True),
    sa.Column("revision", sa.String(20), nullable=False),  # original | amendment N | replacement
    sa.Column("change_note", sa.Text, nullable=False),
    sa.Column("project_json", sa.Text, nullable=False),  # readings as typed, settings, metadata
    sa.Column("software_json", sa.Text, nullable=False),  # software and library versions
    sa.Column("headline_json", sa.Text, nullable=False),  # figures for the trend
    sa.Column("pdf_sha256", sa.String(64), nullable=False),
    sa.Column("pdf", sa.LargeBinary, nullable=False),
    # the hash chain over the records in the order of issue (migration 3; models/register/chain)
    sa.Column("chain_sha256", sa.String(64), nullable=True),
    # migration 4: the record's place in the chain (shared with ENTRIES), the counter and
    # value its number was allocated from, who issued it (the operating-system user) and
    # approved it, and which fields the chain covers (1: CHAINED; 2: CHAINED + CHAINED_V2)
    sa.Column("seq", sa.Integer, nullable=True),
    sa.Column("counter", sa.String(200), nullable=True),
    sa.Column("counter_value", sa.Integer, nullable=True),
    sa.Column("os_user", sa.Text, nullable=True),
    sa.Column("approver", sa.Text, nullable=True),
    sa.Column("withdrawn_reason", sa.Text, nullable=True),
    sa.Column("chain_format", sa.Integer, nullable=True),
    # HMAC-SHA256 of chain_sha256 with the laboratory's key kept outside the database
    # (models/register/signing.py); None when the lab signs nothing
    sa.Column("signature", sa.String(64), nullable=True),
    # migration 5: the digital calibration certificate (DCC XML) issued with the PDF and its
    # SHA-256 (in the chain: chain_format 3); both None for a certificate issued without one
    sa.Column("dcc", sa.LargeBinary, nullable=True),
    sa.Column("dcc_sha256", sa.String(64), nullable=True),
    # migration 6: what the document is, "calibration" (a calibration certificate) or "test"
    # (a test report: asked for, or a result that cannot state traceability), in the chain
    # of every record issued since (chain format 4); None on a record issued before it: not
    # recorded, never guessed
    sa.Column("document_kind", sa.String(20), nullable=True),
    # migration 8: the identity of the record's readings by their values
    # (models/register/readings_identity.readings_key: "" for none), made at issue and filled
    # in once for the records before it, looked up by the index certificates_readings_key
    # (one item's readings issued as another's, a withdrawn certificate's readings reissued);
    # in the chain of every record issued since (chain format 7: a key set otherwise is
    # found at opening); for the records the migration filled it in for, not (it is made
    # from the project state, which is): 'register verify' makes it again from the
    # readings and reports one that differs. None: issued by an
    # AngleBench of schema 7 still running after the migration, made when it is compared
    sa.Column("readings_key", sa.String(64), nullable=True),
    # migration 9: the identity of the record's readings by their physical values, within
    # the resolution each was typed to (models/register/readings_identity.readings_identity:
    # "", 0, 0 for none), by which the register finds readings issued again re-typed (in
    # decimal degrees, another unit: ident80): the layout (an exact key), the anchor and its
    # reach (in 2⁻⁴⁰ rad or m), looked up by the indexes certificates_readings_anchor and
    # certificates_readings_reach; made at issue and filled in once for the records before
    # it; in the chain of every record issued since (chain format 8), made again from the
    # readings by 'register verify' for every record. None: not made (issued by an AngleBench
    # of schema 8 still running after the migration), made when compared
    sa.Column("readings_layout", sa.String(64), nullable=True),
    sa.Column("readings_anchor", sa.BigInteger, nullable=True),
    sa.Column("readings_reach", sa.BigInteger, nullable=True),
)

#: the register's other records, chained with the certificates (migration 4): calibration
#: intervals set, numbering continued, certificates withdrawn, the baseline at migration
ENTRIES = sa.Table(
    "entries", METADATA,
    sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
    sa.Column("seq", sa.Integer, nullable=False, unique=True),
    # interval | numbering | withdrawal | results | signatories | missing (a certificate shown
    # to verify whose record was gone: Register.record_missing)
    sa.Column("kind", sa.String(40), nullable=False),
    sa.Column("subject", sa.String(200), nullable=False),  # serial, counter or number
    sa.Column("body_json", sa.Text, nullable=False),
    sa.Column("recorded_at", sa.String(40), nullable=False),
    sa.Column("os_user", sa.Text, nullable=False),
    sa.Column("workstation", sa.Text, nullable=False),
    sa.Column("chain_sha256", sa.String(64), nullable=False),
    sa.Column("signature", sa.String(64), nullable=True),
)

#: what the register knows of itself, updated in the transaction of every record: the
#: number of records in the chain, its head, and a copy of the schema version (migration 4)
STATE = sa.Table(
    "register_state", METADATA,
    sa.Column("name", sa.String(40), primary_key=True),
    sa.Column("value", sa.Text, nullable=False),
)

#: per instrument, its serial and manufacturer, the calibration interval (migration 7; ""
#: is every maker's item of the serial, as an interval set before it or without a maker).
#: Migration 2 kept it per serial in a table "instruments", which migration 7 replaces by
#: this one under another name: an AngleBench of schema 6 still running against a migrated
#: register (opened before the migration, or on another PC) fails with "no such table" on
#: the intervals instead of deleting every maker's interval of a serial unrecorded (rev65 F3)
INSTRUMENTS = sa.Table(
    "calibration_intervals", METADATA,
    sa.Column("serial", sa.String(200), primary_key=True),
    sa.Column("manufacturer", sa.Text, primary_key=True, nullable=False, server_default=""),
    sa.Column("interval_days", sa.Integer, nullable=False),
)


def intervals_per_serial() -> sa.Table:
    """The intervals' table as versions 2 to 6 have it: "instruments", per serial (a
    read-only register of version 6 is read as it is)."""
    return sa.Table("instruments", sa.MetaData(), sa.Column("serial", sa.String(200), primary_key=True),
                    sa.Column("interval_days", sa.Integer, nullable=False))


_V1_CERTIFICATE_COLUMNS = (
    "id", "number", "issued_at", "issue_date", "calibration_date", "workbench",
    "item_description", "item_manufacturer", "item_serial", "customer", "operator",
    "workstation", "status", "supersedes", "superseded_by", "revision", "change_note",
    "project_json", "software_json", "headline_json", "pdf_sha256", "pdf")


def _v1(conn: sa.Connection) -> None:
    COUNTERS.create(conn)
    # the table as version 1 made it (later migrations add their columns)
    sa.Table("certificates", sa.MetaData(),
             *(CERTIFICATES.c[name]._copy() for name in _V1_CERTIFICATE_COLUMNS)).create(conn)


def _v2(conn: sa.Connection) -> None:
    intervals_per_serial().create(conn)  # as version 2 made it (migration 7 adds the maker)
    conn.execute(sa.text("CREATE INDEX certificates_item_serial ON certificates (item_serial)"))


def _v3(conn: sa.Connection) -> None:
    """Add the hash chain. Add its column (unless version 1 already created the table with
    it), then compute the chain over the records already issued, in the order of issue.
    The chain vouches for those records as they are now: a change made before this
    migration cannot be detected. A register whose records already carry chain values is
    never given a new chain (see :func:`downgrade_evidence`)."""
    from models.register.chain import CHAINED, GENESIS, link

    columns = {c["name"] for c in sa.inspect(conn).get_columns("certificates")}
    if "chain_sha256" not in columns:
        conn.execute(sa.text("ALTER TABLE certificates ADD COLUMN chain_sha256 VARCHAR(64)"))
    elif conn.execute(sa.text("SELECT COUNT(*) FROM certificates WHERE chain_sha256 IS NOT "
                              "NULL")).scalar_one():
        raise ValueError("the records already carry a hash chain")
    previous = GENESIS
    rows = conn.execute(sa.select(CERTIFICATES.c.id, *(CERTIFICATES.c[k] for k in CHAINED))
                        .order_by(CERTIFICATES.c.id)).all()
    for row in rows:
        previous = link(previous, row._asdict())
        conn.execute(CERTIFICATES.update().where(CERTIFICATES.c.id == row.id).values(
            chain_sha256=previous))


_V4_COLUMNS = ("seq INTEGER", "counter VARCHAR(200)", "counter_value INTEGER", "os_user TEXT",
               "approver TEXT", "withdrawn_reason TEXT", "chain_format INTEGER",
               "signature VARCHAR(64)")


def _v4(conn: sa.Connection) -> None:
    """Chain positions, the state row, the entries table. The existing chain is proved
    first (a broken one is refused, never recomputed) and kept value for value; each record
    gets its place; the counters and intervals as they stand are recorded as chained
    baseline entries (the records behind them predate the cross-check)."""
    problem = verify_v1_chain(conn)
    if problem:
        raise ValueError(problem)
    for column in _V4_COLUMNS:
        conn.execute(sa.text(f"ALTER TABLE certificates ADD COLUMN {column}"))
    ENTRIES.create(conn)
    STATE.create(conn)
    ids = conn.execute(sa.select(CERTIFICATES.c.id).order_by(CERTIFICATES.c.id)).scalars().all()
    for seq, row_id in enumerate(ids, 1):
        conn.execute(CERTIFICATES.update().where(CERTIFICATES.c.id == row_id).values(
            seq=seq, chain_format=1))
    append_baseline(conn, len(ids))


def _v5(conn: sa.Connection) -> None:
    """The digital calibration certificate beside the PDF: two nullable columns. No record's
    chain value is touched (the records issued before keep their chain format; only records
    issued with a DCC use chain format 3, which covers its SHA-256); the chain is proved by
    the audit every opening runs right after the migration. Refused when the columns exist
    already (a version set back)."""
    columns = {c["name"] for c in sa.inspect(conn).get_columns("certificates")}
    if {"dcc", "dcc_sha256"} & columns:
        raise ValueError("the columns of version 5 exist already")
    blob = conn.dialect.type_compiler_instance.process(sa.LargeBinary())
    conn.execute(sa.text(f"ALTER TABLE certificates ADD COLUMN dcc {blob}"))
    conn.execute(sa.text("ALTER TABLE certificates ADD COLUMN dcc_sha256 VARCHAR(64)"))


def _v6(conn: sa.Connection) -> None:
    """What each document is (a calibration certificate or a test report): one nullable
    column. No record's chain value is touched: the records issued before keep their chain
    format and their kind None ("not recorded": a test report issued by 0.8.11 is not told
    from a certificate afterwards, so nothing is guessed); records issued since have chain
    format 4, which covers the kind. Refused when the column exists already (a version set
    back)."""
    columns = {c["name"] for c in sa.inspect(conn).get_columns("certificates")}
    if "document_kind" in columns:
        raise ValueError("the column of version 6 exists already")
    conn.execute(sa.text("ALTER TABLE certificates ADD COLUMN document_kind VARCHAR(20)"))


def _v7(conn: sa.Connection) -> None:
    """The calibration interval per maker's serial (stop 63: two makers' serial "001"
    shared one interval): the table "calibration_intervals", keyed by (serial,
    manufacturer), is made, the rows of "instruments" copied into it with manufacturer ""
    (every maker's item of the serial: what they meant) and "instruments" dropped — in the
    migration's one transaction, so a migration killed or failing half-way leaves version 6
    as it was. A new name, not the old one's key changed: an AngleBench of schema 6 still
    running (opened before the migration, or an old install sharing the register) checks
    the version only at opening, and its "DELETE FROM instruments WHERE serial = ?" removed
    every maker's interval of the serial, unrecorded (rev65 F3); on the new name its every
    statement on the intervals fails ("no such table: instruments") and rolls back. No
    record's or entry's chain value is touched: the interval entries already chained
    (subject the serial, no maker in their body) are the intervals of maker "" the audit's
    cross-check compares the table with, so the chain and the cross-check verify as before.
    Refused when the table exists already (a version set back)."""
    if "calibration_intervals" in sa.inspect(conn).get_table_names():
        raise ValueError("the table of version 7 exists already")
    old = intervals_per_serial()
    rows = conn.execute(sa.select(old.c.serial, old.c.interval_days)).all()
    INSTRUMENTS.create(conn)
    if rows:
        conn.execute(INSTRUMENTS.insert(), [{"serial": r.serial, "manufacturer": "",
                                             "interval_days": r.interval_days} for r in rows])
    old.drop(conn)


def _v8(conn: sa.Connection) -> None:
    """The readings' identity stored with each record (readings_identity.readings_key), and
    its index: every issue compared the readings with every record's of the workbench,
    made again from each record's project state (~2 ms a record: 20 s an issue for a
    register of 10,000). One nullable column, filled in here once for every record from
    its project state (in the chain), in the migration's one transaction; no record's
    chain value is touched. Refused when the column exists already (a version set back)."""
    from models.register.readings_identity import readings_key

    columns = {c["name"] for c in sa.inspect(conn).get_columns("certificates")}
    if "readings_key" in columns:
        raise ValueError("the column of version 8 exists already")
    conn.execute(sa.text("ALTER TABLE certificates ADD COLUMN readings_key VARCHAR(64)"))
    conn.execute(sa.text("CREATE INDEX certificates_readings_key ON certificates "
                         "(workbench, readings_key)"))
    c = CERTIFICATES.c
    rows = conn.execute(sa.select(c.id, c.workbench, c.project_json).order_by(c.id)).all()
    if rows:
        conn.execute(CERTIFICATES.update().where(c.id == sa.bindparam("row_id")).values(
            readings_key=sa.bindparam("key")),
            [{"row_id": r.id, "key": readings_key(r.project_json, r.workbench)} for r in rows])


#: the columns of migration 9 (CERTIFICATES: the readings' identity by their physical values)
READINGS_IDENTITY_COLUMNS = ("readings_layout", "readings_anchor", "readings_reach")


def _v9(conn: sa.Connection) -> None:
    """The readings' identity by their physical values (readings_identity.readings_identity:
    the same readings re-typed in decimal degrees or in another unit escaped readings_key,
    ident80), and its indexes. Three nullable columns, filled in here once for every record
    from its project state (in the chain), in the migration's one transaction, as migration
    8's; no record's chain value is touched (readings_key, in the chains of format 7, is
    kept as it is). Refused when the columns exist already (a version set back)."""
    from models.register.readings_identity import NO_READINGS, readings_identity

    columns = {c["name"] for c in sa.inspect(conn).get_columns("certificates")}
    if set(READINGS_IDENTITY_COLUMNS) & columns:
        raise ValueError("the columns of version 9 exist already")
    big = conn.dialect.type_compiler_instance.process(sa.BigInteger())
    conn.execute(sa.text("ALTER TABLE certificates ADD COLUMN readings_layout VARCHAR(64)"))
    conn.execute(sa.text(f"ALTER TABLE certificates ADD COLUMN readings_anchor {big}"))
    conn.execute(sa.text(f"ALTER TABLE certificates ADD COLUMN readings_reach {big}"))
    conn.execute(sa.text("CREATE INDEX certificates_readings_anchor ON certificates "
                         "(workbench, readings_layout, readings_anchor)"))
    conn.execute(sa.text("CREATE INDEX certificates_readings_reach ON certificates "
                         "(workbench, readings_layout, readings_reach)"))
    c = CERTIFICATES.c
    rows = conn.execute(sa.select(c.id, c.workbench, c.project_json).order_by(c.id)).all()
    values = []
    for r in rows:
        identity = readings_identity(r.project_json, r.workbench)
        layout, anchor, reach = NO_READINGS if identity is None else identity.stored
        values.append({"row_id": r.id, "layout": layout, "anchor": anchor, "reach": reach})
    if values:
        conn.execute(CERTIFICATES.update().where(c.id == sa.bindparam("row_id")).values(
            readings_layout=sa.bindparam("layout"), readings_anchor=sa.bindparam("anchor"),
            readings_reach=sa.bindparam("reach")), values)


#: version → the migration that brings a register to it from the version before
MIGRATIONS: dict[int, Callable[[sa.Connection], None]] = {1: _v1, 2: _v2, 3: _v3, 4: _v4,
                                                          5: _v5, 6: _v6, 7: _v7, 8: _v8,
                                                          9: _v9}
LATEST = max(MIGRATIONS)
#: versions a read-only register (which cannot be migrated) is read at as it is: version 6
#: differs from 7 only by the intervals' key, read as every maker's item's (store._intervals);
#: versions 6 and 7 from 8 only by the readings' stored identity, made when compared; 6 to 8
#: from 9 only by the readings' identity by their physical values, made when compared
READ_AS_IS = frozenset({6, 7, 8})
#: the first version that stores the readings' identity (CERTIFICATES.c.readings_key)
READINGS_KEY_VERSION = 8
#: the first version that stores it by the readings' physical values (readings_layout …)
READINGS_IDENTITY_VERSION = 9


def downgrade_evidence(conn: sa.Connection, version: int) -> str:
    """Why ``version`` (read from ``schema_version``) cannot be this register's: a later
    version's structures are present, or the state's copy of the version differs; "" when
    nothing says so."""
    inspector = sa.inspect(conn)
    tables = set(inspector.get_table_names())
    if version < 1 or version > LATEST:
        return ""  # an unknown version is refused by the caller
    if "register_state" in tables:
        copy = conn.execute(sa.select(STATE.c.value).where(STATE.c.name == "schema_version")
                            ).scalar_one_or_none()
        if version < 4 or copy != str(version):
            return f"register_state records schema version {copy}"
    if version < 2 and "instruments" in tables:
        return "the table of version 2 (instruments) exists"
    if version < 6 and "certificates" in tables:
        columns = {c["name"] for c in inspector.get_columns("certificates")}
        if "document_kind" in columns:
            return "the column of version 6 exists"
    if version < 5 and "certificates" in tables:
        columns = {c["name"] for c in inspector.get_columns("certificates")}
        if "dcc_sha256" in columns:
            return "the columns of version 5 exist"
    if version < 4 and "certificates" in tables:
        columns = {c["name"] for c in inspector.get_columns("certificates")}
        if "seq" in columns or "entries" in tables:
            return "the columns of version 4 exist"
        if version < 3 and "chain_sha256" in columns and conn.execute(sa.text(
                "SELECT COUNT(*) FROM certificates WHERE chain_sha256 IS NOT NULL")).scalar_one():
            return "the records carry the hash chain of version 3"
    if version < 7 and "calibration_intervals" in tables:
        return "the table of version 7 (calibration_intervals) exists"
    if version < 8 and "certificates" in tables:
        columns = {c["name"] for c in inspector.get_columns("certificates")}
        if "readings_key" in columns:
            return "the column of version 8 (readings_key) exists"
    if version < 9 and "certificates" in tables:
        columns = {c["name"] for c in inspector.get_columns("certificates")}
        if "readings_layout" in columns:
            return "the columns of version 9 (readings_layout …) exist"
    return ""


def verify_v1_chain(conn) -> str:
    """The chain of a version-3 register recomputed over its records: "" when every stored
    value is what it should be, else which record breaks it."""
    from models.register.chain import CHAINED, GENESIS, link

    previous = GENESIS
    rows = conn.execute(sa.select(CERTIFICATES.c.number, CERTIFICATES.c.chain_sha256,
                                  *(CERTIFICATES.c[k] for k in CHAINED))
                        .order_by(CERTIFICATES.c.id)).all()
    for row in rows:
        previous = link(previous, row._asdict())
        if row.chain_sha256 != previous:
            return (f"record {row.number}: the hash chain is broken here (this record, or one "
                    "before it, was changed, inserted or deleted after issue)")
    return ""


def append_baseline(conn, records: int) -> None:
    """Migration 4: the counters and intervals as they stand, recorded as chained entries
    after the ``records`` certificates, and the state row written."""
    import datetime as dt
    import getpass
    import json
    import socket

    from models.register.chain import GENESIS, link_entry

    head = conn.execute(sa.select(CERTIFICATES.c.chain_sha256).order_by(
        CERTIFICATES.c.id.desc()).limit(1)).scalar_one_or_none() or GENESIS
    seq = records
    now = dt.datetime.now(dt.timezone.utc).replace(microsecond=0).isoformat()
    try:
        user = getpass.getuser()
    except (KeyError, OSError):
        user = ""
    baseline = [("numbering", name, {"last_value": value, "baseline": True})
                for name, value in conn.execute(sa.select(COUNTERS.c.name, COUNTERS.c.last_value)
                                                .order_by(COUNTERS.c.name))]
    instruments = intervals_per_serial()  # as version 4 finds it
    baseline += [("interval", serial, {"days": days, "baseline": True})
                 for serial, days in conn.execute(sa.select(
                     instruments.c.serial, instruments.c.interval_days)
                     .order_by(instruments.c.serial))]
    for kind, subject, body in baseline:
        seq += 1
        entry = {"seq": seq, "kind": kind, "subject": subject,
                 "body_json": json.dumps(body, sort_keys=True), "recorded_at": now,
                 "os_user": user, "workstation": socket.gethostname()}
        head = link_entry(head, entry)
        conn.execute(ENTRIES.insert().values(**entry, chain_sha256=head))
    for name, value in (("records", str(seq)), ("head", head), ("schema_version", "4")):
        conn.execute(STATE.insert().values(name=name, value=value))
