"""What each document in the register is — a calibration certificate or a test report — is
recorded at issue and chained (schema version 6, chain format 4); a register made by
AngleBench 0.8.11 (schema version 5) opens, verifies and migrates with every chain value
as it was, its records' kind "not recorded" (never guessed); changing a kind after issue is
found."""

from __future__ import annotations

import datetime as dt
import hashlib
import json
import re
import shutil
import sqlite3
from pathlib import Path

import pytest
import sqlalchemy as sa

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.register import schema
from models.register.store import IssueRequest, Register, RegisterTampered

META = CertificateMetadata(item_serial="RT-1", item_description="Rotary table",
                           customer_name="Acme Optics", calibration_date="2026-11-20",
                           number_scheme="AB-{year}-{seq:04d}", approver="Dr. Li")
PROJECT = '{"format": "anglebench-project", "schema_version": 1, "workbenches": {}}'
ISSUED = dt.datetime(2026, 11, 25, 10, 0, tzinfo=dt.timezone.utc)
#: a register as AngleBench 0.8.11 (schema version 5) left it, made by that version's own
#: Register (PYTHONPATH at 0.8.11, stand-in PDFs, the DCC of tests/dcc_documents.py):
#: AB-2026-0001 issued without a DCC (chain format 2), AB-2026-0002 with one (format 3)
#: then withdrawn ("wrong item"), AB-2026-0001-A1 amending the first ("customer's
#: address"), an interval of 365 days for PG-12; audit clean, head below
SCHEMA_5 = Path(__file__).parents[2] / "fixtures" / "register_schema5.sqlite"
SCHEMA_5_HEAD = "f94c0320cbd1b6abbc82cac72a99dfa3eb15252880cf524396901124483bd998"


def render(meta: CertificateMetadata, head: str = "") -> bytes:
    return f"%PDF {meta.certificate_number} {meta.revision} head {head}".encode()


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


def _chain_v4(previous: str, record) -> str:
    """Chain format 4 written out here: SHA-256 of the previous value and the issued fields,
    the kind and the DCC's SHA-256 among them, as sorted compact JSON (format 7: and the
    readings' identity; format 8: by their physical values)."""
    keys = ("number", "issued_at", "issue_date", "calibration_date", "workbench",
            "item_description", "item_manufacturer", "item_serial", "customer", "operator",
            "workstation", "supersedes", "revision", "change_note", "project_json",
            "software_json", "headline_json", "pdf_sha256", "seq", "counter", "counter_value",
            "os_user", "approver", "dcc_sha256", "document_kind", "chain_format") + (
        ("readings_key",) if record.chain_format >= 7 else ()) + (
        ("readings_layout", "readings_anchor", "readings_reach") if record.chain_format >= 8
        else ())
    body = json.dumps({k: getattr(record, k) for k in keys}, sort_keys=True,
                      ensure_ascii=False, separators=(",", ":"))
    return hashlib.sha256(f"{previous}\n{body}".encode()).hexdigest()


def test_each_record_chains_what_its_document_is(register_url):
    """The kind the issuer says after rendering (the document of the attempt recorded);
    an amendment records its own document's kind: the original's, or the other kind when
    the corrected document is of it."""
    with _open(register_url) as register:
        report = register.issue(IssueRequest("positioning", META, PROJECT), render,
                                document_kind=lambda: "test")[0]
        before = register.chain_head()
        certificate = register.issue(IssueRequest("polygon", META, PROJECT), render,
                                     document_kind="calibration")[0]
        amended = register.issue(IssueRequest("positioning", META, PROJECT), render,
                                 supersedes=report.number, change_note="serial",
                                 document_kind="test")[0]
        replaced = register.issue(IssueRequest("polygon", META, PROJECT), render,
                                  supersedes=certificate.number, replacement=True,
                                  change_note="standards not stated", document_kind="test")[0]
        kinds = {r.number: r.document_kind for r in register.list()}
        assert kinds == {report.number: "test", certificate.number: "calibration",
                         amended.number: "test", replaced.number: "test"}
        assert {r.chain_format for r in register.list()} == {8}  # 4 and later chain the kind
        assert register.get(certificate.number).chain_sha256 == _chain_v4(before, certificate)
        assert register.audit(pdfs=True) == []
        with pytest.raises(ValueError, match="document_kind 'certificate'"):
            register.issue(IssueRequest("polygon", META, PROJECT), render,
                           document_kind="certificate")
        assert len(register.list()) == 4  # nothing recorded


def _schema_5(tmp_path) -> tuple[str, dict[str, str]]:
    path = tmp_path / "register.sqlite"
    shutil.copy(SCHEMA_5, path)
    with sqlite3.connect(path) as conn:
        chains = dict(conn.execute("SELECT number, chain_sha256 FROM certificates"))
        assert conn.execute("SELECT version FROM schema_version").fetchone() == (5,)
    return f"sqlite:///{path}", chains


def test_a_register_of_0_8_11_opens_verifies_and_migrates_unchanged(tmp_path, capsys):
    url, chains = _schema_5(tmp_path)
    with _open(url) as register:
        assert register.version == schema.LATEST == 9
        assert register.problems == [] and register.audit(pdfs=True) == []
        assert register.chain_head() == SCHEMA_5_HEAD
        old = {r.number: r for r in register.list()}
        assert {n: r.chain_sha256 for n, r in old.items()} == chains  # not one value changed
        assert {r.chain_format for r in old.values()} == {2, 3}
        assert {r.document_kind for r in old.values()} == {None}
        assert old["AB-2026-0002"].status == "withdrawn"
        new = register.issue(IssueRequest("positioning", META, PROJECT), render,
                             document_kind="test")[0]
        assert new.chain_format == 8 and register.chain_before(new.number) == SCHEMA_5_HEAD
        assert register.audit(pdfs=True) == []
    assert main(["register", "--register", url, "verify"]) == 0
    capsys.readouterr()
    assert main(["register", "--register", url, "list"]) == 0
    listed = [re.split(r"\s{2,}", line) for line in capsys.readouterr().out.splitlines()[1:]]
    assert [(row[0], row[2].split(" / ")[1], row[-1]) for row in listed] == [
        (new.number, "Test report", "issued"),
        ("AB-2026-0001-A1", "not recorded", "issued"),
        ("AB-2026-0002", "not recorded", "withdrawn"),
        ("AB-2026-0001", "not recorded", "amended by AB-2026-0001-A1")]
    assert main(["register", "--register", url, "show", "AB-2026-0001"]) == 0
    assert "\n  Document: not recorded\n" in capsys.readouterr().out
    assert main(["register", "--register", url, "show", new.number]) == 0
    assert "\n  Document: Test report\n" in capsys.readouterr().out
    # set back to 5 it is refused, never migrated again
    sql(url, "UPDATE schema_version SET version = 5",
        "UPDATE register_state SET value = '5' WHERE name = 'schema_version'")
    with pytest.raises(RegisterTampered, match=r"schema version 5 was set back \(the column "
                                               r"of version 6 exists\)"):
        Register(url)


@pytest.fixture
def issued(register_url):
    """A test report and a calibration certificate, issued with their kind."""
    with _open(register_url) as register:
        report = register.issue(IssueRequest("positioning", META, PROJECT), render,
                                document_kind="test")[0]
        certificate = register.issue(IssueRequest("polygon", META, PROJECT), render,
                                     document_kind="calibration")[0]
        assert register.audit() == []
    return register_url, report.number, certificate.number


@pytest.mark.parametrize("attack", ["report_as_certificate", "kind_erased", "as_format_3"])
def test_a_kind_changed_after_issue_breaks_the_chain(issued, attack):
    url, report, _ = issued
    sql(url, {"report_as_certificate": "UPDATE certificates SET document_kind = 'calibration' "
                                       "WHERE number = :n",
              "kind_erased": "UPDATE certificates SET document_kind = NULL WHERE number = :n",
              # passed off as a record of 0.8.11, whose chain does not cover the kind
              "as_format_3": "UPDATE certificates SET document_kind = NULL, chain_format = 3 "
                             "WHERE number = :n"}[attack], n=report)
    with _open(url) as register:
        problems = [str(p) for p in register.audit()]
    assert f"record {report}: the hash chain is broken here (this record, or one before it, " \
           "was changed, inserted or deleted after issue)" in problems


def test_a_kind_given_to_a_record_of_0_8_11_is_found(tmp_path, capsys):
    url, _ = _schema_5(tmp_path)
    with _open(url):
        pass  # migrated
    sql(url, "UPDATE certificates SET document_kind = 'calibration' WHERE number = :n",
        n="AB-2026-0001-A1")
    assert main(["register", "--register", url, "verify"]) == 3
    out = capsys.readouterr().out
    assert ("record AB-2026-0001-A1: its document kind (Calibration certificate) was set "
            "after issue: it was issued before the register recorded what a document is, and "
            "its chain does not cover it") in out


def test_register_verify_finds_a_test_report_relabelled(tmp_path, capsys, monkeypatch):
    url = f"sqlite:///{tmp_path / 'own.sqlite'}"
    with _open(url) as register:
        report = register.issue(IssueRequest("positioning", META, PROJECT), render,
                                document_kind="test")[0]
    assert main(["register", "--register", url, "verify"]) == 0
    capsys.readouterr()
    sql(url, "UPDATE certificates SET document_kind = 'calibration' WHERE number = :n",
        n=report.number)
    assert main(["register", "--register", url, "verify"]) == 3
    assert f"record {report.number}: the hash chain is broken" in capsys.readouterr().out
