"""reg72: ``anglebench register verify FILE`` attacked as the tester did (sqlite edits, files
renamed, a full disk): a genuine certificate whose record was deleted is one the register
LOST (exit 3), not a forgery (exit 1); the newest record rewritten with its chain recomputed
is found from the customer's PDF and DCC; a file is judged by its content, not its name; a
keyless verify of a signed register says what it did not check; a full disk after the
commit names every file not written. The register of each test is its own (conftest.py);
the attacks recompute the chain from its documented definition, importing nothing from the
code they check."""

from __future__ import annotations

import errno
import json
import os

import pytest
import sqlalchemy as sa

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.register.location import register_url
from models.register.store import IssueRequest, Register
from tests.register_forgery import relinked, stand_in_pdf

META = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-01", item_serial="RX-1")
PROJECT = json.dumps({"workbenches": {"polygon": {"rows": [["0", "0.41"], ["30", "-0.22"]]}}})
def _dcc(meta: CertificateMetadata, pdf: bytes) -> bytes:
    """A DCC that embeds the PDF, as a DCC does."""
    from tests import dcc_documents

    return dcc_documents.document(meta.certificate_number, pdf=pdf)


def _issue(n: int, key: str = "", headline: float = 2.88) -> list[tuple[str, bytes, bytes]]:
    """``n`` certificates issued with a PDF and a DCC: (number, pdf, dcc) of each."""
    made = []
    with Register(register_url(), key_file=key) as register:
        for _ in range(n):
            record, pdf = register.issue(IssueRequest("polygon", META, PROJECT,
                                                      {"peak_to_peak": headline}), stand_in_pdf,
                                         render_dcc=_dcc)
            made.append((record.number, pdf, register.dcc(record.number)))
    return made


def _sql(*statements: str, **params) -> None:
    engine = sa.create_engine(register_url())
    with engine.begin() as conn:
        for statement in statements:
            conn.execute(sa.text(statement), params)
    engine.dispose()


def _row(query: str, **params) -> dict:
    engine = sa.create_engine(register_url())
    with engine.connect() as conn:
        row = dict(conn.execute(sa.text(query), params).one()._mapping)
    engine.dispose()
    return row


def _truncate(number: str) -> None:
    """The last record deleted, the counter and the state row set back: the register agrees
    with itself (reg72 truncate_tail.sh)."""
    before = _row("SELECT chain_sha256, seq FROM certificates WHERE seq = (SELECT seq - 1 "
                  "FROM certificates WHERE number = :n)", n=number)
    _sql("DELETE FROM certificates WHERE number = :n",
         "UPDATE register_state SET value = :r WHERE name = 'records'",
         "UPDATE register_state SET value = :h WHERE name = 'head'",
         "UPDATE counters SET last_value = last_value - 1",
         n=number, r=str(before["seq"]), h=before["chain_sha256"])


def test_a_genuine_pdf_whose_record_was_deleted_is_lost_not_a_forgery(tmp_path, capsys,
                                                                     monkeypatch):
    """With the lab's key: the PDF carries the proof that this register issued it (reg73
    #3: without one, the register cannot tell it from a file made to print its head)."""
    key = tmp_path / "lab.key"
    key.write_bytes(os.urandom(32))
    monkeypatch.setenv("ANGLEBENCH_REGISTER_KEY", str(key))
    (_, first, _), (number, pdf, dcc) = _issue(2, key=str(key))
    (tmp_path / "2.pdf").write_bytes(pdf)
    (tmp_path / "2.xml").write_bytes(dcc)
    _truncate(number)
    capsys.readouterr()
    (tmp_path / "1.pdf").write_bytes(first + b"%\n")  # a PDF altered: not a lost record
    # exit 3: the state set back is found with the key (reg72 #1), whatever the file
    assert main(["register", "verify", str(tmp_path / "1.pdf")]) == 3
    out = capsys.readouterr().out
    assert "NOT in the register" in out and "LOST" not in out
    for name in ("2.pdf", "2.xml"):  # the DCC by the PDF it embeds
        assert main(["register", "verify", str(tmp_path / name)]) == 3
        out = capsys.readouterr().out
        assert f"was issued by this register ({number}), but the register has LOST its record" \
            in out
        assert "NOT in the register" not in out


def test_a_number_issued_again_after_its_record_was_deleted_is_said_as_either(
        tmp_path, capsys):
    """No key: the PDF in hand is not what the register holds for its number at its place.
    Without a proof of the lab's key the register cannot tell the copy altered from its
    record deleted and the number issued again (reg73 #4): ALTERED, with the other cause."""
    (_, _, _), (number, pdf, _) = _issue(2)
    (tmp_path / "2.pdf").write_bytes(pdf)
    _truncate(number)
    again = _issue(1, headline=1.0)[0][0]
    assert again == number  # no key: nothing in the database stops it
    capsys.readouterr()
    assert main(["register", "verify", str(tmp_path / "2.pdf")]) == 1
    out = capsys.readouterr().out
    assert "LOST" not in out and f"ALTERED: {tmp_path / '2.pdf'} ({number})" in out
    assert "its record was deleted and the number issued again" in out


def test_the_newest_record_rewritten_is_found_from_its_pdf_and_dcc(tmp_path, capsys):
    (_, _, _), (number, pdf, dcc) = _issue(2)
    row = _row("SELECT * FROM certificates WHERE number = :n", n=number)
    previous = _row("SELECT chain_sha256 FROM certificates WHERE seq = :s",
                    s=row["seq"] - 1)["chain_sha256"]
    row["project_json"] = row["project_json"].replace("0.41", "0.14")
    row["headline_json"] = json.dumps({"peak_to_peak": 1.44})
    chain = relinked(previous, row)
    _sql("UPDATE certificates SET project_json = :p, headline_json = :h, chain_sha256 = :c "
         "WHERE number = :n", "UPDATE register_state SET value = :c WHERE name = 'head'",
         p=row["project_json"], h=row["headline_json"], c=chain, n=number)
    # the register agrees with itself, but its own copy of the PDF carries the digest of
    # the record as issued (reg73 #1: found without the customer's copy)
    assert main(["register", "verify"]) == 3
    assert (f"record {number}: it is not the record its stored PDF was issued from"
            in capsys.readouterr().out)
    for name, data in (("last.pdf", pdf), ("last.xml", dcc)):
        (tmp_path / name).write_bytes(data)
        assert main(["register", "verify", str(tmp_path / name)]) == 3
        assert (f"the register's record of {number} is not the record it was issued from"
                in capsys.readouterr().out)


@pytest.mark.parametrize("name", [".c1.xml.Ab12Cd34.tmp", "c1.dcc", "c1.xlsx", "c1"])
def test_a_file_is_judged_by_its_content_not_its_name(tmp_path, capsys, name):
    ((number, pdf, dcc),) = _issue(1)
    for data in (pdf, dcc):
        (tmp_path / name).write_bytes(data)
        assert main(["register", "verify", str(tmp_path / name)]) == 0
        out = capsys.readouterr().out
        assert f"document {number}, issued" in out and "NOT in the register" not in out
        assert ("an unfinished write left by an interrupted issue" in out) == name.endswith(
            ".tmp")


def test_a_keyless_verify_of_a_signed_register_says_what_it_did_not_check(tmp_path, capsys):
    key = tmp_path / "lab.key"
    key.write_bytes(os.urandom(32))
    _issue(2, key=str(key))
    assert main(["register", "verify"]) == 0
    assert ("2 record(s) are signed with the laboratory's key: their signatures and the "
            "register's signed state are NOT checked without the key") in capsys.readouterr().out


def test_a_full_disk_after_the_commit_names_every_file_not_written(samples_dir, tmp_path,
                                                                  capsys, monkeypatch):
    """reg72 disk_full.sh C: the PDF written, neither the DCC nor the results file: both
    named, with what can be done about each."""
    real = os.fsync

    def fsync(fd):  # the disk full for the DCC's and the results file's bytes
        if any(f"/.{n}." in os.readlink(f"/proc/self/fd/{fd}") for n in ("c.xml", "r.xlsx")):
            raise OSError(errno.ENOSPC, "No space left on device")
        return real(fd)

    monkeypatch.setattr(os, "fsync", fsync)
    meta = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    meta.update({"example": False, "certificate_number": ""})
    (tmp_path / "m.json").write_text(json.dumps(meta), encoding="utf-8")
    code = main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"), "--metadata",
                 str(tmp_path / "m.json"), "--certificate", str(tmp_path / "c.pdf"), "--dcc",
                 str(tmp_path / "c.xml"), "--results", str(tmp_path / "r.xlsx")])
    err = capsys.readouterr().err
    assert code == 2 and (tmp_path / "c.pdf").exists()
    with Register(register_url()) as register:
        (number,) = [r.number for r in register.list()]
    assert f"save its DCC with 'anglebench register show {number} --dcc OUT.xml'" in err
    assert (f"nor its results file ({tmp_path / 'r.xlsx'}: No space left on device): the "
            f"register records no results file for {number}, and no command writes it "
            "afterwards") in err


def test_the_windows_verify_a_pdf_says_a_lost_record_and_a_rewritten_one(tmp_path):
    """The register window's *Verify a PDF…* finds what ``register verify FILE`` finds."""
    from unittest import mock

    from app.register_presenter import RegisterPresenter

    key = tmp_path / "lab.key"
    key.write_bytes(os.urandom(32))
    (_, first, _), (number, pdf, _) = _issue(2, key=str(key))
    certificates = mock.Mock()
    certificates.open_register = lambda: Register(register_url(), key_file=str(key))
    view = mock.Mock()
    presenter = RegisterPresenter(view, certificates, lambda *a: True)
    (tmp_path / "1.pdf").write_bytes(first)
    (tmp_path / "2.pdf").write_bytes(pdf)
    _sql("UPDATE certificates SET headline_json = '{}' WHERE seq = 1")  # rewritten: the chain
    view.ask_pdf_to_verify.return_value = str(tmp_path / "1.pdf")  # breaks too, said anyway
    presenter.verify_pdf()
    title, text = view.tell.call_args.args
    assert "is not the record it was issued from" in text
    _truncate(number)
    view.ask_pdf_to_verify.return_value = str(tmp_path / "2.pdf")
    assert presenter.verify_pdf() is None
    title, text = view.tell.call_args.args
    assert title == "Register changed after issue" and "has LOST its record" in text
