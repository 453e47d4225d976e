"""The register's tables and their numbered migrations.

``schema_version`` holds the version a register is at; opening it applies every later
migration in one transaction, so an old register opens in a newer AngleBench. A register
made by a newer AngleBench than this one is refused, not guessed at.
"""

from __future__ import annotations

from collections.abc import Callable

import sqlalchemy as sa

__all__ = ["CERTIFICATES", "COUNTERS", "INSTRUMENTS", "LATEST", "METADATA", "MIGRATIONS",
           "SCHEMA_VERSION"]

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
)

#: per instrument serial: the calibration interval (migration 2)
INSTRUMENTS = sa.Table(
    "instruments", METADATA,
    sa.Column("serial", sa.String(200), primary_key=True),
    sa.Column("interval_days", sa.Integer, nullable=False),
)


def _v1(conn: sa.Connection) -> None:
    for table in (COUNTERS, CERTIFICATES):
        table.create(conn)


def _v2(conn: sa.Connection) -> None:
    INSTRUMENTS.create(conn)
    conn.execute(sa.text("CREATE INDEX certificates_item_serial ON certificates (item_serial)"))


def _v3(conn: sa.Connection) -> None:
    """Add the hash chain. Add its column (unless version 1 already created the table with
    it), then compute the chain over the records already issued, in the order of issue.
    The chain vouches for those records as they are now: a change made before this
    migration cannot be detected."""
    from models.register.chain import CHAINED, GENESIS, link

    columns = {c["name"] for c in sa.inspect(conn).get_columns("certificates")}
    if "chain_sha256" not in columns:
        conn.execute(sa.text("ALTER TABLE certificates ADD COLUMN chain_sha256 VARCHAR(64)"))
    previous = GENESIS
    rows = conn.execute(sa.select(CERTIFICATES.c.id, *(CERTIFICATES.c[k] for k in CHAINED))
                        .order_by(CERTIFICATES.c.id)).all()
    for row in rows:
        previous = link(previous, row._asdict())
        conn.execute(CERTIFICATES.update().where(CERTIFICATES.c.id == row.id).values(
            chain_sha256=previous))


#: version → the migration that brings a register to it from the version before
MIGRATIONS: dict[int, Callable[[sa.Connection], None]] = {1: _v1, 2: _v2, 3: _v3}
LATEST = max(MIGRATIONS)
