"""reg73: ``anglebench register verify`` attacked as the tester did (sqlite edits, a forged
text "PDF", a key file with a newline, a pipe closed early). The attacks recompute the chain
from its documented definition (tests/register_forgery.py), importing nothing from the code
they check. The register of each test is its own (conftest.py)."""

from __future__ import annotations

import hashlib
import json
import os
import re
import subprocess
import sys

import sqlalchemy as sa

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.register.location import register_url
from models.register.store import IssueRequest, Register
from tests.app.test_register_verify_reg72 import _sql
from tests.register_forgery import relinked, stand_in_pdf

META = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-01", item_serial="RX-1")
PROJECT = json.dumps({"workbenches": {"polygon": {"rows": [["0", "0.41"], ["30", "-0.22"]]}}})


def _dcc(meta: CertificateMetadata, pdf: bytes) -> bytes:
    from tests import dcc_documents

    return dcc_documents.document(meta.certificate_number, pdf=pdf)


def _issue(n: int, key: str = "") -> list[tuple[str, bytes, bytes]]:
    made = []
    with Register(register_url(), key_file=key) as register:
        for _ in range(n):
            record, pdf = register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf,
                                         render_dcc=_dcc, document_kind="calibration")
            made.append((record.number, pdf, register.dcc(record.number)))
    return made


def _newest() -> tuple[dict, str]:
    engine = sa.create_engine(register_url())
    with engine.connect() as conn:
        row = dict(conn.execute(sa.text(
            "SELECT * FROM certificates ORDER BY seq DESC LIMIT 1")).one()._mapping)
        previous = conn.execute(sa.text("SELECT chain_sha256 FROM certificates WHERE seq = :s"),
                                {"s": row["seq"] - 1}).scalar() or "0" * 64
    engine.dispose()
    return row, previous


def _rewrite_newest(**changes) -> None:
    row, previous = _newest()
    row.update(changes)
    sets = ", ".join(f"{k} = :{k}" for k in changes)
    _sql(f"UPDATE certificates SET {sets}, chain_sha256 = :c WHERE id = :id",
         "UPDATE register_state SET value = :c WHERE name = 'head'",
         **changes, c=relinked(previous, row), id=row["id"])


def test_the_customers_dcc_finds_the_registers_dcc_rewritten(tmp_path, capsys):
    """reg73 #1: the newest record's DCC replaced (its value changed, the genuine PDF still
    embedded) and its kind flipped, chain recomputed, no key: the register's own check, the
    customer's PDF and the customer's DCC each find it (exit 3)."""
    (_, _, _), (number, pdf, dcc) = _issue(2)
    forged = dcc.replace(b"Braunschweig", b"Hannover")
    _rewrite_newest(dcc=forged, dcc_sha256=hashlib.sha256(forged).hexdigest(),
                    document_kind="test")
    capsys.readouterr()
    assert main(["register", "verify"]) == 3
    assert f"record {number}: it is not the record its stored PDF was issued from" \
        in capsys.readouterr().out
    for name, data in (("c.pdf", pdf), ("c.xml", dcc)):
        (tmp_path / name).write_bytes(data)
        assert main(["register", "verify", str(tmp_path / name)]) == 3, name
        out = capsys.readouterr().out
        assert "rewritten after issue" in out


def test_an_altered_dcc_is_not_said_identical(tmp_path, capsys):
    """reg73 #10: an altered DCC was "NOT in the register" and, next line, "identical to the
    record (SHA-256)" — the second about the PDF embedded in it."""
    ((number, _, dcc),) = _issue(1)
    (tmp_path / "c.xml").write_bytes(dcc.replace(b"Braunschweig", b"Hannover"))
    capsys.readouterr()
    assert main(["register", "verify", str(tmp_path / "c.xml")]) == 1
    out = capsys.readouterr().out
    assert "NOT in the register" in out and "identical to the record (SHA-256)" not in out
    assert f"the PDF embedded in it is {number}'s, record 1" in out


def test_a_pdf_with_its_digest_stripped_is_remarked(tmp_path, capsys):
    """reg73 #10 (strip_digest_launder): the stored PDF replaced by the genuine one with its
    record digest stripped, chain recomputed: the register's copy is said to carry none."""
    ((number, pdf, _),) = _issue(1)
    stripped = re.sub(rb"anglebench-record-content:[0-9a-f]{64}", b"x" * 90, pdf)
    _rewrite_newest(pdf=stripped, pdf_sha256=hashlib.sha256(stripped).hexdigest())
    (tmp_path / "c.pdf").write_bytes(stripped)
    capsys.readouterr()
    main(["register", "verify", str(tmp_path / "c.pdf")])
    assert f"it carries no digest of its record's content, which {number}'s PDF carried" \
        in capsys.readouterr().out


def test_a_forged_file_printing_the_head_stops_nothing(tmp_path, capsys, monkeypatch):
    """reg73 #3 forged_pdf_lost.sh, with the key: not LOST, nothing recorded, issuing goes
    on."""
    key = tmp_path / "lab.key"
    key.write_bytes(os.urandom(32))
    monkeypatch.setenv("ANGLEBENCH_REGISTER_KEY", str(key))
    _issue(1, str(key))
    capsys.readouterr()
    assert main(["register", "head"]) == 0
    head = re.search(r"[0-9a-f]{64}", capsys.readouterr().out).group(0)
    (tmp_path / "f.pdf").write_bytes(
        f"%PDF-1.4\n1 0 obj << /Title (Calibration certificate AB-2026-0777) /Keywords "
        f"(anglebench-register-head-before:{head}) >> endobj\n%%EOF\n".encode())
    assert main(["register", "verify", str(tmp_path / "f.pdf")]) == 1
    out = capsys.readouterr().out
    assert "cannot tell whether this was issued here" in out and "LOST" not in out
    assert main(["register", "verify"]) == 0
    assert len(_issue(1, str(key))) == 1


def test_a_wrong_key_is_a_setting_not_a_forgery(tmp_path, capsys, monkeypatch):
    """reg73 #7 wrong_key.sh: the key file with a newline added: exit 2, the key named,
    nothing forged, no advice to restore a backup."""
    key = tmp_path / "lab.key"
    key.write_bytes(os.urandom(32))
    _issue(2, str(key))
    (tmp_path / "pasted.key").write_bytes(key.read_bytes() + b"\n")
    monkeypatch.setenv("ANGLEBENCH_REGISTER_KEY", str(tmp_path / "pasted.key"))
    capsys.readouterr()
    assert main(["register", "verify"]) == 2
    out = capsys.readouterr().out
    assert "is not the key this register was signed with" in out
    assert "forged" not in out and "backup" not in out and "CHANGED AFTER ISSUE" not in out


def test_verify_read_by_a_closed_pipe_ends_without_a_traceback(tmp_path):
    """reg73 #10: ``python -m app register verify | head`` ended in a BrokenPipeError
    traceback."""
    _issue(1)
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(sys.path)}
    process = subprocess.Popen([sys.executable, "-m", "app", "register", "--register",
                                register_url(), "verify"], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, env=env, cwd=tmp_path)
    process.stdout.close()  # the reader is gone before anything is written
    _, err = process.communicate(timeout=120)
    assert b"unrecognized" not in err  # the command ran
    assert b"Traceback" not in err and b"BrokenPipeError" not in err
    assert process.returncode == 0  # an intact register: verified


def test_verify_read_by_a_closed_pipe_still_exits_with_its_verdict(tmp_path):
    """``register verify | head -1`` of a register whose record was edited (a customer
    changed in the database): the reader went after the first line, and verify exited 0 —
    a script with ``set -o pipefail`` read "verified". It finishes its checks silently and
    exits 3, as it does with its whole output read."""
    _issue(2)
    _sql("UPDATE certificates SET customer = 'Someone Else' WHERE seq = 1")
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(sys.path)}
    whole = subprocess.run([sys.executable, "-m", "app", "register", "--register",
                            register_url(), "verify"], capture_output=True, env=env,
                           cwd=tmp_path, timeout=120)
    assert whole.returncode == 3, whole.stdout + whole.stderr
    process = subprocess.Popen([sys.executable, "-m", "app", "register", "--register",
                                register_url(), "verify"], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, env=env, cwd=tmp_path)
    process.stdout.close()  # the reader is gone before anything is written
    _, err = process.communicate(timeout=120)
    assert b"Traceback" not in err and b"BrokenPipeError" not in err
    assert process.returncode == 3


def test_show_says_which_form_of_record_digest_a_record_uses(capsys):
    """Old records (form 1) verify as they were; ``register show`` says which form each
    record's PDF carries."""
    ((number, _, _),) = _issue(1)
    capsys.readouterr()
    assert main(["register", "show", number]) == 0
    assert "record digest on its PDF: form 2 (readings, results and details, the " \
        "document's kind and its DCC)" in capsys.readouterr().out
    _rewrite_newest(chain_format=5)
    assert main(["register", "show", number]) == 0
    assert "record digest on its PDF: form 1" in capsys.readouterr().out


def _workbook(number: str, pdf_sha256: str) -> bytes:
    """A results workbook's *Certificate* sheet as the results file lays it out: the
    certificate's number on its first row, its PDF's SHA-256 on the sixth, its DCC's on the
    seventh."""
    import io

    from openpyxl import Workbook

    book = Workbook()
    sheet = book.active
    sheet.title = "Certificate"
    for row in (("Certificate number", number), ("Issued", "2026-12-01"), ("Lab", "Angle lab"),
                ("Item", "Rotary encoder"), ("Serial", "RX-1"),
                ("Certificate PDF SHA-256", pdf_sha256), ("Certificate DCC SHA-256", "")):
        sheet.append(row)
    out = io.BytesIO()
    book.save(out)
    return out.getvalue()


def test_the_customers_results_file_names_its_certificate_when_its_entry_was_rewritten(
        tmp_path, capsys):
    """reg73 #1 launder_results.sh: the newest results entry pointed at another file, its
    chain value recomputed, no key: the customer's genuine workbook was "NOT in the
    register" and nothing more; it is now said to be that certificate's, whose recorded
    results file is another."""
    with Register(register_url()) as register:
        record, pdf = register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf)
        workbook = _workbook(record.number, record.pdf_sha256)
        register.record_results(record.number, workbook, "r.xlsx")
    engine = sa.create_engine(register_url())
    with engine.connect() as conn:
        entry = dict(conn.execute(sa.text(
            "SELECT * FROM entries ORDER BY seq DESC LIMIT 1")).one()._mapping)
        previous = conn.execute(sa.text("SELECT chain_sha256 FROM certificates WHERE seq = :s"),
                                {"s": entry["seq"] - 1}).scalar()
    engine.dispose()
    body = json.loads(entry["body_json"])
    body["sha256"] = hashlib.sha256(b"another workbook").hexdigest()
    entry["body_json"] = json.dumps(body, sort_keys=True)
    fields = {k: entry[k] for k in ("seq", "kind", "subject", "body_json", "recorded_at",
                                    "os_user", "workstation")}
    text = json.dumps({"entry": fields}, sort_keys=True, ensure_ascii=False,
                      separators=(",", ":"))
    chain = hashlib.sha256(f"{previous}\n{text}".encode()).hexdigest()
    _sql("UPDATE entries SET body_json = :b, chain_sha256 = :c WHERE id = :id",
         "UPDATE register_state SET value = :c WHERE name = 'head'",
         b=entry["body_json"], c=chain, id=entry["id"])
    assert main(["register", "verify"]) == 0  # the register agrees with itself
    (tmp_path / "r.xlsx").write_bytes(workbook)
    capsys.readouterr()
    assert main(["register", "verify", str(tmp_path / "r.xlsx")]) == 1
    out = capsys.readouterr().out
    assert (f"says it is the results file of certificate {record.number} (its PDF SHA-256 "
            f"{record.pdf_sha256[:16]}…), whose results file the register recorded as another"
            ) in out and "the register's record of it was rewritten" in out


def test_a_certificate_with_its_dcc_is_rendered_once_and_its_digest_covers_both(
        samples_dir, tmp_path, capsys, monkeypatch):
    """The record digest of content form 2 covers the document's kind and its DCC, known
    before the PDF is rendered (issue_certificate's prepare): one rendering, the DCC's
    "not validated" said once, and the register's own copy verifies clean."""
    import app.certificate_issue as issuing

    renders = []
    real = issuing.certificate_pdf_bytes
    monkeypatch.setattr(issuing, "certificate_pdf_bytes",
                        lambda document: renders.append(1) or real(document))
    meta = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    meta.update({"example": False, "certificate_number": ""})
    (tmp_path / "m.json").write_text(json.dumps(meta), encoding="utf-8")
    assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"), "--metadata",
                 str(tmp_path / "m.json"), "--certificate", str(tmp_path / "c.pdf"), "--dcc",
                 str(tmp_path / "c.xml")]) == 0
    assert len(renders) == 1 and capsys.readouterr().err.count("was not validated") == 1
    assert main(["register", "verify", str(tmp_path / "c.xml")]) == 0
