"""The table files say where they hold when harmonic orders fold at the sampled phases
(review finding: the certificate says "at the sampled phases only", the files a chip is
loaded from did not). At N = 8 samples a period, with the 5th harmonic in the signals and
orders 1 and 3 fitted, the 5th folds into the 3rd: the correction table (--table, CSV and
C header) and the interpolator look-up table (--interpolator-table, CSV and C header) carry
the caveat in their header comments; at N = 64 nothing folds and they carry none.

The channels come from tests/fringe_channels.py (first principles: the true phase, each
channel's harmonics in volts, noise), nothing from models/.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from app.main import main
from tests.fringe_channels import Channels, equal_steps

CAVEAT = "at the sampled phases only"
HEAD = Channels(offsets_v=(0.003, -0.004), amplitudes_v=(0.5, 0.49), quadrature_deg=0.5,
                sin_harmonics={3: (0.005, 0.4), 5: (0.004, 1.1)},
                cos_harmonics={3: (0.003, -0.3), 5: (0.0025, 0.2)}, noise_v=0.0003)


def _comments(path: Path) -> str:
    """The file's comment lines ("# …" in a CSV, the /* … */ block of a C header)."""
    text = path.read_text(encoding="utf-8")
    if path.suffix == ".csv":
        return "\n".join(line for line in text.splitlines() if line.startswith("#"))
    return text[text.index("/*"):text.index("*/")]


def _write(tmp_path: Path, per_period: int, capsys) -> tuple[dict[str, Path], str]:
    u_sin, u_cos = HEAD.sample(equal_steps(per_period * 16, per_period),
                               np.random.default_rng(4))
    csv = tmp_path / f"n{per_period}.csv"
    csv.write_text("u_sin,u_cos\n" + "".join(f"{s:.6f},{c:.6f}\n" for s, c in zip(
        u_sin, u_cos, strict=True)), encoding="utf-8")
    out = {name: tmp_path / name for name in ("table.csv", "table.h", "lut.csv", "lut.h")}
    for table, lut in (("table.csv", "lut.csv"), ("table.h", "lut.h")):
        assert main(["analyze", "fringe", str(csv), "--lines-per-rev", "16384",
                     "--samples-per-period", str(per_period), "--max-order", "3",
                     "--language", "en", "--table", str(out[table]),
                     "--interpolator-table", str(out[lut])]) == 0
    return out, capsys.readouterr().out


@pytest.mark.slow  # (the command run twice, ~0.5 s)
def test_folded_orders_put_the_caveat_in_every_table_files_comments(tmp_path, capsys):
    files, said = _write(tmp_path, 8, capsys)
    assert "order 5 into order 3" in said  # (the command's own line said it already)
    for name, path in files.items():
        comments = _comments(path)
        assert CAVEAT in comments and "order 5 into order 3" in comments, (name, comments)


@pytest.mark.slow
def test_no_fold_no_caveat(tmp_path, capsys):
    files, said = _write(tmp_path, 64, capsys)
    assert CAVEAT not in said
    for name, path in files.items():
        assert CAVEAT not in path.read_text(encoding="utf-8"), name


@pytest.mark.slow  # (the command run twice, ~0.5 s)
@pytest.mark.parametrize("per_period, folds", [(8, True), (64, False)])
def test_intel_hex_has_no_comments_so_the_commands_line_says_it_does_not_carry_the_caveat(
        tmp_path, capsys, per_period, folds):
    u_sin, u_cos = HEAD.sample(equal_steps(per_period * 16, per_period),
                               np.random.default_rng(4))
    csv = tmp_path / "head.csv"
    csv.write_text("u_sin,u_cos\n" + "".join(f"{s:.6f},{c:.6f}\n" for s, c in zip(
        u_sin, u_cos, strict=True)), encoding="utf-8")
    lut = tmp_path / "lut.hex"
    assert main(["analyze", "fringe", str(csv), "--lines-per-rev", "16384",
                 "--samples-per-period", str(per_period), "--max-order", "3",
                 "--language", "en", "--interpolator-table", str(lut)]) == 0
    out = capsys.readouterr()
    said = next(line for line in (out.out + out.err).splitlines()
                if line.startswith("Interpolator table"))
    assert lut.read_text(encoding="ascii").endswith(":00000001FF\n")  # written, not refused
    assert (CAVEAT in said) is folds
    assert ("Intel HEX has no comments" in said) is folds, said
