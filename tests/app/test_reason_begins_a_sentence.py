"""A reason the register gives begins in lower case, to follow "anglebench analyze: " on the
command line; where the window's question or message puts it first, as a sentence of its own
("{reason}.\\n\\nIs today …?"), it begins with a capital (0.8.22: "this certificate would be
dated 2026-12-01 …" opened the question Is today …?). A reason that begins with a name that
is no word (a file, a certificate number) keeps its case; Chinese has none.

The reasons are the register's own, raised as an issue raises them: the clock rules for an
issue 40 days after the last record, and a second issue in a time zone whose date is the day
before the first's."""

from __future__ import annotations

import datetime as dt
from unittest import mock

import pytest

from app.certificate_dialogs import CertificateDialogs
from app.certificate_presenter import CertificatePresenter, CertificateView
from models.certificate.metadata import CertificateMetadata
from models.messages import as_sentence
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.register.clock_rules import DateToConfirm, LastChained, clock_checked
from models.registry import KINDS


class _Window:
    """The main window's ``ask``: the question recorded, answered No."""

    def __init__(self) -> None:
        self.asked: list[tuple[str, str]] = []

    def ask(self, title, text, buttons, default):
        self.asked.append((title, text))
        return default


def _far_after_reason() -> tuple[str, str]:
    """The register's reason for asking today's date: an issue 40 days after its last
    record (the date, and the reason as the window is given it)."""
    now = dt.datetime(2026, 12, 7, 9, 0, tzinfo=dt.timezone.utc)
    last = LastChained(7, now - dt.timedelta(days=40), "AB-2026-0007", "bench-2", "wang")
    with pytest.raises(DateToConfirm) as raised:
        clock_checked(last, now, now.date(), None)
    return raised.value.date.isoformat(), str(raised.value)


def test_the_date_question_begins_with_a_capital():
    date, reason = _far_after_reason()
    assert reason.startswith("this certificate would be dated")  # as the register says it
    window = _Window()
    assert CertificateDialogs(window).confirm_issue_date(date, reason) is False
    [(_title, text)] = window.asked
    assert text.startswith("This certificate would be dated " + date), text
    assert text[1:].startswith(reason[1:])  # nothing else of it touched


def test_every_question_that_opens_with_the_reason_begins_with_a_capital():
    _date, reason = _far_after_reason()
    window = _Window()
    dialogs = CertificateDialogs(window)
    dialogs.confirm_another_maker(("AB-2026-0001",), reason)
    revision = mock.Mock(number="AB-2026-0001", replacement=False)
    dialogs.confirm_correction(revision, reason)
    dialogs.confirm_correction(mock.Mock(number="AB-2026-0001", replacement=True), reason)
    assert len(window.asked) == 3
    for _title, text in window.asked:
        assert text.startswith("T" + reason[1:] + "."), text
    with mock.patch.object(CertificateDialogs, "_multiline_answer",
                           side_effect=lambda title, question: window.asked.append(
                               (title, question)) or "") as answer:
        dialogs.ask_separate_calibration(("AB-2026-0001",), reason)
    answer.assert_called_once()
    assert window.asked[-1][1].startswith("T" + reason[1:] + ".")


@pytest.mark.parametrize("text", [
    "ab-2026-0001 was withdrawn (a typing error)",  # a lab's number in lower case
    "run.anglebench.json: not a project file",
    "tilt_bound_arcsec must be a number",
    "这张证书的日期将是 2026-12-01",
    "",
])
def test_a_name_that_is_no_word_keeps_its_case(text):
    assert as_sentence(text) == text


@pytest.mark.slow
def test_a_refused_issue_says_its_reason_as_a_sentence(samples_dir, tmp_path, monkeypatch):
    """The second issue's date, in a zone 25 hours behind the first's, is the day before the
    first's: refused, and the window says why in a sentence of its own."""
    from models.register.store import Register

    class Store(dict):
        def value(self, key, default=None):
            return self.get(key, default)

        def setValue(self, key, value):  # noqa: N802 - QSettings' name
            self[key] = value

    view = mock.create_autospec(CertificateView, instance=True)
    presenter = CertificatePresenter(view, Store(), dict, mock.Mock())
    monkeypatch.setattr(Register, "clock", staticmethod(
        lambda: dt.datetime(2026, 12, 1, 12, 30, tzinfo=dt.timezone.utc)))
    kind = KINDS["theodolite"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))
    details = {
        "lab_name": "Lab", "customer_name": "Customer", "item_description": "Turntable",
        "calibration_date": "2026-11-20", "issue_date": "2026-11-24", "operator": "Wang",
        "approver": "Dr. Li",
        "standards": [{"description": "Theodolite", "certificate_no": "N-1",
                       "uncertainty": 0.5}]}
    presenter.set_lab_timezone("Pacific/Kiritimati")  # UTC+14: 2026-12-02
    view.edit_certificate_details.return_value = CertificateMetadata.from_dict(
        {**details, "item_serial": "T-1"})
    view.choose_save_path.return_value = str(tmp_path / "first.pdf")
    assert presenter.export_certificate(kind, result, {}, "run.csv", [])
    presenter.set_lab_timezone("Pacific/Pago_Pago")  # UTC−11: 2026-12-01
    view.edit_certificate_details.return_value = CertificateMetadata.from_dict(
        {**details, "item_serial": "T-2"})
    view.choose_save_path.return_value = str(tmp_path / "second.pdf")
    assert not presenter.export_certificate(kind, result, {}, "run.csv", [])
    title, text = view.tell.call_args.args
    assert title == "Not issued"
    assert text.startswith("This certificate would be dated 2026-12-01 "), text
    assert not (tmp_path / "second.pdf").exists()
