"""An amendment or replacement is of the calibration it supersedes (ISO/IEC 17025 7.8.8;
rev62 F1): its workbench, its item (serial numbers compared as printed; rev63 F2) and its
date of calibration. A pending Amend… ends when another project is opened, and when the register
refuses it for good. Certificates issued with ``anglebench analyze --certificate``, amended
in the real window (its dialogs answered)."""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

import pytest
from pypdf import PdfReader
from PySide6.QtWidgets import QMessageBox

from app.certificate_presenter import PendingRevision
from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.register.location import register_url, url_for_path
from models.register.store import IssueRequest, NotTheSameCalibration, Register
from tests.own_readings import own_readings
from tests.pdf_stand_in import print_stand_ins


def _issue(samples_dir, tmp_path, name, **changes) -> str:
    """An original issued with the command line, from its item's own readings
    (tests/own_readings.py); its number."""
    meta = json.loads((samples_dir / "certificate_theodolite.json").read_text(encoding="utf-8"))
    meta.update({"example": False, "certificate_number": "", **changes})
    (tmp_path / f"{name}.json").write_text(json.dumps(meta), encoding="utf-8")
    readings = own_readings(samples_dir / "theodolite_sample.csv", meta["item_serial"],
                            tmp_path.with_name(f"{tmp_path.name}-readings"))  # beside it
    assert main(["analyze", "theodolite", str(readings),
                 "--certificate", str(tmp_path / f"{name}.pdf"),
                 "--metadata", str(tmp_path / f"{name}.json")]) == 0
    with Register(register_url()) as register:
        return register.list()[0].number


def _records() -> dict[str, tuple]:
    with Register(register_url()) as register:
        return {r.number: (r.status, r.item_serial, r.calibration_date, r.supersedes)
                for r in register.list()}


def _pdf_text(path) -> str:
    return re.sub(r"\s+", " ", "".join(p.extract_text() for p in PdfReader(path).pages))


@pytest.fixture(scope="module")
def _two_issued(tmp_path_factory) -> tuple[Path, str, str]:
    """A and B issued once for the module (their PDFs stand-ins, tests/pdf_stand_in.py: no
    test reads them), into a register and folder of their own: the folder, A's number, B's."""
    folder = tmp_path_factory.mktemp("two_issued")
    samples_dir = Path(__file__).resolve().parents[2] / "resources" / "samples"
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("ANGLEBENCH_REGISTER", str(folder / "register.sqlite"))
        print_stand_ins(mp)  # their PDFs are never read: the amendments' are, printed
        a = _issue(samples_dir, folder, "a", item_serial="LRA-0815",
                   calibration_date="2026-11-20")
        b = _issue(samples_dir, folder, "b", item_serial="XY-99", calibration_date="2026-11-02",
                   customer_name="Other Customer Ltd")
    return folder, a, b


@pytest.fixture
def two(_two_issued, tmp_path, capsys):
    """A (LRA-0815, calibrated 2026-11-20) and B (XY-99, 2026-11-02, another customer):
    the module's issue copied into the test's register and folder (each test changes its
    own copy)."""
    folder, a, b = _two_issued
    for path in folder.iterdir():
        shutil.copy2(path, tmp_path / path.name)
    assert register_url() == url_for_path(tmp_path / "register.sqlite")  # the test's own
    capsys.readouterr()
    return a, b


def _amend(window, qtbot, tmp_path, number: str, asked: list, replacement: bool = False,
           **details) -> None:
    """Register › Amend… (or Replace…) of ``number`` in the window, the details then changed
    by ``details``; the dialogs answered (the change note "typo in the address")."""
    with Register(register_url()) as register:
        record = register.get(number)
    assert window.projects.open_project_state(record.project_json, record.workbench)
    window.certificates.start_revision(PendingRevision(record.workbench, number, replacement))
    view = window.certificates.view
    view.tell = lambda title, text: asked.append(("tell", text))
    view.show_status = lambda text, *_: asked.append(("status", text))
    view.wait_cursor = lambda on: None
    view.edit_certificate_details = lambda meta, problems, raw: CertificateMetadata.from_dict(
        {**meta.to_dict(), **details})
    view.confirm_draft = view.confirm_implausible = view.confirm_standards = lambda *a: True
    view.ask_change_note = lambda revision: asked.append(("note", revision.number)) or \
        "typo in the address"
    view.ask_separate_calibration = lambda *a: ""
    # the readings of another item's certificate: asked, not answered unless a test does
    view.ask_readings_of_another_item = lambda numbers, reason: asked.append(
        ("readings", numbers)) or ""
    view.choose_save_path = lambda *a: str(tmp_path / "exported.pdf")
    window.projects.view.ask_save_changes = lambda: False  # "Discard"
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)


def test_the_register_refuses_another_items_details_and_another_workbench(two, tmp_path):
    """The register API (the call every Amend…/Replace… makes): A amended with B's details,
    and B replaced on the polygon workbench, are refused before anything is issued."""
    a, b = two
    before = _records()
    with Register(register_url()) as register:
        b_record = register.get(b)
        meta = CertificateMetadata.from_dict(
            json.loads(b_record.project_json)["metadata"]["certificates"]["theodolite"])
        meta = CertificateMetadata.from_dict({**meta.to_dict(), "certificate_number": ""})
        with pytest.raises(NotTheSameCalibration) as refused:
            register.issue(IssueRequest("theodolite", meta, b_record.project_json),
                           lambda m: b"%PDF", supersedes=a, change_note="typo",
                           separate_calibration="")
        assert str(refused.value).startswith(
            f"{a} reports serial number LRA-0815, calibrated 2026-11-20; these details give "
            "serial number XY-99, calibrated 2026-11-02.")
        assert refused.value.corrections[:2] == (
            f"serial number corrected from LRA-0815 (on {a}) to XY-99",
            f"date of calibration corrected from 2026-11-20 (on {a}) to 2026-11-02")
        # B's customer too (#64 review F5)
        assert refused.value.corrections[2].startswith("customer corrected from ")
        # confirmed as a correction: still refused, XY-99 of 2026-11-02 is B's calibration
        with pytest.raises(NotTheSameCalibration, match=f"{b} already reports serial number "
                           "XY-99, calibrated 2026-11-02: a correction of " + a):
            register.issue(IssueRequest("theodolite", meta, b_record.project_json),
                           lambda m: b"%PDF", supersedes=a, change_note="typo",
                           separate_calibration="", correction_confirmed=True)
        with pytest.raises(NotTheSameCalibration) as refused:  # no confirmation makes it one
            register.issue(IssueRequest("polygon", meta, b_record.project_json),
                           lambda m: b"%PDF", supersedes=b, replacement=True,
                           separate_calibration="", correction_confirmed=True)
        assert str(refused.value).startswith(
            f"{b} was issued on the theodolite workbench: its amendment or replacement "
            "corrects that calibration and is issued on that workbench, not on polygon")
        assert refused.value.corrections == ()
    assert _records() == before  # nothing issued, nothing superseded


@pytest.mark.slow
@pytest.mark.usefixtures("pdf_stand_in")  # no PDF read: of the register's answers
def test_a_pending_amendment_ends_when_another_project_is_opened(window, qtbot, two, tmp_path):
    """rev62 F1: Amend… of A, then File › Open of B's project and Export certificate issued
    B's details as "A-A1" (A superseded, B two current certificates)."""
    a, b = two
    assert main(["register", "show", b, "--project", str(tmp_path / "b.anglebench.json")]) == 0
    asked: list = []
    _amend(window, qtbot, tmp_path, a, asked)
    assert window.certificates.pending == PendingRevision("theodolite", a, False)
    assert window.projects.open_project(tmp_path / "b.anglebench.json")
    assert window.certificates.pending is None
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    assert not window.export_certificate()  # an original of B: its number is B's, refused
    assert ("note", a) not in asked  # not asked what changed in A
    assert f"Certificate number {b} was issued on" in asked[-1][1]
    assert _records()[a][0] == "issued" and _records()[b][0] == "issued"
    assert len(_records()) == 2


@pytest.mark.slow
@pytest.mark.usefixtures("pdf_stand_in")  # no PDF read: of the register's answers
def test_a_refusal_for_good_ends_the_pending_amendment(window, qtbot, two, tmp_path):
    """rev62 F1, blocked variant: A amended meanwhile at another workstation; the window's
    amendment is refused, and no later export is held to it."""
    a, _b = two
    asked: list = []
    _amend(window, qtbot, tmp_path, a, asked)
    with Register(register_url()) as register:  # a colleague's amendment
        record = register.get(a)
        meta = CertificateMetadata.from_dict(
            json.loads(record.project_json)["metadata"]["certificates"]["theodolite"])
        register.issue(IssueRequest("theodolite", meta, record.project_json),
                       lambda m: b"%PDF colleague", supersedes=a, change_note="colleague's fix")
    assert not window.export_certificate()
    assert asked[-1][1].startswith(f"{a} was superseded by {a}-A1: amend or replace that one.")
    assert asked[-1][1].endswith(f"The amendment or replacement of {a} is ended: the next "
                                 "certificate of this workbench is an original.")
    assert window.certificates.pending is None
    asked.clear()
    window.certificates.view.edit_certificate_details = lambda meta, p, r: \
        CertificateMetadata.from_dict({**meta.to_dict(), "certificate_number": "",
                                       "item_serial": "QQ-1", "calibration_date": "2026-11-21"})
    # A's readings, still in the window, issued for QQ-1: asked why (hostile78 F7), and said
    window.certificates.view.ask_readings_of_another_item = lambda numbers, reason: \
        asked.append(("readings", numbers)) or "the test is of the amendment's end"
    assert window.export_certificate()  # an original now: no change note asked
    assert [k for k, _ in asked] == ["readings", "status"]
    assert asked[0][1] == (a, f"{a}-A1") and "(amendment" not in asked[1][1]
    assert _records()[a + "-A1"][0] == "issued"


@pytest.mark.slow
def test_a_corrected_serial_is_asked_and_then_stated(window, qtbot, two, tmp_path):
    """A corrected serial number is the classic amendment: asked, then stated on it; No
    issues nothing and ends the amendment."""
    a, _b = two
    asked: list = []
    _amend(window, qtbot, tmp_path, a, asked, item_serial="LRA-0816")
    window.certificates.view.confirm_correction = lambda revision, reason: \
        asked.append(("confirm", reason)) or False
    assert not window.export_certificate()
    assert asked[-2][0] == "confirm" and asked[-2][1].startswith(
        f"{a} reports serial number LRA-0815, calibrated 2026-11-20; these details give serial "
        "number LRA-0816, calibrated 2026-11-20.")
    assert asked[-1][1].startswith("No certificate was written or recorded. The amendment or "
                                   f"replacement of {a} is ended")
    assert window.certificates.pending is None and len(_records()) == 2
    asked.clear()
    _amend(window, qtbot, tmp_path, a, asked, item_serial="LRA-0816")
    window.certificates.view.confirm_correction = lambda revision, reason: \
        asked.append(("confirm", revision.number)) or True
    assert window.export_certificate()
    assert ("confirm", a) in asked
    assert _records()[a + "-A1"] == ("issued", "LRA-0816", "2026-11-20", a)
    assert _records()[a][0] == "superseded"
    text = _pdf_text(tmp_path / "exported.pdf")
    assert (f"Amendment 1 to certificate {a}, which it supersedes; the original stays on record "
            f"unchanged. Changed: serial number corrected from LRA-0815 (on {a}) to LRA-0816; "
            "typo in the address") in text
    with Register(register_url()) as register:
        assert register.get(a + "-A1").change_note == (
            f"serial number corrected from LRA-0815 (on {a}) to LRA-0816; typo in the address")
        assert register.problems == []


def test_a_corrected_customer_or_maker_is_asked_and_then_stated(window, qtbot, two, tmp_path,
                                                                capsys):
    """#64 review F5: Amend… of LRA-0815's certificate with another manufacturer and another
    customer was issued unasked, and nothing but the note ("typo") said so."""
    a, _b = two
    with Register(register_url()) as register:
        customer, maker = register.get(a).customer, register.get(a).item_manufacturer
    asked: list = []
    _amend(window, qtbot, tmp_path, a, asked, item_manufacturer="Other Corp",
           customer_name="Another Customer Ltd")
    window.certificates.view.confirm_correction = lambda revision, reason: \
        asked.append(("confirm", reason)) or False
    assert not window.export_certificate()
    assert asked[-2][0] == "confirm" and asked[-2][1].startswith(
        f"{a}: these details change what it reports: manufacturer corrected from {maker} (on "
        f"{a}) to Other Corp; customer corrected from {customer} (on {a}) to Another Customer "
        "Ltd.")
    assert window.certificates.pending is None and len(_records()) == 2
    asked.clear()
    _amend(window, qtbot, tmp_path, a, asked, item_manufacturer="Other Corp",
           customer_name="Another Customer Ltd")
    window.certificates.view.confirm_correction = lambda revision, reason: True
    assert window.export_certificate()
    text = _pdf_text(tmp_path / "exported.pdf")
    assert (f"Changed: manufacturer corrected from {maker} (on {a}) to Other Corp; customer "
            f"corrected from {customer} (on {a}) to Another Customer Ltd; typo in the "
            "address") in text
    capsys.readouterr()
    assert main(["register", "show", a + "-A1"]) == 0
    assert (f"change_note: manufacturer corrected from {maker} (on {a}) to Other Corp; "
            f"customer corrected from {customer} (on {a}) to Another Customer Ltd; typo in "
            "the address") in capsys.readouterr().out


@pytest.mark.slow
def test_a_serial_typed_otherwise_is_a_correction_asked_and_stated(window, qtbot, two,
                                                                    tmp_path):
    """The same serial typed with other separators or case (one serial_key) prints otherwise:
    it is asked, and stated on the amendment (rev63 F2: the key never lets a change
    through)."""
    a, _b = two
    asked: list = []
    _amend(window, qtbot, tmp_path, a, asked, item_serial="lra 0815")
    window.certificates.view.confirm_correction = lambda revision, reason: \
        asked.append(("confirm", revision.number)) or True
    assert window.export_certificate()
    assert ("confirm", a) in asked
    assert _records()[a + "-A1"][1] == "lra 0815"
    assert (f"Changed: serial number corrected from LRA-0815 (on {a}) to lra 0815; typo in "
            "the address") in _pdf_text(tmp_path / "exported.pdf")


def test_the_windows_question_names_the_certificate_and_defaults_to_no(window):
    """The question of a corrected serial number (app/certificate_dialogs.py): No is the
    default, Yes issues."""
    seen = []
    window.ask = lambda title, text, buttons, default: seen.append((title, text, default)) or \
        QMessageBox.StandardButton.Yes
    assert window.certificates.view.confirm_correction(
        PendingRevision("theodolite", "AB-2026-0001"), "AB-2026-0001 reports serial number X")
    title, text, default = seen[0]
    assert title == "Correct the serial number or date of calibration?"
    assert text == ("AB-2026-0001 reports serial number X.\n\nIs this amendment a correction of "
                    "AB-2026-0001's serial number or date of calibration? Yes: issue it, the "
                    "correction stated on it. No: nothing is issued, and the next certificate "
                    "is an original.")
    assert default == QMessageBox.StandardButton.No


@pytest.mark.usefixtures("pdf_stand_in")  # no PDF read: of the register's answers
def test_the_command_line_joins_a_letter_with_a_mark_and_its_look_alike(samples_dir, tmp_path,
                                                                        capsys):
    """rev63 F3 (ident_diacritic.sh): serial "MÖ-0815" (Latin), then "MӦ-0815" (Cyrillic O
    with diaeresis), same item and day, is refused as a second original; a typed number
    "KӒ-2026-0001" after "KÄ-2026-0001" is refused as issued; "MO-0815" and "KA-2026-0001"
    print otherwise and are issued."""
    meta = json.loads((samples_dir / "certificate_theodolite.json").read_text(encoding="utf-8"))

    def analyze(name, *extra, **changes):
        (tmp_path / f"{name}.json").write_text(json.dumps(
            {**meta, "example": False, "certificate_number": "", **changes}), encoding="utf-8")
        # each item its own readings (one item's readings are refused as another's)
        readings = own_readings(samples_dir / "theodolite_sample.csv", changes["item_serial"],
                                tmp_path / "readings")
        return main(["analyze", "theodolite", str(readings),
                     "--certificate", str(tmp_path / f"{name}.pdf"),
                     "--metadata", str(tmp_path / f"{name}.json"), *extra])

    assert analyze("a", item_serial="M\u00d6-0815") == 0
    assert analyze("b", item_serial="M\u04e6-0815") != 0
    assert "already reports this calibration (serial M\u04e6-0815" in capsys.readouterr().err
    assert analyze("c", item_serial="MO-0815") == 0
    assert analyze("n1", "--separate-calibration", "n1",
                   certificate_number="K\u00c4-2026-0001", item_serial="OTHER-0") == 0
    assert analyze("n2", "--separate-calibration", "n2",
                   certificate_number="K\u04d2-2026-0001", item_serial="OTHER-1") != 0
    assert ("certificate number K\u04d2-2026-0001 (K\u00c4-2026-0001) was issued on"
            in capsys.readouterr().err)
    assert analyze("n3", "--separate-calibration", "n3",
                   certificate_number="KA-2026-0001", item_serial="OTHER-2") == 0
    with Register(register_url()) as register:
        assert sorted(r.item_serial for r in register.list()) == [
            "MO-0815", "M\u00d6-0815", "OTHER-0", "OTHER-2"]
