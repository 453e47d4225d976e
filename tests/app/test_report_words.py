"""A test report is called one wherever AngleBench speaks of it, in English and in Chinese:
the window's and the command line's draft and "issued, but the file was not written"
messages, the status line of an amendment (whose revision was English in a Chinese
window), and ``register verify`` of its PDF or results file (by the kind the register
recorded; "document" for a record issued before it recorded kinds), the command line's
refusals before writing one and a draft's missing "report number", the export's file
dialog's title, and a number not in the register ("no certificate or test report N"). Also
the XLSX's row
naming the test (检测 on a Chinese calibration certificate's sheet), an empty serial of a
standard ("serial ;", "出厂编号 ；") and the cross-calibration's remark ending in an ASCII
"." in Chinese. The positioning sample's result names inputs not stated, so it is a test
report; the polygon's is a calibration certificate."""

from __future__ import annotations

import datetime as dt
import hashlib
import json
import re
import shutil
import xml.etree.ElementTree as ET
from pathlib import Path
from unittest import mock

import pytest

from app.certificate_dialogs import CertificateDialogs
from app.certificate_presenter import CertificatePresenter, CertificateView, PendingRevision
from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.registry import KINDS
from tests.app.test_document_kind_said import Store, _details, _sample

pytestmark = pytest.mark.slow  # certificates are rendered
YEAR = dt.datetime.now(dt.timezone.utc).year
REPORT, CERTIFICATE = f"AB-{YEAR}-0001", f"AB-{YEAR}-0002"  # issued in this order

#: the Chinese of the texts this change adds (en -> zh), for the lead's catalogue
#: (resources/translations): until they are in it, these tests lay them over it, as the
#: catalogue will give them
PENDING_ZH = {
    "Draft test report written to {path} — DRAFT: {missing} missing; nothing was recorded "
    "in the register": "检测报告草稿已写入 {path} — 草稿：缺少 {missing}；未在登记册中记录",
    "These details are missing: {missing}. The PDF will be marked DRAFT, is not a test "
    "report, and nothing is recorded in the register. Export the draft anyway?":
        "缺少以下信息：{missing}。PDF 将标记为草稿，不是检测报告，也不会记录在登记册中。仍要导出草稿吗？",
    "Test report {number} is issued and recorded in the register, but {reason}: save its PDF "
    "from File › Certificate register.":
        "检测报告 {number} 已签发并记录在登记册中，但 {reason}：请从 文件 › 证书登记册 保存其 PDF。",
    "{number} ({revision} of {supersedes})": "{number}（{supersedes} 的{revision}）",
    "anglebench analyze: test report {number} is issued and recorded, but {reason}: save it "
    "with 'anglebench register show {number} --pdf OUT.pdf'":
        "anglebench analyze：检测报告 {number} 已签发并登记，但{reason}：请用 "
        "'anglebench register show {number} --pdf OUT.pdf' 保存",
    "Test report written to {path} (DRAFT: {fields} missing; nothing was recorded in the "
    "register)": "检测报告已写入 {path}（草稿：缺少{fields}；未记入登记册）",
    "{path}: test report {number}, issued {issued_at}, {status}; identical to the record "
    "(SHA-256)": "{path}：检测报告 {number}，签发于 {issued_at}，{status}；与记录一致（SHA-256）",
    "{path}: document {number}, issued {issued_at}, {status}; identical to the record "
    "(SHA-256)": "{path}：文件 {number}，签发于 {issued_at}，{status}；与记录一致（SHA-256）",
    "{path}: the results file of test report {number}, recorded {recorded_at}, {status}; "
    "identical to the record (SHA-256)":
        "{path}：检测报告 {number} 的结果文件，记录于 {recorded_at}，{status}；与记录一致（SHA-256）",
    "{path}: the results file of document {number}, recorded {recorded_at}, {status}; "
    "identical to the record (SHA-256)":
        "{path}：文件 {number} 的结果文件，记录于 {recorded_at}，{status}；与记录一致（SHA-256）",
    "{remarks}.": "{remarks}。",
    "report number": "报告编号",
    "{file}: no test report was written: {progress} is not complete; a test report waits "
    "for it (the complete ones are analysed above)":
        "{file}：未写出检测报告：{progress} 尚未完成；检测报告须待其完成（上面已分析已完成的部分）",
    "{file}: no test report was written: {reason} If the readings are right, run again with "
    "--confirm-implausible":
        "{file}：未写出检测报告：{reason} 若读数无误，请加上 --confirm-implausible 重新运行",
    "no certificate or test report {number} in the register": "登记册中没有证书或检测报告 {number}",
}




def _clear_caches() -> None:
    from app.writers.certificate_pdf import wording
    from models import messages

    messages.translator.cache_clear()
    wording._say.cache_clear()
    wording._chinese_words.cache_clear()


@pytest.fixture
def zh_catalogue(tmp_path, monkeypatch):
    """The command line's and the certificate's Chinese (models.messages.translator): the
    catalogue with :data:`PENDING_ZH` added where it lacks them."""
    from models import messages

    folder = tmp_path / "translations"
    folder.mkdir()
    source = messages.TRANSLATIONS_DIR / "anglebench_zh_CN.ts"
    tree = ET.parse(source)
    context = tree.getroot().find("context")
    have = messages.catalogue(source)
    for english, chinese in PENDING_ZH.items():
        if english not in have:
            element = ET.SubElement(context, "message")
            ET.SubElement(element, "source").text = english
            ET.SubElement(element, "translation").text = chinese
    tree.write(folder / "anglebench_zh_CN.ts", encoding="utf-8")
    monkeypatch.setattr(messages, "TRANSLATIONS_DIR", folder)
    _clear_caches()
    yield
    monkeypatch.undo()
    _clear_caches()


@pytest.fixture
def zh_window(qapp):
    """The window's language Chinese (its .qm), :data:`PENDING_ZH` over it."""
    from PySide6.QtCore import QCoreApplication, QTranslator

    from widgets.i18n import install_language

    class Pending(QTranslator):
        def translate(self, context, source, disambiguation=None, n=-1):  # noqa: ARG002
            return PENDING_ZH.get(source)  # None: not ours, the next translator's

    install_language("zh_CN")
    pending = Pending()
    QCoreApplication.installTranslator(pending)
    yield
    QCoreApplication.removeTranslator(pending)
    install_language("en")


def _presenter():
    view = mock.create_autospec(CertificateView, instance=True)
    return view, CertificatePresenter(view, Store(), lambda: {}, mock.Mock())


def _export(presenter, view, samples_dir, key, path, **changes) -> bool:
    kind, result, rows = _sample(samples_dir, key)
    view.edit_certificate_details.return_value = _details(samples_dir, key, **changes)
    view.choose_save_path.return_value = str(path)
    return presenter.export_certificate(kind, result, {}, kind.sample_file, rows)


def _english(text: str) -> set[str]:
    """English words left in a Chinese text (the paths and numbers taken out)."""
    return {w for w in re.findall(r"[A-Za-z]{3,}", text) if w not in {"PDF", "DRAFT"}}


def test_the_windows_draft_messages_call_a_test_report_one(samples_dir, tmp_path, pdf_stand_in):
    view, presenter = _presenter()
    view.confirm_draft.return_value = True
    for key, report in (("positioning", True), ("polygon", False)):
        path = tmp_path / f"{key}-draft.pdf"
        assert _export(presenter, view, samples_dir, key, path, approver="")
        assert view.confirm_draft.call_args.args == (["approver"], report)
        said = view.show_status.call_args.args[0]
        assert said.startswith(f"Draft test report written to {path} — DRAFT: approver "
                               "missing" if report else
                               f"Draft written to {path} — DRAFT: approver missing"), said
    window = mock.Mock()
    dialogs = CertificateDialogs(window)
    dialogs.confirm_draft(["approver"], True)
    assert window.ask.call_args.args[1] == (
        "These details are missing: approver. The PDF will be marked DRAFT, is not a test "
        "report, and nothing is recorded in the register. Export the draft anyway?")
    dialogs.confirm_draft(["approver"])
    assert "is not a certificate," in window.ask.call_args.args[1]


def full_disk(*_args):
    raise OSError(28, "No space left on device")


def test_the_windows_issued_but_not_written_calls_a_test_report_one(samples_dir, tmp_path,
                                                                    monkeypatch, pdf_stand_in):
    view, presenter = _presenter()
    monkeypatch.setattr("app.certificate_issue._write_new", full_disk)
    for key, number, said in (("positioning", REPORT, "Test report"),
                              ("polygon", CERTIFICATE, "Certificate")):
        assert not _export(presenter, view, samples_dir, key, tmp_path / f"{key}.pdf")
        assert view.tell.call_args.args == (
            "Issued, but the file was not written",
            f"{said} {number} is issued and recorded in the register, but {tmp_path / key}.pdf: "
            "No space left on device: save its PDF from File › Certificate register.")


def test_an_amendments_status_line_in_the_windows_language(samples_dir, tmp_path, zh_window,
                                                           pdf_stand_in):
    """The revision part was "(amendment 1 of AB-…)" in a Chinese window."""
    view, presenter = _presenter()
    view.ask_change_note.return_value = "客户地址"
    for key in ("positioning", "polygon"):
        assert _export(presenter, view, samples_dir, key, tmp_path / f"{key}.pdf")
    for key, number, said in (("positioning", REPORT, "检测报告"), ("polygon", CERTIFICATE, "证书")):
        presenter.start_revision(PendingRevision(key, number))
        path = tmp_path / f"{key}-A1.pdf"
        assert _export(presenter, view, samples_dir, key, path)
        status = view.show_status.call_args.args[0]
        assert status.startswith(f"{said} {number}-A1（{number} 的第 1 次修订） 已签发：已写入 "
                                 f"{path} 并记录在登记册中"), status
        assert not _english(status.replace(str(path), "")), status


def test_an_amendments_status_line_in_english(samples_dir, tmp_path, pdf_stand_in):
    view, presenter = _presenter()
    view.ask_change_note.return_value = "the customer's address"
    assert _export(presenter, view, samples_dir, "positioning", tmp_path / "r.pdf")
    presenter.start_revision(PendingRevision("positioning", REPORT, replacement=True))
    assert _export(presenter, view, samples_dir, "positioning", tmp_path / "r2.pdf")
    status = view.show_status.call_args.args[0]
    assert status.startswith(f"Test report {CERTIFICATE} (replacement of {REPORT}) issued: "
                             f"written to {tmp_path / 'r2.pdf'}"), status


def _analyze(samples_dir, tmp_path, key, *more, **changes) -> int:
    details = tmp_path / f"{key}.json"
    details.write_text(json.dumps(_details(samples_dir, key, **changes).to_dict()),
                       encoding="utf-8")
    return main(["analyze", key, str(samples_dir / KINDS[key].sample_file),
                 "--metadata", str(details), *more])


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_the_command_lines_draft_message(samples_dir, tmp_path, capsys, zh_catalogue,
                                         language, pdf_stand_in):
    said = {}
    for key in ("positioning", "polygon"):
        assert _analyze(samples_dir, tmp_path, key, "--certificate",
                        str(tmp_path / f"{key}-draft.pdf"), "--language", language,
                        approver="") == 0
        said[key] = capsys.readouterr().err
    if language == "en":
        # a test report's number is its report number (it said "certificate number")
        assert (f"Test report written to {tmp_path / 'positioning-draft.pdf'} (DRAFT: report "
                "number, approver missing; nothing was recorded in the register)") in said["positioning"]
        assert (f"Certificate written to {tmp_path / 'polygon-draft.pdf'} (DRAFT: certificate "
                "number, approver missing; nothing was recorded in the register)") in said["polygon"]
    else:
        assert (f"检测报告已写入 {tmp_path / 'positioning-draft.pdf'}（草稿：缺少报告编号、批准人；未记入"
                "登记册）" in said["positioning"]), said["positioning"]
        assert (f"证书已写入 {tmp_path / 'polygon-draft.pdf'}（草稿：缺少证书编号、批准人；未记入登记册）"
                in said["polygon"]), said["polygon"]


def _incomplete_polygon(samples_dir, tmp_path) -> str:
    """The polygon's sample with its last set only begun (3 of 24 readings)."""
    lines = (samples_dir / "polygon_sample.csv").read_text(encoding="utf-8").splitlines()
    header, rows = lines[0], lines[1:]
    path = tmp_path / "partial.csv"
    path.write_text("\n".join([header, *rows[:-21]]) + "\n", encoding="utf-8")
    return str(path)


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_the_command_lines_refusals_call_a_test_report_one(samples_dir, tmp_path, capsys,
                                                           zh_catalogue, language):
    """A test report asked for and refused before it is written (a run in progress, readings
    doubted) was "no certificate was written"; a certificate's refusal is as before, with
    the same exit code."""
    from tests.models.readings.test_hostile_input import _polygon_text

    partial = _incomplete_polygon(samples_dir, tmp_path)
    doubted = tmp_path / "doubted.csv"
    doubted.write_text(_polygon_text(samples_dir, 1.0), encoding="utf-8")
    said = {}
    for asked in ("test", "calibration"):
        details = tmp_path / f"{asked}.json"
        details.write_text(json.dumps(_details(samples_dir, "polygon",
                                               document_type=asked).to_dict()), encoding="utf-8")
        for name, path in (("incomplete", partial), ("doubted", str(doubted))):
            pdf = tmp_path / f"{asked}-{name}.pdf"
            assert main(["analyze", "polygon", path, "--metadata", str(details),
                         "--certificate", str(pdf), "--language", language]) == 2
            said[asked, name] = capsys.readouterr().err
            assert not pdf.exists()
    if language == "en":
        assert f"{partial}: no test report was written: " in said["test", "incomplete"]
        assert "a test report waits for it" in said["test", "incomplete"]
        assert f"{doubted}: no test report was written: " in said["test", "doubted"]
        assert "run again with --confirm-implausible" in said["test", "doubted"]
        assert f"{partial}: no certificate was written: " in said["calibration", "incomplete"]
        assert "a certificate waits for it" in said["calibration", "incomplete"]
        assert f"{doubted}: no certificate was written: " in said["calibration", "doubted"]
        assert not any("certificate was written" in said["test", name]
                       for name in ("incomplete", "doubted")), said
    else:
        assert f"{partial}：未写出检测报告：" in said["test", "incomplete"]
        assert "检测报告须待其完成" in said["test", "incomplete"]
        assert f"{doubted}：未写出检测报告：" in said["test", "doubted"]
        assert f"{partial}：未写出证书：" in said["calibration", "incomplete"]
        assert f"{doubted}：未写出证书：" in said["calibration", "doubted"]


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_a_number_not_in_the_register_is_no_certificate_or_test_report(tmp_path, capsys,
                                                                       zh_catalogue, language):
    """A test report's number not found was "no certificate N in the register"."""
    from models.register.location import register_url
    from models.register.store import Register

    with Register(register_url()):  # there (contract75 F10: one that is not is refused)
        pass
    assert main(["register", "show", "AB-2026-0099", "--language", language]) == 2
    err = capsys.readouterr().err
    assert ("no certificate or test report AB-2026-0099 in the register" if language == "en"
            else "登记册中没有证书或检测报告 AB-2026-0099") in err, err


def test_the_export_dialogs_title_names_a_test_report(samples_dir, tmp_path, pdf_stand_in):
    """File › Export certificate's file dialog was titled "Export certificate" for a test
    report too."""
    view, presenter = _presenter()
    for key, title in (("positioning", "Export test report"), ("polygon", "Export certificate")):
        assert _export(presenter, view, samples_dir, key, tmp_path / f"{key}.pdf")
        assert view.choose_save_path.call_args.args[0] == title, key


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_the_command_lines_issued_but_not_written(samples_dir, tmp_path, capsys, monkeypatch,
                                                  zh_catalogue, language, pdf_stand_in):
    monkeypatch.setattr("app.certificate_issue._write_new", full_disk)
    for key, number in (("positioning", REPORT), ("polygon", CERTIFICATE)):
        out = tmp_path / f"{key}.pdf"
        assert _analyze(samples_dir, tmp_path, key, "--certificate", str(out),
                        "--language", language) != 0
        err = capsys.readouterr().err
        shown = {("en", "positioning"): f"anglebench analyze: test report {number} is issued "
                                        f"and recorded, but {out}: No space left on device: "
                                        f"save it with 'anglebench register show {number} "
                                        "--pdf OUT.pdf'",
                 ("en", "polygon"): f"anglebench analyze: certificate {number} is issued and "
                                    f"recorded, but {out}: No space left on device: save it "
                                    f"with 'anglebench register show {number} --pdf OUT.pdf'",
                 ("zh_CN", "positioning"): f"anglebench analyze：检测报告 {number} 已签发并登记，"
                                           f"但{out}: No space left on device：请用 'anglebench "
                                           f"register show {number} --pdf OUT.pdf' 保存",
                 ("zh_CN", "polygon"): f"anglebench analyze：证书 {number} 已签发并登记，"
                                       f"但{out}: No space left on device：请用 'anglebench "
                                       f"register show {number} --pdf OUT.pdf' 保存"}
        assert shown[language, key] in err, err


@pytest.fixture(scope="module")
def _report_and_certificate_issued(tmp_path_factory) -> Path:
    """The positioning sample's test report and the polygon sample's certificate, each with
    its results file, issued once for the module into a register of their own; the folder
    that holds the register and the files. The PDFs are stand-ins (tests/pdf_stand_in.py):
    ``register verify`` finds a file by its SHA-256 and names the kind the register
    recorded, never the pages (the two printed took ~1 s of CPU)."""
    from tests.pdf_stand_in import print_stand_ins

    folder = tmp_path_factory.mktemp("report_and_certificate")
    samples_dir = Path(__file__).resolve().parents[2] / "resources" / "samples"
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("ANGLEBENCH_REGISTER", str(folder / "register.sqlite"))
        print_stand_ins(mp)
        for key in ("positioning", "polygon"):
            assert _analyze(samples_dir, folder, key, "--certificate", str(folder / f"{key}.pdf"),
                            "--results", str(folder / f"{key}.xlsx")) == 0
    return folder


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_register_verify_names_the_kind_recorded(_report_and_certificate_issued, tmp_path,
                                                  capsys, zh_catalogue, language):
    """A PDF and a results file of a test report, of a calibration certificate, and of a
    record issued before the register recorded kinds (0.8.11's register: "document").
    The register and files issued once for the module, copied into the test's own."""
    for path in _report_and_certificate_issued.iterdir():
        shutil.copy2(path, tmp_path / path.name)
    from models.register.location import register_url, url_for_path

    assert register_url() == url_for_path(tmp_path / "register.sqlite")  # the test's own
    capsys.readouterr()
    lines = {}
    for name in ("positioning.pdf", "positioning.xlsx", "polygon.pdf", "polygon.xlsx"):
        assert main(["register", "verify", str(tmp_path / name), "--language", language]) == 0
        lines[name] = _line_about(capsys.readouterr().out, tmp_path / name)
    p = tmp_path
    if language == "en":
        assert lines["positioning.pdf"].startswith(f"{p / 'positioning.pdf'}: test report {REPORT}, "
                                                   "issued ")
        assert lines["positioning.xlsx"].startswith(
            f"{p / 'positioning.xlsx'}: the results file of test report {REPORT}, recorded ")
        assert lines["polygon.pdf"].startswith(f"{p / 'polygon.pdf'}: certificate {CERTIFICATE}, "
                                               "issued ")
        assert lines["polygon.xlsx"].startswith(
            f"{p / 'polygon.xlsx'}: the results file of certificate {CERTIFICATE}, recorded ")
    else:
        assert lines["positioning.pdf"].startswith(f"{p / 'positioning.pdf'}：检测报告 {REPORT}，"
                                                   "签发于 ")
        assert lines["positioning.xlsx"].startswith(
            f"{p / 'positioning.xlsx'}：检测报告 {REPORT} 的结果文件，记录于 ")
        assert lines["polygon.pdf"].startswith(f"{p / 'polygon.pdf'}：证书 {CERTIFICATE}，签发于 ")
        assert lines["polygon.xlsx"].startswith(
            f"{p / 'polygon.xlsx'}：证书 {CERTIFICATE} 的结果文件，记录于 ")


def test_register_verify_of_a_record_issued_before_kinds_were_recorded(tmp_path, capsys,
                                                                       monkeypatch):
    from models.register.location import url_for_path
    from models.register.store import Register

    url = tmp_path / "v5.sqlite"
    shutil.copy(Path(__file__).parents[1] / "fixtures" / "register_schema5.sqlite", url)
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(url))
    number = "AB-2026-0001-A1"  # issued by 0.8.11: its kind not recorded
    with Register(url_for_path(str(url))) as register:
        assert register.get(number).document_kind is None
        with register._write() as conn:  # a results record of 0.8.11, as it wrote it
            register._append_entry(conn, "results", number, {
                "sha256": hashlib.sha256(b"face,deviation\r\n1,0.1\r\n").hexdigest(),
                "file": "r.csv"})
    (tmp_path / "r.csv").write_bytes(b"face,deviation\r\n1,0.1\r\n")
    assert main(["register", "show", number, "--pdf", str(tmp_path / "a1.pdf")]) == 0
    capsys.readouterr()
    assert main(["register", "verify", str(tmp_path / "a1.pdf")]) == 0
    assert _line_about(capsys.readouterr().out, tmp_path / "a1.pdf").startswith(
        f"{tmp_path / 'a1.pdf'}: document {number}, issued ")
    assert main(["register", "verify", str(tmp_path / "r.csv")]) == 0
    assert _line_about(capsys.readouterr().out, tmp_path / "r.csv").startswith(
        f"{tmp_path / 'r.csv'}: the results file of document {number}, recorded ")


def _line_about(said: str, path) -> str:
    """The line of ``register verify``'s output about the file ``path`` (the chain's lines
    come first, their number not fixed)."""
    return next(line for line in said.splitlines() if line.startswith(str(path)))


def _certificate_sheet(document) -> dict[str, object]:
    import io

    from openpyxl import load_workbook

    from app.writers.results_export import results_xlsx_bytes

    book = load_workbook(io.BytesIO(results_xlsx_bytes(document)))
    # the details' sheet: *Report* on a test report's file (assessment 73 L4)
    sheet = book["Report" if document.is_test_report else "Certificate"]
    return {row[0]: row[1] for row in sheet.iter_rows(values_only=True)}


def _document(samples_dir, key, language, **changes):
    kind, result, _rows = _sample(samples_dir, key)
    return kind.certificate_document(result, _details(samples_dir, key, language=language,
                                                      **changes), kind.sample_file, {})


def test_the_xlsx_row_naming_the_test_has_its_own_chinese(samples_dir):
    """校准项目 on a calibration certificate's sheet, 检测项目 on a test report's (it read 检测,
    the PDF's title of a table, on both); "Test" in English as before; the PDF unchanged."""
    from app.writers.certificate_pdf import wording

    for key, report, chinese in (("polygon", False, "校准项目"), ("positioning", True, "检测项目")):
        for language, label in (("en", "Test"), ("zh", chinese), ("zh+en", f"{chinese} Test")):
            document = _document(samples_dir, key, language)
            assert document.is_test_report is report
            rows = _certificate_sheet(document)
            assert label in rows, (key, language, list(rows)[:12])
            assert rows[label] == wording._say("zh")(document.kind_title) if language == "zh" \
                else document.kind_title
            assert "检测" not in rows and "检测 Test" not in rows
        # the PDF's table title "Test" keeps its Chinese
        assert wording.label(_document(samples_dir, key, "zh"), "Test") == "检测"


def test_an_empty_serial_of_a_standard_is_left_out(samples_dir):
    """It printed "…; serial ; certificate …" and "…；出厂编号 ；证书编号 …"."""
    standards = json.loads((samples_dir / "certificate_polygon.json").read_text("utf-8"))[
        "standards"]
    standards[1] = {**standards[1], "serial": ""}
    for language, first, second in (
            ("en", "24-face polygon (deviations from face 1); serial P24-3; certificate "
                   "NIM-2026-0871",
             "Photoelectric autocollimator; certificate NIM-2026-0212"),
            ("zh", "24-face polygon (deviations from face 1)；出厂编号 P24-3；证书编号 NIM-2026-0871",
             "Photoelectric autocollimator；证书编号 NIM-2026-0212")):
        rows = _certificate_sheet(_document(samples_dir, "polygon", language,
                                            standards=standards))
        standard = "Standard {i}" if language == "en" else "计量标准 {i}"
        assert rows[standard.format(i=1)] == first
        assert rows[standard.format(i=2)] == second


def test_the_cross_calibrations_remark_ends_in_the_certificates_language(samples_dir,
                                                                         zh_catalogue):
    """Statement 4 ended "…不敏感）." in Chinese (an ASCII full stop joined to it)."""
    from app.writers.certificate_pdf import wording

    for key in ("crosscal", "crosscal_encoder"):
        kind, result, _rows = _sample(samples_dir, "crosscal")
        data = json.loads((samples_dir / f"certificate_{key}.json").read_text("utf-8"))
        data.update({"example": False, "certificate_number": "", "language": "zh"})
        document = kind.certificate_document(result, CertificateMetadata.from_dict(data),
                                             kind.sample_file, {})
        remark = document.statements[3]
        assert str(remark).startswith("Not separate rows of the budget: drift (")
        assert str(remark).endswith("insensitive to a uniform temperature).")
        chinese = wording._say("zh")(remark)
        assert chinese.startswith("不单列于预算中：漂移（") and chinese.endswith("不敏感）。"), chinese
