"""A withheld interval quoted in its reason says whose it is (day 68, finding 7): the window's
and the command line's summary quote the readings' own interval, without the reference
standards' U ("16″ … 487″"), the certificate one with it ("14″ … 974″"); the summary's reason
now says so, as its "Coverage intervals" line does, and the certificate's does not. The
readings are simulated here from first principles (positioning: this file's generator;
theodolite: tests/repeatability_rig.py)."""

from __future__ import annotations

import re

import numpy as np

from app.main import main
from tests.repeatability_rig import theodolite_passes_csv

READINGS_OWN = "the interval from the readings without the reference standards' U would be"


def _two_runs_csv(tmp_path, targets: int = 9, noise: float = 0.8):
    """Two runs of an ISO 230-2 test of a rotary axis: x = f(P) ± b/2 + σ z."""
    rng = np.random.default_rng(6807)
    angles = np.linspace(0.0, 360.0, targets, endpoint=False)
    f = 4.0 * np.sin(np.radians(angles))
    lines = ["target,run,direction,deviation"]
    for run in (1, 2):
        for sign, b, order in (("+", 1.0, range(targets)), ("-", -1.0, range(targets - 1, -1, -1))):
            lines += [f"{angles[i]:.6f},{run},{sign},{f[i] + b + noise * rng.standard_normal():.3f}"
                      for i in order]
    csv = tmp_path / "two_runs.csv"
    csv.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return csv


def _reasons(text: str) -> dict[str, str]:
    return dict(re.findall(r"No coverage interval is given for (\w+): (.*?)\.(?:\n|$)", text))


def test_positioning_summary_says_its_withheld_interval_is_the_readings_own(tmp_path, capsys):
    from models.certificate.metadata import CertificateMetadata, ReferenceStandard
    from models.positioning.analysis import POSITIONING

    csv = _two_runs_csv(tmp_path)
    assert main(["analyze", "positioning", str(csv), "--language", "en"]) == 0
    window = _reasons(capsys.readouterr().out)
    assert {"A", "P", "R"} <= set(window)
    assert all(READINGS_OWN in reason and "a certificate's includes it" in reason
               for reason in window.values()), window
    # the certificate's reasons quote its own interval (with the standard's U), said plainly
    from models.readings.sheet import ReadingsSheet

    rows = [line.split(",") + [""] for line in csv.read_text().splitlines()[1:]]
    settings = POSITIONING.settings_with_defaults({})
    result = POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, rows).parse(), settings)
    standard = ReferenceStandard(description="Laser", uncertainty=1.0, uncertainty_unit="arcsec",
                                 basis="U95", applies_to="angle")
    document = POSITIONING.certificate(result, CertificateMetadata(
        tolerance=15.0, tolerance_unit="arcsec", standards=[standard]))
    printed = _reasons("\n".join(str(s) for s in document.statements))
    assert set(printed) == set(window)
    assert all("the interval would be" in r and "reference standards' U" not in r
               for r in printed.values()), printed


def test_theodolite_summary_says_its_withheld_interval_is_the_readings_own(tmp_path, capsys):
    text, _ = theodolite_passes_csv("varying", 13, 2, 0.3, np.random.default_rng(6804))
    csv = tmp_path / "passes2.csv"
    csv.write_text(text, encoding="utf-8")
    assert main(["analyze", "theodolite", str(csv), "--language", "en"]) == 0
    window = _reasons(capsys.readouterr().out)
    assert {"R", "R_up"} <= set(window)
    assert all("the interval from the readings alone would be" in r and
               "a certificate adds its stated standards' u" in r for r in window.values()), window
