"""The intervals of the figures made of the targets' σ withheld where two approaches a
target leave each σ one degree of freedom (ISO 230-2's R↑, R↓, R, A↑, A↓, A; VDI/DGQ 3441's
Ps_max and P).

R↑ = 4 max σ↑_i and its kin take their interval from each target's own s by the
chi-square distribution (models.uncertainty.figure_intervals._repeatability_bounds). With
every target approached at most twice in a direction, ν = 1: the upper bound of σ from one
degree of freedom at 95 % is about 32 times s, and the interval of R says nothing a
customer can use (an audit, 68 finding 3: a theodolite with 2 passes printed R = 3.13″ in
0.86″ … 225″, the truth 1.8″). The figure is still printed as measured; its interval is
withheld with the reason, quoting the interval it would have been. Three approaches (ν = 2)
keep their interval. A and P take theirs from each target's own tolerance bounds of
μ ± 2σ (μ ± 1.5σ for P: ``_band_span_bounds``), which at ν = 1 reach as far (a theodolite with
2 passes: A = 4.96″ in 2.93″ … 194″): withheld alike.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from models.messages import QT_TR_NOOP, Message, message
from models.uncertainty.figure_intervals import FigureInterval

__all__ = ["PASSES_UNDETERMINED", "PASSES_UNDETERMINED_READINGS", "REPEATABILITY_DIRECTIONS",
           "RUNS_UNDETERMINED", "RUNS_UNDETERMINED_READINGS", "undetermined_repeatability"]

#: the figures made of the targets' σ and the directions whose σ each is made of
REPEATABILITY_DIRECTIONS: dict[str, tuple[str, ...]] = {
    "R_up": ("up",), "R_down": ("down",), "R": ("up", "down"), "Ps_max": ("up", "down"),
    "A_up": ("up",), "A_down": ("down",), "A": ("up", "down"), "P": ("up", "down")}

#: why (positioning: runs at a target)
RUNS_UNDETERMINED = QT_TR_NOOP(
    "two runs give each target's repeatability one degree of freedom: the interval would be "
    "{low} … {high}; measure at least 3 runs each way")
#: why (theodolite: passes at a θ)
PASSES_UNDETERMINED = QT_TR_NOOP(
    "two passes give each θ's repeatability one degree of freedom: the interval would be "
    "{low} … {high}; measure at least 3 passes each way")
#: the same where the interval quoted is the readings' own, without the reference standards'
#: U (the window's and the command line's summary): a certificate quotes a wider one, with
#: them (day 68 F7: "16″ … 487″" in the window, "14″ … 974″" on the certificate, unsaid)
RUNS_UNDETERMINED_READINGS = QT_TR_NOOP(
    "two runs give each target's repeatability one degree of freedom: the interval from the "
    "readings without the reference standards' U would be {low} … {high} (a certificate's "
    "includes it); measure at least 3 runs each way")
PASSES_UNDETERMINED_READINGS = QT_TR_NOOP(
    "two passes give each θ's repeatability one degree of freedom: the interval from the "
    "readings alone would be {low} … {high} (a certificate adds its stated standards' u); "
    "measure at least 3 passes each way")


def undetermined_repeatability(intervals: Mapping[str, FigureInterval],
                               runs: Mapping[str, np.ndarray], reason: str, symbol: str = "\""
                               ) -> tuple[dict[str, FigureInterval], dict[str, Message]]:
    """``intervals`` without those of the repeatability figures whose σ come from a
    direction in which every target was approached fewer than 3 times (``runs``: each
    direction's approaches per target), and, by figure, why (``reason``: a template of
    {low} and {high}, the interval withheld, its ends printed in ``symbol``)."""
    thin = {name for name, n in runs.items()
            if np.asarray(n).size and int(np.max(np.asarray(n))) < 3}
    kept = dict(intervals)
    why: dict[str, Message] = {}
    for key, directions in REPEATABILITY_DIRECTIONS.items():
        interval = kept.get(key)
        if interval is None or not any(d in thin for d in directions if d in runs):
            continue
        del kept[key]
        # both ends to one decimal, the upper end's (day review 69 F6: "0.084″ … 443″"
        # beside "0″ … 443″")
        d = _decimals(interval.high)
        why[key] = message(reason, low=_end(interval.low, math.floor, symbol, d),
                           high=_end(interval.high, math.ceil, symbol, d))
    return kept, why


def _decimals(value: float) -> int:
    """The decimal of ``value`` to two significant digits, whole units at least."""
    if not (math.isfinite(value) and value > 0):
        return 0
    return max(0, 1 - math.floor(math.log10(value)))


def _end(value: float, rounding, symbol: str, d: int) -> str:
    """An end of the interval withheld, to the decimal ``d`` of its upper end's two
    significant digits (whole units at least), rounded outward (``rounding``: floor for the
    lower end, ceil for the upper): "0.8″ … 2.3″", "0″ … 225″"; the end of an interval 70
    times its value is quoted, not stated."""
    if not (math.isfinite(value) and value >= 0):
        return f"{value:g}{symbol}"
    shown = rounding(value * 10 ** d) / 10 ** d
    return f"{shown:.{d}f}{symbol}"
