"""The JSON's Monte Carlo seed reaches every reader as the seed it is (assessment 70, L6): a
seed made from the readings' hash may exceed 2⁶³ (an int64 reader overflows) and 2⁵³ (a
double, as JavaScript and jq read every number, rounds it to another seed). The JSON gives
it as a decimal string, and no number a double cannot hold exactly."""

from __future__ import annotations

import json

import pytest

from app.main import main

pytestmark = pytest.mark.slow  # the command line on the positioning sample (seconds)

EXACT_IN_A_DOUBLE = 2**53


def _integers_a_double_rounds(text: str) -> list[str]:
    """Every integer literal of the JSON ``text`` that a reader holding numbers as IEEE
    doubles does not hold exactly (as JSON.parse, jq and an int64 reader beyond 2⁶³ do)."""
    rounded: list[str] = []

    def integer(literal: str) -> int:
        if abs(int(literal)) > EXACT_IN_A_DOUBLE:
            rounded.append(literal)
        return int(literal)

    json.loads(text, parse_int=integer)
    return rounded


def test_the_positioning_seed_is_exact_for_every_json_reader(capsys, samples_dir, tmp_path):
    """The positioning sample decided on its half range: its seed, from the readings'
    SHA-256, was printed 10712984201263442809 (above 2⁶³) as a JSON number until 0.8.18."""
    details = json.loads((samples_dir / "certificate_positioning.json").read_text("utf-8"))
    details.update(decision_quantity="half_range", language="en")
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps(details), encoding="utf-8")
    code = main(["analyze", "positioning", str(samples_dir / "positioning_sample.csv"),
                 "--misalignment-u", "0.2", "--reference-resolution", "0.1",
                 "--temperature-u", "0.2", "--json", "--metadata", str(meta)])
    out = capsys.readouterr()
    assert code == 0, out.err
    assert _integers_a_double_rounds(out.out) == []
    decided = json.loads(out.out)["decided_quantity"]
    seed = decided["monte_carlo_seed"]
    assert decided["monte_carlo_trials"] > 0
    assert isinstance(seed, str) and seed.isdigit() and str(int(seed)) == seed, seed
