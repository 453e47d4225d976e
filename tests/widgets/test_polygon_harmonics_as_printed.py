"""Leftovers 79, item 4: the polygon window's summary printed the 1st and 2nd harmonics'
amplitudes to 0.001″ ("0.362″ / 0.157″") where the certificate made with the same details
rounds them to the place of its largest U (GUM 7.2.6; assessment 78 L6): the window shows
them as the certificate prints them."""

from __future__ import annotations

import re

from models.certificate.metadata import CertificateMetadata
from models.polygon.report import polygon_certificate


def _harmonics(text: str) -> tuple[str, str]:
    found = re.search(r"Harmonics: 1st \(eccentricity\) ([\d.]+)\", 2nd \(ellipticity\) "
                      r"([\d.]+)\"", text)
    assert found, text
    return found.group(1), found.group(2)


def test_the_window_prints_the_harmonics_as_the_certificate(window, qtbot):
    presenter = window.presenter("polygon")
    presenter.load_sample()
    qtbot.waitUntil(lambda: presenter.result is not None and not presenter.analysis_pending,
                    timeout=60000)
    details = presenter.certificate_details()
    document = polygon_certificate(presenter.result, details if details is not None else
                                   CertificateMetadata(), settings=presenter.result_settings)
    row = next(r for r in document.statistics.rows if str(r[0]) == "Harmonics 1st / 2nd")
    first, second = str(row[1]).replace('"', "").split(" / ")
    shown = _harmonics(presenter.view.summary.toPlainText())
    assert shown == (first, second), (shown, row)
    assert shown == ("0.36", "0.16")  # beside the sample's U 0.34″ (0.01″)


def test_the_command_line_prints_the_harmonics_to_the_corrected_errors_place(capsys,
                                                                            samples_dir):
    """Without certificate details the summary printed them to 0.001″ beside corrected errors
    printed to 0.01″ (leftovers 80): the amplitudes, fitted to those errors, to their place."""
    from app.main import main

    assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv")]) == 0
    out = capsys.readouterr().out
    errors = re.search(r"Corrected error (-?\d+\.(\d+))\"", out)
    assert errors and len(errors.group(2)) == 2, out
    assert _harmonics(out) == ("0.36", "0.16")
