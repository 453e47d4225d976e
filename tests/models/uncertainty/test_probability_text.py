"""A study's coverage probability is printed to the digits it has (day review 66 F8): the
studies' probabilities are multiples of 0.5 % reached over 60–80 runs, the asked one 95.45 %."""

from __future__ import annotations

import pytest

from models.uncertainty.probability_text import percent_text


@pytest.mark.parametrize(("probability", "printed"), [
    (0.92, "92"), (0.935, "93.5"), (0.9545, "95.45"), (0.95, "95"), (0.988, "98.8"),
    (0.5, "50"), (1.0, "100")])
def test_a_probability_is_printed_without_trailing_zeros(probability, printed):
    assert percent_text(probability) == printed
