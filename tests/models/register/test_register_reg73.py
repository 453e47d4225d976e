"""reg73: the register attacked by someone with write access to its database (raw SQL, as
/work/reg73/repro does) or with a file made to look like a certificate. The newest record's
DCC and document kind rewritten with the chain recomputed are found from the customer's PDF
(its record digest covers them since 0.8.22, content form 2); a record of 0.8.21 (form 1)
still verifies; a file that prints the public head records nothing that stops issuing
unless it carries the proof only the lab's key makes; a customer's copy edited with its
digest is ALTERED, not a record the register lost; a wrong key is said to be one, nothing
called forged, nothing written.

The attacks recompute the chain and the form-1 digest themselves, from their documented
definitions (tests/register_forgery.py; a digest is the SHA-256 of a label, a newline and
the fields as sorted, compact JSON): nothing is imported from the code they check."""

from __future__ import annotations

import hashlib
import json
import os
import re

import pytest
import sqlalchemy as sa

from models.certificate.metadata import CertificateMetadata
from models.register.store import IssueRequest, Register, RegisterError
from tests.models.register.test_register_reg72 import ISSUED, META, PROJECT
from tests.register_forgery import relinked, stand_in_pdf

#: the fields of content form 1, as the chain's documentation lists them
CONTENT_1 = ("number", "issued_at", "issue_date", "calibration_date", "workbench",
             "item_description", "item_manufacturer", "item_serial", "customer", "operator",
             "workstation", "supersedes", "revision", "change_note", "project_json",
             "software_json", "headline_json", "seq", "counter", "counter_value", "os_user",
             "approver")


def _dcc(meta: CertificateMetadata, pdf: bytes) -> bytes:
    from tests import dcc_documents

    return dcc_documents.document(meta.certificate_number, pdf=pdf)


def _open(url: str, key: str = "") -> Register:
    register = Register(url, timezone="UTC", key_file=key)
    register.clock = lambda: ISSUED  # type: ignore[method-assign]
    return register


def _issue(url: str, n: int, key: str = "", dcc: bool = False) -> list[tuple[dict, bytes]]:
    made = []
    with _open(url, key) as register:
        for _ in range(n):
            record, pdf = register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf,
                                         render_dcc=_dcc if dcc else None,
                                         document_kind="calibration")
            made.append((record.__dict__, pdf))
    return made


def _sql(url: str, *statements: str, **params) -> None:
    engine = sa.create_engine(url.replace("postgresql://", "postgresql+psycopg://"))
    with engine.begin() as conn:
        for statement in statements:
            conn.execute(sa.text(statement), params)
    engine.dispose()


def _rows(url: str, query: str, **params) -> list[dict]:
    engine = sa.create_engine(url.replace("postgresql://", "postgresql+psycopg://"))
    with engine.connect() as conn:
        rows = [dict(r._mapping) for r in conn.execute(sa.text(query), params)]
    engine.dispose()
    return rows


def _rewrite_newest(url: str, **changes) -> None:
    """The newest record changed, its chain value recomputed and written to the state: the
    register agrees with itself (reg73 launder_dcc_kind.sh)."""
    newest = _rows(url, "SELECT * FROM certificates ORDER BY seq DESC LIMIT 1")[0]
    before = _rows(url, "SELECT chain_sha256 FROM certificates WHERE seq = :s",
                   s=newest["seq"] - 1)
    newest.update(changes)
    chain = relinked(before[0]["chain_sha256"] if before else "0" * 64, newest)
    sets = ", ".join(f"{k} = :{k}" for k in changes)
    _sql(url, f"UPDATE certificates SET {sets}, chain_sha256 = :chain WHERE id = :id",
         "UPDATE register_state SET value = :chain WHERE name = 'head'",
         **changes, chain=chain, id=newest["id"])


def _verify_file(url: str, data: bytes, key: str = "") -> list[str]:
    """What the register says of a certificate's PDF it finds: its record's digest."""
    from models.register.printed_place import content_changed

    with _open(url, key) as register:
        found = register.verify_all(data)
        assert len(found) == 1
        said = content_changed(register, "c.pdf", data, found[0])
        return [str(p) for p in register.audit(pdfs=True)] + ([str(said)] if said else [])


@pytest.mark.parametrize("register_url", ["sqlite", "postgresql"], indirect=True)
def test_the_newest_records_dcc_rewritten_is_found_from_the_customers_pdf(register_url):
    """reg73 #1: the stored DCC replaced by one with another value (the genuine PDF still
    embedded), its SHA-256 set, the chain recomputed, no key: found."""
    (_, _), (record, pdf) = _issue(register_url, 2, dcc=True)
    assert _verify_file(register_url, pdf) == []
    stored = _rows(register_url, "SELECT dcc FROM certificates WHERE number = :n",
                   n=record["number"])[0]["dcc"]
    forged = bytes(stored).replace(b"Braunschweig", b"Hannover")
    assert forged != bytes(stored)
    _rewrite_newest(register_url, dcc=forged, dcc_sha256=hashlib.sha256(forged).hexdigest())
    said = " ".join(_verify_file(register_url, pdf))
    assert f"the register's record of {record['number']} is not the record it was issued " \
           "from" in said and "form 2" in said


@pytest.mark.parametrize("register_url", ["sqlite", "postgresql"], indirect=True)
def test_the_newest_records_kind_rewritten_is_found_from_the_customers_pdf(register_url):
    (record, pdf), = _issue(register_url, 1)
    _rewrite_newest(register_url, document_kind="test")
    said = " ".join(_verify_file(register_url, pdf))
    assert "the record was rewritten after issue" in said


@pytest.mark.parametrize("register_url", ["sqlite", "postgresql"], indirect=True)
def test_a_record_of_form_1_still_verifies_and_says_its_form(register_url):
    """A record of 0.8.21 (chain format 5): its PDF carries the digest of form 1, which
    covers neither the kind nor the DCC; it verifies as it is, and its kind rewritten is
    then not found from its PDF (what form 1 does not cover)."""
    from models.register.printed_place import content_changed

    (record, _), = _issue(register_url, 1)
    fields = {k: record[k] for k in CONTENT_1}
    body = json.dumps(fields, sort_keys=True, ensure_ascii=False, separators=(",", ":"))
    form_1 = hashlib.sha256(f"content\n{body}".encode()).hexdigest()
    meta = CertificateMetadata(certificate_number=record["number"])
    old_pdf = stand_in_pdf(meta, head="0" * 64, content=form_1)
    _rewrite_newest(register_url, chain_format=5, pdf=old_pdf,
                    pdf_sha256=hashlib.sha256(old_pdf).hexdigest())
    assert _verify_file(register_url, old_pdf) == []
    with _open(register_url) as register:
        found = register.verify_all(old_pdf)[0]
        assert found.chain_format == 5
        edited = old_pdf.replace(form_1[:8].encode(), b"0" * 8)  # its digest altered
        said = content_changed(register, "c.pdf", edited, found)
        assert said is not None and "form 1" in str(said)


def _key(tmp_path, name: str = "lab.key") -> str:
    path = tmp_path / name
    path.write_bytes(os.urandom(31) + b"k")
    return str(path)


def _forged_pdf(number: str, head: str, proof: str = "") -> bytes:
    """reg73 forged_pdf_lost.sh: a ~200-byte text "PDF" printing the register's head."""
    carried = f" anglebench-register-proof:{proof}" if proof else ""
    return (f"%PDF-1.4\n1 0 obj << /Title (Calibration certificate {number}) /Keywords "
            f"(anglebench-register-head-before:{head}{carried}) >> endobj\n%%EOF\n").encode()


def _place_said(url: str, data: bytes, key: str = "") -> tuple[str, bool]:
    from models.register.printed_place import record_lost, say_its_place

    said: list[str] = []
    with _open(url, key) as register:
        lost = record_lost(register, data)
        say_its_place(register, "f.pdf", data, lambda m: said.append(str(m)))
    return " ".join(said), lost


@pytest.mark.parametrize("register_url", ["sqlite", "postgresql"], indirect=True)
@pytest.mark.parametrize("keyed", [True, False])
def test_a_file_printing_the_head_records_nothing_and_stops_nothing(register_url, tmp_path,
                                                                     keyed):
    """reg73 #3: a forged text file printing the current head is not a LOST certificate:
    no "missing" entry, and the register goes on issuing."""
    key = _key(tmp_path) if keyed else ""
    _issue(register_url, 1, key)
    head = _rows(register_url, "SELECT value FROM register_state WHERE name = 'head'")[0]
    entries = _rows(register_url, "SELECT count(*) AS n FROM entries")[0]["n"]
    for proof in ("", "ab" * 32):
        said, lost = _place_said(register_url, _forged_pdf("AB-2026-0777", head["value"],
                                                           proof), key)
        assert not lost and "LOST" not in said and "recorded in the register" not in said
        assert ("not the laboratory key's" in said if keyed and proof
                else "cannot tell whether this was issued here" in said)
    assert _rows(register_url, "SELECT count(*) AS n FROM entries")[0]["n"] == entries
    assert len(_issue(register_url, 1, key)) == 1  # issuing goes on


@pytest.mark.parametrize("register_url", ["sqlite", "postgresql"], indirect=True)
def test_a_genuine_pdf_with_its_record_deleted_is_lost_only_with_its_proof(register_url,
                                                                           tmp_path):
    """With the key, the certificate issued carries the proof: its record deleted with the
    state set back, it is LOST and recorded; the same file with its proof removed is not."""
    key = _key(tmp_path)
    (first, _), (second, pdf) = _issue(register_url, 2, key)
    assert b"anglebench-register-proof:" in pdf
    _sql(register_url, "DELETE FROM certificates WHERE number = :n",
         "UPDATE register_state SET value = '1' WHERE name = 'records'",
         "UPDATE register_state SET value = :h WHERE name = 'head'",
         "UPDATE counters SET last_value = last_value - 1",
         n=second["number"], h=first["chain_sha256"])
    bare = re.sub(rb" anglebench-register-proof:[0-9a-f]{64}", b"", pdf)
    said, lost = _place_said(register_url, bare, key)
    assert not lost and "cannot tell" in said
    # the state no longer carries the key's signature (reg72 #1): found without the PDF
    with _open(register_url, key) as register:
        assert register.problems
    said, lost = _place_said(register_url, pdf, key)
    assert lost


@pytest.mark.parametrize("register_url", ["sqlite", "postgresql"], indirect=True)
@pytest.mark.parametrize("keyed", [True, False])
def test_a_copy_edited_with_its_digest_is_altered_not_lost(register_url, tmp_path, keyed):
    """reg73 #4: the customer's copy of the newest certificate with its record digest
    changed (head and number kept), on an intact register: ALTERED, not LOST."""
    key = _key(tmp_path) if keyed else ""
    (_, _), (record, pdf) = _issue(register_url, 2, key)
    carried = re.search(rb"anglebench-record-content:([0-9a-f]{64})", pdf).group(1)
    edited = pdf.replace(carried, (b"0" if carried[:1] != b"0" else b"1") + carried[1:])
    said, lost = _place_said(register_url, edited, key)
    assert not lost
    assert said.startswith(f"ALTERED: f.pdf ({record['number']}) is not the certificate") \
        and "LOST" not in said and "recorded in the register" not in said


@pytest.mark.parametrize("register_url", ["sqlite", "postgresql"], indirect=True)
def test_a_wrong_key_is_said_to_be_one_and_writes_nothing(register_url, tmp_path):
    """reg73 #7: the lab's key file with a newline added: not "forged", not "restore a
    backup"; nothing written; the right key then verifies clean."""
    key = _key(tmp_path)
    _issue(register_url, 2, key)
    wrong = tmp_path / "pasted.key"
    with open(key, "rb") as right:
        wrong.write_bytes(right.read() + b"\n")
    state = _rows(register_url, "SELECT * FROM register_state ORDER BY name")
    with _open(register_url, str(wrong)) as register:
        said = " ".join(str(p) for p in [*register.problems,
                                         getattr(register, "key_problem", None)])
        assert "is not the key this register was signed with" in said
        assert "line end added or removed" in said
        assert "forged" not in said and "backup" not in said
        with pytest.raises(RegisterError, match="not the key this register was signed with"):
            register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf)
    assert _rows(register_url, "SELECT * FROM register_state ORDER BY name") == state
    with _open(register_url, key) as register:
        assert register.key_problem is None and register.audit(pdfs=True) == []


@pytest.mark.parametrize("register_url", ["sqlite", "postgresql"], indirect=True)
def test_a_wrong_key_of_a_register_with_no_fingerprint_yet(register_url, tmp_path):
    """A register signed before the fingerprint was kept (its row deleted here): no signed
    record is the key's — the key is wrong, nothing is called forged."""
    _issue(register_url, 2, _key(tmp_path))
    _sql(register_url, "DELETE FROM register_state WHERE name = 'key_fingerprint'")
    with _open(register_url, _key(tmp_path, "other.key")) as register:
        said = " ".join(str(p) for p in [*register.problems,
                                         getattr(register, "key_problem", None)])
        assert "none of its signed records is this key's" in said and "forged" not in said


@pytest.mark.parametrize("register_url", ["sqlite"], indirect=True)
def test_a_wrong_guess_of_the_kind_is_rendered_again_and_a_changing_document_issues_nothing(
        register_url):
    """The digest the PDF carries covers the kind and the DCC the rendering gives: a guess
    (prepare) that is not what the rendering gives is rendered again, with the right one; a
    document whose DCC differs at each rendering is not issued."""
    from models.register.printed_place import content_changed

    renders = []

    def render(meta, head="", content=""):
        renders.append(content)
        return stand_in_pdf(meta, head, content)

    with _open(register_url) as register:
        record, pdf = register.issue(IssueRequest("polygon", META, PROJECT), render,
                                     document_kind=lambda: "calibration",
                                     prepare=lambda final: ("test", None))
        assert len(renders) == 2 and record.document_kind == "calibration"
        assert register.audit(pdfs=True) == []
        assert content_changed(register, "c.pdf", pdf, register.get(record.number)) is None
        made = iter(range(10))
        with pytest.raises(RegisterError, match="changed each time it was rendered"):
            register.issue(IssueRequest("polygon", META, PROJECT), render,
                           render_dcc=lambda final, pdf: _dcc(final, pdf).replace(
                               b"Braunschweig", f"Town {next(made)}".encode()))
        assert [r.number for r in register.list()] == [record.number]
