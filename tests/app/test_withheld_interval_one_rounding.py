"""An interval two passes (or two runs) withhold is quoted with both ends to one decimal,
its upper end's (day review 69, finding 6: the theodolite's certificate quoted A's as
"0.084″ … 443″" beside A_up's "0″ … 443″", and the summary R_up's as "1.3″ … 149″").
The record is simulated by tests/repeatability_rig.py (first principles), nothing from
models/."""

from __future__ import annotations

import re

from tests.theodolite_run_json import passes_summary

WOULD_BE = re.compile(r"would be (-?[\d.]+)\" … (-?[\d.]+)\"")


def _decimals(text: str) -> int:
    return len(text.split(".")[1]) if "." in text else 0


def test_both_ends_of_a_withheld_interval_are_quoted_to_one_decimal(tmp_path, capsys):
    out = passes_summary(capsys, tmp_path, 2, 6909)
    quoted = WOULD_BE.findall(out)
    assert len(quoted) >= 3, out  # R_up, R_down, R at least
    for low, high in quoted:
        assert _decimals(low) == _decimals(high), (low, high)
        assert float(low) <= float(high)
        # the upper end to two significant digits, whole units at least
        assert len(high.replace(".", "").lstrip("0")) >= 2 or float(high) < 10, high
