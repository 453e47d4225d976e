"""GUM uncertainty budget of an error curve (JCGM 100:2008).

Each component is a quoted figure, the divisor that turns it into a standard
uncertainty (2 for an expanded uncertainty with k = 2, √3 for a maximum
permissible error with a rectangular distribution, 1 for a standard
uncertainty or a Type A estimate), and a sensitivity coefficient per point of
the curve (for example √2 where an error is the difference of two readings,
0 at the reference point). The inputs are taken as uncorrelated; the combined
standard uncertainty is the root sum of squares of the contributions, its
effective degrees of freedom follow Welch–Satterthwaite (GUM G.4.1), and the
expanded uncertainty uses k = 2 unless told otherwise.

All values are in arcseconds.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = [
    "BASIS_DIVISORS",
    "BudgetComponent",
    "UncertaintyBudget",
    "divisor_for_basis",
]

# How a reference standard's figure is stated, and the divisor to its standard uncertainty.
BASIS_DIVISORS: dict[str, tuple[str, float, str]] = {
    "U95": ("expanded uncertainty U (k = 2)", 2.0, "normal"),
    "MPE": ("maximum permissible error ±a", math.sqrt(3.0), "rectangular"),
    "u": ("standard uncertainty u", 1.0, "normal"),
}


def divisor_for_basis(basis: str) -> tuple[float, str]:
    """(divisor, distribution) for a figure stated as ``basis`` (a key of BASIS_DIVISORS)."""
    try:
        _, divisor, distribution = BASIS_DIVISORS[basis]
    except KeyError:
        raise ValueError(f"uncertainty basis must be one of {', '.join(BASIS_DIVISORS)}, "
                         f"not '{basis}'") from None
    return divisor, distribution


@dataclass(frozen=True)
class BudgetComponent:
    """One input of the budget.

    ``value_arcsec`` is the quoted figure (a scalar, or one value per point for
    a propagated or per-point estimate); ``sensitivity`` a scalar or one
    coefficient per point; ``dof`` the degrees of freedom (``inf`` for a Type B
    input taken as exactly known).
    """

    name: str
    evaluation: str  # "A" or "B"
    distribution: str
    value_arcsec: float | np.ndarray
    divisor: float
    sensitivity: float | np.ndarray
    dof: float
    note: str = ""

    def standard_uncertainty(self, points: int) -> np.ndarray:
        """Standard uncertainty of the input, per point (before the sensitivity)."""
        return np.broadcast_to(np.asarray(self.value_arcsec, dtype=float) / self.divisor,
                               (points,))

    def contribution(self, points: int) -> np.ndarray:
        """|c_i| · u(x_i) per point: this input's share of the combined uncertainty."""
        c = np.broadcast_to(np.abs(np.asarray(self.sensitivity, dtype=float)), (points,))
        return c * self.standard_uncertainty(points)


@dataclass(frozen=True)
class UncertaintyBudget:
    """The components of one error curve's uncertainty, with ``points`` points."""

    components: tuple[BudgetComponent, ...]
    points: int
    coverage_factor: float = 2.0

    def contributions(self) -> np.ndarray:
        """Array (components, points) of |c_i| · u(x_i)."""
        if not self.components:
            return np.zeros((0, self.points))
        return np.array([c.contribution(self.points) for c in self.components])

    @property
    def combined_arcsec(self) -> np.ndarray:
        """Combined standard uncertainty u_c per point."""
        return np.sqrt(np.sum(self.contributions() ** 2, axis=0))

    @property
    def expanded_arcsec(self) -> np.ndarray:
        """Expanded uncertainty U = k · u_c per point."""
        return self.coverage_factor * self.combined_arcsec

    @property
    def worst_index(self) -> int:
        """The point with the largest U: the budget table is printed for it."""
        return int(np.argmax(self.combined_arcsec)) if self.points else 0

    @property
    def max_expanded_arcsec(self) -> float:
        return float(np.max(self.expanded_arcsec)) if self.points else float("nan")

    def effective_dof(self, index: int | None = None) -> float:
        """Welch–Satterthwaite ν_eff = u_c⁴ / Σ (u_i⁴ / ν_i) at one point (default the worst)."""
        i = self.worst_index if index is None else index
        contrib = self.contributions()[:, i] if self.components else np.zeros(0)
        uc4 = float(np.sum(contrib**2)) ** 2
        denom = sum(u**4 / c.dof for u, c in zip(contrib, self.components, strict=True)
                    if math.isfinite(c.dof) and c.dof > 0)
        if uc4 == 0.0:
            return float("inf")
        return float("inf") if denom == 0.0 else uc4 / denom

    def coverage_probability(self, index: int | None = None) -> float:
        """Coverage probability of U = k · u_c for a t-distribution with ν_eff (GUM G.6.4)."""
        nu = self.effective_dof(index)
        k = self.coverage_factor
        if not math.isfinite(nu):
            return float(math.erf(k / math.sqrt(2.0)))
        from scipy.special import stdtr  # Student's t CDF; imported late, as start-up pays it

        return float(2.0 * stdtr(nu, k) - 1.0)

    def k95(self, index: int | None = None) -> float:
        """Coverage factor for 95 % from ν_eff (GUM Annex G), for comparison with k."""
        nu = self.effective_dof(index)
        if not math.isfinite(nu):
            return 1.959964
        from scipy.special import stdtrit  # inverse of Student's t CDF

        return float(stdtrit(nu, 0.975))

    def table(self, index: int | None = None) -> list[dict[str, object]]:
        """Rows of the budget at one point (default the worst): name, type, distribution,
        quoted value, divisor, u, sensitivity, contribution, share of u_c², ν."""
        i = self.worst_index if index is None else index
        contrib = self.contributions()[:, i] if self.components else np.zeros(0)
        total = float(np.sum(contrib**2)) or 1.0
        rows = []
        for comp, share in zip(self.components, contrib, strict=True):
            value = np.broadcast_to(np.asarray(comp.value_arcsec, dtype=float), (self.points,))[i]
            sens = np.broadcast_to(np.asarray(comp.sensitivity, dtype=float), (self.points,))[i]
            rows.append({
                "name": comp.name, "evaluation": comp.evaluation,
                "distribution": comp.distribution, "value_arcsec": float(value),
                "divisor": comp.divisor, "u_arcsec": float(value / comp.divisor),
                "sensitivity": float(sens), "contribution_arcsec": float(share),
                "share": float(share**2 / total), "dof": comp.dof, "note": comp.note,
            })
        return rows
