"""The window's theodolite summary prints each ISO 230-2 figure to the decimal its
certificate prints it to, once the certificate's details are known (day review 69, finding
6: two passes, "E_up 1.70″ … M 1.55″" in the window beside "1.7″ … 1.5″" on the
certificate, the window's decimals those of the narrower intervals from the readings
alone). Checked against a printed certificate (pdftotext); the record is simulated by
tests/repeatability_rig.py (first principles)."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from tests.repeatability_rig import theodolite_passes_csv

pytestmark = pytest.mark.slow  # a theodolite certificate

SAMPLES = Path(__file__).resolve().parents[2] / "resources" / "samples"


def _decimals(text: str) -> int:
    return len(text.split(".")[1]) if "." in text else 0


def test_the_windows_figures_have_the_certificates_decimals(tmp_path, capsys):
    from app.main import main
    from models.certificate.metadata import CertificateMetadata
    from models.readings.sheet import ReadingsSheet
    from models.theodolite.analysis import THEODOLITE
    from widgets.workbench_presenter import shown_as_printed

    if shutil.which("pdftotext") is None:
        pytest.fail("pdftotext is missing: apt-get install poppler-utils (.ci/run does)")
    text, _ = theodolite_passes_csv("varying", 13, 2, 0.3, np.random.default_rng(6912))
    csv = tmp_path / "passes2.csv"
    csv.write_text(text, encoding="utf-8")
    data = json.loads((SAMPLES / "certificate_theodolite.json").read_text("utf-8"))
    data.pop("certificate_number", None)
    data["language"] = "en"
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps(data), encoding="utf-8")
    pdf = tmp_path / "c.pdf"
    assert main(["analyze", "theodolite", str(csv), "--metadata", str(meta),
                 "--certificate", str(pdf)]) == 0, capsys.readouterr().err
    printed = re.sub(r"\s+", " ", subprocess.run(
        ["pdftotext", "-enc", "UTF-8", str(pdf), "-"], capture_output=True, text=True,
        encoding="utf-8", check=True).stdout)
    on_certificate = dict(re.findall(r"ISO 230-2 (\w+) (-?[\d.]+)\"", printed))
    assert len(on_certificate) >= 6, printed

    lines = [line.split(",") for line in text.splitlines()]
    settings = THEODOLITE.settings_with_defaults({})
    result = THEODOLITE.analyze(ReadingsSheet(THEODOLITE.columns, [
        row + [""] * (len(THEODOLITE.columns) - len(row)) for row in lines[1:]]).parse(),
        settings)
    shown = shown_as_printed(THEODOLITE, result, CertificateMetadata.from_dict(data), settings)
    summary = str(shown.summary)
    iso = next(line for line in summary.splitlines() if line.startswith("ISO 230-2:"))
    in_window = dict(re.findall(r"(\w+) = (-?[\d.]+)\"", iso))
    differ = {key: (in_window[key], value) for key, value in on_certificate.items()
              if key in in_window and _decimals(in_window[key]) != _decimals(value)}
    assert not differ, (differ, iso)
    assert set(on_certificate) <= set(in_window), (on_certificate, iso)
