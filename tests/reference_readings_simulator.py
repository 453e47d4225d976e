"""A rotary axis's positioning test read with a reference instrument, from first principles,
for the tests of how the reference standard enters the budget: numpy only, nothing from the
code it checks.

The axis stops at target i, run j, direction d (+1 up, −1 down) at θ_i + f_i + σ·z,
z ~ N(0, 1) new at every approach (f_i its true deviation, a smooth curve). The reference
reports a position in one of two ways:

* ``"reading"`` (a theodolite, an autocollimator: its certificate states U per reading): it
  reads the axis's angle at target i with an error e_i, one value for the whole test (the
  same position read again in every run), N(0, u) from one test to the next; the datum is
  read once at the start, a reading of its own with its own error e_d, N(0, u). The
  deviation recorded is the difference of two readings, r_target − r_datum − θ_i =
  f_i + σ·z + e_i − e_d: the datum's error is in every one.
* ``"angle"`` (a laser rotary calibrator, an interferometer: U stated for a position from its
  own datum): it reports the angle from its datum with one error ε(θ_i) per position, N(0, u),
  one value for the whole test; the deviation recorded is f_i + σ·z + ε(θ_i).

The truth of each mean deviation x̄_i (either direction) is f_i.
"""

from __future__ import annotations

import numpy as np


def positioning_test(targets: int, runs: int, sigma: float, u: float, per: str,
                     rng: np.random.Generator) -> tuple[list[list[str]], np.ndarray]:
    """(rows of a readings file: target °, run, direction, deviation ″, note; the true
    deviation f at each target) of one test, the reference read ``per`` "reading" or
    "angle" with standard uncertainty ``u`` (″)."""
    angles = np.linspace(0.0, 360.0, targets, endpoint=False)
    t = np.radians(angles)
    f = np.sin(t) + 0.3 * np.sin(2 * t + 1.0)
    scale_error = u * rng.standard_normal(targets)  # e_i or ε_i: one per position
    if per == "reading":
        offset = -u * rng.standard_normal()  # −e_d: the datum reading's, in every deviation
    elif per == "angle":
        offset = 0.0
    else:
        raise ValueError(per)
    rows = []
    for run in range(1, runs + 1):
        for sign, order in (("+", range(targets)), ("-", range(targets - 1, -1, -1))):
            for i in order:
                x = f[i] + sigma * rng.standard_normal() + scale_error[i] + offset
                rows.append([f"{angles[i]:.6f}", str(run), sign, f"{x:.6f}", ""])
    return rows, f
