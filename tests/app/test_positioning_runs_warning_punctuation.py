"""The warning of fewer runs than ISO 230-2 asks joins its directions in the language's own
punctuation (day review 69, finding 6: the Chinese window read "正向 3 次, 反向 3 次", an
ASCII comma in Chinese text). The record is simulated by tests/repeatability_rig.py."""

from __future__ import annotations

import numpy as np

from tests.repeatability_rig import iso230_rows


def test_the_directions_of_the_runs_warning_are_joined_in_chinese_punctuation(
        tmp_path, capsys):
    from app.main import main

    angles = np.linspace(0.0, 330.0, 12)
    f = 4.0 * np.sin(np.radians(angles))
    rows, _ = iso230_rows(angles, {"+": f + 1.0, "-": f - 1.0}, 3, 0.8,
                          np.random.default_rng(6911))
    csv = tmp_path / "axis3.csv"
    csv.write_text("target,run,direction,deviation\n" + "".join(
        f"{a},{r},{sign},{x}\n" for a, r, sign, x, _ in rows), encoding="utf-8")
    assert main(["analyze", "positioning", str(csv), "--language", "zh_CN"]) == 0
    said = capsys.readouterr()
    out = said.out + said.err
    assert "正向 3 次，反向 3 次" in out, out
    assert "正向 3 次, " not in out
    assert main(["analyze", "positioning", str(csv), "--language", "en"]) == 0
    said = capsys.readouterr()
    assert "forward 3, backward 3 at the least measured target" in said.out + said.err
