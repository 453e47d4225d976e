"""Leftovers 79, item 1: a figure printed with its coverage interval withheld — "R = 10″" of
two runs, or every figure where a target was approached once — is printed by the command
line's summary and the window's results with the note the certificate prints beside it, in
the certificate's words (models.positioning.report.figures_withheld_notes): the interval
withheld, why, and the place the figure is rounded to. The summary said why but not that R
was rounded to 10″ ("No coverage interval is given for R: …."), and "No coverage intervals:
…" where the certificate says "No coverage interval is given for the figures: …". The axes
are simulated from first principles (tests/repeatability_rig.py)."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from app.main import main
from tests.models.positioning.test_withheld_figures_printed import _axis


def _write(rows, path: Path) -> Path:
    path.write_text("target,run,direction,deviation\n" + "".join(
        f"{a},{r},{d},{x}\n" for a, r, d, x, _ in rows), encoding="utf-8")
    return path


def _summary(csv: Path, capsys) -> str:
    assert main(["analyze", "positioning", str(csv)]) == 0
    return capsys.readouterr().out


@pytest.fixture(scope="module")
def two_runs(tmp_path_factory) -> Path:
    rows, _ = _axis(np.random.default_rng(6805))
    return _write(rows, tmp_path_factory.mktemp("two") / "two_runs.csv")


@pytest.mark.parametrize("figure", ["A", "R", "P", "Ps_max"])
def test_the_summary_says_the_place_a_withheld_figure_is_rounded_to(two_runs, capsys, figure):
    out = _summary(two_runs, capsys)
    # the figure as printed in the figures' line, e.g. "R = 10″"
    shown = re.search(rf"(?:: |, ){figure} = (\d+(?:\.(\d+))?)\"", out)
    assert shown, out
    # the place it is printed to, from its own text: 10″ for "10", 1″ for "12", 0.1″ for "9.7"
    digits = shown.group(2)
    place = (f"0.{'0' * (len(digits) - 1)}1\"" if digits else
             "10\"" if shown.group(1).endswith("0") and len(shown.group(1)) > 1 else "1\"")
    # the certificate's note, whole: why, the interval withheld, and the place
    note = re.search(rf"No coverage interval is given for {figure}: two runs give each "
                     r"target's repeatability one degree of freedom: .*? would be \S+ … \S+ .*?; "
                     rf"measure at least 3 runs each way; {figure} is printed rounded to "
                     r"(\S+), the last place of that interval's half-width to two significant "
                     r"digits \(GUM 7\.2\.6\): the two runs do not give it more closely\.", out)
    assert note, out
    assert note.group(1) == place, (note.group(0), shown.group(0))


def test_no_interval_at_all_said_as_the_certificate_says_it(tmp_path, capsys):
    rows, _ = _axis(np.random.default_rng(6806))
    # one target approached once upwards: no figure has an interval (its s unknown)
    once = [r for r in rows if not (r[0] == rows[0][0] and r[2] == "+" and r[1] == "2")]
    out = _summary(_write(once, tmp_path / "once.csv"), capsys)
    assert ("No coverage interval is given for the figures: a target was approached fewer "
            "than twice in a direction: its standard deviation is unknown, so no figure has a "
            "coverage interval. Each figure is printed rounded to 0.001\", the last place of "
            "the step the readings were entered in (0.001\"): without an interval nothing "
            "says it is known more closely.") in out, out  # run 2, incomplete, waits: no s
    assert "No coverage intervals:" not in out
