"""Whether a fitted tilt's direction is determined: a tilt in polar form (its magnitude ψ
and the direction it leans to, the theodolite's α or the polygon's ω) has a direction only
where the magnitude is told from zero.

The fit's linearised u of the direction is about u(ψ)/ψ radians: it grows without bound as
ψ nears 0 and stops meaning anything before then, since the direction of a tilt the noise
cannot tell from none is set by the noise. An audit's theodolite rig with no tilt at all
(ψ = 0, pointing noise 0.5″) had ψ fitted as 7.9″ with u 4.3″ and α printed as
173.6° ± 4.5° (u) where it had simulated the set-up at 43.5°, 29 u off; a polygon with no
pyramidal tilt printed ω = 154.1° ± 34.6°. Below :data:`DETERMINED_AT` standard
uncertainties the direction is stated as not identified: a tilt is fitted as two
components (ψ cos α, ψ sin α), each with about the u of ψ, so with no tilt at all the
fitted ψ is Rayleigh-distributed and exceeds √(−2 ln 0.05) u = 2.45 u in 5 % of runs (2 u,
the normal's two-sided 95 %, in 13.5 %). The correction itself needs no direction there:
the tilt's effect is within its own u, which the model's uncertainty carries.
"""

from __future__ import annotations

import math

from models.messages import QT_TR_NOOP

__all__ = ["DETERMINED_AT", "NOT_DETERMINED", "NOT_IDENTIFIED", "direction_determined"]

#: the tilt, in its standard uncertainties, at and above which its direction is stated:
#: the 95 % point of the Rayleigh distribution (a fitted tilt of none exceeds it in 5 %)
DETERMINED_AT = math.sqrt(-2.0 * math.log(0.05))

#: what is said of a direction not determined (the figures: the tilt and its u)
NOT_DETERMINED = QT_TR_NOOP(
    "The tilt {tilt} is not told from 0 by its standard uncertainty {u} (it is less than "
    "2.45 times that, the 95 % point of a fitted tilt where there is none): the direction it "
    "leans to, {direction}, is not identified and is not stated.")


#: a direction's value where it is not determined (a certificate's cell)
NOT_IDENTIFIED = QT_TR_NOOP("not identified (the tilt is not told from 0)")


def direction_determined(tilt: float, u_tilt: float) -> bool:
    """Whether a tilt of magnitude ``tilt`` with standard uncertainty ``u_tilt`` (same unit)
    has a determined direction: |tilt| ≥ :data:`DETERMINED_AT` · u_tilt, both finite. A u of
    0 (an exact fit) determines any tilt but 0."""
    if not (math.isfinite(tilt) and math.isfinite(u_tilt)):
        return False
    return abs(tilt) >= DETERMINED_AT * u_tilt and tilt != 0.0
