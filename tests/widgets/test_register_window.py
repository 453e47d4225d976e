"""The register window: its presenter with a mock view, and the real window driven by
qtbot (list, search, verify, amend through the main window, history with a due date)."""

from __future__ import annotations

import json
from unittest import mock

import pytest
from PySide6.QtCore import Qt

from app.certificate_issue import issue_certificate
from app.register_presenter import RegisterPresenter, RegisterView
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS
from tests.own_readings import own_readings
from tests.pdf_stand_in import print_stand_ins

pytestmark = pytest.mark.slow  # every test here takes more than 0.4 s (a window, a certificate, a program)


def issue_polygon(register, samples_dir, tmp_path, name, **changes):
    """The polygon sample's certificate, the example's details changed by ``changes``: the
    example's item from the sample's readings, another item (serial or maker changed) from
    readings of its own (tests/own_readings.py: one item's readings are refused as
    another's, hostile78 F7)."""
    kind = KINDS["polygon"]
    readings = samples_dir / kind.sample_file
    if "item_serial" in changes or "item_manufacturer" in changes:
        readings = own_readings(readings, f"{changes.get('item_manufacturer', '')} "
                                f"{changes.get('item_serial', '')}",
                                tmp_path.with_name(f"{tmp_path.name}-own"))
    rows = map_columns(read_table(readings), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))
    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    # the lab's own details made from the example (with "example": true the window makes a
    # specimen, as the command line does)
    data.update({"certificate_number": "", "example": False, **changes})
    return issue_certificate(register, kind, result, CertificateMetadata.from_dict(data),
                             kind.checked_settings({}), rows, "polygon_sample.csv",
                             str(tmp_path / f"{name}.pdf"))


@pytest.fixture
def pdf_stand_in(monkeypatch):
    """Each certificate's PDF a stand-in (tests/pdf_stand_in.py), for a test of the register's
    records, its history and its answers that reads no PDF page (verify finds a PDF by its
    SHA-256: the stand-in's is as much its own)."""
    print_stand_ins(monkeypatch)


@pytest.mark.usefixtures("pdf_stand_in")
def test_presenter_lists_searches_and_refuses_a_superseded_amendment(window, samples_dir,
                                                                    tmp_path):
    with window.certificates.open_register() as register:
        first = issue_polygon(register, samples_dir, tmp_path, "a")
        issue_polygon(register, samples_dir, tmp_path, "b", item_serial="OTHER-1",
                      customer_name="Other customer")
    view = mock.create_autospec(RegisterView, instance=True)
    opened = mock.Mock(return_value=True)
    presenter = RegisterPresenter(view, window.certificates, opened)
    presenter.refresh()
    header, rows = view.show_records.call_args.args
    assert header[0] == "Number" and [r[0] for r in rows] == ["AB-2026-0002", "AB-2026-0001"]
    presenter.refresh("other")
    assert [r[0] for r in view.show_records.call_args.args[1]] == ["AB-2026-0002"]
    presenter.refresh("")
    view.selected_row.return_value = 1
    assert presenter.revise()
    # opened with the question that says what Amend… replaces (rev62 F3)
    opened.assert_called_once()
    assert opened.call_args.args[:2] == (first.project_json, "polygon")
    assert opened.call_args.args[2].startswith("Amend… opens the readings and details "
                                               "AB-2026-0001 was issued from in place of")
    assert window.certificates.pending.number == "AB-2026-0001"
    view.ask_pdf_to_verify.return_value = str(tmp_path / "a.pdf")
    assert presenter.verify_pdf().number == "AB-2026-0001"
    view.ask_pdf_path.return_value = str(tmp_path / "copy.pdf")
    assert presenter.save_pdf()
    assert (tmp_path / "copy.pdf").read_bytes() == (tmp_path / "a.pdf").read_bytes()


@pytest.mark.usefixtures("pdf_stand_in")
def test_amend_from_the_window_issues_amendment_one(window, samples_dir, tmp_path, qtbot):
    with window.certificates.open_register() as register:
        issue_polygon(register, samples_dir, tmp_path, "a")
        register.set_interval("RX-26-0815", 365)
    window.show_register()
    dialog = window.register_window
    assert dialog.table.rowCount() == 1 and dialog.table.item(0, 0).text() == "AB-2026-0001"
    dialog.buttons["history"].click()
    assert "next due 2027-11-20" in dialog.history_title.text()
    assert dialog.figure.count() == 2 and dialog.due_line.isVisible()
    x, y = dialog.history_curves[0].getData()
    # corrected peak-to-peak of the sample measured on a levelled bench (#28; 0.9817 in the seed frame)
    assert len(y) == 1 and y[0] == pytest.approx(0.9835, abs=1e-3)
    dialog.figure.setCurrentIndex(1)
    assert dialog.history_curves[0].getData()[1][0] == pytest.approx(480.0, abs=0.5)  # ψ
    dialog.tell = lambda *a: None
    dialog.buttons["amend"].click()
    assert window.current.kind.key == "polygon" and window.current.result is not None
    # the technician exports: the details come back from the record, the change is asked
    window.certificates.view.edit_certificate_details = lambda meta, problems, raw: meta
    window.certificates.view.ask_change_note = lambda revision: "reference standard's certificate number"
    window.certificates.view.choose_save_path = lambda *a: str(tmp_path / "amended.pdf")
    assert window.export_certificate()
    with window.certificates.open_register() as register:
        assert register.get("AB-2026-0001-A1").supersedes == "AB-2026-0001"
        assert register.get("AB-2026-0001").status == "superseded"
    dialog.search.setText("A1")
    assert dialog.table.rowCount() == 1


@pytest.mark.usefixtures("pdf_stand_in")
def test_the_history_of_an_item_holds_its_serial_typed_another_way(window, samples_dir,
                                                                     tmp_path, qtbot):
    """#63 regkeys: a serial typed "rx 26 0815" is the item RX-26-0815 at issue (the
    one-calibration check), but the window's history of either certificate showed its own
    calibration only, and the due date followed it, not the later one."""
    with window.certificates.open_register() as register:
        issue_polygon(register, samples_dir, tmp_path, "a")
        issue_polygon(register, samples_dir, tmp_path, "b", item_serial="rx 26 0815",
                      calibration_date="2026-11-23")
        register.set_interval("RX-26-0815", 365)
    window.show_register()
    dialog = window.register_window
    assert [dialog.table.item(row, 0).text() for row in range(2)] == ["AB-2026-0002",
                                                                      "AB-2026-0001"]
    for row in (0, 1):
        qtbot.mouseClick(dialog.table.viewport(), Qt.MouseButton.LeftButton,
                         pos=dialog.table.visualItemRect(dialog.table.item(row, 0)).center())
        assert dialog.selected_row() == row
        dialog.buttons["history"].click()
        assert "next due 2027-11-23" in dialog.history_title.text()
        x, y = dialog.history_curves[0].getData()
        assert len(y) == 2 and x[1] - x[0] == 3 * 86400.0


@pytest.mark.usefixtures("pdf_stand_in")
def test_the_history_of_a_serial_is_its_makers_item_only(window, samples_dir, tmp_path,
                                                          qtbot):
    """#64 review F6: Acme's "001" (calibrated 2025-06-01) and Zeta's "001" (2026-11-20)
    were one history in the window, Acme's due date 2027-11-20 (Zeta's calibration + 365
    days) where it was overdue since 2026-06-01; setting the interval kept that. Stop 63:
    the interval set in Acme's history was Zeta's too (one per serial); each maker's item
    has its own now."""
    with window.certificates.open_register() as register:
        issue_polygon(register, samples_dir, tmp_path, "a", item_serial="001",
                      item_manufacturer="Acme Optics", calibration_date="2025-06-01")
        issue_polygon(register, samples_dir, tmp_path, "b", item_serial="001",
                      item_manufacturer="Zeta Instruments", calibration_date="2026-11-20")
    window.show_register()
    dialog = window.register_window
    assert [dialog.table.item(row, 0).text() for row in range(2)] == ["AB-2026-0002",
                                                                      "AB-2026-0001"]
    qtbot.mouseClick(dialog.table.viewport(), Qt.MouseButton.LeftButton,
                     pos=dialog.table.visualItemRect(dialog.table.item(1, 0)).center())
    dialog.buttons["history"].click()
    dialog.interval.lineEdit().selectAll()  # the user types the interval and sets it
    qtbot.keyClicks(dialog.interval.lineEdit(), "365")
    assert dialog.interval.value() == 365
    dialog.interval_button.click()
    assert "next due 2026-06-01" in dialog.history_title.text()
    assert len(dialog.history_curves[0].getData()[1]) == 1  # Acme's calibration only
    qtbot.mouseClick(dialog.table.viewport(), Qt.MouseButton.LeftButton,
                     pos=dialog.table.visualItemRect(dialog.table.item(0, 0)).center())
    dialog.buttons["history"].click()
    assert "no due date" in dialog.history_title.text() and dialog.interval.value() == 0
    dialog.interval.lineEdit().selectAll()  # Zeta's item's own interval
    qtbot.keyClicks(dialog.interval.lineEdit(), "730")
    dialog.interval_button.click()
    assert "next due 2028-11-19" in dialog.history_title.text()
    qtbot.mouseClick(dialog.table.viewport(), Qt.MouseButton.LeftButton,
                     pos=dialog.table.visualItemRect(dialog.table.item(1, 0)).center())
    dialog.buttons["history"].click()  # Acme's kept its own
    assert "next due 2026-06-01" in dialog.history_title.text()
    assert dialog.interval.value() == 365
    with window.certificates.open_register() as register:
        assert register.interval("001", "Acme Optics") == 365
        assert register.interval("001", "ZETA instruments") == 730
        assert register.audit() == []


def test_chinese_in_the_window_is_drawn_not_boxed(qapp):
    """Without a system CJK font the window registers the bundled one, which has the glyphs
    of a Chinese customer's name (widgets.fonts.ensure_cjk_font, which the window calls, asked
    here itself: no window needed, ~0.45 s of CPU)."""
    from PySide6.QtGui import QFont, QFontMetrics

    from widgets.fonts import ensure_cjk_font

    family = ensure_cjk_font()
    assert family
    metrics = QFontMetrics(QFont(family))
    assert all(metrics.inFontUcs4(ord(ch)) for ch in "长春光电有限公司转角方位")


def test_an_issued_certificate_prints_page_for_page(window, samples_dir, tmp_path, monkeypatch):
    """Print… in the register: the print dialog, then every page of the PDF as issued,
    full size (to a PDF printer here, read back page by page)."""
    from pypdf import PdfReader
    from PySide6.QtPrintSupport import QPrintDialog, QPrinter

    from widgets.print_view import pdf_page_images

    with window.certificates.open_register() as register:
        issue_polygon(register, samples_dir, tmp_path, "a")
    issued = (tmp_path / "a.pdf").read_bytes()
    printed = tmp_path / "printed.pdf"

    def accept(dialog):
        dialog.printer().setOutputFormat(QPrinter.OutputFormat.PdfFormat)
        dialog.printer().setOutputFileName(str(printed))
        return 1

    monkeypatch.setattr(QPrintDialog, "exec", accept)
    window.show_register()
    dialog = window.register_window
    dialog.table.selectRow(0)
    told = []
    dialog.tell = lambda *a: told.append(a)
    dialog.buttons["print"].click()
    assert told == []
    pages = len(PdfReader(str(tmp_path / "a.pdf")).pages)
    assert pages >= 2 and len(PdfReader(str(printed)).pages) == pages
    first = next(pdf_page_images(issued, 50))
    assert abs(first.width() - 210 / 25.4 * 50) <= 1  # A4 at 50 dpi
    gray = [first.pixelColor(x, y).lightness() for x in range(0, first.width(), 3)
            for y in range(0, first.height(), 3)]
    assert min(gray) < 80 and sum(g > 240 for g in gray) > len(gray) / 2  # text on paper
    monkeypatch.setattr(QPrintDialog, "exec", lambda dialog: 0)
    printed.unlink()
    dialog.buttons["print"].click()  # cancelled: nothing printed, nothing said
    assert not printed.exists() and told == []


def test_the_history_is_labelled_and_empty_says_so_in_the_window_language(qtbot):
    """#31: before a certificate was picked the history showed an unlabelled empty
    drop-down and a meaningless 0.2–0.8 axis; in Chinese its months were "Feb, Mar"."""
    import datetime as dt

    from widgets.i18n import install_language
    from widgets.register_window import EPOCH, RegisterWindow

    view = RegisterWindow()
    qtbot.addWidget(view)
    view.show()
    assert not view.history_plot.isVisible()
    assert view.history_title.text().startswith("Select a certificate and press History")
    assert not view.figure.isVisible() and not view.figure_caption.isVisible()
    day = dt.date(2026, 2, 1).toordinal()
    view.show_history("SN-1", {"corrected peak-to-peak (\")": ([day, day + 60], [0.8, 0.9])},
                      ["2026-02-01", "2026-04-02"], "2027-04-02", 365)
    assert view.history_plot.isVisible()
    assert view.figure.isVisible() and view.figure_caption.text() == "figure"
    assert view.figure.currentText() == "corrected peak-to-peak (\")"
    axis = view.history_plot.getAxis("bottom")
    february = (day - EPOCH) * 86400.0
    months = [february + k * 29 * 86400.0 for k in range(3)]
    # the zoom level pyqtgraph writes months at ("%b")
    axis.zoomLevel = next(level for level in axis.zoomLevels.values()
                          if level.tickSpecs[0].format == "%b")
    english = axis.tickStrings(months, 1.0, axis.zoomLevel.tickSpecs[0].spacing)
    assert any("Feb" in text for text in english), english
    install_language("zh_CN")
    try:
        chinese = axis.tickStrings(months, 1.0, axis.zoomLevel.tickSpecs[0].spacing)
    finally:
        install_language("en")
    assert any("2月" in text for text in chinese) and not any(
        name in text for text in chinese for name in ("Feb", "Mar", "Apr")), chinese


def test_opening_checks_the_stored_pdfs_in_the_background(window, qtbot):
    """A stored PDF swapped for another record's is shown as a warning in the register window,
    found by a worker thread while the window stays free."""
    import sqlalchemy as sa

    from models.register.chain import HEAD_MARK
    from models.register.store import IssueRequest

    meta = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-01",
                               item_serial="RX-1")
    with window.certificates.open_register() as register:
        numbers = [register.issue(IssueRequest("polygon", meta, '{"workbenches": {}}'),
                                  lambda m, head="": f"%PDF {m.certificate_number} "
                                  f"{HEAD_MARK}{head}".encode())[0].number for _ in range(3)]
    window.show_register()
    qtbot.waitUntil(lambda: "matches" in window.register_window.pdf_check.text(), timeout=20000)
    assert not window.register_window.pdf_check_warning
    window.register_window.close()
    engine = sa.create_engine(window.certificates.register_url())
    with engine.begin() as conn:  # the second record's PDF replaced by the first's
        conn.execute(sa.text("UPDATE certificates SET pdf = (SELECT pdf FROM certificates "
                             "WHERE number = :a) WHERE number = :b"),
                     {"a": numbers[0], "b": numbers[1]})
    engine.dispose()
    window.show_register()
    # the check runs on its own thread: on return the window says it is checking
    assert window.register_window.pdf_check.text() == "Checking the stored PDFs…"
    qtbot.waitUntil(lambda: window.register_window.pdf_check_warning, timeout=20000)
    text = window.register_window.pdf_check.text()
    assert numbers[1] in text and "does not match" in text and numbers[0] not in text
    # the list is shown, not refused
    assert sorted(r.number for r in window.register_presenter.records) == sorted(numbers)
    for thread in window.register_window.background:
        thread.join(5)


def _titled_in(window, count: int) -> list[str]:
    """Certificates in the window's register whose stand-in PDF carries its head in its
    keywords and its number in its title, as a certificate's document information does."""
    from models.register.chain import HEAD_MARK
    from models.register.store import IssueRequest

    meta = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-01",
                               item_serial="RX-1")
    with window.certificates.open_register() as register:
        return [register.issue(IssueRequest("polygon", meta, '{"workbenches": {}}'),
                               lambda m, head="": f"%PDF /Title (Calibration certificate "
                               f"{m.certificate_number}) /Keywords ({HEAD_MARK}{head})"
                               .encode())[0].number for _ in range(count)]


def _truncate_consistently(window, number: str) -> None:
    """The last record deleted by hand, the counter and the state row set back to the
    record before it: the register agrees with itself (rev64 F8, f_truncate.sh; as
    tests/app/test_register_cli.py makes it)."""
    import sqlalchemy as sa

    engine = sa.create_engine(window.certificates.register_url())
    with engine.begin() as conn:
        for statement in (
                "UPDATE register_state SET value = (SELECT chain_sha256 FROM certificates "
                "WHERE seq = (SELECT seq - 1 FROM certificates WHERE number = :n)) "
                "WHERE name = 'head'",
                "UPDATE register_state SET value = (SELECT seq - 1 FROM certificates WHERE "
                "number = :n) WHERE name = 'records'",
                "UPDATE counters SET last_value = last_value - 1",
                "DELETE FROM certificates WHERE number = :n"):
            conn.execute(sa.text(statement), {"n": number})
    engine.dispose()


def _verify_in_the_window(window, qtbot, monkeypatch, path) -> list[tuple[str, str]]:
    """The register window opened, "Verify a PDF…" clicked and ``path`` chosen in its file
    dialog: what the window told, (title, text) each."""
    import widgets.register_window as register_window

    told: list[tuple[str, str]] = []
    monkeypatch.setattr(register_window.RegisterWindow, "tell",
                        lambda self, title, text: told.append((title, text)))
    monkeypatch.setattr(register_window, "ask_open_file", lambda *a, **k: str(path))
    window.show_register()
    dialog = window.register_window
    qtbot.waitUntil(lambda: "Checking" not in dialog.pdf_check.text(), timeout=20000)
    qtbot.mouseClick(dialog.buttons["verify"], Qt.MouseButton.LeftButton)
    for thread in dialog.background:
        thread.join(5)
    return told


def test_verify_in_the_window_names_a_deleted_record_by_its_head_and_records_nothing_unproven(
        window, qtbot, monkeypatch, tmp_path):
    """rev64 F8 in the window: "Verify a PDF…" of a certificate whose record was deleted
    (the register agreeing with itself) said only "not in the register"; it says what
    ``anglebench register verify`` says of its place. In a register without the lab's key
    the copy carries no proof of issue, and the head it prints is public: the window says
    the register cannot tell whether it was issued here and records nothing that would stop
    issuing (reg73 #3: a file printing the head stopped the lab for good). With the key,
    the same check (models/register/printed_place.py) records it: tests/app/
    test_register_cli.py::test_a_certificate_whose_record_was_deleted_is_named_by_its_head_
    and_stops_issuing."""
    from models.register.store import Register

    numbers = _titled_in(window, 3)
    with window.certificates.open_register() as register:
        (tmp_path / "3.pdf").write_bytes(register.pdf(numbers[2]))
    _truncate_consistently(window, numbers[2])
    with Register(window.certificates.register_url()) as register:
        assert not register.problems and not register.audit()  # agrees with itself
    told = _verify_in_the_window(window, qtbot, monkeypatch, tmp_path / "3.pdf")
    title, text = told[-1]
    assert title == "Not in the register"
    assert (f"{tmp_path / '3.pdf'} ({numbers[2]}) prints the head before record 3, where the "
            "register's chain ends, and no record has its SHA-256: the register cannot tell "
            "whether this was issued here") in text
    with Register(window.certificates.register_url()) as register:  # nothing recorded
        assert not register.problems


def test_verify_in_the_window_says_another_record_is_in_its_place(window, qtbot, monkeypatch,
                                                                   tmp_path):
    """The record deleted and its number issued again before anyone looked: the window says
    the PDF is not what the register holds at its place, as the command line does, and
    records nothing (the cause is not known)."""
    from models.register.store import IssueRequest, Register

    numbers = _titled_in(window, 2)
    with window.certificates.open_register() as register:
        (tmp_path / "2.pdf").write_bytes(register.pdf(numbers[1]))
    _truncate_consistently(window, numbers[1])
    meta = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-02",
                               item_serial="RX-1")
    with window.certificates.open_register() as register:
        assert register.issue(IssueRequest("polygon", meta, '{"workbenches": {}}'),
                              lambda m, head="": b"%PDF another")[0].number == numbers[1]
    told = _verify_in_the_window(window, qtbot, monkeypatch, tmp_path / "2.pdf")
    assert (f"prints the head before record 2, but record 2 is {numbers[1]}, not this PDF: the "
            "PDF was altered after issue, or the register's record of it was replaced"
            ) in told[-1][1]
    with Register(window.certificates.register_url()) as register:
        assert not register.problems


def test_the_list_has_the_room_until_a_history_is_asked_for(window, samples_dir, tmp_path,
                                                             qtbot):
    """day74: at 200 % on a 1280×720 laptop (the window 627×331) the list showed one row:
    the history's empty area — a sentence, the interval row and a blank plot's room — held a
    fixed share. Now the list takes the room until History is pressed, the interval row
    (the shown instrument's) comes with the history, and the history then gets half."""
    with window.certificates.open_register() as register:
        issue_polygon(register, samples_dir, tmp_path, "a")
    window.show_register()
    dialog = window.register_window
    dialog.resize(627, 331)
    qtbot.waitUntil(lambda: dialog.isVisible())
    qtbot.wait(50)
    upper, lower = dialog.splitter.sizes()
    assert upper > 4 * lower, (upper, lower)
    assert lower >= dialog.history_title.sizeHint().height()  # its title stays in sight
    assert not any(w.isVisible() for w in dialog.interval_row)
    dialog.buttons["history"].click()
    qtbot.wait(50)
    upper, lower = dialog.splitter.sizes()
    assert lower >= 0.45 * (upper + lower), (upper, lower)
    assert all(w.isVisible() for w in dialog.interval_row)
