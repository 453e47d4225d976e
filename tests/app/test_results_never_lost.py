"""The write paths of an issue (rev62 F6–F8, M1, M4–M6): an output that cannot be written is
refused before a number is used; a results file is recorded only once its bytes are on disk,
and a failure says which file is missing; an issued file (PDF, DCC, results file) is never
replaced by a later issue; a certificate has one results file, and ``register verify
FILE.xlsx`` refuses one recorded under two certificates, or as a second one, or saying it is
another certificate's; ``register show``/``export``/``verify`` list the results files. The
steps are those of the review's scripts (out_attacks.sh, diskfull_results.sh,
repro_results_launder.sh, repro_fifo_hang.py, repro_case_names.sh). The register of each test
is its own (conftest.py)."""

from __future__ import annotations

import errno
import hashlib
import json
import os
import tempfile
import threading
import zipfile
from pathlib import Path

import pytest

from app.main import main
from models.project.output_guard import OutputRefused, check_output, check_outputs
from models.register.location import register_url
from models.register.store import Register, RegisterError
from tests.own_readings import own_readings

#: the tests are of where an issue's files go and what the register keeps of them, never of
#: a PDF's pages: each certificate's PDF a stand-in (tests/app/conftest.py; ~0.5 s of CPU a
#: certificate not printed, at each of the module's issues and drafts)
pytestmark = pytest.mark.usefixtures("pdf_stand_in")


def _details(samples_dir, tmp_path, name="details.json", **changes):
    meta = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    meta.update({"example": False, "certificate_number": "", **changes})
    path = tmp_path / name
    path.write_text(json.dumps(meta), encoding="utf-8")
    return path


def _issue(samples_dir, tmp_path, *outputs, details=None, separate=False):
    """The polygon sample issued: the example's item from the sample's readings, another item
    from readings of its own (tests/own_readings.py, beside ``tmp_path``: one item's
    readings are refused as another's, hostile78 F7)."""
    readings = samples_dir / "polygon_sample.csv"
    serial = json.loads(Path(details).read_text(encoding="utf-8"))["item_serial"] \
        if details else ""
    if serial and serial != json.loads((samples_dir / "certificate_polygon.json").read_text(
            encoding="utf-8"))["item_serial"]:
        readings = own_readings(readings, serial, tmp_path.with_name(f"{tmp_path.name}-own"))
    if separate:  # a calibration of its own has readings of its own (register79: the
        # same readings and details are the first calibration issued again, refused)
        readings = own_readings(readings, f"rerun {len(list(tmp_path.glob('*')))}",
                                tmp_path.with_name(f"{tmp_path.name}-rerun"))
    return main(["analyze", "polygon", str(readings),
                 "--metadata", str(details or _details(samples_dir, tmp_path)), *outputs,
                 *(["--separate-calibration", "rerun"] if separate else [])])


def _numbers():
    with Register(register_url()) as register:
        return [r.number for r in register.list()]


def _results():
    with Register(register_url()) as register:
        return register.results_records()


def _sha(path):
    return hashlib.sha256(path.read_bytes()).hexdigest()


# -- outputs that cannot be written: refused before a number is used (F6, M1) -----------------

def test_a_fifo_as_an_output_is_refused_at_once(tmp_path):
    """rev62 M1: the guard opened the FIFO to look for a database and waited for a writer
    for ever."""
    fifo = tmp_path / "fifo.xlsx"
    os.mkfifo(fifo)
    outcome = []

    def check():
        try:
            check_output(str(fifo), [], "--results")
            outcome.append("accepted")
        except OutputRefused as exc:
            outcome.append(str(exc))

    worker = threading.Thread(target=check, daemon=True)
    worker.start()
    worker.join(10)
    if worker.is_alive():  # the old guard: let it go (a writer opens the FIFO) and fail
        with open(fifo, "wb"):
            pass
        worker.join(10)
        pytest.fail("the output guard blocked on a FIFO")
    assert outcome == [f"--results {fifo} is not a regular file (a pipe, a device or a "
                       "socket); nothing was written: name a file"]


def test_names_differing_only_in_case_are_one_output(tmp_path):
    """rev62 M5: out.pdf and OUT.pdf are one file on macOS, Windows and a FAT stick: the DCC
    would replace the PDF there."""
    with pytest.raises(OutputRefused, match=r"--certificate and --dcc name the same file"):
        check_outputs((("--certificate", str(tmp_path / "out.pdf")),
                       ("--dcc", str(tmp_path / "OUT.pdf"))), [])


@pytest.mark.slow
def test_a_name_too_long_uses_no_number(samples_dir, tmp_path, capsys):
    """out_attacks.sh cases 4 and 5: a 256-byte name was issued and recorded, then not
    written."""
    long_results = tmp_path / ("r" * 251 + ".xlsx")
    code = _issue(samples_dir, tmp_path, "--certificate", str(tmp_path / "c.pdf"),
                  "--results", str(long_results))
    said = capsys.readouterr().err
    assert code == 2
    assert (f"--results {long_results}: the name is longer than its folder allows (255 "
            "bytes); nothing was written: choose a shorter name") in said
    assert _numbers() == [] and not (tmp_path / "c.pdf").exists()


@pytest.mark.slow
def test_read_only_media_use_no_number(samples_dir, tmp_path, capsys, monkeypatch):
    """out_attacks.sh cases 2 and 3: --results (or --certificate) on read-only media was
    issued and recorded, then not written. Read-only media are simulated: no file can be
    created in the folder ``ro``."""
    ro = tmp_path / "ro"
    ro.mkdir()
    real = tempfile.mkstemp

    def mkstemp(*args, **kwargs):
        if os.path.abspath(str(kwargs.get("dir", ""))) == str(ro):
            raise OSError(errno.EROFS, "Read-only file system")
        return real(*args, **kwargs)

    monkeypatch.setattr(tempfile, "mkstemp", mkstemp)
    code = _issue(samples_dir, tmp_path, "--certificate", str(tmp_path / "c.pdf"),
                  "--results", str(ro / "r.xlsx"))
    said = capsys.readouterr().err
    assert code == 2
    assert (f"--results {ro / 'r.xlsx'}: no file can be written in {ro} (Read-only file "
            "system); nothing was written") in said
    assert _numbers() == [] and not (tmp_path / "c.pdf").exists()


# -- the results file recorded only once written; the advice names it (F6, M6) ----------------

def _failing_fsync(monkeypatch, name):
    """A full disk for the file ``name`` (its temporary file beside it): the fsync of its
    bytes fails with ENOSPC, as on the review's 300 KiB tmpfs."""
    real = os.fsync

    def fsync(fd):
        if f"/.{name}." in os.readlink(f"/proc/self/fd/{fd}"):
            raise OSError(errno.ENOSPC, "No space left on device")
        return real(fd)

    monkeypatch.setattr(os, "fsync", fsync)


@pytest.mark.slow
@pytest.mark.skipif(not os.path.isdir("/proc/self/fd"), reason="finds the file by /proc")
def test_a_results_file_not_written_is_not_recorded_and_said(samples_dir, tmp_path, capsys):
    """diskfull_results.sh: the results file did not fit; the register recorded it anyway,
    nothing said so, and the advice pointed at --pdf."""
    pdf, dcc, xlsx = tmp_path / "c.pdf", tmp_path / "c.xml", tmp_path / "r.xlsx"
    with pytest.MonkeyPatch.context() as patch:
        _failing_fsync(patch, "r.xlsx")
        code = _issue(samples_dir, tmp_path, "--certificate", str(pdf), "--dcc", str(dcc),
                      "--results", str(xlsx))
    said = capsys.readouterr().err
    (number,) = _numbers()
    assert code == 2
    assert (f"anglebench analyze: certificate {number} is issued, recorded and written (its "
            "PDF, and its DCC if asked for), but its results file was not "
            f"({xlsx}: No space left on device): the register records no results file for "
            f"{number}") in said
    assert "--pdf" not in said
    assert pdf.exists() and dcc.exists() and not xlsx.exists()
    assert _results() == []  # no record of a file that is not there
    assert list(tmp_path.glob(".r.xlsx.*")) == []  # nor its temporary file
    assert main(["register", "show", number]) == 0
    assert "results file" not in capsys.readouterr().out


@pytest.mark.slow
def test_a_results_file_recorded_but_not_renamed_is_kept_and_said(samples_dir, tmp_path,
                                                                  capsys):
    """The narrow case left: recorded, then the rename failed (or the process was killed):
    the recorded bytes are kept beside it under a name that says whose they are (not the
    temporary name, which a later save of r.xlsx clears as a killed save's leftover after
    ten minutes), and the message says where."""
    pdf, xlsx = tmp_path / "c.pdf", tmp_path / "r.xlsx"
    real = os.replace

    def replace(source, target, *args, **kwargs):
        if str(target).endswith("r.xlsx"):
            raise OSError(errno.EIO, "Input/output error")
        return real(source, target, *args, **kwargs)

    def link(source, target, *args, **kwargs):  # the name is taken by a hard link (rev63 F7)
        if str(target).endswith("r.xlsx"):
            raise OSError(errno.EIO, "Input/output error")
        return real_link(source, target, *args, **kwargs)

    real_link = os.link
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(os, "replace", replace)
        patch.setattr(os, "link", link)
        code = _issue(samples_dir, tmp_path, "--certificate", str(pdf), "--results", str(xlsx))
    said = capsys.readouterr().err
    (number,) = _numbers()
    kept = tmp_path / f"r.{number}.xlsx"
    assert kept.is_file() and not list(tmp_path.glob(".r.xlsx.*.tmp"))
    assert code == 2
    assert (f"certificate {number} is issued, recorded and written, and its results file "
            f"recorded, but not renamed into place ({xlsx}: Input/output error): the "
            f"recorded file is {kept}; rename it to {xlsx}") in said
    (entry,) = _results()
    assert entry["number"] == number and entry["sha256"] == _sha(kept)


class _Killed(BaseException):
    """The process killed (kill -9) at that point: nothing after it runs."""


@pytest.mark.slow
def test_a_results_file_recorded_then_killed_before_named_is_never_cleared(samples_dir,
                                                                          tmp_path, capsys):
    """#63 regkeys: an issue killed between recording the results file and naming it left
    the recorded bytes only in the temporary ".r.xlsx.*.tmp", which the next save of r.xlsx
    deleted after ten minutes as a killed save's leftover: the only copy of a recorded
    results file. It is now kept beside it as r.<number>.xlsx, and said."""
    import app.certificate_issue

    pdf, xlsx = tmp_path / "c.pdf", tmp_path / "r.xlsx"

    def killed(*_args, **_kwargs):
        raise _Killed

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(app.certificate_issue, "_place", killed)
        with pytest.raises(_Killed):
            _issue(samples_dir, tmp_path, "--certificate", str(pdf), "--results", str(xlsx))
    (entry,) = _results()
    (temp,) = tmp_path.glob(".r.xlsx.*.tmp")  # the only copy of the recorded file
    assert not xlsx.exists() and _sha(temp) == entry["sha256"]
    eleven_minutes_ago = temp.stat().st_mtime - 660
    os.utime(temp, (eleven_minutes_ago, eleven_minutes_ago))
    capsys.readouterr()
    # a later save of r.xlsx (the results of a draft), which clears killed saves' leftovers
    assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"),
                 "--results", str(xlsx)]) == 0
    kept = tmp_path / f"r.{entry['number']}.xlsx"
    assert [p.name for p in tmp_path.iterdir() if p.is_file() and _sha(p) == entry["sha256"]] \
        == [kept.name]
    assert not list(tmp_path.glob(".r.xlsx.*.tmp")) and xlsx.is_file()
    said = capsys.readouterr().err
    assert (f"{temp} is the results file recorded with certificate {entry['number']}, left "
            f"under a temporary name by an issue stopped before it was named: kept as "
            f"{kept}") in said
    assert main(["register", "verify", str(kept)]) == 0


# -- an issued file is never replaced (F8) ------------------------------------------------------

@pytest.mark.slow
def test_an_issued_file_is_never_replaced_by_a_later_issue(samples_dir, tmp_path, capsys):
    """out_attacks.sh cases 1 and 7: a second certificate's --results replaced the first's
    issued results file (the register keeps its SHA-256 only) or its PDF."""
    one, xlsx = tmp_path / "one.pdf", tmp_path / "r.xlsx"
    assert _issue(samples_dir, tmp_path, "--certificate", str(one), "--results", str(xlsx)) == 0
    (number,) = _numbers()
    kept = {one: _sha(one), xlsx: _sha(xlsx)}
    capsys.readouterr()
    for target, what in ((xlsx, f"the results file of certificate {number}"),
                         (one, f"the PDF of certificate {number}")):
        code = _issue(samples_dir, tmp_path, "--certificate", str(tmp_path / "two.pdf"),
                      "--results", str(target), separate=True)
        said = capsys.readouterr().err
        assert code == 2
        assert (f"anglebench analyze: --results {target} is {what}, as issued; an issued file "
                "is never replaced: nothing was written, choose another name") in said
    code = _issue(samples_dir, tmp_path, "--certificate", str(one), separate=True)
    assert code == 2
    assert (f"{one} is the PDF of certificate {number}, as issued; an issued file is never "
            "replaced") in capsys.readouterr().err
    assert _numbers() == [number]  # no number used
    assert {path: _sha(path) for path in kept} == kept and not (tmp_path / "two.pdf").exists()
    # 'register show --pdf' onto another file issued: refused; onto its own PDF: the same bytes
    assert main(["register", "show", number, "--pdf", str(xlsx)]) == 2
    assert f"--pdf {xlsx} is the results file of certificate {number}" in \
        capsys.readouterr().err
    assert main(["register", "show", number, "--pdf", str(one)]) == 0
    assert {path: _sha(path) for path in kept} == kept


# -- one results file per certificate; verify says whose it is (F7, M4) --------------------------

@pytest.mark.slow
def test_a_results_file_is_one_certificates_and_verify_says_whose(samples_dir, tmp_path,
                                                                 capsys):
    """repro_results_launder.sh: any later record_results made an edited file, or another
    calibration's, verify as "identical to the record", rc 0."""
    one, two = tmp_path / "one.xlsx", tmp_path / "two.xlsx"
    assert _issue(samples_dir, tmp_path, "--certificate", str(tmp_path / "one.pdf"),
                  "--results", str(one)) == 0
    other = _details(samples_dir, tmp_path, "other.json", item_serial="XY-99",
                     customer_name="Other Customer Ltd")
    assert _issue(samples_dir, tmp_path, "--certificate", str(tmp_path / "two.pdf"),
                  "--results", str(two), details=other) == 0
    assert _issue(samples_dir, tmp_path, "--certificate", str(tmp_path / "three.pdf"),
                  details=other, separate=True) == 0  # a certificate without results
    first, second, third = sorted(_numbers())
    edited = one.read_bytes() + b"\0"
    with Register(register_url()) as register:
        for data in (edited, two.read_bytes()):  # a second results file of a certificate
            with pytest.raises(RegisterError, match=(  # only its issue records one
                    f"no results file is recorded for {first}: a results file is recorded "
                    "by the issue of its certificate")):
                register.record_results(first, data, "one.xlsx")
        # what a script writing into the database may still do (record_results refuses a
        # certificate it did not just issue): a certificate without one given another's file
        with register._write() as conn:
            register._append_entry(conn, "results", third,
                                   {"sha256": _sha(two), "file": "two.xlsx"})
    capsys.readouterr()
    assert main(["register", "verify", str(two)]) == 3
    out = capsys.readouterr().out
    assert (f"CHANGED AFTER ISSUE: {two}: its SHA-256 is recorded as the results file of 2 "
            f"certificates ({second}, {third}): a results file is written with one "
            "certificate, so all but one were recorded after issue") in out
    assert (f"CHANGED AFTER ISSUE: {two}: recorded as the results file of certificate "
            f"{third}, but it says it is that of certificate {second} (PDF SHA-256 ") in out
    assert f"{two}: the results file of certificate {second}, recorded " in out
    # the register itself: every record counted, the results files among them
    assert "register: hash chain intact over 6 record(s)" in out
    assert "  of them: 3 certificate(s) and 3 results file(s) recorded at issue" in out
    capsys.readouterr()
    assert main(["register", "verify", str(one)]) == 0
    assert f"{one}: the results file of certificate {first}, recorded " in \
        capsys.readouterr().out


@pytest.mark.slow
def test_a_second_results_record_of_a_certificate_is_found(samples_dir, tmp_path, capsys):
    """A register written before 0.8.12 (or by a script) may hold a second results record of
    a certificate, chained like any: verify and show say it was added after issue."""
    one = tmp_path / "one.xlsx"
    assert _issue(samples_dir, tmp_path, "--certificate", str(tmp_path / "one.pdf"),
                  "--results", str(one)) == 0
    (number,) = _numbers()
    edited = tmp_path / "one-edited.xlsx"
    edited.write_bytes(one.read_bytes() + b"\0")
    with Register(register_url()) as register, register._write() as conn:
        register._append_entry(conn, "results", number,  # what record_results did before
                               {"sha256": _sha(edited), "file": "one.xlsx"})
    capsys.readouterr()
    assert main(["register", "verify", str(edited)]) == 3
    out = capsys.readouterr().out
    assert (f"CHANGED AFTER ISSUE: certificate {number}: 2 results files recorded, where a "
            "certificate has one (recorded at its issue): all but the first were added after "
            "issue") in out
    assert (f"CHANGED AFTER ISSUE: {edited}: recorded ") in out
    assert (f"as a second results file of certificate {number}, whose results file was "
            "already recorded") in out
    assert "identical to the record" not in out
    assert main(["register", "show", number]) == 0
    shown = capsys.readouterr().out
    assert f"  results file: one.xlsx, SHA-256 {_sha(one)}, recorded " in shown
    assert (f"  results file: one.xlsx, SHA-256 {_sha(edited)}, recorded " in shown
            and "(a second one: CHANGED AFTER ISSUE, a certificate has one)" in shown)


@pytest.mark.slow
def test_show_and_export_list_the_results_file(samples_dir, tmp_path, capsys):
    """rev62 M4: neither 'register show' nor 'register export' mentioned a results file."""
    xlsx = tmp_path / "r.xlsx"
    assert _issue(samples_dir, tmp_path, "--certificate", str(tmp_path / "c.pdf"),
                  "--results", str(xlsx)) == 0
    (number,) = _numbers()
    capsys.readouterr()
    assert main(["register", "show", number]) == 0
    shown = capsys.readouterr().out
    assert f"  results file: r.xlsx, SHA-256 {_sha(xlsx)}, recorded " in shown
    (entry,) = _results()
    assert f"recorded {entry['recorded_at']}" in shown
    archive = tmp_path / "all.zip"
    assert main(["register", "export", str(archive)]) == 0
    with zipfile.ZipFile(archive) as z:
        listing = z.read("results.csv").decode("utf-8")
    assert listing.splitlines() == ["number,file,sha256,recorded_at,first",
                                    f"{number},r.xlsx,{_sha(xlsx)},{entry['recorded_at']},True"]


class _Store(dict):
    def value(self, key, default=None):
        return self.get(key, default)

    def setValue(self, key, value):  # noqa: N802 - QSettings' name
        self[key] = value


@pytest.mark.slow
def test_an_issued_file_is_never_replaced_by_an_export(samples_dir, tmp_path, capsys):
    """rev62 F8 ("… or export"): results alone, a draft, and the window's Export results
    and draft certificate onto the files a certificate was issued with."""
    from unittest import mock

    from app.certificate_presenter import CertificatePresenter, CertificateView
    from models.certificate.metadata import CertificateMetadata
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.registry import KINDS

    one, xlsx = tmp_path / "one.pdf", tmp_path / "r.xlsx"
    assert _issue(samples_dir, tmp_path, "--certificate", str(one), "--results", str(xlsx)) == 0
    (number,) = _numbers()
    kept = {one: _sha(one), xlsx: _sha(xlsx)}
    capsys.readouterr()
    sample = str(samples_dir / "polygon_sample.csv")
    assert main(["analyze", "polygon", sample, "--results", str(xlsx)]) == 2
    assert (f"anglebench analyze: --results {xlsx} is the results file of certificate {number}"
            ", as issued; an issued file is never replaced") in capsys.readouterr().err
    draft = _details(samples_dir, tmp_path, "draft.json", approver="")  # a draft: no approver
    assert main(["analyze", "polygon", sample, "--metadata", str(draft),
                 "--certificate", str(one)]) == 2
    assert f"--certificate {one} is the PDF of certificate {number}, as issued" in \
        capsys.readouterr().err
    view = mock.create_autospec(CertificateView, instance=True)
    presenter = CertificatePresenter(view, _Store(), lambda: {}, mock.Mock())
    kind = KINDS["theodolite"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))
    view.choose_save_path.return_value = str(xlsx)
    assert not presenter.export_results(kind, result, {}, "run.csv")
    assert f"{xlsx} is the results file of certificate {number}, as issued" in \
        view.tell.call_args.args[1]
    view.edit_certificate_details.return_value = CertificateMetadata(lab_name="Lab")
    view.confirm_draft.return_value = True
    view.choose_save_path.return_value = str(one)
    assert not presenter.export_certificate(kind, result, {}, "run.csv")
    assert f"{one} is the PDF of certificate {number}, as issued" in view.tell.call_args.args[1]
    assert {path: _sha(path) for path in kept} == kept
    assert _numbers() == [number]


def test_a_recorded_leftover_is_copied_where_no_hard_link_can_be_made_and_never_cleared(
        tmp_path):
    """#63 regkeys: keeping a recorded results file left under its temporary name: a copy
    where hard links cannot be made, never replacing a file; when neither can be made the
    output is refused (the save would have cleared it); an unrecorded leftover is left to
    the save to clear."""
    from app.issued_outputs import keep_recorded_temporaries
    from models.project.atomic_write import write_bytes_atomic

    class Recorded:
        def results_records(self):
            return [{"number": "AB-2026-0007", "sha256": hashlib.sha256(b"recorded").hexdigest()}]

    xlsx = tmp_path / "r.xlsx"
    taken = tmp_path / "r.AB-2026-0007.xlsx"
    taken.write_bytes(b"another file")
    temp, other = tmp_path / ".r.xlsx.abcdefgh.tmp", tmp_path / ".r.xlsx.ijklmnop.tmp"
    temp.write_bytes(b"recorded")
    other.write_bytes(b"never recorded")
    for stale in (temp, other):
        os.utime(stale, (stale.stat().st_mtime - 660,) * 2)

    def no_link(*_args):
        raise OSError(errno.EPERM, "Operation not permitted")

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(os, "link", no_link)
        (said,) = keep_recorded_temporaries(Recorded(), [("", str(xlsx))])
    kept = tmp_path / "r.AB-2026-0007-2.xlsx"
    assert kept.read_bytes() == b"recorded" and taken.read_bytes() == b"another file"
    assert not temp.exists() and f"kept as {kept}" in said
    write_bytes_atomic(xlsx, b"the new save")
    assert not other.exists() and kept.read_bytes() == b"recorded"

    temp.write_bytes(b"recorded")
    os.utime(temp, (temp.stat().st_mtime - 660,) * 2)
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(os, "link", no_link)
        patch.setattr("app.issued_outputs._copy_new", no_link)
        with pytest.raises(OutputRefused, match="could not be kept under another name"):
            keep_recorded_temporaries(Recorded(), [("", str(xlsx))])
    assert temp.read_bytes() == b"recorded"


def _killed_before_named(samples_dir, tmp_path, xlsx, stale=True):
    """An issue killed between recording its results file ``xlsx`` and naming it: the only
    copy left as ``.r.xlsx.*.tmp`` (eleven minutes old when ``stale``); (entry, temp)."""
    import app.certificate_issue

    def killed(*_args, **_kwargs):
        raise _Killed

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(app.certificate_issue, "_place", killed)
        with pytest.raises(_Killed):
            _issue(samples_dir, tmp_path, "--certificate", str(tmp_path / "c.pdf"),
                   "--results", str(xlsx))
    (entry,) = _results()
    (temp,) = tmp_path.glob(f".{xlsx.name}.*.tmp")
    if stale:
        os.utime(temp, (temp.stat().st_mtime - 660,) * 2)
    return entry, temp


@pytest.mark.slow
@pytest.mark.parametrize("writer", ["link", "validate"])
def test_a_recorded_leftover_is_kept_from_a_write_through_a_link_and_from_validate(
        samples_dir, tmp_path, capsys, writer, validation_once):
    """rev64 F2: the keeping looked beside the name given, the atomic write cleared the
    leftovers beside the link's target: a draft's results written to latest.xlsx ->
    r.xlsx deleted the only copy of a recorded results file; so did 'validate --pdf
    r.xlsx' (no check at all). The validation's reference cases are the session's
    (``validation_once``): what is checked is where the report is written, not its cases
    (run again here, they were nearly all of its ~55 s of CPU)."""
    xlsx = tmp_path / "r.xlsx"
    entry, temp = _killed_before_named(samples_dir, tmp_path, xlsx)
    capsys.readouterr()
    if writer == "link":
        latest = tmp_path / "latest.xlsx"
        latest.symlink_to(xlsx)
        assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"),
                     "--results", str(latest)]) == 0
    else:
        assert main(["validate", "--trials", "100", "--pdf", str(xlsx)]) in (0, 1)
    kept = tmp_path / f"r.{entry['number']}.xlsx"
    assert [p.name for p in tmp_path.iterdir() if p.is_file() and _sha(p) == entry["sha256"]] \
        == [kept.name]
    assert not temp.exists() and xlsx.is_file()
    assert f"kept as {kept}" in capsys.readouterr().err
    assert main(["register", "verify", str(kept)]) == 0


@pytest.mark.parametrize("number", ["AB/2026/0007", "AB\\2026\\0007", "AB:2026:0007"])
def test_a_recorded_leftover_is_kept_under_a_name_a_file_can_have(tmp_path, number):
    """rev64 F13: a certificate number holding "/" made the kept name r.AB/2026/0007.xlsx:
    ValueError on every later write of r.xlsx (and in place of IssuedNotWritten when the
    placing failed); "\\" and ":" name no file on Windows or a FAT stick."""
    from app.issued_outputs import keep_in_sight, keep_recorded_temporaries
    from models.project.atomic_write import write_bytes_atomic

    class Recorded:
        def results_records(self):
            return [{"number": number, "sha256": hashlib.sha256(b"recorded").hexdigest()}]

    xlsx = tmp_path / "r.xlsx"
    temp = tmp_path / ".r.xlsx.abcdefgh.tmp"
    temp.write_bytes(b"recorded")
    os.utime(temp, (temp.stat().st_mtime - 660,) * 2)
    (said,) = keep_recorded_temporaries(Recorded(), [("", str(xlsx))])
    kept = tmp_path / "r.AB-2026-0007.xlsx"
    assert kept.read_bytes() == b"recorded" and f"kept as {kept}" in said
    assert keep_recorded_temporaries(Recorded(), [("", str(xlsx))]) == []  # named already
    write_bytes_atomic(xlsx, b"the next save")
    assert kept.read_bytes() == b"recorded"
    again = tmp_path / ".r.xlsx.ijklmnop.tmp"  # a placing that failed: kept at once
    again.write_bytes(b"recorded")
    assert keep_in_sight(again, xlsx, number) == str(tmp_path / "r.AB-2026-0007-2.xlsx")


@pytest.mark.slow
def test_show_and_verify_say_when_the_results_file_named_is_not_the_recorded_one(
        samples_dir, tmp_path, capsys, monkeypatch):
    """rev64 F15: within ten minutes of a killed issue nothing pointed at the only copy of
    its recorded results file, and 'register show' named r.xlsx, which another write had
    filled since: both now say r.xlsx is not it, and where the recorded one is."""
    xlsx = tmp_path / "r.xlsx"
    entry, temp = _killed_before_named(samples_dir, tmp_path, xlsx, stale=False)
    assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"),
                 "--results", str(xlsx)]) == 0  # a draft's, at once
    assert temp.is_file() and _sha(xlsx) != entry["sha256"]
    monkeypatch.chdir(tmp_path)
    capsys.readouterr()
    assert main(["register", "show", entry["number"]]) == 0
    shown = capsys.readouterr().out
    assert (f"  {xlsx} is not the results file recorded under that name with certificate "
            f"{entry['number']} (its SHA-256 is {_sha(xlsx)}") in shown
    assert (f"  the results file recorded with certificate {entry['number']} is {temp} "
            "(SHA-256 as recorded): give it a name of its own") in shown
    assert main(["register", "verify", str(xlsx)]) == 1
    said = capsys.readouterr().out
    assert f"{xlsx}: NOT in the register" in said
    assert f"the results file recorded with certificate {entry['number']} is {temp}" in said


def test_an_issue_clears_a_killed_saves_stale_leftovers_and_keeps_fresh_ones(samples_dir,
                                                                             tmp_path):
    """reg72 #11: a half-written ``.r.xlsx.XXXXXXXX.tmp`` eleven minutes old (not recorded)
    stayed beside the results file an issue wrote, though the docs say the next save clears
    such leftovers after ten minutes: the issue's outputs (PDF, DCC, results file) are
    written beside their names and placed, not by the atomic write that clears them. A
    leftover of five minutes (a save that may still be going) is left alone."""
    pdf, xlsx = tmp_path / "c.pdf", tmp_path / "r.xlsx"
    stale = {name: tmp_path / f".{name}.ZzZz9999.tmp" for name in ("c.pdf", "r.xlsx")}
    fresh = tmp_path / ".r.xlsx.Fresh123.tmp"
    for leftover in (*stale.values(), fresh):
        leftover.write_bytes(b"PK\x03\x04 half written")
    for leftover in stale.values():
        os.utime(leftover, (leftover.stat().st_mtime - 660,) * 2)
    os.utime(fresh, (fresh.stat().st_mtime - 300,) * 2)
    assert _issue(samples_dir, tmp_path, "--certificate", str(pdf), "--results",
                  str(xlsx)) == 0
    assert pdf.is_file() and xlsx.is_file()
    assert [p for p in stale.values() if p.exists()] == []
    assert fresh.read_bytes() == b"PK\x03\x04 half written"


@pytest.mark.slow
def test_a_recorded_leftover_kept_by_an_issue_is_said_once(samples_dir, tmp_path, capsys,
                                                           monkeypatch):
    """reg72 #11: the notice that a recorded results file was kept from under its temporary
    name was printed twice (the command's line, and the same text again through logging's
    last resort on stderr)."""
    import logging

    xlsx = tmp_path / "r.xlsx"
    entry, temp = _killed_before_named(samples_dir, tmp_path, xlsx)
    # as the command runs: no logging configured (pytest's own handler taken off), so that a
    # warning goes to stderr by logging's last resort
    monkeypatch.setattr(logging.root, "handlers", [])
    capsys.readouterr()
    assert _issue(samples_dir, tmp_path, "--certificate", str(tmp_path / "c2.pdf"),
                  "--results", str(xlsx),
                  details=_details(samples_dir, tmp_path, "d2.json", item_serial="X-2")) == 0
    out, err = capsys.readouterr()
    notice = (f"{temp} is the results file recorded with certificate {entry['number']}, left "
              "under a temporary name by an issue stopped before it was named: kept as")
    assert (out + err).count(notice) == 1
    assert not temp.exists() and (tmp_path / f"r.{entry['number']}.xlsx").is_file()
