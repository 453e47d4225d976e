"""Leftovers 80: figures printed with no coverage interval at all — a θ of a theodolite run
read once each way, a positioning target approached once — are printed rounded to the place
their readings support (models.uncertainty.rounding.without_interval_decimals), and the note
says that place, as positioning's note on a figure whose interval two runs withhold already
did. The theodolite summary said only "No coverage intervals: …". The runs are simulated from
first principles (tests/theodolite_passes_simulator.py, tests/repeatability_rig.py)."""

from __future__ import annotations

import re

import numpy as np
import pytest

from app.main import main
from tests.theodolite_passes_simulator import passes_record

_NOTE = (r"No coverage interval is given for the figures: (?P<reason>.*?)\. Each figure is "
         r"printed rounded to (?P<place>[^,:\s]+)(?P<basis>.*?)(?:\n|$)")
_BASES = {
    "scatter": r", the first significant place of the readings' pooled standard deviation "
               r"\((?P<s>[\d.]+)\"\): without an interval nothing says it is known more closely\.",
    "fit": r", the first significant place of the readings' scatter about the set-up fit "
           r"\((?P<s>[\d.]+)\"; one pass gives no scatter over the passes\): without an "
           r"interval nothing says it is known more closely\.",
    "step": r", the last place of the step the readings were entered in \((?P<step>[\d.]+)\"\): "
            r"without an interval nothing says it is known more closely\.",
    "neither": r": the readings show neither their scatter nor the step they were entered "
               r"in, and without an interval nothing says how closely it is known\.",
}


def _place_of(text: str) -> str:
    """The place a printed figure such as "2.3" or "12" is rounded to: 0.1″, 1″."""
    digits = text.split(".")[1] if "." in text else ""
    return f"0.{'0' * (len(digits) - 1)}1\"" if digits else "1\""


@pytest.mark.parametrize("step, basis, place", [(None, "fit", '0.1"'), (0.1, "fit", '0.1"'),
                                                (1.0, "step", '1"')])
def test_the_theodolite_summary_says_the_place_of_figures_without_an_interval(
        capsys, tmp_path, step, basis, place):
    record = tmp_path / "once.csv"
    # one pass each way: no scatter over the passes; typed in decimal degrees or in d°m's"
    # to 0.1″
    passes_record(record, np.random.default_rng(3), 1, 0.3, 0.5, step=step)
    assert main(["analyze", "theodolite", str(record)]) == 0
    out = capsys.readouterr().out
    note = re.search(_NOTE, out)
    assert note, out
    assert "read fewer than twice in a direction" in note.group("reason")
    assert re.fullmatch(_BASES[basis], note.group("basis")), note.group(0)
    # one pass: the place from the readings' scatter about the set-up fit (0.23″ here), not
    # 0.001″ (three decimals where no scatter is known), unless typed coarser
    assert note.group("place") == place
    assert "No coverage intervals:" not in out
    # every figure printed in the summary is rounded to the place the note names
    shown = re.findall(r"\b(E(?:_up|_down)?|M|B) = (-?\d+(?:\.\d+)?)\"", out)
    assert shown, out
    assert {_place_of(v) for _, v in shown} == {note.group("place")}, (shown, note.group(0))


@pytest.mark.parametrize("scatter, step, place, basis", [
    (0.53, 0.01, '0.1"', "scatter"),   # s's first place, the readings finer
    (0.53, None, '0.1"', "scatter"),
    (0.053, 0.01, '0.01"', "scatter"),  # the step no coarser than s's first place
    (0.53, 1.0, '1"', "step"),          # entered coarser than s's first place
    (float("nan"), 0.5, '0.1"', "step"),
    (float("nan"), None, '0.001"', "neither"),
])
def test_the_note_names_what_set_the_place(scatter, step, place, basis):
    from models.uncertainty.without_interval_note import figures_without_interval_note

    note = figures_without_interval_note("a reason", scatter, step, '"')
    assert note == figures_without_interval_note("a reason", scatter, step, '"', False)
    said = re.search(_NOTE, note)
    assert said and said.group("reason") == "a reason", note
    assert said.group("place") == place, note
    quoted = re.fullmatch(_BASES[basis], said.group("basis"))
    assert quoted, note
    if basis == "scatter":
        assert float(quoted.group("s")) == pytest.approx(scatter, rel=0.05)
    if basis == "step":
        assert float(quoted.group("step")) == step
    # about a fit: said so where the scatter set the place, else the same
    fit = figures_without_interval_note("a reason", scatter, step, '"', about_fit=True)
    assert re.fullmatch(_BASES["fit" if basis == "scatter" else basis],
                        re.search(_NOTE, fit).group("basis")), fit
