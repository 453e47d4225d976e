"""The window and a maker's name (rev65): an original whose serial and date of calibration
are those of a current certificate naming another maker asks whether it is another maker's
item — No issues nothing, Yes issues it and the register records the answer (F1); the same
maker spelt otherwise is the same calibration (asked for a separate calibration's reason);
an item whose certificate names no maker shows no due date borrowed from another maker's
(F4). The real main window and register window, driven as a user would."""

from __future__ import annotations

import json

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QMessageBox

from app.certificate_issue import issue_certificate
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.register.location import register_url
from models.register.store import Register
from models.registry import KINDS
from tests.own_readings import own_readings

#: certificates are issued from the window; the tests are of the questions asked and what
#: the register records, never of a PDF's pages: each PDF a stand-in (tests/app/conftest.py;
#: ~0.5 s of CPU a certificate not printed)
pytestmark = [pytest.mark.slow, pytest.mark.usefixtures("pdf_stand_in")]


def _details(samples_dir, **changes) -> CertificateMetadata:
    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    data.update({"example": False, "certificate_number": "", **changes})  # the lab's own
    return CertificateMetadata.from_dict(data)


def _issue(register, samples_dir, tmp_path, name, **changes):
    """An original of the item ``changes`` name, from readings of its own (its maker and
    serial's: tests/own_readings.py; one item's readings are refused as another's, and the
    window's are the sample's)."""
    kind = KINDS["polygon"]
    details = _details(samples_dir, **changes)
    own = own_readings(samples_dir / kind.sample_file,
                       f"{details.item_manufacturer} {details.item_serial}",
                       tmp_path / "readings")
    rows = map_columns(read_table(own), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))
    return issue_certificate(register, kind, result, _details(samples_dir, **changes),
                             kind.checked_settings({}), rows, "polygon_sample.csv",
                             str(tmp_path / f"{name}.pdf"))


def _answer(window, samples_dir, tmp_path, calls: list, maker: str, answer) -> None:
    """The export's dialogs answered: the details with ``maker``; the window's question
    about another maker's item answered ``answer`` (its text recorded)."""
    view = window.certificates.view
    view.edit_certificate_details = lambda meta, problems, raw: calls.append("details") or \
        _details(samples_dir, item_manufacturer=maker)
    view.confirm_draft = view.confirm_implausible = view.confirm_standards = lambda *a: True
    view.ask_separate_calibration = lambda numbers, reason: calls.append(
        ("separate", numbers)) or ""
    view.choose_save_path = lambda title, suggested, file_filter: calls.append("file") or \
        str(tmp_path / f"{maker or 'none'}.pdf")
    view.wait_cursor = lambda on: None
    view.show_status = lambda text, *_: calls.append(("status", text))
    view.tell = lambda title, text: calls.append(("tell", text))
    window.ask = lambda title, text, buttons, default: calls.append(("asked", title, text)) \
        or answer


def test_another_makers_serial_is_asked_and_the_answer_recorded(window, qtbot, samples_dir,
                                                               tmp_path):
    with Register(register_url()) as register:
        first = _issue(register, samples_dir, tmp_path, "first",
                       item_manufacturer="Möller-Wedel Optical GmbH").number
    polygon = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    polygon.load_sample()
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    calls: list = []
    # the same maker spelt otherwise: the same calibration, asked for a separate one's reason
    _answer(window, samples_dir, tmp_path, calls, "Moeller-Wedel Optical", QMessageBox.StandardButton.Yes)
    assert not window.export_certificate()
    assert calls[:2] == ["details", ("separate", (first,))]
    # another maker: asked; No issues nothing
    calls.clear()
    _answer(window, samples_dir, tmp_path, calls, "Zeta Instruments",
            QMessageBox.StandardButton.No)
    assert not window.export_certificate()
    asked = [c for c in calls if c[0] == "asked"]
    assert len(asked) == 1 and asked[0][1] == "Another manufacturer's item?"
    assert asked[0][2].startswith(f"{first} reports serial RX-26-0815, calibrated 2026-11-20, "
                                  "of Möller-Wedel Optical GmbH, not of Zeta Instruments")
    with Register(register_url()) as register:
        assert [r.number for r in register.list()] == [first]
    # Yes: issued, and the answer is in the register's chain
    calls.clear()
    _answer(window, samples_dir, tmp_path, calls, "Zeta Instruments",
            QMessageBox.StandardButton.Yes)
    assert window.export_certificate()
    with Register(register_url()) as register:
        [zeta] = [r for r in register.list() if r.number != first]
        assert zeta.item_manufacturer == "Zeta Instruments"
        [said] = register.another_maker_confirmations(zeta.number)
        assert said["others"] == [{"number": first,
                                   "manufacturer": "Möller-Wedel Optical GmbH"}]
        assert register.audit() == []


def test_an_item_without_a_maker_shows_no_borrowed_due_date(window, qtbot, samples_dir,
                                                            tmp_path):
    """rev65 F4: the makerless "001" (calibrated 2025-01-10) was shown due 2027-11-20, from
    Acme's "001" calibrated 2026-11-20 and Acme's interval."""
    with window.certificates.open_register() as register:
        _issue(register, samples_dir, tmp_path, "a", item_serial="001", item_manufacturer="",
               calibration_date="2025-01-10")
        _issue(register, samples_dir, tmp_path, "b", item_serial="001",
               item_manufacturer="Acme Optics", calibration_date="2026-11-20")
        register.set_interval("001", 365, "Acme Optics")
    window.show_register()
    dialog = window.register_window
    numbers = [dialog.table.item(row, 0).text() for row in range(2)]
    assert numbers == ["AB-2026-0002", "AB-2026-0001"]
    qtbot.mouseClick(dialog.table.viewport(), Qt.MouseButton.LeftButton,
                     pos=dialog.table.visualItemRect(dialog.table.item(1, 0)).center())
    dialog.buttons["history"].click()  # the makerless item's
    title = dialog.history_title.text()
    assert "next due" not in title and not dialog.due_line.isVisible()
    assert "no due date: the certificate names no manufacturer, and this serial's name " \
           "Acme Optics" in title
    qtbot.mouseClick(dialog.table.viewport(), Qt.MouseButton.LeftButton,
                     pos=dialog.table.visualItemRect(dialog.table.item(0, 0)).center())
    dialog.buttons["history"].click()  # Acme's has its own
    assert "next due 2027-11-20" in dialog.history_title.text()
