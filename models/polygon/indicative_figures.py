"""The polygon's figures that are printed as measured but with no coverage interval, and
why: the reversal B (ISO 230-2, largest |x̄↑ − x̄↓|) with its mean B̄, and the 1st and 2nd
harmonics' amplitudes (day review 66 F4: they were printed as results, with no U, although
with one set per direction B cannot be told from the zero drift carried between the sets:
0.112″ in the sample's budget against reversals of 0.08–0.32″).

Each is marked "no coverage interval: …" with its reason in the statistics table (and so
the DCC) and stated in the JSON as {value, interval_low: null, interval_high: null,
coverage_probability: null} beside the reason, as the ISO 230-2 figures' JSON states a figure
the readings do not bound.

Where the autocollimator's zero moved between the sets (:func:`zero_moved`), the figures made
from the sets' scatter or from the difference of the directions are withheld as figures of
the encoder, with that reason (:data:`ZERO_MOVED`), not printed with a qualifier: one offset of
a whole set is the same unknown whether the autocollimator's zero or the encoder moved, so
the readings cannot tell the encoder's share, and a number in an encoder's "Repeatability"
or "Reversal" row is read as the encoder's whatever the note beside it says (day review 68
F3: 1.34″ and B̄ +1.05″ printed beside a budget whose repeatability, each set's offset taken
out, was 0.097″). U is not touched: the budget already takes each set's offset as an input
of its own (models.polygon.report)."""

from __future__ import annotations

from typing import Any

import numpy as np

from models.messages import QT_TR_NOOP, message, separated
from models.polygon.model import PolygonResult, zero_offsets_warning

__all__ = ["HARMONICS_NO_INTERVAL", "ISO230_NO_INTERVAL", "REVERSAL_CONFOUNDED",
           "REVERSAL_NOT_EVALUATED", "SCATTER_FREE_ISO230", "ZERO_MOVED",
           "harmonics_reason", "indicative_figures_json", "no_interval", "reversal_figures",
           "reversal_reason", "zero_moved"]

#: one set in each direction: each direction's mean is one set, whose offset from the common
#: zero is the zero drift it carries (and its reading noise): a difference of the two
#: directions holds that drift whole, and nothing in the readings tells it from a reversal
REVERSAL_CONFOUNDED = QT_TR_NOOP(
    "one set per direction: the reversal cannot be told from the zero drift carried between "
    "the sets and their reading noise; indicative, not a calibration result")
#: sets repeated in a direction: each face's reversal has its U (the JSON's
#: ``expanded_uncertainty_reversal_arcsec``, models.polygon.report.reversal_budget), but B, the
#: largest over the faces, and B̄, their mean, have no interval evaluated
REVERSAL_NOT_EVALUATED = QT_TR_NOOP(
    "no coverage interval is evaluated for the largest and the mean reversal over the faces "
    "(the zero drift carried between the sets and their reading noise enter them); "
    "indicative, not a calibration result")
#: an amplitude √(a² + b²) of noisy Fourier coefficients is biased high, as a range is: pure
#: noise of σ per position gives σ·√(π/n) on average over n positions
HARMONICS_NO_INTERVAL = QT_TR_NOOP(
    "an amplitude is biased high by the readings' noise, as a range is, and its uncertainty "
    "is not evaluated; indicative, not a calibration result")

#: the JSON's ``iso230_arcsec`` (E, M, R, A, B … of the sets, taken as ISO 230-2 runs): plain
#: numbers, no interval (audit 68 finding 4: a lab's system could not tell them from
#: calibrated figures); the reason beside them, ``iso230_arcsec_reason``
ISO230_NO_INTERVAL = QT_TR_NOOP(
    "indicative: no coverage interval evaluated; the ISO 230-2 figures of the sets (not "
    "printed on the certificate) are as computed from the readings, each a largest value or "
    "a range over the faces, biased high by the readings' noise; the calibration results are "
    "the face deviations with their U")

#: the autocollimator's zero moved between the sets (:func:`zero_moved`): why the
#: repeatability, the reversal and the ISO 230-2 figures made from them are not given
ZERO_MOVED = QT_TR_NOOP(
    "the autocollimator's zero moved between the sets: the sets' scatter and the difference "
    "between the directions hold its moves, which the readings cannot tell from the "
    "encoder's, so no figure of the encoder can be made from them (U takes each set's offset "
    "out as an input of its own)")
#: the ISO 230-2 figures a set's offset cannot move: each a range over the faces of one
#: direction's mean, or of the mean of the two directions' (the offsets shift all faces alike)
SCATTER_FREE_ISO230 = ("E_up", "E_down", "M")


def zero_moved(result: PolygonResult) -> bool:
    """Whether the autocollimator's zero moved between the sets: the analysis's warning
    (:func:`models.polygon.model.zero_offsets_warning`) on the same errors."""
    if len(result.sets) < 2:
        return False
    index = (None if any(s.reading_index is None for s in result.sets) else
             np.array([np.asarray(s.reading_index, dtype=float) for s in result.sets]))
    return bool(zero_offsets_warning(
        np.array([s.corrected_error_arcsec for s in result.sets]),
        np.array([s.direction for s in result.sets]), index))


def reversal_reason(result: PolygonResult) -> str | None:
    """Why the reversal has no coverage interval (None: no reversal, one direction run);
    :data:`ZERO_MOVED` where the autocollimator's zero moved between the sets (the
    certificate and the summary then give no reversal at all)."""
    if result.reversal_arcsec is None:
        return None
    if zero_moved(result):
        return ZERO_MOVED
    directions = np.array([s.direction for s in result.sets])
    once = min(int(np.sum(directions > 0)), int(np.sum(directions < 0))) == 1
    return REVERSAL_CONFOUNDED if once else REVERSAL_NOT_EVALUATED


def harmonics_reason(result: PolygonResult) -> str | None:
    """Why the 1st and 2nd harmonics have no coverage interval (None: fewer than 4 faces, no
    2nd harmonic printed)."""
    return HARMONICS_NO_INTERVAL if result.harmonics.amplitude.size > 2 else None


def reversal_figures(result: PolygonResult) -> dict[str, float]:
    """B and B̄ of ISO 230-2 (deviation x = reference − indicated: B̄ the mean of ē↓ − ē↑ of
    the errors); {} when one direction only was run."""
    if result.reversal_arcsec is None or result.mean_reversal_arcsec is None:
        return {}
    return {"B": float(np.max(np.abs(result.reversal_arcsec))),
            "B_mean": -result.mean_reversal_arcsec}


def no_interval(note: Any, reason: str) -> Any:
    """A statistics row's note with "no coverage interval: ``reason``" after it."""
    return separated((note, message(QT_TR_NOOP("no coverage interval: {reason}"),
                                    reason=message(reason))))


def indicative_figures_json(result: PolygonResult) -> dict[str, Any]:
    """The JSON's objects of the figures printed without an interval, each with its reason:
    ``reversal_figures`` (B, B_mean) and ``harmonic_figures`` (first, second; amplitudes),
    nulls and no key where the run gives no such figure."""
    from models.uncertainty.figure_intervals import figure_objects  # scipy: --json only

    out: dict[str, Any] = {}
    reversal = reversal_reason(result)
    if reversal is not None:
        # where the zero moved, no value: the reason says why (:data:`ZERO_MOVED`)
        out["reversal_figures"] = figure_objects(
            ("B", "B_mean"), {} if reversal == ZERO_MOVED else reversal_figures(result), {})
        out["reversal_figures_reason"] = message(reversal)
    harmonics = harmonics_reason(result)
    if harmonics is not None:
        amplitude = result.harmonics.amplitude
        out["harmonic_figures"] = figure_objects(
            ("first", "second"), {"first": amplitude[1], "second": amplitude[2]}, {})
        out["harmonic_figures_reason"] = message(harmonics)
    return out
