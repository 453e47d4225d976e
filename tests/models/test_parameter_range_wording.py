"""A setting out of range says its range once (contract75 F13: ``--cmc-arcsec -1`` said
"cmc_arcsec must be 0 or 0 to 3600", not -1"): "0 or" only where 0 is outside the range."""

from __future__ import annotations

import pytest

from app.main import main
from models.parameters import Parameter, SettingsError


def test_a_range_that_holds_0_is_said_once():
    cmc = Parameter("cmc_arcsec", "CMC", "float", 0.0, "\"", 0.0, 3600.0, zero="none stated")
    with pytest.raises(SettingsError) as refused:
        cmc.check(-1.0)
    assert str(refused.value) == "cmc_arcsec must be 0 to 3600 \", not -1"
    faces = Parameter("faces", "faces", "int", 0, "", 3, 360, zero="auto")
    with pytest.raises(SettingsError) as refused:
        faces.check(2)
    assert str(refused.value) == "faces must be 0 or 3 to 360, not 2"  # 0 is its own case


def test_the_command_line_says_it(capsys):
    from pathlib import Path

    sample = Path(__file__).resolve().parents[2] / "resources" / "samples" / "polygon_sample.csv"
    assert main(["analyze", "polygon", str(sample), "--cmc-arcsec", "-1", "--language",
                 "en"]) == 2
    assert capsys.readouterr().err.strip().splitlines() == [
        "anglebench analyze: cmc_arcsec must be 0 to 3600 \", not -1"]
