"""Where an order folds into a fitted one (N = 8, highest harmonic 3: order 5 into order 3),
the compensated error and the correction table hold at the sampled phases only (day review
68, finding 8, the rest): the window's bold line said it since 0.8.17, but the plot's
legend still read "after compensation" over a curve drawn between the samples, the
certificate's statement on the table (its sha256) said nothing of it, and an "as left"
certificate said "the compensated error and its U are the item as left". Checked on the
real window (qtbot) and on printed certificates (pdftotext).

The channels come from tests/fringe_channels.py (first principles), nothing from models/."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from tests.fringe_channels import Channels, equal_steps

pytestmark = pytest.mark.slow  # a window, and fringe certificates (~3 s each)

LINES = 16384
SAMPLES = Path(__file__).resolve().parents[2] / "resources" / "samples"
# the day review's record: true A3 5 mV, A5 4 mV
HEAD = Channels(offsets_v=(0.003, -0.004), amplitudes_v=(0.5, 0.49), quadrature_deg=0.5,
                sin_harmonics={3: (0.005, 0.4), 5: (0.004, 1.1)},
                cos_harmonics={3: (0.003, -0.3), 5: (0.0025, 0.2)}, noise_v=0.0003)
AT_SAMPLES = "at the sampled phases only"
OPTIONS = {"max_order": 3, "lines_per_rev": LINES, "samples_per_period": 8}


def _record(tmp_path: Path, seed: int = 6808) -> Path:
    """The head's record at N = 8, 64 periods, its noise drawn from ``seed``."""
    theta = equal_steps(64 * 8, 8)
    u_sin, u_cos = HEAD.sample(theta, np.random.default_rng(seed))
    path = tmp_path / "n8.csv"
    path.write_text("u_sin,u_cos\n" + "".join(f"{s:.9f},{c:.9f}\n"
                                             for s, c in zip(u_sin, u_cos, strict=True)))
    return path


def test_the_windows_line_and_legend_say_where_the_compensation_holds(window, qtbot, tmp_path):
    fringe = window.presenter("fringe")
    window.tabs.setCurrentIndex(window.presenters.index(fringe))
    fringe.import_file(_record(tmp_path))
    fringe.set_settings({**fringe._settings, **OPTIONS})
    qtbot.waitUntil(lambda: fringe.result is not None and not fringe.analysis_pending
                    and bool(fringe.result.folded_orders), timeout=60000)
    line = fringe.view.verdict.text()
    assert "after compensation" in line and AT_SAMPLES in line, line
    legend = [item[1].text for item in fringe.view.error_plot.corrected_legend.items]
    assert any("after compensation" in name and AT_SAMPLES in name for name in legend), legend


def _certificate(tmp_path: Path, capsys, seed: int = 6808, **details) -> str:
    """The certificate of the head's record (``seed``) with ``details`` over the sample's, its
    text as pdftotext reads it, whitespace runs as one space."""
    from app.main import main

    if shutil.which("pdftotext") is None:
        pytest.fail("pdftotext is missing: apt-get install poppler-utils (.ci/run does)")
    data = json.loads((SAMPLES / "certificate_fringe.json").read_text("utf-8"))
    data.pop("certificate_number", None)  # the register allocates one
    data.update({"language": "en", **details})
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps(data), encoding="utf-8")
    pdf = tmp_path / f"c{len(list(tmp_path.glob('c*.pdf')))}.pdf"
    code = main(["analyze", "fringe", str(_record(tmp_path, seed)), "--metadata", str(meta),
                 "--certificate", str(pdf), "--max-order", "3", "--lines-per-rev", str(LINES),
                 "--samples-per-period", "8"])
    out = capsys.readouterr()
    assert code == 0, out.err
    text = subprocess.run(["pdftotext", "-enc", "UTF-8", str(pdf), "-"], capture_output=True,
                          text=True, encoding="utf-8", check=True).stdout
    return re.sub(r"\s+", " ", text)


def _statement(text: str, begins: str) -> str:
    """The bullet of the certificate's Statements that begins with ``begins``."""
    start = text.index(begins)
    return text[start:text.index("•", start)]


def test_the_certificates_statement_on_the_table_says_it_holds_at_the_samples_only(
        tmp_path, capsys):
    text = _certificate(tmp_path, capsys)
    table = _statement(text, "No conformity is judged on the interpolation error as found")
    assert "table sha256" in table and AT_SAMPLES in table, table
    assert "the correction table is expected to leave" not in text


def test_an_as_left_certificate_holds_the_item_as_left_at_the_samples_only(tmp_path, capsys):
    """The lab states this table was loaded into the encoder: the item as left is known at
    the sampled phases only."""
    from models.fringe.analysis import FRINGE
    from models.readings.sheet import ReadingsSheet

    rows = [line.split(",") for line in _record(tmp_path).read_text().splitlines()[1:]]
    result = FRINGE.analyze(ReadingsSheet(FRINGE.columns, [
        row + [""] * (len(FRINGE.columns) - len(row)) for row in rows]).parse(), {
        **FRINGE.settings_with_defaults({}), **OPTIONS})
    assert result.folded_orders
    left = _certificate(tmp_path, capsys, as_left_table_sha256=result.table.sha256)
    as_left = _statement(left, "As left: the lab states")
    assert "the item as left " + AT_SAMPLES in as_left, as_left


def test_the_interpolator_table_written_says_its_residual_holds_at_the_samples_only(
        tmp_path, capsys):
    """Its predicted residual is simulated on the fitted signals, which hold order 5 in
    order 3: between the samples it is not determined either."""
    from app.main import main

    table = tmp_path / "lut.csv"
    code = main(["analyze", "fringe", str(_record(tmp_path)), "--max-order", "3",
                 "--lines-per-rev", str(LINES), "--samples-per-period", "8",
                 "--interpolator-table", str(table)])
    said = capsys.readouterr()
    assert code == 0 and table.exists(), said.err
    line = next(text for text in (said.out + said.err).splitlines()
                if text.startswith("Interpolator table"))
    assert "predicted residual" in line and AT_SAMPLES in line, line
