"""The rounding of the horizontal readings as typed: the encoder's display and the
autocollimator's, each on its own.

A face's error is taken from the encoder's reading and the autocollimator's horizontal
reading, each rounded by its display to its step δ (:func:`models.readings.resolution
.readings_step`: the finest difference its digits show). Whether that rounding is noise the
readings show or an error they hide depends on how the shaft was stopped:

* stopped anywhere near the face and the autocollimator read there: the stop moves from
  set to set by many steps of either display, each reading's rounding is new in each set,
  and the sets' scatter holds it (it averages out over the sets);
* turned until the autocollimator shows its zero (nulled), or until the encoder shows the
  face's nominal angle: that column reads alike from set to set, its rounding is the same
  in every set — the mean keeps it, and no scatter shows it.

So each column's step is an input of U of its own (rectangular, half-width δ/2) where the
column's readings at a face vary from set to set by less than its step (a direction read
twice shows that), or, with no direction read twice, for the encoder where the reading
noise is below its step: that noise comes from the vertical readings' fits, which hold the
autocollimator's rounding (its vertical display is the same) but never the encoder's. The
encoder's step is found from its readings less each face's nominal angle (the face pitch,
360°/n, from the first reading), so that a display whose readings all lie a whole pitch
apart is not taken for a step of 30°. Encoder readings that lie on the nominal angles at
every face show no step at all: the encoder was set to each nominal, and where the operator
stopped within its display's step is not in the readings. A pitch that is not a whole
number of micro-arcseconds (7, 11, 13 … faces) takes the step from the readings' own
differences (one above 60″ is the pitch's, not a display's) and cannot tell readings on
the nominal.

A reviewer's rig (numpy only, its own frame): a nulled autocollimator with the encoder
shown to 0.001° (3.6″) covered 11–39 % of the faces' true errors before; a rough null read
to 0.1″ hid the encoder's 3.6″ when the two columns' steps were taken together (18 %); with
the step of readings on a whole pitch taken as 30°, U was 88 000″ and the decision "pass".
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from models.readings.resolution import readings_step, step_counts

__all__ = ["HorizontalRounding", "horizontal_rounding"]

#: one turn and half a turn, in arcseconds
_TURN, _HALF_TURN = 1296000.0, 648000.0


@dataclass(frozen=True)
class HorizontalRounding:
    """The steps of the horizontal readings as typed (″; None: not found) and whether each
    one's rounding is an input of U of its own."""

    encoder_step_arcsec: float | None
    ac_step_arcsec: float | None
    encoder_counts: bool
    ac_counts: bool
    encoder_on_nominal: bool  # every encoder reading on its face's nominal angle
    ac_alike: bool  # the autocollimator read one value throughout (nulled)
    repeated: bool  # a direction was read twice (its sets' spread measured)
    encoder_spread_arcsec: float | None = None  # the pooled spread at a face over the sets
    ac_spread_arcsec: float | None = None
    noise_arcsec: float | None = None  # the reading noise compared with, no direction read twice

    @property
    def nothing_measured(self) -> bool:
        """Every encoder reading on its nominal and the autocollimator alike throughout: every
        error is 0 as typed, whatever the encoder's true errors within its display's step."""
        return self.encoder_on_nominal and self.ac_alike


def horizontal_rounding(sets, faces: int, counting: int, noise: float | None = None,
                        typed=None) -> HorizontalRounding:
    """The rounding of the encoder's and the autocollimator's horizontal readings of
    ``sets`` (PolygonSetReadings, faces numbered 1…``faces``, the encoder counting
    ``counting`` = ±1 with the face numbers). ``noise``: the reading noise the budget takes
    where no direction was read twice (the vertical fits', or the σ stated; None: not
    known): the encoder's step then counts where the noise is below it (a rounding of δ
    random from face to face adds δ²/12 to a variance the noise does not hold: at σ ≥ δ
    under 4 % of U; a 0.01″ display of the sample's DMS readings is not worth a line).
    ``typed``: (face numbers, encoder readings °, autocollimator readings ″) of every row as
    typed, where ``sets`` holds each face's readings averaged (readings per point > 1): the
    steps are the displays', found from these (averages of 3.6″ readings lie on a 0.9″
    grid); the spreads from the averages."""
    if typed is not None:  # the rows as typed (the sets hold averages)
        faces_all, encoder_all, readings = (np.asarray(c, dtype=float) for c in typed)
    else:
        faces_all = np.concatenate([np.asarray(s.positions, dtype=float) for s in sets])
        encoder_all = np.concatenate([np.asarray(s.encoder_deg, dtype=float) for s in sets])
        readings = np.concatenate([np.asarray(s.ac_x_arcsec, dtype=float) for s in sets])
    # the reference: the first reading as typed (an average is off the display's grid)
    at = np.flatnonzero(np.isfinite(faces_all) & np.isfinite(encoder_all))
    reference = float(encoder_all[at[0]] if at.size else sets[0].encoder_deg[0]) * 3600.0
    start = int(faces_all[at[0]] if at.size else sets[0].positions[0])
    encoder, ac, positions, directions = [], [], [], []
    for one in sets:
        encoder.append(_less_nominal(one.positions, one.encoder_deg, reference, start, faces,
                                     counting))
        ac.append(np.asarray(one.ac_x_arcsec, dtype=float))
        positions.append(np.asarray(one.positions, dtype=int))
        directions.append(int(one.direction))
    if _TURN / faces * 1e6 == round(_TURN / faces * 1e6):  # the pitch on the grid
        remainders = _less_nominal(faces_all, encoder_all, reference, start, faces, counting)
        encoder_step = readings_step(remainders)
        on_nominal = bool(np.all(np.abs(remainders[np.isfinite(remainders)]) < 1e-6))
    else:
        # a pitch off the grid (7, 11, 13 … faces): the readings' own differences, where they
        # show a display's step and not the pitch; readings on the nominal not told
        encoder_step = readings_step(np.concatenate([[0.0], encoder_all * 3600.0 - reference]))
        encoder_step = encoder_step if encoder_step is not None and encoder_step <= 60.0 else None
        on_nominal = False
    ac_step = readings_step(readings)
    finite = readings[np.isfinite(readings)]
    ac_alike = bool(np.ptp(finite) == 0.0) if finite.size else True
    encoder_spread = _spread_at_a_face(encoder, positions, directions)
    ac_spread = _spread_at_a_face(ac, positions, directions)
    repeated = encoder_spread is not None
    encoder_counts = encoder_step is not None and (
        step_counts(encoder_step, encoder_spread) if encoder_spread is not None
        else noise is None or step_counts(encoder_step, noise))
    ac_counts = repeated and ac_spread is not None and step_counts(ac_step, ac_spread)
    return HorizontalRounding(encoder_step, ac_step, encoder_counts, ac_counts, on_nominal,
                              ac_alike, repeated, encoder_spread, ac_spread,
                              None if repeated else noise)


def _less_nominal(positions, encoder_deg, reference: float, start: int, faces: int,
                  counting: int) -> np.ndarray:
    """Encoder readings (″) less the first's and each face's nominal angle from its face,
    wrapped to ±180° (past 360° is the same face)."""
    a = np.asarray(encoder_deg, dtype=float) * 3600.0 - reference
    a = a - counting * (np.asarray(positions, dtype=float) - start) * (_TURN / faces)
    return (a + _HALF_TURN) % _TURN - _HALF_TURN


def _spread_at_a_face(values: list[np.ndarray], positions: list[np.ndarray],
                      directions: list[int]) -> float | None:
    """The standard deviation of one column at a face over the sets of a direction, pooled
    over the faces and the directions read at least twice (None: none was)."""
    squares, dof = 0.0, 0
    for d in (1, -1):
        group = [(v, p) for v, p, g in zip(values, positions, directions, strict=True) if g == d]
        if len(group) < 2:
            continue
        faces = set.intersection(*(set(p.tolist()) for _, p in group))
        for face in faces:
            at = np.array([v[p == face][0] for v, p in group], dtype=float)
            at = at[np.isfinite(at)]
            if at.size >= 2:
                squares += float(np.sum((at - at.mean()) ** 2))
                dof += at.size - 1
    return float(np.sqrt(squares / dof)) if dof else None
