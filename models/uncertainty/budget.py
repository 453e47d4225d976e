"""GUM uncertainty budget of an error curve (JCGM 100:2008).

Each component is a quoted figure, the divisor that turns it into a standard
uncertainty (2 for an expanded uncertainty with k = 2, √3 for a maximum
permissible error with a rectangular distribution, 1 for a standard
uncertainty or a Type A estimate), and a sensitivity coefficient per point of
the curve (for example √2 where an error is the difference of two readings,
0 at the reference point). The inputs are taken as uncorrelated; the combined
standard uncertainty is the root sum of squares of the contributions, its
effective degrees of freedom follow Welch–Satterthwaite (GUM G.4.1), and the
expanded uncertainty uses, at each point, the coverage factor of Student's t
with those degrees of freedom, truncated to the next lower integer (GUM
G.4.1 note, G.6.4), for the stated coverage probability (GUM G.3): 95.45 % by
default, so k = 2.00 when ν_eff is large and 2.65 when it is 5.

Inputs whose standard uncertainties come from one and the same Type A
estimate (one s, for example the reading repeatability used for the reading
at a point and again for the shared reference reading) carry the same
``dof_group``: the readings are independent, so their contributions add in
quadrature as usual, but their estimates are one estimate, so for
Welch–Satterthwaite they enter as one input, u² = Σ c_i² u_i², with its ν
(counting them as independent estimates would double their ν).

Every value of a budget is in its ``unit`` (models.quantity): arcseconds for an angle
error, nm or µm for an interferometer's or a linear axis' deviations, as the error curve
it belongs to. The budget states it, and its figures carry it
(:meth:`UncertaintyBudget.quantity`).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import TypedDict

import numpy as np

from models.messages import QT_TR_NOOP, message
from models.quantity import Quantity, Unit
from models.quantity import unit as _unit

__all__ = [
    "BASIS_DIVISORS",
    "DEFAULT_COVERAGE_PROBABILITY",
    "BudgetComponent",
    "BudgetRow",
    "UncertaintyBudget",
    "coverage_factor",
    "divisor_for_basis",
]

#: The coverage probability of k = 2 for a normal distribution (95.45 %).
DEFAULT_COVERAGE_PROBABILITY = math.erf(math.sqrt(2.0))


def coverage_factor(dof: float, probability: float = DEFAULT_COVERAGE_PROBABILITY) -> float:
    """k such that ±k·u_c covers ``probability`` of a t-distribution with ``dof`` degrees
    of freedom (GUM G.3.4); the normal distribution's k for infinite ``dof``."""
    from scipy.special import ndtri, stdtrit  # imported late, as start-up pays it

    tail = 0.5 * (1.0 + probability)
    if not math.isfinite(dof):
        return float(ndtri(tail))
    return float(stdtrit(max(dof, 1.0), tail))

# How a reference standard's figure is stated, and the divisor to its standard uncertainty.
BASIS_DIVISORS: dict[str, tuple[str, float, str]] = {
    "U95": (QT_TR_NOOP("expanded uncertainty U (k = 2)"), 2.0, "normal"),
    "MPE": (QT_TR_NOOP("maximum permissible error ±a"), math.sqrt(3.0), "rectangular"),
    "u": (QT_TR_NOOP("standard uncertainty u"), 1.0, "normal"),
}


#: the distributions a budget's inputs are given (the names its table prints)
DISTRIBUTIONS = (QT_TR_NOOP("normal"), QT_TR_NOOP("rectangular"))


def divisor_for_basis(basis: str) -> tuple[float, str]:
    """(divisor, distribution) for a figure stated as ``basis`` (a key of BASIS_DIVISORS)."""
    try:
        _, divisor, distribution = BASIS_DIVISORS[basis]
    except KeyError:
        raise ValueError(message(
            QT_TR_NOOP("uncertainty basis must be one of {join}, not '{basis}'"),
            join=', '.join(BASIS_DIVISORS), basis=basis)) from None
    return divisor, distribution


@dataclass(frozen=True)
class BudgetComponent:
    """One input of the budget.

    ``value`` is the quoted figure in the budget's unit (a scalar, or one value per
    point for a propagated or per-point estimate); ``sensitivity`` a scalar or one
    coefficient per point; ``dof`` the degrees of freedom (``inf`` for a Type B
    input taken as exactly known).
    """

    name: str
    evaluation: str  # "A" or "B"
    distribution: str
    value: float | np.ndarray
    divisor: float
    sensitivity: float | np.ndarray
    dof: float
    note: str = ""
    common: bool = False
    dof_group: str = ""  # inputs evaluated from one estimate: one input for ν_eff
    # its error at each point is one value for the whole run, held in the measured curve and
    # not in the scatter of the readings (a reference's calibration error at that position)
    in_curve: bool = False
    # a stated (Type B) random error the readings hold as they hold their noise (a phase
    # reference's independent errors at each sample, carried through a fit to the fitted
    # curve): drawn with the noise, its excess on the measured range taken out as the
    # noise's, and, as it may be smaller than stated, the upper end and the value also held
    # with it at zero (models.uncertainty.conformity.half_range_monte_carlo)
    in_readings: bool = False
    # its figure is stated for any angle between two readings (ReferenceStandard.applies_to
    # "angle"): the difference of two points' errors is within it, not within twice it
    per_angle: bool = False
    # its error at a point is the difference of two readings, the one there less the datum's
    # (c = √2 of its per-reading u): the datum reading's part, u, is one value for the run,
    # common to every point, and drops out of the difference of two points' errors
    datum_reading: bool = False

    def __post_init__(self) -> None:
        values = np.asarray(self.value, dtype=float)
        if not np.all(np.isfinite(values)) or np.any(values < 0) or not self.divisor > 0:
            raise ValueError(message(
                QT_TR_NOOP("uncertainty input '{name}': its value must be a finite, non-negative number"),
                name=self.name))

    def standard_uncertainty(self, points: int) -> np.ndarray:
        """Standard uncertainty of the input, per point (before the sensitivity)."""
        return np.broadcast_to(np.asarray(self.value, dtype=float) / self.divisor,
                               (points,))

    def contribution(self, points: int) -> np.ndarray:
        """|c_i| · u(x_i) per point: this input's share of the combined uncertainty."""
        c = np.broadcast_to(np.abs(np.asarray(self.sensitivity, dtype=float)), (points,))
        return c * self.standard_uncertainty(points)


class BudgetRow(TypedDict):
    """One row of :meth:`UncertaintyBudget.table` (its values in the budget's unit)."""

    name: str
    evaluation: str
    distribution: str
    value: float
    divisor: float
    u: float
    sensitivity: float
    contribution: float
    share: float
    dof: float
    note: str


@dataclass(frozen=True, init=False)
class UncertaintyBudget:
    """The components of one error curve's uncertainty, with ``points`` points, every
    value in ``unit`` (given as a key or a :class:`~models.quantity.Unit`, held as the
    :class:`~models.quantity.Unit`)."""

    components: tuple[BudgetComponent, ...]
    points: int
    probability: float = DEFAULT_COVERAGE_PROBABILITY  # stated coverage probability
    unit: Unit = _unit("arcsec")
    # the laboratory's smallest U for this quantity (its CMC, in ``unit``; 0: none stated): a
    # floor on every point's U, except where the error is zero by definition (u_c = 0)
    floor: float = 0.0

    def __init__(self, components: tuple[BudgetComponent, ...], points: int,
                 probability: float = DEFAULT_COVERAGE_PROBABILITY,
                 unit: Unit | str = "arcsec", floor: float = 0.0) -> None:
        object.__setattr__(self, "components", components)
        object.__setattr__(self, "points", points)
        object.__setattr__(self, "probability", probability)
        object.__setattr__(self, "unit", _unit(unit))
        object.__setattr__(self, "floor", floor)

    def quantity(self, value: float | np.ndarray, spec: str = "g") -> Quantity:
        """A figure of this budget (``max_expanded``, a row of ``expanded``) with its unit."""
        return Quantity(value, self.unit, spec)

    def contributions(self) -> np.ndarray:
        """Array (components, points) of |c_i| · u(x_i)."""
        return self._contributions

    @functools.cached_property
    def _contributions(self) -> np.ndarray:
        if not self.components:
            return np.zeros((0, self.points))
        return np.array([c.contribution(self.points) for c in self.components])

    @functools.cached_property
    def combined(self) -> np.ndarray:
        """Combined standard uncertainty u_c per point, in the budget's unit."""
        return np.sqrt(np.sum(self.contributions() ** 2, axis=0))

    @functools.cached_property
    def effective_dofs(self) -> np.ndarray:
        """Welch–Satterthwaite ν_eff = u_c⁴ / Σ (u_i⁴ / ν_i) at every point (∞ where every
        input is exactly known), inputs of one ``dof_group`` as one input; not truncated."""
        contrib = self.contributions()
        uc4 = np.sum(contrib**2, axis=0) ** 2
        variances: dict[str | int, np.ndarray] = {}
        dofs: dict[str | int, float] = {}
        for i, (comp, c) in enumerate(zip(self.components, contrib, strict=True)):
            key = comp.dof_group or i
            variances[key] = variances.get(key, 0.0) + c**2
            dofs[key] = min(dofs.get(key, math.inf), comp.dof)
        denom = np.zeros(self.points)
        for key, var in variances.items():
            dof = dofs[key]
            if math.isfinite(dof) and dof > 0:
                denom = denom + var**2 / dof
        with np.errstate(divide="ignore", invalid="ignore"):
            nu = np.where((denom > 0) & (uc4 > 0), uc4 / np.where(denom > 0, denom, 1.0), np.inf)
        return nu

    @functools.cached_property
    def truncated_dofs(self) -> np.ndarray:
        """ν_eff truncated to the next lower integer (GUM G.6.4): what k is taken for."""
        nu = self.effective_dofs
        finite = np.isfinite(nu)
        # a ν_eff that is an integer but for rounding (8.9999999) is that integer
        return np.where(finite, np.floor(np.where(finite, nu, 0.0) + 1e-9), np.inf)

    @functools.cached_property
    def coverage_factors(self) -> np.ndarray:
        """k at every point for the stated coverage probability, from the truncated ν_eff."""
        nu = self.truncated_dofs
        unique, inverse = np.unique(nu, return_inverse=True)
        ks = np.array([coverage_factor(float(v), self.probability) for v in unique])
        return ks[inverse].reshape(-1) if self.points else np.zeros(0)

    @functools.cached_property
    def computed_expanded(self) -> np.ndarray:
        """U = k · u_c per point as the budget gives it, before the laboratory's CMC."""
        return self.coverage_factors * self.combined

    @functools.cached_property
    def expanded(self) -> np.ndarray:
        """Expanded uncertainty U = k · u_c per point, k from each point's ν_eff; never below
        the laboratory's CMC (``floor``) where the error is not zero by definition."""
        computed = self.computed_expanded
        if not self.floor > 0:
            return computed
        return np.where(self.combined > 0, np.maximum(computed, self.floor), computed)

    @property
    def below_floor(self) -> np.ndarray:
        """The points whose computed U is below the laboratory's CMC: their U is stated as
        the CMC (ILAC-P14 5.4), with the same k."""
        return (self.combined > 0) & (self.computed_expanded < self.floor)

    @property
    def worst_index(self) -> int:
        """The point with the largest U: the budget table is printed for it. Where the
        laboratory's CMC raises several points to one U, the one of them whose computed U
        is largest (the budget nearest the CMC, not the first point raised)."""
        return int(np.argmax(self.computed_expanded)) if self.points else 0

    @property
    def coverage_factor(self) -> float:
        """k at the worst point (the one the budget table shows)."""
        return float(self.coverage_factors[self.worst_index]) if self.points else float("nan")

    @property
    def max_expanded(self) -> float:
        return float(np.max(self.expanded)) if self.points else float("nan")

    def effective_dof(self, index: int | None = None) -> float:
        """ν_eff at one point (default the worst), before truncation."""
        if not self.points:
            return float("inf")
        return float(self.effective_dofs[self.worst_index if index is None else index])

    def truncated_dof(self, index: int | None = None) -> float:
        """The integer ν that k is taken for at one point (default the worst)."""
        if not self.points:
            return float("inf")
        return float(self.truncated_dofs[self.worst_index if index is None else index])

    def table(self, index: int | None = None) -> list[BudgetRow]:
        """Rows of the budget at one point (default the worst): name, type, distribution,
        quoted value, divisor, u, sensitivity, contribution (in the budget's ``unit``),
        share of u_c², ν."""
        i = self.worst_index if index is None else index
        contrib = self.contributions()[:, i] if self.components else np.zeros(0)
        total = float(np.sum(contrib**2)) or 1.0
        rows: list[BudgetRow] = []
        for comp, share in zip(self.components, contrib, strict=True):
            value = np.broadcast_to(np.asarray(comp.value, dtype=float), (self.points,))[i]
            sens = np.broadcast_to(np.asarray(comp.sensitivity, dtype=float), (self.points,))[i]
            rows.append({
                "name": comp.name, "evaluation": comp.evaluation,
                "distribution": comp.distribution, "value": float(value),
                "divisor": comp.divisor, "u": float(value / comp.divisor),
                "sensitivity": float(sens), "contribution": float(share),
                "share": float(share**2 / total), "dof": comp.dof, "note": comp.note,
            })
        return rows
