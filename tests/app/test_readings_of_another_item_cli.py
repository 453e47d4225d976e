"""hostile78 F7 through the command line and the window's presenter: the bundled sample's 41
readings issued for LRA-0815, then for LRA-0900 as a file of its columns re-ordered and its
angles re-typed in decimal degrees — refused, naming the certificate, its item and date,
unless --readings-of-another-item N:REASON says why, which the certificate prints and
`register show` lists; the window asks why before it asks for a file name."""

from __future__ import annotations

import csv
import json
import re

import pytest
from pypdf import PdfReader

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.readings.angles import parse_angle_deg
from models.register.location import register_url
from models.register.store import Register
from tests.app.test_certificate_presenter import theodolite_sample_analysed, window_presenter


def _retyped(samples_dir, path) -> None:
    """The sample's readings re-typed: elevation before azimuth, the angles in decimal
    degrees, the rows upside down — the same values."""
    with open(samples_dir / "theodolite_sample.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    with open(path, "w", newline="", encoding="utf-8") as handle:
        out = csv.writer(handle)
        out.writerow(["elevation_deg", "theta_deg", "azimuth_deg"])
        for row in rows[::-1]:
            out.writerow([f"{parse_angle_deg(row['elevation_deg']):.12f}"
                          if row["elevation_deg"].strip() else "", row["theta_deg"],
                          f"{parse_angle_deg(row['azimuth_deg']):.12f}"])


def _pdf_text(path) -> str:
    return re.sub(r"\s+", " ", "".join(p.extract_text() for p in PdfReader(path).pages))


@pytest.mark.slow
def test_another_items_readings_are_refused_then_issued_saying_why(samples_dir, tmp_path,
                                                                   capsys):
    meta = json.loads((samples_dir / "certificate_theodolite.json").read_text(encoding="utf-8"))
    retyped = tmp_path / "lra0900.csv"
    _retyped(samples_dir, retyped)

    def analyze(name, serial, readings, *extra):
        (tmp_path / f"{name}.json").write_text(json.dumps(
            {**meta, "example": False, "certificate_number": "", "item_serial": serial}),
            encoding="utf-8")
        code = main(["analyze", "theodolite", str(readings), "--certificate",
                     str(tmp_path / f"{name}.pdf"), "--metadata", str(tmp_path / f"{name}.json"),
                     *extra])
        return code, capsys.readouterr().err

    code, err = analyze("a", "LRA-0815", samples_dir / "theodolite_sample.csv")
    assert code == 0, err
    with Register(register_url()) as register:
        [first] = register.list()
    code, err = analyze("b", "LRA-0900", retyped)
    assert code == 2 and err.startswith(
        f"anglebench analyze: the readings are those of {first.number} (item LRA-0815, "
        f"{first.item_manufacturer}, calibrated {first.calibration_date}), another item than "
        "LRA-0900"), err
    assert f"--readings-of-another-item {first.number}:REASON" in err
    assert not (tmp_path / "b.pdf").exists()
    code, err = analyze("b", "LRA-0900", retyped, "--readings-of-another-item",
                        f"{first.number}:the pair was read once, coupled")
    assert code == 0, err
    statement = (f"The readings are those of certificate {first.number} (item LRA-0815, "
                 f"{first.item_manufacturer}, calibrated {first.calibration_date}): the pair "
                 "was read once, coupled")
    assert statement in _pdf_text(tmp_path / "b.pdf")
    with Register(register_url()) as register:
        second = next(r for r in register.list() if r.number != first.number)
        assert register.audit() == []
    assert main(["register", "show", second.number]) == 0
    shown = capsys.readouterr().out
    assert re.search(r"readings of another item, as .* said at issue \(.*\): those of "
                     rf"{first.number} \(LRA-0815, .*\): the pair was read once, coupled", shown)


@pytest.mark.slow
def test_the_window_asks_why_before_the_file_name(samples_dir, tmp_path):
    view, presenter = window_presenter()
    kind, rows, result = theodolite_sample_analysed(samples_dir)
    details = json.loads((samples_dir / "certificate_theodolite.json").read_text(
        encoding="utf-8"))

    def export(serial: str, path: str) -> bool:
        view.edit_certificate_details.return_value = CertificateMetadata.from_dict(
            {**details, "example": False, "certificate_number": "", "item_serial": serial})
        view.choose_save_path.return_value = str(tmp_path / path)
        return presenter.export_certificate(kind, result, {}, "run.csv", rows)

    assert export("LRA-0815", "a.pdf")
    view.ask_readings_of_another_item.assert_not_called()
    view.choose_save_path.reset_mock()
    view.ask_readings_of_another_item.return_value = ""  # cancelled: nothing, no file asked
    assert not export("LRA-0900", "b.pdf")
    numbers, reason = view.ask_readings_of_another_item.call_args.args
    with Register(register_url()) as register:
        [first] = register.list()
    assert numbers == (first.number,) and "(item LRA-0815" in reason
    assert "--readings-of-another-item" not in reason  # the window's question, not the CLI's
    view.choose_save_path.assert_not_called()
    assert "the readings are those of" in view.tell.call_args.args[1]
    view.ask_readings_of_another_item.return_value = "the pair was read once, coupled"
    assert export("LRA-0900", "c.pdf")
    with Register(register_url()) as register:
        [said] = register.readings_of_another_item_confirmations()
    assert said["reason"] == "the pair was read once, coupled"


@pytest.mark.slow
def test_the_window_asks_for_readings_retyped_in_the_unit_its_settings_give(samples_dir,
                                                                            tmp_path):
    """ident80: the window's question before the file name compares the readings with the
    workbench's settings (the units and origins of its columns): the sample's elevations
    typed as zenith angles V, with the setting that says so, are asked about as the issue
    would refuse them, before any file is chosen."""
    view, presenter = window_presenter()
    kind, rows, result = theodolite_sample_analysed(samples_dir)
    details = json.loads((samples_dir / "certificate_theodolite.json").read_text(
        encoding="utf-8"))
    zenith = [[r[0], r[1], f"{parse_angle_deg(r[2]) + 90:.8f}"] for r in rows]

    def export(serial: str, path: str, readings, settings) -> bool:
        view.edit_certificate_details.return_value = CertificateMetadata.from_dict(
            {**details, "example": False, "certificate_number": "", "item_serial": serial})
        view.choose_save_path.return_value = str(tmp_path / path)
        return presenter.export_certificate(kind, result, settings, "run.csv", readings)

    assert export("LRA-0815", "a.pdf", rows, {})
    view.choose_save_path.reset_mock()
    view.ask_readings_of_another_item.return_value = ""  # cancelled: nothing, no file asked
    assert not export("LRA-0900", "b.pdf", zenith, {"vertical_reading": "zenith"})
    with Register(register_url()) as register:
        [first] = register.list()
    numbers, _reason = view.ask_readings_of_another_item.call_args.args
    assert numbers == (first.number,)
    view.choose_save_path.assert_not_called()
