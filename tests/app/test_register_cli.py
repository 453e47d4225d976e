"""``anglebench analyze --certificate`` issues through the register; ``anglebench register``
lists, shows, verifies and exports what was issued (the register of each test is its own,
see conftest.py)."""

from __future__ import annotations

import contextlib
import datetime as dt
import io
import json
import shutil
import subprocess
import zipfile
from pathlib import Path
from types import SimpleNamespace

import pytest
import sqlalchemy as sa

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.register.location import register_url, url_for_path
from models.register.schema import CERTIFICATES, LATEST
from models.register.store import IssueRequest, Register, RegisterError
from tests.own_readings import own_readings
from tests.pdf_stand_in import print_stand_ins
from tests.read_only_file import deny_writing


def issue(samples_dir, tmp_path, name, capsys, *extra, **changes):
    """The polygon sample's certificate issued with the example's details changed by
    ``changes``: the example's item (RX-26-0815) from the sample's readings, another item
    from readings of its own (tests/own_readings.py: one item's readings are refused as
    another's, hostile78 F7)."""
    meta = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    sample = meta["item_serial"]
    meta.update({"example": False, **changes})  # the lab's own details, made from the example
    meta_path = tmp_path / f"{name}.json"
    meta_path.write_text(json.dumps(meta), encoding="utf-8")
    readings = samples_dir / "polygon_sample.csv"
    if meta["item_serial"] != sample:
        readings = own_readings(readings, meta["item_serial"], tmp_path / "readings")
    code = main(["analyze", "polygon", str(readings), "--certificate",
                 str(tmp_path / f"{name}.pdf"), "--metadata", str(meta_path), *extra])
    return code, capsys.readouterr().err


@pytest.fixture(scope="module")
def _sample_issued(tmp_path_factory) -> tuple[Path, int, str]:
    """The polygon sample issued once for the module (``issue(..., "a",
    certificate_number="")``, a certificate rendered) into a register and folder of its own:
    the folder, the exit status and what it said."""
    folder = tmp_path_factory.mktemp("sample_issued")
    samples_dir = Path(__file__).resolve().parents[2] / "resources" / "samples"
    said = io.StringIO()
    with pytest.MonkeyPatch.context() as mp, contextlib.redirect_stderr(said):
        mp.setenv("ANGLEBENCH_REGISTER", str(folder / "register.sqlite"))
        code, _ = issue(samples_dir, folder, "a", _Said(said), certificate_number="")
    return folder, code, said.getvalue()


class _Said:
    """For :func:`issue`, capsys's ``readouterr()``: what the module's issue said on stderr."""

    def __init__(self, said: io.StringIO) -> None:
        self.said = said

    def readouterr(self) -> SimpleNamespace:
        return SimpleNamespace(out="", err=self.said.getvalue())


@pytest.fixture
def issued_a(_sample_issued, tmp_path, capsys) -> tuple[int, str]:
    """``issue(samples_dir, tmp_path, "a", capsys, certificate_number="")`` as the module
    issued it: its register, a.json and a.pdf copied into the test's own (each test changes
    its copy); the exit status and what it said."""
    folder, code, err = _sample_issued
    for path in folder.iterdir():
        shutil.copy2(path, tmp_path / path.name)
    assert register_url() == url_for_path(tmp_path / "register.sqlite")  # the test's own
    capsys.readouterr()
    return code, err


@pytest.mark.slow
def test_issue_list_show_verify_export(samples_dir, tmp_path, capsys, issued_a):
    code, err = issued_a
    year = dt.datetime.now(dt.timezone.utc).year  # the register's day of issue
    assert code == 0 and f"Certificate AB-{year}-0001 issued" in err
    with pytest.MonkeyPatch.context() as mp:  # b's pages are never read: a stand-in PDF
        print_stand_ins(mp)
        code, err = issue(samples_dir, tmp_path, "b", capsys,  # the sample's own number
                          item_serial="RX-26-0816")  # another item: the same one is refused (#61)
    assert code == 0 and "AB-2026-0042" in err
    code, err = issue(samples_dir, tmp_path, "c", capsys, item_serial="RX-26-0817")  # once only
    assert code == 2 and "AB-2026-0042 was issued on" in err and not (tmp_path / "c.pdf").exists()
    assert main(["register", "list", "RX-26", "--json"]) == 0
    listed = json.loads(capsys.readouterr().out)
    assert [r["number"] for r in listed] == ["AB-2026-0042", f"AB-{year}-0001"]
    assert main(["register", "show", f"AB-{year}-0001", "--pdf", str(tmp_path / "copy.pdf"),
                 "--project", str(tmp_path / "p.json")]) == 0
    shown = capsys.readouterr().out
    assert "workbench: polygon" in shown and "headline corrected peak-to-peak" in shown
    assert (tmp_path / "copy.pdf").read_bytes() == (tmp_path / "a.pdf").read_bytes()
    project = json.loads((tmp_path / "p.json").read_text(encoding="utf-8"))
    assert project["workbenches"]["polygon"]["rows"][0][0] == "1"
    assert main(["register", "verify", str(tmp_path / "a.pdf")]) == 0
    assert f"certificate AB-{year}-0001" in capsys.readouterr().out
    tampered = tmp_path / "t.pdf"
    tampered.write_bytes((tmp_path / "a.pdf").read_bytes() + b"%\n")  # one byte changed is enough
    assert main(["register", "verify", str(tampered)]) == 1
    assert "NOT in the register" in capsys.readouterr().out
    assert main(["register", "export", str(tmp_path / "all.zip")]) == 0
    with zipfile.ZipFile(tmp_path / "all.zip") as archive:
        names = set(archive.namelist())
        index = archive.read("index.csv").decode()
    assert {f"pdf/AB-{year}-0001.pdf", "project/AB-2026-0042.anglebench.json"} <= names
    assert index.count("\n") == 3 and "RX-26-0815" in index


def _lab_register() -> None:
    """The test's register made, empty, as a lab's is before a draft is written."""
    with Register(register_url()):
        pass


@pytest.mark.slow
@pytest.mark.usefixtures("pdf_stand_in")  # no PDF page read: the register's answers
def test_a_draft_is_not_recorded_and_bad_requests_exit_2(samples_dir, tmp_path, capsys):
    _lab_register()  # read-only commands refuse a register that is not there (contract75 F10)
    assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"),
                 "--certificate", str(tmp_path / "d.pdf")]) == 0
    assert "nothing was recorded in the register" in capsys.readouterr().err
    assert main(["register", "list"]) == 0 and capsys.readouterr().out == ""
    assert main(["register", "show", "NOPE"]) == 2
    assert "no certificate or test report NOPE in the register" in capsys.readouterr().err
    assert main(["register", "interval", "RX-1", "-5"]) == 2
    assert "positive number of days" in capsys.readouterr().err
    assert main(["register", "--register", "postgresql://x@/db?host=/nonexistent", "list"]) == 2
    assert "register postgresql+psycopg://x@/db" in capsys.readouterr().err


def test_continue_numbering_from_the_command_line(capsys):
    assert main(["register", "continue", "AB-{year}-{seq:04d}", "43", "--date",
                 "2026-11-24"]) == 0
    assert "will be AB-2026-0043" in capsys.readouterr().out
    assert main(["register", "continue", "AB-{year}-{seq:04d}", "5", "--date",
                 "2026-11-24"]) == 2
    assert "never numbers back" in capsys.readouterr().err


@pytest.mark.slow
def test_the_bundled_example_details_never_touch_the_users_register(samples_dir, tmp_path,
                                                                     capsys):
    """Used as the README shows, the examples give a SPECIMEN (#40: they used to give an
    unmarked certificate with the sample's own number, "recorded" in a throw-away
    register): numbered SPECIMEN-…, recorded nowhere, never claiming to be."""
    _lab_register()  # read-only commands refuse a register that is not there (contract75 F10)
    for run in range(2):  # twice: no clash, since nothing is kept
        with pytest.MonkeyPatch.context() as mp:
            if run == 0:  # the first one's pages are never read (the second's are): a stand-in
                print_stand_ins(mp)
            assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"),
                         "--certificate", str(tmp_path / "example.pdf"), "--metadata",
                         str(samples_dir / "certificate_polygon.json")]) == 0
        err = capsys.readouterr().err
        assert "SPECIMEN SPECIMEN-" in err and "recorded in no register" in err
        assert "AB-2026-0042" not in err and "recorded in the register" not in err
    assert (tmp_path / "example.pdf").read_bytes()[:5] == b"%PDF-"
    assert main(["register", "list"]) == 0 and capsys.readouterr().out == ""
    assert main(["register", "verify", str(tmp_path / "example.pdf")]) == 1
    assert "NOT in the register" in capsys.readouterr().out
    if shutil.which("pdftotext"):  # the watermark and the statement on the page
        text = subprocess.run(["pdftotext", str(tmp_path / "example.pdf"), "-"],
                              capture_output=True, text=True, check=True).stdout
        assert "SPECIMEN —" in text and "not a certificate, not recorded in" in text


@pytest.mark.slow
@pytest.mark.usefixtures("pdf_stand_in")  # no PDF page read: the register's answers
def test_issuing_without_an_approver_is_refused(samples_dir, tmp_path, capsys):
    """Without an approver the certificate is only a draft, and nothing is recorded."""
    _lab_register()  # read-only commands refuse a register that is not there (contract75 F10)
    code, err = issue(samples_dir, tmp_path, "n", capsys, approver="")
    assert code == 0 and "DRAFT: approver missing" in err
    assert main(["register", "list"]) == 0 and capsys.readouterr().out == ""


@pytest.mark.slow
def test_verify_names_the_replacement_and_show_refuses_a_changed_pdf(samples_dir, tmp_path,
                                                                     capsys, issued_a):
    assert issued_a[0] == 0
    with Register(register_url()) as register:
        original = register.list()[0].number
        # a replacement is of the same item (rev62 F1): the original's serial number, and
        # (#64 review F5) its maker and customer
        kept = register.get(original)
        meta = CertificateMetadata(approver="Dr. Li", calibration_date="2026-11-20",
                                   item_serial=kept.item_serial,
                                   item_manufacturer=kept.item_manufacturer,
                                   customer_name=kept.customer)
        record, _ = register.issue(
            IssueRequest("polygon", meta, register.get(original).project_json),
            lambda meta: b"%PDF replacement", supersedes=original, replacement=True,
            change_note="re-issued")
    # genuine but no longer valid: its own exit status, not a current one's 0 (day review
    # 65 F12: a script checking by exit status accepted a superseded certificate)
    assert main(["register", "verify", str(tmp_path / "a.pdf")]) == 4
    out = capsys.readouterr().out
    assert "hash chain intact over 2 record(s)" in out
    assert f"{original} is no longer valid: superseded by {record.number}" in out
    engine = sa.create_engine(register_url())
    with engine.begin() as conn:  # the stored PDF changed in the database
        conn.execute(CERTIFICATES.update().where(CERTIFICATES.c.number == original)
                     .values(pdf=b"%PDF forged"))
    engine.dispose()
    assert main(["register", "show", original, "--pdf", str(tmp_path / "out.pdf")]) == 2
    assert "no longer matches the SHA-256" in capsys.readouterr().err
    assert not (tmp_path / "out.pdf").exists()
    assert main(["register", "verify"]) == 3
    assert "stored PDF does not match" in capsys.readouterr().out


def _three(render_head=True) -> list[str]:
    """Three certificates in the test's register (a stand-in PDF that carries its head the
    way a certificate's keywords do)."""
    from models.register.chain import HEAD_MARK

    meta = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-01",
                               item_serial="RX-1")
    with Register(register_url()) as register:
        return [register.issue(IssueRequest("polygon", meta, '{"workbenches": {}}'),
                               lambda m, head="": f"%PDF {m.certificate_number} "
                               f"{HEAD_MARK}{head}".encode())[0].number for _ in range(3)]


def _sql(*statements: str) -> None:
    engine = sa.create_engine(register_url())
    with engine.begin() as conn:
        for statement in statements:
            conn.execute(sa.text(statement))
    engine.dispose()


def test_verify_and_opening_find_a_version_set_back_and_a_truncated_tail(capsys):
    numbers = _three()
    _sql("UPDATE schema_version SET version = 2")
    assert main(["register", "verify"]) == 3
    assert "CHANGED AFTER ISSUE" in capsys.readouterr().out
    assert main(["register", "list"]) == 2
    assert "schema version 2 was set back" in capsys.readouterr().err
    _sql(f"UPDATE schema_version SET version = {LATEST}",  # the version it was at
         f"DELETE FROM certificates WHERE number = '{numbers[-1]}'")
    assert main(["register", "verify"]) == 3
    out = capsys.readouterr().out
    assert "records were deleted" in out and "no record was numbered 3" in out
    assert main(["register", "list"]) == 0
    assert "WARNING: the register recorded 3 record(s)" in capsys.readouterr().err


@pytest.mark.slow
def test_head_verify_head_show_and_withdraw(tmp_path, capsys):
    numbers = _three()
    assert main(["register", "head"]) == 0
    head = capsys.readouterr().out.strip()
    assert len(head) == 64
    assert main(["register", "verify", "--head", head[:16]]) == 0
    assert "the history up to it is still there" in capsys.readouterr().out
    assert main(["register", "verify", "--head", "f" * 20]) == 3
    assert "is not in the register's chain" in capsys.readouterr().out
    assert main(["register", "show", numbers[1], "--pdf", str(tmp_path / "2.pdf")]) == 0
    shown = capsys.readouterr().out
    assert "approver: Dr. Li" in shown and "os_user:" in shown and "chain_sha256:" in shown
    assert main(["register", "verify", "--head-from", str(tmp_path / "2.pdf")]) == 0
    assert main(["register", "withdraw", numbers[1], "--reason", "wrong item"]) == 0
    capsys.readouterr()
    assert main(["register", "verify", str(tmp_path / "2.pdf")]) == 4
    out = capsys.readouterr().out
    assert f"{numbers[1]} is no longer valid: withdrawn (wrong item)" in out
    assert main(["register", "list", "--json"]) == 0
    assert {r["number"]: r["state"] for r in json.loads(capsys.readouterr().out)}[
        numbers[1]] == "withdrawn"
    assert main(["register", "withdraw", numbers[1], "--reason", "again"]) == 2
    assert "was withdrawn" in capsys.readouterr().err


def _titled(number_of_records: int, key: str = "") -> list[str]:
    """Certificates whose stand-in PDF carries its head in its keywords and its number in
    its title, as a certificate's document information does (with ``key``, the register's
    proof of issue too)."""
    from models.register.chain import HEAD_MARK

    meta = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-01",
                               item_serial="RX-1")

    def render(m, head: str = "", proof: str = "") -> bytes:
        carried = f" anglebench-register-proof:{proof}" if proof else ""
        return (f"%PDF /Title (Calibration certificate {m.certificate_number}) /Keywords "
                f"({HEAD_MARK}{head}{carried})").encode()

    with Register(register_url(), key_file=key) as register:
        return [register.issue(IssueRequest("polygon", meta, '{"workbenches": {}}'),
                               render)[0].number for _ in range(number_of_records)]


def _truncate_consistently(number: str) -> None:
    """The last record deleted by hand, the counter and the state row set back to the
    record before it: the register agrees with itself (rev64 F8, f_truncate.sh)."""
    _sql(f"UPDATE register_state SET value = (SELECT chain_sha256 FROM certificates WHERE seq "
         f"= (SELECT seq - 1 FROM certificates WHERE number = '{number}')) WHERE name = 'head'",
         f"UPDATE register_state SET value = (SELECT seq - 1 FROM certificates WHERE number = "
         f"'{number}') WHERE name = 'records'",
         "UPDATE counters SET last_value = last_value - 1",
         f"DELETE FROM certificates WHERE number = '{number}'")


def test_a_certificate_whose_record_was_deleted_is_named_by_its_head_and_stops_issuing(
        tmp_path, capsys, monkeypatch):
    """rev64 F8: verify --head-from CERT.pdf said "the history up to it is still there" of a
    certificate whose own record was deleted, and its number was issued again. Recorded
    (issuing stopped) only for a certificate that carries the proof of the lab's key
    (reg73 #3): with the key."""
    import os

    key = tmp_path / "lab.key"
    key.write_bytes(os.urandom(32))
    monkeypatch.setenv("ANGLEBENCH_REGISTER_KEY", str(key))
    numbers = _titled(2, str(key))
    engine = sa.create_engine(register_url())
    with engine.connect() as conn:  # a signed state to replay (reg73 #2: any backup)
        state = [tuple(r) for r in conn.execute(sa.text("SELECT name, value FROM "
                                                        "register_state"))]
        counters = [tuple(r) for r in conn.execute(sa.text("SELECT name, last_value FROM "
                                                           "counters"))]
    engine.dispose()
    numbers += _titled(1, str(key))
    for n, number in enumerate(numbers, 1):
        assert main(["register", "show", number, "--pdf", str(tmp_path / f"{n}.pdf")]) == 0
    assert main(["register", "verify", "--head-from", str(tmp_path / "3.pdf")]) == 0
    capsys.readouterr()
    _sql(f"DELETE FROM certificates WHERE number = '{numbers[2]}'",
         *(f"UPDATE register_state SET value = '{v}' WHERE name = '{n}'" for n, v in state),
         *(f"UPDATE counters SET last_value = {v} WHERE name = '{n}'" for n, v in counters))
    # by someone who can write every file: the high-water mark beside the key goes too
    # (else it finds the replay on opening: reg73 #2)
    shutil.rmtree(tmp_path / "lab.key.high-water")
    assert main(["register", "verify"]) == 0  # the register agrees with itself
    capsys.readouterr()
    assert main(["register", "verify", "--head-from", str(tmp_path / "3.pdf")]) == 3
    out = capsys.readouterr().out
    assert (f"CHANGED AFTER ISSUE: {tmp_path / '3.pdf'} ({numbers[2]}) was issued as record "
            "3, right after the head it prints, but the register's chain ends at that head "
            "and no record has its SHA-256: its record was deleted after issue") in out
    assert "recorded in the register: nothing is issued" in out
    assert main(["register", "verify"]) == 3  # from now on, on every opening
    assert f"certificate {numbers[2]}: its PDF (SHA-256" in capsys.readouterr().out
    meta = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-01",
                               item_serial="RX-2")
    with Register(register_url()) as register, pytest.raises(  # its number not issued again
            RegisterError, match=f"certificate {numbers[2]}: its PDF.*nothing is recorded "
                                 "into a broken chain"):
        register.issue(IssueRequest("polygon", meta, '{"workbenches": {}}'),
                       lambda m, head="": b"%PDF again")
    assert main(["register", "verify", "--head-from", str(tmp_path / "2.pdf")]) == 3
    assert f"2.pdf: {numbers[1]} is record 2, right after that head" in capsys.readouterr().out


def test_a_certificate_whose_record_was_replaced_after_deletion_is_named(tmp_path, capsys):
    """The record deleted and its number issued again before anyone looked: the PDF in hand
    is not what the register holds at its place, said as either (nothing recorded)."""
    numbers = _titled(2)
    assert main(["register", "show", numbers[1], "--pdf", str(tmp_path / "2.pdf")]) == 0
    _truncate_consistently(numbers[1])
    meta = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-02",
                               item_serial="RX-1")
    with Register(register_url()) as register:
        again = register.issue(IssueRequest("polygon", meta, '{"workbenches": {}}'),
                               lambda m, head="": b"%PDF another")[0].number
    assert again == numbers[1]
    capsys.readouterr()
    for args in (["--head-from", str(tmp_path / "2.pdf")], [str(tmp_path / "2.pdf")]):
        assert main(["register", "verify", *args]) == 1
        assert (f"prints the head before record 2, but record 2 is {numbers[1]}, not this PDF: "
                "the PDF was altered after issue, or the register's record of it was replaced"
                ) in capsys.readouterr().out
    assert main(["register", "verify"]) == 0  # nothing recorded: the cause is not known


def test_a_read_only_sqlite_register_is_listed_and_verified(monkeypatch, capsys):

    numbers = _three()
    path = register_url().split("///", 1)[1]
    deny_writing(monkeypatch, path)
    assert main(["register", "list"]) == 0
    assert capsys.readouterr().out.count("\n") == 4  # the header and three
    assert main(["register", "verify"]) == 0
    assert main(["register", "withdraw", numbers[0], "--reason", "x"]) == 2
    assert "read-only" in capsys.readouterr().err


@pytest.mark.slow
def test_a_pdf_copied_into_a_second_record_is_said(tmp_path, capsys):
    numbers = _three()
    assert main(["register", "show", numbers[0], "--pdf", str(tmp_path / "1.pdf")]) == 0
    _sql(f"UPDATE certificates SET pdf = (SELECT pdf FROM certificates WHERE number = "
         f"'{numbers[0]}'), pdf_sha256 = (SELECT pdf_sha256 FROM certificates WHERE number = "
         f"'{numbers[0]}') WHERE number = '{numbers[2]}'")
    capsys.readouterr()
    assert main(["register", "verify", str(tmp_path / "1.pdf")]) == 3
    out = capsys.readouterr().out
    assert f"its SHA-256 is in 2 records ({numbers[0]}, {numbers[2]})" in out


def _pdf_text(path) -> str:
    """The PDF's text as poppler's pdftotext reads it (pypdf where poppler is missing)."""
    if shutil.which("pdftotext"):
        return subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True,
                              check=True, text=True).stdout
    from pypdf import PdfReader

    return "\n".join(p.extract_text() for p in PdfReader(path).pages)


@pytest.mark.slow
def test_a_checker_signs_when_the_labs_template_asks_and_show_prints_it(samples_dir, tmp_path,
                                                                       capsys):
    # without the setting: two signatures, as before
    code, _ = issue(samples_dir, tmp_path, "two", capsys, certificate_number="",
                    checker="Zhao Min")
    text = _pdf_text(tmp_path / "two.pdf")
    assert code == 0 and "Operator" in text and "Checked by" not in text
    # asked for, but no checker named: a draft, nothing recorded (its pages never read: a
    # stand-in PDF)
    with pytest.MonkeyPatch.context() as mp:
        print_stand_ins(mp)
        code, err = issue(samples_dir, tmp_path, "draft", capsys, certificate_number="",
                          checker_role=True)
    assert code == 0 and "checker missing; nothing was recorded" in err
    for language, roles in (("en", ("Calibrated by", "Checked by", "Approved by")),
                            ("zh", ("校准员", "核验员", "批准人")),
                            ("zh+en", ("校准员 Calibrated by", "核验员 Checked by",
                                       "批准人 Approved by"))):
        name = language.replace("+", "")
        code, err = issue(samples_dir, tmp_path, name, capsys, certificate_number="",
                          checker_role=True, checker="Zhao Min", language=language,
                          item_serial=f"RX-{name}")  # one item each: one issued again is refused
        assert code == 0, err
        text = " ".join(_pdf_text(tmp_path / f"{name}.pdf").split())
        assert all(role in text for role in roles), (language, text[-400:])
        assert "Zhao Min" in text
        number = err.split("Certificate ")[1].split()[0]
        assert main(["register", "show", number]) == 0
        assert "checker: Zhao Min" in capsys.readouterr().out


def test_show_writes_the_dcc_as_issued_and_verify_checks_it(tmp_path, capsys):
    """#43: ``register show N --dcc OUT.xml`` writes the DCC issued with the PDF (atomic,
    guarded like --pdf); a DCC changed in the database is refused and found by verify."""
    from tests import dcc_documents as t

    meta = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-01",
                               item_serial="PG-1")
    with Register(register_url()) as register:
        plain = register.issue(IssueRequest("polygon", meta, '{"workbenches": {}}'),
                               lambda m: f"%PDF {m.certificate_number}".encode())[0].number
        number = register.issue(IssueRequest("polygon", meta, '{"workbenches": {}}'),
                                lambda m: f"%PDF {m.certificate_number}".encode(),
                                render_dcc=lambda m, pdf: t.document(m.certificate_number,
                                                                     pdf=pdf))[0].number
        issued = register.dcc(number)
    out = tmp_path / "out.xml"
    assert main(["register", "show", number, "--dcc", str(out)]) == 0
    assert out.read_bytes() == issued and "dcc_sha256" in capsys.readouterr().out
    assert main(["register", "verify"]) == 0
    assert "every stored PDF and DCC matches" in capsys.readouterr().out
    received = tmp_path / "received.xml"
    received.write_bytes(issued)
    assert main(["register", "verify", str(received)]) == 0
    # issued here without its kind (no document_kind): named "document", never guessed
    assert f"document {number}, issued" in capsys.readouterr().out
    received.write_bytes(issued.replace(b"</dcc:uniqueIdentifier>", b"X</dcc:uniqueIdentifier>"))
    assert main(["register", "verify", str(received)]) == 1
    assert "NOT in the register (no issued DCC has its SHA-256" in capsys.readouterr().out
    assert main(["register", "export", str(tmp_path / "all.zip")]) == 0
    with zipfile.ZipFile(tmp_path / "all.zip") as archive:
        assert archive.read(f"dcc/{number}.xml") == issued
        assert not any(n.startswith(f"dcc/{plain}") for n in archive.namelist())
    capsys.readouterr()
    assert main(["register", "show", plain, "--dcc", str(tmp_path / "none.xml")]) == 2
    assert "issued without a digital calibration certificate" in capsys.readouterr().err
    assert main(["register", "show", number, "--dcc", register_url().split("///", 1)[1]]) == 2
    capsys.readouterr()  # the register itself is never an output
    _sql(f"UPDATE certificates SET dcc = X'3c782f3e' WHERE number = '{number}'")
    assert main(["register", "show", number, "--dcc", str(tmp_path / "changed.xml")]) == 2
    assert "stored DCC of" in capsys.readouterr().err
    assert not (tmp_path / "changed.xml").exists()
    assert main(["register", "verify"]) == 3
    assert "stored DCC does not match" in capsys.readouterr().out


@pytest.mark.slow
def test_an_issued_dcc_is_recorded_signed_and_shown_as_written(samples_dir, tmp_path, capsys,
                                                                monkeypatch):
    """#43: ``analyze --certificate --dcc`` through the register: the register stores the DCC
    written (signed with the lab's key when configured), ``register show --dcc`` gives it
    back byte for byte, the PDF inside is the PDF issued, and verify checks both."""
    from models.dcc import signature
    from models.dcc.reader import embedded_pdfs
    from tests import dcc_documents as t

    key, cert = t.self_signed(tmp_path)
    (tmp_path / "lab.key").write_bytes(key)
    (tmp_path / "lab.pem").write_bytes(cert)
    monkeypatch.setenv(signature.KEY_ENV_VAR, str(tmp_path / "lab.key"))
    monkeypatch.setenv(signature.CERT_ENV_VAR, str(tmp_path / "lab.pem"))
    meta = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    meta.update({"example": False, "certificate_number": ""})
    (tmp_path / "m.json").write_text(json.dumps(meta), encoding="utf-8")
    pdf, xml = tmp_path / "c.pdf", tmp_path / "c.xml"
    assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"), "--metadata",
                 str(tmp_path / "m.json"), "--certificate", str(pdf), "--dcc", str(xml),
                 "--dcc-schema", str(t.SHARED_DCC)]) == 0
    err = capsys.readouterr().err
    number = err.split("Certificate ", 1)[1].split(" issued", 1)[0]
    t.assert_valid(xml.read_bytes())  # signed, and still valid against the schema
    assert signature.verify(xml.read_bytes(), cert).problems == ()
    assert embedded_pdfs(xml.read_bytes()) == [pdf.read_bytes()]
    assert main(["register", "show", number, "--dcc", str(tmp_path / "again.xml")]) == 0
    assert (tmp_path / "again.xml").read_bytes() == xml.read_bytes()
    capsys.readouterr()
    assert main(["register", "verify"]) == 0
    assert "every stored PDF and DCC matches" in capsys.readouterr().out


@pytest.mark.slow
def test_a_calibration_issued_again_is_refused_unless_said_separate(samples_dir, tmp_path,
                                                                    capsys, issued_a):
    """#61 assessor: one reading changed and the same polygon, serial and date of calibration
    issued again gave a second original, both current, neither naming the other. Refused,
    naming the first; --separate-calibration issues it, naming the first and why."""
    code, err = issued_a
    year = dt.datetime.now(dt.timezone.utc).year
    first = f"AB-{year}-0001"
    assert code == 0 and f"Certificate {first} issued" in err
    code, err = issue(samples_dir, tmp_path, "b", capsys, certificate_number="")
    assert code == 2 and f"{first} already reports this calibration" in err
    assert "--separate-calibration" in err and not (tmp_path / "b.pdf").exists()
    meta = json.loads((tmp_path / "b.json").read_text(encoding="utf-8"))
    # the same readings (each within its last digit), with the same details: the first calibration
    # issued again, not one of its own (register79), whatever the reason given
    code = main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"), "--certificate",
                 str(tmp_path / "c.pdf"), "--metadata", str(tmp_path / "b.json"),
                 "--separate-calibration", "as left, after the read head was adjusted"])
    err = " ".join(capsys.readouterr().err.split())
    assert code == 2 and f"the readings are the same as those of {first} " in err
    assert "each within the last digit it was typed to" in err and "every digit" not in err
    assert f"--same-readings-as {first}:REASON" in err and not (tmp_path / "c.pdf").exists()
    # a calibration of its own has readings of its own: the polygon as left after adjustment
    as_left = own_readings(samples_dir / "polygon_sample.csv", "as left", tmp_path / "left")
    code = main(["analyze", "polygon", str(as_left), "--certificate",
                 str(tmp_path / "c.pdf"), "--metadata", str(tmp_path / "b.json"),
                 "--separate-calibration", "as left, after the read head was adjusted"])
    err = capsys.readouterr().err
    assert code == 0 and f"Certificate AB-{year}-0002 issued" in err
    flat = " ".join(_pdf_text(tmp_path / "c.pdf").split())
    assert (f"A calibration of its own, separate from certificate {first} of the same item and "
            "date of calibration, which stays valid: as left, after the read head was "
            "adjusted") in flat
    with Register(register_url()) as register:
        assert register.get(f"AB-{year}-0002").change_note.startswith("as left")
        assert register.get(first).status == "issued"
    assert main(["register", "show", f"AB-{year}-0002"]) == 0  # the link in the register too
    shown = capsys.readouterr().out
    assert f"separate_from: {first}" in shown
    assert "change_note: as left, after the read head was adjusted" in shown
    assert meta["item_serial"]  # the sample names its item: the check had a serial to go by


@pytest.mark.parametrize(("field", "what", "typed", "at"), [
    ("customer_name", "customer", "ACME\u3164Ltd", 5),
    ("item_description", "item description", "Rotary\u034f encoder", 7),
    ("item_manufacturer", "manufacturer", "Example\ufe0f Instruments", 8)])
def test_analyze_refuses_a_customer_description_or_maker_that_prints_nothing(
        samples_dir, tmp_path, capsys, field, what, typed, at):
    """#63 regkeys: ``analyze --certificate`` issued a customer, description or maker
    holding a default-ignorable character that is no control or format character (the
    details file refuses those: U+200B), such as U+3164 HANGUL FILLER, printed as a blank
    and stored as another text; a serial or number with such a character was refused."""
    code, err = issue(samples_dir, tmp_path, "a", capsys, certificate_number="",
                      **{field: typed})
    assert code != 0 and not (tmp_path / "a.pdf").exists()
    assert (f"{what} \"{typed.encode('ascii', 'backslashreplace').decode()}\": character "
            f"{at} is U+{ord(typed[at - 1]):04X}") in err
    assert "no certificate was written" in err
    with Register(register_url()) as register:
        assert register.list() == []


def test_show_gives_the_due_date_of_that_makers_item(capsys):
    """#64 review F6: with Acme's "001" calibrated 2025-06-01 and Zeta's "001" on
    2026-11-20, ``register show`` of Acme's certificate gave "due: 2027-11-20" (Zeta's
    calibration) for an instrument overdue since 2026-06-01."""
    numbers = []
    with Register(register_url()) as register:
        for maker, day in (("Acme Optics", "2025-06-01"), ("Zeta Instruments", "2026-11-20")):
            meta = CertificateMetadata(approver="Dr. Li", calibration_date=day,
                                       item_serial="001", item_manufacturer=maker)
            numbers.append(register.issue(IssueRequest("polygon", meta, "{}"),
                                          lambda meta: b"%PDF")[0].number)
    assert main(["register", "interval", "001", "365"]) == 0
    capsys.readouterr()
    assert main(["register", "show", numbers[0]]) == 0
    assert "next calibration of 001 due: 2026-06-01" in capsys.readouterr().out
    assert main(["register", "show", numbers[1]]) == 0
    assert "next calibration of 001 due: 2027-11-20" in capsys.readouterr().out


def test_show_states_a_corrected_customer_maker_and_description(capsys):
    """#64 review F5: an amendment that changed the manufacturer, description and customer
    of an item with a serial said nothing of it but the note; ``show`` now gives each."""
    item = {"approver": "Dr. Li", "calibration_date": "2026-11-20", "item_serial": "LRA-0815",
            "item_manufacturer": "Example Instruments", "customer_name": "Acme Optics",
            "item_description": "Limited-rotation axis"}
    other = {**item, "item_manufacturer": "Other Corp", "customer_name": "Another Customer Ltd",
             "item_description": "24-face polygon"}
    with Register(register_url()) as register:
        first = register.issue(IssueRequest("polygon", CertificateMetadata(**item), "{}"),
                               lambda meta: b"%PDF")[0].number
        amended = register.issue(IssueRequest("polygon", CertificateMetadata(**other), "{}"),
                                 lambda meta: b"%PDF A1", supersedes=first, change_note="typo",
                                 correction_confirmed=True)[0].number
    capsys.readouterr()
    assert main(["register", "show", amended]) == 0
    shown = capsys.readouterr().out
    assert (f"change_note: manufacturer corrected from Example Instruments (on {first}) to "
            f"Other Corp; customer corrected from Acme Optics (on {first}) to Another Customer "
            f"Ltd; item description changed from Limited-rotation axis (on {first}) to 24-face "
            "polygon; typo") in shown


def test_verify_tells_a_changed_register_from_a_wrong_command_line(tmp_path, capsys):
    """stop 63: ``register verify`` exited 2 both for a register whose records were changed
    after issue and for a command line it could not carry out; a file read after the
    register's findings made a tampered register exit 2. Now: 0 verified, 1 a file the
    register did not issue, 2 the command line (nothing checked), 3 the register changed
    (before 1 when both)."""
    numbers = _three()
    assert main(["register", "show", numbers[0], "--pdf", str(tmp_path / "1.pdf")]) == 0
    (tmp_path / "other.pdf").write_bytes(b"%PDF not issued here")
    capsys.readouterr()
    assert main(["register", "verify", str(tmp_path / "1.pdf")]) == 0
    assert main(["register", "verify", str(tmp_path / "other.pdf")]) == 1
    capsys.readouterr()
    with pytest.raises(SystemExit) as refused:
        main(["register", "verify", "--nonsense"])
    assert refused.value.code == 2
    for wrong in (["verify", str(tmp_path / "missing.pdf")],
                  ["verify", "--head-from", str(tmp_path / "other.pdf")]):
        assert main(["register", *wrong]) == 2, wrong
        assert "CHANGED AFTER ISSUE" not in capsys.readouterr().out
    _sql(f"UPDATE certificates SET customer = 'Someone else' WHERE number = '{numbers[1]}'")
    assert main(["register", "verify"]) == 3
    assert "CHANGED AFTER ISSUE: record" in capsys.readouterr().out
    assert main(["register", "verify", str(tmp_path / "other.pdf")]) == 3  # before 1
    assert "NOT in the register" in capsys.readouterr().out
    # the command line still comes first: nothing is checked, exit 2, the file named
    assert main(["register", "verify", str(tmp_path / "missing.pdf")]) == 2
    captured = capsys.readouterr()
    assert "missing.pdf: cannot read" in captured.err and captured.out == ""


def test_verify_says_a_table_deleted_from_the_register_is_a_change(capsys):
    """A table dropped outside AngleBench was "register …: no such table: entries", exit 2
    (a register that cannot be reached); it is a change after issue, exit 3."""
    _three()
    _sql("DROP TABLE entries")
    assert main(["register", "verify"]) == 3
    out = capsys.readouterr().out
    assert "CHANGED AFTER ISSUE" in out and "table(s) entries are gone" in out
    assert main(["register", "list"]) == 2  # any other command refuses to open it


def test_a_full_disk_when_export_writes_is_said_in_words(tmp_path, monkeypatch, capsys):
    """stop 63: 'cannot write: [Errno 28] No space left on device: …'; now where, and that
    nothing was written and the register is unchanged."""
    import errno

    import app.register_cli as register_cli

    _three()
    before = main(["register", "head"]), capsys.readouterr().out

    def full(path, data):
        raise OSError(errno.ENOSPC, "No space left on device", str(tmp_path / ".all.zip.tmp"))

    monkeypatch.setattr(register_cli, "write_bytes_atomic", full)
    assert main(["register", "export", str(tmp_path / "all.zip")]) == 2  # as analyze's outputs
    err = capsys.readouterr().err
    assert (f"{tmp_path / 'all.zip'} cannot be written: the disk is full; nothing was written "
            "there and the register is unchanged") in err and "Errno" not in err  # the file named
    assert not (tmp_path / "all.zip").exists()
    assert (main(["register", "head"]), capsys.readouterr().out) == before


@pytest.mark.usefixtures("pdf_stand_in")  # no PDF page read: the register's answers
def test_another_makers_item_is_issued_only_with_its_option_and_shown(samples_dir, tmp_path,
                                                                      capsys):
    """rev65 F1: a certificate naming another maker than a current one of the same serial
    and date is refused without --another-makers-item; with it, issued, and `register show`
    prints the user's word from the register's chain."""
    def analyze(name, maker, *options):
        meta = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
        meta.update({"example": False, "certificate_number": "", "item_manufacturer": maker})
        (tmp_path / f"{name}.json").write_text(json.dumps(meta), encoding="utf-8")
        # Zeta's item, another, has readings of its own (one item's are refused as
        # another's: hostile78 F7); Möller-Wedel's, spelt either way, the sample's
        readings = own_readings(samples_dir / "polygon_sample.csv", "Zeta RX-26-0815",
                                tmp_path / "readings") if maker.startswith("Zeta") else \
            samples_dir / "polygon_sample.csv"
        code = main(["analyze", "polygon", str(readings),
                     "--certificate", str(tmp_path / f"{name}.pdf"), "--metadata",
                     str(tmp_path / f"{name}.json"), *options])
        return code, capsys.readouterr().err

    assert analyze("a", "Möller-Wedel Optical GmbH")[0] == 0
    with Register(register_url()) as register:
        [first] = [r.number for r in register.list()]
    code, err = analyze("b", "Moeller-Wedel Optical")  # issued before rev65 F1's fix
    assert code != 0 and f"{first} already reports this calibration" in err, err
    code, err = analyze("b", "Zeta Instruments")
    assert code != 0 and err.startswith(
        f"anglebench analyze: {first} reports serial RX-26-0815, calibrated 2026-11-20, of "
        "Möller-Wedel Optical GmbH, not of Zeta Instruments"), err
    assert "--another-makers-item" in err and "no certificate was written" in err
    code, err = analyze("b", "Moeller-Wedel Optical", "--another-makers-item")
    assert code != 0 and "already reports this calibration" in err  # one maker: no
    code, err = analyze("b", "Zeta Instruments", "--another-makers-item")
    assert code == 0, err
    with Register(register_url()) as register:
        [second] = [r.number for r in register.list() if r.number != first]
    assert main(["register", "show", second]) == 0
    assert (f"Zeta Instruments, not the maker of {first} (Möller-Wedel Optical GmbH)"
            in capsys.readouterr().out)
    assert main(["register", "verify"]) == 0
