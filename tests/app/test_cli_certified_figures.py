"""The JSON states what the certificate prints (issue 39): positioning's figure intervals with
the reference standard's U, and a decided quantity whose measured value is a number whenever a
tolerance is set — its interval null, with the reason, where no honest U exists."""

from __future__ import annotations

import json

import numpy as np
import pytest

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.polygon.analysis import POLYGON
from models.positioning.analysis import POSITIONING
from models.positioning.report import figure_uncertainties, positioning_budget
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.validation.polygon_rig import PolygonRig, write_csv

pytestmark = pytest.mark.slow  # the command line on a sample (seconds each)


def _json(capsys, args) -> dict:
    code = main(["analyze", *args, "--json"])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    return json.loads(captured.out)


def test_positioning_json_figures_are_the_certificates(capsys, samples_dir):
    """With the sample's reference standard (U = 1″) the JSON's figure intervals are the ones
    the certificate prints, and wider than without it (the standard's U is in them)."""
    details = samples_dir / "certificate_positioning.json"
    sample = samples_dir / "positioning_sample.csv"
    with_standard = _json(capsys, ["positioning", str(sample), "--metadata", str(details)])
    without = _json(capsys, ["positioning", str(sample)])
    metadata = CertificateMetadata.from_dict(json.loads(details.read_text(encoding="utf-8")))
    rows = map_columns(read_table(sample), POSITIONING.columns)
    result = POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, rows).parse(),
                                 POSITIONING.settings_with_defaults({}))
    budget = positioning_budget(result, metadata)
    intervals = figure_uncertainties(result, budget)
    document = POSITIONING.certificate(result, metadata)
    printed = {str(row[0]): row[2] for row in document.statistics.rows
               if len(row) == 5}
    widened = 0
    for group in ("iso230_2_figures", "vdi3441_figures"):
        for key, figure in with_standard[group].items():
            if key not in intervals:
                continue
            iv = intervals[key]
            assert figure["interval_low"] == pytest.approx(iv.low, abs=1e-12), key
            assert figure["interval_high"] == pytest.approx(iv.high, abs=1e-12), key
            assert figure["coverage_probability"] == pytest.approx(iv.probability), key
            # the certificate's cell shows the same two numbers
            cell = next(text for name, text in printed.items() if str(name).startswith(key + ":")
                        or str(name).endswith(" " + key))
            low, high = (float(part.strip().rstrip("″\"")) for part in str(cell).split("…"))
            first = str(cell).split("…")[0].strip().rstrip("″\"")
            # the ends' decimal (none where the half-width is ≥ 10: R's, 0.8.16)
            digits = 10.0 ** -(len(first.split(".")[1]) if "." in first else 0)
            assert low == pytest.approx(iv.low, abs=digits) and high == pytest.approx(
                iv.high, abs=digits), key
            plain = without[group][key]
            widened += (figure["interval_high"] - figure["interval_low"]
                        > plain["interval_high"] - plain["interval_low"] + 1e-9)
    assert widened >= 5  # the standard's U widens the figures of the means (E, M, A …)
    assert with_standard["coverage_probability"] == pytest.approx(budget.probability)


def _polygon_json(capsys, tmp_path, rows, settings=()) -> dict:
    path = tmp_path / "polygon.csv"
    write_csv(path, rows)
    return _json(capsys, ["polygon", str(path), "--grade", "3", *settings])


def flat_vertical_rows(faces: int, seed: int):
    """A polygon tilted 300″ on the shaft read by the exact 3-D rig, its vertical column then
    copied down (all equal, not read); and the true encoder error."""
    th = np.radians(np.arange(faces) * 360.0 / faces)
    rng = np.random.default_rng(seed)
    error = rng.uniform(0.1, 0.4) * np.cos(th + rng.uniform(0, 6.3)) + 0.05 * np.sin(2 * th)
    rig = PolygonRig(faces, error, psi_arcsec=300.0, omega_deg=40.0, noise_arcsec=0.03,
                     rng=rng)
    rows = [[*r[:4], "12.5", *r[5:]] for r in rig.set_rows()]
    return rows, rig.truth_arcsec()


def test_decided_value_is_a_number_when_u_is_withheld(capsys, tmp_path):
    """Every vertical reading equal, no σ of a reading stated: the tilt is not identified and
    the reading noise has no degrees of freedom — no interval (never the noise taken as 0),
    but the measured half range is stated; with σ stated the tilt bound is in U and the
    interval is given."""
    rows, truth = flat_vertical_rows(12, seed=7)
    sheet = ReadingsSheet(POLYGON.columns, rows).parse()
    result = POLYGON.analyze(sheet, {"grade": 3})
    decided = _polygon_json(capsys, tmp_path, rows)["decided_quantity"]
    assert decided["value"] == pytest.approx(0.5 * np.ptp(result.mean_corrected_arcsec))
    assert decided["interval_low"] is None and decided["interval_high"] is None
    assert decided["verdict"] is None and "degrees of freedom" in decided["reason"]
    assert decided["coverage_probability"] is None  # no interval, no probability of one
    assert decided["tolerance"] > 0
    stated = _polygon_json(capsys, tmp_path, rows, ("--reading-noise-arcsec", "0.03"))
    decided = stated["decided_quantity"]
    for key in ("value", "interval_low", "interval_high"):
        assert isinstance(decided[key], float), key
    assert decided["interval_low"] <= 0.5 * np.ptp(truth) <= decided["interval_high"]
