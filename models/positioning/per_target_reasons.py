"""Why a per-target figure of the positioning JSON is null: ``per_target``'s ``…_reason`` keys.

Every null figure of the JSON says why beside it (the figures' ``interval_reason``, the
cross-calibration's ``closure_arcsec_reason``). Per target a figure is null where the readings
there cannot give it: a mean where the target has no approach in that direction, a standard
deviation (and its ±2s band) where it has fewer than two, B_i and M_i where it is approached in
one direction only, R_i where either (it needs both directions' s). The reason names those
targets, one sentence for each cause; null where every target's value is given. A run in one
direction has no B_i, M_i, R_i at all: the run's reason, as before.
"""

from __future__ import annotations

import numpy as np

from models.messages import QT_TR_NOOP, Message, message, separated
from models.positioning.model import PositioningResult
from models.positioning.report import NEEDS_BOTH_DIRECTIONS

__all__ = ["APPROACHED_ONCE", "NO_APPROACH", "ONE_DIRECTION_AT_TARGETS",
           "ONCE_IN_A_DIRECTION_AT_TARGETS", "per_target_reasons"]

#: a mean, s and ±2s null where the target has no approach in that direction
NO_APPROACH = {
    "up": QT_TR_NOOP("null at target(s) {targets}: the readings have no approach in the ↑ "
                     "direction there"),
    "down": QT_TR_NOOP("null at target(s) {targets}: the readings have no approach in the ↓ "
                       "direction there")}
#: s and ±2s null where the target is approached once in that direction
APPROACHED_ONCE = {
    "up": QT_TR_NOOP("null at target(s) {targets}: approached only once in the ↑ direction, "
                     "so no standard deviation"),
    "down": QT_TR_NOOP("null at target(s) {targets}: approached only once in the ↓ direction, "
                       "so no standard deviation")}
#: B_i, M_i and R_i null where a target of a run in both directions has one only
ONE_DIRECTION_AT_TARGETS = QT_TR_NOOP(
    "null at target(s) {targets}: it needs both approach directions, and the readings there "
    "have one only")
#: R_i null where a target is approached in both directions, once in one of them
ONCE_IN_A_DIRECTION_AT_TARGETS = QT_TR_NOOP(
    "null at target(s) {targets}: approached only once in a direction there, so no standard "
    "deviation")


def _named(positions: np.ndarray, where: np.ndarray, template: str) -> Message | str:
    """``template`` naming the targets ``where`` is true ("" where it is nowhere)."""
    if not np.any(where):
        return ""
    return message(template, targets=", ".join(f"{t:g}" for t in positions[where]))


def per_target_reasons(result: PositioningResult) -> dict[str, str | None]:
    """Why each per-target list of the JSON has nulls, by its key (``mean_up``, ``s_up``,
    ``band_2s_up`` …, ``B_i``, ``M_i``, ``R_i``): the targets named and why, None where
    every value is given; B_i, M_i and R_i of a run in one direction: the run's reason."""
    positions = result.positions
    runs = {name: np.asarray(stats.runs) for name, stats in
            (("up", result.iso.forward), ("down", result.iso.backward)) if stats is not None}
    out: dict[str, str | None] = {}
    for name, n in runs.items():
        never = _named(positions, n == 0, NO_APPROACH[name])
        out[f"mean_{name}"] = never or None
        out[f"s_{name}"] = out[f"band_2s_{name}"] = separated(
            [never, _named(positions, n == 1, APPROACHED_ONCE[name])], "; ") or None
    if not result.bidirectional:
        both = message(NEEDS_BOTH_DIRECTIONS)
        out.update({"B_i": both, "M_i": both, "R_i": both})
        return out
    one_way = (runs["up"] == 0) | (runs["down"] == 0)
    once = ~one_way & ((runs["up"] == 1) | (runs["down"] == 1))
    one = _named(positions, one_way, ONE_DIRECTION_AT_TARGETS)
    out["B_i"] = out["M_i"] = one or None
    out["R_i"] = separated(
        [one, _named(positions, once, ONCE_IN_A_DIRECTION_AT_TARGETS)], "; ") or None
    return out
