"""The certificate presenter with a mock view: no window, no dialog (Mantid's MVP tests
are the model)."""

from __future__ import annotations

import dataclasses
import datetime as dt
import re
from unittest import mock

import pytest
from pypdf import PdfReader

from app.certificate_presenter import CertificatePresenter, CertificateView, PendingRevision
from models.certificate.metadata import CertificateMetadata
from models.project.file import project_from_json
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS


class Store(dict):
    def value(self, key, default=None):
        return self.get(key, default)

    def setValue(self, key, value):  # noqa: N802 - QSettings' name
        self[key] = value


@pytest.fixture
def parts():
    view = mock.create_autospec(CertificateView, instance=True)
    metadata: dict = {}
    modified = mock.Mock()
    presenter = CertificatePresenter(view, Store(), lambda: metadata, modified)
    return presenter, view, metadata, modified


def window_presenter():
    """(view, presenter): the window's certificate presenter over a stand-in view and settings."""
    view = mock.create_autospec(CertificateView, instance=True)
    return view, CertificatePresenter(view, Store(), lambda: {}, mock.Mock())


def theodolite_sample_analysed(samples_dir):
    """(kind, rows, result) of the bundled theodolite sample."""
    kind = KINDS["theodolite"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    return kind, rows, kind.analyze(ReadingsSheet(kind.columns, rows).parse(),
                                    kind.checked_settings({}))


def _theodolite(samples_dir):
    kind, _, result = theodolite_sample_analysed(samples_dir)
    return kind, result


@pytest.mark.slow
def test_a_draft_is_written_and_nothing_recorded(parts, samples_dir, tmp_path):
    presenter, view, metadata, modified = parts
    entered = CertificateMetadata(certificate_number="AB/7", lab_name="Lab")
    view.edit_certificate_details.return_value = entered
    view.choose_save_path.return_value = str(tmp_path / "out")
    kind, result = _theodolite(samples_dir)
    assert presenter.export_certificate(kind, result, {}, "run.csv")
    assert view.choose_save_path.call_args.args[1] == "AB-7.pdf"
    assert (tmp_path / "out.pdf").read_bytes().startswith(b"%PDF")
    assert metadata["certificates"]["theodolite"]["lab_name"] == "Lab"
    modified.assert_called_once()
    assert "nothing was recorded in the register" in view.show_status.call_args.args[0]
    view.wait_cursor.assert_has_calls([mock.call(True), mock.call(False)])
    with presenter.open_register() as register:
        assert register.list() == []  # a draft allocates nothing


COMPLETE = CertificateMetadata.from_dict({
    "lab_name": "Lab", "customer_name": "Customer", "item_description": "Turntable",
    "item_serial": "T-1", "calibration_date": "2026-11-20", "issue_date": "2026-11-24",
    "operator": "Wang", "approver": "Dr. Li",
    "standards": [{"description": "Theodolite", "certificate_no": "N-1",
                   "uncertainty": 0.5}]})


@pytest.mark.slow
@pytest.mark.usefixtures("pdf_stand_in")  # no PDF page read: the presenter's questions and records
def test_without_an_approver_the_window_writes_a_draft_and_records_nothing(parts, samples_dir,
                                                                          tmp_path):
    presenter, view, _, _ = parts
    kind, result = _theodolite(samples_dir)
    view.edit_certificate_details.return_value = dataclasses.replace(COMPLETE, approver="")
    view.confirm_draft.return_value = True
    view.choose_save_path.return_value = str(tmp_path / "d.pdf")
    assert presenter.export_certificate(kind, result, {}, "run.csv", [])
    assert view.confirm_draft.call_args.args[0] == ["approver"]
    with presenter.open_register() as register:
        assert register.list() == []


@pytest.mark.slow
def test_an_issued_certificate_is_numbered_and_recorded_and_can_be_amended(parts, samples_dir,
                                                                         tmp_path):
    presenter, view, metadata, _ = parts
    kind, result = _theodolite(samples_dir)
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    view.edit_certificate_details.return_value = COMPLETE
    view.choose_save_path.return_value = str(tmp_path / "first.pdf")
    assert presenter.export_certificate(kind, result, {}, "run.csv", rows)
    assert "Certificate AB-2026-0001 issued" in view.show_status.call_args.args[0]
    with presenter.open_register() as register:
        record = register.get("AB-2026-0001")
        stored = project_from_json(record.project_json).workbenches["theodolite"]
        assert stored.rows[3][:3] == rows[3][:3]  # the readings as typed
    # an amendment: the next export of this workbench asks what changed
    presenter.start_revision(PendingRevision("theodolite", "AB-2026-0001"))
    view.ask_change_note.return_value = "customer address corrected"
    view.choose_save_path.return_value = str(tmp_path / "second.pdf")
    assert presenter.export_certificate(kind, result, {}, "run.csv", rows)
    assert "AB-2026-0001-A1 (amendment 1 of AB-2026-0001) issued" in \
        view.show_status.call_args.args[0]
    text = re.sub(r"\s+", " ", "".join(p.extract_text()
                                        for p in PdfReader(tmp_path / "second.pdf").pages))
    assert "Amendment 1 to certificate AB-2026-0001" in text
    assert "customer address corrected" in text
    assert presenter.pending is None
    with presenter.open_register() as register:
        assert register.get("AB-2026-0001").status == "superseded"


@pytest.mark.slow
@pytest.mark.usefixtures("pdf_stand_in")  # no PDF page read: the presenter's questions and records
def test_a_refusal_of_the_register_writes_nothing(parts, samples_dir, tmp_path):
    presenter, view, _, _ = parts
    kind, result = _theodolite(samples_dir)
    view.edit_certificate_details.return_value = COMPLETE
    view.choose_save_path.return_value = str(tmp_path / "a.pdf")
    assert presenter.export_certificate(kind, result, {}, "run.csv", [])
    typed = CertificateMetadata.from_dict({**COMPLETE.to_dict(),
                                           "certificate_number": "AB-2026-0001"})
    view.edit_certificate_details.return_value = typed
    view.choose_save_path.return_value = str(tmp_path / "b.pdf")
    assert not presenter.export_certificate(kind, result, {}, "run.csv", [])
    assert "AB-2026-0001 was issued on" in view.tell.call_args.args[1]
    assert not (tmp_path / "b.pdf").exists()


@pytest.mark.slow
def test_a_calibration_issued_again_asks_whether_it_is_separate(parts, samples_dir, tmp_path):
    """#61 assessor: the same item and date of calibration issued again made a second
    original. The window asks why it is a calibration of its own; cancelled, nothing is
    written and the register's words say how to correct the first instead."""
    presenter, view, _, _ = parts
    kind, result = _theodolite(samples_dir)
    view.edit_certificate_details.return_value = COMPLETE
    view.choose_save_path.return_value = str(tmp_path / "a.pdf")
    assert presenter.export_certificate(kind, result, {}, "run.csv", [])
    view.ask_separate_calibration.return_value = ""  # cancelled
    view.choose_save_path.return_value = str(tmp_path / "b.pdf")
    assert not presenter.export_certificate(kind, result, {}, "run.csv", [])
    numbers, reason = view.ask_separate_calibration.call_args.args
    assert numbers == ("AB-2026-0001",) and "serial T-1, calibrated 2026-11-20" in reason
    assert "AB-2026-0001 already reports this calibration" in view.tell.call_args.args[1]
    assert not (tmp_path / "b.pdf").exists()
    view.ask_separate_calibration.return_value = "as left after the adjustment"
    view.choose_save_path.return_value = str(tmp_path / "c.pdf")
    assert presenter.export_certificate(kind, result, {}, "run.csv", [])
    assert "Certificate AB-2026-0002 issued" in view.show_status.call_args.args[0]
    text = re.sub(r"\s+", " ", "".join(p.extract_text()
                                        for p in PdfReader(tmp_path / "c.pdf").pages))
    assert ("separate from certificate AB-2026-0001 of the same item and date of calibration, "
            "which stays valid: as left after the adjustment") in text
    # the question is asked before the file name, so before the wait cursor is on (rev62 F10)
    order = [c for c in view.mock_calls
             if c[0] in ("ask_separate_calibration", "choose_save_path", "wait_cursor")]
    assert [c[0] for c in order[-4:]] == ["ask_separate_calibration", "choose_save_path",
                                          "wait_cursor", "wait_cursor"]
    assert order[-2:] == [mock.call.wait_cursor(True), mock.call.wait_cursor(False)]


def test_cancelled_details_write_nothing(parts, samples_dir):
    presenter, view, metadata, modified = parts
    view.edit_certificate_details.return_value = None
    kind, result = _theodolite(samples_dir)
    assert not presenter.export_certificate(kind, result, {}, "run.csv")
    view.choose_save_path.assert_not_called()
    assert metadata == {} and not modified.called


def test_a_stored_detail_gone_bad_reaches_the_view_marked(parts):
    presenter, view, metadata, _ = parts
    metadata["certificates"] = {"polygon": {"lab_name": "Lab", "humidity_pct": "45 %"}}
    presenter.save_lab_defaults({"operator": "Wang"})
    meta = presenter.details("polygon")
    assert meta.lab_name == "Lab" and meta.operator == "Wang"
    view.edit_certificate_details.return_value = None
    presenter.edit_details(meta)
    _, problems, raw = view.edit_certificate_details.call_args.args
    assert "humidity_pct" in problems and raw["humidity_pct"] == "45 %"


def test_export_errors_are_told_not_raised(parts, samples_dir, tmp_path):
    presenter, view, _, _ = parts
    view.choose_save_path.return_value = str(tmp_path / "no" / "such" / "dir" / "r.csv")
    kind, result = _theodolite(samples_dir)
    assert not presenter.export_results(kind, result, {}, "run.csv")
    assert "Cannot export" in view.tell.call_args.args[0]


@pytest.mark.usefixtures("pdf_stand_in")  # no PDF page read: the presenter's questions and records
def test_a_draft_is_confirmed_first_and_details_carry_to_the_next_workbench(parts, samples_dir,
                                                                           tmp_path):
    presenter, view, metadata, _ = parts
    kind, result = _theodolite(samples_dir)
    typed = CertificateMetadata(certificate_number="AB/9", lab_name="Angle Lab",
                                customer_name="Acme", operator="Li")
    # "No, not a draft", then the dialog again (#31: "No" closed it), then Cancel
    view.edit_certificate_details.side_effect = [typed, None]
    view.confirm_draft.return_value = False
    assert not presenter.export_certificate(kind, result, {}, "run.csv")
    assert "reference standards" in view.confirm_draft.call_args.args[0]
    assert view.edit_certificate_details.call_count == 2
    assert view.edit_certificate_details.call_args.args[0] == typed  # the number kept too
    view.choose_save_path.assert_not_called()
    offered = presenter.details("polygon")  # nothing typed for the polygon yet
    assert (offered.lab_name, offered.customer_name, offered.operator) == \
        ("Angle Lab", "Acme", "Li")
    assert offered.item_serial == ""  # the item is the next workbench's own


@pytest.mark.slow
@pytest.mark.usefixtures("pdf_stand_in")  # no PDF page read: the presenter's questions and records
def test_an_unreachable_register_issues_nothing_and_says_so(parts, samples_dir, tmp_path,
                                                            monkeypatch):
    presenter, view, _, _ = parts
    monkeypatch.delenv("ANGLEBENCH_REGISTER")
    presenter.set_register_url("postgresql://lab@/register?host=/nonexistent-socket")
    kind, result = _theodolite(samples_dir)
    view.edit_certificate_details.return_value = COMPLETE
    view.choose_save_path.return_value = str(tmp_path / "c.pdf")
    assert not presenter.export_certificate(kind, result, {}, "run.csv", [])
    title, text = view.tell.call_args.args
    assert title == "Not issued" and "postgresql+psycopg://lab@/register" in text
    assert not (tmp_path / "c.pdf").exists()


def _polygon_with_errors_of_degrees(samples_dir):
    kind = KINDS["polygon"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    from models.readings.angles import format_dms, parse_angle_deg

    rows[2][1] = format_dms(parse_angle_deg(rows[2][1]) + 2.0, 2)  # face 3 two degrees off
    return kind, kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))


@pytest.mark.slow
@pytest.mark.usefixtures("pdf_stand_in")  # no PDF page read: the presenter's questions and records
def test_errors_no_encoder_has_are_certified_only_when_confirmed(parts, samples_dir, tmp_path):
    presenter, view, _, _ = parts
    kind, result = _polygon_with_errors_of_degrees(samples_dir)
    view.confirm_implausible.return_value = False
    assert not presenter.export_certificate(kind, result, {}, "poly.csv")
    assert "ERRORS OF 2.00°" in view.confirm_implausible.call_args.args[0]
    view.edit_certificate_details.assert_not_called()
    view.choose_save_path.assert_not_called()
    view.confirm_implausible.return_value = True
    view.edit_certificate_details.return_value = CertificateMetadata(lab_name="Lab")
    view.confirm_draft.return_value = True
    view.choose_save_path.return_value = str(tmp_path / "out.pdf")
    assert presenter.export_certificate(kind, result, {}, "poly.csv")
    assert (tmp_path / "out.pdf").exists()


@pytest.mark.usefixtures("pdf_stand_in")  # no PDF page read: the presenter's questions and records
def test_a_plausible_result_asks_nothing_more(parts, samples_dir, tmp_path):
    presenter, view, _, _ = parts
    kind = KINDS["polygon"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))
    view.edit_certificate_details.return_value = None
    assert not presenter.export_certificate(kind, result, {}, "poly.csv")
    view.confirm_implausible.assert_not_called()


def test_lab_default_standards_are_per_workbench(parts):
    """#41: one list of standards went into every workbench (the theodolite's 0.5" became
    100 % of a fringe budget)."""
    presenter, _, _, _ = parts
    theodolite_std = {"description": "Theodolite", "uncertainty": 0.5}
    presenter.details("theodolite")  # its certificate dialog open: Save as lab defaults
    presenter.save_lab_defaults({"lab_name": "Angle Lab", "standards": [theodolite_std]})
    assert [s.description for s in presenter.details("theodolite").standards] == ["Theodolite"]
    fringe = presenter.details("fringe")
    assert fringe.standards == () or list(fringe.standards) == []
    assert fringe.lab_name == "Angle Lab"  # the lab-wide fields still shared
    presenter.save_lab_defaults({"lab_name": "Angle Lab", "standards": [
        {"description": "Polygon", "uncertainty": 0.1}]}, "polygon")
    assert [s.description for s in presenter.details("polygon").standards] == ["Polygon"]
    assert [s.description for s in presenter.details("theodolite").standards] == ["Theodolite"]


@pytest.mark.usefixtures("pdf_stand_in")  # no PDF page read: the presenter's questions and records
def test_a_standard_of_another_quantity_is_refused_before_the_file_dialog(parts, samples_dir):
    presenter, view, _, _ = parts
    gauge = dataclasses.replace(COMPLETE, standards=CertificateMetadata.from_dict({"standards": [
        {"description": "Gauge block", "uncertainty": 0.2, "uncertainty_unit": "um"}]}).standards)
    view.edit_certificate_details.side_effect = [gauge, None]  # refused, then cancelled
    kind, result = _theodolite(samples_dir)
    assert not presenter.export_certificate(kind, result, {}, "run.csv")
    title, text = view.tell.call_args.args
    assert "Gauge block" in text and "another kind" in text
    assert view.edit_certificate_details.call_count == 2  # back to the details
    view.choose_save_path.assert_not_called()


@pytest.mark.usefixtures("pdf_stand_in")  # no PDF page read: the presenter's questions and records
def test_a_standard_as_large_as_the_tolerance_is_asked_about(parts, samples_dir):
    presenter, view, _, _ = parts
    tight = dataclasses.replace(COMPLETE, tolerance=0.4)  # the theodolite's 0.5" ≥ ±0.4"
    view.edit_certificate_details.side_effect = [tight, None]
    view.confirm_standards.return_value = False
    kind, result = _theodolite(samples_dir)
    assert not presenter.export_certificate(kind, result, {}, "run.csv")
    (warnings,), _ = view.confirm_standards.call_args
    assert "Theodolite" in warnings[0] and "±0.4\"" in warnings[0]
    view.choose_save_path.assert_not_called()


@pytest.mark.slow
@pytest.mark.parametrize("zone, day", [("Pacific/Kiritimati", "2026-12-02"),  # UTC+14
                                       ("Pacific/Pago_Pago", "2026-12-01")])  # UTC−11
def test_the_labs_time_zone_set_in_the_window_dates_the_issue(parts, samples_dir, tmp_path,
                                                             monkeypatch, zone, day):
    from models.register.store import Register, RegisterError

    presenter, view, _, _ = parts
    # the window's setting wins over the command line's variable
    monkeypatch.setenv("ANGLEBENCH_TIMEZONE", "Europe/Berlin")
    monkeypatch.setattr(Register, "clock", staticmethod(
        lambda: dt.datetime(2026, 12, 1, 12, 30, tzinfo=dt.timezone.utc)))
    with pytest.raises(RegisterError, match="Mars/Olympus"):
        presenter.set_lab_timezone("Mars/Olympus")
    assert presenter.lab_timezone() == ""  # a name not known is not stored
    presenter.set_lab_timezone(f" {zone} ")
    assert presenter.lab_timezone() == zone
    kind, result = _theodolite(samples_dir)
    view.edit_certificate_details.return_value = COMPLETE
    view.choose_save_path.return_value = str(tmp_path / "dated.pdf")
    assert presenter.export_certificate(kind, result, {}, "run.csv", [])
    with presenter.open_register() as register:
        (record,) = register.list()
    assert record.issue_date == day
    text = " ".join(p.extract_text() for p in PdfReader(tmp_path / "dated.pdf").pages)
    assert day in text


def test_signal_presets_saved_with_the_lab_defaults_and_kept(parts):
    """#45: the lab's signal tolerance presets live in the lab defaults; saving the
    certificate's lab fields keeps them."""
    from app.certificate_presenter import SIGNAL_PRESETS
    from models.fringe.signal_tolerance import (
        BUILTIN_PRESETS,
        LAB_DEFAULTS_KEY,
        Band,
        TolerancePreset,
        lab_defaults_with_presets,
        load_presets,
        preset_by_key,
    )

    assert SIGNAL_PRESETS == LAB_DEFAULTS_KEY
    presenter = parts[0]
    ours = TolerancePreset("ours", "our band", "1Vpp",
                           (Band("amplitude_a", "Vpp", (0.9, 1.1), (0.6, 1.2)),), "lab rule")
    presenter.save_lab_defaults_entry(LAB_DEFAULTS_KEY, lab_defaults_with_presets(
        presenter.lab_defaults(), [*BUILTIN_PRESETS, ours])[LAB_DEFAULTS_KEY])
    presenter.save_lab_defaults({"lab_name": "Lab"})
    presets, problems = load_presets(presenter.lab_defaults())
    assert problems == [] and preset_by_key("ours", presets) == ours
    assert presenter.lab_defaults()["lab_name"] == "Lab"
    assert len(presets) == len(BUILTIN_PRESETS) + 1


@pytest.mark.usefixtures("pdf_stand_in")  # no PDF page read: the presenter's questions and records
def test_an_issue_far_after_the_last_record_shows_the_date_and_asks(parts, samples_dir,
                                                                    tmp_path, monkeypatch):
    """reg73 #6: a yearly lab's issue was refused and the window had no way to give the
    allowance; now the window shows the date the clock gives and asks, and a Yes is
    recorded with the certificate."""
    from models.register.store import Register

    presenter, view, _, _ = parts
    presenter.set_lab_timezone("UTC")
    first = dt.datetime(2026, 11, 24, 10, 0, tzinfo=dt.timezone.utc)
    monkeypatch.setattr(Register, "clock", staticmethod(lambda: first))
    kind, result = _theodolite(samples_dir)
    view.edit_certificate_details.return_value = COMPLETE
    view.choose_save_path.return_value = str(tmp_path / "a.pdf")
    assert presenter.export_certificate(kind, result, {}, "run.csv", [])
    view.confirm_issue_date.assert_not_called()
    monkeypatch.setattr(Register, "clock", staticmethod(
        lambda: first + dt.timedelta(days=367)))
    # a year later: the item's next calibration
    view.edit_certificate_details.return_value = dataclasses.replace(
        COMPLETE, calibration_date="2027-11-20", issue_date="")
    view.confirm_issue_date.return_value = False  # not today: nothing issued
    view.choose_save_path.return_value = str(tmp_path / "b.pdf")
    assert not presenter.export_certificate(kind, result, {}, "run.csv", [])
    assert view.confirm_issue_date.call_args, view.tell.call_args
    date, reason = view.confirm_issue_date.call_args.args
    assert date == "2027-11-26" and "367 days after" in reason
    assert not (tmp_path / "b.pdf").exists()
    view.confirm_issue_date.return_value = True
    view.choose_save_path.return_value = str(tmp_path / "c.pdf")
    assert presenter.export_certificate(kind, result, {}, "run.csv", [])
    with presenter.open_register() as register:
        newest = register.list()[0]
        assert newest.issue_date == "2027-11-26" and register.problems == []
