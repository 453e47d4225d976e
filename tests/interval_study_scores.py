"""Scores of a coverage-and-width study of intervals (numpy only): per figure, how many of the
tests' intervals held the truth, how many missed below and above, the median width and ends,
and the width against the oracle's (the spread of value − truth between the (1 − p)/2 and
(1 + p)/2 quantiles over the tests: the narrowest interval the same draws would need).

Used by tests/benchmarks/band_width_study.py and tests/benchmarks/repeatability_width_study.py."""

from __future__ import annotations

import numpy as np


def interval_scores(rows: dict[str, list[tuple[float, float, float, float, float]]]) -> dict:
    """``rows``: figure → one (low, high, probability, truth, value) a test."""
    out = {}
    for k, r in rows.items():
        a = np.array(r)
        out[k] = {"tests": len(a),
                  "covered": int(np.sum((a[:, 0] <= a[:, 3]) & (a[:, 3] <= a[:, 1]))),
                  "below": int(np.sum(a[:, 1] < a[:, 3])), "above": int(np.sum(a[:, 0] > a[:, 3])),
                  "p": float(np.min(a[:, 2])), "width": float(np.median(a[:, 1] - a[:, 0])),
                  "low": float(np.median(a[:, 0])), "high": float(np.median(a[:, 1])),
                  "truth": float(a[0, 3])}
        p = out[k]["p"]
        err = a[:, 4] - a[:, 3]
        oracle = float(np.quantile(err, (1 + p) / 2) - np.quantile(err, (1 - p) / 2))
        out[k]["width_oracle"] = out[k]["width"] / oracle if oracle > 0 else float("nan")
    return out
