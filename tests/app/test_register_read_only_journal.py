"""A register this user cannot write is read with its "-wal" journal (rev65 F2): SQLite keeps
the latest commits there until a writer copies them into the file, and the read-only opening
read the main file only (``immutable=1``), so ``register verify`` told an auditor that a
certificate a writer had just issued was "NOT in the register" (exit 1), with an old chain
head. Now the journal is read; where it cannot be (no "-shm" index and a folder that cannot be
written), nothing is said from the main file: the register is not opened (exit 2).

The user who cannot write is emulated as the app decides it (``os.access``: the tests run as
root, for whom a chmod changes nothing); SQLite then opens the file ``mode=ro``."""

from __future__ import annotations

import hashlib
import os
import shutil

import pytest

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.register.store import IssueRequest, Register

META = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-01", item_serial="RX-1")
PROJECT = '{"workbenches": {}}'


def _cannot_write(monkeypatch, folder) -> None:
    """os.access says this user cannot write ``folder`` nor anything in it."""
    real = os.access
    folder = os.path.abspath(folder)

    def access(path, mode, *args, **kwargs):
        if mode & os.W_OK and os.path.abspath(str(path)).startswith(folder):
            return False
        return real(path, mode, *args, **kwargs)

    monkeypatch.setattr(os, "access", access)


def _stored_pdf(register: Register, number: str) -> bytes:
    certificates = register._schema.CERTIFICATES
    with register._read() as conn:
        return conn.execute(register._sa.select(certificates.c.pdf).where(
            certificates.c.number == number)).scalar_one()


@pytest.fixture
def writer(tmp_path):
    """A writer that issued two certificates and stays open (its commits in the -wal)."""
    (tmp_path / "w").mkdir()
    register = Register(f"sqlite:///{tmp_path / 'w' / 'reg.sqlite'}", timezone="UTC")
    register.issue(IssueRequest("polygon", META, PROJECT), lambda m, head="": b"%PDF first")
    register.close()  # the first one checkpointed into the file
    register = Register(f"sqlite:///{tmp_path / 'w' / 'reg.sqlite'}", timezone="UTC")
    record = register.issue(IssueRequest("polygon", CertificateMetadata(**{
        **META.to_dict(), "standards": (), "item_serial": "RX-2"}), PROJECT),
        lambda m, head="": f"%PDF second {head}".encode())[0]
    yield register, record
    register.close()


def test_a_certificate_a_live_writer_issued_is_verified_read_only(tmp_path, writer, capsys,
                                                                  monkeypatch):
    register, record = writer
    assert (tmp_path / "w" / "reg.sqlite-wal").stat().st_size > 0  # the commit is there
    path = tmp_path / "second.pdf"
    pdf = _stored_pdf(register, record.number)
    path.write_bytes(pdf)
    _cannot_write(monkeypatch, tmp_path / "w")
    with Register(f"sqlite:///{tmp_path / 'w' / 'reg.sqlite'}") as reader:
        assert reader.read_only
        assert reader.issued_file(hashlib.sha256(pdf).hexdigest()) == [(record.number, "pdf")]
    capsys.readouterr()
    assert main(["register", "--register", str(tmp_path / "w" / "reg.sqlite"), "verify",
                 str(path)]) == 0
    out = capsys.readouterr().out
    assert f"document {record.number}" in out and "NOT in the register" not in out


def _crashed_copy(tmp_path, with_index: bool):
    """The files a writer that crashed after its commit leaves: the register, its -wal and
    (unless ``with_index`` is false) its -shm, copied while the writer holds them."""
    crashed = tmp_path / "crashed"
    crashed.mkdir()
    for suffix in ("", "-wal", "-shm") if with_index else ("", "-wal"):
        shutil.copyfile(tmp_path / "w" / f"reg.sqlite{suffix}", crashed / f"reg.sqlite{suffix}")
    return crashed / "reg.sqlite"


def test_a_crashed_writers_journal_is_read_read_only(tmp_path, writer, capsys, monkeypatch):
    register, record = writer
    pdf = _stored_pdf(register, record.number)
    crashed = _crashed_copy(tmp_path, with_index=True)
    (tmp_path / "c.pdf").write_bytes(pdf)
    _cannot_write(monkeypatch, crashed.parent)
    capsys.readouterr()
    assert main(["register", "--register", str(crashed), "verify", str(tmp_path / "c.pdf")]) == 0
    assert f"document {record.number}" in capsys.readouterr().out
    with Register(f"sqlite:///{crashed}") as reader:
        assert reader.read_only and [r.number for r in reader.list()][0] == record.number


def test_a_journal_that_cannot_be_read_is_said_never_not_in_the_register(tmp_path, writer,
                                                                          capsys, monkeypatch):
    """A crashed writer's -wal without its -shm in a folder this user cannot write: SQLite
    cannot read the journal read-only; the main file alone lacks the certificate."""
    register, record = writer
    pdf = _stored_pdf(register, record.number)
    crashed = _crashed_copy(tmp_path, with_index=False)
    (tmp_path / "c.pdf").write_bytes(pdf)
    _cannot_write(monkeypatch, crashed.parent)
    capsys.readouterr()
    assert main(["register", "--register", str(crashed), "verify", str(tmp_path / "c.pdf")]) == 2
    said = capsys.readouterr()
    assert "NOT in the register" not in said.out + said.err
    assert "has writes in its journal (reg.sqlite-wal) that a read-only opening cannot read" \
        in said.err
    assert main(["register", "--register", str(crashed), "verify"]) == 2  # no head is said
    assert "chain head" not in capsys.readouterr().out
    assert sorted(p.name for p in crashed.parent.iterdir()) == ["reg.sqlite", "reg.sqlite-wal"]


def test_a_read_only_register_with_nothing_in_its_journal_is_read_as_before(tmp_path, capsys,
                                                                            monkeypatch):
    (tmp_path / "w").mkdir()
    with Register(f"sqlite:///{tmp_path / 'w' / 'reg.sqlite'}", timezone="UTC") as register:
        number = register.issue(IssueRequest("polygon", META, PROJECT),
                                lambda m, head="": b"%PDF first")[0].number
    assert not (tmp_path / "w" / "reg.sqlite-wal").exists()  # closed: checkpointed
    _cannot_write(monkeypatch, tmp_path / "w")
    with Register(f"sqlite:///{tmp_path / 'w' / 'reg.sqlite'}") as reader:
        assert reader.read_only and [r.number for r in reader.list()] == [number]
