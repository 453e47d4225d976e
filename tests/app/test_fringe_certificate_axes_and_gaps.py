"""Two things a fringe certificate printed wrongly (day review 69, finding 6), checked on a
printed certificate (pdftotext): the plots over the record ("Fit residuals", the
interpolation error) ran their x axis to 80 periods for 64 periods of data; and with no
standard that carries the measurand listed, the test report's reason said "…; 0 listed so"
(a list of none printed as a count).

The record is simulated from first principles (tests/fringe_channels.py), nothing from
models/."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from tests.fringe_channels import Channels, equal_steps

pytestmark = pytest.mark.slow  # a fringe certificate

SAMPLES = Path(__file__).resolve().parents[2] / "resources" / "samples"
HEAD = Channels(offsets_v=(0.003, -0.004), amplitudes_v=(0.5, 0.49), quadrature_deg=0.5,
                sin_harmonics={3: (0.005, 0.4)}, cos_harmonics={3: (0.003, -0.3)},
                noise_v=0.0003)
PERIODS, N = 64, 16
X_TITLE = "electrical phase θ (periods)"


def test_the_plots_end_near_the_data_and_no_list_of_none_is_counted(tmp_path, capsys):
    from app.main import main

    if shutil.which("pdftotext") is None:
        pytest.fail("pdftotext is missing: apt-get install poppler-utils (.ci/run does)")
    u_sin, u_cos = HEAD.sample(equal_steps(PERIODS * N, N), np.random.default_rng(6908))
    csv = tmp_path / "n16.csv"
    csv.write_text("u_sin,u_cos\n" + "".join(f"{s:.9f},{c:.9f}\n"
                                             for s, c in zip(u_sin, u_cos, strict=True)))
    data = json.loads((SAMPLES / "certificate_fringe.json").read_text("utf-8"))
    data.pop("certificate_number", None)
    data["language"] = "en"
    # no standard with a stated uncertainty: none carries the measurand
    data["standards"] = [{k: v for k, v in std.items() if k != "uncertainty"}
                         for std in data.get("standards", [])]
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps(data), encoding="utf-8")
    pdf = tmp_path / "c.pdf"
    code = main(["analyze", "fringe", str(csv), "--metadata", str(meta), "--certificate",
                 str(pdf), "--max-order", "3", "--lines-per-rev", "16384",
                 "--samples-per-period", str(N)])
    assert code == 0, capsys.readouterr().err
    text = re.sub(r"\s+", " ", subprocess.run(
        ["pdftotext", "-enc", "UTF-8", str(pdf), "-"], capture_output=True, text=True,
        encoding="utf-8", check=True).stdout)
    # each plot over the record: its x tick labels, just before its x title
    axes = re.findall(r"((?:-?\d+ ){2,})" + re.escape(X_TITLE), text)
    assert len(axes) >= 2, text[:3000]
    last = (PERIODS * N - 1) / N  # the last sample's phase, in periods
    for ticks in axes:
        values = [float(t) for t in ticks.split()]
        assert max(values) <= last * 1.1, (values, last)
    assert "0 listed so" not in text
    assert "each to be listed with a calibration certificate and a stated uncertainty; none " \
           "of them is listed so" in text
