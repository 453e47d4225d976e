"""A repeated reading of a point that cannot be that point's: with n readings per face the
second (third, …) take of a face missed — the table turned on to the next face first — and
the next face's reading came to be filed as this face's repeat, onto a certificate
(capture80). Such a take is refused (the window says why and what to do); every reading
already taken is kept.

**What tells a repeat from another face** (a polygon of N faces on a rotary table, the
autocollimator on one face at a time, the table's encoder read beside):

* the **encoder** reads the table's position. Two readings of one face are taken with the
  table still: they differ by the encoder's noise and resolution (arcseconds) and at most a
  nudge of the table to null the autocollimator again (minutes of arc). A reading of
  another face differs by a whole number of pitches 360°/N (≥ 1° for any polygon up to 360
  faces) give or take that face's error (arcseconds). The two populations lie a pitch
  apart: the limit is **half the pitch** (:func:`turned_away`), equally far from both —
  beyond it the reading is nearer another face than this one (the rule the window counts
  the table's move to the next face by, and warns of a first reading at another face
  with). The pitch not known (the number of faces not set): half of 1°, the finest pitch
  a polygon's guide knows; still hundreds of times a repeat's spread.
* the **autocollimator** cannot tell. Nulled at each face, the next face reads the nulling
  residual plus the difference of the two faces' errors — a few arcseconds, tenths for a
  good polygon — the same order as two readings of one face apart (noise 0.01–0.1″, a
  drift, a re-null). Any limit on it would refuse good repeats or pass the next face. With
  the autocollimator alone the table's turn is seen instead: its mirror out of the view for
  :data:`~models.capture.stability.OUT_OF_VIEW_GAP_S` or longer (a turn by hand or motor
  takes longer; one frame marked not valid is no turn) — the move auto-take counts too.
  Whether the table came back to the face then is the technician's word (a take by hand).
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["FINEST_PITCH_DEG", "TurnedAway", "repeat_limit_deg", "turned_away"]

#: the pitch taken while the number of faces is not known: 360°/360 faces
FINEST_PITCH_DEG = 1.0


@dataclass(frozen=True)
class TurnedAway:
    """The table's encoder at a repeat too far from the point's first reading to be the
    same face (degrees)."""

    value_deg: float
    first_deg: float
    #: value − first, wrapped to ±180°
    off_deg: float
    #: the most a repeat of the face may read from its first reading (half the pitch)
    limit_deg: float


def repeat_limit_deg(pitch_deg: float) -> float:
    """The most a repeat's encoder reading may differ from the face's first: half the pitch
    (``pitch_deg`` 360°/N; 0 or less: not known, :data:`FINEST_PITCH_DEG`)."""
    return (pitch_deg if pitch_deg > 0.0 else FINEST_PITCH_DEG) / 2.0


def turned_away(value_deg: float, first_deg: float, pitch_deg: float) -> TurnedAway | None:
    """A :class:`TurnedAway` when the encoder reading ``value_deg`` of a repeat lies
    :func:`repeat_limit_deg` or more from ``first_deg``, the face's first reading (either
    side of 0°/360°); None when it can be the same face."""
    off = (float(value_deg) - float(first_deg) + 180.0) % 360.0 - 180.0
    limit = repeat_limit_deg(pitch_deg)
    if abs(off) < limit:
        return None
    return TurnedAway(float(value_deg), float(first_deg), off, limit)
