"""Harmonic orders not fitted that fold into a fitted order's amplitude at the sampled phases.

At N equal steps a period, order j and order k take the same values at every sample when
j ≡ ±k (mod N): sin 5θ = −sin 3θ and cos 5θ = cos 3θ at N = 8. Orders that alias among those
fitted are refused (analysis.check_orders_not_aliased). An order that is *not* fitted is not
refused, and cannot be: it is invisible at these phases, its harmonic lands whole in the
fitted order it aliases with. The amplitude printed for that order is then the two together
(their phasors' sum), its U from the fit's residuals does not hold the other, and the model's
curve between the samples is not the signals' (day review F5: at N = 8 with orders 1, 3 fitted,
A3 printed 0.0021 ± 0.0001 V where the true A3 was 0.005 V and A5 0.004 V).

Decided from the design, as the refusal is: an order j not fitted folds into a fitted order k
when the phases cannot tell the two apart by the refusal's own rule (their separation below
:func:`~models.fringe.order_separation.required_separation`: 0 at exact aliasing, the jitter's
alone about N steps) and at least :data:`FOLD_SHARE` of j's harmonic lands in k's amplitude
(j regressed on the fitted columns at the sampled phases: the largest singular value of the
block of order k's coefficients, 1 when j and k alias). An order the phases do tell apart
(random phases, a record of a few samples that does not alias) is not named: the residuals
show it if the signals hold it (models.fringe.unmodelled_harmonics).

The orders looked at: every order not fitted up to :data:`BEYOND` above the highest of the
method's model (5) or of the fit, whichever is higher: 1 … 7 for the model's orders. An
order below half the sampled phases is also in the residuals' test; one above folds and
only this check can name it. A read head's signals hold odd harmonics falling with their
order, and the next odd order above the fitted ones is the first the fit leaves out (audit
69 finding 6: at N = 12 a 7th of 1 % folds into the fitted 5th exactly, 7 ≡ −5 mod 12,
and nothing was said; at N = 8 orders 6 and 7 fold into 2 and 1 as 5 does into 3). Higher
orders fold likewise at any N (at N = 64, 59 into 5), and a check of every order would
name a fold at every N: they are not claimed either way, smaller still than the one above
the fit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from models.fringe.order_separation import order_gram, pair_separation, required_separation

__all__ = ["BEYOND", "FOLD_SHARE", "MODEL_HIGHEST", "FoldedOrder", "folded_orders"]

#: the highest order of the method's model (Gao et al. 2013, eqs 8–9: orders 1, 3, 5)
MODEL_HIGHEST = 5
#: the orders looked at reach this far above the highest of the model's or the fit's: the
#: next odd order, the first a read head's signals hold that the fit leaves out
BEYOND = 2
#: an order not fitted is named when at least this share of its harmonic's amplitude lands
#: in one fitted amplitude (1 at exact aliasing; random phases give about 1/√n)
FOLD_SHARE = 0.5


@dataclass(frozen=True)
class FoldedOrder:
    """Order ``order``, not fitted, lands in the fitted order ``into``'s amplitude (0: the
    offset) by the share ``share`` of its amplitude."""

    order: int
    into: int
    share: float


def folded_orders(phases_rad: np.ndarray, orders: tuple[int, ...],
                  weights: np.ndarray | None = None,
                  phase_u_rad: float = 0.0) -> tuple[FoldedOrder, ...]:
    """The orders not in ``orders`` (up to :data:`BEYOND` above :data:`MODEL_HIGHEST` or the
    highest fitted, whichever is higher) that
    fold into a fitted order's amplitude (or the offset) at the phases ``phases_rad``
    (``weights``: samples at each, when they are distinct phases; ``phase_u_rad`` their
    standard uncertainty, as the refusal takes it), the lowest first. The fitted design must
    be of full rank (the orders fitted are told apart)."""
    fitted = (0, *orders)
    highest = max(MODEL_HIGHEST, max(orders, default=0)) + BEYOND
    others = [j for j in range(1, highest + 1) if j not in orders]
    if not others:
        return ()
    every = (*fitted, *others)
    gram = order_gram(phases_rad, every, weights)
    p = 1 + 2 * len(orders)
    try:
        # the coefficients of each unfitted column on the fitted ones (all scaled alike,
        # √2 sin kθ, √2 cos kθ, the offset 1)
        coef = np.linalg.solve(gram[:p, :p], gram[:p, p:])
    except np.linalg.LinAlgError:
        return ()
    found = []
    for i, j in enumerate(others):
        block_j = coef[:, 2 * i:2 * i + 2]
        for position, k in enumerate(fitted):
            if k == 0:  # the offset's column is 1, the harmonic's √2: a volt of it, 1/√2 V
                share = float(np.linalg.norm(block_j[0])) / math.sqrt(2.0)
            else:
                rows = slice(1 + 2 * (position - 1), 3 + 2 * (position - 1))
                share = float(np.linalg.svd(block_j[rows], compute_uv=False)[0])
            if share >= FOLD_SHARE and pair_separation(gram, every, k, j) < \
                    required_separation(k, j, phase_u_rad):
                found.append(FoldedOrder(j, k, share))
    return tuple(found)
