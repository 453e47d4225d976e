"""Where the autocollimator's zero moved between the polygon's sets, the encoder's
repeatability, reversal and the ISO 230-2 figures made from the sets' scatter are not given
as the encoder's (day review 68, finding 3).

A zero that jumps between sets shifts a whole set; the budget takes each set's offset out
(tests/models/polygon/test_polygon_zero_jumps.py), but the certificate's Statistics printed
"Repeatability (largest s over positions) 1.34″" and "Reversal B 1.36″, B̄ = +1.05″", and the
summary "R_up = 7.55″, A_up = 8.15″", all holding the autocollimator's jump of 2.5″ (the
same positions with no jump: B̄ −0.19″). The readings cannot tell a whole set's offset of the
autocollimator from the encoder's, so these figures are withheld with that reason.

Simulated by tests/polygon_zero_jump_rig.py (numpy only, exact 3-D): 24 faces, 2 sets each
way, σ 0.1″, the zero drawn anew for every set after the first (sd 2″); the control is the
same rig with no jumps. The certificate is issued by the command line and read from its PDF.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from app.main import main
from models.polygon.analysis import POLYGON, to_json
from models.readings.sheet import ReadingsSheet
from tests.pdf_text import pdf_text
from tests.polygon_zero_jump_rig import ZeroJumpRig

MOVED = "the autocollimator's zero moved between the sets: the sets' scatter"
#: the figures the sets' scatter or the directions' difference hold (ISO 230-2 names)
HELD = ("R_up", "A_up", "R_down", "A_down", "E", "B", "B_mean", "R", "A")


def _lines(jump_sd: float, seed: int = 68) -> list[str]:
    lines, _ = ZeroJumpRig(faces=24, sets=4, jump_sd=jump_sd).run(np.random.default_rng(seed))
    return lines


def _offsets_spread(lines: list[str]) -> float:
    """The largest difference of two sets' mean autocollimator reading within a direction
    (from the CSV alone: what the jumps did to the sets)."""
    rows = [r.split(",") for r in lines[1:]]
    means = {}
    for s in {r[5] for r in rows}:
        mine = [r for r in rows if r[5] == s][:-1]  # the closure left out
        means[s] = (mine[0][6], np.mean([float(r[3]) for r in mine]))
    spread = 0.0
    for d in ("+", "-"):
        values = [m for sense, m in means.values() if sense == d]
        spread = max(spread, float(np.ptp(values)))
    return spread


@pytest.mark.parametrize("jump_sd", [2.0, 0.0])
def test_the_summary_withholds_the_sets_scatter_where_the_zero_moved(jump_sd):
    lines = _lines(jump_sd)
    result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, [r.split(",") for r in lines[1:]])
                             .parse(), {"grade": 3})
    moved = any("zero moved between the sets" in w for w in result.warnings)
    assert moved == (jump_sd > 0)  # the rig's jumps, and only they, are seen
    text = " ".join(POLYGON.summary(result).split())
    iso = text[text.index("ISO 230-2: "):]
    if moved:
        assert _offsets_spread(lines) > 0.5  # the sets really moved, by far more than σ
        assert "repeatability and reversal not evaluated: " + MOVED in text, text
        assert "repeatability 0" not in text and "reversal |ē↑ − ē↓| up to" not in text
        for name in HELD:
            assert f" {name} = " not in iso, (name, iso)
        assert "E_up = " in iso and "M = " in iso  # a set's offset moves every face alike
    else:
        assert MOVED not in text
        assert ", repeatability 0." in text and "reversal |ē↑ − ē↓| up to" in text, text
        for name in HELD:
            assert f" {name} = " in " " + iso.replace("ISO 230-2:", ""), (name, iso)
    # the JSON alike: no number of the encoder the jumps hold, and why
    data = to_json(result)
    assert (data["repeatability_arcsec"] is None) == moved
    assert (data["mean_reversal_arcsec"] is None) == moved
    assert (data["reversal_figures"]["B"]["value"] is None) == moved
    assert (MOVED in data["reversal_figures_reason"]) == moved
    assert (MOVED in data["iso230_arcsec_reason"]) == moved
    assert all((name in data["iso230_arcsec"]) != moved for name in HELD), data["iso230_arcsec"]
    assert {"E_up", "E_down", "M"} <= set(data["iso230_arcsec"])


@pytest.mark.slow  # two certificates through the command line
def test_the_certificate_prints_no_repeatability_or_reversal_of_the_encoder_where_the_zero_moved(
        tmp_path, capsys):
    details = tmp_path / "details.json"
    details.write_text(json.dumps({"tolerance": 1.0, "tolerance_unit": "arcsec"}), "utf-8")
    texts = {}
    for jump_sd in (2.0, 0.0):
        readings, pdf = tmp_path / f"sets_{jump_sd:g}.csv", tmp_path / f"c_{jump_sd:g}.pdf"
        readings.write_text("\n".join(_lines(jump_sd)) + "\n", "utf-8")
        assert main(["analyze", "polygon", str(readings), "--grade", "3", "--metadata",
                     str(details), "--certificate", str(pdf)]) == 0, capsys.readouterr()
        texts[jump_sd] = pdf_text(pdf.read_bytes())
    moved, control = texts[2.0], texts[0.0]
    assert "The autocollimator's zero moved between the sets" in moved  # the warning
    assert "Autocollimator zero offsets between the sets" in moved  # the budget's input
    assert "Repeatability (largest s over positions)" not in moved
    assert "Repeatability not evaluated " + MOVED in moved, moved
    assert "Reversal B (largest |x̄↑ − x̄↓|, ISO 230-2) not evaluated " + MOVED in moved
    assert "mean B̄ =" not in moved
    # the control: no jump, no warning, the sets' scatter and the reversal printed
    assert "zero moved" not in control
    assert "Repeatability (largest s over positions)" in control
    assert "mean B̄ =" in control
