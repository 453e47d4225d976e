"""#43: the register keeps the digital calibration certificate (DCC XML) issued with a PDF,
its SHA-256 in the hash chain (chain format 3); a version-4 register migrates keeping every
chain value; what a hostile user does to the DCC behind AngleBench's back is found."""

from __future__ import annotations

import datetime as dt
import hashlib

import pytest
import sqlalchemy as sa

from models.certificate.metadata import CertificateMetadata
from models.register import schema
from models.register.store import IssueRequest, Register, RegisterError
from tests import dcc_documents as t

META = CertificateMetadata(item_serial="PG-12", item_description="Polygon",
                           customer_name="Acme Optics", calibration_date="2026-11-20",
                           number_scheme="AB-{year}-{seq:04d}", approver="Dr. Li")
PROJECT = '{"format": "anglebench-project", "schema_version": 1, "workbenches": {}}'
ISSUED = dt.datetime(2026, 11, 24, 10, 0, tzinfo=dt.timezone.utc)


def render(meta: CertificateMetadata, head: str = "") -> bytes:
    return f"%PDF {meta.certificate_number} head {head}".encode()


def render_dcc(meta: CertificateMetadata, pdf: bytes) -> bytes:
    """A DCC with the final number and the PDF just rendered inside (as the writer does)."""
    return t.document(meta.certificate_number, pdf=pdf)


def _open(url: str) -> Register:
    register = Register(url, timezone="UTC")
    register.clock = lambda: ISSUED
    return register


def sql(url: str, *statements: str, **params) -> None:
    engine = sa.create_engine(url.replace("postgresql://", "postgresql+psycopg://"))
    with engine.begin() as conn:
        for statement in statements:
            conn.execute(sa.text(statement), params)
    engine.dispose()


@pytest.fixture
def issued(register_url):
    """A register with a certificate without a DCC, two with one, and an interval."""
    with _open(register_url) as register:
        plain = register.issue(IssueRequest("polygon", META, PROJECT), render)[0]
        with_dcc = [register.issue(IssueRequest("polygon", META, PROJECT), render,
                                   render_dcc=render_dcc)[0] for _ in range(2)]
        register.set_interval("PG-12", 365)
        assert register.problems == [] and register.audit(pdfs=True) == []
    return register_url, plain, with_dcc


def test_the_dcc_is_stored_with_the_same_number_and_pdf_and_chained(issued):
    url, plain, with_dcc = issued
    with _open(url) as register:
        # chain format 4 and later (7: schema 8) covers the DCC's SHA-256, None here, and the kind
        assert plain.chain_format == 8 and plain.dcc_sha256 is None
        with pytest.raises(RegisterError, match="issued without a digital calibration"):
            register.dcc(plain.number)
        for record in with_dcc:
            dcc = register.dcc(record.number)
            assert record.chain_format == 8
            assert record.dcc_sha256 == hashlib.sha256(dcc).hexdigest()
            assert register.get(record.number).dcc_sha256 == record.dcc_sha256
            t.assert_valid(dcc)
            assert f"<dcc:uniqueIdentifier>{record.number}<".encode() in dcc
            from models.dcc.reader import embedded_pdfs

            assert embedded_pdfs(dcc) == [register.pdf(record.number)]


def test_a_failing_render_dcc_leaves_no_record_and_uses_no_number(register_url):
    with _open(register_url) as register:
        def broken(meta, pdf):
            raise ValueError("the DCC is not valid")
        with pytest.raises(ValueError, match="not valid"):
            register.issue(IssueRequest("polygon", META, PROJECT), render, render_dcc=broken)
        assert register.list() == []
        record = register.issue(IssueRequest("polygon", META, PROJECT), render,
                                render_dcc=render_dcc)[0]
        assert record.number == "AB-2026-0001"


@pytest.mark.parametrize("attack", ["blob", "blob_and_hash", "null", "null_and_hash",
                                    "downgrade", "add_to_plain", "other_pdf"])
def test_a_hostile_change_to_a_dcc_is_found(issued, attack):
    url, plain, with_dcc = issued
    target = with_dcc[0].number
    forged = t.document(target, pdf=b"%PDF forged")
    digest = hashlib.sha256(forged).hexdigest()
    statements = {
        "blob": ("UPDATE certificates SET dcc = :forged WHERE number = :n",),
        "blob_and_hash": ("UPDATE certificates SET dcc = :forged, dcc_sha256 = :digest WHERE "
                          "number = :n",),
        "null": ("UPDATE certificates SET dcc = NULL WHERE number = :n",),
        "null_and_hash": ("UPDATE certificates SET dcc = NULL, dcc_sha256 = NULL WHERE "
                          "number = :n",),
        "downgrade": ("UPDATE certificates SET dcc = NULL, dcc_sha256 = NULL, chain_format = 2 "
                      "WHERE number = :n",),
        "add_to_plain": ("UPDATE certificates SET dcc = :forged, dcc_sha256 = :digest WHERE "
                         "number = :p",),
        "other_pdf": ("UPDATE certificates SET pdf = :pdf, pdf_sha256 = :pdfsha WHERE "
                      "number = :n",),
    }[attack]
    sql(url, *statements, forged=forged, digest=digest, n=target, p=plain.number,
        pdf=b"%PDF other", pdfsha=hashlib.sha256(b"%PDF other").hexdigest())
    with _open(url) as register:
        problems = [str(p) for p in register.audit(pdfs=True)]
        assert problems, attack
        name = plain.number if attack == "add_to_plain" else target
        assert any(name in p for p in problems), problems
        if attack in ("blob", "null"):  # chain intact: the content check finds it
            assert [str(p) for p in register.problems] == [] or attack == "null"
            with pytest.raises(RegisterError, match="stored DCC of"):
                register.dcc(target)
        if attack == "blob":
            assert any("stored DCC does not match" in p for p in problems)
        if attack in ("blob_and_hash", "null_and_hash", "downgrade", "other_pdf"):
            assert any("hash chain is broken" in p for p in problems)


def test_the_pdf_inside_the_dcc_must_be_the_stored_pdf(register_url):
    with _open(register_url) as register:
        record = register.issue(IssueRequest("polygon", META, PROJECT), render,
                                render_dcc=lambda meta, pdf: t.document(
                                    meta.certificate_number, pdf=pdf + b" changed"))[0]
        problems = [str(p) for p in register.audit(pdfs=True)]
        assert problems == [f"record {record.number}: the PDF embedded in its DCC is not the "
                            "stored PDF (1 PDF(s) embedded): the two forms of the certificate "
                            "differ"]


def _as_version_4(url: str) -> str:
    """The register as schema version 4 left it: its records of chain format 2, chained by
    that format's rule (SHA-256 over the previous value and the issued fields as sorted
    JSON, written out here), no DCC or kind columns, the intervals per serial; the head
    returned."""
    import json

    from models.register.chain import CHAINED, CHAINED_V2

    engine = sa.create_engine(url.replace("postgresql://", "postgresql+psycopg://"))
    previous = "0" * 64
    with engine.begin() as conn:
        rows = conn.execute(sa.text("SELECT * FROM certificates ORDER BY seq")).mappings().all()
        for row in rows:
            fields = {**{k: row[k] for k in CHAINED + CHAINED_V2}, "chain_format": 2}
            body = json.dumps(fields, sort_keys=True, ensure_ascii=False, separators=(",", ":"))
            previous = hashlib.sha256(f"{previous}\n{body}".encode()).hexdigest()
            conn.execute(sa.text("UPDATE certificates SET chain_format = 2, chain_sha256 = :c "
                                 "WHERE id = :i"), {"c": previous, "i": row["id"]})
        for statement in ("DROP INDEX certificates_readings_anchor",
                          "DROP INDEX certificates_readings_reach",
                          "ALTER TABLE certificates DROP COLUMN readings_layout",
                          "ALTER TABLE certificates DROP COLUMN readings_anchor",
                          "ALTER TABLE certificates DROP COLUMN readings_reach",
                          "DROP INDEX certificates_readings_key",
                          "ALTER TABLE certificates DROP COLUMN readings_key",
                          "ALTER TABLE certificates DROP COLUMN dcc",
                          "ALTER TABLE certificates DROP COLUMN dcc_sha256",
                          "ALTER TABLE certificates DROP COLUMN document_kind",
                          # the intervals per serial, as version 2 made them (no interval set)
                          "DROP TABLE calibration_intervals",
                          "CREATE TABLE instruments (serial VARCHAR(200) PRIMARY KEY, "
                          "interval_days INTEGER NOT NULL)",
                          "UPDATE schema_version SET version = 4",
                          "UPDATE register_state SET value = '4' WHERE name = 'schema_version'"):
            conn.execute(sa.text(statement))
        conn.execute(sa.text("UPDATE register_state SET value = :h WHERE name = 'head'"),
                     {"h": previous})
    engine.dispose()
    return previous


def test_a_version_4_register_migrates_keeping_its_chain(register_url):
    """A register as schema version 4 left it (records of chain format 2, no DCC columns):
    migration 5 adds the columns, every chain value stays; new records chain their DCC."""
    with _open(register_url) as register:
        old = [register.issue(IssueRequest("polygon", META, PROJECT), render)[0]
               for _ in range(3)]
    head = _as_version_4(register_url)
    with _open(register_url) as register:
        assert register.version == schema.LATEST == 9
        assert register.problems == [] and register.find_head(head) == (3, head)
        kept = [register.get(r.number) for r in old]
        assert kept[-1].chain_sha256 == head and {r.chain_format for r in kept} == {2}
        assert {r.document_kind for r in kept} == {None}  # not recorded, never guessed
        new = register.issue(IssueRequest("polygon", META, PROJECT), render,
                             render_dcc=render_dcc)[0]
        assert new.chain_format == 8 and register.audit(pdfs=True) == []
    sql(register_url, "UPDATE schema_version SET version = 4",
        "UPDATE register_state SET value = '4' WHERE name = 'schema_version'")
    with pytest.raises(RegisterError, match="schema version 4 was set back"):
        Register(register_url)


def test_a_signed_dcc_is_checked_by_verify(register_url, tmp_path, monkeypatch):
    """With the lab's key and certificate configured the DCC is signed; the audit checks the
    signature (against the lab's certificate), and a DCC re-signed with another key after
    issue, its hash and chain recomputed aside, is found."""
    from models.dcc import signature

    key, cert = t.self_signed(tmp_path)
    (tmp_path / "lab.key").write_bytes(key)
    (tmp_path / "lab.pem").write_bytes(cert)
    monkeypatch.setenv(signature.KEY_ENV_VAR, str(tmp_path / "lab.key"))
    monkeypatch.setenv(signature.CERT_ENV_VAR, str(tmp_path / "lab.pem"))
    with _open(register_url) as register:
        record = register.issue(IssueRequest("polygon", META, PROJECT), render,
                                render_dcc=lambda meta, pdf: signature.sign_if_configured(
                                    render_dcc(meta, pdf)))[0]
        dcc = register.dcc(record.number)
        t.assert_valid(dcc)
        assert signature.verify(dcc, cert).problems == ()
        assert register.audit(pdfs=True) == []
    other_key, other_cert = t.self_signed(tmp_path, "Intruder")
    with _open(register_url) as register:
        pdf = register.pdf(record.number)
    forged = signature.sign(t.document(record.number, pdf=pdf), other_key, other_cert)
    digest = hashlib.sha256(forged).hexdigest()
    from dataclasses import asdict

    from models.register.chain import GENESIS, link

    chain = link(GENESIS, {**asdict(record), "dcc_sha256": digest})  # recomputed wholesale
    sql(register_url, "UPDATE certificates SET dcc = :d, dcc_sha256 = :h, chain_sha256 = :c "
        "WHERE number = :n", "UPDATE register_state SET value = :c WHERE name = 'head'",
        d=forged, h=digest, c=chain, n=record.number)
    with _open(register_url) as register:
        assert register.problems == []  # the chain and state agree: only the signature tells
        problems = [str(p) for p in register.audit(pdfs=True)]
        assert any("its DCC's signature: signed by CN=Intruder, which the trusted "
                   "certificate (CN=Test lab DCC signing) does not vouch for" in p
                   for p in problems), problems
    monkeypatch.delenv(signature.CERT_ENV_VAR)
    with pytest.raises(signature.SigningError, match="both are needed"):
        signature.sign_if_configured(b"<x/>")
    monkeypatch.delenv(signature.KEY_ENV_VAR)
    assert signature.sign_if_configured(b"<x/>") == b"<x/>"
