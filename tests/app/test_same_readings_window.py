"""The window's question for a calibration of its own whose readings (each within the last
digit it was typed to) and details are those of a current certificate of its item and date
(register79): asked why after the separate calibration's reason; cancelled, nothing is
issued; answered, it is issued saying so and the answer is recorded."""

from __future__ import annotations

import json

import pytest

from models.certificate.metadata import CertificateMetadata
from models.register.location import register_url
from models.register.store import Register
from tests.app.test_certificate_presenter import theodolite_sample_analysed, window_presenter


@pytest.mark.slow
def test_the_window_asks_why_the_same_readings_are_a_calibration_of_its_own(samples_dir,
                                                                           tmp_path):
    view, presenter = window_presenter()
    kind, rows, result = theodolite_sample_analysed(samples_dir)
    details = json.loads((samples_dir / "certificate_theodolite.json").read_text(
        encoding="utf-8"))
    view.edit_certificate_details.return_value = CertificateMetadata.from_dict(
        {**details, "example": False, "certificate_number": ""})

    def export(path: str) -> bool:
        view.choose_save_path.return_value = str(tmp_path / path)
        return presenter.export_certificate(kind, result, {}, "run.csv", rows)

    assert export("a.pdf")
    with Register(register_url()) as register:
        [first] = register.list()
    view.ask_separate_calibration.return_value = "as left"
    view.ask_same_readings.return_value = ""  # cancelled: nothing issued
    assert not export("b.pdf")
    numbers, reason = view.ask_same_readings.call_args.args
    assert numbers == (first.number,) and "typed to, and so are its details" in reason
    assert "--same-readings-as" not in reason  # the window's question, not the CLI's
    assert not (tmp_path / "b.pdf").exists()
    view.ask_same_readings.return_value = "a second certificate of the  run, asked for"
    assert export("c.pdf")
    with Register(register_url()) as register:
        [said] = register.same_readings_confirmations()
        second = register.get(said["number"])
    assert said["reason"] == "a second certificate of the run, asked for"
    assert second.change_note == (f"as left; The readings are the same as those of "
                                  f"{first.number}, each within the last digit it was typed "
                                  "to, and so are the details: a second certificate of "
                                  "the run, asked for")
