"""The fringe summary prints each fitted phase ± its standard uncertainty, to the decimal
that u supports, and never a negative zero (day review 69, finding 6: "A1 = 0.500026 ±
0.000019 V ∠ -0.0000 rad", the phase to four decimals whatever its u, its sign kept on a
zero). The record is simulated from first principles (tests/fringe_channels.py): the sin
channel's fundamental at phase 0, so that its fitted phase lies within its u of zero."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from tests.fringe_channels import Channels, equal_steps

HEAD = Channels(offsets_v=(0.003, -0.004), amplitudes_v=(0.5, 0.49), quadrature_deg=0.5,
                sin_harmonics={3: (0.005, 0.4)}, cos_harmonics={3: (0.003, -0.3)},
                noise_v=0.0003)
PHASE = re.compile(r"([AB]\d) = [-+\d.]+ ± [\d.]+ V ∠ ([-+]?[\d.]+)(?: ± ([\d.]+))? rad")


def _decimals(text: str) -> int:
    return len(text.split(".")[1]) if "." in text else 0


def test_each_phase_is_printed_with_its_u_and_no_negative_zero(tmp_path: Path, capsys):
    from app.main import main

    u_sin, u_cos = HEAD.sample(equal_steps(64 * 16, 16), np.random.default_rng(6907))
    csv = tmp_path / "n16.csv"
    csv.write_text("u_sin,u_cos\n" + "".join(f"{s:.9f},{c:.9f}\n"
                                             for s, c in zip(u_sin, u_cos, strict=True)))
    assert main(["analyze", "fringe", str(csv), "--max-order", "3", "--lines-per-rev",
                 "16384", "--samples-per-period", "16", "--language", "en"]) == 0
    out = capsys.readouterr().out
    phases = PHASE.findall(out)
    assert {name for name, _, _ in phases} >= {"A1", "A3", "B1", "B3"}, out
    for name, value, u in phases:
        assert u, (name, value, out)  # every phase with its u
        # u to two significant digits, the phase to its decimal
        digits = u.replace(".", "").lstrip("0")
        assert len(digits) == 2, (name, u)
        assert _decimals(value) == _decimals(u), (name, value, u)
        if float(value) == 0.0:
            assert not value.startswith("-"), (name, value)
    # the fundamental of the sin channel was simulated at phase 0: its phase within 3 u
    a1 = next((float(v), float(u)) for name, v, u in phases if name == "A1")
    assert abs(a1[0]) <= 3 * a1[1], a1
    assert not re.search(r"-0\.0+(?![0-9])", out), out
