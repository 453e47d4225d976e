"""Audit 73 finding 3: where the readings do not identify the tilt and no bound was typed,
the certificate printed the program's default bound (300″) as "(stated)", the laboratory's
figure. It is said to be the program's default (no bound stated) in the budget, the set-up
table and the decision; and a decision widened by a bound says that the readings cannot
check it. The JSON tells the bound and whose it is (the polygon's gave no bound).

The readings are the rigs of tests/app/test_tilt_bound_zero_refused.py (their own 3-D
simulation, nothing from models/)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from lxml import etree

from tests.app.test_table_u_one_rounding import _main
from tests.app.test_tilt_bound_zero_refused import SIGMA, _polygon_rows, _theodolite_rows

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = ROOT / "resources" / "samples"


def _theodolite_file(tmp_path: Path) -> Path:
    path = tmp_path / "theodolite.csv"
    path.write_text("theta_deg,azimuth_deg,elevation_deg\n" + "".join(_theodolite_rows(0.1)),
                    encoding="utf-8")
    return path


@pytest.mark.parametrize("bound", [None, "120"])
@pytest.mark.usefixtures("pdf_stand_in")  # the DCC read, not the PDF
def test_the_theodolite_says_whose_bound_it_is(tmp_path, monkeypatch, bound):
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(tmp_path / "register.sqlite"))
    readings = _theodolite_file(tmp_path)
    typed = [] if bound is None else ["--tilt-bound-arcsec", bound]
    options = ["--accuracy-arcsec", str(SIGMA), "--language", "en", *typed]
    out = json.loads(_main(["analyze", "theodolite", str(readings), "--json", *options]))
    assert out["tilt_identified"] is False
    assert out["tilt_bound_arcsec"] == (300.0 if bound is None else 120.0)
    assert out["tilt_bound_origin"] == ("program default" if bound is None else "stated")
    details = json.loads((SAMPLES / "certificate_theodolite.json").read_text("utf-8"))
    details.update(example=False, item_serial=f"A73-{bound}", tolerance="60",
                   tolerance_unit="arcsec", decision_rule="simple",
                   decision_quantity="half_range")
    meta = tmp_path / "details.json"
    meta.write_text(json.dumps(details), "utf-8")
    _main(["analyze", "theodolite", str(readings), "--metadata", str(meta), *options,
           "--certificate", str(tmp_path / "c.pdf"), "--dcc", str(tmp_path / "c.xml")])
    dcc = " ".join("".join(etree.fromstring((tmp_path / "c.xml").read_bytes()).itertext())
                   .split())
    if bound is None:
        assert '300" (stated)' not in dcc
        assert "up to 300\" (the program's default: no bound was stated)" in dcc
        assert "bound 300\" (the program's default) in U" in dcc
    else:
        assert "up to 120\" (stated)" in dcc and "program's default" not in dcc
    # the decision widened by the bound says the readings cannot check it
    assert "cannot check the bound (a larger tilt is not covered)" in dcc


@pytest.mark.parametrize("bound", [None, "120"])
def test_the_polygon_json_gives_its_bound(tmp_path, bound):
    path = tmp_path / "polygon.csv"
    path.write_text("position,encoder_deg,polygon_dev_arcsec,ac_x_arcsec,ac_y_arcsec,set,"
                    "direction\n" + "".join(_polygon_rows()), encoding="utf-8")
    typed = [] if bound is None else ["--tilt-bound-arcsec", bound]
    out = json.loads(_main(["analyze", "polygon", str(path), "--json", "--language", "en",
                            *typed]))
    assert out["tilt_not_identified"]
    assert out["tilt_bound_arcsec"] == (300.0 if bound is None else 120.0)
    assert out["tilt_bound_origin"] == ("program default" if bound is None else "stated")
