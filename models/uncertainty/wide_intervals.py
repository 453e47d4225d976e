"""Why a figure's coverage interval reaches far above the figure at few runs, and what that
means for a specification of it (day review 68 F6: at 3 runs "P 22″: 16″ … 218″", "R 10″:
2″ … 73″" and nothing said why; an assessor asked).

R, A, P and Ps are made of each target's standard deviation, and their intervals are
bounds from each target's own readings (models.uncertainty.figure_intervals: chi-square for
σ, the noncentral t for a band x̄ ± ks): at n runs each σ is known to n − 1 degrees of
freedom, and its upper bound is s·√((n − 1)/χ²) — at 3 runs and 95.45 % per target up to
about 6 s, more with the targets taken at once. So the upper end lies several times above
the figure while the figure itself is as measured. A specification of the figure is decided
to conform only when the upper end is within it, and not to conform only when it is below
the lower end (ISO 14253-1, as the certificate states): with the upper end at
:data:`FAR_ABOVE` times the figure or more, a specification between the interval's ends —
the range a figure of this size is specified in — cannot be decided at this number of runs.
Said only where it is so, naming the figures and their intervals' ends."""

from __future__ import annotations

from collections.abc import Mapping

from models.messages import QT_TR_NOOP, Message, message, separated
from models.uncertainty.rounding import fixed_places, interval_decimals, interval_ends

__all__ = ["FAR_ABOVE", "SIGMA_FIGURES", "far_above", "wide_intervals_statement"]

#: an upper end at least this many times the figure is "far above" it: a specification
#: that wide is not one a figure of this size is given (a figure's own scatter at the 5
#: runs ISO 230-2 asks for takes the upper end to about 2–2.7 times: A 22″ … 44″, P 24″ …
#: 64″ in the bundled sample)
FAR_ABOVE = 3.0

#: the figures made of each target's standard deviation, whose intervals are its bounds
SIGMA_FIGURES = ("A", "A_up", "A_down", "R", "R_up", "R_down", "P", "Ps_max")

RUNS = QT_TR_NOOP(
    "At {runs} runs the upper end of the coverage interval lies far above the figure for "
    "{figures}: each target's σ is known only from its own {runs} readings ({nu} degrees of "
    "freedom) and may lie far above its s. A specification of such a figure is decided only "
    "outside its interval: it conforms when the specification is at least the upper end and "
    "does not conform when it is below the lower end; a specification between the "
    "interval's ends cannot be decided at this number of runs; more runs narrow the interval.")
PASSES = QT_TR_NOOP(
    "At {runs} passes the upper end of the coverage interval lies far above the figure for "
    "{figures}: each θ's σ is known only from its own {runs} readings ({nu} degrees of "
    "freedom) and may lie far above its s. A specification of such a figure is decided only "
    "outside its interval: it conforms when the specification is at least the upper end and "
    "does not conform when it is below the lower end; a specification between the "
    "interval's ends cannot be decided at this number of passes; more passes narrow the "
    "interval.")
#: one figure in the list with its interval's ends: "A 20″ (interval 16″ … 107″)" (day
#: review 69 F4: "no specification … can be decided" overstated, one below the lower end is)
FIGURE = QT_TR_NOOP("{figure} {value} (interval {low} … {high})")


def far_above(figures: Mapping[str, float], intervals: Mapping) -> list[str]:
    """The keys of :data:`SIGMA_FIGURES` whose interval's upper end is at least
    :data:`FAR_ABOVE` times their positive figure."""
    return [key for key in SIGMA_FIGURES
            if key in intervals and (figures.get(key) or 0.0) > 0.0
            and intervals[key].high >= FAR_ABOVE * figures[key]]


def wide_intervals_statement(figures: Mapping[str, float], intervals: Mapping, runs: int,
                             symbol: str, passes: bool = False,
                             outwards: bool = True) -> Message | None:
    """The sentence for the figures :func:`far_above` names, each with its upper end as
    printed (to its interval's decimal, rounded outwards as a certificate prints it;
    ``outwards`` False: to the nearest, as a summary's intervals line), at ``runs`` runs (or
    passes) at the least measured target; None where none is."""
    keys = far_above(figures, intervals)
    if not keys or runs < 2:
        return None
    listed = []
    for key in keys:
        iv = intervals[key]
        d = interval_decimals(iv.low, iv.high)
        low, high = interval_ends(iv.low, iv.high, d) if outwards else (iv.low, iv.high)
        listed.append(message(FIGURE, figure=key,
                              value=f"{fixed_places(figures[key], d)}{symbol}",
                              low=f"{fixed_places(low, d)}{symbol}",
                              high=f"{fixed_places(high, d)}{symbol}"))
    return message(PASSES if passes else RUNS, runs=runs, nu=runs - 1,
                   figures=separated(listed, ", "))
