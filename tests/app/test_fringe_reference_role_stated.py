"""Assessment 78 H1: the fringe's angle reference listed with its certificate and a U but no
role, beside the ADC (role adc), was taken as the phase or angle reference: the PDF titled
"Calibration certificate", "traceable to the SI … through the reference standards listed",
and "pass" against ±0.6″ in the JSON, the PDF and the DCC. A standard with a U and no role
may be any instrument's certificate (the sample's ADC listed without its role is one), so
nothing in the details made it the phase reference (nor one listed with no U behind the
settings' phase reference u, where the settings state the ADC's figures too: which of the two
standards is which, the details do not say). It is now a test report with no
statement of conformity, whose traceability statement names the phase or angle reference as
not listed and the role to state; with the role "reference" stated, the same readings give a
traceable calibration certificate and its verdict."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from app.main import main
from tests.pdf_text import pdf_text

pytestmark = pytest.mark.slow  # certificates are rendered

SAMPLES = Path(__file__).resolve().parents[2] / "resources" / "samples"
#: every ADC figure stated in the settings; the phase reference is the listed standard's
ADC_FIGURES = ["--adc-lsb-mv", "0.3", "--adc-offset-u-mv", "0.5", "--adc-gain-u-pct", "0.05",
               "--adc-linearity-mv", "0.5"]
REFERENCE = {"description": "Angle reference (rotary table with encoder)", "serial": "RT-9",
             "certificate_no": "NIM-2026-0555", "uncertainty": 0.02, "uncertainty_unit": "arcsec",
             "basis": "U95"}
ADC = {"description": "Data acquisition (16-bit ADC)", "serial": "DAQ-5",
       "certificate_no": "CAL-2026-33", "uncertainty": 0.05, "uncertainty_unit": "arcsec",
       "basis": "U95", "role": "adc"}


def _issue(tmp_path: Path, capsys, reference: dict) -> tuple[dict, str, str]:
    """The JSON, the PDF's text and the DCC of the fringe sample with ``reference`` and the
    ADC listed, ±0.6″ under the guarded rule (the sample's details, issued)."""
    details = json.loads((SAMPLES / "certificate_fringe.json").read_text("utf-8"))
    del details["example"], details["certificate_number"]  # a lab's real details
    details.update(tolerance=0.6, decision_rule="guarded", standards=[reference, ADC])
    meta = tmp_path / f"meta_{reference.get('role', 'none')}.json"
    meta.write_text(json.dumps(details), encoding="utf-8")
    pdf, dcc = tmp_path / f"{meta.stem}.pdf", tmp_path / f"{meta.stem}.xml"
    code = main(["analyze", "fringe", str(SAMPLES / "fringe_sample.csv"), "--json",
                 *ADC_FIGURES, "--metadata", str(meta), "--certificate", str(pdf),
                 "--dcc", str(dcc)])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    return json.loads(captured.out), pdf_text(pdf.read_bytes()), dcc.read_text("utf-8")


def test_a_standard_of_no_role_is_not_the_phase_reference(tmp_path, capsys):
    out, text, dcc = _issue(tmp_path, capsys, REFERENCE)
    decided = out["decided_quantity"]
    assert decided["verdict"] is None and decided["probability_conforming"] is None
    said = ("none is listed for a phase or angle reference, as no role is stated for Angle "
            "reference (rotary table with encoder) and only a standard whose role says so is "
            "taken as a phase or angle reference")
    assert said in decided["reason"], decided["reason"]
    assert 'state the role "reference" of the one that is' in decided["reason"]
    assert text.startswith("Test report") or "Calibration certificate" not in text[:300]
    assert "Metrological traceability: not established for these results" in text
    assert said in text and 'state the role "reference"' in text
    assert "traceable to the SI unit of plane angle through the reference standards" not in text
    assert "conforms to the specification" not in text
    assert "<dcc:conformity>" not in dcc and said in dcc


def test_the_role_stated_makes_it_the_phase_reference(tmp_path, capsys):
    out, text, dcc = _issue(tmp_path, capsys, {**REFERENCE, "role": "reference"})
    decided = out["decided_quantity"]
    assert decided["verdict"] == "pass", decided
    assert "Calibration certificate" in text[:300] and "Test report" not in text[:300]
    assert "traceable to the SI unit of plane angle through the reference standards" in text
    assert "The item conforms to the specification ±0.6\" (pass)." in text
    assert "<dcc:conformity>pass</dcc:conformity>" in dcc
