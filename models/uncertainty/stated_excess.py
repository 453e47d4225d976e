"""The part of a stated standard uncertainty per reading that the readings do not show to
scatter.

An instrument's stated u per reading is its whole error in one reading: a part new in every
reading (its pointing noise, which the readings' scatter shows) and a part the same in every
repeat at one place (a theodolite's circle error where it reads a θ), which no scatter shows.
The second is what the stated u leaves over the first: √max(u² − σ², 0). With σ estimated
by s on ν degrees of freedom, the point estimate √max(u² − s², 0) is positive in about half
the runs of an instrument stated at exactly its pointing noise (s below σ by chance), at
0.3–0.5 u on 20–40 degrees of freedom. Taken over s's one-sided upper confidence bound
(:func:`scatter_upper_bound`, s √(ν / χ²_ν(1 − p))) it is the part the readings show to be
there at that probability (the theodolite sized its circle widening by it until 0.8.14);
but what the readings show is not all they allow: where the pointing noise is large beside
the circle's part (σ = 1.5″ against u_c = 0.4″) that part is 0 in nearly every run, while σ
may lie well below s. The largest part they do not exclude, √max(u² − s_lo², 0), is taken
over s's one-sided LOWER confidence bound s √(ν / χ²_ν,upper(β)) (:func:`scatter_lower_bound`,
:func:`excess_not_excluded`): σ ≥ s_lo at 1 − β, so it is at least the true part at that
probability, and an interval sized by it at the rest of its tail holds at the whole (Berger
& Boos 1994, JASA 89:1012).
"""

from __future__ import annotations

import math

from scipy.special import chdtri

__all__ = ["EVIDENCE", "excess_not_excluded", "scatter_lower_bound", "scatter_upper_bound"]

#: the one-sided probability at which the readings must show the stated u to exceed their
#: scatter
EVIDENCE = 0.95


def scatter_upper_bound(s: float, nu: float, evidence: float = EVIDENCE) -> float:
    """The one-sided upper confidence bound of σ at ``evidence`` from s on ν degrees of
    freedom, s √(ν / χ²_ν(1 − evidence)); s itself where ν is not a finite number ≥ 1, and
    ∞ where s is not a number (nothing is then shown to exceed it)."""
    if not math.isfinite(s):
        return math.inf  # no scatter known: nothing is shown to exceed it
    if not (math.isfinite(nu) and nu >= 1.0):
        return s
    return s * math.sqrt(nu / float(chdtri(nu, evidence)))


def scatter_lower_bound(s: float, nu: float, beta: float) -> float:
    """The one-sided lower confidence bound of σ from s on ν degrees of freedom, σ ≥ s_lo
    with probability 1 − ``beta``: s √(ν / χ²_ν,upper(β)), χ²_ν,upper(β) the value a χ²_ν
    exceeds with probability β; s itself where ν is infinite (s is σ), 0 where s is not a
    number or ν is below 1 (nothing excluded)."""
    if not math.isfinite(s) or math.isnan(nu) or nu < 1.0:
        return 0.0
    if math.isinf(nu):
        return s
    return s * math.sqrt(nu / float(chdtri(nu, beta)))


def excess_not_excluded(stated_u: float, s: float, nu: float, beta: float) -> float:
    """The largest part of the stated u that the scatter does not exclude at 1 − ``beta``:
    √max(u² − s_lo², 0), s_lo = :func:`scatter_lower_bound`; 0 where u is at or below it."""
    return math.sqrt(max(stated_u**2 - scatter_lower_bound(s, nu, beta) ** 2, 0.0))
